// kernel_errors.hpp — the two ways a kernel of kernels_cuda/ refuses to run,
// as exceptions the command line turns into one error line and exit code 2:
//   NoDeviceError      --backend cuda without a usable CUDA device (or a
//                      flipflop built without nvcc);
//   DeviceMemoryError  the input does not fit in device memory (the kernels
//                      size their buffers up front from n and ask once).
// Input errors stay std::invalid_argument with the reference's message.
#pragma once

#include <stdexcept>
#include <string>

namespace flipflop::kernels {

struct NoDeviceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct DeviceMemoryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace flipflop::kernels

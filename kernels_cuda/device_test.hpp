// device_test.hpp — the start of every GPU test program: the number of CUDA
// devices, or a visible "skipped" line and exit code 77, which ctest reports as
// skipped (SKIP_RETURN_CODE), never as passed.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace flipflop::kernels_cuda {

int device_count();  // classify_cuda.cu

inline int require_device() {
  // line-buffered: a program the device kills (an abort on a sticky CUDA
  // error) leaves every line it printed before, the case it was in included
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const int devices = device_count();
  if (devices <= 0) {
    std::printf("no CUDA device: skipped\n");
    std::exit(77);
  }
  std::printf("CUDA devices: %d\n", devices);
  return devices;
}

}  // namespace flipflop::kernels_cuda

// device_test.hpp — the start of every GPU test program: the number of CUDA
// devices, or a visible "skipped" line and exit code 77, which ctest reports as
// skipped (SKIP_RETURN_CODE), never as passed.
#pragma once

#include <cstddef>
#include <cstdio>
#include <cstdlib>

namespace flipflop::kernels_cuda {

int device_count();  // classify_cuda.cu
// The device's per-thread stack limit (cudaLimitStackSize; 0 on an error). The
// driver raises it at a launch to the kernel's deepest call chain and keeps
// it, reserving that much local memory for every thread the device can hold:
// the exact stages' frames (predicates/exact_expansion.hpp, "Stack per call")
// decide it. classify_cuda.cu.
std::size_t stack_limit();

inline void report_stack_limit(const char* when) {
  std::printf("per-thread stack limit %s: %zu bytes\n", when, stack_limit());
}

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
  report_stack_limit("at the start");
  return devices;
}

}  // namespace flipflop::kernels_cuda

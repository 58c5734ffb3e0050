// classify_cuda.cu — classify.cuh built by nvcc against thrust's CUDA backend.
#include <cuda_runtime_api.h>

#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/classify.cuh"

namespace flipflop::kernels_cuda {

int device_count() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error of a missing driver
    return 0;
  }
  return count;
}

void start_device() {
  // the driver's initialisation and the primary context's creation: the
  // runtime does both lazily at a process's first call that needs a context;
  // cudaFree(nullptr) is such a call and does nothing else. Without a device
  // the error is cleared: the kernel's own check reports it (one line).
  if (cudaFree(nullptr) != cudaSuccess) cudaGetLastError();
}

std::size_t stack_limit() {
  std::size_t bytes = 0;
  if (cudaDeviceGetLimit(&bytes, cudaLimitStackSize) != cudaSuccess) {
    cudaGetLastError();
    return 0;
  }
  return bytes;
}

}  // namespace flipflop::kernels_cuda

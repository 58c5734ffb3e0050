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

}  // namespace flipflop::kernels_cuda

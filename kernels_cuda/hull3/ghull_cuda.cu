// ghull_cuda.cu — ghull.cuh built by nvcc against thrust's CUDA backend.
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/hull3/ghull.cuh"

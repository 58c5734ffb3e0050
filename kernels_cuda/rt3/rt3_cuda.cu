// rt3_cuda.cu — rt3.cuh built by nvcc against thrust's CUDA backend.
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/rt3/rt3.cuh"

// hull2_cuda.cu — hull2.cuh built by nvcc against thrust's CUDA backend.
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/hull2/hull2.cuh"

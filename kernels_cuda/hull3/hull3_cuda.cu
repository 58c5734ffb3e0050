// hull3_cuda.cu — hull3.cuh built by nvcc against thrust's CUDA backend
// (device_count() is classify_cuda.cu's).
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/hull3/hull3.cuh"

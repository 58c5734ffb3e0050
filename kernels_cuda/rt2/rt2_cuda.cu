// rt2_cuda.cu — rt2.cuh built by nvcc against thrust's CUDA backend
// (device_count() is classify_cuda.cu's).
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/rt2/rt2.cuh"

// predicates_cuda.cu — predicates_device.cuh built by nvcc against thrust's CUDA
// backend (device_count() is defined in classify_cuda.cu).
#define FF_KERNELS_NS kernels_cuda
#include "kernels_cuda/predicates_device.cuh"

// hull2_omp.cpp — hull2.cuh built by the host compiler against thrust's OpenMP
// backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by CMake).
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/hull2/hull2.cuh"

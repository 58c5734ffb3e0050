// hull3_omp.cpp — hull3.cuh built by the host compiler against thrust's
// OpenMP backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by CMake):
// the GPU ffHull, runnable and testable on any multicore CPU.
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/hull3/hull3.cuh"

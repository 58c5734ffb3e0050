// ghull_omp.cpp — ghull.cuh built by the host compiler against thrust's OpenMP
// backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by CMake): gHull
// runnable and testable on any multicore CPU, with its stages' test entries.
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/hull3/ghull.cuh"

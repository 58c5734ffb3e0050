// rt2_omp.cpp — rt2.cuh built by the host compiler against thrust's OpenMP
// backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by CMake): the
// GPU ffRT, runnable and testable on any multicore CPU.
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/rt2/rt2.cuh"

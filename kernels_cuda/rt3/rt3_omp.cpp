// rt3_omp.cpp — rt3.cuh built by the host compiler against thrust's OpenMP
// backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by CMake): the
// GPU 3D regular triangulation, runnable and testable on any multicore CPU.
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/rt3/rt3.cuh"

// predicates_omp.cpp — predicates_device.cuh built by the host compiler against
// thrust's OpenMP backend (THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP, set by
// CMake): the device predicate path, runnable and testable on any multicore CPU.
#define FF_KERNELS_NS kernels_omp
#include "kernels_cuda/predicates_device.cuh"

// omp_threads.hpp — run a kernel of the thrust/OpenMP build (kernels_cuda/,
// --backend cuda-omp) with a given number of OpenMP threads: the machines
// that run these kernels have many cores, while CI and the development VM
// have 2, so a race that needs more threads to show (a shared structure used
// from inside a parallel region, a conflict at a boundary between threads'
// ranges) would otherwise stay hidden. Linked with OpenMP by
// proptests/CMakeLists.txt (the *_cuda_omp_test drivers).
#pragma once

#include <omp.h>

namespace flipflop::test {

// f() with the calling thread's OpenMP team size set to `threads`, then
// restored (the kernels open their parallel regions from this thread).
template <class F>
auto with_omp_threads(int threads, F&& f) {
  struct Restore {
    int before;
    ~Restore() { omp_set_num_threads(before); }
  } restore{omp_get_max_threads()};
  omp_set_num_threads(threads);
  return f();
}

}  // namespace flipflop::test

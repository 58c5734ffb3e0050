// certify_rtd.cpp — certify::rtd with its per-simplex and per-point checks on
// oneTBB (certify_rtd.hpp).
#include "kernels_cpu/rtd/certify_rtd.hpp"

#include "kernels_cpu/parallel.hpp"
#include "reference/rtd/certify_rtd.hpp"

namespace flipflop::cpu {

certify::Report certify_rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices,
                            certify::Level level, bool furthest, int threads, std::vector<std::int64_t>* neighbors) {
  // pieces of 64 simplices or points: an item costs one to d+1 exact SoS
  // predicates (microseconds on degenerate lattices), far above a task's
  // overhead, and a few thousand simplices (a 3^5 grid: 18,761) must still
  // split evenly over the threads
  return certify_in_parallel(
      ps, threads, [&](const certify::Speedups& s) { return certify::rtd(ps, simplices, level, furthest, s, neighbors); },
      64);
}

}  // namespace flipflop::cpu

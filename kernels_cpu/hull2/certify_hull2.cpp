// certify_hull2.cpp — certify::hull2 with parallel point checks (certify_hull2.hpp).
#include "kernels_cpu/hull2/certify_hull2.hpp"

#include "kernels_cpu/parallel.hpp"

namespace flipflop::cpu {

certify::Report certify_hull2(const PointSet& ps, const std::vector<Index>& cycle, certify::Level level,
                              int threads) {
  return certify_in_parallel(ps, threads,
                             [&](const certify::Speedups& s) { return certify::hull2(ps, cycle, level, s); });
}

}  // namespace flipflop::cpu

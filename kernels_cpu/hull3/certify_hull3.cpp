// certify_hull3.cpp — certify::hull3 with parallel checks (certify_hull3.hpp).
#include "kernels_cpu/hull3/certify_hull3.hpp"

#include "kernels_cpu/parallel.hpp"

namespace flipflop::cpu {

certify::Report certify_hull3(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                              int threads) {
  return certify_in_parallel(ps, threads,
                             [&](const certify::Speedups& s) { return certify::hull3(ps, tris, level, s); });
}

}  // namespace flipflop::cpu

// certify_rt2.cpp — certify::rt2 with parallel checks (certify_rt2.hpp).
#include "kernels_cpu/rt2/certify_rt2.hpp"

#include "kernels_cpu/parallel.hpp"

namespace flipflop::cpu {

certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level, int threads) {
  return certify_in_parallel(ps, threads, [&](const certify::Speedups& s) { return certify::rt2(ps, tris, level, s); });
}

}  // namespace flipflop::cpu

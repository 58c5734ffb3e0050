// certify_hull2.cpp — certify::hull2 with parallel point checks (certify_hull2.hpp).
#include "kernels_cpu/hull2/certify_hull2.hpp"

#include "kernels_cpu/parallel.hpp"

namespace flipflop::cpu {

certify::Report certify_hull2(const PointSet& ps, const std::vector<Index>& cycle, certify::Level level,
                              int threads) {
  certify::Report r;
  with_threads(threads, [&] {
    const pred::StaticFilter f =
        parallel_static_filter(ps.coords.size(), [&](std::size_t i) { return ps.coords[i]; }, {});
    certify::Speedups s;
    s.filter = &f;
    s.for_range = [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) {
      par_for(n, kChunk, body);
    };
    r = certify::hull2(ps, cycle, level, s);
  });
  return r;
}

}  // namespace flipflop::cpu

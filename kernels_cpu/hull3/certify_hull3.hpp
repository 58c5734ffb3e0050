// certify_hull3.hpp — the exact certifier of a 3D hull (reference/certify,
// certify::hull3) with its per-facet and per-point checks split over oneTBB
// tasks and the input's static filter from a parallel scan. It needs no
// witnesses from the algorithm that produced the hull, so it also serves
// third-party outputs (`flipflop certify hull3`, e.g. Qhull's facets). The
// verdict and its message are the sequential certifier's (certify.hpp,
// Speedups: the smallest failing facet or point is reported).
#pragma once

#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
certify::Report certify_hull3(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                              int threads = 0);

}  // namespace flipflop::cpu

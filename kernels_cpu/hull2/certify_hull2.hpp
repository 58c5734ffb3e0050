// certify_hull2.hpp — the exact certifier of a 2D hull (reference/certify,
// certify::hull2) with its per-point witnesses checked in parallel: every
// non-vertex point strictly inside (canonical) or on the inner side of (exact)
// the edge of its fan sector, the points split over oneTBB tasks, every
// predicate tried first against the input's static filter (a parallel scan).
// The verdict and its message are the sequential certifier's (certify.hpp,
// Speedups: the smallest failing index is reported).
#pragma once

#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
certify::Report certify_hull2(const PointSet& ps, const std::vector<Index>& cycle, certify::Level level,
                              int threads = 0);

}  // namespace flipflop::cpu

// certify_rt2.hpp — the exact certifier of a 2D regular / Delaunay
// triangulation (reference/certify, certify::rt2: Thm 2.2, every edge locally
// regular and every missing point redundant) with its per-triangle,
// per-vertex and per-point checks and its tables split over oneTBB tasks and
// the input's static filter (coordinates and weights) from a parallel scan.
// It needs no witnesses from the algorithm that produced the triangulation,
// so it also serves third-party outputs (`flipflop certify rt2|dt2`, e.g.
// CGAL's triangles). The verdict and its message are the sequential
// certifier's (certify.hpp, Speedups: the first failing triangle, vertex or
// point in the sequential order is reported).
#pragma once

#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                            int threads = 0);

}  // namespace flipflop::cpu

// certify_rtd.hpp — the exact certifier of a d-dimensional regular /
// Delaunay triangulation (reference/rtd/certify_rtd.hpp, certify::rtd: its
// conditions and the local-to-global argument) with its per-simplex checks —
// orientation, the facet table, local regularity — the quadratic boundary
// test's facets and the missing points' walks split over oneTBB tasks. It
// needs nothing from the algorithm that produced the triangulation (the
// cavity kernel returns no witness), so it serves `flipflop rtd`, Python's
// Delaunay in every dimension the cavity kernel takes and third-party
// outputs (`flipflop certify rtd`). The verdict and its message are the
// sequential certifier's (certify.hpp, Speedups: the first failure in the
// sequential order is reported).
#pragma once

#include <cstdint>
#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
// neighbors: where given and certified, the facet table the certificate
// matched (certify::rtd's `neighbors`: scipy's Delaunay.neighbors).
certify::Report certify_rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices,
                            certify::Level level = certify::Level::canonical, bool furthest = false, int threads = 0,
                            std::vector<std::int64_t>* neighbors = nullptr);

}  // namespace flipflop::cpu

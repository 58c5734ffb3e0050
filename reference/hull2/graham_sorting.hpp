// graham_sorting.hpp — parallel Graham's scan ("Graham-sorting"), thesis §4.2,
// Algorithm 3, run sequentially.
//
// Instead of sorting by polar angle around an input point (inexact in floating
// point, §4.2), the points are split by the line v_l v_r of the leftmost and
// rightmost points and each side is sorted by x: the upper chain is star-
// shaped w.r.t. the kernel point (0, -∞), the lower chain w.r.t. (0, +∞).
// Read <v_r, S_a descending in x, v_l, S_b ascending in x> they form a
// counter-clockwise polygon without self-intersection, which flip-pop (with
// the chain kernels, flip_pop.hpp) turns into the hull; v_l and v_r are extreme
// and never flipped.
//
// Simulation of Simplicity: "leftmost", "above" and the x order are decided by
// pred::compare_sos and pred::orient2d on the one perturbation of the
// computation, so every point is strictly above or below v_l v_r, the x order is
// strict, and the result is the canonical hull.
#pragma once

#include <vector>

#include "reference/hull2/flip_pop.hpp"

namespace flipflop::ref {

// Alg 3 lines 1-6: the polygon P = <v_r, S_a, v_l, S_b>. ps must hold at least 2 points.
ChainPolygon graham_sorting_polygon(const PointSet& ps);

// Algorithm 3: lines 1-6, then flip-pop (line 7). The hull counter-clockwise,
// smallest index first. Precondition: ps spans the plane (hull2.hpp checks).
std::vector<Index> graham_sorting(const PointSet& ps, Hull2Stats* stats = nullptr);

}  // namespace flipflop::ref

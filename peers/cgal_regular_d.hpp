// cgal_regular_d.hpp — CGAL's regular triangulations in R^d as peers of
// flipflop's d-dimensional reference (reference/rtd/), returning flipflop's
// canonical simplex output (reference/rtd/canonical_d.hpp): each simplex
// positively oriented in the volume convention (det[p_1 - p_0, ..., p_d - p_0]
// > 0, that of CGAL's Orientation_d), smallest index first, the rest
// ascending (last two swapped when needed), the list sorted.
//
// CGAL decides exactly (filtered predicates) but with its own rules for
// degeneracies (no flipflop Simulation of Simplicity), so on degenerate input
// (cospherical / coplanar points, duplicates, equal-power ties) its answer may
// legitimately differ; on input in general position it must equal flipflop's.
// CGAL's weight is the squared radius: power(x, (p, w)) = |x - p|^2 - w, the
// same w as flipflop's. Redundant points are hidden by CGAL: they are not
// vertices, and `redundant` (when given) receives them, sorted.
// Throws std::invalid_argument for d outside the supported range and
// std::runtime_error when CGAL's triangulation is lower-dimensional.
#pragma once

#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::peers {

// CGAL::Regular_triangulation (dD, Epick_d with a fixed dimension tag for
// d = 2..5), points inserted in index order.
std::vector<std::vector<Index>> cgal_regular_d(const PointSet& weighted, std::vector<Index>* redundant = nullptr,
                                               double* build_seconds = nullptr);

// CGAL::Regular_triangulation_3 (Epick), ps.dim == 3, spatially sorted range
// insertion. build_seconds (optional): the construction alone, without
// copying the input and sorting the output.
std::vector<std::vector<Index>> cgal_regular_3(const PointSet& weighted, std::vector<Index>* redundant = nullptr,
                                               double* build_seconds = nullptr);

// CGAL's Orientation_d (Epick_d, d = 2..5) of the points `tuple` in that
// order: +1, 0 or -1 (POSITIVE, COPLANAR, NEGATIVE), exact.
int cgal_orientation_d(const PointSet& ps, const std::vector<Index>& tuple);

}  // namespace flipflop::peers

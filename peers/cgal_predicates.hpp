// cgal_predicates.hpp — CGAL's Exact_predicates_inexact_constructions_kernel
// predicates as a timing peer of `flipflop bench predicates`: orientation in
// 2D and 3D (Epick), in 4..6 D (Epick_d), and the power tests of weighted
// points in 2D and 3D (power_side_of_oriented_power_circle_2 / _sphere_3).
#pragma once

#include <cstddef>
#include <vector>

namespace flipflop::peers {

// n calls of k points each: point-major coordinates (dim per point; call i
// uses points i*k .. i*k+k-1) and, for a power test, one weight per point.
struct PredicateCalls {
  int k = 0;
  int dim = 0;
  bool lifted = false;
  std::size_t n = 0;
  const double* coords = nullptr;
  const double* weights = nullptr;
};

// Whether Epick / Epick_d has this predicate here.
bool cgal_epick_has(int k, int dim, bool lifted);

// Runs the predicate on every call, `reps` times (the points converted to
// CGAL's types once, not timed); returns the median seconds of one run over
// the n calls and CGAL's sign of each call in `signs` (+1 / 0 / -1, in CGAL's
// convention: the caller relates it to flipflop's).
double cgal_epick_run(const PredicateCalls& c, int reps, std::vector<int>& signs);

}  // namespace flipflop::peers

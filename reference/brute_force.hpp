// brute_force.hpp — the canonical answers by definition, for small inputs.
//
// These enumerate all candidate edges / facets / triangles and keep those that
// the definition selects, with the perturbed predicates of predicates.hpp:
//   hull2: (i, j) is a hull edge iff every other point is strictly to its left;
//   hull3: (i, j, k) is a hull facet iff every other point is strictly on its
//          inner side;
//   rt2:   a counter-clockwise (i, j, k) is a regular triangle iff every other
//          lifted point is strictly above its lifted plane.
// Under Simulation of Simplicity the input is in general position, so these
// sets are exactly the unique answers. O(n^3) and O(n^4): an independent oracle
// for tests of algorithms and of the certifier, not a production path.
#pragma once

#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::brute {

std::vector<Index> hull2(const PointSet& ps);     // canonical vertex cycle
std::vector<Triangle> hull3(const PointSet& ps);  // canonical triangle list
std::vector<Triangle> rt2(const PointSet& ps);    // canonical triangle list (weights from ps)

}  // namespace flipflop::brute

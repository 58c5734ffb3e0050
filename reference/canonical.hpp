// canonical.hpp — the canonical order of index output (DESIGN.md "Canonical
// output"), the one definition used by every algorithm, peer and writer:
//   * a 2D hull: the counter-clockwise cycle rotated to start at its smallest
//     index;
//   * triangles: each rotated (an even permutation: orientation kept) so its
//     smallest index comes first, the list sorted lexicographically.
// Two backends agree when their canonical outputs are identical.
#pragma once

#include <algorithm>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop {

inline std::vector<Index> canonical_hull2(std::vector<Index> ccw_cycle) {
  std::rotate(ccw_cycle.begin(), std::min_element(ccw_cycle.begin(), ccw_cycle.end()), ccw_cycle.end());
  return ccw_cycle;
}

inline Triangle canonical_rotation(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

inline std::vector<Triangle> canonical_triangles(std::vector<Triangle> tris) {
  for (Triangle& t : tris) t = canonical_rotation(t);
  std::sort(tris.begin(), tris.end());
  return tris;
}

}  // namespace flipflop

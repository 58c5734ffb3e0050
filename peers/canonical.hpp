// canonical.hpp — canonical order of index output (DESIGN.md "Canonical
// output"), private to peers/: the io library offers the public version; this
// copy keeps peers/ free of a dependency on it.
#pragma once

#include <algorithm>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::peers::detail {

// Rotate a cyclic sequence so that its smallest element comes first; the
// cyclic order (here: counter-clockwise) is kept.
inline std::vector<Index> canonical_cycle(std::vector<Index> cycle) {
  auto smallest = std::min_element(cycle.begin(), cycle.end());
  std::rotate(cycle.begin(), smallest, cycle.end());
  return cycle;
}

// Rotate each triangle (an even permutation: orientation kept) so that its
// smallest index comes first, then sort the list lexicographically.
inline std::vector<Triangle> canonical_triangles(std::vector<Triangle> tris) {
  for (Triangle& t : tris) {
    if (t[1] < t[0] && t[1] <= t[2]) t = {t[1], t[2], t[0]};
    else if (t[2] < t[0] && t[2] < t[1]) t = {t[2], t[0], t[1]};
  }
  std::sort(tris.begin(), tris.end());
  return tris;
}

}  // namespace flipflop::peers::detail

// neighbours.hpp — the neighbours of a set of cells by brute force, for
// the tests of the seeded kernels (HullDIncremental, RtdCavityIncremental):
// an oracle that shares nothing with the kernels' own ridge and facet
// matching.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::test {

// nb[k][j]: the other cell holding every vertex of cell k but the j-th (the
// last such in index order), -1 where there is none. O(m^2 k^2): small sets.
inline std::vector<std::vector<std::int64_t>> neighbours_by_search(const std::vector<std::vector<Index>>& cells) {
  std::vector<std::vector<std::int64_t>> nb(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    nb[k].assign(cells[k].size(), -1);
    for (std::size_t j = 0; j < cells[k].size(); ++j)
      for (std::size_t g = 0; g < cells.size(); ++g) {
        if (g == k) continue;
        bool all = true;
        for (std::size_t c = 0; c < cells[k].size() && all; ++c)
          all = c == j || std::find(cells[g].begin(), cells[g].end(), cells[k][c]) != cells[g].end();
        if (all) nb[k][j] = static_cast<std::int64_t>(g);
      }
  }
  return nb;
}

}  // namespace flipflop::test

// visible_region.hpp — the breadth-first search both d-dimensional kernels
// (rtd_cavity: simplices visible from a lifted point; hull_d: hull facets
// visible from a point) run to find what a new point replaces: every
// visible cell is reached through visible cells (the visible facets of a
// convex polytope from a point form a connected set), so only the visible
// cells and their neighbours are tested.
#pragma once

#include <cstdint>
#include <vector>

namespace flipflop::cpu {

// Cells have W links each: links[W t + i] = W u + j, the cell u across the
// face opposite corner i of t (and that face's corner j in u). From `root`
// (visible), collects the visible cells into `region` (root first) and calls
// on_horizon(t, i, link) for each face between a visible t and an invisible
// neighbour. mark: per-cell stamps; `in` marks visible cells, in + 1
// invisible ones, both unique to this search.
template <int W, class Sees, class OnHorizon>
void visible_region(std::uint32_t root, const std::vector<std::uint32_t>& links, std::vector<std::uint32_t>& mark,
                    std::uint32_t in, std::vector<std::uint32_t>& region, Sees&& sees, OnHorizon&& on_horizon) {
  const std::uint32_t out = in + 1;
  region.clear();
  region.push_back(root);
  mark[root] = in;
  for (std::size_t q = 0; q < region.size(); ++q) {
    const std::uint32_t t = region[q];
    for (int i = 0; i < W; ++i) {
      const std::uint32_t l = links[static_cast<std::size_t>(t) * W + static_cast<std::size_t>(i)];
      const std::uint32_t u = l / W;
      if (mark[u] == in) continue;
      if (mark[u] != out) {
        if (sees(u)) {
          mark[u] = in;
          region.push_back(u);
          continue;
        }
        mark[u] = out;
      }
      on_horizon(t, i, l);
    }
  }
}

}  // namespace flipflop::cpu

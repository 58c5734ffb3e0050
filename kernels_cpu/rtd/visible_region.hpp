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

// The same search with each cell's test in two passes, a wave at a time (the
// two passes of thesis §6.4.2, as the GPU hull runs them: the filters
// first, the exact stage for what they leave). A wave is the cells the
// previous wave added to the region (the first: the root). The cells its
// cells name as neighbours that are not tested yet are tested by
// `fast(u)` (1 visible, 0 not, 2 undecided: the filters), then the
// undecided ones of the wave together by `exact_all(cells, n, result)`
// (result[k] = 1 when cells[k] is visible; the caller may run them in
// parallel), and the wave is then scanned as visible_region scans it. The
// region, its order and the on_horizon calls are visible_region's: its
// first-in-first-out search tests a cell where the cells in region order
// first name it and reads the result there; here every result of a wave is
// known when the wave is scanned in that order, and a cell the scan adds
// is scanned in a later wave, as it is scanned after the wave there.
// `pending` and `result` are the caller's buffers. Stamps, unique to this
// search: in (visible, in the region), in + 1 (invisible), in + 2
// (visible, not yet in the region), in + 3 (undecided): the caller
// advances its stamp by 4.
template <int W, class Fast, class ExactAll, class OnHorizon>
void visible_region_waves(std::uint32_t root, const std::vector<std::uint32_t>& links, std::vector<std::uint32_t>& mark,
                          std::uint32_t in, std::vector<std::uint32_t>& region, std::vector<std::uint32_t>& pending,
                          std::vector<char>& result, Fast&& fast, ExactAll&& exact_all, OnHorizon&& on_horizon) {
  const std::uint32_t out = in + 1, seen = in + 2, open = in + 3;
  region.clear();
  region.push_back(root);
  mark[root] = in;
  for (std::size_t q0 = 0; q0 < region.size();) {
    const std::size_t q1 = region.size();
    pending.clear();
    for (std::size_t q = q0; q < q1; ++q) {
      const std::uint32_t t = region[q];
      for (int i = 0; i < W; ++i) {
        const std::uint32_t u = links[static_cast<std::size_t>(t) * W + static_cast<std::size_t>(i)] / W;
        if (mark[u] - in < 4u) continue;  // tested, or waiting for the exact pass (stamps of earlier searches are below in)
        const int s = fast(u);
        if (s == 2) {
          mark[u] = open;
          pending.push_back(u);
        } else {
          mark[u] = s == 1 ? seen : out;
        }
      }
    }
    if (!pending.empty()) {
      result.resize(pending.size());
      exact_all(pending.data(), pending.size(), result.data());
      for (std::size_t k = 0; k < pending.size(); ++k) mark[pending[k]] = result[k] ? seen : out;
    }
    for (std::size_t q = q0; q < q1; ++q) {
      const std::uint32_t t = region[q];
      for (int i = 0; i < W; ++i) {
        const std::uint32_t l = links[static_cast<std::size_t>(t) * W + static_cast<std::size_t>(i)];
        const std::uint32_t u = l / W;
        if (mark[u] == in) continue;
        if (mark[u] == seen) {
          mark[u] = in;
          region.push_back(u);
          continue;
        }
        on_horizon(t, i, l);
      }
    }
    q0 = q1;
  }
}

}  // namespace flipflop::cpu

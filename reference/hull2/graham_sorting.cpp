// graham_sorting.cpp — Graham-sorting, thesis §4.2, Algorithm 3 (see graham_sorting.hpp).
#include "reference/hull2/graham_sorting.hpp"

#include <algorithm>
#include <stdexcept>

namespace flipflop::ref {

ChainPolygon graham_sorting_polygon(const PointSet& ps) {
  if (ps.dim != 2 || ps.size() < 2) throw std::invalid_argument("graham_sorting: at least 2 points in 2D are needed");
  // line 1: {v_l, v_r} <- the leftmost and rightmost points of S
  const auto [vl, vr] = leftmost_rightmost(ps);
  // lines 2-3: S_a above v_l v_r (orient2d(v_l, v_r, p) > 0), S_b below; no
  // third case under the perturbation.
  std::vector<Index> above, below;
  for (Index p = 0; p < static_cast<Index>(ps.size()); ++p) {
    if (p == vl || p == vr) continue;
    (orient(ps, vl, vr, p) > 0 ? above : below).push_back(p);
  }
  // line 4: sort S_a by x in descending order; line 5: S_b ascending
  std::sort(above.begin(), above.end(), [&](Index a, Index b) { return compare_coord(ps, a, b, 0) > 0; });
  std::sort(below.begin(), below.end(), [&](Index a, Index b) { return compare_coord(ps, a, b, 0) < 0; });
  // line 6: P <- <v_r, S_a, v_l, S_b>
  ChainPolygon out;
  out.left = vl;
  out.right = vr;
  out.polygon.reserve(ps.size());
  out.polygon.push_back(vr);
  out.polygon.insert(out.polygon.end(), above.begin(), above.end());
  out.polygon.push_back(vl);
  out.polygon.insert(out.polygon.end(), below.begin(), below.end());
  return out;
}

std::vector<Index> graham_sorting(const PointSet& ps, Hull2Stats* stats) {
  const ChainPolygon chains = graham_sorting_polygon(ps);
  return flip_pop(ps, chains, stats);  // line 7
}

}  // namespace flipflop::ref

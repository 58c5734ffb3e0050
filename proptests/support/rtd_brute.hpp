// rtd_brute.hpp — the d-dimensional regular triangulation by its definition,
// for tiny inputs: under flipflop's Simulation of Simplicity the perturbed
// lifted points (x, |x|^2 - w) are in general position in R^(d+1), and
// RT(S ⊕ W) is the projection of their lower hull (thesis §2.2 [ES92]). A
// (d+1)-subset is a simplex of it iff every other lifted point lies strictly
// above its hyperplane: power_d(positive tuple, x) < 0 for all x (the
// predicate is > 0 iff x's lifted point is below). Enumerates all subsets:
// O(n^(d+2)) predicates — n <= ~12 for d = 4.
#pragma once

#include <vector>

#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"
#include "reference/rtd/canonical_d.hpp"

namespace flipflop::test {

inline std::vector<std::vector<Index>> brute_rtd(const PointSet& ps) {
  const int d = ps.dim;
  const Index n = static_cast<Index>(ps.size());
  std::vector<std::vector<Index>> out;
  std::vector<Index> t(static_cast<std::size_t>(d + 1));
  // enumerate increasing (d+1)-tuples
  for (int i = 0; i <= d; ++i) t[static_cast<std::size_t>(i)] = static_cast<Index>(i);
  if (n < static_cast<Index>(d + 1)) return out;
  for (;;) {
    pred::Pt p[pred::kMaxLambdaK];
    for (int i = 0; i <= d; ++i) p[i] = {t[static_cast<std::size_t>(i)], ps.point(t[static_cast<std::size_t>(i)])};
    std::vector<Index> pos = t;
    if (pred::orient_d(d, p) < 0) std::swap(pos[0], pos[1]);
    bool lower = true;
    pred::WPt w[pred::kMaxLambdaK];
    for (int i = 0; i <= d; ++i) w[i] = {pos[static_cast<std::size_t>(i)], ps.point(pos[static_cast<std::size_t>(i)]), ps.weight(pos[static_cast<std::size_t>(i)])};
    for (Index x = 0; x < n && lower; ++x) {
      bool in = false;
      for (Index y : t) in = in || y == x;
      if (in) continue;
      w[d + 1] = {x, ps.point(x), ps.weight(x)};
      lower = pred::power_d(d, w) < 0;
    }
    if (lower) out.push_back(pos);
    // next combination
    int i = d;
    while (i >= 0 && t[static_cast<std::size_t>(i)] == n - static_cast<Index>(d + 1 - i)) --i;
    if (i < 0) break;
    ++t[static_cast<std::size_t>(i)];
    for (int j = i + 1; j <= d; ++j) t[static_cast<std::size_t>(j)] = t[static_cast<std::size_t>(j - 1)] + 1;
  }
  return canonical_simplices(std::move(out), Orientation::orient_d);
}

}  // namespace flipflop::test

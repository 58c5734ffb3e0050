// brute_force.cpp — definition-level enumeration (see brute_force.hpp).
#include "reference/brute_force.hpp"

#include <algorithm>
#include <stdexcept>

#include "predicates/predicates.hpp"
#include "reference/canonical.hpp"

namespace flipflop::brute {

std::vector<Index> hull2(const PointSet& ps) {
  const Index n = static_cast<Index>(ps.size());
  auto P = [&](Index i) { return pred::Pt{i, ps.point(i)}; };
  std::vector<long> next(n, -1);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      if (i == j) continue;
      bool edge = true;
      for (Index k = 0; k < n && edge; ++k)
        if (k != i && k != j && pred::orient2d(P(i), P(j), P(k)) < 0) edge = false;
      if (edge) next[i] = j;
    }
  Index start = 0;
  while (start < n && next[start] < 0) ++start;
  if (start == n) throw std::invalid_argument("brute::hull2 needs at least 2 points");
  std::vector<Index> cycle;
  Index v = start;
  do {
    cycle.push_back(v);
    v = static_cast<Index>(next[v]);
  } while (v != start && cycle.size() <= n);
  return cycle;  // start is the smallest vertex index by construction
}

std::vector<Triangle> hull3(const PointSet& ps) {
  const Index n = static_cast<Index>(ps.size());
  auto P = [&](Index i) { return pred::Pt{i, ps.point(i)}; };
  std::vector<Triangle> out;
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j)
      for (Index k = j + 1; k < n; ++k) {
        int pos = 0, neg = 0;
        for (Index l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          (pred::orient3d(P(i), P(j), P(k), P(l)) > 0 ? pos : neg)++;
          if (pos && neg) break;
        }
        if (neg == 0) out.push_back({i, j, k});       // all others inside: (i,j,k) faces out
        else if (pos == 0) out.push_back({i, k, j});  // opposite orientation
      }
  return canonical_triangles(std::move(out));
}

std::vector<Triangle> rt2(const PointSet& ps) {
  const Index n = static_cast<Index>(ps.size());
  auto W = [&](Index i) { return pred::WPt{i, ps.point(i), ps.weight(i)}; };
  std::vector<Triangle> out;
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j)
      for (Index k = j + 1; k < n; ++k) {
        Triangle t{i, j, k};
        if (pred::orient2d({i, ps.point(i)}, {j, ps.point(j)}, {k, ps.point(k)}) < 0) std::swap(t[1], t[2]);
        bool regular = true;
        for (Index l = 0; l < n && regular; ++l)
          if (l != i && l != j && l != k && pred::power2d(W(t[0]), W(t[1]), W(t[2]), W(l)) > 0) regular = false;
        if (regular) out.push_back(t);
      }
  return canonical_triangles(std::move(out));
}

}  // namespace flipflop::brute

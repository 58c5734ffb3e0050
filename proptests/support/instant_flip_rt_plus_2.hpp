// instant_flip_rt_plus_2.hpp — the "RT+2" triangulation of thesis §9.1,
// Table 9.1: seven points a..g (weights 0) and a kernel point s, built by
// inserting a and g into the regular triangulation of {b, c, d, e, f} plus
// the virtual vertex. Here the virtual vertex is replaced by real vertices far
// away from s, as the thesis suggests ("By replacing the virtual vertex with
// several real vertices far away from s, we can also build a 'RT+2'
// triangulation as counter-example").
//
// Construction, with exact rational heights h = |x|^2 - w:
//   1. RT of {b, c, d, e, f} ∪ far points with weights 0 (the Delaunay
//      triangulation, computed by brute force over all 4-subsets: empty
//      circumsphere, exactly);
//   2. insert a by a 1-4 flip into the tetrahedron containing it; its height is
//      set just below the lifted hyperplane of that tetrahedron, so the result
//      is regular (an "RT+1" triangulation made regular, Rajan [Raj91]);
//   3. the same for g.
// The weights W are then rounded to doubles and the strict convexity of every
// ridge is re-checked exactly with them.
#pragma once

#include <array>
#include <functional>
#include <set>
#include <vector>

#include "instant_flip_oracles.hpp"

namespace flipflop::test_if {

struct RtPlus2 {
  PointSet ps;               // a b c d e f g, then the far points
  std::vector<double> w;     // W: RT+2 is RT(S ⊕ W)
  SimplexSet start;          // the RT+2 triangulation
  std::vector<std::size_t> order_of_insertion;
};

// Table 9.1 (x, y, z), in the order a b c d e f g, and s.
inline const std::array<std::array<double, 3>, 8>& table_9_1() {
  static const std::array<std::array<double, 3>, 8> t = {{{0.666, 0.795, 0.546},
                                                          {0.849, 0.780, 0.419},
                                                          {0.298, 0.546, 0.067},
                                                          {0.589, 0.327, 0.463},
                                                          {0.848, 0.635, 0.556},
                                                          {0.648, 0.653, 0.139},
                                                          {0.397, 0.654, 0.253},
                                                          {0.597, 0.530, 0.264}}};
  return t;
}

// The simplex of T (sorted tuples) strictly containing point p, if any.
inline bool containing(const PointSet& ps, const SimplexSet& T, Index p, Simplex* out) {
  for (const Simplex& s : T) {
    const int o = orient_q(ps, s);
    bool inside = true;
    for (std::size_t i = 0; i < s.size() && inside; ++i) {
      Simplex t = s;
      t[i] = p;
      inside = orient_q(ps, t) == o;
    }
    if (inside) {
      *out = s;
      return true;
    }
  }
  return false;
}

// Height of the hyperplane through the lifted simplex s at point p.
inline mpq_class plane_height(const PointSet& ps, const std::vector<mpq_class>& h, const Simplex& s, Index p) {
  // barycentric coordinates of p in s: λ_i = orient(s with s_i := p) / orient(s)
  const int d = ps.dim, n = d + 1;
  auto det_of = [&](const Simplex& t) {
    std::vector<mpq_class> a(static_cast<std::size_t>(n * n));
    for (int r = 0; r < n; ++r) {
      for (int j = 0; j < d; ++j) a[static_cast<std::size_t>(r * n + j)] = ps.point(t[static_cast<std::size_t>(r)])[j];
      a[static_cast<std::size_t>(r * n + d)] = 1;
    }
    return det_q(a, n);
  };
  const mpq_class total = det_of(s);
  mpq_class height = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    Simplex t = s;
    t[i] = p;
    height += det_of(t) / total * h[s[i]];
  }
  return height;
}

// Delaunay triangulation by brute force: every 4-subset (3D) whose lifted
// hyperplane has all other lifted points strictly above it. Generic input.
inline SimplexSet brute_delaunay(const PointSet& ps, const std::vector<Index>& pts,
                                 const std::vector<mpq_class>& h) {
  SimplexSet T;
  const std::size_t m = pts.size();
  const int d = ps.dim;
  std::vector<std::size_t> idx(static_cast<std::size_t>(d) + 1);
  // enumerate (d+1)-subsets
  std::function<void(std::size_t, std::size_t)> rec = [&](std::size_t from, std::size_t depth) {
    if (depth == idx.size()) {
      Simplex s;
      for (std::size_t i : idx) s.push_back(pts[i]);
      if (orient_q(ps, s) == 0) return;
      for (Index q : pts) {
        if (std::find(s.begin(), s.end(), q) != s.end()) continue;
        if (!(h[q] > plane_height(ps, h, s, q))) return;
      }
      T.insert(sorted(s));
      return;
    }
    for (std::size_t i = from; i < m; ++i) {
      idx[depth] = i;
      rec(i + 1, depth + 1);
    }
  };
  rec(0, 0);
  return T;
}

// first, second: the inserted points (0 = a, 6 = g); far: far point count
// (4: a regular tetrahedron, 8: a cube) at distance R from s.
inline RtPlus2 make_rt_plus_2(std::size_t first, std::size_t second, int far, double R) {
  RtPlus2 r;
  r.ps.dim = 3;
  r.ps.weighted = true;
  const auto& t = table_9_1();
  for (std::size_t i = 0; i < 7; ++i) r.ps.coords.insert(r.ps.coords.end(), t[i].begin(), t[i].end());
  const auto& s = t[7];
  std::vector<std::array<double, 3>> dirs;
  if (far == 4)
    dirs = {{{1, 1, 1}}, {{1, -1, -1}}, {{-1, 1, -1}}, {{-1, -1, 1}}};
  else
    for (int x = -1; x <= 1; x += 2)
      for (int y = -1; y <= 1; y += 2)
        for (int z = -1; z <= 1; z += 2) dirs.push_back({{double(x), double(y), double(z)}});
  for (std::size_t i = 0; i < dirs.size(); ++i)  // slightly irregular: general position
    for (int j = 0; j < 3; ++j)
      r.ps.coords.push_back(s[static_cast<std::size_t>(j)] + R * dirs[i][static_cast<std::size_t>(j)] * (1.0 + 0.01 * double(i + 1) * double(j + 1)));
  const std::size_t n = r.ps.size();
  r.ps.weights.assign(n, 0.0);

  std::vector<mpq_class> h = heights_q(r.ps, std::vector<mpq_class>(n, mpq_class(0)));
  std::vector<Index> base;
  for (Index p = 0; p < n; ++p)
    if (p != first && p != second) base.push_back(p);
  r.start = brute_delaunay(r.ps, base, h);
  for (std::size_t p : {first, second}) {
    Simplex s;
    if (!containing(r.ps, r.start, static_cast<Index>(p), &s)) throw std::logic_error("RT+2: point outside");
    // lifted point just below the lifted simplex: the 1-4 flip keeps it regular
    h[p] = plane_height(r.ps, h, s, static_cast<Index>(p)) - mpq_class(1, 1000000);
    r.start.erase(s);
    for (std::size_t i = 0; i < s.size(); ++i) {
      Simplex t = s;
      t[i] = static_cast<Index>(p);
      r.start.insert(sorted(t));
    }
    r.order_of_insertion.push_back(p);
  }
  // W = |x|^2 - h, rounded to doubles
  r.w.assign(n, 0.0);
  for (Index p = 0; p < n; ++p) {
    mpq_class sq = 0;
    for (int j = 0; j < 3; ++j) sq += mpq_class(r.ps.point(p)[j]) * mpq_class(r.ps.point(p)[j]);
    r.w[p] = mpq_class(sq - h[p]).get_d();
  }
  return r;
}

// Locally non-regular ridges of T for heights h (reflex: convexity < 0).
inline std::vector<Ridge> non_regular(const PointSet& ps, const std::vector<mpq_class>& h, const SimplexSet& T) {
  std::vector<Ridge> out;
  for (const Ridge& r : ridges_of(T))
    if (ridge_convexity_q(ps, h, r.v, r.a, r.b) < 0) out.push_back(r);
  return out;
}

// Exhaustive monotonic flipping (thesis §9.1, Figure 9.2(b)): from `start`,
// every sequence of flips of locally non-regular, flippable ridges. Returns
// the terminals: triangulations with no such ridge, split into regular ones
// (no non-regular ridge at all) and stuck ones.
struct FlipGraph {
  std::size_t nodes = 0, arcs = 0;
  std::set<SimplexSet> seen;  // every triangulation reached
  std::vector<SimplexSet> regular, stuck;
};

inline FlipGraph monotonic_flip_graph(const PointSet& ps, const std::vector<mpq_class>& h,
                                      const SimplexSet& start, std::size_t limit = 100000) {
  FlipGraph g;
  std::set<SimplexSet> seen{start};
  std::vector<SimplexSet> todo{start};
  while (!todo.empty()) {
    const SimplexSet T = std::move(todo.back());
    todo.pop_back();
    ++g.nodes;
    if (g.nodes > limit) throw std::logic_error("flip graph too large");
    const std::vector<Ridge> bad = non_regular(ps, h, T);
    bool moved = false;
    for (const Ridge& r : bad) {
      SimplexSet next;
      if (!radon_flip(ps, T, r, &next)) continue;
      moved = true;
      ++g.arcs;
      if (seen.insert(next).second) todo.push_back(std::move(next));
    }
    if (!moved) (bad.empty() ? g.regular : g.stuck).push_back(T);
  }
  g.seen = std::move(seen);
  return g;
}

}  // namespace flipflop::test_if

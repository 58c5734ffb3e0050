// instant_flip_oracles.hpp — independent oracles for the instant-flip tests
// (thesis ch. 9): exact rational lifted determinants by plain Gaussian
// elimination (not the minors of failure_time.cpp), ridge enumeration and
// bistellar flips on plain simplex sets via Radon partitions (not
// bistellar_flip.cpp), and point/weight generators.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test_if {

using Simplex = std::vector<Index>;          // sorted vertex indices
using SimplexSet = std::set<Simplex>;

inline Simplex sorted(Simplex s) {
  std::sort(s.begin(), s.end());
  return s;
}

inline SimplexSet to_set(const std::vector<std::vector<Index>>& list) {
  SimplexSet out;
  for (const auto& s : list) out.insert(sorted(s));
  return out;
}

// Determinant of a square mpq matrix (row-major), Gaussian elimination.
inline mpq_class det_q(std::vector<mpq_class> a, int n) {
  mpq_class det = 1;
  for (int c = 0; c < n; ++c) {
    int p = c;
    while (p < n && a[static_cast<std::size_t>(p * n + c)] == 0) ++p;
    if (p == n) return 0;
    if (p != c) {
      for (int j = 0; j < n; ++j) std::swap(a[static_cast<std::size_t>(p * n + j)], a[static_cast<std::size_t>(c * n + j)]);
      det = -det;
    }
    const mpq_class piv = a[static_cast<std::size_t>(c * n + c)];
    det *= piv;
    for (int r = c + 1; r < n; ++r) {
      const mpq_class f = a[static_cast<std::size_t>(r * n + c)] / piv;
      if (f == 0) continue;
      for (int j = c; j < n; ++j) a[static_cast<std::size_t>(r * n + j)] -= f * a[static_cast<std::size_t>(c * n + j)];
    }
  }
  return det;
}

inline int sgn_q(const mpq_class& x) { return sgn(x); }

// Orientation of d+1 points (rows [x 1]) of ps, exactly (may be 0).
inline int orient_q(const PointSet& ps, const std::vector<Index>& pts) {
  const int d = ps.dim, n = d + 1;
  std::vector<mpq_class> a(static_cast<std::size_t>(n * n));
  for (int r = 0; r < n; ++r) {
    for (int j = 0; j < d; ++j) a[static_cast<std::size_t>(r * n + j)] = ps.point(pts[static_cast<std::size_t>(r)])[j];
    a[static_cast<std::size_t>(r * n + d)] = 1;
  }
  return sgn(det_q(a, n));
}

// Heights h_p = |p|^2 - w_p as exact rationals.
inline std::vector<mpq_class> heights_q(const PointSet& ps, const std::vector<mpq_class>& w) {
  std::vector<mpq_class> h(ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p) {
    mpq_class s = 0;
    for (int j = 0; j < ps.dim; ++j) {
      const mpq_class x = ps.point(p)[j];
      s += x * x;
    }
    h[p] = s - w[p];
  }
  return h;
}

inline std::vector<mpq_class> to_q(const std::vector<double>& v) {
  return std::vector<mpq_class>(v.begin(), v.end());
}

// Is the ridge `ridge` (d vertices) with link a (in C1 = ridge + a) and b
// convex (+1: b's lifted point above the hyperplane of lifted C1), flat (0)
// or reflex (-1) for the heights h?
inline int ridge_convexity_q(const PointSet& ps, const std::vector<mpq_class>& h,
                             const std::vector<Index>& ridge, Index a, Index b) {
  const int d = ps.dim, n = d + 2;
  std::vector<Index> rows(ridge);
  rows.push_back(a);
  rows.push_back(b);
  std::vector<mpq_class> m(static_cast<std::size_t>(n * n));
  for (int r = 0; r < n; ++r) {
    const Index p = rows[static_cast<std::size_t>(r)];
    for (int j = 0; j < d; ++j) m[static_cast<std::size_t>(r * n + j)] = ps.point(p)[j];
    m[static_cast<std::size_t>(r * n + d)] = h[p];
    m[static_cast<std::size_t>(r * n + d + 1)] = 1;
  }
  std::vector<Index> c1(ridge);
  c1.push_back(a);
  const int o = orient_q(ps, c1);
  if (o == 0) throw std::logic_error("oracle: flat simplex");
  // det > 0 with C1 positive means b below (predicates.hpp convention)
  return -o * sgn(det_q(m, n));
}

struct Ridge {
  std::vector<Index> v;  // sorted
  Index a, b;
};

// Interior ridges of a simplex set (each facet shared by two simplices).
inline std::vector<Ridge> ridges_of(const SimplexSet& T) {
  std::map<std::vector<Index>, std::vector<Index>> opp;
  for (const Simplex& s : T)
    for (std::size_t i = 0; i < s.size(); ++i) {
      Simplex f = s;
      f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
      opp[f].push_back(s[i]);
    }
  std::vector<Ridge> out;
  for (auto& [f, o] : opp) {
    if (o.size() > 2) throw std::logic_error("oracle: not a triangulation");
    if (o.size() == 2) out.push_back({f, o[0], o[1]});
  }
  return out;
}

// Every interior ridge convex (>= 0 when `allow_flat`) for heights h?
inline bool all_convex_q(const PointSet& ps, const std::vector<mpq_class>& h, const SimplexSet& T,
                         bool allow_flat = false) {
  for (const Ridge& r : ridges_of(T)) {
    const int c = ridge_convexity_q(ps, h, r.v, r.a, r.b);
    if (c < 0 || (c == 0 && !allow_flat)) return false;
  }
  return true;
}

// The bistellar flip on ridge r of T (thesis §2.3) by the Radon partition of
// S = r.v + {a, b}: λ_i = (-1)^i orient(S \ i); the two triangulations of S
// are {S \ i : λ_i > 0} and {S \ i : λ_i < 0}. The ridge is flippable when
// the side holding S \ a and S \ b lies entirely in T; the flip swaps sides.
// Returns false when not flippable. Points must be in general position.
inline bool radon_flip(const PointSet& ps, const SimplexSet& T, const Ridge& r, SimplexSet* out,
                       int* k = nullptr) {
  Simplex S = r.v;
  S.push_back(r.a);
  S.push_back(r.b);
  S = sorted(S);
  std::vector<int> lambda(S.size());
  for (std::size_t i = 0; i < S.size(); ++i) {
    Simplex f = S;
    f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
    const int o = orient_q(ps, f);
    lambda[i] = (i % 2 == 0) ? o : -o;
  }
  const auto ia = static_cast<std::size_t>(std::find(S.begin(), S.end(), r.a) - S.begin());
  const int side = lambda[ia];
  if (side == 0) return false;
  std::vector<Simplex> cur, nxt;
  for (std::size_t i = 0; i < S.size(); ++i) {
    if (lambda[i] == 0) continue;  // S \ i is flat: not a simplex of either side
    Simplex f = S;
    f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
    (lambda[i] == side ? cur : nxt).push_back(f);
  }
  for (const Simplex& s : cur)
    if (!T.count(s)) return false;
  if (out) {
    *out = T;
    for (const Simplex& s : cur) out->erase(s);
    for (const Simplex& s : nxt) out->insert(s);
  }
  if (k) *k = static_cast<int>(cur.size());
  return true;
}

// Random points in the unit cube of R^d (generic doubles).
inline PointSet random_points(int d, std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  PointSet ps;
  ps.dim = d;
  ps.weighted = true;
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(d); ++i) ps.coords.push_back(U(rng));
  ps.weights.assign(n, 0.0);
  return ps;
}

inline std::vector<double> random_weights(std::size_t n, double hi, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, hi);
  std::vector<double> w(n);
  for (double& x : w) x = hi > 0 ? U(rng) : 0.0;
  return w;
}

inline PointSet with_weights(PointSet ps, const std::vector<double>& w) {
  ps.weighted = true;
  ps.weights = w;
  return ps;
}

}  // namespace flipflop::test_if

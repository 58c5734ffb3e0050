// sos_brute.hpp — canonical hulls and regular triangulations of small inputs
// by their definition, decided ONLY by the independent SoS oracle of
// sos_oracle.hpp (no code of predicates/, reference/ or canonical*.hpp).
//
// The definitions (DESIGN.md "The perturbation, precisely", "Canonical
// output"; README "Simulation of Simplicity"): point i has SoS id i (its input
// index, PointSet's comment); under the perturbation the input is in general
// position, so
//   hull2: (a, b) is a hull edge iff every other point is strictly left of
//          a->b; the answer is the counter-clockwise vertex cycle from the
//          smallest index;
//   hull3: {a, b, c} is a hull facet iff every other point is strictly on one
//          side; it is written counter-clockwise seen from outside;
//   rt (d = 2..9, weights 0 for Delaunay): the projection of the lower hull of
//          the lifted points (x, |x|² - w), the height perturbed as an
//          independent coordinate: a (d+1)-subset is a simplex iff every
//          other lifted point is strictly above its hyperplane; only finite
//          simplices are output (the triangulation covers conv(S)); points
//          in no simplex are redundant.
// Signs from Λ (rows: point, 1-column last; sos_oracle.hpp), derived here:
//   det Λ[p_0..p_d] = (-1)^d det[p_1 - p_0, ..., p_d - p_0] (subtract row 0,
//     expand along the 1-column), so "positive volume" = (-1)^d sign Λ;
//   hull2 (d = 2): q strictly left of a->b  <=>  sign Λ[a, b, q] > 0;
//   hull3 (d = 3): q strictly inside (behind the ccw-from-outside (a,b,c))
//     <=> det[b-a, c-a, q-a] < 0  <=>  sign Λ[a, b, c, q] > 0;
//   power (lifted rows, height column d, 1-column d+1; q the last row): the
//     entry (q, height) has cofactor -Λ_orient[p_0..p_d], so
//     det = -Λ_orient·(h_q - H(x_q)), H the lifted hyperplane of the p_i:
//     for a volume-positive tuple, q strictly above <=> sign = (-1)^(d+1).
// These are identities of polynomials in ε, so they hold for the SoS signs.
// Canonical form (DESIGN.md): each simplex positively oriented, smallest
// index first; 2D/3D triangles rotated, d-simplices "smallest first, the rest
// ascending, the last two swapped if that is an odd permutation" (the same
// thing for triangles); lines sorted. Written here from that text.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "proptests/support/sos_oracle.hpp"

namespace flipflop::test::sos_brute {

namespace so = flipflop::test::sos_oracle;

// A small input: n points of dimension d (point-major), weights (0 when
// unweighted).
struct Input {
  int d = 2;
  std::vector<double> x;
  std::vector<double> w;
  int n() const { return static_cast<int>(x.size()) / d; }
  const double* p(int i) const { return x.data() + static_cast<size_t>(i) * static_cast<size_t>(d); }
};

using Tuple = std::vector<std::uint32_t>;

// Orientation sign Λ of the points `idx` (coordinates only).
inline int orient(const Input& in, const Tuple& idx) {
  std::vector<so::QRow> rows;
  std::vector<so::Id> ids;
  for (auto i : idx) {
    rows.push_back(so::coords_row(in.p(static_cast<int>(i)), in.d));
    ids.push_back(i);
  }
  return so::sos_sign(rows, ids).sign;
}

// Power sign Λ of the lifted points `idx` (the tested point last).
inline int power(const Input& in, const Tuple& idx) {
  std::vector<so::QRow> rows;
  std::vector<so::Id> ids;
  for (auto i : idx) {
    rows.push_back(so::lifted_row(in.p(static_cast<int>(i)), in.d, in.w[i]));
    ids.push_back(i);
  }
  return so::sos_sign(rows, ids).sign;
}

// Exact affine dimension of the input (rank of p_i - p_0), no perturbation.
inline int affine_rank(const Input& in) {
  const int n = in.n(), d = in.d;
  if (n == 0) return -1;
  std::vector<std::vector<mpq_class>> m;
  for (int i = 1; i < n; ++i) {
    std::vector<mpq_class> r;
    for (int j = 0; j < d; ++j) r.push_back(so::exact(in.p(i)[j]) - so::exact(in.p(0)[j]));
    m.push_back(r);
  }
  int rank = 0;
  for (int c = 0; c < d && rank < static_cast<int>(m.size()); ++c) {
    int piv = rank;
    while (piv < static_cast<int>(m.size()) && m[static_cast<size_t>(piv)][static_cast<size_t>(c)] == 0) ++piv;
    if (piv == static_cast<int>(m.size())) continue;
    std::swap(m[static_cast<size_t>(piv)], m[static_cast<size_t>(rank)]);
    for (size_t i = static_cast<size_t>(rank) + 1; i < m.size(); ++i) {
      const mpq_class f = m[i][static_cast<size_t>(c)] / m[static_cast<size_t>(rank)][static_cast<size_t>(c)];
      for (int j = c; j < d; ++j) m[i][static_cast<size_t>(j)] -= f * m[static_cast<size_t>(rank)][static_cast<size_t>(j)];
    }
    ++rank;
  }
  return rank;
}
inline bool spans(const Input& in) { return in.n() >= in.d + 1 && affine_rank(in) == in.d; }

// ---- canonical form (DESIGN.md "Canonical output"), written from the text -------------
inline bool odd_permutation(const Tuple& t) {
  bool odd = false;
  for (size_t i = 0; i < t.size(); ++i)
    for (size_t j = i + 1; j < t.size(); ++j)
      if (t[j] < t[i]) odd = !odd;  // inversions
  return odd;
}
// A positively oriented (volume) tuple -> its canonical tuple.
inline Tuple canonical(Tuple t) {
  const bool odd = odd_permutation(t);
  std::sort(t.begin(), t.end());
  if (odd) std::swap(t[t.size() - 1], t[t.size() - 2]);
  return t;
}
inline std::string text(const std::vector<Tuple>& simplices) {
  std::ostringstream o;
  for (const Tuple& t : simplices) {
    for (size_t i = 0; i < t.size(); ++i) o << (i ? " " : "") << t[i];
    o << '\n';
  }
  return o.str();
}
inline std::string cycle_text(const Tuple& c) {
  std::ostringstream o;
  for (auto v : c) o << v << '\n';
  return o.str();
}

// Next combination of k out of n (t increasing); false after the last.
inline bool next_combination(Tuple& t, std::uint32_t n) {
  const int k = static_cast<int>(t.size());
  int i = k - 1;
  while (i >= 0 && t[static_cast<size_t>(i)] == n - static_cast<std::uint32_t>(k - i)) --i;
  if (i < 0) return false;
  ++t[static_cast<size_t>(i)];
  for (int j = i + 1; j < k; ++j) t[static_cast<size_t>(j)] = t[static_cast<size_t>(j - 1)] + 1;
  return true;
}

// ---- hull2 -------------------------------------------------------------------------------
// The ccw cycle from the smallest index. Throws std::logic_error if the kept
// edges are not one cycle (impossible in general position: an oracle bug).
inline Tuple hull2(const Input& in) {
  const auto n = static_cast<std::uint32_t>(in.n());
  std::vector<std::int64_t> next(n, -1);
  std::size_t edges = 0;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = 0; b < n; ++b) {
      if (a == b) continue;
      bool edge = true;
      for (std::uint32_t q = 0; q < n && edge; ++q)
        if (q != a && q != b) edge = orient(in, {a, b, q}) > 0;
      if (edge) {
        if (next[a] >= 0) throw std::logic_error("sos_brute::hull2: two edges leave one vertex");
        next[a] = b;
        ++edges;
      }
    }
  Tuple cyc;
  std::uint32_t start = 0;
  while (start < n && next[start] < 0) ++start;
  if (start == n) throw std::logic_error("sos_brute::hull2: no edge");
  std::uint32_t v = start;
  do {
    cyc.push_back(v);
    if (next[v] < 0 || cyc.size() > n) throw std::logic_error("sos_brute::hull2: the edges are not a cycle");
    v = static_cast<std::uint32_t>(next[v]);
  } while (v != start);
  if (cyc.size() != edges) throw std::logic_error("sos_brute::hull2: more than one cycle");
  return cyc;  // starts at the smallest vertex: `start` is the smallest with an edge
}

// ---- hull3 -------------------------------------------------------------------------------
inline std::vector<Tuple> hull3(const Input& in) {
  const auto n = static_cast<std::uint32_t>(in.n());
  std::vector<Tuple> out;
  Tuple t{0, 1, 2};
  do {
    int side = 0;
    bool facet = true;
    for (std::uint32_t q = 0; q < n && facet; ++q) {
      if (q == t[0] || q == t[1] || q == t[2]) continue;
      const int s = orient(in, {t[0], t[1], t[2], q});
      if (side == 0) side = s;
      facet = s == side;
    }
    if (facet) {
      // all others with Λ > 0 are inside: (t0, t1, t2) is ccw from outside
      Tuple f = side > 0 ? t : Tuple{t[0], t[2], t[1]};
      out.push_back(canonical(f));
    }
  } while (next_combination(t, n));
  std::sort(out.begin(), out.end());
  return out;
}

// ---- regular triangulation, d = 2..9 ------------------------------------------------------
struct Rt {
  std::vector<Tuple> simplices;  // canonical
  Tuple redundant;               // sorted
};

// furthest: the furthest-site triangulation, the upper hull of the same
// perturbed lifted points — every other lifted point strictly BELOW the
// simplex's lifted hyperplane.
inline Rt rt(const Input& in, bool furthest = false) {
  const int d = in.d;
  const auto n = static_cast<std::uint32_t>(in.n());
  const int above = (d % 2 == 1) ? 1 : -1;  // (-1)^(d+1)
  const int vol_from_lambda = (d % 2 == 0) ? 1 : -1;  // (-1)^d
  Rt r;
  Tuple t(static_cast<size_t>(d + 1));
  for (int i = 0; i <= d; ++i) t[static_cast<size_t>(i)] = static_cast<std::uint32_t>(i);
  std::vector<char> vertex(n, 0);
  do {
    Tuple pos = t;
    if (vol_from_lambda * orient(in, t) < 0) std::swap(pos[0], pos[1]);
    bool lower = true;
    Tuple rows = pos;
    rows.push_back(0);
    for (std::uint32_t q = 0; q < n && lower; ++q) {
      if (std::find(t.begin(), t.end(), q) != t.end()) continue;
      rows.back() = q;
      lower = power(in, rows) == (furthest ? -above : above);
    }
    if (lower) {
      r.simplices.push_back(canonical(pos));
      for (auto v : t) vertex[v] = 1;
    }
  } while (next_combination(t, n));
  std::sort(r.simplices.begin(), r.simplices.end());
  for (std::uint32_t i = 0; i < n; ++i)
    if (!vertex[i]) r.redundant.push_back(i);
  return r;
}

}  // namespace flipflop::test::sos_brute

// sos_oracle.hpp — an independent oracle for the Simulation-of-Simplicity signs
// of predicates/ (DESIGN.md "The perturbation, precisely", README "Simulation
// of Simplicity", the header comment of predicates/predicates.hpp). It uses no
// code of predicates/: GMP arithmetic on the definition alone.
//
// Sources of the definition: DESIGN.md (c(i,j) + ε^(2^(i·δ - j)), i = index + 1,
// the lifted height perturbed as an independent coordinate), README.md
// "Simulation of Simplicity", predicates.hpp's header comment (Λ's rows and
// the 1-column last, "rows in any order") and its comment on power_d_pulled.
//
// The definition it implements. A predicate on k points is the sign of the
// k x k matrix Λ whose row r is point r (in argument order): its m
// non-constant columns, then a constant 1. For orientation tests the columns
// are the d coordinates (m = d); for power tests they are the d coordinates and
// the lifted height h = |x|² - w (m = d + 1, the height last). Point r with id
// i_r is perturbed as
//
//     Λ[r][c] + ε^(2^(pos(r, c))),   pos(r, c) = (i_r + 1)·δ - (c + 1),   c = 0..m-1,
//
// δ = m (the column number j = c + 1 of the definition; only the order of the
// positions matters, see below). The 1-column is not perturbed, the height is
// perturbed as an independent column (not recomputed from perturbed x).
//
// Evaluation. det Λ(ε) is multilinear in the entries, so
//     det Λ(ε) = Σ_T coef_T · ε^(E_T),   E_T = Σ_{(r,c) ∈ T} 2^(pos(r, c)),
// over the partial matchings T (perturbed entries, at most one per row and per
// column). coef_T is the mixed partial derivative of det by the entries of T:
// in det = Σ_σ sgn σ Π_r Λ[r][σ(r)] the permutations with σ(r) = c on T give
// sgn(σ_T) · det Λ[kept rows, kept columns], σ_T the permutation that sends
// the rows of T to their columns and the kept rows, in increasing order, to
// the kept columns in increasing order (every other σ is σ_T followed by a
// permutation of the kept columns, whose sign is the minor's). Distinct
// positions give distinct powers of two, so distinct T have distinct E_T, and
// the sign for every small enough ε > 0 is the sign of coef_T for the T of
// least E_T with coef_T != 0.
//
// Order of the exponents. E_T is a sum of distinct powers of two; two such
// sums compare as binary numbers, by the highest position in which they
// differ. That comparison only needs the order of the positions, so each
// entry (r, c) is given rank(r, c) = its place among all k·m positions, sorted
// (computed exactly in 128-bit integers: ids up to 2^64 - 1), and the
// matchings are visited in increasing order of Σ_{T} 2^rank by the recursion
//     visit(t, S): first visit(t-1, S), then, if entry t-1 fits S,
//                  visit(t-1, S ∪ {entry t-1})
// (every set without entry t-1 has a smaller key than every set with it). The
// first matching whose minor is non-zero decides. This is the definition
// evaluated term by term; it does not use the library's dominance order
// (rows by id, "not perturbed" first).
//
// Minors: the matrix is made integral column by column (each column times
// the largest power-of-two denominator in it: a positive factor per column,
// which keeps every minor's sign), then fraction-free Gaussian elimination
// (Bareiss) in mpz, memoised by (kept rows, kept columns).
//
// power_d_pulled (predicates.hpp): the heights are not perturbed with the
// coordinates; h_i becomes h_i + ε1 |x_i|² - ε2^(r_i) (|x_i|² of the exact
// coordinates, r_i = 1 + rank of the id among the k ids: the smallest id is
// pulled most), ε1 >> ε2 >> every coordinate perturbation ε. A term is then
// ε1^a ε2^b ε^E with the coordinate matching T giving E; ε is infinitely
// smaller than any monomial in ε1, ε2, so E decides first (matchings over the
// coordinate columns in increasing order as above); for one T the minor with
// the height column is linear in it: M(h) + ε1 M(|x|²) - Σ_i ε2^(r_i) C_i,
// C_i the signed cofactor of row i's height entry in that minor, ordered
// ε^0 (M(h)), then ε1, then ε2^1, ε2^2, ... (smallest id first).
//
// Repeated ids: two rows with the same id and the same entries are the same
// perturbed point, the determinant is identically 0; the oracle returns 0.
// Same id with different entries is outside the definition (it throws).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace flipflop::test::sos_oracle {

using Id = std::uint64_t;
using QRow = std::vector<mpq_class>;  // the m non-constant entries of one row

// ---- building rows from doubles ---------------------------------------------------
inline mpq_class exact(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("sos_oracle: non-finite value");
  mpq_class q;
  mpq_set_d(q.get_mpq_t(), v);  // exact: every finite double is a dyadic rational
  return q;
}

// Coordinates only (orientation tests).
inline QRow coords_row(const double* x, int d) {
  QRow r;
  for (int j = 0; j < d; ++j) r.push_back(exact(x[j]));
  return r;
}

// |x|² exactly.
inline mpq_class norm2(const double* x, int d) {
  mpq_class s = 0;
  for (int j = 0; j < d; ++j) {
    const mpq_class v = exact(x[j]);
    s += v * v;
  }
  return s;
}

// Coordinates, then the lifted height |x|² - w (power tests).
inline QRow lifted_row(const double* x, int d, double w) {
  QRow r = coords_row(x, d);
  r.push_back(norm2(x, d) - exact(w));
  return r;
}

// ---- the result -----------------------------------------------------------------------
struct Result {
  int sign = 0;
  // the deciding term: for each row the perturbed column (-1: none); for the
  // pulled variant `extra` says which height term decided: 0 the exact
  // heights, 1 the ε1 term, 2 + r a pull of row r.
  std::vector<int> matched;
  int extra = 0;
  int size() const {
    int n = 0;
    for (int c : matched) n += c >= 0;
    return n;
  }
};

namespace detail {

using ZMatrix = std::vector<std::vector<mpz_class>>;

inline int sgn_of(const mpz_class& z) { return mpz_sgn(z.get_mpz_t()); }

// Λ (k rows: the m entries, then 1) as integers, column by column scaled by
// a positive power of two.
inline ZMatrix integral(const std::vector<QRow>& rows, int m) {
  const int k = static_cast<int>(rows.size());
  ZMatrix a(static_cast<size_t>(k), std::vector<mpz_class>(static_cast<size_t>(m + 1)));
  for (int c = 0; c < m; ++c) {
    mpz_class den = 1;
    for (int r = 0; r < k; ++r) {
      const mpz_class& q = rows[static_cast<size_t>(r)][static_cast<size_t>(c)].get_den();
      if (q > den) den = q;  // all denominators are powers of two: the largest is the lcm
    }
    for (int r = 0; r < k; ++r) {
      const mpq_class v = rows[static_cast<size_t>(r)][static_cast<size_t>(c)] * den;
      if (v.get_den() != 1) throw std::logic_error("sos_oracle: non-dyadic entry");
      a[static_cast<size_t>(r)][static_cast<size_t>(c)] = v.get_num();
    }
  }
  for (int r = 0; r < k; ++r) a[static_cast<size_t>(r)][static_cast<size_t>(m)] = 1;
  return a;
}

// Sign of the minor on the rows / columns in the masks (equal counts), Bareiss.
inline int minor_sign(const ZMatrix& a, unsigned rows, unsigned cols) {
  std::vector<int> rs, cs;
  for (int i = 0; i < 32; ++i) {
    if (rows & (1u << i)) rs.push_back(i);
    if (cols & (1u << i)) cs.push_back(i);
  }
  const int n = static_cast<int>(rs.size());
  if (n != static_cast<int>(cs.size())) throw std::logic_error("sos_oracle: non-square minor");
  if (n == 0) return 1;
  ZMatrix b(static_cast<size_t>(n), std::vector<mpz_class>(static_cast<size_t>(n)));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      b[static_cast<size_t>(i)][static_cast<size_t>(j)] =
          a[static_cast<size_t>(rs[static_cast<size_t>(i)])][static_cast<size_t>(cs[static_cast<size_t>(j)])];
  int sgn = 1;
  mpz_class prev = 1;
  for (int p = 0; p < n; ++p) {
    int piv = p;
    while (piv < n && b[static_cast<size_t>(piv)][static_cast<size_t>(p)] == 0) ++piv;
    if (piv == n) return 0;
    if (piv != p) {
      std::swap(b[static_cast<size_t>(piv)], b[static_cast<size_t>(p)]);
      sgn = -sgn;
    }
    for (int i = p + 1; i < n; ++i) {
      for (int j = p + 1; j < n; ++j) {
        mpz_class& e = b[static_cast<size_t>(i)][static_cast<size_t>(j)];
        e = e * b[static_cast<size_t>(p)][static_cast<size_t>(p)] -
            b[static_cast<size_t>(i)][static_cast<size_t>(p)] * b[static_cast<size_t>(p)][static_cast<size_t>(j)];
        mpz_divexact(e.get_mpz_t(), e.get_mpz_t(), prev.get_mpz_t());
      }
    }
    prev = b[static_cast<size_t>(p)][static_cast<size_t>(p)];
  }
  return sgn * sgn_of(b[static_cast<size_t>(n - 1)][static_cast<size_t>(n - 1)]);
}

// sgn σ_T: rows of T to their columns, kept rows (increasing) to kept columns
// (increasing); `matched[r]` = column of row r or -1; n = matrix size.
inline int matching_sign(const std::vector<int>& matched, int n) {
  std::vector<int> sigma(static_cast<size_t>(n));
  std::vector<bool> used(static_cast<size_t>(n), false);
  for (int r = 0; r < n; ++r)
    if (matched[static_cast<size_t>(r)] >= 0) used[static_cast<size_t>(matched[static_cast<size_t>(r)])] = true;
  int next = 0;
  for (int r = 0; r < n; ++r) {
    if (matched[static_cast<size_t>(r)] >= 0) {
      sigma[static_cast<size_t>(r)] = matched[static_cast<size_t>(r)];
    } else {
      while (used[static_cast<size_t>(next)]) ++next;
      sigma[static_cast<size_t>(r)] = next++;
    }
  }
  int s = 1;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (sigma[static_cast<size_t>(i)] > sigma[static_cast<size_t>(j)]) s = -s;
  return s;
}

// Entries (row, column) of the perturbed columns sorted by position,
// ascending: entry t has rank t.
struct Entry {
  int row, col;
};
inline std::vector<Entry> entries_by_rank(const std::vector<Id>& ids, int m) {
  std::vector<std::pair<unsigned __int128, Entry>> v;
  const int k = static_cast<int>(ids.size());
  for (int r = 0; r < k; ++r)
    for (int c = 0; c < m; ++c) {
      const unsigned __int128 pos =
          (static_cast<unsigned __int128>(ids[static_cast<size_t>(r)]) + 1) * static_cast<unsigned>(m) -
          static_cast<unsigned>(c + 1);
      v.push_back({pos, Entry{r, c}});
    }
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t t = 1; t < v.size(); ++t)
    if (v[t].first == v[t - 1].first) throw std::logic_error("sos_oracle: equal positions (repeated id)");
  std::vector<Entry> out;
  for (const auto& e : v) out.push_back(e.second);
  return out;
}

// Visit the matchings over `ent` in increasing order of their exponent;
// `leaf(rows_used, cols_used, matched)` returns true to stop.
template <class Leaf>
bool visit(const std::vector<Entry>& ent, int t, unsigned rows_used, unsigned cols_used,
           std::vector<int>& matched, Leaf& leaf) {
  // skip the entries that cannot join (their row or column is taken)
  while (t > 0 && ((rows_used >> ent[static_cast<size_t>(t - 1)].row) & 1u ||
                   (cols_used >> ent[static_cast<size_t>(t - 1)].col) & 1u))
    --t;
  if (t == 0) return leaf(rows_used, cols_used, matched);
  if (visit(ent, t - 1, rows_used, cols_used, matched, leaf)) return true;
  const Entry e = ent[static_cast<size_t>(t - 1)];
  matched[static_cast<size_t>(e.row)] = e.col;
  const bool stop = visit(ent, t - 1, rows_used | (1u << e.row), cols_used | (1u << e.col), matched, leaf);
  matched[static_cast<size_t>(e.row)] = -1;
  return stop;
}

// Repeated ids: 0 when the rows with equal ids are equal, else throw.
inline bool repeated(const std::vector<QRow>& rows, const std::vector<Id>& ids) {
  bool rep = false;
  for (size_t a = 0; a < ids.size(); ++a)
    for (size_t b = a + 1; b < ids.size(); ++b)
      if (ids[a] == ids[b]) {
        if (rows[a] != rows[b]) throw std::invalid_argument("sos_oracle: one id, two different points");
        rep = true;
      }
  return rep;
}

}  // namespace detail

// The SoS sign of Λ with rows `rows` (each m entries, all perturbed; the
// constant 1-column appended), row r keyed by ids[r]. k = rows.size() = m + 1.
inline Result sos_sign(const std::vector<QRow>& rows, const std::vector<Id>& ids) {
  using namespace detail;
  const int k = static_cast<int>(rows.size());
  if (k < 1 || k > 11 || ids.size() != rows.size()) throw std::invalid_argument("sos_oracle: bad size");
  const int m = k - 1;
  for (const QRow& r : rows)
    if (static_cast<int>(r.size()) != m) throw std::invalid_argument("sos_oracle: rows need k-1 entries");
  Result res;
  res.matched.assign(static_cast<size_t>(k), -1);
  if (repeated(rows, ids)) return res;
  const ZMatrix a = integral(rows, m);
  const std::vector<Entry> ent = entries_by_rank(ids, m);
  std::vector<signed char> memo(static_cast<size_t>(1) << (2 * k), 2);
  const unsigned all = (1u << k) - 1u;
  std::vector<int> matched(static_cast<size_t>(k), -1);
  auto leaf = [&](unsigned ru, unsigned cu, const std::vector<int>& mt) {
    const unsigned kr = all & ~ru, kc = all & ~cu;
    signed char& slot = memo[(static_cast<size_t>(kr) << k) | kc];
    if (slot == 2) slot = static_cast<signed char>(minor_sign(a, kr, kc));
    if (slot == 0) return false;
    res.sign = matching_sign(mt, k) * slot;
    res.matched = mt;
    return true;
  };
  if (!visit(ent, static_cast<int>(ent.size()), 0u, 0u, matched, leaf))
    throw std::logic_error("sos_oracle: every term vanished (impossible for a Λ-matrix)");
  return res;
}

// power_d_pulled: rows of d coordinates (`coords[r]`), the exact heights
// h_r = |x_r|² - w_r and q_r = |x_r|²; k = d + 2 rows.
inline Result pulled_sign(const std::vector<QRow>& coords, const std::vector<mpq_class>& h,
                          const std::vector<mpq_class>& q, const std::vector<Id>& ids) {
  using namespace detail;
  const int k = static_cast<int>(coords.size());
  const int d = k - 2;
  if (k < 3 || k > 11 || h.size() != coords.size() || q.size() != coords.size() || ids.size() != coords.size())
    throw std::invalid_argument("sos_oracle: bad size");
  std::vector<QRow> rh = coords, rq = coords;
  for (int r = 0; r < k; ++r) {
    rh[static_cast<size_t>(r)].push_back(h[static_cast<size_t>(r)]);
    rq[static_cast<size_t>(r)].push_back(q[static_cast<size_t>(r)]);
  }
  Result res;
  res.matched.assign(static_cast<size_t>(k), -1);
  if (repeated(rh, ids)) return res;
  const ZMatrix ah = integral(rh, d + 1), aq = integral(rq, d + 1);
  const std::vector<Entry> ent = entries_by_rank(ids, d);  // coordinate columns only
  std::vector<int> by_id(static_cast<size_t>(k));             // rows, smallest id first
  for (int r = 0; r < k; ++r) by_id[static_cast<size_t>(r)] = r;
  std::sort(by_id.begin(), by_id.end(),
            [&](int x, int y) { return ids[static_cast<size_t>(x)] < ids[static_cast<size_t>(y)]; });
  const int hc = d;  // the height column
  const unsigned all = (1u << k) - 1u;
  std::vector<signed char> memo_h(static_cast<size_t>(1) << (2 * k), 2), memo_q = memo_h;
  auto cached = [&](std::vector<signed char>& memo, const ZMatrix& a, unsigned kr, unsigned kc) {
    signed char& slot = memo[(static_cast<size_t>(kr) << k) | kc];
    if (slot == 2) slot = static_cast<signed char>(minor_sign(a, kr, kc));
    return static_cast<int>(slot);
  };
  std::vector<int> matched(static_cast<size_t>(k), -1);
  auto leaf = [&](unsigned ru, unsigned cu, const std::vector<int>& mt) {
    const unsigned kr = all & ~ru, kc = all & ~cu;  // kc holds the height column
    const int sg = matching_sign(mt, k);
    if (const int s = cached(memo_h, ah, kr, kc)) {
      res = Result{sg * s, mt, 0};
      return true;
    }
    if (const int s = cached(memo_q, aq, kr, kc)) {  // ε1 |x|²
      res = Result{sg * s, mt, 1};
      return true;
    }
    for (int r : by_id) {  // -ε2^(r_i), smallest id first
      if (!((kr >> r) & 1u)) continue;
      std::vector<int> with = mt;
      with[static_cast<size_t>(r)] = hc;
      // the height entry of row r is deleted: the minor does not see h or q
      if (const int s = cached(memo_h, ah, kr & ~(1u << r), kc & ~(1u << hc))) {
        res = Result{-matching_sign(with, k) * s, mt, 2 + r};
        return true;
      }
    }
    return false;
  };
  if (!visit(ent, static_cast<int>(ent.size()), 0u, 0u, matched, leaf))
    throw std::logic_error("sos_oracle: every pulled term vanished");
  return res;
}

}  // namespace flipflop::test::sos_oracle

// exact.cpp — dyadic arithmetic, integer Λ-matrices and Bareiss determinants.
#include "exact.hpp"

#include "predicates/exact_expansion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace flipflop::pred::exact {

Dyadic to_dyadic(double x) {
  Dyadic d;
  if (x == 0.0) return d;
  if (!std::isfinite(x)) throw std::domain_error("exact predicate on a non-finite value");
  int exp = 0;
  double frac = std::frexp(x, &exp);  // x = frac * 2^exp, 0.5 <= |frac| < 1
  // frac * 2^53 is an integer of at most 53 bits (exact for normal and subnormal x)
  auto mant = static_cast<std::int64_t>(std::ldexp(frac, 53));
  d.m = static_cast<long>(mant);
  d.e = static_cast<long>(exp) - 53;
  return d;
}

namespace {
// Aligns two dyadics to the smaller exponent and combines their mantissas.
template <class Op>
Dyadic combine(const Dyadic& a, const Dyadic& b, Op op) {
  if (a.m == 0) {
    Dyadic r;
    r.m = op(mpz_class(0), b.m);
    r.e = b.e;
    return r;
  }
  if (b.m == 0) return a;
  Dyadic r;
  if (a.e <= b.e) {
    mpz_class bm = b.m;
    mpz_mul_2exp(bm.get_mpz_t(), bm.get_mpz_t(), static_cast<mp_bitcnt_t>(b.e - a.e));
    r.m = op(a.m, bm);
    r.e = a.e;
  } else {
    mpz_class am = a.m;
    mpz_mul_2exp(am.get_mpz_t(), am.get_mpz_t(), static_cast<mp_bitcnt_t>(a.e - b.e));
    r.m = op(am, b.m);
    r.e = b.e;
  }
  return r;
}
}  // namespace

Dyadic add(const Dyadic& a, const Dyadic& b) {
  return combine(a, b, [](const mpz_class& x, const mpz_class& y) { return mpz_class(x + y); });
}
Dyadic sub(const Dyadic& a, const Dyadic& b) {
  return combine(a, b, [](const mpz_class& x, const mpz_class& y) { return mpz_class(x - y); });
}
Dyadic mul(const Dyadic& a, const Dyadic& b) {
  Dyadic r;
  r.m = a.m * b.m;
  r.e = a.e + b.e;
  return r;
}
int sign(const Dyadic& a) { return sgn(a.m); }

namespace {
#if defined(__SIZEOF_INT128__)
__extension__ typedef __int128 i128;

// x = m 2^e, m odd (x != 0, finite): e, the exponent of x's lowest set bit
// (xp::bit_span's).
int low_exponent(double x) {
  int low = 0, hi = 0;
  xp::bit_span(x, low, hi);
  return low;
}

// The fast path of build_lambda: each coordinate column in units of its
// lowest set bit, the lifted column in units of 2^uh with uh = min(2 min_c
// unit_c, the weights' lowest bit) — a positive power-of-two factor per
// column, which keeps the sign of every minor, like build_lambda_dyadic's
// scaling — when every entry is then an integer below 2^61 (coordinates
// below 2^30 when lifted). False otherwise (the general path takes over).
bool build_small(int k, const double* const* coords, const double* weights, IntLambda& out) {
  const int ncoord = k - 1, nreal = weights ? ncoord - 1 : ncoord;
  const double cap = weights ? 0x1p30 : 0x1p61;
  int unit[kMaxLambdaK];
  for (int c = 0; c < nreal; ++c) {
    unit[c] = 1 << 20;
    for (int r = 0; r < k; ++r) {
      const double x = coords[r][c];
      if (!std::isfinite(x)) return false;
      if (x != 0.0) unit[c] = std::min(unit[c], low_exponent(x));
    }
    if (unit[c] == 1 << 20) unit[c] = 0;  // a zero column
  }
  out.k = k;
  out.s.assign(static_cast<size_t>(k * k), 0);
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < nreal; ++c) {
      const double v = std::ldexp(coords[r][c], -unit[c]);  // an integer, exactly
      if (!(std::fabs(v) < cap)) return false;
      out.s[static_cast<size_t>(r * k + c)] = static_cast<long>(v);
    }
    out.s[static_cast<size_t>(r * k + k - 1)] = 1;
  }
  if (weights) {
    int uh = 1 << 20;
    for (int c = 0; c < nreal; ++c) uh = std::min(uh, 2 * unit[c]);
    for (int r = 0; r < k; ++r) {
      if (!std::isfinite(weights[r])) return false;
      if (weights[r] != 0.0) uh = std::min(uh, low_exponent(weights[r]));
    }
    for (int r = 0; r < k; ++r) {
      i128 h = 0;
      for (int c = 0; c < nreal; ++c) {
        const int shift = 2 * unit[c] - uh;
        if (shift > 60) return false;
        const i128 v = out.s[static_cast<size_t>(r * k + c)];
        h += (v * v) << shift;  // below 2^120
      }
      if (weights[r] != 0.0) {
        const int low = low_exponent(weights[r]);  // w = m 2^low, m odd, low >= uh
        const auto m = static_cast<std::int64_t>(std::ldexp(weights[r], -low));  // |m| < 2^53
        const int shift = low - uh;
        if (shift > 60) return false;
        h -= static_cast<i128>(m) * (static_cast<i128>(1) << shift);  // m may be negative: no shift of it
      }
      const i128 lim = static_cast<i128>(1) << 61;
      if (h >= lim || h <= -lim) return false;
      out.s[static_cast<size_t>(r * k + nreal)] = static_cast<long>(h);
    }
  }
  return true;
}
#endif
}  // namespace

IntLambda build_lambda(int k, const double* const* coords, const double* weights) {
#if defined(__SIZEOF_INT128__)
  {
    IntLambda small;
    if (build_small(k, coords, weights, small)) return small;
  }
#endif
  const int ncoord = k - 1;                              // columns before the 1-column
  const int nreal = weights ? ncoord - 1 : ncoord;       // real coordinates per point
  std::vector<Dyadic> entries(static_cast<size_t>(k * ncoord));
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < nreal; ++c) entries[static_cast<size_t>(r * ncoord + c)] = to_dyadic(coords[r][c]);
    if (weights) {
      // lifted height |x|^2 - w, exactly
      Dyadic h = sub(Dyadic{}, to_dyadic(weights[r]));
      for (int c = 0; c < nreal; ++c) {
        const Dyadic& x = entries[static_cast<size_t>(r * ncoord + c)];
        h = add(h, mul(x, x));
      }
      entries[static_cast<size_t>(r * ncoord + nreal)] = h;
    }
  }
  return build_lambda_dyadic(k, entries);
}

IntLambda build_lambda_dyadic(int k, const std::vector<Dyadic>& entries) {
  const int ncoord = k - 1;
  IntLambda m;
  m.k = k;
  m.a.assign(static_cast<size_t>(k * k), mpz_class(0));
  for (int c = 0; c < ncoord; ++c) {
    long emin = 0;
    bool any = false;
    for (int r = 0; r < k; ++r) {
      const Dyadic& x = entries[static_cast<size_t>(r * ncoord + c)];
      if (x.m == 0) continue;
      emin = any ? std::min(emin, x.e) : x.e;
      any = true;
    }
    for (int r = 0; r < k; ++r) {
      const Dyadic& x = entries[static_cast<size_t>(r * ncoord + c)];
      mpz_class& dst = m.a[static_cast<size_t>(r * k + c)];
      if (x.m == 0) continue;
      dst = x.m;
      mpz_mul_2exp(dst.get_mpz_t(), dst.get_mpz_t(), static_cast<mp_bitcnt_t>(x.e - emin));
    }
  }
  for (int r = 0; r < k; ++r) m.a[static_cast<size_t>(r * k + k - 1)] = 1;
  return m;
}

namespace {
// The positions of the set bits of `mask` below k, ascending; their count.
int positions(std::uint32_t mask, int k, int* out) {
  int n = 0;
  for (int i = 0; i < k; ++i)
    if (mask & (1u << i)) out[n++] = i;
  return n;
}

#if defined(__SIZEOF_INT128__)
// The rows ri x columns ci of m as __int128 when every entry is below 2^62 in
// magnitude and the Hadamard bound Π_i max(1, |row_i|_2) is below 2^62 (with
// a margin for its rounding): every minor of the submatrix, hence every value
// of a fraction-free elimination on it, is then below 2^62, and every
// product of two below 2^124.
bool load_small(const IntLambda& m, const int* ri, int nr, const int* ci, int nc, i128* a) {
  double bound = 1.0;
  for (int i = 0; i < nr; ++i) {
    double norm2 = 0.0;
    for (int j = 0; j < nc; ++j) {
      long v = 0;
      if (!m.s.empty()) {
        v = m.s[static_cast<size_t>(ri[i] * m.k + ci[j])];  // below 2^61 (build_small)
      } else {
        const mpz_class& x = m.at(ri[i], ci[j]);
        if (mpz_sizeinbase(x.get_mpz_t(), 2) > 61) return false;  // |x| < 2^61
        v = x.get_si();
      }
      a[i * nc + j] = v;
      norm2 += static_cast<double>(v) * static_cast<double>(v);
    }
    bound *= std::max(1.0, std::sqrt(norm2));
  }
  return bound * (1.0 + 0x1p-30) < 0x1p62;
}

// Fraction-free elimination (Bareiss) with column pivoting on an nr x nc
// matrix (nr <= nc) of small values (load_small): false when the rows are
// dependent; else `sign` = the sign of the determinant of the columns chosen
// as pivots (for nr == nc: of the matrix). A column swap is a permutation of
// the columns made up front (rows above p no longer read them), so every
// division stays exact.
bool bareiss_small(i128* a, int nr, int nc, int* sign) {
  i128 prev = 1;
  int s = 1;
  for (int p = 0; p < nr; ++p) {
    int pc = p;
    while (pc < nc && a[p * nc + pc] == 0) ++pc;
    if (pc == nc) return false;
    if (pc != p) {
      for (int i = 0; i < nr; ++i) std::swap(a[i * nc + p], a[i * nc + pc]);
      s = -s;
    }
    const i128 piv = a[p * nc + p];
    for (int i = p + 1; i < nr; ++i)
      for (int j = p + 1; j < nc; ++j)
        a[i * nc + j] = (a[i * nc + j] * piv - a[i * nc + p] * a[p * nc + j]) / prev;
    prev = piv;
  }
  *sign = prev > 0 ? s : -s;
  return true;
}
#endif
}  // namespace

int minor_sign(const IntLambda& m, std::uint32_t rows, std::uint32_t cols) {
  int ri[kMaxLambdaK] = {}, ci[kMaxLambdaK] = {};
  const int n = positions(rows, m.k, ri), nc = positions(cols, m.k, ci);
  if (n != nc) throw std::logic_error("minor_sign: non-square minor");
  if (n == 0) return 1;
#if defined(__SIZEOF_INT128__)
  {
    // small integers (lattice input, the degenerate calls that reach GMP):
    // the same elimination in __int128, no allocation
    i128 a[kMaxLambdaK * kMaxLambdaK];
    int sign = 0;
    if (load_small(m, ri, n, ci, n, a)) return bareiss_small(a, n, n, &sign) ? sign : 0;
  }
#endif
  // Bareiss fraction-free elimination with row pivoting, on raw mpz_t (only
  // the n x n entries in use are initialised: this is the hot path of the
  // exact stage).
  mpz_t a[kMaxLambdaK][kMaxLambdaK];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (m.s.empty())
        mpz_init_set(a[i][j], m.at(ri[i], ci[j]).get_mpz_t());
      else
        mpz_init_set_si(a[i][j], m.s[static_cast<size_t>(ri[i] * m.k + ci[j])]);
    }
  mpz_t prev, tmp;
  mpz_init_set_ui(prev, 1);
  mpz_init(tmp);
  int sign_perm = 1, result = 0;
  bool singular = false;
  for (int p = 0; p < n - 1 && !singular; ++p) {
    if (mpz_sgn(a[p][p]) == 0) {
      int q = p + 1;
      while (q < n && mpz_sgn(a[q][p]) == 0) ++q;
      if (q == n) {
        singular = true;
        break;
      }
      for (int j = 0; j < n; ++j) mpz_swap(a[p][j], a[q][j]);
      sign_perm = -sign_perm;
    }
    for (int i = p + 1; i < n; ++i) {
      for (int j = p + 1; j < n; ++j) {
        // a[i][j] = (a[i][j] * a[p][p] - a[i][p] * a[p][j]) / prev, exactly
        mpz_mul(tmp, a[i][j], a[p][p]);
        mpz_submul(tmp, a[i][p], a[p][j]);
        mpz_divexact(a[i][j], tmp, prev);
      }
    }
    mpz_set(prev, a[p][p]);
  }
  if (!singular) result = sign_perm * mpz_sgn(a[n - 1][n - 1]);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) mpz_clear(a[i][j]);
  mpz_clear(prev);
  mpz_clear(tmp);
  return result;
}

namespace {
// Do rows `rows` of m, restricted to columns `cols` (at least as many), have
// full row rank? Fraction-free elimination (Bareiss) on that submatrix, with
// column pivoting; false as soon as a row reduces to zero.
bool full_row_rank(const IntLambda& m, std::uint32_t rows, std::uint32_t cols) {
  int ri[kMaxLambdaK] = {}, ci[kMaxLambdaK] = {};
  const int nr = positions(rows, m.k, ri), nc = positions(cols, m.k, ci);
  if (nr > nc) return false;
#if defined(__SIZEOF_INT128__)
  {
    i128 small[kMaxLambdaK * kMaxLambdaK];
    int sign = 0;
    if (load_small(m, ri, nr, ci, nc, small)) return bareiss_small(small, nr, nc, &sign);
  }
#endif
  std::vector<mpz_class> a(static_cast<size_t>(nr * nc));
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nc; ++j)
      a[static_cast<size_t>(i * nc + j)] =
          m.s.empty() ? m.at(ri[i], ci[j]) : mpz_class(m.s[static_cast<size_t>(ri[i] * m.k + ci[j])]);
  mpz_class prev = 1, tmp;
  for (int p = 0; p < nr; ++p) {
    int pc = -1;  // a non-zero entry of row p among the columns p..nc-1
    for (int j = p; j < nc && pc < 0; ++j)
      if (sgn(a[static_cast<size_t>(p * nc + j)]) != 0) pc = j;
    if (pc < 0) return false;
    if (pc != p)
      for (int i = 0; i < nr; ++i) swap(a[static_cast<size_t>(i * nc + p)], a[static_cast<size_t>(i * nc + pc)]);
    const mpz_class& piv = a[static_cast<size_t>(p * nc + p)];
    for (int i = p + 1; i < nr; ++i) {
      for (int j = p + 1; j < nc; ++j) {
        mpz_class& x = a[static_cast<size_t>(i * nc + j)];
        tmp = x * piv - a[static_cast<size_t>(i * nc + p)] * a[static_cast<size_t>(p * nc + j)];
        mpz_divexact(x.get_mpz_t(), tmp.get_mpz_t(), prev.get_mpz_t());
      }
    }
    prev = piv;
  }
  return true;
}

// Depth-first search over matchings in the dominance order of predicates.hpp:
// rows from the largest index (last row) to the smallest; on each row first
// "not perturbed", then the coordinate columns from the last (j = m) to the
// first (j = 1). Leaves are visited in order of decreasing significance; the
// first leaf with a non-zero complementary minor decides the sign.
struct SosSearch {
  const IntLambda& m;
  const IntLambda* q = nullptr;  // pulled: the unweighted Λ (exact_expansion.hpp sos_search, Pulled)
  // memo of minor signs: index = (rows << k) | cols, value 2 = unknown; a
  // table of 2^(2k) bytes for k <= 8, a hash map beyond (k = 11: 4 MB as a
  // table, of which a search touches a few entries)
  std::vector<signed char> memo;
  std::unordered_map<std::uint32_t, signed char> sparse;

  explicit SosSearch(const IntLambda& mat)
      : m(mat), memo(mat.k <= 8 ? static_cast<size_t>(1) << (2 * mat.k) : 0, 2) {}

  int cached_minor(std::uint32_t rows, std::uint32_t cols) {
    const std::uint32_t key = (rows << m.k) | cols;
    if (m.k > 8) {
      const auto it = sparse.find(key);
      if (it != sparse.end()) return it->second;
      const int s = minor_sign(m, rows, cols);
      sparse.emplace(key, static_cast<signed char>(s));
      return s;
    }
    signed char& slot = memo[key];
    if (slot == 2) slot = static_cast<signed char>(minor_sign(m, rows, cols));
    return slot;
  }

  static int popcount_below(std::uint32_t mask, int bit) {
    return __builtin_popcount(mask & ((1u << bit) - 1u));
  }

  // r: row to decide; kept rows/cols: not yet deleted; sgn: product of the
  // Laplace signs of the deletions made so far.
  //
  // Pruning (plain perturbation only): the rows above r that are kept (F)
  // belong to every leaf of this subtree, whose columns are subsets of
  // kept_cols. When F has not full row rank on kept_cols, every such minor is
  // 0, so no leaf decides and the subtree is skipped — the order of the leaves
  // visited is unchanged. On heavily degenerate rows (all points equal: no
  // minor of two rows is non-zero) it turns an exponential walk over the
  // matchings into a few rank tests (k = 11: seconds to milliseconds).
  int dfs(int r, std::uint32_t kept_rows, std::uint32_t kept_cols, int sgn) {
    if (!q && r >= 0) {
      const std::uint32_t fixed = kept_rows & ~((2u << r) - 1u);
      if (__builtin_popcount(fixed) >= 2 && !full_row_rank(m, fixed, kept_cols)) return 0;
    }
    if (r < 0) {
      if (const int s = cached_minor(kept_rows, kept_cols)) return sgn * s;
      if (!q) return 0;
      if (const int s = minor_sign(*q, kept_rows, kept_cols)) return sgn * s;  // the ε1 term
      const int hc = m.k - 2;  // the pulled heights of the kept rows, smallest index first
      for (int i = 0; i < m.k; ++i) {
        if (!(kept_rows & (1u << i))) continue;
        const int parity = popcount_below(kept_rows, i) + popcount_below(kept_cols, hc);
        if (const int s = cached_minor(kept_rows & ~(1u << i), kept_cols & ~(1u << hc)))
          return ((parity & 1) ? sgn : -sgn) * s;
      }
      return 0;
    }
    if (int s = dfs(r - 1, kept_rows, kept_cols, sgn)) return s;  // row r not perturbed
    for (int c = m.k - 2; c >= 0; --c) {                             // 1-column never perturbed
      if (q && c == m.k - 2) continue;
      if (!(kept_cols & (1u << c))) continue;
      int parity = popcount_below(kept_rows, r) + popcount_below(kept_cols, c);
      int f = (parity & 1) ? -1 : 1;
      if (int s = dfs(r - 1, kept_rows & ~(1u << r), kept_cols & ~(1u << c), sgn * f)) return s;
    }
    return 0;
  }
};
}  // namespace

int sos_sign(const IntLambda& m, const IntLambda* unweighted) {
  if (m.k < 1 || m.k > kMaxLambdaK) throw std::logic_error("sos_sign: k must be in 1..11");
  if (unweighted && (m.k < 3 || unweighted->k != m.k))
    throw std::logic_error("sos_sign: the pulled perturbation needs two lifted matrices of one size");
  SosSearch search(m);
  search.q = unweighted;
  const std::uint32_t all = (1u << m.k) - 1u;
  int s = search.dfs(m.k - 1, all, all, 1);
  if (s == 0) throw std::logic_error("sos_sign: no non-zero term (impossible for a Λ-matrix)");
  return s;
}

}  // namespace flipflop::pred::exact

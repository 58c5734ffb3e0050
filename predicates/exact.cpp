// exact.cpp — dyadic arithmetic, integer Λ-matrices and Bareiss determinants.
#include "exact.hpp"

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

IntLambda build_lambda(int k, const double* const* coords, const double* weights) {
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
}  // namespace

int minor_sign(const IntLambda& m, std::uint32_t rows, std::uint32_t cols) {
  int ri[kMaxLambdaK], ci[kMaxLambdaK];
  const int n = positions(rows, m.k, ri), nc = positions(cols, m.k, ci);
  if (n != nc) throw std::logic_error("minor_sign: non-square minor");
  if (n == 0) return 1;
  // Bareiss fraction-free elimination with row pivoting, on raw mpz_t (only
  // the n x n entries in use are initialised: this is the hot path of the
  // exact stage).
  mpz_t a[kMaxLambdaK][kMaxLambdaK];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) mpz_init_set(a[i][j], m.at(ri[i], ci[j]).get_mpz_t());
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
  int ri[kMaxLambdaK], ci[kMaxLambdaK];
  const int nr = positions(rows, m.k, ri), nc = positions(cols, m.k, ci);
  if (nr > nc) return false;
  std::vector<mpz_class> a(static_cast<size_t>(nr * nc));
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nc; ++j) a[static_cast<size_t>(i * nc + j)] = m.at(ri[i], ci[j]);
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

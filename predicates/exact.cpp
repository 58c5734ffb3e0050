// exact.cpp — dyadic arithmetic, integer Λ-matrices and Bareiss determinants.
#include "exact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

int minor_sign(const IntLambda& m, std::uint32_t rows, std::uint32_t cols) {
  int ri[8], ci[8];
  int n = 0, nc = 0;
  for (int r = 0; r < m.k; ++r)
    if (rows & (1u << r)) ri[n++] = r;
  for (int c = 0; c < m.k; ++c)
    if (cols & (1u << c)) ci[nc++] = c;
  if (n != nc) throw std::logic_error("minor_sign: non-square minor");
  if (n == 0) return 1;
  // Bareiss fraction-free elimination with row pivoting, on raw mpz_t (only
  // the n x n entries in use are initialised: this is the hot path of the
  // exact stage).
  mpz_t a[8][8];
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
// Depth-first search over matchings in the dominance order of predicates.hpp:
// rows from the largest index (last row) to the smallest; on each row first
// "not perturbed", then the coordinate columns from the last (j = m) to the
// first (j = 1). Leaves are visited in order of decreasing significance; the
// first leaf with a non-zero complementary minor decides the sign.
struct SosSearch {
  const IntLambda& m;
  const IntLambda* q = nullptr;  // pulled: the unweighted Λ (exact_expansion.hpp sos_search, Pulled)
  // memo of minor signs: index = (rows << k) | cols, value 2 = unknown
  std::vector<signed char> memo;

  explicit SosSearch(const IntLambda& mat) : m(mat), memo(static_cast<size_t>(1) << (2 * mat.k), 2) {}

  int cached_minor(std::uint32_t rows, std::uint32_t cols) {
    signed char& slot = memo[(rows << m.k) | cols];
    if (slot == 2) slot = static_cast<signed char>(minor_sign(m, rows, cols));
    return slot;
  }

  static int popcount_below(std::uint32_t mask, int bit) {
    return __builtin_popcount(mask & ((1u << bit) - 1u));
  }

  // r: row to decide; kept rows/cols: not yet deleted; sgn: product of the
  // Laplace signs of the deletions made so far.
  int dfs(int r, std::uint32_t kept_rows, std::uint32_t kept_cols, int sgn) {
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
  if (m.k < 1 || m.k > 8) throw std::logic_error("sos_sign: k must be in 1..8");
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

// dd_filter.hpp — the double-double filter with an a-priori error bound: the
// stage of the default path (staged.hpp) after the static and semi-static
// filters for k = 3..5 points (orient2d/3d/4d, power2d/3d), and in the
// exact stage's path for lattices with moved points for k = 6, 7
// (dd_filter_sign_wide below: another window, tiny values set to 0). Near-degenerate
// calls (1-3 ulp off a degenerate set) have det Λ of order u times its terms,
// below what any double filter resolves (the dynamic ErrDouble filter decided
// 15-76 % of them, at the cost of a running bound), but far above the
// double-double error, of order u^2 times the terms. The running bound of
// ErrDD (err_dd.hpp) costs more than the value it bounds (about 45 flops per
// product without FMA); here the same operations (dd_add_parts, dd_mul_parts:
// the same values h + l) are bounded once, a priori, from the column
// magnitudes (their permanent) — Shewchuk's errbound approach ([She97]
// §4.3) one precision further — so each operation is its error-free
// transformations only.
//
// ============================================================================
// The bound (derivation)
// ============================================================================
// Notation as in err_dd.hpp: u = 2^-53; a DD value a = a.h + a.l with
// |a.l| <= u |a.h| (every value below is the output of a two_sum: l is the
// rounding error of h). Window: every input value v (coordinates, weights) is
// 0 or a multiple of 2^-202 with |v| < 2^150 — checked here per call as 0 or
// 2^-150 <= |v| < 2^150 (the lowest set bit of such a double is >= 2^-202;
// NaN and infinities fail the test), or known for the whole input
// (StaticFilter::dd_window(), from the exponents for_points scans). Then
// Range::fits(D) of exact_expansion.hpp holds for every degree D <= 5 (|v| <
// 2^150: E <= 150, D (E + 1) <= 755 <= 950; D (-202) >= -1074), which is err_dd.hpp's
// precondition: every value computed here is a multiple of 2^-1074, so a
// rounded result that is subnormal is exact, nothing overflows, and every
// rounded operation obeys |fl(x) - x| <= u |fl(x)| and <= u |x|.
//
// For every node v of the evaluation (entry, product, sum) let V be its exact
// value and M(v) its magnitude: for an entry, M = |V| (a coordinate
// difference d, exact as a two_sum pair) or Σ_j d_j^2 + |Δw| (a lifted entry
// |d|^2 - Δw); M(a b) = M(a) M(b), M(a ± b) = M(a) + M(b). So |V| <= M(v), and
// at the root M is the permanent of the matrix of entry magnitudes (Laplace on
// the magnitudes is the permanent's expansion). Claim: the computed v obeys
//     |V - (v.h + v.l)| <= β_v u^2 M(v),   β_v <= 2^10,
// hence |v.h| <= (|V| + β_v u^2 M(v)) / (1 - u) <= (1 + 2u) M(v).
//   * entries: coordinate differences and Δw are exact (β = 0).
//   * a * b (dd_mul_parts): err_dd.hpp's rule gives |(a.h + a.l)(b.h + b.l) -
//     (h + l)| <= |a.l b.l| + u (|c1| + |c2| + |c| + |t3|); with A = |a.h|,
//     B = |b.h|: |a.l b.l| <= u^2 AB, |c1|, |c2| <= (1 + u) u AB, |c| <=
//     2u (1 + u)^2 AB, |q| <= u AB, |t3| <= (1 + u)(|q| + |c|) <= 3u (1 + u)^3 AB:
//     at most 8 (1 + u)^3 u^2 AB <= 8 (1 + u)^3 (1 + 2u)^2 u^2 M(a) M(b). The inputs'
//     errors add |A||B - b| + |b||A - a| <= (β_b + β_a (1 + β_b u^2)) u^2
//     M(a) M(b). So β_ab = β_a + β_b + 9 (the 1 covers every (1 + O(u))).
//   * a ± b (dd_add_parts): error u (|t2| + |t3|), |t2| <= (1 + u) u (A + B),
//     |t| <= u |s| <= u (1 + u)(A + B), |t3| <= 2u (1 + u)^2 (A + B): at most
//     3 (1 + u)^2 u^2 (A + B) <= 3 (1 + u)^2 (1 + 2u) u^2 (M(a) + M(b)); the inputs'
//     errors add at most max(β_a, β_b) u^2 (M(a) + M(b)): β = max(β_a, β_b) + 4.
//   * a lifted entry: -Δw, then + d_j d_j for j < m (m = N - 1 coordinates):
//     β_L = 9 + 4m.
//   * det_by_minors<N> (lambda_filter.hpp): a level-r minor is a chain of r
//     products (row r - 1's entry times a level r - 1 minor), summed left to
//     right: β_r = β_entry + β_{r-1} + 9 + 4 (r - 1). Without a lifted column
//     β^p_1 = 0, β^p_r = β^p_{r-1} + 5 + 4r (13, 30, 51 for r = 2, 3, 4).
//     With one, each term has at most one lifted factor, and by induction
//     β_r <= β_L + β^p_r (a lifted entry times a plain minor, or a plain entry
//     times a minor with the lifted column). dd_beta below; at most 72.
// Root: |det Λ - (h + l)| <= β u^2 per(M), per(M) the permanent of the
// entry magnitudes, computed (det_by_minors<N, Mag>: the same Laplace
// expansion with every sign +) from the heads: |d| <= (1 + u)|d.h|, a lifted
// magnitude <= (1 + u)^2 (Σ d_j.h^2 + |Δw.h|), so per(M) <= (1 + u)^(2N) times
// the permanent of the head magnitudes, and each rounded operation on the way
// (at most N + N(N-1)/2 + 4 along a term, plus the product with β u^2) loses
// at most a factor (1 - u): fewer than 40 factors in all, covered by the final
// (1 + 2^-40). The magnitudes are of degree <= D inside the window, hence
// multiples of 2^-1074 and computed with relative errors only; the product
// β u^2 per may underflow, losing at most 2^-1075 absolutely: + 2^-1072
// covers it. No overflow: per(M) <= 4! 2^(3 x 151 + 304) = 2^762.
// Sign: the sign of det Λ is that of h when |h| > (bound + |l|)(1 + 2^-40).
//
// Evaluation: det_small<N> (lambda_filter.hpp) on DDv values, whose product
// is dd_mul_parts' with an exact fast_two_sum at the end (the same values) and
// whose two_product uses an FMA where the caller instantiates Fma = true
// (predicates.cpp's after_filters entries, on a host with FMA): the same
// exact pair, so the same values and the same bound.
//
// Header-only and __host__ __device__; no heap, no recursion; stack: (K-1)^2
// DD values and magnitudes (24 bytes each) and the minors of det_by_minors
// (K = 5: under 1 KB).
#pragma once

#include <cmath>

#include "predicates/err_dd.hpp"
#include "predicates/lambda_filter.hpp"

namespace flipflop::pred {

// Two_Product with a fused multiply-add (Fma) or Dekker's product with
// Veltkamp's split: both return the same exact pair (x, y), x = fl(a b), x + y
// = a b ([She97] Thm 18 and its remark on FMA; every product here is inside
// the window, so a b - x is a representable multiple of 2^-1074), so the
// a-priori bound above and every sign are the same for both instantiations —
// only the cost differs (about 2 flops against 17). On the device, and on the
// host when compiled with FMA (-mfma), xp::Dbl::two_product already uses it.
template <bool Fma>
FF_HD FF_FORCEINLINE void dd_two_product(double a, double b, double& x, double& y) {
#if defined(__CUDA_ARCH__) || defined(__FMA__)
  xp::Dbl::two_product(a, b, x, y);
#else
  if constexpr (Fma) {
    x = a * b;
    y = std::fma(a, b, -x);
  } else {
    xp::Dbl::two_product(a, b, x, y);
  }
#endif
}

FF_HD FF_FORCEINLINE double fused_multiply_add(double a, double b, double c) {
#if defined(__CUDA_ARCH__)
  return fma(a, b, c);
#else
  return std::fma(a, b, c);
#endif
}

// A double-double value without a running bound (the bound is a priori).
// Fma chooses the two_product of its products (dd_two_product).
template <bool Fma>
struct DDv {
  double h = 0.0, l = 0.0;
  DDv() = default;  // host and device: defaulted
  FF_HD static DDv difference(double x, double y) {
    DDv r;
    xp::Dbl::two_sum(x, -y, r.h, r.l);
    return r;
  }
};
using DD = DDv<false>;
template <bool Fma>
FF_HD FF_FORCEINLINE DDv<Fma> operator+(const DDv<Fma>& a, const DDv<Fma>& b) {
  DDv<Fma> r;
  double t2 = 0.0, t3 = 0.0;
  dd_add_parts(a.h, a.l, b.h, b.l, r.h, r.l, t2, t3);
  return r;
}
template <bool Fma>
FF_HD FF_FORCEINLINE DDv<Fma> operator-(const DDv<Fma>& a) {
  DDv<Fma> r;
  r.h = -a.h;
  r.l = -a.l;
  return r;
}
template <bool Fma>
FF_HD FF_FORCEINLINE DDv<Fma> operator-(const DDv<Fma>& a, const DDv<Fma>& b) {
  return a + (-b);
}
// dd_mul_parts (err_dd.hpp) with its last two_sum(p, t3) as fast_two_sum:
// the same (h, l), since |t3| <= |p|. Proof: if a.h b.h = 0 then a.h or b.h
// is 0, so is its tail (|l| <= u |h|), and c1 = c2 = q = t3 = 0. Otherwise,
// inside the window (no underflow), |q| <= u |p|, |c1|, |c2| <= (1 + u) u
// |a.h b.h|, |c| <= 2u (1 + u)^2 |a.h b.h|, |a.h b.h| <= (1 + u) |p|, so
// |t3| <= (1 + u)(|q| + |c|) <= 4u |p| < |p|, and Dekker's fast_two_sum
// ([She97] Thm 6) is exact with x = fl(p + t3), as two_sum.
template <bool Fma>
FF_HD FF_FORCEINLINE DDv<Fma> operator*(const DDv<Fma>& a, const DDv<Fma>& b) {
  DDv<Fma> r;
  double p = 0.0, q = 0.0;
  dd_two_product<Fma>(a.h, b.h, p, q);
  const double c1 = a.h * b.l;
  const double c2 = a.l * b.h;
  const double c = c1 + c2;
  const double t3 = q + c;
  xp::Dbl::fast_two_sum(p, t3, r.h, r.l);
  return r;
}

// A magnitude: det_small<N, Mag> on the entry magnitudes is their
// permanent (every sign of the Laplace expansion taken as +).
struct Mag {
  double v = 0.0;
};
FF_HD FF_FORCEINLINE Mag operator+(Mag a, Mag b) { return {a.v + b.v}; }
FF_HD FF_FORCEINLINE Mag operator-(Mag a, Mag b) { return {a.v + b.v}; }
FF_HD FF_FORCEINLINE Mag operator-(Mag a) { return a; }
FF_HD FF_FORCEINLINE Mag operator*(Mag a, Mag b) { return {a.v * b.v}; }

// β of the derivation above for det_by_minors<N> (m = N - 1 coordinates per
// row when lifted).
FF_HD constexpr int dd_beta(int n, bool lifted) {
  int b = 0;
  for (int r = 2; r <= n; ++r) b += 5 + 4 * r;
  return lifted ? b + 9 + 4 * (n - 1) : b;
}

// The entries of dd_filter_sign's matrix T (row i: p_i - p_{K-1}, and with
// weights the lifted difference Σ (p_i - p_{K-1})_j^2 - (w_i - w_{K-1})) in
// double-double, and their magnitudes from the heads (|d.h|; lifted: Σ d.h^2 +
// |Δw.h|), from which its threshold is computed. Shared with the filter's
// deterministic sensitivity test (proptests/filter_sensitivity_test.cpp).
template <int K, bool Fma>
FF_HD FF_FORCEINLINE void dd_filter_entries(const double* const* p, const double* w, DDv<Fma>* t, Mag* m) {
  constexpr int N = K - 1;
  using V = DDv<Fma>;
  const int ncoord = w ? N - 1 : N;
  const double* base = p[K - 1];
  for (int i = 0; i < N; ++i) {
    double lmag = 0.0;
    for (int j = 0; j < ncoord; ++j) {
      const V d = V::difference(p[i][j], base[j]);
      t[i * N + j] = d;
      m[i * N + j].v = std::fabs(d.h);
      lmag += d.h * d.h;
    }
    if (w) {
      V lift = -V::difference(w[i], w[K - 1]);
      lmag += std::fabs(lift.h);
      for (int j = 0; j < ncoord; ++j) lift = lift + t[i * N + j] * t[i * N + j];
      t[i * N + N - 1] = lift;
      m[i * N + N - 1].v = lmag;
    }
  }
}

// Six and seven rows (orient5d, orient6d, power4d, power5d; issue 39's
// lattices with a few points moved by some ulp, whose calls the static and
// semi-static filters leave to this stage): the same a-priori bound on a
// narrower window, and values far below it set to 0 with a bound of their own.
//   * Window: every value kept is 0 or 2^-100 <= |v| < 2^100. Its lowest set
//     bit is then >= 2^-152 and Range::fits(D) holds for every degree D <= 7
//     (7 x 101 = 707 <= 950; 7 x (-152) = -1064 >= -1074): err_dd.hpp's
//     precondition, as above. Entries: differences below 2^101, lifted ones
//     below 6 x 2^202 + 2^101 < 2^205; per(M) <= 6! 2^(5 x 101 + 205) < 2^720
//     (no overflow). Along a term at most N + N(N-1)/2 + 4 = 25 (N = 6)
//     rounded operations: the (1 + 2^-40) above still covers them. dd_beta
//     is the derivation's β for N = 5, 6 (det_by_minors<N>: the same Laplace
//     expansion as det_small, in the same operation order): at most 134.
//   * Tiny values: a nonzero value with |v| < 2^-100 (a lattice's 0 moved by
//     some ulp is a subnormal) is replaced by 0; t is the largest such |v|.
//     The filter then decides det T' = det Λ(p') of the points p' so changed,
//     and det T = det Λ(p) differs from it by at most E = N! N δ (B +
//     δ)^(N-1), where B bounds every entry of T' and δ every entry of T - T'
//     (the Leibniz expansion's N! terms each change by at most (B + δ)^N -
//     B^N <= N δ (B + δ)^(N-1)). A coordinate difference changes by at most
//     2t (both points' values); a lifted entry Σ_j d_j^2 - Δw by at most
//     Σ_j |d_j - d'_j| |d_j + d'_j| + 2t <= 2t (1 + 2m (D + t)), D the
//     largest |d'_j|. B and D come from the magnitudes (each at least its
//     entry's |value| / (1 + u)^2), rounded up by (1 + 2^-50); N! N <= 2^13;
//     E's rounded operations (at most 12) are covered by the final (1 +
//     2^-40), and an underflow of δ (B + δ)^(N-1) (at most 2^-1075) by a
//     second 2^-1072; an E that overflows is infinite and decides nothing.
//     With no ones column left (T is translation-invariant) E scales with the
//     input, so values just below the window next to values just above it
//     are bounded as tightly as a lattice's moved zeros. The sign is h's when
//     |h| > (bound + |l| + E)(1 + 2^-40): det T' and det T both have it.
// The window flag (StaticFilter::dd_window, the 2^±150 window) does not apply
// here: the test runs per call.
// Evaluation (the cost: the 6 x 6 Laplace expansion on double-double values
// took 15,600 instructions a call, a third of the exact stage's): the base row
// of T is a row whose kept values are all integers where there is one (an
// unmoved lattice point: swapping it to the last row flips the sign), and
// T's rows are reordered (the permutation's sign kept) so that the rows of
// integer entries whose row sums S_i have a product below 2^52 come first.
// Their levels are computed in binary64: every minor over them and every
// partial sum of its Laplace expansion is an integer of magnitude at most
// the permanent of their magnitudes, <= Π S_i < 2^53 — exact. The double-
// double operations on those exact values (tails 0) would give the same
// values with tails 0 (two_product and two_sum of exactly representable
// results), so the evaluation is det_by_minors<N, DDv> on the reordered T
// value for value, and the bound above holds as derived (per(M) does not
// depend on the order of the rows). The levels above go on in double-double.
template <int N, int U, class V>
FF_HD FF_FORCEINLINE V dd_levels_from(const double* td, const V* tv) {
  V d[1 << N];
  if constexpr (U == 0) {
    for (int j = 0; j < N; ++j) d[1 << j] = tv[j];
    minors_above<N, 1, V>(tv, d, std::make_integer_sequence<int, (1 << N)>{});
  } else {
    double e[1 << N];
    minor_levels<N, U, double>(td, e);
    for (int S = 1; S < (1 << N); ++S)
      if (popcount_small(static_cast<unsigned>(S)) == U) {
        d[S].h = e[S];
        d[S].l = 0.0;
      }
    if constexpr (U < N) minors_above<N, U, V>(tv, d, std::make_integer_sequence<int, (1 << N)>{});
  }
  return d[(1 << N) - 1];
}

// What dd_filter_sign_wide compared, for the sensitivity test of its bound
// (proptests/filter_sensitivity_test.cpp): the sign is parity x sgn h when
// |h| > (c per + |l| + 2^-1072 + tail)(1 + 2^-40).
struct DdWideParts {
  double h = 0.0, l = 0.0, c_per = 0.0, tail = 0.0;
  int parity = 1;
};

template <int K, bool Fma>
FF_HD FF_FORCEINLINE int dd_filter_sign_wide(const double* const* p, const double* w, DdWideParts* parts = nullptr) {
  static_assert(K == 6 || K == 7, "dd_filter_sign_wide: six or seven rows");
  constexpr int N = K - 1;
  constexpr double kHi = 0x1p100, kLo = 0x1p-100;
  const int ncoord = w ? N - 1 : N;
  double q[K][N];  // coordinates, tiny ones zeroed
  double qw[K];
  bool outside = false;
  double t = 0.0;
  int base = K - 1;
  bool base_found = false;
  auto keep = [&](double v) {
    const double a = std::fabs(v);
    outside = outside | !(a < kHi);  // also NaN, inf
    const bool tiny = a < kLo;
    t = tiny && a > t ? a : t;
    return tiny ? 0.0 : v;
  };
  for (int i = K - 1; i >= 0; --i) {
    bool integral = true;
    for (int j = 0; j < ncoord; ++j) {
      const double v = keep(p[i][j]);
      q[i][j] = v;
      integral = integral && v == std::floor(v);
    }
    if (w) {
      const double v = keep(w[i]);
      qw[i] = v;
      integral = integral && v == std::floor(v);
    }
    if (integral && !base_found) base = i, base_found = true;
  }
  if (outside) return 2;
  // the base row last: rows K-1 and base exchanged (det Λ changes sign)
  const double* qp[K];
  double qws[K];
  for (int i = 0; i < K; ++i) {
    const int src = i == base ? K - 1 : i == K - 1 ? base : i;
    qp[i] = q[src];
    qws[i] = w ? qw[src] : 0.0;
  }
  int parity = base == K - 1 ? 1 : -1;
  using V = DDv<Fma>;
  V tm[N * N];
  Mag m[N * N];
  dd_filter_entries<K, Fma>(qp, w ? qws : nullptr, tm, m);
  // the integer rows (tails 0, integer heads) while Π S_i < 2^52, first
  int order[N], u = 0;
  {
    int rest[N], nr = 0;
    double prod = 1.0;
    for (int i = 0; i < N; ++i) {
      bool integral = true;
      double sum = 0.0;
      for (int j = 0; j < N; ++j) {
        const V& e = tm[i * N + j];
        integral = integral && e.l == 0.0 && e.h == std::floor(e.h);
        sum += std::fabs(e.h);
      }
      if (integral && prod * sum < 0x1p52) {
        prod *= sum > 1.0 ? sum : 1.0;
        order[u++] = i;
      } else {
        rest[nr++] = i;
      }
    }
    for (int r = 0; r < nr; ++r) order[u + r] = rest[r];
    int inversions = 0;
    for (int x = 0; x < N; ++x)
      for (int y = x + 1; y < N; ++y) inversions += order[x] > order[y];
    if (inversions & 1) parity = -parity;
  }
  V tv[N * N];
  double td[N * N];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      tv[i * N + j] = tm[order[i] * N + j];
      td[i * N + j] = tv[i * N + j].h;
    }
  V det;
  switch (u) {
    case 0: det = dd_levels_from<N, 0, V>(td, tv); break;
    case 1: det = dd_levels_from<N, 1, V>(td, tv); break;
    case 2: det = dd_levels_from<N, 2, V>(td, tv); break;
    case 3: det = dd_levels_from<N, 3, V>(td, tv); break;
    case 4: det = dd_levels_from<N, 4, V>(td, tv); break;
    case 5: det = dd_levels_from<N, 5, V>(td, tv); break;
    default: det = dd_levels_from<N, (N >= 6 ? 6 : 5), V>(td, tv); break;
  }
  constexpr double c = dd_beta(N, true) * 0x1p-106;  // (the lifted β covers the plain one)
  const double per = det_by_minors<N, Mag>(m).v;
  double tail = 0.0;
  if (t > 0.0) {
    // E = N! N δ (B + δ)^(N-1): B from the magnitudes (each >= its entry's
    // |value| / (1 + u)^2), D the coordinates' part of them, δ as derived
    double B = 0.0, D = 0.0;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const double v = m[i * N + j].v;
        B = v > B ? v : B;
        D = j < ncoord && v > D ? v : D;
      }
    B *= 1.0 + 0x1p-50;
    D *= 1.0 + 0x1p-50;
    const double delta = w ? 2.0 * t * (1.0 + 2.0 * ncoord * (D + t)) : 2.0 * t;
    double Bk = 1.0;
    for (int i = 0; i < N - 1; ++i) Bk *= B + delta;
    tail = 0x1p13 * delta * Bk + 0x1p-1072;
  }
  const double bound = (c * per + std::fabs(det.l) + 0x1p-1072 + tail) * (1.0 + 0x1p-40);
  if (parts) *parts = {det.h, det.l, c * per, tail, parity};
  if (det.h > bound) return parity;
  if (-det.h > bound) return -parity;
  return 0;
}

// +1 / -1 when certain; 0 when undecided; 2 when an input value lies outside
// the window (the caller's other filters and exact stages decide). `window`:
// the caller knows every input value to lie in the window
// (StaticFilter::dd_window() of the input), and the per-call check is skipped.
// Fma: dd_two_product's choice; with it, orient2d (K = 3, plain) whose four
// differences are exact (every Two_Diff tail 0) is decided by Kahan's 2 x 2
// determinant below instead.
template <int K, bool Fma = false>
FF_HD FF_FORCEINLINE int dd_filter_sign(const double* const* p, const double* w, bool window = false) {
  static_assert(K >= 3 && K <= 7, "the double-double filter serves k = 3..7");
  if constexpr (K >= 6) {
    (void)window;
    return dd_filter_sign_wide<K, Fma>(p, w);
  }
  constexpr int N = K - 1;
  constexpr double kHi = 0x1p150, kLo = 0x1p-150;
  const int ncoord = w ? N - 1 : N;
  if (!window) {
    // outside: !(|v| < 2^150) (also NaN, inf) or 0 < |v| < 2^-150; bitwise
    // operators, not branches, one test at the end
    bool outside = false;
    auto check = [&outside](double v) {
      const double a = std::fabs(v);
      outside = outside | !(a < kHi) | ((a < kLo) & (a != 0.0));
    };
    for (int i = 0; i < K; ++i) {
      for (int j = 0; j < ncoord; ++j) check(p[i][j]);
      if (w) check(w[i]);
    }
    if (outside) return 2;
  }
  using V = DDv<Fma>;
  V t[N * N];
  Mag m[N * N];
  dd_filter_entries<K, Fma>(p, w, t, m);
  if constexpr (Fma && K == 3) {
    // Exact differences: det T = a d - b c of four doubles, a = t00, b =
    // t01, c = t10, d = t11. Kahan's algorithm with FMA: w = fl(b c), e =
    // fma(b, c, -w) = b c - w (exact), f = fma(a, d, -w) = fl(a d - w), r =
    // fl(f - e). Claim: sign(r) = sign(a d - b c); in particular r = 0 iff
    // a d = b c (Jeannerod, Louvet, Muller, Math. Comp. 82 (2013) prove |r -
    // x| <= 2u |x|; the sign alone, inside the window, as follows).
    // Inside the window every value here is a multiple of 2^-404 (the inputs
    // of 2^-202) below 2^303: no operation underflows or overflows, so
    // binary64 behaves as with an unbounded exponent, and a difference of two
    // doubles, a multiple of 2^-1074, rounds to 0 only when it is 0.
    // Let x = a d - b c, y = a d - w, so x = y - e and f = fl(y). sign(r) =
    // sign(f - e). Rounding is monotone and e is a double, so y > e implies
    // f >= e, y < e implies f <= e, y = e implies f = e: sign(f - e) =
    // sign(x) unless f = e while y != e. Suppose so. Then e != 0 (fl(y) = 0
    // forces y = 0 on this grid), |x| = |y - e| <= u 2^E(e) (half the spacing
    // of doubles at e, E(v) the exponent of v: 2^E(v) <= |v| < 2^(E(v)+1)),
    // and |e| <= u 2^E(w) (the rounding error of w), so E(e) <= E(w) - 53 and
    // |x| <= 2^(E(w) - 106). Write a = A 2^α, d = D 2^δ, b = B 2^β, c = C 2^γ
    // with integers |A|, |B|, |C|, |D| < 2^53; x is a multiple of 2^min(α+δ,
    // β+γ). (i) α + δ >= β + γ: |w| <= |b c| (1 + u) < 2^(β+γ+106) (1 + u),
    // so E(w) <= β + γ + 106 and 0 < |x| <= 2^(β+γ): x = ±2^(β+γ), E(w) =
    // β+γ+106, and |b c| >= |w| - |e| >= 2^(β+γ) (2^106 - 2^53) exceeds
    // |B C| 2^(β+γ) <= (2^53 - 1)^2 2^(β+γ): impossible. (ii) α + δ < β + γ:
    // |a d| >= |b c| - |x| >= 2^E(w) (1 - u) - 2^(E(w)-106) > 2^(E(w)-1) and
    // |a d| < 2^(α+δ+106), so E(w) <= α + δ + 106 and 0 < |x| <= 2^(α+δ):
    // x = ±2^(α+δ), E(w) = α+δ+106, and |a d| >= |b c| - |x| >= 2^E(w) -
    // 2^(E(w)-53) - 2^(E(w)-106) = 2^(α+δ) (2^106 - 2^53 - 1) exceeds (2^53 -
    // 1)^2 2^(α+δ) = (2^106 - 2^54 + 1) 2^(α+δ): impossible. If a d = 0 then
    // y = -w is a double, f = y, and the argument is not needed; if b c = 0,
    // w = e = 0 and r = fl(a d) has its sign. ∎ (|b c| >= |w| - |e| uses
    // |w| >= 2^E(w) and |e| <= 2^(E(w)-53).)
    // r = 0 (det T = 0) is left undecided: the exact stage and SoS decide.
    if (w == nullptr && ((t[0].l == 0.0) & (t[1].l == 0.0) & (t[2].l == 0.0) & (t[3].l == 0.0))) {
      const double wv = t[1].h * t[2].h;
      const double e = fused_multiply_add(t[1].h, t[2].h, -wv);
      const double f = fused_multiply_add(t[0].h, t[3].h, -wv);
      const double r = f - e;
      return (r > 0.0) - (r < 0.0);
    }
  }
  constexpr double kPlain = dd_beta(N, false) * 0x1p-106;
  constexpr double kLifted = dd_beta(N, true) * 0x1p-106;
  const double c = w ? kLifted : kPlain;
  const double per = det_by_minors<N, Mag>(m).v;  // (det_small for N <= 4)
  const V det = det_by_minors<N, V>(t);
  const double bound = (c * per + std::fabs(det.l) + 0x1p-1072) * (1.0 + 0x1p-40);
  if (det.h > bound) return 1;
  if (-det.h > bound) return -1;
  return 0;
}

}  // namespace flipflop::pred

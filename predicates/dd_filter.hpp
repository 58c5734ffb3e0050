// dd_filter.hpp — the double-double filter with an a-priori error bound: the
// stage of the default path (staged.hpp) after the static and semi-static
// filters for k = 3..5 points (orient2d/3d/4d, power2d/3d). Near-degenerate
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

// +1 / -1 when certain; 0 when undecided; 2 when an input value lies outside
// the window (the caller's other filters and exact stages decide). `window`:
// the caller knows every input value to lie in the window
// (StaticFilter::dd_window() of the input), and the per-call check is skipped.
// Fma: dd_two_product's choice; with it, orient2d (K = 3, plain) whose four
// differences are exact (every Two_Diff tail 0) is decided by Kahan's 2 x 2
// determinant below instead.
template <int K, bool Fma = false>
FF_HD FF_FORCEINLINE int dd_filter_sign(const double* const* p, const double* w, bool window = false) {
  static_assert(K >= 3 && K <= 5, "the double-double filter serves k = 3..5");
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
  const double per = det_small<N, Mag>(m).v;
  const V det = det_small<N, V>(t);
  const double bound = (c * per + std::fabs(det.l) + 0x1p-1072) * (1.0 + 0x1p-40);
  if (det.h > bound) return 1;
  if (-det.h > bound) return -1;
  return 0;
}

}  // namespace flipflop::pred

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
// 0 or 2^-150 <= |v| < 2^150 (checked here, NaN and infinities fail the
// test). Then Range::fits(D) of exact_expansion.hpp holds for every degree
// D <= 5 (|v| < 2^150: E <= 150, D (E + 1) <= 755 <= 950; the lowest set bit
// of a double >= 2^-150 is >= 2^-202, D (-202) >= -1074), which is err_dd.hpp's
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
// Header-only and __host__ __device__; no heap, no recursion; stack: (K-1)^2
// DD values and magnitudes (24 bytes each) and the minors of det_by_minors
// (K = 5: under 1 KB).
#pragma once

#include <cmath>

#include "predicates/err_dd.hpp"
#include "predicates/lambda_filter.hpp"

namespace flipflop::pred {

// A double-double value without a running bound (the bound is a priori).
struct DD {
  double h = 0.0, l = 0.0;
  FF_HD DD() = default;
  FF_HD static DD difference(double x, double y) {
    DD r;
    xp::Dbl::two_sum(x, -y, r.h, r.l);
    return r;
  }
};
FF_HD inline DD operator+(const DD& a, const DD& b) {
  DD r;
  double t2 = 0.0, t3 = 0.0;
  dd_add_parts(a.h, a.l, b.h, b.l, r.h, r.l, t2, t3);
  return r;
}
FF_HD inline DD operator-(const DD& a) {
  DD r;
  r.h = -a.h;
  r.l = -a.l;
  return r;
}
FF_HD inline DD operator-(const DD& a, const DD& b) { return a + (-b); }
FF_HD inline DD operator*(const DD& a, const DD& b) {
  DD r;
  double c1 = 0.0, c2 = 0.0, c = 0.0, t3 = 0.0;
  dd_mul_parts(a.h, a.l, b.h, b.l, r.h, r.l, c1, c2, c, t3);
  return r;
}

// A magnitude: det_by_minors<N, Mag> on the entry magnitudes is their
// permanent (every sign of the Laplace expansion taken as +).
struct Mag {
  double v = 0.0;
};
FF_HD inline Mag operator+(Mag a, Mag b) { return {a.v + b.v}; }
FF_HD inline Mag operator-(Mag a, Mag b) { return {a.v + b.v}; }
FF_HD inline Mag operator-(Mag a) { return a; }
FF_HD inline Mag operator*(Mag a, Mag b) { return {a.v * b.v}; }

// β of the derivation above for det_by_minors<N> (m = N - 1 coordinates per
// row when lifted).
FF_HD constexpr int dd_beta(int n, bool lifted) {
  int b = 0;
  for (int r = 2; r <= n; ++r) b += 5 + 4 * r;
  return lifted ? b + 9 + 4 * (n - 1) : b;
}

// +1 / -1 when certain; 0 when undecided; 2 when an input value lies outside
// the window (the caller's other filters and exact stages decide).
template <int K>
FF_HD inline int dd_filter_sign(const double* const* p, const double* w) {
  static_assert(K >= 3 && K <= 5, "the double-double filter serves k = 3..5");
  constexpr int N = K - 1;
  constexpr double kHi = 0x1p150, kLo = 0x1p-150;
  const int ncoord = w ? N - 1 : N;
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
  DD t[N * N];
  Mag m[N * N];  // entry magnitudes from the heads: |d.h|, Σ d.h^2 + |Δw.h|
  const double* base = p[K - 1];
  for (int i = 0; i < N; ++i) {
    double lmag = 0.0;
    for (int j = 0; j < ncoord; ++j) {
      const DD d = DD::difference(p[i][j], base[j]);
      t[i * N + j] = d;
      m[i * N + j].v = std::fabs(d.h);
      lmag += d.h * d.h;
    }
    if (w) {
      DD lift = -DD::difference(w[i], w[K - 1]);
      lmag += std::fabs(lift.h);
      for (int j = 0; j < ncoord; ++j) lift = lift + t[i * N + j] * t[i * N + j];
      t[i * N + N - 1] = lift;
      m[i * N + N - 1].v = lmag;
    }
  }
  constexpr double kPlain = dd_beta(N, false) * 0x1p-106;
  constexpr double kLifted = dd_beta(N, true) * 0x1p-106;
  const double c = w ? kLifted : kPlain;
  const double per = det_by_minors<N, Mag>(m).v;
  const DD det = det_by_minors<N, DD>(t);
  const double bound = (c * per + std::fabs(det.l) + 0x1p-1072) * (1.0 + 0x1p-40);
  if (det.h > bound) return 1;
  if (-det.h > bound) return -1;
  return 0;
}

}  // namespace flipflop::pred

// err_double.hpp — a double together with a proven bound on its absolute error.
//
// This is the floating-point filter behind every filtered predicate of flipflop
// (a "running error bound", the dynamic variant of Shewchuk's forward error
// analysis, [She97] §4). Each value carries `v`, the computed double, and `e`,
// an upper bound on |V - v| where V is the exact real value of the expression.
//
// Rules (IEEE binary64, round to nearest, u = 2^-53, eta = 2^-1074):
//   * an input double is exact:                         e = 0
//   * a ± b:  v = fl(a.v ± b.v)
//             |V - v| <= a.e + b.e + u|v|                (rounding of the sum)
//   * a * b:  v = fl(a.v * b.v)
//             |AB - a.v b.v| <= |a.v| b.e + |b.v| a.e + a.e b.e
//             plus the rounding u|v| of the product.
//   * a / b:  only when |b.v| > b.e (then B != 0, of b.v's sign); else
//             e = inf (undecided). v = fl(a.v / b.v) and
//             |A/B - a.v/b.v| = |(A - a.v) b.v - a.v (B - b.v)| / |B b.v|
//                             <= (a.e + |a.v / b.v| b.e) / (|b.v| - b.e),
//             with |a.v / b.v| taken as |v| (one more rounding of the bound),
//             plus the rounding u|v| of the quotient. Gaussian elimination
//             in ErrDouble (lambda_filter.hpp, det_gauss_rt) uses it.
//   * underflow: a result in the subnormal range may be off by up to eta/2 in
//     absolute terms, where the relative bound u|v| does not hold; every
//     operation therefore adds 4*eta (also covering underflow inside the bound
//     products themselves).
//   * exact zeros stay exact (e = 0): a ± b with a.e = b.e = 0 and v = 0 (two
//     doubles whose rounded sum is 0 have the exact sum 0: a non-zero sum in
//     the subnormal range is representable, hence exact), and a * b with one
//     factor an exact 0 and v = 0 (the other factor finite: an infinite or
//     NaN one makes v NaN, and the rule does not apply). Without this rule a
//     difference of equal coordinates (every lattice, and every translated
//     row of itself) carried the allowance 4*eta, a subnormal, and every
//     product with it took a floating-point assist (about 100 cycles each on
//     x86): the instant flip's moving model spent 2.5 us a call there.
//   * the bound is itself computed in floating point from non-negative terms;
//     each of its operations can round down by a factor (1-u). A sign decision
//     multiplies the final bound by (1 + 2^-40), which covers more than 2^12
//     such roundings, far beyond the longest expression used (a 7x7 Laplace
//     expansion).
//   * overflow: an infinite or NaN value makes `sign_if_certain` answer 0
//     ("uncertain"), because |v| > e fails for NaN and for e = inf.
//
// The sign is certain when |v| > e * (1 + 2^-40): then V lies in [v - e, v + e],
// which does not contain 0. Otherwise the caller falls back to exact arithmetic.
//
// Header-only and __host__ __device__, so that the CUDA kernels and their OpenMP
// build share it (DESIGN.md, "The GPU").
#pragma once

#include <cmath>

#if defined(__CUDACC__)
#define FF_HD __host__ __device__
#else
#define FF_HD
#endif
// FF_DEVICE_NOINLINE: a function the device calls rather than inlines (the
// exact stage of the predicates: rarely reached, large; inlined into every
// kernel that calls a predicate it multiplies ptxas' work and the kernels'
// code). Host code is unaffected.
#if defined(__CUDA_ARCH__)
#define FF_DEVICE_NOINLINE __noinline__
#else
#define FF_DEVICE_NOINLINE
#endif
// FF_FORCEINLINE: always inlined by the host compilers (GCC, clang). The
// FMA entry points of predicates.cpp compile the double-double filter inside
// a function with __attribute__((target("fma"))): only code inlined there is
// compiled with the fused multiply-add, so the filter's pieces must be
// inlined (an out-of-line copy would be compiled for the default target and
// call the library's fma). Plain inline in CUDA compilations.
#if defined(__CUDACC__) || !defined(__GNUC__)
#define FF_FORCEINLINE inline
#else
#define FF_FORCEINLINE inline __attribute__((always_inline))
#endif

namespace flipflop::pred {

struct ErrDouble {
  double v = 0.0;  // computed value
  double e = 0.0;  // bound on the absolute error of v

  static constexpr double kU = 0x1p-53;      // unit roundoff
  static constexpr double kEta4 = 0x1p-1072; // 4 * smallest subnormal

  ErrDouble() = default;  // host and device: defaulted
  FF_HD explicit ErrDouble(double x) : v(x), e(0.0) {}
  FF_HD ErrDouble(double x, double err) : v(x), e(err) {}
};

FF_HD inline ErrDouble operator+(ErrDouble a, ErrDouble b) {
  double v = a.v + b.v;
  const double e = a.e + b.e + std::fabs(v) * ErrDouble::kU + ErrDouble::kEta4;
  return {v, v == 0 && a.e == 0 && b.e == 0 ? 0.0 : e};  // exact zero (header)
}

FF_HD inline ErrDouble operator-(ErrDouble a, ErrDouble b) {
  double v = a.v - b.v;
  const double e = a.e + b.e + std::fabs(v) * ErrDouble::kU + ErrDouble::kEta4;
  return {v, v == 0 && a.e == 0 && b.e == 0 ? 0.0 : e};  // exact zero (header)
}

FF_HD inline ErrDouble operator-(ErrDouble a) { return {-a.v, a.e}; }

FF_HD inline ErrDouble operator*(ErrDouble a, ErrDouble b) {
  double v = a.v * b.v;
  double e = std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e;
  const bool exact_zero = v == 0 && ((a.v == 0 && a.e == 0) || (b.v == 0 && b.e == 0));  // (header)
  return {v, exact_zero ? 0.0 : e + std::fabs(v) * ErrDouble::kU + ErrDouble::kEta4};
}

FF_HD inline ErrDouble operator/(ErrDouble a, ErrDouble b) {
  const double v = a.v / b.v;
  const double den = std::fabs(b.v) - b.e;
  if (!(den > 0.0)) return {v, HUGE_VAL};  // B may be 0 (or NaN): undecided
  const double e = (a.e + std::fabs(v) * b.e) / den;
  return {v, e + std::fabs(v) * ErrDouble::kU + ErrDouble::kEta4};
}

// +1 / -1 when the sign of the exact value is certain, 0 when it is not.
FF_HD inline int sign_if_certain(ErrDouble a) {
  double bound = a.e * (1.0 + 0x1p-40);
  if (a.v > bound) return 1;
  if (-a.v > bound) return -1;
  return 0;  // also for NaN and infinities
}

}  // namespace flipflop::pred

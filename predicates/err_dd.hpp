// err_dd.hpp — a double-double value together with a proven bound on its
// absolute error: the running error bound of err_double.hpp carried one
// precision further. The stage of the predicates it serves (xp::lambda_sign_dd,
// exact_expansion.hpp) sits between the dynamic filter (ErrDouble, errors of
// order u |terms|) and the exact expansion stage: on near-degenerate input
// (1-3 ulp off a degenerate set) det Λ is of order u times its terms, below
// what any double filter resolves, but far above the errors of order u^2
// |terms| left here, so this stage decides such calls without building an
// exact expansion ([She97] §4.3 reaches the same point with its stage C, a
// first-order tail correction; here the correction is carried through every
// operation, which also covers the lifted column, whose exact form made
// lifted_adaptive the cost of the near-degenerate power tests).
//
// A value is h + l (the exact real sum of two doubles, |l| <= u |h| after
// every operation) and e, an upper bound on |V - (h + l)| where V is the exact
// real value of the expression. Notation: u = 2^-53, eta = 2^-1074; for a
// rounded operation, |fl(x) - x| <= u |fl(x)| (round to nearest: the error is
// at most half an ulp of the result, and ulp(y)/2 <= u |y| for normal y).
//
// Precondition (checked by the caller, xp::lambda_exact): every input is in
// the double window of exact_expansion.hpp for the degree of the expression.
// There every value computed below is a multiple of 2^-1074 (rounding keeps
// multiples of a power of two; a product of values of degrees a and b is a
// multiple of 2^((a + b) L-), a + b <= D), so two_product is exact, a rounded
// product or sum whose result is subnormal is exact, and nothing overflows
// (|values| < 2^973): the relative rule above holds for every operation on
// values. Outside it the caller does not call this stage.
//
// Rules, with a = a.h + a.l, b = b.h + b.l and A, B the exact values
// (|A - a| <= a.e, |B - b| <= b.e):
//   * exact input (a double, or an exact two_sum / two_product pair): e = 0.
//   * a + b:  (s, t) = two_sum(a.h, b.h)          s + t = a.h + b.h exactly
//             t2 = fl(a.l + b.l),  t3 = fl(t + t2),  (h, l) = two_sum(s, t3)
//             h + l - (a + b) = (t3 - (t + t2)) + (t2 - (a.l + b.l)):
//             e = a.e + b.e + u (|t2| + |t3|).
//   * a * b:  (p, q) = two_product(a.h, b.h)       p + q = a.h b.h exactly
//             c1 = fl(a.h b.l), c2 = fl(a.l b.h), c = fl(c1 + c2),
//             t3 = fl(q + c),  (h, l) = two_sum(p, t3); a.l b.l is dropped:
//             h + l - ab = (t3 - (q + c)) + (c - (c1 + c2)) + (c1 - a.h b.l)
//                          + (c2 - a.l b.h) - a.l b.l, and
//             |AB - ab| <= |a| b.e + |b| a.e + a.e b.e, |a| <= |a.h| + |a.l|:
//             e = (|a.h| + |a.l|) b.e + (|b.h| + |b.l|) a.e + a.e b.e
//                 + |a.l| |b.l| + u (|c1| + |c2| + |c| + |t3|).
//   * the bound is computed in floating point from non-negative terms: each
//     of its operations rounds down by at most a factor (1 - u), or by at
//     most eta/2 absolutely where its result is subnormal (u |x| may be). The
//     sum adds 4 eta (its bound takes 5 operations), the product 8 eta (at
//     most 15), covering the absolute losses; a sign decision multiplies the
//     final bound by (1 + 2^-40), which covers more than 2^12 relative
//     roundings along any path of the bound's expression, far beyond the
//     longest used (det_by_minors<7>: a few hundred).
//
// Sign: V lies within e of h + l, and |h + l| >= |h| - |l|; the sign of V is
// that of h when |h| > (e + |l|)(1 + 2^-40). NaN never passes the test.
//
// Header-only and __host__ __device__ (the CUDA kernels and their OpenMP build
// share it with the host), no heap, no recursion.
#pragma once

#include <cmath>

#include "predicates/expansion.hpp"

namespace flipflop::pred {

struct ErrDD {
  double h = 0.0, l = 0.0;  // value h + l
  double e = 0.0;           // bound on the absolute error of h + l

  static constexpr double kU = 0x1p-53;
  static constexpr double kEta4 = 0x1p-1072;  // 4 eta
  static constexpr double kEta8 = 0x1p-1071;  // 8 eta

  ErrDD() = default;  // host and device: defaulted
  FF_HD explicit ErrDD(double x) : h(x) {}
  // The exact difference x - y (two_sum: e = 0).
  FF_HD static ErrDD difference(double x, double y) {
    ErrDD r;
    xp::Dbl::two_sum(x, -y, r.h, r.l);
    return r;
  }
};

// The value parts of a + b and a * b (the rules above), shared with the
// a-priori-bounded DD of dd_filter.hpp: (h, l) and the rounded intermediates
// the running bound is made of.
FF_HD FF_FORCEINLINE void dd_add_parts(double ah, double al, double bh, double bl, double& h, double& l,
                               double& t2, double& t3) {
  double s = 0.0, t = 0.0;
  xp::Dbl::two_sum(ah, bh, s, t);
  t2 = al + bl;
  t3 = t + t2;
  xp::Dbl::two_sum(s, t3, h, l);
}
FF_HD inline void dd_mul_parts(double ah, double al, double bh, double bl, double& h, double& l,
                               double& c1, double& c2, double& c, double& t3) {
  double p = 0.0, q = 0.0;
  xp::Dbl::two_product(ah, bh, p, q);
  c1 = ah * bl;
  c2 = al * bh;
  c = c1 + c2;
  t3 = q + c;
  xp::Dbl::two_sum(p, t3, h, l);
}

FF_HD inline ErrDD operator+(const ErrDD& a, const ErrDD& b) {
  double t2 = 0.0, t3 = 0.0;
  ErrDD r;
  dd_add_parts(a.h, a.l, b.h, b.l, r.h, r.l, t2, t3);
  r.e = a.e + b.e + ErrDD::kU * (std::fabs(t2) + std::fabs(t3)) + ErrDD::kEta4;
  return r;
}

FF_HD inline ErrDD operator-(const ErrDD& a) {
  ErrDD r = a;
  r.h = -a.h;
  r.l = -a.l;
  return r;
}

FF_HD inline ErrDD operator-(const ErrDD& a, const ErrDD& b) { return a + (-b); }

FF_HD inline ErrDD operator*(const ErrDD& a, const ErrDD& b) {
  double c1 = 0.0, c2 = 0.0, c = 0.0, t3 = 0.0;
  ErrDD r;
  dd_mul_parts(a.h, a.l, b.h, b.l, r.h, r.l, c1, c2, c, t3);
  const double ma = std::fabs(a.h) + std::fabs(a.l), mb = std::fabs(b.h) + std::fabs(b.l);
  r.e = (ma * b.e + mb * a.e + a.e * b.e) + std::fabs(a.l) * std::fabs(b.l) +
        ErrDD::kU * ((std::fabs(c1) + std::fabs(c2)) + (std::fabs(c) + std::fabs(t3))) +
        ErrDD::kEta8;
  return r;
}

// +1 / -1 when the sign of the exact value is certain, 0 when it is not.
FF_HD inline int sign_if_certain(const ErrDD& a) {
  const double bound = (a.e + std::fabs(a.l)) * (1.0 + 0x1p-40);
  if (a.h > bound) return 1;
  if (-a.h > bound) return -1;
  return 0;
}

}  // namespace flipflop::pred

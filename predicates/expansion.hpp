// expansion.hpp — exact arithmetic on floating-point expansions (Shewchuk,
// "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", 1997 [She97]; thesis ref [She97]). No heap, no recursion, no
// GMP: header-only and __host__ __device__.
//
// An expansion is a sum of components x_1 + ... + x_n, sorted by increasing
// magnitude, pairwise nonoverlapping (the lowest set bit of each component is
// above the highest set bit of the previous one); its value is exact. The
// algorithms below are Shewchuk's, line by line:
//   two_sum, fast_two_sum, two_product       [She97] Thm 6, 7, 18 (Dekker/FMA)
//   sum_zeroelim      fast_expansion_sum_zeroelim   [She97] Fig. 8, Thm 13
//   scale_zeroelim    scale_expansion_zeroelim      [She97] Fig. 10, Thm 19
//   compress          compress                      [She97] Fig. 13, Thm 23
// (Shewchuk's code reads one element past the end of its inputs in the sum;
// the loops here do not.)
//
// The algorithms are written once, for two component types (an "arithmetic"
// policy A):
//   Dbl  components are doubles. Exact as long as no operation overflows and
//        no product's rounding error underflows — the "window" conditions that
//        exact_expansion.hpp checks before choosing it.
//   XDbl components are (m, e) pairs, value m 2^e, 1/2 <= |m| < 1 or m = 0,
//        with an int exponent: a binary64 system with 53-bit significands and
//        an unbounded exponent range (see XDbl below). Shewchuk's theorems
//        assume exactly such a system (p-bit, round-to-nearest-even, no
//        overflow or underflow), so they hold for XDbl on every input; it is
//        the exact stage for inputs outside the window (1e±300, subnormals).
//
// Length bound (used to size every buffer). Lemma: let every component of an
// expansion be a multiple of 2^L and let its value and all partial sums of its
// components be below 2^H in magnitude. Then compress returns at most
// (H - L) / 52 + 2 components.
// Proof. compress' first pass walks from the largest component down, keeping a
// running sum Q; when an addition Q + e_i rounds (q != 0) it emits
// g = fl(Q + e_i) and continues with Q = q, |q| <= ulp(g)/2. At that moment
// 2^lsb(e_i) < ulp(g): otherwise Q (a multiple of 2^lsb(e_{i+1}), which
// exceeds 2^msb(e_i)) and e_i are both multiples of ulp(g), so is their sum,
// and the rounding error q, |q| <= ulp(g)/2, would be 0. The components below
// e_i sum to less than 2^lsb(e_i) <= ulp(g)/2 (nonoverlapping). So everything
// after g — q plus the rest — is less than ulp(g) in magnitude, and every
// later emitted value, a rounded partial sum of it, is at most ulp(g) <=
// 2^-52 |g|. Emitted magnitudes thus fall by 2^52 per component, from below
// 2^(H+1) to at least 2^L (all are multiples of 2^L: two_sum keeps the grid):
// at most (H + 1 - L)/52 + 1 of them. The second pass only merges. ∎
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "predicates/err_double.hpp"  // FF_HD

namespace flipflop::pred::xp {

// ---------------------------------------------------------------------------
// Dbl: double components.
// ---------------------------------------------------------------------------
struct Dbl {
  using T = double;
  static constexpr bool kExtended = false;

  FF_HD static T from_double(double x) { return x; }
  FF_HD static T zero() { return 0.0; }
  FF_HD static bool is_zero(T a) { return a == 0.0; }
  FF_HD static bool is_one(T a) { return a == 1.0; }
  FF_HD static T neg(T a) { return -a; }
  FF_HD static int sign(T a) { return (a > 0.0) - (a < 0.0); }
  // |a| < |b|
  FF_HD static bool abs_less(T a, T b) { return std::fabs(a) < std::fabs(b); }

  // [She97] Thm 7 (Knuth): x + y = a + b exactly, x = fl(a + b).
  FF_HD static void two_sum(T a, T b, T& x, T& y) {
    x = a + b;
    const double bv = x - a;
    const double av = x - bv;
    const double br = b - bv;
    const double ar = a - av;
    y = ar + br;
  }
  // [She97] Thm 6 (Dekker): the same when |a| >= |b| (or a = 0).
  FF_HD static void fast_two_sum(T a, T b, T& x, T& y) {
    x = a + b;
    const double bv = x - a;
    y = b - bv;
  }
  // [She97] Thm 18: x + y = a b exactly, x = fl(a b). With a fused multiply-
  // add the error is fma(a, b, -x); otherwise Dekker's product with
  // Veltkamp's split (splitter 2^27 + 1; valid while |a|, |b| < 2^995).
  FF_HD static void two_product(T a, T b, T& x, T& y) {
    x = a * b;
#if defined(__CUDA_ARCH__) || defined(__FMA__)
    y = fma(a, b, -x);
#else
    constexpr double kSplitter = 134217729.0;  // 2^27 + 1
    double c = kSplitter * a;
    const double abig = c - a;
    const double ahi = c - abig;
    const double alo = a - ahi;
    c = kSplitter * b;
    const double bbig = c - b;
    const double bhi = c - bbig;
    const double blo = b - bhi;
    const double err1 = x - ahi * bhi;
    const double err2 = err1 - alo * bhi;
    const double err3 = err2 - ahi * blo;
    y = alo * blo - err3;
#endif
  }
};

// ---------------------------------------------------------------------------
// XDbl: components with an unbounded (int) exponent.
// ---------------------------------------------------------------------------
// No default member initializers: a trivial default constructor leaves the
// large component buffers of the exact stage (MinorLaplace's levels: 182 KB
// of XD at K = 6) uninitialized, as their double counterparts are; every
// component is written before it is read, and XDbl::zero() (T{}) is the
// value-initialized 0. With the initializers, zeroing those buffers took
// 60 % of MinorLaplace<XDbl, 6> on a perturbed grid.
struct XD {
  double m;  // 0, or 1/2 <= |m| < 1
  int e;     // value m 2^e
};

struct XDbl {
  using T = XD;
  static constexpr bool kExtended = true;

  // v 2^e as (m, e): frexp by its bits for a normal v (every value two_sum and
  // two_product below produce: they are >= 2^-114 in magnitude), the library
  // frexp for a subnormal input value.
  FF_HD static T norm(double v, int e) {
    T r{};
    if (v == 0.0) return r;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased == 0) {
      int ex = 0;
      r.m = std::frexp(v, &ex);  // exact
      r.e = e + ex;
      return r;
    }
    bits = (bits & ~(std::uint64_t{0x7ff} << 52)) | (std::uint64_t{1022} << 52);
    std::memcpy(&r.m, &bits, sizeof bits);  // same significand, in [1/2, 1)
    r.e = e + biased - 1022;
    return r;
  }
  // 2^d for -1022 <= d <= 1023 (a normal power of two, built from its bits)
  FF_HD static double pow2(int d) {
    const std::uint64_t bits = static_cast<std::uint64_t>(d + 1023) << 52;
    double r = 0.0;
    std::memcpy(&r, &bits, sizeof bits);
    return r;
  }
  FF_HD static T from_double(double x) { return norm(x, 0); }
  FF_HD static T zero() { return T{}; }
  FF_HD static bool is_zero(T a) { return a.m == 0.0; }
  FF_HD static bool is_one(T a) { return a.m == 0.5 && a.e == 1; }
  FF_HD static T neg(T a) { return T{-a.m, a.e}; }
  FF_HD static int sign(T a) { return (a.m > 0.0) - (a.m < 0.0); }
  FF_HD static bool abs_less(T a, T b) {
    if (b.m == 0.0) return false;
    if (a.m == 0.0) return true;
    if (a.e != b.e) return a.e < b.e;
    return std::fabs(a.m) < std::fabs(b.m);
  }

  // Exact sum in the unbounded-exponent system, rounded to nearest-even like
  // a binary64 addition. Let E be the larger exponent. If the smaller operand
  // is below 2^(E-60) it is less than half an ulp of the larger one (>= 2^(E-1),
  // ulp 2^(E-53)): fl(a + b) is the larger operand and the error is the
  // smaller one. Otherwise both are scaled by 2^-E (exact: they become
  // doubles in [2^-61, 1), normal), added by two_sum in binary64 — no
  // overflow, no underflow, so this is the correctly rounded sum and its
  // exact error — and scaled back.
  FF_HD static void two_sum(T a, T b, T& x, T& y) {
    if (a.m == 0.0) {
      x = b;
      y = T{};
      return;
    }
    if (b.m == 0.0) {
      x = a;
      y = T{};
      return;
    }
    const int E = a.e > b.e ? a.e : b.e;
    const int lo = a.e > b.e ? b.e : a.e;
    if (lo < E - 60) {
      const bool a_big = a.e > b.e;
      x = a_big ? a : b;
      y = a_big ? b : a;
      return;
    }
    const double am = a.m * pow2(a.e - E), bm = b.m * pow2(b.e - E);  // exact: >= 2^-61
    double s = 0.0, t = 0.0;
    Dbl::two_sum(am, bm, s, t);
    x = norm(s, E);
    y = norm(t, E);
  }
  FF_HD static void fast_two_sum(T a, T b, T& x, T& y) { two_sum(a, b, x, y); }
  // Significands in [1/4, 1): their product and its exact error (>= 2^-108,
  // normal) are binary64 values; exponents add.
  FF_HD static void two_product(T a, T b, T& x, T& y) {
    if (a.m == 0.0 || b.m == 0.0) {
      x = y = T{};
      return;
    }
    double p = 0.0, err = 0.0;
    Dbl::two_product(a.m, b.m, p, err);
    x = norm(p, a.e + b.e);
    y = norm(err, a.e + b.e);
  }
};

// ---------------------------------------------------------------------------
// Shewchuk's algorithms on either component type. Lengths are ints; every
// output array must hold the documented number of components.
// ---------------------------------------------------------------------------

// h = e + f; h holds elen + flen components. [She97] Fig. 8
// (fast_expansion_sum_zeroelim): merges by magnitude and accumulates with
// two_sum; zero components are eliminated, a zero result is one component 0.
template <class A>
FF_HD inline int sum_zeroelim(int elen, const typename A::T* e, int flen, const typename A::T* f,
                              typename A::T* h) {
  using T = typename A::T;
  int ei = 0, fi = 0, hi = 0;
  T Q, Qnew, hh;
  // the smaller-magnitude head goes first
  if (A::abs_less(f[0], e[0])) {
    Q = f[fi++];
  } else {
    Q = e[ei++];
  }
  while (ei < elen && fi < flen) {
    if (A::abs_less(f[fi], e[ei])) {
      A::two_sum(Q, f[fi++], Qnew, hh);
    } else {
      A::two_sum(Q, e[ei++], Qnew, hh);
    }
    Q = Qnew;
    if (!A::is_zero(hh)) h[hi++] = hh;
  }
  while (ei < elen) {
    A::two_sum(Q, e[ei++], Qnew, hh);
    Q = Qnew;
    if (!A::is_zero(hh)) h[hi++] = hh;
  }
  while (fi < flen) {
    A::two_sum(Q, f[fi++], Qnew, hh);
    Q = Qnew;
    if (!A::is_zero(hh)) h[hi++] = hh;
  }
  if (!A::is_zero(Q) || hi == 0) h[hi++] = Q;
  return hi;
}

// h = b e; h holds 2 elen components. [She97] Fig. 10
// (scale_expansion_zeroelim).
template <class A>
FF_HD inline int scale_zeroelim(int elen, const typename A::T* e, typename A::T b,
                                typename A::T* h) {
  using T = typename A::T;
  int hi = 0;
  T Q, hh, product1, product0, sum;
  A::two_product(e[0], b, Q, hh);
  if (!A::is_zero(hh)) h[hi++] = hh;
  for (int i = 1; i < elen; ++i) {
    A::two_product(e[i], b, product1, product0);
    A::two_sum(Q, product0, sum, hh);
    if (!A::is_zero(hh)) h[hi++] = hh;
    A::fast_two_sum(product1, sum, Q, hh);
    if (!A::is_zero(hh)) h[hi++] = hh;
  }
  if (!A::is_zero(Q) || hi == 0) h[hi++] = Q;
  return hi;
}

// In place: e becomes a nonadjacent expansion of the same value whose largest
// component approximates it within one ulp. [She97] Fig. 13 (compress).
// Returns the new length (see the length bound at the top of this file).
template <class A>
FF_HD inline int compress(int elen, typename A::T* e) {
  using T = typename A::T;
  int bottom = elen - 1;
  T Q = e[bottom], Qnew, q;
  for (int i = elen - 2; i >= 0; --i) {
    A::fast_two_sum(Q, e[i], Qnew, q);
    if (!A::is_zero(q)) {
      e[bottom--] = Qnew;
      Q = q;
    } else {
      Q = Qnew;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < elen; ++i) {
    A::fast_two_sum(e[i], Q, Qnew, q);
    if (!A::is_zero(q)) e[top++] = q;
    Q = Qnew;
  }
  e[top] = Q;
  return top + 1;
}

// Sign of an expansion: the sign of its largest (last) component.
template <class A>
FF_HD inline int sign_of(int elen, const typename A::T* e) {
  return A::sign(e[elen - 1]);
}

// A fixed-capacity expansion.
template <class A, int Cap>
struct Exp {
  using T = typename A::T;
  int n = 1;
  T c[Cap];
  FF_HD Exp() { c[0] = A::zero(); }
  FF_HD bool zero() const { return n == 1 && A::is_zero(c[0]); }
  FF_HD int sign() const { return sign_of<A>(n, c); }
};

}  // namespace flipflop::pred::xp

// exact_expansion.hpp — the exact stage of every predicate: the sign of
// det Λ (lambda_filter.hpp), and its Simulation-of-Simplicity sign
// (predicates.hpp, "The perturbation"), in expansion arithmetic
// (expansion.hpp). No heap, no recursion, no GMP; header-only,
// __host__ __device__.
//
// Λ is evaluated as it stands (raw coordinates, lifted heights |x|^2 - w
// computed exactly as expansions, the 1-column): its determinant and every
// minor the perturbation asks for are then determinants of submatrices of the
// same matrix. A minor is expanded by Laplace over column subsets, row by row
// (as det_by_minors, one level at a time), products of expansions by
// scale_zeroelim, sums by sum_zeroelim, and every intermediate result is
// compressed so that its length obeys the bound of expansion.hpp.
//
// ============================================================================
// Which arithmetic: the window (correct over the whole double range)
// ============================================================================
// Let D be the degree of det Λ in the input values (k - 1 coordinate columns
// of degree 1; a lifted column counts 2), E the largest exponent with
// |v| < 2^E over all values v of the call (coordinates, weights), and L the
// exponent of the lowest set bit over all of them; E+ = max(E, 0),
// L- = min(L, 0).
//   * Grid: every entry of Λ is a multiple of 2^(2 L-) (2^(L-) for
//     coordinates), so every product of at most D factors, every minor and
//     every expansion component built from them is a multiple of 2^(D L-)
//     (two_sum and two_product keep a common grid: rounding a multiple of a
//     power of two to 53 bits gives a multiple of it).
//   * If D L- >= -1074, every such multiple is a binary64 value or rounds to
//     one with a representable error: a product's rounding error is a multiple
//     of 2^-1074 of at most 53 bits, so two_product is exact even where the
//     product is subnormal; sums are always exact (two_sum).
//   * If D (E+ + 1) <= 950, every entry (also a difference of two values, or
//     a lifted entry |x_i - x_k|^2 - (w_i - w_k)) is below 2^(2(E+ + 1) + 3),
//     every product of entries below 2^(D (E+ + 1) + 5), every sum of at most
//     8! of them and every partial sum inside the expansion algorithms below
//     2^(D (E+ + 1) + 23) <= 2^973: nothing overflows, and Veltkamp's split
//     (|x| < 2^995) is valid.
// Inside this window the double components (xp::Dbl) are exact; the lengths
// are then at most (973 + 1074)/52 + 2 < 42 (expansion.hpp, length bound):
// kCapD = 44. Outside it (1e±300 inputs, subnormals mixed with large values)
// the same algorithms run on xp::XDbl, whose exponent is unbounded: exact on
// every finite input. There H <= 1024 D + 23 and L >= -1074 D, so lengths
// are at most (2098 D + 23)/52 + 2: cap_x(D), D <= K + 1 for a K x K minor.
//
// Stack per call (bytes, the buffers below; K = number of rows):
//   Λ entries: K^2 entries of raw_entry_cap (K <= 5: 8 components; Dbl 8 B,
//   XDbl 16 B: 1.6 KB / 3.2 KB at K = 5); T of K + 1 points, K^2 entries of
//   entry_cap (8K - 6, Dbl at most 28: K = 4 3.6 KB / 6.7 KB). Laplace minors:
//   2 levels of C(K, K/2) expansions of minor_cap components — Dbl (44 x 8 B):
//   K = 4 4.3 KB, K = 5 7.1 KB, K = 8 50 KB; XDbl on the host
//   (cap_x(K+1) x 16 B): K = 4 39 KB, K = 5 78 KB, K = 8 820 KB (inside the
//   4 MB of a TBB or OpenMP worker; only inputs outside the double window get
//   there). XDbl on the device, permutations (MinorX): 7 cap_x(K+1) x 16 B
//   (K = 5: 27 KB). The SoS memo: 2^(2K-1) bytes for K <= 6 (K = 5: 512 B), 2.5 KB above.
//   On the device each expansion stage is a call of its own
//   (FF_DEVICE_NOINLINE: det_translated, sos_expansions, pulled_expansions,
//   mixed_expansions, the minors), so a thread's stack is the deepest chain
//   of calls, not the sum of every branch's buffers: the device compiler
//   gives every local array of a function its own slot. Measured (PTX local
//   depots along the deepest call chain, sm_90, one thread per call of
//   lambda_exact_sorted<K>): K = 3 25 KB, K = 4 32 KB, K = 5 40 KB, against
//   42, 91 and 122 KB with the stages inlined into one frame, 11-cap
//   permutation buffers and 50-component entries. The driver raises the
//   per-thread stack limit at launch to the deepest chain, and reserves it
//   for every thread the device can hold; a kernel runs the exact stage as a
//   separate pass over the few undecided calls (thesis §6.4.2, two_pass.cuh).
#pragma once

#include <cstddef>

#include <cstdint>
#include <cstring>
#if !defined(__CUDA_ARCH__)
#include <stdexcept>
#endif

#include "predicates/err_dd.hpp"
#include "predicates/expansion.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/near_lattice.hpp"
#include "predicates/static_filter.hpp"  // filter_detail::det_plain

namespace flipflop::pred::xp {

constexpr int kCapD = 44;
FF_HD constexpr int cap_x(int k) { return (2098 * k + 23) / 52 + 3; }
// Components of one entry of a k x k matrix: Λ of k points (raw) or T of
// k + 1 points (translated), K <= 8 points. Without compression an entry has
// at most as many components as the terms it sums (sum_zeroelim and compress
// never lengthen): raw coordinates and the 1-column 1, lifted |x|^2 - w
// <= 2(k-2) + 1 (13 at k = 8), centroid sum <= 8 (RationalPoint: at most 8
// points); translated differences <= 2, lifted |d|^2 - (w_i - w_k)
// <= 8(k-1) + 2 (each d_j^2 of a two-component difference <= 8; 50 at k = 7).
// Dbl compresses to the window's length bound (expansion.hpp): values below
// 2^(2(E+ + 1) + 3), grid 2^(2 L-), D >= 4 for a lifted entry:
// (1900/4 + 3 + 2148/4)/52 + 2 < 22 <= 28. XDbl has no window: the term count.
// entry_cap bounds both kinds (LambdaX's default), raw_entry_cap the raw Λ.
template <class A>
FF_HD constexpr int entry_cap(int k) {
  return A::kExtended || 8 * k - 6 < 28 ? 8 * k - 6 : 28;
}
template <class A>
FF_HD constexpr int raw_entry_cap(int k) {
  return 2 * k - 3 > 8 ? 2 * k - 3 : 8;
}

FF_HD inline int ctz64(std::uint64_t x) {
#if defined(__CUDA_ARCH__)
  return __ffsll(static_cast<long long>(x)) - 1;
#else
  return __builtin_ctzll(x);
#endif
}
FF_HD inline int clz64(std::uint64_t x) {
#if defined(__CUDA_ARCH__)
  return __clzll(static_cast<long long>(x));
#else
  return __builtin_clzll(x);
#endif
}
FF_HD FF_FORCEINLINE int bit_length(unsigned long long x) { return x == 0 ? 0 : 64 - clz64(x); }
// ceil(log2 k!) for k <= 11 (kMaxLambdaK rows): the factor of the minor
// bounds below (a function: a namespace-scope array is not usable in device
// code).
FF_HD constexpr int log2_factorial_ceil(int k) {
  return k <= 1    ? 0
         : k == 2  ? 1
         : k == 3  ? 3
         : k == 4  ? 5
         : k == 5  ? 7
         : k == 6  ? 10
         : k == 7  ? 13
         : k == 8  ? 16
         : k == 9  ? 19
         : k == 10 ? 22
                   : 26;
}
FF_HD inline int popcount32(unsigned x) {
#if defined(__CUDA_ARCH__)
  return __popc(x);
#else
  // SWAR popcount (no dependence on -mpopcnt)
  x = x - ((x >> 1) & 0x55555555u);
  x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
  x = (x + (x >> 4)) & 0x0f0f0f0fu;
  return static_cast<int>((x * 0x01010101u) >> 24);
#endif
}

// The next larger mask with the same number of set bits (Gosper's hack; s
// nonzero): the subsets of {0..r-1} of one size in ascending order, without
// scanning all 2^r masks (DoublePrefix, MinorLaplace).
FF_HD FF_FORCEINLINE unsigned next_same_popcount(unsigned s) {
  const unsigned t = s | (s - 1u);
  return (t + 1u) | (((~t & (0u - ~t)) - 1u) >> (ctz64(s) + 1));
}

// Lowest set bit 2^low and bound |v| < 2^hi of a finite nonzero double
// (Range::add, int_lambda); false for inf and NaN.
FF_HD FF_FORCEINLINE bool bit_span(double v, int& low, int& hi) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0x7ff) return false;
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0) {  // subnormal: mant 2^-1074
    hi = 64 - clz64(mant) - 1074;
    low = ctz64(mant) - 1074;
  } else {
    mant |= std::uint64_t{1} << 52;
    hi = biased - 1022;
    low = biased - 1075 + ctz64(mant);
  }
  return true;
}

// Exponent range of the values of one call (see the window above).
struct Range {
  int ehi = -100000;  // |v| < 2^ehi for every v
  int llo = 100000;   // every v is a multiple of 2^llo
  bool finite = true;
  FF_HD void add(double v) {
    if (v == 0.0) return;
    int e = 0, low = 0;
    if (!bit_span(v, low, e)) {  // inf or NaN: no exact sign
      finite = false;
      return;
    }
    if (e > ehi) ehi = e;
    if (low < llo) llo = low;
  }
  // Inside the window for a determinant of degree D?
  FF_HD bool fits(int degree) const {
    const int ep = ehi > 0 ? ehi : 0;
    const int lm = llo < 0 ? llo : 0;
    return degree * (ep + 1) <= 950 && degree * lm >= -1074;
  }
};

// Inputs must be finite. The filters never decide on an infinite or NaN value
// (their tests fail on them), so the exact stage is where one arrives: on the
// host it throws, as the GMP stage does; on the device (no exceptions) the
// precondition is documented by the callers and the answer is 0.
FF_HD inline int non_finite_input() {
#if defined(__CUDA_ARCH__)
  return 0;
#else
  throw std::domain_error("exact predicate on a non-finite value");
#endif
}

// One entry of Λ: a short expansion of at most Cap components.
template <class A, int Cap>
struct Entry {
  using T = typename A::T;
  static constexpr int kCap = Cap;
  int n = 1;
  T c[kCap];
  FF_HD Entry() { c[0] = A::zero(); }
  // Components c[n, kCap) set to 0 after a write of run-time length: only
  // c[0, n) is ever read, but GCC cannot see it once a small cap lets it
  // unroll the readers (-Wmaybe-uninitialized on the lifted entries of a
  // raw Λ); the cost is a few stores per raw entry (SoS only).
  FF_HD void clear_tail() {
    for (int i = n; i < kCap; ++i) c[i] = A::zero();
  }
  FF_HD void set(double v) {
    n = 1;
    c[0] = A::from_double(v);
  }
  FF_HD bool zero() const { return n == 1 && A::is_zero(c[0]); }
};

// Exact lifted height |x|^2 - w of m coordinates.
template <class A, int C>
FF_HD inline void lifted_entry(const double* x, int m, double w, Entry<A, C>& out) {
  using T = typename A::T;
  T buf[C], tmp[C];
  int len = 1;
  buf[0] = A::neg(A::from_double(w));
  for (int j = 0; j < m; ++j) {
    T sq[2];
    const T xj = A::from_double(x[j]);
    A::two_product(xj, xj, sq[1], sq[0]);
    const int sl = A::is_zero(sq[0]) ? 1 : 2;
    const T* sp = A::is_zero(sq[0]) ? sq + 1 : sq;
    len = sum_zeroelim<A>(len, buf, sl, sp, tmp);
    len = compress<A>(len, tmp);
    for (int i = 0; i < len; ++i) buf[i] = tmp[i];
  }
  out.n = len;
  for (int i = 0; i < len; ++i) out.c[i] = buf[i];
  out.clear_tail();
}

// Exact sum of `count` doubles (a centroid row scaled by count).
template <class A, int C>
FF_HD inline void sum_entry(const double* v, int stride, int count, Entry<A, C>& out) {
  using T = typename A::T;
  T buf[C], tmp[C];
  int len = 1;
  buf[0] = A::from_double(v[0]);
  for (int i = 1; i < count; ++i) {
    const T x = A::from_double(v[i * stride]);
    len = sum_zeroelim<A>(len, buf, 1, &x, tmp);
    len = compress<A>(len, tmp);
    for (int j = 0; j < len; ++j) buf[j] = tmp[j];
  }
  out.n = len;
  for (int i = 0; i < len; ++i) out.c[i] = buf[i];
  out.clear_tail();
}

// Λ (or T) of K rows as expansions; RawLambda: a Λ of K points (build_lambda,
// build_lambda_mixed), whose entries are shorter.
template <class A, int K, int Cap = entry_cap<A>(K)>
struct LambdaX {
  Entry<A, Cap> a[K][K];
};
template <class A, int K>
using RawLambda = LambdaX<A, K, raw_entry_cap<A>(K)>;

// binomial(n, r), compile time only (buffer sizes)
constexpr int binom(int n, int r) {
  return (r < 0 || r > n) ? 0 : (r == 0 || r == n) ? 1 : binom(n - 1, r - 1) + binom(n - 1, r);
}

// part = sign * (entry x m), m of length mlen <= cap: a scale of m per
// component of the entry, summed; returns the product's length (<= cap), 0
// when the entry is 0. Every intermediate (a scaled m, a partial sum) is
// compressed as soon as it exceeds cap — valid by the length bound of
// expansion.hpp, each of them being on the grid and below the bound of the
// top of this file (a partial sum of products of entries, of degree at most
// the minor's). `part` holds cap components, `scaled` and `sum` 2 cap; m must
// not alias them.
template <class A, int C>
FF_HD inline int times_entry(int cap, const Entry<A, C>& entry, int mlen, const typename A::T* m, bool negative,
                             typename A::T* scaled, typename A::T* part, typename A::T* sum) {
  if (entry.n == 1 && A::is_one(entry.c[0])) {  // the 1-column: no product
    for (int j = 0; j < mlen; ++j) part[j] = negative ? A::neg(m[j]) : m[j];
    return mlen;
  }
  int plen = 0;
  for (int i = 0; i < entry.n; ++i) {
    const auto b = negative ? A::neg(entry.c[i]) : entry.c[i];
    if (A::is_zero(b)) continue;
    int sl = scale_zeroelim<A>(mlen, m, b, scaled);
    if (sl > cap) sl = compress<A>(sl, scaled);
    if (plen == 0) {
      for (int j = 0; j < sl; ++j) part[j] = scaled[j];
      plen = sl;
      continue;
    }
    plen = sum_zeroelim<A>(plen, part, sl, scaled, sum);
    if (plen > cap) plen = compress<A>(plen, sum);
    for (int j = 0; j < plen; ++j) part[j] = sum[j];
  }
  return plen;
}

// acc (len n <= cap) += sign * (entry x m), m of length <= cap; returns the new
// length (<= cap, compressed when longer, as in times_entry). `part` holds
// cap components, `scaled` and `sum` 2 cap.
template <class A, int C>
FF_HD inline int add_product(int cap, int n, typename A::T* acc, const Entry<A, C>& entry, int mlen,
                             const typename A::T* m, bool negative, typename A::T* scaled,
                             typename A::T* part, typename A::T* sum) {
  const int plen = times_entry<A>(cap, entry, mlen, m, negative, scaled, part, sum);
  if (plen == 0) return n;
  int len = sum_zeroelim<A>(n, acc, plen, part, sum);
  if (len > cap) len = compress<A>(len, sum);
  for (int j = 0; j < len; ++j) acc[j] = sum[j];
  return len;
}

// ---- Minors by Laplace over column subsets, one level at a time ---------------
// Level l holds the l x l minors on the first l kept rows and every l-subset of
// the kept columns; level l+1 expands each of its minors along its last row:
// Σ_l C(r, l) l = r 2^(r-1) products in all (against r! r for the sum over
// permutations). Capacity per expansion: kCapD (Dbl, the window's bound) or
// cap_x(K + 1) (XDbl, see the top of this file).
template <class A>
FF_HD constexpr int minor_cap(int k) {
  return A::kExtended ? cap_x(k + 1) : kCapD;
}

// The kept rows and columns of a K x K matrix (bit masks of equal popcount),
// as increasing index lists of their common length r: how every minor below
// (expansion, ErrDouble and double) gathers its entries.
template <int K>
struct Kept {
  int ri[K] = {}, ci[K] = {}, r = 0;
  FF_HD Kept(unsigned rows, unsigned cols) {
    int nc = 0;
    for (int i = 0; i < K; ++i)
      if (rows & (1u << i)) ri[r++] = i;
    for (int j = 0; j < K; ++j)
      if (cols & (1u << j)) ci[nc++] = j;
  }
  // t (r x r, row-major) = the kept entries, at(i, j) the entry of row i, column j
  template <class T, class At>
  FF_HD void gather(T* t, At at) const {
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; ++j) t[i * r + j] = at(ri[i], ci[j]);
  }
};

// The value of a one-component entry as a binary64 number, when it is one:
// always for Dbl; for XDbl when m 2^e is a normal double (m in [1/2, 1) has
// 53 bits: m 2^e is then exact).
template <class A, int C>
FF_HD FF_FORCEINLINE bool entry_double(const Entry<A, C>& e, double& v) {
  if (e.n != 1) return false;
  if constexpr (A::kExtended) {
    const auto x = e.c[0];
    if (x.m == 0.0) {
      v = 0.0;
      return true;
    }
    if (x.e < -1020 || x.e > 1023) return false;
    v = x.m * A::pow2(x.e);
    return true;
  } else {
    v = e.c[0];
    return true;
  }
}

// Are a point's ncoord coordinates and its weight (w null: none) integers
// below 2^bits in magnitude? (Its Λ row is then one of small integers.)
FF_HD FF_FORCEINLINE bool small_integer_point(const double* x, int ncoord, const double* w, int i, int bits) {
  const double limit = XDbl::pow2(bits);
  for (int j = 0; j <= ncoord; ++j) {
    const double v = j < ncoord ? x[j] : (w ? w[i] : 0.0);
    if (!(std::fabs(v) < limit) || static_cast<double>(static_cast<long long>(v)) != v) return false;
  }
  return true;
}

// Laplace levels on binary64 values, exactly: a level-l minor of rows whose
// entries are all multiples of 2^g and below 2^m in magnitude is a signed sum
// of at most l! products of l entries, and so is every partial sum that
// MinorLaplace forms on the way (an entry times a level l-1 minor, summed):
// a multiple of 2^(l g) below l! 2^(l m) <= 2^(lf(l) + l m). Such a value is
// a double when lf(l) + l (m - g) <= 53 and l g >= -1074; it does not
// overflow when lf(l) + l m <= 1000. Then every product and sum is exact
// (its exact value is representable), by induction over the levels, and the
// computed level-l minors are the exact ones. (g, m) = (0, 0) for no nonzero
// value yet.
FF_HD FF_FORCEINLINE bool double_levels_exact(int l, int g, int m) {
  return l * g >= -1074 && log2_factorial_ceil(l) + l * (m - g) <= 53 && log2_factorial_ceil(l) + l * m <= 1000;
}

// The binary64 part of MinorLaplace, on the kept entries as doubles (a
// function of K only: one instantiation per row count, not per component
// type and capacity). Candidates: the rows of one-component entries
// (single[t]), narrowest bit span first (bit_span over the row's nonzero
// values), kept while double_levels_exact holds for all of them together.
// order: those rows, then the others, each in their kept order; parity: its
// sign (inversions); rank: each column subset's index among the subsets of
// its size; level: the level-u minors (by rank) of the prefix rows, exact.
// run returns u.
template <int K>
struct DoublePrefix {
  static constexpr int kLevel = binom(K, K / 2);
  int order[K] = {};
  int parity = 1;
  unsigned char rank[1u << K];
  double level[kLevel];
  FF_HD int run(int r, const double (&val)[K][K], const bool (&single)[K]) {
    int lo[K], hi[K], cand[K], nc = 0;
    for (int t = 0; t < r; ++t) {
      if (!single[t]) continue;
      int rl = 100000, rh = -100000;
      for (int q = 0; q < r; ++q) {
        int vl = 0, vh = 0;
        if (val[t][q] != 0.0 && bit_span(val[t][q], vl, vh)) {
          rl = vl < rl ? vl : rl;
          rh = vh > rh ? vh : rh;
        }
      }
      lo[t] = rl;
      hi[t] = rh;
      // insertion by span (an all-zero row: span 0, first)
      const int span = rh >= rl ? rh - rl : 0;
      int at = nc++;
      while (at > 0) {
        const int o = cand[at - 1];
        const int ospan = hi[o] >= lo[o] ? hi[o] - lo[o] : 0;
        if (ospan <= span) break;
        cand[at] = o;
        --at;
      }
      cand[at] = t;
    }
    bool inprefix[K] = {};
    int u = 0, g = 100000, m = -100000;
    for (int c = 0; c < nc; ++c) {
      const int t = cand[c];
      const int ng = lo[t] < g ? lo[t] : g, nm = hi[t] > m ? hi[t] : m;
      const bool any = nm >= ng;  // some nonzero value among the rows
      if (!double_levels_exact(u + 1, any ? ng : 0, any ? nm : 0)) continue;
      g = ng, m = nm;
      inprefix[t] = true;
      ++u;
    }
    int n = 0;
    for (int t = 0; t < r; ++t)
      if (inprefix[t]) order[n++] = t;
    for (int t = 0; t < r; ++t)
      if (!inprefix[t]) order[n++] = t;
    int inversions = 0;
    for (int a = 0; a < r; ++a)
      for (int b = a + 1; b < r; ++b) inversions += order[a] > order[b];
    parity = (inversions & 1) ? -1 : 1;
    // rank: each subset's index among those of its size, in ascending order
    // (the subsets of one size enumerated by next_same_popcount)
    const unsigned limit = 1u << r;
    rank[0] = 0;
    for (int l = 1; l <= r; ++l) {
      unsigned char n = 0;
      for (unsigned s = (1u << l) - 1u; s < limit; s = next_same_popcount(s)) rank[s] = n++;
    }
    if (u == 0) return 0;
    double dl[2][kLevel];
    for (int j = 0; j < r; ++j) dl[1][rank[1u << j]] = val[order[0]][j];
    for (int l = 2; l <= u && l <= K; ++l) {  // (u <= r <= K; said for the compiler's K = 1)
      double* cur = dl[l & 1];
      const double* prev = dl[(l - 1) & 1];
      const double* row = val[order[l - 1]];
      for (unsigned s = (1u << l) - 1u; s < limit; s = next_same_popcount(s)) {
        double d = 0.0;
        int pos = 0;
        for (unsigned b = s; b != 0; b &= b - 1u) {  // the columns of s, ascending
          const int j = ctz64(b);
          const double term = row[j] * prev[rank[s & ~(1u << j)]];
          d = (((l - 1 + pos) & 1) != 0) ? d - term : d + term;  // (-1)^((l-1) + pos)
          ++pos;
        }
        cur[rank[s]] = d;
      }
    }
    for (unsigned s = (1u << u) - 1u; s < limit; s = next_same_popcount(s)) level[rank[s]] = dl[u & 1][rank[s]];
    return u;
  }
};

template <class A, int K>
struct MinorLaplace {
  static constexpr int kLevel = binom(K, K / 2);
  static constexpr int kCap = minor_cap<A>(K);
  using T = typename A::T;
  using E = Exp<A, kCap>;

  // sign of the minor of L on the kept rows / columns (bit masks, equal
  // popcount); a call of its own on the device (see sos_expansions).
  //
  // Rows first in binary64. Near-degenerate inputs are mostly exact small
  // values — the unmoved points of a lattice with a few points moved by some
  // ulp, whose Λ rows (or differences from an unmoved base row, see
  // det_translated) are small integers. The kept rows whose kept entries are
  // one-component doubles are taken narrowest span first (bit_span over the
  // row's nonzero values) while double_levels_exact holds for all of them
  // together; the minor is expanded over those rows first (levels 1..u in
  // binary64, exact), the other rows after, as expansions. Reordering the
  // rows multiplies the minor by the permutation's sign (its inversions).
  // With u of the r rows in binary64 the expansion levels cost
  // Σ_{l > u} C(r, l) l products instead of r 2^(r-1): 6 instead of 192 for
  // one moved point among 7 (r = 6), 36 for two.
  template <int C>
  FF_HD FF_DEVICE_NOINLINE static int sign(const LambdaX<A, K, C>& L, unsigned rows, unsigned cols) {
    const Kept<K> kept(rows, cols);
    const int* ci = kept.ci;
    const int r = kept.r;
    if (r == 0) return 1;
    // the binary64 prefix (DoublePrefix): the kept entries as doubles where
    // one-component (single[t]: the whole kept row is)
    double val[K][K] = {};  // (rows not single stay 0; read only for the prefix rows)
    bool single[K];
    for (int t = 0; t < r; ++t) {
      const int i = kept.ri[t];
      bool one = true;
      for (int q = 0; q < r && one; ++q) one = entry_double<A>(L.a[i][ci[q]], val[t][q]);
      single[t] = one;
    }
    DoublePrefix<K> pre;
    int u = pre.run(r, val, single);
    const int* order = pre.order;
    const int parity = pre.parity;
    const unsigned char* rank = pre.rank;
    const unsigned full = (1u << r) - 1u;
    E lev[2][kLevel];
    if (u > 0) {
      if (u == r) {
        const double d = pre.level[0];
        return parity * ((d > 0.0) - (d < 0.0));
      }
      for (unsigned s = (1u << u) - 1u; s <= full; s = next_same_popcount(s)) {
        E& d = lev[u & 1][rank[s]];
        d.n = 1;
        d.c[0] = A::from_double(pre.level[rank[s]]);
      }
    } else {
      // level 1: the first row, single columns
      for (int j = 0; j < r; ++j) {
        const auto& e = L.a[kept.ri[order[0]]][ci[j]];
        E& d = lev[1][rank[1u << j]];
        d.n = e.n;
        for (int t = 0; t < e.n; ++t) d.c[t] = e.c[t];
      }
      u = 1;
    }
    T scaled[2 * kCap], part[kCap], sum[2 * kCap];
    for (int l = u + 1; l <= r; ++l) {
      E* cur = lev[l & 1];
      const E* prev = lev[(l - 1) & 1];
      const int i = kept.ri[order[l - 1]];
      for (unsigned s = (1u << l) - 1u; s <= full; s = next_same_popcount(s)) {
        E& d = cur[rank[s]];
        d.n = 1;
        d.c[0] = A::zero();
        int pos = 0;
        for (unsigned b = s; b != 0; b &= b - 1u) {  // the columns of s, ascending
          const int j = ctz64(b);
          const E& sub = prev[rank[s & ~(1u << j)]];
          const auto& e = L.a[i][ci[j]];
          const bool negative = ((l - 1 + pos) & 1) != 0;  // (-1)^((l-1) + pos)
          ++pos;
          if (sub.zero() || e.zero()) continue;
          d.n = add_product<A>(kCap, d.n, d.c, e, sub.n, sub.c, negative, scaled, part, sum);
        }
      }
    }
    return parity * lev[r & 1][0].sign();
  }
};

// ---- XDbl: minors as sums over permutations (little memory) ------------------
// Each term Π_t a[ri[t]][ci[perm[t]]] is built one entry at a time
// (times_entry, every intermediate compressed above kCap), then added to the
// accumulator. Buffers: acc and two alternating term buffers kCap, scaled and
// sum 2 kCap: 7 kCap components of 16 bytes (K = 5: 27 KB; 11 kCap, 43 KB,
// with add_product's former 3 kCap buffers).
template <int K>
struct MinorX {
  // degree of a K x K minor in the input values: at most K + 1 (a lifted
  // column counts 2) — the translated T of K + 1 points is K x K of degree K + 1
  static constexpr int kCap = cap_x(K + 1);
  using T = XD;

  template <int C>
  FF_HD FF_DEVICE_NOINLINE static int sign(const LambdaX<XDbl, K, C>& L, unsigned rows, unsigned cols) {
    const Kept<K> kept(rows, cols);
    const int* ri = kept.ri;
    const int* ci = kept.ci;
    const int r = kept.r;
    if (r == 0) return 1;
    T acc[kCap], term_a[kCap], term_b[kCap], scaled[2 * kCap], sum[2 * kCap];
    int alen = 1;
    acc[0] = XDbl::zero();
    // Heap's algorithm, iterative: every permutation once, one swap apart.
    int perm[K], cnt[K];
    for (int i = 0; i < r; ++i) perm[i] = i, cnt[i] = 0;
    int parity = 1;  // sign of perm
    for (int i = 0;;) {
      // the term Π_t a[ri[t]][ci[perm[t]]]
      bool zero = false;
      for (int t = 0; t < r && !zero; ++t) zero = L.a[ri[t]][ci[perm[t]]].zero();
      if (!zero) {
        const auto& e0 = L.a[ri[0]][ci[perm[0]]];
        T* term = term_a;
        T* next = term_b;
        int tlen = e0.n;
        for (int t = 0; t < tlen; ++t) term[t] = e0.c[t];
        for (int t = 1; t < r; ++t) {  // no entry is 0 (tested above): tlen > 0
          tlen = times_entry<XDbl>(kCap, L.a[ri[t]][ci[perm[t]]], tlen, term, false, scaled, next, sum);
          T* const done = next;
          next = term;
          term = done;
        }
        // acc += parity * term
        if (parity < 0)
          for (int q = 0; q < tlen; ++q) term[q] = XDbl::neg(term[q]);
        alen = sum_zeroelim<XDbl>(alen, acc, tlen, term, sum);
        if (alen > kCap) alen = compress<XDbl>(alen, sum);
        for (int q = 0; q < alen; ++q) acc[q] = sum[q];
      }
      // next permutation (Heap)
      while (i < r && cnt[i] >= i) {
        cnt[i] = 0;
        ++i;
      }
      if (i >= r) break;
      if (i % 2 == 0) {
        const int tmp = perm[0];
        perm[0] = perm[i];
        perm[i] = tmp;
      } else {
        const int tmp = perm[cnt[i]];
        perm[cnt[i]] = perm[i];
        perm[i] = tmp;
      }
      parity = -parity;
      ++cnt[i];
      i = 0;
    }
    return sign_of<XDbl>(alen, acc);
  }
};

// Which minor algorithm: Laplace levels, except XDbl on the device, where the
// levels' stack (2 C(K, K/2) cap_x(K+1) x 16 bytes: 78 KB at K = 5) would
// dominate the kernel's frame and the sum over permutations needs
// 7 cap_x(K+1) x 16 bytes (27 KB at K = 5). FF_XDBL_PERMUTATIONS selects the
// device choice on the host (whole program only: it changes an inline
// definition); predicates_stages_test compares both algorithms directly.
#if defined(__CUDA_ARCH__) || defined(FF_XDBL_PERMUTATIONS)
constexpr bool kXdblPermutations = true;
#else
constexpr bool kXdblPermutations = false;
#endif
template <class A, int K>
struct MinorOf : MinorLaplace<A, K> {};
template <int K>
struct MinorOf<XDbl, K> {
  template <int C>
  FF_HD static int sign(const LambdaX<XDbl, K, C>& L, unsigned rows, unsigned cols) {
    if constexpr (kXdblPermutations) return MinorX<K>::sign(L, rows, cols);
    else return MinorLaplace<XDbl, K>::sign(L, rows, cols);
  }
};

// ---- Simulation of Simplicity ----------------------------------------------
// The sign of det Λ(ε) is the sign of the first non-zero signed complementary
// minor in the dominance order of predicates.hpp: rows from the largest index
// (the last row: rows are sorted by increasing index) to the smallest; on each
// row first "not perturbed", then the coordinate columns from the last to the
// first; the 1-column is never perturbed. The depth-first search over these
// matchings is written with an explicit stack (no recursion); minor signs are
// memoised (a minor recurs under many matchings).
// An ErrDouble view of an entry (its components summed with a proven bound).
template <class A, int C>
FF_HD inline ErrDouble approx_entry(const Entry<A, C>& e) {
  if constexpr (A::kExtended) {
    ErrDouble acc(0.0);
    for (int i = 0; i < e.n; ++i) {
      const double m = e.c[i].m;
      const int ex = e.c[i].e;
      if (ex > 1000) return ErrDouble(0.0, HUGE_VAL);  // leave it to the exact stage
      // below the normal range ldexp rounds (to a subnormal or 0): off by at
      // most half the smallest subnormal
      const ErrDouble c = ex < -900 ? ErrDouble(std::ldexp(m, ex), 0x1p-1074) : ErrDouble(std::ldexp(m, ex));
      acc = (i == 0) ? c : acc + c;
    }
    return acc;
  } else {
    ErrDouble acc(e.c[0]);
    for (int i = 1; i < e.n; ++i) acc = acc + ErrDouble(e.c[i]);
    return acc;
  }
}

// The minor of an ErrDouble K x K matrix (row-major) on the kept rows and
// columns (bit masks, equal popcount), by det_by_minors (lambda_filter.hpp):
// its value and a proven bound on its error. The empty minor is 1; 8 x 8 (K =
// 8, nothing deleted) is beyond det_by_minors and returns an undecided value.
template <int K>
FF_HD inline ErrDouble errdouble_minor(const ErrDouble* ap, unsigned rows, unsigned cols) {
  const Kept<K> kept(rows, cols);
  const int r = kept.r;
  ErrDouble t[K * K];
  kept.gather(t, [&](int i, int j) { return ap[i * K + j]; });
  switch (r) {
    case 0: return ErrDouble(1.0);
    case 1: return t[0];
    case 2: return det_by_minors<2>(t);
    case 3: return det_by_minors<3>(t);
    case 4: return det_by_minors<4>(t);
    case 5: return det_by_minors<5>(t);
    case 6: return det_by_minors<6>(t);
    case 7: return det_by_minors<7>(t);
    default: return ErrDouble(0.0, HUGE_VAL);
  }
}

// errdouble_minor for the search of sos_lazy: orders 5..7 by Gaussian
// elimination (det_gauss, a proven running bound like det_by_minors'):
// about r^3/3 operations against r 2^(r-1).
template <int K>
FF_HD inline ErrDouble errdouble_minor_lazy(const ErrDouble* ap, unsigned rows, unsigned cols) {
  if constexpr (K >= 6) {
    const Kept<K> kept(rows, cols);
    if (kept.r >= 5) {
      ErrDouble t[K * K];
      kept.gather(t, [&](int i, int j) { return ap[i * K + j]; });
      if (kept.r == 5) return det_gauss<5>(t);
      if (kept.r == 6) return det_gauss<6>(t);
      if constexpr (K >= 7) if (kept.r == 7) return det_gauss<7>(t);
    }
  }
  return errdouble_minor<K>(ap, rows, cols);
}

// det_plain<N>(t) for the run-time order r, N <= r <= min(K, 7): only orders
// that fit t (K x K entries) are instantiated.
template <int N, int K>
FF_HD inline double det_plain_of_order(const double* t, int r) {
  if constexpr (N > K || N > 7) {
    return 0.0;  // unreachable: r <= K and r <= 7
  } else {
    if (r == N) return filter_detail::det_plain<N>(t);
    return det_plain_of_order<N + 1, K>(t, r);
  }
}

// The sign of a minor of near-lattice entries, without the expansion minor:
// the SoS searches on a perturbed grid (lattice points, some moved by a few
// ulps, zeros moved to subnormals) meet mostly minors that are exactly 0,
// which the ErrDouble filter cannot decide. Three steps, each exact:
//   * a kept column whose kept entries are all 0 but one, a_ab at positions
//     (a, b) of the kept rows and columns: minor = (-1)^(a+b) a_ab times the
//     minor without row a and column b (Laplace along that column); the sign
//     of a_ab is its expansion's leading non-zero component's;
//   * the rest split entry by entry into an integer part below 2^30 and a
//     tail below 2^-40 (comments below), the integer parts' determinant d in
//     plain doubles, exactly: with b_j the bit length of column j's largest
//     |integer part|, every value det_plain forms is a partial sum of at most
//     r! products of one entry per column, an integer below r! Π 2^(b_j) <=
//     2^53 when lf(r) + Σ b_j <= 53 (doubles_exact_minors' argument): no
//     rounding, and a computed 0 is a true 0;
//   * with the tails all in one row or all in one column, the minor is d +
//     Σ tail_k C_k (linear in that row or column; C_k integer cofactors,
//     exact the same way): d's sign when d != 0 and the tails cannot reach
//     1, else the largest term's sign where it dominates the others.
// 2 when a step does not apply (the expansion minor decides). Tested against
// the expansion minor on near-lattice Λ (predicates_int_lattice_test,
// "small_integer_minor").
template <class A, int K, int C>
FF_HD inline int small_integer_minor(const LambdaX<A, K, C>& L, const Kept<K>& kept) {
  int r = kept.r;
  int ri[K], ci[K];
  for (int i = 0; i < r; ++i) ri[i] = kept.ri[i], ci[i] = kept.ci[i];
  int sign = 1;
  for (bool again = true; again && r > 0;) {
    again = false;
    for (int b = 0; b < r && !again; ++b) {
      int a = -1, nonzero = 0;
      for (int i = 0; i < r && nonzero < 2; ++i)
        if (!L.a[ri[i]][ci[b]].zero()) ++nonzero, a = i;
      if (nonzero == 0) return 0;
      if (nonzero != 1) continue;
      const auto& e = L.a[ri[a]][ci[b]];
      int es = 0;
      for (int t = e.n - 1; t >= 0 && es == 0; --t) es = A::sign(e.c[t]);
      sign *= ((a + b) & 1) ? -es : es;
      for (int i = a; i + 1 < r; ++i) ri[i] = ri[i + 1];
      for (int j = b; j + 1 < r; ++j) ci[j] = ci[j + 1];
      --r;
      again = true;
    }
  }
  if (r == 0) return sign;
  // The rest: each entry an integer part I (its largest component rounded
  // to an integer below 2^30) plus a tail (the rounding's remainder, exact,
  // and the lower components) below 2^-40, the tails all in one row or all
  // in one column. A tail's sign is its leading part's (below), and |tail|
  // lies in [2^(texp-2), 2^(texp+1)), 2^(texp-1) <= |lead| < 2^texp.
  double t[K * K] = {};
  int tsign[K * K] = {}, texp[K * K] = {};
  int trow = -1, tcol = -1, tails = 0, max_texp = -100000;
  bool one_row = true, one_col = true;
  int bits = log2_factorial_ceil(r);
  for (int j = 0; j < r; ++j) {
    double big = 0.0;
    for (int i = 0; i < r; ++i) {
      const auto& e = L.a[ri[i]][ci[j]];
      double top = 0.0;  // the largest component as a double (0 when below 2^-60)
      if constexpr (A::kExtended) {
        const XD& h = e.c[e.n - 1];
        if (h.e > 30) return 2;  // |v| >= 2^30
        if (h.m != 0.0 && h.e >= -60) top = h.m * XDbl::pow2(h.e);  // exact: -60 <= e <= 30
      } else {
        top = e.c[e.n - 1];
        if (!(std::fabs(top) < 0x1p30)) return 2;
        if (std::fabs(top) < 0x1p-60) top = 0.0;
      }
      const double v = std::rint(top), rem = top - v;  // exact: |top| < 2^30
      // the tail's parts, largest first: rem (when not 0), then the lower
      // components (from the top one when it was below 2^-60); its sign is
      // the first part's, te that part's exponent, and the next part must
      // be below 2^(te-3): the parts after the first then sum to less than
      // 2^(te-2) (each component is below the previous one's lowest bit)
      int ts = 0, te = 0;
      auto part = [&](int q, int& sg, int& ex) {
        sg = A::sign(e.c[q]);
        if constexpr (A::kExtended) ex = e.c[q].e;
        else ex = sg != 0 ? std::ilogb(e.c[q]) + 1 : 0;
      };
      int q = top == 0.0 ? e.n - 1 : e.n - 2;
      if (rem != 0.0) {
        ts = (rem > 0.0) - (rem < 0.0);
        te = std::ilogb(rem) + 1;
      } else {
        for (; q >= 0 && ts == 0; --q) part(q, ts, te);
      }
      for (int s2 = 0, e2 = 0; q >= 0 && ts != 0; --q) {
        part(q, s2, e2);
        if (s2 == 0) continue;
        if (e2 > te - 3) return 2;
        break;
      }
      if (ts != 0) {
        if (te + 1 > -40) return 2;
        const int k = i * r + j;
        tsign[k] = ts;
        texp[k] = te;
        max_texp = te > max_texp ? te : max_texp;
        ++tails;
        one_row = one_row && (trow < 0 || trow == i);
        one_col = one_col && (tcol < 0 || tcol == j);
        trow = i, tcol = j;
      }
      t[i * r + j] = v;
      big = std::fmax(big, std::fabs(v));
    }
    bits += bit_length(static_cast<unsigned long long>(big));
  }
  if (bits > 53 || r > 7) return 2;
  auto int_det = [](const double* m, int n) -> double {
    if (n == 0) return 1.0;
    if (n == 1) return m[0];
    return det_plain_of_order<2, K>(m, n);
  };
  const double d = int_det(t, r);  // det of the integer parts, exactly
  if (tails == 0) return sign * ((d > 0.0) - (d < 0.0));
  if (!one_row && !one_col) return 2;
  // The minor is linear in the row (or column) holding the tails: minor = d
  // + Σ_k tail_k C_k, C_k the integer parts' cofactor at tail k's entry, an
  // integer with |C_k| < 2^bits (the bound above). At most 7 terms, each
  // below 2^(max_texp + 1 + bits): the sum is below 1 <= |d| when d != 0
  // and max_texp + bits + 4 <= 0. When d = 0 the largest term's sign is the
  // minor's where it dominates: |tail_top C_top| >= 2^(texp_top - 2)
  // against the others' < 7 2^(texp_2nd + 1 + bits), less when texp_top -
  // texp_2nd > bits + 6.
  if (d != 0.0) {
    if (max_texp + bits + 4 > 0) return 2;
    return sign * ((d > 0.0) - (d < 0.0));
  }
  int best = -1, best_exp = 0, second_exp = -100000, best_sign = 0;
  for (int k = 0; k < r * r; ++k) {
    if (tsign[k] == 0) continue;
    const int i = k / r, j = k % r;
    double m[K * K] = {};
    int q = 0;
    for (int a = 0; a < r; ++a)
      for (int b = 0; b < r; ++b)
        if (a != i && b != j) m[q++] = t[a * r + b];
    const double c = int_det(m, r - 1);
    if (c == 0.0) continue;
    const int sc = (c > 0.0) - (c < 0.0);
    if (best < 0 || texp[k] > best_exp) {
      second_exp = best < 0 ? second_exp : best_exp;
      best = k, best_exp = texp[k];
      best_sign = (((i + j) & 1) ? -sc : sc) * tsign[k];
    } else if (texp[k] > second_exp) {
      second_exp = texp[k];
    }
  }
  if (best < 0) return 0;
  if (second_exp > -100000 && best_exp - second_exp <= bits + 6) return 2;
  return sign * best_sign;
}

// Cheap decisions on a minor before the exact evaluation: 0 when two kept
// rows are equal or a kept column is zero (duplicated points, lattices), the
// ErrDouble filter's sign when it is certain; 2 when undecided.
// The ErrDouble view of Λ (approx_entry per entry), built on the first minor
// that asks for it: near-lattice SoS searches (minor_quick sends their minors
// past the ErrDouble minor) then never convert the expansion Λ (its
// extended-double components through ldexp: 3.6 % of a perturbed grid's run).
template <class A, int K, int C>
struct LazyApprox {
  const LambdaX<A, K, C>& L;
  ErrDouble ap[K * K];
  bool ready = false;
  FF_HD explicit LazyApprox(const LambdaX<A, K, C>& lambda) : L(lambda) {}
  FF_HD const ErrDouble* get() {
    if (!ready) {
      for (int i = 0; i < K; ++i)
        for (int j = 0; j < K; ++j) ap[i * K + j] = approx_entry<A>(L.a[i][j]);
      ready = true;
    }
    return ap;
  }
};

template <class A, int K, int C>
FF_HD inline int minor_quick(const LambdaX<A, K, C>& L, LazyApprox<A, K, C>& approx, unsigned rows,
                             unsigned cols) {
  const Kept<K> kept(rows, cols);
  const int* ri = kept.ri;
  const int* ci = kept.ci;
  const int r = kept.r;
  if (r == 0) return 1;
  auto same = [](const auto& x, const auto& y) {
    bool eq = x.n == y.n;
    for (int t = 0; t < x.n && eq; ++t)
      eq = !A::abs_less(x.c[t], y.c[t]) && !A::abs_less(y.c[t], x.c[t]) && A::sign(x.c[t]) == A::sign(y.c[t]);
    return eq;
  };
  // with the last column kept and constant on the kept rows (the 1-column of
  // points; a mixed row's is its count, build_lambda_mixed), a kept column
  // constant on them (points on a plane x_j = c) is a multiple of it: the
  // minor is 0, as in sos_lazy
  bool one = (cols >> (K - 1)) & 1u;
  for (int i = 1; i < r && one; ++i) one = same(L.a[ri[i]][K - 1], L.a[ri[0]][K - 1]);
  for (int j = 0; j < r; ++j) {
    bool zero = true, constant = one && ci[j] != K - 1;
    for (int i = 0; i < r && (zero || constant); ++i) {
      zero = zero && L.a[ri[i]][ci[j]].zero();
      constant = constant && same(L.a[ri[i]][ci[j]], L.a[ri[0]][ci[j]]);
    }
    if (zero || constant) return 0;
  }
  for (int a = 1; a < r; ++a)
    for (int b = 0; b < a; ++b) {
      bool equal = true;
      for (int j = 0; j < r && equal; ++j) equal = same(L.a[ri[a]][ci[j]], L.a[ri[b]][ci[j]]);
      if (equal) return 0;
    }
  // Near-lattice minors (all kept rows but at most two of small integers:
  // the unmoved points of a perturbed grid) are mostly exactly 0 or decided
  // by their tails, which the ErrDouble minor cannot do; the exact minor's
  // binary64 levels over the integer rows (MinorLaplace) cost about as much
  // as the ErrDouble minor, so it is skipped there. Measured on the 3^5 grid
  // with 20 % of the points moved by 2 ulp (subnormal zeros, the XDbl SoS):
  // rtd compute + certify 2.99 -> 2.21 s.
  int integral = 0;
  for (int a = 0; a < r; ++a) {
    bool in = true;
    for (int b = 0; b < r && in; ++b) {
      double v = 0.0;
      in = entry_double<A>(L.a[ri[a]][ci[b]], v) && std::fabs(v) < 0x1p26 &&
           static_cast<double>(static_cast<long long>(v)) == v;
    }
    integral += in;
  }
  if (integral >= r - 2) return small_integer_minor<A, K>(L, kept);
  const int s = sign_if_certain(errdouble_minor<K>(approx.get(), rows, cols));
  if (s != 0) return s;
  return small_integer_minor<A, K>(L, kept);
}

// sos_search's memo of minor signs by key (kept rows << (K-1) | kept
// coordinate columns, 2K - 1 bits). K <= 6: a byte per key (2 KB at most).
// Larger K: the table would be 2^(2K-1) bytes, set on every call (K = 8:
// 32 KB, 32 % of a 6D Delaunay's instructions on points given twice), while
// a search reads tens of minors: an open-addressed table of 512 keys, which
// stops remembering at 384 (a minor not remembered is computed again: the
// same sign). get: the sign, or 2 when not remembered.
template <int K, bool Direct = (K <= 6)>
struct SosMemo {
  signed char v[1u << (2 * K - 1)];
  FF_HD SosMemo() {
    for (unsigned i = 0; i < (1u << (2 * K - 1)); ++i) v[i] = 2;
  }
  FF_HD int get(unsigned key) const { return v[key]; }
  FF_HD void put(unsigned key, int s) { v[key] = static_cast<signed char>(s); }
};
template <int K>
struct SosMemo<K, false> {
  static constexpr unsigned kSlots = 512, kMax = 384, kEmpty = ~0u;
  unsigned key[kSlots];
  signed char v[kSlots];
  unsigned n = 0;
  FF_HD SosMemo() {
    for (unsigned i = 0; i < kSlots; ++i) key[i] = kEmpty;
  }
  FF_HD static unsigned home(unsigned k) { return (k * 2654435761u) >> 23; }  // 9 bits
  FF_HD int get(unsigned k) const {
    for (unsigned i = home(k);; i = (i + 1) & (kSlots - 1)) {
      if (key[i] == k) return v[i];
      if (key[i] == kEmpty) return 2;
    }
  }
  FF_HD void put(unsigned k, int s) {
    if (n == kMax) return;
    unsigned i = home(k);
    while (key[i] != kEmpty && key[i] != k) i = (i + 1) & (kSlots - 1);
    if (key[i] == kEmpty) ++n;
    key[i] = k;
    v[i] = static_cast<signed char>(s);
  }
};

// The search over matchings in the dominance order for a Λ of K rows; with
// det_is_zero the caller has decided det Λ = 0 and the memo starts with it.
// minor(kr, kc) returns the sign of the minor on the kept rows / columns, or 2
// when it cannot decide; the search then returns 2 (the caller's slower
// evaluation takes over). Memo: 2^(2K-1) bytes.
//
// Pulled = true: the perturbation of the strict views of d-dimensional
// regular triangulations (predicates.hpp, power_d_pulled): the lifted height
// (column K-2) is not perturbed with the coordinates; instead it becomes
// h + ε1 |x|^2 - ε2^(r) (r: the row's rank, smallest index first), with
// ε1 >> ε2 and both infinitely larger than every coordinate perturbation.
// The determinant is linear in that column, so a term is a matching of rows
// to coordinate columns (its δ-order, the dominance order above) times one
// of: the heights h, the ε1 column |x|^2 (minor_q: the same minor of the
// unweighted Λ), or one pulled height (the cofactor of its entry, with the
// pull's sign -1) — in that order, pulls smallest index first. So the search
// is the one above without the height column, and a leaf whose complementary
// minor is 0 tries minor_q and then the pulls of its kept rows.
//
// eq (optional, not with Pulled): eq[x K + y] the columns on which rows x and
// y of Λ are exactly equal (bit j: column j). The subtree test of the lemma
// below (the SoS search on an integer Λ by ranks): every leaf under a node is
// 0 when F, the rows kept among those already decided, loses rank on the
// columns left — in particular when two rows of F are equal on them (points
// given twice: without this the search walks every leaf of the subtree under
// the higher copy's "not perturbed", K = 8: thousands of leaves per call).
// Such a node is skipped; the leaves skipped are all 0, so the first non-zero
// leaf, and the answer, are the same.
template <int K, bool Pulled = false, class MinorFn, class MinorQFn = std::nullptr_t>
FF_HD inline int sos_search(bool det_is_zero, MinorFn&& minor_fn, MinorQFn&& minor_q = nullptr,
                            const unsigned* eq = nullptr) {
  constexpr unsigned kAll = (1u << K) - 1u;
  constexpr unsigned kColMask = (1u << (K - 1)) - 1u;  // the 1-column (bit K-1) is always kept
  SosMemo<K> memo;
  if (det_is_zero) memo.put((kAll << (K - 1)) | (kAll & kColMask), 0);  // det Λ itself
  auto minor = [&](unsigned kr, unsigned kc) -> int {
    const unsigned key = (kr << (K - 1)) | (kc & kColMask);
    int s = memo.get(key);
    if (s == 2) {
      s = minor_fn(kr, kc);
      memo.put(key, s);
    }
    return s;
  };
  int choice[K];
  unsigned skr[K], skc[K];
  int ssg[K];
  int r = K - 1;
  skr[r] = kAll;
  skc[r] = kAll;
  ssg[r] = 1;
  choice[r] = -1;
  // options on a row: 0 = not perturbed, o = 1..K-1 = column K-1-o (K-2 .. 0)
  while (true) {
    const int opt = ++choice[r];
    if (opt > K - 1) {  // row exhausted: back to the row above (larger index)
      ++r;
      if (r > K - 1) return 0;  // impossible for a Λ-matrix (the 1x1 minor "1")
      continue;
    }
    unsigned kr = skr[r], kc = skc[r];
    int sg = ssg[r];
    if (opt >= 1) {
      const int c = K - 1 - opt;
      if (Pulled && c == K - 2) continue;  // heights are pulled, not perturbed with the coordinates
      if (!(kc & (1u << c))) continue;
      const int parity = popcount32(kr & ((1u << r) - 1u)) + popcount32(kc & ((1u << c) - 1u));
      if (parity & 1) sg = -sg;
      kr &= ~(1u << r);
      kc &= ~(1u << c);
    }
    if (!Pulled && eq) {
      // F: the kept rows among r .. K-1; two of them equal on kc: skip
      const unsigned f = kr & ~((1u << r) - 1u);
      bool dead = false;
      if (opt == 0) {
        for (int q = r + 1; q < K && !dead; ++q)
          dead = ((f >> q) & 1u) && (kc & ~eq[r * K + q]) == 0;
      } else {
        for (int x = r + 1; x < K && !dead; ++x) {
          if (!((f >> x) & 1u)) continue;
          for (int y = x + 1; y < K && !dead; ++y) dead = ((f >> y) & 1u) && (kc & ~eq[x * K + y]) == 0;
        }
      }
      if (dead) continue;
    }
    if (r == 0) {
      const int s = minor(kr, kc);
      if (s == 2) return 2;
      if (s != 0) return sg * s;
      if constexpr (Pulled) {
        const int sq = minor_q(kr, kc);  // the ε1 term (kc holds the height column)
        if (sq == 2) return 2;
        if (sq != 0) return sg * sq;
        constexpr int hc = K - 2;
        for (int i = 0; i < K; ++i) {
          if (!(kr & (1u << i))) continue;
          const int parity = popcount32(kr & ((1u << i) - 1u)) + popcount32(kc & ((1u << hc) - 1u));
          const int sp = minor(kr & ~(1u << i), kc & ~(1u << hc));
          if (sp == 2) return 2;
          if (sp != 0) return ((parity & 1) ? sg : -sg) * sp;  // -ε^(r_i): the pull's sign
        }
      }
      continue;
    }
    --r;
    skr[r] = kr;
    skc[r] = kc;
    ssg[r] = sg;
    choice[r] = -1;
  }
}

// SoS sign on Λ as expansions: every minor decided by minor_quick, else
// exactly by MinorOf (det_is_zero: the caller has found det Λ = 0).
template <class A, int K, int C>
FF_HD inline int sos_sign(const LambdaX<A, K, C>& L, bool det_is_zero = false) {
  LazyApprox<A, K, C> ap(L);
  return sos_search<K>(det_is_zero, [&](unsigned kr, unsigned kc) -> int {
    const int q = minor_quick<A, K>(L, ap, kr, kc);
    return q != 2 ? q : MinorOf<A, K>::sign(L, kr, kc);
  });
}

// The pulled perturbation (sos_search, Pulled) on L, with Lq the same Λ with
// zero weights (its height column |x|^2).
template <class A, int K, int C>
FF_HD inline int sos_sign_pulled(const LambdaX<A, K, C>& L, const LambdaX<A, K, C>& Lq) {
  LazyApprox<A, K, C> ap(L), aq(Lq);
  return sos_search<K, true>(
      true,
      [&](unsigned kr, unsigned kc) -> int {
        const int q = minor_quick<A, K>(L, ap, kr, kc);
        return q != 2 ? q : MinorOf<A, K>::sign(L, kr, kc);
      },
      [&](unsigned kr, unsigned kc) -> int {
        const int q = minor_quick<A, K>(Lq, aq, kr, kc);
        return q != 2 ? q : MinorOf<A, K>::sign(Lq, kr, kc);
      });
}

// ---- SoS on doubles (det Λ = 0, inside the window) ---------------------------
// On exactly degenerate input the perturbation's minors are mostly far from 0;
// the expansions above are needed only where one is (nearly) 0. Λ as doubles:
// coordinates, the 1-column and, for a lifted column, |x|^2 - w when computing
// it in double loses nothing (every two_product and two_sum error of the
// left-to-right evaluation is 0; a sufficient test) — then every entry is
// exact and a minor of Λ is a determinant of doubles. Returns false when a
// lifted entry is not a double.
template <int K>
FF_HD inline bool lambda_doubles(const double* const* p, const double* w, double (&a)[K][K]) {
  const int ncoord = w ? K - 2 : K - 1;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) a[i][j] = p[i][j];
    if (w) {
      double s = -w[i];
      for (int j = 0; j < ncoord; ++j) {
        double sq = 0.0, sqe = 0.0, t = 0.0, te = 0.0;
        Dbl::two_product(p[i][j], p[i][j], sq, sqe);
        Dbl::two_sum(s, sq, t, te);
        if (sqe != 0.0 || te != 0.0) return false;
        s = t;
      }
      a[i][K - 2] = s;
    }
    a[i][K - 1] = 1.0;
  }
  return true;
}

// Are all r x r minors of the double matrix a computed exactly by
// det_by_minors in double arithmetic? Let every entry be a multiple of 2^g and
// below 2^m in magnitude (`range` covers every entry: the caller's input
// values, to which the 1-column and the lifted entries are added here), g- =
// min(g, 0), m+ = max(m, 0). det_by_minors forms, level by level, sums of
// products entry x (level l-1 minor); if every earlier value is exact, every
// exact value it forms is a signed partial sum of at most r! products of
// l <= r entries (det_plain's levels and its last row are of this form too):
// a multiple of 2^(l g-), hence of 2^(r g-), and below
// r! 2^(r m+) <= 2^(lf(r) + r m+), lf(r) = ceil(log2 r!). Such a value is a
// double when lf(r) + r m+ - r g- <= 53 and r g- >= -1074 (no underflow, and
// no overflow: the magnitude stays below 2^53). Then each rounding is exact,
// by induction every value is exact, and a computed 0 is a true 0.
template <int K>
FF_HD inline bool doubles_exact_minors(const double (&a)[K][K], bool lifted, Range range, int r) {
  range.add(1.0);
  if (lifted)
    for (int i = 0; i < K; ++i) range.add(a[i][K - 2]);
  const int mp = range.ehi > 0 ? range.ehi : 0;
  const int gm = range.llo < 0 ? range.llo : 0;
  return r * gm >= -1074 && log2_factorial_ceil(r) + r * mp - r * gm <= 53;
}

// Plain-double minor of a on the kept rows / columns (static_filter.hpp's
// det_plain: Laplace over column subsets, sums of products as above).
template <int K>
FF_HD inline double double_minor(const double (&a)[K][K], unsigned rows, unsigned cols) {
  const Kept<K> kept(rows, cols);
  const int r = kept.r;
  double t[K * K];
  kept.gather(t, [&](int i, int j) { return a[i][j]; });
  if (r == 0) return 1.0;
  if (r == 1) return t[0];
  return det_plain_of_order<2, K>(t, r);
}

// SoS sign from the double Λ: when doubles_exact_minors holds (small
// integers, lattices) each minor is evaluated in plain doubles, exactly; else
// by det_by_minors in ErrDouble, its sign taken where the bound certifies it;
// 2 when some minor the order reaches is undecided (the expansion search then
// decides). `range`: the input values (coordinates, weights) of the call.
// Stack: K^2 doubles, K^2 ErrDouble, the memo (K = 5: 1.1 KB).
template <int K>
FF_HD inline int sos_sign_doubles(const double* const* p, const double* w, const Range& range) {
  double a[K][K];
  if (!lambda_doubles<K>(p, w, a)) return 2;
  if (doubles_exact_minors<K>(a, w != nullptr, range, K - 1))
    return sos_search<K>(true, [&](unsigned kr, unsigned kc) -> int {
      const double m = double_minor<K>(a, kr, kc);
      return (m > 0.0) - (m < 0.0);
    });
  ErrDouble ap[K * K];
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) ap[i * K + j] = ErrDouble(a[i][j]);
  return sos_search<K>(true, [&](unsigned kr, unsigned kc) -> int {
    const int s = sign_if_certain(errdouble_minor<K>(ap, kr, kc));
    return s != 0 ? s : 2;
  });
}
// The same with the range computed here (tests).
template <int K>
FF_HD inline int sos_sign_doubles(const double* const* p, const double* w) {
  Range range;
  const int ncoord = w ? K - 2 : K - 1;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) range.add(p[i][j]);
    if (w) range.add(w[i]);
  }
  return sos_sign_doubles<K>(p, w, range);
}

template <class A, int K, int C>
FF_HD inline int det_or_sos(const LambdaX<A, K, C>& L, bool sos) {
  constexpr unsigned kAll = (1u << K) - 1u;
  const int s = MinorOf<A, K>::sign(L, kAll, kAll);
  if (s != 0 || !sos) return s;
  return sos_sign<A, K>(L, true);
}

// Λ of K points: p[i] coordinates, w weights (lifted: K-2 coordinates and the
// height) or null (K-1 coordinates).
template <class A, int K, int C>
FF_HD inline void build_lambda(const double* const* p, const double* w, LambdaX<A, K, C>& L) {
  const int ncoord = w ? K - 2 : K - 1;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) L.a[i][j].set(p[i][j]);
    if (w) lifted_entry<A>(p[i], ncoord, w[i], L.a[i][K - 2]);
    L.a[i][K - 1].set(1.0);
  }
}

// The SoS sign of K points (rows sorted by index, det Λ = 0, inside the Dbl
// window) with each minor decided by the cheapest exact means: on the double
// Λ of lambda_doubles (coordinates, the 1-column, and a lifted column that is
// exact in double, or its ErrDouble value |x|^2 - w where it is not) a minor
// is 0 when a kept column is 0 on the kept rows, when the 1-column is kept
// and another kept column is constant on them (points on a plane x_j = c:
// that column minus c times the 1-column is 0), or when two kept rows are
// equal on the kept columns (for an inexact lifted column: when the points'
// coordinates and weights are all equal); else the ErrDouble minor's sign
// where certain; else the exact expansion minor (MinorOf on Λ as
// expansions, built once, on the first such minor). Every minor's sign is
// exact, and sos_search asks for the same minors in the same order as
// sos_sign_doubles then sos_expansions: the same answer, without the
// expansion Λ where no minor needs it (sos_expansions built all of it, its
// lifted entries the dearest part, and restarted the search) — the exactly
// degenerate calls of points on planes (the floors and walls of buildings).
// When doubles_exact_minors holds, every minor in plain doubles, as
// sos_sign_doubles. Stack: the double, ErrDouble and expansion Λ, the memo
// (K = 5: about 2.9 KB, against 2.6 KB in sos_expansions' frame before).
// The columns on which rows x and y of Λ are equal, for sos_search's eq:
// coordinate and 1-columns compared as the doubles they are; a lifted column
// (w) compared as doubles where lambda_doubles made it exact (exact), else
// counted equal only for equal coordinates and weights.
template <int K>
FF_HD inline void lambda_row_eq(const double (&a)[K][K], const double* const* p, const double* w, bool exact,
                                unsigned (&eq)[K * K]) {
  const int ncoord = w ? K - 2 : K - 1;
  for (int x = 0; x < K; ++x)
    for (int y = x + 1; y < K; ++y) {
      unsigned m = 1u << (K - 1);
      bool coords = true;
      for (int j = 0; j < ncoord; ++j) {
        const bool e = p[x][j] == p[y][j];
        coords = coords && e;
        m |= e ? 1u << j : 0u;
      }
      if (w && (exact ? a[x][K - 2] == a[y][K - 2] : coords && w[x] == w[y])) m |= 1u << (K - 2);
      eq[x * K + y] = eq[y * K + x] = m;
    }
}

#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
// The greedy walk over several primes (defined below, after the walk modulo
// one prime): 1 with the leaf's rows, columns and sign, 2 where it does not
// apply or cannot decide.
template <int K>
int multiprime_walk(const double* const* p, const double* w, unsigned& kr, unsigned& kc, int& sg,
                    bool zero_test = false);
#endif

template <int K>
FF_HD FF_DEVICE_NOINLINE int sos_lazy(const double* const* p, const double* w, const Range& range) {
  double a[K][K];
  const bool exact = lambda_doubles<K>(p, w, a);
  unsigned eq[K * K];
  if (exact && doubles_exact_minors<K>(a, w != nullptr, range, K - 1)) {
    lambda_row_eq<K>(a, p, w, true, eq);
    return sos_search<K>(
        true,
        [&](unsigned kr, unsigned kc) -> int {
          const double m = double_minor<K>(a, kr, kc);
          return (m > 0.0) - (m < 0.0);
        },
        nullptr, eq);
  }
  const int ncoord = w ? K - 2 : K - 1;
  // exact: a as it stands. Else lambda_doubles stopped at a row whose lifted
  // entry is not a double: every coordinate and 1-column entry is still
  // exact; the lifted column is approximated (ErrDouble) and never compared
  ErrDouble ap[K * K];
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) {
      a[i][j] = p[i][j];
      ap[i * K + j] = ErrDouble(p[i][j]);
    }
    a[i][K - 1] = 1.0;
    ap[i * K + K - 1] = ErrDouble(1.0);
    if (w) {
      if (exact) {
        ap[i * K + K - 2] = ErrDouble(a[i][K - 2]);
      } else {
        ErrDouble h = ErrDouble(-w[i]);
        for (int j = 0; j < ncoord; ++j) h = h + ErrDouble(p[i][j]) * ErrDouble(p[i][j]);
        ap[i * K + K - 2] = h;
      }
    }
  }
  const int hc = (w && !exact) ? K - 2 : K;  // the column that is not compared (none: K)
  RawLambda<Dbl, K> L;
  bool built = false;
  bool int_row[K];  // the point's Λ row is one of small integers (2^13: |x|^2 < 2^31)
  for (int i = 0; i < K; ++i) int_row[i] = small_integer_point(p[i], ncoord, w, i, 13);
  lambda_row_eq<K>(a, p, w, exact, eq);
  // cheap: 2 instead of the exact expansion minor (the first pass below)
  bool cheap = true;
  auto minor_fn = [&](unsigned kr, unsigned kc) -> int {
    const Kept<K> kept(kr, kc);
    const int* ri = kept.ri;
    const int* ci = kept.ci;
    const int r = kept.r;
    if (r == 0) return 1;
    const bool one = (kc >> (K - 1)) & 1u;
    for (int t = 0; t < r; ++t) {
      const int j = ci[t];
      if (j == hc || j == K - 1) continue;
      bool zero = true, constant = true;
      for (int q = 0; q < r; ++q) {
        zero = zero && a[ri[q]][j] == 0.0;
        constant = constant && a[ri[q]][j] == a[ri[0]][j];
      }
      if (zero || (one && constant)) return 0;
    }
    // two kept rows equal on the kept columns (eq: lambda_row_eq's masks of
    // equal columns; where the lifted entries are not doubles, theirs is
    // equal when the points and weights are): the minor is 0
    for (int x = 1; x < r; ++x)
      for (int y = 0; y < x; ++y)
        if ((kc & ~eq[ri[x] * K + ri[y]]) == 0) return 0;
    // near-lattice minors straight to the exact ones (minor_quick)
    int integral = 0;
    for (int t = 0; t < r; ++t) integral += int_row[ri[t]];
    if (integral < r - 2) {
      const int s = sign_if_certain(errdouble_minor_lazy<K>(ap, kr, kc));
      if (s != 0) return s;
    }
    if (cheap) return 2;
    if (!built) {
      build_lambda<Dbl, K>(p, w, L);
      built = true;
    }
    const int q = small_integer_minor<Dbl, K>(L, kept);
    return q != 2 ? q : MinorOf<Dbl, K>::sign(L, kr, kc);
  };
  // Three passes, each exact where it answers: (1) the search with the
  // cheap minors only (exact zeros by pattern, signs by the ErrDouble
  // filter), 2 at the first minor that would need expansions — points given
  // twice end here, their zero minors all equal rows; (2) the walk by ranks
  // modulo primes to the search's leaf, its minor then decided in full —
  // exact zeros of other kinds (tensor grids of any spacing: rectangles'
  // corners are cospherical) cost the search tens of expansion minors per
  // call; (3) the search with every minor, where (2) does not apply.
  // Measured one thread, rtd compute + certify (the 2-core VM): 16 random
  // 6D points given twice 0.39 s (no eq, a 32 KB memo) -> 0.05 s after (1)
  // alone, 0.24 s with (2) alone; a 5^4 grid of spacing 0.1, 1.10 -> 0.64 s.
  if (const int s = sos_search<K>(true, minor_fn, nullptr, eq); s != 2) return s;
  cheap = false;
#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
  // the leaf sos_search would reach, found by rank tests modulo primes; its
  // minor, not 0 by the walk, decided as the search decides it (a 0 there
  // would contradict the walk: the search then runs, as without it)
  {
    unsigned kr = 0, kc = 0;
    int sg = 1;
    if (multiprime_walk<K>(p, w, kr, kc, sg) == 1) {
      const int s = minor_fn(kr, kc);
      if (s == 1 || s == -1) return sg * s;
    }
  }
#endif
  return sos_search<K>(true, minor_fn, nullptr, eq);
}

#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
// The sign of one minor of Λ (rows kr, columns kc; K points inside the Dbl
// window), exactly: its ErrDouble value where the bound certifies the sign,
// else the expansion minor (MinorOf, as sos_lazy's last resort). For a
// minor the walk modulo primes has shown not to be 0.
template <int K>
inline int lambda_minor_sign(const double* const* p, const double* w, unsigned kr, unsigned kc) {
  const int ncoord = w ? K - 2 : K - 1;
  const bool lifted = w && ((kc >> (K - 2)) & 1u);
  if constexpr (K >= 3) {
    const Kept<K> kept(kr, kc);
    const int r = kept.r;
    if (r >= 3 && ((kc >> (K - 1)) & 1u)) {
      // the 1-column kept (the last kept column): the last kept row b
      // subtracted from the others leaves det = det T, T the (r - 1)^2
      // differences (as det_translated) — one order less than Λ's minor by
      // minors (the 3^5 grid of step 0.1: its leaves are mostly 6 x 6
      // orientations, minor_levels<6, 6, ErrDouble> 10 % of `rtd`). A lifted
      // entry's difference h_i - h_b = Σ_j (x_ij - x_bj)(x_ij + x_bj) -
      // (w_i - w_b), without cancelling |p|^2 terms.
      const int b = kept.ri[r - 1];
      const int n = r - 1;
      ErrDouble t[(K - 1) * (K - 1)];
      for (int i = 0; i < n; ++i) {
        const int row = kept.ri[i];
        for (int jj = 0; jj < n; ++jj) {
          const int col = kept.ci[jj];
          if (col < ncoord) {
            t[i * n + jj] = ErrDouble(p[row][col]) - ErrDouble(p[b][col]);
          } else {  // the lifted column
            ErrDouble h = -(ErrDouble(w[row]) - ErrDouble(w[b]));
            for (int j = 0; j < ncoord; ++j)
              h = h + (ErrDouble(p[row][j]) - ErrDouble(p[b][j])) * (ErrDouble(p[row][j]) + ErrDouble(p[b][j]));
            t[i * n + jj] = h;
          }
        }
      }
      ErrDouble v(0.0, HUGE_VAL);
      if (n == 2) v = det_by_minors<2>(t);
      if (n == 3) v = det_by_minors<3>(t);
      if constexpr (K >= 5) if (n == 4) v = det_by_minors<4>(t);
      if constexpr (K >= 6) if (n == 5) v = det_gauss<5>(t);
      if constexpr (K >= 7) if (n == 6) v = det_gauss<6>(t);
      if constexpr (K >= 8) if (n == 7) v = det_gauss<7>(t);
      if (const int s = sign_if_certain(v); s != 0) return s;
      RawLambda<Dbl, K> L;
      build_lambda<Dbl, K>(p, w, L);
      return MinorOf<Dbl, K>::sign(L, kr, kc);
    }
  }
  ErrDouble ap[K * K];  // the kept rows only (errdouble_minor reads no other)
  for (int i = 0; i < K; ++i) {
    if (!((kr >> i) & 1u)) continue;
    ErrDouble h = ErrDouble(lifted ? -w[i] : 0.0);
    for (int j = 0; j < ncoord; ++j) {
      ap[i * K + j] = ErrDouble(p[i][j]);
      if (lifted) h = h + ErrDouble(p[i][j]) * ErrDouble(p[i][j]);
    }
    if (w) ap[i * K + K - 2] = h;
    ap[i * K + K - 1] = ErrDouble(1.0);
  }
  if (const int s = sign_if_certain(errdouble_minor<K>(ap, kr, kc)); s != 0) return s;
  RawLambda<Dbl, K> L;
  build_lambda<Dbl, K>(p, w, L);
  return MinorOf<Dbl, K>::sign(L, kr, kc);
}

// The SoS sign of K points whose determinant the filters left undecided
// (inside the Dbl window, rows sorted by index), by the walk modulo primes
// first: 2 where the walk finds det Λ not 0 (the caller's exact stages give
// its sign) or does not apply; else det Λ = 0 exactly, and the sign is the
// walk's parity times its leaf's minor — without the exact determinant. On
// tensor grids of non-dyadic spacing (np.mgrid step 0.1, np.linspace) nearly
// every call the filters leave is exactly degenerate, and its exact
// determinant (lifted_adaptive / orient_adaptive running to their last,
// exact stage) was the largest cost: 31 % of `dt3` on a 20^3 grid of step
// 0.1, one thread (perf), before the perturbation's search (sos_lazy) began.
template <int K>
inline int sos_walk_first(const double* const* p, const double* w) {
  constexpr unsigned kAll = (1u << K) - 1u;
  unsigned kr = 0, kc = 0;
  int sg = 1;
  if (multiprime_walk<K>(p, w, kr, kc, sg) != 1) return 2;
  if (kr == kAll && kc == kAll) return 2;  // det Λ is not 0
  const int s = lambda_minor_sign<K>(p, w, kr, kc);
  return s == 1 || s == -1 ? sg * s : 2;  // (0: contradicts the walk; the search decides)
}

// det Λ = 0, shown by the walk modulo primes (its first dependence, every
// prime agreeing); false where det Λ is not 0 or the walk cannot tell.
template <int K>
inline bool det_zero_by_walk(const double* const* p, const double* w) {
  unsigned kr = 0, kc = 0;
  int sg = 1;
  return multiprime_walk<K>(p, w, kr, kc, sg, true) == 1 && kr != (1u << K) - 1u;
}
#endif

// The expansion stages' entry points, one function each, Dbl and XDbl apart.
// On the device (FF_DEVICE_NOINLINE) each is a call with its own frame, so a
// thread's stack is the deepest of them, not their sum: the device compiler
// does not share stack between a function's branches (ptxas, sm_90: the frame
// of one thread running lambda_exact<5> was 122 KB, the Dbl and XDbl buffers
// side by side; "Stack per call" at the top of this file has the sizes now).
//
// SoS of K points (rows sorted by index) on Λ as expansions, det Λ = 0.
template <class A, int K>
FF_HD FF_DEVICE_NOINLINE int sos_expansions(const double* const* p, const double* w) {
  RawLambda<A, K> L;
  build_lambda<A, K>(p, w, L);
  return sos_sign<A, K>(L, true);
}

// det Λ = (-1)^(K-1-b) det T, T the (K-1) x (K-1) matrix of exact
// differences t_ij = p_i[j] - p_b[j] (two_sum: one or two components) over
// the rows i != b in increasing order, b the base row (default K-1, where
// the sign is +1: subtract row b from the others, expand along the 1-column);
// a lifted column holds |p_i - p_b|^2 - (w_i - w_b), exactly
// (lambda_filter.hpp: the dropped term 2 p_b.(p_i - p_b) is the same
// combination of the other columns in every row). Fewer levels and smaller
// entries than Λ itself.
template <class A, int K, int C>
FF_HD inline void build_translated(const double* const* p, const double* w, LambdaX<A, K - 1, C>& T,
                                   int b = K - 1) {
  using V = typename A::T;
  constexpr int N = K - 1;
  const int ncoord = w ? K - 2 : K - 1;
  const double* base = p[b];
  for (int i = 0; i < N; ++i) {
    const double* pi = p[i < b ? i : i + 1];
    const double wi = w ? w[i < b ? i : i + 1] : 0.0;
    for (int j = 0; j < ncoord; ++j) {
      V hi, lo;
      A::two_sum(A::from_double(pi[j]), A::neg(A::from_double(base[j])), hi, lo);
      auto& e = T.a[i][j];
      if (A::is_zero(lo)) {
        e.n = 1;
        e.c[0] = hi;
      } else {
        e.n = 2;
        e.c[0] = lo;
        e.c[1] = hi;
      }
    }
    if (w) {
      // |d|^2 - (w_i - w_k): products of the difference expansions, then the weights
      V buf[C + 8], tmp[C + 8], sq[8], wd[2];
      int len = 0;
      A::two_sum(A::from_double(wi), A::neg(A::from_double(w[b])), wd[1], wd[0]);
      wd[0] = A::neg(wd[0]);
      wd[1] = A::neg(wd[1]);
      if (A::is_zero(wd[0])) {
        buf[0] = wd[1];
        len = 1;
      } else {
        buf[0] = wd[0];
        buf[1] = wd[1];
        len = 2;
      }
      for (int j = 0; j < ncoord; ++j) {
        const auto& d = T.a[i][j];
        // d^2 = Σ_c d_c d (a scale per component, summed)
        int slen = 0;
        for (int c = 0; c < d.n; ++c) {
          V part[4];
          const int pl = scale_zeroelim<A>(d.n, d.c, d.c[c], part);
          if (slen == 0) {
            for (int q = 0; q < pl; ++q) sq[q] = part[q];
            slen = pl;
          } else {
            V t2[8];
            slen = sum_zeroelim<A>(slen, sq, pl, part, t2);
            slen = compress<A>(slen, t2);
            for (int q = 0; q < slen; ++q) sq[q] = t2[q];
          }
        }
        len = sum_zeroelim<A>(len, buf, slen, sq, tmp);
        len = compress<A>(len, tmp);
        for (int q = 0; q < len; ++q) buf[q] = tmp[q];
      }
      auto& e = T.a[i][N - 1];
      e.n = len;
      for (int q = 0; q < len; ++q) e.c[q] = buf[q];
    }
  }
}

// The base row for det_translated: the row whose values (coordinates and
// weight) span the fewest bits (bit_span; 0 for a row of zeros), the last such
// row on ties (K-1 when no row is narrower than it). On a lattice with a few
// points moved by some ulp that is an unmoved point: the differences of the
// other unmoved points from it stay small integers, and MinorLaplace expands
// over those rows in binary64; from a moved base every difference would carry
// its tails.
template <int K>
FF_HD inline int narrowest_row(const double* const* p, const double* w) {
  const int ncoord = w ? K - 2 : K - 1;
  int best = K - 1, best_span = 1 << 30;
  for (int i = K - 1; i >= 0; --i) {
    int lo = 100000, hi = -100000;
    for (int j = 0; j <= ncoord; ++j) {
      const double v = j < ncoord ? p[i][j] : (w ? w[i] : 0.0);
      int vl = 0, vh = 0;
      if (v != 0.0 && bit_span(v, vl, vh)) {
        lo = vl < lo ? vl : lo;
        hi = vh > hi ? vh : hi;
      }
    }
    const int span = hi >= lo ? hi - lo : 0;
    if (span < best_span) best = i, best_span = span;
  }
  return best;
}

template <class A, int K>
FF_HD FF_DEVICE_NOINLINE int det_translated(const double* const* p, const double* w) {
  LambdaX<A, K - 1> T;
  const int b = narrowest_row<K>(p, w);
  build_translated<A, K>(p, w, T, b);
  constexpr unsigned kAll = (1u << (K - 1)) - 1u;
  const int s = MinorOf<A, K - 1>::sign(T, kAll, kAll);
  return ((K - 1 - b) & 1) ? -s : s;
}

// Exact determinants of doubles as expansions ([She97] §4.3, stage B):
// a0 b1 - a1 b0 (<= 4 components) and the 3 x 3 determinant of rows a, b, c
// expanded along the third column (<= 24 components).
FF_HD inline int det2_exact(double a0, double a1, double b0, double b1, double* out) {
  double x[2], y[2];
  Dbl::two_product(a0, b1, x[1], x[0]);
  Dbl::two_product(a1, b0, y[1], y[0]);
  y[0] = -y[0];
  y[1] = -y[1];
  return sum_zeroelim<Dbl>(2, x, 2, y, out);
}
FF_HD inline int det3_exact(const double* a, const double* b, const double* c, double* out) {
  double m_bc[4], m_ac[4], m_ab[4], s0[8], s1[8], s2[8], u[16];
  const int l_bc = det2_exact(b[0], b[1], c[0], c[1], m_bc);
  const int l_ac = det2_exact(a[0], a[1], c[0], c[1], m_ac);
  const int l_ab = det2_exact(a[0], a[1], b[0], b[1], m_ab);
  const int x = scale_zeroelim<Dbl>(l_bc, m_bc, a[2], s0);
  const int y = scale_zeroelim<Dbl>(l_ac, m_ac, -b[2], s1);
  const int z = scale_zeroelim<Dbl>(l_ab, m_ab, c[2], s2);
  const int xy = sum_zeroelim<Dbl>(x, s0, y, s1, u);
  return sum_zeroelim<Dbl>(xy, u, z, s2, out);
}

// Shewchuk's adaptive stages B and C for orient2d / orient3d (K = 3, 4, no
// lift) [She97 §4.3, orient2dadapt / orient3dadapt], on T (rows p_i - p_{K-1},
// det T = det Λ). Stage B: the determinant of the rounded differences (heads)
// exactly, as an expansion (<= 4 / 24 components); its estimate decides when
// it exceeds errboundB x the permanent of |heads|, the bound on what the
// neglected tails (|tail| <= u |head|) can change. When every tail is 0 the
// stage-B expansion is the exact determinant. Stage C adds the first-order
// tail terms in floating point and decides beyond errboundC x permanent +
// resulterrbound x |det|. Shewchuk's bounds assume relative rounding errors
// only: inside the double window (Range::fits, checked by the caller) every
// value is a multiple of 2^-1074, so no operation underflows inexactly and
// none overflows. Returns 2 when undecided (the caller's full exact stage).
template <int K>
FF_HD inline int orient_adaptive(const double* const* p) {
  static_assert(K == 3 || K == 4, "orient2d / orient3d only");
  constexpr int N = K - 1;
  constexpr double eps = 0x1p-53;
  constexpr double resulterrbound = (3.0 + 8.0 * eps) * eps;
  double t[N * N], tail[N * N];
  bool exact = true;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      Dbl::two_sum(p[i][j], -p[K - 1][j], t[i * N + j], tail[i * N + j]);
      exact = exact && tail[i * N + j] == 0.0;
    }
  auto estimate = [](int len, const double* e) {
    double v = e[0];
    for (int i = 1; i < len; ++i) v += e[i];
    return v;
  };
  if constexpr (K == 3) {
    constexpr double errB = (2.0 + 12.0 * eps) * eps;
    constexpr double errC = (9.0 + 64.0 * eps) * eps * eps;
    const double acx = t[0], acy = t[1], bcx = t[2], bcy = t[3];
    const double detsum = std::fabs(acx * bcy) + std::fabs(acy * bcx);
    double B[4];
    const int len = det2_exact(acx, acy, bcx, bcy, B);
    if (exact) return sign_of<Dbl>(len, B);
    double det = estimate(len, B);
    double bound = errB * detsum;
    if (det > bound || -det > bound) return det > 0 ? 1 : -1;
    const double acxt = tail[0], acyt = tail[1], bcxt = tail[2], bcyt = tail[3];
    bound = errC * detsum + resulterrbound * std::fabs(det);
    det += (acx * bcyt + bcy * acxt) - (acy * bcxt + bcx * acyt);
    if (det > bound || -det > bound) return det > 0 ? 1 : -1;
    return 2;
  } else {
    constexpr double errB = (3.0 + 28.0 * eps) * eps;
    constexpr double errC = (26.0 + 288.0 * eps) * eps * eps;
    // rows a, b, c minus d; Shewchuk's names
    const double adx = t[0], ady = t[1], adz = t[2], bdx = t[3], bdy = t[4], bdz = t[5];
    const double cdx = t[6], cdy = t[7], cdz = t[8];
    const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                             (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                             (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
    // det T along the z column: adz (bdx cdy - bdy cdx) - bdz (adx cdy - ady cdx)
    //                           + cdz (adx bdy - ady bdx)
    double B[24];
    const int len = det3_exact(t, t + 3, t + 6, B);
    if (exact) return sign_of<Dbl>(len, B);
    double det = estimate(len, B);
    double bound = errB * permanent;
    if (det > bound || -det > bound) return det > 0 ? 1 : -1;
    const double adxt = tail[0], adyt = tail[1], adzt = tail[2], bdxt = tail[3], bdyt = tail[4];
    const double bdzt = tail[5], cdxt = tail[6], cdyt = tail[7], cdzt = tail[8];
    bound = errC * permanent + resulterrbound * std::fabs(det);
    det += (adz * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
            adzt * (bdx * cdy - bdy * cdx)) +
           (bdz * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
            bdzt * (cdx * ady - cdy * adx)) +
           (cdz * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
            cdzt * (adx * bdy - ady * bdx));
    if (det > bound || -det > bound) return det > 0 ? 1 : -1;
    return 2;
  }
}

// The adaptive stage of power2d / power3d (K = 4, 5; [She97] §4.4,
// incircleadapt / insphereadapt, stage B): T of the translated rows
// d_i = p_i - p_(K-1) with the lifted column l_i = |d_i|^2 - (w_i - w_(K-1))
// (lambda_filter.hpp). When every Two_Diff tail of the coordinates is 0 — the
// usual case when the points are close to each other, as in near-degenerate
// and small-integer sets — the d_ij are exact doubles, l_i is an exact short
// expansion (M two_products and one two_sum: <= 2M + 2 components), and so is
// every cofactor C_i of the coordinate columns (det2_exact / det3_exact):
// det T = Σ_i (-1)^(i+M) l_i C_i is then computed exactly, with no error
// bound to test, far more cheaply than the whole-matrix Laplace expansion of
// det_translated (whose entry-by-minor products and merges dominated the
// profile). l_i and C_i are compressed first ([She97] Fig. 13: a few
// components instead of up to 8 and 24), so each product is a few
// scale_zeroelim calls. Returns 2 when a tail is not 0 (det_translated
// decides). Inside the double window only (Range::fits(K), checked by the
// caller): nothing overflows, no product's error underflows, and the
// accumulator, compressed whenever it exceeds kCapD, obeys the length bound of
// expansion.hpp. Stack: about 3 kCapD + 2 x 48 doubles (1.8 KB).
template <int K>
FF_HD inline int lifted_adaptive(const double* const* p, const double* w) {
  static_assert(K == 4 || K == 5, "power2d / power3d only");
  constexpr int N = K - 1, M = K - 2;
  double d[N][3];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < M; ++j) {
      double tail = 0.0;
      Dbl::two_sum(p[i][j], -p[K - 1][j], d[i][j], tail);
      if (tail != 0.0) return 2;
    }
  double acc[2 * kCapD + 4], sum[2 * kCapD + 4], scaled[48];
  int alen = 1;
  acc[0] = 0.0;
  for (int i = 0; i < N; ++i) {
    // C_i: the M x M determinant of the coordinates of the other rows (first:
    // when it is 0, as for coplanar points, l_i is not needed)
    double cof[24];
    int clen = 0;
    {
      const double* r[3];
      int n = 0;
      for (int q = 0; q < N; ++q)
        if (q != i) r[n++] = d[q];
      if constexpr (M == 2) clen = det2_exact(r[0][0], r[0][1], r[1][0], r[1][1], cof);
      else clen = det3_exact(r[0], r[1], r[2], cof);
      clen = compress<Dbl>(clen, cof);
    }
    if (clen == 1 && cof[0] == 0.0) continue;
    // l_i = Σ_j d_ij^2 - (w_i - w_k), exactly
    double lift[2 * M + 2], ltmp[2 * M + 2];
    int llen = 0;
    {
      double wh = 0.0, wl = 0.0;
      Dbl::two_sum(w[i], -w[K - 1], wh, wl);
      lift[0] = -wl;
      lift[1] = -wh;
      llen = 2;
      for (int j = 0; j < M; ++j) {
        double sq[2];
        Dbl::two_product(d[i][j], d[i][j], sq[1], sq[0]);
        llen = sum_zeroelim<Dbl>(llen, lift, 2, sq, ltmp);
        for (int q = 0; q < llen; ++q) lift[q] = ltmp[q];
      }
      llen = compress<Dbl>(llen, lift);
    }
    if (llen == 1 && lift[0] == 0.0) continue;
    const bool negative = ((i + M) & 1) != 0;
    for (int c = 0; c < llen; ++c) {
      if (lift[c] == 0.0) continue;
      const int sl = scale_zeroelim<Dbl>(clen, cof, negative ? -lift[c] : lift[c], scaled);
      alen = sum_zeroelim<Dbl>(alen, acc, sl, scaled, sum);
      if (alen > kCapD) alen = compress<Dbl>(alen, sum);
      for (int q = 0; q < alen; ++q) acc[q] = sum[q];
    }
  }
  return sign_of<Dbl>(alen, acc);
}

// The double-double stage (err_dd.hpp) for every K: det T (lambda_filter.hpp:
// rows d_i = p_i - p_(K-1), with the lifted column l_i = |d_i|^2 - (w_i -
// w_(K-1)) when w is given) by det_by_minors on ErrDD values. The differences
// d_ij and w_i - w_(K-1) enter exactly (two_sum: a head and its Two_Diff tail,
// e = 0), so the only errors are those of the products and sums, each bounded
// by err_dd.hpp's rules — of order u^2 times the terms of the determinant,
// where the dynamic filter's are of order u. A near-degenerate call (det of
// order u times its terms) is decided here whether or not the tails are 0;
// an exactly degenerate one never is (its computed value is within the bound
// of 0 by construction). Inside the double window of degree K (lifted) or
// K - 1 only (Range::fits, checked by the caller: err_dd.hpp's precondition).
// Returns ±1 when certain, 2 when not (the exact stages decide). Stack:
// 2^(K-1) + (K-1)^2 ErrDD values of 24 bytes (K = 5: 0.8 KB, K = 8: 4.2 KB).
template <int K>
FF_HD inline int lambda_sign_dd(const double* const* p, const double* w) {
  constexpr int N = K - 1;
  ErrDD t[N * N];
  const double* base = p[K - 1];
  const int ncoord = w ? N - 1 : N;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < ncoord; ++j) t[i * N + j] = ErrDD::difference(p[i][j], base[j]);
    if (w) {
      ErrDD lift = -ErrDD::difference(w[i], w[K - 1]);
      for (int j = 0; j < ncoord; ++j) lift = lift + t[i * N + j] * t[i * N + j];
      t[i * N + N - 1] = lift;
    }
  }
  const int s = sign_if_certain(det_by_minors<N, ErrDD>(t));
  return s != 0 ? s : 2;
}

// Exact sign of det Λ of K points in the given row order; with `sos`, the
// Simulation-of-Simplicity sign (rows must then be sorted by increasing,
// distinct point index).
// The input values of one call (coordinates, weights).
template <int K>
FF_HD inline Range call_range(const double* const* p, const double* w) {
  Range range;
  const int ncoord = w ? K - 2 : K - 1;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) range.add(p[i][j]);
    if (w) range.add(w[i]);
  }
  return range;
}

// Small integers and lattices (the exactly degenerate inputs): when every
// entry of Λ is a double (lambda_doubles) and doubles_exact_minors proves
// every operation of det_plain exact for the whole K x K determinant, its
// plain-double value is det Λ itself — a computed 0 is a true 0 — and the
// same holds for every smaller minor the perturbation asks for. Fills a and
// returns true in that case (K <= 7; inside the double window).
template <int K>
FF_HD inline bool lattice_doubles(const double* const* p, const double* w, const Range& range, double (&a)[K][K]) {
  if constexpr (K <= 7) {
    return range.finite && range.fits(w ? K : K - 1) && lambda_doubles<K>(p, w, a) &&
           doubles_exact_minors<K>(a, w != nullptr, range, K);
  } else {
    (void)p, (void)w, (void)range, (void)a;
    return false;
  }
}

// The exact (sos: SoS) sign on lattice_doubles' matrix.
template <int K>
FF_HD inline int lattice_sign(const double (&a)[K][K], bool sos) {
  auto sign_of = [&](unsigned kr, unsigned kc) -> int {
    const double m = double_minor<K>(a, kr, kc);
    return (m > 0.0) - (m < 0.0);
  };
  constexpr unsigned kAll = (1u << K) - 1u;
  const int s = sign_of(kAll, kAll);
  if (s != 0 || !sos) return s;
  return sos_search<K>(true, sign_of);
}

// ---- Integer lattices: det Λ and the SoS minors in integer arithmetic --------
// lattice_doubles needs the whole K x K determinant exact in doubles, which a
// lifted Λ of small integers exceeds quickly (K = 5, coordinates below 2^6:
// log2(5!) + 3 x 6 + 13 + 1 > 53 bits in the worst case of its global bound).
// Integers have no rounding: when every value of the call is an integer
// multiple of a common power of two, Λ is scaled column by column to an
// integer matrix and every minor is evaluated exactly in int64 or __int128.
//
// Scaling. Let 2^gc be the lowest set bit over the nonzero coordinates and
// every coordinate |x| < 2^hc (gc = hc = 0 when all are 0): X = x 2^-gc is an
// integer, |X| < 2^mc, mc = hc - gc. Lifted, with 2^gw the lowest set bit and
// 2^hw the bound of the nonzero weights, gl = min(2 gc, gw) (2 gc without
// weights): the height column becomes H = (|x|^2 - w) 2^-gl =
// (Σ_j X_j^2) 2^(2 gc - gl) - w 2^-gl, an integer. Each column of Λ is thus
// multiplied by a positive power of two (2^-gc, 2^-gl; the 1-column by 1), so
// every minor is multiplied by a positive number: the sign of det Λ and of
// every minor of the perturbation is unchanged, and the SoS search on the
// integer matrix (the same sos_search, the same minors) returns the same sign
// as every other exact stage.
// Entry bounds (int64): |X| < 2^mc with mc <= 62 unlifted; lifted mc <= 29,
// so Σ_j X_j^2 < (K - 2) 2^(2 mc) <= 2^(2 mc + q), q = 3 for K - 2 <= 8 and
// 4 up to 16, shifted by s = 2 gc - gl with 2 mc + q + s <= 61, and |w 2^-gl| < 2^(hw - gl) with
// hw - gl <= 61: |H| < 2^61 + 2^61 = 2^62. Every entry is below 2^62. The
// scaled values are computed as v 2^-gc (and w 2^-gl) in double, the power of
// two normal (-1022 <= -gc, -gl <= 1023, else the path is not taken): exact,
// the result being an integer below 2^62 with the 53-bit mantissa of v, and
// so is its conversion to int64.
// Minor bound: let b_j be the bit length of the largest |entry| of column j
// (0 for a zero column; 1 for the 1-column), B = Σ_j b_j, lf(K) =
// ceil(log2 K!). An r x r minor on columns S is a sum of r! products of one
// entry per column of S, so |minor| <= r! Π_{j in S} 2^(b_j) <= K! 2^B <=
// 2^(lf(K) + B). The Laplace expansion (det_by_minors: d[S] = Σ_j ± t[j]
// d[S \ j] along row |S| - 1) forms only such minors, products t[j] d[S \ j]
// — a sum of (|S| - 1)! of those products — and partial sums of the terms of
// d[S] — a sum of at most |S|! of them — all bounded the same way. So with
// lf(K) + B <= 63 every value is below 2^63 (int64), with lf(K) + B <= 127
// below 2^127 (__int128, where the compiler has it): no operation overflows,
// every value is exact, and the computed sign is the sign of the minor.
// For the motivating 3D Delaunay grid (coordinates 0..46, K = 5): b = 6, 6,
// 6, 13, 1, B = 32, lf(5) = 7: int64. K <= 7 (det_by_minors' orders).
#if defined(__SIZEOF_INT128__)
#define FLIPFLOP_INT128 1
__extension__ typedef __int128 int128_t;  // __extension__: no -Wpedantic warning
__extension__ typedef unsigned __int128 uint128_t;
#endif

// Up to 11 rows (predicates.hpp kMaxLambdaK): beyond 7, only the walk by
// ranks modulo p below decides (int_lattice_sign returns 2 where it cannot).
inline constexpr int kIntLambdaMaxK = 11;

template <int K>
struct IntLambda {
  long long a[K][K];
  bool wide = false;  // __int128 needed (lf(K) + B > 63)
  int bits = 127;     // lf(K) + B: every minor is below 2^bits in magnitude
};


// int_lambda's first half: the coordinates' exponent span (gc, hc). Unlifted,
// it also knows the bound lf(K) + 1 + B exactly (see below), hence whether
// the call needs __int128 (`wide`) before any entry is built.
struct IntScan {
  int gc = 100000, hc = -100000;
  bool wide = false;  // unlifted: lf(K) + 1 + B > 63 (lifted: decided by int_lambda_build)
  int bits = 127;     // unlifted: lf(K) + 1 + B (lifted: computed by int_lambda_build)
};

#if defined(FLIPFLOP_INT128)
inline constexpr int kIntLambdaMaxBits = 127;
#else
inline constexpr int kIntLambdaMaxBits = 63;
#endif

// False when a value is not finite or a bound fails. Random doubles fail
// within the first row: lifted, a value whose own mantissa spans more than 29
// bits; unlifted, once the columns' spans read so far exceed the bound — a
// nonzero v with |v| < 2^hi has |v| >= 2^(hi-1) (normal or subnormal), so
// column j's bound b_j below is exactly max_i hi_ij - gc, and gc only falls
// as more values are read: the sum so far is a lower bound of the final B.
template <int K>
FF_HD inline bool int_lambda_scan(const double* const* p, const double* w, IntScan& S) {
  const int ncoord = w ? K - 2 : K - 1;
  const int max_mc = w ? 29 : 62;
  int colhi[K > 2 ? K - 1 : 1];
  for (int j = 0; j < ncoord; ++j) colhi[j] = -100000;
  int gc = 100000, hc = -100000, lower = 0;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) {
      const double v = p[i][j];
      if (v == 0.0) continue;
      int low = 0, hi = 0;
      if (!bit_span(v, low, hi) || hi - low > max_mc) return false;
      gc = low < gc ? low : gc;
      hc = hi > hc ? hi : hc;
      colhi[j] = hi > colhi[j] ? hi : colhi[j];
    }
    if (!w) {
      lower = log2_factorial_ceil(K) + 1;  // the 1-column
      for (int j = 0; j < ncoord; ++j)
        if (colhi[j] > -100000) lower += colhi[j] - gc;
      if (lower > kIntLambdaMaxBits) return false;
    }
  }
  if (hc < gc) gc = hc = 0;  // every coordinate is 0
  if (hc - gc > max_mc || gc < -1023 || gc > 1022) return false;
  S.gc = gc;
  S.hc = hc;
  S.wide = !w && lower > 63;
  S.bits = w ? 127 : lower;
  return true;
}

// int_lambda's second half: the entries, after int_lambda_scan(p, w, S).
template <int K>
FF_HD inline bool int_lambda_build(const double* const* p, const double* w, const IntScan& S, IntLambda<K>& L) {
  const int ncoord = w ? K - 2 : K - 1;
  const int gc = S.gc, mc = S.hc - S.gc;
  const double cscale = XDbl::pow2(-gc);  // v 2^-gc: an integer below 2^mc, exactly
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < ncoord; ++j) L.a[i][j] = static_cast<long long>(p[i][j] * cscale);
  for (int i = 0; i < K; ++i) L.a[i][K - 1] = 1;
  if (!w) {  // B is known from the scan
    L.wide = S.wide;
    L.bits = S.bits;
    return true;
  }
  int gw = 100000, hw = -100000;
  for (int i = 0; i < K; ++i) {
    const double v = w[i];
    if (v == 0.0) continue;
    int low = 0, hi = 0;
    if (!bit_span(v, low, hi)) return false;
    gw = low < gw ? low : gw;
    hw = hi > hw ? hi : hw;
  }
  const int gl = gw < 2 * gc ? gw : 2 * gc;
  const int s = 2 * gc - gl;
  constexpr int q = K - 2 <= 8 ? 3 : 4;  // Σ_j X_j^2 < 2^(2 mc + q)
  if (2 * mc + q + s > 61 || gl < -1023 || gl > 1022) return false;
  if (hw > -100000 && hw - gl > 61) return false;
  const double wscale = XDbl::pow2(-gl);
  for (int i = 0; i < K; ++i) {
    long long sq = 0;
    for (int j = 0; j < ncoord; ++j) sq += L.a[i][j] * L.a[i][j];
    L.a[i][K - 2] = static_cast<long long>(static_cast<unsigned long long>(sq) << s) -
                    static_cast<long long>(w[i] * wscale);
  }
  int bits = log2_factorial_ceil(K) + 1;  // the 1-column
  for (int j = 0; j < K - 1; ++j) {
    unsigned long long any = 0;  // the OR of the magnitudes: the bit length of their maximum
    for (int i = 0; i < K; ++i) {
      const long long v = L.a[i][j];
      any |= v < 0 ? 0ull - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
    }
    bits += bit_length(any);
  }
  if (bits > kIntLambdaMaxBits) return false;
  L.wide = bits > 63;
  L.bits = bits;
  return true;
}

// Λ of the call as integers (see above); false when a value is not finite or
// a bound fails (the other stages decide).
template <int K>
FF_HD inline bool int_lambda(const double* const* p, const double* w, IntLambda<K>& L) {
  if constexpr (K > kIntLambdaMaxK) {
    (void)p, (void)w, (void)L;
    return false;
  } else {
    IntScan S;
    return int_lambda_scan<K>(p, w, S) && int_lambda_build<K>(p, w, S, L);
  }
}

// det_by_minors<N, I>(t) for the run-time order r, N <= r <= K (only orders
// that fit t, K x K entries, are instantiated).
template <int N, int K, class I>
FF_HD inline I int_det_of_order(const I* t, int r) {
  if constexpr (N > K) {
    (void)t, (void)r;
    return I(0);  // unreachable: r <= K
  } else {
    if (r == N) return det_by_minors<N, I>(t);
    return int_det_of_order<N + 1, K, I>(t, r);
  }
}

// Sign of the minor of the integer Λ on the kept rows / columns.
template <class I, int K>
FF_HD inline int int_minor_sign(const IntLambda<K>& L, unsigned rows, unsigned cols) {
  const Kept<K> kept(rows, cols);
  if (kept.r == 0) return 1;
  I t[K * K];
  kept.gather(t, [&](int i, int j) { return static_cast<I>(L.a[i][j]); });
  const I m = int_det_of_order<1, K, I>(t, kept.r);
  return (m > 0) - (m < 0);
}

// ---- The SoS search on an integer Λ by ranks modulo a prime p ------------
// sos_search returns sg · minor(kr, kc) at the first leaf, in its order, whose
// minor is not 0; on a degenerate lattice it reads ~25 minors and walks
// hundreds of leaves per call (3^5 grid Delaunay, K = 7: 107,569 calls, 2.7 M
// minors, 65 % of rtd_cavity's instructions). The same leaf is found by rank
// tests, one row at a time.
//
// Lemma (the subtree test). Fix the choices of rows K-1 .. r+1: F the rows
// kept so far, kc the columns left (the 1-column always among them; |F| +
// r + 1 = |kc|). The leaves below are the partial matchings of rows r .. 0
// to the perturbable columns of kc, and their terms are exactly the terms of
// det [F; G] (on the columns kc) expanded along the rows of G, where row i of
// G is Λ's row i with an indeterminate ε_ij added in each perturbable column
// of kc: a row contributes either its entries or ε_ij e_j, two rows with the
// same e_j give 0, and distinct matchings give distinct monomials (no
// cancellation). So some leaf below is not 0 iff det [F; G] is not the zero
// polynomial, iff F has full row rank on kc: necessary at once; sufficient
// because a row of G ranges over every vector (y, 1) (its 1-column entry is
// 1, y free), an affine hyperplane off the origin, which spans the space, so
// each row of G can be chosen outside the span of the rows before it.
// Hence the greedy walk: at row r take the first option (not perturbed, then
// columns K-2 .. 0 still in kc) whose subtree passes the test — for "not
// perturbed", F + row r independent on kc; for column c, F independent on
// kc \ {c}, i.e. e_c not in the row space of F on kc. The root passes (F
// empty) and a passing subtree has a passing option, so the walk reaches a
// leaf with F square and of full rank: sos_search's first non-zero leaf,
// with the same sign bookkeeping. Only that leaf's minor is evaluated
// (int_lattice_sos_mod below).
// Ranks modulo p. Every minor of Λ is below 2^bits (int_lambda's bound lf(K)
// + B) in magnitude; with bits <= P::kMaxBits < log2 p a minor is 0 iff it is
// 0 modulo the prime p, so every rank above — the size of the largest
// non-zero minor — is the same over the integers and over GF(p). The
// elimination is fraction-free (row <- g row - f pivot_row, g a non-zero
// pivot: an invertible row operation in GF(p)), with no inverse to compute.
// Two primes: p = 2^31 - 1 (products in 64 bits; the 3^5 grid's K = 7 calls
// have bits = 29) and p = 2^61 - 1 (products in 128 bits).
struct ModP31 {
  static constexpr unsigned long long p = (1ull << 31) - 1ull;
  static constexpr int kMaxBits = 30;
  // x mod p for any 64-bit x: 2^31 = 1 (mod p), so x = hi + lo; twice leaves
  // it below 2^31 + 8, one subtraction below p
  FF_HD static unsigned long long fold(unsigned long long x) {
    x = (x & p) + (x >> 31);
    x = (x & p) + (x >> 31);
    return x >= p ? x - p : x;
  }
  FF_HD static unsigned long long mul(unsigned long long a, unsigned long long b) { return fold(a * b); }
  // a x - b y = a x + b (p - y) (mod p): each product at most 2^62, the sum below 2^63
  FF_HD static unsigned long long cross(unsigned long long a, unsigned long long x, unsigned long long b,
                                        unsigned long long y) {
    return fold(a * x + b * (p - y));
  }
};
#if defined(FLIPFLOP_INT128)
struct ModP61 {
  static constexpr unsigned long long p = (1ull << 61) - 1ull;
  static constexpr int kMaxBits = 60;
  // 2^61 = 1 (mod p): hi + lo < 2^61 + 8 for a 64-bit x, then one subtraction
  FF_HD static unsigned long long fold(unsigned long long x) {
    x = (x & p) + (x >> 61);
    return x >= p ? x - p : x;
  }
  // a product (< 2^122) folds to hi + lo < 2^62, then below p
  FF_HD static unsigned long long mul(unsigned long long a, unsigned long long b) {
    const uint128_t s = static_cast<uint128_t>(a) * b;
    return fold((static_cast<unsigned long long>(s) & p) + static_cast<unsigned long long>(s >> 61));
  }
  FF_HD static unsigned long long cross(unsigned long long a, unsigned long long x, unsigned long long b,
                                        unsigned long long y) {
    const unsigned long long u = mul(a, x), v = mul(b, y);
    return u >= v ? u - v : u + (p - v);
  }
};
#endif

// A value of Λ (|v| < 2^63) modulo P::p.
template <class P>
FF_HD inline unsigned long long mod_of(long long v) {
  const unsigned long long m =
      P::fold(v < 0 ? 0ull - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v));
  return v < 0 && m != 0 ? P::p - m : m;
}

// Rows in echelon form over GF(p) on a column mask: row t is 0 at the pivot
// columns of rows 0 .. t-1 and not 0 at its own. Row operations run on all K
// columns (no branch per entry); only the columns in the mask are read.
template <class P, int K>
struct ModEchelon {
  P ar{};  // the arithmetic (static for ModP31 / ModP61; multiprime_walk's prime chosen at run time)
  unsigned long long row[K][K];
  int piv[K] = {};
  int n = 0;
  // v minus its components along the rows: 0 on the mask iff v lies in their span
  FF_HD void reduce(unsigned long long* v) const {
    for (int t = 0; t < n; ++t) {
      const unsigned long long f = v[piv[t]];
      if (f == 0) continue;
      const unsigned long long g = row[t][piv[t]];
      for (int j = 0; j < K; ++j) v[j] = ar.cross(g, v[j], f, row[t][j]);
    }
  }
  FF_HD void reduce_pattern(unsigned long long* v) const { reduce(v); }  // (the walk's zero tests)
  FF_HD bool is_pivot(int c) const {
    for (int t = 0; t < n; ++t)
      if (piv[t] == c) return true;
    return false;
  }
  FF_HD static int first_nonzero(const unsigned long long* v, unsigned cols) {
    unsigned nz = 0;  // (a mask, without a branch per entry: the residues' zeros are data)
    for (int j = 0; j < K; ++j) nz |= static_cast<unsigned>(v[j] != 0) << j;
    nz &= cols;
    return nz != 0 ? ctz64(nz) : -1;
  }
  // adds v (reduced in place) when it is independent of the rows on cols
  FF_HD bool add(unsigned long long* v, unsigned cols) {
    reduce(v);
    const int j = first_nonzero(v, cols);
    if (j < 0) return false;
    for (int i = 0; i < K; ++i) row[n][i] = v[i];
    piv[n++] = j;
    return true;
  }
};

// p - 2 powers: the inverse of a non-zero a in GF(p) (Fermat).
template <class P>
FF_HD inline unsigned long long mod_inverse(unsigned long long a) {
  unsigned long long r = 1, e = P::p - 2;
  while (e) {
    if (e & 1u) r = P::mul(r, a);
    a = P::mul(a, a);
    e >>= 1;
  }
  return r;
}

// The sign of the determinant of the r x r matrix t (row-major, entries in
// GF(p)) of an integer matrix whose |determinant| < 2^P::kMaxBits <= (p - 1)
// / 2: fraction-free elimination (row_i <- g row_i - f row_k multiplies the
// determinant by g; den collects those g), det = Π pivots / den, and the
// residue in [1, (p - 1) / 2] is a positive determinant, above it a negative
// one. t is overwritten.
template <class P>
FF_HD inline int mod_det_sign(unsigned long long* t, int r) {
  unsigned long long num = 1, den = 1;
  bool negate = false;
  for (int k = 0; k < r; ++k) {
    int i = k;
    while (i < r && t[i * r + k] == 0) ++i;
    if (i == r) return 0;
    if (i != k) {
      for (int j = k; j < r; ++j) {
        const unsigned long long x = t[i * r + j];
        t[i * r + j] = t[k * r + j];
        t[k * r + j] = x;
      }
      negate = !negate;
    }
    const unsigned long long g = t[k * r + k];
    num = P::mul(num, g);
    for (i = k + 1; i < r; ++i) {
      const unsigned long long f = t[i * r + k];
      if (f == 0) continue;
      for (int j = k + 1; j < r; ++j) t[i * r + j] = P::cross(g, t[i * r + j], f, t[k * r + j]);
      den = P::mul(den, g);
    }
  }
  unsigned long long d = P::mul(num, mod_inverse<P>(den));
  if (negate && d != 0) d = P::p - d;
  return d == 0 ? 0 : d <= (P::p - 1) / 2 ? 1 : -1;
}

// The greedy walk of the lemma above on D's rows m, in the arithmetic of the
// echelon E (ModEchelon: GF(p); DblEchelon below: binary64 by Bareiss): the
// leaf's rows kr and columns kc (bit i: row / column i of Λ) and the sign
// bookkeeping sg, E left holding the kept rows on kc. Returns 1 there, 0 when
// !sos and the rows are dependent (det Λ = 0), 2 where no option passes (the
// lemma says it cannot happen).
// An option c that is no pivot column of E passes without reducing e_c: each
// reduction step only scales e_c (its entries at the pivot columns are 0),
// so it stays a non-zero multiple of e_c, not in F's row space on kc (c is
// in kc). The lifted column, tried first, is hardly ever a pivot.
template <int K, class Ech, class T>
FF_HD inline int sos_walk(const T (&m)[K - 1][K - 1], bool sos, Ech& E, unsigned& kr, unsigned& kc, int& sg) {
  constexpr int W = K - 1;
  kr = kc = (1u << K) - 1u;
  sg = 1;
  for (int r = K - 2; r >= 0; --r) {
    T v[W];
    for (int j = 0; j < W; ++j) v[j] = m[r][j];
    if (E.add(v, kc)) continue;  // not perturbed: F + row r independent on kc
    if (!sos) return 0;            // det Λ = 0 (the rows are dependent)
    bool moved = false;
    for (int c = K - 2; c >= 0 && !moved; --c) {  // options 1 .. K-1: columns K-2 .. 0
      if (!((kc >> c) & 1u)) continue;
      const bool pivot = E.is_pivot(c);
      if (pivot) {
        T e[W] = {};
        e[c] = T(1);
        E.reduce_pattern(e);  // only which entries are 0 is asked
        if (Ech::first_nonzero(e, kc) < 0) continue;  // e_c in F's row space: F loses rank without c
      }
      const int parity = popcount32(kr & ((1u << r) - 1u)) + popcount32(kc & ((1u << c) - 1u));
      if (parity & 1) sg = -sg;
      kr &= ~(1u << r);
      kc &= ~(1u << c);
      moved = true;
      if (pivot && r > 0) {  // re-pivot: F's rows again, on kc (independent there by the test)
        E.n = 0;
        for (int i = K - 2; i > r; --i) {
          if (!((kr >> i) & 1u)) continue;
          for (int j = 0; j < W; ++j) v[j] = m[i][j];
          E.add(v, kc);
        }
      }
    }
    if (!moved) return 2;
  }
  return 1;
}

// The exact SoS sign of an integer Λ (rows sorted by index): the leaf of
// sos_search reached by the greedy walk above — with every row kept, det Λ
// itself, when it is not 0; L.bits <= P::kMaxBits. Returns 2 only where the
// lemma says it cannot (the caller's search then decides).
// Row K-1 is always kept (the walk's first row: F empty, its 1-column entry
// 1), with its pivot in the 1-column, where every other row also has a 1:
// reducing a row against it is subtracting it. So the walk runs on the
// differences D_i = Λ_i - Λ_{K-1} (i < K-1) without the 1-column, exactly
// (|entries| < 2^60, differences < 2^61): F has full rank on kc iff its rows
// other than K-1 have full rank on D's columns of kc, and e_c (0 in the
// 1-column) is in F's row space iff it is in theirs. The leaf's minor, rows
// kr and columns kc of Λ in increasing order, equals the minor of D on kr and
// kc without K-1 (the row operations keep it; its last row and column then
// hold the only 1 of the last column, at cofactor sign +1) — a minor of Λ, so
// below 2^bits: mod_det_sign gives its sign.
template <class P, int K>
FF_HD inline int int_lattice_sos_mod(const IntLambda<K>& L, bool sos = true) {
  constexpr int W = K - 1;  // D's columns: Λ's coordinate columns
  unsigned long long m[W][W];
  for (int i = 0; i < W; ++i)
    for (int j = 0; j < W; ++j) m[i][j] = mod_of<P>(L.a[i][j] - L.a[K - 1][j]);
  ModEchelon<P, W> E;
  unsigned kr = 0, kc = 0;
  int sg = 1;
  if (const int w = sos_walk<K>(m, sos, E, kr, kc, sg); w != 1) return w;
  int ri[W], ci[W], n = 0, nc = 0;
  for (int i = 0; i < W; ++i) {
    if ((kr >> i) & 1u) ri[n++] = i;
    if ((kc >> i) & 1u) ci[nc++] = i;
  }
  if (n == 0) return sg;  // every row but K-1 perturbed: the minor is the 1-column's 1
  // D's entries are below 2^(b_j + 1) in column j: Laplace's values below
  // 2^(lf + B + W) <= 2^(bits + W) (int_lambda's bound, one bit per column
  // more); det_by_minors has orders up to 7 (larger leaves: mod_det_sign)
  if constexpr (W <= 7) {
    if (L.bits + W <= 63) {
      long long t[W * W];
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) t[i * n + j] = L.a[ri[i]][ci[j]] - L.a[K - 1][ci[j]];
      const long long d = int_det_of_order<1, W, long long>(t, n);
      return sg * ((d > 0) - (d < 0));
    }
  }
  unsigned long long t[W * W];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) t[i * n + j] = m[ri[i]][ci[j]];
  return sg * mod_det_sign<P>(t, n);
}

#if !defined(__CUDA_ARCH__) && defined(FLIPFLOP_INT128)
// ---- The same walk modulo several primes: dyadic Λ of any size (host) ------
// Every double is an integer times a power of two. Scaling every coordinate
// by 2^-E and the lifted column by 2^-2E (E: the lowest set bit over the
// call's coordinates, and half that of its weights) makes Λ an integer
// matrix Λ' whose minors are Λ's times positive powers of two: the same
// signs, so the same SoS leaf and sign (sos_search reads only minors' signs).
// On tensor-product grids of non-dyadic spacing (np.mgrid with step 0.1:
// rectangles' corners are cospherical whatever the spacing), on copies of
// points and on decimal-coordinate floors the exactly degenerate calls read
// tens of minors each, as expansions (a 4D 5^4 grid of spacing 0.1: 0.73 s
// against 0.06 s for the integer grid); Λ' has entries of 55-110 bits.
//   The walk (sos_walk's lemma and steps) needs only rank tests. Let every
// minor of Λ' be below 2^B in magnitude (B = lf(K) + Σ_j b_j, b_j the bits
// of column j, as int_lambda's bound) and p_1 .. p_N primes with Π p_i >
// 2^B. Rows independent modulo some p_i are independent over Q (a minor
// not 0 modulo p_i is not 0); rows dependent modulo every p_i are dependent
// over Q (each maximal minor M is 0 modulo each p_i, so Π p_i divides M,
// and |M| < Π p_i: M = 0). Each prime keeps its own echelon; the primes
// agree on every test of the walk but with probability about 2^-60 per test
// and prime, and where they do not, the walk returns 2 (the search then
// decides). So a leaf reached with every prime agreeing is sos_search's
// leaf; its minor is not 0, and the caller decides its sign.
//   Primes 2^61 - c (the 12 smallest c: 1, 31, 45, ..., 579), each above
// 2^60.99: N = floor(B / 60) + 1 of them, at most 12 (B < 720 bits: 5D
// Delaunay calls on 55-bit coordinates have B about 400, 7D about 530, 9D
// about 650); more: 2.
// 2^61 - c is prime for these c (a test checks it: Miller-Rabin with the
// first 12 prime bases, deterministic below 2^64)
inline constexpr int kMultiprimeCount = 12;
inline constexpr unsigned long long kMultiprimeC[kMultiprimeCount] = {1,   31,  45,  229, 259, 283,
                                                                      339, 391, 403, 465, 531, 579};
// How often, on this thread, multiprime_walk showed a dependence over Z
// (exact_dependence) instead of asking the other primes; the tests read it
// so that the path they cover cannot vanish unnoticed.
struct WalkCounts {
  long long certificates = 0;
};
inline WalkCounts& walk_counts() {
  thread_local WalkCounts c;
  return c;
}
struct PseudoMersenne61 {
  static constexpr unsigned long long kM = (1ull << 61) - 1ull;
  unsigned long long p = kM, c = 1;
  // s < 2^122: s = h 2^61 + l = h c + l (mod p), below 2^71 + 2^61 (c <
  // 2^10); once more below 2^61 + 2^21 < 2p: one subtraction
  unsigned long long red(uint128_t s) const {
    // 2^61 - 1 (the walk's first prime): ModP61's folds, without the
    // products by c (s < 2^123: the two halves sum below 2^63)
    if (c == 1)
      return ModP61::fold((static_cast<unsigned long long>(s) & kM) + static_cast<unsigned long long>(s >> 61));
    const uint128_t t = static_cast<uint128_t>(static_cast<unsigned long long>(s >> 61)) * c +
                        (static_cast<unsigned long long>(s) & kM);
    unsigned long long r = (static_cast<unsigned long long>(t) & kM) + static_cast<unsigned long long>(t >> 61) * c;
    return r >= p ? r - p : r;
  }
  unsigned long long mul(unsigned long long a, unsigned long long b) const {
    return red(static_cast<uint128_t>(a) * b);
  }
  unsigned long long add(unsigned long long a, unsigned long long b) const {
    const unsigned long long s = a + b;
    return s >= p ? s - p : s;
  }
  unsigned long long sub(unsigned long long a, unsigned long long b) const { return a >= b ? a - b : a + (p - b); }
  // a x - b y (ModEchelon's row operation) as a x + b (p - y), one
  // reduction: both products are below 2^122 (p - y <= p), their sum below
  // 2^123, where red still holds (t < 2^62 c + 2^61 < 2^73, then r < 2^61 +
  // 2^12 c < 2p). The walk's elimination is mostly this (perf, a 20^3 grid
  // of step 0.1: 45 % of `dt3` in multiprime_walk<5>, its hottest loop here)
  unsigned long long cross(unsigned long long a, unsigned long long x, unsigned long long b,
                           unsigned long long y) const {
    return red(static_cast<uint128_t>(a) * x + static_cast<uint128_t>(b) * (p - y));
  }
  // 2^e, e >= 0: 2^61 = c (mod p)
  unsigned long long pow2(int e) const {
    unsigned long long r = 1ull << (e % 61);
    for (int q = e / 61; q > 0; --q) r = mul(r, c);
    return r;
  }
};

// |v| = odd 2^low: the odd integer (below 2^53) of a finite v other than 0.
inline unsigned long long odd_part(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if ((bits >> 52) & 0x7ff) mant |= std::uint64_t{1} << 52;
  return mant >> ctz64(mant);
}

template <int K>
int multiprime_walk(const double* const* p, const double* w, unsigned& kr, unsigned& kc, int& sg, bool zero_test) {
  constexpr int W = K - 1;  // D's columns: Λ's columns but the 1-column
  constexpr int kMaxPrimes = kMultiprimeCount;
  const unsigned long long* kC = kMultiprimeC;
  const int ncoord = w ? K - 2 : K - 1;
  // E, and the columns' bits over Λ' (|x 2^-E| < 2^(hi - E))
  int lo[K][W], hi[K][W], lw[K], hw[K];
  int E = 100000;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < ncoord; ++j) {
      lo[i][j] = hi[i][j] = 0;
      if (p[i][j] == 0.0) continue;
      if (!bit_span(p[i][j], lo[i][j], hi[i][j])) return 2;
      if (lo[i][j] < E) E = lo[i][j];
    }
    lw[i] = hw[i] = 0;
    if (w && w[i] != 0.0) {
      if (!bit_span(w[i], lw[i], hw[i])) return 2;
      const int half = lw[i] >= 0 ? lw[i] / 2 : -((1 - lw[i]) / 2);  // floor(lw / 2)
      if (half < E) E = half;
    }
  }
  if (E == 100000) return 2;  // every value 0
  int B = log2_factorial_ceil(K);
  int lifted_bits = 0;
  for (int j = 0; j < ncoord; ++j) {
    int b = 0;
    for (int i = 0; i < K; ++i)
      if (p[i][j] != 0.0 && hi[i][j] - E > b) b = hi[i][j] - E;
    if (b > 240) return 2;
    B += b;
    if (2 * b > lifted_bits) lifted_bits = 2 * b;
  }
  if (w) {
    // Σ x_j^2 2^-2E - w 2^-2E: at most ncoord + 1 <= 11 terms below 2^t each
    for (int i = 0; i < K; ++i)
      if (w[i] != 0.0 && hw[i] - 2 * E > lifted_bits) lifted_bits = hw[i] - 2 * E;
    if (lifted_bits > 720) return 2;
    B += lifted_bits + 4;
  }
  const int N = B / 60 + 1;
  if (N > kMaxPrimes) return 2;
  // Λ' once, exactly, where it fits (every coordinate below 2^60 after the
  // scaling, so each |x| is a uint64 and Σ x^2 < 2^124 a uint128): then a
  // prime's entries are one fold per coordinate and one reduction per row,
  // instead of two products per coordinate
  int maxb = 0;
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < ncoord; ++j)
      if (p[i][j] != 0.0 && hi[i][j] - E > maxb) maxb = hi[i][j] - E;
  const bool once = maxb <= 60;
  // once: D's coordinate entries (differences below 2^61 in magnitude) and
  // the lifted column's Σ x^2 differences (below 2^124), signed, exact
  long long dx[W][W];
  uint128_t dsq[W];
  bool dneg[W];
  unsigned long long dx_or = 0;  // the |D_ij| OR-ed: below 2^60 (< every p_q), one correction in build
  unsigned char bl[W][W] = {};  // bit lengths of |D_ij| (0: a zero entry)
  bool per_column = false;  // bl holds (once, weights 0)
  if (once) {
    unsigned long long X[K][W];
    uint128_t sq[K];
    for (int i = 0; i < K; ++i) {
      sq[i] = 0;
      for (int j = 0; j < ncoord; ++j) {
        const unsigned long long x = p[i][j] != 0.0 ? odd_part(p[i][j]) << (lo[i][j] - E) : 0ull;
        X[i][j] = x;
        sq[i] += static_cast<uint128_t>(x) * x;
      }
    }
    for (int i = 0; i < W; ++i) {
      for (int j = 0; j < ncoord; ++j) {
        const long long a = p[i][j] < 0.0 ? -static_cast<long long>(X[i][j]) : static_cast<long long>(X[i][j]);
        const long long b = p[K - 1][j] < 0.0 ? -static_cast<long long>(X[K - 1][j])
                                              : static_cast<long long>(X[K - 1][j]);
        dx[i][j] = a - b;
        dx_or |= dx[i][j] < 0 ? 0ull - static_cast<unsigned long long>(dx[i][j])
                              : static_cast<unsigned long long>(dx[i][j]);
      }
      dneg[i] = sq[i] < sq[K - 1];
      dsq[i] = dneg[i] ? sq[K - 1] - sq[i] : sq[i] - sq[K - 1];
    }
    // Fewer primes from D itself where the weights are 0: every dependence
    // the walk claims is the vanishing, modulo every prime, of minors of D —
    // of order |F| + 1 on the rows of F and row r and the columns kc (row r
    // depends on F), or of order |F| on F's rows and kc less the option's
    // column c (e_c lies in F's row space: F loses rank without c). By
    // Hadamard's inequality such a minor is at most the product over its
    // columns of sqrt(W) times the column's largest entry on the claim's
    // rows: below 2^cb_j per column, cb_j = bit_length(max_i |D_ij|) + 2
    // (sqrt(W) <= 2^2, W <= 16), and a column of zeros on those rows (points
    // on a plane x_j = c, the flat calls) has only zero minors. So a claim of
    // order n on the columns S needs the primes whose product exceeds 2^s, s
    // the sum of the n largest cb_j over S: N = s / 60 + 1 of them (each p_q
    // > 2^60.99), and none beyond the first where S holds fewer than n
    // non-zero columns (the rows are then dependent by their number); never
    // more than N, the bound over all of Λ. Counted on the 4^5 grid of step
    // 0.1 (`rtd`, 1.46 M walks, 5.2 primes each by the whole-D bound): 54 %
    // of the 2.5 M dependences and 82 % of the 3.3 M failed options are such
    // counts, and the others need 4.1 and 3.1 primes on average. Callgrind,
    // `rtd` on one thread, against the whole-D bound for every claim (six
    // rows and more): the 3^5 grid of values 0, 0.1, 0.1 + 0.2 5.204 -> 4.045 G
    // instructions, the 4D 5^4 grid of step 0.1 1.721 -> 1.529 G (with the
    // first prime's reduction without products, below: 1.522 G). Each
    // column's largest entry over the claim's rows rather than all of D's:
    // 3.873 G and 1.496 G.
    bool wzero = true;
    if (w)
      for (int i = 0; i < K; ++i) wzero = wzero && w[i] == 0.0;
    if (wzero) {
      per_column = true;
      for (int i = 0; i < W; ++i) {
        for (int j = 0; j < ncoord; ++j) {
          const unsigned long long a = dx[i][j] < 0 ? 0ull - static_cast<unsigned long long>(dx[i][j])
                                                    : static_cast<unsigned long long>(dx[i][j]);
          bl[i][j] = static_cast<unsigned char>(bit_length(a));
        }
        if (w) {
          const unsigned long long hi64 = static_cast<unsigned long long>(dsq[i] >> 64);
          bl[i][K - 2] = static_cast<unsigned char>(hi64 != 0 ? 64 + bit_length(hi64)
                                                              : bit_length(static_cast<unsigned long long>(dsq[i])));
        }
      }
    }
  }
  // The primes a claim of order n on D's rows `rows` and columns `cols`
  // needs (above, with each column's largest entry over those rows): at most N
  auto primes_for = [&](unsigned rows, unsigned cols, int n) -> int {
    if (!per_column) return N;
    unsigned char mb[W] = {};  // each column's largest bit length over the rows
    for (unsigned rs = rows; rs != 0; rs &= rs - 1u) {
      const int i = ctz64(rs);
      for (int j = 0; j < W; ++j) mb[j] = bl[i][j] > mb[j] ? bl[i][j] : mb[j];
    }
    unsigned nz = 0;
    for (int j = 0; j < W; ++j) nz |= static_cast<unsigned>(mb[j] != 0) << j;
    nz &= cols;
    const int nb = popcount32(nz);
    if (n > nb) return 1;  // dependent by the count of non-zero columns
    int s = 0;
    if (n == nb) {  // every non-zero column (the usual case: no order needed)
      for (unsigned z = nz; z != 0; z &= z - 1u) s += mb[ctz64(z)] + 2;
    } else {  // the n largest, by insertion
      int b[W];
      int m = 0;
      for (unsigned z = nz; z != 0; z &= z - 1u) {
        const int v = mb[ctz64(z)] + 2;
        int t = m++;
        for (; t > 0 && b[t - 1] < v; --t) b[t] = b[t - 1];
        b[t] = v;
      }
      for (int t = 0; t < n; ++t) s += b[t];
    }
    return s / 60 + 1 < N ? s / 60 + 1 : N;
  };
  PseudoMersenne61 P[kMaxPrimes];
  unsigned long long m[kMaxPrimes][W][W];
  // prime q's D = Λ' minus its last row, modulo p_q
  auto build = [&](int q) {
    P[q].c = kC[q];
    P[q].p = PseudoMersenne61::kM + 1ull - kC[q];
    const PseudoMersenne61& F = P[q];
    if (once) {
      for (int i = 0; i < W; ++i) {
        for (int j = 0; j < ncoord; ++j) {
          // |d| < 2^61 < 2p: d, or d + 2p for d < 0, lies in [0, 2p): two
          // conditional subtractions at most, as masks (the differences'
          // signs are data: branches on them were mispredicted, a third of
          // the walk's time on a 20^3 grid of step 0.1)
          // (|d| < 2^60 < p, the usual case: d, or p + d for d < 0, at once)
          const long long d = dx[i][j];
          if (dx_or < (1ull << 60)) {
            m[q][i][j] = static_cast<unsigned long long>(d) + ((0ull - static_cast<unsigned long long>(d < 0)) & F.p);
            continue;
          }
          unsigned long long u =
              static_cast<unsigned long long>(d) + ((0ull - static_cast<unsigned long long>(d < 0)) & (2 * F.p));
          u -= F.p & (0ull - static_cast<unsigned long long>(u >= F.p));
          u -= F.p & (0ull - static_cast<unsigned long long>(u >= F.p));
          m[q][i][j] = u;
        }
        if (w) {
          const unsigned long long h = F.red(dsq[i]);
          const unsigned long long n = F.p - h;  // (h = 0: p, reduced below)
          unsigned long long u = dneg[i] ? n : h;
          u -= F.p & (0ull - static_cast<unsigned long long>(u >= F.p));
          m[q][i][K - 2] = u;
        }
      }
      if (w)
        for (int i = 0; i < K; ++i) {
          if (w[i] == 0.0) continue;
          // - (w_i - w_last) 2^-2E on row i, or on every row for the last
          const unsigned long long y = F.mul(odd_part(w[i]), F.pow2(lw[i] - 2 * E));
          const bool plus = (w[i] > 0.0) == (i == K - 1);
          for (int t = 0; t < W; ++t) {
            if (i != K - 1 && t != i) continue;
            m[q][t][K - 2] = plus ? F.add(m[q][t][K - 2], y) : F.sub(m[q][t][K - 2], y);
          }
        }
      return;
    }
    unsigned long long row[K][W];
    for (int i = 0; i < K; ++i) {
      unsigned long long h = 0;
      for (int j = 0; j < ncoord; ++j) {
        unsigned long long x = 0;
        if (p[i][j] != 0.0) {
          x = F.mul(odd_part(p[i][j]), F.pow2(lo[i][j] - E));
          if (p[i][j] < 0.0 && x != 0) x = F.p - x;
        }
        row[i][j] = x;
        h = F.add(h, F.mul(x, x));
      }
      if (w) {
        if (w[i] != 0.0) {
          unsigned long long y = F.mul(odd_part(w[i]), F.pow2(lw[i] - 2 * E));
          h = w[i] > 0.0 ? F.sub(h, y) : F.add(h, y);
        }
        row[i][K - 2] = h;
      }
    }
    for (int i = 0; i < W; ++i)
      for (int j = 0; j < W; ++j) m[q][i][j] = F.sub(row[i][j], row[K - 1][j]);
  };
  // The walk runs on the first prime; the others are asked only where it
  // finds a dependence. Independence modulo one prime is independence over
  // Q, so the first prime's "independent" needs no other; its "dependent"
  // holds over Q only where every prime says so, and any prime that
  // disagrees makes the walk return 2, as before. A prime's echelon is built
  // (again) for the walk's current rows and columns when it is asked: on a
  // 20^3 grid of step 0.1 (K = 5, N = 5 primes) the typical exactly
  // degenerate call meets one dependence, and the other primes skip the
  // option tests that the first prime passes.
  using Ech = ModEchelon<PseudoMersenne61, W>;
  Ech ech[kMaxPrimes];
  unsigned built = 0, valid = 0;  // bit q: prime q's D built / its echelon holds F on kc
  build(0);
  built = 1u;
  ech[0].ar = P[0];
  kr = kc = (1u << K) - 1u;
  sg = 1;
  // prime q's echelon of F (the kept rows after r) on kc; false: F is not
  // independent there modulo p_q, against the first prime
  auto ready = [&](int q, int r) -> bool {
    if (!((built >> q) & 1u)) {
      build(q);
      built |= 1u << q;
      ech[q].ar = P[q];
    }
    if ((valid >> q) & 1u) return true;
    ech[q].n = 0;
    for (int i = K - 2; i > r; --i) {
      if (!((kr >> i) & 1u)) continue;
      unsigned long long v[W];
      for (int j = 0; j < W; ++j) v[j] = m[q][i][j];
      if (!ech[q].add(v, kc)) return false;
    }
    valid |= 1u << q;
    return true;
  };
  // e_c outside F's row space on kc modulo p_q: F keeps its rank without c
  auto passes = [&](int q, int c) -> bool {
    if (!ech[q].is_pivot(c)) return true;
    unsigned long long e[W] = {};
    e[c] = 1;
    ech[q].reduce(e);
    return Ech::first_nonzero(e, kc) >= 0;
  };
  // A dependence the first prime claims, shown over Z instead of modulo the
  // other primes: the rows `rows` of D are dependent on the columns `cols`
  // when some integer vector λ != 0 has Σ_i λ_i D_i = 0 on them. A candidate
  // λ comes from binary64: the null vector of those rows (each column scaled
  // to its largest entry, elimination with partial pivoting and the rows'
  // combinations carried along, entries below 2^-40 after the scaling taken
  // as 0; the claims' nullity is 1, F being independent on kc), divided by
  // its smallest entry, then multiplied by d = 1 .. 12; where every entry is
  // then within 10^-6 of an integer below 2^24, those integers are tested on
  // D itself, exactly: in the coordinate columns in __int128 (|λ| |D| < 2^24
  // 2^60, at most 16 terms), in the lifted column (Σ x^2 differences below
  // 2^124) modulo 2^128 where Σ |λ_i| |dsq_i| < 2^127 — a sum that is 0
  // modulo 2^128 and smaller than that in magnitude is 0. Nothing rests on the rounding or on the prime: a
  // verified λ is a proof, and a candidate that fails leaves the primes to
  // decide, as before. Weights 0 only (dsq is then the lifted column of D).
  // Tensor grids' dependences are sums and differences of rows (a box's
  // corners: D_a - D_b - D_c + D_d = 0 whatever the spacing), where the
  // other primes cost up to N - 1 echelons of F, each of D modulo p_q.
  auto exact_dependence = [&](unsigned rows, unsigned cols) -> bool {
    if (!per_column || dx_or >= (1ull << 60)) return false;
    int ri[W] = {}, ci[W] = {}, n = 0, nc = 0;
    for (int i = 0; i < W; ++i) {
      if ((rows >> i) & 1u) ri[n++] = i;
      if ((cols >> i) & 1u) ci[nc++] = i;
    }
    if (n == 0) return false;
    double a[W][W], b[W][W];
    for (int jj = 0; jj < nc; ++jj) {
      const int j = ci[jj];
      double big = 0.0;
      for (int t = 0; t < n; ++t) {
        const int i = ri[t];
        const double v = j < ncoord ? static_cast<double>(dx[i][j])
                                    : (dneg[i] ? -1.0 : 1.0) * static_cast<double>(dsq[i]);
        a[t][jj] = v;
        big = std::fabs(v) > big ? std::fabs(v) : big;
      }
      const double sc = big > 0.0 ? 1.0 / big : 0.0;
      for (int t = 0; t < n; ++t) a[t][jj] *= sc;
    }
    for (int t = 0; t < n; ++t)
      for (int k = 0; k < n; ++k) b[t][k] = t == k ? 1.0 : 0.0;
    int rank = 0;
    for (int jj = 0; jj < nc && rank < n; ++jj) {
      int piv = rank;
      for (int t = rank + 1; t < n; ++t)
        if (std::fabs(a[t][jj]) > std::fabs(a[piv][jj])) piv = t;
      if (std::fabs(a[piv][jj]) < 0x1p-40) continue;  // (0 here: rounding of the others' combination)
      if (piv != rank) {
        for (int k = 0; k < nc; ++k) std::swap(a[piv][k], a[rank][k]);
        for (int k = 0; k < n; ++k) std::swap(b[piv][k], b[rank][k]);
      }
      const double g = 1.0 / a[rank][jj];
      for (int t = rank + 1; t < n; ++t) {
        const double f = a[t][jj] * g;
        if (f == 0.0) continue;
        for (int k = jj; k < nc; ++k) a[t][k] -= f * a[rank][k];
        for (int k = 0; k < n; ++k) b[t][k] -= f * b[rank][k];
      }
      ++rank;
    }
    if (rank == n) return false;
    const double* lam = b[rank];
    double top = 0.0;
    for (int t = 0; t < n; ++t) top = std::fabs(lam[t]) > top ? std::fabs(lam[t]) : top;
    double low = top;
    for (int t = 0; t < n; ++t)
      if (std::fabs(lam[t]) > 1e-6 * top && std::fabs(lam[t]) < low) low = std::fabs(lam[t]);
    if (!(low > 0.0)) return false;
    long long c[W];
    bool found = false;
    for (int d = 1; d <= 12 && !found; ++d) {
      found = true;
      const double sc = d / low;
      for (int t = 0; t < n && found; ++t) {
        const double x = lam[t] * sc;
        const double rx = std::nearbyint(x);
        if (!(std::fabs(rx) < 16777216.0) || std::fabs(x - rx) > 1e-6) found = false;
        else c[t] = static_cast<long long>(rx);
      }
    }
    if (!found) return false;
    unsigned long long total = 0;  // Σ |λ_i| (below 2^28), for the lifted column's bound
    for (int t = 0; t < n; ++t) total += static_cast<unsigned long long>(c[t] < 0 ? -c[t] : c[t]);
    for (int jj = 0; jj < nc; ++jj) {
      const int j = ci[jj];
      if (j < ncoord) {
        int128_t sum = 0;
        for (int t = 0; t < n; ++t) sum += static_cast<int128_t>(c[t]) * dx[ri[t]][j];
        if (sum != 0) return false;
      } else {  // the lifted column (w: weights 0)
        uint128_t big = 0, sum = 0;
        for (int t = 0; t < n; ++t) {
          const uint128_t v = dsq[ri[t]];
          if (v > big) big = v;
          const uint128_t mag = static_cast<uint128_t>(c[t] < 0 ? -c[t] : c[t]) * v;  // mod 2^128
          sum += (c[t] < 0) != dneg[ri[t]] ? 0 - mag : mag;
        }
        // Σ |λ| max|dsq| < 2^127: big < 2^(127 - bit_length(total))
        const int tb = bit_length(total);
        if ((big >> (127 - tb)) != 0) return false;
        if (sum != 0) return false;
      }
    }
    ++walk_counts().certificates;
    return true;
  };
  for (int r = K - 2; r >= 0; --r) {
    {
      unsigned long long v[W];
      for (int j = 0; j < W; ++j) v[j] = m[0][r][j];
      if (ech[0].add(v, kc)) {  // not perturbed: F + row r independent on kc
        valid = 0;
        continue;
      }
    }
    const unsigned frows = kr & ~((2u << r) - 1u) & ((1u << W) - 1u);  // F: the kept rows after r
    const int Nr = primes_for(frows | (1u << r), kc, ech[0].n + 1);
    const bool shown = Nr > 1 && exact_dependence(frows | (1u << r), kc);
    for (int q = 1; q < Nr && !shown; ++q) {  // dependent: every prime it needs must say so
      if (!ready(q, r)) return 2;
      unsigned long long v[W];
      for (int j = 0; j < W; ++j) v[j] = m[q][r][j];
      if (ech[q].add(v, kc)) return 2;  // the primes disagree
    }
    if (zero_test) {  // det Λ = 0: row r depends on the rows after it, on every column
      kr &= ~(1u << r);
      return 1;
    }
    bool moved = false;
    for (int c = K - 2; c >= 0 && !moved; --c) {  // options 1 .. K-1: columns K-2 .. 0
      if (!((kc >> c) & 1u)) continue;
      if (!passes(0, c)) {
        // e_c in F's row space: F loses rank without c — on every prime needed
        const unsigned fr = kr & ~((2u << r) - 1u) & ((1u << W) - 1u);
        const int Nc = primes_for(fr, kc & ~(1u << c), ech[0].n);
        const bool shown = Nc > 1 && exact_dependence(fr, kc & ~(1u << c) & ((1u << W) - 1u));
        for (int q = 1; q < Nc && !shown; ++q) {
          if (!ready(q, r)) return 2;
          if (passes(q, c)) return 2;  // the primes disagree
        }
        continue;
      }
      const bool pivot = ech[0].is_pivot(c);
      const int parity = popcount32(kr & ((1u << r) - 1u)) + popcount32(kc & ((1u << c) - 1u));
      if (parity & 1) sg = -sg;
      kr &= ~(1u << r);
      kc &= ~(1u << c);
      moved = true;
      for (unsigned vq = valid; vq != 0; vq &= vq - 1u) {
        const int q = ctz64(vq);
        if (ech[q].is_pivot(c)) valid &= ~(1u << q);
      }
      if (pivot && r > 0) {
        ech[0].n = 0;  // re-pivot: F's rows again, on kc (independent there by the test)
        for (int i = K - 2; i > r; --i) {
          if (!((kr >> i) & 1u)) continue;
          unsigned long long v[W];
          for (int j = 0; j < W; ++j) v[j] = m[0][i][j];
          if (!ech[0].add(v, kc)) return 2;
        }
      }
    }
    if (!moved) return 2;
  }
  return 1;
}
#endif

// ---- The same walk in binary64 by Bareiss's elimination ------------------
// Where every minor of D is small, the walk above runs exactly in doubles,
// and about twice as fast (no reduction modulo p; the leaf's minor is the
// elimination's last pivot instead of a determinant of its own). Measured
// per call (one core of the 2-core VM) on exactly degenerate calls of 7
// points of a 3^5 grid (K = 7, power5d), of a 6^4 grid (K = 6, power4d) and
// of an 8^3 grid (K = 5), against the walk modulo 2^31 - 1: 433 -> 213 ns,
// 282 -> 139 ns, 153 -> 77 ns.
//   Bareiss (fraction-free elimination with exact division): reducing a row
// v against echelon rows 0 .. t (pivot columns c_0 .. c_t, pivots g_t, g_-1
// = 1) by v_j <- (g_t v_j - v_{c_t} row_t[j]) / g_{t-1} leaves v_j = the
// minor of the rows r_0 .. r_t, v on the columns c_0 .. c_t, j (Sylvester's
// identity), every stored row likewise; so every value met is a minor of D
// (or of D with a unit row e_c appended — by expansion along that row, a
// minor of D with one column fewer) and the last pivot g_{n-1} is the minor
// of all the kept rows, in the order added, on the pivot columns, in pivot
// order.
//   Exactness: H = Π_j max(1, |D_j|_2) over D's columns bounds every such
// minor (Hadamard's inequality on a submatrix; an integer column is 0 or of
// norm >= 1). With H^2 < 2^51 (computed with at most W roundings upward of
// 2^-52 each: the true H^2 < 2^52) every product of two values is an
// integer below 2^52, exact in binary64, their difference below 2^53,
// exact; the quotient by g_{t-1} is taken as a product with 1 / g_{t-1}
// rounded, within |Q| 2^-51 < 2^-25 of the integer Q (|Q| < H < 2^26),
// and rounded to it exactly by adding and subtracting 1.5 2^52 (unit
// spacing there; |Q| < 2^51). A fused multiply-add anywhere (nvcc, GCC's
// target("fma") clone) keeps this: the products are exact either way and a
// fused rounding step rounds the exact value once. A column norm squared
// is exact while it is below 2^53 and then already above the bound (an
// entry's difference of 2^53 or more may round, its square is beyond it).
//   The leaf's sign: the walk adds the kept rows in decreasing order (K-2
// down: n(n-1)/2 transpositions from increasing) and the pivot columns in
// their own order (its inversions); the result is sg times the sign of the
// leaf on increasing rows and columns, as int_lattice_sos_mod computes it.
// Returns 2 where H^2 >= 2^51 (int_lattice_walk then takes the primes).
template <int W>
struct DblEchelon {
  double row[W][W];
  double inv[W];  // 1 / row[t][piv[t]], rounded
  int piv[W] = {};
  int n = 0;
  static constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  // Reduces v against rows 0 .. n-1. A step whose factor f = v_{c_t} is 0
  // only scales v by g_t / g_{t-1}, and a run of such steps by g_b / g_{a-1}
  // (the quotients telescope), so they are skipped and the scale owed is
  // paid by the next step with f != 0, whose divisor is then g_{a-1} (a: the
  // first skipped step): with u the vector before the run, (g_t (g_{t-1} /
  // g_{a-1}) u_j - (g_{t-1} / g_{a-1}) u_{c_t} row_t[j]) / g_{t-1} = (g_t u_j
  // - u_{c_t} row_t[j]) / g_{a-1}, the same integer as step by step, from
  // products of two minors (below H^2 < 2^51: exact, as above). Returns the
  // factor owed at the end, 1 / g_{a-1} where the last steps were skipped
  // (the true v is then v g_{n-1} / g_{a-1}), 0 where none is: `exact`
  // pays it (one rounded product per entry, as a step), the zero tests do
  // not need it (the factor is not 0). On the lattices' rows, most factors
  // are 0: 3^5 grid Delaunay, 14 row steps per 7-row walk, most of them
  // skipped (callgrind below, at DblEchelon's use).
  FF_HD double reduce_pattern(double* v) const {
    double prev = 1.0;  // 1 / g_{a-1}
    bool owed = false;
    for (int t = 0; t < n; ++t) {
      const double f = v[piv[t]];
      if (f == 0.0) {
        owed = true;
        continue;
      }
      const double g = row[t][piv[t]];
      for (int j = 0; j < W; ++j) {
        const double q = (g * v[j] - f * row[t][j]) * prev;
        v[j] = (q + kRound) - kRound;
      }
      prev = inv[t];
      owed = false;
    }
    return owed ? prev : 0.0;
  }
  FF_HD void reduce(double* v) const {
    const double owed = reduce_pattern(v);
    if (owed != 0.0) {
      const double g = row[n - 1][piv[n - 1]];  // g_{n-1}
      for (int j = 0; j < W; ++j) {
        const double q = (g * v[j]) * owed;
        v[j] = (q + kRound) - kRound;
      }
    }
  }
  FF_HD bool is_pivot(int c) const {
    bool p = false;
    for (int t = 0; t < W; ++t) p = p || (t < n && piv[t] == c);
    return p;
  }
  FF_HD static int first_nonzero(const double* v, unsigned cols) {
    for (int j = 0; j < W; ++j)
      if (((cols >> j) & 1u) && v[j] != 0.0) return j;
    return -1;
  }
  FF_HD bool add(double* v, unsigned cols) {
    reduce(v);
    const int j = first_nonzero(v, cols);
    if (j < 0) return false;
    for (int i = 0; i < W; ++i) row[n][i] = v[i];
    inv[n] = 1.0 / v[j];
    piv[n++] = j;
    return true;
  }
};

// Hadamard's bound H^2 = Π_j max(1, |D_j|^2) over D's columns, rounded up
// by at most W roundings of 2^-52 each (DblEchelon's exactness argument).
template <int K>
FF_HD inline double dbl_walk_hadamard_sq(const double (&m)[K - 1][K - 1]) {
  constexpr int W = K - 1;
  double h2 = 1.0;
  for (int j = 0; j < W; ++j) {
    double s = 0.0;
    for (int i = 0; i < W; ++i) s += m[i][j] * m[i][j];
    h2 *= s > 1.0 ? s : 1.0;
  }
  return h2;
}

// The walk in binary64 on D given as doubles (integer entries): 2 where
// Hadamard's bound fails. `bounded`: the caller knows the bound to hold
// (StaticFilter::walk_bounded: from the input's largest magnitudes), and it
// is not computed (about 260 of the 1300 instructions of a 7-row call on the
// 3^5 grid, callgrind).
template <int K>
FF_HD inline int int_lattice_sos_dbl_rows(const double (&m)[K - 1][K - 1], bool sos, bool bounded = false) {
  constexpr int W = K - 1;
  if (!bounded && !(dbl_walk_hadamard_sq<K>(m) < 0x1p51)) return 2;
  DblEchelon<W> E;
  unsigned kr = 0, kc = 0;
  int sg = 1;
  if (const int w = sos_walk<K>(m, sos, E, kr, kc, sg); w != 1) return w;
  const int n = E.n < W ? E.n : W;  // (E.n <= W; said for the compiler's bounds analysis)
  if (n == 0) return sg;  // every row but K-1 perturbed: the 1-column's 1
  int swaps = n * (n - 1) / 2;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) swaps += E.piv[a] > E.piv[b];
  const double g = E.row[n - 1][E.piv[n - 1]];
  const int s = (g > 0.0) - (g < 0.0);
  return (swaps & 1) ? -sg * s : sg * s;
}

// The walk in binary64 on an integer Λ (D's entries converted exactly where
// they are below 2^53; a larger one fails the bound anyway).
template <int K>
FF_HD inline int int_lattice_sos_dbl(const IntLambda<K>& L, bool sos = true) {
  constexpr int W = K - 1;  // D's columns: Λ's coordinate columns
  if (L.bits > 62) return 2;  // entries below 2^62: their differences fit int64
  double m[W][W];
  for (int i = 0; i < W; ++i)
    for (int j = 0; j < W; ++j) m[i][j] = static_cast<double>(L.a[i][j] - L.a[K - 1][j]);
  return int_lattice_sos_dbl_rows<K>(m, sos);
}

// D straight from the doubles where every coordinate and weight of the call
// is an integer below 2^20 in magnitude (the usual lattice: no int_lambda
// scan and build): the coordinates' differences (below 2^21) and the lifted
// column's (|x|^2 - w below 2^44 + 2^20, its differences below 2^46) are
// then computed exactly. False (m unspecified) otherwise, NaN and infinities
// included. Known: the caller knows every value to be such an integer (the
// input's StaticFilter::small_integers()), and the tests are skipped (on the
// 3^5 grid they were the walk's callers' hottest line, 12 % of the kernel's
// instructions).
template <int K, bool Known = false>
FF_HD inline bool small_integer_differences(const double* const* p, const double* w, double (&m)[K - 1][K - 1]) {
  constexpr int W = K - 1;
  const int ncoord = w ? K - 2 : K - 1;
  auto small = [](double v) {
    if constexpr (Known) return true;
    return v > -0x1p20 && v < 0x1p20 && v == static_cast<double>(static_cast<long long>(v));
  };
  const double* base = p[K - 1];
  double lb = 0.0;
  for (int j = 0; j < ncoord; ++j) {
    if (!small(base[j])) return false;
    lb += base[j] * base[j];
  }
  if (w) {
    if (!small(w[K - 1])) return false;
    lb -= w[K - 1];
  }
  for (int i = 0; i < W; ++i) {
    double l = 0.0;
    for (int j = 0; j < ncoord; ++j) {
      const double v = p[i][j];
      if (!small(v)) return false;
      m[i][j] = v - base[j];
      l += v * v;
    }
    if (w) {
      if (!small(w[i])) return false;
      m[i][K - 2] = (l - w[i]) - lb;
    }
  }
  return true;
}

// The walk in binary64 where every minor is small, else on the prime that
// holds every minor of L; 2 where none does.
template <int K>
FF_HD inline int int_lattice_walk(const IntLambda<K>& L, bool sos) {
  if (const int s = int_lattice_sos_dbl<K>(L, sos); s != 2) return s;
  if (L.bits <= ModP31::kMaxBits) return int_lattice_sos_mod<ModP31, K>(L, sos);
#if defined(FLIPFLOP_INT128)
  if (L.bits <= ModP61::kMaxBits) return int_lattice_sos_mod<ModP61, K>(L, sos);
#endif
  return 2;
}

// sos_search on the exact integer minors (det Λ = 0): the fallback of
// int_lattice_sign_as beyond 60 bits, and the walk's reference in the tests.
template <class I, int K>
FF_HD inline int int_lattice_sos_search(const IntLambda<K>& L) {
  return sos_search<K>(true, [&](unsigned kr, unsigned kc) -> int { return int_minor_sign<I, K>(L, kr, kc); });
}

// The exact (sos: SoS) sign of det Λ on the integer matrix; rows sorted by
// index for sos, as lattice_sign. SoS: the greedy walk by ranks modulo p
// where every minor fits the prime, else det Λ and sos_search on the exact
// minors (K <= 7).
template <class I, int K>
FF_HD inline int int_lattice_sign_as(const IntLambda<K>& L, bool sos) {
  if (sos) {
    const int g = int_lattice_walk<K>(L, true);
    if (g != 2) return g;
  }
  constexpr unsigned kAll = (1u << K) - 1u;
  const int s = int_minor_sign<I, K>(L, kAll, kAll);
  if (s != 0 || !sos) return s;
  return int_lattice_sos_search<I, K>(L);
}
// K <= 7: always decided (0, 1 or -1). K = 8..11: the walk alone — 2 where
// the minors exceed 60 bits (the caller's other stages decide).
template <int K>
FF_HD inline int int_lattice_sign(const IntLambda<K>& L, bool sos) {
  if constexpr (K > 7) {
    return int_lattice_walk<K>(L, sos);
  } else {
#if defined(FLIPFLOP_INT128)
    if (L.wide) return int_lattice_sign_as<int128_t, K>(L, sos);
#endif
    return int_lattice_sign_as<long long, K>(L, sos);
  }
}

// The largest j < m whose column is constant on the K rows (equal values),
// or -1; constant_column: is there one?
template <int K>
FF_HD inline int last_constant_column(const double* const* p, int m) {
  for (int j = m - 1; j >= 0; --j) {
    bool same = true;
    for (int i = 1; i < K; ++i) same = same && p[i][j] == p[0][j];
    if (same) return j;
  }
  return -1;
}
template <int K>
FF_HD inline bool constant_column(const double* const* p, int m) {
  return last_constant_column<K>(p, m) >= 0;
}

// Are two of the K points the same point (equal coordinates and, lifted,
// equal weights: exact copies in the input, a point located at or tested
// against its copy)? Then two rows of Λ are equal and det Λ = 0 exactly, which
// no filter decides; the perturbation does.
template <int K>
FF_HD inline bool equal_points(const double* const* p, const double* w) {
  const int ncoord = w ? K - 2 : K - 1;
  for (int i = 1; i < K; ++i)
    for (int j = 0; j < i; ++j) {
      bool same = !w || w[i] == w[j];
      for (int c = 0; c < ncoord && same; ++c) same = p[i][c] == p[j][c];
      if (same) return true;
    }
  return false;
}

// How many of the K rows are not small integers (a coordinate or the weight
// not an integer of magnitude below 2^26)? On a lattice with a few points
// moved by some ulp: the moved points of the call.
template <int K>
FF_HD inline int non_integer_rows(const double* const* p, const double* w) {
  const int ncoord = w ? K - 2 : K - 1;
  int n = 0;
  for (int i = 0; i < K; ++i) n += !small_integer_point(p[i], ncoord, w, i, 26);
  return n;
}

#if !defined(__CUDA_ARCH__)
// A lattice with a few points moved by some ulp (host): det Λ and, where it
// is 0 and `sos`, the perturbation's minors as polynomials in two
// infinitesimal units (near_lattice.hpp, exact); 2 where a value does not
// split or a minor is out of that stage's reach (the expansion stages then
// decide). The 3^5 grid with 20 % of its points moved by 2 ulp, its moved 0s
// subnormals, went through the XDbl expansions here (outside the Dbl
// window): 104,000 calls at 43,000-121,000 instructions.
template <int K>
inline int near_lattice_sign(const double* const* p, const double* w, bool sos) {
  NlMinors<K> N;
  if (!nl_build<K>(p, w, N.L)) return 2;
  constexpr unsigned kAll = (1u << K) - 1u;
  const int s = N.sign(kAll, kAll);
  if (s != 0 || !sos) return s;
  return sos_search<K>(true, [&](unsigned kr, unsigned kc) -> int { return N.sign(kr, kc); });
}
#endif

// `dd_ran`: the caller has tried the integer path (int_lambda) and its
// double-double filter (dd_filter.hpp: the same
// double-double values, an a-priori bound of the same order u^2 times the
// permanent as lambda_sign_dd's running one) has run on these points and not
// decided; both are skipped here. Such calls are (near-)zero determinants
// — on degenerate input exactly zero ones, which no filter decides — and the
// exact stages below decide every call, so only time changes, no sign.
template <int K>
FF_HD inline int lambda_exact(const double* const* p, const double* w, bool sos, bool dd_ran = false) {
  const Range range = call_range<K>(p, w);
  if (!range.finite) return non_finite_input();
  const int degree = w ? K : K - 1;
  // det Λ = 0 at once when a coordinate column is constant (points on a plane
  // x_j = c, e.g. the floors and walls of a building: the column minus c
  // times the 1-column is 0); the perturbation decides.
  // Likewise when two points are equal (exact copies).
  const bool copies = equal_points<K>(p, w);
  const bool flat = copies || constant_column<K>(p, w ? K - 2 : K - 1);
  if (range.fits(degree)) {
    double a[K][K];
    if constexpr (K <= 7) {
      if (!dd_ran) {  // (lambda_sign_after_filters tries it before the filters)
        IntLambda<K> L;
        if (int_lambda<K>(p, w, L)) return int_lattice_sign<K>(L, sos);
      }
    }
    if (lattice_doubles<K>(p, w, range, a)) return lattice_sign<K>(a, sos);
#if !defined(__CUDA_ARCH__)
    if (const int s = near_lattice_sign<K>(p, w, sos); s != 2) return s;
#endif
    // near-lattice calls (1..K-3 rows not of small integers): det_translated
    // from an integer base row expands over the other integer rows in
    // binary64 (MinorLaplace) and costs less than the double-double stage
    int s = 0;
    if (!flat) {
      const int moved = dd_ran ? 0 : non_integer_rows<K>(p, w);
      const bool near_lattice = moved >= 1 && moved <= K - 3;
      s = (dd_ran || near_lattice) ? 2 : lambda_sign_dd<K>(p, w);
    }
#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
    // undecided so far: on degenerate input an exact 0 far more often than
    // not, which the walk modulo primes shows without the exact determinant
    // (points on a plane x_j = c, det Λ = 0 known, likewise: the search's
    // cheap first pass is for copies, whose zero minors are equal rows)
    if (sos && (s == 2 || (flat && !copies)))
      if (const int t = sos_walk_first<K>(p, w); t != 2) return t;
    // the exact sign alone (no ids: the projections of flat_sign_sorted,
    // mostly exact zeros on those grids) — 0 without the exact determinant
    if (!sos && s == 2 && det_zero_by_walk<K>(p, w)) return 0;
#endif
    if constexpr (K == 3 || K == 4)
      if (!w && s == 2) s = orient_adaptive<K>(p);
    if constexpr (K == 4 || K == 5)
      if (w && s == 2) s = lifted_adaptive<K>(p, w);
    if (s == 2) s = det_translated<Dbl, K>(p, w);
    if (s != 0 || !sos) return s;
    // det Λ = 0: the perturbation's minors on doubles first, expansions
    // only for those undecided there
    return sos_lazy<K>(p, w, range);
  }
#if !defined(__CUDA_ARCH__)
  if (const int s = near_lattice_sign<K>(p, w, sos); s != 2) return s;
#endif
  const int s = flat ? 0 : det_translated<XDbl, K>(p, w);
  if (s != 0 || !sos) return s;
  return sos_expansions<XDbl, K>(p, w);
}

// lambda_pulled_sos's expansion stage on A (one call each on the device, as
// sos_expansions).
template <class A, int K>
FF_HD FF_DEVICE_NOINLINE int pulled_expansions(const double* const* p, const double* w) {
  const double zero[K] = {};
  RawLambda<A, K> L, Lq;
  build_lambda<A, K>(p, w, L);
  build_lambda<A, K>(p, zero, Lq);
  return sos_sign_pulled<A, K>(L, Lq);
}

// The pulled perturbation (sos_search, Pulled; predicates.hpp power_d_pulled)
// of a lifted Λ (w non-null) whose rows are sorted by increasing index and
// whose exact determinant the caller has found to be 0. Host and device; the
// expansions directly (the strict views call it only on degenerate tuples).
template <int K>
FF_HD inline int lambda_pulled_sos(const double* const* p, const double* w) {
  Range range;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < K - 2; ++j) range.add(p[i][j]);
    range.add(w[i]);
  }
  if (!range.finite) return non_finite_input();
  if (range.fits(K)) return pulled_expansions<Dbl, K>(p, w);
  return pulled_expansions<XDbl, K>(p, w);
}

// A row of a mixed Λ-matrix for the exact stage: an input point (x) or the
// centroid of `count` input points (src, row-major, `dim` coordinates each),
// taken as the row (Σ src, count) = count x (centroid, 1) — a positive
// multiple of the centroid's row, so every sign is unchanged.
struct MixedRowX {
  const double* x = nullptr;
  const double* src = nullptr;
  int count = 0;
};

template <class A, int K, int C>
FF_HD inline void build_lambda_mixed(const MixedRowX* rows, LambdaX<A, K, C>& L) {
  constexpr int dim = K - 1;
  for (int i = 0; i < K; ++i) {
    if (rows[i].x) {
      for (int j = 0; j < dim; ++j) L.a[i][j].set(rows[i].x[j]);
      L.a[i][K - 1].set(1.0);
    } else {
      for (int j = 0; j < dim; ++j) sum_entry<A>(rows[i].src + j, dim, rows[i].count, L.a[i][j]);
      L.a[i][K - 1].set(static_cast<double>(rows[i].count));
    }
  }
}

// lambda_exact_mixed's expansion stage on A (one call each on the device, as
// sos_expansions).
template <class A, int K>
FF_HD FF_DEVICE_NOINLINE int mixed_expansions(const MixedRowX* rows, bool sos) {
  RawLambda<A, K> L;
  build_lambda_mixed<A, K>(rows, L);
  return det_or_sos<A, K>(L, sos);
}

template <int K>
FF_HD inline int lambda_exact_mixed(const MixedRowX* rows, bool sos) {
  constexpr int dim = K - 1;
  Range range;
  for (int i = 0; i < K; ++i) {
    if (rows[i].x) {
      for (int j = 0; j < dim; ++j) range.add(rows[i].x[j]);
    } else {
      for (int t = 0; t < rows[i].count * dim; ++t) range.add(rows[i].src[t]);
      range.add(8.0 * rows[i].count);  // sums of up to 8 values: 3 more bits of magnitude
    }
  }
  if (!range.finite) return non_finite_input();
  if (range.fits(K - 1)) return mixed_expansions<Dbl, K>(rows, sos);
  return mixed_expansions<XDbl, K>(rows, sos);
}

}  // namespace flipflop::pred::xp

// static_filter.hpp — the two cheap filters in front of every predicate: a
// per-input *static* bound (thesis §6.4.2, "precomputed error bound"; CGAL's
// static filters) and a per-call *semi-static* bound (CGAL's semi-static
// filters, Shewchuk's errbound A with magnitudes taken column by column).
//
// Both evaluate det Λ as det T, the (N x N) determinant of differences of
// lambda_filter.hpp (N = k - 1): t_ij = fl(p_i[j] - p_k[j]), and for a lifted
// matrix the last column t_iN = fl(fl(Σ_j fl(d_ij^2)) - fl(w_i - w_k)), d_ij the
// rounded differences; then det T by the same Laplace expansion over column
// subsets as det_by_minors (plain doubles, no error terms).
//
// ============================================================================
// The bound (derivation)
// ============================================================================
// Notation: u = 2^-53 (unit roundoff), gamma_m = m u / (1 - m u) [Higham,
// Lemma 3.1]: a product of m factors (1 + δ_i)^{±1}, |δ_i| <= u, equals
// 1 + θ with |θ| <= gamma_m.
//
// (1) Without underflow, every floating-point operation is fl(x op y) =
//     (x op y)(1 + δ). The computed determinant is then Σ_σ sgn σ Π_i t_iσ(i)
//     (1 + θ_σ), where t are the *exact* entries and θ_σ collects the
//     roundings along the path of the term σ:
//       - one per entry (the difference p_i[j] - p_k[j]);
//       - one per product of a level (det_by_minors levels 2..N: N - 1);
//       - the additions of each level: level r adds r terms, a term passes
//         through at most r - 1 of them: Σ_{r=2..N} (r - 1) = N(N-1)/2.
//     For a lifted entry (differences<K>: the N - 1 monomials summed left to
//     right, then w_i - w_k subtracted), each monomial d_ij^2 takes 2 (the
//     difference, squared) + 1 (the square) + (N - 2) (the sum of the
//     monomials) + 1 (the weight difference subtracted) roundings, and
//     w_i - w_k takes 1 + 1; both are <= N + 2, i.e. N + 1 more than a plain
//     entry. Hence
//         m_plain(N)  = N + (N - 1) + N(N-1)/2,
//         m_lifted(N) = m_plain(N) + N + 1,
//     and |computed - exact| <= gamma_m · per(|T|), where per(|T|) is the
//     permanent of the entries' magnitudes, a lifted entry counting as
//     Σ_j d_ij^2 + |w_i - w_k| (exact). per(|T|) <= N! Π_c m_c for any column
//     bounds m_c >= max_i |t_ic|. (Until 2026-12-05 this paragraph counted
//     N + 1 roundings for a lifted entry and m_plain(N) + N, one short; the
//     constant gamma_m of that count was nonetheless sound: it is
//     gamma_{m-1} of the count here, which (1') shows is enough.)
// (1') The last rounding is not charged. Every path ends in the same last
//     operation, the last addition of level N (with_last_row's accumulator;
//     for N = 2 the one subtraction), so with r its exact result on the
//     computed operands, |r - exact| <= gamma_{m-1} per(|T|) and the
//     computed det is fl(r). Rounding to nearest is monotone and fixes 0, so
//     fl(r) has the sign of r or is 0, and |fl(r)| <= (1 + u)|r| (exactly
//     |r| where r is subnormal). Hence |fl(r)| > (1 + u) gamma_{m-1} per
//     gives |r| > |r - exact|: sign(fl(r)) = sign(r) = sign(exact). A fused
//     multiply-add in place of the last addition (nvcc's default, or
//     contraction on the host) is again one rounding of an exact result, and
//     it only removes a product's rounding from the other paths. The factor
//     (1 + u) is inside the slack of (2). (6) below argues the same way for
//     the permanent bound. For N = 1 (k = 2, plain) the one difference is
//     the last operation: gamma_0 = 0, the bound is (3)'s underflow term
//     alone, and fl(a - b) has the sign of a - b (a difference of doubles
//     rounds to 0 only when it is 0). For N = 2 this is 24u M^2 against
//     32u M^2 with the last rounding charged (orient2d's static bound):
//     filter_sensitivity_test's k = 3 set holds a wrong sign of fl(det) at
//     0.67 of it, so the bound is within 1.5x of the worst case there.
// (2) The bounds m_c are themselves computed: from rounded entries (|t| <=
//     |fl(t)| / (1 - u)), multiplied in floating point (N - 1 roundings down)
//     and multiplied by the constant (1 more). All of it is covered by the
//     factor (1 + 2^-30) on the constant (needs (1 - u)^{-3N} <= 1 + 2^-30,
//     true for N <= 7 by a margin of 2^20; it also covers the (1 + u) of
//     (1')).
// (3) Underflow. Sums and differences are exact when their result is
//     subnormal (IEEE 754 gradual underflow), so only products can lose more
//     than the relative bound: at most 2^-1075 absolutely each.
//     - static filter: the bound is used only when every input coordinate and
//       weight is a multiple of 2^L with D·min(L, 0) >= -1074, D the degree of
//       the determinant (N, or N + 1 lifted). Every computed value is then a
//       multiple of 2^-1074 (rounding keeps multiples of a power of two), so a
//       product never loses bits to underflow and (1) holds as stated.
//     - semi-static filter: the bound is used only when every column bound
//       lies in [2^-B, 2^B] with B = floor(960 / N). An absolute error of at
//       most 2^-1075 per product is multiplied afterwards only by entries of
//       other columns, |t| <= max(m_c, 1), so the total is at most
//       P_N 2^-1075 Π_c max(m_c, 1) <= P_N 2^-1075 2^{BN} Π_c m_c
//       <= 2^{12-1075+960} Π_c m_c = 2^-103 Π_c m_c (P_N <= N 2^N + N^2 <= 2^12
//       products), covered by adding 2^-100 to the constant.
// (4) Overflow: the semi-static window keeps Π_c m_c <= 2^960 and every
//     intermediate below 2^1000; the static filter is disabled when
//     N! Π_c m_c >= 2^1000. An infinite or NaN computed value never passes
//     the test |det| > bound.
// Sign decision: |fl(det)| > bound, with bound = C_N Π_c m_c computed as above.
//
// Static column bounds (once per input): M = the largest |coordinate| of the
// input, W = the largest |weight|: plain columns m = 2M (|fl(a - b)| <= fl(2M)
// by monotonicity of rounding), the lifted column m = (N - 1)(2M)^2 + 2W
// (times (1 + 2^-40) for the roundings of this bound itself).
//
// Header-only and __host__ __device__.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "predicates/err_double.hpp"
#include "predicates/lambda_filter.hpp"

namespace flipflop::pred {

namespace filter_detail {

// number of roundings along the path of one term of det T (see (1)), the
// last one included
FF_HD constexpr int rounding_depth(int n, bool lifted) {
  return n + (n - 1) + n * (n - 1) / 2 + (lifted ? n + 1 : 0);
}
FF_HD constexpr double factorial(int n) {  // a loop: no recursion on the device
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}
// C_N of (1)-(3): gamma_{m-1} N! (1 + 2^-30) + 2^-100, rounded up
// generously; m - 1: the last rounding cannot change the sign ((1')).
FF_HD constexpr double bound_constant(int n, bool lifted) {
  const double m = rounding_depth(n, lifted) - 1;
  const double u = 0x1p-53;
  return (m * u / (1.0 - m * u)) * factorial(n) * (1.0 + 0x1p-30) + 0x1p-100;
}
// semi-static window exponent B_N of (3)
FF_HD constexpr int window_exponent(int n) { return 960 / n; }
// 2^e, exact, evaluated at compile time where e is a constant (no libm call)
FF_HD constexpr double pow2i(int e) {
  double r = 1.0;
  for (; e > 0; --e) r *= 2.0;
  for (; e < 0; ++e) r *= 0.5;
  return r;
}
// max(a, b) without a libm call; like fmax, a NaN b is ignored (a NaN input
// makes the determinant NaN, which no filter test accepts)
FF_HD inline double max_of(double a, double b) { return b > a ? b : a; }

// The column bounds m_c of T from its entries t (differences<K> below): max
// |t_ic|; for a lifted column the max of Σ d^2 + |Δw|, Σ d^2 computed again
// from the coordinate differences in differences' order (the same value).
template <int K>
FF_HD inline void column_bounds(const double* w, const double* t, double* mag) {
  constexpr int N = K - 1;
  for (int j = 0; j < N; ++j) mag[j] = 0.0;
  if (w == nullptr) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) mag[j] = max_of(mag[j], std::fabs(t[i * N + j]));
  } else {
    constexpr int M = N - 1;
    for (int i = 0; i < N; ++i) {
      double lift = 0.0;
      for (int j = 0; j < M; ++j) {
        const double d = t[i * N + j];
        mag[j] = max_of(mag[j], std::fabs(d));
        lift = (j == 0) ? d * d : lift + d * d;
      }
      const double dw = w[i] - w[K - 1];
      mag[M] = max_of(mag[M], lift + std::fabs(dw));
    }
  }
}

// Entries of T in plain doubles (the evaluation the bounds are derived for);
// `mag` receives the column bounds m_c (column_bounds) when kMag.
template <int K, bool kMag = true>
FF_HD inline void differences(const double* const* p, const double* w, double* t, double* mag) {
  constexpr int N = K - 1;
  const double* base = p[K - 1];
  if (w == nullptr) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) t[i * N + j] = p[i][j] - base[j];
  } else {
    constexpr int M = N - 1;
    for (int i = 0; i < N; ++i) {
      double lift = 0.0;
      for (int j = 0; j < M; ++j) {
        const double d = p[i][j] - base[j];
        t[i * N + j] = d;
        lift = (j == 0) ? d * d : lift + d * d;
      }
      t[i * N + M] = lift - (w[i] - w[K - 1]);
    }
  }
  if constexpr (kMag) column_bounds<K>(w, t, mag);
}

// det_plain<N> split at its last level, for many determinants that share
// rows 0..N-2 and differ in row N-1 (the instant flip's scan: one simplex, its
// neighbours' opposite vertices). top_minors<N> computes, for every column j,
// the minor of rows 0..N-2 on the columns other than j (levels 2..N-1 of the
// Laplace expansion over column subsets), and with_last_row<N> the last level
// against a row (explicit for N = 3, 4, a loop beyond; row r of a subset's
// expansion in ascending column order, alternating signs from (r + position)
// parity). det_plain<N> is exactly this composition for N >= 3 (and the same
// roundings for N = 2), so every bound derived for det_plain holds for a
// split evaluation; predicates_stages_test checks both against the exact
// determinant. N >= 2.
template <int N>
FF_HD inline void top_minors(const double* t, double* minor) {
  static_assert(N >= 2 && N <= 8, "top_minors: 2 <= N <= 8");
  if constexpr (N == 2) {
    minor[0] = t[1];
    minor[1] = t[0];
  } else if constexpr (N == 3) {  // det_plain<3>'s m12, m02, m01
    minor[0] = t[1] * t[5] - t[2] * t[4];
    minor[1] = t[0] * t[5] - t[2] * t[3];
    minor[2] = t[0] * t[4] - t[1] * t[3];
  } else if constexpr (N == 4) {  // det_plain<4>'s d123, d023, d013, d012
    const double m01 = t[0] * t[5] - t[1] * t[4], m02 = t[0] * t[6] - t[2] * t[4];
    const double m03 = t[0] * t[7] - t[3] * t[4], m12 = t[1] * t[6] - t[2] * t[5];
    const double m13 = t[1] * t[7] - t[3] * t[5], m23 = t[2] * t[7] - t[3] * t[6];
    minor[0] = t[9] * m23 - t[10] * m13 + t[11] * m12;
    minor[1] = t[8] * m23 - t[10] * m03 + t[11] * m02;
    minor[2] = t[8] * m13 - t[9] * m03 + t[11] * m01;
    minor[3] = t[8] * m12 - t[9] * m02 + t[10] * m01;
  } else {
    constexpr int kFull = (1 << N) - 1;
    double d[1 << N];
    minor_levels<N, N - 1, double>(t, d);
    for (int j = 0; j < N; ++j) minor[j] = d[kFull & ~(1 << j)];
  }
}
template <int N>
FF_HD inline double with_last_row(const double* minor, const double* last) {
  double acc = 0.0;
  for (int j = 0; j < N; ++j) {
    const double term = last[j] * minor[j];
    const bool negative = ((N - 1 + j) & 1) != 0;
    acc = (j == 0) ? (negative ? -term : term) : (negative ? acc - term : acc + term);
  }
  return acc;
}

// det T by Laplace expansion over column subsets, plain doubles (same
// operation structure as det_by_minors<N>; explicit for N = 2; for N >= 3 the
// levels of top_minors<N> and the last row by with_last_row<N>).
template <int N>
FF_HD inline double det_plain(const double* t) {
  if constexpr (N == 1) {
    return t[0];
  } else if constexpr (N == 2) {
    return t[0] * t[3] - t[1] * t[2];
  } else {
    // the Laplace levels over column subsets; the last one against row N-1
    double minor[N];
    top_minors<N>(t, minor);
    return with_last_row<N>(minor, t + (N - 1) * N);
  }
}

// Branchless on purpose: on random input the first comparison goes either way
// half the time, and as two branches it was mispredicted about that often
// (issue 10: 50.0 -> 44.3 ns per power3d call in the bench's loop). A NaN det
// or bound makes both comparisons false: 0, undecided.
FF_HD inline int sign_beyond(double det, double bound) {
  return static_cast<int>(det > bound) - static_cast<int>(-det > bound);
}

}  // namespace filter_detail

namespace filter_detail {
// The semi-static test of (1)-(4) on a computed det T and T's column bounds.
template <int K>
FF_HD inline int semi_static_decide(double det, const double* mag, bool lifted) {
  constexpr int N = K - 1;
  constexpr int B = window_exponent(N);
  constexpr double wlo = pow2i(-B), whi = pow2i(B);
  constexpr double kPlain = bound_constant(N, false);
  constexpr double kLifted = bound_constant(N, true);
  double prod = lifted ? kLifted : kPlain;
  for (int c = 0; c < N; ++c) {
    if (!(mag[c] >= wlo && mag[c] <= whi)) return 0;  // outside the window (or NaN)
    prod *= mag[c];
  }
  return sign_beyond(det, prod);
}
}  // namespace filter_detail

// Per-call semi-static filter on K points (see (1)-(4)).
template <int K>
FF_HD inline int semi_static_sign(const double* const* p, const double* w) {
  constexpr int N = K - 1;
  double t[N * N], mag[N];
  filter_detail::differences<K>(p, w, t, mag);
  return filter_detail::semi_static_decide<K>(filter_detail::det_plain<N>(t), mag, w != nullptr);
}


// Per-call semi-static filter for a Λ-matrix with one row known only
// approximately: the exact kernel point of the reference's hulls (a centroid
// of input points, rational_point.hpp), seen as q_j = k_j ± e_j (its filter
// value and a bound on the error, ErrDouble). Unlifted, K <= 4.
//
// (5) Derivation. Move the approximate row r last (a row swap: the sign flips
//     when r != K - 1). det Λ is affine in that row: with c_j the cofactor of
//     Λ at (K-1, j),
//         det Λ(q) = det Λ(k) + Σ_j (q_j - k_j) c_j,
//     so |det Λ(q) - r| <= bound(1)-(4) on the rows with k in place + U,
//     U = Σ_j e_j |c_j|, r the exact result of det T(k)'s last operation
//     ((1'): fl(r) is the computed value, and the test's factor 1 + 2^-40
//     covers |fl(r)| <= (1 + u)|r|). The cofactor c_j is ± the determinant of rows
//     0..K-2 on the columns other than j (the 1-column included); subtracting
//     row 0 gives the (N-1) x (N-1) determinant of differences x_i - x_0 on
//     the coordinate columns c != j, so |c_j| <= (N-1)! Π_{c != j} G_c with
//     G_c = max_i |x_ic - x_0c|. U is computed in floating point from upper
//     bounds only: e_j and every non-zero G_c are raised to at least 2^-B
//     (B = floor(960 / N), as in (3)), so no product underflows (N factors
//     >= 2^-960) and, with every factor <= 2^B, none overflows; the roundings
//     (2N operations, and |exact G| <= fl(G)(1 + u)) are covered by the factor
//     1 + 2^-30, and the final addition bound + U by 1 + 2^-40. A zero G_c is
//     exact (column c constant on those rows: the cofactors with c have a zero
//     column).
template <int K>
FF_HD inline int mixed_semi_static_sign(const double* const* rows, int r, const double* err) {
  static_assert(K >= 2 && K <= 4, "mixed rows: K <= 4");
  constexpr int N = K - 1;
  const double* p[K];
  for (int i = 0; i < K; ++i) p[i] = rows[i];
  const int flip = (r == K - 1) ? 1 : -1;
  p[r] = rows[K - 1];
  p[K - 1] = rows[r];
  double t[N * N], mag[N];
  filter_detail::differences<K>(p, nullptr, t, mag);
  constexpr int B = filter_detail::window_exponent(N);
  constexpr double wlo = filter_detail::pow2i(-B), whi = filter_detail::pow2i(B);
  double bound = filter_detail::bound_constant(N, false);
  for (int c = 0; c < N; ++c) {
    if (!(mag[c] >= wlo && mag[c] <= whi)) return 0;  // outside the window (or NaN)
    bound *= mag[c];
  }
  // G_c over rows 0..K-2 (the exact rows), raised to 2^-B when non-zero
  double G[N];
  for (int c = 0; c < N; ++c) {
    double g = 0.0;
    for (int i = 1; i < N; ++i) g = filter_detail::max_of(g, std::fabs(p[i][c] - p[0][c]));
    if (!(g <= whi)) return 0;
    G[c] = (g == 0.0) ? 0.0 : filter_detail::max_of(g, wlo);
  }
  double U = 0.0;
  for (int j = 0; j < N; ++j) {
    const double e = err[j];
    if (!(e <= whi)) return 0;  // also NaN
    double term = filter_detail::max_of(e, wlo) * filter_detail::factorial(N - 1);
    for (int c = 0; c < N; ++c)
      if (c != j) term *= G[c];
    U += term;
  }
  const double total = (bound + U * (1.0 + 0x1p-30)) * (1.0 + 0x1p-40);
  return flip * filter_detail::sign_beyond(filter_detail::det_plain<N>(t), total);
}

// The per-input static filter: bounds for every k (2..8), plain and lifted.
class StaticFilter {
 public:
  // A filter that decides nothing (bounds +inf, no double-double window).
  FF_HD StaticFilter() {
    for (int i = 0; i < 9; ++i) plain_[i] = lifted_[i] = HUGE_VAL;
  }

  // From n points of `dim` coordinates (row-major) and optional weights.
  // Every predicate call whose coordinates and weights are among these values
  // (any subset of points, any coordinate projection) may use the bounds.
  // `extra` (extra_count values) are further coordinate values the calls may
  // use (e.g. an auxiliary point of double coordinates), scanned like coords.
  static StaticFilter for_points(const double* coords, std::size_t n, int dim,
                                 const double* weights = nullptr, const double* extra = nullptr,
                                 std::size_t extra_count = 0) {
    StaticFilter f;
    double M = 0.0, W = 0.0;
    int lsb = 0;  // min(L, 0) over every value, L the exponent of its lowest set bit
    bool finite = true;
    bool small_int = true;  // every value an integer below 2^20 in magnitude
    // from the IEEE 754 bits: a normal x = (2^52 + m) 2^(e - 1075), a
    // subnormal x = m 2^-1074; the lowest set bit of the integer mantissa
    // gives L
    auto scan = [&](double x, double& mx) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      const int e = static_cast<int>((bits >> 52) & 0x7ff);
      if (e == 0x7ff) {
        finite = false;
        return;
      }
      mx = std::fmax(mx, std::fabs(x));
      small_int = small_int && x > -0x1p20 && x < 0x1p20 && x == static_cast<double>(static_cast<long long>(x));
      std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
      if (e != 0) mant |= std::uint64_t{1} << 52;
      if (mant == 0) return;  // a zero
      const int low = (e == 0 ? -1074 : e - 1075) + __builtin_ctzll(mant);
      if (low < lsb) lsb = low;
    };
    for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i) scan(coords[i], M);
    for (std::size_t i = 0; i < extra_count; ++i) scan(extra[i], M);
    if (weights)
      for (std::size_t i = 0; i < n; ++i) scan(weights[i], W);
    if (!finite || n == 0) return f;
    // the double-double filter's window (dd_filter.hpp): every value 0 or a
    // multiple of 2^-202 below 2^150 in magnitude
    f.dd_window_ = lsb >= -202 && M < 0x1p150 && W < 0x1p150;
    f.small_int_ = small_int;
    // Where every value is such an integer: the calls of k rows whose walk in
    // binary64 (exact_expansion.hpp, int_lattice_sos_dbl_rows) needs no
    // per-call test of its bound H^2 = Π_j max(1, |D_j|^2) < 2^51 over the
    // columns of D (k - 1 rows of differences to the last row). From the
    // magnitudes alone, as every bound here (the kernels' filters are built
    // from representatives that keep the largest magnitude and the lowest
    // bit, not the values' signs: parallel.hpp): a coordinate column's
    // differences are at most 2M, a lifted one's (|x|^2 - w over at most
    // k - 2 coordinates, in [-W, (k - 2) M^2 + W]) at most (k - 2) M^2 + 2W,
    // and |D_j|^2 is at most k - 1 times their square. The products of
    // integers below 2^53 are exact but for the last few factors; the margin
    // (1 + 2^-40) covers their roundings upward (under 30 of 2^-53 each).
    if (small_int && n > 0)
      for (int k = 3; k <= 8; ++k) {
        const double rows = static_cast<double>(k - 1);
        const double coord = filter_detail::max_of(1.0, rows * (2.0 * M) * (2.0 * M));
        const double lift = static_cast<double>(k - 2) * M * M + 2.0 * W;
        const double lifted = filter_detail::max_of(1.0, rows * lift * lift);
        double plain_h2 = 1.0, lifted_h2 = lifted;
        for (int c = 0; c < k - 1; ++c) plain_h2 *= coord;
        for (int c = 0; c < k - 2; ++c) lifted_h2 *= coord;
        if (plain_h2 * (1.0 + 0x1p-40) < 0x1p51) f.walk_bounded_ |= 1u << (2 * k);
        if (lifted_h2 * (1.0 + 0x1p-40) < 0x1p51) f.walk_bounded_ |= 1u << (2 * k + 1);
      }
    for (int k = 2; k <= 8; ++k) {
      const int N = k - 1;
      // plain: degree N
      if (static_cast<long>(N) * lsb >= -1074) {
        // (4): the test is on N! Π m_c itself (every intermediate of det T is
        // at most that), not on the bound, which is ~2^-50 smaller
        double prod = 1.0;
        for (int c = 0; c < N; ++c) prod *= 2.0 * M;
        const double b = filter_detail::bound_constant(N, false) * prod;
        if (prod * filter_detail::factorial(N) < 0x1p1000 && b > 0.0) f.plain_[k] = b;
        if (M == 0.0) f.plain_[k] = HUGE_VAL;
      }
      // lifted: degree N + 1
      if (k >= 3 && static_cast<long>(N + 1) * lsb >= -1074) {
        const double liftmag = ((N - 1) * (2.0 * M) * (2.0 * M) + 2.0 * W) * (1.0 + 0x1p-40);
        double prod = liftmag;
        for (int c = 0; c + 1 < N; ++c) prod *= 2.0 * M;
        const double b = filter_detail::bound_constant(N, true) * prod;
        if (prod * filter_detail::factorial(N) < 0x1p1000 && b > 0.0 && M > 0.0) f.lifted_[k] = b;
      }
    }
    return f;
  }

  // The bound for det Λ of k points, lifted or not (+inf: cannot decide).
  FF_HD double bound(int k, bool lifted) const {
    if (k < 2 || k > 8) return HUGE_VAL;
    return lifted ? lifted_[k] : plain_[k];
  }

  // Every value the input's calls use lies in the window of the double-double
  // filter (dd_filter.hpp: 0 or a multiple of 2^-202 below 2^150 in
  // magnitude), so its per-call window check can be skipped.
  FF_HD bool dd_window() const { return dd_window_; }

  // Every value is an integer below 2^20 in magnitude (an integer lattice
  // such as a k^d grid, weights included): the calls' determinants are then
  // exactly zero more often than not, and lambda_sign_staged goes to the
  // integer walk (lambda_small_int_sorted) before the float filters, which
  // cannot decide a zero (staged.hpp, kLatticeFirstK); below that, the
  // stages after the filters are told so (lattice()). Like the bounds, it
  // holds only for calls whose values are among the scanned ones (`extra`
  // included): there the walk is told to skip its per-value tests, so a call
  // with ids on any other value (an auxiliary point left out of the scan)
  // must not use this filter — every caller builds its filter over the
  // values it calls on (convex_surface.cpp rescans with its auxiliary
  // centre; calls without ids, the unperturbed ones, never take this path).
  FF_HD bool small_integers() const { return small_int_; }

  // Where small_integers(): the calls of k rows, lifted (with weights) or not,
  // whose binary64 SoS walk is within its bound for any rows of these values
  // (for_points: from the largest magnitudes), so that it skips its per-call
  // test (3^5 grid Delaunay: a fifth of the walk's instructions). The same
  // contract as small_integers(): only for calls on the scanned values.
  FF_HD bool walk_bounded(int k, bool lifted) const {
    return k >= 3 && k <= 8 && ((walk_bounded_ >> (2 * k + (lifted ? 1 : 0))) & 1u) != 0;
  }
  // Both as one level for the stages after the filters (staged.hpp,
  // lambda_sign_after_filters' `lattice`): 0 neither, 1 small_integers(), 2
  // also walk_bounded(k, lifted).
  FF_HD int lattice(int k, bool lifted) const { return !small_int_ ? 0 : walk_bounded(k, lifted) ? 2 : 1; }

  // Test hook: every bound multiplied by `factor` (a weakened filter for the
  // sensitivity check of the test suite; never used by the library).
  StaticFilter scaled_for_testing(double factor) const {
    StaticFilter g = *this;
    for (int i = 0; i < 9; ++i) {
      g.plain_[i] *= factor;
      g.lifted_[i] *= factor;
    }
    return g;
  }

 private:
  double plain_[9];
  double lifted_[9];
  bool dd_window_ = false;
  bool small_int_ = false;
  std::uint32_t walk_bounded_ = 0;  // bit 2k (plain) and 2k + 1 (lifted): walk_bounded(k, lifted)
};

// The plain determinant of det Λ's differences T against a bound derived
// for it: +1/-1 when |det T| exceeds `bound`, 0 otherwise (static_sign, and
// the exact kernel point's per-input bound, ref::RationalKernel::side and the
// GPU hull's Geo::side).
template <int K>
FF_HD inline int sign_beyond_bound(const double* const* p, const double* w, double bound) {
  constexpr int N = K - 1;
  double t[N * N];
  filter_detail::differences<K, false>(p, w, t, nullptr);
  return filter_detail::sign_beyond(filter_detail::det_plain<N>(t), bound);
}

// Static filter sign of det Λ of K points: +1/-1 when |det| exceeds the
// per-input bound, 0 otherwise.
template <int K>
FF_HD inline int static_sign(const StaticFilter& f, const double* const* p, const double* w) {
  return sign_beyond_bound<K>(p, w, f.bound(K, w != nullptr));
}

// static_sign (when f is given), then semi_static_sign, on one evaluation of
// T and det T: the values both compute, bit for bit, computed once. Where the
// static filter fails (lattices: most calls are exactly degenerate) the
// semi-static test costs its column bounds only, not a second determinant
// (3^5 grid Delaunay, K = 7, together with building the integer stage's Λ
// in id order: 1322 -> 1296 M instructions, callgrind).
template <int K>
FF_HD inline int static_semi_static_sign(const StaticFilter* f, const double* const* p, const double* w) {
  constexpr int N = K - 1;
  double t[N * N], mag[N];
  filter_detail::differences<K, false>(p, w, t, nullptr);
  const double det = filter_detail::det_plain<N>(t);
  if (f)
    if (const int s = filter_detail::sign_beyond(det, f->bound(K, w != nullptr))) return s;
  filter_detail::column_bounds<K>(w, t, mag);
  return filter_detail::semi_static_decide<K>(det, mag, w != nullptr);
}

// ============================================================================
// The static filter and the permanent filter, in one evaluation (orient2d,
// orient3d: plain K = 3, 4)
// ============================================================================
// plain_filters<K>(f, p) computes T and det T once, by the operations of
// differences<K> and det_plain<N> (the same values bit for bit), and returns
// static_sign<K>'s answer when that decides. Otherwise, where the input's
// static bound is finite, it tries a per-call bound from the permanent of the
// entries' magnitudes (Shewchuk's errbound A for orient2d/orient3d, [She97]
// §4.2, Fig. 21: a bound per term instead of per column; on the bench's
// near-degenerate calls it decides 87 % (orient2d) and 59 % (orient3d) where
// the semi-static bound decides 50 % and 2 %); elsewhere semi_static_sign<K>.
//
// (6) Derivation (N = K - 1 = 2, 3). Where f.bound(K, false) is finite, the
//     conditions of (3) and (4) for the static filter hold for every call on
//     f's input: every value is a multiple of 2^L with N min(L, 0) >= -1074
//     and N! (2M)^N < 2^1000 (M the largest |coordinate|). Every value
//     computed below (the entries t, their products of at most N factors,
//     sums of those, and the same for the magnitudes) is then a multiple of
//     2^-1074 below 2^1001 in magnitude: no product loses bits to underflow,
//     nothing overflows, and every rounded operation obeys |fl(x) - x| <= u
//     |fl(x)| (a subnormal multiple of 2^-1074 is exact).
//     Error. As in (1), the computed value before the last rounding, z, is
//     Σ_σ sgn σ Π_i t_iσ(i) (1 + θ_σ) over the exact entries t, with θ_σ
//     collecting every rounding on the term's path but the last one: N (the
//     differences) + N - 1 (the products) + the additions other than the last
//     one: m = 3 (N = 2: t00 t11 - t01 t10) and m = 7 (N = 3: the minors'
//     subtraction, then ((x0 - x1) + x2) of with_last_row<3>, a term passing
//     at most two additions before the last). So |z - det T| <= γ_m per(|T|),
//     per the permanent of the exact entries' magnitudes, and |det̂ - z| <=
//     u |det̂|: |det T - det̂| <= γ_m per(|T|) + u |det̂|, and the sign of det̂
//     is that of det T when |det̂| (1 - u) > γ_m per(|T|).
//     The permanent is computed from the rounded entries' magnitudes (|t| <=
//     |t̂| / (1 - u)) by the same Laplace expansion with every sign +, all
//     terms non-negative: each rounding lowers it by at most a factor (1 - u),
//     so per(|T|) <= per̂ (1 - u)^-k, k <= 8 (N = 3: 3 entries, then a
//     product, a sum, a product and two sums). (Not from the determinant's
//     own products |fl(t̂ t̂')|, the same values: keeping those alive through
//     the static test cost the random calls two instructions more.) The bound
//     b = fl(fl(C per̂) + 2^-1073) >= C per̂ (1 - u)^2 (fl(C per̂) may underflow:
//     it is at least C per̂ (1 - u) - 2^-1075, and the added 2^-1073 covers
//     that). So |det̂| > b implies the sign when C (1 - u)^3 >= γ_m (1 - u)^-8,
//     i.e. C >= m u (1 + 20 u) for m <= 7: C = m u (1 + 2^-40).
//     Without underflow or overflow no other error enters; NaN never passes.
namespace filter_detail {
// C of (6): m u (1 + 2^-40), m = 3 (N = 2), 7 (N = 3); exact in binary64
FF_HD constexpr double permanent_constant(int n) {
  return (n == 2 ? 3.0 : 7.0) * 0x1p-53 * (1.0 + 0x1p-40);
}
}  // namespace filter_detail

template <int K>
FF_HD inline int plain_filters(const StaticFilter& f, const double* const* p) {
  static_assert(K == 3 || K == 4, "plain_filters: orient2d, orient3d");
  constexpr int N = K - 1;
  double t[N * N];
  filter_detail::differences<K, false>(p, nullptr, t, nullptr);
  const double sbound = f.bound(K, false);
  double det = 0.0, per = 0.0;
  if constexpr (N == 2) {
    const double l = t[0] * t[3], r = t[1] * t[2];
    det = l - r;  // det_plain<2>
    if (const int s = filter_detail::sign_beyond(det, sbound)) return s;
    if (!(sbound < HUGE_VAL)) return semi_static_sign<K>(p, nullptr);
    per = std::fabs(t[0]) * std::fabs(t[3]) + std::fabs(t[1]) * std::fabs(t[2]);
  } else {
    // det_plain<3>: top_minors<3> (m0 = m12, m1 = m02, m2 = m01), then
    // with_last_row<3>: ((t6 m0 - t7 m1) + t8 m2)
    const double a0 = t[1] * t[5], b0 = t[2] * t[4];
    const double a1 = t[0] * t[5], b1 = t[2] * t[3];
    const double a2 = t[0] * t[4], b2 = t[1] * t[3];
    const double m0 = a0 - b0, m1 = a1 - b1, m2 = a2 - b2;
    det = (t[6] * m0 - t[7] * m1) + t[8] * m2;
    if (const int s = filter_detail::sign_beyond(det, sbound)) return s;
    if (!(sbound < HUGE_VAL)) return semi_static_sign<K>(p, nullptr);
    double a[9];
    for (int i = 0; i < 9; ++i) a[i] = std::fabs(t[i]);
    per = (a[6] * (a[1] * a[5] + a[2] * a[4]) + a[7] * (a[0] * a[5] + a[2] * a[3])) +
          a[8] * (a[0] * a[4] + a[1] * a[3]);
  }
  constexpr double C = filter_detail::permanent_constant(N);
  return filter_detail::sign_beyond(det, C * per + 0x1p-1073);
}

}  // namespace flipflop::pred

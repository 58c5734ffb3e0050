// plane_form.hpp — orient_d(t_0, ..., t_{D-1}, x) for a fixed D-tuple t and
// many points x: the orientation as a linear function of x with a proven
// per-tuple error bound, so that each further x costs a dot product (about
// 6D flops) instead of a (D+1)-row determinant. Host only.
//
// The function. orient_d is the sign of det Λ, Λ's rows (t_0, 1), ...,
// (t_{D-1}, 1), (x, 1) (predicates.hpp: the 1-column last). Subtracting row 0
// from the others and expanding along the 1-column, det Λ = (-1)^D det M with
// M's rows t_1 - t_0, ..., t_{D-1} - t_0, x - t_0; expanding M along its last
// row, det Λ = Σ_j N_j (x_j - t0_j) with N_j = -(-1)^j det M_j, M_j the
// (D-1) x (D-1) matrix of the difference rows without column j.
//
// The bound. The N_j are computed once in ErrDouble (err_double.hpp: a
// running bound e_j on |n_j - N_j|, n_j the computed value, with the rounded
// differences included; every ErrDouble operation adds 4 eta, so e_j >= 4 eta,
// eta = 2^-1074; det_by_minors' expansion with the smaller minors shared, or
// Gaussian elimination for D - 1 > 7). For
// x: d_j = x_j - t0_j exactly, a_j = fl(d_j), |d_j - a_j| <= u |a_j|
// (round to nearest; a difference of doubles that lands in the subnormal
// range is exact), s = fl(Σ n_j a_j). Then
//   det Λ - Σ n_j a_j = Σ (N_j - n_j) d_j + Σ n_j (d_j - a_j),
//   |det Λ - s| <= Σ e_j |d_j| + u Σ |n_j| |a_j| + γ_D Σ |n_j| |a_j| + D eta/2
//               <= Σ [(1 + 2u) e_j + (u + γ_D) |n_j|] |a_j| + D eta/2
// (|d_j| <= (1 + u)|a_j|; the dot product's error, left to right, γ_D = D u /
// (1 - D u) times Σ |n_j a_j|, and at most eta/2 per product that
// underflows). The weights are computed as w_j = fl((1 + 2u) e_j + (u + γ_D)
// |n_j|) + eta: the product (u + γ_D)|n_j| may underflow, losing at most
// eta/2, which the added eta covers after the multiplication by |a_j|; every
// other rounding of the weights and of Σ w_j |a_j| is relative (sums of
// non-negative terms, e_j >= 4 eta), and the products w_j |a_j| lose at most
// eta/2 each where they underflow. So |det Λ - s| is below
// Σ w_j |a_j| (1 + 2^-40) + D 2^-1072 (ErrDouble's rule for the bound's own
// roundings: the factor covers far more than the 2D + 6 roundings along any
// path; 4 eta per product for the rest). |s| above it: det Λ has s's sign,
// which is then orient_d's under SoS too (a non-zero determinant is never
// perturbed). (Before 2026-11-30 the weights were e_j + 2 (u + γ_D)|n_j|;
// the sensitivity search of proptests/filter_sensitivity_test.cpp then met
// wrong signs only below 1/4.4 of the bound.)
// Otherwise — NaN or infinity anywhere, an overflowing sum included — sign()
// answers 0 and the
// caller asks the exact predicate. Tested against the exact predicate on
// random, near-degenerate and exactly degenerate tuples for D = 2..9
// (proptests/predicates_stages_test.cpp, "PlaneForm").
#pragma once

#include <cmath>

#include "predicates/err_double.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::pred {

template <int D>
struct PlaneForm {
  static_assert(D >= 2 && D <= 9, "PlaneForm: D in 2..9");
  double n[D];  // N_j (above)
  double w[D];  // the error weights w_j
  const double* base = nullptr;  // t_0

  PlaneForm() = default;
  // t: the D points of the tuple, in order
  explicit PlaneForm(const double* const* t) {
    base = t[0];
    ErrDouble rows[(D - 1) * D];
    for (int i = 1; i < D; ++i)
      for (int j = 0; j < D; ++j) rows[(i - 1) * D + j] = ErrDouble(t[i][j]) - ErrDouble(base[j]);
    constexpr double u = ErrDouble::kU;
    const double gamma = D * u / (1.0 - D * u);
    // The D minors det M_j share their smaller minors: levels 2..D-1 of the
    // Laplace expansion over column subsets of the difference rows
    // (lambda_filter.hpp minor_levels; rows is the top D-1 rows of a D x D
    // layout), det M_j the subset of every column but j. Each det M_j is
    // det_by_minors<D-1>'s expression on M_j, term for term (a subset's
    // columns keep their ascending order and positions; det_small, for
    // D - 1 <= 4, writes the same expansion out; for D - 1 = 2 the same
    // roundings in another order). ErrDouble's bound is proven per operation,
    // so it holds in any order. 5D: 70 products in ErrDouble per
    // form instead of 140 (hull_d_problem's inner box, callgrind: 44 M of
    // 139 M instructions in det_by_minors<4> on 2x10^4 normal 5D points).
    [[maybe_unused]] ErrDouble levels[D - 1 <= 7 ? (1 << D) : 1];
    if constexpr (D - 1 <= 7) minor_levels<D, D - 1, ErrDouble>(rows, levels);
    for (int j = 0; j < D; ++j) {
      ErrDouble minor;
      if constexpr (D - 1 <= 7) {
        minor = levels[((1 << D) - 1) & ~(1 << j)];
      } else {
        ErrDouble m[(D - 1) * (D - 1)];
        for (int a = 0; a < D - 1; ++a) {
          int b = 0;
          for (int c = 0; c < D; ++c)
            if (c != j) m[a * (D - 1) + b++] = rows[a * D + c];
        }
        minor = det_gauss_rt(m, D - 1);
      }
      n[j] = j % 2 == 0 ? -minor.v : minor.v;
      w[j] = ((1.0 + 2.0 * u) * minor.e + (u + gamma) * std::fabs(minor.v)) + 0x1p-1074;
    }
  }

  // the floating-point value s of det Λ (above), for heuristics
  double value(const double* x) const {
    double s = 0.0;
    for (int j = 0; j < D; ++j) s += n[j] * (x[j] - base[j]);
    return s;
  }

  // orient_d(t, x): +1 / -1 when certain, 0 when undecided
  int sign(const double* x) const {
    double s = 0.0, b = 0.0;
    for (int j = 0; j < D; ++j) {
      const double a = x[j] - base[j];
      s += n[j] * a;
      b += w[j] * std::fabs(a);
    }
    // an overflow in the sum leaves no bound on s's error (a partial sum can
    // reach infinity and the rest not bring it back): undecided
    if (!(std::fabs(s) <= 0x1.fffffffffffffp+1023)) return 0;
    const double bound = b * (1.0 + 0x1p-40) + D * 0x1p-1072;
    if (s > bound) return 1;
    if (-s > bound) return -1;
    return 0;  // also for NaN and infinities
  }

  // Whether det Λ(x) < 0 for every x with |x - c| <= r, certainly (c: a
  // point of doubles, r > 0): a ball strictly on the negative side of the
  // tuple's hyperplane. det Λ(x) = Σ N_j (x_j - t0_j) is affine in x, so on
  // the ball it is at most det Λ(c) + r |N|. det Λ(c) <= s + bound (sign()'s
  // s and bound at x = c, the derivation above), and |N| <= |n| + |N - n|
  // <= |n| + Σ e_j <= |n| + Σ w_j (the 1-norm bounds the 2-norm; e_j <= w_j).
  // Computed: room = fl(-s - bound), one rounding of a difference (relative
  // u, exact where subnormal); |n| = sqrt of the rounded sum of squares,
  // within a relative (D + 2) u of the exact one once that sum is at least
  // 2^-800 (an underflowing square then loses at most 2^-1075 against it);
  // Σ w_j, non-negative terms, relative D u; the product by r, u. The factors
  // 1 +- 2^-40 cover all of these for D <= 9, and 2^-1000 an underflowing
  // product: reach < room (1 - 2^-40) gives s + bound + r (|n| + Σ w_j) < 0.
  // False where it cannot tell: a facet of (almost) zero volume (|n|^2 below
  // 2^-800), NaN or infinity anywhere. Used for a certifier's inner ball
  // (kernels_cpu/rtd/hull_d.cpp, propose_ball).
  bool ball_below(const double* c, double r) const {
    double s = 0.0, b = 0.0, nn = 0.0, wsum = 0.0;
    for (int j = 0; j < D; ++j) {
      const double a = c[j] - base[j];
      s += n[j] * a;
      b += w[j] * std::fabs(a);
      nn += n[j] * n[j];
      wsum += w[j];
    }
    if (!(std::fabs(s) <= 0x1.fffffffffffffp+1023) || !(nn >= 0x1p-800) || !(r > 0.0)) return false;
    const double bound = b * (1.0 + 0x1p-40) + D * 0x1p-1072;
    const double room = -s - bound;
    const double reach = r * (std::sqrt(nn) + wsum) * (1.0 + 0x1p-40) + 0x1p-1000;
    return reach < room * (1.0 - 0x1p-40);  // false for NaN and infinities
  }
};

// The same orientation against the per-input static bound instead of a
// per-tuple one: cheaper to build (one determinant's top levels in plain
// doubles, where PlaneForm takes D minors in ErrDouble), and it decides
// only where |det Λ| exceeds StaticFilter::bound(D + 1, false).
//
// Why the static bound holds. Reorder Λ's rows as (t_1, ..., t_{D-1}, x,
// t_0): moving t_0 last is D transpositions, so orient_d(t, x) = (-1)^D sign
// det Λ', and det Λ' = det T' with T' the differences against t_0 (rows
// fl(t_i - t_0), then fl(x - t_0): lambda_filter.hpp). The form keeps
// top_minors<D> of T''s first D-1 rows and finishes with with_last_row<D>
// against x's row: det_plain<D>(T')'s operations in its order
// (static_filter.hpp), so its computed value is det_plain's bit for bit and
// the static bound for D + 1 plain points bounds its error (its entries are
// rounded differences of input coordinates, as the bound's derivation
// requires). D <= 7: the static filter's bounds stop at 8 points (beyond,
// bound() is +inf and nothing is decided).
template <int D>
struct StaticPlaneForm {
  static_assert(D >= 2 && D <= 7, "StaticPlaneForm: D in 2..7");
  double minor[D];  // top_minors<D> of the rows t_1 - t_0, ..., t_{D-1} - t_0
  const double* base = nullptr;  // t_0

  StaticPlaneForm() = default;
  // t: the D points of the tuple, in order
  explicit StaticPlaneForm(const double* const* t) {
    base = t[0];
    double rows[D * D];  // row D-1 is not read by top_minors
    for (int i = 1; i < D; ++i)
      for (int j = 0; j < D; ++j) rows[(i - 1) * D + j] = t[i][j] - base[j];
    for (int j = 0; j < D; ++j) rows[(D - 1) * D + j] = 0.0;
    filter_detail::top_minors<D>(rows, minor);
  }

  // orient_d(t, x) against `bound` (StaticFilter::bound(D + 1, false) of an
  // input holding t and x): +1 / -1 when certain, 0 when undecided (NaN and
  // an infinite bound included)
  int sign(const double* x, double bound) const {
    const int s = filter_detail::sign_beyond(det(x), bound);
    return D % 2 == 0 ? s : -s;
  }
  // the computed det T' (above; orient_d's sign times (-1)^D)
  double det(const double* x) const {
    double last[D];
    for (int j = 0; j < D; ++j) last[j] = x[j] - base[j];
    return filter_detail::with_last_row<D>(minor, last);
  }
};

}  // namespace flipflop::pred

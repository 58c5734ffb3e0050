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
// running bound e_j on |N_j* - N_j| with the rounded differences included;
// det_by_minors, or Gaussian elimination for D - 1 > 7). For x: a_j =
// fl(x_j - t0_j) = (x_j - t0_j)(1 + δ_j), |δ_j| <= u (a difference of doubles
// that lands in the subnormal range is exact), s = fl(Σ N_j a_j), and
//   |det Λ - s| <= (1 + 2u) [Σ e_j |a_j| + (u + γ_D) Σ |N_j| |a_j|] + D η
// (the cofactors' errors; the differences' roundings, |x_j - t0_j - a_j| <=
// u(1 + 2u) |a_j|; the dot product's, γ_D = D u / (1 - D u), with η = 2^-1073
// per product that may underflow). With w_j = e_j + 2(u + γ_D)|N_j| the
// bound is below Σ w_j |a_j| + D η, itself computed in floating point from
// non-negative terms and multiplied by (1 + 2^-40) (ErrDouble's rule for the
// bound's own roundings). |s| above it: det Λ has s's sign, which is then
// orient_d's under SoS too (a non-zero determinant is never perturbed).
// Otherwise — NaN or infinity anywhere, an overflowing sum included — sign()
// answers 0 and the
// caller asks the exact predicate. Tested against the exact predicate on
// random, near-degenerate and exactly degenerate tuples for D = 2..9
// (proptests/predicates_stages_test.cpp, "PlaneForm").
#pragma once

#include <cmath>

#include "predicates/err_double.hpp"
#include "predicates/lambda_filter.hpp"

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
    for (int j = 0; j < D; ++j) {
      ErrDouble m[(D - 1) * (D - 1) + 1];
      for (int a = 0; a < D - 1; ++a) {
        int b = 0;
        for (int c = 0; c < D; ++c)
          if (c != j) m[a * (D - 1) + b++] = rows[a * D + c];
      }
      ErrDouble minor;
      if constexpr (D - 1 <= 7) {
        minor = det_by_minors<D - 1>(m);
      } else {
        minor = det_gauss_rt(m, D - 1);
      }
      n[j] = j % 2 == 0 ? -minor.v : minor.v;
      w[j] = minor.e + 2.0 * (u + gamma) * std::fabs(minor.v);
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
};

}  // namespace flipflop::pred

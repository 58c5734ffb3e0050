// inner_ball.hpp — a ball inside a certified convex hull (D = 2: a polygon,
// D = 3: a closed triangle surface), so that the certifiers decide most points
// of full inputs without locating them.
//
// A point strictly inside the ball is strictly inside conv(S), so it lies
// strictly on the inner side of every hull edge / facet — exactly and under
// the perturbation (an infinitesimal perturbation keeps it inside) — and its
// sector or cone need not be found (10^7 ball points: 97 % of them).
//
// Set-up: a centre c (the rounded mean of the facets' vertices or the middle
// of their bounding box, whichever is farther from the facets), r2 =
// (0.999999 * min over facets of the floating distance from c)^2, a double;
// then, for every facet with outward normal n — D = 2, edge a -> b of a
// counter-clockwise polygon: n = (b.y - a.y, a.x - b.x); D = 3, triangle
// (a, b, c') counter-clockwise seen from outside: n = (b - a) x (c' - a) —
// and w = c - a, exactly (GMP rationals): -n.w > 0 and (n.w)^2 >= r2 |n|^2,
// i.e. the facet's line or plane is at distance >= sqrt(r2) on the outer side
// (zero-length / zero-area facets bound nothing and are skipped), each first
// through a floating-point filter with a proven error bound; any failure
// leaves the ball empty. These checks suffice only because the caller has
// certified that the facets bound a convex region (then it is the
// intersection of their inner half-spaces). The per-point test |p - c|^2 < r2
// is decided in floating point with room for its rounding: the computed sum
// of D <= 3 squared differences is within a relative 8u of the exact one, plus
// 3 * 2^-1000 for underflow; with r2 >= 2^-900 the test computed + 2^-990 <
// r2 (1 - 2^-40) implies the exact one. Overflow gives Inf and no decision.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "predicates/err_double.hpp"
#include "reference/certify/ball_test.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify::detail {

template <int D>
class InnerBall {
  static_assert(D == 2 || D == 3, "InnerBall: hull edges (D = 2) or facets (D = 3)");

 public:
  InnerBall() = default;
  // facets: D vertex indices each, oriented as above; the exact per-facet
  // checks run through for_range (Speedups::for_range; may be empty).
  template <class Facet, class ForRange>
  InnerBall(const PointSet& ps, const std::vector<Facet>& facets, const ForRange& for_range) {
    // the centre (any point works: the set-up verifies exactly that the ball
    // is inside): of two candidates — the mean of the facets' vertices and
    // the middle of their bounding box, rounded — the one farther from every
    // facet in floating point. The mean leans towards where vertices are
    // dense (a polygon sampled unevenly from a circle); the box middle fails
    // on skewed hulls (a right triangle's lies on its hypotenuse).
    double mean[D] = {}, lo[D], hi[D];
    for (int j = 0; j < D; ++j) lo[j] = std::numeric_limits<double>::infinity(), hi[j] = -lo[j];
    const double weight = 1.0 / (static_cast<double>(D) * static_cast<double>(facets.size()));
    for (const Facet& f : facets)
      for (int k = 0; k < D; ++k)
        for (int j = 0; j < D; ++j) {
          const double x = ps.point(f[static_cast<std::size_t>(k)])[j];
          mean[j] += x * weight;
          lo[j] = std::min(lo[j], x), hi[j] = std::max(hi[j], x);
        }
    double box[D];
    for (int j = 0; j < D; ++j) box[j] = lo[j] / 2 + hi[j] / 2;
    // the smallest floating distance from c to a facet (inner side positive)
    auto clearance = [&](const double* c) {
      double dmin = std::numeric_limits<double>::infinity();
      for (const Facet& f : facets) {
        double nn[D];
        normal<double>(ps, f, nn);
        double len2 = 0, dot = 0;
        const double* a = ps.point(f[0]);
        for (int j = 0; j < D; ++j) len2 += nn[j] * nn[j], dot += nn[j] * (c[j] - a[j]);
        const double len = std::sqrt(len2);
        if (!(len > 0)) continue;
        dmin = std::min(dmin, -dot / len);
      }
      return dmin;
    };
    const double dmean = clearance(mean), dbox = clearance(box);
    const bool use_box = dbox > dmean;  // false on NaN
    const double* sd = use_box ? box : mean;
    const double dmin = use_box ? dbox : dmean;
    for (int j = 0; j < D; ++j) test_.s[j] = sd[j];
    const double r = dmin * 0.999999;
    const double r2 = r * r;
    if (!(r > 0) || !std::isfinite(r2) || r2 < 0x1p-900) return;
    auto outside = [&](std::size_t i) {
      return !clears_filtered(ps, facets[i], sd, r2) && !clears_exact(ps, facets[i], sd, r2);
    };
    if (smallest_failing(facets.size(), for_range, outside) < facets.size()) return;  // not verified: no ball
    test_.limit = r2 * (1 - 0x1p-40);
  }

  bool strictly_inside(const double* p) const { return test_.strictly_inside(p); }

  // Whether facet f (outward normal n, vertex a, w = c - a) bounds nothing or
  // keeps the ball of centre c and squared radius r2 on its inner side:
  // n = 0, or -n.w > 0 and (n.w)^2 >= r2 |n|^2 — exactly, in rationals.
  template <class Facet>
  static bool clears_exact(const PointSet& ps, const Facet& f, const double* c, double r2) {
    mpq_class N[D];
    normal<mpq_class>(ps, f, N);
    mpq_class M = 0, Dot = 0;
    for (int j = 0; j < D; ++j) M += N[j] * N[j], Dot -= N[j] * (mpq_class(c[j]) - mpq_class(ps.point(f[0])[j]));
    if (M == 0) return true;
    return Dot > 0 && Dot * Dot >= mpq_class(r2) * M;
  }

  // The filter before clears_exact: true only when floating point with a
  // running error bound (pred::ErrDouble; every input — coordinates, c, r2 —
  // is an exact double, so the bound covers every rounding, underflow and
  // overflow, and an infinite or NaN value is never certain) proves |n|^2 > 0,
  // -n.w > 0 and (n.w)^2 - r2 |n|^2 > 0, hence clears_exact. With r =
  // 0.999999 dmin every facet clears the ball by a relative 1e-6, far above
  // the bound, so the rationals are left to degenerate facets.
  template <class Facet>
  static bool clears_filtered(const PointSet& ps, const Facet& f, const double* c, double r2) {
    pred::ErrDouble N[D];
    normal<pred::ErrDouble>(ps, f, N);
    pred::ErrDouble M(0.0), Dot(0.0);
    const double* a = ps.point(f[0]);
    for (int j = 0; j < D; ++j) M = M + N[j] * N[j], Dot = Dot - N[j] * (pred::ErrDouble(c[j]) - pred::ErrDouble(a[j]));
    return pred::sign_if_certain(M) > 0 && pred::sign_if_certain(Dot) > 0 &&
           pred::sign_if_certain(Dot * Dot - pred::ErrDouble(r2) * M) > 0;
  }
  const BallTest<D>& test() const { return test_; }

 private:
  // the outward normal of facet f (see the header), in T (double or mpq_class)
  template <class T, class Facet>
  static void normal(const PointSet& ps, const Facet& f, T* n) {
    const double *a = ps.point(f[0]), *b = ps.point(f[1]);
    if constexpr (D == 2) {
      n[0] = T(b[1]) - T(a[1]);
      n[1] = T(a[0]) - T(b[0]);
    } else {
      const double* c = ps.point(f[2]);
      const T u[3] = {T(b[0]) - T(a[0]), T(b[1]) - T(a[1]), T(b[2]) - T(a[2])};
      const T v[3] = {T(c[0]) - T(a[0]), T(c[1]) - T(a[1]), T(c[2]) - T(a[2])};
      n[0] = u[1] * v[2] - u[2] * v[1];
      n[1] = u[2] * v[0] - u[0] * v[2];
      n[2] = u[0] * v[1] - u[1] * v[0];
    }
  }

  BallTest<D> test_;  // centre and limit; limit 0: empty ball
};

}  // namespace flipflop::certify::detail

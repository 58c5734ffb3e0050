// inner_ball_test.cpp — the floating-point filter of the certifiers' inner ball
// (reference/certify/inner_ball.hpp): whenever it says a facet clears the ball,
// the exact rational test agrees.
//
// Inputs are built at the filter's edge: r2 is the facet's squared distance
// from the centre, rounded, then moved by a few ulps either way, so that the
// exact answer flips between neighbouring cases; coordinates are drawn at
// ordinary, huge (2^±900) and subnormal magnitudes.
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "reference/certify/inner_ball.hpp"

using namespace flipflop;

namespace {

template <int D>
struct Case {
  PointSet ps;
  std::array<Index, D> facet{};
  double c[D] = {};
  double r2 = 0;
};

double coordinate(int scale) {
  const double m = *rc::gen::inRange(-1000000, 1000000) / 1000.0;
  return std::ldexp(m, scale);
}

template <int D>
Case<D> edge_case() {
  Case<D> k;
  k.ps.dim = D;
  const int scale = *rc::gen::element(0, 0, 0, 900, -900, -1060);
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) k.ps.coords.push_back(coordinate(scale));
  for (int i = 0; i < D; ++i) k.facet[static_cast<std::size_t>(i)] = static_cast<Index>(i);
  for (int j = 0; j < D; ++j) k.c[j] = coordinate(scale);
  // the squared distance from c to the facet's line / plane, in floating
  // point, then a few ulps off (or a random value)
  double n[D];
  const double *a = k.ps.point(0), *b = k.ps.point(1);
  if constexpr (D == 2) {
    n[0] = b[1] - a[1], n[1] = a[0] - b[0];
  } else {
    const double* e = k.ps.point(2);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
  }
  double len2 = 0, dot = 0;
  for (int j = 0; j < D; ++j) len2 += n[j] * n[j], dot += n[j] * (k.c[j] - a[j]);
  const double d2 = dot * dot / len2;
  k.r2 = d2;
  const int ulps = *rc::gen::inRange(-4, 5);
  for (int s = 0; s < std::abs(ulps); ++s) k.r2 = std::nextafter(k.r2, ulps > 0 ? INFINITY : 0.0);
  if (*rc::gen::arbitrary<bool>()) k.r2 = std::ldexp(*rc::gen::inRange(1, 1000) / 1000.0, 2 * scale);
  return k;
}

template <int D>
void filter_implies_exact() {
  const Case<D> k = edge_case<D>();
  using Ball = certify::detail::InnerBall<D>;
  if (Ball::clears_filtered(k.ps, k.facet, k.c, k.r2)) RC_ASSERT(Ball::clears_exact(k.ps, k.facet, k.c, k.r2));
  // the centre flipped to the outer side never clears
  double far[D];
  const double* a = k.ps.point(0);
  for (int j = 0; j < D; ++j) far[j] = 2 * a[j] - k.c[j];
  if (Ball::clears_filtered(k.ps, k.facet, far, k.r2)) RC_ASSERT(Ball::clears_exact(k.ps, k.facet, far, k.r2));
}

}  // namespace

TEST_CASE("inner ball: the floating-point filter proves a facet clear only when the exact test does",
          "[certify][inner-ball]") {
  rc::prop("2D edges at the edge of the ball", [] { filter_implies_exact<2>(); });
  rc::prop("3D facets at the edge of the ball", [] { filter_implies_exact<3>(); });
}

TEST_CASE("inner ball: the filter decides facets that clear by a relative 1e-6", "[certify][inner-ball]") {
  // the set-up's radius is 0.999999 of the smallest floating distance: the
  // filter, not the rationals, must decide such facets (else it is useless)
  rc::prop("clear by 1e-6: the filter decides", [] {
    Case<3> k = edge_case<3>();
    using Ball = certify::detail::InnerBall<3>;
    RC_PRE(k.r2 > 0x1p-900 && std::isfinite(k.r2));
    // a well-shaped facet: |n| not small against |b - a| |c - a| (on a
    // nearly flat one the floating normal loses its digits and the filter
    // rightly defers to the rationals)
    const double *a = k.ps.point(0), *b = k.ps.point(1), *e = k.ps.point(2);
    double u2 = 0, v2 = 0, n2 = 0, n[3];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
    for (int j = 0; j < 3; ++j) u2 += u[j] * u[j], v2 += v[j] * v[j], n2 += n[j] * n[j];
    RC_PRE(n2 > 1e-6 * u2 * v2 && std::isfinite(u2 * v2) && u2 * v2 > 0x1p-900);
    const double r = std::sqrt(k.r2) * 0.999999;
    RC_PRE(Ball::clears_exact(k.ps, k.facet, k.c, r * r));  // c on the inner side
    RC_ASSERT(Ball::clears_filtered(k.ps, k.facet, k.c, r * r));
  });
}

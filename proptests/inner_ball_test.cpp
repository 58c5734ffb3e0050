// inner_ball_test.cpp — the floating-point filter of the certifiers' inner ball
// (reference/certify/inner_ball.hpp): whenever it says a facet clears the ball,
// the exact rational test agrees. And the inner box's verification
// (reference/certify/inner_box.hpp) against an oracle in GMP rationals: in
// 3D (every corner exactly) and in 4D..6D with plane forms (only the corners
// that can maximise a facet's orientation).
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

#include "reference/certify/certify.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/certify/inner_box.hpp"
#include "predicates/plane_form.hpp"
#include "proptests/support/mpq_det.hpp"

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

namespace {

// det[a - p; b - p; c - p] in rationals (Shewchuk's orient3d(a, b, c, p)):
// > 0 when p is below the plane in which a, b, c appear counter-clockwise,
// i.e. on the inner side of a facet (a, b, c) counter-clockwise from outside
int rational_side(const double* a, const double* b, const double* c, const double* p) {
  mpq_class m[3][3];
  for (int j = 0; j < 3; ++j) {
    m[0][j] = mpq_class(a[j]) - mpq_class(p[j]);
    m[1][j] = mpq_class(b[j]) - mpq_class(p[j]);
    m[2][j] = mpq_class(c[j]) - mpq_class(p[j]);
  }
  const mpq_class d = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(d);
}

}  // namespace

TEST_CASE("inner box: verified exactly when every corner is strictly inside every facet", "[certify][inner-box]") {
  // a tetrahedron of small integers (scaled), its facets oriented by the
  // rational oracle, and a box of halves near it: box_inside_facets must
  // agree with the oracle over the eight corners, including corners exactly
  // on a facet's plane (not strictly inside: rejected)
  rc::prop("random tetrahedra and boxes", [] {
    const int scale = *rc::gen::element(0, 0, 600, -600, -1000);
    PointSet ps;
    ps.dim = 3;
    int sum[3] = {0, 0, 0};
    for (int i = 0; i < 12; ++i) {
      const int v = *rc::gen::inRange(-16, 17);
      sum[i % 3] += v;
      ps.coords.push_back(std::ldexp(v, scale));
    }
    const double *p0 = ps.point(0), *p1 = ps.point(1), *p2 = ps.point(2), *p3 = ps.point(3);
    const int o = rational_side(p0, p1, p2, p3);
    RC_PRE(o != 0);
    // facets counter-clockwise from outside: the fourth point on the inner side
    std::vector<std::array<Index, 3>> facets;
    const Index q[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
    for (const auto& f : q) {
      const bool inner = rational_side(ps.point(f[0]), ps.point(f[1]), ps.point(f[2]), ps.point(f[3])) > 0;
      facets.push_back(inner ? std::array<Index, 3>{f[0], f[1], f[2]} : std::array<Index, 3>{f[0], f[2], f[1]});
    }
    certify::BoxTest3 box;
    for (int j = 0; j < 3; ++j) {  // around the centroid (rounded to an integer), half-extents of halves
      const int m = sum[j] / 4, a = *rc::gen::inRange(0, 4), b = *rc::gen::inRange(0, 4);
      box.lo[j] = std::ldexp(m - a / 2.0, scale), box.hi[j] = std::ldexp(m + b / 2.0, scale);
    }
    bool oracle = !box.empty();
    for (int k = 0; k < 8 && oracle; ++k) {
      double c[3];
      box.corner(k, c);
      for (const auto& f : facets)
        if (rational_side(ps.point(f[0]), ps.point(f[1]), ps.point(f[2]), c) <= 0) oracle = false;
    }
    RC_TAG(oracle ? "inside" : "not inside");
    RC_ASSERT(certify::detail::box_inside_facets(ps, facets, box, decltype(certify::Speedups{}.for_range){}) ==
              oracle);
  });
}

TEST_CASE("inner box: hand-made cases", "[certify][inner-box]") {
  // the tetrahedron (0,0,0), (4,0,0), (0,4,0), (0,0,4): inside is x, y, z > 0
  // and x + y + z < 4
  PointSet ps;
  ps.dim = 3;
  ps.coords = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4};
  const std::vector<std::array<Index, 3>> facets = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto check = [&](std::array<double, 3> lo, std::array<double, 3> hi) {
    certify::BoxTest3 b;
    for (int j = 0; j < 3; ++j) b.lo[j] = lo[static_cast<std::size_t>(j)], b.hi[j] = hi[static_cast<std::size_t>(j)];
    return certify::detail::box_inside_facets(ps, facets, b, decltype(certify::Speedups{}.for_range){});
  };
  CHECK(check({0.5, 0.5, 0.5}, {1, 1, 1}));          // corner sum 3 < 4
  CHECK(!check({0.5, 0.5, 0.5}, {1.5, 1.5, 1.0}));   // a corner on x + y + z = 4
  CHECK(!check({0, 0.5, 0.5}, {1, 1, 1}));           // a corner on x = 0
  CHECK(!check({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));   // a corner outside
  CHECK(!check({1, 1, 1}, {0.5, 0.5, 0.5}));         // empty
  CHECK(!check({0.5, 0.5, 0.5}, {1, 1, HUGE_VAL}));  // not finite
  // a facet of zero area (collinear points, as SoS hulls of degenerate input
  // have) bounds nothing: skipped
  ps.coords.insert(ps.coords.end(), {2, 0, 0});
  std::vector<std::array<Index, 3>> with_flat = facets;
  with_flat.push_back({0, 4, 1});
  certify::BoxTest3 b;
  for (int j = 0; j < 3; ++j) b.lo[j] = 0.5, b.hi[j] = 1;
  CHECK(certify::detail::box_inside_facets(ps, with_flat, b, decltype(certify::Speedups{}.for_range){}));
}

// d-dimensional boxes, the hull certifier's test (NegativeInsideFormTest: a
// facet's plane form names the signs of its normal it knows, and only the
// corners that can maximise the orientation are tested) against GMP over all
// 2^D corners: a simplex of small integers (scaled), its facets oriented with
// the opposite vertex negative by the rational oracle, a box of halves about
// its centroid; some simplices have axis-parallel facets (normal components
// exactly 0: those signs unknown, several corners tested), and some boxes
// touch a facet's plane (rejected).
namespace {
template <int D>
int q_orient(const std::vector<const double*>& rows) {  // sign det[r_1 - r_0, ..., r_D - r_0]
  std::vector<std::vector<mpq_class>> m(D, std::vector<mpq_class>(D));
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m[i][j] = mpq_class(rows[i + 1][j]) - mpq_class(rows[0][j]);
  return test::mpq_det_sign(std::move(m));
}

template <int D>
void box_property() {
  rc::prop("random " + std::to_string(D) + "D simplices and boxes", [] {
    const int scale = *rc::gen::element(0, 0, 500, -500, -1000);
    const bool axis = *rc::gen::arbitrary<bool>();
    PointSet ps;
    ps.dim = D;
    std::vector<long> sum(D, 0);
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < D; ++j) {
        // axis: the corner simplex 0, 8 e_1, ..., 8 e_D (D facets on
        // coordinate planes)
        const int v = axis ? (i == j + 1 ? 8 : 0) : *rc::gen::inRange(-16, 17);
        sum[static_cast<std::size_t>(j)] += v;
        ps.coords.push_back(std::ldexp(v, scale));
      }
    std::vector<const double*> all;
    for (int i = 0; i <= D; ++i) all.push_back(ps.point(static_cast<Index>(i)));
    RC_PRE(q_orient<D>(all) != 0);
    // facet i: every vertex but i, ordered so that vertex i is on the negative side
    std::vector<std::array<const double*, D>> facets;
    for (int i = 0; i <= D; ++i) {
      std::array<const double*, D> f{};
      int c = 0;
      for (int k = 0; k <= D; ++k)
        if (k != i) f[static_cast<std::size_t>(c++)] = ps.point(static_cast<Index>(k));
      std::vector<const double*> rows(f.begin(), f.end());
      rows.push_back(ps.point(static_cast<Index>(i)));
      // orient_d = (-1)^D det[...] (plane_form.hpp): negative wanted
      if ((D % 2 == 0 ? 1 : -1) * q_orient<D>(rows) > 0) std::swap(f[0], f[1]);
      facets.push_back(f);
    }
    certify::BoxTest<D> box;
    for (int j = 0; j < D; ++j) {  // about the centroid (rounded to an integer), half-extents of halves
      const long m = sum[static_cast<std::size_t>(j)] / (D + 1);
      const int a = *rc::gen::inRange(0, 4), b = *rc::gen::inRange(0, 4);
      box.lo[j] = std::ldexp(static_cast<double>(m) - a / 2.0, scale);
      box.hi[j] = std::ldexp(static_cast<double>(m) + b / 2.0, scale);
    }
    bool oracle = !box.empty();
    for (unsigned k = 0; k < (1u << D) && oracle; ++k) {
      double c[D];
      box.corner(k, c);
      for (const auto& f : facets) {
        std::vector<const double*> rows(f.begin(), f.end());
        rows.push_back(c);
        if ((D % 2 == 0 ? 1 : -1) * q_orient<D>(rows) >= 0) oracle = false;
      }
    }
    std::vector<pred::PlaneForm<D>> forms;
    for (const auto& f : facets) forms.emplace_back(f.data());
    RC_TAG(oracle ? "inside" : "not inside");
    RC_ASSERT(certify::detail::box_inside<D>(forms.size(), box, decltype(certify::Speedups{}.for_range){},
                                             [&](std::size_t k) {
                                               return certify::detail::NegativeInsideFormTest<D>(forms[k],
                                                                                                 facets[k].data());
                                             }) == oracle);
  });
}
}  // namespace

TEST_CASE("inner box: d-dimensional, with plane forms, verified exactly as every corner", "[certify][inner-box]") {
  box_property<4>();
  box_property<5>();
  box_property<6>();
}

TEST_CASE("inner box: a facet of zero volume is skipped, a corner on a plane rejected (4D)", "[certify][inner-box]") {
  // the simplex 0, 4 e_j in R^4: inside is x_j > 0 and Σ x_j < 4
  PointSet ps;
  ps.dim = 4;
  ps.coords = {0, 0, 0, 0, 4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 4,
               2, 0, 0, 0};  // point 5: on the edge between 0 and 1
  std::vector<std::array<Index, 4>> facets;
  for (int i = 0; i <= 4; ++i) {
    std::array<Index, 4> f{};
    int c = 0;
    for (int k = 0; k <= 4; ++k)
      if (k != i) f[static_cast<std::size_t>(c++)] = static_cast<Index>(k);
    const double* p[5] = {ps.point(f[0]), ps.point(f[1]), ps.point(f[2]), ps.point(f[3]), ps.point(static_cast<Index>(i))};
    if (pred::lambda_sign(nullptr, 5, nullptr, p, nullptr) > 0) std::swap(f[0], f[1]);
    facets.push_back(f);
  }
  const auto check = [&](const std::vector<std::array<Index, 4>>& fs, double lo, double hi, int max_free = 4) {
    std::vector<pred::PlaneForm<4>> forms;
    std::vector<std::array<const double*, 4>> rows;
    for (const auto& f : fs) {
      rows.push_back({ps.point(f[0]), ps.point(f[1]), ps.point(f[2]), ps.point(f[3])});
      forms.emplace_back(rows.back().data());
    }
    certify::BoxTest<4> b;
    for (int j = 0; j < 4; ++j) b.lo[j] = lo, b.hi[j] = hi;
    return certify::detail::box_inside<4>(
        fs.size(), b, decltype(certify::Speedups{}.for_range){},
        [&](std::size_t k) { return certify::detail::NegativeInsideFormTest<4>(forms[k], rows[k].data()); }, max_free);
  };
  CHECK(check(facets, 0.5, 0.75));   // corner sum 3 < 4
  CHECK(!check(facets, 0.5, 1.0));   // a corner on Σ x_j = 4
  CHECK(!check(facets, 0.0, 0.75));  // corners on x_j = 0
  CHECK(!check(facets, 0.5, 1.5));   // a corner outside
  std::vector<std::array<Index, 4>> with_flat = facets;
  with_flat.push_back({0, 5, 1, 2});  // 0, 5, 1 on one line: zero volume
  CHECK(check(with_flat, 0.5, 0.75));
  // more than 2^max_free corners to test (the flat facet knows no sign, a
  // facet on a coordinate plane one): rejected, never wrongly accepted
  CHECK(check(facets, 0.5, 0.75, 3));
  CHECK(!check(with_flat, 0.5, 0.75, 3));
}

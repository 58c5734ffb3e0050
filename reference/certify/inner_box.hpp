// inner_box.hpp — an axis-aligned box inside a certified convex hull in R^D,
// the companion of inner_ball.hpp for inputs that fill a box rather than a
// ball (10^6 uniform cube points in 3D: the inner ball holds 52 % of them, a
// box inside the hull about 95 %). The 3D certifiers (kernels_cpu/hull3) and
// the d-dimensional hull's certifier (kernels_cpu/rtd/hull_d.cpp) use it.
//
// A point strictly inside the box (lo < p < hi in every coordinate, exact
// comparisons of doubles) is strictly inside conv(S) when the box is: it is
// then strictly on the inner side of every hull facet, exactly and under the
// perturbation (an infinitesimal perturbation keeps it inside), and needs no
// cone, record or walk.
//
// Verification (box_inside): the box is the convex hull of its 2^D corners;
// each corner strictly on the inner side of a facet's plane (the orientation
// of the facet's D points and the corner, exact and unperturbed: the corners
// are not input points) puts the whole closed box strictly on that side.
// Every facet checked so puts the box strictly inside the intersection of the
// inner half-spaces — which is the hull only because the caller has certified
// that the facets bound a convex region (certify_hull3_surface.hpp,
// convex_surface.hpp), as for the inner ball. A facet of zero volume (D
// affinely dependent points, which SoS hulls of degenerate input have) bounds
// nothing and is skipped, as the ball skips it: its orientation is 0
// everywhere, and it is the one facet that gives 0 at the D + 1 affinely
// independent corners 0 and 2^j (the orientation is affine in the corner).
// Which corners need a test: the orientation is an affine function
// N . x + c of the corner x, largest on the box at the corner that takes hi
// where N_j > 0 and lo where N_j < 0; a facet test that knows the signs of
// some N_j (a plane form's coefficients beyond their error bound,
// plane_form.hpp) names them, and only the corners that agree with them are
// tested — one corner where every sign is known, all 2^D where none is (the
// 3D certifiers: eight orient3d_exact calls). Where the box comes from does
// not matter (kernels_cpu/hull3 proposes one from the extreme points of the
// input, ffhull.cpp: inner_region; hull_d.cpp the largest scaled bounding box
// around the vertices' mean that floating point puts inside the facets).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "predicates/err_double.hpp"  // FF_HD
#include "predicates/plane_form.hpp"
#include "predicates/predicates.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify {

template <int D>
struct BoxTest {
  // empty by default: no point is strictly inside
  double lo[D], hi[D];
  BoxTest() {
    for (int j = 0; j < D; ++j) lo[j] = HUGE_VAL, hi[j] = -HUGE_VAL;
  }

  bool empty() const {
    for (int j = 0; j < D; ++j)
      if (!(lo[j] < hi[j])) return true;
    return false;
  }
  // corner k: bit j of k picks hi (1) or lo (0) in coordinate j
  void corner(unsigned k, double* c) const {
    for (int j = 0; j < D; ++j) c[j] = ((k >> j) & 1u) ? hi[j] : lo[j];
  }
  FF_HD bool strictly_inside(const double* p) const {
    bool in = true;
    for (int j = 0; j < D; ++j) in = in && lo[j] < p[j] && p[j] < hi[j];
    return in;
  }
};
using BoxTest3 = BoxTest<3>;

namespace detail {

// Whether the (non-empty, finite) box lies strictly on the inner side of
// every facet 0..facets-1 of non-zero volume. test_of(i) gives facet i's
// test: an object with `unsigned known` (the coordinates j whose N_j sign it
// knows, a bit each), `unsigned high` (of those, the bits of the corner that
// maximises the orientation: N_j > 0) and `int inner(const double* corner)`
// (exact and unperturbed: > 0 strictly on the inner side, 0 on the plane,
// < 0 beyond). Facets run through for_range (Speedups::for_range; may be
// empty: sequential). A facet whose test knows fewer than D - max_free signs
// (more than 2^max_free corners to test: a flat facet in high dimension)
// counts as failed — the box is rejected, never wrongly accepted.
template <int D, class TestOf, class ForRange>
bool box_inside(std::size_t facets, const BoxTest<D>& box, const ForRange& for_range, const TestOf& test_of,
                int max_free = D) {
  static_assert(D >= 2 && D <= 16, "box_inside: 2 <= D <= 16");
  if (box.empty()) return false;
  for (int j = 0; j < D; ++j)
    if (!std::isfinite(box.lo[j]) || !std::isfinite(box.hi[j])) return false;
  constexpr unsigned kAll = (1u << D) - 1;
  const auto fails = [&](std::size_t i) {
    const auto t = test_of(i);
    const unsigned free = kAll & ~t.known, high = t.high & t.known;
    if (__builtin_popcount(free) > max_free) return true;
    bool zero = false;
    double c[D];
    // every corner that agrees with the known signs: the subsets of `free`
    for (unsigned sub = free;; sub = (sub - 1) & free) {
      box.corner(high | sub, c);
      const int o = t.inner(c);
      if (o < 0) return true;
      zero = zero || o == 0;
      if (sub == 0) break;
    }
    if (!zero) return false;
    // a corner on the plane fails, unless the facet has zero volume: 0 at
    // corner 0 and at every corner 2^j (D + 1 affinely independent points)
    box.corner(0, c);
    if (t.inner(c) != 0) return true;
    for (int j = 0; j < D; ++j) {
      box.corner(1u << j, c);
      if (t.inner(c) != 0) return true;
    }
    return false;
  };
  return smallest_failing(facets, for_range, fails) == facets;
}

// box_inside's test of a facet of a d-dimensional hull whose facets are
// oriented with the inside negative (orient_d(t, x) < 0, hull_d.hpp's
// convention), from its plane form f (plane_form.hpp) and its D points t (in
// f's order): N_j's sign is known where |n_j| > w_j (w_j bounds the error of
// n_j), and the orientation is largest at hi where N_j > 0; a corner's sign
// from the form, the exact unperturbed predicate where the form is undecided.
template <int D>
struct NegativeInsideFormTest {
  unsigned known = 0, high = 0;
  const pred::PlaneForm<D>* form = nullptr;
  const double* rows[D] = {};
  NegativeInsideFormTest(const pred::PlaneForm<D>& f, const double* const* t) : form(&f) {
    for (int c = 0; c < D; ++c) {
      rows[c] = t[c];
      if (std::fabs(f.n[c]) > f.w[c]) {
        known |= 1u << c;
        if (f.n[c] > 0.0) high |= 1u << c;
      }
    }
  }
  int inner(const double* x) const {
    if (const int s = form->sign(x)) return -s;
    const double* p[D + 1];
    for (int c = 0; c < D; ++c) p[c] = rows[c];
    p[D] = x;
    return -pred::lambda_sign(nullptr, D + 1, nullptr, p, nullptr);
  }
};

// The 3D certifiers' form: facets (a, b, c) counter-clockwise seen from
// outside, orient3d(a, b, c, corner) > 0 inside; every corner tested.
template <class Facet, class ForRange>
bool box_inside_facets(const PointSet& ps, const std::vector<Facet>& facets, const BoxTest3& box,
                       const ForRange& for_range) {
  struct Test {
    unsigned known = 0, high = 0;
    const double *a, *b, *d;
    int inner(const double* c) const { return pred::orient3d_exact(a, b, d, c); }
  };
  return box_inside<3>(facets.size(), box, for_range, [&](std::size_t i) {
    const Facet& f = facets[i];
    return Test{0, 0, ps.point(f[0]), ps.point(f[1]), ps.point(f[2])};
  });
}

}  // namespace detail
}  // namespace flipflop::certify

// inner_box.hpp — an axis-aligned box inside a certified convex 3D hull, the
// companion of inner_ball.hpp for inputs that fill a box rather than a ball
// (10^6 uniform cube points: the inner ball holds 52 % of them, a box inside
// the hull about 95 %).
//
// A point strictly inside the box (lo < p < hi in every coordinate, exact
// comparisons of doubles) is strictly inside conv(S) when the box is: it is
// then strictly on the inner side of every hull facet, exactly and under the
// perturbation (an infinitesimal perturbation keeps it inside), and needs no
// cone, record or walk.
//
// Verification (box_inside_facets): the box is the convex hull of its eight
// corners; each corner strictly on the inner side of a facet's plane
// (orient3d(a, b, c, corner) > 0, exact and unperturbed: the corners are not
// input points) puts the whole closed box strictly on that side. Every facet
// checked so puts the box strictly inside the intersection of the inner
// half-spaces — which is the hull only because the caller has certified that
// the facets bound a convex region (certify_hull3_surface.hpp), as for the
// inner ball. A facet of zero area (three collinear points, which SoS hulls of
// degenerate input have) bounds nothing and is skipped, as the ball skips it:
// it is the one facet that gives 0 at all eight corners. Where the box comes
// from does not matter (kernels_cpu/hull3 proposes one from the extreme points
// of the input, ffhull.cpp: inner_region).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "predicates/err_double.hpp"  // FF_HD
#include "predicates/predicates.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify {

struct BoxTest3 {
  // empty by default: no point is strictly inside
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  bool empty() const { return !(lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2]); }
  // corner k: bit j of k picks hi (1) or lo (0) in coordinate j
  void corner(int k, double* c) const {
    for (int j = 0; j < 3; ++j) c[j] = ((k >> j) & 1) ? hi[j] : lo[j];
  }
  FF_HD bool strictly_inside(const double* p) const {
    return lo[0] < p[0] && p[0] < hi[0] && lo[1] < p[1] && p[1] < hi[1] && lo[2] < p[2] && p[2] < hi[2];
  }
};

namespace detail {

// Whether every corner of the (non-empty, finite) box lies strictly on the
// inner side of every facet (a, b, c) of non-zero area, counter-clockwise
// seen from outside: orient3d(a, b, c, corner) > 0 exactly. Facets run
// through for_range (Speedups::for_range; may be empty: sequential).
template <class Facet, class ForRange>
bool box_inside_facets(const PointSet& ps, const std::vector<Facet>& facets, const BoxTest3& box,
                       const ForRange& for_range) {
  if (box.empty()) return false;
  double c[8][3];
  for (int k = 0; k < 8; ++k) {
    box.corner(k, c[k]);
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(c[k][j])) return false;
  }
  const auto fails = [&](std::size_t i) {
    const Facet& f = facets[i];
    const double *a = ps.point(f[0]), *b = ps.point(f[1]), *d = ps.point(f[2]);
    int zeros = 0;
    for (int k = 0; k < 8; ++k) {
      const int o = pred::orient3d_exact(a, b, d, c[k]);
      if (o < 0) return true;
      zeros += o == 0;
    }
    // a corner on the plane fails, unless all eight are: then a, b, d are
    // collinear (a non-empty box's corners span R^3, so no plane holds them
    // all) and the facet bounds nothing
    return zeros > 0 && zeros < 8;
  };
  return smallest_failing(facets.size(), for_range, fails) == facets.size();
}

}  // namespace detail
}  // namespace flipflop::certify

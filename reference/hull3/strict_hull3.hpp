// strict_hull3.hpp — the strict view of a 3D hull: strictly extreme points
// and polygonal facets, as users of Qhull and CGAL expect them (thesis §6.4.2
// discusses degenerate input; DESIGN.md "Canonical output" fixes the SoS
// triangulation, this view removes what the perturbation decided).
//
// The canonical SoS hull (brute::hull3, every backend) triangulates exactly
// coplanar facets in a perturbation-dependent way and may keep, as vertices,
// points that lie on a hull edge or inside a hull facet, or several copies
// of one location. The strict view keeps only what does not depend on the
// perturbation:
//
//   * extreme_points — the locations that are vertices of the exact hull
//     (strictly extreme: some plane meets the input in that location only),
//     each reported by the SMALLEST input index holding it (the choice of
//     peers::cgal_extreme_points_3, which maps CGAL's points back to the
//     smallest index at their location); sorted;
//   * facets — the facets of the exact hull, each the convex polygon of its
//     strictly extreme vertices (same indices), counter-clockwise seen from
//     outside, rotated to start at its smallest index; the list sorted.
//
// How (strict_hull3.cpp): map every hull vertex to the smallest index at
// its location; a triangle whose three locations are collinear (or
// repeated) is degenerate. Every non-degenerate SoS triangle lies in the
// plane of one exact facet (in the limit of the perturbation the SoS hull is
// the exact hull's boundary, tiled by its triangles), so the facets are the
// classes of non-degenerate triangles under "exactly coplanar":
//   1. union across every edge whose two triangles are non-degenerate and
//      exactly coplanar (orient3d_exact == 0);
//   2. a facet split into several such classes is tiled by them and can only
//      be split along edges whose other triangle is degenerate (a
//      non-degenerate triangle across an edge that runs through the facet's
//      relative interior lies in the facet's plane); so only classes that
//      touch a degenerate triangle may be incomplete, and those are merged by
//      an exact key of their plane (normal and offset as coprime integers);
//   3. a location is strictly extreme iff it lies in at least three facets
//      (a vertex of a 3-polytope is in >= 3 facets, a point inside an edge in
//      2, inside a facet in 1); a facet's polygon is its strictly extreme
//      locations, ordered counter-clockwise by orient3d_exact against a hull
//      point off its plane.
// All tests are exact (predicates.hpp *_exact, GMP for the plane keys).
#pragma once

#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::ref {

struct StrictHull3 {
  std::vector<Index> extreme_points;         // sorted
  std::vector<std::vector<Index>> facets;    // polygons (see above), sorted

  bool operator==(const StrictHull3& o) const { return extreme_points == o.extreme_points && facets == o.facets; }
};

// The strict view of `canonical_hull`, any correct SoS hull of ps (e.g.
// brute::hull3, hull3_splay), triangles counter-clockwise seen from outside.
// Throws std::invalid_argument for ps.dim != 3, an index out of range or a
// triangle list that is not a closed oriented surface.
StrictHull3 strict_hull3(const PointSet& ps, const std::vector<Triangle>& canonical_hull);

// The strict view with every facet polygon fan-triangulated from its first
// (smallest) vertex: triangles (f0, fj, fj+1), counter-clockwise seen from
// outside and starting at their smallest index like the polygon, the list
// sorted (`hull3 --strict --triangulate`, the triangle mesh of Qhull's `Qt`
// users). No triangle has zero area: a polygon's vertices are strictly
// extreme, so no three of them are collinear (three collinear vertices of a
// convex polygon would put the middle one inside an edge of the exact hull).
// Each polygon's area is kept: a fan covers its convex polygon once.
StrictHull3 fan_triangulated(const StrictHull3& h);

// Text form (deterministic), for the CLI:
//   line 1:           "E F"  — the number of extreme points and of facets
//   next E lines:     one extreme point index each, increasing
//   next F lines:     one facet each: its vertex indices separated by single
//                     spaces, counter-clockwise seen from outside, starting
//                     at the smallest; the lines in sorted (lexicographic
//                     index) order
// Every line ends with '\n'.
std::string format_strict_hull3(const StrictHull3& h);

}  // namespace flipflop::ref

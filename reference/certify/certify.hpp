// certify.hpp — exact certification of convex hulls and regular triangulations.
//
// The certifier decides, with exact predicates, whether an index output is the
// right answer for a point set. It accepts outputs of any program (flipflop's
// backends, Qhull, CGAL) and names the first violated condition.
//
// Two levels:
//   Level::exact      — is the output *a* correct hull / regular triangulation
//                       of the exact input? Degeneracies are tolerated as a
//                       demanding user would: points on a hull edge or facet
//                       may or may not be vertices; cocircular edges may go
//                       either way; duplicate points may be represented once.
//   Level::canonical  — is it *the* answer under flipflop's Simulation of
//                       Simplicity (predicates.hpp), in canonical form
//                       (DESIGN.md)? This is what every backend must produce.
//
// The local-to-global theorems that make the checks sufficient:
//   hull2 — a closed polygon whose every turn is convex and which winds once is
//           convex; with every point on the inner side of its edges it is the
//           hull boundary.
//   hull3 — thesis Lemma 6.1 / Thm 6.2: a polyhedron star-shaped w.r.t. an
//           interior point s whose edges are all convex is convex. Star-
//           shapedness is certified by: every facet faces away from s, and the
//           central projection from s winds exactly once around every vertex
//           (then the projection onto the sphere is an unbranched covering of
//           degree 1). s is the exact centroid of four affinely independent
//           hull vertices (thesis §6.4.2: never a rounded point).
//   rt2   — thesis Thm 2.2 [ES92]: a triangulation of conv(S) whose edges are
//           all locally regular is the regular triangulation of its vertices;
//           with every missing point redundant (its lifted point on or above
//           the lifted triangle containing it) it is RT(S ⊕ W).
//
// Structural checks (orientation, winding, point location) use the Simulation
// of Simplicity at both levels, so that flat triangles that the perturbation
// legitimately creates on degenerate input are handled consistently; the
// geometric conditions (convexity, containment, regularity, redundancy) are
// exact and non-strict at Level::exact and perturbed and strict at
// Level::canonical.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::pred {
class StaticFilter;
}

namespace flipflop::certify {

enum class Level { exact, canonical };

struct Report {
  bool ok = true;
  std::string condition;  // short name of the first violated condition
  std::string detail;     // what exactly is wrong, with indices

  static Report pass() { return {}; }
  static Report fail(std::string condition, std::string detail) {
    return {false, std::move(condition), std::move(detail)};
  }
  std::string message() const { return ok ? "certified" : condition + ": " + detail; }
};

// 2D hull: vertex indices in counter-clockwise order.
Report hull2(const PointSet& ps, const std::vector<Index>& cycle, Level level = Level::exact);

// Ways to certify faster that never change the verdict or its message (the
// multithreaded backends pass them, kernels_cpu/hull2/certify_hull2.hpp):
//   filter     a per-input static filter valid for every coordinate of ps
//              (predicates/static_filter.hpp), tried before every predicate;
//              for rt2 also for every weight of ps;
//   for_range  runs body(lo, hi) over pieces covering [0, n), in any order,
//              possibly at once; the per-point checks run through it (the
//              first failing point, in index order, is still the one reported);
//   make_filter  builds the per-input static filter of ps' coordinates (and
//              weights, when ps has them) and `extra` further values (an
//              auxiliary point of the certifier), e.g. by a parallel scan;
//              certifiers that need such a filter call it instead of their
//              own sequential scan.
struct Speedups {
  const pred::StaticFilter* filter = nullptr;
  std::function<void(std::size_t n, const std::function<void(std::size_t lo, std::size_t hi)>& body)> for_range;
  std::function<pred::StaticFilter(const std::vector<double>& extra)> make_filter;
};
Report hull2(const PointSet& ps, const std::vector<Index>& cycle, Level level, const Speedups& speedups);

// 3D hull: triangles counter-clockwise seen from outside.
Report hull3(const PointSet& ps, const std::vector<Triangle>& tris, Level level = Level::exact);
// The same verdict and message, the per-facet and per-point checks through
// speedups.for_range, the static filter from speedups.make_filter
// (kernels_cpu/hull3/certify_hull3.hpp).
Report hull3(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups);

// 2D regular triangulation (weights from ps; a Delaunay triangulation when
// ps is unweighted): counter-clockwise triangles.
Report rt2(const PointSet& ps, const std::vector<Triangle>& tris, Level level = Level::exact);
// The same verdict and message, the per-triangle, per-vertex and per-point
// checks and the tables they use built through speedups.for_range, the static
// filter from speedups.filter or make_filter (kernels_cpu/rt2/certify_rt2.hpp).
Report rt2(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups);

// The strict view of a 2D regular triangulation (reference/rt2/strict_rt2.hpp):
// condition `zero-area` — every triangle counter-clockwise with non-zero area
// (exact orient2d > 0) — then rt2 at Level::exact. With no flat triangle the
// perturbed structural checks of rt2 coincide with the exact ones, so this
// certifies a regular triangulation of the exact input without zero-area
// triangles: weakly regular edges (Thm 2.2), every missing point weakly
// redundant (so every point that is not redundant in the exact sense is a
// vertex).
Report rt2_strict(const PointSet& ps, const std::vector<Triangle>& tris);

// The strict view of a 3D hull (reference/hull3/strict_hull3.hpp, `hull3
// --strict`): `extreme` the strictly extreme points (increasing, the
// smallest index at each location), `facets` convex polygons counter-
// clockwise seen from outside, no two adjacent ones coplanar; with
// `triangulated` (`--strict --triangulate`) the facets are triangles of
// non-zero area and adjacent ones may be coplanar. Conditions in
// certify_hull3_strict.cpp (strict-indices, smallest-index, facet-polygon,
// hull3's conditions on the fan triangles at Level::exact, strictly-extreme,
// maximal-facets). Independent of the algorithm: any program's strict hull
// in this form can be checked.
Report hull3_strict(const PointSet& ps, const std::vector<Index>& extreme,
                    const std::vector<std::vector<Index>>& facets, bool triangulated);

}  // namespace flipflop::certify

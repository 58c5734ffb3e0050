// certify_rtd.hpp — exact certification of a d-dimensional regular
// triangulation RT(S ⊕ W) (2 <= d <= 5) at the canonical level: is the
// output THE answer under flipflop's Simulation of Simplicity (predicates.hpp),
// in canonical form (canonical_d.hpp)? Accepts any program's output.
//
// Conditions, in order (the first violated one is reported):
//   input-dimension          ps.dim in 2..9 and the points span R^d
//   simplex-indices          d+1 distinct in-range indices per simplex, at
//                            least one simplex
//   canonical-form           every tuple canonical, the list sorted, no repeats
//   simplex-orientation      every simplex positive in the volume convention
//                            (det[p_1 - p_0, ..., p_d - p_0] > 0 under SoS;
//                            canonical_d.hpp)
//   facet-manifold           every facet (d-1 face) lies in one or two
//                            simplices; when in two, they induce opposite
//                            orientations on it (they lie on its two sides)
//   boundary-is-hull         the boundary facets (in one simplex), each on the
//                            inner side of its simplex, have every boundary
//                            vertex not on them strictly on their inner side
//   locally-regular          every interior facet is locally regular (Thm 2.2):
//                            power_d(C1, b) < 0 — b's lifted point strictly
//                            above the lifted C1
//   missing-point-redundant  every input point that is not a vertex lies
//                            strictly inside a simplex (SoS) whose lifted
//                            hyperplane passes strictly below its lifted point
//
// Why these suffice (the local-to-global argument, in the perturbed
// configuration, which is a real configuration in general position):
//  1. Tiling. Let C be the chain of all simplices with their (positive)
//     orientations. The facet-manifold condition makes interior facets
//     cancel in ∂C, so ∂C = B, the boundary facets with their induced
//     orientation. For a point y off all facets, the number of simplices
//     containing y is Σ_σ wind(∂σ, y) = wind(B, y) (every simplex is positive).
//     Let P be the intersection of the inner half-spaces of the facets of B.
//     boundary-is-hull puts every vertex of B in P, so every facet of B lies
//     on ∂P, outward. A non-zero (d-1)-cycle on ∂P forces P bounded, and then
//     B = m[∂P] with m the number of facets of B covering a generic point of
//     ∂P. Such a point y in the relative interior of a facet f of B has a
//     unique supporting hyperplane, so every facet of B through y lies in the
//     hyperplane of f; all its vertices are then vertices of f (the others are
//     STRICTLY inside), so it is f itself: m = 1. Hence every point of P lies
//     in exactly one simplex and no point outside P lies in any: the simplices
//     tile P = conv(vertices of B), and every vertex of a simplex lies in P.
//  2. Hull. Every input point is a vertex (in P) or, by the last condition,
//     inside a simplex (in P): P = conv(S). So the simplices form a
//     triangulation of conv(S) (thesis §2.1).
//  3. Regularity. Theorem 2.2 [ES92] (thesis §2.2): "A triangulation with its
//     weighted vertex set S ⊕ W in R^d is RT(S ⊕ W) if and only if all its
//     ridges are locally regular": the lifted triangulation is then locally
//     convex at every interior ridge, hence (a locally convex piecewise-linear
//     function on a convex domain is convex) the lower hull of the lifted
//     vertices. Under SoS the comparison is strict, so it is THE regular
//     triangulation of its vertex set.
//  4. Redundancy. A missing point whose lifted point lies strictly above the
//     lifted simplex containing it lies strictly above the lower hull (which
//     is that convex function), so it is redundant: the triangulation is
//     RT(S ⊕ W), the unique lower hull of all perturbed lifted points.
// The boundary in linear time (reference/rtd/convex_surface.hpp; Level::canonical, with a vertex v of the
// simplices that is not a boundary vertex, or the auxiliary point below):
// boundary-is-hull is then established
// by three checks whose cost is linear in |B| instead of testing every
// boundary vertex against every boundary facet:
//   (a) every ridge of B lies in exactly two facets of B, and each of the
//       two has its vertex off the ridge strictly on the inner side of the
//       other (B is a closed surface, convex at every ridge);
//   (b) v lies strictly on the inner side of every facet of B;
//   (c) the vertical ray up from v (the last coordinate growing) crosses
//       exactly one facet of B: a facet f (vertices f_0..f_{d-1}) is crossed
//       iff the projection of v to the first d-1 coordinates lies strictly in
//       f's projection and f passes strictly above v; since det Λ(f, v) is
//       affine in v's last coordinate with slope -orient_{d-1}(f projected),
//       "above" is sign orient_d(f, v) = sign orient_{d-1}(f projected).
//       Projections are predicates on a prefix of the columns, so they are
//       signs of the same perturbed configuration (predicates.hpp).
// Why they suffice: by (b) the central projection from v maps every facet
// of B onto the sphere around v preserving orientation, so its degree is the
// number of facets over any regular value — by (c), 1 — and every direction
// from v meets B exactly once: B is an embedded surface star-shaped from v.
// A compact region bounded by an embedded polyhedral surface that is convex
// at every ridge is locally convex at every boundary point (at a face of
// lower dimension its link is again such a surface, one dimension lower, by
// induction), hence convex (Tietze–Nakajima). Every vertex of B is then in
// the closed region and, the configuration being in general position under
// SoS, strictly inside every facet it is not on: the condition of 1. holds.
// (The degree check is what (a) and (b) cannot replace: a boundary winding
// twice around v — a branched double cover — is convex at every ridge.)
// When every vertex is a boundary vertex, v is an auxiliary point: the
// boundary vertices' average rounded to doubles, with the SoS index n after
// every input (predicates.hpp, "Points that are not inputs"; the argument is
// the same for any point of the perturbed configuration), used when (b)
// holds for it. Otherwise, and at Level::exact, the quadratic test runs
// (each pair first through a floating-point filter of the facet's affine
// orientation form, certify_rtd.cpp FacetForm).
// Cost: O(|B|) orient_d for the hull condition (O(|B-vertices| · |B|)
// without an interior vertex), O(#simplices) power_d, and a visibility walk
// per missing point.
#pragma once

#include <string>
#include <cstdint>
#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify {

// Level::canonical (the default): flipflop's unique answer, conditions above.
// Level::exact: *a* regular triangulation of the exact input, any program's,
// any tie-breaking (CGAL's on degenerate input): no canonical form; every
// simplex of strictly positive volume (exact, no perturbation: a zero-volume
// simplex, which flipflop's canonical answer may hold on degenerate input,
// is refused — that answer is certified at the canonical level); facet-
// manifold; every boundary vertex on the inner side (weakly) of every
// boundary facet; every interior facet weakly locally regular (the lifted
// opposite vertex on or above); every missing point in a simplex (closed)
// with its lifted point on or above it; and covers-hull-once: the exact
// total volume of the simplices equals that of conv(P) (from the canonical
// answer, certified first).
// Why: as in 1. above, the simplices cover the polytope Q cut out by the
// boundary facets' half-spaces k >= 1 times (every boundary vertex is in Q,
// so the boundary cycle lies on ∂Q and the covering number is constant
// inside); the missing points lie in simplices and the vertices are input
// points, so Q = conv(P); the volumes give k = 1. The lifted piecewise-
// linear function is then convex (weakly regular facets) and interpolates
// the lifted vertices with every other lifted point on or above it: it is
// the lower hull (Thm 2.2, weak form), i.e. a regular triangulation.
//
// furthest: the furthest-site triangulation (ref::rtd_incremental's
// `furthest`): the same conditions with every power_d sign negated — the lower
// hull of the negated lifted heights, i.e. the upper hull of the lifted points;
// the argument above holds for any heights.
Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices, Level level = Level::canonical,
           bool furthest = false);
// The same verdict and message, the per-simplex checks (orientation, the
// facet table, local regularity), the quadratic boundary test's facets and
// the missing points' walks through speedups.for_range (certify.hpp;
// kernels_cpu/rtd/certify_rtd.hpp runs them on oneTBB).
Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices, Level level, bool furthest,
           const Speedups& speedups);
// The same, and where the verdict is "certified" and `neighbors` is given,
// *neighbors = the facet table the certificate matched (condition
// facet-manifold): (d + 1) entries per simplex, entry i the simplex across
// the facet opposite simplices[s][i], -1 on the boundary (scipy's
// Delaunay.neighbors); left unchanged otherwise.
Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices, Level level, bool furthest,
           const Speedups& speedups, std::vector<std::int64_t>* neighbors);

namespace rtd_detail {
// The structural part (conditions simplex-indices, simplex-orientation,
// facet-manifold, boundary-is-hull on the vertices of the simplices; no
// canonical form, no regularity): empty when the simplices — given POSITIVELY
// ORIENTED in the predicates' convention (Orientation::orient_d, as the
// algorithms hold them) — tile the convex hull of their vertices, otherwise the condition
// and what is wrong. Used by rtd::from_simplices.
std::string tiling_problem(const PointSet& ps, const std::vector<std::vector<Index>>& positive_simplices);
}  // namespace rtd_detail

}  // namespace flipflop::certify

namespace flipflop::ref {
// The brief's name: certify_rtd(ps, simplices) == certify::rtd(ps, simplices).
inline certify::Report certify_rtd(const PointSet& ps, const std::vector<std::vector<Index>>& simplices) {
  return certify::rtd(ps, simplices);
}
}  // namespace flipflop::ref

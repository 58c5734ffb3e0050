// certify_hull3.hpp — the exact certifiers of a 3D hull on oneTBB.
//
// cpu::certify_hull3: the witness-free certifier (reference/certify,
// certify::hull3) with its per-facet and per-point checks split over oneTBB
// tasks and the input's static filter from a parallel scan. It needs nothing
// from the algorithm that produced the hull, so it serves third-party outputs
// (`flipflop certify hull3`, e.g. Qhull's facets). The verdict and its message
// are the sequential certifier's (certify.hpp, Speedups: the smallest failing
// facet or point is reported).
//
// cpu::certify_hull3_witnessed: the output of the multithreaded ffHull
// (ffhull.hpp) with the kernel's witness (hull3_witness.hpp): the same
// per-facet and per-edge checks, then per point a constant number of exact
// SoS predicates instead of a walk. Conditions, in order:
//   witness-size          one witness entry per input point
//   witness-output        the output is the facet set the witness is about
//   witness-interior-point  s's four points are input indices, distinct and
//                        affinely independent (exact orient3d != 0)
//   input-dimension .. convex-edge   certify::hull3's (certify_hull3.cpp), with
//                        s the centroid of the witness' four points
//   witness-facet        every non-vertex names a facet in range, or none when
//                        strictly inside the exactly verified inner ball
//   witness-cone         the named facet's cone from s contains the point
//                        (three perturbed orient3d with s)
//   point-inside         the point is beneath the named facet (one orient3d:
//                        perturbed and strict at the canonical level, exact
//                        and non-strict at the exact level)
// Why this proves the output is the hull (thesis Lemma 6.1, Thm 6.2): s is
// strictly inside the tetrahedron of four input points, hence strictly inside
// conv(S). facet-orientation and star-shaped make the surface star-shaped
// w.r.t. s: every facet F faces away from s, the central projection from s
// is a bijection onto the sphere, so the cones C_s(F) (closed, perturbed: no
// point lies on two of them) tile R^3 and the polytope bounded by the surface
// is P = union of the tetrahedra conv(s, F). convex-edge then makes P convex
// (Thm 6.2), with input points as vertices: P ⊆ conv(S). A point p in C_s(F)
// on the inner side of F's plane lies in C_s(F) ∩ {inner half-space of F} =
// conv(s, F) ⊆ P (s is on the inner side, facet-orientation); a point strictly
// inside the inner ball lies in P (the ball is verified inside every facet's
// inner half-space, and P, convex, is their intersection); a vertex is in P.
// So S ⊆ P, conv(S) ⊆ P, and P = conv(S). At the canonical level the point
// tests are strict under the perturbation, so no non-vertex is extreme, and
// with strictly convex edges every vertex is: the output is the SoS hull, in
// canonical form (canonical-form). At the exact level the signs are exact and
// non-strict (a perturbed sign > 0 implies an exact one >= 0, so the closed
// cones still cover p): a correct hull of the exact input.
#pragma once

#include <vector>

#include "kernels_cpu/hull3/hull3_witness.hpp"
#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
certify::Report certify_hull3(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                              int threads = 0);

certify::Report certify_hull3_witnessed(const PointSet& ps, const std::vector<Triangle>& tris,
                                        certify::Level level, const Hull3Witness& witness, int threads = 0);

}  // namespace flipflop::cpu

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
//   witness-size          one witness entry per input point (and one record
//                        entry, or no records at all)
//   witness-output        the output is the facet set the witness is about
//   witness-interior-point  s's four points are input indices, distinct and
//                        affinely independent (exact orient3d != 0)
//   input-dimension .. convex-edge   certify::hull3's (certify_hull3.cpp), with
//                        s the centroid of the witness' four points
// then per non-vertex p, by the certificate it carries:
//   witness-tetrahedron  (no facet, a record: an index into the witness'
//                        triangles `made`, which must exist, naming (a, b, c)) a, b, c are input
//                        indices, distinct and not p; none of them has a
//                        record itself; p is not one of s's four points; and
//                        p is strictly inside the tetrahedron (s, a, b, c)
//                        under the perturbation: orient3d(s, x, y, p) < 0 for
//                        the edges (x, y) of (a, b, c) (p in the cone) and
//                        orient3d(a, b, c, p) > 0 (p on the inner side) —
//                        four perturbed orient3d, at both levels, as many as
//                        for a facet
//   witness-facet        (neither) strictly inside the exactly verified inner
//                        ball, or strictly inside the witness' box when that
//                        box is verified exactly against every facet (all
//                        eight corners strictly on the inner side:
//                        reference/certify/inner_box.hpp); (a facet) the
//                        facet index is in range
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
// inside the inner ball or the verified box lies in P (ball and box are
// verified inside every facet's inner half-space, and P, convex, is their
// intersection); a vertex is in P.
// So S ⊆ P, conv(S) ⊆ P, and P = conv(S). At the canonical level the point
// tests are strict under the perturbation, so no non-vertex is extreme, and
// with strictly convex edges every vertex is: the output is the SoS hull, in
// canonical form (canonical-form). At the exact level the signs are exact and
// non-strict (a perturbed sign > 0 implies an exact one >= 0, so the closed
// cones still cover p): a correct hull of the exact input.
// The records (the kernel's early removals, thesis §6.4 Algorithm 7 line 14)
// fit the same argument. Call a point anchored when it is a vertex, has a
// facet, or lies strictly inside the ball or the verified box: by the above an anchored point is
// in P (at the canonical level, in P's interior unless a vertex). s is in P:
// it is strictly inside the tetrahedron of its four points, which carry no
// record (checked), hence are anchored. A record's corners a, b, c carry no
// record (checked), so they are anchored too. The four signs of a record put
// the perturbed p strictly inside the perturbed tetrahedron (s, a, b, c):
// let o = orient3d(a, b, c, s), nonzero under the perturbation, so that
// a - s, b - s, c - s are a basis and p = s + la (a - s) + lb (b - s) +
// lc (c - s). orient3d(s, a, b, .) is linear in the offset from s and
// vanishes on a - s and b - s, so orient3d(s, a, b, p) = lc orient3d(s, a,
// b, c) = -lc o (moving s from first to last is three transpositions); the
// same for la, lb. orient3d(a, b, c, .) is affine, o at s and 0 at a, b, c,
// so orient3d(a, b, c, p) = o (1 - la - lb - lc). The three cone signs < 0
// make la, lb, lc all of o's sign: if o < 0, then 1 - la - lb - lc > 1 and
// orient3d(a, b, c, p) < 0, excluded by the fourth sign; so o > 0 (s is on
// the inner side), la, lb, lc > 0, and the fourth sign gives la + lb + lc
// < 1: p is interior to the tetrahedron. As the perturbation vanishes, p
// lies in the closed tetrahedron conv(s, a, b, c), which P, convex, contains:
// S ⊆ P at the exact level. At the canonical level the perturbed p is an interior point of a
// tetrahedron of points of the perturbed P (s strictly inside exactly stays
// strictly inside for a small enough perturbation), hence not extreme: the
// non-vertex is not a vertex of the SoS hull. One level of records suffices
// (no chains, so no cycles to exclude): every record's corners are vertices of
// the surface under construction at the removal, i.e. the initial
// tetrahedron's points or inserted points, none of which is ever removed
// early.
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

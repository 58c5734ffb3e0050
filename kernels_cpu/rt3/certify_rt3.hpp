// certify_rt3.hpp — the witness-checked certifier of the multithreaded 3D
// regular / Delaunay triangulation's own output (cpu::rt3 with an
// Rt3Witness, rt3.hpp): `tets`, the output about to be written, is
// RT(S ⊕ W) of ps — at Level::canonical THE one under flipflop's Simulation
// of Simplicity, in canonical form (DESIGN.md, reference/rtd/canonical_d.hpp)
// — when the witness passes. A constant number of exact predicates per
// tetrahedron, per facet and per point (pred::fast: the per-input static
// filter from a parallel scan, then the staged exact path with SoS), every
// check split over oneTBB tasks in the kernel's own (spatial) slot order, no
// point location. Third-party outputs have no witness: certify::rtd
// (reference/rtd/certify_rtd.hpp) certifies those.
//
// Positions are indices into w.pts; the virtual vertex v is position n =
// ps.size(). A slot is used unless its four corners are Rt3Witness::kNoSlot;
// a used slot is real when v is not a corner, else virtual. Conditions in
// order (the first violated one is named; within one, the smallest slot or
// position, whatever the thread count — each condition records its smallest
// failing item, and an item failing one condition is not tested for the
// later ones):
//   input-dimension          ps.dim == 3 and the points span R^3
//   witness-size             pts and at have n entries, tv and tn as many
//                            (a multiple of 4)
//   witness-points           pts is the input permuted: each input index at
//                            one position, with its coordinates and weight
//                            bit for bit
//   simplex-indices          a used slot holds four distinct positions in
//                            [0, n] (v allowed), an unused one four kNoSlot;
//                            at least one slot is real
//   simplex-orientation      every real slot is positive in the predicates'
//                            convention: pred::orient3d of its corners > 0
//                            under SoS (Orientation::orient_d)
//   facet-manifold           for every used slot t and corner i, tn names a
//                            used slot u and corner j with tn[4u + j] = 4t + i,
//                            u's corners but j are t's corners but i, and the
//                            two induce opposite orientations on that facet
//                            (u with corner j replaced by t's corner i is an
//                            odd permutation of t: replacing the corner
//                            opposite a facet keeps the orientation it
//                            induces there, and two tuples of one set induce
//                            the same orientations iff they have the same
//                            parity): the used slots form a closed oriented
//                            pseudomanifold, v included
//   witness-vertex           every corner k of a real slot is a vertex: w.at[k]
//                            is a real slot with k as a corner
//   boundary-is-hull         the boundary triangles — the facets of real slots
//                            linked to virtual slots, counter-clockwise seen
//                            from outside the real slot, in input indices — are
//                            the convex hull of the input: the surface part of
//                            certify::hull3 (certify_hull3_surface.hpp: a closed
//                            oriented 2-manifold of genus 0, star-shaped w.r.t.
//                            an exact interior point, every edge convex; thesis
//                            Lemma 6.1 / Thm 6.2) at the same level
//   locally-regular          every facet between two real slots t (the smaller
//                            half-facet 4t + i) and u: power3d(t's corners, u's
//                            corner opposite the facet) < 0 — that lifted point
//                            strictly above the lifted t (Thm 2.2; canonical:
//                            SoS, strict; exact: exact, <= 0)
//   missing-point-witness    every position k that is not a vertex: w.at[k] is
//                            a real slot and k lies strictly inside it under
//                            SoS (orient3d > 0 with each corner replaced by k)
//   missing-point-redundant  and power3d(its corners, k) < 0 (k's lifted point
//                            strictly above; exact level: <= 0, exact)
//   canonical-output         every tuple of `tets` has four distinct indices
//                            below n (checked first, then:)
//   canonical-form           (Level::canonical) every tuple of `tets` is
//                            canonical (canonical_d.hpp: smallest first, the
//                            middle ascending) and the list strictly increasing
//   canonical-output         `tets` is exactly the set of the real slots
//                            mapped to input indices as volume-positive
//                            tuples: at Level::canonical in canonical form, at
//                            Level::exact in any order, each tuple any even
//                            permutation of a volume-positive one (any
//                            positively oriented tuple; no repeats)
//
// Why these suffice (in the perturbed configuration, a real configuration in
// general position whose signs are all the SoS answers — EM90 — for every
// small enough ε > 0):
//  1. Points. witness-points makes every position one input point with its
//     own SoS index and every input point one position. witness-vertex and
//     missing-point-witness give every position either a real slot with it as
//     a corner (a vertex) or a real slot strictly containing it (a missing
//     point); a missing position is a corner of no real slot (witness-vertex).
//  2. Tiling. Let C be the 3-chain of the real slots, each positive (a
//     non-degenerate tetrahedron with its positive orientation). The links of
//     facet-manifold pair the facets of real slots linked to real slots by an
//     involution (tn[tn[e]] = e), each pair the same three points with
//     opposite orientations, so they cancel in ∂C: ∂C = B, the boundary
//     triangles, each with the orientation induced by its real slot — for a
//     positive (c0, c1, c2, c3), (c0, c1, c2) is counter-clockwise seen from
//     outside (orient3d(c0, c1, c2, c3) > 0: c3 on its inner side,
//     predicates.hpp), and so for every facet. For a point y on no facet's
//     plane, the number of real slots containing y is Σ_σ wind(∂σ, y) =
//     wind(B, y) (a positive tetrahedron's boundary winds once around its
//     interior points and zero times around the others; winding numbers add
//     over chains). boundary-is-hull: B, as a list of distinct triangles, is
//     the boundary of a convex polytope P whose vertices are input points,
//     oriented outward (certify::hull3's surface conditions), so wind(B, y) =
//     1 inside P and 0 outside: the real slots have disjoint interiors and
//     their union is P. In general position (no four points coplanar) two
//     tetrahedra with disjoint interiors meet in a common face or not at all
//     (an edge crossing a facet transversally, or a vertex in a facet or an
//     edge, would make the interiors meet), so the real slots form a
//     triangulation of P whose vertex set V is the set of vertex positions
//     (1.). P's vertices are in V, V ⊆ P: P = conv(V). Every missing point
//     lies in a real slot, so S ⊆ P: P = conv(S) (thesis §2.1). The virtual
//     slots take no further part (B is a cycle, ∂∂C = 0, whatever they
//     are): the closed pseudomanifold through v is checked as the structure
//     the kernel holds, by link reads only, no predicate.
//  3. Regularity. Thm 2.2 [ES92] (thesis §2.2): a triangulation of conv(V)
//     with every interior facet locally regular is RT(V ⊕ W) — its lifted
//     surface is locally convex at every interior ridge, hence convex on the
//     convex domain, hence the lower hull. locally-regular tests each interior
//     facet once, from one side, by the power test of the other side's
//     opposite corner (the lifted tetrahedra fold convexly at the facet iff
//     that lifted point is above the lifted hyperplane of the first).
//  4. Redundancy. A missing point whose lifted point lies strictly above the
//     lifted tetrahedron containing it lies strictly above the lower hull (that
//     convex function) and is redundant; adding redundant points leaves the
//     lower hull as it is, so the real slots are RT(S ⊕ W) — with every test
//     strict under SoS, the unique one of the perturbed points, i.e. the
//     canonical answer (DESIGN.md; ref::rtd_incremental's).
//  5. Output. Each real slot mapped to input indices is a positive tuple in
//     the predicates' convention; canonical_d.hpp's rule (odd d: swap the last
//     two entries, then sort, swapping the last two again when the sort was an
//     odd permutation) gives its canonical, volume-positive tuple, which must
//     be in `tets`. The real slots are distinct as sets (disjoint interiors),
//     `tets` has no repeats and as many tuples: the two are the same set.
// At Level::exact the structural conditions (orientation, containment) stay
// perturbed and the geometric ones are exact and non-strict (a perturbed sign
// > 0 implies an exact one >= 0), as in certify::rt2's witness-checked
// certifier (kernels_cpu/rt2/certify_rt2.hpp): boundary-is-hull is
// certify::hull3's surface at the exact level, the locally-regular and
// redundancy power tests exact and non-strict — a regular triangulation of
// the exact input, flat tetrahedra of the SoS answer included.
// Cost: per real slot one orient3d, at most four power3d (each interior
// facet once: two per slot on average), four link checks and four `at`
// reads; per missing point four orient3d and one power3d; the hull's
// surface checks on the boundary triangles (a constant number of orient3d per
// triangle and per hull vertex); the output looked up per real slot in a
// table of first indices, bucketed for locality.
#pragma once

#include <vector>

#include "kernels_cpu/rt3/rt3.hpp"  // Rt3Witness, Tet
#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// tets: the canonical output about to be written (Rt3Result::tets).
// Level::canonical: THE regular triangulation under SoS in canonical form;
// Level::exact: a regular triangulation of the exact input, any order of
// positively oriented (volume convention) tuples accepted for
// canonical-output. threads: worker threads (0: the runtime's default).
certify::Report certify_rt3(const PointSet& ps, const Rt3Witness& w, const std::vector<Tet>& tets,
                            certify::Level level = certify::Level::canonical, int threads = 0);

}  // namespace flipflop::cpu

// strict_rtd.hpp — the strict view of a d-dimensional regular (Delaunay)
// triangulation (`flipflop rtd --strict`): a triangulation of the exact
// input without simplices of zero volume, derived deterministically from the
// canonical SoS answer (DESIGN.md "Canonical output", `--strict` views).
//
// Why the canonical answer has flat simplices in d >= 3 and why deleting
// them is not enough: under the canonical perturbation (predicates.hpp: each
// point's coordinates and lifted height perturbed, point by point) the exact
// regular subdivision — the projection of the lower hull of the unperturbed
// lifted points, whose cells can be polytopes with many vertices (the cubes
// of a grid's Delaunay subdivision) — is refined in a way that may join four
// coplanar, cocircular points by a flat tetrahedron: the two cubes on either
// side of a square are split along different diagonals, and the flat
// tetrahedron glues them. Deleting it would leave a T-junction. The rt2 view
// (strict_rt2.hpp) repairs 2D by local moves; in d >= 3 the view is instead
// recomputed under a perturbation that does not create such simplices.
//
// The rule, d >= 3. Let V be the vertices of the canonical answer. The strict
// view is the regular triangulation of V under pred::power_d_pulled — every
// lifted height h becomes h + ε1 |x|^2 - ε2^(rank of its index) (the
// smallest index pulled down most), the coordinates perturbed as in the
// canonical perturbation but infinitely less — with its simplices of zero
// exact volume removed. Computed by the same RT+1 (rt_incremental.hpp,
// build_rtd with pulled = true): RT+1 needs only one consistent perturbation,
// and power_d_pulled with orient_d are the signs of one real configuration in
// general position (predicates.hpp).
//
// Why it holds (ε1 >> ε2 fixed and small, δ -> 0 the coordinate
// perturbation):
//  1. With the heights perturbed alone (δ = 0), the lower hull of the lifted
//     V is simplicial and non-vertical: d+2 lifted points on one
//     non-vertical hyperplane would make det Λ = exact + ε1 D_q - Σ ε2^(r_i)
//     C_i vanish although the d+2 points span R^d (some cofactor C_i != 0).
//     Its projection P is a triangulation of conv(V) with no simplex of zero
//     volume (a lower facet is non-vertical, so its projection is a
//     full-dimensional simplex). P refines the exact regular subdivision of
//     V: the ε1 term adds a strictly convex function to heights that are
//     affine on each cell, so each cell is refined by the Delaunay
//     subdivision of its points, in which every point of the cell is a
//     vertex; the ε2 pulls then split the cospherical ties of those (a
//     pulling triangulation: the cubes of a grid get d! simplices each).
//  2. Every simplex of P and every power test between two adjacent simplices
//     of P is decided at δ-order 0 (the d+2 points span R^d), so for small
//     δ every simplex of P is a simplex of the triangulation T_δ computed
//     here; the rest of T_δ covers conv(V_δ) minus conv(V), whose volume
//     tends to 0: those simplices have zero exact volume. Removing them
//     leaves exactly P: conforming (a subcomplex of T_δ), covering conv(V) =
//     conv(S) once, no simplex of zero volume.
//  3. Regularity: P's interior ridges are locally regular under the height
//     perturbation; in the limit every ridge is weakly locally regular (the
//     opposite lifted vertex on or above), and every point of V not in P lies
//     on or above the lifted P. Points outside V are redundant in the
//     canonical answer, hence weakly redundant. So the exact-level
//     certificate (certify::rtd, Level::exact) holds, and every point that is
//     not redundant in the exact sense is a vertex of P.
// The weakly regular cases: a point of V whose lifted point lies exactly on
// the lower hull (on a lifted facet or ridge) is a vertex, as it is in the
// canonical answer; a point of V strictly above it (the canonical
// perturbation can push a point inside a hull facet out of the hull) is not;
// of coinciding points of V with equal weights only the smallest index
// remains (pulled most), of different weights the largest weight (the others
// are strictly above). (The canonical answer itself keeps one copy of
// coinciding points inside the hull, the one its perturbation lifts least,
// and may keep several on the boundary.) This is the rule of strict_rt2 for
// the vertex set; the simplices inside a cell of the exact subdivision are
// P's (Delaunay, then pulling from the smallest index), not the result of
// strict_rt2's local moves.
//
// d = 2: the view of `rt2|dt2 --strict` (strict_rt2), so that `rtd --dim 2
// --strict` and `rt2 --strict` agree byte for byte.
//
// On input in general position (no exact determinant 0) the view is the
// canonical answer. Output: canonical form (canonical_d.hpp, volume
// convention), certified by the callers at Level::exact.
#pragma once

#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::ref {

// The strict view of `canonical`, the canonical answer for ps (ps.dim 2..5,
// weights ps.weight(i); zero for Delaunay). Throws std::invalid_argument when
// `canonical` names a point outside ps or has fewer than d+1 vertices.
std::vector<std::vector<Index>> strict_rtd(const PointSet& ps, const std::vector<std::vector<Index>>& canonical);

}  // namespace flipflop::ref

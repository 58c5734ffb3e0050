// strict_rt2.hpp — the strict view of a 2D regular / Delaunay triangulation:
// a triangulation of the exact input without zero-area triangles, derived
// deterministically from the canonical SoS answer (DESIGN.md "Canonical
// output": `--strict` views; `flipflop dt2|rt2 --strict`).
//
// The canonical answer RT(S ⊕ W) under Simulation of Simplicity may hold
// triangles of zero area: three collinear points that the perturbation joins
// (along the hull boundary and along lines of a grid), or coinciding points
// that the perturbation keeps apart. The strict view removes them:
//
//  0. Coinciding vertices. At a location held by several vertices of the
//     canonical answer (the perturbation separates coinciding points; on the
//     hull boundary it can make two copies extreme), the one of largest
//     weight is kept (equal weights: the smallest index); the others are
//     exactly redundant (their lifted points are on or above the kept one's)
//     and are removed by recomputing the canonical answer without them
//     (ref::rt2_ffrt): the exact lower hull of the lifted points does not
//     change, so no point's exact redundancy does.
//  1. Flat triangles. A flat triangle (a, m, c) with m strictly between a and
//     c (collinear, distinct): when its long edge ac is on the boundary, it is
//     removed (m becomes a boundary vertex inside the hull edge); otherwise,
//     with (c, a, d) across ac non-flat, the pair is replaced by (a, m, d) and
//     (m, c, d) — d is off the line, so both have non-zero area; the union
//     (triangle a c d) is unchanged, so the result stays a conforming
//     triangulation of the same region. A flat neighbour across ac waits for
//     a later pass; flat triangles are taken in sorted order, so the outcome
//     is deterministic.
//  1b. Boundary points. The perturbation can push a point lying inside a hull
//     edge out of the hull and so make it a vertex although its lifted point
//     is strictly above the lifted hull edge (exactly redundant; weighted
//     input only — the paraboloid is strictly convex). Such vertices are
//     found after step 1 (consecutive collinear boundary vertices p, m, c and
//     power2d(p, c, d, m) < 0 for the apex d of the triangle on pm: every
//     plane through the lifted p and c contains the lifted line pc) and
//     dropped like the coinciding ones, recomputing without them; steps 0,
//     1, 1b repeat until none is found (each round drops a point).
//     In the interior the perturbation is infinitesimal: an exactly strictly
//     redundant point is redundant under it, so the canonical answer never
//     has one as a vertex there.
//     Why no edge is then strictly non-regular: the non-flat canonical
//     triangles are, in the limit of the perturbation, faces of the exact
//     lower hull of the lifted points (weakly: no lifted point strictly below
//     their planes), and a flat triangle's middle vertex m lies on the lifted
//     line through its long edge (below it, m would be strictly below the
//     lifted neighbour across that edge; above it, m would be strictly
//     redundant, excluded by 0 and 1b), so the two triangles replacing the
//     pair lie in the plane of the neighbour: the lifted surface does not
//     change.
//  2. Weak regularity checked by Lawson's flips (by the argument of 1b none
//     is expected; they keep the view a regular triangulation if one were):: an interior edge whose
//     quadrilateral is strictly convex and whose opposite vertex is strictly
//     non-regular (power2d_exact > 0: strictly inside the circumcircle for
//     unweighted input) is flipped, edges in a deterministic queue order.
//     Each flip strictly lowers the lifted surface over the quadrilateral, so
//     the process ends; no flip creates a flat triangle (the quadrilateral is
//     strictly convex). At the end every interior edge is weakly locally
//     regular or sits in a quadrilateral that is not strictly convex.
//
// The rule for the weakly regular cases (lifted points exactly on a lifted
// triangle or edge): the vertex set is the canonical answer's (after 0), so a
// point whose lifted point lies exactly on the lower hull is a vertex iff the
// perturbation made it one; among triangulations of that vertex set the
// result is the one steps 1 and 2 reach from the canonical answer.
//
// What holds, certified by the callers (flipflop dt2|rt2 --strict) and by
// proptests/rt2_strict_test.cpp: every triangle has non-zero area
// (orient2d_exact > 0); certify::rt2 at Level::exact accepts it (a
// triangulation of conv(S), every edge weakly locally regular — Thm 2.2 —,
// every missing point weakly redundant); every point that is not redundant in
// the exact sense is a vertex (it is one under any small perturbation, and
// steps 0-2 remove only exactly redundant coinciding points).
// Output: canonical form (reference/canonical.hpp), counter-clockwise.
#pragma once

#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::ref {

// The strict view of `canonical`, the canonical SoS answer for ps (weights
// ps.weight(i); zero for Delaunay). Throws std::invalid_argument when the
// triangles are not a triangulation of ps's points (a malformed input list).
std::vector<Triangle> strict_rt2(const PointSet& ps, const std::vector<Triangle>& canonical);

}  // namespace flipflop::ref

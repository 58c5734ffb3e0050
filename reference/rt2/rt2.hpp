// rt2.hpp — the public entry points of the 2D regular / Delaunay
// triangulation reference (thesis chapter 5 and §3.3.1).
//
// Every function returns THE regular triangulation RT(S ⊕ W) under flipflop's
// Simulation of Simplicity (predicates.hpp; one perturbation with δ = 3: x, y
// and the lifted height, input index = SoS index), as counter-clockwise
// triangles of input indices in canonical form (DESIGN.md: each rotated to
// its smallest index, lines sorted) — equal to brute::rt2 on every input.
// On degenerate input the answer can contain triangles that are flat in
// exact arithmetic (along collinear boundary points): they are positive under
// the perturbation and the certifier accepts them. Exact duplicates (same x,
// y and weight) are distinct perturbed points; of such a group only the copy
// of largest index can be a vertex (the smaller index's height perturbation
// dominates and lifts it above its copy).
//
// Inputs: a 2D point set (ps.dim == 2) that spans the plane; weights from ps
// (0 when unweighted). Lower-dimensional input (fewer than 3 points, all
// collinear) and invalid triangulations throw std::invalid_argument with one
// line naming the problem. The algorithms verify their final state (every
// edge locally regular) and throw std::logic_error rather than return an
// unverified result.
#pragma once

#include <vector>

#include "reference/point_set.hpp"
#include "reference/rt2/triangulation2.hpp"  // Rt2Stats, FlipFlopVariant

namespace flipflop::ref {

// Throws std::invalid_argument "WHO: <problem>" unless ps is a 2D point set
// of at least 3 points that spans the plane (the check of every entry point
// below, and of the cpu backend, kernels_cpu/rt2).
void require_plane(const PointSet& ps, const char* who);

// ffRT (§5.3): constructing stage (1-3 insertions into an extended
// triangulation, points proved redundant by their triangle discarded) then
// flip-flop (Algorithm 5, or the V-first variant).
std::vector<Triangle> rt2_ffrt(const PointSet& ps, Rt2Stats* stats = nullptr,
                               FlipFlopVariant variant = FlipFlopVariant::combined);

// The Delaunay triangulation by Lawson's flip algorithm (§3.3.1). The initial
// triangulation is ffRT's constructing stage without discarding (1-3
// insertions into an extended triangulation, no flips; the real part is
// star-shaped and Lawson's flips on the virtual edges (§2.2) make it convex).
// Weights must be absent or all zero (throws std::invalid_argument otherwise:
// with weights Lawson can get stuck, Figure 3.3 — use rt2_ffrt). Of a group of
// identical points only the one of largest index is inserted (see above: the
// others are redundant under the perturbation); every other point is a vertex
// of the answer (distinct lifted points on the paraboloid are in strictly
// convex position), so Theorem 2.1 applies.
std::vector<Triangle> dt2_lawson(const PointSet& ps, Rt2Stats* stats = nullptr);

// Flip-flop (§5.1, Algorithm 5) from a user's triangulation: counter-clockwise
// triangles of input indices forming a valid triangulation of a disk whose
// union is star-shaped w.r.t. the kernel point (a + b + 2c)/4 of the first
// triangle (a, b, c) of the list with non-zero area — any triangulation of a
// convex polygon qualifies, in particular of conv(S) (validated; exact or
// perturbed-flat triangles along collinear boundary points are accepted when
// positive under the perturbation). Its vertices may be any subset of S:
// points that are not vertices are first inserted exactly as in ffRT's
// constructing stage (§5.3: located, then inserted by 1-3 flips — into a
// virtual triangle when outside the triangulated region — or discarded when
// their triangle proves them redundant), so that the triangulation flip-flop
// starts from contains every non-redundant point, as §5.1 requires.
std::vector<Triangle> flip_flop(const PointSet& ps, std::vector<Triangle> triangulation,
                                FlipFlopVariant variant = FlipFlopVariant::combined, Rt2Stats* stats = nullptr);

// Lawson's flip algorithm (§3.3.1) from a user's triangulation (validated as
// for flip_flop) in which every point of ps is a vertex (Theorem 2.1 needs the
// vertex set to be S; throws std::invalid_argument naming a missing point).
// With weights it flips locally non-regular flippable edges (the V-criterion
// alone); when that gets stuck with a locally non-regular edge left — which
// happens exactly when a vertex is redundant (Lemma 5.1, Figure 3.3, also a
// duplicated point) — it throws std::runtime_error instead of returning a
// triangulation that is not regular.
std::vector<Triangle> lawson(const PointSet& ps, std::vector<Triangle> triangulation, Rt2Stats* stats = nullptr);

}  // namespace flipflop::ref

// rt_incremental.hpp — RT(S ⊕ W) in R^d (2 <= d <= 5) by incremental
// insertion and monotonic flips: the "RT+1" algorithm of Edelsbrunner and
// Shah [ES92] (thesis §3.1 Table 3.1, §9.1 "Arbitrarily Monotonic Flip
// Algorithm Works for 'RT+1' Triangulation").
//
// Every function returns THE regular triangulation under flipflop's
// Simulation of Simplicity (predicates.hpp: one perturbation of the d
// coordinates and the lifted height |x|^2 - w, perturbed as an independent
// coordinate — thesis §9.2.2 last paragraph; the input index is the SoS
// index): the projection of the lower hull of the perturbed lifted points.
// Simplices are positively oriented tuples of input indices in canonical
// form (canonical_d.hpp); for d = 2 the output equals ref::rt2_ffrt byte for
// byte. Points that are not vertices are redundant (their lifted point lies
// strictly above the lower hull) and are listed, sorted.
//
// Inputs: ps.dim in 2..9, weighted or not (weights 0). Input that does not
// span R^d (fewer than d+1 points, all in a hyperplane) throws
// std::invalid_argument carrying dimension_problem(ps). The algorithm
// verifies its final state (every ridge locally regular, Theorem 2.2) and
// throws std::logic_error rather than return an unverified result.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/point_set.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref {

struct RtdStats {
  std::uint64_t flips[rtd::kMaxDim + 2] = {};  // flips[k] = number of k-(d+2-k) flips (k = 2..d+1 by
                                // ridges; flips[1] = 1-(d+1) insertions into a simplex)
  std::uint64_t insertions = 0;     // points made vertices (placing included)
  std::uint64_t placed = 0;         // of those: outside the current hull (placing, below)
  std::uint64_t redundant = 0;      // points not in the output (redundant)
  std::uint64_t removed = 0;        // of those: vertices removed by (d+1)-1 flips
  std::uint64_t queue_pushes = 0;   // ridges pushed on the flip queue
  std::uint64_t queue_pops = 0;     // ridges popped
  std::uint64_t unflippable = 0;    // popped ridges that were locally non-regular and unflippable
  std::uint64_t sweeps = 0;         // re-examinations of star(p) after the queue emptied
  std::uint64_t walk_steps = 0;     // simplices visited by point location
};

struct Rtd {
  std::vector<std::vector<Index>> simplices;  // canonical (canonical_d.hpp)
  std::vector<Index> redundant;               // sorted
};

// The input checks of rtd_incremental (shared with kernels_cpu/rtd): throws
// std::invalid_argument for a dimension outside 2..kMaxDim, a weight count
// that is not the point count, a non-finite value, more than 2^32 - 16 points,
// or points that do not span R^d (dimension_problem's message).
void validate_rtd_input(const PointSet& ps);

// RT+1 [ES92]: insert the points one at a time (in a spatially coherent
// order; the result does not depend on the order); a point inside the
// current hull is located (exact visibility walk) and is either redundant
// w.r.t. its simplex (lifted point strictly above it: redundant for good,
// since adding points only lowers the lower hull) or inserted by a 1-(d+1)
// flip; a point outside is placed (the cone from it over the hull facets it
// sees — the thesis' "RT+1 extended triangulation", §9.1). Then the link
// ridges of the new vertex are flipped while locally non-regular and
// flippable, from a queue, until none (monotonic flips; (d+1)-1 flips remove
// vertices that became redundant).
//
// furthest: the furthest-site triangulation instead — the lower hull of the
// points lifted to the NEGATED heights -(|x|^2 - w) - ε_h, i.e. the upper hull
// of flipflop's perturbed lifted points (x + ε_x, |x|^2 - w + ε_h) (DESIGN.md):
// every power_d sign negated (multilinearity in the height column), orient_d
// unchanged. One consistent real configuration again, so RT+1 applies as it
// is (the heights are any heights for Edelsbrunner-Shah); its vertices are the
// vertices of the convex hull, every other point is redundant.
Rtd rtd_incremental(const PointSet& ps, RtdStats* stats = nullptr, bool furthest = false);

// The same, returning the structure (for the instant flip, thesis §9.2).
// pulled: under pred::power_d_pulled instead of the canonical perturbation
// (the strict view, strict_rtd.hpp); the algorithm is the same, it needs only
// one consistent perturbation.
rtd::TriangulationD build_rtd(const PointSet& ps, RtdStats* stats = nullptr, bool pulled = false,
                              bool furthest = false);

}  // namespace flipflop::ref

// graham_insertion.hpp — parallel Graham's scan via insertion ("Graham-
// insertion"), thesis §4.3, Algorithm 4, run sequentially.
//
// The two chains of Graham-sorting (§4.2) are grown by insertion instead of
// sorting. An oriented edge a -> b is non-vertical here; c is *beyond* it if
// △abc is clockwise, and *right beyond* if moreover c.x lies between a.x and
// b.x. Starting from P = <v_r, v_l>, every other point is right beyond v_r -> v_l
// (upper chain) or v_l -> v_r (lower chain) and is associated with that edge.
// Each iteration inserts into every edge p -> q one point r associated with it
// (edge -> p -> r, r -> q) and re-associates the other points of that edge with
// p -> r or r -> q by their x; a point beneath its new edge lies inside the
// triangle p r q, is proved non-extreme and is dropped. When no point is left,
// P is two x-monotone chains (star-shaped w.r.t. (0, ∓∞)) and flip-pop
// finishes.
//
// Which associated point is inserted is free (§4.3: the GPU inserts an
// approximately furthest one; any choice is correct thanks to flip-pop).
// InsertionChoice selects the rule; the result is the same canonical hull for
// every rule, which the tests check.
//
// Simulation of Simplicity: beyond/beneath is pred::orient2d and "x between" is
// pred::compare_sos on the one perturbation, so no point is ever on an edge's
// line or at an edge's end in x. Only the choice of the inserted point uses
// floating point, which cannot affect the result.
//
// Checked build: after every iteration the chains are strictly x-monotone and
// every remaining point is right beyond its edge; every dropped point is
// strictly inside the triangle p r q.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/hull2/flip_pop.hpp"

namespace flipflop::ref {

enum class InsertionChoice {
  furthest,        // the largest floating-point distance to the edge (ties: nearest the
                   // middle of the edge in x, then the smallest index)
  smallest_index,  // the associated point with the smallest index
  random,          // uniformly at random (std::mt19937_64 seeded by InsertionOptions::seed)
};

struct InsertionOptions {
  InsertionChoice choice = InsertionChoice::furthest;
  std::uint64_t seed = 1;
};

// Alg 4 lines 1-18: the two chains. Adds insertions, insertion_rounds and
// discarded_early to *stats. ps must hold at least 2 points.
ChainPolygon graham_insertion_polygon(const PointSet& ps, Hull2Stats* stats = nullptr,
                                      const InsertionOptions& options = {});

// Algorithm 4: lines 1-18, then flip-pop (line 19). The hull counter-clockwise,
// smallest index first. Precondition: ps spans the plane (hull2.hpp checks).
std::vector<Index> graham_insertion(const PointSet& ps, Hull2Stats* stats = nullptr,
                                    const InsertionOptions& options = {});

}  // namespace flipflop::ref

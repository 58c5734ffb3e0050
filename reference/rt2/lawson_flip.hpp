// lawson_flip.hpp — Lawson's flip algorithm (thesis §3.3.1) on the extended
// triangulation of triangulation2.hpp.
//
// Geometric structure: a 2D triangulation; criterion: flip every locally
// non-Delaunay edge; local operation: the 2-2 flip ("a 3-1 edge is always
// locally Delaunay"); local check: is the edge locally non-Delaunay (an
// unflippable 2-2 edge is intrinsically locally Delaunay); candidate: an edge
// with its two triangles. The local test is power2d, i.e. the incircle test
// for zero weights; edges of the virtual vertex follow §2.2 ("a locally
// regular ridge incident to virtual facets is also locally Delaunay"), so on
// an extended triangulation Lawson also makes the link of v convex.
//
// Monotonicity (§3.3.1, Theorem 5.3): a flip replaces a reflex lifted edge by a
// convex one, so the lifted surface (closed by a virtual point v^+ above all
// points) only goes down and no removed edge reappears: it terminates. With
// all vertices non-redundant (any set of distinct points with zero weights:
// they lie on the paraboloid in strictly convex position) every locally
// non-regular edge is a flippable 2-2 edge (Lemma 5.2), so the end is the
// Delaunay / regular triangulation (Theorem 2.1 / 2.2). With weights it can
// get stuck (Figure 3.3): run() then reports failure instead of an answer.
//
// Checked build: after every flip the triangulation is valid and the new edge
// is locally regular (the lifted surface went down).
#pragma once

#include <utility>
#include <vector>

#include "reference/rt2/triangulation2.hpp"

namespace flipflop::ref::lawson_flip {

enum class Move {
  none,    // locally regular
  flip22,  // locally non-regular, flippable: flip it
  stuck    // locally non-regular but not a flippable 2-2 edge (Lemma 5.1: a redundant vertex)
};

Move decide(const tri::Triangulation2& T, tri::Edge e);

// Flip e (decide(e) == flip22) and append the four edges of its quadrilateral
// to `pushed` when given.
void apply(tri::Triangulation2& T, tri::Edge e, std::vector<std::pair<Index, Index>>* pushed, Rt2Stats* stats);

// The sequential workflow (Figure 3.1): a FIFO queue Q initialised with
// `candidates` (every edge when null), pop, local check, flip, push the four
// edges of the flipped quadrilateral; until Q is empty. Starting from only
// the edges that can be locally non-regular (e.g. the triangle a point was
// just inserted into) is Lawson's algorithm with the others popped and found
// locally Delaunay.
void flip(tri::Triangulation2& T, Rt2Stats* stats,
          const std::vector<std::pair<Index, Index>>* candidates = nullptr);

// Is every edge locally regular (then T is the regular triangulation of its
// vertices, Theorem 2.2)?
bool all_locally_regular(const tri::Triangulation2& T);

// flip(T) from all edges, then all_locally_regular(T): false when stuck
// (Figure 3.3).
bool run(tri::Triangulation2& T, Rt2Stats* stats);

}  // namespace flipflop::ref::lawson_flip

// flip_flop_2d.hpp — flip-flop for 2D regular triangulation: thesis §5.1,
// Algorithm 5 (V- and D-criterion, smallest-index rule), proof §5.2 (Lemma
// 5.1, 5.2, 5.4, Theorems 5.3 and 5.5), on the extended triangulation of
// §5.3 (virtual-edge rules of §2.2, triangulation2.hpp).
//
// Geometric structure: a 2D (extended) triangulation; local operations: 2-2
// flip, 3-1 flip, labelling a vertex as redundant; candidate: an edge with its
// induced subcomplex; criterion: the V-criterion (flip locally non-regular
// edges: lowers the lifted surface) combined with the D-criterion (given the
// labelled vertex x of smallest index in the induced subcomplex of e: flip e
// if x is an endpoint of e, never flip e if x is in its link) — D first.
//
// The functions below expose the local check (decide) and the local operation
// (apply) separately so that the exhaustive order search of the tests can
// take every applicable candidate in every order; run() is the sequential
// workflow of Figure 3.1 (a FIFO queue Q of edges) on top of them.
//
// Checked build (reference/checked.hpp): after every operation apply()
// asserts that the triangulation is valid (validity_problem), that a removed
// vertex never reappears, that a V-flip lowers the lifted surface (the new
// edge is locally regular / the removed vertex lies above the new triangle),
// that a D-flip lowers the degree of the smallest-index labelled vertex of
// the induced subcomplex and raises the degree of no labelled vertex of
// smaller index (Theorem 5.5's measure), and that a labelled vertex is
// redundant (Lemma 5.1: its lifted point is above the lifted triangle of the
// other three).
#pragma once

#include <deque>
#include <utility>
#include <vector>

#include "reference/rt2/triangulation2.hpp"

namespace flipflop::ref::ff {

struct State {
  tri::Triangulation2 T;
  std::vector<std::uint8_t> labelled;  // n+1 entries: labelled as redundant (line 18)
};

// Algorithm 5 line 1: all vertices labelled "unknown".
State make_state(tri::Triangulation2 T);

enum class Action {
  none,
  flip31_v,  // line 8-9, e locally non-regular (V-criterion)
  flip31_d,  // line 8-9, the inner vertex is labelled (D-criterion)
  flip22_v,  // line 12-13 (V-criterion)
  flip22_d,  // line 14-15 (D-criterion: a "flop")
  label      // line 16-19 (Lemma 5.1)
};

struct Decision {
  Action action = Action::none;
  Index inner = 0;  // flip31_*: the vertex removed; label: the vertex labelled
};

// Which criterion decides. FlipFlopVariant::v_first runs them in separate
// passes: v_only (lines 8, 12-13: flips of locally non-regular edges), then
// the labelling of lines 16-18 (the `label` decisions of `combined`), then
// d_only (lines 8, 14-15: flips that lower the degree of labelled vertices).
enum class Criteria { combined, v_only, d_only };

// Lines 5-19 for edge e: the decision of the local check, no change made.
Decision decide(const State& s, tri::Edge e, Criteria c = Criteria::combined);

// Apply a decision to edge e; the edges the thesis pushes (lines 9, 13, 15,
// 19) are appended to `pushed` when given. Counts go to `stats` when given.
void apply(State& s, tri::Edge e, const Decision& d, std::vector<std::pair<Index, Index>>* pushed,
           Rt2Stats* stats);

// The whole algorithm on s (lines 1-19 with Q a FIFO queue, or the v_first
// variant). Afterwards every edge is locally regular and no labelled vertex
// is left: the real triangles are RT(S ⊕ W) of the points that were vertices
// or were proved redundant (Theorem 5.5). This is verified at the end in
// every build; a violation throws std::logic_error.
void run(State& s, FlipFlopVariant variant, Rt2Stats* stats);

}  // namespace flipflop::ref::ff

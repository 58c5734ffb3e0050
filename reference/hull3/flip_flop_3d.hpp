// flip_flop_3d.hpp — flip-flop for 3D convex hull: thesis §6.1-6.3,
// Algorithm 6 (V- and D-criterion, smallest-index rule, labelling of
// non-extreme vertices), proof §6.3 (Lemmas 6.3-6.11, Theorems 6.2, 6.7,
// 6.12).
//
// Geometric structure: a polyhedron star-shaped w.r.t. a fixed kernel point s
// (polyhedron3.hpp); local operations: 2-2 flip, 3-1 flip, labelling a vertex
// non-extreme; candidate: an edge with its induced subcomplex; criterion: the
// V-criterion (flip reflex edges: the volume grows) combined with the
// D-criterion (given the labelled vertex x of smallest index among a, b, c,
// d: flip e if x is an endpoint of e and the flip keeps s inside, never if x
// is in its link) — D first. Local check: flippability (§6.1: s outside the
// tetrahedron abcd and C_s(T_e) convex), convexity w.r.t. s, labels.
//
// The result is the convex hull of the vertex set of the input surface under
// the Simulation of Simplicity of predicates.hpp, with s an auxiliary point
// ordered after all inputs (KernelPoint): the canonical SoS hull of those
// vertices (points of ps that are not vertices of the surface play no role).
//
// Checked build (reference/checked.hpp): after every operation apply()
// asserts that the polyhedron is a consistent closed surface star-shaped
// w.r.t. s (Lemma 6.1 / 6.3), that a 3-1 flip removes a vertex labelled
// non-extreme or one inside the cone of the triangle of its link (Lemma 6.4),
// that a V-flip makes the volume grow (the tetrahedron abcd is added to the
// polyhedron: d beyond the plane of abc before, and the new edge convex),
// that a labelled vertex lies inside the tetrahedron of s and the other three
// (Lemma 6.5), and that a removed vertex never reappears.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "predicates/static_filter.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "reference/hull3/kernel_point.hpp"
#include "reference/hull3/polyhedron3.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// surface: closed, coherently oriented (counter-clockwise seen from outside)
// triangulated sphere over input indices; s strictly inside its kernel.
// Returns canonical_triangles of the SoS convex hull of the surface's vertex
// set. Throws std::invalid_argument (one line) when ps is not 3D, when the
// surface is not a closed oriented 2-manifold of genus 0, or (check_star)
// when it is not star-shaped w.r.t. s. Counts go to stats (flips_2_2,
// flips_3_1, labelled_non_extreme; the other fields are reset to 0).
// check_star == false skips the O(F) star-shapedness test for callers that
// guarantee it (termination, Theorem 6.12, rests on it); the final state is
// verified in any case (std::logic_error if an edge is reflex or a labelled
// vertex is left).
std::vector<Triangle> flip_flop_3d(const PointSet& ps, const std::vector<Triangle>& surface, const KernelPoint& s,
                                   Hull3Stats* stats = nullptr, bool check_star = true);

// Lemma 6.1: the surface is a closed oriented genus-0 surface over indices of
// ps whose cones from s do not overlap (checked by orientation and winding,
// polyhedron3.hpp). False for anything that is not such a surface.
bool is_star_shaped(const PointSet& ps, const std::vector<Triangle>& surface, const KernelPoint& s);

namespace ff3 {

// The state of Algorithm 6: the polyhedron and the labels of line 1/18.
struct State {
  const PointSet* ps = nullptr;
  const KernelPoint* s = nullptr;
  poly::Polyhedron3 P;
  std::vector<std::uint8_t> labelled;  // per index: labelled non-extreme (line 18)
  std::vector<std::uint8_t> removed;   // per index: removed by a 3-1 flip (never comes back)
  pred::StaticFilter filter;           // per input (thesis §6.4.2's precomputed bound): orient3d's first stage
};

// Line 1: all vertices labelled "unknown". Does not check star-shapedness.
State make_state(const PointSet& ps, const KernelPoint& s, poly::Polyhedron3 P);
// The same with a static filter the caller has for ps already (one valid
// for every point of ps: StaticFilter::for_points over them, possibly with
// more values) instead of a scan of ps for it (kernels_cpu/hull3: 10^6
// points, a sequential pass of about 5 % of the kernel's time).
State make_state(const PointSet& ps, const KernelPoint& s, poly::Polyhedron3 P, const pred::StaticFilter& filter);

enum class Action {
  none,
  flip31_v,  // lines 8-9, e reflex (V-criterion; Lemma 6.4: flippable)
  flip31_d,  // lines 8-9, the inner vertex is labelled (D-criterion)
  flip22_v,  // lines 12-13 (V-criterion)
  flip22_d,  // lines 14-15 (D-criterion: a "flop")
  label      // lines 16-19 (Lemma 6.5)
};

struct Decision {
  Action action = Action::none;
  Index inner = 0;  // flip31_*: the vertex removed; label: the vertex labelled
};

// Lines 5-19 for the edge {u, w} (which must be an edge of the polyhedron):
// the decision of the local check, no change made.
Decision decide(const State& st, Index u, Index w);

// Applies a decision to the edge {u, w}; the edges the thesis pushes onto Q
// (lines 9, 13, 15, 19) are appended to `pushed` when given.
void apply(State& st, Index u, Index w, const Decision& d, std::vector<std::pair<Index, Index>>* pushed,
           Hull3Stats* stats);

// Every applicable operation of the current state: each edge whose local
// check decides something, with that decision. This is what "free execution
// order" (§3.2) may pick from next.
struct Candidate {
  Index u, w;
  Decision d;
};
std::vector<Candidate> applicable(const State& st);

// Afterwards: "" when every edge is convex and no labelled vertex is left
// (Theorem 6.2: then the star-shaped polyhedron is the convex hull of its
// vertices, and by Theorem 6.12 of the input's vertices); else the problem.
std::string final_problem(const State& st);

// Chooses which applicable operation is taken next (an index into the
// candidates); used by tests to explore every order.
using Chooser = std::function<std::size_t(const std::vector<Candidate>&)>;

// The sequential workflow of Figure 3.1 with a FIFO queue Q of edges (lines
// 2-19) when `choose` is empty; otherwise, at every step, `choose` picks one
// of applicable(st) until none is left. Verifies final_problem() at the end
// (std::logic_error when violated).
void run(State& st, Hull3Stats* stats, const Chooser& choose = {});

}  // namespace ff3

}  // namespace flipflop::ref

// instant_flip.hpp — the monotonic instant flip algorithm, thesis §9.2.1,
// Algorithm 14: RT(S ⊕ W) -> RT(S ⊕ U) by flips in the order of failure time.
//
// The moving model (§9.2, failure_time.hpp): the weights move linearly from W
// (t = 0) to U (t = 1); a ridge fails when it turns from convex to flat. The
// algorithm is a kinetic data structure: it keeps RT(S ⊕ V(t)) while t runs
// from 0 to 1, flipping each ridge at its failure time.
//
//   1      T <- RT(S ⊕ W)
//   2      Q <- priority queue of ridges keyed by failure time
//   3-5    every ridge F of T with failure time t_F in (0,1): Q <- <F, t_F>
//   6-7    while Q is not empty: F <- Q.extractMin()
//   8-9      if F is in T with the same link vertices: flip F
//   10-12      every boundary ridge G of the induced subcomplex of F with
//              failure time in (0,1): Q <- <G, t_G>
//   13     RT(S ⊕ U) <- T
//
// Failure times are never computed: two are compared exactly by
// compare_times() (§9.2.2: the sign of B_F A_G - A_F B_G, ties broken by the
// weight perturbation under a perturbation order). The popped ridge is the
// minimum negative node of the time line (§9.3), flippable by Lemma 9.10; a
// flip is whatever bistellar flip its d+2 points admit (bistellar_flip.hpp):
// a vertex becoming redundant under the moving weights leaves by a (d+1)-1
// flip. Lemma 9.4: a ridge never reappears, so the run is finite
// (O(n^(⌊d/2⌋+1)) flips).
//
// Scope (as in the thesis, §9.2: "Assume that every vertex of RT(S ⊕ U)
// belongs to RT(S ⊕ W)"): points that are redundant in T (not vertices) stay
// out — the moving model has no insertion. The result is the regular
// triangulation of (vertices of T) ⊕ U; it is RT(S ⊕ U) iff no point outside
// T is non-redundant under U. reappearing_points() finds such points.
//
// Preconditions (checked; std::invalid_argument): T is strongly regular for
// W under the perturbation order — every interior ridge is convex at t = 0
// (find one with find_perturbation_order, Algorithm 15, when T is only weakly
// regular); the points are in general position in R^d as far as the
// algorithm meets them (no zero-volume simplex, failure_time.hpp). With the
// index order, T = build_rtd(S ⊕ W) qualifies and the result is the
// reference's RT(S ⊕ U) whenever the d-dimensional orientation minors do not
// vanish (failure_time.hpp, "sign convention"). If the popped minimum is
// unflippable (possible only when degenerate coordinates leave two distinct
// events at one perturbed time, §9.2.2), it waits for the events of the same
// time; if none is left the run throws std::logic_error rather than return a
// triangulation that is not regular.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "reference/rtd/failure_time.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref {

struct InstantFlipStats {
  std::uint64_t flips[8] = {};      // flips[k]: k-(d+2-k) flips; flips[d+1]: vertex removals
  std::uint64_t initial_ridges = 0;  // interior ridges of RT(S ⊕ W) examined (lines 3-5)
  std::uint64_t pushes = 0;          // queue insertions (lines 5, 12)
  std::uint64_t pops = 0;            // extractMin (line 7)
  std::uint64_t stale = 0;           // popped ridges no longer in T with the same link (line 8)
  std::uint64_t deferred = 0;        // popped unflippable ridges waiting for a simultaneous event
  std::uint64_t max_queue = 0;       // largest queue size
  std::uint64_t removed_vertices = 0;  // (d+1)-1 flips
  std::uint64_t total_flips() const {
    std::uint64_t s = 0;
    for (std::uint64_t f : flips) s += f;
    return s;
  }
};

// Passed to the per-flip callback after each flip.
struct InstantFlipEvent {
  const RidgeMotion* ridge = nullptr;  // the flipped ridge; its failure time is the current time
  int k = 0;                           // a k-(d+2-k) flip
  Index removed = rtd::kNoVertex;      // the vertex removed by a (d+1)-1 flip
};

struct InstantFlipOptions {
  // The perturbation order of §9.2.2; empty: the index order.
  PerturbationOrder order;
  // Called after every flip with the current triangulation (for tests and
  // debugging views; may be empty).
  std::function<void(const rtd::TriangulationD&, const InstantFlipEvent&)> on_flip;
};

// Algorithm 14 on T (in place): T = RT(S ⊕ W) on input, RT((vertices of T) ⊕
// U) on return. S = *T.ps (its weights are not used); w, u: T.ps->size()
// weights each.
InstantFlipStats instant_flip(rtd::TriangulationD& T, const std::vector<double>& w,
                              const std::vector<double>& u, const InstantFlipOptions& options = {});

// The points of S that are not vertices of T but are non-redundant w.r.t. T
// under the weights u: each lies outside conv(T) or strictly below the lifted
// simplex of T containing it (exact SoS power test). Empty iff every
// non-vertex is redundant, i.e. (with T regular for u) T = RT(S ⊕ u).
std::vector<Index> reappearing_points(const rtd::TriangulationD& T, const std::vector<double>& u);

}  // namespace flipflop::ref

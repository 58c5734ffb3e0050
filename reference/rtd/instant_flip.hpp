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
// ============================================================================
// Insertions (beyond the thesis, issue 16)
// ============================================================================
// The thesis assumes every vertex of RT(S ⊕ U) is a vertex of RT(S ⊕ W)
// (§9.2). Here every point p that is not a vertex is tracked in the real
// simplex C = (c_0..c_d) of T containing it (point_buckets.hpp; exact SoS
// orient_d). Its event is the time its lifted point passes below the lifted
// hyperplane of C: the same (d+2)-point determinant as a ridge, with
// S = (c_0..c_{d-1}, a = c_d, b = p) (failure_time.hpp, point_motion), so
// compare_times() orders insertion events and ridge failures exactly in ONE
// queue, with the same perturbation order. At its time p enters by the
// 1-(d+1) flip of C (rtd::insert_in_simplex). Every non-vertex lies inside a
// real simplex (conv(vertices) = conv(S), point_buckets.hpp), so the extended
// triangulation's virtual simplices never receive a point and the hull never
// changes. After every flip the points of the destroyed simplices are handed
// to the new ones, and a vertex removed by a (d+1)-1 flip becomes a tracked
// point of the simplex that replaces its star. An insertion event is valid
// only while p is still tracked in that very simplex (same slot generation):
// the analogue of line 8.
//
// Lemma 9.4, restated for the extended process. Every event — a ridge flip or
// an insertion — is the bistellar flip of some (d+2)-point set S whose
// determinant Orient^{d+1}(S*, t) is affine in t (the heights move linearly,
// the perturbation is constant): the event happens at its unique sign change
// from + to - (the lower side of S becomes the upper one). Proof sketch: with
// t > t_S written t_S + λε, the thesis' identity λ·Orient(S, t_S - ε) +
// Orient(S, t_S + λε) = (λ+1)·Orient(S, t_S) = 0 shows the sign stays
// negative after t_S, so the simplices of the side removed never come back —
// for an insertion, the simplex C with p above it; for a ridge, C1 and C2.
// Hence (i) each (d+2)-subset of S hosts at most one event, so the process is
// finite (at most C(n, d+2) events, each a flip); (ii) any ridge — and any
// simplex — appears at most once. A point may enter and later leave (or leave
// and later enter), but through different (d+2)-sets; in fact at most once
// each: p is a vertex at t iff h_p(t) < L_p(t), L_p(t) the lower envelope of
// the other lifted points above p, a minimum of functions affine in t, hence
// concave; so the times p is a vertex form one interval. The other
// ingredient of the thesis' correctness, Lemma 9.10 (the minimum event is
// flippable), holds for insertions trivially: a 1-(d+1) flip of a simplex is
// always possible.
//
// Scope: the result is RT(S ⊕ U) under the perturbation order (the whole
// point set, not only the vertices of T). With the index order and no flat
// (d+2)-set at t = 1 it is the reference's RT(S ⊕ U) byte for byte;
// otherwise the order's and the Simulation of Simplicity's resolutions of a
// flat set may differ — DynamicRegularTriangulation (dynamic_rt.hpp) then
// finishes with SoS flips. reappearing_points() checks the result.
//
// Preconditions (checked; std::invalid_argument): T is strongly regular for
// W under the perturbation order — every interior ridge is convex at t = 0
// and every non-vertex lies above the lifted simplex containing it (find an
// order with find_perturbation_order, Algorithm 15, when T is only weakly
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
#include "reference/rtd/point_buckets.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref {

struct InstantFlipStats {
  std::uint64_t flips[8] = {};      // flips[k]: k-(d+2-k) flips; flips[1]: insertions; flips[d+1]: removals
  std::uint64_t initial_ridges = 0;  // interior ridges of RT(S ⊕ W) examined (lines 3-5)
  std::uint64_t initial_points = 0;  // non-vertices of RT(S ⊕ W) examined (tracked points)
  std::uint64_t pushes = 0;          // queue insertions (lines 5, 12; insertion events)
  std::uint64_t pops = 0;            // extractMin (line 7)
  std::uint64_t stale = 0;           // popped events no longer in T (line 8; points moved)
  std::uint64_t deferred = 0;        // popped unflippable ridges waiting for a simultaneous event
  std::uint64_t max_queue = 0;       // largest queue size
  std::uint64_t removed_vertices = 0;   // (d+1)-1 flips
  std::uint64_t inserted_vertices = 0;  // 1-(d+1) flips (insertion events)
  std::uint64_t moved_points = 0;       // tracked points handed to a new simplex
  std::uint64_t total_flips() const {
    std::uint64_t s = 0;
    for (std::uint64_t f : flips) s += f;
    return s;
  }
};

// Passed to the per-flip callback after each flip.
struct InstantFlipEvent {
  const RidgeMotion* ridge = nullptr;  // the event's S (ridge or (C, p)); its time is the current time
  int k = 0;                           // a k-(d+2-k) flip (1: insertion)
  Index removed = rtd::kNoVertex;      // the vertex removed by a (d+1)-1 flip
  Index inserted = rtd::kNoVertex;     // the point inserted by a 1-(d+1) flip
};

// What the run leaves for a caller that verifies the result with other
// predicates (DynamicRegularTriangulation): every ridge or tracked point of
// the final T that was not shown strictly convex / strictly above at t = 1 by
// the exact unperturbed sign lies in a simplex listed here.
struct InstantFlipTrace {
  std::vector<std::int32_t> slots;    // slots created by flips, or holding an undecided ridge or point
  std::vector<std::uint32_t> gens;    // their generations at the time (stale when changed)
};

struct InstantFlipOptions {
  // The perturbation order of §9.2.2; empty: the index order.
  PerturbationOrder order;
  // Called after every flip with the current triangulation (for tests and
  // debugging views; may be empty).
  std::function<void(const rtd::TriangulationD&, const InstantFlipEvent&)> on_flip;
  // The tracked points of T (every non-vertex, point_buckets.hpp), updated in
  // place; null: instant_flip locates them itself.
  rtd::PointBuckets* points = nullptr;
  // Check the precondition at t = 0 for every ridge and point (line 3-5 then
  // compute every failure time). Without it only ridges and points not shown
  // strictly convex at t = 1 by the exact sign enter the moving model — for a
  // caller that knows T is RT(S ⊕ W) and verifies the result (dynamic_rt.hpp).
  bool check_start = true;
  // Two events of exactly the same time (the same flip, or simultaneous
  // events that no perturbing value separates): 0 takes them in push order,
  // another value in a pseudo-random order drawn from it (tests: every order
  // reaches the same triangulation).
  std::uint64_t tie_seed = 0;
  // Filled when not null (see InstantFlipTrace).
  InstantFlipTrace* trace = nullptr;
  // Runs body(lo, hi) over pieces covering [0, n) (the pieces in any order,
  // concurrently or not); empty: sequentially. Used for the filter part of
  // lines 3-5 without check_start (one result per slot, independent of the
  // split: the answer does not depend on it); kernels_cpu/rtd/instant_flip.hpp
  // passes oneTBB's parallel_for.
  std::function<void(std::size_t n, const std::function<void(std::size_t lo, std::size_t hi)>& body)> for_range;
};

// Algorithm 14 with insertions on T (in place): T = RT(S ⊕ W) on input,
// RT(S ⊕ U) under the perturbation order on return. S = *T.ps (its weights
// are not used); w, u: T.ps->size() weights each.
InstantFlipStats instant_flip(rtd::TriangulationD& T, const std::vector<double>& w,
                              const std::vector<double>& u, const InstantFlipOptions& options = {});

// The points of S that are not vertices of T but are non-redundant w.r.t. T
// under the weights u: each lies outside conv(T) or strictly below the lifted
// simplex of T containing it (exact SoS power test). Empty iff every
// non-vertex is redundant, i.e. (with T regular for u) T = RT(S ⊕ u).
std::vector<Index> reappearing_points(const rtd::TriangulationD& T, const std::vector<double>& u);

}  // namespace flipflop::ref

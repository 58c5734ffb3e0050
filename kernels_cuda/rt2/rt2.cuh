// rt2.cuh — the one source of the GPU ffRT (rt2.hpp explains the task).
// Included by rt2_omp.cpp (thrust's OpenMP backend, host compiler) and
// rt2_cuda.cu (nvcc), each defining FF_KERNELS_NS to the namespace it
// implements; the helpers live in FF_KERNELS_NS::rt2_detail.
//
// ============================================================================
// The data (flat arrays, sized once from n and reused by every round)
// ============================================================================
// Vertices 0..n-1 are the input points in Morton order (their coordinates,
// weights and input indices copied in that order: the input index is the SoS
// index of predicates.hpp); vertex n is the virtual vertex v of the extended
// triangulation (thesis §2.1, reference/rt2/triangulation2.hpp). Triangle t
// has the vertices tv[3t..3t+2] counter-clockwise; half-edge 3t+i is its edge
// opposite corner i, directed from corner i+1 to corner i+2 (the reference's
// tn[t][i]), and opp[3t+i] is the twin half-edge 3u+j. Every 1-3 flip takes
// two new slots, so 4 + 2n slots suffice; the slots freed by 3-1 flips stay
// dead. The kernel point s (SoS index n) is the exact dyadic centroid
// (a + b + 2c)/4 of the initial triangle, never rounded (thesis §6.4.2):
// orient(p, q, v) := orient(q, p, s), the reference's rule.
//
// ============================================================================
// The algorithm (ffRT, §5.3; flip-flop, §5.1 Algorithm 5)
// ============================================================================
//   sort      Morton keys, thrust::sort_by_key; the initial extended
//             triangulation (ref::ffrt::initial_triangle: one real and three
//             virtual triangles); every other point located in one of them.
//   insertion round (§5.3, "for each triangle, one of the points associated
//             with it is selected and inserted by a 1-3 flip"): each point
//             votes for its triangle with an atomic minimum of its key (a hash
//             of its id: a random point of the triangle, so that triangles
//             split evenly); the winners, compacted by copy_if, insert their
//             points by 1-3 flips into disjoint new slots numbered by their
//             place in the compacted list (an exclusive scan); the other points
//             of split triangles are re-associated with one of the three new
//             triangles, and a point whose real triangle proves it redundant
//             (its lifted point above the triangle's lifted plane, §5.3) is
//             discarded.
//   flip-flop rounds (Algorithm 5, in parallel as §5.2's closing paragraph
//             and §4.1 describe): the candidate edges are the edges of the
//             triangles touched since the last round; for each one, in
//             parallel, the local check of lines 5-19 (the reference's
//             decide()); each action claims the triangles it touches (2-2
//             flip and labelling: 2, 3-1 flip: 3) by an atomic minimum of its
//             candidate number, and acts when it holds all its claims; the
//             adjacency across the changed triangles' outer edges is repaired
//             by a remapping of old to new half-edges; points in flipped
//             triangles move to the new ones; the triangles each action
//             touches (line 9, 13, 15, 19's pushes; a lost action's own
//             triangle) are the next round's candidates (sort + unique).
//   Interleaving: as gDel2D, the flip-flop rounds run after every insertion
//             round until no candidate is left, so that points are located in
//             a regular triangulation (short, even triangles). When no point
//             is left, a final sweep checks every edge (Algorithm 5 line 2)
//             and flips on if one is not done; it ends when a sweep finds
//             nothing to do — the reference's final verification.
//   output    the real triangles, canonical (rotated to the smallest input
//             index), sorted.
//
// ============================================================================
// Why the answer is the reference's
// ============================================================================
// Under the SoS perturbation (predicates.hpp) the lifted weighted points are
// in general position, so RT(S ⊕ W) is unique (DESIGN.md). Every decision is
// an exact SoS predicate with the reference's argument order. A point is
// dropped only when proved redundant: by its real triangle (§5.3; redundancy
// w.r.t. a subset implies redundancy w.r.t. S, the lower hull only moves down
// as points are added) or by a 3-1 flip of a labelled vertex (Lemma 5.1) or of
// a locally non-regular 3-1 edge (its lifted point above the other three). At
// the end every edge is locally regular (the final sweep checks all of them)
// and no labelled vertex remains, so (Theorem 2.2, §2.2) the real triangles
// are the regular triangulation of the vertices, the link of v is their convex
// hull, and as every point of S is a vertex or redundant, it is RT(S ⊕ W).
// Hence which point a triangle inserts, which of two conflicting flips goes
// first, and how insertions and flips interleave change the work, never the
// answer. Termination: the actions that act in one round touch disjoint
// triangles, and each one's decision reads only its own triangles, the labels
// (changed only by labelling, whose fact "a is redundant" holds whatever else
// changes) and, for a 3-1 flip, the degree of its inner vertex, whose three
// triangles it holds — so a round is a sequence of Algorithm 5 steps and
// Theorem 5.5 applies; the action of smallest candidate number always holds
// all its claims, so every round with an action makes progress.
//
// Functors: __host__ __device__, no heap, no recursion; atomics are
// cuda::atomic_ref (libcu++, also for the host compiler). Predicates:
// device_predicates.cuh (staged filters, exact expansions, SoS).
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including rt2.cuh"
#endif

#include <cuda/atomic>
#include <thrust/copy.h>
#include <thrust/count.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/fill.h>
#include <thrust/for_each.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/scan.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#include <thrust/unique.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/device_predicates.cuh"
#include "kernels_cuda/elections.cuh"
#include "kernels_cuda/kernel_errors.hpp"
#include "kernels_cuda/rt2/rt2.hpp"
#include "kernels_cuda/two_pass.cuh"
#include "predicates/rational_point.hpp"
#include "reference/rt2/ffrt.hpp"
#include "reference/rt2/rt2.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace rt2_detail {

using std::uint32_t;
using std::uint64_t;
using std::uint8_t;

constexpr uint32_t kNil = ~uint32_t{0};        // no triangle / no vertex
constexpr uint32_t kInserted = kNil - 1;       // loc[]: the point is a vertex
constexpr uint32_t kDiscarded = kNil - 2;      // loc[]: proved redundant (§5.3)

// Candidate actions (Algorithm 5) and their state bits.
constexpr uint8_t kNone = 0, kFlip22 = 1, kFlip31 = 2, kLabel = 3;
constexpr uint8_t kWon = 0x80;    // held all its claims: acts this round
constexpr uint8_t kFirst = 0x40;  // label: the first to label its vertex this round
constexpr uint8_t kKind = 0x0f;

// What happened to a triangle slot in the round of stamp[t] (relocation).
constexpr uint8_t kSplit = 1;   // 1-3 flip: t = (a, b, r), partner (b, c, r), partner + 1 (c, a, r)
constexpr uint8_t kPair = 2;    // 2-2 flip: t and partner share the new edge 3t+1
constexpr uint8_t kMerged = 3;  // 3-1 flip: dead, its region is now the triangle `partner`
constexpr uint8_t kKept = 4;    // 3-1 flip: the surviving triangle

FF_HD inline int nx(int i) { return i == 2 ? 0 : i + 1; }
FF_HD inline int pv(int i) { return i == 0 ? 2 : i - 1; }

using dev::atomic_exchange;
using dev::atomic_fetch_add;
using dev::atomic_fetch_min;
using dev::IsWinner;
using dev::Vote;
using dev::vote_key;

// ---- the points and the predicates with the virtual vertex ------------------
struct Geo {
  const double* xy;  // 2 per vertex
  const double* w;   // 1 per vertex (0 unweighted)
  const Index* id;   // input index = SoS index
  Index n;           // vertex n is v; the kernel point s has SoS index n
  double ksrc[8];    // s = the centroid of these four points (a, b, c, c)
  pred::ErrDouble kapprox[2];

  FF_HD const double* P(Index x) const { return xy + 2 * static_cast<std::size_t>(x); }

  // orient2d(x, y, s) under SoS (x, y real): the filter on s's rounded value
  // with its error bound, then the exact sign on the unrounded centroid with
  // the rows sorted by SoS index (s, index n, is last) — pred::mixed_sign's
  // stages (predicates.cpp).
  FF_HD int orient_kernel(Index x, Index y) const {
    const double *px = P(x), *py = P(y);
    const pred::ErrDouble rows[6] = {pred::ErrDouble(px[0]), pred::ErrDouble(px[1]), pred::ErrDouble(py[0]),
                                     pred::ErrDouble(py[1]), kapprox[0], kapprox[1]};
    if (const int s = pred::lambda_sign_filter_err<3>(rows)) return s;
    pred::xp::MixedRowX r[3];
    const bool sorted = id[x] < id[y];
    r[0].x = sorted ? px : py;
    r[1].x = sorted ? py : px;
    r[2].src = ksrc;
    r[2].count = 4;
    return (sorted ? 1 : -1) * pred::xp::lambda_exact_mixed<3>(r, true);
  }

  // orient2d under SoS of three real vertices
  FF_HD int orient_real(Index a, Index b, Index c) const {
    return dev::orient2d(nullptr, id[a], P(a), id[b], P(b), id[c], P(c));
  }

  // tri::power: > 0 iff d^+ lies below the lifted plane of the
  // counter-clockwise real triangle (a, b, c), under SoS.
  FF_HD int power(Index a, Index b, Index c, Index d) const {
    const pred::PointId ids[4] = {id[a], id[b], id[c], id[d]};
    const double* p[4] = {P(a), P(b), P(c), P(d)};
    const double ww[4] = {w[a], w[b], w[c], w[d]};
    return dev::power2d(nullptr, ids, p, ww);
  }
};

// ---- §6.4.2's two passes (kernels_cuda/two_pass.cuh) ----------------------------
// The signs a decision asks for: orient_kernel(x, y), orient_real(a, b, c),
// power(a, b, c, d) as Geo's. The first pass's (FastSigns) are filters only,
// each a forward error bound on the double evaluation: the per-call
// semi-static filter (static_filter.hpp) for orient2d and power2d of input
// points, the ErrDouble filter on the kernel point's rounded value for
// orient_kernel; 0 where a filter cannot decide. The second pass's
// (ExactSigns) are Geo's whole staged path.
struct FastSigns : dev::Undecided {
  const Geo& g;
  FF_HD explicit FastSigns(const Geo& geo) : g(geo) {}
  FF_HD Index n() const { return g.n; }
  FF_HD int orient_kernel(Index x, Index y) {
    const double *px = g.P(x), *py = g.P(y);
    const pred::ErrDouble rows[6] = {pred::ErrDouble(px[0]), pred::ErrDouble(px[1]), pred::ErrDouble(py[0]),
                                     pred::ErrDouble(py[1]), g.kapprox[0], g.kapprox[1]};
    return certain(pred::lambda_sign_filter_err<3>(rows));
  }
  FF_HD int orient_real(Index a, Index b, Index c) {
    const double* p[3] = {g.P(a), g.P(b), g.P(c)};
    return certain(pred::semi_static_sign<3>(p, nullptr));
  }
  FF_HD int power(Index a, Index b, Index c, Index d) {
    const double* p[4] = {g.P(a), g.P(b), g.P(c), g.P(d)};
    const double ww[4] = {g.w[a], g.w[b], g.w[c], g.w[d]};
    return certain(pred::semi_static_sign<4>(p, ww));
  }
};
struct ExactSigns {
  const Geo& g;
  static constexpr bool undecided = false;
  FF_HD Index n() const { return g.n; }
  FF_HD int orient_kernel(Index x, Index y) const { return g.orient_kernel(x, y); }
  FF_HD int orient_real(Index a, Index b, Index c) const { return g.orient_real(a, b, c); }
  FF_HD int power(Index a, Index b, Index c, Index d) const { return g.power(a, b, c, d); }
};
// The signs of a decision on Geo, for dev::Pass.
struct OnGeo {
  Geo g;
  FF_HD FastSigns fast() const { return FastSigns(g); }
  FF_HD ExactSigns exact() const { return ExactSigns{g}; }
};

// tri::orient: orient2d under SoS of three vertices, at most one of them v
// (cyclic rotations keep the sign; orient(a, b, v) := orient(b, a, s)).
template <class S>
FF_HD int orient(S& sg, Index a, Index b, Index c) {
  const Index n = sg.n();
  if (a == n) {
    a = b, b = c, c = n;
  } else if (b == n) {
    b = a, a = c, c = n;
  }
  if (c == n) return sg.orient_kernel(b, a);
  return sg.orient_real(a, b, c);
}

// §2.2 local regularity of the edge a -> b with link c (left), d (right):
// tri::locally_regular.
template <class S>
FF_HD bool locally_regular(S& sg, Index a, Index b, Index c, Index d) {
  const Index n = sg.n();
  if (c == n || d == n) return true;  // one virtual triangle
  if (a == n || b == n) {             // two virtual triangles: F1 = pc, F2 = pd
    const Index p = b == n ? a : b;
    return orient(sg, p, d, c) == sg.orient_kernel(p, d);
  }
  return sg.power(a, b, c, d) < 0;
}

// ---- the triangulation --------------------------------------------------------
struct Mesh {
  Index* tv;         // 3 per slot
  uint32_t* opp;     // 3 per slot: twin half-edge
  uint8_t* alive;    // per slot
  uint32_t* deg;     // n + 1
  uint32_t* label;   // n + 1: labelled redundant (Algorithm 5 line 18)
  uint32_t* stamp;   // per slot: the round that last changed it
  uint8_t* kind;     // per slot: how (kSplit, kPair, kMerged, kKept)
  uint32_t* partner; // per slot: see kSplit etc.
  uint32_t* remap;   // per half-edge: its new half-edge, valid while its slot's stamp is this round's
  uint64_t* claim;   // per slot: atomic minimum of the claims of this round
  uint32_t* in_list; // per slot: the round whose candidate list holds it
  Index n;

  FF_HD bool is_real(uint32_t t) const { return tv[3 * t] != n && tv[3 * t + 1] != n && tv[3 * t + 2] != n; }
  FF_HD int corner(uint32_t t, Index x) const { return tv[3 * t] == x ? 0 : tv[3 * t + 1] == x ? 1 : 2; }
  // The third triangle around the degree-3 vertex x of the edge 3t+i = a -> b
  // (t = (a, b, c)): across c -> a when x = a, across b -> c when x = b.
  FF_HD uint32_t third(uint32_t t, int i, Index x) const {
    return opp[3 * t + (x == tv[3 * t + nx(i)] ? pv(i) : nx(i))] / 3;
  }

  // Phase B of every change: the outer half-edge h of a changed triangle holds
  // the old twin; make the two twins of each other, through the other side's
  // remap when the other side changed this round too (it then links its side).
  FF_HD void link_outer(uint32_t h, uint32_t epoch) const {
    const uint32_t o = opp[h];
    if (stamp[o / 3] == epoch) {
      opp[h] = remap[o];
    } else {
      opp[o] = h;
    }
  }
};

// The round's claim value: rounds count down in the high word, so a stale
// claim of an earlier round is larger than any claim of this one (no reset).
FF_HD inline uint64_t claim_key(uint32_t epoch, uint32_t j) {
  return (static_cast<uint64_t>(~epoch) << 32) | j;
}

// ---- insertion rounds (§5.3) ----------------------------------------------------

// A point's vote for its triangle: dev::Vote, dev::IsWinner (elections.cuh).

// 1-3 flip of winner q: point p into t = (a, b, c) — t becomes (a, b, p), the
// new slots (b, c, p) and (c, a, p) are base + 2q and base + 2q + 1
// (tri::flip13). Phase A: the three triangles with their inner links, the old
// outer twins kept in the outer half-edges (3x+2), the remap of t's old
// half-edges; the triangles become the first round of flip candidates.
struct Split13 {
  Mesh m;
  const uint32_t* winners;
  const uint32_t* loc;
  uint64_t* best;
  uint32_t* cand;  // 3 per winner
  uint32_t base, epoch;
  FF_HD void operator()(uint32_t q) const {
    const uint32_t p = winners[q], t = loc[p];
    best[t] = ~uint64_t{0};
    const uint32_t t1 = base + 2 * q, t2 = t1 + 1;
    const Index a = m.tv[3 * t], b = m.tv[3 * t + 1], c = m.tv[3 * t + 2];
    const uint32_t na = m.opp[3 * t], nb = m.opp[3 * t + 1], nc = m.opp[3 * t + 2];
    m.tv[3 * t + 2] = p;
    m.opp[3 * t] = 3 * t1 + 1, m.opp[3 * t + 1] = 3 * t2, m.opp[3 * t + 2] = nc;
    m.tv[3 * t1] = b, m.tv[3 * t1 + 1] = c, m.tv[3 * t1 + 2] = p;
    m.opp[3 * t1] = 3 * t2 + 1, m.opp[3 * t1 + 1] = 3 * t, m.opp[3 * t1 + 2] = na;
    m.tv[3 * t2] = c, m.tv[3 * t2 + 1] = a, m.tv[3 * t2 + 2] = p;
    m.opp[3 * t2] = 3 * t + 1, m.opp[3 * t2 + 1] = 3 * t1, m.opp[3 * t2 + 2] = nb;
    m.alive[t1] = m.alive[t2] = 1;
    m.remap[3 * t] = 3 * t1 + 2, m.remap[3 * t + 1] = 3 * t2 + 2, m.remap[3 * t + 2] = 3 * t + 2;
    m.stamp[t] = epoch, m.kind[t] = kSplit, m.partner[t] = t1;
    m.deg[p] = 3;
    atomic_fetch_add(m.deg + a, 1u), atomic_fetch_add(m.deg + b, 1u), atomic_fetch_add(m.deg + c, 1u);
    cand[3 * q] = t, cand[3 * q + 1] = t1, cand[3 * q + 2] = t2;
  }
};

struct Link13 {
  Mesh m;
  const uint32_t* cand;
  uint32_t epoch;
  FF_HD void operator()(uint32_t q) const {
    for (int k = 0; k < 3; ++k) m.link_outer(3 * cand[3 * q + k] + 2, epoch);
  }
};

// After a round: the point's new triangle when its triangle changed in round
// `epoch` (1-3, 2-2 or 3-1 flip), then §5.3's early discard when the new
// triangle is real and proves the point redundant. In two passes over the
// active list (two_pass.cuh): the result is the point's new loc, kNil when it
// stays; a point the first pass cannot place keeps its loc (the second pass
// reads it) and is marked in pending[i], which is 0 again after the second
// pass (all of it is 0 between calls).
struct Relocate : OnGeo {
  Mesh m;
  const uint32_t* active;
  uint32_t* loc;
  uint8_t* pending;
  uint32_t epoch;
  template <class S>
  FF_HD uint32_t decide(std::size_t i, S& sg) const {
    const uint32_t p = active[i];
    uint32_t t = loc[p];
    if (t >= kDiscarded || m.stamp[t] != epoch) return kNil;  // discarded in an earlier flip round
    switch (m.kind[t]) {
      case kSplit: {  // ffrt.cpp insert_points: the rays r->a, r->b, r->c split the old triangle
        const uint32_t t1 = m.partner[t], t2 = t1 + 1;
        const Index a = m.tv[3 * t], b = m.tv[3 * t + 1], r = m.tv[3 * t + 2], c = m.tv[3 * t1 + 1];
        if (r == p) return kInserted;
        if (orient(sg, r, b, p) < 0)
          t = orient(sg, r, a, p) > 0 ? t : t2;
        else
          t = orient(sg, r, c, p) < 0 ? t1 : t2;
        break;
      }
      case kPair:  // the new edge is 3t+1, from corner 2 to corner 0 of both
        if (orient(sg, m.tv[3 * t + 2], m.tv[3 * t], p) < 0) t = m.partner[t];
        break;
      case kMerged: t = m.partner[t]; break;
      default: break;
    }
    if (m.is_real(t) && sg.power(m.tv[3 * t], m.tv[3 * t + 1], m.tv[3 * t + 2], p) < 0) return kDiscarded;
    return t;
  }
  FF_HD void write(std::size_t i, uint32_t r) const {
    if (r != kNil) loc[active[i]] = r;
    if (pending[i]) pending[i] = 0;
  }
  FF_HD void mark(std::size_t i) const { pending[i] = 1; }
  FF_HD bool marked(std::size_t i) const { return pending[i] != 0; }
};

struct StillActive {
  const uint32_t* loc;
  FF_HD bool operator()(uint32_t p) const { return loc[p] < kDiscarded; }
};
struct IsDiscarded {
  const uint32_t* loc;
  FF_HD bool operator()(uint32_t p) const { return loc[p] == kDiscarded; }
};

// Initial location (§5.3): the triangle of the initial four containing p.
// In two passes over the active list (kNil in loc: the first pass's mark).
struct LocateInitial : OnGeo {
  Mesh m;
  const uint32_t* active;
  uint32_t* loc;
  template <class S>
  FF_HD uint32_t decide(std::size_t i, S& sg) const {
    const uint32_t p = active[i];
    uint32_t t = 0;
    for (; t < 3; ++t) {
      const Index* x = m.tv + 3 * t;
      if (orient(sg, x[0], x[1], p) > 0 && orient(sg, x[1], x[2], p) > 0 && orient(sg, x[2], x[0], p) > 0) break;
    }
    return t;  // the last one when none of the first three contains p
  }
  FF_HD void write(std::size_t i, uint32_t t) const { loc[active[i]] = t; }
  FF_HD void mark(std::size_t i) const { loc[active[i]] = kNil; }
  FF_HD bool marked(std::size_t i) const { return loc[active[i]] == kNil; }
};

// ---- flip-flop rounds (Algorithm 5) ------------------------------------------------

struct MarkListed {
  uint32_t* in_list;
  uint32_t epoch;
  FF_HD void operator()(uint32_t t) const { in_list[t] = epoch; }
};

// Lines 5-19 for candidate j = edge 3t+i of the listed triangle t = list[j/3]
// (skipped when the twin's triangle is listed too and smaller: the edge is
// checked once), the reference's decide(): the action in act[j], its vertex in
// inner[j]; an action claims the triangles it would touch. In two passes
// (two_pass.cuh; kUndecided in act[j]: the first pass's mark), the claims
// made by the pass that decides.
constexpr uint8_t kUndecided = 4;
struct Decision {
  uint8_t act;
  uint32_t x;
};
struct Decide : OnGeo {
  Mesh m;
  const uint32_t* list;
  uint8_t* act;
  uint32_t* inner;
  uint32_t epoch;

  template <class S>
  FF_HD uint8_t decide_edge(S& sg, uint32_t t, int i, uint32_t& x_out) const {
    const uint32_t o = m.opp[3 * t + i], u = o / 3;
    if (m.in_list[u] == epoch && u < t) return kNone;
    const Index a = m.tv[3 * t + nx(i)], b = m.tv[3 * t + pv(i)], c = m.tv[3 * t + i], dd = m.tv[o];
    // line 5: x, the labelled vertex of smallest index in the induced subcomplex
    Index x = kNil;
    const Index q[4] = {a, b, c, dd};
    for (int k = 0; k < 4; ++k)
      if (q[k] != g.n && m.label[q[k]] && q[k] < x) x = q[k];
    // line 6: a 3-1 edge (tri::classify)
    Index inner31 = kNil;
    if (m.deg[a] == 3 && orient(sg, b, c, dd) > 0) inner31 = a;
    int at_a = 2;
    if (inner31 == kNil && m.deg[b] == 3) {
      at_a = orient(sg, c, a, dd);
      if (at_a > 0) inner31 = b;
    }
    if (inner31 != kNil) {
      x_out = inner31;
      if (m.label[inner31] || !locally_regular(sg, a, b, c, dd)) return kFlip31;  // lines 7-9
      return kNone;
    }
    if (at_a == 2) at_a = orient(sg, c, a, dd);
    const int at_b = orient(sg, dd, b, c);
    if (at_a > 0 && at_b > 0) {  // line 11: a 2-2 flippable edge
      if (x == kNil) return locally_regular(sg, a, b, c, dd) ? kNone : kFlip22;  // lines 12-13
      return x == a || x == b ? kFlip22 : kNone;                                // lines 14-15
    }
    // lines 16-18: unflippable; the reflex corner lies in the triangle of the other three
    const Index r = at_a < 0 ? a : b;
    if (!m.label[r] && !locally_regular(sg, a, b, c, dd)) {
      x_out = r;
      return kLabel;
    }
    return kNone;
  }

  template <class S>
  FF_HD Decision decide(std::size_t j, S& sg) const {
    const uint32_t t = list[j / 3];
    Decision r{kNone, kNil};
    if (m.alive[t]) r.act = decide_edge(sg, t, static_cast<int>(j % 3), r.x);
    return r;
  }
  FF_HD void write(std::size_t j, const Decision& r) const {
    act[j] = r.act;
    inner[j] = r.x;
    if (r.act == kNone) return;
    const uint32_t t = list[j / 3];
    const int i = static_cast<int>(j % 3);
    const uint64_t key = claim_key(epoch, static_cast<uint32_t>(j));
    const uint32_t u = m.opp[3 * t + i] / 3;
    atomic_fetch_min(m.claim + t, key);
    atomic_fetch_min(m.claim + u, key);
    if (r.act == kFlip31) atomic_fetch_min(m.claim + m.third(t, i, r.x), key);
  }
  FF_HD void mark(std::size_t j) const { act[j] = kUndecided; }
  FF_HD bool marked(std::size_t j) const { return act[j] == kUndecided; }
};

// The decided candidates of a round, as the later passes read them.
struct Candidates {
  Mesh m;
  const uint32_t* list;
  uint8_t* act;
  const uint32_t* inner;
  uint32_t epoch;
  FF_HD uint32_t tri(uint32_t j) const { return list[j / 3]; }
  FF_HD int edge(uint32_t j) const { return static_cast<int>(j % 3); }
};

struct Won {
  Candidates c;
  FF_HD void operator()(uint32_t j) const {
    const uint8_t a = c.act[j];
    if (a == kNone) return;
    const uint32_t t = c.tri(j);
    const int i = c.edge(j);
    const uint64_t key = claim_key(c.epoch, j);
    const Mesh& m = c.m;
    bool won = m.claim[t] == key && m.claim[m.opp[3 * t + i] / 3] == key;
    if (won && a == kFlip31) won = m.claim[m.third(t, i, c.inner[j])] == key;
    if (won) c.act[j] = a | kWon;
  }
};

// Phase A of the winners: the flips of tri::flip22 / tri::flip31 on their own
// triangles, the old outer twins kept in the new outer half-edges, the remap of
// the old outer half-edges; labelling (line 18).
struct Apply {
  Candidates c;
  FF_HD void operator()(uint32_t j) const {
    const uint8_t a = c.act[j];
    if (!(a & kWon)) return;
    switch (a & kKind) {
      case kFlip22: flip22(c.tri(j), c.edge(j)); break;
      case kFlip31: flip31(c.tri(j), c.inner[j]); break;
      case kLabel:
        if (atomic_exchange(c.m.label + c.inner[j], 1u) == 0) c.act[j] = a | kFirst;
        break;
      default: break;
    }
  }

  // edge a -> b of t = (a, b, c) and u = (b, a, d) become t = (c, a, d),
  // u = (d, b, c): the new edge is d -> c (3t+1) / c -> d (3u+1).
  FF_HD void flip22(uint32_t t, int i) const {
    const Mesh& m = c.m;
    const uint32_t epoch = c.epoch;
    const uint32_t o = m.opp[3 * t + i], u = o / 3;
    const int k = static_cast<int>(o % 3);
    const Index a = m.tv[3 * t + nx(i)], b = m.tv[3 * t + pv(i)], c = m.tv[3 * t + i], d = m.tv[3 * u + k];
    const uint32_t n_bc = m.opp[3 * t + nx(i)], n_ca = m.opp[3 * t + pv(i)];
    const uint32_t n_ad = m.opp[3 * u + nx(k)], n_db = m.opp[3 * u + pv(k)];
    m.remap[3 * t + nx(i)] = 3 * u, m.remap[3 * t + pv(i)] = 3 * t + 2;
    m.remap[3 * u + nx(k)] = 3 * t, m.remap[3 * u + pv(k)] = 3 * u + 2;
    m.tv[3 * t] = c, m.tv[3 * t + 1] = a, m.tv[3 * t + 2] = d;
    m.opp[3 * t] = n_ad, m.opp[3 * t + 1] = 3 * u + 1, m.opp[3 * t + 2] = n_ca;
    m.tv[3 * u] = d, m.tv[3 * u + 1] = b, m.tv[3 * u + 2] = c;
    m.opp[3 * u] = n_bc, m.opp[3 * u + 1] = 3 * t + 1, m.opp[3 * u + 2] = n_db;
    m.stamp[t] = m.stamp[u] = epoch;
    m.kind[t] = m.kind[u] = kPair;
    m.partner[t] = u, m.partner[u] = t;
    atomic_fetch_add(m.deg + a, ~0u), atomic_fetch_add(m.deg + b, ~0u);
    atomic_fetch_add(m.deg + c, 1u), atomic_fetch_add(m.deg + d, 1u);
  }

  // the degree-3 vertex x of t0 = t removed: t0 := (b, c, d), the other two
  // triangles around x die.
  FF_HD void flip31(uint32_t t0, Index x) const {
    const Mesh& m = c.m;
    const uint32_t epoch = c.epoch;
    const int k0 = m.corner(t0, x);
    const Index b = m.tv[3 * t0 + nx(k0)], c = m.tv[3 * t0 + pv(k0)];
    const uint32_t t1 = m.opp[3 * t0 + nx(k0)] / 3;  // across c -> x
    const int k1 = m.corner(t1, x);
    const Index d = m.tv[3 * t1 + pv(k1)];
    const uint32_t t2 = m.opp[3 * t1 + nx(k1)] / 3;  // across d -> x
    const int k2 = m.corner(t2, x);
    const uint32_t n_bc = m.opp[3 * t0 + k0], n_cd = m.opp[3 * t1 + k1], n_db = m.opp[3 * t2 + k2];
    m.remap[3 * t0 + k0] = 3 * t0 + 2, m.remap[3 * t1 + k1] = 3 * t0, m.remap[3 * t2 + k2] = 3 * t0 + 1;
    m.tv[3 * t0] = b, m.tv[3 * t0 + 1] = c, m.tv[3 * t0 + 2] = d;
    m.opp[3 * t0] = n_cd, m.opp[3 * t0 + 1] = n_db, m.opp[3 * t0 + 2] = n_bc;
    m.alive[t1] = m.alive[t2] = 0;
    m.stamp[t0] = m.stamp[t1] = m.stamp[t2] = epoch;
    m.kind[t0] = kKept, m.kind[t1] = m.kind[t2] = kMerged;
    m.partner[t1] = m.partner[t2] = t0;
    m.deg[x] = 0;
    atomic_fetch_add(m.deg + b, ~0u), atomic_fetch_add(m.deg + c, ~0u), atomic_fetch_add(m.deg + d, ~0u);
  }
};

// Phase B of the winners: link the outer half-edges (Mesh::link_outer).
struct LinkFlips {
  Candidates c;
  FF_HD void operator()(uint32_t j) const {
    const uint8_t a = c.act[j];
    if (!(a & kWon)) return;
    const uint32_t t = c.tri(j), epoch = c.epoch;
    const Mesh& m = c.m;
    if ((a & kKind) == kFlip22) {
      const uint32_t u = m.partner[t];
      m.link_outer(3 * t, epoch), m.link_outer(3 * t + 2, epoch);
      m.link_outer(3 * u, epoch), m.link_outer(3 * u + 2, epoch);
    } else if ((a & kKind) == kFlip31) {
      for (int k = 0; k < 3; ++k) m.link_outer(3 * t + k, epoch);
    }
  }
};

// The next round's candidates of candidate j (the edges Algorithm 5 pushes, as
// the triangles holding them): a 2-2 flip's two triangles (lines 13, 15), a
// 3-1 flip's new triangle (line 9), the star of a newly labelled vertex (line
// 19), and the own triangle of an action that lost a claim (to be retried).
struct PushCount {
  Candidates c;
  FF_HD uint32_t operator()(uint32_t j) const {
    const uint8_t a = c.act[j];
    if (a == kNone) return 0;
    if (!(a & kWon)) return c.m.alive[c.tri(j)] ? 1 : 0;
    switch (a & kKind) {
      case kFlip22: return 2;
      case kFlip31: return 1;
      default: return (a & kFirst) ? c.m.deg[c.inner[j]] : 0;
    }
  }
};

struct PushWrite {
  Candidates c;
  const uint32_t* offset;
  uint32_t* out;
  FF_HD void operator()(uint32_t j) const {
    const uint8_t a = c.act[j];
    if (a == kNone) return;
    const Mesh& m = c.m;
    const uint32_t* inner = c.inner;
    const uint32_t t = c.tri(j);
    uint32_t* o = out + offset[j];
    if (!(a & kWon)) {
      if (m.alive[t]) o[0] = t;
      return;
    }
    switch (a & kKind) {
      case kFlip22: o[0] = t, o[1] = m.partner[t]; break;
      case kFlip31: o[0] = t; break;
      default:
        if (a & kFirst) {  // the star of x, counter-clockwise (tri::link's walk)
          const Index x = inner[j];
          uint32_t s = t;
          for (uint32_t k = 0, deg = m.deg[x]; k < deg; ++k) {
            o[k] = s;
            s = m.opp[3 * s + nx(m.corner(s, x))] / 3;
          }
        }
        break;
    }
  }
};

struct ActionIs {
  const uint8_t* act;
  uint8_t kind;
  FF_HD bool operator()(uint32_t j) const { return (act[j] & kWon) && (act[j] & kKind) == kind; }
};
struct HasAction {
  const uint8_t* act;
  FF_HD uint32_t operator()(uint32_t j) const { return act[j] != kNone; }
};

// ---- output ------------------------------------------------------------------------
struct Tri3 {
  Index v[3];
};
struct IsRealAlive {
  Mesh m;
  FF_HD bool operator()(uint32_t t) const { return m.alive[t] && m.is_real(t); }
};
struct Canonical {  // input indices, rotated to the smallest (DESIGN.md)
  Mesh m;
  const Index* id;
  FF_HD Tri3 operator()(uint32_t t) const {
    const Index a = id[m.tv[3 * t]], b = id[m.tv[3 * t + 1]], c = id[m.tv[3 * t + 2]];
    if (a < b && a < c) return {{a, b, c}};
    if (b < c) return {{b, c, a}};
    return {{c, a, b}};
  }
};
struct TriLess {
  FF_HD bool operator()(const Tri3& x, const Tri3& y) const {
    if (x.v[0] != y.v[0]) return x.v[0] < y.v[0];
    if (x.v[1] != y.v[1]) return x.v[1] < y.v[1];
    return x.v[2] < y.v[2];
  }
};
struct Alive {
  const uint8_t* alive;
  FF_HD bool operator()(uint32_t t) const { return alive[t] != 0; }
};
struct NotInitial {
  Index a, b, c;
  FF_HD bool operator()(uint32_t p) const { return p != a && p != b && p != c; }
};
struct LabelledVertex {
  const uint32_t* deg;
  const uint32_t* label;
  FF_HD bool operator()(uint32_t v) const { return deg[v] != 0 && label[v] != 0; }
};

// ---- sort (Morton order for locality) -----------------------------------------------
struct Box {
  double lo[2], hi[2];
};
struct PointBox {
  const double* xy;
  FF_HD Box operator()(uint32_t i) const {
    return {{xy[2 * i], xy[2 * i + 1]}, {xy[2 * i], xy[2 * i + 1]}};
  }
};
struct BoxUnion {
  FF_HD Box operator()(const Box& a, const Box& b) const {
    return {{a.lo[0] < b.lo[0] ? a.lo[0] : b.lo[0], a.lo[1] < b.lo[1] ? a.lo[1] : b.lo[1]},
            {a.hi[0] > b.hi[0] ? a.hi[0] : b.hi[0], a.hi[1] > b.hi[1] ? a.hi[1] : b.hi[1]}};
  }
};
// Morton key: 16 bits of each coordinate on the bounding box's grid, bits
// interleaved; scaled by halves so that no difference overflows (only the
// locality depends on the key, never the answer).
struct MortonKey {
  const double* xy;
  Box box;
  FF_HD static uint32_t spread(uint32_t x) {
    x &= 0xffffu;
    x = (x | (x << 8)) & 0x00ff00ffu;
    x = (x | (x << 4)) & 0x0f0f0f0fu;
    x = (x | (x << 2)) & 0x33333333u;
    return (x | (x << 1)) & 0x55555555u;
  }
  FF_HD uint32_t cell(double x, int k) const {
    const double span = box.hi[k] * 0.5 - box.lo[k] * 0.5;
    double f = span > 0 ? (x * 0.5 - box.lo[k] * 0.5) / span : 0.0;
    f = f >= 0 ? (f <= 1 ? f : 1.0) : 0.0;
    return static_cast<uint32_t>(f * 65535.0);
  }
  FF_HD uint32_t operator()(uint32_t i) const { return (spread(cell(xy[2 * i], 0)) << 1) | spread(cell(xy[2 * i + 1], 1)); }
};
struct Gather {
  const double* xy_in;
  const double* w_in;  // null: unweighted
  const uint32_t* order;
  double* xy;
  double* w;
  uint32_t* rank;  // input index -> vertex
  FF_HD void operator()(uint32_t i) const {
    const uint32_t s = order[i];
    xy[2 * i] = xy_in[2 * s], xy[2 * i + 1] = xy_in[2 * s + 1];
    w[i] = w_in ? w_in[s] : 0.0;
    rank[s] = i;
  }
};

// ---- the whole kernel -------------------------------------------------------------------
using backend::raw;
using backend::read_one;

// OpenMP: one thread below this many items (backend.cuh).
constexpr std::size_t kParallelFrom = std::size_t{1} << 12;

template <class F>
void step(std::size_t count, F&& f) {
  backend::run_step<kParallelFrom>(count, f);
}

template <class F>
void for_range(std::size_t count, const F& f) {
  backend::for_range<kParallelFrom>(count, f);
}

// f's two passes over [0, count) (two_pass.cuh)
template <class F>
void two_passes(std::size_t count, const F& f) {
  for_range(count, dev::Pass<F, false>{f});
  for_range(count, dev::Pass<F, true>{f});
}

struct Buffers {
  // points (n) and vertices (n + 1)
  backend::Buffer<double> xy_in, w_in, xy, w;
  backend::Buffer<uint32_t> order, rank, keys, deg, label, loc, active, active2, winners;
  // triangle slots (cap) and half-edges (3 cap)
  backend::Buffer<Index> tv;
  backend::Buffer<uint32_t> opp, remap, stamp, partner, in_list, list, list2, inner, offset;
  backend::Buffer<uint8_t> alive, kind, act, pending;  // pending: per active point (Relocate)
  backend::Buffer<uint64_t> claim, best;
};

inline std::vector<Triangle> run(const PointSet& ps, ref::Rt2Stats* stats, cpu::StageTimes* times, const char* who) {
  ref::require_plane(ps, who);
  backend::require_device(who);
  const std::size_t n = ps.size();
  // slots: 4 initial + 2 per insertion; half-edge ids 3 * slots must stay below kDiscarded
  if (n > (std::size_t{0xfffffff0u} / 3 - 4) / 2)
    throw kernels::DeviceMemoryError(std::string(who) + ": " + std::to_string(n) +
                                     " points exceed the 32-bit triangle ids of this kernel");
  const std::size_t cap = 4 + 2 * n;
  // candidate lists: at most cap listed triangles, 3 candidate edges each;
  // pushes of one round: the winners' triangles (disjoint: <= cap), the stars
  // of the newly labelled vertices (each triangle in at most 3: <= 3 cap), the
  // losers' own triangles (one per candidate: <= 3 cap)
  const std::size_t list_cap = 7 * cap;
  ref::Rt2Stats st;
  cpu::StageClock clock(times);
  Buffers B;
  try {
    B.xy_in.resize(2 * n), B.xy.resize(2 * n), B.w.resize(n);
    if (ps.weighted) B.w_in.resize(n);
    B.order.resize(n), B.rank.resize(n), B.keys.resize(n), B.deg.resize(n + 1), B.label.resize(n + 1);
    B.loc.resize(n), B.active.resize(n), B.active2.resize(n), B.winners.resize(n), B.pending.resize(n);
    B.tv.resize(3 * cap), B.opp.resize(3 * cap), B.remap.resize(3 * cap);
    B.stamp.resize(cap), B.partner.resize(cap), B.in_list.resize(cap);
    B.list.resize(list_cap), B.list2.resize(list_cap), B.inner.resize(3 * cap), B.offset.resize(3 * cap + 1);
    B.alive.resize(cap), B.kind.resize(cap), B.act.resize(3 * cap);
    B.claim.resize(cap), B.best.resize(cap);
  } catch (const std::bad_alloc&) {
    throw kernels::DeviceMemoryError(std::string(who) + ": " + std::to_string(n) +
                                     " points do not fit in device memory (about " +
                                     std::to_string((n * 330) >> 20) + " MiB needed)");
  }
  // ---- upload
  thrust::copy(ps.coords.begin(), ps.coords.end(), B.xy_in.begin());
  if (ps.weighted) thrust::copy(ps.weights.begin(), ps.weights.end(), B.w_in.begin());
  clock.mark("upload");

  // ---- sort: Morton order; the initial extended triangulation
  const thrust::counting_iterator<uint32_t> first(0);
  Box box{};
  step(n, [&](auto policy) {
    // the initial value is made on the host: the empty box (BoxUnion's
    // identity; every coordinate is finite), never a point read from the
    // buffer, which is device memory in the CUDA build
    const Box empty{{HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL}};
    box = thrust::transform_reduce(policy, first, first + n, PointBox{raw(B.xy_in)}, empty, BoxUnion());
  });
  step(n, [&](auto policy) {
    thrust::transform(policy, first, first + n, B.keys.begin(), MortonKey{raw(B.xy_in), box});
    thrust::sequence(policy, B.order.begin(), B.order.end());
    thrust::stable_sort_by_key(policy, B.keys.begin(), B.keys.end(), B.order.begin());
  });
  for_range(n, Gather{raw(B.xy_in), ps.weighted ? raw(B.w_in) : nullptr, raw(B.order), raw(B.xy), raw(B.w),
                      raw(B.rank)});
  std::vector<Index> all(n);
  std::iota(all.begin(), all.end(), Index{0});
  const auto init = ref::ffrt::initial_triangle(ps, all);  // counter-clockwise, throws on collinear input
  const Index v = static_cast<Index>(n);
  const Index a0 = read_one(B.rank, init[0]), b0 = read_one(B.rank, init[1]), c0 = read_one(B.rank, init[2]);

  Geo g{};
  g.xy = raw(B.xy), g.w = raw(B.w), g.id = raw(B.order), g.n = v;
  {
    const double* src[4] = {ps.point(init[0]), ps.point(init[1]), ps.point(init[2]), ps.point(init[2])};
    const pred::RationalPoint s = pred::RationalPoint::centroid(src, 4, 2);
    for (int k = 0; k < 8; ++k) g.ksrc[k] = s.src[k];
    g.kapprox[0] = s.approx[0], g.kapprox[1] = s.approx[1];
  }
  Mesh m{};
  m.tv = raw(B.tv), m.opp = raw(B.opp), m.alive = raw(B.alive), m.deg = raw(B.deg), m.label = raw(B.label);
  m.stamp = raw(B.stamp), m.kind = raw(B.kind), m.partner = raw(B.partner), m.remap = raw(B.remap);
  m.claim = raw(B.claim), m.in_list = raw(B.in_list), m.n = v;
  step(cap, [&](auto policy) {
    thrust::fill(policy, B.alive.begin(), B.alive.end(), uint8_t{0});
    thrust::fill(policy, B.stamp.begin(), B.stamp.end(), 0u);
    thrust::fill(policy, B.in_list.begin(), B.in_list.end(), 0u);
    thrust::fill(policy, B.claim.begin(), B.claim.end(), ~uint64_t{0});
    thrust::fill(policy, B.best.begin(), B.best.end(), ~uint64_t{0});
    thrust::fill(policy, B.deg.begin(), B.deg.end(), 0u);
    thrust::fill(policy, B.label.begin(), B.label.end(), 0u);
    thrust::fill(policy, B.pending.begin(), B.pending.end(), uint8_t{0});
  });
  {
    // tri::make_initial: (a, b, c) and, for each edge p -> q, the virtual (q, p, v)
    const Index tv0[12] = {a0, b0, c0, b0, a0, v, c0, b0, v, a0, c0, v};
    uint32_t opp0[12];
    for (uint32_t h = 0; h < 12; ++h) {
      const uint32_t t = h / 3, i = h % 3;
      const Index p = tv0[3 * t + (i + 1) % 3], q = tv0[3 * t + (i + 2) % 3];
      for (uint32_t k = 0; k < 12; ++k)
        if (tv0[3 * (k / 3) + (k % 3 + 1) % 3] == q && tv0[3 * (k / 3) + (k % 3 + 2) % 3] == p) opp0[h] = k;
    }
    const uint8_t alive0[4] = {1, 1, 1, 1};
    const uint32_t deg0[1] = {3};
    thrust::copy(tv0, tv0 + 12, B.tv.begin());
    thrust::copy(opp0, opp0 + 12, B.opp.begin());
    thrust::copy(alive0, alive0 + 4, B.alive.begin());
    for (Index x : {a0, b0, c0, v}) thrust::copy(deg0, deg0 + 1, B.deg.begin() + x);
  }
  // the active points: all but the initial three, each located (§5.3)
  std::size_t n_active = 0;
  {
    step(n, [&](auto policy) {
      n_active = static_cast<std::size_t>(
          thrust::copy_if(policy, first, first + n, B.active.begin(), NotInitial{a0, b0, c0}) - B.active.begin());
    });
    two_passes(n_active, LocateInitial{{g}, m, raw(B.active), raw(B.loc)});
  }
  uint32_t slots = 4;
  uint32_t epoch = 0;
  clock.mark("sort");

  // ---- flip-flop rounds on the listed triangles until no candidate is left;
  // returns the number of actions
  auto flip_flop = [&](std::size_t listed) {
    std::size_t actions = 0;
    while (listed > 0) {
      ++epoch;
      const std::size_t nc = 3 * listed;
      step(listed, [&](auto policy) {
        thrust::for_each(policy, B.list.begin(), B.list.begin() + listed, MarkListed{raw(B.in_list), epoch});
      });
      two_passes(nc, Decide{{g}, m, raw(B.list), raw(B.act), raw(B.inner), epoch});
      const Candidates cands{m, raw(B.list), raw(B.act), raw(B.inner), epoch};
      for_range(nc, Won{cands});
      for_range(nc, Apply{cands});
      for_range(nc, LinkFlips{cands});
      std::size_t f22 = 0, f31 = 0, lab = 0, checked = 0;
      step(nc, [&](auto policy) {
        f22 = thrust::count_if(policy, first, first + nc, ActionIs{raw(B.act), kFlip22});
        f31 = thrust::count_if(policy, first, first + nc, ActionIs{raw(B.act), kFlip31});
        lab = thrust::count_if(policy, first, first + nc, ActionIs{raw(B.act), kLabel});
        checked = thrust::transform_reduce(policy, first, first + nc, HasAction{raw(B.act)}, uint32_t{0},
                                           thrust::plus<uint32_t>());
      });
      st.flips_2_2 += f22, st.flips_3_1 += f31, st.labelled_redundant += lab, st.candidates += nc;
      actions += checked;
      if (f22 + f31 > 0 && n_active > 0)
        two_passes(n_active, Relocate{{g}, m, raw(B.active), raw(B.loc), raw(B.pending), epoch});
      // the next list: counts, exclusive scan, writes, sort + unique
      std::size_t pushed = 0;
      step(nc, [&](auto policy) {
        thrust::transform(policy, first, first + nc, B.offset.begin(),
                          PushCount{cands});
        thrust::fill(policy, B.offset.begin() + nc, B.offset.begin() + nc + 1, 0u);
        thrust::exclusive_scan(policy, B.offset.begin(), B.offset.begin() + nc + 1, B.offset.begin());
      });
      pushed = read_one(B.offset, nc);
      for_range(nc, PushWrite{cands, raw(B.offset), raw(B.list2)});
      step(pushed, [&](auto policy) {
        thrust::sort(policy, B.list2.begin(), B.list2.begin() + pushed);
        listed = static_cast<std::size_t>(thrust::unique(policy, B.list2.begin(), B.list2.begin() + pushed) -
                                          B.list2.begin());
      });
      B.list.swap(B.list2);
    }
    return actions;
  };

  // ---- insertion rounds (§5.3), each followed by flip-flop
  for (;;) {
    // the points inserted or discarded (§5.3) since the last round leave
    step(n_active, [&](auto policy) {
      st.discarded_early += static_cast<std::size_t>(
          thrust::count_if(policy, B.active.begin(), B.active.begin() + n_active, IsDiscarded{raw(B.loc)}));
      n_active = static_cast<std::size_t>(thrust::copy_if(policy, B.active.begin(), B.active.begin() + n_active,
                                                          B.active2.begin(), StillActive{raw(B.loc)}) -
                                          B.active2.begin());
    });
    B.active.swap(B.active2);
    if (n_active == 0) break;
    ++epoch;
    ++st.rounds;
    step(n_active, [&](auto policy) {
      thrust::for_each(policy, B.active.begin(), B.active.begin() + n_active, Vote{raw(B.loc), raw(B.best)});
    });
    std::size_t k = 0;
    step(n_active, [&](auto policy) {
      k = static_cast<std::size_t>(thrust::copy_if(policy, B.active.begin(), B.active.begin() + n_active,
                                                   B.winners.begin(), IsWinner{raw(B.loc), raw(B.best)}) -
                                   B.winners.begin());
    });
    for_range(k, Split13{m, raw(B.winners), raw(B.loc), raw(B.best), raw(B.list), slots, epoch});
    for_range(k, Link13{m, raw(B.list), epoch});
    slots += static_cast<uint32_t>(2 * k);
    st.flips_1_3 += k;
    two_passes(n_active, Relocate{{g}, m, raw(B.active), raw(B.loc), raw(B.pending), epoch});
    clock.mark("insertion rounds");
    flip_flop(3 * k);
    clock.mark("flip-flop");
  }
  // ---- the final sweep: every edge (Algorithm 5 line 2) until nothing is left to do
  for (;;) {
    std::size_t listed = 0;
    step(slots, [&](auto policy) {
      listed = static_cast<std::size_t>(
          thrust::copy_if(policy, first, first + slots, B.list.begin(), Alive{raw(B.alive)}) - B.list.begin());
    });
    if (flip_flop(listed) == 0) break;
  }
  std::size_t left = 0;
  step(n + 1, [&](auto policy) {
    left = thrust::count_if(policy, first, first + n + 1, LabelledVertex{raw(B.deg), raw(B.label)});
  });
  if (left > 0) throw std::logic_error(std::string(who) + ": flip-flop ended with a labelled vertex");
  clock.mark("flip-flop");

  // ---- output: canonical real triangles, sorted
  std::size_t nt = 0;
  backend::Buffer<Tri3> out;
  try {
    out.resize(slots);
  } catch (const std::bad_alloc&) {
    throw kernels::DeviceMemoryError(std::string(who) + ": the output does not fit in device memory");
  }
  step(slots, [&](auto policy) {
    nt = static_cast<std::size_t>(thrust::copy_if(policy, first, first + slots, B.list.begin(), IsRealAlive{m}) -
                                  B.list.begin());
    thrust::transform(policy, B.list.begin(), B.list.begin() + nt, out.begin(), Canonical{m, raw(B.order)});
    thrust::sort(policy, out.begin(), out.begin() + nt, TriLess());
  });
  clock.mark("output");
  const std::vector<Tri3> host = backend::to_host(out, nt);
  std::vector<Triangle> result(nt);
  static_assert(sizeof(Tri3) == sizeof(Triangle), "Tri3 and Triangle are three packed ids");
  if (nt) std::memcpy(result.data(), host.data(), nt * sizeof(Tri3));
  clock.mark("download");
  if (stats) *stats = st;
  return result;
}

}  // namespace rt2_detail

std::vector<Triangle> rt2_ffrt(const PointSet& ps, ref::Rt2Stats* stats, cpu::StageTimes* times) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  return rt2_detail::run(ps, stats, times, "rt2 (omp)");
#else
  return rt2_detail::run(ps, stats, times, "rt2 (cuda)");
#endif
}

}  // namespace flipflop::FF_KERNELS_NS

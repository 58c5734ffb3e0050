// rt3.cuh — the one source of the GPU 3D regular triangulation (rt3.hpp
// explains the task). Included by rt3_omp.cpp (thrust's OpenMP backend, host
// compiler) and rt3_cuda.cu (nvcc), each defining FF_KERNELS_NS to the
// namespace it implements; the helpers live in FF_KERNELS_NS::rt3_detail.
//
// ============================================================================
// The data (flat arrays; the tetrahedron arrays grow between rounds)
// ============================================================================
// Vertices 0..n-1 are the input points in Morton order (coordinates, weights
// and input indices copied in that order; the input index is the SoS index of
// predicates.hpp); vertex n is the virtual vertex v of the extended
// triangulation (thesis §2.1): with v the triangulation is a triangulated
// 3-sphere, the boundary complex of Q = conv(lifted points) + the upward ray
// (kernels_cpu/rt3/rt3.cpp, "Insertion"). Tetrahedron slot t has the corners
// tv[4t..4t+3] and the links tn[4t+i] = 4u+j (u the neighbour across the facet
// opposite corner i, j u's corner opposite that facet) — the layout of
// cpu::Rt3Witness, so the certificate is these arrays as they are. A real
// slot is positive (orient3d > 0 under SoS); a virtual one gives a positive
// tuple when v is replaced by a point strictly beyond its hull facet (the rule
// of kernels_cpu/rt3/rt3.hpp). Dead slots hold four kNil.
//
// ============================================================================
// The algorithm: Edelsbrunner–Shah's insertion, composed, in parallel rounds
// ============================================================================
// Inserting p into the regular triangulation of the points inserted so far is
// the 1-4 flip into the tetrahedron containing p followed by the 2-3 / 3-2 /
// 4-1 flips of its non-regular link facets ([ES92]; thesis §3.1 Table 3.1,
// §9.1; the reference's RT+1). Their whole sequence replaces exactly the
// facets of Q visible from the lifted point p̂ (the cavity: real tetrahedra
// whose lifted hyperplane passes strictly above p̂ — power3d > 0 — and, outside
// the hull, virtual ones whose hull facet p sees) by the cone from p̂ over the
// cavity's boundary (the horizon): kernels_cpu/rt3/rt3.cpp proves this, and
// this kernel performs the composed step, in rounds, each insertion as one
// atomic action — so no flip sequence can get stuck here (the 3D flip
// algorithm's trouble, which gDel3D repairs by star splaying on the host):
//   sort      Morton keys, thrust::sort_by_key; the first tetrahedron (four
//             points spread along the curve: under SoS no four points are
//             coplanar) and its four virtual tetrahedra; every other point
//             located by a visibility walk from it.
//   vote      (§5.3's "for each triangle, one of the points associated with it
//             is selected", in 3D as gDel3D's rounds) each point votes for its
//             tetrahedron with an atomic minimum of a hash of its id; the
//             winners, compacted by copy_if, are the round's insertions.
//   cavity    each winner, in parallel, finds its cavity by a breadth-first
//             search from its tetrahedron (the visible facets are connected)
//             into its own scratch of K tetrahedra and 2K + 2 horizon facets
//             (a cavity of c tetrahedra is a ball with at most 2c + 2
//             boundary facets; K per point, 64 at first); a larger cavity
//             marks the winner overflowed: it retries in a later round with
//             twice the room.
//   claim     each winner claims every tetrahedron of its cavity and every
//             neighbour across its horizon by an atomic minimum of (round,
//             winner number), as the 2D kernel's flips; a winner that holds
//             all its claims inserts, the others retry in the next round.
//   insert    slots: the cavity's, then fresh ones numbered by an exclusive
//             scan of what each insertion needs beyond its cavity; the cone
//             over the horizon written, linked across the horizon to the
//             claimed neighbours and inside by matching the horizon's edges;
//             a cavity slot the cone does not reuse dies (a 4-1 flip's
//             removed vertex).
//   relocate  the points whose tetrahedron an insertion destroyed walk from a
//             new tetrahedron of that insertion; a point whose new tetrahedron
//             is real and proves it redundant (its lifted point not below
//             that tetrahedron's lifted hyperplane, §5.3's early discard) is
//             discarded for good.
//   output    the real tetrahedra, canonical (canonical_tet.hpp), sorted; the
//             points that are no vertex, ascending; when asked for, the
//             witness of cpu::certify_rt3 (for each non-vertex the real
//             tetrahedron containing it, by a visibility walk).
// Every predicate runs in §6.4.2's two passes (two_pass.cuh): a filter-only
// pass (the per-call semi-static filters of static_filter.hpp), then the
// exact staged path (device_predicates.cuh: expansions and SoS, no GMP) for
// the items the filters could not decide only. Nothing is handed back to the
// host: the rounds, the exact passes and the retries all run on the device.
//
// ============================================================================
// Why the answer is the reference's
// ============================================================================
// Under SoS the lifted weighted points are in general position and RT(S ⊕ W)
// is unique (DESIGN.md). A round's insertions that act hold disjoint claims:
// each one's cavity and the neighbours across its horizon belong to it alone.
// Take them in any order: an insertion before this one wrote only slots of
// its own cavity, fresh slots and the links of its own horizon neighbours, so
// this one's cavity, the corners of the tetrahedra around it and the links it
// reads are as the search found them; the visible set is connected and every
// tetrahedron around it is invisible and unchanged, so the search in the
// updated triangulation finds the same cavity. The round is therefore a
// sequence of single insertions, each of which returns the regular
// triangulation of the points inserted so far (rt3.cpp); points are dropped
// only when proved redundant (by their real tetrahedron — redundancy for a
// subset implies redundancy for S, Q only grows — or by losing every
// tetrahedron to a later cavity), so the last round leaves RT(S ⊕ W) under
// SoS: ref::rtd_incremental's answer. Which point a tetrahedron elects, which
// insertion wins a claim and how rounds are cut change the work, never the
// answer; the claim of smallest number always holds all its claims and a
// cavity that overflowed gets twice the room next time, so every round
// inserts or grows a room, and the rounds end.
//
// Functors: __host__ __device__, no heap, no recursion; atomics are
// cuda::atomic_ref (libcu++, also for the host compiler). Every choice is a
// deterministic function of the input (votes and claims are minima, slots
// come from scans, the walks' choices are hashed from the point and round),
// so the witness too is the same at any thread count.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including rt3.cuh"
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
#include <thrust/binary_search.h>
#include <thrust/reduce.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cpu/grid_keys.hpp"
#include "kernels_cpu/rt3/canonical_tet.hpp"
#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/device_predicates.cuh"
#include "kernels_cuda/elections.cuh"
#include "kernels_cuda/kernel_errors.hpp"
#include "kernels_cuda/rt3/rt3.hpp"
#include "kernels_cuda/spread.cuh"
#include "kernels_cuda/two_pass.cuh"
#include "predicates/predicates.hpp"
#include "reference/dimension.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace rt3_detail {

using std::uint32_t;
using std::uint64_t;
using std::uint8_t;

constexpr uint32_t kNil = ~uint32_t{0};     // no tetrahedron; the corners of a dead slot
constexpr uint32_t kInserted = kNil - 1;    // loc[]: the point is (or was) a vertex
constexpr uint32_t kDiscarded = kNil - 2;   // loc[]: proved redundant when located (§5.3)
// links 4u + j in 32 bits: slots below 2^30
constexpr std::size_t kMaxSlots = std::size_t{1} << 30;

// A winner's state in its round.
// the cavity search's lists at which it switches from scans to a hash table
constexpr uint32_t kHashFrom = 48;

constexpr uint8_t kOk = 0;         // cavity found
constexpr uint8_t kOverflow = 1;   // cavity larger than its room: retries with twice the room
constexpr uint8_t kUndecided = 2;  // the filter pass's mark (two_pass.cuh)
constexpr uint8_t kRedundant = 3;  // its real tetrahedron proves it redundant (the walk's test already does)
constexpr uint8_t kWon = 4;        // held all its claims: inserts
constexpr uint8_t kLost = 5;       // another insertion holds one of its claims (Revive decides: retry now or next round)
constexpr uint8_t kOut = 6;        // meets an insertion of this round: retries in the next round

using dev::atomic_fetch_min;
using dev::atomic_store;
using dev::IsWinner;
using dev::Vote;
using dev::vote_key;

// ---- the points and the two kinds of signs ------------------------------------------
struct Geo {
  const double* xyz;  // 3 per vertex
  const double* w;    // 1 per vertex (0 unweighted)
  const Index* id;    // input index = SoS index
  FF_HD const double* P(uint32_t x) const { return xyz + 3 * static_cast<std::size_t>(x); }
};

// The first pass's signs: the per-call semi-static filters (static_filter.hpp),
// 0 and `undecided` where they cannot decide (two_pass.cuh).
struct FastSigns : dev::Undecided {
  const Geo& g;
  FF_HD explicit FastSigns(const Geo& geo) : g(geo) {}
  FF_HD int orient(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const double* p[4] = {g.P(a), g.P(b), g.P(c), g.P(d)};
    return certain(pred::semi_static_sign<4>(p, nullptr));
  }
  FF_HD int power(uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t e) {
    const double* p[5] = {g.P(a), g.P(b), g.P(c), g.P(d), g.P(e)};
    const double w[5] = {g.w[a], g.w[b], g.w[c], g.w[d], g.w[e]};
    return certain(pred::semi_static_sign<5>(p, w));
  }
};
// The second pass's: the whole staged path under SoS — pred::orient3d and
// pred::power3d's signs (predicates.hpp; power3d is the 5-row lifted Λ).
struct ExactSigns {
  const Geo& g;
  static constexpr bool undecided = false;
  FF_HD int orient(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const {
    return dev::orient3d(nullptr, g.id[a], g.P(a), g.id[b], g.P(b), g.id[c], g.P(c), g.id[d], g.P(d));
  }
  FF_HD int power(uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t e) const {
    const pred::PointId ids[5] = {g.id[a], g.id[b], g.id[c], g.id[d], g.id[e]};
    const double* p[5] = {g.P(a), g.P(b), g.P(c), g.P(d), g.P(e)};
    const double w[5] = {g.w[a], g.w[b], g.w[c], g.w[d], g.w[e]};
    return dev::lambda<5>(nullptr, ids, p, w);
  }
};
struct OnGeo {
  Geo g;
  FF_HD FastSigns fast() const { return FastSigns(g); }
  FF_HD ExactSigns exact() const { return ExactSigns{g}; }
};

// ---- the triangulation ------------------------------------------------------------------
struct Mesh {
  uint32_t* tv;
  uint32_t* tn;
  uint32_t v;  // the virtual vertex (= n)
  FF_HD const uint32_t* corners(uint32_t t) const { return tv + 4 * static_cast<std::size_t>(t); }
  FF_HD bool is_virtual(uint32_t t) const {
    const uint32_t* c = corners(t);
    return (c[0] == v) | (c[1] == v) | (c[2] == v) | (c[3] == v);
  }
};

// Is tetrahedron t a facet of Q visible from p̂ (the header)? Real: power3d >
// 0; virtual: orient3d with v replaced by p > 0.
template <class S>
FF_HD bool visible(S& sg, const Mesh& m, uint32_t t, uint32_t p) {
  const uint32_t* c = m.corners(t);
  for (int i = 0; i < 4; ++i)
    if (c[i] == m.v) {
      uint32_t u[4] = {c[0], c[1], c[2], c[3]};
      u[i] = p;
      return sg.orient(u[0], u[1], u[2], u[3]) > 0;
    }
  return sg.power(c[0], c[1], c[2], c[3], p) > 0;
}

// The visibility walk toward p from tetrahedron t (kernels_cpu/rt3's walk):
// across a facet that separates t from p (orient3d with that corner replaced
// by p negative), never straight back, the facets tried from a hashed one
// (the stochastic walk of Devillers–Pion–Teillaud; on a regular triangulation
// every such walk ends: Edelsbrunner's acyclicity theorem). Returns the real
// tetrahedron containing p (SoS: strictly) or the first virtual tetrahedron
// reached, one whose hull facet p sees. A virtual start: itself when p sees
// its hull facet, else the walk goes on from the real tetrahedron across it.
// In the filter pass an undecided sign is never taken as separating, so the
// walk still only crosses separating facets and ends; the pass marks it.
template <class S>
FF_HD uint32_t walk(S& sg, const Mesh& m, uint32_t p, uint32_t t, uint64_t seed) {
  uint32_t from = 4;  // t's corner opposite the facet crossed into t
  if (m.is_virtual(t)) {
    if (visible(sg, m, t, p)) return t;
    const uint32_t* c = m.corners(t);
    const uint32_t iv = c[0] == m.v ? 0 : c[1] == m.v ? 1 : c[2] == m.v ? 2 : 3;
    const uint32_t l = m.tn[4 * static_cast<std::size_t>(t) + iv];
    t = l >> 2, from = l & 3u;
  }
  uint64_t rng = cpu::brio::splitmix64(seed) | 1;
  for (;;) {
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    const uint32_t r = static_cast<uint32_t>(rng >> 32) & 3u;
    const uint32_t* c = m.corners(t);
    uint32_t next = kNil;
    for (uint32_t q = 0; q < 4; ++q) {
      const uint32_t i = (r + q) & 3u;
      if (i == from) continue;
      uint32_t u[4] = {c[0], c[1], c[2], c[3]};
      u[i] = p;
      if (sg.orient(u[0], u[1], u[2], u[3]) < 0) {
        next = m.tn[4 * static_cast<std::size_t>(t) + i];
        break;
      }
    }
    if (next == kNil) return t;
    t = next >> 2, from = next & 3u;
    if (m.is_virtual(t)) return t;
  }
}

// ---- location (two passes) ----------------------------------------------------------------
struct Located {
  uint32_t t;        // the new tetrahedron, kNil: unchanged
  uint32_t discard;  // 1: t is real and proves the point redundant
};

// The points of list[] whose tetrahedron the round's insertions destroyed
// (stamp == epoch) walk from a new tetrahedron of the insertion that did
// (start_of[owner]). With anchor set (a live slot: a BRIO level's first
// location), every point walks from its last location when that slot holds a
// tetrahedron now (slots are reused by cones over the same region, so it is
// near), else from the anchor. A point ending in a real tetrahedron that is
// not visible from it is redundant (§5.3) and leaves; hint[] keeps that
// tetrahedron (the witness's walk starts there).
struct Relocate : OnGeo {
  Mesh m;
  const uint32_t* list;
  uint32_t* loc;
  uint32_t* hint;
  uint8_t* pending;  // per list item: the filter pass's mark, 0 again after the exact pass
  const uint32_t* stamp;
  const uint32_t* owner;
  const uint32_t* start_of;
  uint32_t epoch;
  uint32_t anchor;  // kNil: the round's relocation
  uint32_t slots;
  template <class S>
  FF_HD Located decide(std::size_t i, S& sg) const {
    const uint32_t p = list[i];
    const uint32_t t = loc[p];
    uint32_t s;
    if (anchor == kNil) {
      if (t >= kDiscarded || stamp[t] != epoch) return {kNil, 0};
      s = start_of[owner[t]];
    } else {
      s = t < slots && m.corners(t)[0] != kNil ? t : anchor;
    }
    const uint32_t u = walk(sg, m, p, s, (uint64_t{p} << 32) ^ epoch);
    if (!m.is_virtual(u) && !visible(sg, m, u, p)) return {u, 1};
    return {u, 0};
  }
  FF_HD void write(std::size_t i, Located r) const {
    pending[i] = 0;
    if (r.t == kNil) return;
    const uint32_t p = list[i];
    if (r.discard) {
      loc[p] = kDiscarded;
      hint[p] = r.t;
    } else {
      loc[p] = r.t;
    }
  }
  FF_HD void mark(std::size_t i) const { pending[i] = 1; }
  FF_HD bool marked(std::size_t i) const { return pending[i] != 0; }
};

// ---- the round's elections (dev::Vote, dev::IsWinner: elections.cuh) -----------------------------
// BRIO (Amenta–Choi–Rote) in levels: a point belongs to the level at which
// its hash falls below the level's threshold (the levels' samples double); a
// level's points are located and inserted, in rounds, into the triangulation
// of the earlier levels, whose hull already covers most of them — a point
// outside the current hull sees much of it, and such cavities block one
// another. Only the current level's points take part in a round.
// (the hash is vote_key's, elections.cuh)
FF_HD inline uint64_t level_hash(uint32_t p) { return static_cast<uint64_t>(vote_key(p) >> 32); }
struct InLevel {
  uint64_t lo, hi;  // level_hash in [lo, hi)
  uint32_t r[4];    // the first tetrahedron's corners: never in a level
  FF_HD bool operator()(uint32_t p) const {
    const uint64_t h = level_hash(p);
    return h >= lo && h < hi && p != r[0] && p != r[1] && p != r[2] && p != r[3];
  }
};
struct ResetVote {
  const uint32_t* winners;
  const uint32_t* loc;
  uint64_t* best;
  FF_HD void operator()(uint32_t q) const { best[loc[winners[q]]] = ~uint64_t{0}; }
};

// The claim value of winner q: insertions with smaller cavities first (a
// cavity that reaches far — a point outside the current hull that sees much
// of it — would otherwise block every insertion around it), the winner's
// number breaking ties. The claims are cleared after each round's election
// (ResetClaims), so every claim array entry is ~0 between rounds.
FF_HD inline uint64_t claim_key(uint32_t size, uint32_t q) {
  return (static_cast<uint64_t>(size) << 32) | q;
}

// ---- cavities (two passes) --------------------------------------------------------------------
// One horizon facet: the new tetrahedron over it (the cavity tetrahedron's
// corners with corner i replaced by p: p lies on the same side of the facet
// as that corner, so a real one stays positive and a virtual one keeps the
// rule), and the invisible neighbour's link across it.
struct HorEntry {
  uint32_t v[4];
  uint32_t i;
  uint32_t out;
};

// Per winner q: room for K_q cavity tetrahedra and 2 K_q + 2 horizon facets
// (a cavity of c tetrahedra is a ball with at most 2c + 2 boundary facets),
// K_q = want[its point]; first[q] = K_0 + ... + K_{q-1} (an exclusive scan),
// so that its cavity list starts at first[q] and its horizon list at
// 2 first[q] + 2q.
struct Scratch {
  uint32_t* cav;
  HorEntry* hor;
  uint32_t* table;        // 8 K_q per winner, from 8 first[q] (the cavity search's hash table)
  const uint64_t* first;  // per winner
  const uint32_t* room;   // per winner: K_q
  uint32_t* ncav;         // per winner
  uint32_t* nhor;         // per winner
  uint8_t* status;
  FF_HD uint32_t K(uint32_t q) const { return room[q]; }
  FF_HD uint32_t H(uint32_t q) const { return 2 * room[q] + 2; }
  FF_HD uint32_t* C(uint32_t q) const { return cav + first[q]; }
  FF_HD HorEntry* E(uint32_t q) const { return hor + 2 * first[q] + 2 * static_cast<uint64_t>(q); }
  FF_HD uint32_t* T(uint32_t q) const { return table + 8 * first[q]; }
};

// Breadth-first search of the facets visible from p̂ from the winner's
// tetrahedron (every visible facet is reached through visible ones), testing
// only the cavity's neighbours; a neighbour already found invisible is not
// tested again. A cavity larger than its room is kOverflow: the point wants
// twice the room, which it gets in its next round (its own, not every
// winner's: a few large cavities — SoS on cospherical lattices — then do not
// shrink how many insertions a round's scratch holds).
struct Cavity : OnGeo {
  Mesh m;
  const uint32_t* winners;
  const uint32_t* loc;
  uint32_t* want;  // per point: the room its next cavity search gets
  Scratch s;
  template <class S>
  FF_HD uint8_t decide(std::size_t qi, S& sg) const {
    const uint32_t q = static_cast<uint32_t>(qi);
    const uint32_t p = winners[q], root = loc[p];
    uint32_t* C = s.C(q);
    HorEntry* E = s.E(q);
    if (!visible(sg, m, root, p)) return kRedundant;
    uint32_t nc = 1, nh = 0;
    C[0] = root;
    // Is a neighbour in C, or an invisible one met before? Small cavities:
    // 64-bit signatures of the two lists (bit: a hash of the slot) — a
    // neighbour whose bit is clear is in neither, the lists are scanned only
    // when it is set. From kHashFrom entries on (cospherical and coplanar sets
    // under SoS make cavities of thousands of tetrahedra, and the scans
    // quadratic): an open-addressing table in the winner's scratch (8 K slots
    // for at most 3 K + 2 keys), entry 2t for t in C, 2t + 1 for t invisible.
    auto bit = [](uint32_t t) { return uint64_t{1} << ((t * 0x9E3779B1u) >> 26); };
    uint64_t in_c = bit(root), in_out = 0;
    uint32_t* T = s.T(q);
    const uint32_t mask = 8 * s.K(q) - 1;
    bool hashed = false;
    auto slot_of = [&](uint32_t t) {
      uint32_t h = (t * 0x9E3779B1u) & mask;
      while (T[h] != kNil && (T[h] >> 1) != t) h = (h + 1) & mask;
      return h;
    };
    for (uint32_t a = 0; a < nc; ++a) {
      const uint32_t t = C[a];
      if (!hashed && nc + nh > kHashFrom) {
        for (uint32_t h = 0; h <= mask; ++h) T[h] = kNil;
        for (uint32_t b = 0; b < nc; ++b) T[slot_of(C[b])] = 2 * C[b];
        for (uint32_t b = 0; b < nh; ++b) T[slot_of(E[b].out >> 2)] = 2 * (E[b].out >> 2) + 1;
        hashed = true;
      }
      for (uint32_t i = 0; i < 4; ++i) {
        const uint32_t l = m.tn[4 * static_cast<std::size_t>(t) + i], u = l >> 2;
        const uint64_t bu = bit(u);
        bool inside = false, known = false;
        uint32_t h = 0;
        if (hashed) {
          h = slot_of(u);
          inside = T[h] == 2 * u;
          known = T[h] == 2 * u + 1;
        } else {
          if (in_c & bu)
            for (uint32_t b = 0; b < nc && !inside; ++b) inside = C[b] == u;
          if (!inside && (in_out & bu))
            for (uint32_t b = 0; b < nh && !known; ++b) known = (E[b].out >> 2) == u;
        }
        if (inside) continue;
        if (!known) {
          const bool vis = visible(sg, m, u, p);
          if (sg.undecided) return kUndecided;
          if (vis) {
            if (nc == s.K(q)) return kOverflow;
            C[nc++] = u;
            in_c |= bu;
            if (hashed) T[h] = 2 * u;
            continue;
          }
          in_out |= bu;
          if (hashed) T[h] = 2 * u + 1;
        }
        if (nh == s.H(q)) return kOverflow;
        HorEntry& e = E[nh++];
        const uint32_t* c = m.corners(t);
        for (uint32_t j = 0; j < 4; ++j) e.v[j] = j == i ? p : c[j];
        e.i = i;
        e.out = l;
      }
    }
    s.ncav[q] = nc;
    s.nhor[q] = nh;
    return kOk;
  }
  FF_HD void write(std::size_t q, uint8_t r) const {
    s.status[q] = r;
    if (r == kOverflow) want[winners[q]] = 2 * s.K(static_cast<uint32_t>(q));  // (the next try's room)
  }
  FF_HD void mark(std::size_t q) const { s.status[q] = kUndecided; }
  FF_HD bool marked(std::size_t q) const { return s.status[q] == kUndecided; }
};

// ---- claims and the insertions ----------------------------------------------------------------
// Two kinds of claims, by atomic minimum: on the cavity's tetrahedra
// (cclaim) and on the neighbours across its horizon (hclaim). Two insertions
// conflict when one's cavity meets the other's cavity or horizon; two
// horizons may share a neighbour (each writes the link of a different facet
// of it — the facet's other side lies in its own cavity — and neither changes
// its corners), which is most of the overlap between neighbouring cavities.
struct Claim {
  Scratch s;
  uint64_t* cclaim;
  uint64_t* hclaim;
  FF_HD void operator()(uint32_t q) const {
    if (s.status[q] != kOk) return;
    const uint64_t key = claim_key(s.ncav[q] + s.nhor[q], q);
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    for (uint32_t b = 0; b < s.ncav[q]; ++b) atomic_fetch_min(cclaim + C[b], key);
    for (uint32_t b = 0; b < s.nhor[q]; ++b) atomic_fetch_min(hclaim + (E[b].out >> 2), key);
  }
};

// A winner acts when no insertion of smaller key claimed one of its cavity's
// tetrahedra (either kind of claim) or has one of its horizon's neighbours in
// its cavity: kWon, and need[q] = the fresh slots its cone takes beyond its
// cavity's; else kLost. The smallest key always acts; two that act are apart.
struct Won {
  Scratch s;
  const uint64_t* cclaim;
  const uint64_t* hclaim;
  uint32_t* need;
  FF_HD void operator()(uint32_t q) const {
    if (s.status[q] != kOk) return;
    const uint64_t key = claim_key(s.ncav[q] + s.nhor[q], q);
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    const uint32_t nc = s.ncav[q], nh = s.nhor[q];
    bool all = true;
    for (uint32_t b = 0; b < nc && all; ++b) all = cclaim[C[b]] == key && hclaim[C[b]] > key;
    for (uint32_t b = 0; b < nh && all; ++b) all = cclaim[E[b].out >> 2] > key;
    s.status[q] = all ? kWon : kLost;
    if (all) need[q] = nh > nc ? nh - nc : 0;
  }
};

// The election in sub-rounds (a maximal set of apart insertions, as Luby's
// rounds): the winners' cavities and horizons are marked taken (ctaken,
// htaken: the round's epoch); a loser that meets no taken tetrahedron — it
// lost only to other losers — takes part again (kOk), the others wait for
// the next round (kOut). Taken marks only ever grow within a round, so a
// later sub-round's winner is apart from every earlier one.
struct MarkTaken {
  Scratch s;
  uint32_t* ctaken;
  uint32_t* htaken;
  uint32_t epoch;
  FF_HD void operator()(uint32_t q) const {
    if (s.status[q] != kWon) return;
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    for (uint32_t b = 0; b < s.ncav[q]; ++b) ctaken[C[b]] = epoch;
    for (uint32_t b = 0; b < s.nhor[q]; ++b) atomic_store(htaken + (E[b].out >> 2), epoch);
  }
};
struct Revive {
  Scratch s;
  const uint32_t* ctaken;
  const uint32_t* htaken;
  uint32_t epoch;
  FF_HD void operator()(uint32_t q) const {
    if (s.status[q] != kLost) return;
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    bool apart = true;
    for (uint32_t b = 0; b < s.ncav[q] && apart; ++b) apart = ctaken[C[b]] != epoch && htaken[C[b]] != epoch;
    for (uint32_t b = 0; b < s.nhor[q] && apart; ++b) apart = ctaken[E[b].out >> 2] != epoch;
    s.status[q] = apart ? kOk : kOut;
  }
};

// After a sub-round's Won: every entry a winner claimed back to ~0.
struct ResetClaims {
  Scratch s;
  uint64_t* cclaim;
  uint64_t* hclaim;
  FF_HD void operator()(uint32_t q) const {
    if (s.status[q] != kWon && s.status[q] != kLost) return;
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    for (uint32_t b = 0; b < s.ncav[q]; ++b) atomic_store(cclaim + C[b], ~uint64_t{0});
    for (uint32_t b = 0; b < s.nhor[q]; ++b) atomic_store(hclaim + (E[b].out >> 2), ~uint64_t{0});
  }
};

struct RoomOf {
  const uint32_t* winners;
  const uint32_t* want;
  FF_HD uint32_t operator()(uint32_t q) const { return want[winners[q]]; }
};
// the bytes of winner q's scratch per unit of room, and the rest
constexpr std::size_t kScratchPerRoom = 4 + 2 * sizeof(HorEntry) + 8 * 4;

struct StatusIs {
  const uint8_t* status;
  uint8_t value;
  FF_HD bool operator()(uint32_t q) const { return status[q] == value; }
};
// cavity tetrahedra (first) and created ones (second) of the insertions
struct WonSizes {
  Scratch s;
  FF_HD uint64_t operator()(uint32_t q) const {
    if (s.status[q] != kWon) return 0;
    return (static_cast<uint64_t>(s.ncav[q]) << 32) | s.nhor[q];
  }
};

// The insertion of a winner that holds its claims: the cone from p over its
// horizon in its cavity's slots, then fresh ones (base + offset[q] ...); the
// links across the horizon (the neighbour is claimed: its link is ours to
// write) and inside the cone — the new tetrahedra over two horizon facets
// that share a horizon edge xy share the facet (p, x, y): a closed surface has
// each edge in exactly two of its triangles. Cavity slots get the round's
// stamp and the winner as owner (relocation); the ones not reused die.
struct Insert {
  Mesh m;
  Scratch s;
  const uint32_t* winners;
  uint32_t* loc;
  uint32_t* hint;
  const uint32_t* offset;
  uint32_t base;
  uint32_t* stamp;
  uint32_t* owner;
  uint32_t* start_of;
  uint32_t epoch;
  FF_HD void operator()(uint32_t q) const {
    const uint32_t p = winners[q];
    if (s.status[q] == kRedundant) {  // (the walk's test discards such a point first)
      hint[p] = loc[p];
      loc[p] = kDiscarded;
      return;
    }
    if (s.status[q] != kWon) return;
    const uint32_t* C = s.C(q);
    const HorEntry* E = s.E(q);
    const uint32_t nc = s.ncav[q], nh = s.nhor[q], fresh = base + offset[q];
    auto slot = [&](uint32_t b) { return b < nc ? C[b] : fresh + (b - nc); };
    for (uint32_t b = 0; b < nc; ++b) stamp[C[b]] = epoch, owner[C[b]] = q;
    uint32_t start = kNil;
    // the links inside the cone: each new tetrahedron's three facets through
    // p hold p and an edge of the horizon, which is in exactly two horizon
    // facets (a closed surface); matched by a scan of the horizon, or, for a
    // large one, through a hash table of edges in the winner's scratch (8 K
    // slots for at most 3 K + 3 edges)
    const bool hashed = nh > kHashFrom;
    uint32_t* T = s.T(q);
    const uint32_t mask = 8 * s.K(q) - 1;
    if (hashed)
      for (uint32_t h = 0; h <= mask; ++h) T[h] = kNil;
    for (uint32_t b = 0; b < nh; ++b) {
      const HorEntry& e = E[b];
      const uint32_t t = slot(b);
      uint32_t* c = m.tv + 4 * static_cast<std::size_t>(t);
      uint32_t* l = m.tn + 4 * static_cast<std::size_t>(t);
      for (int j = 0; j < 4; ++j) c[j] = e.v[j];
      l[e.i] = e.out;
      m.tn[e.out] = 4 * t + e.i;
      if (start == kNil && e.v[0] != m.v && e.v[1] != m.v && e.v[2] != m.v && e.v[3] != m.v) start = t;
      for (uint32_t j = 0; j < 4; ++j) {
        if (j == e.i) continue;
        // the facet opposite corner j: p and the horizon edge (x, y)
        uint32_t xy[2], k = 0;
        for (uint32_t r = 0; r < 4; ++r)
          if (r != e.i && r != j) xy[k++] = e.v[r];
        if (hashed) {  // the edge's first half waits in the table for its second
          const uint32_t lo = xy[0] < xy[1] ? xy[0] : xy[1], hi = xy[0] < xy[1] ? xy[1] : xy[0];
          uint32_t h = (lo * 0x9E3779B1u ^ hi * 0x85EBCA77u) & mask;
          for (;; h = (h + 1) & mask) {
            if (T[h] == kNil) {
              T[h] = 4 * b + j;
              break;
            }
            if (T[h] == kNil - 1) continue;  // a matched edge's tombstone
            const uint32_t b2 = T[h] >> 2, j2 = T[h] & 3u;
            uint32_t e2[2], n2 = 0;
            for (uint32_t r = 0; r < 4; ++r)
              if (r != E[b2].i && r != j2) e2[n2++] = E[b2].v[r];
            if ((e2[0] == lo && e2[1] == hi) || (e2[0] == hi && e2[1] == lo)) {
              l[j] = 4 * slot(b2) + j2;
              m.tn[4 * static_cast<std::size_t>(slot(b2)) + j2] = 4 * t + j;
              T[h] = kNil - 1;  // (matched: a tombstone, never a first half again)
              break;
            }
          }
          continue;
        }
        uint32_t link = kNil;
        for (uint32_t b2 = 0; b2 < nh && link == kNil; ++b2) {
          if (b2 == b) continue;
          const HorEntry& f = E[b2];
          int px = -1, py = -1;
          for (int r = 0; r < 4; ++r) {
            if (f.v[r] == xy[0]) px = r;
            if (f.v[r] == xy[1]) py = r;
          }
          if (px < 0 || py < 0) continue;
          uint32_t j2 = 0;
          while (j2 == f.i || static_cast<int>(j2) == px || static_cast<int>(j2) == py) ++j2;
          link = 4 * slot(b2) + j2;
        }
        l[j] = link;  // (always found: the horizon is closed; the certifier checks every link)
      }
    }
    for (uint32_t b = nh; b < nc; ++b) {
      for (int j = 0; j < 4; ++j) m.tv[4 * static_cast<std::size_t>(C[b]) + j] = kNil;
      for (int j = 0; j < 4; ++j) m.tn[4 * static_cast<std::size_t>(C[b]) + j] = kNil;
    }
    start_of[q] = start;
    loc[p] = kInserted;
    hint[p] = start;
  }
};

struct StillActive {
  const uint32_t* loc;
  FF_HD bool operator()(uint32_t p) const { return loc[p] < kDiscarded; }
};
struct LocIs {
  const uint32_t* loc;
  uint32_t value;
  FF_HD bool operator()(uint32_t p) const { return loc[p] == value; }
};

// ---- output --------------------------------------------------------------------------------
struct Tet4 {
  Index v[4];
};
struct IsRealLive {
  Mesh m;
  FF_HD bool operator()(uint32_t t) const { return m.corners(t)[0] != kNil && !m.is_virtual(t); }
};
struct Canonical {
  Mesh m;
  const Index* id;
  FF_HD Tet4 operator()(uint32_t t) const {
    const uint32_t* c = m.corners(t);
    Tet4 r;
    canonical_tet(id[c[0]], id[c[1]], id[c[2]], id[c[3]], r.v);
    return r;
  }
};
struct TetLess {
  FF_HD bool operator()(const Tet4& a, const Tet4& b) const {
    for (int k = 0; k < 4; ++k)
      if (a.v[k] != b.v[k]) return a.v[k] < b.v[k];
    return false;
  }
};

// The witness: for each vertex the smallest real slot it is a corner of; for
// the others a walk (two passes) to the real tetrahedron containing them, from
// their hint when that slot still holds a real tetrahedron, else from anchor.
struct ScatterAt {
  Mesh m;
  const uint32_t* list;  // the live real slots
  uint32_t* at;
  FF_HD void operator()(uint32_t k) const {
    const uint32_t t = list[k];
    const uint32_t* c = m.corners(t);
    for (int j = 0; j < 4; ++j) atomic_fetch_min(at + c[j], t);
  }
};
struct AtIsNil {
  const uint32_t* at;
  FF_HD bool operator()(uint32_t p) const { return at[p] == kNil; }
};
struct WitnessWalk : OnGeo {
  Mesh m;
  const uint32_t* list;
  const uint32_t* hint;
  uint32_t* at;
  uint8_t* pending;
  uint32_t slots, anchor;
  template <class S>
  FF_HD uint32_t decide(std::size_t i, S& sg) const {
    const uint32_t p = list[i];
    uint32_t s = hint[p];
    if (s >= slots || m.corners(s)[0] == kNil || m.is_virtual(s)) s = anchor;
    return walk(sg, m, p, s, uint64_t{p} * 0x2545F4914F6CDD1Dull);
  }
  FF_HD void write(std::size_t i, uint32_t t) const {
    pending[i] = 0;
    at[list[i]] = t;
  }
  FF_HD void mark(std::size_t i) const { pending[i] = 1; }
  FF_HD bool marked(std::size_t i) const { return pending[i] != 0; }
};
struct IdOf {
  const Index* id;
  FF_HD Index operator()(uint32_t p) const { return id[p]; }
};

// ---- the sort ---------------------------------------------------------------------------------
using dev::Box;  // spread.cuh
using dev::BoxUnion;
using dev::PointBox;
// Morton key: 21 bits of each coordinate on the bounding box's grid
// (grid_keys.hpp; only the locality depends on it, never the answer).
struct MortonKey {
  const double* xyz;
  Box box;
  FF_HD uint64_t operator()(uint32_t i) const {
    return cpu::brio::morton(xyz + 3 * static_cast<std::size_t>(i), box.lo, box.hi, 3, 63);
  }
};
// The first tetrahedron's corners, chosen in double on the box-normalised
// coordinates (a heuristic: any four distinct points are a tetrahedron under
// SoS; spread ones leave fewer points outside it, whose cavities reach far):
// the smallest and the largest x, the point farthest from their line, the one
// farthest from the plane of the three. Score of each position by `mode`;
// the reduction keeps the largest score, the smaller position on ties.
struct Scored {
  double v;
  uint32_t i;
};
struct Spread {
  const double* xyz;
  Box box;
  int mode;             // 0: -x, 1: x, 2: distance² from line ab, 3: |volume| with abc
  double a[3], b[3], c[3];  // normalised corners chosen so far
  FF_HD static void norm(const double* x, const Box& box, double* y) {
    for (int k = 0; k < 3; ++k) y[k] = cpu::brio::unit(x[k], box.lo[k], box.hi[k]);
  }
  FF_HD Scored operator()(uint32_t i) const {
    double y[3];
    norm(xyz + 3 * static_cast<std::size_t>(i), box, y);
    double v = 0;
    if (mode == 0) v = -y[0];
    if (mode == 1) v = y[0];
    if (mode >= 2) {
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
      const double x[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      if (mode == 2) {
        v = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
      } else {
        const double z[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        // (b - a) x (y - a) . (c - a): the volume of (a, b, y, c) up to sign
        v = x[0] * z[0] + x[1] * z[1] + x[2] * z[2];
        v = v < 0 ? -v : v;
      }
    }
    return {v == v ? v : -1.0, i};  // (NaN: never chosen)
  }
};
struct BestScore {
  FF_HD Scored operator()(const Scored& x, const Scored& y) const {
    if (x.v != y.v) return x.v > y.v ? x : y;
    return x.i < y.i ? x : y;
  }
};

struct Gather {
  const double* xyz_in;
  const double* w_in;  // null: unweighted
  const uint32_t* order;
  double* xyz;
  double* w;
  FF_HD void operator()(uint32_t i) const {
    const std::size_t s = order[i];
    for (int k = 0; k < 3; ++k) xyz[3 * static_cast<std::size_t>(i) + k] = xyz_in[3 * s + k];
    w[i] = w_in ? w_in[s] : 0.0;
  }
};

// ---- the whole kernel ----------------------------------------------------------------------
using backend::raw;
using backend::read_one;

// OpenMP: one thread below this many items (backend.cuh).
constexpr std::size_t kParallelFrom = std::size_t{1} << 8;
// claim sub-rounds per round (MarkTaken, Revive)
constexpr int kSubRounds = 4;

template <class F>
void step(std::size_t count, F&& f) {
  backend::run_step<kParallelFrom>(count, f);
}

template <class F>
void for_range(std::size_t count, const F& f) {
  backend::for_range<kParallelFrom>(count, f);
}

template <class T>
void grow(backend::Buffer<T>& b, std::size_t size, T fill) {
  if (b.size() < size) b.resize(size, fill);
}

struct Buffers {
  // points (n)
  backend::Buffer<double> xyz_in, w_in, xyz, w;
  backend::Buffer<uint64_t> keys;
  backend::Buffer<uint32_t> order, loc, hint, active, active2, winners;
  backend::Buffer<uint8_t> pending;
  // tetrahedron slots (cap) and links (4 cap)
  backend::Buffer<uint32_t> tv, tn, stamp, owner, ctaken, htaken, list;
  backend::Buffer<uint64_t> claim, hclaim, best;
  // per winner
  backend::Buffer<uint32_t> cav, table, room, ncav, nhor, need, offset, start_of, want;
  backend::Buffer<uint64_t> first;
  backend::Buffer<HorEntry> hor;
  backend::Buffer<uint8_t> status;
};

inline cpu::Rt3Result run(const PointSet& ps, kernels::Rt3GpuStats* stats, cpu::StageTimes* times,
                          cpu::Rt3Witness* witness, const kernels::Rt3GpuOptions& opt, const char* who) {
  const std::string me(who);
  if (ps.dim != 3) throw std::invalid_argument(me + ": the points must be 3D, got dimension " + std::to_string(ps.dim));
  if (ps.weighted && ps.weights.size() != ps.size())
    throw std::invalid_argument(me + ": " + std::to_string(ps.weights.size()) + " weights for " +
                                std::to_string(ps.size()) + " points");
  const std::size_t n = ps.size();
  for (std::size_t i = 0; i < 3 * n; ++i)
    if (!std::isfinite(ps.coords[i])) throw std::invalid_argument(me + ": a coordinate is not finite");
  for (std::size_t i = 0; ps.weighted && i < n; ++i)
    if (!std::isfinite(ps.weights[i])) throw std::invalid_argument(me + ": a weight is not finite");
  if (std::string why = dimension_problem(ps); !why.empty()) throw std::invalid_argument(me + ": " + why);
  backend::require_device(who);
  if (n >= kDiscarded / 2)
    throw kernels::DeviceMemoryError(me + ": " + std::to_string(n) + " points exceed the 32-bit vertex ids of this kernel");

  kernels::Rt3GpuStats st;
  cpu::StageClock clock(times);
  Buffers B;
  std::size_t cap = std::min(kMaxSlots, 7 * n + 64);
  auto no_memory = [&](const std::string& what) {
    return kernels::DeviceMemoryError(me + ": " + what + " does not fit in device memory");
  };
  try {
    B.xyz_in.resize(3 * n), B.xyz.resize(3 * n), B.w.resize(n), B.keys.resize(n);
    if (ps.weighted) B.w_in.resize(n);
    B.order.resize(n), B.loc.resize(n), B.hint.resize(n, kNil), B.active.resize(n), B.active2.resize(n);
    B.winners.resize(n), B.pending.resize(n, 0);
    B.tv.resize(4 * cap, kNil), B.tn.resize(4 * cap, kNil), B.stamp.resize(cap, 0), B.owner.resize(cap, 0);
    B.ctaken.resize(cap, 0), B.htaken.resize(cap, 0);
    B.claim.resize(cap, ~uint64_t{0}), B.hclaim.resize(cap, ~uint64_t{0}), B.best.resize(cap, ~uint64_t{0});
  } catch (const std::bad_alloc&) {
    throw no_memory("the input (" + std::to_string(n) + " points; about " + std::to_string((n * 420) >> 20) +
                    " MiB)");
  }
  // ---- upload
  thrust::copy(ps.coords.begin(), ps.coords.end(), B.xyz_in.begin());
  if (ps.weighted) thrust::copy(ps.weights.begin(), ps.weights.end(), B.w_in.begin());
  clock.mark("upload");

  // ---- sort: Morton order; the first tetrahedron; every point located
  const thrust::counting_iterator<uint32_t> first(0);
  Box box{};
  step(n, [&](auto policy) {
    const Box empty{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
    box = thrust::transform_reduce(policy, first, first + n, PointBox{raw(B.xyz_in)}, empty, BoxUnion());
  });
  step(n, [&](auto policy) {
    thrust::transform(policy, first, first + n, B.keys.begin(), MortonKey{raw(B.xyz_in), box});
    thrust::sequence(policy, B.order.begin(), B.order.end());
    thrust::stable_sort_by_key(policy, B.keys.begin(), B.keys.end(), B.order.begin());
  });
  for_range(n, Gather{raw(B.xyz_in), ps.weighted ? raw(B.w_in) : nullptr, raw(B.order), raw(B.xyz), raw(B.w)});
  const uint32_t V = static_cast<uint32_t>(n);
  Geo g{raw(B.xyz), raw(B.w), raw(B.order)};
  auto mesh = [&] { return Mesh{raw(B.tv), raw(B.tn), V}; };

  // The first tetrahedron: four positions spread along the curve (distinct,
  // n >= 4), made positive, and its four virtual tetrahedra (v, facet i): the
  // real tuple with corner i := v and two other corners swapped (odd) —
  // kernels_cpu/rt3's start(). Slot 0 is the real one, slot 1 + i the virtual
  // one over its facet i; the links by matching facets.
  uint32_t r[4] = {0, static_cast<uint32_t>(n / 3), static_cast<uint32_t>(2 * n / 3), static_cast<uint32_t>(n - 1)};
  {
    Spread sp{raw(B.xyz), box, 0, {}, {}, {}};
    uint32_t e[4];
    for (int mode = 0; mode < 4; ++mode) {
      sp.mode = mode;
      step(n, [&](auto policy) {
        e[mode] = thrust::transform_reduce(policy, first, first + n, sp, Scored{-2.0, 0}, BestScore()).i;
      });
      double* into[3] = {sp.a, sp.b, sp.c};
      if (mode < 3) {
        // the chosen point's normalised coordinates, on the host
        Spread::norm(ps.point(read_one(B.order, e[mode])), box, into[mode]);
      }
    }
    if (e[0] != e[1] && e[0] != e[2] && e[0] != e[3] && e[1] != e[2] && e[1] != e[3] && e[2] != e[3])
      for (int k = 0; k < 4; ++k) r[k] = e[k];
  }
  {
    Index rid[4];
    for (int k = 0; k < 4; ++k) rid[k] = read_one(B.order, r[k]);
    if (pred::orient3d(pred::Pt{rid[0], ps.point(rid[0])}, pred::Pt{rid[1], ps.point(rid[1])},
                       pred::Pt{rid[2], ps.point(rid[2])}, pred::Pt{rid[3], ps.point(rid[3])}) < 0)
      std::swap(r[0], r[1]);
    uint32_t tv0[20], tn0[20];
    for (int k = 0; k < 4; ++k) tv0[k] = r[k];
    for (int i = 0; i < 4; ++i) {
      uint32_t* h = tv0 + 4 * (1 + i);
      for (int j = 0; j < 4; ++j) h[j] = r[j];
      h[i] = V;
      const int j1 = i == 0 ? 1 : 0, j2 = (i == 0 || i == 1) ? 2 : 1;
      std::swap(h[j1], h[j2]);
    }
    for (uint32_t f = 0; f < 20; ++f) {
      tn0[f] = kNil;
      for (uint32_t f2 = 0; f2 < 20 && tn0[f] == kNil; ++f2) {
        if (f2 / 4 == f / 4) continue;
        int shared = 0;
        for (uint32_t a = 0; a < 4; ++a)
          for (uint32_t b = 0; b < 4; ++b)
            shared += a != f % 4 && b != f2 % 4 && tv0[4 * (f / 4) + a] == tv0[4 * (f2 / 4) + b];
        if (shared == 3) tn0[f] = 4 * (f2 / 4) + f2 % 4;
      }
    }
    thrust::copy(tv0, tv0 + 20, B.tv.begin());
    thrust::copy(tn0, tn0 + 20, B.tn.begin());
  }
  uint32_t slots = 5;
  std::size_t n_active = 0;
  step(n, [&](auto policy) { thrust::fill(policy, B.loc.begin(), B.loc.end(), 0u); });  // slot 0: the first tetrahedron
  for (int k = 0; k < 4; ++k) B.loc[r[k]] = kInserted;
  uint32_t epoch = 0;
  // the two passes of f over [0, count) (two_pass.cuh); exact_items counts
  // the second pass's items
  auto two_passes = [&](std::size_t count, const auto& f, auto marked_count) {
    for_range(count, dev::Pass<std::decay_t<decltype(f)>, false>{f});
    const std::size_t marked = marked_count();
    st.exact_items += marked;
    if (marked) for_range(count, dev::Pass<std::decay_t<decltype(f)>, true>{f});
  };
  auto pending_count = [&](std::size_t count) {
    return [&B, count] {
      std::size_t c = 0;
      step(count, [&](auto policy) {
        c = static_cast<std::size_t>(thrust::count(policy, B.pending.begin(), B.pending.begin() + count, uint8_t{1}));
      });
      return c;
    };
  };
  auto relocate = [&](uint32_t anchor) {
    two_passes(n_active,
               Relocate{{g}, mesh(), raw(B.active), raw(B.loc), raw(B.hint), raw(B.pending), raw(B.stamp),
                        raw(B.owner), raw(B.start_of), epoch, anchor, slots},
               pending_count(n_active));
  };
  B.start_of.resize(1);
  clock.mark("sort");

  // ---- insertion rounds, level by level
  // per point: the room its next cavity search gets (64 tetrahedra, doubled
  // after each overflow)
  try {
    B.want.resize(n, 64u);
  } catch (const std::bad_alloc&) {
    throw no_memory("the input");
  }
  // scratch per round: at most this many bytes (or one winner's)
  const std::size_t budget =
      opt.scratch_bytes ? opt.scratch_bytes : std::max<std::size_t>(std::size_t{64} << 20, 256 * n);
  // the first level's sample: about 64 points
  uint64_t lo = 0, hi = std::max<uint64_t>(1, (uint64_t{64} << 32) / std::max<std::size_t>(n, 1));
  for (;;) {
    step(n_active, [&](auto policy) {
      n_active = static_cast<std::size_t>(thrust::copy_if(policy, B.active.begin(), B.active.begin() + n_active,
                                                          B.active2.begin(), StillActive{raw(B.loc)}) -
                                          B.active2.begin());
    });
    B.active.swap(B.active2);
    // the next level: its points, each located from its last location
    while (n_active == 0 && lo < (uint64_t{1} << 32)) {
      step(n, [&](auto policy) {
        n_active = static_cast<std::size_t>(
            thrust::copy_if(policy, first, first + n, B.active.begin(), InLevel{lo, hi, {r[0], r[1], r[2], r[3]}}) -
            B.active.begin());
      });
      lo = hi, hi *= 2;
      if (n_active == 0) continue;
      ++st.levels;
      uint32_t anchor = 0;
      step(slots, [&](auto policy) {
        anchor = static_cast<uint32_t>(thrust::find_if(policy, first, first + slots, IsRealLive{mesh()}) - first);
      });
      relocate(anchor);
      step(n_active, [&](auto policy) {
        n_active = static_cast<std::size_t>(thrust::copy_if(policy, B.active.begin(), B.active.begin() + n_active,
                                                            B.active2.begin(), StillActive{raw(B.loc)}) -
                                            B.active2.begin());
      });
      B.active.swap(B.active2);
    }
    if (n_active == 0) break;
    ++epoch;
    ++st.rounds;
    std::size_t k_all = 0;
    step(n_active, [&](auto policy) {
      thrust::for_each(policy, B.active.begin(), B.active.begin() + n_active, Vote{raw(B.loc), raw(B.best)});
    });
    step(n_active, [&](auto policy) {
      k_all = static_cast<std::size_t>(thrust::copy_if(policy, B.active.begin(), B.active.begin() + n_active,
                                                       B.winners.begin(), IsWinner{raw(B.loc), raw(B.best)}) -
                                       B.winners.begin());
    });
    for_range(k_all, ResetVote{raw(B.winners), raw(B.loc), raw(B.best)});
    // each winner's room, its scratch's first entry (an inclusive scan, then
    // shifted), and how many winners the round's scratch holds: those whose
    // scan stays within the budget (at least one)
    std::size_t k = 0;
    uint64_t total = 0;
    try {
      if (B.room.size() < k_all + 1) B.room.resize(k_all + 1), B.first.resize(k_all + 1);
    } catch (const std::bad_alloc&) {
      throw no_memory("the round's " + std::to_string(k_all) + " insertions");
    }
    step(k_all, [&](auto policy) {
      thrust::transform(policy, first, first + k_all, B.room.begin(), RoomOf{raw(B.winners), raw(B.want)});
      thrust::inclusive_scan(policy, B.room.begin(), B.room.begin() + static_cast<std::ptrdiff_t>(k_all),
                             B.first.begin() + 1, thrust::plus<uint64_t>());
      const uint64_t units = std::max<uint64_t>(1, budget / kScratchPerRoom);
      k = static_cast<std::size_t>(thrust::upper_bound(policy, B.first.begin() + 1,
                                                       B.first.begin() + 1 + static_cast<std::ptrdiff_t>(k_all),
                                                       units) -
                                   (B.first.begin() + 1));
    });
    k = std::max<std::size_t>(k, std::min<std::size_t>(k_all, 1));
    B.first[0] = 0;
    if (k > 0) total = read_one(B.first, k);
    st.max_capacity = std::max<std::uint64_t>(
        st.max_capacity, k ? thrust::reduce(B.room.begin(), B.room.begin() + static_cast<std::ptrdiff_t>(k), 0u,
                                            thrust::maximum<uint32_t>())
                           : 0u);
    try {
      if (B.cav.size() < total) B.cav.resize(total);
      if (B.table.size() < 8 * total) B.table.resize(8 * total);
      if (B.hor.size() < 2 * total + 2 * k) B.hor.resize(2 * total + 2 * k);
      if (B.ncav.size() < k + 1) {
        B.ncav.resize(k + 1), B.nhor.resize(k + 1), B.need.resize(k + 1), B.offset.resize(k + 1);
        B.start_of.resize(k + 1), B.status.resize(k + 1);
      }
    } catch (const std::bad_alloc&) {
      throw no_memory("the cavities of one round (" + std::to_string(k) + " insertions, room for " +
                      std::to_string(total) + " tetrahedra)");
    }
    const Scratch s{raw(B.cav), raw(B.hor), raw(B.table), raw(B.first), raw(B.room), raw(B.ncav), raw(B.nhor), raw(B.status)};
    two_passes(k, Cavity{{g}, mesh(), raw(B.winners), raw(B.loc), raw(B.want), s}, [&] {
      std::size_t c = 0;
      step(k, [&](auto policy) { c = static_cast<std::size_t>(thrust::count_if(policy, first, first + k, StatusIs{raw(B.status), kUndecided})); });
      return c;
    });
    step(k, [&](auto policy) { thrust::fill(policy, B.need.begin(), B.need.begin() + static_cast<std::ptrdiff_t>(k), 0u); });
    for (int sub = 0; sub < kSubRounds; ++sub) {
      for_range(k, Claim{s, raw(B.claim), raw(B.hclaim)});
      for_range(k, Won{s, raw(B.claim), raw(B.hclaim), raw(B.need)});
      for_range(k, MarkTaken{s, raw(B.ctaken), raw(B.htaken), epoch});
      for_range(k, ResetClaims{s, raw(B.claim), raw(B.hclaim)});
      if (sub + 1 < kSubRounds) for_range(k, Revive{s, raw(B.ctaken), raw(B.htaken), epoch});
    }
    std::size_t won = 0, lost = 0, over = 0, red = 0;
    uint64_t sizes = 0;
    step(k, [&](auto policy) {
      won = static_cast<std::size_t>(thrust::count_if(policy, first, first + k, StatusIs{raw(B.status), kWon}));
      over = static_cast<std::size_t>(thrust::count_if(policy, first, first + k, StatusIs{raw(B.status), kOverflow}));
      sizes = thrust::transform_reduce(policy, first, first + k, WonSizes{s}, uint64_t{0}, thrust::plus<uint64_t>());
      red = static_cast<std::size_t>(thrust::count_if(policy, first, first + k, StatusIs{raw(B.status), kRedundant}));
      thrust::exclusive_scan(policy, B.need.begin(), B.need.begin() + static_cast<std::ptrdiff_t>(k), B.offset.begin());
    });
    const std::size_t fresh = k ? static_cast<std::size_t>(read_one(B.offset, k - 1)) + read_one(B.need, k - 1) : 0;
    lost = k - won - over - red;
    st.attempts += k, st.lost += lost, st.overflowed += over;
    st.cavity_tets += sizes >> 32, st.created_tets += sizes & 0xffffffffu;
    if (slots + fresh > cap) {
      if (slots + fresh > kMaxSlots)
        throw kernels::DeviceMemoryError(me + ": more than 2^30 tetrahedra (32-bit links)");
      cap = std::min(kMaxSlots, std::max(slots + fresh, cap + cap / 2));
      try {
        grow(B.tv, 4 * cap, kNil), grow(B.tn, 4 * cap, kNil), grow(B.stamp, cap, 0u), grow(B.owner, cap, 0u);
        grow(B.claim, cap, ~uint64_t{0}), grow(B.hclaim, cap, ~uint64_t{0}), grow(B.best, cap, ~uint64_t{0});
        grow(B.ctaken, cap, 0u), grow(B.htaken, cap, 0u);
      } catch (const std::bad_alloc&) {
        throw no_memory(std::to_string(cap) + " tetrahedron slots");
      }
    }
    for_range(k, Insert{mesh(), s, raw(B.winners), raw(B.loc), raw(B.hint), raw(B.offset), slots, raw(B.stamp),
                        raw(B.owner), raw(B.start_of), epoch});
    slots += static_cast<uint32_t>(fresh);
    if (over > 0 && st.max_capacity >= (1u << 22)) throw no_memory("a cavity of more than 2^22 tetrahedra");
    if (won == 0 && over == 0 && red == 0 && k > 0)
      throw std::logic_error(me + ": a round without an insertion (the smallest claim must win)");
    relocate(kNil);
    clock.mark("insertion rounds");
  }

  // ---- output: canonical real tetrahedra, sorted; the points that are no vertex
  const Mesh m = mesh();
  st.slots = slots;
  std::size_t nt = 0;
  backend::Buffer<Tet4> out;
  try {
    if (B.list.size() < slots) B.list.resize(slots);
    out.resize(slots);
  } catch (const std::bad_alloc&) {
    throw no_memory("the output");
  }
  step(slots, [&](auto policy) {
    nt = static_cast<std::size_t>(thrust::copy_if(policy, first, first + slots, B.list.begin(), IsRealLive{m}) -
                                  B.list.begin());
    thrust::transform(policy, B.list.begin(), B.list.begin() + nt, out.begin(), Canonical{m, raw(B.order)});
    thrust::sort(policy, out.begin(), out.begin() + nt, TetLess());
  });
  // at: per vertex its smallest real slot; the rest kNil (not vertices)
  backend::Buffer<uint32_t> at;
  at.resize(n, kNil);
  for_range(nt, ScatterAt{m, raw(B.list), raw(at)});
  std::size_t nr = 0;
  step(n, [&](auto policy) {
    nr = static_cast<std::size_t>(thrust::copy_if(policy, first, first + n, B.active.begin(), AtIsNil{raw(at)}) -
                                  B.active.begin());
    thrust::transform(policy, B.active.begin(), B.active.begin() + nr, B.active2.begin(), IdOf{raw(B.order)});
    thrust::sort(policy, B.active2.begin(), B.active2.begin() + nr);
  });
  step(n, [&](auto policy) {
    st.inserted = static_cast<std::uint64_t>(thrust::count_if(policy, first, first + n, LocIs{raw(B.loc), kInserted}));
    st.discarded = static_cast<std::uint64_t>(thrust::count_if(policy, first, first + n, LocIs{raw(B.loc), kDiscarded}));
  });
  clock.mark("output");
  cpu::Rt3Result res;
  {
    const std::vector<Tet4> host = backend::to_host(out, nt);
    res.tets.resize(nt);
    static_assert(sizeof(Tet4) == sizeof(cpu::Tet), "Tet4 and Tet are four packed ids");
    if (nt) std::memcpy(res.tets.data(), host.data(), nt * sizeof(Tet4));
    std::vector<uint32_t> red = backend::to_host(B.active2, nr);
    res.redundant.assign(red.begin(), red.end());
  }
  clock.mark("download");
  if (witness) {
    if (nr > 0) {
      const uint32_t anchor = read_one(B.list, 0);  // a live real slot (n >= 4 spanning R^3: nt > 0)
      two_passes(nr, WitnessWalk{{g}, m, raw(B.active), raw(B.hint), raw(at), raw(B.pending), slots, anchor},
                 pending_count(nr));
    }
    std::vector<double> xyz = backend::to_host(B.xyz, 3 * n), w = backend::to_host(B.w, n);
    std::vector<uint32_t> id = backend::to_host(B.order, n);
    witness->pts.resize(n);
    for (std::size_t k = 0; k < n; ++k) witness->pts[k] = {{xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]}, w[k], id[k], 0};
    witness->tv = backend::to_host(B.tv, 4 * std::size_t{slots});
    witness->tn = backend::to_host(B.tn, 4 * std::size_t{slots});
    witness->at = backend::to_host(at, n);
    clock.mark("witness");
  }
  if (stats) *stats = st;
  return res;
}

}  // namespace rt3_detail

cpu::Rt3Result rt3(const PointSet& ps, kernels::Rt3GpuStats* stats, cpu::StageTimes* times, cpu::Rt3Witness* witness,
                   const kernels::Rt3GpuOptions& opt) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  return rt3_detail::run(ps, stats, times, witness, opt, "rt3 (omp)");
#else
  return rt3_detail::run(ps, stats, times, witness, opt, "rt3 (cuda)");
#endif
}

}  // namespace flipflop::FF_KERNELS_NS

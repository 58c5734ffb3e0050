// ghull.cuh — the one source of the data-parallel gHull (ghull.hpp explains
// the task). Included by ghull_omp.cpp (thrust's OpenMP backend, host
// compiler) and ghull_cuda.cu (nvcc), each defining FF_KERNELS_NS to the
// namespace it implements; the helpers live in FF_KERNELS_NS::ghull_detail.
//
// ============================================================================
// The data (flat arrays, structure of arrays; §7.2 Figure 7.2)
// ============================================================================
// Points keep their input order; the input index is the SoS index. Every
// point that takes part in star splaying has a star: status[p] alive or dead
// (none: takes no part). The *star list* is beg[p], cnt[p], cap[p]: the
// star's chunk link[beg .. beg + cap) of the *edge list*, of which the first
// cnt entries are its link, counter-clockwise seen from outside (the star's
// triangles are (p, link[i], link[i + 1 mod cnt])); a dead star keeps its
// death certificate cert[4p .. 4p + 3] (§7.1 Stage 3: "for any dead vertex,
// we only maintain 4 neighbors"). The edge list grows when a star needs more
// room than its chunk (Algorithm 9 lines 7-8): every star's chunk is then
// re-sized to its need plus a quarter and the links copied over.
//
// ============================================================================
// The stages (§7.1), each a sequence of thrust steps over functors
// ============================================================================
//  0. r = the ≺-least point (compare_sos on x, a reduction): a vertex of the
//     hull of every subset holding it; four points spanning R^3 (spread.cuh:
//     ffHull's line 1 reductions, exact orient3d on the host; else the
//     reference's rule, which rejects input that does not span R^3). The points are mapped by an affine map
//     per axis into the middle `fill` of the box B = [0, grid]^3 (§7.3.2's
//     remedy for the slicing problem; an affine map keeps the hull's
//     combinatorics, so it changes only the approximation).
//  1. Voronoi construction: digital_voronoi.cuh (projection onto the six
//     sides, the exact separable transform per side). S' = the points whose
//     digital Voronoi cell meets a side, with r and the four points of step 0.
//  2. Star creation: the working sets (digital_voronoi.cuh: the dual); per
//     point of S', one thread makes a star of 3 points of its working set,
//     oriented by one orient3d, and inserts the rest by beneath-beyond
//     (splay_insert), and r.
//  3. Hull approximation: star splaying on the GPU (Algorithm 9, splay()).
//  4. Point addition: the triangles of CH(S') (each from the star of its
//     smallest vertex, §7.2) are rendered into six depth maps (a software
//     rasteriser, one item per bounding-box row of a front-facing triangle;
//     the thesis uses OpenGL), each pixel keeping the nearest depth and one
//     vertex (the colour buffer). A point passes the depth test (§7.3.1,
//     Lemma 7.1) when in some view its depth is at most one pixel behind the
//     map's, or the map is empty there. Each candidate is located exactly
//     (Algorithm 10's question, locate()): beyond a triangle of r's star, or
//     beyond/beneath the triangle B whose cone from r holds it, found by a
//     walk over the triangles not incident to r from the vertex the map
//     recorded. Outside: its star is B (then r inserted); inside: dropped, r
//     and B being a death certificate.
//  5. Hull completion: star splaying again, only the new stars flagged.
//  6. Verification (not in the thesis): Lemma 7.1 holds for exact depths; the
//     maps here are rounded, so every point the depth test dropped is checked
//     exactly against the final hull: strictly inside its inner ball or box
//     (inner_region: the certifier's, built and filtered on the device), or
//     located as in Stage 4. One found outside (a
//     "depth miss", counted) gets its star and Stage 5 runs again; the points
//     found inside stay inside, hulls only grow. So the digital stages decide
//     only the work, never the answer.
//  output: the triangles of the alive stars, each once (from its smallest
//     vertex, which is then first: the canonical rotation), sorted on the
//     device.
//
// ============================================================================
// Why the answer is the canonical hull (thesis §3.3.2, [She05])
// ============================================================================
// star_splaying.hpp (the reference) proves that star splaying from convex
// stars and valid death certificates ends, when every star except the
// ≺-least point's encloses a point ≺ its apex, with the canonical SoS hull of
// the participating points. Here every star is made convex (3 points, then
// beneath-beyond insertions) and every star but r's gets r inserted: after
// that r is a link vertex, or strictly inside the cone, or the star died
// with a valid certificate — the precondition, kept because cones only grow.
// Stage 3 thus ends with CH(S'), and Stage 5 with the hull of S' and the
// added points; a point that takes no part is strictly inside a tetrahedron
// of participating points (Stage 4's or 6's certificate: r and a triangle of
// a hull of participating points), so it is no vertex of the hull of all
// points, and that hull is the output. The parallel rounds are the
// reference's workflow with a different order: each round checks the flagged
// candidate edges against the stars as they are (demanded(), read-only),
// then applies the demanded insertions per star in ascending order
// (apply()); an edge whose check demanded insertions has, by the reference's
// progress argument, an insertion that succeeds on the state it read — in the
// round either it succeeds or its star changed before it — so one of the
// edge's two stars changed, and the next round flags every edge with a
// changed endpoint. Rounds end when no flagged edge demands anything: every
// alive star is consistent. All decisions are orient3d under SoS
// (device_predicates.cuh: the per-input static filter, the exact expansion
// stage and SoS, on the device); every choice is a minimum, a scan or a sort,
// so the work too is the same at any thread count.
//
// Not done as the thesis does (said here and in the docs): Algorithm 8's
// shared-memory tiles (the projection is an atomic minimum in global memory:
// thrust functors have no shared memory); the Parallel Banding Algorithm's
// transposes (its bands are done: digital_voronoi.cuh); OpenGL rendering (a
// rasteriser in functors). §6.4.2's two passes (not in
// the thesis' gHull) run the read-only checks — Algorithm 9's edge check and
// the exact location — on the static filter first; the steps that change
// stars (creation, insertion) run the staged predicate in one pass.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including ghull.cuh"
#endif

#include <cuda/atomic>
#include <thrust/binary_search.h>
#include <thrust/copy.h>
#include <thrust/count.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/fill.h>
#include <thrust/for_each.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#include <thrust/unique.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/device_predicates.cuh"
#include "kernels_cuda/elections.cuh"
#include "kernels_cuda/hull3/digital_voronoi.cuh"
#include "kernels_cuda/hull3/ghull.hpp"
#include "kernels_cuda/kernel_errors.hpp"
#include "kernels_cuda/spread.cuh"
#include "kernels_cuda/static_filter.cuh"
#include "kernels_cuda/two_pass.cuh"
#include "predicates/predicates.hpp"
#include "reference/certify/ball_test.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/certify/inner_box.hpp"
#include "reference/hull3/ffhull.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace ghull_detail {

using std::uint32_t;
using std::uint64_t;
using std::uint8_t;

constexpr uint32_t kNo = ~uint32_t{0};
constexpr uint64_t kNoKey = ~uint64_t{0};
constexpr std::size_t kGrain = 2048;  // items below this run on one thread (OpenMP build)

constexpr uint8_t kNone = 0, kAlive = 1, kDead = 2;  // status
// a point's part in Stage 4 (role[])
constexpr uint8_t kMember = 0;     // has a star (S' or added)
constexpr uint8_t kCandidate = 1;  // passed the depth test
constexpr uint8_t kDropped = 2;    // failed it: verified in Stage 6
constexpr uint8_t kInside = 3;     // located strictly inside a hull of members

using dev::atomic_fetch_add;
using dev::atomic_fetch_min;
using dev::atomic_store;

template <std::size_t Grain = kGrain, class F>
void for_range(std::size_t count, const F& f) {
  backend::for_range<Grain>(count, f);
}
using backend::raw;

FF_HD inline uint32_t nx(uint32_t i, uint32_t k) { return i + 1 == k ? 0 : i + 1; }
FF_HD inline uint32_t pv(uint32_t i, uint32_t k) { return i == 0 ? k - 1 : i - 1; }

// ---- the points and orient3d under SoS ----------------------------------------------
struct Geo {
  const double* xyz;
  pred::StaticFilter filter;
  FF_HD const double* P(uint32_t i) const { return xyz + 3 * static_cast<std::size_t>(i); }
  // > 0 when d is on the inner side of (a, b, c) counter-clockwise seen from
  // outside (predicates.hpp); never 0 for distinct points
  FF_HD int orient(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const {
    const double* p[4] = {P(a), P(b), P(c), P(d)};
    if (const int r = pred::static_sign<4>(filter, p, nullptr)) return r;
    return dev::orient3d(&filter, a, p[0], b, p[1], c, p[2], d, p[3]);
  }
};

// §6.4.2's two passes (two_pass.cuh) for the read-only checks (Check,
// LocateAll): the first pass's signs are the per-input static filter alone
// (0 and `undecided` where it cannot decide: the item is marked and its
// decision abandoned), the second pass's the whole staged path, for the
// marked items only. The checks that change stars (Create, Apply, AddStar)
// run the staged path in one pass.
using FastSigns = dev::StaticOrient<Geo>;
struct ExactSigns {
  const Geo& g;
  static constexpr bool undecided = false;
  FF_HD int orient(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const { return g.orient(a, b, c, d); }
};
// q strictly inside the cone apex + R+{A - apex, ...} (want 1) or its reflection (want -1)
template <class Sg>
FF_HD bool in_cone(Sg& sg, uint32_t apex, uint32_t A, uint32_t B, uint32_t C, uint32_t q, int want) {
  const int s = sg.orient(apex, A, B, C) * want;
  return sg.orient(apex, A, B, q) == s && sg.orient(apex, B, C, q) == s && sg.orient(apex, C, A, q) == s;
}

// ---- the stars ------------------------------------------------------------------------
struct Stars {
  uint8_t* status;
  uint32_t* beg;
  uint32_t* cnt;
  uint32_t* cap;
  uint32_t* link;
  uint32_t* cert;
  uint32_t* broken;  // set when an insertion finds a star that is not convex (check_stars throws)
};

FF_HD inline uint32_t find_in(const uint32_t* L, uint32_t k, uint32_t x) {
  for (uint32_t i = 0; i < k; ++i)
    if (L[i] == x) return i;
  return kNo;
}
FF_HD inline void reverse_range(uint32_t* L, uint32_t lo, uint32_t hi) {  // [lo, hi)
  while (lo + 1 < hi) {
    --hi;
    const uint32_t t = L[lo];
    L[lo] = L[hi];
    L[hi] = t;
    ++lo;
  }
}

// Splaying (Figure 3.4, star_splaying.hpp): insert p into the star of s.
// 0: unchanged (s not alive, p == s, p a link vertex, or Case 1: p beneath
// every triangle); 1: Case 2, the run of beyond triangles replaced by two
// triangles at p; 2: Case 3, s died with the certificate {p, L0, Li, Li+1}
// (the fan cone from L0 holding s - p). The chunk must have room for one more
// link vertex.
FF_HD inline int splay_insert(const Geo& g, const Stars& S, uint32_t s, uint32_t p) {
  if (S.status[s] != kAlive || p == s) return 0;
  uint32_t* L = S.link + S.beg[s];
  const uint32_t k = S.cnt[s];
  if (find_in(L, k, p) != kNo) return 0;
  uint32_t beyond = 0, beneath_at = kNo;
  for (uint32_t i = 0; i < k; ++i) {
    if (g.orient(s, L[i], L[nx(i, k)], p) < 0) ++beyond;
    else if (beneath_at == kNo) beneath_at = i;
  }
  if (beyond == 0) return 0;  // Case 1
  if (beyond == k) {          // Case 3
    for (uint32_t i = 1; i + 1 < k; ++i) {
      ExactSigns sg{g};
      if (!in_cone(sg, s, L[0], L[i], L[i + 1], p, -1)) continue;
      uint32_t* c = S.cert + 4 * static_cast<std::size_t>(s);
      c[0] = p, c[1] = L[0], c[2] = L[i], c[3] = L[i + 1];
      S.status[s] = kDead;
      S.cnt[s] = 0;
      return 2;
    }
    atomic_store(S.broken, uint32_t{1});  // no fan cone: not a convex star (the reference throws too)
    return 0;
  }
  // Case 2: the beyond triangles form one run i0 .. i0 + beyond - 1
  uint32_t i0 = nx(beneath_at, k);
  while (!(g.orient(s, L[i0], L[nx(i0, k)], p) < 0)) i0 = nx(i0, k);
  // rotate i0 to the front: L0 stays, L1 .. L(m-1) leave, p joins after L0
  reverse_range(L, 0, i0);
  reverse_range(L, i0, k);
  reverse_range(L, 0, k);
  const uint32_t m = beyond;
  if (m == 1) {
    for (uint32_t i = k; i > 1; --i) L[i] = L[i - 1];
  } else {
    for (uint32_t i = m; i < k; ++i) L[i - m + 2] = L[i];
  }
  L[1] = p;
  S.cnt[s] = k - m + 2;
  return 1;
}

// ---- Algorithm 9 ----------------------------------------------------------------------
FF_HD inline uint64_t ins_key(uint32_t star, uint32_t point) { return (uint64_t{star} << 32) | point; }

// The link entries j of the alive members' stars that Sel picks
// (Sel::pick(v, L, j, k), L the link of v, k its length): counted per member,
// then written at the member's offset as Sel::make(v, L, j, k).
template <class Sel>
struct CountLinks {
  Stars S;
  const uint32_t* members;
  Sel sel;
  uint32_t* count;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t v = members[i];
    uint32_t c = 0;
    if (S.status[v] == kAlive) {
      const uint32_t* L = S.link + S.beg[v];
      const uint32_t k = S.cnt[v];
      for (uint32_t j = 0; j < k; ++j) c += sel.pick(v, L, j, k);
    }
    count[i] = c;
  }
};
template <class Sel, class T>
struct WriteLinks {
  Stars S;
  const uint32_t* members;
  Sel sel;
  const uint32_t* offset;
  T* out;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t v = members[i];
    if (S.status[v] != kAlive) return;
    const uint32_t* L = S.link + S.beg[v];
    const uint32_t k = S.cnt[v];
    uint32_t at = offset[i];
    for (uint32_t j = 0; j < k; ++j)
      if (sel.pick(v, L, j, k)) out[at++] = sel.make(v, L, j, k);
  }
};
// Lines 1 and 10: the candidate edges (v, u) with a changed endpoint.
struct Flagged {
  const uint8_t* changed;
  FF_HD bool pick(uint32_t v, const uint32_t* L, uint32_t j, uint32_t) const { return changed[v] || changed[L[j]]; }
  FF_HD uint64_t make(uint32_t v, const uint32_t* L, uint32_t j, uint32_t) const { return ins_key(v, L[j]); }
};

// Line 5: the local check and criterion on candidate edge (v, u)
// (star_splaying.cpp: demanded — the same cases, the same insertions), up to
// four insertions into out[4e .. 4e + 3] (kNoKey where fewer).
struct Demand {
  uint64_t k[4];
};
constexpr uint64_t kUndecidedKey = kNoKey - 1;  // the first pass's mark (no insertion has star 2^32 - 1)
struct Check {
  Geo g;
  Stars S;
  const uint64_t* edges;
  uint64_t* out;
  FF_HD FastSigns fast() const { return FastSigns(g); }
  FF_HD ExactSigns exact() const { return ExactSigns{g}; }
  FF_HD void write(std::size_t e, const Demand& d) const {
    for (int t = 0; t < 4; ++t) out[4 * e + t] = d.k[t];
  }
  FF_HD void mark(std::size_t e) const { out[4 * e] = kUndecidedKey; }
  FF_HD bool marked(std::size_t e) const { return out[4 * e] == kUndecidedKey; }
  template <class Sg>
  FF_HD Demand decide(std::size_t e, Sg& sg) const {
    Demand o{{kNoKey, kNoKey, kNoKey, kNoKey}};
    const uint32_t v = static_cast<uint32_t>(edges[e] >> 32), u = static_cast<uint32_t>(edges[e]);
    if (S.status[v] != kAlive) return o;
    const uint32_t* Lv = S.link + S.beg[v];
    const uint32_t kv = S.cnt[v];
    const uint32_t i = find_in(Lv, kv, u);
    if (i == kNo) return o;  // no longer a candidate
    if (S.status[u] == kDead) {  // u's certificate into v's star
      const uint32_t* c = S.cert + 4 * static_cast<std::size_t>(u);
      for (int t = 0; t < 4; ++t)
        if (c[t] != v) o.k[t] = ins_key(v, c[t]);
      return o;
    }
    if (S.status[u] != kAlive) return o;  // (every link vertex has a star: unreachable)
    const uint32_t* Lu = S.link + S.beg[u];
    const uint32_t ku = S.cnt[u];
    const uint32_t j = find_in(Lu, ku, v);
    if (j == kNo) {
      // v not in u's star: insert it, unless it would fail (Case 1) ...
      for (uint32_t t = 0; t < ku; ++t) {
        const bool beyond = sg.orient(u, Lu[t], Lu[nx(t, ku)], v) < 0;
        if (sg.undecided) return o;  // (abandoned: the second pass decides)
        if (beyond) {
          o.k[0] = ins_key(u, v);
          return o;
        }
      }
      // ... then the three link vertices of u that prohibit it go into v's star
      for (uint32_t t = 1; t + 1 < ku; ++t) {
        const bool inside = in_cone(sg, u, Lu[0], Lu[t], Lu[t + 1], v, 1);
        if (sg.undecided) return o;
        if (inside) {
          o.k[0] = ins_key(v, Lu[0]), o.k[1] = ins_key(v, Lu[t]), o.k[2] = ins_key(v, Lu[t + 1]);
          return o;
        }
      }
      return o;
    }
    const uint32_t a = Lv[pv(i, kv)], b = Lv[nx(i, kv)];
    const uint32_t c = Lu[pv(j, ku)], d = Lu[nx(j, ku)];
    int at = 0;
    if (b != c) o.k[at++] = ins_key(u, b), o.k[at++] = ins_key(v, c);
    if (a != d) o.k[at++] = ins_key(u, a), o.k[at++] = ins_key(v, d);
    return o;
  }
};

// The insertions into one star: a run of the sorted, unique list.
struct SegmentStart {
  const uint64_t* ins;
  FF_HD bool operator()(uint32_t i) const { return i == 0 || (ins[i] >> 32) != (ins[i - 1] >> 32); }
};
// The sorted, unique insertions ins[0, m) and the starts seg[0, nseg) of
// their runs, one run per star: run i is ins[lo, hi), into star v.
struct Runs {
  const uint64_t* ins;
  const uint32_t* seg;
  uint32_t nseg, m;
  FF_HD uint32_t get(uint32_t i, uint32_t& lo, uint32_t& hi) const {
    lo = seg[i], hi = i + 1 < nseg ? seg[i + 1] : m;
    return static_cast<uint32_t>(ins[lo] >> 32);
  }
};
// Lines 7-8: the room each star needs (its link plus one per insertion).
struct Need {
  Stars S;
  Runs runs;
  uint32_t* extra;
  uint32_t* short_of_room;
  FF_HD void operator()(uint32_t i) const {
    uint32_t lo, hi;
    const uint32_t v = runs.get(i, lo, hi);
    extra[v] = hi - lo;
    if (S.cnt[v] + (hi - lo) > S.cap[v]) atomic_store(short_of_room, uint32_t{1});
  }
};
struct NewCap {
  Stars S;
  const uint32_t* members;
  const uint32_t* extra;
  uint32_t* room;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t v = members[i];
    const uint32_t need = S.status[v] == kAlive ? S.cnt[v] + extra[v] : 0;
    room[i] = need + need / 4 + 4;
  }
};
struct Move {
  Stars S;
  const uint32_t* members;
  const uint32_t* room;
  const uint32_t* newbeg;
  uint32_t* newlink;
  uint32_t* extra;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t v = members[i];
    const uint32_t* L = S.link + S.beg[v];
    for (uint32_t j = 0; j < S.cnt[v]; ++j) newlink[newbeg[i] + j] = L[j];
    S.beg[v] = newbeg[i];
    S.cap[v] = room[i];
    extra[v] = 0;
  }
};
// Line 9: the insertions into one star, in ascending order of the point.
struct Apply {
  Geo g;
  Stars S;
  Runs runs;
  uint8_t* changed;
  uint32_t* extra;
  unsigned long long* counts;  // [0] successful insertions, [1] deaths
  FF_HD void operator()(uint32_t i) const {
    uint32_t lo, hi;
    const uint32_t v = runs.get(i, lo, hi);
    extra[v] = 0;
    unsigned long long splayed = 0, died = 0;
    for (uint32_t t = lo; t < hi; ++t) {
      const int r = splay_insert(g, S, v, static_cast<uint32_t>(runs.ins[t]));
      splayed += r == 1;
      died += r == 2;
    }
    if (splayed + died) {
      changed[v] = 1;
      atomic_fetch_add(counts, splayed);
      atomic_fetch_add(counts + 1, died);
    }
  }
};
struct ClearChanged {
  const uint32_t* members;
  uint8_t* changed;
  FF_HD void operator()(uint32_t i) const { changed[members[i]] = 0; }
};

// ---- Stage 0 ----------------------------------------------------------------------------
// the ≺-least of two points (compare_sos on x)
struct LexLess {
  const double* xyz;
  FF_HD uint32_t operator()(uint32_t a, uint32_t b) const {
    const double *A = xyz + 3 * static_cast<std::size_t>(a), *B = xyz + 3 * static_cast<std::size_t>(b);
    return dev::compare_sos(a, A, b, B, 0) < 0 ? a : b;
  }
};
// the points into the middle `fill` of [0, G]^3, per axis (halves: no overflow)
struct ScalePoints {
  const double* xyz;
  double lo[3], inv[3];
  double G, margin, fill;
  double* out;
  FF_HD void operator()(uint32_t i) const {
    for (int j = 0; j < 3; ++j) {
      double t = (xyz[3 * static_cast<std::size_t>(i) + j] * 0.5 - lo[j] * 0.5) * inv[j];
      t = t > 0 ? (t < 1 ? t : 1) : 0;
      out[3 * static_cast<std::size_t>(i) + j] = G * (margin + fill * t);
    }
  }
};

// ---- Stage 2 -------------------------------------------------------------------------------
struct MarkLabels {
  const uint32_t* labels;
  uint32_t* in_s;
  FF_HD void operator()(uint32_t px) const {
    if (labels[px] != kNo) atomic_store(in_s + labels[px], uint32_t{1});
  }
};
// item i's flag is set (for copy_if over indices)
template <class T>
struct IsSet {
  const T* flag;
  FF_HD bool operator()(uint32_t i) const { return flag[i] != 0; }
};
struct CreateRoom {
  const uint32_t* members;
  const uint32_t* off;
  uint32_t* room;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t v = members[i];
    room[i] = off[v + 1] - off[v] + 8;
  }
};
// One star per point of S' (Stage 2): three points of its working set (then
// r, then the first members) oriented by one orient3d, the rest of the
// working set and r inserted by beneath-beyond.
struct Create {
  Geo g;
  Stars S;
  const uint32_t* members;
  uint32_t nmembers;
  const uint32_t* off;
  const uint32_t* nbr;
  const uint32_t* room;
  const uint32_t* newbeg;
  uint32_t r;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t s = members[i];
    S.beg[s] = newbeg[i];
    S.cap[s] = room[i];
    S.status[s] = kAlive;
    uint32_t* L = S.link + S.beg[s];
    uint32_t k = 0;
    auto take = [&](uint32_t x) {
      if (k < 3 && x != s && x != kNo && find_in(L, k, x) == kNo) L[k++] = x;
    };
    for (uint32_t t = off[s]; t < off[s + 1] && k < 3; ++t) take(nbr[t]);
    take(r);
    for (uint32_t t = 0; t < nmembers && k < 3; ++t) take(members[t]);
    if (g.orient(s, L[0], L[1], L[2]) < 0) {  // (s, L0, L1) counter-clockwise from outside: L2 inside
      const uint32_t x = L[1];
      L[1] = L[2];
      L[2] = x;
    }
    S.cnt[s] = 3;
    for (uint32_t t = off[s]; t < off[s + 1]; ++t) splay_insert(g, S, s, nbr[t]);
    splay_insert(g, S, s, r);
  }
};

// ---- Stage 4: triangles, depth maps, the depth test, the exact location -------------
struct Tri {
  Index v[3];
};
static_assert(sizeof(Tri) == sizeof(Triangle), "Tri and Triangle must be three packed ids");
// the triangles of the alive stars, each from its smallest vertex
struct FromSmallest {
  FF_HD bool pick(uint32_t v, const uint32_t* L, uint32_t j, uint32_t k) const { return v < L[j] && v < L[nx(j, k)]; }
  FF_HD Tri make(uint32_t v, const uint32_t* L, uint32_t j, uint32_t k) const { return {{v, L[j], L[nx(j, k)]}}; }
};
struct TriLess {
  FF_HD bool operator()(const Tri& x, const Tri& y) const {
    if (x.v[0] != y.v[0]) return x.v[0] < y.v[0];
    if (x.v[1] != y.v[1]) return x.v[1] < y.v[1];
    return x.v[2] < y.v[2];
  }
};

// A view f = 2 axis + side of the render grid (R pixels a side): pixel axes
// as digital_voronoi.cuh's faces; depth measured from the side's plane.
struct View {
  int axis, a0, a1, side;
  FF_HD explicit View(uint32_t f)
      : axis(static_cast<int>(f / 2)),
        a0(static_cast<int>(first_axis(f / 2))),
        a1(static_cast<int>(second_axis(f / 2))),
        side(static_cast<int>(f % 2)) {}
};
FF_HD inline uint32_t float_bits(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
FF_HD inline float bits_float(uint32_t b) {
  float x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

// The rows of a front-facing triangle's bounding box in a view (0 when it
// faces away or is seen edge-on).
struct RasterGeometry {
  const Tri* tris;
  const double* sc;  // scaled coordinates (grid units)
  double to_render;  // R / G
  uint32_t R;
  FF_HD bool setup(uint32_t item, View& w, double (&A)[3][3], uint32_t& v0, uint32_t& v1) const {
    const uint32_t t = item / 6;
    w = View(item % 6);
    for (int c = 0; c < 3; ++c)
      for (int j = 0; j < 3; ++j) A[c][j] = sc[3 * static_cast<std::size_t>(tris[t].v[c]) + j] * to_render;
    // the outward normal's component on the view axis (counter-clockwise seen from outside)
    const double ux = A[1][w.a0] - A[0][w.a0], uy = A[1][w.a1] - A[0][w.a1];
    const double vx = A[2][w.a0] - A[0][w.a0], vy = A[2][w.a1] - A[0][w.a1];
    double nz = ux * vy - uy * vx;  // the normal's axis component, up to the axes' handedness
    // (a0, a1, axis) is a right-handed frame for axis 0 and 2, left-handed for 1
    if (w.axis == 1) nz = -nz;
    // side 0 looks along +axis: a triangle faces it when its normal points to -axis
    const bool front = w.side == 0 ? nz < 0 : nz > 0;
    if (!front) return false;
    double lo = A[0][w.a1], hi = lo;
    for (int c = 1; c < 3; ++c) lo = A[c][w.a1] < lo ? A[c][w.a1] : lo, hi = A[c][w.a1] > hi ? A[c][w.a1] : hi;
    // pixel rows j whose centre j + 0.5 is in [lo, hi]
    const double jlo = std::ceil(lo - 0.5), jhi = std::floor(hi - 0.5);
    if (jhi < jlo || jhi < 0 || jlo > R - 1.0) return false;
    v0 = static_cast<uint32_t>(jlo < 0 ? 0.0 : jlo);
    v1 = static_cast<uint32_t>(jhi > R - 1.0 ? R - 1.0 : jhi);
    return true;
  }
};
struct CountRows {
  RasterGeometry rg;
  uint32_t* rows;
  FF_HD void operator()(uint32_t item) const {
    View w(0);
    double A[3][3];
    uint32_t v0, v1;
    rows[item] = rg.setup(item, w, A, v0, v1) ? v1 - v0 + 1 : 0;
  }
};
// One bounding-box row of one (triangle, view): every pixel centre inside the
// projected triangle gets the triangle's depth there (the plane through its
// vertices) by an atomic minimum of (depth, the triangle's first vertex).
struct RasterRow {
  RasterGeometry rg;
  const uint32_t* row_offset;  // exclusive scan of the rows per item
  uint32_t items;
  uint64_t* maps;  // 6 R^2
  FF_HD void operator()(uint32_t k) const {
    // the item: the last whose offset is <= k
    uint32_t lo = 0, hi = items;
    while (hi - lo > 1) {
      const uint32_t mid = lo + (hi - lo) / 2;
      if (row_offset[mid] <= k) lo = mid;
      else hi = mid;
    }
    const uint32_t item = lo;
    View w(0);
    double A[3][3];
    uint32_t v0, v1;
    if (!rg.setup(item, w, A, v0, v1)) return;
    const uint32_t j = v0 + (k - row_offset[item]);
    const double y = j + 0.5;
    const uint32_t R = rg.R;
    // the span of the row inside the triangle: intersect y with its edges
    double xl = HUGE_VAL, xr = -HUGE_VAL;
    for (int c = 0; c < 3; ++c) {
      const double* P = A[c];
      const double* Q = A[(c + 1) % 3];
      const double py = P[w.a1], qy = Q[w.a1];
      if ((py <= y && y <= qy) || (qy <= y && y <= py)) {
        double x;
        if (py == qy) {
          x = P[w.a0];
          xl = x < xl ? x : xl, xr = x > xr ? x : xr;
          x = Q[w.a0];
        } else {
          x = P[w.a0] + (y - py) / (qy - py) * (Q[w.a0] - P[w.a0]);
        }
        xl = x < xl ? x : xl, xr = x > xr ? x : xr;
      }
    }
    if (!(xl <= xr)) return;
    const double ilo = std::ceil(xl - 0.5), ihi = std::floor(xr - 0.5);
    if (ihi < ilo || ihi < 0 || ilo > R - 1.0) return;
    const uint32_t i0 = static_cast<uint32_t>(ilo < 0 ? 0.0 : ilo), i1 = static_cast<uint32_t>(ihi > R - 1.0 ? R - 1.0 : ihi);
    // depth along the view by the plane: n . (X - A0) = 0
    const double e1[3] = {A[1][0] - A[0][0], A[1][1] - A[0][1], A[1][2] - A[0][2]};
    const double e2[3] = {A[2][0] - A[0][0], A[2][1] - A[0][1], A[2][2] - A[0][2]};
    const double nrm[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const uint32_t vertex = rg.tris[item / 6].v[0];
    uint64_t* map = maps + static_cast<std::size_t>(item % 6) * R * R + static_cast<std::size_t>(j) * R;
    for (uint32_t i = i0; i <= i1; ++i) {
      const double x = i + 0.5;
      // solve for the axis coordinate Z: nrm[a0](x - A0[a0]) + nrm[a1](y - A0[a1]) + nrm[axis](Z - A0[axis]) = 0
      const double Z = A[0][w.axis] - (nrm[w.a0] * (x - A[0][w.a0]) + nrm[w.a1] * (y - A[0][w.a1])) / nrm[w.axis];
      double d = w.side ? R - Z : Z;
      d = d > 0 ? d : 0;
      const uint64_t key = (uint64_t{float_bits(static_cast<float>(d))} << 32) | vertex;
      atomic_fetch_min(map + i, key);
    }
  }
};
// The digital depth test (§7.3.1): a point that is no member passes it when,
// in some view, its depth is at most one pixel behind the map's there
// (Lemma 7.1), or the map is empty there. start[p]: the vertex the map
// recorded (the colour buffer) in the first view that decided, for the walk.
struct DepthTest {
  const double* sc;
  double to_render;
  uint32_t R;
  const uint64_t* maps;
  uint8_t* role;
  uint32_t* start;
  bool drop_all;  // GhullOptions::drop_all (tests): every point dropped
  FF_HD void operator()(uint32_t p) const {
    if (role[p] != kDropped) return;  // members (and points already decided) keep their role
    double X[3];
    for (int j = 0; j < 3; ++j) X[j] = sc[3 * static_cast<std::size_t>(p) + j] * to_render;
    uint32_t any = kNo;
    for (uint32_t f = 0; f < 6; ++f) {
      const OnFace at = on_face(X, R, f);  // its pixel and depth on the render grid (digital_voronoi.cuh)
      const uint64_t key = maps[static_cast<std::size_t>(f) * R * R + static_cast<std::size_t>(at.v) * R + at.u];
      if (key == kNoKey) {
        if (drop_all) continue;
        role[p] = kCandidate;
        start[p] = any;
        return;
      }
      const uint32_t vertex = static_cast<uint32_t>(key);
      if (any == kNo) any = vertex;
      const double D = bits_float(static_cast<uint32_t>(key >> 32));
      if (at.h - D <= 1.0 && !drop_all) {
        role[p] = kCandidate;
        start[p] = vertex;
        return;
      }
    }
    start[p] = any;
  }
};

// Where point p is against the hull of the alive stars (Algorithm 10's
// question, answered as reference/hull3/initial_stars.cpp's Locator does):
// beyond a triangle of r's star (outside, B that triangle); else the walk
// over the triangles not incident to r (centrally projected from r they
// triangulate the cross-section of r's cone) to the triangle B whose cone
// from r holds p — a remembering stochastic walk on orient3d(r, x, y, p)
// (its choices hashed from p and the step), with a scan of every triangle
// after a step bound — and p beyond B (outside) or beneath it (strictly
// inside the tetrahedron (r, B)). Returns 1 outside, 0 inside; B in b[3].
struct Locator {
  Geo g;
  Stars S;
  uint32_t r;
  const Tri* tris;
  uint32_t ntris;
  FF_HD bool incident(const uint32_t* t) const { return t[0] == r || t[1] == r || t[2] == r; }
  // -2: a sign the fast signs could not decide (the decision is abandoned)
  template <class Sg>
  FF_HD int locate(Sg& sg, uint32_t p, uint32_t start, uint32_t* b) const {
    const uint32_t* Lr = S.link + S.beg[r];
    const uint32_t kr = S.cnt[r];
    for (uint32_t i = 0; i < kr; ++i) {
      const bool beyond = sg.orient(r, Lr[i], Lr[nx(i, kr)], p) < 0;
      if (sg.undecided) return -2;
      if (beyond) {
        b[0] = r, b[1] = Lr[i], b[2] = Lr[nx(i, kr)];
        return 1;
      }
    }
    // a triangle not incident to r at the start vertex (or at r's first neighbour)
    uint32_t c = start;
    if (c == kNo || c == r || S.status[c] != kAlive) c = Lr[0];
    uint32_t t[3] = {kNo, kNo, kNo};
    {
      const uint32_t* L = S.link + S.beg[c];
      const uint32_t k = S.cnt[c];
      for (uint32_t i = 0; i < k; ++i)
        if (L[i] != r && L[nx(i, k)] != r) {
          t[0] = c, t[1] = L[i], t[2] = L[nx(i, k)];
          break;
        }
    }
    bool settled = t[0] != kNo;
    const std::size_t bound = 4 * static_cast<std::size_t>(ntris) + 64;
    uint32_t h = p * 0x9E3779B1u + 0x7F4A7C15u;
    for (std::size_t step = 0; settled; ++step) {
      if (step > bound) {
        settled = false;
        break;
      }
      int cross[3], nc = 0;
      for (int e = 0; e < 3; ++e)
        if (sg.orient(r, t[e], t[(e + 1) % 3], p) > 0) cross[nc++] = e;
      if (sg.undecided) return -2;
      if (nc == 0) break;
      h ^= h << 13, h ^= h >> 17, h ^= h << 5;
      const int e = cross[nc == 1 ? 0 : h % static_cast<uint32_t>(nc)];
      const uint32_t x = t[e], y = t[(e + 1) % 3];
      // across directed edge (x, y): the triangle (y, x, w) of y's star
      const uint32_t* Ly = S.link + S.beg[y];
      const uint32_t ky = S.cnt[y];
      const uint32_t j = find_in(Ly, ky, x);
      if (j == kNo) {
        settled = false;
        break;
      }
      t[0] = y, t[1] = x, t[2] = Ly[nx(j, ky)];
      if (incident(t)) {
        settled = false;
        break;
      }
    }
    if (!settled) {  // every triangle not incident to r (the walk cannot miss: the cones tile r's cone)
      for (uint32_t q = 0; q < ntris; ++q) {
        const uint32_t* T = tris[q].v;
        if (incident(T)) continue;
        const bool holds = sg.orient(r, T[0], T[1], p) < 0 && sg.orient(r, T[1], T[2], p) < 0 &&
                           sg.orient(r, T[2], T[0], p) < 0;
        if (sg.undecided) return -2;
        if (holds) {
          t[0] = T[0], t[1] = T[1], t[2] = T[2];
          settled = true;
          break;
        }
      }
      if (!settled) return -1;  // no hull of the stars: reported by the caller
    }
    b[0] = t[0], b[1] = t[1], b[2] = t[2];
    const bool beyond = sg.orient(t[0], t[1], t[2], p) < 0;
    if (sg.undecided) return -2;
    return beyond ? 1 : 0;
  }
};
// Locate each listed point: outside -> its triangle in face[3i..], flag 1;
// inside -> role kInside, flag 0; -1 (no triangle: the stars are not a hull)
// counted in bad.
struct Located {
  int o;
  uint32_t b[3];
};
constexpr uint32_t kLocMark = 2;  // outside[i]: the first pass's mark
struct LocateAll {
  Locator loc;
  const uint32_t* list;
  const uint32_t* start;
  uint8_t* role;
  uint32_t* face;
  uint32_t* outside;
  uint32_t* bad;
  FF_HD FastSigns fast() const { return FastSigns(loc.g); }
  FF_HD ExactSigns exact() const { return ExactSigns{loc.g}; }
  template <class Sg>
  FF_HD Located decide(std::size_t i, Sg& sg) const {
    Located r{0, {kNo, kNo, kNo}};
    const uint32_t p = list[i];
    r.o = loc.locate(sg, p, start[p], r.b);
    return r;
  }
  FF_HD void write(std::size_t i, const Located& r) const {
    const uint32_t p = list[i];
    for (int j = 0; j < 3; ++j) face[3 * i + j] = r.b[j];
    outside[i] = r.o == 1;
    if (r.o == 0) role[p] = kInside;
    if (r.o < 0) atomic_store(bad, uint32_t{1});
  }
  FF_HD void mark(std::size_t i) const { outside[i] = kLocMark; }
  FF_HD bool marked(std::size_t i) const { return outside[i] == kLocMark; }
};
// The new stars of the points found outside: B's vertices (the cone over B
// holds r's direction: the segment from p to r crosses B), then r inserted.
struct AddStar {
  Geo g;
  Stars S;
  const uint32_t* list;     // the located points
  const uint32_t* face;     // their triangles
  const uint32_t* which;    // the indices (into list) of those outside
  uint32_t first_beg;       // their chunks: 8 entries each from here
  uint32_t r;
  uint8_t* role;
  uint8_t* changed;
  FF_HD void operator()(uint32_t k) const {
    const uint32_t i = which[k], p = list[i];
    S.beg[p] = first_beg + 8 * k;
    S.cap[p] = 8;
    S.status[p] = kAlive;
    uint32_t* L = S.link + S.beg[p];
    const uint32_t* B = face + 3 * static_cast<std::size_t>(i);
    L[0] = B[0], L[1] = B[1], L[2] = B[2];
    S.cnt[p] = 3;
    role[p] = kMember;
    changed[p] = 1;
    splay_insert(g, S, p, r);
  }
};
// ---- Stage 6's inner ball and box (Ghull::inner_region) --------------------------
FF_HD inline void tri_normal(const double* a, const double* b, const double* c, double* n) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
}
// the weighted sum, the minima and the maxima of the triangles' vertices
struct Acc {
  double sum[3], lo[3], hi[3];
};
template <class Acc>
struct VertexAcc {
  const double* xyz;
  const Tri* tris;
  double w;
  FF_HD Acc operator()(std::size_t k) const {
    const double* p = xyz + 3 * static_cast<std::size_t>(tris[k / 3].v[k % 3]);
    return {{p[0] * w, p[1] * w, p[2] * w}, {p[0], p[1], p[2]}, {p[0], p[1], p[2]}};
  }
};
template <class Acc>
struct AccJoin {
  FF_HD Acc operator()(const Acc& x, const Acc& y) const {
    Acc r;
    for (int j = 0; j < 3; ++j) {
      r.sum[j] = x.sum[j] + y.sum[j];
      r.lo[j] = x.lo[j] < y.lo[j] ? x.lo[j] : y.lo[j];
      r.hi[j] = x.hi[j] > y.hi[j] ? x.hi[j] : y.hi[j];
    }
    return r;
  }
};
struct MinOf {
  FF_HD double operator()(double x, double y) const { return x < y ? x : y; }
};
// the floating distance from c to the plane of triangle t, inner side
// positive (+inf for a triangle of zero area: it bounds nothing; NaN -> 0)
struct Clearance {
  const double* xyz;
  const Tri* tris;
  double c[3];
  FF_HD double operator()(uint32_t t) const {
    const double *a = xyz + 3 * static_cast<std::size_t>(tris[t].v[0]), *b = xyz + 3 * static_cast<std::size_t>(tris[t].v[1]),
                 *d = xyz + 3 * static_cast<std::size_t>(tris[t].v[2]);
    double n[3];
    tri_normal(a, b, d, n);
    double len2 = 0, dot = 0;
    for (int j = 0; j < 3; ++j) len2 += n[j] * n[j], dot += n[j] * (c[j] - a[j]);
    const double len = sqrt(len2);
    if (!(len > 0)) return HUGE_VAL;
    const double r = -dot / len;
    return r == r ? r : 0.0;
  }
};
// the largest t with the box mid + t [-half, half] on the inner side of
// triangle t's plane in floating point (+inf for a zero-area triangle)
struct BoxReach {
  const double* xyz;
  const Tri* tris;
  double m[3], h[3];
  FF_HD double operator()(uint32_t t) const {
    const double *a = xyz + 3 * static_cast<std::size_t>(tris[t].v[0]), *b = xyz + 3 * static_cast<std::size_t>(tris[t].v[1]),
                 *c = xyz + 3 * static_cast<std::size_t>(tris[t].v[2]);
    double n[3];
    tri_normal(a, b, c, n);
    double gap = 0, spread = 0;  // n.(a - m) > 0 inside; the box reaches t sum |n_j| h_j
    for (int j = 0; j < 3; ++j) gap += n[j] * (a[j] - m[j]), spread += (n[j] < 0 ? -n[j] : n[j]) * h[j];
    if (!(spread > 0)) return HUGE_VAL;
    const double r = gap / spread;
    return r == r ? r : 0.0;
  }
};
// Triangle t keeps the ball (centre c, squared radius r2) on its inner side,
// certainly (InnerBall::clears_filtered's test, on the device), or is marked.
struct BallFilter {
  const double* xyz;
  const Tri* tris;
  double c[3], r2;
  uint8_t* uncertain;
  FF_HD void operator()(uint32_t t) const {
    const double *a = xyz + 3 * static_cast<std::size_t>(tris[t].v[0]), *b = xyz + 3 * static_cast<std::size_t>(tris[t].v[1]),
                 *d = xyz + 3 * static_cast<std::size_t>(tris[t].v[2]);
    using pred::ErrDouble;
    const ErrDouble u[3] = {ErrDouble(b[0]) - ErrDouble(a[0]), ErrDouble(b[1]) - ErrDouble(a[1]), ErrDouble(b[2]) - ErrDouble(a[2])};
    const ErrDouble v[3] = {ErrDouble(d[0]) - ErrDouble(a[0]), ErrDouble(d[1]) - ErrDouble(a[1]), ErrDouble(d[2]) - ErrDouble(a[2])};
    const ErrDouble N[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    ErrDouble M(0.0), Dot(0.0);
    for (int j = 0; j < 3; ++j) M = M + N[j] * N[j], Dot = Dot - N[j] * (ErrDouble(c[j]) - ErrDouble(a[j]));
    const bool sure = pred::sign_if_certain(M) > 0 && pred::sign_if_certain(Dot) > 0 &&
                      pred::sign_if_certain(Dot * Dot - ErrDouble(r2) * M) > 0;
    uncertain[t] = !sure;
  }
};
// Triangle t has every corner of the box strictly on its inner side,
// certainly (the per-call semi-static filter of orient3d), or is marked.
struct BoxFilter {
  const double* xyz;
  const Tri* tris;
  certify::BoxTest3 box;
  uint8_t* uncertain;
  FF_HD void operator()(uint32_t t) const {
    const double* p[4] = {xyz + 3 * static_cast<std::size_t>(tris[t].v[0]), xyz + 3 * static_cast<std::size_t>(tris[t].v[1]),
                          xyz + 3 * static_cast<std::size_t>(tris[t].v[2]), nullptr};
    bool sure = true;
    for (unsigned k = 0; k < 8 && sure; ++k) {
      const double corner[3] = {(k & 1u) ? box.hi[0] : box.lo[0], (k & 2u) ? box.hi[1] : box.lo[1],
                                (k & 4u) ? box.hi[2] : box.lo[2]};
      p[3] = corner;
      sure = pred::semi_static_sign<4>(p, nullptr) > 0;
    }
    uncertain[t] = !sure;
  }
};
// A dropped point strictly inside the verified inner ball or box (Stage 6).
struct InnerRegion {
  const double* xyz;
  certify::BallTest<3> ball;
  certify::BoxTest3 box;
  uint8_t* role;
  FF_HD void operator()(uint32_t p) const {
    if (role[p] != kDropped) return;
    const double* x = xyz + 3 * static_cast<std::size_t>(p);
    if (ball.strictly_inside(x) || box.strictly_inside(x)) role[p] = kInside;
  }
};
struct HasRole {
  const uint8_t* role;
  uint8_t want;
  FF_HD bool operator()(uint32_t p) const { return role[p] == want; }
};

// ---- the whole computation -----------------------------------------------------------------
template <class F>
auto on_device(std::size_t n, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw kernels::DeviceMemoryError("hull3 ghull: " + std::to_string(n) + " points do not fit in device memory");
  }
}

template <class T>
void fill_buf(backend::Buffer<T>& b, std::size_t count, T value) {
  if (count == 0) return;
  backend::run_step<kGrain>(count, [&](auto policy) { thrust::fill_n(policy, b.begin(), count, value); });
}
// exclusive scan of in[0, m) into out (m + 1 entries: out[m] is the total); the total
template <class T>
uint64_t scan_total(backend::Buffer<T>& in, std::size_t m, backend::Buffer<T>& out) {
  if (out.size() < m + 1) out.resize(m + 1);
  if (m == 0) {
    out[0] = 0;
    return 0;
  }
  const T last = backend::read_one(in, m - 1);
  backend::run_step<kGrain>(m, [&](auto policy) {
    thrust::exclusive_scan(policy, in.begin(), in.begin() + static_cast<std::ptrdiff_t>(m), out.begin());
  });
  const uint64_t total = static_cast<uint64_t>(backend::read_one(out, m - 1)) + last;
  out[m] = static_cast<T>(total);
  return total;
}
template <class Pred>
std::size_t select_indices(std::size_t n, backend::Buffer<uint32_t>& out, Pred pred) {
  if (out.size() < n) out.resize(n);
  std::size_t m = 0;
  thrust::counting_iterator<uint32_t> first(0);
  backend::run_step<kGrain>(n, [&](auto policy) {
    m = static_cast<std::size_t>(thrust::copy_if(policy, first, first + n, out.begin(), pred) - out.begin());
  });
  return m;
}
// Stage 2's members: a star each, all of them to be checked in Stage 3.
// (Functors that kernels run live at namespace scope: nvcc's launch stubs
// name them from outside any class.)
struct MarkMembers {
  const uint32_t* members;
  uint8_t* role;
  uint8_t* changed;
  FF_HD void operator()(uint32_t i) const {
    role[members[i]] = kMember;
    changed[members[i]] = 1;
  }
};

// The triangles' side of Stage 6 (Ghull::inner_region): reductions and
// filtered checks on the device, the undecided triangles exactly on the host.
struct InnerFacets {
  const double* xyz;
  const Tri* tris;
  double min_clearance(std::size_t F, const double* c) const {
    double m = HUGE_VAL;
    Clearance cl{xyz, tris, {c[0], c[1], c[2]}};
    backend::run_step<kGrain>(F, [&](auto policy) {
      m = thrust::transform_reduce(policy, thrust::counting_iterator<uint32_t>(0),
                                   thrust::counting_iterator<uint32_t>(static_cast<uint32_t>(F)), cl, m, MinOf());
    });
    return m;
  }
  double box_scale(std::size_t F, const double* mid, const double* half) const {
    double m = HUGE_VAL;
    BoxReach br{xyz, tris, {mid[0], mid[1], mid[2]}, {half[0], half[1], half[2]}};
    backend::run_step<kGrain>(F, [&](auto policy) {
      m = thrust::transform_reduce(policy, thrust::counting_iterator<uint32_t>(0),
                                   thrust::counting_iterator<uint32_t>(static_cast<uint32_t>(F)), br, m, MinOf());
    });
    return m;
  }
  // the triangles the filter marked, on the host (ids and vertices)
  template <class Filter>
  std::vector<Tri> undecided(std::size_t F, const Filter& make) const {
    backend::Buffer<uint8_t> mark(F);
    backend::Buffer<uint32_t> list;
    for_range(F, make(raw(mark)));
    const std::size_t k = select_indices(F, list, IsSet<uint8_t>{raw(mark)});
    std::vector<uint32_t> ids(k);
    if (k) thrust::copy(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(k), ids.begin());
    std::vector<Tri> out;
    for (uint32_t t : ids) out.push_back(read_tri(t));
    return out;
  }
  Tri read_tri(uint32_t t) const {
    Tri x;
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
    x = tris[t];
#else
    cudaMemcpy(&x, tris + t, sizeof x, cudaMemcpyDeviceToHost);
#endif
    return x;
  }
  bool ball_holds(std::size_t F, const double* c, double r2, const PointSet& ps) const {
    const std::array<double, 3> cc = {c[0], c[1], c[2]};
    for (const Tri& x : undecided(F, [&](uint8_t* m) { return BallFilter{xyz, tris, {c[0], c[1], c[2]}, r2, m}; })) {
      const Triangle f = {x.v[0], x.v[1], x.v[2]};
      if (!certify::detail::InnerBall<3>::clears_exact(ps, f, cc.data(), r2)) return false;
    }
    return true;
  }
  bool box_holds(std::size_t F, const certify::BoxTest3& box, const PointSet& ps) const {
    for (const Tri& x : undecided(F, [&](uint8_t* m) { return BoxFilter{xyz, tris, box, m}; })) {
      // every corner strictly inside, or all eight on the plane: a zero-area triangle, which bounds nothing
      int positive = 0, zero = 0;
      for (unsigned k = 0; k < 8; ++k) {
        double corner[3];
        box.corner(k, corner);
        const int o = pred::orient3d_exact(ps.point(x.v[0]), ps.point(x.v[1]), ps.point(x.v[2]), corner);
        positive += o > 0, zero += o == 0;
      }
      if (positive != 8 && zero != 8) return false;
    }
    return true;
  }
};

// §6.4.2: the filter-only pass over every item, then the exact pass for the marked ones
template <class F>
void two_passes(std::size_t n, const F& f) {
  for_range<256>(n, dev::Pass<F, false>{f});
  for_range<256>(n, dev::Pass<F, true>{f});
}

class Ghull {
 public:
  Ghull(const PointSet& ps, const kernels::GhullOptions& opt, kernels::GhullStats& st, cpu::StageClock& clock)
      : ps_(ps), n_(ps.size()), opt_(opt), st_(st), clock_(clock) {}

  // Stages 0-3 only, the stars after Stage 2 copied out (ghull_stages::approximation)
  std::vector<ref::Star>* stage2_stars = nullptr;
  bool stop_after_stage3 = false;

  std::vector<Triangle> run() {
    const std::size_t n = n_;
    const double* xyz = backend::to_device(ps_.coords.data(), ps_.coords.size(), coords_);
    g_.xyz = xyz;
    g_.filter = filter::static_filter<kGrain>(xyz, 3 * n);
    clock_.mark("upload");
    stage0();
    clock_.mark("stage 0: r, scaling");
    // ---- Stage 1
    const uint32_t G = grid_;
    backend::Buffer<uint32_t> labels, sites;
    st_.bands = ghull_detail::digital_voronoi(raw(scaled_), static_cast<uint32_t>(n), G, labels, sites, opt_.bands);
    clock_.mark("stage 1: digital Voronoi");
    // ---- Stage 2
    backend::Buffer<uint32_t> off, nbr;
    ghull_detail::working_sets(raw(labels), G, static_cast<uint32_t>(n), off, nbr);
    st_.working_pairs = nbr.size();
    backend::Buffer<uint32_t> in_s(n);
    fill_buf(in_s, n, uint32_t{0});
    for_range(labels.size(), MarkLabels{raw(labels), raw(in_s)});
    for (uint32_t x : {r_, tet_[0], tet_[1], tet_[2], tet_[3]}) in_s[x] = 1;
    labels = backend::Buffer<uint32_t>();
    sites = backend::Buffer<uint32_t>();
    nm_ = select_indices(n, members_, IsSet<uint32_t>{raw(in_s)});
    in_s = backend::Buffer<uint32_t>();
    st_.captured = nm_;
    status_.resize(n), beg_.resize(n), cnt_.resize(n), cap_.resize(n), cert_.resize(4 * n), changed_.resize(n),
        extra_.resize(n), role_.resize(n);
    fill_buf(status_, n, kNone);
    fill_buf(cnt_, n, uint32_t{0});
    fill_buf(cap_, n, uint32_t{0});
    fill_buf(changed_, n, uint8_t{0});
    fill_buf(extra_, n, uint32_t{0});
    fill_buf(role_, n, kDropped);
    {
      backend::Buffer<uint32_t> room(nm_), newbeg;
      for_range(nm_, CreateRoom{raw(members_), raw(off), raw(room)});
      const uint64_t total = scan_total(room, nm_, newbeg);
      check_edge_list(total);
      link_.resize(total);
      for_range<64>(nm_, Create{g_, stars(), raw(members_), static_cast<uint32_t>(nm_), raw(off), raw(nbr), raw(room),
                                raw(newbeg), r_});
      link_end_ = total;
      check_stars();
    }
    off = backend::Buffer<uint32_t>();
    nbr = backend::Buffer<uint32_t>();
    for_range(nm_, MarkMembers{raw(members_), raw(role_), raw(changed_)});
    clock_.mark("stage 2: stars");
    if (stage2_stars) *stage2_stars = copy_stars();
    // ---- Stage 3
    splay();
    st_.approx_vertices = count_status(kAlive);
    clock_.mark("stage 3: star splaying");
    if (stop_after_stage3) {
      build_triangles();
      return output();
    }
    // ---- Stage 4
    build_triangles();
    const uint32_t R = render_;
    {
      backend::Buffer<uint64_t> maps(6 * static_cast<std::size_t>(R) * R);
      fill_buf(maps, maps.size(), kNoKey);
      const RasterGeometry rg{raw(tris_), raw(scaled_), static_cast<double>(R) / G, R};
      const std::size_t items = 6 * static_cast<std::size_t>(ntris_);
      backend::Buffer<uint32_t> rows(items), row_offset;
      for_range(items, CountRows{rg, raw(rows)});
      const uint64_t total_rows = scan_total(rows, items, row_offset);
      if (total_rows > 0xffffffffull) throw std::invalid_argument("hull3 ghull: too many rows to render");
      for_range<64>(total_rows, RasterRow{rg, raw(row_offset), static_cast<uint32_t>(items), raw(maps)});
      start_.resize(n);
      for_range(n, DepthTest{raw(scaled_), static_cast<double>(R) / G, R, raw(maps), raw(role_), raw(start_), opt_.drop_all});
    }
    clock_.mark("stage 4: depth test");
    backend::Buffer<uint32_t> list;
    const std::size_t nc = select_indices(n, list, HasRole{raw(role_), kCandidate});
    st_.depth_candidates = nc;
    st_.added = add_outside(list, nc);
    clock_.mark("stage 4: point addition");
    // ---- Stage 5
    splay();
    clock_.mark("stage 5: star splaying");
    // ---- Stage 6
    build_triangles();
    inner_region();
    const std::size_t nd = select_indices(n, list, HasRole{raw(role_), kDropped});
    st_.depth_misses = add_outside(list, nd);
    if (st_.depth_misses) {
      splay();
      build_triangles();
    }
    clock_.mark("stage 6: verification");
    st_.dead_stars = count_status(kDead);
    if (opt_.drop_all && st_.depth_candidates) throw std::logic_error("hull3 ghull: drop_all kept a candidate");
    return output();
  }

 private:
  // the triangles (each from its smallest vertex: the canonical rotation), sorted
  std::vector<Triangle> output() {
    backend::run_step<kGrain>(ntris_, [&](auto policy) {
      thrust::sort(policy, tris_.begin(), tris_.begin() + static_cast<std::ptrdiff_t>(ntris_), TriLess());
    });
    backend::sync();
    clock_.mark("output");
    const std::vector<Tri> host = backend::to_host(tris_, ntris_);
    std::vector<Triangle> out(ntris_);
    if (ntris_) std::memcpy(out.data(), host.data(), ntris_ * sizeof(Tri));
    clock_.mark("download");
    return out;
  }
  std::vector<ref::Star> copy_stars() {
    const std::vector<uint32_t> members = download(members_, nm_);
    const std::vector<uint8_t> status = download(status_, n_);
    const std::vector<uint32_t> beg = download(beg_, n_), cnt = download(cnt_, n_), cert = download(cert_, 4 * n_),
                                link = download(link_, link_end_);
    std::vector<ref::Star> out;
    for (uint32_t v : members) {
      ref::Star s;
      s.apex = v;
      s.dead = status[v] == kDead;
      if (s.dead)
        for (int j = 0; j < 4; ++j) s.certificate[j] = cert[4 * static_cast<std::size_t>(v) + j];
      else
        s.link.assign(link.begin() + beg[v], link.begin() + beg[v] + cnt[v]);
      out.push_back(std::move(s));
    }
    return out;
  }
  // the first count elements, copied to the host in one transfer (the
  // buffer stays: backend::to_host would move it out in the OpenMP build)
  template <class T>
  static std::vector<T> download(const backend::Buffer<T>& b, std::size_t count) {
    std::vector<T> h(count);
    if (count) thrust::copy(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(count), h.begin());
    return h;
  }
  Stars stars() {
    return {raw(status_), raw(beg_), raw(cnt_), raw(cap_), raw(link_), raw(cert_), raw(broken_)};
  }
  // after the steps that insert into stars: a star that was not convex is a
  // bug, reported, never a hull computed from it
  void check_stars() {
    if (backend::read_one(broken_, 0))
      throw std::logic_error("hull3 ghull: an insertion met a star that is not convex (no fan cone holds the point)");
  }
  static void check_edge_list(uint64_t total) {
    if (total >= 0xffffffffull) throw std::invalid_argument("hull3 ghull: the edge list exceeds 32-bit offsets");
  }

  // Stage 0: r, a spanning tetrahedron (or the reference's rejection), the grid, the scaled points.
  void stage0() {
    const std::size_t n = n_;
    if (filter::representatives<kGrain>(g_.xyz, 3 * n).bad != 0)
      throw std::invalid_argument("hull3 ghull: every coordinate must be finite (NaN or infinity in the input)");
    thrust::counting_iterator<uint32_t> first(0);
    backend::run_step<kGrain>(n, [&](auto policy) {
      r_ = thrust::reduce(policy, first + 1, first + n, uint32_t{0}, LexLess{g_.xyz});
    });
    bool by_reference = false;
    const auto t = dev::spanning_tetrahedron(ps_, g_.xyz, [&](const auto& key) {
      dev::Best best{-HUGE_VAL, kNo};
      backend::run_step<kGrain>(n, [&](auto policy) {
        best = thrust::transform_reduce(policy, thrust::counting_iterator<std::size_t>(0),
                                        thrust::counting_iterator<std::size_t>(n), key, best, dev::BestOf());
      });
      return best.id;
    }, &by_reference);
    st_.handed_back += by_reference;
    tet_ = {t[0], t[1], t[2], t[3]};
    dev::Box ext{{0, 0, 0}, {0, 0, 0}};
    for (int j = 0; j < 3; ++j) ext.lo[j] = ext.hi[j] = ps_.point(0)[j];
    backend::run_step<kGrain>(n, [&](auto policy) {
      ext = thrust::transform_reduce(policy, first, first + n, dev::PointBox{g_.xyz}, ext, dev::BoxUnion());
    });
    // the grid: a power of two near sqrt(n), in [64, 1024] (the thesis: 1024 for 10^6..10^7)
    uint32_t G = opt_.grid;
    if (G == 0) {
      G = 64;
      while (G < 1024 && 4.0 * G * G < static_cast<double>(n)) G *= 2;
    }
    if (G < 4 || G > 2048) throw std::invalid_argument("hull3 ghull: the grid must be 4..2048 pixels a side");
    grid_ = G;
    render_ = opt_.render ? opt_.render : std::max<uint32_t>(G / 2, 4);
    st_.grid = grid_, st_.render = render_;
    const double fill = opt_.fill > 0 && opt_.fill <= 0.98 ? opt_.fill : 0.8;
    ScalePoints sp{g_.xyz, {0, 0, 0}, {0, 0, 0}, static_cast<double>(G) * (1 - 1e-9), (1 - fill) / 2, fill, nullptr};
    for (int j = 0; j < 3; ++j) {
      sp.lo[j] = ext.lo[j];
      const double w = ext.hi[j] * 0.5 - ext.lo[j] * 0.5;
      sp.inv[j] = w > 0 ? 1 / w : 0;
    }
    scaled_.resize(3 * n);
    sp.out = raw(scaled_);
    for_range(n, sp);
  }

  // Algorithm 9 until no flagged edge demands an insertion; changed_ flags the stars to check.
  void splay() {
    backend::Buffer<uint32_t> count(nm_), offset, seg;
    backend::Buffer<uint64_t> edges, ins;
    backend::Buffer<uint32_t> flag(1);
    backend::Buffer<unsigned long long> counts(2);
    fill_buf(counts, 2, 0ull);
    for (;;) {
      if (count.size() < nm_) count.resize(nm_);
      const Flagged flagged{raw(changed_)};
      for_range(nm_, CountLinks<Flagged>{stars(), raw(members_), flagged, raw(count)});
      const uint64_t E = scan_total(count, nm_, offset);
      if (E == 0) break;
      if (E > 0x3fffffffull) throw std::invalid_argument("hull3 ghull: too many flagged edges");
      edges.resize(E);
      for_range(nm_, WriteLinks<Flagged, uint64_t>{stars(), raw(members_), flagged, raw(offset), raw(edges)});
      ins.resize(4 * E);
      two_passes(E, Check{g_, stars(), raw(edges), raw(ins)});
      std::size_t m = 4 * E;
      backend::run_step<kGrain>(m, [&](auto policy) {
        thrust::sort(policy, ins.begin(), ins.begin() + static_cast<std::ptrdiff_t>(m));
        m = static_cast<std::size_t>(thrust::unique(policy, ins.begin(), ins.begin() + static_cast<std::ptrdiff_t>(m)) -
                                     ins.begin());
        m = static_cast<std::size_t>(
            thrust::lower_bound(policy, ins.begin(), ins.begin() + static_cast<std::ptrdiff_t>(m), kNoKey) - ins.begin());
      });
      ++st_.splay_rounds;
      if (m == 0) break;
      // the runs of one star each
      const std::size_t nseg = select_indices(m, seg, SegmentStart{raw(ins)});
      fill_buf(flag, 1, uint32_t{0});
      const Runs runs{raw(ins), raw(seg), static_cast<uint32_t>(nseg), static_cast<uint32_t>(m)};
      for_range(nseg, Need{stars(), runs, raw(extra_), raw(flag)});
      if (backend::read_one(flag, 0)) grow();
      for_range(nm_, ClearChanged{raw(members_), raw(changed_)});
      const unsigned long long before = backend::read_one(counts, 0) + backend::read_one(counts, 1);
      for_range<64>(nseg, Apply{g_, stars(), runs, raw(changed_), raw(extra_), raw(counts)});
      check_stars();
      // (the reference's progress argument: some demanded insertion succeeds)
      if (backend::read_one(counts, 0) + backend::read_one(counts, 1) == before)
        throw std::logic_error("hull3 ghull: star splaying made no progress");
    }
    st_.splay_insertions += backend::read_one(counts, 0);
    for_range(nm_, ClearChanged{raw(members_), raw(changed_)});
  }
  // Lines 7-8: every member's chunk re-sized to its need plus a quarter.
  void grow() {
    backend::Buffer<uint32_t> room(nm_), newbeg;
    for_range(nm_, NewCap{stars(), raw(members_), raw(extra_), raw(room)});
    const uint64_t total = scan_total(room, nm_, newbeg);
    check_edge_list(total);
    backend::Buffer<uint32_t> newlink(total);
    for_range(nm_, Move{stars(), raw(members_), raw(room), raw(newbeg), raw(newlink), raw(extra_)});
    link_.swap(newlink);
    link_end_ = total;
    ++st_.edge_list_growths;
  }
  // Stage 4 (and 6): locate the listed points against the hull of the alive
  // stars; those outside get stars and join the members. Returns how many.
  std::size_t add_outside(backend::Buffer<uint32_t>& list, std::size_t count) {
    if (count == 0) return 0;
    backend::Buffer<uint32_t> face(3 * count), outside(count), bad(1), which;
    fill_buf(bad, 1, uint32_t{0});
    const Locator loc{g_, stars(), r_, raw(tris_), static_cast<uint32_t>(ntris_)};
    two_passes(count, LocateAll{loc, raw(list), raw(start_), raw(role_), raw(face), raw(outside), raw(bad)});
    if (backend::read_one(bad, 0))
      throw std::logic_error("hull3 ghull: a point inside r's cone lies in no triangle's cone (the stars are not a hull)");
    const std::size_t k = select_indices(count, which, IsSet<uint32_t>{raw(outside)});
    if (k == 0) return 0;
    const uint64_t first_beg = link_end_;
    check_edge_list(first_beg + 8 * k);
    link_.resize(first_beg + 8 * k);
    link_end_ = first_beg + 8 * k;
    for_range<64>(k, AddStar{g_, stars(), raw(list), raw(face), raw(which), static_cast<uint32_t>(first_beg), r_,
                             raw(role_), raw(changed_)});
    check_stars();
    nm_ = select_indices(n_, members_, HasRole{raw(role_), kMember});
    return k;
  }
  // Stage 6's shortcut: an inner ball and an inner box of the hull of the
  // stars, as the certifier's (reference/certify/inner_ball.hpp,
  // inner_box.hpp), built and checked on the device: the candidate centres,
  // radius and box by reductions over the triangles, each triangle's check
  // by a floating filter with an error bound (InnerFacets); only the
  // triangles the filter cannot decide (zero-area ones, a few near the
  // bound) are checked exactly on the host (clears_exact, orient3d_exact).
  // A dropped point strictly inside the ball or the box is then strictly
  // inside the hull (the consistent stars bound the convex hull of the
  // members: the splaying theorem) and needs no walk. A region whose check
  // fails is empty: every point then walks.
  void inner_region() {
    if (ntris_ == 0) return;
    const InnerFacets f{g_.xyz, raw(tris_)};
    const std::size_t F = ntris_;
    // the vertices' mean and bounding box (each vertex counted once per triangle)
    const double* xyz = g_.xyz;
    const Tri* tris = raw(tris_);
    Acc acc{{0, 0, 0}, {HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
    backend::run_step<kGrain>(3 * F, [&](auto policy) {
      acc = thrust::transform_reduce(
          policy, thrust::counting_iterator<std::size_t>(0), thrust::counting_iterator<std::size_t>(3 * F),
          VertexAcc<Acc>{xyz, tris, 1.0 / (3.0 * static_cast<double>(F))}, acc, AccJoin<Acc>());
    });
    double mean[3], mid[3], half[3];
    for (int j = 0; j < 3; ++j)
      mean[j] = acc.sum[j], mid[j] = acc.lo[j] / 2 + acc.hi[j] / 2, half[j] = acc.hi[j] / 2 - acc.lo[j] / 2;
    // the ball: the centre farther from every triangle's plane, 0.999999 of that distance
    const double dmean = f.min_clearance(F, mean), dmid = f.min_clearance(F, mid);
    certify::BallTest<3> ball;
    const bool use_mid = dmid > dmean;
    const double* c = use_mid ? mid : mean;
    const double r = (use_mid ? dmid : dmean) * 0.999999, r2 = r * r;
    if (r > 0 && std::isfinite(r2) && r2 >= 0x1p-900 && f.ball_holds(F, c, r2, ps_)) {
      for (int j = 0; j < 3; ++j) ball.s[j] = c[j];
      ball.limit = r2 * (1 - 0x1p-40);
    }
    // the box: around the middle, the largest scale of the half-extents that
    // floating point puts inside every triangle's plane, shrunk by 2^-20
    certify::BoxTest3 box;
    double t = f.box_scale(F, mid, half) * (1 - 0x1p-20);
    if (t > 0 && std::isfinite(t)) {
      for (int j = 0; j < 3; ++j) box.lo[j] = mid[j] - t * half[j], box.hi[j] = mid[j] + t * half[j];
      if (box.empty() || !f.box_holds(F, box, ps_)) box = certify::BoxTest3{};
    }
    if (ball.limit == 0 && box.empty()) return;
    for_range(n_, InnerRegion{g_.xyz, ball, box, raw(role_)});
  }
  void build_triangles() {
    backend::Buffer<uint32_t> count(nm_), offset;
    for_range(nm_, CountLinks<FromSmallest>{stars(), raw(members_), {}, raw(count)});
    ntris_ = scan_total(count, nm_, offset);
    tris_.resize(ntris_);
    for_range(nm_, WriteLinks<FromSmallest, Tri>{stars(), raw(members_), {}, raw(offset), raw(tris_)});
  }
  std::size_t count_status(uint8_t s) {
    std::size_t c = 0;
    backend::run_step<kGrain>(n_, [&](auto policy) {
      c = static_cast<std::size_t>(thrust::count(policy, status_.begin(), status_.begin() + static_cast<std::ptrdiff_t>(n_), s));
    });
    return c;
  }

  const PointSet& ps_;
  std::size_t n_;
  const kernels::GhullOptions& opt_;
  kernels::GhullStats& st_;
  cpu::StageClock& clock_;
  Geo g_{};
  uint32_t r_ = 0;
  std::array<uint32_t, 4> tet_{};
  uint32_t grid_ = 0, render_ = 0;
  backend::Buffer<double> coords_, scaled_;
  backend::Buffer<uint32_t> members_;
  std::size_t nm_ = 0;
  backend::Buffer<uint8_t> status_, changed_, role_;
  backend::Buffer<uint32_t> beg_, cnt_, cap_, cert_, link_, extra_, start_;
  backend::Buffer<uint32_t> broken_ = backend::Buffer<uint32_t>(1, 0u);
  uint64_t link_end_ = 0;
  backend::Buffer<Tri> tris_;
  std::size_t ntris_ = 0;
};

}  // namespace ghull_detail

std::vector<Triangle> hull3_ghull(const PointSet& ps, const kernels::GhullOptions& opt, kernels::GhullStats* stats,
                                  cpu::StageTimes* times) {
  backend::require_device("hull3 ghull");
  if (ps.dim != 3 || ps.size() < 4) {
    ref::ffhull::initial_tetrahedron(ps);  // throws the reference's message
    throw std::logic_error("hull3 ghull: the reference accepted input of fewer than 4 points");
  }
  if (ps.size() >= (std::size_t{1} << 30))
    throw std::invalid_argument("hull3 ghull: too many points for 32-bit indices");
  kernels::GhullStats st;
  cpu::StageClock clock(times);
  std::vector<Triangle> out = ghull_detail::on_device(ps.size(), [&] {
    ghull_detail::Ghull h(ps, opt, st, clock);
    return h.run();
  });
  if (stats) *stats = st;
  return out;
}

#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
namespace ghull_stages {
Approximation approximation(const PointSet& ps, const kernels::GhullOptions& opt) {
  if (ps.dim != 3 || ps.size() < 4) ref::ffhull::initial_tetrahedron(ps);
  kernels::GhullStats st;
  cpu::StageClock clock(nullptr);
  Approximation a;
  ghull_detail::Ghull h(ps, opt, st, clock);
  h.stage2_stars = &a.stars;
  h.stop_after_stage3 = true;
  a.hull = h.run();
  return a;
}
}  // namespace ghull_stages
#endif

}  // namespace flipflop::FF_KERNELS_NS

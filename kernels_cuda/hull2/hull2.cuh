// hull2.cuh — the one source of the GPU 2D hull (hull2.hpp explains the task),
// included by hull2_omp.cpp (thrust's OpenMP backend, host compiler) and
// hull2_cuda.cu (nvcc), each defining FF_KERNELS_NS.
//
// Every step is a thrust primitive over a __host__ __device__ functor on flat
// arrays of point indices (the coordinates stay where they are, point-major):
//
//   0. the per-input static filter by one reduction (static_filter.cuh);
//   1. throw-away (Akl–Toussaint): a convex polygon of input points — the
//      extreme points in 8 directions by one reduction, or on large inputs
//      the hull of a sample (throw_away_polygon) — with an inner box and an
//      exactly verified inner disk; the points strictly inside are dropped by a stream
//      compaction (copy_if). A point strictly inside a convex polygon of
//      perturbed input points is inside the perturbed hull and so no vertex
//      of the SoS hull: no vertex is lost;
//   2. Algorithm 3 line 1 and lines 4-5: the survivors sorted by x under the
//      perturbation (a stable radix sort on the doubles' ordered bits, equal x
//      in the SoS order of indices); v_l, v_r the first and the last;
//   3. lines 2-3 and 6: S_a = {p above v_l v_r} and S_b = the rest by two
//      stable compactions; the polygon P = <v_l, S_b (x ascending), v_r, S_a
//      (x descending)>, counter-clockwise and star-shaped with respect to the
//      points at infinity below (S_b) and above (S_a) — §4.2;
//   4. line 7: flip-pop in rounds until no vertex is reflex. Each round is
//      (a) the chunked pass of §4.2's shared-memory variant (Fig 4.3): one
//          thread per chunk of `chunk` consecutive vertices flips its chunk
//          as long as it can — a stack scan in which every pop is the 2-1
//          flip of Alg 1 line 6 on the vertex between the stack's top-but-one
//          and the next vertex, the chunk's two end vertices held (their
//          outer neighbours belong to other chunks) — and a compaction;
//      (b) one pass of Algorithm 2 on the whole cyclic polygon: every reflex
//          vertex p_i (orient2d(p_{i-1}, p_{i+1}, p_i) > 0, Alg 2 line 6)
//          labels itself and its two neighbours with i by an atomic minimum
//          (lines 7-8), and after the barrier (line 9) p_i is flipped away
//          when all three labels are still i (lines 10-12): the flips of a
//          pass touch disjoint vertex triples, and the reflex vertex of
//          smallest position always wins, so each pass flips at least one
//          vertex while any is reflex. A pass that finds none ends the loop:
//          the polygon is convex.
//      v_l and v_r are extreme, never reflex; they are held explicitly.
//
// Why the answer is the reference's byte for byte: flip-pop's result does not
// depend on the order of its flips (free execution order, §4.1, reference/
// hull2/flip_pop.hpp): it is the SoS hull of the polygon's vertices, which
// include every vertex of the SoS hull of the input (step 1 drops none, step 3
// keeps all survivors). Every decision is an exact SoS predicate on the input
// indices (device_predicates.cuh); the cycle is rotated to its smallest index.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including hull2.cuh"
#endif

#include <thrust/copy.h>
#include <thrust/fill.h>
#include <thrust/for_each.h>
#include <thrust/functional.h>
#include <thrust/iterator/zip_iterator.h>
#include <thrust/scan.h>
#include <thrust/transform_scan.h>
#include <thrust/tuple.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/reverse_iterator.h>
#include <thrust/reverse.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>

#include <cuda/atomic>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/device_predicates.cuh"
#include "kernels_cuda/hull2/hull2.hpp"
#include "kernels_cuda/static_filter.cuh"
#include "kernels_cuda/two_pass.cuh"
#include "kernels_cpu/stage_times.hpp"
#include "predicates/predicates.hpp"
#include "reference/certify/ball_test.hpp"
#include "reference/hull2/polygon.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace hull2_detail {

constexpr std::size_t kParallelFrom = std::size_t{1} << 14;
constexpr Index kNoLabel = 0xffffffffu;

FF_HD inline const double* at(const double* xy, Index i) { return xy + 2 * static_cast<std::size_t>(i); }

// orient2d(a, b, c) of input points under SoS, with the per-input filter.
struct Orient {
  const double* xy;
  pred::StaticFilter f;
  FF_HD int operator()(Index a, Index b, Index c) const {
    return dev::orient2d(&f, a, at(xy, a), b, at(xy, b), c, at(xy, c));
  }
};

// §6.4.2's two passes (kernels_cuda/two_pass.cuh) for the functors that test
// every point: the first pass's signs are the per-input static filter's alone
// (its bound precomputed once per input, Orient::f), 0 where it cannot decide
// (a comparison of equal coordinates included: the perturbation decides it);
// the second pass's the whole staged path.
struct FastSigns : dev::Undecided {
  const Orient& o;
  FF_HD explicit FastSigns(const Orient& orient) : o(orient) {}
  FF_HD int orient(Index a, Index b, Index c) {
    const double* p[3] = {at(o.xy, a), at(o.xy, b), at(o.xy, c)};
    return certain(pred::static_sign<3>(o.f, p, nullptr));
  }
  FF_HD int compare(Index a, Index b, int coord) {  // dev::compare_sos
    const double x = at(o.xy, a)[coord], y = at(o.xy, b)[coord];
    return certain(x < y ? -1 : y < x ? 1 : 0);
  }
};
struct ExactSigns {
  const Orient& o;
  static constexpr bool undecided = false;
  FF_HD int orient(Index a, Index b, Index c) const { return o(a, b, c); }
  FF_HD int compare(Index a, Index b, int coord) const {
    return dev::compare_sos(a, at(o.xy, a), b, at(o.xy, b), coord);
  }
};
// The signs of a decision on the input points, for dev::Pass.
struct OnOrient {
  Orient o;
  FF_HD FastSigns fast() const { return FastSigns(o); }
  FF_HD ExactSigns exact() const { return ExactSigns{o}; }
};
// f's two passes over [0, n) (step's policy)
template <class Policy, class F>
void two_passes(Policy policy, std::size_t n, const F& f) {
  const thrust::counting_iterator<std::size_t> k0(0);
  thrust::for_each(policy, k0, k0 + n, dev::Pass<F, false>{f});
  thrust::for_each(policy, k0, k0 + n, dev::Pass<F, true>{f});
}
constexpr char kUndecidedFlag = 2;  // the mark of a 0/1 result (char flags; AboveLine's edge ids)

// ---- step 1: the extreme points in 8 directions ------------------------------
// Directions counter-clockwise from -x: 0 min x, 1 min x+y, 2 min y, 3 max x-y,
// 4 max x, 5 max x+y, 6 max y, 7 max y-x. Along the axes the order is the
// perturbed one (compare_sos), so those four are vertices of the SoS hull in
// counter-clockwise order; along the diagonals the rounded sums decide (ties:
// the smaller index) and the polygon is checked exactly before it is used.
struct Extremes {
  Index e[8];
};

struct AllDirections {
  FF_HD Extremes operator()(Index i) const {
    Extremes r;
    for (int k = 0; k < 8; ++k) r.e[k] = i;
    return r;
  }
};

struct BestInEachDirection {
  const double* xy;
  FF_HD static double diagonal(int k, const double* p) {
    if (k == 1) return -(p[0] + p[1]);
    if (k == 3) return p[0] - p[1];
    if (k == 5) return p[0] + p[1];
    return p[1] - p[0];
  }
  // i beats j in direction k (a strict total order on indices for each k)
  FF_HD bool beats(int k, Index i, Index j) const {
    if (i == j) return false;
    const double* p = at(xy, i);
    const double* q = at(xy, j);
    if (k % 2 == 0) {
      const int s = dev::compare_sos(i, p, j, q, k == 0 || k == 4 ? 0 : 1);
      return k < 4 ? s < 0 : s > 0;
    }
    const double a = diagonal(k, p), b = diagonal(k, q);
    return a > b || (a == b && i < j);
  }
  FF_HD Extremes operator()(const Extremes& a, const Extremes& b) const {
    Extremes r;
    for (int k = 0; k < 8; ++k) r.e[k] = beats(k, b.e[k], a.e[k]) ? b.e[k] : a.e[k];
    return r;
  }
};

// An axis-parallel box whose four corners lie strictly inside the polygon
// (checked with exact orient2d on the host): a point strictly inside the box
// (four comparisons, exact) is strictly inside the polygon. Empty: lo > hi.
struct InnerBox {
  double lo[2] = {1.0, 1.0}, hi[2] = {0.0, 0.0};
  FF_HD bool strictly_inside(const double* p) const {
    return lo[0] < p[0] && p[0] < hi[0] && lo[1] < p[1] && p[1] < hi[1];
  }
};

// Keep flag of the throw-away: point i is not proved strictly inside the
// polygon `poly` (h >= 3 input points, convex and counter-clockwise under the
// perturbation, checked on the host) — first by its inner box and its exactly
// verified inner disk (comparisons, one floating-point test,
// certify/ball_test.hpp), then
// by the fan from poly[0]: a binary search for the wedge poly[0] poly[k]
// poly[k+1] holding i and one edge test, O(log h) SoS orient2d calls. A
// vertex of the polygon is kept (orient2d with a repeated index is 0).
// In two passes: keep[i] = 1 or 0.
struct NotInside : OnOrient {
  InnerBox box;
  certify::BallTest<2> disk;
  const Index* poly;
  int h;
  char* keep;
  template <class S>
  FF_HD char decide(std::size_t k, S& sg) const {
    const Index i = static_cast<Index>(k);
    if (box.strictly_inside(at(o.xy, i)) || disk.strictly_inside(at(o.xy, i))) return 0;
    if (sg.orient(poly[0], poly[1], i) <= 0 || sg.orient(poly[0], poly[h - 1], i) >= 0) return 1;
    int lo = 1, hi = h - 1;  // orient(v0, v_lo, i) > 0 > orient(v0, v_hi, i)
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (sg.orient(poly[0], poly[mid], i) > 0) lo = mid;
      else hi = mid;
    }
    return sg.orient(poly[lo], poly[hi], i) <= 0 ? 1 : 0;
  }
  FF_HD void write(std::size_t k, char r) const { keep[k] = r; }
  FF_HD void mark(std::size_t k) const { keep[k] = kUndecidedFlag; }
  FF_HD bool marked(std::size_t k) const { return keep[k] == kUndecidedFlag; }
};

// ---- step 2: sort keys -------------------------------------------------------
// The bits of x as an unsigned key of the same order (-0 and +0 equal).
struct XKey {
  const double* xy;
  FF_HD std::uint64_t operator()(Index i) const {
    const double x = at(xy, i)[0] + 0.0;
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return (b >> 63) ? ~b : (b | (std::uint64_t{1} << 63));
  }
};

// ---- step 3: S_a ---------------------------------------------------------------
// In two passes: out[k] = 1 when pts[k] is above v_l v_r (orient2d > 0,
// never 0 for a point other than v_l and v_r), else 0; kUndecidedFlag: the
// first pass's mark. Step 3's S_a (char flags) and Algorithm 4's first edges
// (lines 4-6: below v_l v_r edge 0, v_l -> v_r; above edge 1).
template <class T>
struct AboveLine : OnOrient {
  Index vl, vr;
  const Index* pts;
  T* out;
  template <class S>
  FF_HD T decide(std::size_t k, S& sg) const {
    return sg.orient(vl, vr, pts[k]) > 0 ? 1 : 0;
  }
  FF_HD void write(std::size_t k, T r) const { out[k] = r; }
  FF_HD void mark(std::size_t k) const { out[k] = static_cast<T>(kUndecidedFlag); }
  FF_HD bool marked(std::size_t k) const { return out[k] == static_cast<T>(kUndecidedFlag); }
};
struct IsSet {
  FF_HD bool operator()(char c) const { return c != 0; }
};
struct IsClear {
  FF_HD bool operator()(char c) const { return c == 0; }
};

// ---- step 4a: the chunked pass ----------------------------------------------
struct ChunkScan {
  Orient o;
  Index* c;  // the polygon, flipped in place chunk by chunk
  std::size_t m, chunk;
  Index vl, vr;
  std::size_t* kept;  // per chunk: vertices left at the chunk's start
  FF_HD void operator()(std::size_t ch) const {
    const std::size_t lo = ch * chunk, hi = lo + chunk < m ? lo + chunk : m;
    std::size_t top = lo, base = lo;  // c[lo, top): the stack; c[base] is never popped
    for (std::size_t k = lo; k < hi; ++k) {
      const Index v = c[k];
      while (top - base >= 2 && o(c[top - 2], v, c[top - 1]) > 0) --top;  // Alg 1 line 6
      c[top++] = v;
      if (v == vl || v == vr) base = top - 1;  // held
    }
    kept[ch] = top - lo;
  }
};

struct KeptInChunk {
  const std::size_t* kept;
  std::size_t chunk;
  FF_HD bool operator()(std::size_t k) const { return k % chunk < kept[k / chunk]; }
};

// ---- step 4b: one pass of Algorithm 2 ----------------------------------------
struct LabelReflex {  // lines 5-8
  Orient o;
  const Index* c;
  std::size_t m;
  Index vl, vr;
  Index* label;
  FF_HD void operator()(std::size_t i) const {
    const Index v = c[i];
    if (v == vl || v == vr) return;
    const std::size_t prev = (i + m - 1) % m, next = (i + 1) % m;
    if (o(c[prev], c[next], v) <= 0) return;
    const Index me = static_cast<Index>(i);
    cuda::atomic_ref<Index, cuda::thread_scope_device>(label[prev]).fetch_min(me);
    cuda::atomic_ref<Index, cuda::thread_scope_device>(label[i]).fetch_min(me);
    cuda::atomic_ref<Index, cuda::thread_scope_device>(label[next]).fetch_min(me);
  }
};

struct SurvivesPass {  // lines 10-12: p_i goes when its three labels are still i
  const Index* label;
  std::size_t m;
  FF_HD bool operator()(std::size_t i) const {
    const Index me = static_cast<Index>(i);
    return !(label[i] == me && label[(i + m - 1) % m] == me && label[(i + 1) % m] == me);
  }
};

// ---- Algorithm 4 (Graham-insertion) -------------------------------------------
// v_l and v_r of the survivors: the extremes in x under the perturbation.
struct XRange {
  Index lo, hi;
};
struct XRangeOf {
  FF_HD XRange operator()(Index i) const { return {i, i}; }
};
struct WiderX {
  const double* xy;
  FF_HD XRange operator()(const XRange& a, const XRange& b) const {
    XRange r;
    r.lo = dev::compare_sos(b.lo, at(xy, b.lo), a.lo, at(xy, a.lo), 0) < 0 ? b.lo : a.lo;
    r.hi = dev::compare_sos(b.hi, at(xy, b.hi), a.hi, at(xy, a.hi), 0) > 0 ? b.hi : a.hi;
    return r;
  }
};
struct NotEnd {
  Index vl, vr;
  FF_HD bool operator()(Index i) const { return i != vl && i != vr; }
};
// line 9: each edge's point to insert — the farthest from the edge's line by
// the rounded cross product (any associated point keeps the polygon x-monotone
// per chain and the answer unchanged; the farthest drops the most points), as
// one atomic maximum of (distance as float bits, complement of the index) per
// edge: ties go to the smaller index, so the choice is deterministic.
struct Bid {
  const double* xy;
  const Index* P;
  std::size_t m;
  const Index* pts;
  const Index* eid;
  unsigned long long* best;
  FF_HD void operator()(std::size_t k) const {
    const Index u = pts[k], e = eid[k];
    const double *p = at(xy, P[e]), *q = at(xy, P[(e + 1) % m]), *x = at(xy, u);
    double c = (q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0]);
    c = c < 0 ? -c : c;
    // as a float, clamped (a cast beyond the float range is undefined); NaN
    // (inf - inf): no preference
    const float cf = !(c == c) ? 0.0f : c < 3.0e38 ? static_cast<float>(c) : 3.0e38f;
    std::uint32_t bits;
    std::memcpy(&bits, &cf, sizeof bits);
    const unsigned long long key = (static_cast<unsigned long long>(bits) << 32) | (0xffffffffu - u);
    cuda::atomic_ref<unsigned long long, cuda::thread_scope_device>(best[e]).fetch_max(key);
  }
};
FF_HD inline Index bid_point(unsigned long long b) { return 0xffffffffu - static_cast<Index>(b & 0xffffffffu); }
struct SlotsOf {  // vertices edge e contributes to the new polygon
  FF_HD std::size_t operator()(unsigned long long b) const { return b ? 2 : 1; }
};
struct Splice {  // line 10: P' = ... p, r, q ...
  const Index* P;
  const unsigned long long* best;
  const std::size_t* pos;
  Index* P2;
  FF_HD void operator()(std::size_t e) const {
    P2[pos[e]] = P[e];
    if (best[e]) P2[pos[e] + 1] = bid_point(best[e]);
  }
};
// lines 12-17: the new edge of u (p -> r when u.x lies between p.x and r.x,
// else r -> q, signs of the differences under the perturbation), kept when u
// is beyond it, else dropped (inside the triangle p r q); inserted points go.
// Writes the new edge id, or kDropped; in two passes (kUndecidedEdge: the
// first pass's mark).
constexpr Index kDropped = 0xffffffffu;
constexpr Index kUndecidedEdge = 0xfffffffeu;
struct Reassociate : OnOrient {
  const Index* P;
  std::size_t m;
  const unsigned long long* best;
  const std::size_t* pos;
  const Index* P2;
  std::size_t m2;
  const Index* pts;
  const Index* eid;
  Index* eid2;
  template <class S>
  FF_HD Index decide(std::size_t k, S& sg) const {
    const Index u = pts[k], e = eid[k];
    const Index r = bid_point(best[e]);
    if (u == r) return kDropped;
    const Index p = P[e];
    const int sp = sg.compare(u, p, 0);
    const int sr = sg.compare(u, r, 0);
    const std::size_t ne = sp * sr <= 0 ? pos[e] : pos[e] + 1;
    const bool beyond = sg.orient(P2[ne], P2[(ne + 1) % m2], u) < 0;
    return beyond ? static_cast<Index>(ne) : kDropped;
  }
  FF_HD void write(std::size_t k, Index r) const { eid2[k] = r; }
  FF_HD void mark(std::size_t k) const { eid2[k] = kUndecidedEdge; }
  FF_HD bool marked(std::size_t k) const { return eid2[k] == kUndecidedEdge; }
};
struct Kept {
  FF_HD bool operator()(Index e) const { return e != kDropped; }
};

// `ids` as a polygon for the throw-away, checked exactly (host): consecutive
// repeats removed; empty unless it has >= 3 vertices and turns left at every
// vertex under the perturbation (then it is convex and counter-clockwise).
inline std::vector<Index> checked_polygon(const PointSet& ps, std::vector<Index> ids) {
  std::vector<Index> poly;
  for (Index v : ids)
    if (poly.empty() || poly.back() != v) poly.push_back(v);
  while (poly.size() > 1 && poly.back() == poly.front()) poly.pop_back();
  const std::size_t h = poly.size();
  if (h < 3) return {};
  for (std::size_t k = 0; k < h; ++k) {
    const Index a = poly[k], b = poly[(k + 1) % h], c = poly[(k + 2) % h];
    if (a == c || pred::orient2d({a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)}) <= 0) return {};
  }
  return poly;
}

// The inner box of a polygon checked by checked_polygon: its bounding box
// shrunk towards `centre` by the first factor t in 0.995, 0.98, 0.95, 0.9,
// 0.8, 0.7 whose four corners are strictly inside every edge in exact
// arithmetic; empty if none is (O(h) exact tests per candidate, on the host).
inline InnerBox inner_box(const PointSet& ps, const std::vector<Index>& poly, const double* centre) {
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (Index v : poly)
    for (int j = 0; j < 2; ++j) lo[j] = std::min(lo[j], ps.point(v)[j]), hi[j] = std::max(hi[j], ps.point(v)[j]);
  for (double t : {0.995, 0.98, 0.95, 0.9, 0.8, 0.7}) {
    InnerBox b;
    for (int j = 0; j < 2; ++j) {
      b.lo[j] = centre[j] + t * (lo[j] - centre[j]);
      b.hi[j] = centre[j] + t * (hi[j] - centre[j]);
    }
    // finite corners only: near the largest doubles lo - centre or
    // hi - centre overflows to an infinity, which the comparisons below let
    // through, and the exact test refuses a non-finite corner (the fuzz
    // stage's hull2 target, stop 76: y in {-DBL_MAX, 0, 1.1e301, DBL_MAX}
    // threw "exact predicate on a non-finite value";
    // fuzz/corpus/hull2/crash-7ef39146...)
    if (!(std::isfinite(b.lo[0]) && std::isfinite(b.lo[1]) && std::isfinite(b.hi[0]) && std::isfinite(b.hi[1])))
      continue;
    if (!(b.lo[0] < b.hi[0] && b.lo[1] < b.hi[1])) continue;  // empty
    const double corners[4][2] = {{b.lo[0], b.lo[1]}, {b.hi[0], b.lo[1]}, {b.hi[0], b.hi[1]}, {b.lo[0], b.hi[1]}};
    bool inside = true;
    for (std::size_t k = 0; k < poly.size() && inside; ++k)
      for (const auto& c : corners)
        if (pred::orient2d_exact(ps.point(poly[k]), ps.point(poly[(k + 1) % poly.size()]), c) <= 0) {
          inside = false;
          break;
        }
    if (inside) return b;
  }
  return {};
}

inline std::vector<Index> hull2_run(const PointSet& ps, const kernels::Hull2GpuOptions& opt,
                                    ref::Hull2Stats& st, const char* who, bool insert);

// The throw-away's polygon. Below kSampleFrom points: the extreme points in 8
// directions (one reduction). From kSampleFrom points (Akl–Toussaint with a
// sample): the SoS hull of a strided sample of s = min(2^17, max(n/64, 1024))
// points, computed by this same algorithm — close to the whole hull, so that
// almost every interior point is dropped on disks and rings too. The sample
// keeps the input order, so its SoS hull under its own indices is the SoS
// hull of the same input points under theirs (SoS depends on the order of the
// indices only); it is checked again under the input's indices regardless.
constexpr std::size_t kSampleFrom = std::size_t{1} << 15;

inline std::vector<Index> throw_away_polygon(const PointSet& ps, const double* xy, const kernels::Hull2GpuOptions& opt,
                                             const char* who) {
  const std::size_t n = ps.size();
  if (n >= kSampleFrom) {
    const std::size_t s = std::min<std::size_t>(std::size_t{1} << 17, std::max<std::size_t>(n / 64, 1024));
    const std::size_t stride = n / s;
    PointSet sample;
    sample.dim = 2;
    sample.coords.resize(2 * s);
    for (std::size_t k = 0; k < s; ++k) {
      sample.coords[2 * k] = ps.point(k * stride)[0];
      sample.coords[2 * k + 1] = ps.point(k * stride)[1];
    }
    kernels::Hull2GpuOptions o;
    o.chunk = opt.chunk;
    ref::Hull2Stats sst;
    std::vector<Index> cycle = hull2_run(sample, o, sst, who, false);
    for (Index& v : cycle) v = static_cast<Index>(v * stride);
    std::vector<Index> poly = checked_polygon(ps, std::move(cycle));
    if (!poly.empty()) return poly;
  }
  Extremes ext{};
  thrust::counting_iterator<Index> first(0);
  backend::run_step<kParallelFrom>(n, [&](auto policy) {
    ext = thrust::transform_reduce(policy, first, first + n, AllDirections(), AllDirections()(0),
                                   BestInEachDirection{xy});
  });
  std::vector<Index> poly = checked_polygon(ps, std::vector<Index>(ext.e, ext.e + 8));
  if (poly.empty()) poly = checked_polygon(ps, {ext.e[0], ext.e[2], ext.e[4], ext.e[6]});
  return poly;
}

// The whole kernel: Graham-sorting (Algorithm 3) or, with `insert`,
// Graham-insertion (Algorithm 4); then the same flip-pop.
inline std::vector<Index> hull2_run(const PointSet& ps, const kernels::Hull2GpuOptions& opt,
                                    ref::Hull2Stats& st, const char* who, bool insert) {
  const std::size_t n = ps.size();
  const std::size_t chunk = std::max<std::size_t>(opt.chunk, 3);
  cpu::StageClock clock(opt.times);
  backend::Buffer<double> b_xy;
  backend::Scratch<Index> b_surv, b_poly, b_poly2, b_label, b_eid, b_eid2, b_pts2;
  backend::Scratch<std::uint64_t> b_keys;
  backend::Scratch<unsigned long long> b_best;
  backend::Scratch<char> b_above;
  backend::Scratch<std::size_t> b_kept, b_pos;
  const double* xy = nullptr;
  try {
    xy = backend::to_device(ps.coords.data(), ps.coords.size(), b_xy);
    b_surv.resize(n), b_poly.resize(n), b_poly2.resize(n), b_keys.resize(n), b_above.resize(n);
    b_label.resize(n), b_kept.resize(n / chunk + 1);
    if (insert) b_eid.resize(n), b_eid2.resize(n), b_pts2.resize(n), b_best.resize(n), b_pos.resize(n + 1);
  } catch (const std::bad_alloc&) {
    throw kernels::DeviceMemoryError(std::string(who) + ": " + std::to_string(n) +
                                     " points do not fit in device memory (about " +
                                     std::string(insert ? "90" : "50") + " bytes per point)");
  }
  backend::sync();
  clock.mark("upload");
  thrust::counting_iterator<Index> first(0);
  thrust::counting_iterator<std::size_t> k0(0);
  auto step = [&](std::size_t count, auto&& body) { backend::run_step<kParallelFrom>(count, body); };

  // 0. the static filter; 1. throw-away
  const pred::StaticFilter f = filter::static_filter<kParallelFrom>(xy, 2 * n);
  const Orient o{xy, f};
  const std::vector<Index> poly = opt.throw_away ? throw_away_polygon(ps, xy, opt, who) : std::vector<Index>{};
  Index* surv = thrust::raw_pointer_cast(b_surv.data());
  std::size_t s = n;
  if (!poly.empty()) {
    backend::Buffer<Index> b_ring;
    const Index* ring = backend::to_device(poly.data(), poly.size(), b_ring);
    const certify::BallTest<2> disk = certify::inner_disk(ps, poly);
    double centre[2] = {0.0, 0.0};  // the disk's centre, else the vertices' mean
    for (int j = 0; j < 2; ++j) {
      if (disk.limit > 0) centre[j] = disk.s[j];
      else
        for (Index v : poly) centre[j] += ps.point(v)[j] / static_cast<double>(poly.size());
    }
    char* flag = thrust::raw_pointer_cast(b_above.data());
    const NotInside keep{{o}, inner_box(ps, poly, centre), disk, ring, static_cast<int>(poly.size()), flag};
    // the keep flags in two passes (the predicates' exact stage, 42 KB of
    // stack per thread on the device, in the second), then a compaction over
    // the flags. Run as one copy_if with NotInside as its
    // predicate, CUB's select kernel wrote out of its shared memory on the
    // H100 whenever many calls reached the exact stage (tiny2: wrong hulls
    // from 200 points, an illegal instruction at 10^6; compute-sanitizer:
    // "Invalid __shared__ write" in DeviceSelectSweepKernel<..., NotInside>).
    step(n, [&](auto policy) {
      two_passes(policy, n, keep);
      s = static_cast<std::size_t>(thrust::copy_if(policy, first, first + n, flag, surv, IsSet()) - surv);
    });
  } else {
    step(n, [&](auto policy) { thrust::sequence(policy, surv, surv + n); });
  }
  backend::sync();
  clock.mark("throw-away");

  // 2-3 (Algorithm 3) or Algorithm 4: the polygon P[0, m), P[0] = v_l
  Index* P = thrust::raw_pointer_cast(b_poly.data());
  Index* P2 = thrust::raw_pointer_cast(b_poly2.data());
  Index vl = 0, vr = 0;
  std::size_t m = 0;
  const std::size_t polygon_from = s;  // the points the polygon is built from
  std::size_t dropped_by_insertion = 0;
  if (!insert) {
    // 2. sort by x under the perturbation: equal x in the SoS order of indices
    // (one rule for every pair, read off compare_sos once)
    const double probe[2] = {0.0, 0.0};
    const bool larger_index_first = pred::compare_sos({1, probe}, {0, probe}, 0) < 0;
    std::uint64_t* keys = thrust::raw_pointer_cast(b_keys.data());
    step(s, [&](auto policy) {
      if (larger_index_first) thrust::reverse(policy, surv, surv + s);
      thrust::transform(policy, surv, surv + s, keys, XKey{xy});
      thrust::stable_sort_by_key(policy, keys, keys + s, surv);
    });
    backend::sync();
    clock.mark("sort by x");

    // 3. split; P = <v_l, S_b ascending, v_r, S_a descending>
    vl = b_surv[0], vr = b_surv[s - 1];
    char* above = thrust::raw_pointer_cast(b_above.data());
    std::size_t nb = 0, na = 0;
    step(s, [&](auto policy) {
      two_passes(policy, s > 2 ? s - 2 : 0, AboveLine<char>{{o}, vl, vr, surv + 1, above + 1});
      nb = static_cast<std::size_t>(thrust::copy_if(policy, surv + 1, surv + s - 1, above + 1, P + 1, IsClear()) -
                                    (P + 1));
      using RevIdx = thrust::reverse_iterator<Index*>;
      using RevChar = thrust::reverse_iterator<char*>;
      na = static_cast<std::size_t>(thrust::copy_if(policy, RevIdx(surv + s - 1), RevIdx(surv + 1),
                                                    RevChar(above + s - 1), P + 2 + nb, IsSet()) -
                                    (P + 2 + nb));
    });
    b_poly[0] = vl;
    b_poly[1 + nb] = vr;
    m = s;
    if (nb + na + 2 != s) throw std::logic_error(std::string(who) + ": the split lost points");
    backend::sync();
    clock.mark("split");
  } else {
    // Algorithm 4 lines 1-18 on the survivors, then line 19 below
    Index* pts = surv;
    Index* pts2 = thrust::raw_pointer_cast(b_pts2.data());
    Index* eid = thrust::raw_pointer_cast(b_eid.data());
    Index* eid2 = thrust::raw_pointer_cast(b_eid2.data());
    unsigned long long* best = thrust::raw_pointer_cast(b_best.data());
    std::size_t* pos = thrust::raw_pointer_cast(b_pos.data());
    XRange ends{};
    step(s, [&](auto policy) {  // line 1
      ends = thrust::transform_reduce(policy, surv, surv + s, XRangeOf(), XRangeOf()(b_surv[0]), WiderX{xy});
    });
    vl = ends.lo, vr = ends.hi;
    std::size_t live = 0;
    step(s, [&](auto policy) {  // lines 2-6
      live = static_cast<std::size_t>(thrust::copy_if(policy, surv, surv + s, pts2, NotEnd{vl, vr}) - pts2);
      two_passes(policy, live, AboveLine<Index>{{o}, vl, vr, pts2, eid});  // lines 4-6
    });
    std::swap(pts, pts2);
    b_poly[0] = vl;
    b_poly[1] = vr;
    m = 2;
    std::size_t insertions = 0, dropped = 0, ins_rounds = 0;
    while (live > 0) {  // lines 7-18
      std::size_t m2 = 0;
      step(std::max(live, m), [&](auto policy) {
        thrust::fill(policy, best, best + m + 1, 0ull);  // m + 1 <= s - live < n
        thrust::for_each(policy, k0, k0 + live, Bid{xy, P, m, pts, eid, best});  // lines 8-9
        thrust::transform_exclusive_scan(policy, best, best + m + 1, pos, SlotsOf(), std::size_t{0},
                                         thrust::plus<std::size_t>());
      });
      m2 = b_pos[m];
      std::size_t left = 0;
      step(std::max(live, m), [&](auto policy) {
        thrust::for_each(policy, k0, k0 + m, Splice{P, best, pos, P2});  // line 10
        two_passes(policy, live, Reassociate{{o}, P, m, best, pos, P2, m2, pts, eid, eid2});
        auto in = thrust::make_zip_iterator(thrust::make_tuple(pts, eid2));
        auto out = thrust::make_zip_iterator(thrust::make_tuple(pts2, eid));
        left = static_cast<std::size_t>(thrust::copy_if(policy, in, in + live, eid2, out, Kept()) - out);
      });
      insertions += m2 - m;
      dropped += live - left - (m2 - m);
      live = left;
      std::swap(pts, pts2);
      std::swap(P, P2);
      m = m2;
      ++ins_rounds;
    }
    st.insertions = insertions;
    st.insertion_rounds = ins_rounds;
    backend::sync();
    clock.mark("insertion rounds");
    dropped_by_insertion = dropped;
  }
  const std::size_t polygon_size = m;

  // 4. flip-pop rounds
  std::size_t* kept = thrust::raw_pointer_cast(b_kept.data());
  Index* label = thrust::raw_pointer_cast(b_label.data());
  std::size_t passes = 0;
  for (;;) {
    if (m > chunk) {  // (a)
      const std::size_t chunks = (m + chunk - 1) / chunk;
      std::size_t left = 0;
      step(m, [&](auto policy) {
        thrust::for_each(policy, k0, k0 + chunks, ChunkScan{o, P, m, chunk, vl, vr, kept});
        left = static_cast<std::size_t>(thrust::copy_if(policy, P, P + m, k0, P2, KeptInChunk{kept, chunk}) - P2);
      });
      std::swap(P, P2);
      m = left;
      ++passes;
    }
    std::size_t left = m;  // (b)
    step(m, [&](auto policy) {
      thrust::fill(policy, label, label + m, kNoLabel);
      thrust::for_each(policy, k0, k0 + m, LabelReflex{o, P, m, vl, vr, label});
      left = static_cast<std::size_t>(thrust::copy_if(policy, P, P + m, k0, P2, SurvivesPass{label, m}) - P2);
    });
    std::swap(P, P2);
    ++passes;
    const bool flipped = left != m;
    m = left;
    if (!flipped) break;
  }
  backend::sync();
  clock.mark("flip-pop");

  std::vector<Index> cycle(m);
  thrust::copy(thrust::device_pointer_cast(P), thrust::device_pointer_cast(P) + static_cast<std::ptrdiff_t>(m),
               cycle.begin());
  clock.mark("download");
  st.input_vertices = n;
  st.discarded_early = n - polygon_from + dropped_by_insertion;
  st.polygon_vertices = polygon_size;
  st.flips_2_1 = polygon_size - m;
  st.rounds = passes;
  st.hull_vertices = m;
  return cycle;
}

}  // namespace hull2_detail

namespace hull2_detail {

inline std::vector<Index> run(const PointSet& ps, const kernels::Hull2GpuOptions& opt, ref::Hull2Stats* stats,
                              bool insert) {
  // the reference's names of the algorithms (its messages)
  const char* who = insert ? "hull2 graham-insert" : "hull2 graham-sort";
  if (ps.dim != 2 || ps.size() < 3) {
    ref::require_planar_input(ps, who);  // throws the reference's message
    throw std::invalid_argument(std::string(who) + ": at least 3 points in 2D are needed");
  }
  if (ps.size() >= kNoLabel / 2) throw std::invalid_argument(std::string(who) + ": too many points for 32-bit indices");
  backend::require_device(who);
  ref::Hull2Stats st;
  std::vector<Index> cycle = hull2_run(ps, opt, st, who, insert);
  // the cycle holds every extreme point of the input: collinear iff the input
  // is (the throw-away's SoS test drops points of collinear input too)
  if (!ref::cycle_spans_plane(ps, cycle)) {
    ref::require_planar_input(ps, who);  // throws the reference's message
    throw std::logic_error(std::string(who) + ": collinear hull of an input that spans the plane");
  }
  if (stats) *stats = st;
  return ref::rotate_to_smallest(std::move(cycle));
}

}  // namespace hull2_detail

std::vector<Index> hull2_graham_sort(const PointSet& ps, const kernels::Hull2GpuOptions& opt,
                                     ref::Hull2Stats* stats) {
  return hull2_detail::run(ps, opt, stats, false);
}

std::vector<Index> hull2_graham_insert(const PointSet& ps, const kernels::Hull2GpuOptions& opt,
                                       ref::Hull2Stats* stats) {
  return hull2_detail::run(ps, opt, stats, true);
}

}  // namespace flipflop::FF_KERNELS_NS

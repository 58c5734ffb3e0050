// ffhull.cpp — multithreaded ffHull (thesis §6.4 Algorithm 7, rounds of
// §6.4.1) on oneTBB; what is parallel and why the answer is the reference's
// is documented in ffhull.hpp.
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/hull3/in_plane_tie.hpp"
#include "kernels_cpu/hull3/rounded_centroid.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/stage_times.hpp"
#include "kernels_cpu/tsan.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/canonical.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/certify/certify_hull3_surface.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/certify/inner_box.hpp"
#include "reference/checked.hpp"
#include "reference/default_init.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/polyhedron3.hpp"
#include "reference/hull3/rational_kernel.hpp"

namespace flipflop::cpu {

namespace {

using pred::PointId;
using pred::Pt;
using pred::StaticFilter;

// orient3d under SoS, static filter first (inline), then the staged predicate.
inline int orient(const StaticFilter& f, PointId ia, const double* a, PointId ib, const double* b, PointId ic,
                  const double* c, PointId id, const double* d) {
  const double* p[4] = {a, b, c, d};
  if (int s = pred::static_sign<4>(f, p, nullptr)) return s;
  return pred::orient3d(f, Pt{ia, a}, Pt{ib, b}, Pt{ic, c}, Pt{id, d});
}

// The fast kernel point: a double point strictly inside the initial
// tetrahedron exactly, SoS index n (after all inputs, as the reference's).
class DoubleKernel final : public ref::KernelPoint {
 public:
  DoubleKernel(const PointSet& ps, const std::array<double, 3>& s, const StaticFilter& f)
      : ps_(&ps), s_(s), f_(&f), id_(ps.size()) {}
  int side(Index a, Index b, Index c) const override {
    return orient(*f_, a, ps_->point(a), b, ps_->point(b), c, ps_->point(c), id_, s_.data());
  }

 private:
  const PointSet* ps_;
  std::array<double, 3> s_;
  const StaticFilter* f_;
  PointId id_;
};

// ---- a plane through three points, for many queries --------------------------
// The sign of det[b - o; c - o; p - o] = (p - o) · ((b - o) × (c - o)) for many
// points p with o, b, c fixed: the cross product m and the magnitudes of its
// products are computed once, a query costs three differences, a dot product
// and its bound. This is Shewchuk's orient3d filter (errbound A,
// (7 + 56u)u times the permanent, u = 2^-53) with the cofactor expansion
// taken along the row of p instead of the z column: every term is still a
// rounded difference times a difference of two products of rounded
// differences, and the three terms are summed left to right, which is what
// the bound rests on. kPlaneErr = 2^-49 > 2.2 (7 + 56u)u leaves a margin.
// Valid only without underflow and overflow: used only when the per-input
// static filter is enabled (every value a multiple of 2^L with 3L >= -1074,
// 6 (2M)^3 far below 2^1000, static_filter.hpp), the kernel point included.
// When the filter cannot decide, the caller evaluates the exact SoS predicate.
//
// Before that bound, a static one per plane (sb, two thirds of the query's
// floating-point operations fewer, and it decides nearly every query: the
// construction's queries are rarely within 10^-10 relative of their plane):
// when every coordinate of the points queried and of o has magnitude at most
// M, each rounded difference has |fl(p_i - o_i)| <= 2M (rounding is
// monotone and 2M is a double), and every operation of the bound above is
// monotone in its operands, so that bound evaluated in doubles is at most
// sb = kPlaneErr * (2M perm[0] + 2M perm[1] + 2M perm[2]) evaluated by the
// same operations in the same order: a determinant beyond sb is beyond the
// bound. m2 = 2M (HUGE_VAL: no static bound).
constexpr double kPlaneErr = 0x1p-49;
struct Plane {
  const double* o = nullptr;
  double m[3] = {0, 0, 0}, perm[3] = {0, 0, 0};
  double sb = HUGE_VAL;
  void set(const double* O, const double* b, const double* c, double m2) {
    o = O;
    const double bx = b[0] - O[0], by = b[1] - O[1], bz = b[2] - O[2];
    const double cx = c[0] - O[0], cy = c[1] - O[1], cz = c[2] - O[2];
    const double p0 = by * cz, q0 = bz * cy, p1 = bz * cx, q1 = bx * cz, p2 = bx * cy, q2 = by * cx;
    m[0] = p0 - q0, m[1] = p1 - q1, m[2] = p2 - q2;
    perm[0] = std::fabs(p0) + std::fabs(q0), perm[1] = std::fabs(p1) + std::fabs(q1);
    perm[2] = std::fabs(p2) + std::fabs(q2);
    sb = m2 < HUGE_VAL ? kPlaneErr * (m2 * perm[0] + m2 * perm[1] + m2 * perm[2]) : HUGE_VAL;
  }
  // det (rounded) into `det`; its sign when certain, else 0
  int eval(const double* p, double& det) const {
    const double ax = p[0] - o[0], ay = p[1] - o[1], az = p[2] - o[2];
    det = ax * m[0] + ay * m[1] + az * m[2];
    if (det > sb) return 1;
    if (det < -sb) return -1;
    const double bound = kPlaneErr * (std::fabs(ax) * perm[0] + std::fabs(ay) * perm[1] + std::fabs(az) * perm[2]);
    return det > bound ? 1 : det < -bound ? -1 : 0;
  }
  int sign(const double* p) const {
    double det;
    return eval(p, det);
  }
};

// ---- one pass over the input: extreme points and the static filter's scan --------
// The input's extreme points in 14 directions (par_argmax_multi: the largest
// rounded key, ties the smaller index): entries 0..6 maximise x, y, z,
// x+y+z, x+y-z, x-y+z, -x+y+z, entries 7..13 minimise them. They serve line
// 1 (its first two points) and the inner box. The same pass takes the static
// filter's representatives of the coordinates (parallel.hpp: FilterScan), so
// that the filter (with the kernel point, known only after line 1) needs no
// pass of its own.
constexpr int kDirs = 14;
struct InputScan {
  std::array<Index, kDirs> ext;
  std::vector<double> reps;  // filter_representatives' form
};
InputScan scan_input(const PointSet& ps) {
  std::vector<FilterScan> chunk;
  InputScan in;
  in.ext = par_argmax_multi<kDirs, FilterScan>(
      ps.size(),
      [&](Index p, double* k, FilterScan& f) {
        const double* x = ps.point(p);
        f.add(x[0]), f.add(x[1]), f.add(x[2]);
        const double g[7] = {x[0], x[1], x[2], x[0] + x[1] + x[2], x[0] + x[1] - x[2], x[0] - x[1] + x[2],
                             -x[0] + x[1] + x[2]};
        for (int j = 0; j < 7; ++j) k[j] = g[j], k[7 + j] = -g[j];
      },
      &chunk);
  in.reps.resize(3 * chunk.size());
  for (std::size_t c = 0; c < chunk.size(); ++c) chunk[c].put(&in.reps[3 * c]);
  return in;
}

// ---- line 1: the initial tetrahedron --------------------------------------------
// Approximately extreme points, accepted when exactly affinely independent:
// a, b the extremes in x; c the point farthest from the line ab and d the
// one farthest from the plane abc (rounded keys, ties the smaller index),
// first among the 14 extreme points (no pass over the input), then, when
// those are coplanar, over all points (two parallel arg-max passes);
// otherwise the reference's rule (which also rejects lower-dimensional input
// with its message).
std::array<Index, 4> initial_tetrahedron(const PointSet& ps, const std::array<Index, kDirs>& ext) {
  const std::size_t n = ps.size();
  const auto P = [&](Index i) { return ps.point(i); };
  const Index a = ext[7], b = ext[0];  // min x, max x
  const double* A = P(a);
  const double u[3] = {P(b)[0] - A[0], P(b)[1] - A[1], P(b)[2] - A[2]};
  const auto from_line = [&](Index p) {
    const double w[3] = {P(p)[0] - A[0], P(p)[1] - A[1], P(p)[2] - A[2]};
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    return x * x + y * y + z * z;
  };
  const auto among = [&](const auto& key) {  // the arg-max over ext, par_argmax's order
    Best best;
    for (Index p : ext)
      if (better(key(p), p, best)) best = {key(p), p};
    return best.i;
  };
  for (const bool all : {false, true}) {
    const Index c = all ? par_argmax(n, from_line) : among(from_line);
    const double v[3] = {P(c)[0] - A[0], P(c)[1] - A[1], P(c)[2] - A[2]};
    const double N[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const auto from_plane = [&](Index p) {
      return std::fabs(N[0] * (P(p)[0] - A[0]) + N[1] * (P(p)[1] - A[1]) + N[2] * (P(p)[2] - A[2]));
    };
    const Index d = all ? par_argmax(n, from_plane) : among(from_plane);
    const int o = pred::orient3d_exact(P(a), P(b), P(c), P(d));
    if (o == 0) continue;  // distinct, independent points not found
    // (a, b, c) counter-clockwise seen from outside: d on its inner side (orient3d > 0)
    if (o < 0) return {a, c, b, d};
    return {a, b, c, d};
  }
  return ref::ffhull::initial_tetrahedron(ps);
}

// ---- a box and a ball inside the hull, for round 0 ------------------------------
// Q = the hull of the extreme points E (up to 14, scan_input) lies in
// conv(S), so a point strictly inside a box or a ball strictly inside Q is
// strictly inside conv(S) — exactly, hence under every small enough
// perturbation: not a vertex of the SoS hull (thesis §6.4 Algorithm 7 line
// 14's removal, decided before any cone). Round 0 drops such points without a
// record (construct); the witness hands the box on (make_witness), and a
// dropped point that neither the box nor the certifier's own inner ball
// holds is located by a walk, so the certifier trusts nothing here. Q by
// brute force over E's triples: (i, j, k) is a facet when every other point
// of E is strictly on one side of its plane (exact orient3d), oriented so
// that they are on its inner side; Q is used only when those facets close up
// (every directed edge once, and its reverse once) — E in general position, a
// simplicial polytope; otherwise (a grid's coplanar corners, duplicates) no
// box and no ball. Both are centred at m, the middle of E's bounding box. The
// box: half-extents t h (h: half of that box's extents) with t the largest
// value keeping every corner inside every facet in floating point, shrunk by
// 2^-20 (then by 1 %), accepted only when all eight corners are strictly
// inside every facet of Q exactly. The ball: radius 0.999999 times m's
// smallest floating distance to a facet, each facet verified exactly as the
// certifier's inner ball is (inner_ball.hpp: clears_filtered, clears_exact).
// Only the one of larger volume is kept. 10^6 uniform cube points: the box
// holds about 95 % of them, which the rounds then never classify (the
// initial tetrahedron leaves 82 % to them); 10^6 ball points: the ball about
// half (the box would hold a quarter).
struct InnerRegion {
  bool closed = false;  // Q was found (its facets close up)
  certify::BoxTest3 box;
  certify::BallTest<3> ball;  // limit 0: none
  bool strictly_inside(const double* x) const { return box.strictly_inside(x) || ball.strictly_inside(x); }
  double box_volume() const {
    return box.empty() ? 0.0 : (box.hi[0] - box.lo[0]) * (box.hi[1] - box.lo[1]) * (box.hi[2] - box.lo[2]);
  }
  double ball_volume() const { return 4.18879 * ball.limit * std::sqrt(ball.limit); }  // 4/3 pi r^3
  // only the larger of the two is tested (the other adds little and costs a
  // test per point: the ball on uniform cube points 2.3 ms of 18 ms)
  void keep_larger() {
    if (ball_volume() > box_volume()) box = certify::BoxTest3{};
    else ball = certify::BallTest<3>{};
  }
};
InnerRegion inner_region(const PointSet& ps, const std::array<Index, kDirs>& ext) {
  std::vector<Index> e(ext.begin(), ext.end());
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  const std::size_t m = e.size();
  if (m < 4) return {};
  std::vector<std::array<Index, 3>> facets;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        int side = 0;
        bool facet = true;
        for (std::size_t q = 0; q < m && facet; ++q) {
          if (q == i || q == j || q == k) continue;
          const int o = pred::orient3d_exact(ps.point(e[i]), ps.point(e[j]), ps.point(e[k]), ps.point(e[q]));
          if (o == 0 || (side != 0 && o != side)) facet = false;
          side = o;
        }
        if (!facet) continue;
        if (side > 0) facets.push_back({e[i], e[j], e[k]});
        else facets.push_back({e[i], e[k], e[j]});
      }
  if (facets.size() < 4) return {};
  std::vector<std::pair<Index, Index>> edges, reversed;
  for (const auto& f : facets)
    for (int k = 0; k < 3; ++k) edges.push_back({f[k], f[(k + 1) % 3]}), reversed.push_back({f[(k + 1) % 3], f[k]});
  std::sort(edges.begin(), edges.end());
  std::sort(reversed.begin(), reversed.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end() || edges != reversed) return {};
  double lo[3], hi[3], mid[3], h[3];
  for (int j = 0; j < 3; ++j) {
    lo[j] = HUGE_VAL, hi[j] = -HUGE_VAL;
    for (Index p : e) lo[j] = std::min(lo[j], ps.point(p)[j]), hi[j] = std::max(hi[j], ps.point(p)[j]);
    mid[j] = lo[j] / 2 + hi[j] / 2;
    h[j] = hi[j] / 2 - lo[j] / 2;
  }
  double t = HUGE_VAL, dmin = HUGE_VAL;
  for (const auto& f : facets) {
    const double *a = ps.point(f[0]), *b = ps.point(f[1]), *c = ps.point(f[2]);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double off = n[0] * (mid[0] - a[0]) + n[1] * (mid[1] - a[1]) + n[2] * (mid[2] - a[2]);
    const double reach = std::fabs(n[0]) * h[0] + std::fabs(n[1]) * h[1] + std::fabs(n[2]) * h[2];
    if (!(off < 0) || !(reach > 0)) return {};  // the centre not inside (or NaN)
    t = std::min(t, -off / reach);
    dmin = std::min(dmin, -off / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
  }
  InnerRegion in;
  in.closed = true;
  if (t > 0 && std::isfinite(t))
    for (const double shrink : {1 - 0x1p-20, 0.99}) {
      certify::BoxTest3 box;
      for (int j = 0; j < 3; ++j) box.lo[j] = mid[j] - shrink * t * h[j], box.hi[j] = mid[j] + shrink * t * h[j];
      if (certify::detail::box_inside_facets(ps, facets, box, decltype(certify::Speedups{}.for_range){})) {
        in.box = box;
        break;
      }
    }
  const double r = dmin * 0.999999, r2 = r * r;
  if (r > 0 && std::isfinite(r2) && r2 >= 0x1p-900) {
    using Ball = certify::detail::InnerBall<3>;
    bool clear = true;
    for (const auto& f : facets)
      clear = clear && (Ball::clears_filtered(ps, f, mid, r2) || Ball::clears_exact(ps, f, mid, r2));
    if (clear) {
      for (int j = 0; j < 3; ++j) in.ball.s[j] = mid[j];
      in.ball.limit = r2 * (1 - 0x1p-40);  // inner_ball.hpp's per-point test
    }
  }
  return in;
}

// ---- lines 2-14: the star-shaped polyhedron, in rounds --------------------------

// The per-point buffers of the rounds (up to 28 bytes a point) are written by
// the parallel scatter before they are read: not zeroed first
// (reference/default_init.hpp; a fresh call, e.g. from Python, gets fresh
// pages, whose faults then fall on the writing threads).
template <class T>
using RawVec = UninitVector<T>;

// The surface under construction: flat arrays, 3 entries per triangle slot.
// v[3t + k] is vertex k of triangle t (counter-clockwise seen from outside);
// nb[3t + k] the triangle across its edge v[3t + k] -> v[3t + (k + 1) % 3].
struct Mesh {
  std::vector<Index> v;
  std::vector<std::uint32_t> nb;
  std::uint32_t size() const { return static_cast<std::uint32_t>(v.size() / 3); }
};

// Associated points grouped by triangle: segment k holds pts[lo[k] .. lo[k+1])
// associated with (in the cone of, and beyond) triangle tri[k];
// xyz[3i..3i+2] the coordinates of pts[i], carried along so that every pass
// reads memory in order (the points of a segment are scattered over the
// input; reading them from the input in every round took 0.08–0.1 s more CPU
// time on the 10^6 ball, most of it waiting for the loads of the
// coordinates). Round 0's segments do not carry them: they hold most points
// (92 % of the 10^6 ball, 82 % of the cube) in only four segments, so
// rounds 1 and 2 read the input nearly in order (with prefetching; both on
// round 0's four segments, construct) and the largest buffers of the
// regrouping are not allocated: the first carried copy is of the points
// round 2 keeps. Carrying them from round 1's regrouping instead cost 16.8
// MB on the 10^6 ball (699 k points; its peak 6.8 MB above issue 11's bound); carrying
// them from round 2's regrouping with round 2 reading the input in its own
// order (12 sweeps) made the rounds' classification 1.5x as costly (`perf`:
// 0.59 -> 0.88 s of samples over five runs; flipflop:cpu 0.40 -> 0.51 s,
// median of 3, load 5). The carried segments are regrouped in place
// (regroup).
// Line 8's distance
// key of a point, the rounded (p - t0) · ((t1 - t0) × (t2 - t0)) for its
// triangle (t0, t1, t2), is not stored: the round that needs it evaluates the
// triangle's Plane again, which gives the same double as the test that put
// the point there (same plane, same operations), at 16 bytes a point less
// (the key in both buffers of the regrouping).
struct Segments {
  RawVec<Index> pts;
  RawVec<double> xyz;           // empty: not carried, read from the input
  std::vector<std::size_t> lo;  // size K + 1
  std::vector<std::uint32_t> tri;
  std::vector<Index> far;       // per segment: its furthest point (line 8; regroup)
  std::size_t count() const { return tri.size(); }
  const double* coords(const PointSet& input, std::size_t i) const {
    return xyz.empty() ? input.point(pts[i]) : &xyz[3 * i];
  }
  // ahead of a pass over the points in order: a gather from the input (the
  // loads of the coordinates) need not wait for each miss in turn
  void prefetch(const PointSet& input, std::size_t i) const {
    if (xyz.empty()) __builtin_prefetch(input.point(pts[i]));
  }
};
constexpr std::size_t kAhead = 16;  // points prefetched ahead

// The whole pages of [p + used, p + cap) (bytes; the unused tail of an array
// we own) go back to the kernel, which maps zeros there when they are
// touched again; the allocation itself stays (no free: see regroup).
inline void release_tail(void* p, std::size_t used, std::size_t cap) {
#ifdef __linux__
  static const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + used + page - 1) & ~(page - 1), hi = (a + cap) & ~(page - 1);
  if (p && hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
#else
  (void)p, (void)used, (void)cap;
#endif
}

// The buffers of the rounds: the per-point child codes (a byte: m <= 9
// children, or kDropped), and the copy of a group of segments the in-place
// regrouping reads from (regroup), both allocated once (fresh allocations
// every round cost more in page faults than the round's work).
constexpr std::uint8_t kDropped = 0xff;
struct Buffers {
  RawVec<std::uint8_t> code;
  RawVec<Index> tmp_pts;
  RawVec<double> tmp_xyz;
};

// Line 8's choice of the point to insert: the largest rounded distance key;
// among equal keys the larger `tie` (in_plane_tie.hpp: the order of the
// perturbed distance for points exactly in the triangle's plane), then the
// smaller index — a strict total order, so the choice does not depend on the
// units or the schedule.
struct Far {
  double key = -HUGE_VAL, tie = 0;
  Index i = kNone;
};
inline bool further(double key, double tie, Index i, const Far& b) {
  if (std::isnan(key)) key = -HUGE_VAL;
  if (std::isnan(tie)) tie = -HUGE_VAL;
  if (b.i == kNone) return true;
  return key > b.key || (key == b.key && (tie > b.tie || (tie == b.tie && i < b.i)));
}
// A point's key for line 8 (Far), from the classifier that keeps it.
struct Key {
  double d = 0;    // the rounded distance (p - t0) · ((t1 - t0) × (t2 - t0))
  double tie = 0;  // when d == 0: in_plane_tie
};

// The classification pass of a regrouping: B.code[i] per point (its child,
// or kDropped), and per unit u and child c the number of points kept cnt[u m
// + c] and their furthest point best[u m + c].
struct Classified {
  std::vector<std::size_t> cnt;
  std::vector<Far> best;
  // child c of segment k over its units: the furthest point, and the count
  Far child(const Units& U, std::size_t k, std::uint32_t c, int m, std::size_t& count) const {
    Far bb;
    count = 0;
    for (std::size_t u = U.first[k]; u < U.first[k + 1]; ++u) {
      count += cnt[u * m + c];
      const Far& b = best[u * m + c];
      if (b.i != kNone && further(b.key, b.tie, b.i, bb)) bb = b;
    }
    return bb;
  }
};
template <class Classify>
Classified classify_units(const Segments& S, Buffers& B, const Units& U, int m, const PointSet& input,
                          const Classify& classify) {
  const std::size_t nu = U.seg.size();
  if (B.code.size() < S.pts.size()) B.code.resize(S.pts.size());
  std::uint8_t* code = B.code.data();
  Classified r{std::vector<std::size_t>(nu * static_cast<std::size_t>(m), 0),
               std::vector<Far>(nu * static_cast<std::size_t>(m))};
  par_for(nu, 1, [&](std::size_t ulo, std::size_t uhi) {
    for (std::size_t u = ulo; u < uhi; ++u) {
      std::size_t* c = &r.cnt[u * m];
      Far* b = &r.best[u * m];
      const auto cl = classify(U.seg[u]);
      for (std::size_t i = U.lo[u]; i < U.hi[u]; ++i) {
        if (i + kAhead < U.hi[u]) S.prefetch(input, i + kAhead);
        Key key;
        const Index p = S.pts[i];
        const std::uint32_t ch = cl(i, p, S.coords(input, i), key);
        code[i] = ch == kNone ? kDropped : static_cast<std::uint8_t>(ch);
        if (ch != kNone) {
          ++c[ch];
          if (further(key.d, key.tie, p, b[ch]))
            b[ch] = {std::isnan(key.d) ? -HUGE_VAL : key.d, std::isnan(key.tie) ? -HUGE_VAL : key.tie, p};
        }
      }
    }
  });
  return r;
}

// Regrouping after a round: every point of segment k goes to child c in
// [0, m) of k (classify(k) is made once per unit of segment k and gives
// cl(i, p, x, key) -> c, or kNone: dropped, for point p at position i; x: its
// coordinates; key: when kept, its rounded distance key for line 8 in the
// child triangle, the value the child's Plane gives, i.e. what a pass over
// the new segment would compute again); child c of segment k is triangle
// child_tri(k, c). Stable: per-unit counts, a sequential scan in the order
// (segment, child, unit), a parallel scatter. The new segments carry the
// coordinates when `carry` (Segments; once carried, always), and their
// furthest points (line 8, by `better`: the largest key, ties the smallest
// index, whatever the units) reduced from per-unit maxima taken while
// classifying — no pass of its own over the points (it was 6 % of the 10^6
// ball's profile and one more read of every point a round). Returns the
// number of dropped points.
//
// Memory (issue 11: peak at most twice the input plus the output). The
// segments that do not carry coordinates are scattered into fresh arrays and
// the old ones freed at once. The segments that carry them are regrouped in
// place: a child's points only move towards the front (the children of
// segment k start at most where k started, as points are only dropped), so
// the segments are taken in groups of consecutive segments of about an
// eighth of the points (or one larger segment), each group copied to
// Buffers::tmp and scattered from there into the same arrays — the
// positions below the group's start belong to groups already read, those
// from it on to its copy. The result is the out-of-place scatter's, element
// for element; the second carried copy of the coordinates (9.9 MB for round
// 2 of the 10^6 ball) becomes a copy of a group (about 1.5 MB), and the
// indices of round 1 (whose coordinates come from the input) are regrouped
// in place too (its four segments: a quarter of them copied, not all).
template <class Classify, class ChildTri>
std::size_t regroup(Segments& S, Buffers& B, const Units& U, int m, const PointSet& input, bool carry,
                    const Classify& classify, const ChildTri& child_tri) {
  const std::size_t nu = U.seg.size();
  const Classified cl = classify_units(S, B, U, m, input, classify);
  const std::uint8_t* code = B.code.data();
  const std::vector<std::size_t>& cnt = cl.cnt;
  std::vector<std::size_t> off(nu * static_cast<std::size_t>(m));
  std::vector<std::size_t> lo;
  std::vector<std::uint32_t> tri;
  std::vector<Index> far;
  std::size_t pos = 0;
  for (std::size_t k = 0; k < S.count(); ++k)
    for (int c = 0; c < m; ++c) {
      const std::size_t start = pos;
      for (std::size_t u = U.first[k]; u < U.first[k + 1]; ++u) off[u * m + c] = pos, pos += cnt[u * m + c];
      std::size_t count;
      const Far bb = cl.child(U, k, static_cast<std::uint32_t>(c), m, count);
      if (pos > start) {
        lo.push_back(start);
        tri.push_back(child_tri(k, c));
        far.push_back(bb.i);
      }
    }
  lo.push_back(pos);
  const std::size_t dropped = S.pts.size() - pos;
  // the scatter of units [u0, u1) reading point i at from_pts[i - base],
  // from_xyz[3 (i - base)] (from_xyz null: from the input)
  const auto scatter = [&](std::size_t u0, std::size_t u1, const Index* from_pts, const double* from_xyz,
                           std::size_t base, Index* to_pts, double* to_xyz) {
    par_for(u1 - u0, 1, [&](std::size_t ulo, std::size_t uhi) {
      for (std::size_t u = u0 + ulo; u < u0 + uhi; ++u) {
        std::size_t* o = &off[u * m];
        for (std::size_t i = U.lo[u]; i < U.hi[u]; ++i)
          if (code[i] != kDropped) {
            const std::size_t j = o[code[i]]++;
            to_pts[j] = from_pts[i - base];
            if (to_xyz) {
              if (!from_xyz && i + kAhead < U.hi[u] && code[i + kAhead] != kDropped)
                __builtin_prefetch(input.point(from_pts[i + kAhead - base]));
              std::memcpy(&to_xyz[3 * j], from_xyz ? &from_xyz[3 * (i - base)] : input.point(from_pts[i - base]),
                          3 * sizeof(double));
            }
          }
      }
    });
  };
  if (S.count() == 1) {  // round 0: one segment, into fresh arrays; the old ones are freed
    Segments N;
    N.pts.resize(pos);
    N.xyz.resize(carry ? 3 * pos : 0);
    scatter(0, nu, S.pts.data(), nullptr, 0, N.pts.data(), carry ? N.xyz.data() : nullptr);
    S.pts = std::move(N.pts);
    S.xyz = std::move(N.xyz);
  } else {  // in place, a group of segments at a time (coordinates from the input: into a fresh array)
    const bool from_input = S.xyz.empty();
    RawVec<double> fresh(from_input && carry ? 3 * pos : 0);
    double* to_xyz = from_input ? (carry ? fresh.data() : nullptr) : S.xyz.data();
    const std::size_t group = std::max(S.pts.size() / 8, kChunk);
    for (std::size_t k0 = 0, k1; k0 < S.count(); k0 = k1) {
      for (k1 = k0 + 1; k1 < S.count() && S.lo[k1 + 1] - S.lo[k0] <= group;) ++k1;
      const std::size_t base = S.lo[k0], len = S.lo[k1] - base;
      if (B.tmp_pts.size() < len) B.tmp_pts.resize(len);
      if (!from_input && B.tmp_xyz.size() < 3 * len) B.tmp_xyz.resize(3 * len);
      par_for(len, kChunk, [&](std::size_t lo_, std::size_t hi_) {
        std::memcpy(&B.tmp_pts[lo_], &S.pts[base + lo_], (hi_ - lo_) * sizeof(Index));
        if (!from_input) std::memcpy(&B.tmp_xyz[3 * lo_], &S.xyz[3 * (base + lo_)], 3 * (hi_ - lo_) * sizeof(double));
      });
      scatter(U.first[k0], U.first[k1], B.tmp_pts.data(), from_input ? nullptr : B.tmp_xyz.data(), base,
              S.pts.data(), to_xyz);
    }
    S.pts.resize(pos);
    if (from_input) S.xyz = std::move(fresh);
    else S.xyz.resize(3 * pos);
    // The pages of the dropped points (and of the buffers past this
    // round's size) go back to the kernel: otherwise they stay resident. On
    // the 10^6 sphere shell of thickness 1e-4 nearly every point is kept
    // until round 11, and the 24 MB of carried coordinates stayed resident
    // through the rounds that split the most triangles (12-14), where the
    // construction's peak is (issue 11's memory bound). Not shrink_to_fit:
    // freeing a large block raises glibc's mmap threshold to its size, and
    // the mesh's and the records' growth then fragmented the heap (about
    // 40 MB of free but resident holes on that shell).
    release_tail(S.pts.data(), pos * sizeof(Index), S.pts.capacity() * sizeof(Index));
    release_tail(S.xyz.data(), 3 * pos * sizeof(double), S.xyz.capacity() * sizeof(double));
    release_tail(B.code.data(), pos, B.code.size());
    const std::size_t next = std::max(pos / 8, kChunk);  // about the next round's group
    release_tail(B.tmp_pts.data(), next * sizeof(Index), B.tmp_pts.size() * sizeof(Index));
    release_tail(B.tmp_xyz.data(), 3 * next * sizeof(double), B.tmp_xyz.size() * sizeof(double));
  }
  S.lo = std::move(lo);
  S.tri = std::move(tri);
  S.far = std::move(far);
  return dropped;
}

// A round's 1-3 splits (line 9; construct): segment k's triangle tri[k] is
// split at far[k]; old_v its corners before; its children are tri[k], T + 2k
// and T + 2k + 1 (T: the number of slots before), made[made0 + 3k + c] the
// record's copy of child c.
struct Split {
  std::vector<std::uint32_t> tri;
  std::vector<Index> far, old_v;
  std::uint32_t T = 0, made0 = 0;
  std::uint32_t child(std::size_t k, std::uint32_t c) const {
    return c == 0 ? tri[k] : T + 2 * static_cast<std::uint32_t>(k) + c - 1;
  }
};

// The predicates of the construction, through the plane filters when `fast`
// (a double kernel point and an enabled static filter), else exactly.
template <class Kernel>
struct Tests {
  const PointSet& ps;
  const StaticFilter& f;
  const Kernel& s;
  const double* sd;  // the kernel point's coordinates (DoubleKernel), or null
  bool fast;
  double m2;  // twice the largest coordinate magnitude of the inputs and sd (Plane's sb), when fast
  // side(x, y, p) = orient3d(x, y, p, s), by the plane (s; x, y) when it decides
  // (px: p's coordinates, a copy)
  int side(const Plane& pl, Index x, Index y, Index p, const double* px) const {
    if (fast)
      if (int r = pl.sign(px)) return r;
    return s.side(x, y, p);
  }
  void side_plane(Plane& pl, Index x, Index y) const {
    if (sd) pl.set(sd, ps.point(x), ps.point(y), m2);
  }
  // p on the inner side of (t0, t1, t2) — orient3d(t0, t1, t2, p) > 0, i.e.
  // (p - t0) · ((t1 - t0) × (t2 - t0)) < 0
  // (key: the rounded distance, line 8's key in t)
  bool inner(const Plane& face, const Index* t, Index p, const double* px, Key& key) const {
    const int r = face.eval(px, key.d);
    if (fast && r) return r < 0;
    const bool in = orient(f, t[0], ps.point(t[0]), t[1], ps.point(t[1]), t[2], ps.point(t[2]), p, px) > 0;
    if (!in && key.d == 0.0) {
      const double* c[3] = {ps.point(t[0]), ps.point(t[1]), ps.point(t[2])};
      key.tie = in_plane_tie(t, c, p, px);
    }
    return in;
  }
  void face_plane(Plane& pl, const Index* t) const {
    pl.set(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), m2);
  }
};

// The triangles the construction made, in order (the tetrahedron's four
// faces, then each round's 3 children of each split triangle), so that a
// point's early-removal record is one index into it (4 bytes a point instead
// of a triangle's 12: 8 MB less memory on 10^6 points; the triangles are few
// where most points are removed early). Both are handed to the witness as
// they are (Hull3Witness::beneath, made). record: when given (size n, kNoFacet),
// every point removed early (line 14) gets the index in `made` of the
// triangle whose tetrahedron with s it was proven in.
struct Made {
  std::vector<std::uint32_t> record;
  std::vector<Triangle> made;
};

template <class Kernel>
Mesh construct(const PointSet& ps, const StaticFilter& f, double largest, const Kernel& s, const double* sd,
               const std::array<Index, 4>& tet, const InnerRegion& inner, ref::Hull3Stats& st, Made* rec) {
  std::uint32_t* const record = rec ? rec->record.data() : nullptr;
  const std::size_t n = ps.size();
  const bool fast = sd != nullptr && f.bound(4, false) < HUGE_VAL;
  // (all finite when fast: the filter is enabled; `largest` covers sd, scanned with the inputs)
  const Tests<Kernel> X{ps, f, s, sd, fast, fast ? 2.0 * largest : HUGE_VAL};
  const Index a = tet[0], b = tet[1], c = tet[2], d = tet[3];  // (no structured binding: lambdas capture them)
  // line 3: the tetrahedron, faces counter-clockwise from outside:
  // 0 (a,b,c), 1 (a,c,d), 2 (a,d,b), 3 (b,d,c)
  Mesh M;
  M.v = {a, b, c, a, c, d, a, d, b, b, d, c};
  M.nb.assign(12, kNone);
  for (std::uint32_t t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k)
      for (std::uint32_t r = 0; r < 4; ++r)
        for (int j = 0; j < 3; ++j)
          if (M.v[3 * r + j] == M.v[3 * t + (k + 1) % 3] && M.v[3 * r + (j + 1) % 3] == M.v[3 * t + k])
            M.nb[3 * t + k] = r;

  // Every insertion adds two slots and three made triangles: at most 2n - 4
  // slots and 3n - 8 made. Reserved once — address space only, a page is
  // resident when first written — so these arrays never grow by copying (a
  // doubling held the old and the new array at once: peak memory, issue 11).
  const std::size_t max_slots = 2 * n - 4;
  M.v.reserve(3 * max_slots);
  M.nb.reserve(3 * max_slots);
  if (rec) {
    rec->made.reserve(3 * n - 8);
    for (std::uint32_t t = 0; t < 4; ++t) rec->made.push_back({M.v[3 * t], M.v[3 * t + 1], M.v[3 * t + 2]});
  }

  // line 5 (round 0): each point to the cone of a face from s. The faces
  // around d are the 1-3 split of the triangle (a, c, b) by d, seen from s, so
  // line 13's rule picks the wedge around the line sd: (a,c,d), (c,b,d) or
  // (b,a,d); within the wedge of the face (x, y, d) the point is in that
  // face's cone when it is on d's side of the plane (s, x, y) — side(x, y, p)
  // > 0 like side(x, y, d) — else in the cone of (a, b, c).
  Segments S;
  {  // the inputs but a, b, c, d, increasing: p goes to p less the corners below it
    std::array<Index, 4> sorted = tet;
    std::sort(sorted.begin(), sorted.end());
    S.pts.resize(n - 4);
    par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t p = lo; p < hi; ++p) {
        const std::size_t below = (sorted[0] < p) + (sorted[1] < p) + (sorted[2] < p) + (sorted[3] < p);
        if (p != sorted[0] && p != sorted[1] && p != sorted[2] && p != sorted[3]) S.pts[p - below] = static_cast<Index>(p);
      }
    });
  }
  Buffers B;
  S.lo = {0, S.pts.size()};
  S.tri = {0};
  {
    Plane da, dc, dbp, ac, cb, ba, face[4];
    X.side_plane(da, d, a), X.side_plane(dc, d, c), X.side_plane(dbp, d, b);
    X.side_plane(ac, a, c), X.side_plane(cb, c, b), X.side_plane(ba, b, a);
    for (int t = 0; t < 4; ++t) X.face_plane(face[t], &M.v[3 * t]);
    const Units U = make_units(S.lo);
    const auto classify0 = [&](std::size_t, Index p, const double* x, Key& key) -> std::uint32_t {
      if (inner.strictly_inside(x)) return kNone;  // line 14 before any cone (inner_region), no record
      std::uint32_t t;
      if (X.side(da, d, a, p, x) > 0) {
        if (X.side(dc, d, c, p, x) < 0) t = X.side(ac, a, c, p, x) > 0 ? 1 : 0;  // wedge (a, c, d)
        else t = X.side(cb, c, b, p, x) > 0 ? 3 : 0;                             // wedge (c, b, d)
      } else {
        if (X.side(dbp, d, b, p, x) > 0) t = X.side(ba, b, a, p, x) > 0 ? 2 : 0;  // wedge (b, a, d)
        else t = X.side(cb, c, b, p, x) > 0 ? 3 : 0;                              // wedge (c, b, d)
      }
      if (!X.inner(face[t], &M.v[3 * t], p, x, key)) return t;
      if (record) record[p] = t;  // made[t]: face t
      return kNone;  // line 14: inside the tetrahedron (s, t)
    };
    st.discarded_early += regroup(
        S, B, U, 4, ps, false, [&](std::uint32_t) { return classify0; },
        [](std::size_t, int ch) { return std::uint32_t(ch); });
  }

  // lines 6-14 in rounds: every triangle with points is split at once
  std::vector<std::uint32_t> rank;  // per slot: its segment in this round, or kNone
  rank.reserve(max_slots);
  // line 9: a round's 1-3 splits. Segment k's triangle t = tri[k] = (ta, tb,
  // tc) becomes t = (ta, tb, v), T+2k = (tb, tc, v), T+2k+1 = (tc, ta, v)
  // with v = far[k] (line 8: its furthest point by the rounded distance keys,
  // ties the smaller index, found by the regrouping that made the segment;
  // any point of the segment is correct, ffhull.hpp): old edge e lives on in
  // child e (t, T+2k, T+2k+1) at position 0.
  const auto split = [&](Split& R) {
    ++st.rounds;
    const std::size_t K = R.tri.size();
    const std::uint32_t T = R.T = M.size();
    M.v.resize(3 * (T + 2 * K));
    M.nb.resize(3 * (T + 2 * K));
    rank.resize(T + 2 * K, kNone);
    R.old_v.resize(3 * K);
    std::vector<std::uint32_t> old_nb(3 * K);
    std::vector<std::uint8_t> old_pos(3 * K);
    par_for(K, 64, [&](std::size_t lo, std::size_t hi) {  // read the old state
      for (std::size_t k = lo; k < hi; ++k) {
        const std::uint32_t t = R.tri[k];
        rank[t] = static_cast<std::uint32_t>(k);
        for (int e = 0; e < 3; ++e) {
          const std::uint32_t m = M.nb[3 * t + e];
          R.old_v[3 * k + e] = M.v[3 * t + e];
          old_nb[3 * k + e] = m;
          int j = 0;
          while (M.nb[3 * m + j] != t) ++j;
          old_pos[3 * k + e] = static_cast<std::uint8_t>(j);
        }
      }
    });
    R.made0 = rec ? static_cast<std::uint32_t>(rec->made.size()) : 0;
    if (rec) rec->made.resize(R.made0 + 3 * K);
    par_for(K, 64, [&](std::size_t lo, std::size_t hi) {  // new triangles, inner adjacency
      for (std::size_t k = lo; k < hi; ++k) {
        const std::uint32_t t = R.tri[k], n1 = T + 2 * static_cast<std::uint32_t>(k), n2 = n1 + 1;
        const Index ta = R.old_v[3 * k], tb = R.old_v[3 * k + 1], tc = R.old_v[3 * k + 2], v = R.far[k];
        M.v[3 * t + 2] = v;
        M.v[3 * n1] = tb, M.v[3 * n1 + 1] = tc, M.v[3 * n1 + 2] = v;
        M.v[3 * n2] = tc, M.v[3 * n2 + 1] = ta, M.v[3 * n2 + 2] = v;
        M.nb[3 * t + 1] = n1, M.nb[3 * t + 2] = n2;    // b->v | v->b, v->a | a->v
        M.nb[3 * n1 + 1] = n2, M.nb[3 * n1 + 2] = t;   // c->v | v->c, v->b | b->v
        M.nb[3 * n2 + 1] = t, M.nb[3 * n2 + 2] = n1;   // a->v | v->a, v->c | c->v
        if (rec) {  // child ch of segment k is made[made0 + 3k + ch]
          Triangle* mk = &rec->made[R.made0 + 3 * k];
          mk[0] = {ta, tb, v}, mk[1] = {tb, tc, v}, mk[2] = {tc, ta, v};
        }
      }
    });
    par_for(K, 64, [&](std::size_t lo, std::size_t hi) {  // outer adjacency
      for (std::size_t k = lo; k < hi; ++k) {
        const std::uint32_t t = R.tri[k], n1 = T + 2 * static_cast<std::uint32_t>(k);
        const std::uint32_t child[3] = {t, n1, n1 + 1};
        for (int e = 0; e < 3; ++e) {
          const std::uint32_t m = old_nb[3 * k + e];
          const int j = old_pos[3 * k + e];
          if (rank[m] != kNone) {  // m split too: the edge is in m's child j, position 0
            M.nb[3 * child[e]] = j == 0 ? m : T + 2 * rank[m] + static_cast<std::uint32_t>(j - 1);
          } else {  // this edge of m is written by this task only
            M.nb[3 * child[e]] = m;
            M.nb[3 * m + j] = child[e];
          }
        }
      }
    });
    for (std::size_t k = 0; k < K; ++k) rank[R.tri[k]] = kNone;
    st.insertions += K;
  };
  // lines 10-14: every point of segment k of round R to one of the three new
  // cones (line 13's rule, as in the reference's ffhull.cpp), dropped when
  // inside the tetrahedron (s, new triangle). The planes (s; v, ta),
  // (s; v, tb), (s; v, tc) and the three new triangles' are set up here,
  // once per unit of the segment (regroup), not stored per segment: that was
  // 384 bytes per split triangle, 42 MB in round 13 of the 10^6 sphere shell
  // of thickness 1e-4 (issue 11's memory bound); a unit is at most kChunk
  // points of one segment, so a large segment sets them up once per kChunk
  // points and a small one once, as before.
  const auto classifier = [&](const Split& R, std::uint32_t k) {
    const Index v = R.far[k], ta = R.old_v[3 * k], tb = R.old_v[3 * k + 1], tc = R.old_v[3 * k + 2];
    const std::uint32_t t[3] = {R.child(k, 0), R.child(k, 1), R.child(k, 2)};
    std::array<Plane, 6> pl;
    X.side_plane(pl[0], v, ta), X.side_plane(pl[1], v, tb), X.side_plane(pl[2], v, tc);
    X.face_plane(pl[3], &M.v[3 * t[0]]), X.face_plane(pl[4], &M.v[3 * t[1]]), X.face_plane(pl[5], &M.v[3 * t[2]]);
    return [&X, &M, &R, record, k, v, ta, tb, tc, pl](std::size_t, Index p, const double* x,
                                                       Key& key) -> std::uint32_t {
      if (p == v) return kNone;  // line 10
      std::uint32_t ch;
      if (X.side(pl[0], v, ta, p, x) > 0) ch = X.side(pl[1], v, tb, p, x) < 0 ? 0 : 1;
      else ch = X.side(pl[2], v, tc, p, x) > 0 ? 2 : 1;
      if (!X.inner(pl[3 + ch], &M.v[3 * R.child(k, ch)], p, x, key)) return ch;
      // line 14: in the cone of the child (the parent's cone, narrowed by the
      // two side tests above) and on its inner side: inside (s, child)
      if (record) record[p] = R.made0 + 3 * k + ch;
      return kNone;
    };
  };
  while (S.count() > 0) {
    Split R;
    R.tri = S.tri;
    R.far.swap(S.far);
    split(R);
    const std::size_t K = R.tri.size();
    const Units U = make_units(S.lo);
    if (!S.xyz.empty()) {
      const std::size_t dropped =
          regroup(S, B, U, 3, ps, true, [&](std::uint32_t k) { return classifier(R, k); },
                  [&](std::size_t k, int ch) { return R.child(k, static_cast<std::uint32_t>(ch)); });
      st.discarded_early += dropped - K;  // the K inserted points are not discarded
      continue;
    }
    // Round 1 (the segments of round 0, coordinates not carried) and round 2
    // in one regrouping (issue 11's memory bound): the first regrouping that
    // carries coordinates allocates them for every point it keeps (16.8 MB
    // for round 1's 699 k points of the 10^6 ball, 9.9 MB for the 413 k
    // round 2 keeps), so it is round 2's, on
    // the points in round 1's order — four sweeps over the input, where
    // round 2's own order would be twelve (measured 1.5x the rounds'
    // classification when round 2 read the input so). Pass 1 classifies round
    // 1 (codes, counts and furthest points, as regroup's first pass), which
    // gives round 1's children — the segments its regrouping would make, in
    // its order — and so round 2's splits; pass 2 classifies every point kept
    // by round 1 for round 2 in its child's segment, child 3 c1 + c2, and the
    // scatter puts it where two regroupings would: segments in the order
    // (round-1 segment, c1, c2), each stable. Every decision is the one the
    // two rounds make in turn.
    const std::size_t before = S.pts.size();
    const Classified c1 = classify_units(S, B, U, 3, ps, [&](std::uint32_t k) { return classifier(R, k); });
    Split R2;
    std::vector<std::uint32_t> seg2(3 * K, kNone);  // (k, c1) -> its segment in round 2
    std::size_t kept = 0;
    for (std::size_t k = 0; k < K; ++k)
      for (std::uint32_t c = 0; c < 3; ++c) {
        std::size_t count = 0;
        const Far bb = c1.child(U, k, c, 3, count);
        if (count == 0) continue;
        seg2[3 * k + c] = static_cast<std::uint32_t>(R2.tri.size());
        R2.tri.push_back(R.child(k, c));
        R2.far.push_back(bb.i);
        kept += count;
      }
    st.discarded_early += before - kept - K;
    if (R2.tri.empty()) {  // nothing left
      S = Segments{};
      break;
    }
    split(R2);
    const std::uint8_t* code1 = B.code.data();
    using Classifier = decltype(classifier(R2, 0));
    const std::size_t dropped = regroup(
        S, B, U, 9, ps, true,
        [&](std::uint32_t k) {
          std::array<std::optional<Classifier>, 3> cl;
          for (std::uint32_t c = 0; c < 3; ++c)
            if (seg2[3 * k + c] != kNone) cl[c].emplace(classifier(R2, seg2[3 * k + c]));
          return [code1, cl](std::size_t i, Index p, const double* x, Key& key) -> std::uint32_t {
            const std::uint8_t c = code1[i];  // read before regroup writes the new code of i
            if (c == kDropped) return kNone;
            const std::uint32_t ch = (*cl[c])(i, p, x, key);
            return ch == kNone ? kNone : 3 * c + ch;
          };
        },
        [&](std::size_t k, int c) { return R2.child(seg2[3 * k + c / 3], static_cast<std::uint32_t>(c % 3)); });
    st.discarded_early += dropped - (before - kept) - R2.tri.size();
  }
  return M;
}

// ---- line 15: flip-flop (Algorithm 6), sequential --------------------------------
// The reference's FIFO run (ff3::run, ff3::decide, ff3::apply of
// reference/hull3/flip_flop_3d.cpp) with the same decisions in the same
// order — every predicate exact, so the run is the same operation for
// operation — but cheaper: the edge is located once per step (the reference
// locates it in run, decide, apply and flip22), from a hint (the slot of a
// triangle that had it when it was queued, or a neighbour of that slot)
// before walking around a star, and orient3d of input points goes through
// the per-input static filter first.
// A vertex of the polyhedron during flip-flop: its coordinates and its input
// index (the SoS id of every predicate) in one 32-byte line.
struct alignas(32) FlipVertex {
  double x[3];
  Index id;
};

class FlipFlop {
 public:
  // P over the local vertex numbers 0..P.n-1 of v (P.n of them); s: the
  // kernel point over input indices, sd its coordinates when it is a double
  // point (DoubleKernel, SoS id sid), else null
  FlipFlop(ref::poly::Polyhedron3& P, const FlipVertex* v, const ref::KernelPoint& s, const double* sd, PointId sid,
           const StaticFilter& f, ref::Hull3Stats& stats)
      : P_(P), v_(v), s_(s), sd_(sd), sid_(sid), f_(f), stats_(stats), labelled_(P.n, 0) {}

  void run() {
    using Action = ref::ff3::Action;
    // line 2, straight into the queue: a vector of the edges copied into it
    // stayed alive beside it for the whole run (12 bytes an edge, 15 MB on
    // the 10^6 sphere shell of thickness 1e-4, where flip-flop's is the peak)
    std::deque<Queued> Q;
    all_edges(Q);
    while (!Q.empty()) {  // line 3
      const auto [u, w, hint] = Q.front();  // line 4
      Q.pop_front();
      const ref::poly::DEdge e = locate(u, w, hint);
      if (!e.valid()) continue;  // flipped away since it was pushed
      const Quad q{u, w, P_.apex(e), P_.apex(P_.twin(e))};
      const ref::ff3::Decision d = decide(q);
      switch (d.action) {
        case Action::none: break;
        case Action::label: {  // lines 16-19: the edges around the labelled vertex
          labelled_[d.inner] = 1;
          ++stats_.labelled_non_extreme;
          const Index a = d.inner;
          const std::uint32_t t0 = P_.corner[a];
          std::uint32_t t = t0;
          std::uint32_t steps = 0;
          do {  // ref::poly::link, with the slots
            int k = 0;
            while (P_.tri[t][k] != a) ++k;
            Q.push_back({a, P_.tri[t][(k + 1) % 3], t});
            t = P_.adj[t][(k + 2) % 3];
          } while (t != t0 && ++steps <= P_.deg[a]);
          break;
        }
        case Action::flip31_v:
        case Action::flip31_d: {  // lines 8-9
          const std::uint32_t t = ref::poly::flip31(P_, d.inner);
          const Triangle L = P_.tri[t];  // the link of d.inner, in ref::poly::link's order (flip31 keeps it)
          ++stats_.flips_3_1;
          Q.push_back({L[0], L[1], t});
          Q.push_back({L[1], L[2], t});
          Q.push_back({L[2], L[0], t});
          break;
        }
        case Action::flip22_v:
        case Action::flip22_d:  // lines 12-15
          ref::poly::flip22(P_, e);  // (a, d, c) and (d, b, c) in the two slots of e and its twin
          ++stats_.flips_2_2;
          Q.push_back({q.a, q.c, e.t});
          Q.push_back({q.b, q.c, e.t});
          Q.push_back({q.a, q.d, e.t});
          Q.push_back({q.b, q.d, e.t});
          break;
      }
    }
    final_check();
  }

  // Flip-flop in rounds (§6.4.1, with the labelling of §3.3.1). A round:
  //   check   every candidate edge is located and decided (ff3::decide)
  //           against the state before the round, in parallel, read-only; a
  //           flip claims the triangles it replaces (2-2: the two of its
  //           edge; 3-1: the three around the vertex) by an atomic minimum of
  //           its candidate number per slot, a label claims its vertex;
  //   flip    the flips that hold all their claims rewrite their own slots in
  //           parallel (degrees and corners of shared vertices atomically);
  //   stitch  each winner points the outer edges of its new triangles at the
  //           neighbours: a neighbour that flipped too holds the edge in one
  //           of its own slots; a neighbour that did not gets its one entry
  //           across that edge rewritten (nobody else borders it there);
  //   queue   the edges the FIFO run would queue after each action (for a
  //           label: the edges around its vertex now) and every action that
  //           lost a claim are the next round's candidates.
  // Why the result is flip-flop's: the flips of a round replace disjoint sets
  // of triangles, and a flip's decision reads only its own triangles (a 3-1
  // flip: all three around its vertex, so that vertex's degree is fixed too),
  // the points, the labels before the round, and degrees only to choose a
  // 3-1 flip (when the decision is a 2-2 flip, the endpoint is in no cone and
  // its degree did not matter). So the round is the sequential run of its
  // flips in any order followed by its labels (a label is a fact, Lemma 6.5,
  // true in any state), each decision valid when performed; the stitch
  // leaves the structure that run leaves. Every round with an action
  // performs one (the smallest candidate number holds its claims), the
  // result is the SoS hull whatever the order (Thm 6.12: unique), hence
  // byte for byte the reference's, and the claims are minima, so the run
  // does not depend on the thread count.
  void run_rounds() {
    using Action = ref::ff3::Action;
    std::vector<Queued> cand;
    all_edges(cand);  // line 2
    std::vector<std::atomic<std::uint32_t>> slot_claim(P_.tri.size()), vertex_claim(P_.n);
    par_for(slot_claim.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t t = lo; t < hi; ++t) slot_claim[t].store(kNone, std::memory_order_relaxed);
    });
    par_for(P_.n, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t v = lo; v < hi; ++v) vertex_claim[v].store(kNone, std::memory_order_relaxed);
    });
    std::vector<Checked> ck;
    std::vector<std::uint8_t> won;
    std::vector<std::size_t> off;
    std::vector<Queued> next;
    const auto is_flip = [](const ref::ff3::Decision& d) {
      return d.action != Action::none && d.action != Action::label;
    };
    while (!cand.empty()) {  // line 3, a round at a time
      const std::size_t K = cand.size();
      ck.resize(K);
      par_for(K, 256, [&](std::size_t lo, std::size_t hi) {  // check (lines 4-5)
        for (std::size_t i = lo; i < hi; ++i) {
          Checked& c = ck[i];
          c.d = {};
          c.ns = 0;
          c.slot[0] = c.slot[1] = c.slot[2] = kNone;
          c.e = locate(cand[i].u, cand[i].w, cand[i].hint);
          if (!c.e.valid()) continue;  // flipped away since it was queued
          c.f = P_.twin(c.e);
          c.q = {cand[i].u, cand[i].w, P_.apex(c.e), P_.apex(c.f)};
          c.d = decide(c.q);
          const auto id = static_cast<std::uint32_t>(i);
          if (c.d.action == Action::label) {
            claim_min(vertex_claim[c.d.inner], id);
          } else if (c.d.action == Action::flip22_v || c.d.action == Action::flip22_d) {
            c.slot[0] = c.e.t, c.slot[1] = c.f.t, c.ns = 2;
          } else if (c.d.action != Action::none) {  // the three triangles around the vertex, from its corner
            const Index a = c.d.inner;
            c.slot[0] = P_.corner[a];
            for (int j = 1; j < 3; ++j) c.slot[j] = P_.adj[c.slot[j - 1]][(pos(c.slot[j - 1], a) + 2) % 3];
            c.ns = 3;
          }
          for (int j = 0; j < c.ns; ++j) claim_min(slot_claim[c.slot[j]], id);
        }
      });
      won.assign(K, 0);
      par_for(K, 1024, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) {
          const Checked& c = ck[i];
          bool all = c.d.action != Action::none;
          if (c.d.action == Action::label) all = vertex_claim[c.d.inner].load(std::memory_order_relaxed) == i;
          for (int j = 0; j < c.ns; ++j) all = all && slot_claim[c.slot[j]].load(std::memory_order_relaxed) == i;
          won[i] = all;
        }
      });
      par_for(K, 256, [&](std::size_t lo, std::size_t hi) {  // flip (lines 8-9, 12-15), own slots only
        for (std::size_t i = lo; i < hi; ++i)
          if (won[i]) apply(ck[i]);
      });
      par_for(K, 256, [&](std::size_t lo, std::size_t hi) {  // stitch
        for (std::size_t i = lo; i < hi; ++i)
          if (won[i] && is_flip(ck[i].d)) stitch(ck[i], static_cast<std::uint32_t>(i), slot_claim, won, ck);
      });
      // queue: where each candidate's successors go (a winner's queued
      // edges, or the loser itself), counted in order
      off.resize(K + 1);
      off[0] = 0;
      for (std::size_t i = 0; i < K; ++i) {
        const Checked& c = ck[i];
        std::size_t m = 0;
        if (c.d.action != Action::none) {
          if (!won[i]) m = 1;
          else if (c.d.action == Action::label) m = P_.deg[c.d.inner], ++stats_.labelled_non_extreme;
          else if (c.ns == 3) m = 3, ++stats_.flips_3_1;
          else m = 4, ++stats_.flips_2_2;
        }
        off[i + 1] = off[i] + m;
      }
      next.resize(off[K]);
      par_for(K, 256, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) {
          const Checked& c = ck[i];
          if (c.d.action == Action::none) continue;
          Queued* out = &next[off[i]];
          if (!won[i]) {
            *out = cand[i];
          } else if (c.d.action == Action::label) {  // lines 16-19: the edges around the labelled vertex
            const Index a = c.d.inner;
            std::uint32_t t = P_.corner[a];
            for (std::uint32_t j = 0; j < P_.deg[a]; ++j) {
              const int k = pos(t, a);
              out[j] = {a, P_.tri[t][(k + 1) % 3], t};
              t = P_.adj[t][(k + 2) % 3];
            }
          } else if (c.ns == 3) {  // the link of the removed vertex
            const std::uint32_t t = c.slot[0];
            const Triangle& L = P_.tri[t];
            out[0] = {L[0], L[1], t}, out[1] = {L[1], L[2], t}, out[2] = {L[2], L[0], t};
          } else {  // the four outer edges of the flipped pair
            out[0] = {c.q.a, c.q.c, c.e.t}, out[1] = {c.q.b, c.q.c, c.e.t};
            out[2] = {c.q.a, c.q.d, c.e.t}, out[3] = {c.q.b, c.q.d, c.e.t};
          }
        }
      });
      par_for(K, 1024, [&](std::size_t lo, std::size_t hi) {  // release the claims
        for (std::size_t i = lo; i < hi; ++i) {
          const Checked& c = ck[i];
          if (c.d.action == Action::label) vertex_claim[c.d.inner].store(kNone, std::memory_order_relaxed);
          for (int j = 0; j < c.ns; ++j) slot_claim[c.slot[j]].store(kNone, std::memory_order_relaxed);
        }
      });
      for (std::size_t i = 0; i < K; ++i)  // the slots 3-1 flips released
        if (won[i] && ck[i].ns == 3) P_.free_slots.push_back(ck[i].slot[1]), P_.free_slots.push_back(ck[i].slot[2]);
      cand.swap(next);
    }
    final_check();
  }

 private:
  struct Quad {
    Index a, b, c, d;  // edge a -> b, link c (apex of a b c) and d (apex of b a d)
  };
  struct Queued {
    Index u, w;
    std::uint32_t hint;  // a slot near the edge when it was queued
  };
  // Theorems 6.2 and 6.12: all edges convex and no non-extreme vertex left —
  // ref::ff3::final_problem, in the same order with the same message, reading
  // each edge's far apex through the adjacency instead of finding the edge
  void final_check() const {
    for (std::uint32_t t = 0; t < P_.tri.size(); ++t)
      if (P_.alive[t])
        for (int k = 0; k < 3; ++k) {
          const Index u = P_.tri[t][k], w = P_.tri[t][(k + 1) % 3];
          if (v_[u].id < v_[w].id && orient3(u, w, P_.tri[t][(k + 2) % 3], P_.apex(P_.twin({t, k}))) < 0)
            throw std::logic_error("hull3 (cpu): flip-flop ended with the reflex edge " + std::to_string(v_[u].id) +
                                   " " + std::to_string(v_[w].id));
        }
    for (Index v = 0; v < P_.n; ++v)
      if (labelled_[v] && P_.is_vertex(v))
        throw std::logic_error("hull3 (cpu): flip-flop ended with the non-extreme vertex " + std::to_string(v_[v].id));
  }
  // every edge once (line 2), in the order of ref::poly::edges (slot order,
  // from the endpoint of smaller input index), with its slot as the hint,
  // into `to` (a container with push_back)
  template <class To>
  void all_edges(To& to) const {
    for (std::uint32_t t = 0; t < P_.tri.size(); ++t)
      if (P_.alive[t])
        for (int k = 0; k < 3; ++k)
          if (v_[P_.tri[t][k]].id < v_[P_.tri[t][(k + 1) % 3]].id)
            to.push_back({P_.tri[t][k], P_.tri[t][(k + 1) % 3], t});
  }
  struct Checked {  // a candidate of a round: its edge (e, twin f), quad, decision, claimed slots
    ref::poly::DEdge e, f;
    Quad q{};
    ref::ff3::Decision d;
    std::uint32_t slot[3] = {kNone, kNone, kNone};
    int ns = 0;
  };
  static void claim_min(std::atomic<std::uint32_t>& c, std::uint32_t i) {
    std::uint32_t cur = c.load(std::memory_order_relaxed);
    while (i < cur && !c.compare_exchange_weak(cur, i, std::memory_order_relaxed)) {
    }
  }
  int pos(std::uint32_t t, Index v) const {
    int k = 0;
    while (P_.tri[t][k] != v) ++k;
    return k;
  }
  // degrees and corners of vertices that other winners of the round share
  void add_deg(Index v, int delta) {
    __atomic_fetch_add(&P_.deg[v], static_cast<std::uint32_t>(delta), __ATOMIC_RELAXED);
  }
  void set_corner(Index v, std::uint32_t t) { __atomic_store_n(&P_.corner[v], t, __ATOMIC_RELAXED); }
  // A winner's action on its own slots (ref::poly::flip22 / flip31 without
  // touching a neighbour: stitch does that), or its label.
  void apply(const Checked& c) {
    using Action = ref::ff3::Action;
    if (c.d.action == Action::label) {
      __atomic_store_n(&labelled_[c.d.inner], std::uint8_t{1}, __ATOMIC_RELAXED);
    } else if (c.ns == 2) {  // (a, b, c), (b, a, d) -> (a, d, c), (d, b, c) in the slots of e and its twin
      const std::uint32_t t1 = c.e.t, t2 = c.f.t;
      const Index a = c.q.a, b = c.q.b, cc = c.q.c, d = c.q.d;
      const std::uint32_t n_bc = P_.adj[t1][(c.e.k + 1) % 3], n_ca = P_.adj[t1][(c.e.k + 2) % 3];
      const std::uint32_t n_ad = P_.adj[t2][(c.f.k + 1) % 3], n_db = P_.adj[t2][(c.f.k + 2) % 3];
      P_.tri[t1] = {a, d, cc};
      P_.adj[t1] = {n_ad, t2, n_ca};
      P_.tri[t2] = {d, b, cc};
      P_.adj[t2] = {n_db, n_bc, t1};
      set_corner(a, t1), set_corner(cc, t1), set_corner(d, t1), set_corner(b, t2);
      add_deg(a, -1), add_deg(b, -1), add_deg(cc, 1), add_deg(d, 1);
    } else {  // slots (a, L0, L1), (a, L1, L2), (a, L2, L0) -> (L0, L1, L2) in the first
      const Index a = c.d.inner;
      Index L[3];
      std::uint32_t outer[3];
      for (int i = 0; i < 3; ++i) {
        const int k = pos(c.slot[i], a);
        L[i] = P_.tri[c.slot[i]][(k + 1) % 3];
        outer[i] = P_.adj[c.slot[i]][(k + 1) % 3];
      }
      const std::uint32_t t = c.slot[0];
      P_.tri[t] = {L[0], L[1], L[2]};
      P_.adj[t] = {outer[0], outer[1], outer[2]};
      P_.alive[c.slot[1]] = 0, P_.alive[c.slot[2]] = 0;
      for (Index v : L) set_corner(v, t), add_deg(v, -1);
      P_.corner[a] = kNone;
      P_.deg[a] = 0;
    }
  }
  // The outer edges of winner i's new triangles: adj entries pointing at the
  // triangle across, and the entry back from a neighbour that did not flip.
  void stitch(const Checked& c, std::uint32_t i, const std::vector<std::atomic<std::uint32_t>>& claim,
              const std::vector<std::uint8_t>& won, const std::vector<Checked>& ck) {
    const auto own = [&](std::uint32_t t) { return t == c.slot[0] || t == c.slot[1] || t == c.slot[2]; };
    for (int j = 0; j < c.ns; ++j) {
      const std::uint32_t t = c.slot[j];
      if (!P_.alive[t]) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t nb = P_.adj[t][k];
        if (own(nb)) continue;
        const Index x = P_.tri[t][k], y = P_.tri[t][(k + 1) % 3];  // edge x -> y; the neighbour has y -> x
        const std::uint32_t w = claim[nb].load(std::memory_order_relaxed);
        if (w != kNone && w != i && won[w]) {  // the neighbour flipped: the edge is in one of its slots
          const Checked& o = ck[w];
          std::uint32_t to = kNone;
          for (int m = 0; m < o.ns && to == kNone; ++m)
            if (P_.alive[o.slot[m]])
              for (int r = 0; r < 3; ++r)
                if (P_.tri[o.slot[m]][r] == y && P_.tri[o.slot[m]][(r + 1) % 3] == x) to = o.slot[m];
          if (to == kNone)
            throw std::logic_error("hull3 (cpu): a flip-flop round lost the edge " + std::to_string(x) + " " +
                                   std::to_string(y));
          P_.adj[t][k] = to;
        } else {
          for (int r = 0; r < 3; ++r)
            if (P_.tri[nb][r] == y && P_.tri[nb][(r + 1) % 3] == x) P_.adj[nb][r] = t;
        }
      }
    }
  }
  // the directed edge u -> w in slot t, or invalid
  ref::poly::DEdge in_slot(std::uint32_t t, Index u, Index w) const {
    if (t >= P_.tri.size() || !P_.alive[t]) return {};
    const Triangle& T = P_.tri[t];
    for (int k = 0; k < 3; ++k) {
      if (T[k] == u && T[(k + 1) % 3] == w) return {t, k};
      if (T[k] == w && T[(k + 1) % 3] == u) return P_.twin({t, k});
    }
    return {};
  }
  // find_edge(u, w), trying the hint and its neighbours first
  ref::poly::DEdge locate(Index u, Index w, std::uint32_t hint) const {
    if (ref::poly::DEdge e = in_slot(hint, u, w); e.valid()) return e;
    if (hint < P_.tri.size() && P_.alive[hint])
      for (int j = 0; j < 3; ++j)
        if (ref::poly::DEdge e = in_slot(P_.adj[hint][j], u, w); e.valid()) return e;
    return ref::poly::find_edge(P_, u, w);
  }
  int orient3(Index a, Index b, Index c, Index p) const {
    return orient(f_, v_[a].id, v_[a].x, v_[b].id, v_[b].x, v_[c].id, v_[c].x, v_[p].id, v_[p].x);
  }
  // s.side(a, b, c) = orient3d(a, b, c, s) (DoubleKernel::side, from the local copies)
  int side(Index a, Index b, Index c) const {
    if (sd_) return orient(f_, v_[a].id, v_[a].x, v_[b].id, v_[b].x, v_[c].id, v_[c].x, sid_, sd_);
    return s_.side(v_[a].id, v_[b].id, v_[c].id);
  }
  // the kernel point over the local numbers, for ref::poly::in_cone
  struct LocalKernel final : ref::KernelPoint {
    const FlipFlop* ff;
    explicit LocalKernel(const FlipFlop* f) : ff(f) {}
    int side(Index a, Index b, Index c) const override { return ff->side(a, b, c); }
  };
  [[maybe_unused]] bool in_cone(Index a, Index b, Index c, Index p) const {
    return ref::poly::in_cone(LocalKernel(this), a, b, c, p);
  }

  // ff3::decide, line by line (flip_flop_3d.cpp), with its cone tests reduced
  // to two orientations. Every triangle of the polyhedron has s beneath it
  // (§6.4.1's first technique; Lemma 6.1: the polyhedron stays star-shaped
  // w.r.t. s through every flip), i.e. s.side(x, y, z) = +1 for each of its
  // triangles (x, y, z) — the fact ff3's `reflex` already rests on. The quad's
  // triangles are (a, b, c) and (b, a, d), so of the twelve signs that
  // in_cone(b, c, d, a), in_cone(a, c, d, b) and s_in_tetrahedron compare,
  // all but X = s.side(b, c, d) and Y = s.side(a, c, d) (the two planes
  // through s and the link cd) are known (a swap of two vertices negates):
  //   in_cone(b, c, d, a): X == side(b, c, a) = +1, Y = side(c, d, a) == X,
  //                        side(d, b, a) = side(b, a, d) = +1 == X;
  //   in_cone(a, c, d, b): Y == side(a, c, b) = -1, X = side(c, d, b) == Y,
  //                        side(d, a, b) = -side(b, a, d) = -1 == Y;
  //   s_in_tetrahedron:    side(a, b, c) = +1 == o, -side(a, b, d) = +1 == o,
  //                        Y == o, -X == o.
  // So a is inside the cone of bcd exactly when X = Y = +1, b inside that of
  // acd exactly when X = Y = -1, the cone C_s(T_e) is convex (neither)
  // exactly when X != Y, and s lies in abcd exactly when o = Y = +1 = -X:
  // the same decisions as the reference's from 2 kernel-point orientations
  // instead of up to 8 (10^6 points of the sphere shell, the sample hull's
  // run included: 1.81 M -> 0.63 M; flip-flop stage 0.121 -> 0.088 s).
  ref::ff3::Decision decide(const Quad& q) const {
    using Action = ref::ff3::Action;
    constexpr Index kNo = ~Index{0};
    Index x = kNo, x_id = kNo;  // line 5: the labelled vertex of smallest (input) index
    for (Index v : {q.a, q.b, q.c, q.d})
      if (labelled_[v] && v_[v].id < x_id) x = v, x_id = v_[v].id;
    const int o = orient3(q.a, q.b, q.c, q.d);
    const bool is_reflex = o < 0;
    if (!is_reflex && x == kNo) return {};
    const int X = side(q.b, q.c, q.d), Y = side(q.a, q.c, q.d);
    const bool a_in = X > 0 && Y > 0, b_in = X < 0 && Y < 0;
    assert(a_in == in_cone(q.b, q.c, q.d, q.a) && b_in == in_cone(q.a, q.c, q.d, q.b));
    // lines 6-7: an endpoint of degree 3 inside the cone of its link's triangle
    Index inner = kNo;
    if (P_.deg[q.a] == 3 && a_in) inner = q.a;
    else if (P_.deg[q.b] == 3 && b_in) inner = q.b;
    if (inner != kNo) {  // line 8
      if (labelled_[inner]) return {Action::flip31_d, inner};
      if (is_reflex) return {Action::flip31_v, inner};
      return {};
    }
    // line 11: C_s(T_e) convex
    if (!a_in && !b_in) {
      if (x == kNo) return is_reflex ? ref::ff3::Decision{Action::flip22_v, 0} : ref::ff3::Decision{};
      // lines 14-15: D-criterion, flippable when s is not inside abcd
      const bool s_in = o > 0 && Y > 0 && X < 0;
      assert(s_in == s_in_tetrahedron(q, o));
      if ((x == q.a || x == q.b) && !s_in) return {Action::flip22_d, 0};
      return {};
    }
    // lines 16-18: label the inner endpoint (Lemma 6.5)
    const Index in = a_in ? q.a : q.b;
    if (!labelled_[in] && is_reflex) return {Action::label, in};
    return {};
  }
  // s inside the tetrahedron abcd, o = orient3d(a, b, c, d) (ff3's
  // s_in_tetrahedron; decide's assertion compares its shortcut with it)
  [[maybe_unused]] bool s_in_tetrahedron(const Quad& q, int o) const {
    return side(q.a, q.b, q.c) == o && -side(q.a, q.b, q.d) == o && side(q.a, q.c, q.d) == o &&
           -side(q.b, q.c, q.d) == o;
  }

  ref::poly::Polyhedron3& P_;
  const FlipVertex* v_;
  const ref::KernelPoint& s_;
  const double* sd_;
  PointId sid_;
  const StaticFilter& f_;
  ref::Hull3Stats& stats_;
  std::vector<std::uint8_t> labelled_;  // line 1: all vertices "unknown"
};

// The canonical output (canonical.hpp: each triangle rotated, the list
// sorted) of the alive slots of P, and rank[slot] its index there.
std::vector<Triangle> canonical_with_ranks(const ref::poly::Polyhedron3& P, std::vector<std::uint32_t>& rank) {
  std::vector<std::pair<Triangle, std::uint32_t>> rows;
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    if (P.alive[t]) rows.push_back({canonical_rotation(P.tri[t]), t});
  par_sort(rows, [](const auto& x, const auto& y) { return x.first < y.first; });  // the triangles are distinct
  std::vector<Triangle> out(rows.size());
  rank.assign(P.tri.size(), kNone);
  for (std::size_t i = 0; i < rows.size(); ++i) out[i] = rows[i].first, rank[rows[i].second] = static_cast<std::uint32_t>(i);
  return out;
}

// The witness (ffhull.hpp, hull3_witness.hpp) of the final hull P with
// canonical output `out` (rank: slot -> index in out); s_approx: the kernel
// point rounded (a hint only).
template <class Kernel>
void make_witness(const PointSet& ps, const Kernel& s, const ref::poly::Polyhedron3& P,
                  const std::vector<Triangle>& out, const std::vector<std::uint32_t>& rank,
                  const std::array<Index, 4>& tet, const certify::BoxTest3& box, const double* s_approx,
                  Hull3Witness& w, StageClock& clock) {
  const std::size_t n = ps.size();
  w.tet = tet;
  w.facets = out;
  w.facet.assign(n, kNoFacet);  // w.beneath: filled by the construction rounds
  std::size_t vertices = 0;
  for (Index p = 0; p < n; ++p) vertices += P.deg[p] > 0;
  w.ball = worth_inner_ball(n - vertices, out.size());
  const auto for_range = par_for_range();
  const certify::detail::InnerBall<3> ball =
      w.ball ? certify::detail::InnerBall<3>(ps, out, for_range) : certify::detail::InnerBall<3>();
  clock.mark("witness: inner ball");
  const std::size_t cap = 4 * P.tri.size() + 100;
  std::vector<std::uint32_t> slot_of(out.size());
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    if (rank[t] != kNone) slot_of[rank[t]] = t;
  // about one cell per facet (a finer table leaves most cells empty, and an
  // empty cell's hint is the previous row's: longer walks)
  const int side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(out.size()) / 6)), 64, 1024);
  const certify::detail::DirectionTable table(ps, out, s_approx, side);
  // p outside the cone of slot t across edge k: orient3d(s, a, b, p) > 0,
  // i.e. orient3d(a, b, p, s) = s.side(a, b, p) < 0
  const auto across = [&](std::uint32_t t, int k, Index p) {
    return s.side(P.tri[t][k], P.tri[t][(k + 1) % 3], p) < 0;
  };
  const auto locate = [&](Index p) -> std::uint32_t {
    std::uint32_t cur = slot_of[table.hint(ps.point(p))];
    certify::detail::XorShift rng;  // the certifier's remembering stochastic walk
    rng.s ^= static_cast<std::uint64_t>(p) * 0xD1B54A32D192ED03ull;
    for (std::size_t steps = 0; steps < cap; ++steps) {
      int cand[3], nc = 0;
      for (int k = 0; k < 3; ++k)
        if (across(cur, k, p)) cand[nc++] = k;
      if (nc == 0) return cur;
      cur = P.adj[cur][cand[nc == 1 ? 0 : rng.next() % static_cast<std::uint32_t>(nc)]];
    }
    for (std::uint32_t t = 0; t < P.tri.size(); ++t)  // the walk did not settle: every facet
      if (P.alive[t] && !across(t, 0, p) && !across(t, 1, p) && !across(t, 2, p)) return t;
    throw std::logic_error("hull3 (cpu): no facet's cone contains point " + std::to_string(p));
  };
  // a point inside the ball drops its record (the ball test is the
  // certifier's cheapest); a point removed early keeps it and walks no more;
  // a point strictly inside round 0's box has no record (construct) and waits
  // for the decision on the box; the rest — the points flip-flop removed (3-1
  // flips), and those round 0's ball dropped that the certifier's ball does
  // not hold — walk. The box goes to the certifier when it pays there
  // (worth_box); otherwise its points walk too.
  std::vector<std::size_t> pending((n + kChunk - 1) / kChunk, 0);
  par_for(pending.size(), 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c)
      for (std::size_t p = c * kChunk; p < std::min(n, (c + 1) * kChunk); ++p) {
        if (P.deg[p] != 0) continue;
        const double* x = ps.point(static_cast<Index>(p));
        if (w.has_record(p)) {
          if (ball.strictly_inside(x)) w.beneath[p] = kNoFacet;
        } else if (box.strictly_inside(x)) {
          pending[c] += !ball.strictly_inside(x);
        } else if (!ball.strictly_inside(x)) {
          w.facet[p] = rank[locate(static_cast<Index>(p))];
        }
      }
  });
  std::size_t in_box = 0;
  for (std::size_t c : pending) in_box += c;
  w.box = worth_box(in_box, out.size()) ? box : certify::BoxTest3{};
  if (in_box > 0 && w.box.empty())
    par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t p = lo; p < hi; ++p) {
        const double* x = ps.point(static_cast<Index>(p));
        if (P.deg[p] == 0 && !ball.strictly_inside(x) && !w.has_record(p) && box.strictly_inside(x))
          w.facet[p] = rank[locate(static_cast<Index>(p))];
      }
    });
  clock.mark("witness: walks");
}

// Flip-flop in rounds or as the FIFO run (Hull3Options::flip_flop): the
// rounds check about 1.3x the edges the FIFO run pops (losers and repeated
// candidates are checked again; 10^6 ball: 256k against 196k checks, 52
// rounds) and add four parallel passes a round, so on this 2-core machine
// they did not beat the FIFO run (docs/benchmarks.md, 3D hull), and with more threads
// than cores they wait at every pass; automatic takes them only with at
// least 4 threads on at least 4 cores.
bool use_rounds(FlipFlopRun run) {
  if (run == FlipFlopRun::automatic)
    return tbb::this_task_arena::max_concurrency() >= 4 && std::thread::hardware_concurrency() >= 4;
  return run == FlipFlopRun::rounds;
}

template <class Kernel>
std::vector<Triangle> hull_with_kernel(const PointSet& ps, const StaticFilter& f, double largest, const Kernel& s,
                                       const double* sd,
                                       const std::array<Index, 4>& tet, const InnerRegion& inner,
                                       ref::Hull3Stats& st, StageClock& clock, const double* s_approx,
                                       Hull3Witness* witness, FlipFlopRun run) {
  std::optional<Made> made;
  if (witness) made.emplace().record.assign(ps.size(), kNoFacet);
  Mesh M = construct(ps, f, largest, s, sd, tet, inner, st, made ? &*made : nullptr);
  if (witness) {  // the records as they are: indices into the triangles made
    witness->beneath = std::move(made->record);
    witness->made = std::move(made->made);
    made.reset();
  }
  clock.mark("construction rounds");
  st.flips_1_3 = st.insertions;
  // Flip-flop on the polyhedron's own vertices, numbered 0..V-1 in the order
  // the slots first name them, each with its coordinates and input index in
  // one line (FlipVertex): the queue visits edges in slot order, and the
  // input's order of the points is arbitrary — 10^6 points in a shell of
  // thickness 1e-4 left 415k vertices spread over the 24 MB of coordinates,
  // and the same points in Morton order made the flip-flop stage 30 % faster.
  // The predicates take the input indices (the SoS ids), so every decision
  // and the output are the same. The reference's polyhedron structure, from
  // the flat arrays (same conventions: adj[t][k] is the triangle across edge
  // k of t).
  // (M.v renumbered in place, and verts reserved at its size: a closed
  // surface of F triangles has F / 2 + 2 vertices; growing it by doubling
  // raised the 10^6 ball's peak RSS from 49.3 to 53.4 MB)
  std::vector<FlipVertex> verts;
  verts.reserve(M.size() / 2 + 2);
  {
    std::vector<Index> local(ps.size(), kNone);
    for (Index& g : M.v) {
      if (local[g] == kNone) {
        local[g] = static_cast<Index>(verts.size());
        const double* x = ps.point(g);
        verts.push_back({{x[0], x[1], x[2]}, g});
      }
      g = local[g];
    }
  }
  ref::poly::Polyhedron3 P;
  P.tri.resize(M.size());
  P.adj.resize(M.size());
  P.alive.assign(M.size(), 1);
  for (std::uint32_t t = 0; t < M.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      P.tri[t][k] = M.v[3 * t + k];
      P.adj[t][k] = M.nb[3 * t + k];
    }
  P.n = verts.size();
  P.corner.assign(P.n, kNone);
  P.deg.assign(P.n, 0);
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    for (Index v : P.tri[t]) P.corner[v] = t, ++P.deg[v];
  M = Mesh{};  // copied into P: 24 bytes a slot less during flip-flop and the witness
  if constexpr (FF_CHECKED)
    FF_CHECK(ref::poly::structure_problem(P).empty(), "hull3 (cpu): inconsistent polyhedron after construction");
  // line 15: flip-flop (Algorithm 6), with the kernel's filter (valid for ps
  // and the kernel point)
  {
    FlipFlop ff(P, verts.data(), s, sd, static_cast<PointId>(ps.size()), f, st);
    if (use_rounds(run)) ff.run_rounds();
    else ff.run();
  }
  // back to input indices
  ref::poly::Polyhedron3 G;
  G.n = ps.size();
  G.corner.assign(G.n, kNone);
  G.deg.assign(G.n, 0);
  for (Index v = 0; v < P.n; ++v) G.corner[verts[v].id] = P.corner[v], G.deg[verts[v].id] = P.deg[v];
  for (Triangle& T : P.tri)
    for (Index& v : T) v = verts[v].id;
  G.tri = std::move(P.tri);
  G.adj = std::move(P.adj);
  G.alive = std::move(P.alive);
  G.free_slots = std::move(P.free_slots);
  P = ref::poly::Polyhedron3{};
  verts = {};
  clock.mark("flip-flop");
  std::vector<std::uint32_t> rank;
  std::vector<Triangle> out = canonical_with_ranks(G, rank);
  clock.mark("canonical output");
  if (witness) {
    make_witness(ps, s, G, out, rank, tet, inner.box, s_approx, *witness, clock);
  }
  return out;
}

std::vector<Triangle> compute(const PointSet& ps, ref::Hull3Stats& st, StageClock& clock, Hull3Witness* witness,
                              FlipFlopRun run);

// ---- a ball inside the hull of a sample, for round 0 ------------------------------
// The hull of every k-th input point (sample_size of them, by this kernel) lies in
// conv(S); the inner ball of its facets (inner_ball.hpp: centred where the
// facets are farthest, 0.999999 of the smallest floating distance, every
// facet verified exactly) is then strictly inside conv(S), and round 0 drops
// the points strictly inside it like those of the extreme points' box and
// ball (inner_region) — when it is the largest of the three. It serves input
// that packs its points just inside its hull: 10^6 points in a spherical
// shell of thickness 0.01 have none within 0.49 of the centre, where the 14
// extreme points' ball ends (0.40), but about two thirds within the sample
// hull's inner ball. The sample hull is this kernel's output and is not
// certified here: were its ball wrong, a dropped hull vertex would be missing
// from the output, and the certifier — which locates every dropped point
// itself unless its own ball or the verified box holds it (make_witness,
// certify_hull3.hpp) — would reject the result; no answer rests on it.
// (n / 16 points, at most 2^16, from n = 2^17 on)
constexpr std::size_t kSampleMax = std::size_t{1} << 16, kSampleFrom = std::size_t{1} << 17;
std::size_t sample_size(std::size_t n) { return std::min(n / 16, kSampleMax); }
// The inner ball of the hull of m points, every (n / m)-th from 0; none when
// the sample is flat or the ball would not pay (worth_inner_ball).
certify::BallTest<3> ball_of_sample(const PointSet& ps, FlipFlopRun run, std::size_t m) {
  const std::size_t n = ps.size(), k = n / m;
  PointSet sample;
  sample.dim = 3;
  std::vector<double> xyz(3 * m);
  for (std::size_t i = 0; i < m; ++i)
    for (int j = 0; j < 3; ++j) xyz[3 * i + static_cast<std::size_t>(j)] = ps.point(i * k)[j];
  sample.coords = std::move(xyz);
  ref::Hull3Stats st;
  StageClock quiet(nullptr);
  std::vector<Triangle> tris;
  try {
    tris = compute(sample, st, quiet, nullptr, run);
  } catch (const std::invalid_argument&) {  // a flat sample (of input that is not): no ball
    return {};
  }
  if (!worth_inner_ball(n - m, tris.size())) return {};
  return certify::detail::InnerBall<3>(sample, tris, par_for_range()).test();
}

// The fraction of m sample points (every (n / m)-th) strictly inside b.
double held_fraction(const certify::BallTest<3>& b, const PointSet& ps, std::size_t m) {
  const std::size_t k = ps.size() / m;
  std::size_t held = 0;
  for (std::size_t i = 0; i < m; ++i) held += b.strictly_inside(ps.point(i * k + k / 2));
  return static_cast<double>(held) / static_cast<double>(m);
}

// First a probe of kProbe points: its ball, when it holds at least a tenth
// of the input (estimated on other points), says the input packs points just
// inside its hull, and the sample of sample_size(n) points gives a closer
// ball; otherwise the probe's ball is kept (a thin shell, thickness 1e-4:
// almost every point of a sample is a vertex of its hull, whose 2^16 points
// cost more than the ball saves).
constexpr std::size_t kProbe = 4096;
certify::BallTest<3> sample_ball(const PointSet& ps, FlipFlopRun run) {
  const certify::BallTest<3> probe = ball_of_sample(ps, run, kProbe);
  const double f = held_fraction(probe, ps, kProbe);
  if (f < 0.1) return probe;
  return ball_of_sample(ps, run, sample_size(ps.size()));
}

// Whether the region already holds 90 % of kProbe sample points (uniform cube
// points: the box about 95 %): then no sample hull is made.
bool holds_most(const InnerRegion& in, const PointSet& ps) {
  const std::size_t k = ps.size() / kProbe;
  std::size_t held = 0;
  for (std::size_t i = 0; i < kProbe; ++i) held += in.strictly_inside(ps.point(i * k + k / 2));
  return held >= kProbe / 10 * 9;
}

std::vector<Triangle> compute(const PointSet& ps, ref::Hull3Stats& st, StageClock& clock, Hull3Witness* witness,
                              FlipFlopRun run) {
  if (ps.dim != 3 || ps.size() < 4 || ps.size() >= kNone / 2) {
    ref::ffhull::initial_tetrahedron(ps);  // throws the reference's message
    throw std::invalid_argument("hull3 (cpu): too many points for 32-bit indices");
  }
  InputScan scan = scan_input(ps);
  const std::array<Index, 4> tet = initial_tetrahedron(ps, scan.ext);  // line 1
  InnerRegion inner = inner_region(ps, scan.ext);
  // line 4: the kernel point
  std::array<double, 3> s{};
  const bool inside = rounded_centroid(ps, tet, s);
  double largest = 0.0;  // the largest coordinate magnitude, the kernel point's included when inside
  const StaticFilter f =
      static_filter_of(std::move(scan.reps), inside ? std::vector<double>(s.begin(), s.end()) : std::vector<double>{},
                       &largest);
  // the sample's ball only where the static filter is on: at extreme
  // magnitudes (1e±300) the sample hull runs on the exact stages and an inner
  // ball cannot be verified (inner_ball.hpp: r2 >= 2^-900, finite)
  // (and only where the 14 extreme points are in general position: a grid's
  // or duplicates' degenerate sample costs its SoS stages for little)
  if (ps.size() >= kSampleFrom && f.bound(4, false) < HUGE_VAL && inner.closed && !holds_most(inner, ps)) {
    InnerRegion sampled;
    sampled.ball = sample_ball(ps, run);
    if (sampled.ball_volume() > std::max(inner.ball_volume(), inner.box_volume())) inner = sampled;
  }
  inner.keep_larger();
  clock.mark("initial tetrahedron, inner box and ball, static filter");
  if (inside)
    return hull_with_kernel(ps, f, largest, DoubleKernel(ps, s, f), s.data(), tet, inner, st, clock, s.data(), witness,
                            run);
  // §6.4.2: the rounded centroid is not strictly inside; the exact one is
  ++st.exact_kernel_point;
  const ref::RationalKernel exact = ref::centroid_kernel(ps, tet[0], tet[1], tet[2], tet[3]);
  return hull_with_kernel(ps, f, largest, exact, nullptr, tet, inner, st, clock, s.data(), witness, run);
}

}  // namespace

std::vector<Triangle> hull3_ffhull(const PointSet& ps, const Hull3Options& opt, ref::Hull3Stats* stats) {
  ref::Hull3Stats st;
  std::vector<Triangle> out;
  if (opt.threads < 0) throw std::invalid_argument("hull3 (cpu): the number of threads must be positive");
  StageClock clock(opt.times);
  // one thread below 2^14 points by default: measured with 1 and 2 threads
  // (2-core VM, uniform cube, build only): 1000 points 0.28 / 0.34 ms, 3375
  // 0.68 / 0.78 ms, 10^4 1.07 / 1.15 ms, 3x10^4 2.33 / 2.09 ms
  with_threads(threads_for_size(opt.threads, ps.size(), std::size_t{1} << 14),
               [&] { out = compute(ps, st, clock, opt.witness, opt.flip_flop); });
  if (stats) *stats = st;
  return out;
}

}  // namespace flipflop::cpu

// digital_voronoi.cuh — gHull's Stage 1 and the dual of its Stage 2 (thesis
// §7.1 Stages 1-2, §7.2 "Voronoi Construction" and "Star Creation"): the
// digital Voronoi diagram of the points restricted to the six faces of the
// box B, and the working sets it dualizes to. Included by ghull.cuh, in
// FF_KERNELS_NS::ghull_detail; its test entries (ghull.hpp's ghull_stages) at
// the end, in the OpenMP build only.
//
// ============================================================================
// The grid (ghull.hpp's definitions)
// ============================================================================
// The points come scaled into grid units, every coordinate inside (0, G).
// Face f = 2 axis + side is the plane X_axis = 0 (side 0) or X_axis = G
// (side 1); its pixel (u, v) spans the other two axes in increasing order (u
// = floor of the first, v of the second, clamped to [0, G-1]), index
// f G^2 + v G + u. A point's height over face f is h = X_axis (side 0) or
// G - X_axis (side 1).
//
// ============================================================================
// Stage 1: the six slices of the digital Voronoi diagram
// ============================================================================
//   project   Algorithm 8: every point projects onto all six faces, and each
//             pixel keeps the point nearest the face (least h; equal h: the
//             smaller index) — an atomic minimum of h's bits (a positive
//             double's bits order as its value), then, among the points whose
//             h equals that minimum, an atomic minimum of the index (lines
//             10-14). The thesis does this in shared-memory tiles of k x k
//             pixels over points sorted into bricks; a thrust functor has no
//             shared memory, so here both minima are atomics in global
//             memory, one item per (point, face). sites[pixel]: that point,
//             or ~0 (kNoSite).
//   envelope  the nearest site of every pixel q = (i, j) of a face, among the
//             face's sites, each placed at its pixel's centre (u_s, v_s) at
//             its height h_s (the thesis: "the two coordinates ... shifted to
//             the center of the nearest 2D grid cell, while the third ...
//             unmodified"): the least
//                 D = ((i - u_s)^2 + (j - v_s)^2) 2^Q + Hq_s,
//                 Hq_s = round(h_s^2 2^Q)   (kQ = 16 fractional bits),
//             an integer — the squared distance with the squared height in
//             fixed point. PBA [CTMT10] computes the diagram by the separable
//             transform, and so does this, exactly: pass 1 over the columns
//             (face, u): g(u, j) = min over the column's sites of
//             (j - v_s)^2 2^Q + Hq_s and its site, for every row j; pass 2
//             over the rows (face, j): label(i, j) = the site of min over
//             columns u of (i - u)^2 2^Q + g(u, j) (columns without a site
//             skipped). min over all sites = min over columns of the min
//             within the column, so the two passes give the least D. Each
//             pass is a 1D lower envelope of parabolas per line
//             (Felzenszwalb–Huttenlocher's stack of the parabolas that are
//             least somewhere, then a sweep over the positions), computed
//             with PBA's bands: every line cut into m bands, one thread per
//             (line, band) builds the band's own stack, log2 m rounds merge
//             neighbouring groups of bands, and one thread per (line, band)
//             colours the band's pixels (BandStacks' comment below).
//             PBA's phase 1 is a nearest-site sweep per column band, which
//             holds for sites of equal weight only; here the sites carry
//             their heights Hq_s, so pass 1 is an envelope pass like pass 2.
//             PBA's transposes for coalesced access are not done: the
//             passes read the pixels in place.
// Exactness: every comparison is in int64, no floating point after Hq. The
// parabolas y = (x - a)^2 2^Q + y_a and y = (x - b)^2 2^Q + y_b, a < b, meet
// at x = N / (2^{Q+1} d), N = (b^2 - a^2) 2^Q + y_b - y_a, d = b - a; two
// such points are compared as N1 d2 <= N2 d1 (the common 2^{Q+1} dropped),
// a point and an integer x as N < x d 2^{Q+1}. Bounds, with G <= 2048 =
// 2^11 (kMaxGrid): offsets are below 2^11, their squares below 2^22, h < 2^11
// so Hq <= 2^38; every value y (an Hq, a g, a D) is below
// 2 2^22 2^16 + 2^38 < 2^40; |N| < 2^38 + 2^40 < 2^41; N d < 2^52 and
// x d 2^{Q+1} < 2^39 — all far below 2^63. Ties between sites of equal D go
// to the site of least pixel (u, v), u first (pass 2 keeps the least column,
// pass 1 the least row in it), at every band count and thread count. The
// digital diagram only decides where star splaying starts (ghull.hpp): this
// fixed point cannot change the hull.
//
// ============================================================================
// Stage 2's dual: the working sets
// ============================================================================
// The grid vertices of B's surface are the integer points of [0, G]^3 with a
// coordinate 0 or G. The pixels around vertex V: on every face (axis, side)
// with V_axis = side G, the pixels (u, v) with u in {V_o1 - 1, V_o1} and v in
// {V_o2 - 1, V_o2} within [0, G-1] (o1 < o2 the other axes) — 4 inside a
// face; on a box edge 2 on each of the two faces meeting there (the one
// coordinate at 0 or G leaves one row or column of that face); at a box
// corner 1 on each of the three faces. A vertex whose pixels carry 3 or 4
// distinct labels (kNoSite ignored) is one or two dual triangles (§7.1
// Stage 2): every ordered pair (a, b) of its distinct labels puts b in a's
// working set. As §7.2: a kernel counts each vertex's pairs, a scan places
// them, a second kernel writes them (a << 32 | b), then sort and unique;
// the CSR offsets are lower bounds of p << 32. One thread per (face, vertex
// of that face); a vertex on several faces is taken by its smallest face.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including digital_voronoi.cuh"
#endif

#include <cuda/std/bit>
#include <thrust/binary_search.h>
#include <thrust/fill.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/scan.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/unique.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/elections.cuh"  // dev::atomic_fetch_min
#include "kernels_cuda/hull3/ghull.hpp"
#include "predicates/err_double.hpp"   // FF_HD

namespace flipflop::FF_KERNELS_NS::ghull_detail {

using std::int64_t;
using std::uint32_t;
using std::uint64_t;

constexpr uint32_t kNoSite = ~uint32_t{0};  // a pixel without a site, a label of a face without one
constexpr uint32_t kMaxGrid = 2048;         // the int64 bounds of the header
constexpr int kQ = 16;                      // fractional bits of the squared heights
constexpr int64_t kOne = int64_t{1} << kQ;  // 1 pixel^2 in D's units
// Grains (backend::run_step): below them one thread does the step in the
// OpenMP build. Per point-face or per vertex items are a few operations;
// per band items sweep a band's pixels.
constexpr std::size_t kItemGrain = 4096;
constexpr std::size_t kBandGrain = 1024;  // per (line, band) items: up to kBandLength pixels each
// PBA's band length by default (digital_voronoi's bands = 0): G / 32 bands a
// line, one thread per 32 pixels of a column or row in each step.
constexpr std::uint32_t kBandLength = 32;

// ---- the grid ------------------------------------------------------------------------
// The two axes a face of axis `axis` spans, in increasing order.
FF_HD inline uint32_t first_axis(uint32_t axis) { return axis == 0 ? 1u : 0u; }
FF_HD inline uint32_t second_axis(uint32_t axis) { return axis == 2 ? 1u : 2u; }

// floor(c) clamped to [0, G-1] (c >= 0 truncates to its floor).
FF_HD inline uint32_t cell(double c, uint32_t G) {
  if (!(c > 0)) return 0;
  if (c >= static_cast<double>(G)) return G - 1;
  return static_cast<uint32_t>(c);
}

// A point seen from face f: its pixel (u, v) and its height.
struct OnFace {
  uint32_t u, v;
  double h;
};
FF_HD inline OnFace on_face(const double* P, uint32_t G, uint32_t face) {
  const uint32_t axis = face >> 1;
  const double h = (face & 1u) ? static_cast<double>(G) - P[axis] : P[axis];
  return {cell(P[first_axis(axis)], G), cell(P[second_axis(axis)], G), h};
}

// Hq = round(h^2 2^Q), 0 <= h < 2^11: h^2 2^Q < 2^38, whose ulp is at most
// 2^-15, so adding 1/2 is exact and truncation is the rounding (half up).
FF_HD inline int64_t height_key(double h) {
  const double h2 = h * h;
  return static_cast<int64_t>(h2 * static_cast<double>(kOne) + 0.5);
}

// D of the header: pixel (i, j) of face f to the site of point p.
FF_HD inline int64_t site_distance_at(const double* scaled, uint32_t G, uint32_t face, uint32_t i, uint32_t j,
                                      uint32_t p) {
  const OnFace s = on_face(scaled + 3 * static_cast<std::size_t>(p), G, face);
  const int64_t du = static_cast<int64_t>(i) - s.u, dv = static_cast<int64_t>(j) - s.v;
  return (du * du + dv * dv) * kOne + height_key(s.h);
}
// The same for a pixel index: v G + u within the face (a whole index
// f G^2 + v G + u is read modulo G^2).
FF_HD inline int64_t site_distance(const double* scaled, uint32_t G, uint32_t face, uint32_t pixel, uint32_t p) {
  const uint32_t q = pixel % (G * G);
  return site_distance_at(scaled, G, face, q % G, q / G, p);
}

// ---- project (Algorithm 8) ------------------------------------------------------------
// Item t: point t / 6 onto face t % 6.
struct ProjectHeight {  // lines 4-7: best[pixel] = min of h's bits
  const double* scaled;
  uint32_t G;
  uint64_t* best;
  FF_HD void operator()(uint32_t t) const {
    const uint32_t p = t / 6, f = t % 6;
    const OnFace s = on_face(scaled + 3 * static_cast<std::size_t>(p), G, f);
    const std::size_t px = std::size_t{f} * G * G + std::size_t{s.v} * G + s.u;
    dev::atomic_fetch_min(best + px, cuda::std::bit_cast<uint64_t>(s.h));
  }
};
struct ProjectIndex {  // lines 10-14: sites[pixel] = least index whose h is that minimum
  const double* scaled;
  uint32_t G;
  const uint64_t* best;
  uint32_t* sites;
  FF_HD void operator()(uint32_t t) const {
    const uint32_t p = t / 6, f = t % 6;
    const OnFace s = on_face(scaled + 3 * static_cast<std::size_t>(p), G, f);
    const std::size_t px = std::size_t{f} * G * G + std::size_t{s.v} * G + s.u;
    if (best[px] == cuda::std::bit_cast<uint64_t>(s.h)) dev::atomic_fetch_min(sites + px, p);
  }
};

// ---- envelope ----------------------------------------------------------------------------
// Where the parabolas over positions a < b (values ya, yb) meet: N / (2^{Q+1} d).
struct Meet {
  int64_t num, d;
};
FF_HD inline Meet meet(int64_t a, int64_t ya, int64_t b, int64_t yb) {
  return {(b * b - a * a) * kOne + yb - ya, b - a};
}
FF_HD inline bool not_after(Meet s, Meet t) { return s.num * t.d <= t.num * s.d; }  // s <= t
FF_HD inline bool before(Meet s, int64_t x) { return s.num < x * s.d * (2 * kOne); }  // s < x

// The lower envelope of y = (x - a)^2 2^Q + line.value(a) over the positions
// a in [0, G) with line.has(a), evaluated at x = 0 .. G-1: line.put(x, y, a)
// with a the least parabola there (line.none(x) where the line has none).
// Felzenszwalb–Huttenlocher's stack, with the meeting points compared exactly
// (Meet): the top parabola t leaves the stack when the new one x meets it no
// later than t meets the one below, s (`hidden`: t is least at no point but
// a tie). The stack is then the strict lower hull of the points (a, a^2 2^Q
// + value(a)) — a set that does not depend on the order of the pushes and
// pops that found it —, its meeting points b_0 < b_1 < ... increase
// strictly, and the parabola put at x is stack element k = #{b_i < x}: the
// least at x, a tie going to the smaller position.
//
// PBA's bands [CTMT10] (thesis §7.2): a line is cut into m bands of
// consecutive positions, and each step is one thread per (line, band)
// instead of per line:
//   build  each band's own stack, over its positions only (BandStacks);
//   merge  log2 m rounds; round r merges groups of 2^r bands pairwise
//          (MergeBands): the left group's top leaves while it is hidden by
//          the element below it and the right group's bottom, the right
//          group's bottom leaves while it is hidden by the left's top and
//          the element above it — the lower tangent of two x-separated
//          strictly convex chains (the merge of divide-and-conquer hulls:
//          an element leaves only when it lies on or above a segment
//          between two points of the union, so it is no strict hull vertex
//          of the union; where neither test removes anything, the two ends
//          are both chains' points of tangency). Each band keeps its
//          survivors as the slice [lo, hi) of its own positions' scratch,
//          so the groups' lists are the bands' slices in order, empty ones
//          skipped;
//   color  each band sweeps its own positions (ColorBand), starting from the
//          list element least at its first position x0: the last element at
//          a position <= x0, then back while the element before it meets it
//          at or after x0, forward while the one after it meets it before
//          x0 (k = #{b_i < x0} from any start, b strictly increasing).
// The result is the strict lower hull of the whole line, as one thread's
// stack finds it, so every band count gives the same labels; m = 1 is
// Felzenszwalb–Huttenlocher's single sweep.
FF_HD inline bool hidden(uint32_t s, int64_t ys, uint32_t t, int64_t yt, uint32_t x, int64_t yx) {
  return not_after(meet(t, yt, x, yx), meet(s, ys, t, yt));
}

// m bands of B = ceil(G / m) positions (m clamped to [1, G] and lowered so
// that no band is empty); band b holds positions [b B, min(G, (b + 1) B)).
struct Banding {
  uint32_t G, m, B;
  FF_HD uint32_t begin(uint32_t b) const { return b * B < G ? b * B : G; }
  FF_HD uint32_t end(uint32_t b) const { return (b + 1) * B < G ? (b + 1) * B : G; }
};
inline Banding banding(uint32_t G, uint32_t m) {
  if (m < 1) m = 1;
  if (m > G) m = G;
  const uint32_t B = (G + m - 1) / m;
  return {G, (G + B - 1) / B, B};
}

// The survivors of line `line`'s bands: band b's slice [lo, hi) of the
// line's scratch (positions, increasing), bands in order.
struct BandList {
  const uint32_t* st;  // the line's scratch (G entries)
  const uint32_t* lo;  // the line's m slice starts
  const uint32_t* hi;  // ... and ends
  uint32_t m;
  struct Ref {
    uint32_t band, at;  // at: an index into st within band's slice
  };
  FF_HD bool last_before(uint32_t b, Ref& r) const {  // the last element of bands < b
    for (uint32_t c = b; c-- > 0;)
      if (hi[c] > lo[c]) return r = {c, hi[c] - 1}, true;
    return false;
  }
  FF_HD bool first_from(uint32_t b, uint32_t e, Ref& r) const {  // the first element of bands [b, e)
    for (uint32_t c = b; c < e; ++c)
      if (hi[c] > lo[c]) return r = {c, lo[c]}, true;
    return false;
  }
  FF_HD bool prev(Ref r, Ref& p) const {
    if (r.at > lo[r.band]) return p = {r.band, r.at - 1}, true;
    return last_before(r.band, p);
  }
  FF_HD bool next(Ref r, Ref& n) const {
    if (r.at + 1 < hi[r.band]) return n = {r.band, r.at + 1}, true;
    return first_from(r.band + 1, m, n);
  }
};

// build: item t = line m + b.
template <class Lines>
struct BandStacks {
  Lines lines;
  Banding bd;
  uint32_t* stack;  // G per line
  uint32_t* lo;     // m per line
  uint32_t* hi;
  FF_HD void operator()(uint32_t t) const {
    const uint32_t l = t / bd.m, b = t % bd.m;
    const auto line = lines(l);
    uint32_t* st = stack + std::size_t{l} * bd.G;
    const uint32_t x0 = bd.begin(b), x1 = bd.end(b);
    uint32_t top = x0;
    for (uint32_t x = x0; x < x1; ++x) {
      if (!line.has(x)) continue;
      const int64_t yx = line.value(x);
      while (top - x0 >= 2) {
        const uint32_t u = st[top - 1], s = st[top - 2];
        if (!hidden(s, line.value(s), u, line.value(u), x, yx)) break;
        --top;
      }
      st[top++] = x;
    }
    lo[t] = x0;
    hi[t] = top;
  }
};

// merge, round with groups of `half` bands: item t = line pairs + p merges
// bands [p 2 half, p 2 half + half) with [p 2 half + half, p 2 half + 2 half).
template <class Lines>
struct MergeBands {
  Lines lines;
  Banding bd;
  uint32_t half, pairs;
  const uint32_t* stack;
  uint32_t* lo;
  uint32_t* hi;
  FF_HD void operator()(uint32_t t) const {
    const uint32_t l = t / pairs, s0 = (t % pairs) * 2 * half, mid = s0 + half;
    if (mid >= bd.m) return;
    const uint32_t e = mid + half < bd.m ? mid + half : bd.m;
    const auto line = lines(l);
    uint32_t* L0 = lo + std::size_t{l} * bd.m;
    uint32_t* H0 = hi + std::size_t{l} * bd.m;
    const BandList list{stack + std::size_t{l} * bd.G, L0, H0, bd.m};
    using Ref = BandList::Ref;
    for (;;) {
      Ref a, x;  // the left group's top, the right group's bottom
      bool left = false;
      for (uint32_t c = mid; c-- > s0;)
        if (H0[c] > L0[c]) {
          a = {c, H0[c] - 1}, left = true;
          break;
        }
      if (!left || !list.first_from(mid, e, x)) return;
      const uint32_t pa = list.st[a.at], px = list.st[x.at];
      const int64_t ya = line.value(pa), yx = line.value(px);
      Ref r;
      if (list.prev(a, r) && r.band >= s0) {
        const uint32_t pr = list.st[r.at];
        if (hidden(pr, line.value(pr), pa, ya, px, yx)) {
          --H0[a.band];
          continue;
        }
      }
      if (list.next(x, r) && r.band < e) {
        const uint32_t pr = list.st[r.at];
        if (hidden(pa, ya, px, yx, pr, line.value(pr))) {
          ++L0[x.band];
          continue;
        }
      }
      return;
    }
  }
};

// color: item t = line m + b.
template <class Lines>
struct ColorBand {
  Lines lines;
  Banding bd;
  const uint32_t* stack;
  const uint32_t* lo;
  const uint32_t* hi;
  FF_HD void operator()(uint32_t t) const {
    const uint32_t l = t / bd.m, b = t % bd.m;
    const auto line = lines(l);
    const BandList list{stack + std::size_t{l} * bd.G, lo + std::size_t{l} * bd.m, hi + std::size_t{l} * bd.m, bd.m};
    using Ref = BandList::Ref;
    const uint32_t x0 = bd.begin(b), x1 = bd.end(b);
    Ref k;  // the last element at a position <= x0, else the first one
    bool found = list.hi[b] > list.lo[b] && list.st[list.lo[b]] == x0;
    if (found)
      k = {b, list.lo[b]};
    else
      found = list.last_before(b, k) || list.first_from(b, bd.m, k);
    if (!found) {  // no parabola on the whole line
      for (uint32_t x = x0; x < x1; ++x) line.none(x);
      return;
    }
    uint32_t pk = list.st[k.at];
    int64_t yk = line.value(pk);
    Ref r;
    while (list.prev(k, r)) {  // back while the one before is least at x0 (a tie: the smaller position)
      const uint32_t pr = list.st[r.at];
      const int64_t yr = line.value(pr);
      if (before(meet(pr, yr, pk, yk), x0)) break;
      k = r, pk = pr, yk = yr;
    }
    for (uint32_t x = x0; x < x1; ++x) {
      while (list.next(k, r)) {
        const uint32_t pn = list.st[r.at];
        const int64_t yn = line.value(pn);
        if (!before(meet(pk, yk, pn, yn), x)) break;
        k = r, pk = pn, yk = yn;
      }
      const int64_t dx = static_cast<int64_t>(x) - pk;
      line.put(x, dx * dx * kOne + yk, pk);
    }
  }
};

// Pass 1's line: column u of face f; its parabolas are the sites, value Hq;
// writes g and its site (arg) per row.
struct ColumnLine {
  const double* scaled;
  const uint32_t* sites;
  uint64_t* g;
  uint32_t* arg;
  uint32_t G, f, u;
  FF_HD std::size_t at(uint32_t v) const { return (std::size_t{f} * G + v) * G + u; }
  FF_HD bool has(uint32_t v) const { return sites[at(v)] != kNoSite; }
  FF_HD int64_t value(uint32_t v) const {
    return height_key(on_face(scaled + 3 * static_cast<std::size_t>(sites[at(v)]), G, f).h);
  }
  FF_HD void put(uint32_t j, int64_t y, uint32_t v) const {
    g[at(j)] = static_cast<uint64_t>(y);
    arg[at(j)] = sites[at(v)];
  }
  FF_HD void none(uint32_t j) const { arg[at(j)] = kNoSite; }
};
// Pass 2's line: row j of face f; its parabolas are the columns with a site,
// value g; writes the labels.
struct RowLine {
  const uint64_t* g;
  const uint32_t* arg;
  uint32_t* labels;
  uint32_t G, f, j;
  FF_HD std::size_t at(uint32_t u) const { return (std::size_t{f} * G + j) * G + u; }
  FF_HD bool has(uint32_t u) const { return arg[at(u)] != kNoSite; }
  FF_HD int64_t value(uint32_t u) const { return static_cast<int64_t>(g[at(u)]); }
  FF_HD void put(uint32_t i, int64_t, uint32_t u) const { labels[at(i)] = arg[at(u)]; }
  FF_HD void none(uint32_t i) const { labels[at(i)] = kNoSite; }
};
// Line l = f G + (column u or row j).
struct ColumnLines {
  const double* scaled;
  const uint32_t* sites;
  uint64_t* g;
  uint32_t* arg;
  uint32_t G;
  FF_HD ColumnLine operator()(uint32_t l) const { return {scaled, sites, g, arg, G, l / G, l % G}; }
};
struct RowLines {
  const uint64_t* g;
  const uint32_t* arg;
  uint32_t* labels;
  uint32_t G;
  FF_HD RowLine operator()(uint32_t l) const { return {g, arg, labels, G, l / G, l % G}; }
};

template <class V>
auto* ptr(V& v) {
  return thrust::raw_pointer_cast(v.data());
}

inline void check_grid(std::uint32_t G, const char* who) {
  if (G == 0 || G > kMaxGrid)
    throw std::invalid_argument(std::string(who) + ": grid " + std::to_string(G) + " not in [1, " +
                                std::to_string(kMaxGrid) + "]");
}

// One envelope pass over the 6 G lines of G positions, in m bands per line
// (PBA's build, merge and color steps). stack: G per line; lo, hi: m per
// line (banding(G, m).m).
template <class Lines>
void banded_envelopes(const Lines& lines, const Banding& bd, uint32_t* stack, uint32_t* lo, uint32_t* hi) {
  const std::size_t count = 6 * std::size_t{bd.G}, items = count * bd.m;
  backend::for_range<kBandGrain>(items, BandStacks<Lines>{lines, bd, stack, lo, hi});
  for (uint32_t half = 1; half < bd.m; half *= 2) {
    const uint32_t pairs = (bd.m + 2 * half - 1) / (2 * half);
    backend::for_range<kBandGrain>(count * pairs, MergeBands<Lines>{lines, bd, half, pairs, stack, lo, hi});
  }
  backend::for_range<kBandGrain>(items, ColorBand<Lines>{lines, bd, stack, lo, hi});
}

// Stage 1. scaled: device pointer, 3 doubles per point, every coordinate in
// (0, G); labels, sites: resized to 6 G^2 (pixel index f G^2 + v G + u).
// bands: PBA's bands per line in both passes (0: G / kBandLength; any count
// gives the same labels). Returns the band count used (banding()).
inline std::uint32_t digital_voronoi(const double* scaled, std::uint32_t n, std::uint32_t G,
                                     backend::Buffer<std::uint32_t>& labels, backend::Buffer<std::uint32_t>& sites,
                                     std::uint32_t bands = 0) {
  check_grid(G, "ghull: digital_voronoi");
  const std::size_t P = 6 * std::size_t{G} * G;
  const Banding bd = banding(G, bands ? bands : G / kBandLength);
  labels.resize(P);
  sites.resize(P);
  backend::Buffer<uint64_t> g(P, ~uint64_t{0});  // the projection's minima, then pass 1's g
  backend::Scratch<uint32_t> arg(P), stack(P), lo(6 * std::size_t{G} * bd.m), hi(6 * std::size_t{G} * bd.m);
  backend::run_step_async<kItemGrain>(P, [&](auto policy) {
    thrust::fill(policy, sites.begin(), sites.end(), kNoSite);
  });
  const std::size_t items = 6 * std::size_t{n};
  backend::for_range<kItemGrain>(items, ProjectHeight{scaled, G, ptr(g)});
  backend::for_range<kItemGrain>(items, ProjectIndex{scaled, G, ptr(g), ptr(sites)});
  banded_envelopes(ColumnLines{scaled, ptr(sites), ptr(g), ptr(arg), G}, bd, ptr(stack), ptr(lo), ptr(hi));
  banded_envelopes(RowLines{ptr(g), ptr(arg), ptr(labels), G}, bd, ptr(stack), ptr(lo), ptr(hi));
  return bd.m;
}

// ---- Stage 2's dual ------------------------------------------------------------------------
// Vertex item t = f (G+1)^2 + b (G+1) + a: the point of face f at (a, b) on
// its two axes. Its distinct labels, when face f is the smallest face it lies
// on (else none: another item has it).
struct VertexLabels {
  const uint32_t* labels;
  uint32_t G;
  FF_HD uint32_t operator()(uint32_t t, uint32_t out[4]) const {
    const uint32_t W = G + 1, f = t / (W * W), r = t % (W * W);
    uint32_t V[3];
    V[f >> 1] = (f & 1u) ? G : 0;
    V[first_axis(f >> 1)] = r % W;
    V[second_axis(f >> 1)] = r / W;
    uint32_t d = 0;
    bool owner = true;
    for (uint32_t e = 0; e < 6; ++e) {
      const uint32_t axis = e >> 1;
      if (V[axis] != ((e & 1u) ? G : 0)) continue;
      if (e < f) owner = false;
      const uint32_t a = V[first_axis(axis)], b = V[second_axis(axis)];
      for (uint32_t v = b > 0 ? b - 1 : 0; v <= b && v < G; ++v)
        for (uint32_t u = a > 0 ? a - 1 : 0; u <= a && u < G; ++u) {
          const uint32_t l = labels[(std::size_t{e} * G + v) * G + u];
          if (l == kNoSite) continue;
          bool seen = false;
          for (uint32_t k = 0; k < d; ++k) seen |= out[k] == l;
          if (!seen && d < 4) out[d++] = l;  // at most 4 pixels around a vertex
        }
    }
    return owner ? d : 0;
  }
};
FF_HD inline uint32_t pair_count(uint32_t d) { return d >= 3 ? d * (d - 1) : 0; }

struct CountPairs {
  VertexLabels at;
  uint32_t* count;
  FF_HD void operator()(uint32_t t) const {
    uint32_t l[4];
    count[t] = pair_count(at(t, l));
  }
};
struct WritePairs {
  VertexLabels at;
  const uint32_t* first;
  uint64_t* pairs;
  FF_HD void operator()(uint32_t t) const {
    uint32_t l[4];
    const uint32_t d = at(t, l);
    if (pair_count(d) == 0) return;
    uint64_t* o = pairs + first[t];
    for (uint32_t a = 0; a < d; ++a)
      for (uint32_t b = 0; b < d; ++b)
        if (a != b) *o++ = (uint64_t{l[a]} << 32) | l[b];
  }
};
struct PointKey {  // p << 32: where point p's pairs start
  FF_HD uint64_t operator()(uint64_t p) const { return p << 32; }
};
struct Neighbour {
  FF_HD uint32_t operator()(uint64_t k) const { return static_cast<uint32_t>(k); }
};

// The working sets as CSR over the n points: the neighbours of p are
// nbr[off[p] .. off[p+1]), ascending. labels: device pointer, 6 G^2 entries,
// each a point index below n or kNoSite.
inline void working_sets(const std::uint32_t* labels, std::uint32_t G, std::uint32_t n,
                         backend::Buffer<std::uint32_t>& off, backend::Buffer<std::uint32_t>& nbr) {
  check_grid(G, "ghull: working_sets");
  const std::size_t W = std::size_t{G} + 1, items = 6 * W * W;  // below 2^28 for G <= 2048
  const VertexLabels at{labels, G};
  // counts, then their exclusive scan (count[items] = 0: first[items] is the total)
  backend::Scratch<uint32_t> count(items + 1), first(items + 1);
  backend::run_step_async<kItemGrain>(1, [&](auto policy) {
    thrust::fill(policy, count.begin() + static_cast<std::ptrdiff_t>(items), count.end(), 0u);
  });
  backend::for_range<kItemGrain>(items, CountPairs{at, ptr(count)});
  backend::run_step<kItemGrain>(items, [&](auto policy) {
    thrust::exclusive_scan(policy, count.begin(), count.end(), first.begin());
  });
  // at most 12 pairs per vertex: below 2^32
  const std::size_t total = static_cast<uint32_t>(first[items]);  // a read from the device
  backend::Scratch<uint64_t> pairs(total);
  backend::for_range<kItemGrain>(items, WritePairs{at, ptr(first), ptr(pairs)});
  std::size_t m = 0;
  backend::run_step<kItemGrain>(total, [&](auto policy) {
    thrust::sort(policy, pairs.begin(), pairs.end());
    m = static_cast<std::size_t>(thrust::unique(policy, pairs.begin(), pairs.end()) - pairs.begin());
  });
  off.resize(std::size_t{n} + 1);
  nbr.resize(m);
  const auto keys = thrust::make_transform_iterator(thrust::counting_iterator<uint64_t>(0), PointKey{});
  backend::run_step<kItemGrain>(m + n, [&](auto policy) {
    thrust::lower_bound(policy, pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(m), keys,
                        keys + (static_cast<std::ptrdiff_t>(n) + 1), off.begin());
    thrust::transform(policy, pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(m), nbr.begin(), Neighbour{});
  });
}

}  // namespace flipflop::FF_KERNELS_NS::ghull_detail

#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
// ghull.hpp's test entries (the OpenMP build: Buffer is std::vector, and the
// host's arrays are the device's); defined by their qualified names, so that
// they must match the declarations.
namespace flipflop::FF_KERNELS_NS::ghull_detail {

inline std::uint32_t scaled_count(const std::vector<double>& scaled, const char* who) {
  if (scaled.size() % 3 != 0 || scaled.size() / 3 >= kNoSite)
    throw std::invalid_argument(std::string(who) + ": scaled holds " + std::to_string(scaled.size()) +
                                " doubles, not 3 per point");
  return static_cast<std::uint32_t>(scaled.size() / 3);
}

}  // namespace flipflop::FF_KERNELS_NS::ghull_detail

namespace flipflop::FF_KERNELS_NS {

std::vector<std::uint32_t> ghull_stages::digital_voronoi(const std::vector<double>& scaled, std::uint32_t grid,
                                                         std::vector<std::uint32_t>* sites, std::uint32_t bands) {
  const std::uint32_t n = ghull_detail::scaled_count(scaled, "ghull_stages::digital_voronoi");
  std::vector<std::uint32_t> labels, s;
  ghull_detail::digital_voronoi(scaled.data(), n, grid, labels, s, bands);
  if (sites) *sites = std::move(s);
  return labels;
}

std::int64_t ghull_stages::site_distance(const std::vector<double>& scaled, std::uint32_t grid, std::uint32_t face,
                                         std::uint32_t pixel, std::uint32_t p) {
  const std::uint32_t n = ghull_detail::scaled_count(scaled, "ghull_stages::site_distance");
  ghull_detail::check_grid(grid, "ghull_stages::site_distance");
  if (face >= 6 || p >= n) throw std::invalid_argument("ghull_stages::site_distance: face or point out of range");
  return ghull_detail::site_distance(scaled.data(), grid, face, pixel, p);
}

void ghull_stages::working_sets(const std::vector<std::uint32_t>& labels, std::uint32_t grid, std::uint32_t n,
                                std::vector<std::uint32_t>& off, std::vector<std::uint32_t>& nbr) {
  ghull_detail::check_grid(grid, "ghull_stages::working_sets");
  if (labels.size() != 6 * std::size_t{grid} * grid)
    throw std::invalid_argument("ghull_stages::working_sets: labels must hold 6 grid^2 entries");
  ghull_detail::working_sets(labels.data(), grid, n, off, nbr);
}

}  // namespace flipflop::FF_KERNELS_NS
#endif

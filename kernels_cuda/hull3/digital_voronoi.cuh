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
//             transform, and so does this, exactly: pass 1, one thread per
//             (face, column u): g(u, j) = min over the column's sites of
//             (j - v_s)^2 2^Q + Hq_s and its site, for every row j; pass 2,
//             one thread per (face, row j): label(i, j) = the site of
//             min over columns u of (i - u)^2 2^Q + g(u, j) (columns without
//             a site skipped). min over all sites = min over columns of the
//             min within the column, so the two passes give the least D.
//             Each pass is a 1D lower envelope of parabolas
//             (Felzenszwalb–Huttenlocher): a stack of the parabolas that are
//             least somewhere, then a sweep over the positions. PBA's bands
//             (a row split among threads, merged afterwards) and its
//             transposes for coalesced access are not done: one thread per
//             line, its stack a slice of a preallocated buffer.
// Exactness: every comparison is in int64, no floating point after Hq. The
// parabolas y = (x - a)^2 2^Q + y_a and y = (x - b)^2 2^Q + y_b, a < b, meet
// at x = N / (2^{Q+1} d), N = (b^2 - a^2) 2^Q + y_b - y_a, d = b - a; two
// such points are compared as N1 d2 <= N2 d1 (the common 2^{Q+1} dropped),
// a point and an integer x as N < x d 2^{Q+1}. Bounds, with G <= 2048 =
// 2^11 (kMaxGrid): offsets are below 2^11, their squares below 2^22, h < 2^11
// so Hq <= 2^38; every value y (an Hq, a g, a D) is below
// 2 2^22 2^16 + 2^38 < 2^40; |N| < 2^38 + 2^40 < 2^41; N d < 2^52 and
// x d 2^{Q+1} < 2^39 — all far below 2^63. Ties between sites of equal D go
// to one of them, the same on every run (each line is one thread's
// sequential sweep). The digital diagram only decides where star splaying
// starts (ghull.hpp): this fixed point cannot change the hull.
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
// per line items sweep G pixels (twice).
constexpr std::size_t kItemGrain = 4096;
constexpr std::size_t kLineGrain = 256;

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
// stack: G entries of scratch. Felzenszwalb–Huttenlocher, with the meeting
// points compared exactly (Meet): the top parabola leaves the stack when the
// new one meets it no later than it meets the one below (it is least at no
// point but a tie); the stack's meeting points then increase strictly and
// the sweep moves up at each one it passes.
template <class Line>
FF_HD void lower_envelope(const Line& line, uint32_t G, uint32_t* stack) {
  uint32_t m = 0;
  for (uint32_t x = 0; x < G; ++x) {
    if (!line.has(x)) continue;
    const int64_t yx = line.value(x);
    while (m >= 2) {
      const uint32_t t = stack[m - 1], s = stack[m - 2];
      const int64_t yt = line.value(t);
      if (!not_after(meet(t, yt, x, yx), meet(s, line.value(s), t, yt))) break;
      --m;
    }
    stack[m++] = x;
  }
  if (m == 0) {
    for (uint32_t x = 0; x < G; ++x) line.none(x);
    return;
  }
  uint32_t k = 0;
  int64_t yk = line.value(stack[0]);
  for (uint32_t x = 0; x < G; ++x) {
    while (k + 1 < m) {
      const int64_t yn = line.value(stack[k + 1]);
      if (!before(meet(stack[k], yk, stack[k + 1], yn), x)) break;
      ++k, yk = yn;
    }
    const int64_t dx = static_cast<int64_t>(x) - stack[k];
    line.put(x, dx * dx * kOne + yk, stack[k]);
  }
}

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
// Item t = f G + line.
struct Columns {
  const double* scaled;
  const uint32_t* sites;
  uint64_t* g;
  uint32_t* arg;
  uint32_t* stack;
  uint32_t G;
  FF_HD void operator()(uint32_t t) const {
    lower_envelope(ColumnLine{scaled, sites, g, arg, G, t / G, t % G}, G, stack + std::size_t{t} * G);
  }
};
struct Rows {
  const uint64_t* g;
  const uint32_t* arg;
  uint32_t* labels;
  uint32_t* stack;
  uint32_t G;
  FF_HD void operator()(uint32_t t) const {
    lower_envelope(RowLine{g, arg, labels, G, t / G, t % G}, G, stack + std::size_t{t} * G);
  }
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

// Stage 1. scaled: device pointer, 3 doubles per point, every coordinate in
// (0, G); labels, sites: resized to 6 G^2 (pixel index f G^2 + v G + u).
inline void digital_voronoi(const double* scaled, std::uint32_t n, std::uint32_t G,
                            backend::Buffer<std::uint32_t>& labels, backend::Buffer<std::uint32_t>& sites) {
  check_grid(G, "ghull: digital_voronoi");
  const std::size_t P = 6 * std::size_t{G} * G;
  labels.resize(P);
  sites.resize(P);
  backend::Buffer<uint64_t> g(P, ~uint64_t{0});  // the projection's minima, then pass 1's g
  backend::Scratch<uint32_t> arg(P), stack(P);
  backend::run_step_async<kItemGrain>(P, [&](auto policy) {
    thrust::fill(policy, sites.begin(), sites.end(), kNoSite);
  });
  const std::size_t items = 6 * std::size_t{n};
  backend::for_range<kItemGrain>(items, ProjectHeight{scaled, G, ptr(g)});
  backend::for_range<kItemGrain>(items, ProjectIndex{scaled, G, ptr(g), ptr(sites)});
  backend::for_range<kLineGrain>(6 * std::size_t{G}, Columns{scaled, ptr(sites), ptr(g), ptr(arg), ptr(stack), G});
  backend::for_range<kLineGrain>(6 * std::size_t{G}, Rows{ptr(g), ptr(arg), ptr(labels), ptr(stack), G});
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
                                                         std::vector<std::uint32_t>* sites) {
  const std::uint32_t n = ghull_detail::scaled_count(scaled, "ghull_stages::digital_voronoi");
  std::vector<std::uint32_t> labels, s;
  ghull_detail::digital_voronoi(scaled.data(), n, grid, labels, s);
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

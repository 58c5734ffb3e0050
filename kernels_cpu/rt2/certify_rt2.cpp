// certify_rt2.cpp — certify::rt2 with parallel checks, and the certifier of
// the kernel's own output from its witness (certify_rt2.hpp).
//
// Why the witnessed checks suffice. Positions are a permutation of the input
// (witness-points), so every position is one input point with its own SoS
// index, and every input point is either a vertex of a real triangle or a
// missing point with a witness triangle (each position passes one of the two
// tests). Let T be the real triangles, all counter-clockwise under SoS, i.e.
// of positive area in the perturbed configuration at every small enough ε >
// 0 (EM90: SoS answers are the signs of one real configuration in general
// position, in which we argue from here on).
//   1. T covers conv(S) exactly once. The links pair every real edge a -> b
//      that is not a hull edge with the reversed edge b -> a of another real
//      triangle (neighbour-links: symmetric, so the pairing is an
//      involution), so as 1-chains the boundaries of the triangles sum to
//      the cycle C of hull edges. The winding number around a point y on no
//      edge is additive over 1-chains, and a positive triangle's boundary
//      winds once around y inside it and zero times outside, so the number of
//      triangles of T containing y equals wind(C, y). C is one closed convex
//      polygon, counter-clockwise and winding once, whose region is conv(S)
//      (boundary, boundary-is-hull: certify::hull2), so every y of conv(S)
//      (off the edges) lies in exactly one triangle and none outside it.
//      Hence the triangles have disjoint interiors and their union is conv(S);
//      in general position no vertex lies inside another edge and no two
//      edges overlap, so any two triangles meet in a common edge, a common
//      vertex or not at all: T is a triangulation of conv(S) whose vertex set
//      is the set of vertex positions. (The fan checks, vertex-fan, are
//      implied by this; they are kept as the structural check that every
//      corner belongs to the one fan of its vertex — so that a point named
//      missing is no corner — and are link reads only, no predicate.)
//   2. Thm 2.2 [ES92] (thesis; certify.hpp): a triangulation of a point set
//      whose edges are all locally regular is its regular triangulation.
//      locally-regular tests each interior edge once, by the power test of
//      the neighbour's opposite vertex against the triangle's power circle
//      (the lifted quadrilateral is convex at the edge iff that vertex's
//      lifted point is above the triangle's lifted plane).
//   3. Every missing point p lies in its witness triangle (3 orient, SoS) and
//      its lifted point is not below (canonical: strictly above) that
//      triangle's lifted plane, i.e. above the lower hull of the lifted
//      vertices at p: p is redundant, and adding redundant points does not
//      change the lower hull, so T is RT(S ⊕ W) — at Level::canonical, with
//      every test strict under SoS, the unique one of the perturbed points,
//      which is the canonical answer (DESIGN.md).
//   4. canonical-output: every witnessed triangle, mapped to input indices and
//      rotated to its smallest index, is a triangle of `tris`; `tris` has no
//      repeated triangle and as many as T (whose triangles are distinct: they
//      cover each point once), so they are the same set.
// Per point and per edge: one orient per real triangle, one power test per
// interior edge, 3 orient and 1 power per missing point, a constant number of
// link reads per corner, one lookup of the output per triangle; the hull's
// check (certify::hull2) is one orient per input point.
#include "kernels_cpu/rt2/certify_rt2.hpp"

#include <algorithm>
#include <atomic>
#include <string>

#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/witnessed_output.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/dimension.hpp"

namespace flipflop::cpu {

certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level, int threads) {
  return certify_in_parallel(ps, threads, [&](const certify::Speedups& s) { return certify::rt2(ps, tris, level, s); });
}

namespace {

using certify::Report;
using certify::detail::smallest_failing;
using certify::detail::tri_str;
constexpr std::uint32_t kNo = Rt2Witness::kNoSlot;

// half-edge e = 3t + i: opposite corner i, from corner i + 1 to corner i + 2
inline std::uint32_t nx(std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::uint32_t pv(std::uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

struct Witnessed {
  const PointSet& ps;
  const Rt2Witness& w;
  const pred::StaticFilter& f;  // over the input's coordinates and weights
  bool canonical;
  std::uint32_t n;  // the number of points, also the virtual vertex
  std::size_t slots;

  pred::Pt pt(std::uint32_t k) const { return {w.pts[k].id, w.pts[k].xy}; }
  pred::WPt wpt(std::uint32_t k) const { return {w.pts[k].id, w.pts[k].xy, w.pts[k].w}; }
  const std::uint32_t* corners(std::size_t t) const { return &w.tv[3 * t]; }
  // The predicates as in the kernel: the per-call semi-static filter first
  // (the points of a triangle and its neighbours are much closer to each
  // other than the input's extent, so the per-input static bound rarely
  // decides), then the staged exact path with SoS (predicates.hpp).
  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const double* p[3] = {w.pts[a].xy, w.pts[b].xy, w.pts[c].xy};
    if (const int s = pred::semi_static_sign<3>(p, nullptr)) return s;
    return pred::orient2d(f, pt(a), pt(b), pt(c));
  }
  // > 0 when d's lifted point is strictly below the lifted plane of the
  // counter-clockwise (a, b, c); perturbed at the canonical level, exact at
  // the exact level
  int power(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
    const double* p[4] = {w.pts[a].xy, w.pts[b].xy, w.pts[c].xy, w.pts[d].xy};
    const double wt[4] = {w.pts[a].w, w.pts[b].w, w.pts[c].w, w.pts[d].w};
    if (const int s = pred::semi_static_sign<4>(p, wt)) return s;
    if (canonical) return pred::power2d(f, wpt(a), wpt(b), wpt(c), wpt(d));
    return pred::power2d_exact(wpt(a), wpt(b), wpt(c), wpt(d));
  }
  bool irregular(int s) const { return canonical ? s >= 0 : s > 0; }
  bool used(std::size_t t) const { return w.tv[3 * t] != kNo; }
  bool real(std::size_t t) const {
    const std::uint32_t* c = corners(t);
    return c[0] != kNo && c[0] != n && c[1] != n && c[2] != n;
  }
  // position k is a vertex: its `at` is a real triangle with k as a corner
  bool vertex(std::uint32_t k) const {
    const std::uint32_t t = w.at[k];
    if (t >= slots || !real(t)) return false;
    const std::uint32_t* c = corners(t);
    return c[0] == k || c[1] == k || c[2] == k;
  }
  Triangle ids(std::size_t t) const {
    const std::uint32_t* c = corners(t);
    return {w.pts[c[0]].id, w.pts[c[1]].id, w.pts[c[2]].id};
  }
  std::string tri(std::size_t t) const { return tri_str(ids(t)); }
  std::string point(std::uint32_t k) const { return "point " + std::to_string(w.pts[k].id); }

  // The triangles around vertex k, from w.at[k] through the links of the
  // edges at k: their number, closed = true for a cycle; for a path, its
  // ends are hull edges. 0 when the walk does not end (links not symmetric).
  std::size_t fan(std::uint32_t k, bool& closed) const {
    const std::uint32_t t0 = w.at[k];
    const std::uint32_t* c = corners(t0);
    const std::uint32_t j0 = c[0] == k ? 0 : c[1] == k ? 1 : 2;
    std::size_t count = 1;
    // one way: across the edge into k (opposite corner j + 1), k is the
    // corner after the twin's source
    for (std::uint32_t t = t0, j = j0; count <= slots;) {
      const std::uint32_t f = w.tn[3 * t + (j + 1) % 3];
      if (!real(f / 3)) break;
      t = f / 3, j = (f % 3 + 1) % 3;
      if (t == t0) {
        closed = true;
        return count;
      }
      ++count;
    }
    closed = false;
    // the other way: across the edge out of k (opposite corner j + 2)
    for (std::uint32_t t = t0, j = j0; count <= slots;) {
      const std::uint32_t f = w.tn[3 * t + (j + 2) % 3];
      if (!real(f / 3)) return count;
      t = f / 3, j = (f % 3 + 2) % 3;
      ++count;
    }
    return 0;
  }
};

Report certify_witnessed(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                         const Rt2Witness& w) {
  if (ps.dim != 2) return Report::fail("input-dimension", "rt2 needs 2D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  auto for_range = [](std::size_t m, const std::function<void(std::size_t, std::size_t)>& body) {
    par_for(m, kChunk, body);
  };
  const pred::StaticFilter filter = parallel_static_filter(ps, {});
  const Witnessed W{ps, w, filter, level == certify::Level::canonical, static_cast<std::uint32_t>(n), w.tv.size() / 3};
  const std::size_t slots = W.slots;

  // witness-size, witness-points, triangle-indices (witnessed_output.hpp)
  if (auto bad = witness_problem<3>(ps, w.pts, w.at, w.tv, w.tn, kNo, "triangles", "triangle-indices",
                                     [](const Rt2Point& q) { return q.xy; }, for_range))
    return *bad;

  // The per-triangle conditions in one pass over fixed chunks of slots (each
  // slot's points are read once: the passes are memory-bound), each
  // recording its smallest failing slot; a slot failing one condition is not
  // tested for the later ones, so a condition's smallest failing slot is exact
  // whenever no earlier condition failed anywhere — the first condition
  // reported is the sequential scan's. The same pass counts the real
  // triangles, collects the hull edges and gathers the triangles in canonical
  // form (input indices rotated to the smallest), bucketed by that index for
  // the output check at the end.
  //   triangle-orientation, neighbour-links (the edge from corner i + 1 to
  //   i + 2 of t is, in its twin f, the edge from corner f + 2 to f + 1),
  //   vertex-fan (each corner is a vertex), locally-regular (Thm 2.2: each
  //   interior edge once, from its half-edge e smaller than its twin f; d =
  //   the corner of f's triangle opposite f).
  enum { kOrient, kLinks, kCorners, kRegular, kSlotConditions };
  std::atomic<std::size_t> first_bad[kSlotConditions];
  for (auto& x : first_bad) x.store(slots);
  auto record = [&](int cond, std::size_t t) {
    std::size_t cur = first_bad[cond].load(std::memory_order_relaxed);
    while (t < cur && !first_bad[cond].compare_exchange_weak(cur, t)) {
    }
  };
  auto bad_link = [&](std::size_t t, int i) {
    const std::uint32_t e = static_cast<std::uint32_t>(3 * t) + static_cast<std::uint32_t>(i), f = w.tn[e];
    if (f >= 3 * slots || !W.used(f / 3)) return true;
    if (!W.real(f / 3)) return false;  // a hull edge
    return w.tn[f] != e || w.tv[nx(f)] != w.tv[pv(e)] || w.tv[pv(f)] != w.tv[nx(e)];
  };
  auto irregular_edge = [&](std::size_t t, int i) {
    const std::uint32_t e = static_cast<std::uint32_t>(3 * t) + static_cast<std::uint32_t>(i), f = w.tn[e];
    if (f < e || !W.real(f / 3)) return false;
    const std::uint32_t* c = W.corners(t);
    return W.irregular(W.power(c[0], c[1], c[2], w.tv[f]));
  };
  auto canonical_ids = [&](std::size_t t) {
    Triangle x = W.ids(t);
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    return x;
  };
  // buckets of the output check: at most 4097 ranges of 2^shift indices
  int shift = 0;
  while ((n >> shift) > 4096) ++shift;
  const std::size_t B = (n >> shift) + 1;
  auto bucket = [&](Index m) { return static_cast<std::size_t>(m >> shift); };
  const std::size_t per = std::max<std::size_t>(kChunk, (slots + 63) / 64), chunks = (slots + per - 1) / per;
  std::vector<std::size_t> pos(chunks * B, 0);  // pos[c * B + b]: counts, then write positions
  std::vector<std::vector<Triangle>> part(chunks);
  std::vector<std::vector<std::uint32_t>> hull_part(chunks);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t ch = lo; ch < hi; ++ch)
      for (std::size_t t = ch * per; t < std::min(slots, (ch + 1) * per); ++t) {
        if (!W.real(t)) continue;
        const std::uint32_t* c = W.corners(t);
        if (W.orient(c[0], c[1], c[2]) <= 0) {
          record(kOrient, t);
          continue;
        }
        if (bad_link(t, 0) || bad_link(t, 1) || bad_link(t, 2)) {
          record(kLinks, t);
          continue;
        }
        if (!(W.vertex(c[0]) && W.vertex(c[1]) && W.vertex(c[2]))) {
          record(kCorners, t);
          continue;
        }
        if (irregular_edge(t, 0) || irregular_edge(t, 1) || irregular_edge(t, 2)) record(kRegular, t);
        for (std::uint32_t i = 0; i < 3; ++i)
          if (!W.real(w.tn[3 * t + i] / 3)) hull_part[ch].push_back(static_cast<std::uint32_t>(3 * t) + i);
        const Triangle x = canonical_ids(t);
        part[ch].push_back(x);
        ++pos[ch * B + bucket(x[0])];
      }
  });
  if (const std::size_t t = first_bad[kOrient].load(); t < slots)
    return Report::fail("triangle-orientation", "triangle " + W.tri(t) + " is clockwise");
  if (const std::size_t t = first_bad[kLinks].load(); t < slots) {
    int i = 0;
    while (!bad_link(t, i)) ++i;
    const std::uint32_t* c = W.corners(t);
    return Report::fail("neighbour-links", "edge " + certify::detail::edge_str(w.pts[c[(i + 1) % 3]].id,
                                                                                w.pts[c[(i + 2) % 3]].id) +
                                               " of triangle " + W.tri(t) +
                                               " is not linked to the same edge, reversed, of a triangle linked back");
  }
  if (const std::size_t t = first_bad[kCorners].load(); t < slots) {
    const std::uint32_t* c = W.corners(t);
    const std::uint32_t k = W.vertex(c[0]) ? (W.vertex(c[1]) ? c[2] : c[1]) : c[0];
    return Report::fail("vertex-fan", W.point(k) + " is a corner of triangle " + W.tri(t) +
                                          " but its witness triangle does not have it as a corner");
  }
  std::size_t real_triangles = 0;
  for (const auto& x : part) real_triangles += x.size();

  // The per-point conditions in one pass: vertex-fan (one fan per vertex,
  // the fans' sizes adding up to the number of corners) and, for the other
  // points, missing-point-witness and missing-point-redundant (in their
  // witness triangle under SoS, redundant there), reported in that order
  // after the hull's conditions and local regularity.
  std::atomic<std::size_t> fans{0}, first_open{n}, first_missing{n};
  auto outside_witness = [&](std::uint32_t k) {
    const std::uint32_t t = w.at[k];
    if (t >= slots || !W.real(t)) return true;
    const std::uint32_t* c = W.corners(t);
    return W.orient(c[0], c[1], k) <= 0 || W.orient(c[1], c[2], k) <= 0 || W.orient(c[2], c[0], k) <= 0;
  };
  auto not_redundant = [&](std::uint32_t k) {
    const std::uint32_t* c = W.corners(w.at[k]);
    return W.irregular(W.power(c[0], c[1], c[2], k));
  };
  auto record_point = [&](std::atomic<std::size_t>& first, std::size_t k) {
    std::size_t cur = first.load(std::memory_order_relaxed);
    while (k < cur && !first.compare_exchange_weak(cur, k)) {
    }
  };
  par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
    std::size_t count = 0;
    for (std::size_t k = lo; k < hi; ++k) {
      const std::uint32_t v = static_cast<std::uint32_t>(k);
      if (W.vertex(v)) {
        bool closed = false;
        const std::size_t c = W.fan(v, closed);
        if (c == 0) record_point(first_open, k);
        count += c;
      } else if (outside_witness(v) || not_redundant(v)) {
        record_point(first_missing, k);
      }
    }
    fans.fetch_add(count, std::memory_order_relaxed);
  });
  if (const std::size_t k = first_open.load(); k < n)
    return Report::fail("vertex-fan", "the triangles around " + W.point(static_cast<std::uint32_t>(k)) +
                                          " do not end: the links around it are not a fan");
  if (fans.load() != 3 * real_triangles)
    return Report::fail("vertex-fan", "the fans of the vertices hold " + std::to_string(fans.load()) + " of the " +
                                          std::to_string(3 * real_triangles) +
                                          " corners of the triangles: some vertex has more than one fan");

  // boundary: the hull edges (real triangles' edges linked into virtual
  // triangles), one outgoing per vertex, one cycle through all of them
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;  // (source, target) positions
  for (const auto& h : hull_part)
    for (std::uint32_t e : h) out.emplace_back(w.tv[nx(e)], w.tv[pv(e)]);
  if (out.size() < 3) return Report::fail("boundary", "the triangles have no boundary cycle");
  std::sort(out.begin(), out.end());
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i].first == out[i - 1].first)
      return Report::fail("boundary", "the boundary passes twice through " + W.point(out[i].first));
  std::vector<Index> cycle;
  for (std::uint32_t v = out[0].first; cycle.size() <= out.size();) {
    cycle.push_back(w.pts[v].id);
    const auto it = std::lower_bound(out.begin(), out.end(), std::make_pair(v, std::uint32_t{0}));
    if (it == out.end() || it->first != v) return Report::fail("boundary", "the boundary ends at " + W.point(v));
    v = it->second;
    if (v == out[0].first) break;
  }
  if (cycle.size() != out.size())
    return Report::fail("boundary", "the boundary edges form more than one cycle (holes or several pieces)");
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  {
    certify::Speedups s;
    s.filter = &filter;
    s.for_range = for_range;
    if (Report r = certify::hull2(ps, cycle, level, s); !r.ok)
      return Report::fail("boundary-is-hull", "the boundary is not the convex hull: " + r.message());
  }

  if (const std::size_t t = first_bad[kRegular].load(); t < slots) {
    int i = 0;
    while (!irregular_edge(t, i)) ++i;
    const std::uint32_t* c = W.corners(t);
    return Report::fail("locally-regular",
                        "edge " + certify::detail::edge_str(w.pts[c[(i + 1) % 3]].id, w.pts[c[(i + 2) % 3]].id) +
                            " is not locally regular: " + W.point(w.tv[w.tn[3 * t + static_cast<std::size_t>(i)]]) +
                            (W.canonical ? " is not strictly outside" : " is strictly inside") +
                            " the power circle of " + W.tri(t));
  }

  if (const std::size_t k = first_missing.load(); k < n) {
    const std::uint32_t v = static_cast<std::uint32_t>(k);
    if (outside_witness(v))
      return Report::fail("missing-point-witness", W.point(v) + " is not a vertex and " +
                                                       (w.at[v] < slots && W.real(w.at[v])
                                                            ? "does not lie in its witness triangle " + W.tri(w.at[v])
                                                            : std::string("has no real witness triangle")) +
                                                       (W.canonical ? " under the perturbation" : " (SoS)"));
    return Report::fail("missing-point-redundant",
                        W.point(v) + " is not a vertex but is not redundant: its lifted point is " +
                            (W.canonical ? "not strictly above" : "strictly below") + " the lifted triangle " +
                            W.tri(w.at[v]));
  }

  // canonical-output: tris is the set of the witnessed triangles
  if (std::string why = certify::detail::check_triangle_indices(tris, n, for_range); !why.empty())
    return Report::fail("canonical-output", why);
  std::vector<Triangle> sorted;
  const std::vector<Triangle>* out_tris = &tris;
  if (std::string why = certify::detail::check_canonical_triangles(tris, for_range); !why.empty()) {
    if (W.canonical) return Report::fail("canonical-output", why);
    // the exact level takes any rotation and order: compare in canonical form
    sorted = tris;
    par_for(sorted.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i)
        std::rotate(sorted[i].begin(), std::min_element(sorted[i].begin(), sorted[i].end()), sorted[i].end());
    });
    par_sort(sorted, [](const Triangle& a, const Triangle& b) { return a < b; });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i] == sorted[i - 1])
        return Report::fail("canonical-output", "triangle " + tri_str(sorted[i]) + " is repeated");
    out_tris = &sorted;
  }
  const std::vector<Triangle>& T = *out_tris;
  if (T.size() != real_triangles)
    return Report::fail("canonical-output", "the output has " + std::to_string(T.size()) + " triangles, the witness " +
                                                std::to_string(real_triangles));
  // every witnessed triangle is in the output, bucketed by smallest index
  // (witnessed_output.hpp)
  if (const std::size_t t = first_unwitnessed_slot(
          n, T, part, pos, B, bucket, slots, for_range, [&](std::size_t t) { return W.real(t); }, canonical_ids);
      t < slots)
    return Report::fail("canonical-output", "triangle " + W.tri(t) + " of the witness is not in the output");
  return Report::pass();
}

}  // namespace

certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                            const Rt2Witness& witness, int threads) {
  certify::Report r;
  with_threads(threads, [&] { r = certify_witnessed(ps, tris, level, witness); });
  return r;
}

}  // namespace flipflop::cpu

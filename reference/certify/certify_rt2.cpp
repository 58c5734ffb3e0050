// certify_rt2.cpp — exact certification of a 2D regular (weighted Delaunay)
// triangulation.
//
// Conditions, in order (the first violated one is reported):
//   input-dimension        the points span the plane
//   triangle-indices       indices in range, three distinct per triangle
//   canonical-form         (canonical) rotation and order of DESIGN.md
//   triangle-orientation   every triangle is counter-clockwise (perturbed, so
//                          flat triangles that the perturbation creates on
//                          collinear input are decided consistently)
//   edge-manifold          every directed edge appears once
//   boundary               the edges without twin form one closed cycle
//   boundary-is-hull       that cycle is the convex hull of all input points
//                          (certified by the hull2 certifier)
//   vertex-fan             the triangles around each vertex form one fan: a
//                          cycle winding exactly once around an interior
//                          vertex, a path that does not wrap around a boundary
//                          vertex
//   euler-characteristic   V - E + F = 1 (a disk) and one component
//   locally-regular        every interior edge is locally regular (Thm 2.2):
//                          the opposite vertex is not strictly inside the power
//                          circle; canonical: strictly outside, perturbed
//   missing-point-redundant every input point that is not a vertex is
//                          redundant: its lifted point is on or above the lifted
//                          triangle containing it; canonical: strictly above
// With all triangles positive, one fan per vertex and the boundary mapped onto
// the hull boundary, the triangles cover conv(S) exactly once (a local
// homeomorphism of a disk onto a convex region that is one-to-one on the
// boundary). Thm 2.2 then makes it the regular triangulation of its vertices,
// and the last condition extends that to all of S.
// The checks run through Speedups::for_range where they are per element (the
// triangles, the vertices, the missing points), each reporting the failing
// element the sequential scan meets first (detail::smallest_failing); the
// combinatorial tables (VertexLinks: the triangles around each vertex, which
// also hold the directed edges; the triangle across each edge; the
// components) are built through it too. Predicates: the per-input static
// filter (predicates/fast.hpp) in front of the perturbed predicates and of
// power2d_exact; it decides only exactly non-zero signs, so the answers are
// the same.
#include <algorithm>
#include <cmath>

#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/dimension.hpp"

namespace flipflop::certify {

namespace {
using detail::edge_str;
using detail::kNoTriangle;
using detail::tri_str;

constexpr Index kNoVertex = ~Index{0};

struct Rt2Checker {
  const PointSet& ps;
  bool canonical;
  const pred::StaticFilter& f;  // over the coordinates and the weights

  const double* P(Index i) const { return ps.point(i); }
  pred::WPt W(Index i) const { return {i, P(i), ps.weight(i)}; }
  int orient_sos(Index a, Index b, Index c) const { return pred::fast::orient2d(f, {a, P(a)}, {b, P(b)}, {c, P(c)}); }
  // > 0 when d is strictly inside the power circle of the counter-clockwise
  // triangle t (d's lifted point strictly below the lifted plane of t)
  int power(const Triangle& t, Index d) const {
    if (canonical) return pred::fast::power2d(f, W(t[0]), W(t[1]), W(t[2]), W(d));
    const double* p[4] = {P(t[0]), P(t[1]), P(t[2]), P(d)};
    const double w[4] = {ps.weight(t[0]), ps.weight(t[1]), ps.weight(t[2]), ps.weight(d)};
    if (const int s = pred::static_sign<4>(f, p, w)) return s;
    return pred::power2d_exact(W(t[0]), W(t[1]), W(t[2]), W(d));
  }
  // p inside t under the perturbation (p is not a vertex of t)
  bool inside_sos(const Triangle& t, Index p) const {
    return orient_sos(t[0], t[1], p) > 0 && orient_sos(t[1], t[2], p) > 0 && orient_sos(t[2], t[0], p) > 0;
  }
  // t has non-zero area and its closed region contains p, exactly
  bool inside_exact(const Triangle& t, Index p) const {
    return pred::orient2d_exact(P(t[0]), P(t[1]), P(t[2])) > 0 && pred::orient2d_exact(P(t[0]), P(t[1]), P(p)) >= 0 &&
           pred::orient2d_exact(P(t[1]), P(t[2]), P(p)) >= 0 && pred::orient2d_exact(P(t[2]), P(t[0]), P(p)) >= 0;
  }
};

// Where a point-location walk starts: a kSide x kSide grid over the bounding
// box of the input, each cell holding a triangle whose centroid falls into it
// (empty cells: the previous filled cell's). Floating point throughout — a
// hint, never a decision: the walk from any triangle finds the same triangle,
// a near start only makes it short.
class StartTable {
 public:
  static constexpr int kSide = 256;
  StartTable(const PointSet& ps, const std::vector<Triangle>& tris) {
    lo_[0] = hi_[0] = ps.point(0)[0], lo_[1] = hi_[1] = ps.point(0)[1];
    for (std::size_t i = 0; i < ps.size(); ++i)
      for (int j = 0; j < 2; ++j) lo_[j] = std::min(lo_[j], ps.point(i)[j]), hi_[j] = std::max(hi_[j], ps.point(i)[j]);
    // a sample of the triangles, about 4 per cell, is enough for a hint
    const std::size_t cells = std::size_t{kSide} * kSide;
    cell_ = detail::start_cells(cells, ps, tris, std::max<std::size_t>(1, tris.size() / (4 * cells)),
                                [&](const double* c) { return cell(c); });
  }
  std::uint32_t hint(const double* p) const { return cell_[cell(p)]; }

 private:
  std::size_t cell(const double* p) const {
    std::size_t c[2];
    for (int j = 0; j < 2; ++j) {
      const double t = (p[j] - lo_[j]) / (hi_[j] - lo_[j]);  // NaN when the span is 0 or overflows
      c[j] = t >= 0 ? static_cast<std::size_t>(std::min(t, 1.0) * (kSide - 1)) : 0;
    }
    return c[1] * kSide + c[0];
  }
  double lo_[2], hi_[2];
  std::vector<std::uint32_t> cell_;
};

}  // namespace

Report rt2(const PointSet& ps, const std::vector<Triangle>& tris, Level level) {
  return rt2(ps, tris, level, Speedups{});
}

Report rt2(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups) {
  if (ps.dim != 2) return Report::fail("input-dimension", "rt2 needs 2D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size(), F = tris.size();
  const bool canonical = level == Level::canonical;
  const auto& for_range = speedups.for_range;

  if (tris.empty()) return Report::fail("triangle-indices", "the output has no triangles");
  if (std::string why = detail::check_triangle_indices(tris, n, for_range); !why.empty())
    return Report::fail("triangle-indices", why);
  if (canonical)
    if (std::string why = detail::check_canonical_triangles(tris, for_range); !why.empty())
      return Report::fail("canonical-form", why);

  pred::StaticFilter own;
  const pred::StaticFilter* filter = speedups.filter;
  if (!filter) {
    own = speedups.make_filter ? speedups.make_filter({})
                               : pred::StaticFilter::for_points(ps.coords.data(), n, 2,
                                                               ps.weighted ? ps.weights.data() : nullptr);
    filter = &own;
  }
  const Rt2Checker ck{ps, canonical, *filter};

  if (const std::size_t bad = detail::smallest_failing(
          F, for_range, [&](std::size_t t) { return ck.orient_sos(tris[t][0], tris[t][1], tris[t][2]) <= 0; });
      bad < F)
    return Report::fail("triangle-orientation", "triangle " + tri_str(tris[bad]) + " is clockwise");

  detail::VertexLinks links;
  links.build(n, tris, for_range);
  {
    Index a = 0, b = 0;
    std::uint32_t t1 = 0, t2 = 0;
    if (links.repeated_edge(tris, for_range, a, b, t1, t2))
      return Report::fail("edge-manifold", "directed edge " + edge_str(a, b) + " appears in triangles " +
                                               tri_str(tris[t1]) + " and " + tri_str(tris[t2]));
  }

  // boundary: directed edges without twin; one outgoing and one incoming each
  // (a scan in (triangle, edge) order, as the first vertex met twice is named)
  detail::UnionFind uf(F);
  const std::vector<std::array<std::uint32_t, 3>> across = detail::neighbours(tris, links, uf, for_range);
  std::vector<Index> bnext(n, kNoVertex), bprev(n, kNoVertex);
  std::size_t nboundary = 0;
  for (std::uint32_t t = 0; t < F; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (across[t][k] != kNoTriangle) continue;
      Index a = tris[t][k], b = tris[t][(k + 1) % 3];
      if (bnext[a] != kNoVertex || bprev[b] != kNoVertex)
        return Report::fail("boundary", "the boundary passes twice through vertex " +
                                            std::to_string(bnext[a] != kNoVertex ? a : b));
      bnext[a] = b;
      bprev[b] = a;
      ++nboundary;
    }
  }
  if (nboundary < 3) return Report::fail("boundary", "the triangles have no boundary cycle");
  std::vector<Index> cycle;
  {
    Index start = 0;
    while (bnext[start] == kNoVertex) ++start;
    Index v = start;
    do {
      cycle.push_back(v);
      v = bnext[v];
    } while (v != start && cycle.size() <= nboundary);
    if (cycle.size() != nboundary)
      return Report::fail("boundary", "the boundary edges form more than one cycle (holes or several pieces)");
  }
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  // (the filter covers the coordinates, so it serves hull2's orient2d too)
  if (Report r = hull2(ps, cycle, level, Speedups{filter, for_range, {}}); !r.ok)
    return Report::fail("boundary-is-hull", "the boundary is not the convex hull: " + r.message());

  // vertex fans: the first vertex whose fan fails, and why
  auto fan_problem = [&](Index v, std::vector<Index>& fan) -> std::string {
    const bool on_boundary = bnext[v] != kNoVertex;
    // around a boundary vertex the fan runs from its boundary successor to its
    // boundary predecessor
    const Index first = on_boundary ? bnext[v] : links.first_from(v);
    const bool closed = links.walk(v, first, fan);
    const std::size_t expect = links.degree(v) + (on_boundary ? 1 : 0);
    if (closed == on_boundary || fan.size() != expect)
      return "the triangles around vertex " + std::to_string(v) + " do not form a single fan";
    const Index u1 = fan[0];
    int turns = detail::count_turns(fan, !on_boundary,
                                    [&](Index u) { return (u == u1 || ck.orient_sos(v, u1, u) > 0) ? 0 : 1; });
    if (turns != (on_boundary ? 0 : 1))
      return "the triangles around vertex " + std::to_string(v) + " wind " +
             std::to_string(turns + (on_boundary ? 1 : 0)) + " times around it";
    return {};
  };
  if (const std::size_t bad = detail::smallest_failing_by_piece(n, for_range,
                                                                [&](std::size_t) {
                                                                  return [&, fan = std::vector<Index>()](
                                                                             std::size_t v) mutable {
                                                                    return links.degree(static_cast<Index>(v)) > 0 &&
                                                                           !fan_problem(static_cast<Index>(v), fan).empty();
                                                                  };
                                                                });
      bad < n) {
    std::vector<Index> fan;
    return Report::fail("vertex-fan", fan_problem(static_cast<Index>(bad), fan));
  }
  long V = 0;
  for (Index v = 0; v < n; ++v) V += links.degree(v) > 0;
  const long E = static_cast<long>((F * 3 + nboundary) / 2);
  if (V - E + static_cast<long>(F) != 1)
    return Report::fail("euler-characteristic",
                        "V - E + F = " + std::to_string(V - E + static_cast<long>(F)) + ", a disk has 1");
  if (const std::size_t bad = detail::smallest_failing(
          F, for_range, [&](std::size_t t) { return uf.find(static_cast<std::uint32_t>(t)) != uf.find(0); });
      bad < F)
    return Report::fail("euler-characteristic", "triangle " + tri_str(tris[bad]) + " is not connected to " +
                                                    tri_str(tris[0]));

  // local regularity (Thm 2.2): edge k of triangle t, each interior edge once
  // (from its triangle with a < b); the sign of its opposite vertex d against
  // the power circle of t, 0 for the other edges
  auto edge_power = [&](std::size_t t, int k, Index& d) {
    const Index a = tris[t][k], b = tris[t][(k + 1) % 3];
    if (a > b || across[t][k] == kNoTriangle) return canonical ? -1 : 0;
    d = detail::third_vertex(tris[across[t][k]], a, b);
    return ck.power(tris[t], d);
  };
  auto irregular = [&](int sgn) { return canonical ? sgn >= 0 : sgn > 0; };
  if (const std::size_t bad = detail::smallest_failing(F, for_range,
                                                       [&](std::size_t t) {
                                                         Index d = 0;
                                                         for (int k = 0; k < 3; ++k)
                                                           if (irregular(edge_power(t, k, d))) return true;
                                                         return false;
                                                       });
      bad < F) {
    for (int k = 0; k < 3; ++k) {
      Index d = 0;
      if (irregular(edge_power(bad, k, d)))
        return Report::fail("locally-regular", "edge " + edge_str(tris[bad][k], tris[bad][(k + 1) % 3]) +
                                                   " is not locally regular: vertex " + std::to_string(d) +
                                                   (canonical ? " is not strictly outside" : " is strictly inside") +
                                                   " the power circle of " + tri_str(tris[bad]));
    }
  }

  // every missing point is redundant: locate it, compare its lifted point with
  // the lifted triangle containing it. The points are taken in Morton order
  // (the first failing one in that order is named) and split into pieces
  // through for_range; each piece walks from the start table's triangle for
  // its first point and its own random generator.
  std::vector<Index> missing;
  for (Index p = 0; p < n; ++p)
    if (links.degree(p) == 0) missing.push_back(p);
  if (missing.empty()) return Report::pass();
  detail::morton_sort(ps, missing, for_range);
  const StartTable table(ps, tris);
  const std::size_t cap = 4 * F + 100;
  // The triangle p is checked against, kNoTriangle when there is none: the one
  // containing p under the perturbation (unique: the perturbed triangles tile
  // the region they cover), found by a perturbed visibility walk from `cur`
  // (stochastic: a random violated edge, Devillers–Pion–Teillaud), else — the
  // walk left the triangulation or did not settle — by a scan. Without one:
  // at the canonical level p is outside every perturbed triangle, a point of
  // the perturbed hull that is not a vertex; at the exact level p may lie
  // exactly on the boundary (a copy of a hull vertex, a point on a hull edge)
  // while the perturbation moves it out, and its lifted point is compared with
  // the lifted surface at p through any non-flat triangle whose closed region
  // contains p exactly (the surface is continuous, so every such triangle
  // gives the same answer; flat triangles have no region and are skipped).
  // The answer depends on p alone, not on where the walk started.
  auto locate = [&](Index p, std::uint32_t& cur, detail::XorShift& rng) -> std::uint32_t {
    for (std::size_t steps = 0; steps < cap; ++steps) {
      const Triangle& t = tris[cur];
      int cand[3], nc = 0;
      for (int k = 0; k < 3; ++k)
        if (ck.orient_sos(t[k], t[(k + 1) % 3], p) < 0) cand[nc++] = k;
      if (nc == 0) return cur;
      const int k = cand[nc == 1 ? 0 : rng.next() % static_cast<std::uint32_t>(nc)];
      if (across[cur][k] == kNoTriangle) break;  // outside the perturbed triangles
      cur = across[cur][k];
    }
    for (std::size_t t = 0; t < F; ++t)
      if (ck.inside_sos(tris[t], p)) return static_cast<std::uint32_t>(t);
    if (!canonical)
      for (std::size_t t = 0; t < F; ++t)
        if (ck.inside_exact(tris[t], p)) return static_cast<std::uint32_t>(t);
    return kNoTriangle;
  };
  auto not_redundant = [&](std::uint32_t t, Index p) { return t == kNoTriangle || irregular(ck.power(tris[t], p)); };
  const std::size_t bad = detail::smallest_failing_by_piece(missing.size(), for_range, [&](std::size_t lo) {
    detail::XorShift rng;
    rng.s ^= static_cast<std::uint64_t>(lo) * 0xD1B54A32D192ED03ull;
    return [&, rng, cur = table.hint(ps.point(missing[lo]))](std::size_t i) mutable {
      const std::uint32_t t = locate(missing[i], cur, rng);
      return not_redundant(t, missing[i]);
    };
  });
  if (bad == missing.size()) return Report::pass();
  const Index p = missing[bad];
  detail::XorShift rng;
  std::uint32_t cur = table.hint(ps.point(p));
  const std::uint32_t t = locate(p, cur, rng);
  if (t == kNoTriangle)
    return Report::fail("missing-point-redundant", "point " + std::to_string(p) +
                                                       " is not a vertex and lies in no triangle" +
                                                       (canonical ? " under the perturbation" : ""));
  return Report::fail("missing-point-redundant",
                      "point " + std::to_string(p) + " is not a vertex but is not redundant: its lifted point is " +
                          (canonical ? "not strictly above" : "strictly below") + " the lifted triangle " +
                          tri_str(tris[t]));
}

Report rt2_strict(const PointSet& ps, const std::vector<Triangle>& tris) {
  if (ps.dim != 2) return Report::fail("input-dimension", "rt2 needs 2D points");
  for (const Triangle& t : tris) {
    for (Index x : t)
      if (x >= ps.size())
        return Report::fail("triangle-indices", "index " + std::to_string(x) + " but the input has " +
                                                    std::to_string(ps.size()) + " points");
    if (pred::orient2d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2])) <= 0)
      return Report::fail("zero-area", "triangle (" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," +
                                           std::to_string(t[2]) + ") has zero area or is clockwise");
  }
  return rt2(ps, tris, Level::exact);
}

}  // namespace flipflop::certify

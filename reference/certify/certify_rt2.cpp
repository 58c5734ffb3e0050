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
#include <algorithm>

#include "predicates/predicates.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/dimension.hpp"

namespace flipflop::certify {

namespace {
using detail::edge_str;
using detail::tri_str;

struct Rt2Checker {
  const PointSet& ps;
  bool canonical;

  const double* P(Index i) const { return ps.point(i); }
  pred::WPt W(Index i) const { return {i, P(i), ps.weight(i)}; }
  int orient_sos(Index a, Index b, Index c) const { return pred::orient2d({a, P(a)}, {b, P(b)}, {c, P(c)}); }
  // > 0 when d is strictly inside the power circle of the counter-clockwise
  // triangle t (d's lifted point strictly below the lifted plane of t)
  int power(const Triangle& t, Index d) const {
    return canonical ? pred::power2d(W(t[0]), W(t[1]), W(t[2]), W(d))
                     : pred::power2d_exact(W(t[0]), W(t[1]), W(t[2]), W(d));
  }
};
}  // namespace

Report rt2(const PointSet& ps, const std::vector<Triangle>& tris, Level level) {
  if (ps.dim != 2) return Report::fail("input-dimension", "rt2 needs 2D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  const bool canonical = level == Level::canonical;
  Rt2Checker ck{ps, canonical};

  if (tris.empty()) return Report::fail("triangle-indices", "the output has no triangles");
  if (std::string why = detail::check_triangle_indices(tris, n); !why.empty())
    return Report::fail("triangle-indices", why);
  if (canonical)
    if (std::string why = detail::check_canonical_triangles(tris); !why.empty())
      return Report::fail("canonical-form", why);

  for (const Triangle& t : tris)
    if (ck.orient_sos(t[0], t[1], t[2]) <= 0)
      return Report::fail("triangle-orientation", "triangle " + tri_str(t) + " is clockwise");

  detail::DirectedEdges edges;
  {
    Index a = 0, b = 0;
    std::uint32_t t1 = 0, t2 = 0;
    if (!edges.build(tris, a, b, t1, t2))
      return Report::fail("edge-manifold", "directed edge " + edge_str(a, b) + " appears in triangles " +
                                               tri_str(tris[t1]) + " and " + tri_str(tris[t2]));
  }

  // boundary: directed edges without twin; one outgoing and one incoming each
  std::vector<long> bnext(n, -1), bprev(n, -1);
  std::size_t nboundary = 0;
  detail::UnionFind uf(tris.size());
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      Index a = tris[t][k], b = tris[t][(k + 1) % 3];
      long twin = edges.find(b, a);
      if (twin >= 0) {
        uf.unite(t, static_cast<std::uint32_t>(twin));
        continue;
      }
      if (bnext[a] >= 0 || bprev[b] >= 0)
        return Report::fail("boundary", "the boundary passes twice through vertex " +
                                            std::to_string(bnext[a] >= 0 ? a : b));
      bnext[a] = b;
      bprev[b] = a;
      ++nboundary;
    }
  }
  if (nboundary < 3) return Report::fail("boundary", "the triangles have no boundary cycle");
  std::vector<Index> cycle;
  {
    Index start = 0;
    while (bnext[start] < 0) ++start;
    Index v = start;
    do {
      cycle.push_back(v);
      v = static_cast<Index>(bnext[v]);
    } while (v != start && cycle.size() <= nboundary);
    if (cycle.size() != nboundary)
      return Report::fail("boundary", "the boundary edges form more than one cycle (holes or several pieces)");
  }
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  if (Report r = hull2(ps, cycle, level); !r.ok)
    return Report::fail("boundary-is-hull", "the boundary is not the convex hull: " + r.message());

  // vertex fans
  detail::VertexLinks links;
  links.build(n, tris);
  std::vector<char> is_vertex(n, 0);
  std::vector<Index> fan;
  long V = 0;
  for (Index v = 0; v < n; ++v) {
    if (links.degree(v) == 0) continue;
    is_vertex[v] = 1;
    ++V;
    const bool on_boundary = bnext[v] >= 0;
    // around a boundary vertex the fan runs from its boundary successor to its
    // boundary predecessor
    const Index first = on_boundary ? static_cast<Index>(bnext[v]) : links.edge[links.start[v]].first;
    const bool closed = links.walk(v, first, fan);
    const std::size_t expect = links.degree(v) + (on_boundary ? 1 : 0);
    if (closed == on_boundary || fan.size() != expect)
      return Report::fail("vertex-fan", "the triangles around vertex " + std::to_string(v) +
                                            " do not form a single fan");
    const Index u1 = fan[0];
    int turns = detail::count_turns(fan, !on_boundary,
                                    [&](Index u) { return (u == u1 || ck.orient_sos(v, u1, u) > 0) ? 0 : 1; });
    if (turns != (on_boundary ? 0 : 1))
      return Report::fail("vertex-fan", "the triangles around vertex " + std::to_string(v) + " wind " +
                                            std::to_string(turns + (on_boundary ? 1 : 0)) + " times around it");
  }
  const long E = static_cast<long>((tris.size() * 3 + nboundary) / 2), F = static_cast<long>(tris.size());
  if (V - E + F != 1)
    return Report::fail("euler-characteristic", "V - E + F = " + std::to_string(V - E + F) + ", a disk has 1");
  for (std::uint32_t t = 1; t < tris.size(); ++t)
    if (uf.find(t) != uf.find(0))
      return Report::fail("euler-characteristic", "triangle " + tri_str(tris[t]) + " is not connected to " +
                                                      tri_str(tris[0]));

  // local regularity (Thm 2.2)
  for (const Triangle& t : tris) {
    for (int k = 0; k < 3; ++k) {
      Index a = t[k], b = t[(k + 1) % 3];
      long o = edges.find(b, a);
      if (a > b || o < 0) continue;
      Index d = detail::third_vertex(tris[static_cast<std::size_t>(o)], a, b);
      int sgn = ck.power(t, d);
      if (canonical ? sgn >= 0 : sgn > 0)
        return Report::fail("locally-regular", "edge " + edge_str(a, b) + " is not locally regular: vertex " +
                                                   std::to_string(d) + (canonical ? " is not strictly outside" : " is strictly inside") +
                                                   " the power circle of " + tri_str(t));
    }
  }

  // every missing point is redundant: locate it (perturbed visibility walk),
  // compare with the lifted triangle containing it
  std::vector<Index> todo;
  for (Index p = 0; p < n; ++p)
    if (!is_vertex[p]) todo.push_back(p);
  detail::morton_sort(ps, todo);
  detail::XorShift rng;
  std::size_t cur = 0;
  const std::size_t cap = 4 * tris.size() + 100;
  for (Index p : todo) {
    auto check = [&](const Triangle& t) -> Report {
      int sgn = ck.power(t, p);
      if (canonical ? sgn >= 0 : sgn > 0)
        return Report::fail("missing-point-redundant",
                            "point " + std::to_string(p) + " is not a vertex but is not redundant: its lifted point is " +
                                (canonical ? "not strictly above" : "strictly below") + " the lifted triangle " + tri_str(t));
      return Report::pass();
    };
    std::size_t steps = 0;
    bool found = false;
    while (steps++ < cap) {
      const Triangle& t = tris[cur];
      int cand[3], nc = 0;
      for (int k = 0; k < 3; ++k)
        if (ck.orient_sos(t[k], t[(k + 1) % 3], p) < 0) cand[nc++] = k;
      if (nc == 0) {
        found = true;
        break;
      }
      int k = cand[nc == 1 ? 0 : rng.next() % static_cast<std::uint32_t>(nc)];
      long next = edges.find(t[(k + 1) % 3], t[k]);
      if (next < 0) break;  // outside the hull: cannot happen after boundary-is-hull
      cur = static_cast<std::size_t>(next);
    }
    if (found) {
      if (Report r = check(tris[cur]); !r.ok) return r;
      continue;
    }
    // The walk left the triangulation or did not settle. Canonical level: p is
    // then outside every perturbed triangle — a point of the perturbed hull
    // that is not a vertex. Exact level: p may lie exactly on the boundary
    // (a copy of a hull vertex, a point on a hull edge) while the perturbation
    // moves it out; its lifted point is compared with the lifted surface at p
    // through any non-flat triangle whose closed region contains p exactly
    // (the surface is continuous, so every such triangle gives the same
    // answer; flat triangles have no region and are skipped).
    bool located = false;
    for (const Triangle& t : tris) {
      bool inside = canonical
                        ? ck.orient_sos(t[0], t[1], p) > 0 && ck.orient_sos(t[1], t[2], p) > 0 &&
                              ck.orient_sos(t[2], t[0], p) > 0
                        : pred::orient2d_exact(ck.P(t[0]), ck.P(t[1]), ck.P(t[2])) > 0 &&
                              pred::orient2d_exact(ck.P(t[0]), ck.P(t[1]), ck.P(p)) >= 0 &&
                              pred::orient2d_exact(ck.P(t[1]), ck.P(t[2]), ck.P(p)) >= 0 &&
                              pred::orient2d_exact(ck.P(t[2]), ck.P(t[0]), ck.P(p)) >= 0;
      if (!inside) continue;
      if (Report r = check(t); !r.ok) return r;
      located = true;
      break;
    }
    if (!located)
      return Report::fail("missing-point-redundant", "point " + std::to_string(p) +
                                                         " is not a vertex and lies in no triangle" +
                                                         (canonical ? " under the perturbation" : ""));
  }
  return Report::pass();
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

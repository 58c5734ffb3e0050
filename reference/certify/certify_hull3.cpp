// certify_hull3.cpp — exact certification of a 3D convex hull (triangles).
//
// Conditions, in order (the first violated one is reported):
//   input-dimension      the points span R^3
//   triangle-indices     indices in range, three distinct per triangle
//   canonical-form       (canonical) rotation and order of DESIGN.md
//   oriented-manifold    every directed edge appears once (consistent
//                        orientation, at most two triangles per edge)
//   closed-surface       every edge has its opposite twin (no hole)
//   vertex-link          the triangles around every vertex form one cycle
//   connected            one component
//   euler-characteristic V - E + F = 2 (a topological sphere)
//   interior-point       four affinely independent hull vertices exist; their
//                        exact centroid s is then strictly inside conv(S)
//   facet-orientation    every facet faces away from s (Lemma 6.1: its cone
//                        from s is a proper cone)
//   star-shaped          the projection from s winds exactly once around every
//                        vertex; with facet-orientation the central projection
//                        is an unbranched covering of the sphere of degree 1,
//                        i.e. the surface is star-shaped w.r.t. s (Lemma 6.1)
//   convex-edge          every edge is convex (Thm 6.2: then the star-shaped
//                        surface is convex)
//   point-inside         every point lies on the inner side of (or on) the
//                        facet whose cone from s contains it; canonical:
//                        strictly, for every point that is not a vertex
// s is an auxiliary point: in the perturbation it has index n (after all
// inputs, predicates.hpp). It is the centroid of the four vertices rounded to
// doubles when that point is strictly inside their tetrahedron exactly (four
// exact orient3d signs; then every predicate on s is an ordinary orient3d
// with the per-input static filter, several times faster than on a rational
// point), else the exact dyadic centroid. Either is strictly inside conv(S),
// which is all the conditions below need. Structural predicates (those involving s) are
// perturbed at both levels; geometric conditions are exact (>= 0) at the exact
// level and perturbed and strict at the canonical level.
// The conditions up to convex-edge are detail::hull3_surface
// (certify_hull3_surface.hpp), shared with the witness-checked certifier of
// the multithreaded kernel (kernels_cpu/hull3/certify_hull3.hpp), which takes
// s's four points from the witness and replaces point-inside's walk by a
// check of the facet the witness names.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/certify/certify_hull3_surface.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/dimension.hpp"

namespace flipflop::certify {

namespace {

using detail::edge_str;
using detail::tri_str;

// The rounded centroid of the tetrahedron (tp), when it is strictly inside it
// exactly: each vertex replaced by it, the orientation keeps its sign.
bool rounded_centroid_inside(const double* const* tp, double* sd) {
  for (int j = 0; j < 3; ++j) {
    sd[j] = ((tp[0][j] + tp[1][j]) + (tp[2][j] + tp[3][j])) * 0.25;
    if (!std::isfinite(sd[j])) return false;
  }
  const int o = pred::orient3d_exact(tp[0], tp[1], tp[2], tp[3]);
  for (int i = 0; i < 4; ++i) {
    const double* q[4] = {tp[0], tp[1], tp[2], tp[3]};
    q[i] = sd;
    if (o == 0 || pred::orient3d_exact(q[0], q[1], q[2], q[3]) != o) return false;
  }
  return true;
}

double dist2(const double* a, const double* b) {
  double s = 0;
  for (int j = 0; j < 3; ++j) s += (a[j] - b[j]) * (a[j] - b[j]);
  return s;
}

// Four affinely independent vertices, chosen far apart by floating-point
// estimates and confirmed by exact predicates. Returns false if the vertices
// are coplanar.
bool pick_tetrahedron(const PointSet& ps, const std::vector<Index>& verts, Index out[4]) {
  auto P = [&](Index i) { return ps.point(i); };
  Index a = verts[0];
  for (Index v : verts)
    if (P(v)[0] < P(a)[0]) a = v;
  Index b = a;
  double best = -1;
  for (Index v : verts)
    if (double d = dist2(P(a), P(v)); d > best) best = d, b = v;
  auto same = [&](Index u, Index v) { return P(u)[0] == P(v)[0] && P(u)[1] == P(v)[1] && P(u)[2] == P(v)[2]; };
  if (same(a, b)) {
    // the floating-point estimate underflowed (tiny coordinates): any other
    // location will do, the exact tests below decide
    auto it = std::find_if(verts.begin(), verts.end(), [&](Index v) { return !same(a, v); });
    if (it == verts.end()) return false;
    b = *it;
  }
  auto cross_norm = [&](Index c) {
    double u[3], w[3];
    for (int j = 0; j < 3; ++j) u[j] = P(b)[j] - P(a)[j], w[j] = P(c)[j] - P(a)[j];
    double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    return x * x + y * y + z * z;
  };
  auto collinear = [&](Index c) {
    const int ax[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (const auto& q : ax) {
      double pa[2] = {P(a)[q[0]], P(a)[q[1]]}, pb[2] = {P(b)[q[0]], P(b)[q[1]]}, pc[2] = {P(c)[q[0]], P(c)[q[1]]};
      if (pred::orient2d_exact(pa, pb, pc) != 0) return false;
    }
    return true;
  };
  Index c = a;
  best = -1;
  for (Index v : verts)
    if (double d = cross_norm(v); d > best) best = d, c = v;
  if (collinear(c)) {
    auto it = std::find_if(verts.begin(), verts.end(), [&](Index v) { return !collinear(v); });
    if (it == verts.end()) return false;
    c = *it;
  }
  auto nonflat = [&](Index d) { return pred::orient3d_exact(P(a), P(b), P(c), P(d)) != 0; };
  auto vol_est = [&](Index d) {
    double u[3], w[3], z[3];
    for (int j = 0; j < 3; ++j) u[j] = P(b)[j] - P(a)[j], w[j] = P(c)[j] - P(a)[j], z[j] = P(d)[j] - P(a)[j];
    return std::fabs(u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) +
                     u[2] * (w[0] * z[1] - w[1] * z[0]));
  };
  Index d = a;
  best = -1;
  for (Index v : verts)
    if (double e = vol_est(v); e > best) best = e, d = v;
  if (!nonflat(d)) {
    auto it = std::find_if(verts.begin(), verts.end(), nonflat);
    if (it == verts.end()) return false;
    d = *it;
  }
  out[0] = a, out[1] = b, out[2] = c, out[3] = d;
  return true;
}

}  // namespace

Report hull3(const PointSet& ps, const std::vector<Triangle>& tris, Level level) {
  return hull3(ps, tris, level, Speedups{});
}

namespace detail {

Report hull3_surface(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups,
                     const std::array<Index, 4>* given_tet, Hull3Surface& ck) {
  if (ps.dim != 3) return Report::fail("input-dimension", "hull3 needs 3D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  const bool canonical = level == Level::canonical;

  if (tris.size() < 4)
    return Report::fail("triangle-indices", "a closed surface needs at least 4 triangles, the output has " +
                                                std::to_string(tris.size()));
  if (std::string why = detail::check_triangle_indices(tris, n, speedups.for_range); !why.empty())
    return Report::fail("triangle-indices", why);
  if (canonical)
    if (std::string why = detail::check_canonical_triangles(tris, speedups.for_range); !why.empty())
      return Report::fail("canonical-form", why);

  // ---- topology -------------------------------------------------------------
  detail::VertexLinks links;
  links.build(n, tris, speedups.for_range);
  {
    Index a = 0, b = 0;
    std::uint32_t t1 = 0, t2 = 0;
    if (links.repeated_edge(tris, speedups.for_range, a, b, t1, t2))
      return Report::fail("oriented-manifold", "directed edge " + edge_str(a, b) + " appears in triangles " +
                                                   tri_str(tris[t1]) + " and " + tri_str(tris[t2]) +
                                                   " (inconsistent orientation or more than two triangles on an edge)");
  }
  detail::UnionFind uf(tris.size());
  ck.across = detail::neighbours(tris, links, uf, speedups.for_range);
  const std::vector<std::array<std::uint32_t, 3>>& across = ck.across;
  if (const std::size_t bad = detail::smallest_failing(tris.size(), speedups.for_range,
                                                       [&](std::size_t t) {
                                                         return across[t][0] == detail::kNoTriangle ||
                                                                across[t][1] == detail::kNoTriangle ||
                                                                across[t][2] == detail::kNoTriangle;
                                                       });
      bad < tris.size()) {
    const std::size_t k = across[bad][0] == detail::kNoTriangle ? 0 : across[bad][1] == detail::kNoTriangle ? 1 : 2;
    return Report::fail("closed-surface", "edge " + edge_str(tris[bad][k], tris[bad][(k + 1) % 3]) + " of triangle " +
                                              tri_str(tris[bad]) + " has no opposite triangle (the surface has a hole)");
  }
  std::vector<Index> verts;
  std::vector<char>& is_vertex = ck.is_vertex;
  is_vertex.assign(n, 0);
  std::vector<Index> cyc;
  for (Index v = 0; v < n; ++v) {
    if (links.degree(v) == 0) continue;
    is_vertex[v] = 1;
    verts.push_back(v);
    bool closed = links.walk(v, links.first_from(v), cyc);
    if (!closed || cyc.size() != links.degree(v))
      return Report::fail("vertex-link", "the triangles around vertex " + std::to_string(v) +
                                             " do not form a single cycle (the surface is pinched there)");
  }
  if (const std::size_t bad = detail::smallest_failing(
          tris.size(), speedups.for_range,
          [&](std::size_t t) { return uf.find(static_cast<std::uint32_t>(t)) != uf.find(0); });
      bad < tris.size())
    return Report::fail("connected", "triangle " + tri_str(tris[bad]) + " is not connected to triangle " +
                                         tri_str(tris[0]));
  const long V = static_cast<long>(verts.size()), E = static_cast<long>(tris.size() * 3 / 2),
             F = static_cast<long>(tris.size());
  if (V - E + F != 2)
    return Report::fail("euler-characteristic", "V - E + F = " + std::to_string(V) + " - " + std::to_string(E) +
                                                    " + " + std::to_string(F) + " = " + std::to_string(V - E + F) +
                                                    ", a sphere has 2");

  // ---- interior point ---------------------------------------------------------
  ck.vertices = verts.size();
  Index tet[4];
  if (given_tet) std::copy(given_tet->begin(), given_tet->end(), tet);
  else if (!pick_tetrahedron(ps, verts, tet))
    return Report::fail("interior-point", "all vertices of the surface are coplanar, the hull of the input is not");
  const double* tp[4] = {ps.point(tet[0]), ps.point(tet[1]), ps.point(tet[2]), ps.point(tet[3])};
  ck.ps = &ps;
  ck.canonical = canonical;
  ck.s = pred::RationalPoint::centroid(tp, 4, 3);
  ck.s_id = static_cast<pred::PointId>(n);
  ck.s_is_double = rounded_centroid_inside(tp, ck.sd);
  if (speedups.make_filter)
    ck.f = speedups.make_filter(ck.s_is_double ? std::vector<double>(ck.sd, ck.sd + 3) : std::vector<double>{});
  else
    ck.f = pred::StaticFilter::for_points(ps.coords.data(), ps.size(), 3, nullptr, ck.s_is_double ? ck.sd : nullptr,
                                         ck.s_is_double ? 3 : 0);

  // ---- star-shapedness w.r.t. s --------------------------------------------
  if (const std::size_t bad = detail::smallest_failing(
          tris.size(), speedups.for_range, [&](std::size_t i) { return ck.facet_vs_s(tris[i]) <= 0; });
      bad < tris.size())
      return Report::fail("facet-orientation", "facet " + tri_str(tris[bad]) +
                                                   " does not face away from the interior point (it is oriented "
                                                   "inward or is not on the hull)");
  for (Index v : verts) {
    links.walk(v, links.first_from(v), cyc);
    const Index u1 = cyc[0];
    // rotation sense around the axis s→v: rot(x, y) = -orient3d(s, v, x, y) > 0
    // for consecutive link vertices of facets facing away from s.
    int turns = detail::count_turns(cyc, true, [&](Index u) { return (u == u1 || -ck.side(v, u1, u) > 0) ? 0 : 1; });
    if (turns != 1)
      return Report::fail("star-shaped", "seen from the interior point the surface winds " + std::to_string(turns) +
                                             " times around vertex " + std::to_string(v));
  }

  // ---- convexity (Thm 6.2) ----------------------------------------------------
  // edge k of triangle t (each undirected edge once, from its triangle with
  // a < b): its opposite vertex d across it, d's orientation against t
  auto convexity = [&](std::size_t i, int k, Index& d, const Triangle*& o) {
    const Triangle& t = tris[i];
    const Index a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
    if (a > b) return 1;
    o = &tris[across[i][static_cast<std::size_t>(k)]];
    d = detail::third_vertex(*o, a, b);
    return ck.facet_vs_point(t, d);
  };
  auto reflex = [&](int sgn) { return canonical ? sgn <= 0 : sgn < 0; };
  if (const std::size_t bad = detail::smallest_failing(tris.size(), speedups.for_range,
                                                       [&](std::size_t i) {
                                                         Index d = 0;
                                                         const Triangle* o = nullptr;
                                                         for (int k = 0; k < 3; ++k)
                                                           if (reflex(convexity(i, k, d, o))) return true;
                                                         return false;
                                                       });
      bad < tris.size()) {
    const Triangle& t = tris[bad];
    for (int k = 0; k < 3; ++k) {
      Index d = 0;
      const Triangle* o = nullptr;
      const int sgn = convexity(bad, k, d, o);
      if (reflex(sgn))
        return Report::fail("convex-edge", "edge " + edge_str(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]) +
                                               " is " + (sgn < 0 ? "reflex" : "flat") + ": vertex " +
                                               std::to_string(d) + " of facet " + tri_str(*o) +
                                               " is not on the inner side of facet " + tri_str(t) +
                                               (canonical ? " under the perturbation" : ""));
    }
  }

  return Report::pass();
}

}  // namespace detail

Report hull3(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups) {
  detail::Hull3Surface ck;
  if (Report r = detail::hull3_surface(ps, tris, level, speedups, nullptr, ck); !r.ok) return r;
  const std::size_t n = ps.size();
  const bool canonical = level == Level::canonical;
  const std::vector<char>& is_vertex = ck.is_vertex;
  const auto& across = ck.across;

  // ---- every point inside ------------------------------------------------------
  // Each point is located by a stochastic visibility walk over the cones from
  // s (perturbed, so no ties), started at the facet a direction table gives
  // for the direction from s (a hint only: any start reaches the one cone
  // that contains the point), then checked against that facet. The points
  // are taken in index order, so the first failing point is the smallest.
  const double s_approx[3] = {ck.s_is_double ? ck.sd[0] : ck.s.approx[0].v, ck.s_is_double ? ck.sd[1] : ck.s.approx[1].v,
                              ck.s_is_double ? ck.sd[2] : ck.s.approx[2].v};
  const detail::DirectionTable table(ps, tris, s_approx);
  std::size_t candidates = 0;
  for (Index p = 0; p < n; ++p) candidates += !is_vertex[p];
  // worth its exact set-up (one GMP test per facet) when points outnumber facets
  const detail::InnerBall<3> ball =
      candidates >= 8 * tris.size() ? detail::InnerBall<3>(ps, tris, speedups.for_range) : detail::InnerBall<3>();
  const std::size_t cap = 4 * tris.size() + 100;
  auto check_point = [&](Index p) -> Report {
    if (ball.strictly_inside(ps.point(p))) return Report::pass();
    std::size_t cur = table.hint(ps.point(p));
    detail::XorShift rng;
    rng.s ^= static_cast<std::uint64_t>(p) * 0xD1B54A32D192ED03ull;
    std::size_t steps = 0;
    bool found = false;
    while (steps++ < cap) {
      const Triangle& t = tris[cur];
      int cand[3], nc = 0;
      for (int k = 0; k < 3; ++k)
        if (ck.side(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)], p) > 0) cand[nc++] = k;
      if (nc == 0) {
        found = true;
        break;
      }
      const int k = cand[nc == 1 ? 0 : rng.next() % static_cast<std::uint32_t>(nc)];
      cur = across[cur][static_cast<std::size_t>(k)];
    }
    auto check = [&](const Triangle& t) -> Report {
      int sgn = ck.facet_vs_point(t, p);
      if (canonical ? sgn <= 0 : sgn < 0)
        return Report::fail("point-inside", "point " + std::to_string(p) +
                                                (canonical ? " is not a vertex and not strictly inside facet "
                                                           : " lies strictly outside facet ") +
                                                tri_str(t) + (canonical ? " under the perturbation" : ""));
      return Report::pass();
    };
    if (found) return check(tris[cur]);
    // The walk did not settle (it terminates with probability 1; this bound
    // only protects against pathological cases): test every facet.
    for (const Triangle& t : tris)
      if (Report r = check(t); !r.ok) return r;
    return Report::pass();
  };
  if (const std::size_t bad = detail::smallest_failing(
          n, speedups.for_range,
          [&](std::size_t p) { return !is_vertex[p] && !check_point(static_cast<Index>(p)).ok; });
      bad < n)
    return check_point(static_cast<Index>(bad));
  return Report::pass();
}

}  // namespace flipflop::certify

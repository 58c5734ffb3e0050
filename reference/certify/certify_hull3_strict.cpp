// certify_hull3_strict.cpp — certify::hull3_strict: the strict view of a 3D
// hull (reference/hull3/strict_hull3.hpp; `flipflop hull3 --strict
// [--triangulate]`), checked from the input alone, exactly. It does not
// recompute the view; it checks the properties that define it:
//
//   strict-indices    indices < n; the extreme points strictly increasing;
//                     every facet of >= 3 distinct indices, all of them
//                     listed extreme points; every extreme point in a facet;
//   smallest-index    each extreme point is the smallest index at its
//                     location (so no location is listed twice);
//   facet-polygon     every facet is a planar convex polygon, counter-
//                     clockwise seen from outside, with strictly convex
//                     corners: all vertices in the plane of its first three
//                     (not collinear), and with q an extreme point off that
//                     plane, which must be on its inner side,
//                     orient3d(f[i-1], f[i], f[i+1], q) > 0 at every corner
//                     and orient3d(f0, fj, fj+1, q) > 0 for the fan from f0
//                     (the angular order around f0 is monotone: the polygon
//                     winds once, so it is convex and simple);
//   hull3 conditions  the fan triangles of all facets pass certify::hull3 at
//                     Level::exact: a closed oriented convex surface with
//                     every input point inside or on it — so the polygons
//                     tile the boundary of conv(S);
//   strictly-extreme  every vertex lies in facets of at least three distinct
//                     planes: a point of the boundary of a 3-polytope lies in
//                     one facet plane (inside a facet), two (inside an edge)
//                     or >= 3 (a vertex, i.e. strictly extreme); with the
//                     surface conv(S)'s boundary, the vertices are then
//                     exactly the strictly extreme locations of S;
//   maximal-facets    (polygon view only) no two facets sharing an edge are
//                     coplanar: each facet is a whole facet of the exact hull.
// All predicates are exact and unperturbed (predicates.hpp *_exact).
#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

#include "predicates/predicates.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/dimension.hpp"
#include "reference/locations.hpp"

namespace flipflop::certify {

namespace {

std::string poly_str(const std::vector<Index>& f) {
  std::string s = "(";
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? "," : "") + std::to_string(f[i]);
  return s + ")";
}

}  // namespace

Report hull3_strict(const PointSet& ps, const std::vector<Index>& extreme,
                    const std::vector<std::vector<Index>>& facets, bool triangulated) {
  if (ps.dim != 3) return Report::fail("input-dimension", "hull3 needs 3D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  auto P = [&](Index v) { return ps.point(v); };

  // ---- strict-indices ---------------------------------------------------------
  std::vector<char> is_extreme(n, 0), used(n, 0);
  for (std::size_t i = 0; i < extreme.size(); ++i) {
    if (extreme[i] >= n)
      return Report::fail("strict-indices", "extreme point " + std::to_string(extreme[i]) + " but the input has " +
                                                std::to_string(n) + " points");
    if (i > 0 && extreme[i] <= extreme[i - 1])
      return Report::fail("strict-indices", "the extreme points are not strictly increasing at " +
                                                std::to_string(extreme[i]));
    is_extreme[extreme[i]] = 1;
  }
  if (facets.size() < 4)
    return Report::fail("strict-indices", "a 3D hull has at least 4 facets, the output has " +
                                              std::to_string(facets.size()));
  for (const auto& f : facets) {
    if (f.size() < 3) return Report::fail("strict-indices", "facet " + poly_str(f) + " has fewer than 3 vertices");
    if (triangulated && f.size() != 3)
      return Report::fail("strict-indices", "facet " + poly_str(f) + " of the triangulated view is not a triangle");
    std::vector<Index> s = f;
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end())
      return Report::fail("strict-indices", "facet " + poly_str(f) + " repeats a vertex");
    for (Index v : f) {
      if (v >= n || !is_extreme[v])
        return Report::fail("strict-indices", "facet " + poly_str(f) + " has vertex " + std::to_string(v) +
                                                  ", which is not a listed extreme point");
      used[v] = 1;
    }
  }
  for (Index v : extreme)
    if (!used[v]) return Report::fail("strict-indices", "extreme point " + std::to_string(v) + " is in no facet");

  // ---- smallest-index -----------------------------------------------------------
  {
    const SmallestAtLocation first(ps);
    for (Index v : extreme)
      if (const Index s = first(v); s != v)
        return Report::fail("smallest-index", "extreme point " + std::to_string(v) + " has the location of point " +
                                                  std::to_string(s) + ", a smaller index");
  }

  // ---- facet-polygon --------------------------------------------------------------
  std::vector<Triangle> fan;
  for (const auto& f : facets) {
    const std::size_t k = f.size();
    if (pred::collinear3_exact(P(f[0]), P(f[1]), P(f[2])))
      return Report::fail("facet-polygon", "the first three vertices of facet " + poly_str(f) + " are collinear");
    for (std::size_t i = 3; i < k; ++i)
      if (pred::orient3d_exact(P(f[0]), P(f[1]), P(f[2]), P(f[i])) != 0)
        return Report::fail("facet-polygon", "facet " + poly_str(f) + " is not planar: vertex " +
                                                 std::to_string(f[i]) + " is off the plane of its first three");
    Index q = static_cast<Index>(n);
    int side = 0;
    for (Index v : extreme)
      if ((side = pred::orient3d_exact(P(f[0]), P(f[1]), P(f[2]), P(v))) != 0) {
        q = v;
        break;
      }
    if (q == n) return Report::fail("facet-polygon", "every extreme point lies in the plane of facet " + poly_str(f));
    if (side < 0)
      return Report::fail("facet-polygon", "extreme point " + std::to_string(q) + " lies on the outer side of facet " +
                                               poly_str(f) + " (inward orientation, or not a hull facet)");
    for (std::size_t i = 0; i < k; ++i) {
      const Index a = f[(i + k - 1) % k], b = f[i], c = f[(i + 1) % k];
      if (pred::orient3d_exact(P(a), P(b), P(c), P(q)) <= 0)
        return Report::fail("facet-polygon", "the corner at vertex " + std::to_string(b) + " of facet " + poly_str(f) +
                                                 " is not strictly convex (counter-clockwise seen from outside)");
    }
    for (std::size_t j = 1; j + 1 < k; ++j) {
      if (pred::orient3d_exact(P(f[0]), P(f[j]), P(f[j + 1]), P(q)) <= 0)
        return Report::fail("facet-polygon", "facet " + poly_str(f) + " winds more than once around its vertex " +
                                                 std::to_string(f[0]));
      fan.push_back({f[0], f[j], f[j + 1]});
    }
  }

  // ---- the fan is the boundary of conv(S) --------------------------------------------
  if (Report r = hull3(ps, fan, Level::exact); !r.ok) return r;

  // ---- strictly-extreme ---------------------------------------------------------------
  std::vector<std::vector<std::uint32_t>> around(n);
  for (std::uint32_t i = 0; i < facets.size(); ++i)
    for (Index v : facets[i]) around[v].push_back(i);
  auto coplanar = [&](const std::vector<Index>& F, const std::vector<Index>& G) {
    for (Index g : G)
      if (pred::orient3d_exact(P(F[0]), P(F[1]), P(F[2]), P(g)) != 0) return false;
    return true;
  };
  for (Index v : extreme) {
    std::vector<std::uint32_t> planes;  // one facet per distinct plane through v
    for (std::uint32_t i : around[v]) {
      bool fresh = true;
      for (std::uint32_t j : planes) fresh = fresh && !coplanar(facets[j], facets[i]);
      if (fresh) planes.push_back(i);
      if (planes.size() == 3) break;
    }
    if (planes.size() < 3)
      return Report::fail("strictly-extreme", "vertex " + std::to_string(v) + " lies in " +
                                                  (planes.size() == 1 ? std::string("one facet plane (inside a facet)")
                                                                      : std::string("two facet planes (inside an edge)")) +
                                                  " of the hull, so it is not strictly extreme");
  }

  // ---- maximal-facets ---------------------------------------------------------------------
  if (!triangulated) {
    std::unordered_map<std::uint64_t, std::uint32_t> edge;  // directed polygon edge -> facet
    for (std::uint32_t i = 0; i < facets.size(); ++i)
      for (std::size_t j = 0; j < facets[i].size(); ++j)
        edge[detail::edge_key(facets[i][j], facets[i][(j + 1) % facets[i].size()])] = i;
    for (std::uint32_t i = 0; i < facets.size(); ++i)
      for (std::size_t j = 0; j < facets[i].size(); ++j) {
        const Index a = facets[i][j], b = facets[i][(j + 1) % facets[i].size()];
        const auto it = edge.find(detail::edge_key(b, a));
        if (it == edge.end())  // the fan passed the closed-surface check, so this is a fan diagonal
          return Report::fail("maximal-facets", "edge " + detail::edge_str(a, b) + " of facet " + poly_str(facets[i]) +
                                                    " is a diagonal of another facet");
        if (it->second > i && coplanar(facets[i], facets[it->second]))
          return Report::fail("maximal-facets", "facets " + poly_str(facets[i]) + " and " +
                                                    poly_str(facets[it->second]) +
                                                    " are coplanar: one facet of the exact hull split in two");
      }
  }
  return Report::pass();
}

}  // namespace flipflop::certify

// certify_hull3.cpp — certify::hull3 with parallel checks, and the witness-
// checked certifier of the multithreaded ffHull (certify_hull3.hpp).
#include "kernels_cpu/hull3/certify_hull3.hpp"

#include <string>

#include "kernels_cpu/parallel.hpp"
#include "predicates/predicates.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/certify/certify_hull3_surface.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/certify/inner_box.hpp"

namespace flipflop::cpu {

certify::Report certify_hull3(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                              int threads) {
  return certify_in_parallel(ps, threads,
                             [&](const certify::Speedups& s) { return certify::hull3(ps, tris, level, s); });
}

namespace {

using certify::Report;
using certify::detail::tri_str;

// witness-size, witness-output, witness-interior-point (certify_hull3.hpp)
Report check_witness_frame(const PointSet& ps, const std::vector<Triangle>& tris, const Hull3Witness& w) {
  const std::size_t n = ps.size();
  if (w.facet.size() != n)
    return Report::fail("witness-size", "the witness names facets for " + std::to_string(w.facet.size()) +
                                            " points, the input has " + std::to_string(n));
  if (!w.beneath.empty() && w.beneath.size() != n)
    return Report::fail("witness-size", "the witness has records for " + std::to_string(w.beneath.size()) +
                                            " points, the input has " + std::to_string(n));
  if (w.facets.size() != tris.size())
    return Report::fail("witness-output", "the output has " + std::to_string(tris.size()) +
                                              " facets, the witness is about " + std::to_string(w.facets.size()));
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (tris[t] != w.facets[t])
      return Report::fail("witness-output", "facet " + std::to_string(t) + " of the output is " + tri_str(tris[t]) +
                                                ", the witness' is " + tri_str(w.facets[t]));
  const std::string tet = "(" + std::to_string(w.tet[0]) + "," + std::to_string(w.tet[1]) + "," +
                          std::to_string(w.tet[2]) + "," + std::to_string(w.tet[3]) + ")";
  for (int i = 0; i < 4; ++i) {
    if (w.tet[i] >= n)
      return Report::fail("witness-interior-point", "the interior point's tetrahedron " + tet + " names point " +
                                                        std::to_string(w.tet[i]) + " but the input has " +
                                                        std::to_string(n) + " points");
    for (int j = 0; j < i; ++j)
      if (w.tet[i] == w.tet[j])
        return Report::fail("witness-interior-point", "the interior point's tetrahedron " + tet + " repeats a point");
  }
  if (pred::orient3d_exact(ps.point(w.tet[0]), ps.point(w.tet[1]), ps.point(w.tet[2]), ps.point(w.tet[3])) == 0)
    return Report::fail("witness-interior-point", "the interior point's tetrahedron " + tet +
                                                      " is flat (its four points are coplanar)");
  return Report::pass();
}

}  // namespace

certify::Report certify_hull3_witnessed(const PointSet& ps, const std::vector<Triangle>& tris,
                                        certify::Level level, const Hull3Witness& w, int threads) {
  if (ps.dim != 3) return Report::fail("input-dimension", "hull3 needs 3D points");
  if (Report r = check_witness_frame(ps, tris, w); !r.ok) return r;
  // one thread below 4096 points by default (1 / 2 threads, uniform cube:
  // 3375 points 0.16 / 0.18 ms, 10^4 0.33 / 0.26 ms)
  threads = threads_for_size(threads, ps.size(), 4096);
  return certify_in_parallel(ps, threads, [&](const certify::Speedups& sp) -> Report {
    certify::detail::Hull3Surface ck;
    if (Report r = certify::detail::hull3_surface(ps, tris, level, sp, &w.tet, ck); !r.ok) return r;
    // the inner ball, verified exactly against every facet; only now, with
    // the surface certified convex, does that put it inside the hull
    const certify::detail::InnerBall<3> ball =
        w.ball ? certify::detail::InnerBall<3>(ps, tris, sp.for_range) : certify::detail::InnerBall<3>();
    // the witness' box, likewise: every corner strictly inside every facet
    const bool box = !w.box.empty() && certify::detail::box_inside_facets(ps, tris, w.box, sp.for_range);
    const std::size_t n = ps.size();
    // witness-tetrahedron: p strictly inside the tetrahedron (s, a, b, c) of
    // its record under the perturbation (four orient3d; that s is on the
    // inner side of (a, b, c) follows from them), a, b, c anchored (no record
    // of their own); why this suffices: certify_hull3.hpp
    auto check_record = [&](Index p) -> Report {
      if (w.beneath[p] >= w.made.size())
        return Report::fail("witness-tetrahedron", "point " + std::to_string(p) + " is not a vertex and its record " +
                                                       "names triangle " + std::to_string(w.beneath[p]) +
                                                       " but the witness has " + std::to_string(w.made.size()));
      const Triangle t = w.record(p);
      const auto fail = [&](const std::string& why) {
        return Report::fail("witness-tetrahedron", "point " + std::to_string(p) + " is not a vertex and its record " +
                                                       tri_str(t) + " " + why);
      };
      for (int k = 0; k < 3; ++k) {
        if (t[k] >= n)
          return fail("names point " + std::to_string(t[k]) + " but the input has " + std::to_string(n) + " points");
        if (t[k] == p || t[k] == t[(k + 1) % 3]) return fail("repeats a point or names the point itself");
      }
      for (int k = 0; k < 3; ++k)
        if (w.has_record(t[k]))
          return fail("names point " + std::to_string(t[k]) + ", which is itself certified by a record");
      for (Index q : w.tet)
        if (q == p) return fail("is for one of the interior point's four points");
      for (int k = 0; k < 3; ++k)
        if (ck.side(t[k], t[(k + 1) % 3], p) >= 0)
          return fail("does not hold the point: it is not strictly inside the plane through s and edge " +
                      certify::detail::edge_str(t[k], t[(k + 1) % 3]) + " (under the perturbation)");
      if (pred::fast::orient3d(ck.f, ck.pt(t[0]), ck.pt(t[1]), ck.pt(t[2]), ck.pt(p)) <= 0)
        return fail("does not hold the point: it is not strictly on the inner side of the record's plane (under "
                    "the perturbation)");
      return Report::pass();
    };
    // the point's first failing condition, or pass
    auto check = [&](Index p) -> Report {
      const std::uint32_t f = w.facet[p];
      if (f == kNoFacet && w.has_record(p)) return check_record(p);
      if (f == kNoFacet) {
        const double* x = ps.point(p);
        if ((box && w.box.strictly_inside(x)) || ball.strictly_inside(x)) return Report::pass();
        const std::string why_box = w.box.empty() ? "the witness has no box"
                                    : !box         ? "the witness' box is not inside every facet"
                                                   : "it is not strictly inside the witness' box";
        return Report::fail("witness-facet", "point " + std::to_string(p) +
                                                 " is not a vertex, the witness names no facet and no record " +
                                                 "for it, " +
                                                 (w.ball ? "it is not strictly inside the verified inner ball"
                                                         : "the witness asks for no inner ball") +
                                                 ", and " + why_box);
      }
      if (f >= tris.size())
        return Report::fail("witness-facet", "the witness names facet " + std::to_string(f) + " for point " +
                                                 std::to_string(p) + " but the output has " +
                                                 std::to_string(tris.size()));
      const Triangle& t = tris[f];
      for (int k = 0; k < 3; ++k)
        if (ck.side(t[k], t[(k + 1) % 3], p) > 0)
          return Report::fail("witness-cone", "point " + std::to_string(p) + " is not in the cone of facet " +
                                                  tri_str(t) + " from the interior point (it is across the plane " +
                                                  "through the interior point and edge " +
                                                  certify::detail::edge_str(t[k], t[(k + 1) % 3]) + ")");
      if (ck.outside(t, p))
        return Report::fail("point-inside", "point " + std::to_string(p) +
                                                (ck.canonical ? " is not a vertex and not strictly inside facet "
                                                              : " lies strictly outside facet ") +
                                                tri_str(t) + (ck.canonical ? " under the perturbation" : ""));
      return Report::pass();
    };
    const std::size_t bad = certify::detail::smallest_failing(n, sp.for_range, [&](std::size_t p) {
      return !ck.is_vertex[p] && !check(static_cast<Index>(p)).ok;
    });
    return bad < n ? check(static_cast<Index>(bad)) : Report::pass();
  });
}

}  // namespace flipflop::cpu

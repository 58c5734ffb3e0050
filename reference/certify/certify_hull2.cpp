// certify_hull2.cpp — exact certification of a 2D convex hull (a vertex cycle).
//
// Conditions, checked in this order (the first violated one is reported):
//   input-dimension   the points span the plane
//   vertex-indices    indices in range, none repeated, at least 3
//   canonical-form    (canonical) the cycle starts at its smallest index
//   convex-turn       every turn is convex: exact level — left or straight
//                     ahead (never folding back), after merging consecutive
//                     vertices at one location; canonical — strictly left
//                     under the perturbation
//   winds-once        the edge directions turn through exactly 2π
//   point-inside      every point is on the inner side of (or on) the edge of
//                     the fan sector that contains it; canonical: strictly
//                     inside for every point that is not a vertex. The sector
//                     is guessed from a pseudo-angle bucket table and the
//                     guess verified exactly (the two rays around p); only an
//                     unverified guess costs the exact binary search. The
//                     points may be checked in parallel (Speedups): the
//                     smallest failing index is reported either way.
// A polygon with convex turns that winds once is convex; with all points on
// the inner side of its edges its vertices span conv(S), so every extreme
// point is a vertex and every vertex lies on the boundary.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/dimension.hpp"
#include "reference/pseudo_angle.hpp"

namespace flipflop::certify {

namespace {

using detail::edge_str;

struct Hull2Checker {
  const PointSet& ps;
  bool canonical;
  const pred::StaticFilter* filter = nullptr;

  const double* P(Index i) const { return ps.point(i); }
  bool same_location(Index a, Index b) const { return P(a)[0] == P(b)[0] && P(a)[1] == P(b)[1]; }
  // orientation used for the geometric conditions (the static filter decides
  // only non-zero exact signs, which the perturbation keeps)
  int orient(Index a, Index b, Index c) const {
    if (filter) {
      const double* p[3] = {P(a), P(b), P(c)};
      if (int s = pred::static_sign<3>(*filter, p, nullptr)) return s;
    }
    return canonical ? pred::orient2d({a, P(a)}, {b, P(b)}, {c, P(c)})
                     : pred::orient2d_exact(P(a), P(b), P(c));
  }
  // Is b "above" a in the sense of the half-turn classification of directions?
  // Exact level: compares (y, x) exactly. Canonical: compares perturbed y.
  bool up(Index a, Index b) const {
    if (canonical) return pred::compare_sos({b, P(b)}, {a, P(a)}, 1) > 0;
    if (P(b)[1] != P(a)[1]) return P(b)[1] > P(a)[1];
    return P(b)[0] > P(a)[0];
  }
};

}  // namespace

Report hull2(const PointSet& ps, const std::vector<Index>& cycle, Level level) {
  return hull2(ps, cycle, level, Speedups{});
}

Report hull2(const PointSet& ps, const std::vector<Index>& cycle, Level level, const Speedups& speedups) {
  if (ps.dim != 2) return Report::fail("input-dimension", "hull2 needs 2D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  const bool canonical = level == Level::canonical;
  pred::StaticFilter own;
  const pred::StaticFilter* filter = speedups.filter;
  if (!filter && speedups.make_filter) own = speedups.make_filter({}), filter = &own;
  Hull2Checker ck{ps, canonical, filter};

  // vertex-indices
  if (cycle.size() < 3)
    return Report::fail("vertex-indices", "a hull of 2D points has at least 3 vertices, the output has " +
                                              std::to_string(cycle.size()));
  std::vector<char> is_vertex(n, 0);
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    Index v = cycle[k];
    if (v >= n)
      return Report::fail("vertex-indices", "vertex " + std::to_string(k) + " names point " + std::to_string(v) +
                                                " but the input has " + std::to_string(n) + " points");
    if (is_vertex[v]) return Report::fail("vertex-indices", "point " + std::to_string(v) + " is listed twice");
    is_vertex[v] = 1;
  }
  if (canonical && cycle[0] != *std::min_element(cycle.begin(), cycle.end()))
    return Report::fail("canonical-form", "the cycle does not start at its smallest index");

  // Working cycle: at the exact level, consecutive vertices at one location are
  // one corner of the polygon.
  std::vector<Index> L;
  if (canonical) {
    L = cycle;
  } else {
    for (Index v : cycle)
      if (L.empty() || !ck.same_location(L.back(), v)) L.push_back(v);
    while (L.size() > 1 && ck.same_location(L.back(), L.front())) L.pop_back();
    if (L.size() < 3)
      return Report::fail("convex-turn", "the vertices occupy fewer than 3 distinct locations");
  }
  const std::size_t m = L.size();

  // convex-turn
  for (std::size_t k = 0; k < m; ++k) {
    Index a = L[(k + m - 1) % m], b = L[k], c = L[(k + 1) % m];
    int o = ck.orient(a, b, c);
    std::string where = "at vertex " + std::to_string(b) + " (between " + std::to_string(a) + " and " +
                        std::to_string(c) + ")";
    if (canonical && o <= 0)
      return Report::fail("convex-turn", "the turn " + where + " is not strictly convex under the perturbation");
    if (o < 0) return Report::fail("convex-turn", "the polygon turns clockwise " + where);
    if (o == 0 && pred::dot2d_exact(ck.P(a), ck.P(b), ck.P(c)) <= 0)
      return Report::fail("convex-turn", "the polygon folds back " + where);
  }

  // winds-once: edge direction in the upper half-turn [0, π) ↔ "up"
  std::vector<Index> pos(m);
  for (std::size_t k = 0; k < m; ++k) pos[k] = static_cast<Index>(k);
  int turns = detail::count_turns(pos, true, [&](Index k) { return ck.up(L[k], L[(k + 1) % m]) ? 0 : 1; });
  if (turns != 1)
    return Report::fail("winds-once", "the polygon winds " + std::to_string(turns) + " times around its interior");

  // point-inside: fan from a corner v0, sectors found by binary search on the
  // orientation of the fan rays (monotone since the fan spans less than a
  // half-turn). At the exact level the fan runs over the strictly convex
  // corners only: the same region (the straight vertices lie on its edges,
  // checked above), and no two fan rays coincide — with collinear boundary
  // vertices on v0's edges, a point on such a ray beyond the last of them
  // would otherwise be tested against a degenerate sector.
  if (!canonical) {
    std::vector<Index> corners;
    for (std::size_t k = 0; k < m; ++k)
      if (ck.orient(L[(k + m - 1) % m], L[k], L[(k + 1) % m]) > 0) corners.push_back(L[k]);
    L.swap(corners);
  }
  const std::size_t mc = L.size();
  const Index v0 = L[0];
  const int strict = canonical ? 0 : -1;  // smallest accepted orientation is strict+1
  // The sector of p: the largest k in [1, mc-2] with orient(v0, L[k], p) >= 0.
  // First a guess from floating point, accepted when exactly
  // orient(v0, L[k], p) >= 0 and (k = mc-2 or orient(v0, L[k+1], p) < 0): by
  // the monotonicity of the fan rays that k is the exact search's answer, run
  // only when the guess fails. The guess: the rays' pseudo-angles around v0
  // measured from the first ray (increasing along the fan, which spans less
  // than a half-turn) and a table of 4 mc buckets over them.
  const double* o = ck.P(v0);
  const double first_ray = pseudo_angle(ck.P(L[1])[0] - o[0], ck.P(L[1])[1] - o[1]);
  auto turn = [&](Index q) {
    const double a = pseudo_angle(ck.P(q)[0] - o[0], ck.P(q)[1] - o[1]) - first_ray;
    return a < 0 ? a + 4 : a;
  };
  std::vector<double> ang(mc, 0.0);
  bool table = true;
  for (std::size_t k = 2; k < mc; ++k) {
    ang[k] = turn(L[k]);
    table = table && ang[k] > ang[k - 1] && ang[k] < 4;  // false also on NaN (overflow)
  }
  const std::size_t buckets = 4 * mc;
  const double scale = table ? static_cast<double>(buckets) / ang[mc - 1] : 0.0;
  table = table && std::isfinite(scale);  // a subnormal fan angle overflows the scale: no table
  std::vector<std::size_t> bucket_first(table ? buckets : 0);
  for (std::size_t b = 0; b < bucket_first.size(); ++b) {
    const auto it = std::upper_bound(ang.begin() + 1, ang.begin() + static_cast<long>(mc - 1),
                                     static_cast<double>(b) / scale);
    bucket_first[b] = std::max<std::size_t>(1, static_cast<std::size_t>(it - ang.begin()) - 1);
  }
  auto sector = [&](Index p) {
    std::size_t k = 1;
    const double a = table ? turn(p) : -1.0;
    if (a >= 0 && a <= ang[mc - 1]) {
      const double x = a * scale;  // in [0, buckets], compared before the conversion
      k = bucket_first[x < static_cast<double>(buckets) ? static_cast<std::size_t>(x) : buckets - 1];
      while (k < mc - 2 && ang[k + 1] <= a) ++k;
    }
    if (ck.orient(v0, L[k], p) >= 0 && (k == mc - 2 || ck.orient(v0, L[k + 1], p) < 0)) return k;
    std::size_t lo = 1, hi = mc - 2;
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (ck.orient(v0, L[mid], p) >= 0) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  };
  // Points strictly inside an exactly verified inner disk pass at once
  // (inner_ball.hpp; the polygon L is certified convex above).
  std::size_t candidates = 0;
  for (Index p = 0; p < n; ++p) candidates += !is_vertex[p];
  std::vector<std::array<Index, 2>> edges(mc);
  for (std::size_t k = 0; k < mc; ++k) edges[k] = {L[k], L[(k + 1) % mc]};
  const detail::InnerBall<2> ball =
      candidates >= 8 * mc ? detail::InnerBall<2>(ps, edges, speedups.for_range) : detail::InnerBall<2>();
  // The edge p is not inside (ea -> eb), or false when p passes.
  auto fails = [&](Index p, Index& ea, Index& eb) {
    if (ball.strictly_inside(ck.P(p))) return false;
    if (ck.orient(v0, L[1], p) <= strict) return ea = v0, eb = L[1], true;
    if (-ck.orient(v0, L[mc - 1], p) <= strict) return ea = L[mc - 1], eb = v0, true;
    const std::size_t k = sector(p);
    if (ck.orient(L[k], L[k + 1], p) <= strict) return ea = L[k], eb = L[k + 1], true;
    return false;
  };
  const std::size_t bad = detail::smallest_failing(n, speedups.for_range, [&](std::size_t i) {
    Index a, b;
    return !is_vertex[i] && fails(static_cast<Index>(i), a, b);
  });
  if (const auto p = static_cast<Index>(bad); bad < n) {
    Index a = 0, b = 0;
    fails(p, a, b);
    return Report::fail("point-inside", "point " + std::to_string(p) +
                                            (canonical ? " is not strictly inside" : " lies strictly outside") +
                                            " edge " + edge_str(a, b) + (canonical ? " under the perturbation" : ""));
  }
  return Report::pass();
}

BallTest<2> inner_disk(const PointSet& ps, const std::vector<Index>& ccw) {
  if (ccw.size() < 3) return {};
  std::vector<std::array<Index, 2>> edges(ccw.size());
  for (std::size_t k = 0; k < ccw.size(); ++k) edges[k] = {ccw[k], ccw[(k + 1) % ccw.size()]};
  return detail::InnerBall<2>(ps, edges, decltype(Speedups{}.for_range){}).test();  // sequential
}

}  // namespace flipflop::certify

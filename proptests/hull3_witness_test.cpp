// hull3_witness_test.cpp — the witness of the multithreaded ffHull
// (kernels_cpu/hull3/hull3_witness.hpp) and the witness-checked certifier
// (cpu::certify_hull3_witnessed, kernels_cpu/hull3/certify_hull3.hpp).
//
// Acceptance: on every 3D generator family (degenerate ones included) and on
// the degenerate mixers, at 1, 2 and 8 threads, the kernel's output with its
// witness is certified at both levels, the witness-free certifier
// (certify::hull3, the independent oracle: it locates every point by its own
// walk) agrees, and the witness does not depend on the thread count.
//
// Rejection, each with its named condition: a facet whose cone does not
// contain the point (witness-cone), a facet index out of range and a
// non-vertex without a facet (witness-facet), a hull vertex dropped from the
// output with the facet whose cone holds it named (point-inside: it is above
// that facet; certify::hull3 names the same condition), a non-convex edge
// (convex-edge), a bad interior point (repeated, out of range, coplanar:
// witness-interior-point), an output that is not the witnessed facet set
// (witness-output) and a witness of the wrong size (witness-size); and
// corrupted early-removal records (witness-tetrahedron): a tetrahedron that
// does not hold the point, one turned inside out, a corner that has a record
// itself, a repeated or out-of-range corner, a record for one of s's points.
// A record dropped, with no facet and no ball, is witness-facet.
// The box (round 0's, handed on for uniform cube points): points that rely on
// it are accepted, and a box grown past a facet, or shrunk so that such a
// point falls outside, is witness-facet.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/canonical.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_hull3_surface.hpp"
#include "reference/certify/inner_ball.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};

struct Witnessed {
  std::vector<Triangle> tris;
  cpu::Hull3Witness w;
};

Witnessed run(const PointSet& ps, int threads) {
  Witnessed r;
  cpu::Hull3Options o;
  o.threads = threads;
  o.witness = &r.w;
  r.tris = cpu::hull3_ffhull(ps, o);
  return r;
}

bool same_box(const certify::BoxTest3& a, const certify::BoxTest3& b) {
  for (int j = 0; j < 3; ++j)
    if (a.lo[j] != b.lo[j] || a.hi[j] != b.hi[j]) return false;
  return true;
}

// The kernel's output and witness at every thread count: the output is the
// one without a witness, the witness the same, both levels certified, and
// certify::hull3 agrees. False (nothing checked) for input that does not span
// R^3.
template <class Check>
bool check_accepts(const PointSet& ps, const Check& check) {
  if (!dimension_problem(ps).empty()) return false;
  const std::vector<Triangle> plain = cpu::hull3_ffhull(ps);
  const Witnessed first = run(ps, 1);
  for (int t : kThreads) {
    const Witnessed r = t == 1 ? first : run(ps, t);
    check(r.tris == plain);
    check(r.w.facets == r.tris);
    check(r.w.tet == first.w.tet && r.w.facet == first.w.facet && r.w.beneath == first.w.beneath &&
          r.w.made == first.w.made && r.w.ball == first.w.ball && same_box(r.w.box, first.w.box));
    check(r.w.beneath.size() == ps.size());
    for (certify::Level level : {certify::Level::canonical, certify::Level::exact}) {
      const certify::Report rep = cpu::certify_hull3_witnessed(ps, r.tris, level, r.w, t);
      if (!rep.ok) std::cerr << "rejected: " << rep.message() << "\n";
      check(rep.ok);
    }
  }
  check(certify::hull3(ps, plain, certify::Level::canonical).ok);
  return true;
}

void rc_accepts(const PointSet& ps) {
  check_accepts(ps, [](bool ok) { RC_ASSERT(ok); });
}

certify::Report witnessed(const PointSet& ps, const std::vector<Triangle>& tris, const cpu::Hull3Witness& w,
                          certify::Level level = certify::Level::canonical) {
  return cpu::certify_hull3_witnessed(ps, tris, level, w, 2);
}

// the first non-vertex that the witness gives a facet
Index witnessed_point(const cpu::Hull3Witness& w) {
  Index p = 0;
  while (p < w.facet.size() && w.facet[p] == cpu::kNoFacet) ++p;
  REQUIRE(p < w.facet.size());
  return p;
}

// the first facet whose cone from s holds q, by the certifier's own
// predicate (over all facets); facets.size() if none
std::uint32_t cone_of(const certify::detail::Hull3Surface& ck, const std::vector<Triangle>& facets, Index q) {
  std::uint32_t f = 0;
  while (f < facets.size() && (ck.side(facets[f][0], facets[f][1], q) > 0 ||
                               ck.side(facets[f][1], facets[f][2], q) > 0 ||
                               ck.side(facets[f][2], facets[f][0], q) > 0))
    ++f;
  return f;
}

std::size_t records(const cpu::Hull3Witness& w) {
  std::size_t r = 0;
  for (std::size_t p = 0; p < w.beneath.size(); ++p) r += w.has_record(p);
  return r;
}

PointSet generated(const char* fam, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  return gen::generate(fam, n, o);
}

}  // namespace

TEST_CASE("hull3 witness: degenerate and random small sets are certified with the witness at 1, 2, 8 threads "
          "(shrinking)",
          "[hull3_witness]") {
  test::prop_scaled("degenerate sets of 4..60 points: witnessed certifier accepts, agrees with certify::hull3", 4,
                    [] { rc_accepts(*test::degenerate_points(3, 4, 60, false)); });
}

TEST_CASE("hull3 witness: every generator family up to 3000 points is certified with the witness (shrinking)",
          "[hull3_witness]") {
  test::prop_scaled("family sets of 4..3000 points: witnessed certifier accepts at 1, 2, 8 threads", 20,
                    [] { rc_accepts(*test::thinned(test::family_points(3, 4, 3000, false))); });
}

TEST_CASE("hull3 witness: deterministic sweep over the families, sizes and thread counts", "[hull3_witness][long]") {
  std::size_t cases = 0, balls = 0, with_records = 0;
  test::for_each_family_input(3, {4, 30, 3000}, 2,
                              [&](const std::string& fam, std::size_t n, std::uint64_t seed, const PointSet& ps) {
                                INFO(fam << " n=" << n << " seed=" << seed);
                                if (check_accepts(ps, [](bool ok) { REQUIRE(ok); })) ++cases;
                                if (dimension_problem(ps).empty()) {
                                  const Witnessed r = run(ps, 2);
                                  balls += r.w.ball;
                                  with_records += records(r.w) > 0;
                                }
                              });
  std::cout << "hull3 witness sweep: " << cases << " inputs certified with their witness at 1, 2, 8 threads ("
            << balls << " with the inner ball, " << with_records << " with early-removal records)\n";
  REQUIRE(cases >= 13 * 3);
  REQUIRE(balls > 0);
  REQUIRE(with_records > 0);
}

// Flip-flop in rounds (ffhull.hpp) leaves the same hull, hence the same
// witness (records come from the construction, facets from walks over the
// same final hull), and it is certified.
TEST_CASE("hull3 witness: flip-flop in rounds gives the FIFO run's output and witness", "[hull3_witness]") {
  for (const char* fam : {"ball", "sphere", "grid3", "sphere-lattice", "duplicates3", "jitter3"}) {
    INFO(fam);
    const PointSet ps = generated(fam, 3000, 4);
    Witnessed by[2];
    const cpu::FlipFlopRun runs[2] = {cpu::FlipFlopRun::fifo, cpu::FlipFlopRun::rounds};
    for (int k = 0; k < 2; ++k) {
      cpu::Hull3Options o;
      o.threads = 2;
      o.flip_flop = runs[k];
      o.witness = &by[k].w;
      by[k].tris = cpu::hull3_ffhull(ps, o);
    }
    REQUIRE(by[1].tris == by[0].tris);
    REQUIRE(by[1].w.facet == by[0].w.facet);
    REQUIRE(by[1].w.beneath == by[0].w.beneath);
    REQUIRE(by[1].w.tet == by[0].w.tet);
    const certify::Report rep = witnessed(ps, by[1].tris, by[1].w);
    INFO(rep.message());
    REQUIRE(rep.ok);
  }
}

TEST_CASE("hull3 witness: a wrong facet for a point is rejected", "[hull3_witness]") {
  const PointSet ps = generated("ball", 2000, 3);
  const Witnessed r = run(ps, 2);
  REQUIRE(witnessed(ps, r.tris, r.w).ok);
  const Index p = witnessed_point(r.w);
  SECTION("a facet whose cone does not contain the point") {
    // under the perturbation the cones from s do not overlap: any other facet
    cpu::Hull3Witness w = r.w;
    w.facet[p] = (w.facet[p] + 1) % static_cast<std::uint32_t>(r.tris.size());
    const certify::Report rep = witnessed(ps, r.tris, w);
    INFO(rep.message());
    REQUIRE(rep.condition == "witness-cone");
    REQUIRE(rep.detail.find("point " + std::to_string(p) + " ") == 0);
  }
  SECTION("a facet index out of range") {
    cpu::Hull3Witness w = r.w;
    w.facet[p] = static_cast<std::uint32_t>(r.tris.size());
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-facet");
  }
  SECTION("no facet for a non-vertex (no inner ball)") {
    cpu::Hull3Witness w = r.w;
    REQUIRE(!w.ball);
    w.facet[p] = cpu::kNoFacet;
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-facet");
  }
  SECTION("no facet for a non-vertex outside the inner ball") {
    const PointSet big = generated("ball", 20000, 3);
    Witnessed b = run(big, 2);
    REQUIRE(b.w.ball);
    REQUIRE(witnessed(big, b.tris, b.w).ok);
    const Index q = witnessed_point(b.w);  // not strictly inside the ball, or it would have no facet
    b.w.facet[q] = cpu::kNoFacet;
    REQUIRE(witnessed(big, b.tris, b.w).condition == "witness-facet");
  }
}

// The early-removal records (hull3_witness.hpp: `beneath`), each corruption
// with its named condition; the point named is the corrupted one (the
// certifier reports the smallest failing point, every other record is intact).
TEST_CASE("hull3 witness: a corrupted early-removal record is rejected", "[hull3_witness]") {
  const PointSet ps = generated("ball", 2000, 3);
  const Witnessed r = run(ps, 2);
  REQUIRE(witnessed(ps, r.tris, r.w).ok);
  REQUIRE(!r.w.ball);  // every removal in the rounds keeps its record
  // (round 0's inner ball — ffhull.cpp: inner_region — drops about half of
  // the points before any cone, without a record; the rest are many)
  REQUIRE(records(r.w) > ps.size() / 4);
  const auto expect = [&](const cpu::Hull3Witness& w, Index p, const std::string& what,
                          certify::Level level = certify::Level::canonical) {
    const certify::Report rep = witnessed(ps, r.tris, w, level);
    INFO(rep.message());
    REQUIRE(rep.condition == "witness-tetrahedron");
    REQUIRE(rep.detail.find("point " + std::to_string(p) + " ") == 0);
    REQUIRE(rep.detail.find(what) != std::string::npos);
  };
  // s, approximately: the centroid of the witness' tetrahedron
  double sx = 0;
  for (Index q : r.w.tet) sx += ps.point(q)[0] / 4;
  const auto x = [&](Index q) { return ps.point(q)[0]; };
  Index p = 0;
  while (!r.w.has_record(p)) ++p;
  const Triangle rec = r.w.record(p);
  cpu::Hull3Witness w = r.w;
  // p's record replaced by triangle t (appended to the witness' triangles)
  const auto set_record = [](cpu::Hull3Witness& v, Index q, const Triangle& t) {
    v.beneath[q] = static_cast<std::uint32_t>(v.made.size());
    v.made.push_back(t);
  };
  SECTION("a tetrahedron that does not hold the point") {
    // a record point right of s gets a record all of whose corners lie left
    // of s (with a margin, in doubles): the closed tetrahedron with s lies in
    // x <= sx, the point does not
    Index right = 0, left = 0;
    while (right < ps.size() && !(r.w.has_record(right) && x(right) > sx + 0.1)) ++right;
    const auto left_of_s = [&](Index q) {
      if (!r.w.has_record(q)) return false;
      for (Index c : r.w.record(q))
        if (!(x(c) < sx - 0.1)) return false;
      return true;
    };
    while (left < ps.size() && !left_of_s(left)) ++left;
    REQUIRE(right < ps.size());
    REQUIRE(left < ps.size());
    w.beneath[right] = r.w.beneath[left];
    expect(w, right, "does not hold the point");
    expect(w, right, "does not hold the point", certify::Level::exact);
  }
  SECTION("a tetrahedron turned inside out (s outside the record's plane)") {
    set_record(w, p, {rec[0], rec[2], rec[1]});
    expect(w, p, "does not hold the point");
  }
  SECTION("a triangle whose cone from s holds the point, nearer to s than the point") {
    // only the inner-side test (the fourth predicate) sees this: the point
    // furthest from s gets the record (a, b, c) of three other points around
    // its ray at under 0.6 of its distance from s. The closed tetrahedron
    // (s, a, b, c) lies in the ball about s through its furthest corner (in
    // doubles, with that margin), the point outside it. The corners are
    // given facets instead of their records (the facet whose cone holds
    // each, by the certifier's own predicate, as in the dropped-vertex test
    // below), so that they are anchored.
    certify::detail::Hull3Surface ck;
    REQUIRE(certify::detail::hull3_surface(ps, r.tris, certify::Level::canonical, certify::Speedups{}, &r.w.tet, ck)
                .ok);
    double sc[3] = {0, 0, 0};
    for (Index q : r.w.tet)
      for (int j = 0; j < 3; ++j) sc[j] += ps.point(q)[j] / 4;
    const auto dist = [&](Index q) {
      double d = 0;
      for (int j = 0; j < 3; ++j) d += (ps.point(q)[j] - sc[j]) * (ps.point(q)[j] - sc[j]);
      return std::sqrt(d);
    };
    Index far = p;
    for (Index q = 0; q < ps.size(); ++q)
      if (r.w.has_record(q) && dist(q) > dist(far)) far = q;
    const auto cosine = [&](Index q) {
      double c = 0;
      for (int j = 0; j < 3; ++j) c += (ps.point(q)[j] - sc[j]) * (ps.point(far)[j] - sc[j]);
      return c / (dist(q) * dist(far));
    };
    std::vector<Index> near;  // non-vertices at 0.2 to 0.6 of far's distance, by angle from far's ray
    for (Index q = 0; q < ps.size(); ++q)
      if (!ck.is_vertex[q] && dist(q) > 0.2 * dist(far) && dist(q) < 0.6 * dist(far)) near.push_back(q);
    std::sort(near.begin(), near.end(), [&](Index u, Index v) { return cosine(u) > cosine(v); });
    near.resize(std::min<std::size_t>(near.size(), 15));
    const auto holds = [&](const Triangle& t) {  // far in the cone of t from s, s inside
      return ck.facet_vs_s(t) > 0 && ck.side(t[0], t[1], far) < 0 && ck.side(t[1], t[2], far) < 0 &&
             ck.side(t[2], t[0], far) < 0;
    };
    Triangle rec2{};
    bool found = false;
    for (std::size_t i = 0; i < near.size() && !found; ++i)
      for (std::size_t j = i + 1; j < near.size() && !found; ++j)
        for (std::size_t k = j + 1; k < near.size() && !found; ++k)
          for (const Triangle& t : {Triangle{near[i], near[j], near[k]}, Triangle{near[i], near[k], near[j]}})
            if (!found && holds(t)) rec2 = t, found = true;
    REQUIRE(found);
    for (Index c : rec2) {
      REQUIRE(dist(c) < 0.6 * dist(far));
      w.beneath[c] = cpu::kNoFacet;
      w.facet[c] = cone_of(ck, r.tris, c);
    }
    REQUIRE(witnessed(ps, r.tris, w).ok);  // the corners anchored by facets: still the same hull
    set_record(w, far, rec2);
    expect(w, far, "not strictly on the inner side of the record's plane");
    expect(w, far, "not strictly on the inner side of the record's plane", certify::Level::exact);
  }
  SECTION("a corner that has a record itself") {
    Index q = 0;
    while (q == p || !r.w.has_record(q)) ++q;
    set_record(w, p, {q, rec[1], rec[2]});
    expect(w, p, "which is itself certified by a record");
  }
  SECTION("a repeated corner, the point as a corner, a corner out of range") {
    set_record(w, p, {rec[0], rec[0], rec[2]});
    expect(w, p, "repeats a point");
    set_record(w, p, {rec[0], rec[1], p});
    expect(w, p, "repeats a point");
    set_record(w, p, {rec[0], static_cast<Index>(ps.size()), rec[2]});
    expect(w, p, "names point " + std::to_string(ps.size()) + " but the input has");
  }
  SECTION("a record naming a triangle the witness does not have") {
    w.beneath[p] = static_cast<std::uint32_t>(w.made.size());
    expect(w, p, "names triangle " + std::to_string(w.made.size()) + " but the witness has");
  }
  SECTION("a record dropped: no facet, no record, no ball") {
    w.beneath[p] = cpu::kNoFacet;
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-facet");
  }
  SECTION("records for the wrong number of points") {
    w.beneath.pop_back();
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-size");
  }
}

// A record may not certify one of s's four points (s is in the hull because
// they are anchored): on a lattice the initial tetrahedron's points need not
// be vertices of the SoS hull; such a point gets another point's record.
TEST_CASE("hull3 witness: a record for one of the interior point's points is rejected", "[hull3_witness]") {
  bool found = false;
  for (std::uint64_t seed = 1; seed <= 20 && !found; ++seed) {
    const PointSet ps = generated("grid3", 2000, seed);
    const Witnessed r = run(ps, 2);
    certify::detail::Hull3Surface ck;
    REQUIRE(certify::detail::hull3_surface(ps, r.tris, certify::Level::canonical, certify::Speedups{}, &r.w.tet, ck)
                .ok);
    for (Index t : r.w.tet) {
      if (ck.is_vertex[t] || found) continue;
      Index q = 0;  // a record whose corners are not t
      while (q < ps.size() && !(r.w.has_record(q) && std::count(r.w.record(q).begin(), r.w.record(q).end(), t) == 0))
        ++q;
      if (q == ps.size()) continue;
      INFO("seed " << seed << ", point " << t);
      cpu::Hull3Witness w = r.w;
      w.facet[t] = cpu::kNoFacet;
      w.beneath[t] = r.w.beneath[q];
      const certify::Report rep = witnessed(ps, r.tris, w);
      INFO(rep.message());
      REQUIRE(rep.condition == "witness-tetrahedron");
      REQUIRE(rep.detail.find("is for one of the interior point's four points") != std::string::npos);
      found = true;
    }
  }
  REQUIRE(found);
}

// The hull of the input without one of its vertices v, indices mapped back:
// a convex, star-shaped surface that v lies above. The witness of that hull
// (the kernel's, on the rest, mapped back) names for v the facet whose cone
// from s contains it (found with the certifier's own predicate); the
// certifier must find v above it.
TEST_CASE("hull3 witness: a point declared inside that is outside (a hull vertex dropped) is rejected",
          "[hull3_witness]") {
  for (const char* fam : {"ball", "sphere", "cube", "grid3"}) {
    INFO(fam);
    const PointSet ps = generated(fam, 3000, 5);
    const std::vector<Triangle> hull = cpu::hull3_ffhull(ps);
    const Index v = hull[hull.size() / 2][1];
    std::vector<bool> keep(ps.size(), true);
    keep[v] = false;
    const PointSet rest = test::subset(ps, keep);
    std::vector<Index> back;
    for (Index i = 0; i < ps.size(); ++i)
      if (keep[i]) back.push_back(i);
    const Witnessed r = run(rest, 2);
    cpu::Hull3Witness w;
    for (Triangle t : r.tris) {
      for (Index& x : t) x = back[x];
      w.facets.push_back(t);
    }
    w.facets = canonical_triangles(w.facets);  // v < others may reorder; the map keeps the rotation
    std::vector<std::uint32_t> index_of(r.tris.size());
    for (std::size_t i = 0; i < r.tris.size(); ++i) {
      Triangle t = r.tris[i];
      for (Index& x : t) x = back[x];
      index_of[i] = static_cast<std::uint32_t>(
          std::lower_bound(w.facets.begin(), w.facets.end(), canonical_rotation(t)) - w.facets.begin());
    }
    for (int k = 0; k < 4; ++k) w.tet[k] = back[r.w.tet[k]];
    w.facet.assign(ps.size(), cpu::kNoFacet);
    for (Index i = 0; i < rest.size(); ++i)
      if (r.w.facet[i] != cpu::kNoFacet) w.facet[back[i]] = index_of[r.w.facet[i]];
    // the facet of the smaller hull whose cone from s holds a point (by the
    // certifier's own predicate, over all facets)
    certify::detail::Hull3Surface ck;
    certify::Speedups none;
    REQUIRE(certify::detail::hull3_surface(ps, w.facets, certify::Level::canonical, none, &w.tet, ck).ok);
    // the rest's points inside its inner ball: a facet each (the ball the
    // certifier builds from the mapped facets need not be the same)
    w.ball = false;
    for (Index i = 0; i < ps.size(); ++i)
      if (i != v && !ck.is_vertex[i] && w.facet[i] == cpu::kNoFacet) w.facet[i] = cone_of(ck, w.facets, i);
    const std::uint32_t f = cone_of(ck, w.facets, v);
    REQUIRE(f < w.facets.size());
    w.facet[v] = f;
    // only v is outside: every other point keeps its (mapped) witness
    const certify::Report rep = witnessed(ps, w.facets, w);
    INFO(rep.message());
    REQUIRE(rep.condition == "point-inside");
    REQUIRE(rep.detail.find("point " + std::to_string(v) + " ") == 0);
    REQUIRE(certify::hull3(ps, w.facets, certify::Level::canonical).condition == "point-inside");
    // without a facet for v: no facet named
    w.facet[v] = cpu::kNoFacet;
    REQUIRE(witnessed(ps, w.facets, w).condition == "witness-facet");
  }
}

TEST_CASE("hull3 witness: a non-convex edge is rejected", "[hull3_witness]") {
  const PointSet ps = generated("ball", 2000, 7);
  const Witnessed r = run(ps, 2);
  // a 2-2 flip of an edge of the hull: (a, b, c), (b, a, d) -> (a, d, c),
  // (d, b, c); the new edge (c, d) is reflex
  std::vector<Triangle> tris = r.tris;
  const Triangle t1 = tris[0];
  const Index a = t1[0], b = t1[1], c = t1[2];
  std::size_t j = 0;
  Index d = 0;
  for (; j < tris.size(); ++j) {
    const Triangle& t = tris[j];
    bool found = false;
    for (int k = 0; k < 3; ++k)
      if (t[k] == b && t[(k + 1) % 3] == a) d = t[(k + 2) % 3], found = true;
    if (found) break;
  }
  REQUIRE(j < tris.size());
  tris[0] = {a, d, c};
  tris[j] = {d, b, c};
  tris = canonical_triangles(tris);
  cpu::Hull3Witness w = r.w;
  w.facets = tris;
  const certify::Report rep = witnessed(ps, tris, w);
  INFO(rep.message());
  REQUIRE(rep.condition == "convex-edge");
  REQUIRE(certify::hull3(ps, tris, certify::Level::canonical).condition == "convex-edge");
}

TEST_CASE("hull3 witness: a bad interior point is rejected", "[hull3_witness]") {
  const PointSet ps = generated("grid3", 2000, 1);
  const Witnessed r = run(ps, 2);
  REQUIRE(witnessed(ps, r.tris, r.w).ok);
  cpu::Hull3Witness w = r.w;
  SECTION("a repeated point") {
    w.tet[3] = w.tet[0];
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-interior-point");
  }
  SECTION("an index out of range") {
    w.tet[2] = static_cast<Index>(ps.size());
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-interior-point");
  }
  SECTION("four coplanar points") {
    // four grid points of one z
    std::vector<Index> plane;
    for (Index i = 0; i < ps.size() && plane.size() < 4; ++i)
      if (ps.point(i)[2] == ps.point(0)[2]) plane.push_back(i);
    REQUIRE(plane.size() == 4);
    std::copy(plane.begin(), plane.end(), w.tet.begin());
    const certify::Report rep = witnessed(ps, r.tris, w);
    INFO(rep.message());
    REQUIRE(rep.condition == "witness-interior-point");
    REQUIRE(rep.detail.find("flat") != std::string::npos);
  }
}

TEST_CASE("hull3 witness: an output that is not the witnessed facet set is rejected", "[hull3_witness]") {
  const PointSet ps = generated("sphere", 2000, 2);
  const Witnessed r = run(ps, 2);
  REQUIRE(witnessed(ps, r.tris, r.w).ok);
  SECTION("a facet changed") {
    std::vector<Triangle> tris = r.tris;
    std::swap(tris[1][1], tris[1][2]);
    REQUIRE(witnessed(ps, tris, r.w).condition == "witness-output");
  }
  SECTION("a facet missing") {
    std::vector<Triangle> tris = r.tris;
    tris.pop_back();
    REQUIRE(witnessed(ps, tris, r.w).condition == "witness-output");
  }
  SECTION("a witness of the wrong size") {
    cpu::Hull3Witness w = r.w;
    w.facet.pop_back();
    REQUIRE(witnessed(ps, r.tris, w).condition == "witness-size");
  }
  SECTION("at the exact level too") {
    std::vector<Triangle> tris = r.tris;
    std::swap(tris[0], tris[1]);
    REQUIRE(witnessed(ps, tris, r.w, certify::Level::exact).condition == "witness-output");
  }
}

// The kernel's inner box (ffhull.cpp: inner_region) on points filling a cube:
// it is handed on, the points without facet or record that lie outside the
// ball rely on it, the certifier accepts them, the witness-free certifier
// agrees — and a box that pokes out of the hull, or that misses one of those
// points, is rejected with the point named.
TEST_CASE("hull3 witness: the inner box certifies the points round 0 dropped", "[hull3_witness]") {
  const PointSet ps = generated("cube", 100000, 11);
  const Witnessed r = run(ps, 2);
  REQUIRE(!r.w.box.empty());
  REQUIRE(witnessed(ps, r.tris, r.w).ok);
  REQUIRE(witnessed(ps, r.tris, r.w, certify::Level::exact).ok);
  REQUIRE(certify::hull3(ps, r.tris, certify::Level::canonical).ok);
  // which points only the box certifies: no facet, no record, strictly inside
  // the box and, for the ball the certifier builds, not strictly inside it
  const certify::detail::InnerBall<3> ball =
      r.w.ball ? certify::detail::InnerBall<3>(ps, r.tris, decltype(certify::Speedups{}.for_range){})
               : certify::detail::InnerBall<3>();
  std::vector<char> vertex(ps.size(), 0);
  for (const Triangle& t : r.tris)
    for (Index v : t) vertex[v] = 1;
  std::vector<Index> relying;
  for (Index p = 0; p < ps.size(); ++p)
    if (!vertex[p] && r.w.facet[p] == cpu::kNoFacet && !r.w.has_record(p) && !ball.strictly_inside(ps.point(p))) {
      REQUIRE(r.w.box.strictly_inside(ps.point(p)));
      relying.push_back(p);
    }
  REQUIRE(relying.size() > 2 * r.tris.size());  // what worth_box asks
  // every vertex of the hull is outside the box (a point strictly inside it
  // is strictly inside the hull)
  for (Index p = 0; p < ps.size(); ++p)
    if (vertex[p]) REQUIRE(!r.w.box.strictly_inside(ps.point(p)));
  SECTION("a box grown past the hull's facets") {
    cpu::Hull3Witness w = r.w;
    for (int j = 0; j < 3; ++j) w.box.lo[j] -= 0.5, w.box.hi[j] += 0.5;
    const certify::Report rep = witnessed(ps, r.tris, w);
    INFO(rep.message());
    REQUIRE(rep.condition == "witness-facet");
    REQUIRE(rep.detail.find("point " + std::to_string(relying.front()) + " ") == 0);
    REQUIRE(rep.detail.find("the witness' box is not inside every facet") != std::string::npos);
  }
  SECTION("a box that misses a point relying on it") {
    const Index q = relying[relying.size() / 2];
    cpu::Hull3Witness w = r.w;
    // shrink one side to just below q's coordinate: q is then on or outside
    // the box; every point smaller than q that relied on the box must still
    // be inside, so pick the side and check the report names q or one before
    int side = 0;
    double best = HUGE_VAL;
    for (int j = 0; j < 3; ++j) {
      const double x = ps.point(q)[j];
      if (x - w.box.lo[j] < best) best = x - w.box.lo[j], side = j;
    }
    w.box.lo[side] = ps.point(q)[side];
    const certify::Report rep = witnessed(ps, r.tris, w);
    INFO(rep.message());
    REQUIRE(rep.condition == "witness-facet");
    REQUIRE(rep.detail.find("not strictly inside the witness' box") != std::string::npos);
    Index named = 0;
    REQUIRE(std::sscanf(rep.detail.c_str(), "point %u ", &named) == 1);
    REQUIRE(named <= q);
    REQUIRE(!w.box.strictly_inside(ps.point(named)));
  }
}

// From 2^17 points on, round 0 may drop the points inside the inner ball of
// a sample's hull (ffhull.cpp: sample_ball, after a probe of 4096 points):
// a spherical shell of thickness 0.01, a ball and a controlled ball take
// that path, a cube keeps its box, a thin shell (1e-4) keeps the probe's
// ball. Each output is the reference's, and the witness is certified at both
// levels, the witness-free certifier agreeing.
TEST_CASE("hull3 witness: inputs large enough for the sample hull's ball equal the reference and are certified",
          "[hull3_witness][long]") {
  for (const char* fam : {"sphere", "ball", "cball", "cube"}) {
    gen::Options o;
    o.seed = 21;
    const PointSet ps = gen::generate(fam, 150000, o);
    INFO(fam);
    const Witnessed r = run(ps, 2);
    REQUIRE(r.tris == ref::hull3_ffhull(ps));
    for (certify::Level level : {certify::Level::canonical, certify::Level::exact}) {
      const certify::Report rep = witnessed(ps, r.tris, r.w, level);
      INFO(rep.message());
      REQUIRE(rep.ok);
    }
    REQUIRE(certify::hull3(ps, r.tris, certify::Level::canonical).ok);
  }
  gen::Options o;
  o.seed = 22;
  o.thickness = 1e-4;
  const PointSet thin = gen::generate("sphere", 150000, o);
  const Witnessed r = run(thin, 2);
  REQUIRE(r.tris == ref::hull3_ffhull(thin));
  REQUIRE(witnessed(thin, r.tris, r.w).ok);
}

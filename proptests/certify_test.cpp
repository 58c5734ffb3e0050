// certify_test.cpp — the certifier accepts right answers and rejects wrong ones.
//
// Oracles: the brute-force definitions of reference/brute_force.hpp (canonical
// answers by enumeration), hand-built alternative answers that are right only
// at the exact level (degenerate inputs), and deliberately broken outputs.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <set>

#include "predicates/predicates.hpp"
#include "proptests/support/planar_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "gen/generate.hpp"
#include "reference/certify/certify.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/dimension.hpp"

using namespace flipflop;
using certify::Level;


namespace {

// Small point sets: integer coordinates in [-r, r] (rich in collinear,
// cocircular, coplanar and duplicate points) or random doubles.
rc::Gen<PointSet> gen_points(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(nmin, nmax + 1);
    const bool integer = *rc::gen::arbitrary<bool>();
    const int r = *rc::gen::inRange(1, 4);
    PointSet ps;
    ps.dim = dim;
    ps.weighted = weighted;
    for (int i = 0; i < n * dim; ++i)
      ps.coords.push_back(integer ? double(*rc::gen::inRange(-r, r + 1))
                                  : *rc::gen::inRange(-1000000, 1000001) / 1048576.0);
    for (int i = 0; weighted && i < n; ++i)
      ps.weights.push_back(integer ? double(*rc::gen::inRange(0, 3)) : *rc::gen::inRange(0, 1000) / 4096.0);
    return ps;
  });
}

PointSet points(int dim, std::vector<double> c, std::vector<double> w = {}) {
  PointSet ps;
  ps.dim = dim;
  ps.coords = std::move(c);
  ps.weighted = !w.empty();
  ps.weights = std::move(w);
  return ps;
}

bool spans(const PointSet& ps) { return dimension_problem(ps).empty(); }

}  // namespace

TEST_CASE("certify: brute-force canonical answers are certified at both levels", "[certify]") {
  rc::prop("hull2", [] {
    PointSet ps = *gen_points(2, 3, 30, false);
    RC_PRE(spans(ps));
    auto h = brute::hull2(ps);
    RC_ASSERT(certify::hull2(ps, h, Level::canonical).message() == "certified");
    RC_ASSERT(certify::hull2(ps, h, Level::exact).message() == "certified");
  });
  rc::prop("hull3", [] {
    PointSet ps = *gen_points(3, 4, 11, false);
    RC_PRE(spans(ps));
    auto h = brute::hull3(ps);
    RC_ASSERT(certify::hull3(ps, h, Level::canonical).message() == "certified");
    RC_ASSERT(certify::hull3(ps, h, Level::exact).message() == "certified");
  });
  rc::prop("rt2 and dt2", [] {
    const bool weighted = *rc::gen::arbitrary<bool>();
    PointSet ps = *gen_points(2, 3, 13, weighted);
    RC_PRE(spans(ps));
    auto t = brute::rt2(ps);
    RC_ASSERT(certify::rt2(ps, t, Level::canonical).message() == "certified");
    RC_ASSERT(certify::rt2(ps, t, Level::exact).message() == "certified");
  });
}

TEST_CASE("certify: broken hull2 outputs are rejected", "[certify]") {
  rc::prop("missing, reversed or permuted vertices", [] {
    PointSet ps = *gen_points(2, 5, 30, false);
    RC_PRE(spans(ps));
    auto h = brute::hull2(ps);
    RC_PRE(h.size() >= 4);
    // a strictly extreme vertex (under the perturbation) removed
    auto missing = h;
    missing.erase(missing.begin() + static_cast<long>(*rc::gen::inRange<std::size_t>(1, h.size())));
    auto r = certify::hull2(ps, missing, Level::canonical);
    RC_ASSERT(!r.ok);
    RC_ASSERT(r.condition == "point-inside");
    // reversed orientation
    auto rev = h;
    std::reverse(rev.begin() + 1, rev.end());
    RC_ASSERT(!certify::hull2(ps, rev, Level::exact).ok);
    RC_ASSERT(!certify::hull2(ps, rev, Level::canonical).ok);
    // two vertices swapped
    auto sw = h;
    std::swap(sw[1], sw[2]);
    RC_ASSERT(!certify::hull2(ps, sw, Level::canonical).ok);
  });
  SECTION("a missing extreme point in general position is rejected at the exact level") {
    PointSet ps = points(2, {0, 0, 4, 0, 4, 3, 0, 3, 1, 1, 2, 5});  // 5 is extreme (2,5)
    auto h = brute::hull2(ps);
    REQUIRE(certify::hull2(ps, h, Level::exact).ok);
    std::vector<Index> missing = {0, 1, 2, 3};
    auto r = certify::hull2(ps, missing, Level::exact);
    REQUIRE_FALSE(r.ok);
    CHECK(r.condition == "point-inside");
    CHECK(r.detail.find("point 5") != std::string::npos);
  }
  SECTION("a corner beyond collinear boundary vertices (found by fuzz_hull2)") {
    // 3 and 4 lie on the edge 2-0 (x = -8); leaving out corner 2 must fail
    PointSet ps = points(2, {-8, -8, 5, 0, -8, 7, -8, 1, -8, -1});
    CHECK(certify::hull2(ps, {0, 1, 3, 4}, Level::exact).condition == "point-inside");
    CHECK(certify::hull2(ps, {0, 1, 2, 3, 4}, Level::exact).ok);
    CHECK(certify::hull2(ps, {0, 1, 2}, Level::exact).ok);
  }
  SECTION("index errors") {
    PointSet ps = points(2, {0, 0, 1, 0, 0, 1});
    CHECK(certify::hull2(ps, {0, 1, 7}, Level::exact).condition == "vertex-indices");
    CHECK(certify::hull2(ps, {0, 1, 1}, Level::exact).condition == "vertex-indices");
    CHECK(certify::hull2(ps, {0, 1}, Level::exact).condition == "vertex-indices");
    CHECK(certify::hull2(ps, {1, 2, 0}, Level::canonical).condition == "canonical-form");
  }
  SECTION("lower-dimensional input is reported, not certified") {
    PointSet ps = points(2, {0, 0, 1, 1, 2, 2, 3, 3});
    auto r = certify::hull2(ps, {0, 3, 1}, Level::exact);
    CHECK(r.condition == "input-dimension");
  }
}

TEST_CASE("certify: exact level accepts the alternative answers of degenerate input", "[certify]") {
  SECTION("hull2 with collinear boundary points included or not") {
    // square with points on its edges
    PointSet ps = points(2, {0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 1, 1});
    std::vector<Index> corners = {0, 1, 2, 3};
    std::vector<Index> all = {0, 4, 1, 5, 2, 6, 3, 7};
    CHECK(certify::hull2(ps, corners, Level::exact).ok);
    CHECK(certify::hull2(ps, all, Level::exact).ok);
    auto canon = brute::hull2(ps);
    CHECK(certify::hull2(ps, canon, Level::canonical).ok);
    // at most one of the two alternatives can be the perturbed answer
    CHECK(!(certify::hull2(ps, corners, Level::canonical).ok && certify::hull2(ps, all, Level::canonical).ok));
    // the centre is never on the hull
    std::vector<Index> with_centre = {0, 1, 2, 8};
    CHECK_FALSE(certify::hull2(ps, with_centre, Level::exact).ok);
  }
  SECTION("Delaunay triangulations of a square: both diagonals") {
    PointSet ps = points(2, {0, 0, 1, 0, 1, 1, 0, 1});
    std::vector<Triangle> d02 = {{0, 1, 2}, {0, 2, 3}}, d13 = {{0, 1, 3}, {1, 2, 3}};
    CHECK(certify::rt2(ps, d02, Level::exact).ok);
    CHECK(certify::rt2(ps, d13, Level::exact).ok);
    const bool c02 = certify::rt2(ps, d02, Level::canonical).ok, c13 = certify::rt2(ps, d13, Level::canonical).ok;
    CHECK(c02 != c13);  // exactly one is the perturbed answer
    CHECK((c02 ? d02 : d13) == brute::rt2(ps));
  }
  SECTION("a copy of a hull corner may be left out (found by the property suite)") {
    // (0,0) twice: CGAL keeps one copy; the perturbation moves the other out of
    // every triangle, but at the exact level it is a redundant duplicate
    PointSet ps = points(2, {0, 0, 0, -1, 1, 0, 0, 0});
    CHECK(certify::rt2(ps, {{0, 1, 2}}, Level::exact).message() == "certified");
    CHECK(certify::rt2(ps, {{1, 2, 3}}, Level::exact).message() == "certified");
    // a heavier copy lifts lower: leaving it out is wrong
    PointSet heavy = points(2, {0, 0, 0, -1, 1, 0, 0, 0}, {0, 0, 0, 1});
    CHECK(certify::rt2(heavy, {{0, 1, 2}}, Level::exact).condition == "missing-point-redundant");
    CHECK(certify::rt2(heavy, {{1, 2, 3}}, Level::exact).ok);
  }
  SECTION("tiny coordinates (floating-point estimates underflow)") {
    PointSet ps = points(3, {0, 0, 0, 1e-301, 0, 0, 0, 1e-301, 0, 0, 0, 1e-301});
    auto h = brute::hull3(ps);
    CHECK(certify::hull3(ps, h, Level::exact).message() == "certified");
    CHECK(certify::hull3(ps, h, Level::canonical).message() == "certified");
  }
  SECTION("a cube's facets may be split along either diagonal") {
    PointSet ps = points(3, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1});
    auto canon = brute::hull3(ps);
    REQUIRE(canon.size() == 12);
    CHECK(certify::hull3(ps, canon, Level::canonical).ok);
    // flip the diagonal of the bottom face z = 0 (vertices 0,1,2,3)
    std::vector<Triangle> alt;
    for (const Triangle& t : canon) {
      bool bottom = true;
      for (Index v : t) bottom = bottom && v < 4;
      if (!bottom) alt.push_back(t);
    }
    REQUIRE(alt.size() == 10);
    bool has02 = false;
    for (const Triangle& t : canon) {
      std::set<Index> s(t.begin(), t.end());
      if (s.count(0) && s.count(2) && *s.rbegin() < 4) has02 = true;
    }
    // seen from outside (below), the bottom face is 0,3,2,1 counter-clockwise
    if (has02) alt.insert(alt.end(), {{0, 3, 1}, {1, 3, 2}});
    else alt.insert(alt.end(), {{0, 3, 2}, {0, 2, 1}});
    CHECK(certify::hull3(ps, alt, Level::exact).message() == "certified");
    CHECK_FALSE(certify::hull3(ps, alt, Level::canonical).ok);
  }
}

TEST_CASE("certify: broken hull3 outputs are rejected", "[certify]") {
  rc::prop("flipped facet, missing facet, removed vertex", [] {
    PointSet ps = *gen_points(3, 6, 11, false);
    RC_PRE(spans(ps));
    auto h = brute::hull3(ps);
    const std::size_t pick = *rc::gen::inRange<std::size_t>(0, h.size());
    auto flipped = h;
    std::swap(flipped[pick][1], flipped[pick][2]);
    RC_ASSERT(!certify::hull3(ps, flipped, Level::exact).ok);
    auto holed = h;
    holed.erase(holed.begin() + static_cast<long>(pick));
    RC_ASSERT(!certify::hull3(ps, holed, Level::exact).ok);
    // remove vertex v and close its hole by a fan: v (extreme under the
    // perturbation) is then outside the new surface
    const Index v = h[pick][0];
    std::vector<Triangle> rest, star;
    for (const Triangle& t : h) (std::find(t.begin(), t.end(), v) != t.end() ? star : rest).push_back(t);
    RC_PRE(star.size() >= 4);
    std::vector<std::pair<Index, Index>> link;  // link edges b→c of triangles (v,b,c)
    for (Triangle t : star) {
      std::rotate(t.begin(), std::find(t.begin(), t.end(), v), t.end());
      link.emplace_back(t[1], t[2]);
    }
    std::vector<Index> cyc = {link[0].first};
    while (cyc.size() < link.size())
      for (auto& e : link)
        if (e.first == cyc.back()) {
          cyc.push_back(e.second);
          break;
        }
    for (std::size_t k = 1; k + 1 < cyc.size(); ++k) rest.push_back({cyc[0], cyc[k], cyc[k + 1]});
    auto r = certify::hull3(ps, canonical_triangles(rest), Level::canonical);
    RC_ASSERT(!r.ok);  // point-inside, convex-edge, or a chord of the fan that already was an edge
  });
  SECTION("a facet with a point beyond it (tetrahedron missing an extreme point)") {
    PointSet ps = points(3, {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 3, 3, 3});
    std::vector<Triangle> tet = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    auto r = certify::hull3(ps, tet, Level::exact);
    REQUIRE_FALSE(r.ok);
    CHECK(r.condition == "point-inside");
    CHECK(r.detail.find("point 4") != std::string::npos);
    PointSet inside = points(3, {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 1, 1, 1});
    CHECK(certify::hull3(inside, tet, Level::exact).ok);
    CHECK(certify::hull3(inside, canonical_triangles(tet), Level::canonical).ok);
  }
  SECTION("two disjoint surfaces") {
    PointSet ps = points(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 5, 5, 6, 5, 5, 5, 6, 5, 5, 5, 6});
    std::vector<Triangle> two = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}, {5, 6, 7}};
    CHECK_FALSE(certify::hull3(ps, two, Level::exact).ok);
  }
  SECTION("coplanar input is reported as lower-dimensional") {
    PointSet ps = points(3, {0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1});
    CHECK(certify::hull3(ps, {{0, 1, 2}, {0, 2, 1}, {1, 2, 3}, {1, 3, 2}}, Level::exact).condition ==
          "input-dimension");
  }
}

TEST_CASE("certify: broken rt2 outputs are rejected", "[certify]") {
  rc::prop("flipped edge is not locally regular; missing non-redundant point", [] {
    const bool weighted = *rc::gen::arbitrary<bool>();
    PointSet ps = *gen_points(2, 5, 13, weighted);
    RC_PRE(spans(ps));
    auto t = brute::rt2(ps);
    // flip an interior edge whose quadrilateral is convex
    bool flipped_one = false;
    for (std::size_t i = 0; i < t.size() && !flipped_one; ++i)
      for (std::size_t j = i + 1; j < t.size() && !flipped_one; ++j)
        for (int k = 0; k < 3 && !flipped_one; ++k) {
          Index a = t[i][k], b = t[i][(k + 1) % 3], c = t[i][(k + 2) % 3];
          for (int l = 0; l < 3; ++l) {
            if (t[j][l] != b || t[j][(l + 1) % 3] != a) continue;
            Index d = t[j][(l + 2) % 3];
            auto P = [&](Index x) { return pred::Pt{x, ps.point(x)}; };
            if (pred::orient2d(P(c), P(a), P(d)) > 0 && pred::orient2d(P(d), P(b), P(c)) > 0) {
              auto bad = t;
              bad[i] = {c, a, d};
              bad[j] = {d, b, c};
              auto r = certify::rt2(ps, canonical_triangles(bad), Level::canonical);
              RC_ASSERT(!r.ok);
              RC_ASSERT(r.condition == "locally-regular");
              flipped_one = true;
            }
            break;
          }
        }
    // a vertex of the answer left out: its triangles replaced by the answer
    // without it; the point is non-redundant, so the result is rejected
    std::set<Index> verts;
    for (auto& tr : t) verts.insert(tr.begin(), tr.end());
    const Index p = *std::next(verts.begin(), static_cast<long>(*rc::gen::inRange<std::size_t>(0, verts.size())));
    PointSet sub = ps;
    sub.coords.erase(sub.coords.begin() + 2 * p, sub.coords.begin() + 2 * p + 2);
    if (ps.weighted) sub.weights.erase(sub.weights.begin() + p);
    RC_PRE(spans(sub));
    auto ts = brute::rt2(sub);  // indices of sub: shift back
    for (auto& tr : ts)
      for (Index& x : tr) x = x >= p ? x + 1 : x;
    auto r = certify::rt2(ps, canonical_triangles(ts), Level::canonical);
    RC_ASSERT(!r.ok);
  });
  SECTION("a clockwise triangle") {
    PointSet ps = points(2, {0, 0, 1, 0, 0, 1});
    CHECK(certify::rt2(ps, {{0, 2, 1}}, Level::exact).condition == "triangle-orientation");
    CHECK(certify::rt2(ps, {{0, 1, 2}}, Level::exact).ok);
  }
  SECTION("a missing interior point that is not redundant") {
    PointSet ps = points(2, {0, 0, 4, 0, 0, 4, 1, 1}, {0, 0, 0, 0});
    CHECK(certify::rt2(ps, {{0, 1, 2}}, Level::exact).condition == "missing-point-redundant");
    // a negative weight lifts the point high above the plane: redundant
    PointSet red = points(2, {0, 0, 4, 0, 0, 4, 1, 1}, {0, 0, 0, -10});
    CHECK(certify::rt2(red, {{0, 1, 2}}, Level::exact).ok);
  }
}

TEST_CASE("certify: hull3 on many interior points (the inner-ball fast path) still rejects every outside point", "[certify]") {
  // 20000 ball points: far more interior points than facets, so the
  // certifier's exactly verified inner ball decides most of them; a hull of
  // the input without some of its vertices must still be rejected, naming
  // the smallest outside point
  gen::Options o;
  o.seed = 17;
  const PointSet ps = gen::generate("ball", 20000, o);
  const std::vector<Triangle> hull = ref::hull3(ps, "ffhull");
  REQUIRE(certify::hull3(ps, hull, certify::Level::exact).ok);
  REQUIRE(certify::hull3(ps, hull, certify::Level::canonical).ok);
  std::vector<Index> verts;
  for (const Triangle& t : hull) verts.insert(verts.end(), t.begin(), t.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (std::size_t k : {std::size_t{0}, verts.size() / 2, verts.size() - 1}) {
    // the hull without vertices verts[k] and verts[k/3]: they end up outside
    std::set<Index> gone = {verts[k], verts[k / 3]};
    PointSet sub;
    sub.dim = 3;
    std::vector<Index> back;
    for (Index i = 0; i < ps.size(); ++i)
      if (!gone.count(i)) {
        back.push_back(i);
        sub.coords.insert(sub.coords.end(), ps.point(i), ps.point(i) + 3);
      }
    std::vector<Triangle> smaller = ref::hull3(sub, "ffhull");
    for (Triangle& t : smaller)
      for (Index& x : t) x = back[x];
    smaller = canonical_triangles(smaller);
    for (certify::Level level : {certify::Level::exact, certify::Level::canonical}) {
      const certify::Report r = certify::hull3(ps, smaller, level);
      INFO(r.message());
      REQUIRE(r.condition == "point-inside");
      REQUIRE(r.detail.rfind("point " + std::to_string(*gone.begin()) + " ", 0) == 0);
    }
  }
}

TEST_CASE("certify: hull2 on many interior points (the inner-disk fast path) still rejects every outside point", "[certify]") {
  // the 2D analogue: 20000 disk and square points, the hull of the input
  // without two of its vertices, which must be named (the smallest)
  for (const char* dist : {"disk", "square"}) {
    gen::Options o;
    o.seed = 23;
    const PointSet ps = gen::generate(dist, 20000, o);
    const std::vector<Index> hull = ref::hull2(ps, "graham-sort");
    REQUIRE(certify::hull2(ps, hull, certify::Level::exact).ok);
    REQUIRE(certify::hull2(ps, hull, certify::Level::canonical).ok);
    std::vector<Index> verts = hull;
    std::sort(verts.begin(), verts.end());
    for (std::size_t k : {std::size_t{0}, verts.size() / 2, verts.size() - 1}) {
      std::set<Index> gone = {verts[k], verts[k / 3]};
      PointSet sub;
      sub.dim = 2;
      std::vector<Index> back;
      for (Index i = 0; i < ps.size(); ++i)
        if (!gone.count(i)) {
          back.push_back(i);
          sub.coords.insert(sub.coords.end(), ps.point(i), ps.point(i) + 2);
        }
      std::vector<Index> smaller = ref::hull2(sub, "graham-sort");
      for (Index& x : smaller) x = back[x];
      std::rotate(smaller.begin(), std::min_element(smaller.begin(), smaller.end()), smaller.end());
      for (certify::Level level : {certify::Level::exact, certify::Level::canonical}) {
        const certify::Report r = certify::hull2(ps, smaller, level);
        INFO(dist << ": " << r.message());
        REQUIRE(r.condition == "point-inside");
        REQUIRE(r.detail.rfind("point " + std::to_string(*gone.begin()) + " ", 0) == 0);
      }
    }
  }
}

// splay_reference_test.cpp — star splaying (thesis §3.3.2) and its pipeline
// hull3_splay (ch. 7) against independent oracles:
//   * brute::hull3 (the canonical SoS hull by enumeration), byte for byte,
//     and the certifier at Level::canonical, on every 3D family, degenerate
//     ones included, 4..40 points (RapidCheck);
//   * star_splaying on the pipeline's initial stars, on random valid stars
//     and in random orders of candidate edges (the free execution order);
//   * larger inputs (10^3 .. 10^5): certified canonical, and equal to CGAL's
//     convex_hull_3 where the input is in general position;
//   * death certificates (item (d)): every dead star's certificate is checked
//     with CGAL's exact kernel (the point lies in the closed tetrahedron) and
//     the point is not a vertex of the hull;
//   * lower-dimensional input is rejected with dimension_problem.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <random>
#include <set>

#include "peers/peers.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/splay_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/star_splaying.hpp"

using namespace flipflop;
using ref::splay::State;
using ref::splay::Status;

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;

bool spans_3d(const PointSet& ps) { return ps.size() >= 4 && affine_dimension(ps) == 3; }

// Independent check of a death certificate: v in the closed tetrahedron of
// the four points, decided by CGAL's exact kernel (the SoS claim is
// "strictly inside after perturbation", which implies this).
bool cgal_in_tetrahedron(const PointSet& ps, Index v, const std::array<Index, 4>& c) {
  auto P = [&](Index i) { return K::Point_3(ps.point(i)[0], ps.point(i)[1], ps.point(i)[2]); };
  const K::Tetrahedron_3 t(P(c[0]), P(c[1]), P(c[2]), P(c[3]));
  if (t.is_degenerate()) {
    // a flat tetrahedron: v must lie in it (in its plane, inside the hull of the 4)
    // — check with barycentric signs of the coplanar triangles
    for (int skip = 0; skip < 4; ++skip) {
      std::vector<K::Point_3> tri;
      for (int i = 0; i < 4; ++i)
        if (i != skip) tri.push_back(P(c[i]));
      if (!CGAL::collinear(tri[0], tri[1], tri[2]) && K::Triangle_3(tri[0], tri[1], tri[2]).has_on(P(v))) return true;
    }
    return K::Segment_3(P(c[0]), P(c[1])).has_on(P(v)) || K::Segment_3(P(c[0]), P(c[2])).has_on(P(v)) ||
           K::Segment_3(P(c[0]), P(c[3])).has_on(P(v)) || K::Segment_3(P(c[1]), P(c[2])).has_on(P(v)) ||
           K::Segment_3(P(c[1]), P(c[3])).has_on(P(v)) || K::Segment_3(P(c[2]), P(c[3])).has_on(P(v));
  }
  return !t.has_on_unbounded_side(P(v));
}

std::set<Index> vertices(const std::vector<Triangle>& tris) {
  std::set<Index> s;
  for (const Triangle& t : tris) s.insert(t.begin(), t.end());
  return s;
}

// Runs star splaying from `stars`, checks every death certificate (SoS and
// CGAL) and returns the hull.
std::vector<Triangle> splay_and_check_deaths(const PointSet& ps, const std::vector<ref::Star>& stars,
                                             const ref::splay::Chooser& choose = nullptr) {
  State st = ref::splay::make_state(ps, stars, true);
  ref::splay::run(st, nullptr, choose);
  REQUIRE(ref::splay::consistent(st));
  const auto hull = ref::splay::triangles(st);
  const auto verts = vertices(hull);
  for (Index v = 0; v < ps.size(); ++v) {
    if (st.status[v] != Status::dead) {
      REQUIRE(st.status[v] == Status::alive);
      REQUIRE(verts.count(v) == 1);  // alive at the end = a hull vertex
      continue;
    }
    INFO("dead point " << v);
    REQUIRE(ref::is_death_certificate(ps, v, st.cert[v]));
    REQUIRE(cgal_in_tetrahedron(ps, v, st.cert[v]));
    REQUIRE(verts.count(v) == 0);
  }
  return hull;
}

void require_canonical(const PointSet& ps, const std::vector<Triangle>& hull) {
  const auto rep = certify::hull3(ps, hull, certify::Level::canonical);
  INFO(rep.message());
  REQUIRE(rep.ok);
}

}  // namespace

TEST_CASE("splay: hull3_splay equals brute::hull3 on every 3D family, 4..40 points", "[splay]") {
  test::prop_scaled("canonical, certified, byte-identical", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, *rc::gen::weightedElement<int>({{3, 20}, {1, 40}}), false);
    RC_PRE(spans_3d(ps));
    const auto expected = brute::hull3(ps);
    ref::Hull3Stats stats;
    const auto got = ref::hull3_splay(ps, &stats);
    RC_ASSERT(got == expected);
    RC_ASSERT(certify::hull3(ps, got, certify::Level::canonical).ok);
    RC_ASSERT(stats.dead_stars == ps.size() - vertices(got).size());
  });
}

TEST_CASE("splay: star splaying from the pipeline's, random, and randomly ordered stars", "[splay]") {
  test::prop_scaled("same hull, valid death certificates", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 24, false);
    RC_PRE(spans_3d(ps));
    const auto expected = brute::hull3(ps);
    RC_ASSERT(ref::star_splaying(ps, ref::initial_stars(ps)) == expected);
    const std::uint64_t seed = *test::any_seed();
    const auto stars = test::random_stars(ps, seed);
    RC_ASSERT(ref::star_splaying(ps, stars) == expected);
    std::mt19937_64 rng(seed);
    const ref::splay::Chooser random_edge = [&](const std::vector<ref::splay::Edge>& f) { return rng() % f.size(); };
    RC_ASSERT(splay_and_check_deaths(ps, stars, random_edge) == expected);
    RC_ASSERT(splay_and_check_deaths(ps, ref::initial_stars(ps), random_edge) == expected);
  });
}

TEST_CASE("splay: every generator family: brute force (60 points) and certifier (1000 points)", "[splay][long]") {
  for (const std::string& fam : test::splay_families())
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      INFO(fam << " seed " << seed);
      const PointSet small = test::family3(fam, 60, seed);
      if (spans_3d(small)) {
        const auto got = ref::hull3_splay(small);
        REQUIRE(got == brute::hull3(small));
        require_canonical(small, got);
        REQUIRE(splay_and_check_deaths(small, ref::initial_stars(small)) == got);
      }
      const PointSet ps = test::family3(fam, 1000, seed);
      if (!spans_3d(ps)) continue;
      const auto got = ref::hull3_splay(ps);
      require_canonical(ps, got);
      REQUIRE(splay_and_check_deaths(ps, ref::initial_stars(ps)) == got);
    }
}

TEST_CASE("splay: larger inputs: certified canonical, equal to CGAL in general position", "[splay][long]") {
  struct Case {
    const char* fam;
    std::size_t n;
    bool general;  // in general position: CGAL's hull is the same triangulation
  };
  const Case cases[] = {{"ball", 10000, true},   {"sphere", 10000, true}, {"cube", 10000, true},
                        {"box", 10000, true},    {"cball", 10000, true},  {"grid3", 5000, false},
                        {"sphere-lattice", 5000, false}, {"duplicates3", 5000, false}, {"jitter3", 5000, false},
                        {"huge3", 5000, true},   {"tiny3", 5000, true},   {"ball", 100000, true}};
  for (const Case& c : cases) {
    INFO(c.fam << " " << c.n);
    const PointSet ps = test::family3(c.fam, c.n, 7);
    ref::Hull3Stats stats;
    const auto got = ref::hull3_splay(ps, &stats);
    require_canonical(ps, got);
    REQUIRE(stats.dead_stars == ps.size() - vertices(got).size());
    if (c.general) REQUIRE(got == peers::cgal_hull3(ps));
  }
}

TEST_CASE("splay: lower-dimensional and malformed input is rejected", "[splay]") {
  for (const char* fam : {"collinear3", "coplanar3"}) {
    const PointSet ps = test::family3(fam, 50, 3);
    try {
      ref::hull3_splay(ps);
      FAIL("accepted " << fam);
    } catch (const std::invalid_argument& e) {
      REQUIRE(std::string(e.what()) == dimension_problem(ps));
    }
  }
  PointSet three;
  three.dim = 3;
  three.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  REQUIRE_THROWS_AS(ref::hull3_splay(three), std::invalid_argument);
  PointSet equal;
  equal.dim = 3;
  equal.coords.assign(30, 1.5);
  REQUIRE_THROWS_WITH(ref::hull3_splay(equal), dimension_problem(equal));
  PointSet flat2;
  flat2.dim = 2;
  flat2.coords = {0, 0, 1, 0, 0, 1, 1, 1};
  REQUIRE_THROWS_AS(ref::hull3_splay(flat2), std::invalid_argument);
}

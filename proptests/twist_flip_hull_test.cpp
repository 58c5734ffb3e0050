// twist_flip_hull_test.cpp — the 3D hull by twist-flip then flip-flop
// (reference/hull3/twist_flip.hpp: hull3_twist_flip; thesis §8.4.1 then §6.2).
//
// Oracles, independent of the code under test:
//   brute::hull3       the canonical SoS hull by enumeration (small inputs of
//                      every 3D family, degenerate ones included);
//   certify::hull3     exact certification at Level::canonical (any size);
//   peers::cgal_hull3  CGAL's convex_hull_3 on random inputs (general position).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <stdexcept>
#include <string>

#include "gen/generate.hpp"
#include "peers/peers.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/twist_flip.hpp"

using namespace flipflop;
using certify::Level;

TEST_CASE("hull3_twist_flip == brute::hull3 on every 3D family (4..30 points)", "[twist_flip][hull3]") {
  test::prop_scaled("identical to brute force, or rejected as flat", 8, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 30, false);
    const std::string problem = dimension_problem(ps);
    if (!problem.empty()) {
      try {
        ref::hull3_twist_flip(ps);
      } catch (const std::invalid_argument& e) {
        RC_ASSERT(std::string(e.what()) == problem);
        return;
      }
      RC_FAIL("flat input accepted");
    }
    ref::Hull3Stats st;
    const std::vector<Triangle> hull = ref::hull3_twist_flip(ps, &st);
    RC_ASSERT(hull == brute::hull3(ps));
    const certify::Report r = certify::hull3(ps, hull, Level::canonical);
    RC_ASSERT(r.ok);
  });
}

TEST_CASE("hull3_twist_flip: every family by name, certified against brute force", "[twist_flip][hull3]") {
  for (const std::string& fam : test::families(3))
    for (std::size_t n : {4u, 5u, 9u, 24u})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(fam, n, o);
        INFO(fam << " n=" << n << " seed=" << seed);
        if (!dimension_problem(ps).empty()) {
          CHECK_THROWS_AS(ref::hull3_twist_flip(ps), std::invalid_argument);
          continue;
        }
        const std::vector<Triangle> hull = ref::hull3_twist_flip(ps);
        CHECK(hull == brute::hull3(ps));
      }
}

TEST_CASE("hull3_twist_flip: larger random inputs equal CGAL's and are certified", "[twist_flip][hull3][cgal]") {
  const std::vector<std::pair<std::string, std::size_t>> cases = {
      {"ball", 1000}, {"cube", 1000}, {"sphere", 1000}, {"box", 1000}, {"cball", 1000}, {"ball", 10000}, {"sphere", 10000}};
  for (const auto& [fam, n] : cases)
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      gen::Options o;
      o.seed = seed;
      const PointSet ps = gen::generate(fam, n, o);
      INFO(fam << " n=" << n << " seed=" << seed);
      ref::Hull3Stats st;
      const std::vector<Triangle> hull = ref::hull3_twist_flip(ps, &st);
      CHECK(hull == peers::cgal_hull3(ps));
      const certify::Report r = certify::hull3(ps, hull, Level::canonical);
      CHECK(r.message() == "certified");
    }
}

TEST_CASE("hull3_twist_flip rejects input that is not 3D", "[twist_flip][hull3]") {
  PointSet ps;
  ps.dim = 2;
  ps.coords = {0, 0, 1, 0, 0, 1, 1, 1};
  CHECK_THROWS_AS(ref::hull3_twist_flip(ps), std::invalid_argument);
  PointSet three;
  three.dim = 3;
  three.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  try {
    ref::hull3_twist_flip(three);
    FAIL("three points accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == dimension_problem(three));
  }
}

// ffhull_reference_checked_test.cpp — flip-flop 3D (Algorithm 6) and ffHull
// (Algorithm 7) in the checked build (FLIPFLOP_CHECKED=1, linked against
// flipflop_ffhull_checked): after every operation the invariants of §6.1-6.3
// are asserted (flip_flop_3d.hpp: star-shaped w.r.t. the kernel point by
// Lemma 6.1/6.3, 3-1 flips remove only labelled or covered vertices, the
// V-criterion makes the volume grow, labelled vertices lie in the tetrahedron
// of s and the other three by Lemma 6.5, removed vertices never come back).
// A violated invariant throws InvariantViolation; the results must still
// equal brute::hull3. The last case feeds deliberately wrong operations and
// expects the checks to fire.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <string>

#include "gen/generate.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/ffhull_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/checked.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/polyhedron3.hpp"

using namespace flipflop;
namespace ff3 = flipflop::ref::ff3;
namespace poly = flipflop::ref::poly;
using test::spans3;

TEST_CASE("ffhull checked: the checked build is the one linked", "[ffhull][checked]") { REQUIRE(FF_CHECKED); }

TEST_CASE("ffhull checked: ffHull on every family with invariants asserted", "[ffhull][checked]") {
  std::size_t cases = 0;
  for (const std::string& f : test::families(3))
    for (std::size_t n : {4, 7, 15, 40})
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(f, n, o);
        if (!spans3(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        REQUIRE(ref::hull3_ffhull(ps) == brute::hull3(ps));
        ++cases;
      }
  REQUIRE(cases > 80);
}

TEST_CASE("ffhull checked: flip-flop from random star-shaped polyhedra with invariants asserted",
          "[ffhull][checked]") {
  test::prop_scaled("random starts of degenerate sets of 4..25 points", 20, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 25, false);
    RC_PRE(spans3(ps));
    const test::StarStart start = test::random_start(ps, *test::any_seed());
    RC_ASSERT(ref::flip_flop_3d(ps, start.surface, start.s) == test::brute_hull_of_vertices(ps, start.surface));
  });
  const test::Figure61 fig = test::figure_6_1();
  const double* kp[1] = {fig.kernel};
  const ref::RationalKernel s(fig.ps, pred::RationalPoint::centroid(kp, 1, 3));
  REQUIRE(ref::flip_flop_3d(fig.ps, fig.surface, s) == brute::hull3(fig.ps));
}

TEST_CASE("ffhull checked: wrong operations trip the invariant checks", "[ffhull][checked]") {
  gen::Options o;
  o.seed = 3;
  const PointSet ps = gen::generate("ball", 30, o);
  const ref::RationalKernel s = test::ffhull_kernel(ps);
  const auto hull = ref::hull3_ffhull(ps);
  const Triangle t = hull.front();
  {
    // a V-flip of a convex edge (every edge of the hull is convex)
    ff3::State st = ff3::make_state(ps, s, poly::build(ps.size(), hull));
    REQUIRE_THROWS_AS(ff3::apply(st, t[0], t[1], {ff3::Action::flip22_v, 0}, nullptr, nullptr), InvariantViolation);
  }
  {
    // labelling an extreme vertex (Lemma 6.5 cannot hold)
    ff3::State st = ff3::make_state(ps, s, poly::build(ps.size(), hull));
    REQUIRE_THROWS_AS(ff3::apply(st, t[0], t[1], {ff3::Action::label, t[0]}, nullptr, nullptr), InvariantViolation);
  }
  {
    // a D-flip without any labelled vertex
    ff3::State st = ff3::make_state(ps, s, poly::build(ps.size(), hull));
    REQUIRE_THROWS_AS(ff3::apply(st, t[0], t[1], {ff3::Action::flip22_d, 0}, nullptr, nullptr), InvariantViolation);
  }
}

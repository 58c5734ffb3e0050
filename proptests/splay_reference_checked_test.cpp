// splay_reference_checked_test.cpp — star splaying with its invariants
// checked after every operation (the checked build, reference/checked.hpp):
// every splayed star convex, every death certificate valid, the pipeline's
// stars validated (convexity, certificates, the lexicographic precondition),
// all stars consistent at the end. Outputs compared with brute::hull3.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/splay_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/star_splaying.hpp"

using namespace flipflop;

static_assert(FF_CHECKED, "this test links the checked build");

TEST_CASE("splay: checked star splaying: 4..30 points, every family", "[splay][checked]") {
  test::prop_scaled("invariants hold, output = brute::hull3", 8, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 30, false);
    RC_PRE(ps.size() >= 4 && affine_dimension(ps) == 3);
    const auto expected = brute::hull3(ps);
    RC_ASSERT(ref::hull3_splay(ps) == expected);
    RC_ASSERT(ref::star_splaying(ps, test::random_stars(ps, *test::any_seed())) == expected);
  });
}

TEST_CASE("splay: checked star splaying: 3000 points of every family, certified", "[splay][checked]") {
  for (const std::string& fam : test::splay_families()) {
    const PointSet ps = test::family3(fam, 3000, 9);
    INFO(fam);
    if (affine_dimension(ps) < 3) continue;
    const auto got = ref::hull3_splay(ps);
    const auto rep = certify::hull3(ps, got, certify::Level::canonical);
    INFO(rep.message());
    REQUIRE(rep.ok);
  }
}

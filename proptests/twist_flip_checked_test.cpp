// twist_flip_checked_test.cpp — twist-flip in the checked build
// (reference/checked.hpp): every twist removes an inversion of the angular
// order around s (Theorem 8.1), star(v) is star-shaped w.r.t. s after the
// twisting stage (Lemma 8.3), every fold flip is on an inner edge whose new
// edge is not in P (Lemma 8.7) and never creates two negative triangles
// (Figure 8.9 (b)), every triangle is positive at the end (Theorem 8.9); then
// flip-flop's own checks, and the hull equals brute force.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/twist_flip_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/twist_flip.hpp"
#include "reference/hull3/twist_flip_input.hpp"

using namespace flipflop;

TEST_CASE("twist_flip checked: the invariants of Lemmas 8.3, 8.7 and Theorem 8.9 hold", "[twist_flip][checked]") {
  static_assert(FF_CHECKED, "this test must link the checked build");
  test::prop_scaled("every family, every start", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 30, false);
    RC_PRE(ps.size() >= 4 && dimension_problem(ps).empty());
    const std::vector<Triangle> input = ref::special_polyhedron(ps, *test::special_options());
    ref::Hull3Stats st;
    ref::twist_flip(ps, input, ref::topmost_point(ps), &st);
  });
}

TEST_CASE("twist_flip checked: hull3_twist_flip == brute::hull3", "[twist_flip][checked]") {
  test::prop_scaled("degenerate families", 16, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 20, false);
    RC_PRE(dimension_problem(ps).empty());
    RC_ASSERT(ref::hull3_twist_flip(ps) == brute::hull3(ps));
  });
}

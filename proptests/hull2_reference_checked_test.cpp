// hull2_reference_checked_test.cpp — the reference 2D hulls in the checked
// build (reference/checked.hpp, linked against flipflop_reference_checked):
// every invariant the proofs rest on is asserted after every operation —
//   flip-pop: the input is star-shaped w.r.t. its kernel (or Graham's chains
//     are x-monotone), it stays so after every 2-1 flip, every flipped vertex
//     passed the local check, no removed vertex is on the polygon, no valid
//     candidate is left at the end;
//   twist: every twist removes one inversion of the angular order (independent
//     comparator), the result is star-shaped (Theorem 8.1);
//   Graham-insertion: every point is beyond its edge, dropped points lie
//     strictly inside the triangle p r q, the chains stay x-monotone.
// Small inputs only (n <= 60): the checks cost O(n) per operation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

#include "gen/generate.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

PointSet from_coords(std::vector<double> c) {
  PointSet ps;
  ps.dim = 2;
  ps.coords = std::move(c);
  return ps;
}

pred::RationalPoint centroid(const PointSet& ps, Index a, Index b, Index c) {
  const double* pts[4] = {ps.point(a), ps.point(b), ps.point(c), ps.point(c)};
  return pred::RationalPoint::centroid(pts, 4, 2);
}

}  // namespace

TEST_CASE("hull2 checked: every algorithm on small inputs of every 2D family, all invariants asserted",
          "[hull2][reference][checked]") {
  REQUIRE(FF_CHECKED);
  std::size_t runs = 0;
  for (const std::string& fam : gen::distributions()) {
    if (gen::dimension_of(fam) != 2) continue;
    for (std::size_t n : {3, 4, 5, 7, 10, 15, 22, 31, 45, 60})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(fam, n, o);
        if (!dimension_problem(ps).empty()) {
          REQUIRE_THROWS_AS(ref::hull2_graham_sort(ps), std::invalid_argument);
          continue;
        }
        INFO(fam << " n=" << n << " seed=" << seed);
        const std::vector<Index> hull = brute::hull2(ps);
        REQUIRE(ref::hull2_graham_sort(ps) == hull);
        REQUIRE(ref::hull2_graham_insert(ps) == hull);
        REQUIRE(ref::hull2_twist(ps) == hull);
        ref::InsertionOptions io;
        io.choice = ref::InsertionChoice::random;
        io.seed = seed;
        REQUIRE(ref::graham_insertion(ps, nullptr, io) == hull);
        io.choice = ref::InsertionChoice::smallest_index;
        REQUIRE(ref::graham_insertion(ps, nullptr, io) == hull);
        // twist from a random order around another kernel, then flip-pop
        std::mt19937_64 rng(seed + 1000 * n);
        std::vector<Index> order(n);
        std::iota(order.begin(), order.end(), Index{0});
        std::shuffle(order.begin(), order.end(), rng);
        pred::RationalPoint s = ref::interior_kernel(ps);
        for (int attempt = 0; attempt < 20; ++attempt) {
          const Index a = Index(rng() % n), b = Index(rng() % n), c = Index(rng() % n);
          if (pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)) != 0) {
            s = centroid(ps, a, b, c);
            break;
          }
        }
        const std::vector<Index> star = ref::twist_to_star(ps, order, s);
        REQUIRE(ref::flip_pop(ps, star, s) == hull);
        ++runs;
      }
  }
  REQUIRE(runs >= 250);
}

TEST_CASE("hull2 checked: violated preconditions and invariants throw InvariantViolation",
          "[hull2][reference][checked]") {
  REQUIRE(FF_CHECKED);
  // a square 0..3 with a point 4 inside, and far points 5, 6, 7 outside it
  const PointSet ps = from_coords({0, 0, 4, 0, 4, 4, 0, 4, 1, 2, 10, 10, 12, 10, 10, 12});
  const pred::RationalPoint inside = centroid(ps, 0, 1, 2);   // (2, 1)
  const pred::RationalPoint outside = centroid(ps, 5, 6, 7);  // (10.5, 11)
  const std::vector<Index> square{0, 1, 2, 3};

  SECTION("flip-pop accepts a star-shaped polygon") {
    REQUIRE(ref::flip_pop(ps, {0, 1, 2, 3, 4}, inside) == square);
  }
  SECTION("flip-pop input not star-shaped: clockwise, self-intersecting, kernel outside") {
    REQUIRE_THROWS_AS(ref::flip_pop(ps, {3, 2, 1, 0}, inside), InvariantViolation);
    REQUIRE_THROWS_AS(ref::flip_pop(ps, {0, 2, 1, 3}, inside), InvariantViolation);
    REQUIRE_THROWS_AS(ref::flip_pop(ps, square, outside), InvariantViolation);
  }
  SECTION("a 2-1 flip on a vertex outside its kernel triangle") {
    ref::FlipPop fp(ref::StarKernel(ps, inside), {0, 1, 2, 3, 4});
    REQUIRE(fp.applicable() == std::vector<Index>{4});
    REQUIRE_THROWS_AS(fp.apply(1), InvariantViolation);  // a convex corner
    fp.apply(4);
    REQUIRE_THROWS_AS(fp.apply(4), InvariantViolation);  // a removed vertex
  }
  SECTION("Graham chains that are not x-monotone") {
    const PointSet q = from_coords({0, 0, 2, 3, 4, 0, 2, -3, 3, 1});
    ref::ChainPolygon chains;
    chains.left = 0;
    chains.right = 2;
    chains.polygon = {2, 1, 0, 3};  // upper chain 2 -> 1 -> 0 decreasing in x, lower 0 -> 3 -> 2 increasing
    REQUIRE_NOTHROW(ref::FlipPop(q, chains));
    chains.polygon = {2, 1, 4, 0, 3};  // 1 (x = 2) -> 4 (x = 3): increasing on the upper chain
    REQUIRE_THROWS_AS(ref::FlipPop(q, chains), InvariantViolation);
  }
  SECTION("a twist on an edge already in angular order") {
    // around (2, 1): g(2) < g(3) < g(0) < g(1) (56°, 124°, 207°, 333°)
    ref::Twist sorted(ref::StarKernel(ps, inside), {2, 3, 0, 1});
    REQUIRE(sorted.applicable().empty());
    REQUIRE_THROWS_AS(sorted.apply(0), InvariantViolation);
    ref::Twist unsorted(ref::StarKernel(ps, inside), {3, 2, 0, 1});
    REQUIRE(unsorted.applicable() == std::vector<std::size_t>{0});
    REQUIRE_THROWS_AS(unsorted.apply(1), InvariantViolation);
    unsorted.apply(0);
    REQUIRE(unsorted.order() == std::vector<Index>{2, 3, 0, 1});
  }
  SECTION("twist with a kernel outside the hull cannot give a star-shaped polygon (Thm 8.1)") {
    REQUIRE(ref::twist_to_star(ps, {3, 1, 0, 2}, inside) == std::vector<Index>{2, 3, 0, 1});
    REQUIRE_THROWS_AS(ref::twist_to_star(ps, {3, 1, 0, 2}, outside), InvariantViolation);
  }
}

// instant_flip_checked_test.cpp — the monotonic instant flip (thesis §9.2.1,
// Algorithm 14) in the checked build (reference/checked.hpp): the invariant
// checks after every operation (no ridge fails before the current time —
// Lemma 9.10; a valid triangulation at the end; the structure's own checks
// after every flip) hold on random runs in d = 2..5, and the result equals a
// fresh construction.
#include <catch2/catch.hpp>

#include <random>

#include "reference/checked.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "support/instant_flip_oracles.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

TEST_CASE("instant flip, checked build: invariants hold, result equals RT(S+U)", "[instant_flip][checked]") {
  REQUIRE(FF_CHECKED);
  const struct {
    int d;
    std::size_t n;
  } cases[] = {{2, 50}, {3, 30}, {4, 16}, {5, 12}};
  for (const auto& c : cases)
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      std::mt19937_64 rng(seed * 97 + static_cast<std::uint64_t>(c.d));
      const PointSet pts = random_points(c.d, c.n, rng);
      const std::vector<double> w(c.n, 0.0), u = random_weights(c.n, 0.05, rng);
      const PointSet pw = with_weights(pts, w), pu = with_weights(pts, u);
      ref::rtd::TriangulationD T = ref::build_rtd(pw);
      ref::instant_flip(T, w, u);  // W = 0: every point a vertex, none comes back
      CHECK(ref::reappearing_points(T, u).empty());
      CHECK(ref::rtd::real_simplices(T) == ref::rtd_incremental(pu).simplices);
    }
}

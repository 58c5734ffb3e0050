// rtd_reference_checked_test.cpp — RT+1 in the checked build
// (reference/checked.hpp: FLIPFLOP_CHECKED=1): after every insertion the
// structure's validity (validity_problem: symmetric links, positive real
// simplices, opposite induced orientations, convex hull) is asserted inside
// the algorithm. Outputs equal the brute-force definition for tiny inputs.
#include <catch2/catch.hpp>

#include "proptests/support/rtd_brute.hpp"
#include "proptests/support/rtd_inputs.hpp"
#include "reference/checked.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

TEST_CASE("rtd checked: invariants hold after every insertion for d 2 to 5") {
  static_assert(FF_CHECKED, "this test must link the checked build");
  // a loop over seeds: the checks cost O(#simplices) per insertion
  for (std::uint64_t seed = 1; seed <= 120 / test::kRtdSanitizerDivisor; ++seed) {
    const int d = 2 + static_cast<int>(seed % 4);
    const std::size_t n = static_cast<std::size_t>(d + 1) + (seed * 7) % (d >= 4 ? 12 : 30);
    const int kind = static_cast<int>((seed / 4) % 3);
    const PointSet ps = kind == 0 ? test::rtd_uniform(d, n, seed, 0.1)
                        : kind == 1 ? test::rtd_lattice(d, n, seed, 2, static_cast<int>((seed / 12) % 3))
                                    : test::rtd_duplicated(test::rtd_uniform(d, (n + 1) / 2, seed, 0.0), 2);
    try {
      const ref::Rtd r = ref::rtd_incremental(ps);
      if (ps.size() <= (d >= 4 ? 9u : 12u)) REQUIRE(r.simplices == test::brute_rtd(ps));
    } catch (const std::invalid_argument&) {
      REQUIRE(kind != 0);  // lattice and duplicated samples can be lower-dimensional
    }
  }
}

// hull3_cpu_test.cpp — the multithreaded ffHull of kernels_cpu/hull3 against
// the exact sequential reference (ref::hull3_ffhull): byte-identical canonical
// text for every input, at 1, 2 and 8 threads, degenerate inputs included,
// and the same rejection (same message) of input that does not span R^3.
//
// Oracles: ref::hull3_ffhull (GMP-free exact reference, itself tested against
// brute force and CGAL in ffhull_reference_test.cpp) and certify::hull3 at
// Level::canonical.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate / random sets of 4..60 points 2000 / 4 = 500;
// every generator family at 4..3000 points 2000 / 20 = 100; the deterministic
// sweep below: 13 families x 6 sizes x 2 seeds x 3 thread counts.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/outcome.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};

using test::is_error;
using test::outcome;

std::string cpu_text(const PointSet& ps, int threads, ref::Hull3Stats* st = nullptr) {
  cpu::Hull3Options o;
  o.threads = threads;
  return outcome([&] { return cpu::hull3_ffhull(ps, o, st); });
}

std::string ref_text(const PointSet& ps) {
  return outcome([&] { return ref::hull3_ffhull(ps); });
}

// cpu == reference at every thread count; counts consistent (every point is
// inserted, discarded early or one of the initial four). Returns the text.
std::string check_rc(const PointSet& ps) {
  const std::string expect = ref_text(ps);
  for (int t : kThreads) {
    ref::Hull3Stats st;
    const std::string got = cpu_text(ps, t, &st);
    RC_ASSERT(got == expect);
    if (!is_error(expect)) {
      RC_ASSERT(st.insertions == st.flips_1_3);
      RC_ASSERT(st.insertions + st.discarded_early + 4 == ps.size());
    }
  }
  return expect;
}

}  // namespace

TEST_CASE("hull3 cpu: degenerate and random small sets equal the reference at 1, 2, 8 threads (shrinking)",
          "[hull3_cpu]") {
  test::prop_scaled("degenerate sets of 4..60 points: cpu == reference byte for byte, certified", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 60, false);
    const std::string expect = check_rc(ps);
    if (!is_error(expect))
      RC_ASSERT(certify::hull3(ps, cpu::hull3_ffhull(ps), certify::Level::canonical).ok);
  });
}

TEST_CASE("hull3 cpu: every generator family up to 3000 points equals the reference (shrinking)", "[hull3_cpu]") {
  test::prop_scaled("family sets of 4..3000 points (grid3, sphere-lattice, coplanar3, duplicates3, huge3, "
                    "tiny3, jitter3, ...): cpu == reference at 1, 2, 8 threads",
                    20, [] {
                      const PointSet ps = *test::thinned(test::family_points(3, 4, 3000, false));
                      check_rc(ps);
                    });
}

TEST_CASE("hull3 cpu: deterministic sweep over the families, sizes and thread counts", "[hull3_cpu]") {
  std::size_t cases = 0, rejected = 0;
  for (const std::string& fam : test::families(3))
    for (std::size_t n : {4, 7, 30, 200, 2000, 20000})
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(fam, n, o);
        INFO(fam << " n=" << n << " seed=" << seed);
        const std::string expect = ref_text(ps);
        if (is_error(expect)) {
          ++rejected;
          REQUIRE(!dimension_problem(ps).empty());
        }
        for (int t : kThreads) {
          INFO("threads " << t);
          REQUIRE(cpu_text(ps, t) == expect);
          ++cases;
        }
      }
  std::cout << "hull3 cpu sweep: " << cases << " runs identical to the reference (" << rejected
            << " inputs rejected as flat by both)\n";
  REQUIRE(cases >= 13 * 6 * 2 * 3);
}

TEST_CASE("hull3 cpu: large ball, sphere and box inputs equal the reference, certified", "[hull3_cpu]") {
  for (const char* fam : {"ball", "sphere", "box", "cball", "sphere-lattice", "grid3"}) {
    gen::Options o;
    o.seed = 11;
    const PointSet ps = gen::generate(fam, 100000, o);
    INFO(fam);
    const auto expect = ref::hull3_ffhull(ps);
    for (int t : {1, 2, 8}) {
      cpu::Hull3Options opt;
      opt.threads = t;
      REQUIRE(cpu::hull3_ffhull(ps, opt) == expect);
    }
    REQUIRE(certify::hull3(ps, expect, certify::Level::canonical).ok);
  }
}

TEST_CASE("hull3 cpu: input that does not span R^3 is rejected like the reference", "[hull3_cpu]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0};  // coplanar
  REQUIRE(cpu_text(ps, 2) == ref_text(ps));
  REQUIRE(is_error(cpu_text(ps, 2)));
  ps.coords.resize(9);  // three points
  REQUIRE(cpu_text(ps, 1) == ref_text(ps));
  REQUIRE(is_error(cpu_text(ps, 1)));
  cpu::Hull3Options bad;
  bad.threads = -1;
  REQUIRE_THROWS_AS(cpu::hull3_ffhull(ps, bad), std::invalid_argument);
}

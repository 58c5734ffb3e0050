// rt2_cuda_omp_test.cpp — the GPU ffRT (kernels_cuda/rt2/rt2.cuh) built
// against thrust's OpenMP backend (kernels_omp::rt2_ffrt) against the exact
// sequential reference ref::rt2_ffrt: byte-identical canonical text for every
// input, degenerate inputs included, the same rejection of input that does not
// span the plane, and counters that add up.
//
// Oracle: ref::rt2_ffrt (itself tested against brute force, CGAL and the
// certifier in rt2_reference_test.cpp). The same comparison runs on a GPU in
// kernels_cuda/rt2_cuda_test.cpp.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate sets of 3..60 points 2000 / 8 = 250 each
// weighted and unweighted; every generator family at 3..1500 points
// 2000 / 40 = 50 each; the deterministic sweep: 2D families x 5 sizes x 2
// weightings; 20000 points in the three weight ranges of §5.4 and unweighted;
// 10^5 uniform points weighted and unweighted.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#ifdef FLIPFLOP_HAVE_KERNELS_OMP

#include <iostream>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cuda/rt2/rt2.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/omp_threads.hpp"
#include "proptests/support/outcome.hpp"
#include "proptests/support/rt2_outcome.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/rt2.hpp"

using namespace flipflop;

namespace {

using test::is_error;
using test::outcome;
using test::problem_of;
using test::ref_text;
using test::vertex_count;

std::string omp_text(const PointSet& ps, ref::Rt2Stats* st = nullptr) {
  return problem_of(outcome([&] { return kernels_omp::rt2_ffrt(ps, st); }));
}

// kernel == reference; the counts add up: every point is one of the initial
// three, inserted by a 1-3 flip, or discarded early, and the vertices are the
// inserted points less the 3-1 flips.
template <class Assert>
std::string check(const PointSet& ps, const Assert& require) {
  const std::string expect = ref_text(ps);
  ref::Rt2Stats st;
  require(omp_text(ps, &st) == expect);
  if (!is_error(expect)) {
    require(st.flips_1_3 + st.discarded_early + 3 == ps.size());
    require(vertex_count(kernels_omp::rt2_ffrt(ps)) == st.flips_1_3 + 3 - st.flips_3_1);
  }
  return expect;
}

std::string check_rc(const PointSet& ps) {
  return check(ps, [](bool ok) { RC_ASSERT(ok); });
}

}  // namespace

TEST_CASE("rt2 cuda-omp: degenerate and random small sets equal the reference (shrinking)", "[rt2_cuda_omp]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("degenerate sets of 3..60 points (grids, cocircular, collinear subsets, "
                                  "duplicates, equal weights), ") +
                          (weighted ? "weighted" : "unweighted") + ": omp == reference byte for byte",
                      8, [weighted] { check_rc(*test::degenerate_points(2, 3, 60, weighted)); });
}

TEST_CASE("rt2 cuda-omp: every generator family up to 1500 points equals the reference (shrinking)", "[rt2_cuda_omp]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("family sets of 3..1500 points (grid2, circle, duplicates2, huge2, tiny2, ...), ") +
                          (weighted ? "weights from none to 99% redundant" : "unweighted") + ": omp == reference",
                      40, [weighted] { check_rc(*test::thinned(test::family_points(2, 3, 1500, weighted))); });
}

TEST_CASE("rt2 cuda-omp: deterministic sweep over the families, sizes and weights", "[rt2_cuda_omp]") {
  std::size_t cases = 0, rejected = 0, families = 0;
  for (const std::string& fam : test::families(2)) {
    ++families;
    for (std::size_t n : {3, 4, 9, 40, 1000})
      for (bool weighted : {false, true}) {
        const PointSet ps = test::family_input(fam, n, 7, weighted, 1e-3);
        INFO(fam << " n=" << n << (weighted ? " weighted" : ""));
        const std::string expect = check(ps, [](bool ok) { REQUIRE(ok); });
        if (is_error(expect)) {
          ++rejected;
          REQUIRE(!dimension_problem(ps).empty());
        }
        ++cases;
      }
  }
  std::cout << "rt2 omp sweep: " << cases << " inputs over " << families << " families identical to the reference ("
            << rejected << " rejected as collinear by both)\n";
  REQUIRE(families >= 8);
}

TEST_CASE("rt2 cuda-omp: 20000 points in the three weight ranges of §5.4 and 10^5 points equal the reference",
          "[rt2_cuda_omp][long]") {
  // weights in [0, w] of a unit square: about 99 %, 20-30 % and 1 % of the
  // points non-redundant, and unweighted; degenerate families unweighted
  struct Case {
    const char* fam;
    std::size_t n;
    double whi;
  };
  // under TSan (make tsan) at sizes that still take several parallel steps
  const std::size_t k20 = test::large_n(20000, 6000), k100 = test::large_n(100000, 20000);
  for (const Case c : {Case{"square", k20, 2e-7}, Case{"square", k20, 1e-5}, Case{"square", k20, 1e-2},
                       Case{"grid2", k20, 0}, Case{"circle", k20, 0}, Case{"duplicates2", k20, 0},
                       Case{"square", k100, 0}, Case{"square", k100, 1e-5}}) {
    gen::Options o;
    o.seed = 11;
    o.weighted = c.whi > 0;
    o.whi = c.whi;
    const PointSet ps = gen::generate(c.fam, c.n, o);
    INFO(c.fam << " n=" << c.n << " weights [0, " << c.whi << "]");
    const auto expect = ref::rt2_ffrt(ps);
    ref::Rt2Stats st;
    REQUIRE(kernels_omp::rt2_ffrt(ps, &st) == expect);
    std::cout << "rt2 omp " << c.fam << " n=" << c.n << " w<=" << c.whi << ": " << vertex_count(expect)
              << " vertices; insertion rounds " << st.rounds << ", 1-3 flips " << st.flips_1_3 << ", 2-2 flips "
              << st.flips_2_2 << ", 3-1 flips " << st.flips_3_1 << ", discarded early " << st.discarded_early << "\n";
  }
}

// 16 OpenMP threads, as on the many-core machines that run this build (CI
// and the development VM have 2; see hull3_cuda_omp_test.cpp). Several runs
// in Release, one under ThreadSanitizer (make tsan).
TEST_CASE("rt2 cuda-omp: 16 OpenMP threads give the reference's output", "[rt2_cuda_omp]") {
  for (const double whi : {0.0, 1e-5}) {
    gen::Options o;
    o.seed = 5;
    o.weighted = whi > 0;
    o.whi = whi;
    const PointSet ps = gen::generate("square", test::large_n(50000, 8000), o);
    INFO("weights [0, " << whi << "]");
    const auto expect = ref::rt2_ffrt(ps);
    for (std::size_t run = 0; run < test::large_n(3, 1); ++run)
      REQUIRE(test::with_omp_threads(16, [&] { return kernels_omp::rt2_ffrt(ps); }) == expect);
  }
}

TEST_CASE("rt2 cuda-omp: input that does not span the plane is rejected like the reference", "[rt2_cuda_omp]") {
  PointSet ps;
  ps.dim = 2;
  ps.coords = {0, 0, 1, 1, 2, 2, 3, 3, -1, -1};  // collinear
  REQUIRE(omp_text(ps) == ref_text(ps));
  REQUIRE(is_error(omp_text(ps)));
  ps.coords = {0, 0, 1, 1};  // two points
  REQUIRE(omp_text(ps) == ref_text(ps));
  REQUIRE(is_error(omp_text(ps)));
  ps.coords = {4, 4, 4, 4, 4, 4, 4, 4};  // one location
  REQUIRE(omp_text(ps) == ref_text(ps));
  REQUIRE(is_error(omp_text(ps)));
  ps.dim = 3;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  REQUIRE_THROWS_AS(kernels_omp::rt2_ffrt(ps), std::invalid_argument);
}

#endif

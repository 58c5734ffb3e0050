// hull2_cuda_omp_test.cpp — the GPU 2D hull (kernels_cuda/hull2: throw-away,
// Graham-sorting or Graham-insertion, chunked and labelled parallel flip-pop)
// built against thrust's OpenMP backend (kernels_omp::hull2_graham_sort,
// hull2_graham_insert) against the exact sequential reference
// (ref::hull2_graham_sort, and ref::hull2_graham_insert for the messages of
// rejected input): byte-identical canonical text
// for every input, degenerate ones included, with and without the throw-away
// and with chunks of 3..256 vertices (many chunk borders, many labelled
// passes); the same rejection (same message) of input that does not span the
// plane. The CUDA build runs the same comparisons on a device
// (kernels_cuda/hull2_cuda_test.cpp).
//
// Oracles: ref::hull2_graham_sort (tested against brute::hull2, CGAL and the
// certifier in hull2_reference_test.cpp) and certify::hull2 at
// Level::canonical; the counts are checked for consistency.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate / random sets of 3..80 points 2000 / 4 = 500;
// every generator family at 3..4000 points 2000 / 10 = 200; the deterministic
// sweep: 11 families x 6 sizes x 2 seeds x 2 option sets x 2 algorithms.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <sstream>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cuda/hull2/hull2.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/family_sweep.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/omp_threads.hpp"
#include "proptests/support/outcome.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

using test::is_error;
using test::outcome;

// Graham-sorting (Algorithm 3) and Graham-insertion (Algorithm 4), each
// against the reference's run of the same algorithm (the same hull; on
// rejected input the same message, which names the algorithm).
enum class Algo { sort, insert };
constexpr Algo kAlgos[] = {Algo::sort, Algo::insert};

std::string omp_text(const PointSet& ps, const kernels::Hull2GpuOptions& o, ref::Hull2Stats* st = nullptr,
                     Algo a = Algo::sort) {
  return outcome([&] {
    return a == Algo::sort ? kernels_omp::hull2_graham_sort(ps, o, st) : kernels_omp::hull2_graham_insert(ps, o, st);
  });
}

std::string ref_text(const PointSet& ps, Algo a = Algo::sort) {
  return outcome([&] { return a == Algo::sort ? ref::hull2_graham_sort(ps) : ref::hull2_graham_insert(ps); });
}

rc::Gen<kernels::Hull2GpuOptions> any_options() {
  return rc::gen::exec([] {
    kernels::Hull2GpuOptions o;
    o.throw_away = *rc::gen::element(true, false);
    o.chunk = *rc::gen::element<std::size_t>(3, 4, 5, 8, 256);
    return o;
  });
}

// No throw-away, chunks of 3: every point reaches flip-pop, in the most passes.
kernels::Hull2GpuOptions tiny_options() {
  kernels::Hull2GpuOptions o;
  o.throw_away = false;
  o.chunk = 3;
  return o;
}

// kernels_omp == reference for both algorithms; counts consistent. Returns
// the reference text.
std::string check_rc(const PointSet& ps, const kernels::Hull2GpuOptions& o) {
  const std::string expect = ref_text(ps);
  for (Algo a : kAlgos) {
    ref::Hull2Stats st;
    const std::string got = omp_text(ps, o, &st, a);
    RC_ASSERT(got == ref_text(ps, a));
    if (!is_error(expect)) {
      RC_ASSERT(got == expect);
      RC_ASSERT(st.discarded_early + st.polygon_vertices == ps.size());
      RC_ASSERT(st.polygon_vertices - st.flips_2_1 == st.hull_vertices);
      if (a == Algo::insert) RC_ASSERT(st.polygon_vertices == st.insertions + 2);
      if (!o.throw_away && a == Algo::sort) RC_ASSERT(st.discarded_early == 0u);
    }
  }
  return expect;
}

}  // namespace

TEST_CASE("hull2 cuda-omp: degenerate and random small sets equal the reference (shrinking)", "[hull2_cuda_omp]") {
  test::prop_scaled("degenerate sets of 3..80 points: cuda-omp == reference byte for byte, certified", 4, [] {
    const PointSet ps = *test::degenerate_points(2, 3, 80, false);
    const kernels::Hull2GpuOptions o = *any_options();
    const std::string expect = check_rc(ps, o);
    if (!is_error(expect))
      RC_ASSERT(certify::hull2(ps, kernels_omp::hull2_graham_sort(ps, o), certify::Level::canonical).ok);
  });
}

TEST_CASE("hull2 cuda-omp: every generator family up to 4000 points equals the reference (shrinking)",
          "[hull2_cuda_omp]") {
  test::prop_scaled("family sets of 3..4000 points: cuda-omp == reference", 10, [] {
    const PointSet ps = *test::thinned(test::family_points(2, 3, 4000, false));
    check_rc(ps, *any_options());
  });
}

TEST_CASE("hull2 cuda-omp: deterministic sweep over the families, sizes and options", "[hull2_cuda_omp][long]") {
  std::size_t cases = 0;
  const kernels::Hull2GpuOptions tiny = tiny_options();
  const test::SweepCounts sweep = test::family_sweep(
      2, {3, 7, 30, 200, 2000, 50000}, 2, [](const PointSet& p) { return ref_text(p); }, [&](const PointSet& ps, const std::string& expect) {
        for (const kernels::Hull2GpuOptions& o : {kernels::Hull2GpuOptions{}, tiny})
          for (Algo a : kAlgos) {
            ref::Hull2Stats st;
            REQUIRE(omp_text(ps, o, &st, a) == (a == Algo::sort ? expect : ref_text(ps, a)));
            if (!is_error(expect)) REQUIRE(st.polygon_vertices - st.flips_2_1 == st.hull_vertices);
            ++cases;
          }
      });
  const std::size_t rejected = sweep.rejected;
  INFO("cases " << cases << ", rejected " << rejected);
  REQUIRE(cases > 0);
  REQUIRE(rejected < cases);
}

// Every family above the 16384 items from which a step runs on several
// threads (kParallelFrom): with the default options, and without the
// throw-away in chunks of 3, so that the chunked passes and Algorithm 2's
// atomic-minimum labels (lines 5-12) run over every point.
TEST_CASE("hull2 cuda-omp: large inputs of every family equal the reference, certified", "[hull2_cuda_omp][long]") {
  for (const std::string& fam : test::families(2)) {
    gen::Options g;
    g.seed = 11;
    g.thickness = 0.01;
    const PointSet ps = gen::generate(fam, 100000, g);
    INFO(fam);
    bool rejected = false;
    for (Algo a : kAlgos) {
      const std::string expect = ref_text(ps, a);
      rejected = is_error(expect);
      for (const kernels::Hull2GpuOptions& o : {kernels::Hull2GpuOptions{}, tiny_options()}) {
        ref::Hull2Stats st;
        REQUIRE(omp_text(ps, o, &st, a) == expect);
        if (!rejected) REQUIRE(st.polygon_vertices - st.flips_2_1 == st.hull_vertices);
      }
    }
    if (!rejected) REQUIRE(certify::hull2(ps, kernels_omp::hull2_graham_sort(ps, {}), certify::Level::canonical).ok);
  }
}

// 16 OpenMP threads, as on the many-core machines that run this build (CI
// and the development VM have 2; see hull3_cuda_omp_test.cpp): more
// boundaries between the threads' ranges, where Algorithm 2's labels of
// neighbouring vertices meet. Without the throw-away in chunks of 3, so that
// every pass runs over many points. Several runs in Release, one under
// ThreadSanitizer (make tsan).
TEST_CASE("hull2 cuda-omp: 16 OpenMP threads give the reference's output", "[hull2_cuda_omp]") {
  const kernels::Hull2GpuOptions tiny = tiny_options();
  for (const char* fam : {"disk", "circle"}) {
    gen::Options g;
    g.seed = 5;
    const PointSet ps = gen::generate(fam, test::large_n(100000, 40000), g);
    INFO(fam);
    for (Algo a : kAlgos) {
      const std::string expect = ref_text(ps, a);
      for (std::size_t run = 0; run < test::large_n(3, 1); ++run)
        REQUIRE(test::with_omp_threads(16, [&] { return omp_text(ps, tiny, nullptr, a); }) == expect);
    }
  }
}

TEST_CASE("hull2 cuda-omp: input that does not span the plane is rejected with the reference's message",
          "[hull2_cuda_omp]") {
  for (const std::string& pts : {std::string("0 0\n1 1\n2 2\n3 3\n"), std::string("1 2\n1 2\n1 2\n"),
                                 std::string("0 0\n1 0\n")}) {
    PointSet ps;
    ps.dim = 2;
    double x, y;
    std::istringstream in(pts);
    while (in >> x >> y) ps.coords.insert(ps.coords.end(), {x, y});
    for (Algo a : kAlgos) {
      const std::string expect = ref_text(ps, a);
      REQUIRE(is_error(expect));
      REQUIRE(omp_text(ps, {}, nullptr, a) == expect);
    }
  }
}

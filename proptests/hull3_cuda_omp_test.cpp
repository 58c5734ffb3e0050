// hull3_cuda_omp_test.cpp — the data-parallel ffHull of kernels_cuda/hull3
// (hull3.cuh), built against thrust's OpenMP backend (kernels_omp), against
// the exact sequential reference ref::hull3_ffhull: byte-identical canonical
// text for every input, degenerate inputs included, the same rejection (same
// message) of input that does not span R^3, ffHull's counters' lemmas, and no
// work handed back to the host; line 1's reductions (kernels_cuda/spread.cuh)
// on their own, with floating keys that pick the worst points.
//
// Oracle: ref::hull3_ffhull (itself tested against brute force and CGAL in
// ffhull_reference_test.cpp); certify::hull3 at Level::canonical on the
// large inputs.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate / random sets of 4..60 points 2000 / 4 = 500;
// every generator family at 4..3000 points 2000 / 20 = 100; line 1 with
// adversarial keys 2000 / 4 = 500; the deterministic
// sweep: every 3D family x 6 sizes (4..10000: above the kernel's parallel threshold of
// 4096, half the time of 20000) x 2 seeds; five large inputs of
// 10^4..10^5 points.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#ifdef FLIPFLOP_HAVE_KERNELS_OMP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <iostream>
#include <limits>
#include <set>
#include <type_traits>
#include <stdexcept>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cuda/hull3/hull3.hpp"
#include "kernels_cuda/spread.cuh"
#include "proptests/support/families.hpp"
#include "proptests/support/hull3_expect.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/omp_threads.hpp"
#include "proptests/support/outcome.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"

using namespace flipflop;

namespace {

using test::is_error;
using test::outcome;

std::string omp_text(const PointSet& ps, ref::Hull3Stats* st = nullptr, cpu::StageTimes* times = nullptr) {
  return outcome([&] { return kernels_omp::hull3_ffhull(ps, st, times); });
}

std::string ref_text(const PointSet& ps) { return test::hull3_reference_text(ps); }

using test::vertex_count;

// ffHull's counters (fuzz/hull3_check.cpp): every point but the tetrahedron
// is inserted or discarded early; every 3-1 flip removes an inserted vertex;
// only removed vertices are labelled.
bool counts_ok(const PointSet& ps, const ref::Hull3Stats& st, std::size_t V) {
  return st.insertions == st.flips_1_3 && 4 + st.insertions + st.discarded_early == ps.size() &&
         4 + st.insertions == V + st.flips_3_1 && st.labelled_non_extreme <= st.flips_3_1 &&
         st.handed_back == 0;  // issue 36: a returned hull never ran the reference's line 1
}

// kernels_omp == reference, counters consistent. Returns the text.
std::string check_rc(const PointSet& ps) {
  const std::string expect = ref_text(ps);
  ref::Hull3Stats st;
  const std::string got = omp_text(ps, &st);
  RC_ASSERT(got == expect);
  if (!is_error(expect)) RC_ASSERT(counts_ok(ps, st, vertex_count(ref::hull3_ffhull(ps))));
  return expect;
}

bool has_stage(const cpu::StageTimes& t, const std::string& name) {
  return std::any_of(t.stages.begin(), t.stages.end(), [&](const auto& s) { return s.first == name; });
}

}  // namespace

TEST_CASE("hull3 cuda-omp: degenerate and random small sets equal the reference (shrinking)",
          "[hull3_cuda_omp]") {
  test::prop_scaled("degenerate sets of 4..60 points: kernels_omp == reference byte for byte", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 60, false);
    check_rc(ps);
  });
}

// Line 1 (spread.cuh) with an arg-max that answers every floating key with an
// arbitrary point (drawn per case: the heuristic's worst misses, a point
// repeated, collinear or coplanar choices) and the exact keys honestly, by a
// sequential reduction with BestOf's tie rule: the repair alone must give four
// exactly independent points, (a, b, c) counter-clockwise from outside, without
// the reference's rule; and reject, with the reference's message, exactly the
// input the reference rejects.
TEST_CASE("hull3 cuda-omp: line 1's exact repair spans R^3 whatever the floating keys pick (shrinking)",
          "[hull3_cuda_omp]") {
  test::prop_scaled("adversarial TetKey answers: four independent points, never the reference's rule", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 60, false);
    const std::vector<std::size_t> pick = *rc::gen::container<std::vector<std::size_t>>(
        5, rc::gen::inRange<std::size_t>(0, ps.size()));
    const auto argmax = [&](const auto& key) -> Index {
      if constexpr (std::is_same_v<std::decay_t<decltype(key)>, dev::TetKey>) {
        return static_cast<Index>(pick[static_cast<std::size_t>(key.mode)]);
      } else {
        dev::Best b{-HUGE_VAL, std::numeric_limits<Index>::max()};
        for (std::size_t i = 0; i < ps.size(); ++i) b = dev::BestOf()(b, key(i));
        return b.id;
      }
    };
    const std::string expect = ref_text(ps);
    bool by_reference = false;
    std::array<Index, 4> t{};
    try {
      t = dev::spanning_tetrahedron(ps, ps.coords.data(), argmax, &by_reference);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(by_reference);
      RC_ASSERT(is_error(expect));
      RC_ASSERT(expect.find(e.what()) != std::string::npos);
      return;
    }
    RC_ASSERT(!is_error(expect));
    RC_ASSERT(!by_reference);
    RC_ASSERT(pred::orient3d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), ps.point(t[3])) > 0);
  });
}

// CI's seed 5750008963199692262 (stop 85's run; hull3_expect.hpp): line 1's
// keys picked four coplanar points, the reference's rule ran and the run
// counted a hand-back. Both GPU hulls (ffHull here, gHull in
// ghull_cuda_omp_test.cpp) now repair it on the device.
TEST_CASE("hull3 cuda-omp: subnormal coordinates beside unit ones stay on the device", "[hull3_cuda_omp]") {
  const PointSet ps = test::subnormal_line1_points();
  ref::Hull3Stats st;
  REQUIRE(omp_text(ps, &st) == ref_text(ps));
  REQUIRE_FALSE(is_error(ref_text(ps)));
  CHECK(st.handed_back == 0);
}

TEST_CASE("hull3 cuda-omp: every generator family up to 3000 points equals the reference (shrinking)",
          "[hull3_cuda_omp]") {
  test::prop_scaled("family sets of 4..3000 points (grid3, sphere-lattice, coplanar3, duplicates3, huge3, "
                    "tiny3, jitter3, ...): kernels_omp == reference",
                    20, [] {
                      const PointSet ps = *test::thinned(test::family_points(3, 4, 3000, false));
                      check_rc(ps);
                    });
}

TEST_CASE("hull3 cuda-omp: deterministic sweep over the families and sizes", "[hull3_cuda_omp][long]") {
  std::size_t cases = 0, rejected = 0, exact_kernel = 0;
  const std::vector<std::string> fams = test::families(3);
  test::for_each_family_input(3, {4, 7, 30, 200, 2000, 10000}, 2,
                              [&](const std::string& fam, std::size_t n, std::uint64_t seed, const PointSet& ps) {
                                INFO(fam << " n=" << n << " seed=" << seed);
                                const std::string expect = test::hull3_sweep_expect(ps, rejected);
                                ref::Hull3Stats st;
                                REQUIRE(omp_text(ps, &st) == expect);
                                if (!is_error(expect)) {
                                  REQUIRE(counts_ok(ps, st, vertex_count(ref::hull3_ffhull(ps))));
                                  REQUIRE(st.handed_back == 0);  // every family stays on the device
                                }
                                exact_kernel += st.exact_kernel_point;
                                ++cases;
                              });
  std::cout << "hull3 kernels_omp sweep: " << cases << " runs identical to the reference (" << rejected
            << " inputs rejected as flat by both, " << exact_kernel << " with the exact kernel point)\n";
  REQUIRE(cases == fams.size() * 6 * 2);
  REQUIRE(fams.size() >= 13);
}

TEST_CASE("hull3 cuda-omp: large ball, sphere, box and lattice inputs equal the reference, certified",
          "[hull3_cuda_omp][long]") {
  const std::pair<const char*, std::size_t> inputs[] = {
      {"ball", test::large_n(100000, 20000)},        {"sphere", test::large_n(100000, 20000)},
      {"box", test::large_n(30000, 10000)},          {"sphere-lattice", test::large_n(30000, 10000)},
      {"grid3", 10000}};
  for (const auto& [fam, n] : inputs) {
    gen::Options o;
    o.seed = 11;
    const PointSet ps = gen::generate(fam, n, o);
    INFO(fam << " n=" << n);
    const auto expect = ref::hull3_ffhull(ps);
    ref::Hull3Stats st;
    cpu::StageTimes times;
    REQUIRE(kernels_omp::hull3_ffhull(ps, &st, &times) == expect);
    REQUIRE(counts_ok(ps, st, vertex_count(expect)));
    for (const char* stage : {"upload", "tetrahedron", "construction", "flip-flop", "output", "download"})
      REQUIRE(has_stage(times, stage));
    REQUIRE(certify::hull3(ps, expect, certify::Level::canonical).ok);
  }
}

// 16 OpenMP threads, as on the many-core machines that run this build (CI
// and the development VM have 2): thrust's OpenMP sort of the output allocates
// its merges' temporary arrays from inside its parallel region, from the
// kernel's pool of temporary storage (TempStorage, locked since; unlocked, 16 of
// 40 runs of flipflop hull3 --backend cuda-omp on 50000 sphere points crashed
// or hung at OMP_NUM_THREADS=16, 2026-11-27). Several runs in Release, one
// under ThreadSanitizer (make tsan), which needs no unlucky timing.
// Line 8 among points exactly in a triangle's plane (in_plane_tie.hpp), as
// hull3_cpu_test's case: the reference's answer, and few insertions (with
// ties broken by the smaller index alone, most of the bottom face's points
// were inserted).
TEST_CASE("hull3 cuda-omp: points in the plane of a face are inserted furthest first under the perturbation",
          "[hull3_cuda_omp]") {
  for (const double apex_z : {1000.0, -1000.0}) {
    const PointSet ps = test::lattice_pyramid(10000, apex_z, 5);
    const std::string expect = ref_text(ps);
    REQUIRE(!is_error(expect));
    ref::Hull3Stats st;
    INFO("apex z " << apex_z);
    REQUIRE(omp_text(ps, &st) == expect);
    REQUIRE(counts_ok(ps, st, vertex_count(ref::hull3_ffhull(ps))));
    std::cout << "hull3 cuda-omp lattice pyramid, apex z " << apex_z << ": insertions " << st.insertions << " of "
              << ps.size() << " points\n";
    REQUIRE(st.insertions <= ps.size() / 5);
  }
}

TEST_CASE("hull3 cuda-omp: 16 OpenMP threads give the reference's output", "[hull3_cuda_omp]") {
  for (const char* fam : {"sphere", "ball"}) {
    gen::Options o;
    o.seed = 5;
    const PointSet ps = gen::generate(fam, test::large_n(50000, 10000), o);
    INFO(fam);
    const auto expect = ref::hull3_ffhull(ps);
    for (std::size_t run = 0; run < test::large_n(5, 1); ++run)
      REQUIRE(test::with_omp_threads(16, [&] { return kernels_omp::hull3_ffhull(ps); }) == expect);
  }
}

// An almost flat initial tetrahedron: the fourth point 2^-1074 above the
// plane z = 0, so the rounded centroid (z = 2^-1076 -> 0) lies on the face
// plane, not strictly inside — the exact kernel point (hull3.cuh, line 4),
// whose side tests the kernel decides itself (issue 38: no hand-back to the
// reference; the stages are the kernel's own).
TEST_CASE("hull3 cuda-omp: an almost flat tetrahedron takes the exact kernel point", "[hull3_cuda_omp]") {
  PointSet ps;
  ps.dim = 3;
  const double tiny = 4.9406564584124654e-324;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, tiny, 0.5, 0.25, 0, 0.2, 0.2, tiny, 1, 1, 0};
  cpu::StageTimes times;
  ref::Hull3Stats st;
  REQUIRE(omp_text(ps, &st, &times) == ref_text(ps));
  REQUIRE(!is_error(ref_text(ps)));
  REQUIRE(st.exact_kernel_point == 1);
  for (const char* stage : {"upload", "tetrahedron", "construction", "flip-flop", "output", "download"})
    REQUIRE(has_stage(times, stage));
  REQUIRE(counts_ok(ps, st, vertex_count(ref::hull3_ffhull(ps))));
}

// Larger almost flat inputs on the exact kernel point: points of [0, 1]^2 at
// two heights one ulp apart (z = 1 or 1 + 2^-52: the centroid's z, 1 + 2^-54
// or 1 + 2^-53, rounds onto a face plane) or 0 and 2^-1074, many of them
// coplanar (the SoS decides the faces), thinned and whole. Every run must
// take the exact kernel point (else this test would not test it) and equal
// the reference byte for byte.
TEST_CASE("hull3 cuda-omp: almost flat slabs on the exact kernel point equal the reference",
          "[hull3_cuda_omp]") {
  std::size_t runs = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    for (const bool subnormal : {false, true}) {
      const PointSet ps = test::almost_flat_slab(seed, subnormal, seed <= 3 ? 40 : 2000);
      const std::string expect = ref_text(ps);
      INFO("seed " << seed << " subnormal " << subnormal << ": " << expect.substr(0, 80));
      if (is_error(expect)) continue;  // all points on one plane: rejected by both
      ref::Hull3Stats st;
      REQUIRE(omp_text(ps, &st) == expect);
      if (st.exact_kernel_point == 0) continue;  // the extreme points' tetrahedron was not flat enough
      REQUIRE(counts_ok(ps, st, vertex_count(ref::hull3_ffhull(ps))));
      ++runs;
    }
  std::cout << "hull3 kernels_omp almost flat slabs: " << runs << " runs on the exact kernel point\n";
  REQUIRE(runs >= 10);
}

TEST_CASE("hull3 cuda-omp: input that does not span R^3 is rejected like the reference", "[hull3_cuda_omp]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0};  // coplanar
  REQUIRE(is_error(omp_text(ps)));
  REQUIRE(omp_text(ps) == ref_text(ps));
  ps.coords = {1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3};  // one point, five times
  REQUIRE(is_error(omp_text(ps)));
  REQUIRE(omp_text(ps) == ref_text(ps));
  ps.coords = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};  // collinear
  REQUIRE(omp_text(ps) == ref_text(ps));
  ps.coords.resize(9);  // three points
  REQUIRE(is_error(omp_text(ps)));
  REQUIRE(omp_text(ps) == ref_text(ps));
  PointSet flat2;
  flat2.dim = 2;
  flat2.coords = {0, 0, 1, 0, 0, 1, 1, 1};
  REQUIRE(is_error(omp_text(flat2)));
  REQUIRE(omp_text(flat2) == ref_text(flat2));
}

#endif

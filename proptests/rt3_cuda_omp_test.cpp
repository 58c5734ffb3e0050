// rt3_cuda_omp_test.cpp — the GPU 3D regular triangulation
// (kernels_cuda/rt3/rt3.cuh) built against thrust's OpenMP backend
// (kernels_omp::rt3) against the exact sequential reference (RT+1,
// ref::rtd_incremental with d = 3) and kernels_cpu/rt3: byte-identical
// canonical text and redundant points for every input, degenerate inputs
// included, weighted and not; the kernel's witness certified by
// cpu::certify_rt3; the same rejection of input that is not finite or does
// not span R^3; counters that add up; the same answer at 1, 2 and 16 OpenMP
// threads.
//
// Oracles: ref::rtd_incremental (tested against brute force, CGAL and the
// certifier in rtd_reference_test.cpp), kernels_cpu/rt3 where the reference
// is too slow (itself equal to the reference: rt3_cpu_test.cpp), and
// cpu::certify_rt3 at Level::canonical on the kernel's own witness.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate sets of 4..60 points 2000 / 8 = 250 each
// weighted and unweighted; generator families at 4..1000 points 2000 / 40 =
// 50 each; the deterministic sweep: every 3D family x 5 sizes x 2
// weightings; the named degenerate families; 20000 points in three weight
// ranges and the degenerate families ([long]); 10^5 uniform points ([long]).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#ifdef FLIPFLOP_HAVE_KERNELS_OMP

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#include "kernels_cuda/rt3/rt3.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif
#include "proptests/support/families.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/omp_threads.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/rt3_outcome.hpp"
#include "reference/dimension.hpp"

using namespace flipflop;

namespace {

using test::is_error;
using test::with_weights;

std::string omp_text(const PointSet& ps, kernels::Rt3GpuStats* st = nullptr) {
  return test::rt3_outcome([&] { return kernels_omp::rt3(ps, st); });
}

// kernel == expect; the counts add up (every point is inserted — the first
// four included — or discarded when located; the tetrahedra replaced and
// created differ by the slots used beyond the first five, less those that
// died); the kernel's witness certifies its answer at Level::canonical.
template <class Assert>
void check_against(const PointSet& ps, const std::string& expect, const Assert& require) {
  kernels::Rt3GpuStats st;
  require(omp_text(ps, &st) == expect);
  if (is_error(expect)) return;
  require(st.inserted + st.discarded == ps.size());
  require(st.inserted >= 4 && st.attempts >= st.inserted - 4);
  require(st.created_tets >= st.cavity_tets);
  cpu::Rt3Witness w;
  const cpu::Rt3Result r = kernels_omp::rt3(ps, nullptr, nullptr, &w);
  require(cpu::certify_rt3(ps, w, r.tets, certify::Level::canonical).ok);
}

std::string check_rc(const PointSet& ps) {
  const std::string expect = test::rt3_ref_text(ps);
  check_against(ps, expect, [](bool ok) { RC_ASSERT(ok); });
  return expect;
}

std::string check_req(const PointSet& ps) {
  const std::string expect = test::rt3_ref_text(ps);
  check_against(ps, expect, [](bool ok) { REQUIRE(ok); });
  return expect;
}

}  // namespace

TEST_CASE("rt3 cuda-omp: degenerate and random small sets equal the reference (shrinking)", "[rt3_cuda_omp]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("degenerate 3D sets of 4..60 points (grids, cospherical, coplanar subsets, "
                                  "duplicates, equal weights), ") +
                          (weighted ? "weighted" : "unweighted") + ": omp == reference byte for byte, certified",
                      8, [weighted] { check_rc(*test::degenerate_points_d(3, 4, 60, weighted)); });
}

TEST_CASE("rt3 cuda-omp: every 3D generator family up to 1000 points equals the reference (shrinking)",
          "[rt3_cuda_omp]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("3D family sets of 4..1000 points (cube, ball, sphere, grid3, sphere-lattice, "
                                  "duplicates3, planes3, ...), ") +
                          (weighted ? "weights from none to many redundant" : "unweighted") + ": omp == reference",
                      40, [weighted] { check_rc(*test::thinned(test::family_points(3, 4, 1000, weighted))); });
}

TEST_CASE("rt3 cuda-omp: deterministic sweep over the 3D families, sizes and weights", "[rt3_cuda_omp]") {
  std::size_t cases = 0, rejected = 0, families = 0;
  for (const std::string& fam : test::families(3)) {
    ++families;
    for (std::size_t n : {4, 5, 9, 40, 800})
      for (bool weighted : {false, true}) {
        const PointSet ps = test::family_input(fam, n, 7, weighted, 1e-3);
        INFO(fam << " n=" << n << (weighted ? " weighted" : ""));
        const std::string expect = check_req(ps);
        if (is_error(expect)) {
          ++rejected;
          REQUIRE(!dimension_problem(ps).empty());
        }
        ++cases;
      }
  }
  std::cout << "rt3 omp sweep: " << cases << " inputs over " << families << " families identical to the reference ("
            << rejected << " rejected by both)\n";
  REQUIRE(families >= 8);
}

// The degenerate families of the CPU issue, each with its own structure.
TEST_CASE("rt3 cuda-omp: lattices, cospherical sets, duplicates and redundant-heavy inputs equal the reference",
          "[rt3_cuda_omp]") {
  gen::Options o;
  o.seed = 7;
  const PointSet grid = gen::generate("grid3", 343, o);  // 7^3: every cell cospherical
  SECTION("the named degenerate inputs (rt3_outcome.hpp)") {
    for (const auto& [name, ps] : test::rt3_degenerate_inputs(grid)) {
      INFO(name);
      check_req(ps);
    }
  }
  SECTION("sphere lattice (cospherical)") { check_req(gen::generate("sphere-lattice", 400, o)); }
  SECTION("planes with duplicates (planes3)") { check_req(gen::generate("planes3", 1500, o)); }
  SECTION("duplicates3") { check_req(gen::generate("duplicates3", 1500, o)); }
  SECTION("all points redundant but four") {
    PointSet ps;
    ps.dim = 3;
    std::vector<double> c, w;
    for (int i = 0; i < 200; ++i) {
      c.insert(c.end(), {(i % 7) * 0.3 - 1, (i % 5) * 0.3 - 1, (i % 3) * 0.3 - 1});
      w.push_back(0);
    }
    // a huge-weight tetrahedron swallows everything inside it
    c.insert(c.end(), {-10, -10, -10, 10, -10, -10, 0, 10, -10, 0, 0, 10});
    w.insert(w.end(), {1000, 1000, 1000, 1000});
    ps.coords = Values(std::move(c));
    ps = with_weights(ps, w);
    const std::string expect = check_req(ps);
    REQUIRE(std::count(expect.begin(), expect.end(), '\n') == 1);  // one tetrahedron
  }
}

// A cavity larger than its room (64 tetrahedra at first) retries in a later
// round with twice the room: the sphere lattice (cavities reach far under SoS)
// and a grid overflow it; the answer is still the reference's.
TEST_CASE("rt3 cuda-omp: cavities that overflow the scratch retry with more room", "[rt3_cuda_omp]") {
  gen::Options o;
  o.seed = 3;
  std::uint64_t overflowed = 0, lost = 0, exact = 0;
  for (const PointSet& ps : {gen::generate("sphere-lattice", 2000, o), gen::generate("grid3", 1000, o)}) {
    kernels::Rt3GpuStats st;
    REQUIRE(omp_text(ps, &st) == test::rt3_ref_text(ps));
    overflowed += st.overflowed, lost += st.lost, exact += st.exact_items;
    std::cout << "rt3 omp " << ps.size() << " points: rounds " << st.rounds << ", attempts " << st.attempts
              << ", lost " << st.lost << ", overflowed " << st.overflowed << " (capacity up to " << st.max_capacity
              << "), exact items " << st.exact_items << "\n";
  }
  REQUIRE(overflowed > 0);
  REQUIRE(lost > 0);
  REQUIRE(exact > 0);
}

TEST_CASE("rt3 cuda-omp: 20000 points in three weight ranges and the degenerate families equal the CPU kernel, "
          "certified",
          "[rt3_cuda_omp][long]") {
  struct Case {
    const char* fam;
    double whi;
  };
  for (const Case c : {Case{"cube", 0}, Case{"cube", 1e-6}, Case{"cube", 1e-4}, Case{"cube", 1e-2},
                       Case{"ball", 0}, Case{"sphere", 0}, Case{"grid3", 0}, Case{"sphere-lattice", 0},
                       Case{"planes3", 0}, Case{"duplicates3", 0}}) {
    gen::Options o;
    o.seed = 5;
    o.weighted = c.whi > 0;
    o.whi = c.whi;
    const PointSet ps = gen::generate(c.fam, test::large_n(20000, 5000), o);
    INFO(c.fam << " weights [0, " << c.whi << "]");
    const cpu::Rt3Result expect = cpu::rt3(ps);
    kernels::Rt3GpuStats st;
    cpu::Rt3Witness w;
    const cpu::Rt3Result r = kernels_omp::rt3(ps, &st, nullptr, &w);
    REQUIRE(r.tets == expect.tets);
    REQUIRE(r.redundant == expect.redundant);
    REQUIRE(cpu::certify_rt3(ps, w, r.tets).ok);
    std::cout << "rt3 omp " << c.fam << " n=" << ps.size() << " w<=" << c.whi << ": " << r.tets.size()
              << " tetrahedra; rounds " << st.rounds << ", attempts " << st.attempts << ", lost " << st.lost
              << ", overflowed " << st.overflowed << ", discarded " << st.discarded << ", exact items "
              << st.exact_items << "\n";
  }
}

// The round's scratch budget (Rt3GpuOptions::scratch_bytes) decides how many
// of a round's winners take part; the others wait for a later round. Budgets
// of 1 byte (one winner a round, the rule's minimum), 64 KiB (a dozen) and
// 1 MiB change the rounds, never the answer or its certificate.
TEST_CASE("rt3 cuda-omp: a small scratch budget takes part of a round's winners, with the same answer",
          "[rt3_cuda_omp]") {
  gen::Options o;
  o.seed = 9;
  for (const PointSet& ps : {gen::generate("ball", 3000, o), gen::generate("grid3", 1000, o)}) {
    const std::string expect = test::rt3_outcome([&] { return cpu::rt3(ps); });
    kernels::Rt3GpuStats full;
    REQUIRE(test::rt3_outcome([&] { return kernels_omp::rt3(ps, &full); }) == expect);
    for (std::size_t bytes : {std::size_t{1} << 20, std::size_t{1} << 16, std::size_t{1}}) {
      kernels::Rt3GpuOptions opt;
      opt.scratch_bytes = bytes;
      kernels::Rt3GpuStats st;
      cpu::Rt3Witness w;
      cpu::Rt3Result r;
      REQUIRE(test::rt3_outcome([&] { return r = kernels_omp::rt3(ps, &st, nullptr, &w, opt); }) == expect);
      INFO(ps.size() << " points, budget " << bytes << " bytes: " << st.rounds << " rounds (" << full.rounds
                     << " with the default budget)");
      REQUIRE(cpu::certify_rt3(ps, w, r.tets).ok);
      // one winner a round at the smallest budget: a round per insertion
      if (bytes == 1) REQUIRE(st.rounds >= st.inserted - 4);
      if (bytes == 1) REQUIRE(st.attempts == st.rounds);
    }
  }
}

// 16 OpenMP threads, as on the many-core machines that run this build, and
// 1: every choice is a minimum or a scan, so the witness is the same too.
TEST_CASE("rt3 cuda-omp: 1, 2 and 16 OpenMP threads give the same answer and the same witness", "[rt3_cuda_omp]") {
  for (const double whi : {0.0, 1e-4}) {
    gen::Options o;
    o.seed = 5;
    o.weighted = whi > 0;
    o.whi = whi;
    const PointSet ps = gen::generate("ball", test::large_n(30000, 3000), o);
    INFO("weights [0, " << whi << "]");
    const cpu::Rt3Result expect = cpu::rt3(ps);
    cpu::Rt3Witness w1;
    const cpu::Rt3Result r1 = test::with_omp_threads(1, [&] { return kernels_omp::rt3(ps, nullptr, nullptr, &w1); });
    REQUIRE(r1.tets == expect.tets);
    REQUIRE(r1.redundant == expect.redundant);
    for (int threads : {2, 16}) {
      cpu::Rt3Witness w;
      const cpu::Rt3Result r =
          test::with_omp_threads(threads, [&] { return kernels_omp::rt3(ps, nullptr, nullptr, &w); });
      INFO(threads << " threads");
      REQUIRE(r.tets == expect.tets);
      REQUIRE(r.redundant == expect.redundant);
      REQUIRE(w.tv == w1.tv);
      REQUIRE(w.tn == w1.tn);
      REQUIRE(w.at == w1.at);
    }
  }
}

TEST_CASE("rt3 cuda-omp: input that is not finite or does not span R^3 is rejected like the reference",
          "[rt3_cuda_omp]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 3, 2, 0};  // coplanar
  REQUIRE(is_error(omp_text(ps)));
  REQUIRE(omp_text(ps) == test::rt3_ref_text(ps));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // three points
  REQUIRE(is_error(omp_text(ps)));
  REQUIRE(omp_text(ps) == test::rt3_ref_text(ps));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN, 1, 1, 0};
  REQUIRE(omp_text(ps) == "error: a coordinate is not finite");
  REQUIRE(omp_text(ps) == test::rt3_ref_text(ps));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
  ps = with_weights(ps, {0, 0, INFINITY, 0, 0});
  REQUIRE(omp_text(ps) == "error: a weight is not finite");
  REQUIRE(omp_text(ps) == test::rt3_ref_text(ps));
  PointSet flat;
  flat.dim = 2;
  flat.coords = {0, 0, 1, 0, 0, 1};
  REQUIRE_THROWS_AS(kernels_omp::rt3(flat), std::invalid_argument);
}

TEST_CASE("rt3 cuda-omp: extreme magnitudes (1e±300, subnormals) equal the reference", "[rt3_cuda_omp]") {
  for (double s : {1e300, 1e-300, 4.9406564584124654e-324 * 1024, 1.0}) {
    PointSet ps;
    ps.dim = 3;
    std::vector<double> c;
    for (int i = 0; i < 40; ++i) c.insert(c.end(), {s * (i % 4), s * ((i / 4) % 3), s * ((i * 7) % 5)});
    ps.coords = Values(std::move(c));
    INFO("scale " << s);
    check_req(ps);
  }
}

#ifdef FLIPFLOP_HAVE_KERNELS_GPU
// Issue 36 item 4: the command line begins the CUDA start-up in a thread
// while it reads the input — for --backend cuda in a build with the CUDA
// kernels only (without a device the start-up fails quietly and the kernel
// reports the missing device in one line).
TEST_CASE("rt3 cuda-omp: the CUDA start-up thread begins for --backend cuda in a build with the CUDA kernels only",
          "[rt3_cuda_omp]") {
  kernels::DeviceStart omp("cuda-omp"), cpu("cpu");
  REQUIRE(!omp.started());
  REQUIRE(!cpu.started());
  REQUIRE(omp.wait() == 0);
  const auto built = kernels::gpu_backends_built();
  const bool cuda_built = std::find(built.begin(), built.end(), "cuda") != built.end();
  kernels::DeviceStart cuda("cuda");
  REQUIRE(cuda.started() == cuda_built);
  const double s = cuda.wait();
  REQUIRE((cuda_built ? s > 0 : s == 0));
  REQUIRE(cuda.wait() == s);  // joined once; the seconds stay
}
#endif

#endif

// hull2_cpu_test.cpp — the multithreaded 2D hull of kernels_cpu/hull2 (throw-
// away, then parallel Graham-sorting or parallel Graham-insertion, with
// chunked flip-pop) against the exact sequential reference
// (ref::hull2_graham_sort, and ref::hull2_graham_insert for the messages of
// rejected input): byte-identical canonical
// text for every input, at 1, 2 and 8 threads, degenerate inputs included,
// and the same rejection (same message) of input that does not span the plane.
//
// The tuning options (Hull2Options: throw-away threshold, sample size, chunk
// of the parallel flip-pop pass) are drawn too: on small inputs they force the
// throw-away with tiny samples (badly placed polygons, centres on the
// boundary) and chunks of 1..8 vertices (many chunk borders), so every path is
// reached; the answer must not depend on them.
//
// Oracles: ref::hull2_graham_sort (tested against brute::hull2, CGAL and the
// certifier in hull2_reference_test.cpp), certify::hull2 at Level::canonical,
// and for the throw-away alone: no vertex of the reference hull is discarded.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate / random sets of 3..80 points 2000 / 4 = 500;
// every generator family at 3..4000 points 2000 / 10 = 200; the deterministic
// sweep: 11 families x 6 sizes x 2 seeds x 3 thread counts x 2 option sets
// x 2 algorithms;
// the parallel certifier: 2000 / 4 = 500 sets, each with 5 answers (right and
// edited) at 2 levels and 3 thread counts.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull2/throw_away.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/family_sweep.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/outcome.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};

using test::is_error;
using test::outcome;

// The cpu backend's two algorithms, each against the reference's run of the
// same algorithm (the same hull; on rejected input the same message, which
// names the algorithm).
enum class Algo { sort, insert };
constexpr Algo kAlgos[] = {Algo::sort, Algo::insert};

std::string cpu_text(const PointSet& ps, cpu::Hull2Options o, int threads, ref::Hull2Stats* st = nullptr,
                     Algo a = Algo::sort) {
  o.threads = threads;
  return outcome([&] { return a == Algo::sort ? cpu::hull2_graham_sort(ps, o, st) : cpu::hull2_graham_insert(ps, o, st); });
}

std::string ref_text(const PointSet& ps, Algo a = Algo::sort) {
  return outcome([&] { return a == Algo::sort ? ref::hull2_graham_sort(ps) : ref::hull2_graham_insert(ps); });
}

// Options that reach every path on small inputs (or the defaults).
rc::Gen<cpu::Hull2Options> any_options() {
  return rc::gen::exec([] {
    cpu::Hull2Options o;
    if (*rc::gen::element(0, 1, 2) != 0) {
      o.throw_away_from = 0;
      o.sample = *rc::gen::element<std::size_t>(0, 3, 4, 5, 8, 16, 64, 100000);
    }
    o.scan_chunk = *rc::gen::element<std::size_t>(1, 2, 3, 5, 8, 4096);
    return o;
  });
}

// cpu == reference at every thread count; counts consistent (every point is
// discarded by the throw-away or goes into the chains' polygon; every flip
// removes one polygon vertex). Returns the reference text.
std::string check_rc(const PointSet& ps, const cpu::Hull2Options& o) {
  const std::string expect = ref_text(ps);
  for (Algo a : kAlgos)
    for (int t : kThreads) {
      ref::Hull2Stats st;
      const std::string got = cpu_text(ps, o, t, &st, a);
      RC_ASSERT(got == ref_text(ps, a));
      if (!is_error(expect)) {
        RC_ASSERT(got == expect);
        RC_ASSERT(st.discarded_early + st.polygon_vertices == ps.size());
        RC_ASSERT(st.polygon_vertices - st.flips_2_1 == st.hull_vertices);
      }
    }
  // the throw-away alone keeps every vertex of the reference hull
  if (!is_error(expect)) {
    const auto kept = cpu::hull2::throw_away(ps, o.throw_away_from, o.sample).survivors;
    RC_ASSERT(std::is_sorted(kept.begin(), kept.end()));
    for (Index v : ref::hull2_graham_sort(ps)) RC_ASSERT(std::binary_search(kept.begin(), kept.end(), v));
  }
  return expect;
}

}  // namespace

TEST_CASE("hull2 cpu: degenerate and random small sets equal the reference at 1, 2, 8 threads (shrinking)",
          "[hull2_cpu]") {
  test::prop_scaled("degenerate sets of 3..80 points: cpu == reference byte for byte, certified", 4, [] {
    const PointSet ps = *test::degenerate_points(2, 3, 80, false);
    const cpu::Hull2Options o = *any_options();
    const std::string expect = check_rc(ps, o);
    if (!is_error(expect))
      RC_ASSERT(certify::hull2(ps, cpu::hull2_graham_sort(ps, o), certify::Level::canonical).ok);
  });
}

TEST_CASE("hull2 cpu: every generator family up to 4000 points equals the reference (shrinking)", "[hull2_cpu]") {
  test::prop_scaled("family sets of 3..4000 points (square, disk, frame, circle, grid2, circle-lattice, "
                    "collinear2, duplicates2, jitter2, huge2, tiny2): cpu == reference at 1, 2, 8 threads",
                    10, [] {
                      const PointSet ps = *test::thinned(test::family_points(2, 3, 4000, false));
                      check_rc(ps, *any_options());
                    });
}

TEST_CASE("hull2 cpu: deterministic sweep over the families, sizes, thread counts and options", "[hull2_cpu][long]") {
  std::size_t cases = 0;
  cpu::Hull2Options forced;  // throw-away on every input, a small sample, tiny chunks
  forced.throw_away_from = 0;
  forced.sample = 16;
  forced.scan_chunk = 3;
  const test::SweepCounts sweep =
      test::family_sweep(2, {3, 7, 30, 200, 2000, 20000}, 2, [](const PointSet& p) { return ref_text(p); }, [&](const PointSet& ps, const std::string& expect) {
        for (const cpu::Hull2Options& o : {cpu::Hull2Options{}, forced})
          for (Algo a : kAlgos)
            for (int t : kThreads) {
              INFO("threads " << t << ", sample " << o.sample << (a == Algo::insert ? ", insertion" : ", sorting"));
              REQUIRE(cpu_text(ps, o, t, nullptr, a) == (a == Algo::sort ? expect : ref_text(ps, a)));
              ++cases;
            }
      });
  const std::size_t rejected = sweep.rejected;
  std::cout << "hull2 cpu sweep: " << cases << " runs identical to the reference (" << rejected
            << " inputs rejected as collinear by both)\n";
  REQUIRE(cases >= 11 * 6 * 2 * 3 * 2 * 2);
}

TEST_CASE("hull2 cpu: large inputs of every family equal the reference, certified", "[hull2_cpu][long]") {
  for (const std::string& fam : test::families(2)) {
    gen::Options g;
    g.seed = 11;
    g.thickness = 0.01;
    // under TSan 40000 points: five pieces, the throw-away's parallel scan (151 s
    // of make tsan in CI at 200000)
    const PointSet ps = gen::generate(fam, test::large_n(200000, 40000), g);
    INFO(fam);
    const std::string expect = ref_text(ps);
    if (is_error(expect)) {
      REQUIRE(cpu_text(ps, {}, 2) == expect);
      continue;
    }
    for (int t : kThreads) REQUIRE(cpu_text(ps, {}, t) == expect);
    for (int t : kThreads) REQUIRE(cpu_text(ps, {}, t, nullptr, Algo::insert) == expect);
    REQUIRE(certify::hull2(ps, cpu::hull2_graham_sort(ps), certify::Level::canonical).ok);
  }
}

TEST_CASE("hull2 cpu: input that does not span the plane is rejected like the reference", "[hull2_cpu]") {
  PointSet ps;
  ps.dim = 2;
  // collinear, large enough for the throw-away (from 1024 points); every
  // orientation is degenerate (SoS) and Graham-insertion is quadratic here
  for (int i = 0; i < 1200; ++i) {
    ps.coords.push_back(0.5 * i);
    ps.coords.push_back(3.0 - 0.25 * i);
  }
  for (int t : kThreads) REQUIRE(cpu_text(ps, {}, t) == ref_text(ps));
  for (int t : kThreads) REQUIRE(cpu_text(ps, {}, t, nullptr, Algo::insert) == ref_text(ps, Algo::insert));
  REQUIRE(is_error(cpu_text(ps, {}, 2)));
  ps.coords.assign(2000, 1.25);  // 1000 copies of one point
  REQUIRE(cpu_text(ps, {}, 2) == ref_text(ps));
  REQUIRE(is_error(cpu_text(ps, {}, 2)));
  ps.coords.resize(4);  // two points
  REQUIRE(cpu_text(ps, {}, 1) == ref_text(ps));
  REQUIRE(is_error(cpu_text(ps, {}, 1)));
  cpu::Hull2Options bad;
  bad.threads = -1;
  ps.coords = {0, 0, 1, 0, 0, 1};
  REQUIRE_THROWS_AS(cpu::hull2_graham_sort(ps, bad), std::invalid_argument);
}

TEST_CASE("hull2 cpu: the parallel certifier gives the sequential certifier's verdict and message", "[hull2_cpu]") {
  test::prop_scaled("right and edited answers of family and degenerate sets: cpu::certify_hull2 == certify::hull2 "
                    "at both levels, 1, 2, 8 threads",
                    4, [] {
                      const PointSet ps = *rc::gen::oneOf(test::thinned(test::family_points(2, 3, 3000, false)),
                                                          test::degenerate_points(2, 3, 80, false));
                      if (!dimension_problem(ps).empty()) return;
                      const std::vector<Index> answer = ref::hull2_graham_sort(ps);
                      std::vector<std::vector<Index>> cycles = {answer};
                      const std::size_t m = answer.size(), k = *rc::gen::inRange<std::size_t>(0, m);
                      std::vector<Index> c = answer;  // a vertex removed
                      c.erase(c.begin() + static_cast<long>(k));
                      cycles.push_back(c);
                      cycles.emplace_back(answer.rbegin(), answer.rend());  // clockwise
                      c = answer;  // rotated
                      std::rotate(c.begin(), c.begin() + 1, c.end());
                      cycles.push_back(c);
                      c = answer;  // a point inserted (the first index that is no vertex, if any)
                      for (Index p = 0; p < ps.size(); ++p)
                        if (std::find(answer.begin(), answer.end(), p) == answer.end()) {
                          c.insert(c.begin() + static_cast<long>(k) + 1, p);
                          break;
                        }
                      cycles.push_back(c);
                      for (const auto& cycle : cycles)
                        for (certify::Level level : {certify::Level::canonical, certify::Level::exact}) {
                          const std::string expect = certify::hull2(ps, cycle, level).message();
                          for (int t : kThreads) RC_ASSERT(cpu::certify_hull2(ps, cycle, level, t).message() == expect);
                        }
                      RC_ASSERT(cpu::certify_hull2(ps, answer, certify::Level::canonical).ok);
                    });
}

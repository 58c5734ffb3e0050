// rt3_cpu_test.cpp — the multithreaded 3D regular / Delaunay triangulation of
// kernels_cpu/rt3 against the exact sequential reference (RT+1,
// ref::rtd_incremental with d = 3): byte-identical canonical text for every
// input, at 1, 2 and 8 threads and with two BRIO round sizes, degenerate
// inputs included, the same redundant points, consistent counts, and the same
// rejection of input that is not finite or does not span R^3.
//
// Oracles: ref::rtd_incremental (itself tested against brute force, CGAL and
// the certifier in rtd_reference_test.cpp) and certify::rtd at
// Level::canonical (the witness-free certifier). CGAL's triangulations on
// input in general position: rt3_cgal_oracle_test.cpp.
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate sets of 4..60 points 2000 / 4 = 500 each
// weighted and unweighted; generator families at 4..1000 points 2000 / 40 =
// 50 each; the deterministic sweep ([long]): every 3D family x 6 sizes (4 to 1200) x 2
// weightings x 3 thread counts x 2 BRIO settings (and the insertion mode
// those imply: parallel rounds at 2 and 8 threads).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/large_n.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/rt3_outcome.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};

using Insertion = cpu::Rt3Options::Insertion;
// How the kernel inserts: one by one at two BRIO settings (one round; rounds
// down to a single point), and in parallel rounds from the fifth point on in
// pieces of at least 4 points (small inputs reach the claims and deferrals
// too) or of 16 after the first 64 points.
// The last parallel mode makes every 7th claim fail (Rt3Options::
// fail_claims_every), as if another task held the tetrahedron.
struct Mode {
  Insertion how;
  std::size_t brio, parallel_from, min_piece, fail_every = 0;
};
constexpr Mode kModes[] = {{Insertion::sequential, 1, 4096, 256},
                           {Insertion::sequential, 256, 4096, 256},
                           {Insertion::parallel, 1, 4, 4},
                           {Insertion::parallel, 256, 64, 16, 7}};
const char* name(Insertion how) { return how == Insertion::sequential ? "sequential" : "parallel"; }
cpu::Rt3Options options(int threads, const Mode& m) {
  cpu::Rt3Options o;
  o.threads = threads;
  o.brio_min = m.brio;
  o.insertion = m.how;
  o.parallel_from = m.parallel_from;
  o.min_piece = m.min_piece;
  o.fail_claims_every = m.fail_every;
  return o;
}

using test::as_simplices;
using test::with_weights;
std::string ref_text(const PointSet& ps) { return test::rt3_ref_text(ps); }

std::string cpu_text(const PointSet& ps, int threads, const Mode& m = kModes[1], cpu::Rt3Stats* st = nullptr) {
  return test::rt3_outcome([&] { return cpu::rt3(ps, options(threads, m), st); });
}

using test::is_error;

// cpu == reference at every thread count in every mode; the counts are
// consistent: every point is one of the first four, inserted or discarded
// when located, and the vertices are the inserted points less the removed.
template <class Assert>
std::string check(const PointSet& ps, const Assert& require) {
  const std::string expect = ref_text(ps);
  for (int t : kThreads)
    for (const Mode& m : kModes) {
      cpu::Rt3Stats st;
      require(cpu_text(ps, t, m, &st) == expect, t, m);
      if (!is_error(expect)) {
        require(st.inserted + st.discarded == ps.size(), t, m);
        require(st.discarded + st.removed == test::rt3_redundant_count(expect), t, m);
      }
    }
  return expect;
}

std::string check_rc(const PointSet& ps) {
  return check(ps, [](bool ok, int, const Mode&) { RC_ASSERT(ok); });
}

std::string check_req(const PointSet& ps) {
  return check(ps, [](bool ok, int t, const Mode& m) {
    INFO("threads " << t << ", " << name(m.how) << ", brio_min " << m.brio << ", parallel_from " << m.parallel_from);
    REQUIRE(ok);
  });
}

}  // namespace

TEST_CASE("rt3 cpu: degenerate and random small sets equal the reference (shrinking)", "[rt3_cpu]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("degenerate 3D sets of 4..60 points, ") + (weighted ? "weighted" : "unweighted") +
                          ": cpu == reference byte for byte at 1, 2, 8 threads, certified",
                      4, [weighted] {
                        const PointSet ps = *test::degenerate_points_d(3, 4, 60, weighted);
                        const std::string expect = check_rc(ps);
                        if (!is_error(expect)) {
                          const cpu::Rt3Result r = cpu::rt3(ps);
                          RC_ASSERT(certify::rtd(ps, as_simplices(r.tets), certify::Level::canonical).ok);
                        }
                      });
}

TEST_CASE("rt3 cpu: every 3D generator family up to 1000 points equals the reference (shrinking)", "[rt3_cpu]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("3D family sets of 4..1000 points (cube, ball, sphere, grid3, sphere-lattice, "
                                  "duplicates, ...), ") +
                          (weighted ? "weights from none to many redundant" : "unweighted") +
                          ": cpu == reference at 1, 2, 8 threads",
                      64, [weighted] {
                        const PointSet ps = *test::thinned(test::family_points(3, 4, 1000, weighted));
                        check_rc(ps);
                      });
}

TEST_CASE("rt3 cpu: deterministic sweep over the 3D families, sizes, weights and thread counts", "[rt3_cpu][long]") {
  std::size_t cases = 0, rejected = 0, families = 0;
  for (const std::string& fam : test::families(3)) {
    ++families;
    for (std::size_t n : {4, 5, 9, 40, 300, 800})
      for (std::uint64_t seed = 1; seed <= 1; ++seed)
        for (bool weighted : {false, true}) {
          const PointSet ps = test::family_input(fam, n, seed, weighted, 1e-3);
          INFO(fam << " n=" << n << " seed=" << seed << (weighted ? " weighted" : ""));
          const std::string expect = check_req(ps);
          if (is_error(expect)) {
            ++rejected;
            REQUIRE(!dimension_problem(ps).empty());
          }
          cases += 12;
        }
  }
  std::cout << "rt3 cpu sweep: " << cases << " runs over " << families << " families identical to the reference ("
            << rejected << " inputs rejected by both)\n";
  REQUIRE(families >= 8);
}

// The degenerate families the issue names, each with its own structure.
TEST_CASE("rt3 cpu: lattices, cospherical sets, duplicates and redundant-heavy inputs equal the reference",
          "[rt3_cpu]") {
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
  SECTION("all points redundant but four") {
    // a huge-weight tetrahedron swallows everything inside it
    PointSet ps;
    ps.dim = 3;
    std::vector<double> c = {-10, -10, -10, 10, -10, -10, 0, 10, -10, 0, 0, 10};
    std::vector<double> w = {1000, 1000, 1000, 1000};
    for (int i = 0; i < 200; ++i) {
      c.insert(c.end(), {(i % 7) * 0.3 - 1, (i % 5) * 0.3 - 1, (i % 3) * 0.3 - 1});
      w.push_back(0);
    }
    ps.coords = Values(std::move(c));
    ps = with_weights(ps, w);
    const std::string expect = check_req(ps);
    REQUIRE(std::count(expect.begin(), expect.end(), '\n') == 1);  // one tetrahedron
  }
  SECTION("the scanned building (planes3): a vertex is the smallest index of a long fan of flat tetrahedra") {
    // the output stage sorts such a run (more than 32 tetrahedra with one
    // smallest index: 262 at 2000 points) by std::sort, the short ones by
    // insertion; the witness certifier looks tetrahedra up in it by binary
    // search
    const PointSet ps = gen::generate("planes3", 2000, o);
    check_req(ps);
    cpu::Rt3Witness w;
    const cpu::Rt3Result r = cpu::rt3(ps, {}, nullptr, &w);
    std::size_t longest = 0;
    for (std::size_t i = 0, j = 0; i < r.tets.size(); i = j) {
      for (j = i; j < r.tets.size() && r.tets[j][0] == r.tets[i][0]; ++j) {
      }
      longest = std::max(longest, j - i);
    }
    INFO("longest run of one smallest index: " << longest);
    REQUIRE(longest > 32);
    REQUIRE(cpu::certify_rt3(ps, w, r.tets).ok);
  }
  SECTION("exact copies wait for the one that can be a vertex") {
    // duplicates3: uniform points, each 2 to 5 times, shuffled. The copy of
    // largest index is the one that can be a vertex; the others wait until
    // it is in (rt3.cpp, Builder::run) and are found redundant when located:
    // few vertices are removed again (with every copy inserted as it came,
    // 57 % of the points at 10^6)
    const PointSet ps = gen::generate("duplicates3", 3000, o);
    check_req(ps);
    for (const Mode& m : kModes) {
      cpu::Rt3Stats st;
      cpu::rt3(ps, options(2, m), &st);
      INFO("removed " << st.removed << ", discarded " << st.discarded);
      REQUIRE(st.removed <= ps.size() / 100);
    }
  }
}

TEST_CASE("rt3 cpu: 20000-point inputs in three weight ranges equal the reference, certified", "[rt3_cpu][long]") {
  struct Case {
    const char* fam;
    double whi;
  };
  for (const Case c : {Case{"cube", 0}, Case{"cube", 1e-6}, Case{"cube", 1e-4}, Case{"cube", 1e-2},
                       Case{"ball", 0}, Case{"sphere", 0}, Case{"grid3", 0}}) {
    gen::Options o;
    o.seed = 5;
    o.weighted = c.whi > 0;
    o.whi = c.whi;
    const PointSet ps = gen::generate(c.fam, test::large_n(20000, 6000), o);
    INFO(c.fam << " weights [0, " << c.whi << "]");
    const ref::Rtd expect = ref::rtd_incremental(ps);
    for (int t : kThreads) {
      cpu::Rt3Options opt;
      opt.threads = t;
      cpu::Rt3Stats st;
      const cpu::Rt3Result r = cpu::rt3(ps, opt, &st);
      INFO(t << " threads");
      REQUIRE(as_simplices(r.tets) == expect.simplices);
      REQUIRE(r.redundant == expect.redundant);
      if (t == 1)
        std::cout << "rt3 cpu " << c.fam << " w<=" << c.whi << ": " << r.tets.size() << " tetrahedra, "
                  << ps.size() - r.redundant.size() << " of " << ps.size() << " points vertices; placed "
                  << st.placed << ", discarded " << st.discarded << ", removed " << st.removed << ", walk steps "
                  << st.walk_steps << "\n";
    }
    REQUIRE(certify::rtd(ps, expect.simplices, certify::Level::canonical).ok);
  }
}

// The parallel rounds where pieces meet the most: small pieces from the
// fifth point on, at 2 and 8 threads, on a lattice with equal and with
// lattice weights (every cell cospherical: visibility decided by SoS alone),
// on a cospherical set (every point's cavity reaches far) and on a ball: the
// tetrahedra equal the reference's, the counts are consistent and the rounds
// ran. Claims that other tasks hold depend on timing (printed); the test
// hook fail_claims_every makes every k-th claim fail, so the give-up paths
// (walk start, walk, cavity, slots) and the deferrals run in every run.
TEST_CASE("rt3 cpu: parallel rounds resolve conflicts on lattices and cospherical sets", "[rt3_cpu]") {
  std::size_t deferred = 0, forced = 0, rounds = 0;
  gen::Options o;
  o.seed = 3;
  const PointSet grid = gen::generate("grid3", 1000, o);
  std::vector<double> lw(grid.size());
  for (std::size_t i = 0; i < lw.size(); ++i) lw[i] = static_cast<double>(i % 3) / 4;
  for (const PointSet& ps : {grid, with_weights(grid, std::vector<double>(grid.size(), 0.5)), with_weights(grid, lw),
                             gen::generate("sphere-lattice", 600, o), gen::generate("ball", 5000, o)}) {
    const std::string expect = ref_text(ps);
    REQUIRE(!is_error(expect));
    for (int t : {2, 8})
      for (const Mode& m : {Mode{Insertion::parallel, 1, 4, 4}, Mode{Insertion::parallel, 256, 16, 8},
                            Mode{Insertion::parallel, 1, 4, 4, 3}, Mode{Insertion::parallel, 256, 16, 8, 11}}) {
        INFO(ps.size() << " points, " << t << " threads, parallel_from " << m.parallel_from << ", pieces of "
                       << m.min_piece << ", every " << m.fail_every << "th claim fails");
        cpu::Rt3Stats st;
        REQUIRE(cpu_text(ps, t, m, &st) == expect);
        REQUIRE(st.inserted + st.discarded == ps.size());
        REQUIRE(st.parallel_rounds > 0);
        (m.fail_every ? forced : deferred) += st.deferred;
        rounds += st.parallel_rounds;
      }
  }
  std::cout << "rt3 cpu conflicts: " << rounds << " parallel rounds; insertions deferred: " << deferred
            << " on claims held by other tasks, " << forced << " with failing claims forced\n";
  REQUIRE(forced > 0);
}

TEST_CASE("rt3 cpu: input that is not finite or does not span R^3 is rejected like the reference", "[rt3_cpu]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 3, 2, 0};  // coplanar
  REQUIRE(is_error(cpu_text(ps, 2)));
  REQUIRE(cpu_text(ps, 2) == ref_text(ps));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // three points
  REQUIRE(is_error(cpu_text(ps, 1)));
  REQUIRE(cpu_text(ps, 1) == ref_text(ps));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};  // a spanning set ...
  REQUIRE(!is_error(cpu_text(ps, 1)));
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN, 1, 1, 0};  // ... with a NaN
  REQUIRE(cpu_text(ps, 1) == "error: a coordinate is not finite");
  ps.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
  ps = with_weights(ps, {0, 0, INFINITY, 0, 0});
  REQUIRE(cpu_text(ps, 1) == "error: a weight is not finite");
  REQUIRE(cpu_text(ps, 1) == ref_text(ps));
  PointSet flat;
  flat.dim = 2;
  flat.coords = {0, 0, 1, 0, 0, 1};
  REQUIRE_THROWS_AS(cpu::rt3(flat), std::invalid_argument);
}

TEST_CASE("rt3 cpu: extreme magnitudes (1e±300, subnormals) equal the reference", "[rt3_cpu]") {
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

// cpu::rt3_neighbors (scipy's `neighbors`, read off the witness) against the
// neighbours found by matching facets: a map from each facet's sorted
// vertices to the (tetrahedron, opposite position) pairs that hold it —
// independent of the kernel's links. Every 3D family, weighted or not, with
// its flat tetrahedra, at 1 and 2 threads; a corrupted witness link must be
// refused or change the answer the matching gives.
TEST_CASE("rt3 cpu: neighbours read off the witness equal those found by matching facets", "[rt3_cpu]") {
  std::size_t inputs = 0, tets = 0, hull_sides = 0;
  for (const std::string& fam : test::families(3))
    for (std::size_t n : {5, 60, 700})
      for (bool weighted : {false, true}) {
        const PointSet ps = test::family_input(fam, n, 3, weighted, 1e-3);
        if (!dimension_problem(ps).empty()) continue;
        INFO(fam << " n=" << n << (weighted ? " weighted" : ""));
        std::map<std::array<Index, 3>, std::vector<std::pair<std::size_t, int>>> facets;
        for (int threads : {1, 2}) {
          cpu::Rt3Options o;
          o.threads = threads;
          cpu::Rt3Witness w;
          const cpu::Rt3Result r = cpu::rt3(ps, o, nullptr, &w);
          const std::vector<std::int64_t> nb = cpu::rt3_neighbors(w, r.tets, threads);
          REQUIRE(nb.size() == 4 * r.tets.size());
          if (threads == 1) {
            facets.clear();
            for (std::size_t k = 0; k < r.tets.size(); ++k)
              for (int j = 0; j < 4; ++j) {
                std::array<Index, 3> f;
                int c = 0;
                for (int q = 0; q < 4; ++q)
                  if (q != j) f[static_cast<std::size_t>(c++)] = r.tets[k][static_cast<std::size_t>(q)];
                std::sort(f.begin(), f.end());
                facets[f].push_back({k, j});
              }
          }
          for (const auto& [f, holders] : facets) {
            REQUIRE(holders.size() <= 2);
            const auto [k, j] = holders[0];
            if (holders.size() == 1) {
              CHECK(nb[4 * k + static_cast<std::size_t>(j)] == -1);
              hull_sides += threads == 1;
            } else {
              const auto [k2, j2] = holders[1];
              CHECK(nb[4 * k + static_cast<std::size_t>(j)] == static_cast<std::int64_t>(k2));
              CHECK(nb[4 * k2 + static_cast<std::size_t>(j2)] == static_cast<std::int64_t>(k));
            }
          }
          if (threads == 1) {
            ++inputs;
            tets += r.tets.size();
            // a dropped output tetrahedron: the pair no longer agrees
            std::vector<cpu::Tet> fewer(r.tets.begin() + 1, r.tets.end());
            CHECK_THROWS_AS(cpu::rt3_neighbors(w, fewer), std::logic_error);
            // a real slot witnessed twice (copied over another real slot)
            cpu::Rt3Witness twice = w;
            std::size_t a = 0, b = 0;
            const std::size_t slots = w.tv.size() / 4;
            auto real = [&](std::size_t t) {
              for (int i = 0; i < 4; ++i)
                if (w.tv[4 * t + static_cast<std::size_t>(i)] >= w.pts.size()) return false;
              return true;
            };
            while (a < slots && !real(a)) ++a;
            b = a + 1;
            while (b < slots && !real(b)) ++b;
            if (b < slots) {
              for (int i = 0; i < 4; ++i) twice.tv[4 * b + static_cast<std::size_t>(i)] = w.tv[4 * a + static_cast<std::size_t>(i)];
              CHECK_THROWS_AS(cpu::rt3_neighbors(twice, r.tets), std::logic_error);
            }
          }
        }
      }
  std::cout << "rt3 neighbours from the witness: " << inputs << " inputs, " << tets << " tetrahedra (" << hull_sides
            << " hull sides) equal to facet matching at 1 and 2 threads\n";
  REQUIRE(inputs >= 20);
}

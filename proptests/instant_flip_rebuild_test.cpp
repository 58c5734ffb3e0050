// instant_flip_rebuild_test.cpp — the monotonic instant flip (thesis §9.2.1,
// Algorithm 14, with insertion events) from RT(S ⊕ W) ends at the regular
// triangulation that a fresh construction (rtd_incremental, RT+1 [ES92])
// computes for U, in d = 2..5, for random independent W and U (points enter
// and leave), including U that make many vertices redundant; the result is
// certified (certify_rtd) and the counters are consistent.
#include <catch2/catch.hpp>

#include <random>

#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "support/rtd_oracles.hpp"
#include "support/instant_flip_oracles.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

namespace {


struct Case {
  int d;
  std::size_t n;
  double w_hi, u_hi;  // weight ranges [0, hi]
};

void run_case(const Case& c, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const PointSet pts = random_points(c.d, c.n, rng);
  const std::vector<double> w = random_weights(c.n, c.w_hi, rng);
  const std::vector<double> u = random_weights(c.n, c.u_hi, rng);
  const PointSet pw = with_weights(pts, w), pu = with_weights(pts, u);
  INFO("d " << c.d << " n " << c.n << " seed " << seed << " W in [0," << c.w_hi << "] U in [0,"
            << c.u_hi << "]");

  ref::rtd::TriangulationD T = ref::build_rtd(pw);
  std::size_t flips_seen = 0, inserted_seen = 0;
  ref::InstantFlipOptions opt;
  opt.on_flip = [&](const ref::rtd::TriangulationD&, const ref::InstantFlipEvent& e) {
    ++flips_seen;
    if (e.inserted != ref::rtd::kNoVertex) ++inserted_seen;
  };
  const ref::InstantFlipStats st = ref::instant_flip(T, w, u, opt);
  CHECK(st.total_flips() == flips_seen);
  CHECK(st.inserted_vertices == inserted_seen);
  CHECK(st.inserted_vertices == st.flips[1]);
  CHECK(st.pops == st.total_flips() + st.stale + st.deferred);
  CHECK(st.pushes == st.pops);  // the queue runs empty
  CHECK(st.removed_vertices == st.flips[c.d + 1]);
  const std::vector<std::vector<Index>> got = ref::rtd::real_simplices(T);

  // RT(S ⊕ U) itself, built afresh: points redundant under W come back by
  // insertion events (the extended Algorithm 14), none is left out
  const ref::Rtd full = ref::rtd_incremental(pu);
  CHECK(got == full.simplices);
  CHECK(ref::reappearing_points(T, u).empty());
  const certify::Report r = ref::certify_rtd(pu, got);
  INFO(r.message());
  CHECK(r.ok);
}

}  // namespace

TEST_CASE("instant flip equals a fresh RT(S+U): random W and U, d = 2..5", "[instant_flip]") {
  const Case cases[] = {{2, 120, 0.01, 0.01}, {3, 60, 0.01, 0.01}, {4, 30, 0.02, 0.02},
                        {5, 16, 0.05, 0.05}};
  for (const Case& c : cases)
    for (std::uint64_t seed = 1; seed <= 6; ++seed) run_case(c, seed * 1000 + static_cast<std::uint64_t>(c.d));
}

TEST_CASE("instant flip: many vertices become redundant under U", "[instant_flip]") {
  // W = 0 (Delaunay: every point a vertex); U large: many (d+1)-1 flips.
  const Case cases[] = {{2, 150, 0.0, 0.05}, {3, 70, 0.0, 0.2}, {4, 30, 0.0, 0.4},
                        {5, 16, 0.0, 0.6}};
  for (const Case& c : cases)
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      run_case(c, seed * 7919 + static_cast<std::uint64_t>(c.d));
    }
  // and the counts: with d = 2, n = 150, U in [0, 0.05], vertices do disappear
  std::mt19937_64 rng(42);
  const PointSet pts = random_points(2, 150, rng);
  const std::vector<double> w(150, 0.0), u = random_weights(150, 0.05, rng);
  const PointSet pw = with_weights(pts, w);  // T keeps a pointer to it
  ref::rtd::TriangulationD T = ref::build_rtd(pw);
  const ref::InstantFlipStats st = ref::instant_flip(T, w, u);
  const ref::Rtd full = ref::rtd_incremental(with_weights(pts, u));
  CHECK(st.removed_vertices == full.redundant.size());
  CHECK(full.redundant.size() > 10);
}

TEST_CASE("instant flip: W = U changes nothing, and the reversed run returns", "[instant_flip]") {
  for (int d = 2; d <= 5; ++d) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(100 + d));
    const std::size_t n = d == 2 ? 80 : (d == 3 ? 40 : 20);
    const PointSet pts = random_points(d, n, rng);
    const std::vector<double> w = random_weights(n, 0.01, rng), u = random_weights(n, 0.01, rng);
    const PointSet pw = with_weights(pts, w);  // T keeps a pointer to it
    ref::rtd::TriangulationD T = ref::build_rtd(pw);
    const auto start = ref::rtd::real_simplices(T);
    const ref::InstantFlipStats same = ref::instant_flip(T, w, w);
    CHECK(same.total_flips() == 0);
    CHECK(same.pushes == 0);
    CHECK(ref::rtd::real_simplices(T) == start);
    // W -> U -> W: the vertices removed on the way come back by insertion
    // events, so the round trip restores RT(S ⊕ W).
    ref::instant_flip(T, w, u);
    ref::instant_flip(T, u, w);
    CHECK(ref::rtd::real_simplices(T) == start);
  }
}

TEST_CASE("instant flip rejects a start that is not regular for W", "[instant_flip]") {
  std::mt19937_64 rng(5);
  const PointSet pts = random_points(3, 30, rng);
  const std::vector<double> w = random_weights(30, 0.01, rng), u = random_weights(30, 0.01, rng);
  const PointSet pu = with_weights(pts, u);
  ref::rtd::TriangulationD T = ref::build_rtd(pu);  // regular for U, not for W
  // the oracle: is some interior ridge reflex for W?
  const bool convex_for_w =
      all_convex_q(pts, heights_q(pts, to_q(w)), to_set(ref::rtd::real_simplices(T)));
  REQUIRE_FALSE(convex_for_w);
  CHECK_THROWS_AS(ref::instant_flip(T, w, u), std::invalid_argument);
  CHECK_THROWS_AS(ref::instant_flip(T, std::vector<double>(3, 0.0), u), std::invalid_argument);
}

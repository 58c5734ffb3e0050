// rt2_reference_checked_test.cpp — the 2D regular-triangulation reference in
// its checked build (flipflop_reference_checked, reference/checked.hpp): every
// operation of ffRT's constructing stage, of flip-flop and of Lawson asserts
// the invariants its proof rests on — a valid (extended) triangulation after
// every flip, the V-criterion lowers the lifted surface, a removed vertex
// never reappears, the D-criterion lowers the degree of the smallest-index
// redundant vertex, a labelled vertex is redundant (Lemma 5.1). This suite
// runs the algorithms on small inputs so that every check executes, and shows
// that the checks fire on states that break them.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "proptests/support/planar_inputs.hpp"
#include "gen/generate.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/ffrt.hpp"
#include "reference/rt2/flip_flop_2d.hpp"
#include "reference/rt2/lawson_flip.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/triangulation2.hpp"

using namespace flipflop;
using ref::FlipFlopVariant;
using ref::Rt2Stats;
namespace tri = flipflop::ref::tri;
namespace ff = flipflop::ref::ff;

static_assert(FF_CHECKED, "this test must link the checked build of the reference");


namespace {

using test::spans;

rc::Gen<PointSet> gen_planar(int nmin, int nmax, bool weighted) {
  return test::gen_small_points(2, nmin, nmax, weighted, 5);
}

using test::random_insertion;

// Every algorithm on ps, with all checks on; results equal brute force (or,
// beyond 35 points, the certified answer of ffRT).
void run_all(const PointSet& ps, std::uint64_t seed) {
  const auto want = ps.size() <= 35 ? brute::rt2(ps) : ref::rt2_ffrt(ps);
  if (ps.size() > 35) REQUIRE(certify::rt2(ps, want, certify::Level::canonical).ok);
  REQUIRE(ref::rt2_ffrt(ps) == want);
  REQUIRE(ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first) == want);
  const auto all = random_insertion(ps, seed);
  REQUIRE(ref::flip_flop(ps, all) == want);
  REQUIRE(ref::flip_flop(ps, all, FlipFlopVariant::v_first) == want);
  bool weights = false;
  for (std::size_t i = 0; i < ps.size(); ++i) weights = weights || ps.weight(i) != 0;
  if (!weights) REQUIRE(ref::dt2_lawson(ps) == want);
  std::vector<Triangle> got;
  bool stuck = false;
  try {
    got = ref::lawson(ps, all);
  } catch (const std::runtime_error&) {
    stuck = true;  // a redundant vertex: Lawson cannot remove it
  }
  if (!stuck) REQUIRE(got == want);
}

// A small weighted input with redundant points and its constructed state.
PointSet sample() {
  gen::Options o;
  o.seed = 3;
  o.weighted = true;
  o.whi = 0.05;
  return gen::generate("square", 30, o);
}

tri::Triangulation2 constructed(const PointSet& ps, bool discard) {
  std::vector<Index> all(ps.size());
  std::iota(all.begin(), all.end(), Index{0});
  return ref::ffrt::construct(ps, all, discard, nullptr);
}

// Move the kernel point far outside: the virtual triangles are no longer
// positive, the polygon no longer star-shaped w.r.t. it.
void corrupt_kernel(tri::Triangulation2& T) {
  static const double far[2] = {1e6, -1e6};
  const double* pts[4] = {far, far, far, far};
  T.kernel = pred::RationalPoint::centroid(pts, 4, 2);
}

}  // namespace

TEST_CASE("checked: every algorithm on small inputs with all invariant checks on", "[rt2][checked]") {
  test::prop_scaled("weighted sets of 3..60 points", 14, [] {
    const PointSet ps = *gen_planar(3, 60, true);
    RC_PRE(spans(ps));
    run_all(ps, ps.size());
  });
  test::prop_scaled("unweighted sets of 3..60 points", 14, [] {
    const PointSet ps = *gen_planar(3, 60, false);
    RC_PRE(spans(ps));
    run_all(ps, ps.size());
  });
  for (const std::string& f : {"grid2", "circle-lattice", "duplicates2", "jitter2", "disk"})
    for (std::size_t n : {5, 12, 30})
      for (bool weighted : {false, true}) {
        gen::Options o;
        o.seed = n;
        o.weighted = weighted;
        o.whi = f == "circle-lattice" ? 1e20 : (f == "duplicates2" || f == "disk") ? 0.02 : 3.0;
        const PointSet ps = gen::generate(f, n, o);
        if (!spans(ps)) continue;
        INFO(f << " n=" << n << " weighted=" << weighted);
        run_all(ps, n);
      }
}

TEST_CASE("checked: the invariant checks fire on broken states", "[rt2][checked]") {
  const PointSet ps = sample();
  SECTION("flip-flop checks validity before it starts") {
    ff::State s = ff::make_state(constructed(ps, true));
    corrupt_kernel(s.T);
    REQUIRE_THROWS_AS(ff::run(s, FlipFlopVariant::combined, nullptr), InvariantViolation);
  }
  SECTION("Lawson checks validity before it starts") {
    tri::Triangulation2 T = constructed(ps, false);
    corrupt_kernel(T);
    REQUIRE_THROWS_AS(ref::lawson_flip::run(T, nullptr), InvariantViolation);
  }
  SECTION("the constructing stage checks validity (its input, and after every 1-3 flip)") {
    tri::Triangulation2 T = tri::make_initial(ps, 0, 1, 2);
    if (pred::orient2d_exact(ps.point(0), ps.point(1), ps.point(2)) < 0) T = tri::make_initial(ps, 0, 2, 1);
    corrupt_kernel(T);
    std::vector<Index> rest;
    for (Index i = 3; i < ps.size(); ++i) rest.push_back(i);
    REQUIRE_THROWS_AS(ref::ffrt::insert_points(T, rest, true, nullptr), InvariantViolation);
  }
  // decisions that Algorithm 5 would never take, applied by hand
  ff::State s = ff::make_state(constructed(ps, false));
  tri::Edge regular_flippable, blocked_regular;
  for (const auto& [u, w] : tri::edges(s.T)) {
    const tri::Edge e = tri::find_edge(s.T, u, w);
    const tri::Quad q = tri::quad(s.T, e);
    const bool real = q.a < ps.size() && q.b < ps.size() && q.c < ps.size() && q.d < ps.size();
    const auto shape = tri::classify(s.T, e).shape;
    if (real && shape == tri::Shape::two_two && tri::locally_regular(s.T, e)) regular_flippable = e;
    if (real && shape == tri::Shape::two_two_blocked && tri::locally_regular(s.T, e)) blocked_regular = e;
  }
  SECTION("a V-flip of a locally regular edge does not lower the lifted surface") {
    REQUIRE(regular_flippable.valid());
    REQUIRE_THROWS_AS(ff::apply(s, regular_flippable, {ff::Action::flip22_v, 0}, nullptr, nullptr),
                      InvariantViolation);
  }
  SECTION("a D-flip needs a labelled vertex whose degree it lowers") {
    REQUIRE(regular_flippable.valid());
    REQUIRE_THROWS_AS(ff::apply(s, regular_flippable, {ff::Action::flip22_d, 0}, nullptr, nullptr),
                      InvariantViolation);
  }
  SECTION("Lemma 5.1: only a vertex above the lifted triangle of the other three is labelled") {
    REQUIRE(blocked_regular.valid());
    const Index inner = tri::classify(s.T, blocked_regular).inner;
    REQUIRE_THROWS_AS(ff::apply(s, blocked_regular, {ff::Action::label, inner}, nullptr, nullptr),
                      InvariantViolation);
  }
  SECTION("input validation is not a checked-build matter: invalid triangulations are rejected everywhere") {
    REQUIRE_THROWS_AS(ref::flip_flop(ps, {{0, 1, 2}, {0, 1, 2}}), std::invalid_argument);
  }
}

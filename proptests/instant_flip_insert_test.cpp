// instant_flip_insert_test.cpp — the monotonic instant flip with insertion
// events (instant_flip.hpp, Algorithm 14 extended; issue 16) and the in-place
// update of dynamic_rt.hpp, against independent oracles: a fresh RT+1
// construction of S ⊕ U (rtd_incremental), the exact certifier (certify_rtd)
// and, for the lemmas, the run's own flip sequence.
//   * random independent W and U, d = 2..5 (RapidCheck, shrinking on the
//     seed): redundant points enter, vertices leave;
//   * degenerate weights: equal weights on integer lattices (many events at
//     one unperturbed time, flat (d+2)-sets resolved by the perturbation);
//   * small inputs with simultaneous events: every tie order and several
//     perturbation orders reach the same triangulation.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/rtd_inputs.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/dynamic_rt.hpp"
#include "reference/rtd/failure_time.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/perturbation_order.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "support/instant_flip_examples.hpp"
#include "support/instant_flip_oracles.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

namespace {

std::size_t points_for(int d) { return d == 2 ? 45 : (d == 3 ? 25 : (d == 4 ? 15 : 11)); }

// Weights in [0, hi] with hi drawn from a few scales (0: Delaunay; the
// largest hides a good share of the points).
double weight_scale(std::uint64_t k) {
  static const double scales[] = {0.0, 1e-3, 0.02, 0.1};
  return scales[k % 4];
}

struct Checked {
  std::string problem;  // empty when every oracle agrees
  std::uint64_t inserted = 0;
};

// The instant flip from build_rtd(S ⊕ W) to U against every oracle.
Checked check_instant_flip(const PointSet& pts, const std::vector<double>& w, const std::vector<double>& u) {
  const PointSet pw = with_weights(pts, w), pu = with_weights(pts, u);
  ref::rtd::TriangulationD T = ref::build_rtd(pw);
  const std::size_t start_vertices = ref::rtd::vertices(T).size();
  std::vector<char> was_removed(pts.size(), 0);
  bool back = false;
  ref::InstantFlipOptions opt;
  opt.on_flip = [&](const ref::rtd::TriangulationD&, const ref::InstantFlipEvent& e) {
    if (e.removed != ref::rtd::kNoVertex) was_removed[e.removed] = 1;
    if (e.inserted != ref::rtd::kNoVertex && was_removed[e.inserted]) back = true;
  };
  const ref::InstantFlipStats st = ref::instant_flip(T, w, u, opt);
  Checked c;
  c.inserted = st.inserted_vertices;
  const ref::Rtd fresh = ref::rtd_incremental(pu);
  const auto got = ref::rtd::real_simplices(T);
  if (got != fresh.simplices) c.problem = "not the fresh RT(S+U)";
  else if (!ref::certify_rtd(pu, got).ok) c.problem = "not certified";
  else if (!ref::reappearing_points(T, u).empty()) c.problem = "a non-vertex is not redundant under U";
  // counters: every pop a flip, stale or deferred; the queue runs empty;
  // vertices enter by 1-(d+1) and leave by (d+1)-1 flips only
  else if (st.pops != st.total_flips() + st.stale + st.deferred) c.problem = "pops do not add up";
  else if (st.pushes != st.pops) c.problem = "the queue is not empty";
  else if (st.inserted_vertices != st.flips[1] || st.removed_vertices != st.flips[pts.dim + 1])
    c.problem = "insertions/removals are not the 1-(d+1)/(d+1)-1 flips";
  else if (ref::rtd::vertices(T).size() + st.removed_vertices != start_vertices + st.inserted_vertices)
    c.problem = "vertex count does not add up";
  // a removed vertex never comes back (its vertex times form an interval)
  else if (back) c.problem = "a removed vertex came back";
  return c;
}

}  // namespace

TEST_CASE("instant flip with insertions equals a fresh RT(S+U): independent W, U, d = 2..5",
          "[instant_flip][insert]") {
  rc::prop("random points, W and U drawn independently", [](std::uint64_t seed) {
    const int d = 2 + static_cast<int>(seed % 4);
    std::mt19937_64 rng(seed);
    const std::size_t n = static_cast<std::size_t>(d + 2) + (seed >> 3) % points_for(d);
    const PointSet pts = random_points(d, n, rng);
    const std::vector<double> w = random_weights(n, weight_scale(seed >> 10), rng);
    const std::vector<double> u = random_weights(n, weight_scale(seed >> 12), rng);
    const Checked c = check_instant_flip(pts, w, u);
    RC_ASSERT(c.problem == std::string());
    // the same through the in-place API: no fallback in general position
    ref::DynamicRegularTriangulation rt(pts, w);
    const ref::WeightUpdateStats st = rt.set_weights(u);
    RC_ASSERT(!st.rebuilt);
    RC_ASSERT(rt.simplices() == ref::rtd_incremental(with_weights(pts, u)).simplices);
  });
}

TEST_CASE("instant flip: points do enter and leave (fixed cases)", "[instant_flip][insert]") {
  // Heavy weights under W hide many points; U hides others: both kinds of
  // events happen in every dimension.
  for (int d = 2; d <= 5; ++d) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(900 + d));
    const std::size_t n = d == 2 ? 150 : (d == 3 ? 80 : (d == 4 ? 60 : 45));
    const double hi = d <= 3 ? 0.1 : 0.4;
    const PointSet pts = random_points(d, n, rng);
    const std::vector<double> w = random_weights(n, hi, rng), u = random_weights(n, hi, rng);
    const ref::Rtd a = ref::rtd_incremental(with_weights(pts, w)), b = ref::rtd_incremental(with_weights(pts, u));
    std::vector<Index> entering;
    std::set_difference(a.redundant.begin(), a.redundant.end(), b.redundant.begin(), b.redundant.end(),
                        std::back_inserter(entering));
    INFO("d " << d << ": " << a.redundant.size() << " redundant under W, " << b.redundant.size() << " under U");
    REQUIRE(!entering.empty());
    REQUIRE(b.redundant.size() > 0);
    const Checked c = check_instant_flip(pts, w, u);
    CHECK(c.problem == "");
    CHECK(c.inserted >= entering.size());
  }
}

TEST_CASE("instant flip: equal weights on integer lattices (degenerate, simultaneous events)",
          "[instant_flip][insert]") {
  // A lattice in a generic frame (no flat simplex): W and U take a few equal
  // values, so many (d+2)-sets are flat and many events share one time.
  for (int d = 2; d <= 4; ++d) {
    const int k = d == 2 ? 6 : (d == 3 ? 3 : 2);
    const PointSet pts = lattice_points(d, k);
    const std::size_t n = pts.size();
    for (int pattern = 0; pattern < 4; ++pattern) {
      std::vector<double> w(n, 0.0), u(n, 0.0);
      for (std::size_t i = 0; i < n; ++i) {
        int parity = 0;
        for (int j = 0; j < d; ++j) parity += static_cast<int>(pts.point(i)[j] >= 0 ? pts.point(i)[j] : 0);
        if (pattern == 0) u[i] = parity % 2 ? 0.5 : 0.0;              // checkerboard: half the points lifted down
        if (pattern == 1) w[i] = parity % 2 ? 0.9 : 0.0;              // ... and back (points enter)
        if (pattern == 2) w[i] = (i % 3 == 0) ? 1.0 : 0.0, u[i] = (i % 3 == 1) ? 1.0 : 0.0;
        if (pattern == 3) w[i] = 0.25 * static_cast<double>(i % 4), u[i] = 0.25 * static_cast<double>((i + 2) % 4);
      }
      INFO("d " << d << " pattern " << pattern);
      const PointSet pu = with_weights(pts, u);
      const ref::Rtd fresh = ref::rtd_incremental(pu);
      ref::DynamicRegularTriangulation rt(pts, w);
      const ref::WeightUpdateStats st = rt.set_weights(u);
      INFO("instant flips " << st.instant.total_flips() << ", repair flips " << st.total_flips() - st.instant.total_flips()
                            << ", rebuilt " << st.rebuilt << " " << st.rebuild_reason);
      CHECK(rt.simplices() == fresh.simplices);
      CHECK(rt.redundant() == fresh.redundant);
      CHECK(ref::certify_rtd(pu, rt.simplices()).ok);
      // In the plane the frame keeps every simplex of positive volume, so the
      // instant flip does the work. From d = 3 on, the SoS Delaunay
      // triangulation of a cubic lattice has flat simplices (four coplanar
      // cocircular points), outside the thesis' general position: there the
      // update may fall back to RT+1 (dynamic_rt.hpp step 3), still exact.
      if (d == 2) CHECK(!st.rebuilt);
    }
  }
}

TEST_CASE("instant flip: lattices without a frame (flat simplices on the hull)", "[instant_flip][insert]") {
  // Collinear points on the hull boundary give zero-volume simplices, outside
  // the thesis' general position: the update must still equal a fresh build
  // (dynamic_rt.hpp step 3 when the failure times cannot be formed).
  rc::prop("lattice points with integer weights", [](std::uint64_t seed) {
    const int d = 2 + static_cast<int>(seed % 2);
    const std::size_t n = d == 2 ? 12 + (seed >> 2) % 30 : 9 + (seed >> 2) % 16;
    const PointSet pw = test::rtd_lattice(d, n, seed, 3, 2);
    if (!dimension_problem(pw).empty()) return;
    std::mt19937_64 g(seed ^ 0x5eed);
    PointSet pu = pw;
    for (double& x : pu.weights) x = static_cast<double>(g() % 3);
    ref::DynamicRegularTriangulation rt(pw, pw.weights.to_vector());
    rt.set_weights(pu.weights.to_vector());
    RC_ASSERT(rt.simplices() == ref::rtd_incremental(pu).simplices);
  });
}

TEST_CASE("instant flip: every order of simultaneous events reaches the same triangulation",
          "[instant_flip][insert]") {
  // Small lattices (generic frame), W = 0 and U with equal values: the events
  // of one unperturbed time are taken in pseudo-random tie orders and under
  // several perturbation orders (Algorithm 15's and random ones); each run
  // ends, after the SoS check, at the fresh RT(S ⊕ U).
  // (The plane only: 3D lattices have flat simplices, outside the thesis'
  // general position, where the update may fall back to RT+1.)
  for (int k = 4; k <= 5; ++k) {
    const int d = 2;
    const PointSet pts = lattice_points(d, k);
    const std::size_t n = pts.size();
    std::vector<double> w(n, 0.0), u(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) u[i] = 0.3 * static_cast<double>(i % 3);
    const ref::Rtd fresh = ref::rtd_incremental(with_weights(pts, u));
    std::mt19937_64 rng(static_cast<std::uint64_t>(k));
    std::vector<Index> perm(n);
    std::iota(perm.begin(), perm.end(), Index{0});
    std::uint64_t instant_flips = 0;
    for (int run = 0; run < 24; ++run) {
      ref::WeightUpdateOptions opt;
      opt.tie_seed = static_cast<std::uint64_t>(run + 1);
      if (run % 3 == 1) {
        std::shuffle(perm.begin(), perm.end(), rng);
        opt.order = ref::PerturbationOrder::from_order(perm);
      } else if (run % 3 == 2) {
        const auto po = ref::find_perturbation_order(pts, w, ref::rtd_incremental(with_weights(pts, w)).simplices);
        REQUIRE(po.order);
        opt.order = *po.order;
      }
      ref::DynamicRegularTriangulation rt(pts, w);
      const ref::WeightUpdateStats st = rt.set_weights(u, opt);
      INFO("k " << k << " run " << run << " rebuilt " << st.rebuilt << " " << st.rebuild_reason);
      CHECK(rt.simplices() == fresh.simplices);
      CHECK(rt.redundant() == fresh.redundant);
      CHECK(!st.rebuilt);
      instant_flips += st.instant.total_flips();
    }
    CHECK(instant_flips > 0);
  }
}

// The moving model's filtered stage (failure_time.cpp: filter_motion, the
// Laplace expansion in ErrDouble with the last row set exactly) against its
// exact stage (GMP): whenever the filter is certain of a sign — Orient at
// t = 0 and t = 1, and the direction B - A — it is the exact one, and the
// approximate failure time lies within its proven relative bound of the exact
// ratio A / (A - B). On random points and weights, and on integer lattices
// with integer weights (exact zeros everywhere: translated coordinates, equal
// weights, flat sets, where the filter must say "uncertain").
TEST_CASE("moving model: the filtered stage's certain signs and times are the exact stage's", "[instant_flip]") {
  test::prop_scaled("random and lattice tuples, d = 2..5", 1, [] {
    const int d = *rc::gen::inRange(2, 6);
    const bool lattice = *rc::gen::arbitrary<bool>();
    const int k = d + 2;
    const std::size_t n = static_cast<std::size_t>(k) + 3;
    PointSet ps;
    ps.dim = d;
    std::vector<double> w(n), u(n);
    for (std::size_t p = 0; p < n; ++p) {
      for (int j = 0; j < d; ++j)
        ps.coords.push_back(lattice ? *rc::gen::inRange(0, 3) : *rc::gen::inRange(0, 1 << 20) / double(1 << 20));
      w[p] = lattice ? *rc::gen::inRange(0, 2) : *rc::gen::inRange(0, 1000) * 1e-4;
      u[p] = lattice ? *rc::gen::inRange(0, 2) : *rc::gen::inRange(0, 1000) * 1e-4;
    }
    std::vector<Index> id(n);
    std::iota(id.begin(), id.end(), Index{0});
    std::shuffle(id.begin(), id.end(), std::mt19937(*rc::gen::arbitrary<unsigned>()));
    const ref::MovingModel mm(ps, w, u);
    ref::RidgeMotion m;
    try {
      m = ref::ridge_motion(mm, id.data(), id[static_cast<std::size_t>(d)], id[static_cast<std::size_t>(d) + 1]);
    } catch (const std::invalid_argument&) {  // C1 flat, found by the exact stage the filter deferred to
      RC_TAG("flat simplex");
      return;
    }
    RC_TAG(m.filtered ? "filtered" : "exact at once");
    if (!m.filtered) return;
    ref::RidgeMotion x = m;
    try {
      x.ensure_exact();
    } catch (const std::invalid_argument&) {  // a zero-volume C1: the filter must not have been certain of it
      RC_FAIL("the filter was certain of a simplex the exact stage finds flat");
    }
    const int a0 = sgn(x.a0), a1 = sgn(x.a1), dir = sgn(mpz_class(x.a1 - x.a0));
    if (const int s = pred::sign_if_certain(m.fa0)) RC_ASSERT(s == a0);
    if (const int s = pred::sign_if_certain(m.fa1)) RC_ASSERT(s == a1);
    if (const int s = pred::sign_if_certain(m.fd)) RC_ASSERT(s == dir);
    if (std::isfinite(m.t_rel) && dir != 0) {
      mpq_class t(x.a0, mpz_class(x.a0 - x.a1));  // A / (A - B), exactly
      t.canonicalize();
      const double te = t.get_d();
      RC_ASSERT(std::fabs(m.t_approx - te) <= std::fabs(te) * m.t_rel * (1 + 0x1p-40) + 1e-300);
    }
  });
}

// instant_flip_timeline_test.cpp — the time line of thesis §9.3: during the
// monotonic instant flip every intermediate triangulation has a well-separated
// time line (Lemma 9.10), and a well-separated time line is a regularity
// certificate (Theorem 9.6) — checked independently: at a time t inside the
// witness interval every ridge is convex for the weights V(t), by exact
// rational determinants (support/instant_flip_oracles.hpp). A non-regular
// triangulation never has a well-separated time line.
#include <catch2/catch.hpp>

#include <random>

#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/timeline.hpp"
#include "support/instant_flip_examples.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

namespace {

// A rational time inside the witness interval [τ(max N+), τ(min N-)].
mpq_class witness_time(const ref::Timeline& tl) {
  const bool has_lo = tl.max_positive >= 0 && !tl.nodes[static_cast<std::size_t>(tl.max_positive)].minus_infinity;
  const bool has_hi = tl.min_negative >= 0;
  const mpq_class lo = has_lo ? ref::exact_time(tl.nodes[static_cast<std::size_t>(tl.max_positive)].motion) : mpq_class(0);
  const mpq_class hi = has_hi ? ref::exact_time(tl.nodes[static_cast<std::size_t>(tl.min_negative)].motion) : mpq_class(0);
  if (has_lo && has_hi) return (lo + hi) / 2;
  if (has_lo) return lo + 1;
  if (has_hi) return hi - 1;
  return 0;
}

// Independent check of Theorem 9.6 at the witness time: all ridges convex
// (or flat, when the interval is a single time) for V(t) = (1-t)W + tU.
bool convex_at(const PointSet& ps, const std::vector<double>& w, const std::vector<double>& u,
               const std::vector<std::vector<Index>>& simplices, const mpq_class& t) {
  std::vector<mpq_class> v(ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p) v[p] = (1 - t) * mpq_class(w[p]) + t * mpq_class(u[p]);
  return all_convex_q(ps, heights_q(ps, v), to_set(simplices), /*allow_flat=*/true);
}

}  // namespace

TEST_CASE("time line: every intermediate triangulation of an instant flip is well-separated",
          "[instant_flip][timeline]") {
  const struct {
    int d;
    std::size_t n;
    double hi;
  } cases[] = {{2, 40, 0.02}, {3, 25, 0.05}, {4, 14, 0.1}};
  std::size_t checked = 0;
  for (const auto& c : cases)
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      std::mt19937_64 rng(seed * 31 + static_cast<std::uint64_t>(c.d));
      const PointSet pts = random_points(c.d, c.n, rng);
      const std::vector<double> w = random_weights(c.n, c.hi, rng), u = random_weights(c.n, c.hi, rng);
      const PointSet pw = with_weights(pts, w);
      ref::rtd::TriangulationD T = ref::build_rtd(pw);
      const ref::MovingModel mm(pts, w, u);
      const auto order = ref::PerturbationOrder::identity(c.n);
      INFO("d " << c.d << " seed " << seed);

      const ref::Timeline t0 = ref::build_timeline(mm, ref::rtd::real_simplices(T), order);
      CHECK(t0.well_separated);
      CHECK(ref::well_separated_within(t0, 0.0, 0.0, order));  // RT(S ⊕ W) at t = 0
      ref::InstantFlipOptions opt;
      opt.on_flip = [&](const ref::rtd::TriangulationD& cur, const ref::InstantFlipEvent& ev) {
        const auto list = ref::rtd::real_simplices(cur);
        const ref::Timeline tl = ref::build_timeline(mm, list, order);
        CHECK(tl.well_separated);
        // the current time τ of the flip lies in the witness interval
        const double tau = ref::approximate_time(*ev.ridge);
        if (tau > 1e-9 && tau < 1 - 1e-9) CHECK(ref::well_separated_within(tl, tau * (1 - 1e-9), tau * (1 + 1e-9), order));
        CHECK(convex_at(pts, w, u, list, witness_time(tl)));
        ++checked;
      };
      ref::instant_flip(T, w, u, opt);
      const ref::Timeline t1 = ref::build_timeline(mm, ref::rtd::real_simplices(T), order);
      CHECK(t1.well_separated);
      CHECK(ref::well_separated_within(t1, 1.0, 1.0, order));  // RT ⊕ U at t = 1
    }
  CHECK(checked > 50);
}

TEST_CASE("time line: a non-regular triangulation is never well-separated", "[instant_flip][timeline]") {
  const PointSet ps = mother_points();
  const SimplexSet twisted = mother_twisted();
  const std::vector<std::vector<Index>> list(twisted.begin(), twisted.end());
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<double> w = random_weights(6, 10.0, rng), u = random_weights(6, 10.0, rng);
    const ref::MovingModel mm(ps, w, u);
    const ref::Timeline tl = ref::build_timeline(mm, list, ref::PerturbationOrder::identity(6));
    CHECK_FALSE(tl.well_separated);
    CHECK(tl.nodes.size() == 9);  // 15 edges, 6 on the hull
    CHECK(tl.boundary_ridges == 3);
  }
}

TEST_CASE("time line: the text view", "[instant_flip][timeline]") {
  std::mt19937_64 rng(4);
  const PointSet pts = random_points(3, 20, rng);
  const std::vector<double> w = random_weights(20, 0.05, rng), u = random_weights(20, 0.05, rng);
  const PointSet pw = with_weights(pts, w);
  const auto list = ref::rtd::real_simplices(ref::build_rtd(pw));
  const ref::MovingModel mm(pts, w, u);
  const ref::Timeline tl = ref::build_timeline(mm, list, ref::PerturbationOrder::identity(20));
  const std::string text = ref::format_timeline(tl);
  std::size_t lines = 0, node_lines = 0;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') {
      ++lines;
      if (i + 1 < text.size() && text[i + 1] != '#') ++node_lines;
    }
  CHECK(node_lines == tl.nodes.size());
  CHECK(node_lines == ridges_of(to_set(list)).size());
  CHECK(lines == node_lines + 3);
  CHECK(text.find("# well-separated") != std::string::npos);
  CHECK(tl.positive + tl.negative == tl.nodes.size());
  // nodes are in time order (exact rational times; equal for nodes of one flip)
  for (std::size_t i = 1; i < tl.nodes.size(); ++i)
    if (!tl.nodes[i - 1].minus_infinity)
      CHECK(ref::exact_time(tl.nodes[i - 1].motion) <= ref::exact_time(tl.nodes[i].motion));

  const PointSet mp = mother_points();
  const SimplexSet tw = mother_twisted();
  const ref::MovingModel m2(mp, random_weights(6, 1.0, rng), random_weights(6, 1.0, rng));
  const std::string bad = ref::format_timeline(
      ref::build_timeline(m2, {tw.begin(), tw.end()}, ref::PerturbationOrder::identity(6)));
  CHECK(bad.find("# not well-separated") != std::string::npos);
}

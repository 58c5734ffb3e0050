// instant_flip_perturbation_order_test.cpp — thesis §9.2.3, Algorithm 15, on
// weakly regular inputs (flat ridges): lattice points and cospherical points
// with equal weights. The order found is checked independently: with concrete
// perturbing values 2^(-40(rank+1)) added to the heights, every ridge is
// strictly convex (exact rationals, support/instant_flip_examples.hpp). For
// six points, Theorem 9.5 is checked exhaustively: over all triangulations and
// all 720 orders, the finder succeeds iff some order works; the non-regular
// "mother of all examples" triangulation is reported as having none.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/perturbation_order.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "support/instant_flip_examples.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

namespace {

std::vector<std::vector<Index>> as_list(const SimplexSet& T) { return {T.begin(), T.end()}; }

bool order_works(const PointSet& ps, const std::vector<double>& w, const SimplexSet& T,
                 const std::vector<Index>& order) {
  return all_convex_q(ps, perturbed_heights(ps, w, order), T);
}

// The regular triangulation of ps computed with the points relabelled by
// `perm` (new point i is old point perm[i]), in old labels: another
// resolution of the same weakly regular subdivision.
SimplexSet rt_relabelled(const PointSet& ps, const std::vector<Index>& perm) {
  PointSet q;
  q.dim = ps.dim;
  q.weighted = true;
  for (Index old : perm) {
    q.coords.insert(q.coords.end(), ps.point(old), ps.point(old) + ps.dim);
    q.weights.push_back(ps.weight(old));
  }
  SimplexSet out;
  for (auto s : ref::rtd_incremental(q).simplices) {
    for (Index& x : s) x = perm[x];
    out.insert(sorted(s));
  }
  return out;
}

// The finder on T: succeeds, its order works, and it is the index order
// whenever that one works (the smallest-index-first queue).
void check_found(const PointSet& ps, const std::vector<double>& w, const SimplexSet& T) {
  const ref::PerturbationOrderResult r = ref::find_perturbation_order(ps, w, as_list(T));
  INFO(r.reason);
  REQUIRE(r.order.has_value());
  CHECK(r.reason.empty());
  CHECK(order_works(ps, w, T, r.order->order));
  std::vector<Index> id(ps.size());
  std::iota(id.begin(), id.end(), Index{0});
  if (order_works(ps, w, T, id)) CHECK(r.order->order == id);
}

void check_weakly_regular_family(const PointSet& ps, int relabellings, std::uint64_t seed) {
  const std::vector<double> w = ps.weights.to_vector();  // equal weights (0)
  const SimplexSet T = to_set(ref::rtd_incremental(ps).simplices);
  REQUIRE(all_convex_q(ps, heights_q(ps, to_q(w)), T, /*allow_flat=*/true));  // weakly regular
  const ref::PerturbationOrderResult r0 = ref::find_perturbation_order(ps, w, as_list(T));
  CHECK(r0.flat_ridges > 0);
  check_found(ps, w, T);
  std::mt19937_64 rng(seed);
  std::vector<Index> perm(ps.size());
  std::iota(perm.begin(), perm.end(), Index{0});
  for (int i = 0; i < relabellings; ++i) {
    std::shuffle(perm.begin(), perm.end(), rng);
    const SimplexSet Ti = rt_relabelled(ps, perm);
    REQUIRE(all_convex_q(ps, heights_q(ps, to_q(w)), Ti, true));
    check_found(ps, w, Ti);
  }
}

}  // namespace

TEST_CASE("perturbation order: lattice points with equal weights", "[instant_flip][perturbation_order]") {
  check_weakly_regular_family(lattice_points(2, 5), 6, 1);
  check_weakly_regular_family(lattice_points(3, 3), 3, 2);
}

TEST_CASE("perturbation order: cospherical points with equal weights", "[instant_flip][perturbation_order]") {
  const PointSet circle = circle_points();
  REQUIRE(circle.size() >= 12);
  check_weakly_regular_family(circle, 6, 3);
  const PointSet sphere = sphere_points(12);
  REQUIRE(sphere.size() >= 10);
  check_weakly_regular_family(sphere, 3, 4);
}

TEST_CASE("perturbation order: Theorem 9.5 exhaustively on six points", "[instant_flip][perturbation_order]") {
  // All triangulations of the mother-of-all-examples points (flip graph from
  // one of them), every point lifted onto one plane: every ridge is flat.
  const PointSet ps = mother_points();
  const std::vector<double> w = flat_weights(ps);
  std::set<SimplexSet> all{to_set(ref::rtd_incremental(ps).simplices)};
  std::vector<SimplexSet> todo(all.begin(), all.end());
  while (!todo.empty()) {
    const SimplexSet T = todo.back();
    todo.pop_back();
    for (const Ridge& r : ridges_of(T)) {
      SimplexSet next;
      if (radon_flip(ps, T, r, &next) && all.insert(next).second) todo.push_back(next);
    }
  }
  REQUIRE(all.count(mother_twisted()) == 1);
  std::vector<Index> perm(6);
  std::size_t with_order = 0, without = 0;
  for (const SimplexSet& T : all) {
    std::iota(perm.begin(), perm.end(), Index{0});
    bool exists = false;
    do exists = order_works(ps, w, T, perm);
    while (!exists && std::next_permutation(perm.begin(), perm.end()));
    const ref::PerturbationOrderResult r = ref::find_perturbation_order(ps, w, as_list(T));
    CHECK(r.flat_ridges == r.interior_ridges);
    CHECK(r.order.has_value() == exists);
    if (r.order) {
      CHECK(order_works(ps, w, T, r.order->order));
      ++with_order;
    } else {
      CHECK_FALSE(r.reason.empty());
      CHECK_FALSE(r.blocked_points.empty());
      ++without;
    }
  }
  CHECK(with_order > 0);
  CHECK(without > 0);
  const ref::PerturbationOrderResult twisted = ref::find_perturbation_order(ps, w, as_list(mother_twisted()));
  CHECK_FALSE(twisted.order.has_value());
  CHECK(twisted.reason.find("no perturbation order") != std::string::npos);
}

TEST_CASE("perturbation order: a reflex ridge is reported", "[instant_flip][perturbation_order]") {
  // The Delaunay triangulation is not regular for weights favouring a point
  // strongly: some ridge is reflex, no order can help.
  const PointSet ps = circle_points();
  const SimplexSet T = to_set(ref::rtd_incremental(ps).simplices);
  std::vector<double> w(ps.size(), 0.0);
  w[0] = 1000.0;  // lowers point 0 (an ear): the edge across its triangle becomes reflex
  const ref::PerturbationOrderResult r = ref::find_perturbation_order(ps, w, as_list(T));
  CHECK_FALSE(r.order.has_value());
  CHECK(r.reason.find("reflex") != std::string::npos);
}

TEST_CASE("instant flip from a weakly regular start with the finder's order", "[instant_flip][perturbation_order]") {
  // Cocircular points, equal weights W = 0, a triangulation that the index
  // order does not make strongly regular; U random (generic): the instant
  // flip with the order of Algorithm 15 reaches RT(S ⊕ U).
  const PointSet ps = circle_points();
  const std::size_t n = ps.size();
  const std::vector<double> w(n, 0.0);
  std::mt19937_64 rng(11);
  std::vector<Index> perm(n);
  std::iota(perm.begin(), perm.end(), Index{0});
  std::vector<Index> id = perm;
  int runs = 0;
  for (int trial = 0; trial < 20 && runs < 5; ++trial) {
    std::shuffle(perm.begin(), perm.end(), rng);
    const SimplexSet T0 = rt_relabelled(ps, perm);
    if (order_works(ps, w, T0, id)) continue;  // want a start that needs the finder
    const ref::PerturbationOrderResult r = ref::find_perturbation_order(ps, w, as_list(T0));
    REQUIRE(r.order.has_value());
    const std::vector<double> u = random_weights(n, 400.0, rng);
    const PointSet pu = with_weights(ps, u);
    ref::rtd::TriangulationD T = ref::rtd::from_simplices(ps, as_list(T0));
    // the index order is rejected, the finder's order accepted
    {
      ref::rtd::TriangulationD copy = T;
      CHECK_THROWS_AS(ref::instant_flip(copy, w, u), std::invalid_argument);
    }
    ref::InstantFlipOptions opt;
    opt.order = *r.order;
    ref::instant_flip(T, w, u, opt);
    if (ref::reappearing_points(T, u).empty()) {
      CHECK(ref::rtd::real_simplices(T) == ref::rtd_incremental(pu).simplices);
      CHECK(ref::certify_rtd(pu, ref::rtd::real_simplices(T)).ok);
    }
    ++runs;
  }
  CHECK(runs >= 3);
}

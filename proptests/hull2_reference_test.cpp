// hull2_reference_test.cpp — the reference 2D hulls (thesis ch. 4 and §8.3) are
// THE canonical hull.
//
// Oracles: brute::hull2 (the SoS hull by its definition, O(n^3)); the exact
// certifier (certify::hull2 at Level::canonical and Level::exact); CGAL's
// convex_hull_2 (exact predicates, its own handling of degeneracies: only
// strictly convex vertices) through peers::cgal_hull2; and the algorithms
// against each other (graham-sort == graham-insert == twist + flip-pop, flip-pop
// from many star-shaped polygons, every insertion rule of Graham-insertion).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "gen/generate.hpp"
#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;
using certify::Level;

namespace flipflop {
// counterexamples printed by RapidCheck
void showValue(const PointSet& ps, std::ostream& os) {
  os << ps.size() << " points:" << std::setprecision(17);
  for (std::size_t i = 0; i < ps.size(); ++i) os << " (" << ps.point(i)[0] << " " << ps.point(i)[1] << ")";
}
}  // namespace flipflop

namespace {

std::vector<std::string> families2d() {
  std::vector<std::string> out;
  for (const std::string& d : gen::distributions())
    if (gen::dimension_of(d) == 2) out.push_back(d);
  return out;
}

const std::vector<std::string> kRandomFamilies = {"square", "disk", "frame", "circle"};
const std::vector<std::string> kDegenerateFamilies = {"grid2", "circle-lattice", "duplicates2",
                                                      "jitter2", "huge2", "tiny2"};

PointSet generate(const std::string& fam, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  return gen::generate(fam, n, o);
}

bool spans(const PointSet& ps) { return dimension_problem(ps).empty(); }

// A 64-bit seed, not scaled down by RapidCheck's size.
rc::Gen<std::uint64_t> any_seed() {
  return rc::gen::noShrink(rc::gen::resize(100, rc::gen::arbitrary<std::uint64_t>()));
}

// Small sets with integer coordinates in [-r, r]: rich in collinear points and duplicates.
rc::Gen<PointSet> small_integer_points(int nmin, int nmax) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(nmin, nmax + 1);
    const int r = *rc::gen::inRange(1, 5);
    PointSet ps;
    ps.dim = 2;
    // (inRange scales with RapidCheck's size; coordinates use the full range)
    for (int i = 0; i < 2 * n; ++i) ps.coords.push_back(double(*rc::gen::resize(100, rc::gen::inRange(-r, r + 1))));
    return ps;
  });
}

// Points of any 2D family, n in [nmin, nmax], spanning the plane.
rc::Gen<PointSet> family_points(const std::vector<std::string>& fams, int nmin, int nmax) {
  return rc::gen::exec([=] {
    const std::string fam = *rc::gen::elementOf(fams);
    const int n = *rc::gen::inRange(nmin, nmax + 1);
    const auto seed = *any_seed();
    return generate(fam, static_cast<std::size_t>(n), seed);
  });
}

// The three algorithms agree byte for byte and are certified canonical (twist,
// Θ(n^2) from the input order, up to twist_max points).
std::vector<Index> all_three(const PointSet& ps, std::size_t twist_max = 1000) {
  const auto a = ref::hull2_graham_sort(ps);
  const auto b = ref::hull2_graham_insert(ps);
  RC_ASSERT(a == b);
  if (ps.size() <= twist_max) RC_ASSERT(a == ref::hull2_twist(ps));
  RC_ASSERT(certify::hull2(ps, a, Level::canonical).message() == "certified");
  return a;
}

// A kernel point strictly inside: (a + b + c + c)/4 for a random exactly
// non-degenerate triangle abc of input points (falls back to interior_kernel).
pred::RationalPoint random_kernel(const PointSet& ps, std::mt19937_64& rng) {
  const std::size_t n = ps.size();
  for (int attempt = 0; attempt < 50; ++attempt) {
    const double* a = ps.point(rng() % n);
    const double* b = ps.point(rng() % n);
    const double* c = ps.point(rng() % n);
    if (pred::orient2d_exact(a, b, c) == 0) continue;
    const double* pts[4] = {a, b, c, c};
    return pred::RationalPoint::centroid(pts, 4, 2);
  }
  return ref::interior_kernel(ps);
}

// The polygon of the given vertices sorted by angle around the kernel, from γ
// (an independent construction of a star-shaped polygon: std::sort).
std::vector<Index> angular_polygon(const PointSet& ps, std::vector<Index> vertices, const pred::RationalPoint& s) {
  const ref::StarKernel k(ps, s);
  std::sort(vertices.begin(), vertices.end(), [&](Index p, Index q) { return k.angle_less(p, q); });
  return vertices;
}

// Locations of the strictly convex corners of a hull cycle (consecutive
// vertices at one location merged first): the strictly extreme points.
std::set<std::pair<double, double>> strict_corners(const PointSet& ps, const std::vector<Index>& cycle) {
  std::vector<Index> L;
  auto same = [&](Index a, Index b) { return ps.point(a)[0] == ps.point(b)[0] && ps.point(a)[1] == ps.point(b)[1]; };
  for (Index v : cycle)
    if (L.empty() || !same(L.back(), v)) L.push_back(v);
  while (L.size() > 1 && same(L.back(), L.front())) L.pop_back();
  std::set<std::pair<double, double>> out;
  const std::size_t m = L.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Index a = L[(k + m - 1) % m], b = L[k], c = L[(k + 1) % m];
    if (pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)) > 0)
      out.insert({ps.point(b)[0], ps.point(b)[1]});
  }
  return out;
}

std::set<std::pair<double, double>> locations(const PointSet& ps, const std::vector<Index>& v) {
  std::set<std::pair<double, double>> out;
  for (Index i : v) out.insert({ps.point(i)[0], ps.point(i)[1]});
  return out;
}

}  // namespace

TEST_CASE("hull2 reference: every 2D family, small n — equal to brute::hull2 and certified", "[hull2][reference]") {
  rc::prop("generator families, n in [3, 40]", [] {
    const PointSet ps = *family_points(families2d(), 3, 40);
    if (!spans(ps)) {  // collinear2: lower-dimensional input is rejected
      RC_ASSERT_THROWS_AS(ref::hull2_graham_sort(ps), std::invalid_argument);
      RC_ASSERT_THROWS_AS(ref::hull2_graham_insert(ps), std::invalid_argument);
      RC_ASSERT_THROWS_AS(ref::hull2_twist(ps), std::invalid_argument);
      return;
    }
    RC_ASSERT(all_three(ps) == brute::hull2(ps));
  });
  rc::prop("integer coordinates in [-4, 4] (collinear points, duplicates), n in [3, 30]", [] {
    const PointSet ps = *small_integer_points(3, 30);
    RC_PRE(spans(ps));
    RC_ASSERT(all_three(ps) == brute::hull2(ps));
  });
}

TEST_CASE("hull2 reference: every 2D family up to 2000 points — certified, three algorithms identical",
          "[hull2][reference][long]") {
  std::size_t runs = 0;
  for (const std::string& fam : families2d()) {
    if (fam == "collinear2") continue;  // lower-dimensional, rejected (tested above)
    for (std::size_t n : {3, 4, 5, 6, 10, 31, 100, 300, 1000, 2000})
      for (std::uint64_t seed : {1, 2}) {
        const PointSet ps = generate(fam, n, seed);
        if (!spans(ps)) continue;  // e.g. 3 points of a lattice on one line
        INFO(fam << " n=" << n << " seed=" << seed);
        const auto a = ref::hull2_graham_sort(ps);
        REQUIRE(certify::hull2(ps, a, Level::canonical).message() == "certified");
        REQUIRE(ref::hull2_graham_insert(ps) == a);
        if (n <= 1000) REQUIRE(ref::hull2_twist(ps) == a);  // Θ(n^2) twists from the input order
        if (n <= 100) REQUIRE(brute::hull2(ps) == a);
        ++runs;
      }
  }
  REQUIRE(runs >= 180);
}

TEST_CASE("hull2 reference: random non-degenerate input — the same vertices as CGAL", "[hull2][reference][cgal]") {
  rc::prop("square, disk, frame, circle; n in [3, 400]", [] {
    const PointSet ps = *family_points(kRandomFamilies, 3, 400);
    const auto h = ref::hull2_graham_sort(ps);
    RC_ASSERT(h == peers::cgal_hull2(ps, peers::Hull2Algo::akl_toussaint));
    RC_ASSERT(h == peers::cgal_hull2(ps, peers::Hull2Algo::graham_andrew));
    RC_ASSERT(h == ref::hull2_graham_insert(ps));
    if (ps.size() <= 150) RC_ASSERT(h == ref::hull2_twist(ps));
  });
}

TEST_CASE("hull2 reference: degenerate input — certified, strictly extreme points equal CGAL's",
          "[hull2][reference][cgal]") {
  auto check = [](const PointSet& ps) {
    const auto h = all_three(ps, 120);
    RC_ASSERT(certify::hull2(ps, h, Level::exact).message() == "certified");
    // CGAL reports only strictly convex vertices, one index per location
    const auto cg = peers::cgal_hull2(ps, peers::Hull2Algo::akl_toussaint);
    RC_ASSERT(strict_corners(ps, h) == locations(ps, cg));
  };
  rc::prop("grid2, circle-lattice, duplicates2, jitter2, huge2, tiny2; n in [3, 300]", [&] {
    const PointSet ps = *family_points(kDegenerateFamilies, 3, 300);
    RC_PRE(spans(ps));
    check(ps);
  });
  rc::prop("integer coordinates in [-4, 4], n in [3, 40]", [&] {
    const PointSet ps = *small_integer_points(3, 40);
    RC_PRE(spans(ps));
    check(ps);
  });
}

TEST_CASE("hull2 reference: flip-pop from other star-shaped polygons and twist from other polygons",
          "[hull2][reference][flip-pop][twist]") {
  rc::prop("random kernels, random vertex orders, subsets", [] {
    const bool integer = *rc::gen::arbitrary<bool>();
    const PointSet ps = integer ? *small_integer_points(3, 40) : *family_points(families2d(), 3, 150);
    RC_PRE(spans(ps));
    std::mt19937_64 rng(*any_seed());
    const auto hull = ref::hull2_graham_sort(ps);
    const Index n = static_cast<Index>(ps.size());
    std::vector<Index> all(n);
    std::iota(all.begin(), all.end(), Index{0});

    // 1. sorted by angle around a random interior kernel: star-shaped; flip-pop -> the hull
    const pred::RationalPoint s = random_kernel(ps, rng);
    const auto star = angular_polygon(ps, all, s);
    RC_ASSERT(ref::is_star_shaped(ps, star, s));
    ref::Hull2Stats st;
    RC_ASSERT(ref::flip_pop(ps, star, s, &st) == hull);
    RC_ASSERT(st.flips_2_1 == n - hull.size());
    RC_ASSERT(st.hull_vertices == hull.size());
    // any rotation of the same polygon
    auto rotated = star;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<long>(rng() % n), rotated.end());
    RC_ASSERT(ref::flip_pop(ps, rotated, s) == hull);

    // 2. twist from a random vertex order: the angular order (Thm 8.1), then flip-pop
    auto shuffled = all;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    ref::Hull2Stats tst;
    const auto twisted = ref::twist_to_star(ps, shuffled, s, &tst);
    RC_ASSERT(twisted == star);
    std::size_t inversions = 0;  // bubble sort: one twist per inversion
    const ref::StarKernel k(ps, s);
    for (Index i = 0; i < n; ++i)
      for (Index j = i + 1; j < n; ++j) inversions += k.angle_less(shuffled[j], shuffled[i]);
    RC_ASSERT(tst.twists == inversions);
    RC_ASSERT(ref::flip_pop(ps, twisted, s) == hull);

    // 3. a subset (kept in index order, so the perturbation order is the same):
    //    flip-pop on its star-shaped polygon == the hull of the subset
    std::vector<Index> subset;
    for (Index i = 0; i < n; ++i)
      if (rng() % 3 != 0) subset.push_back(i);
    PointSet sub;
    sub.dim = 2;
    for (Index i : subset) sub.coords.insert(sub.coords.end(), ps.point(i), ps.point(i) + 2);
    RC_PRE(subset.size() >= 3 && spans(sub));
    std::vector<Index> sub_hull;
    for (Index i : ref::hull2_graham_sort(sub)) sub_hull.push_back(subset[i]);
    const pred::RationalPoint ss = ref::interior_kernel(sub);
    RC_ASSERT(ref::flip_pop(ps, angular_polygon(ps, subset, ss), ss) == ref::rotate_to_smallest(sub_hull));
  });
}

TEST_CASE("hull2 reference: Graham-insertion reaches the same hull whichever point it inserts",
          "[hull2][reference][graham-insertion]") {
  rc::prop("furthest, smallest index, random", [] {
    const bool integer = *rc::gen::arbitrary<bool>();
    const PointSet ps = integer ? *small_integer_points(3, 40) : *family_points(families2d(), 3, 300);
    RC_PRE(spans(ps));
    const auto hull = ref::hull2_graham_sort(ps);
    ref::InsertionOptions o;
    ref::Hull2Stats st;
    RC_ASSERT(ref::graham_insertion(ps, &st, o) == hull);
    // every point is inserted or dropped early; every inserted non-hull point is flipped away
    RC_ASSERT(st.insertions + st.discarded_early + 2 == ps.size());
    RC_ASSERT(st.insertions + 2 == st.polygon_vertices);
    RC_ASSERT(st.flips_2_1 + hull.size() == st.polygon_vertices);
    o.choice = ref::InsertionChoice::smallest_index;
    RC_ASSERT(ref::graham_insertion(ps, nullptr, o) == hull);
    o.choice = ref::InsertionChoice::random;
    o.seed = *any_seed();
    RC_ASSERT(ref::graham_insertion(ps, nullptr, o) == hull);
  });
}

TEST_CASE("hull2 reference: 10^5 points of square, disk, frame, circle — certified, flip counts",
          "[hull2][reference][large][long]") {
  const std::size_t n = 100000, n_twist = 3000;
  std::ostringstream table;
  table << "hull2 reference, 2-1 flips (seed 1; ins = Graham-insertion inserting the furthest point,\n"
        << "ins(random) = inserting a random associated point; rounds = passes of Alg 1):\n"
        << std::left << std::setw(8) << "dist" << std::right << std::setw(8) << "n" << std::setw(7) << "hull"
        << std::setw(12) << "sort:flips" << std::setw(8) << "rounds" << std::setw(12) << "ins:flips"
        << std::setw(8) << "rounds" << std::setw(9) << "inserted" << std::setw(10) << "dropped"
        << std::setw(8) << "irounds" << std::setw(13) << "ins(random)" << "\n";
  for (const std::string& fam : kRandomFamilies) {
    const PointSet ps = generate(fam, n, 1);
    ref::Hull2Stats s1, s2;
    const auto a = ref::hull2_graham_sort(ps, &s1);
    INFO(fam);
    REQUIRE(certify::hull2(ps, a, Level::canonical).message() == "certified");
    REQUIRE(ref::hull2_graham_insert(ps, &s2) == a);
    REQUIRE(s1.flips_2_1 == n - a.size());  // Graham-sorting's polygon holds every point
    REQUIRE(s2.insertions + s2.discarded_early + 2 == n);
    REQUIRE(a == peers::cgal_hull2(ps, peers::Hull2Algo::akl_toussaint));
    table << std::left << std::setw(8) << fam << std::right << std::setw(8) << n << std::setw(7) << a.size()
          << std::setw(12) << s1.flips_2_1 << std::setw(8) << s1.rounds << std::setw(12) << s2.flips_2_1
          << std::setw(8) << s2.rounds << std::setw(9) << s2.insertions << std::setw(10) << s2.discarded_early
          << std::setw(8) << s2.insertion_rounds;
    // Graham-insertion inserting a random associated point instead of the furthest
    ref::InsertionOptions random_choice;
    random_choice.choice = ref::InsertionChoice::random;
    ref::Hull2Stats s3;
    REQUIRE(ref::graham_insertion(ps, &s3, random_choice) == a);
    table << std::setw(13) << s3.flips_2_1 << "\n";
  }
  // twist from the input order costs one twist per inversion, Θ(n^2) on
  // random order: compared on fewer points.
  table << "hull2 reference, twist + flip-pop from the input order (seed 1):\n";
  for (const std::string& fam : kRandomFamilies) {
    const PointSet ps = generate(fam, n_twist, 1);
    ref::Hull2Stats st;
    const auto a = ref::hull2_twist(ps, &st);
    INFO(fam);
    REQUIRE(certify::hull2(ps, a, Level::canonical).message() == "certified");
    REQUIRE(a == ref::hull2_graham_sort(ps));
    REQUIRE(st.flips_2_1 == n_twist - a.size());
    table << "  " << std::left << std::setw(8) << fam << std::right << " n=" << n_twist << " twists=" << st.twists
          << " edge checks=" << st.twist_checks << " flips=" << st.flips_2_1 << " rounds=" << st.rounds
          << " hull=" << a.size() << "\n";
  }
  std::cout << table.str() << std::flush;
}

TEST_CASE("hull2 reference: invalid input is rejected", "[hull2][reference]") {
  PointSet line;
  line.dim = 2;
  line.coords = {0, 0, 1, 1, 2, 2, 3, 3};
  for (const std::string& algo : ref::hull2_algorithms())
    REQUIRE_THROWS_AS(ref::hull2(line, algo), std::invalid_argument);
  PointSet two;
  two.dim = 2;
  two.coords = {0, 0, 1, 0};
  REQUIRE_THROWS_AS(ref::hull2_graham_sort(two), std::invalid_argument);
  PointSet same;
  same.dim = 2;
  same.coords = {5, 5, 5, 5, 5, 5};
  REQUIRE_THROWS_AS(ref::hull2_twist(same), std::invalid_argument);
  PointSet tri;
  tri.dim = 2;
  tri.coords = {0, 0, 4, 0, 0, 4};
  REQUIRE_THROWS_AS(ref::hull2(tri, "quickhull"), std::invalid_argument);
  const pred::RationalPoint s = ref::interior_kernel(tri);
  REQUIRE_THROWS_AS(ref::flip_pop(tri, {0, 1}, s), std::invalid_argument);
  REQUIRE_THROWS_AS(ref::flip_pop(tri, {0, 1, 1}, s), std::invalid_argument);
  REQUIRE_THROWS_AS(ref::flip_pop(tri, {0, 1, 3}, s), std::invalid_argument);
  REQUIRE_THROWS_AS(ref::twist_to_star(tri, {0, 1}, s), std::invalid_argument);
  REQUIRE(ref::flip_pop(tri, {0, 1, 2}, s) == std::vector<Index>{0, 1, 2});
  REQUIRE(ref::is_star_shaped(tri, {0, 1, 2}, s));
  REQUIRE(!ref::is_star_shaped(tri, {0, 2, 1}, s));  // clockwise
}

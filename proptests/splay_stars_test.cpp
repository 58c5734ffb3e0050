// splay_stars_test.cpp — star_splaying's contract on user stars (item (e)):
// valid stars in any form are accepted (pipeline stars, random convex and
// dead stars, any order of the list), and every kind of bad star is rejected
// with std::invalid_argument naming the problem — among them a violation of
// Shewchuk's lexicographic precondition, shown to matter: two far-apart
// clusters, each with the stars of its own hull, are consistent convex stars
// whose splaying (with the check switched off) stops at two polytopes, not
// at the hull.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <map>
#include <numeric>
#include <set>

#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/splay_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/star_splaying.hpp"

using namespace flipflop;

namespace {

bool spans_3d(const PointSet& ps) { return ps.size() >= 4 && affine_dimension(ps) == 3; }

// The stars of a convex polytope given by its triangles (counter-clockwise
// seen from outside): around v, triangle (v, x, y) is followed by the one
// holding directed edge (v, y). Written here independently of the library.
std::vector<ref::Star> stars_of_polytope(const std::vector<Triangle>& tris) {
  std::map<std::pair<Index, Index>, Index> third;  // directed edge (a, b) of triangle (a, b, c) -> c
  std::set<Index> verts;
  for (const Triangle& t : tris)
    for (int e = 0; e < 3; ++e) {
      third[{t[e], t[(e + 1) % 3]}] = t[(e + 2) % 3];
      verts.insert(t[e]);
    }
  std::vector<ref::Star> out;
  for (Index v : verts) {
    ref::Star s;
    s.apex = v;
    Index first = 0;
    for (const auto& [e, c] : third)
      if (e.first == v) {
        first = e.second;
        break;
      }
    Index x = first;
    do {
      s.link.push_back(x);
      x = third.at({v, x});
    } while (x != first);
    out.push_back(s);
  }
  return out;
}

std::string rejection(const PointSet& ps, const std::vector<ref::Star>& stars) {
  try {
    ref::star_splaying(ps, stars);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

bool mentions(const std::string& msg, const std::string& what) { return msg.find(what) != std::string::npos; }

std::size_t alive_with_link(const std::vector<ref::Star>& s, std::size_t min_link) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!s[i].dead && s[i].link.size() >= min_link) return i;
  return s.size();
}

}  // namespace

TEST_CASE("splay: valid stars are accepted in every form", "[splay]") {
  test::prop_scaled("pipeline, random, shuffled, dead-given stars -> brute::hull3", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 20, false);
    RC_PRE(spans_3d(ps));
    const auto expected = brute::hull3(ps);
    auto stars = ref::initial_stars(ps);
    std::mt19937_64 rng(*test::any_seed());
    std::shuffle(stars.begin(), stars.end(), rng);
    RC_ASSERT(ref::star_splaying(ps, stars) == expected);
    RC_ASSERT(ref::star_splaying(ps, test::random_stars(ps, rng())) == expected);
    // the final stars of one run (hull stars and dead stars) are a fixed point
    auto st = ref::splay::make_state(ps, stars, true);
    ref::splay::run(st);
    ref::Hull3Stats stats;
    RC_ASSERT(ref::star_splaying(ps, ref::splay::stars(st), &stats) == expected);
    RC_ASSERT(stats.splay_insertions == 0u);
  });
}

TEST_CASE("splay: bad stars are rejected with one clear message", "[splay]") {
  const PointSet ps = test::family3("ball", 40, 11);
  const auto good = ref::initial_stars(ps);
  REQUIRE(ref::star_splaying(ps, good) == brute::hull3(ps));
  const std::size_t s4 = alive_with_link(good, 4);
  REQUIRE(s4 < good.size());
  const Index n = static_cast<Index>(ps.size());

  auto bad = good;
  bad.pop_back();
  CHECK(mentions(rejection(ps, bad), "exactly one star"));

  bad = good;
  bad[1].apex = bad[0].apex;
  CHECK(mentions(rejection(ps, bad), "has two stars"));

  bad = good;
  bad[0].apex = n + 3;
  CHECK(mentions(rejection(ps, bad), "no such point"));

  bad = good;
  bad[s4].link.resize(2);
  CHECK(mentions(rejection(ps, bad), "at least 3 vertices"));

  bad = good;
  bad[s4].link[1] = bad[s4].link[0];
  CHECK(mentions(rejection(ps, bad), "repeated"));

  bad = good;
  bad[s4].link[1] = bad[s4].apex;
  CHECK(mentions(rejection(ps, bad), "own link"));

  bad = good;
  bad[s4].link[1] = n;
  CHECK(mentions(rejection(ps, bad), "has no star"));

  bad = good;  // clockwise
  std::reverse(bad[s4].link.begin(), bad[s4].link.end());
  CHECK(mentions(rejection(ps, bad), "not convex"));

  bad = good;  // two link vertices swapped: the link crosses itself
  std::swap(bad[s4].link[0], bad[s4].link[1]);
  CHECK(mentions(rejection(ps, bad), "not convex"));

  bad = good;  // a point inside the cone added to the link
  {
    ref::Star& s = bad[s4];
    for (Index p = 0; p < n; ++p) {
      if (p == s.apex || std::find(s.link.begin(), s.link.end(), p) != s.link.end()) continue;
      auto st = ref::splay::make_state(ps, {s}, false);
      if (ref::splay::insert(st, s.apex, p) != ref::splay::Outcome::unchanged) continue;
      s.link.insert(s.link.begin() + 1, p);  // strictly inside: not a link vertex of a convex star
      break;
    }
    REQUIRE(bad[s4].link.size() == good[s4].link.size() + 1);
  }
  CHECK(mentions(rejection(ps, bad), "not convex"));

  // a hull vertex declared dead: no tetrahedron of other points holds it
  const auto hull = brute::hull3(ps);
  bad = good;
  for (auto& s : bad)
    if (s.apex == hull[0][0]) {
      s.dead = true;
      s.link.clear();
      std::size_t k = 0;  // the first four other points
      for (Index p = 0; k < 4; ++p)
        if (p != s.apex) s.certificate[k++] = p;
    }
  CHECK(mentions(rejection(ps, bad), "certificate"));

  bad = good;  // a dead star whose certificate repeats a point
  for (auto& s : bad)
    if (s.dead) {
      s.certificate[1] = s.certificate[0];
      break;
    }
  CHECK(mentions(rejection(ps, bad), "certificate"));

  PointSet flat = test::family3("coplanar3", 40, 1);
  CHECK(rejection(flat, ref::initial_stars(ps)) == dimension_problem(flat));
  PointSet two_d = ps;
  two_d.dim = 2;
  CHECK(mentions(rejection(two_d, good), "expected 3D"));
}

TEST_CASE("splay: the lexicographic precondition is checked, and it matters", "[splay]") {
  // Two clusters far apart along x: A = points 0..19, B = points 20..39.
  PointSet ps = test::family3("ball", 20, 3);
  const PointSet b = test::family3("ball", 20, 4);
  for (std::size_t i = 0; i < b.size(); ++i)
    ps.coords.insert(ps.coords.end(), {b.point(i)[0] + 10, b.point(i)[1], b.point(i)[2]});
  std::vector<Index> ia(20), ib(20);
  std::iota(ia.begin(), ia.end(), Index{0});
  std::iota(ib.begin(), ib.end(), Index{20});
  // Each cluster's own hull (brute force on the cluster, indices kept).
  auto hull_of = [&](const std::vector<Index>& idx) {
    PointSet sub;
    sub.dim = 3;
    for (Index i : idx) test::add_point(sub, ps.point(i));
    auto tris = brute::hull3(sub);
    for (auto& t : tris)
      for (auto& v : t) v = idx[v];
    return tris;
  };
  const auto ha = hull_of(ia), hb = hull_of(ib);
  std::vector<ref::Star> stars = stars_of_polytope(ha);
  const auto sb = stars_of_polytope(hb);
  stars.insert(stars.end(), sb.begin(), sb.end());
  // the points inside each cluster's hull: dead, certificate from the splaying of a valid star
  std::set<Index> have;
  for (const auto& s : stars) have.insert(s.apex);
  const auto valid = ref::initial_stars(ps);
  for (const auto& s : valid)
    if (!have.count(s.apex)) {
      // a non-vertex of its cluster's hull: declare it dead by a certificate
      // from its cluster (brute force search over tetrahedra)
      const auto& idx = s.apex < 20 ? ia : ib;
      ref::Star d;
      d.apex = s.apex;
      d.dead = true;
      bool found = false;
      for (std::size_t i = 0; i < idx.size() && !found; ++i)
        for (std::size_t j = i + 1; j < idx.size() && !found; ++j)
          for (std::size_t k = j + 1; k < idx.size() && !found; ++k)
            for (std::size_t l = k + 1; l < idx.size() && !found; ++l) {
              d.certificate = {idx[i], idx[j], idx[k], idx[l]};
              found = ref::is_death_certificate(ps, s.apex, d.certificate);
            }
      REQUIRE(found);
      stars.push_back(d);
    }
  REQUIRE(stars.size() == ps.size());
  // B's least point has a star whose cone holds only points after it.
  const std::string msg = rejection(ps, stars);
  INFO(msg);
  REQUIRE(mentions(msg, "lexicographic precondition"));
  // Without the check the stars are already consistent: splaying changes
  // nothing and ends at two polytopes, not at the hull.
  auto st = ref::splay::make_state(ps, stars, /*validate=*/false);
  ref::splay::run(st);
  auto two = ha;
  two.insert(two.end(), hb.begin(), hb.end());
  REQUIRE(ref::splay::triangles(st) == canonical_triangles(two));
  REQUIRE(ref::splay::triangles(st) != brute::hull3(ps));
  // With the pipeline's stars the same points give the hull.
  REQUIRE(ref::star_splaying(ps, valid) == brute::hull3(ps));
}

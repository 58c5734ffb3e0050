// twist_flip_precondition_test.cpp — twist-flip's input (thesis §8.4.1: a
// coherently oriented polyhedron, i.e. a closed triangulated sphere, whose
// topmost vertex v is joined to all other vertices) is checked, and anything
// else is rejected with one line (reference/hull3/twist_flip.hpp); the
// generator of special inputs (twist_flip_input.hpp) builds only valid ones.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "predicates/predicates.hpp"
#include "proptests/support/twist_flip_inputs.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/twist_flip.hpp"
#include "reference/hull3/twist_flip_input.hpp"

using namespace flipflop;

namespace {

// The message of the std::invalid_argument thrown by f, or "" when none is.
template <typename F>
std::string rejection(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool one_line(const std::string& m) { return !m.empty() && m.find('\n') == std::string::npos; }

std::string rejects(const PointSet& ps, const std::vector<Triangle>& tris, Index v) {
  return rejection([&] { ref::twist_flip(ps, tris, v); });
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// swap a and b in every triangle (§8.2: a twist when ab is an edge)
std::vector<Triangle> swapped(std::vector<Triangle> tris, Index a, Index b) {
  for (Triangle& t : tris)
    for (Index& x : t) x = x == a ? b : x == b ? a : x;
  return tris;
}

PointSet ball(std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  return gen::generate("ball", n, o);
}

}  // namespace

TEST_CASE("twist_flip input: special polyhedra are valid inputs", "[twist_flip]") {
  rc::prop("special_polyhedron: v topmost, joined to all, closed oriented sphere", [] {
    const PointSet ps = *test::degenerate_points(3, 4, 40, false);
    RC_PRE(ps.size() >= 4);
    const ref::SpecialInputOptions o = *test::special_options();
    const std::vector<Triangle> tris = ref::special_polyhedron(ps, o);
    const Index v = ref::topmost_point(ps);
    // topmost by the SoS comparison, independently of the generator
    for (Index p = 0; p < ps.size(); ++p)
      if (p != v) RC_ASSERT(pred::compare_sos({v, ps.point(v)}, {p, ps.point(p)}, 2) > 0);
    // Euler: a sphere over n vertices has 2n - 4 triangles
    RC_ASSERT(tris.size() == 2 * ps.size() - 4);
    std::set<std::pair<Index, Index>> e;
    std::set<Index> nbr;
    for (const Triangle& t : tris)
      for (int k = 0; k < 3; ++k) {
        RC_ASSERT(e.insert({t[k], t[(k + 1) % 3]}).second);
        if (t[k] == v) nbr.insert(t[(k + 1) % 3]);
      }
    for (const auto& [a, b] : e) RC_ASSERT(e.count({b, a}) == 1u);
    RC_ASSERT(nbr.size() == ps.size() - 1);
    // accepted unless the vertices are coplanar
    const std::string m = rejects(ps, tris, v);
    if (dimension_problem(ps).empty()) {
      RC_ASSERT(m.empty());
    } else {
      RC_ASSERT(one_line(m));
      RC_ASSERT(contains(m, "coplanar") || contains(m, "collinear"));
    }
  });
}

TEST_CASE("twist_flip rejects what is not a closed coherently oriented sphere", "[twist_flip]") {
  const PointSet ps = ball(12, 5);
  const Index v = ref::topmost_point(ps);
  const std::vector<Triangle> good = ref::special_polyhedron(ps, {});
  REQUIRE(rejects(ps, good, v).empty());

  SECTION("2D points") {
    PointSet flat;
    flat.dim = 2;
    flat.coords = {0, 0, 1, 0, 0, 1, 1, 1};
    const std::string m = rejects(flat, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}, 0);
    CHECK(one_line(m));
    CHECK(contains(m, "3D"));
  }
  SECTION("too few triangles") {
    const std::string m = rejects(ps, {good[0], good[1], good[2]}, v);
    CHECK(one_line(m));
    CHECK(contains(m, "at least 4 triangles"));
  }
  SECTION("index out of range") {
    auto bad = good;
    bad[3][1] = 99;
    const std::string m = rejects(ps, bad, v);
    CHECK(one_line(m));
    CHECK(contains(m, "out of range"));
  }
  SECTION("a triangle repeating a vertex") {
    auto bad = good;
    bad[4][2] = bad[4][0];
    const std::string m = rejects(ps, bad, v);
    CHECK(one_line(m));
    CHECK(contains(m, "repeats a vertex"));
  }
  SECTION("a triangle twice") {
    auto bad = good;
    bad.push_back(good[5]);
    const std::string m = rejects(ps, bad, v);
    CHECK(one_line(m));
    CHECK(contains(m, "in two triangles"));
  }
  SECTION("one triangle reversed: not coherently oriented") {
    for (std::size_t i = 0; i < good.size(); ++i) {
      auto bad = good;
      std::swap(bad[i][1], bad[i][2]);
      const std::string m = rejects(ps, bad, v);
      CHECK(one_line(m));
      CHECK((contains(m, "in two triangles") || contains(m, "not closed")));
    }
  }
  SECTION("a triangle missing: not closed") {
    for (std::size_t i = 0; i < good.size(); ++i) {
      auto bad = good;
      bad.erase(bad.begin() + static_cast<std::ptrdiff_t>(i));
      const std::string m = rejects(ps, bad, v);
      CHECK(one_line(m));
      CHECK(contains(m, "not closed"));
    }
  }
  SECTION("two spheres: not connected") {
    auto two = good;
    const PointSet big = ball(24, 6);
    // a second tetrahedron over points 12..15, disjoint from the first sphere
    PointSet both = ps;
    both.coords.insert(both.coords.end(), big.coords.begin(), big.coords.begin() + 12);
    for (Triangle t : std::vector<Triangle>{{12, 13, 14}, {12, 14, 15}, {12, 15, 13}, {13, 15, 14}}) two.push_back(t);
    const std::string m = rejects(both, two, ref::topmost_point(both));
    CHECK(one_line(m));
    CHECK(contains(m, "not connected"));
  }
  SECTION("a torus (the 7-vertex torus: every vertex joined to all others)") {
    const PointSet seven = ball(7, 8);
    std::vector<Triangle> torus;
    for (Index i = 0; i < 7; ++i) {
      torus.push_back({i, (i + 1) % 7, (i + 3) % 7});
      torus.push_back({i, (i + 3) % 7, (i + 2) % 7});
    }
    const std::string m = rejects(seven, torus, ref::topmost_point(seven));
    CHECK(one_line(m));
    CHECK(contains(m, "not a sphere"));
  }
}

TEST_CASE("twist_flip rejects a vertex v that is not topmost or not joined to all", "[twist_flip]") {
  const PointSet ps = ball(15, 9);
  const Index v = ref::topmost_point(ps);
  const std::vector<Triangle> good = ref::special_polyhedron(ps, {});
  SECTION("v not a vertex") {
    PointSet more = ps;
    more.coords.insert(more.coords.end(), {0.5, 0.5, 9.0});  // above everything, not on the surface
    const std::string m = rejects(more, good, 15);
    CHECK(one_line(m));
    CHECK(contains(m, "not a vertex"));
  }
  SECTION("twisting v with a neighbour: v is no longer joined to all, its neighbour is not topmost") {
    for (const Triangle& t : good) {
      if (t[0] != v) continue;
      const Index p = t[1];
      const auto bad = swapped(good, v, p);
      const std::string mv = rejects(ps, bad, v);
      CHECK(one_line(mv));
      CHECK(contains(mv, "not to all"));
      const std::string mp = rejects(ps, bad, p);
      CHECK(one_line(mp));
      CHECK(contains(mp, "not the topmost"));
    }
  }
  SECTION("an octahedron: no vertex is joined to all") {
    PointSet oct;
    oct.dim = 3;
    oct.coords = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    // counter-clockwise seen from outside: (+x, +y, +z) ...
    const std::vector<Triangle> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                     {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    REQUIRE(ref::topmost_point(oct) == 4);
    const std::string m = rejects(oct, t, 4);
    CHECK(one_line(m));
    CHECK(contains(m, "not to all"));
  }
  SECTION("coplanar vertices") {
    PointSet flat = ps;
    for (std::size_t i = 0; i < flat.size(); ++i) flat.coords[3 * i + 2] = 0.25;
    const std::string m = rejects(flat, ref::special_polyhedron(flat, {}), ref::topmost_point(flat));
    CHECK(one_line(m));
    CHECK(contains(m, "coplanar"));
  }
  SECTION("either orientation is accepted") {
    ref::SpecialInputOptions o;
    o.reversed = true;
    CHECK(rejects(ps, ref::special_polyhedron(ps, o), v).empty());
    CHECK(rejects(ps, good, v).empty());
  }
}

TEST_CASE("twist_flip: the stages run once, twisting first", "[twist_flip]") {
  const PointSet ps = ball(10, 3);
  ref::TwistFlip tf(ps, ref::special_polyhedron(ps, {}), ref::topmost_point(ps));
  CHECK_THROWS_AS(tf.flipping_stage(), std::logic_error);
  tf.twisting_stage();
  CHECK_THROWS_AS(tf.twisting_stage(), std::logic_error);
  tf.flipping_stage();
  CHECK_THROWS_AS(tf.flipping_stage(), std::logic_error);
}

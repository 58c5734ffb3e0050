// ffhull_reference_test.cpp — flip-flop for 3D convex hull (thesis §6.1-6.3,
// Algorithm 6, reference/hull3/flip_flop_3d.hpp) and ffHull (§6.4, Algorithm
// 7, reference/hull3/ffhull.hpp).
//
// Oracles, all independent of the code under test:
//   brute::hull3      the canonical SoS hull by enumeration (small n);
//   certify::hull3    exact certification at Level::canonical (any n);
//   peers::cgal_hull3 CGAL's convex_hull_3 on random inputs in general position;
//   hand-built input  Figure 6.1's stuck polyhedron with exact coordinates, an
//                     exact self-intersection witness (support/ffhull_inputs.hpp);
//   other surfaces    star-shaped polyhedra built by random insertion orders
//                     and by central projection (CGAL), checked star-shaped
//                     exactly before use.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>

#include "gen/generate.hpp"
#include "peers/peers.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/ffhull_inputs.hpp"
#include "proptests/support/predicate_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/rational_kernel.hpp"

using namespace flipflop;
using certify::Level;
using test::spans3;

namespace {

const std::vector<std::string>& families3() {
  static const std::vector<std::string> f = test::families(3);
  return f;
}

PointSet family(const std::string& f, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  return gen::generate(f, n, o);
}

std::string certified(const PointSet& ps, const std::vector<Triangle>& out) {
  return certify::hull3(ps, out, Level::canonical).message();
}

}  // namespace

// ---- (a), (b): ffHull against brute force, the certifier and CGAL ------------

TEST_CASE("ffhull: every 3D family equals brute force on small inputs", "[ffhull]") {
  std::size_t cases = 0;
  for (const std::string& f : families3())
    for (std::size_t n : {4, 5, 6, 8, 12, 20, 30})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const PointSet ps = family(f, n, seed);
        if (!spans3(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        ref::Hull3Stats st;
        const auto out = ref::hull3_ffhull(ps, &st);
        REQUIRE(certified(ps, out) == "certified");
        REQUIRE(out == brute::hull3(ps));
        // every input point is inserted, discarded early or one of the four
        // initial points; insertions are 1-3 flips; each 3-1 flip removes a
        // vertex, so the hull has 4 + insertions - flips_3_1 vertices
        REQUIRE(st.insertions == st.flips_1_3);
        REQUIRE(st.insertions + st.discarded_early + 4 == ps.size());
        const std::vector<Index> V = test::vertex_set(out);
        REQUIRE(4 + st.insertions - st.flips_3_1 == V.size());
        // Algorithm 7 line 1: the initial tetrahedron consists of extreme
        // points (of the SoS hull), affinely independent exactly
        const auto tet = ref::ffhull::initial_tetrahedron(ps);
        for (Index v : tet) REQUIRE(std::binary_search(V.begin(), V.end(), v));
        REQUIRE(pred::orient3d_exact(ps.point(tet[0]), ps.point(tet[1]), ps.point(tet[2]), ps.point(tet[3])) > 0);
        ++cases;
      }
  std::cout << "ffhull families vs brute force: " << cases << " inputs\n";
  REQUIRE(cases > 150);
}

TEST_CASE("ffhull: random small inputs of every kind equal brute force (shrinking)", "[ffhull]") {
  test::prop_scaled("degenerate and random sets of 4..40 points: ffHull == brute::hull3, certified", 10, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 40, false);
    RC_PRE(spans3(ps));
    const auto out = ref::hull3_ffhull(ps);
    RC_ASSERT(out == brute::hull3(ps));
    const std::vector<Index> V = test::vertex_set(out);
    for (Index v : ref::ffhull::initial_tetrahedron(ps)) RC_ASSERT(std::binary_search(V.begin(), V.end(), v));
  });
}

TEST_CASE("ffhull: identical to CGAL convex_hull_3 on random inputs in general position", "[ffhull]") {
  // cube / ball / sphere / box of random doubles: in general position with
  // probability 1, where CGAL's exact answer is the unique hull
  test::prop_scaled("random cube/ball/sphere/box sets: ffHull == CGAL, certified", 10, [] {
    const std::string f = *rc::gen::element<std::string>("cube", "ball", "sphere", "box");
    const int n = *rc::gen::inRange(4, 400);
    const PointSet ps = family(f, static_cast<std::size_t>(n), *test::any_seed());
    const auto out = ref::hull3_ffhull(ps);
    RC_ASSERT(out == peers::cgal_hull3(ps));
  });
  for (const std::string f : {"cube", "ball", "sphere", "box", "cball"}) {
    const PointSet ps = family(f, 5000, 7);
    INFO(f);
    const auto out = ref::hull3_ffhull(ps);
    REQUIRE(out == peers::cgal_hull3(ps));
    REQUIRE(certified(ps, out) == "certified");
  }
}

TEST_CASE("ffhull: larger inputs of every family are certified", "[ffhull]") {
  for (const std::string& f : families3())
    for (std::size_t n : {300, 3000}) {
      const PointSet ps = family(f, n, 11);
      if (!spans3(ps)) continue;
      INFO(f << " n=" << n);
      const auto out = ref::hull3_ffhull(ps);
      REQUIRE(certified(ps, out) == "certified");
    }
  // 10^5 points, once (ball: the thesis' experiment; sphere: most flips)
  for (const std::string f : {"ball", "sphere"}) {
    const PointSet ps = family(f, 100000, 3);
    INFO(f << " n=100000");
    ref::Hull3Stats st;
    const auto out = ref::hull3_ffhull(ps, &st);
    REQUIRE(certified(ps, out) == "certified");
    REQUIRE(out == peers::cgal_hull3(ps));
  }
}

// ---- (c): Figure 6.1 ------------------------------------------------------------

TEST_CASE("ffhull: Figure 6.1 stuck for hill-climbing is solved by flip-flop", "[ffhull]") {
  const test::Figure61 fig = test::figure_6_1();
  const PointSet& ps = fig.ps;
  const double* kp[1] = {fig.kernel};
  const ref::RationalKernel s(ps, pred::RationalPoint::centroid(kp, 1, 3));
  // the polyhedron is star-shaped w.r.t. s and does not intersect itself
  REQUIRE(ref::is_star_shaped(ps, fig.surface, s));
  REQUIRE_FALSE(test::self_intersects(ps, fig.surface));
  // d, e, f are not extreme: the hull is the tetrahedron gabc
  const auto hull = brute::hull3(ps);
  REQUIRE(test::vertex_set(hull) == std::vector<Index>{0, 1, 2, 6});
  // every reflex edge (w.r.t. s: the opposite vertex of the other triangle
  // beyond the plane of the first) is stuck: its 2-2 flip makes the surface
  // intersect itself
  int reflex = 0;
  for (std::size_t i = 0; i < fig.surface.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = fig.surface[i];
      const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      if (a > b) continue;
      std::size_t j = 0;
      Index d = 0;
      for (; j < fig.surface.size(); ++j) {
        const Triangle& o = fig.surface[j];
        bool found = false;
        for (int m = 0; m < 3; ++m)
          if (o[m] == b && o[(m + 1) % 3] == a) d = o[(m + 2) % 3], found = true;
        if (found) break;
      }
      REQUIRE(j < fig.surface.size());
      if (pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d)) >= 0) continue;
      ++reflex;
      std::vector<Triangle> flipped;
      for (std::size_t m = 0; m < fig.surface.size(); ++m)
        if (m != i && m != j) flipped.push_back(fig.surface[m]);
      flipped.push_back({a, d, c});
      flipped.push_back({d, b, c});
      INFO("reflex edge " << a << " " << b);
      REQUIRE(test::self_intersects(ps, flipped));
      REQUIRE_FALSE(ref::is_star_shaped(ps, flipped, s));
    }
  REQUIRE(reflex >= 3);
  // flip-flop: labels the twisted vertices non-extreme (Lemma 6.5), removes them
  ref::Hull3Stats st;
  const auto out = ref::flip_flop_3d(ps, fig.surface, s, &st);
  REQUIRE(out == hull);
  REQUIRE(st.flips_3_1 == 3);
  REQUIRE(st.labelled_non_extreme >= 1);
  REQUIRE(certified(ps, out) == "certified");
}

// ---- (d): many star-shaped polyhedra of one point set, one hull ------------------

TEST_CASE("ffhull: flip-flop from many different star-shaped polyhedra reaches the same hull", "[ffhull]") {
  std::size_t runs = 0, projected = 0;
  for (const std::string& f : families3())
    for (std::size_t n : {6, 12, 30, 80})
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const PointSet ps = family(f, n, seed);
        if (!spans3(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        const auto expect = n <= 30 ? brute::hull3(ps) : ref::hull3_ffhull(ps);
        if (n > 30) REQUIRE(certified(ps, expect) == "certified");
        const ref::RationalKernel s = test::ffhull_kernel(ps);
        for (std::uint64_t k = 0; k < 4; ++k) {
          // random insertion orders; with discard_inside == false every point
          // becomes a vertex (dents), the hardest start
          const bool furthest = k == 0, discard = k == 1;
          const auto surface = test::random_star_polyhedron(ps, s, furthest, discard, seed * 10 + k);
          REQUIRE(ref::is_star_shaped(ps, surface, s));
          ref::Hull3Stats st;
          REQUIRE(ref::flip_flop_3d(ps, surface, s, &st) == expect);
          ++runs;
        }
        // central projection (CGAL on projected points), when exactly star-shaped
        const auto tet = ref::ffhull::initial_tetrahedron(ps);
        double c[3];
        for (int j = 0; j < 3; ++j)
          c[j] = (ps.point(tet[0])[j] + ps.point(tet[1])[j] + ps.point(tet[2])[j] + ps.point(tet[3])[j]) / 4;
        std::vector<Triangle> surface;
        try {
          surface = test::central_projection_surface(ps, c);
        } catch (const std::runtime_error&) {
          continue;  // the projected points are flat in floating point
        }
        if (!ref::is_star_shaped(ps, surface, s)) continue;
        REQUIRE(ref::flip_flop_3d(ps, surface, s) == test::brute_hull_of_vertices(ps, surface));
        ++projected;
      }
  std::cout << "ffhull: " << runs << " flip-flop runs from random star-shaped polyhedra, " << projected
            << " from central projections\n";
  REQUIRE(runs > 300);
  REQUIRE(projected > 50);
}

// ---- (g) and API errors ---------------------------------------------------------------

TEST_CASE("ffhull: lower-dimensional inputs are rejected with the dimension in the message", "[ffhull]") {
  auto expect_rejected = [](const PointSet& ps, const std::string& word) {
    INFO(word);
    const std::string why = dimension_problem(ps);
    REQUIRE_FALSE(why.empty());
    REQUIRE(why.find(word) != std::string::npos);
    try {
      ref::hull3_ffhull(ps);
      FAIL("accepted a lower-dimensional input");
    } catch (const std::invalid_argument& e) {
      REQUIRE(std::string(e.what()) == why);
    }
  };
  expect_rejected(family("collinear3", 50, 1), "collinear");
  expect_rejected(family("coplanar3", 50, 1), "coplanar");
  PointSet same;
  same.dim = 3;
  for (int i = 0; i < 6; ++i) same.coords.insert(same.coords.end(), {0.25, -3.0, 7.0});
  expect_rejected(same, "equal");
  PointSet three;
  three.dim = 3;
  three.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  expect_rejected(three, "needed");
  PointSet none;
  none.dim = 3;
  expect_rejected(none, "needed");
  rc::prop("flat small-integer sets are rejected", [] {
    const int n = *rc::gen::inRange(1, 30);
    const int kind = *rc::gen::inRange(0, 3);  // 0 equal, 1 collinear, 2 coplanar
    PointSet ps;
    ps.dim = 3;
    for (int i = 0; i < n; ++i) {
      const double s = *rc::gen::inRange(-9, 10), t = *rc::gen::inRange(-9, 10);
      const double p[3] = {kind >= 1 ? s : 1.0, kind >= 2 ? t : 2.0, kind >= 1 ? 3 * s - (kind >= 2 ? t : 0) : 3.0};
      ps.coords.insert(ps.coords.end(), p, p + 3);
    }
    RC_PRE(!spans3(ps));
    try {
      ref::hull3_ffhull(ps);
      RC_FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(std::string(e.what()) == dimension_problem(ps));
    }
  });
  PointSet two_d;
  two_d.dim = 2;
  two_d.coords = {0, 0, 1, 0, 0, 1, 1, 1};
  REQUIRE_THROWS_AS(ref::hull3_ffhull(two_d), std::invalid_argument);
}

TEST_CASE("ffhull: flip_flop_3d rejects surfaces that are not star-shaped spheres", "[ffhull]") {
  const PointSet ps = family("ball", 40, 5);
  const ref::RationalKernel s = test::ffhull_kernel(ps);
  const auto good = ref::hull3_ffhull(ps);
  REQUIRE(ref::is_star_shaped(ps, good, s));
  auto message = [&](const std::vector<Triangle>& surface) -> std::string {
    try {
      ref::flip_flop_3d(ps, surface, s);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  auto hole = good;
  hole.pop_back();
  REQUIRE(message(hole).find("hole") != std::string::npos);
  auto flipped = good;
  std::swap(flipped[0][1], flipped[0][2]);
  REQUIRE(message(flipped).find("directed edge") != std::string::npos);
  auto out_of_range = good;
  out_of_range[0][0] = 1000;
  REQUIRE(message(out_of_range).find("index") != std::string::npos);
  // two tetrahedra: not connected
  std::vector<Triangle> two = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}, {4, 5, 6}, {4, 6, 7}, {4, 7, 5}, {5, 7, 6}};
  REQUIRE(message(two).find("connected") != std::string::npos);
  // the whole hull turned inside out: a sphere, not star-shaped w.r.t. s
  auto inverted = good;
  for (Triangle& t : inverted) std::swap(t[1], t[2]);
  REQUIRE_FALSE(ref::is_star_shaped(ps, inverted, s));
  REQUIRE(message(inverted).find("star-shaped") != std::string::npos);
  // a tetrahedron whose kernel does not contain s
  const auto tet = ref::ffhull::initial_tetrahedron(ps);
  REQUIRE(ref::is_star_shaped(ps, {{tet[0], tet[1], tet[2]}, {tet[0], tet[2], tet[3]}, {tet[0], tet[3], tet[1]},
                                   {tet[1], tet[3], tet[2]}},
                              s));
  REQUIRE_THROWS_AS(ref::centroid_kernel(family("coplanar3", 10, 1), 0, 1, 2, 3), std::invalid_argument);
}

// ---- the kernel point's per-input bound (rational_kernel.cpp) ----------------------
// RationalKernel::side() decides by a static bound before the exact mixed
// predicate. Inputs at that bound's edge: planes (a, b, c) through or within
// a few ulps of s (c the point reflection 2s - a rounded, b anything), at unit,
// 1e±300 and subnormal magnitudes, and sets whose largest magnitude M is
// reached by a point other than a, b, c. Every sign must be GMP's.
TEST_CASE("ffhull: the kernel point's static bound gives the GMP sign near and on its planes", "[ffhull]") {
  rc::prop("side() equals mixed_sign in GMP", [] {
    // coordinates up to M = 2^scale in magnitude; the kernel's sources near
    // alternate corners of the cube [-M, M]^3, so the query differences reach
    // 2M as the bound assumes
    const int scale = *rc::gen::element(0, -1070, -600, -300, 300, 500, 1020);
    const double M = std::ldexp(1.0, scale);
    auto corner = [&](double sign) { return sign * M * (0.75 + 0.25 * std::fabs(test::gen_unit())); };
    PointSet ps;
    ps.dim = 3;
    const double signs[12] = {-1, -1, -1, 1, 1, -1, 1, -1, 1, -1, 1, 1};
    for (double sg : signs) ps.coords.push_back(corner(sg));
    const std::size_t n = 4 + static_cast<std::size_t>(*rc::gen::inRange(3, 12));
    for (std::size_t i = 4; i < n; ++i)
      for (int j = 0; j < 3; ++j) ps.coords.push_back(M * test::gen_unit());
    if (scale < 1000 && *rc::gen::weightedElement<int>({{4, 0}, {1, 1}}))  // the largest magnitude elsewhere
      ps.coords.insert(ps.coords.end(), {std::ldexp(1.0, scale + 20), 0.0, 0.0});
    const double* src[4] = {ps.point(0), ps.point(1), ps.point(2), ps.point(3)};
    RC_PRE(pred::orient3d_exact(src[0], src[1], src[2], src[3]) != 0);
    const ref::RationalKernel s(ps, pred::RationalPoint::centroid(src, 4, 3));
    // c = 2s - a (rounded, nudged) for four a: the planes (a, b, c) pass within
    // ulps of s; then every b, and for contrast one ordinary triple per a
    const std::size_t m = ps.size();
    std::array<Index, 4> as{};
    for (Index& a : as) {
      a = static_cast<Index>(*rc::gen::inRange<std::size_t>(0, m));
      for (int j = 0; j < 3; ++j) ps.coords.push_back(test::gen_nudged(2.0 * s.point().approx[j].v - ps.point(a)[j]));
    }
    for (double v : ps.coords) RC_PRE(std::isfinite(v));
    const ref::RationalKernel s2(ps, s.point());  // the same point, SoS index after the c's
    auto check = [&](Index a, Index b, Index c) {
      const pred::MixedRow rows[4] = {{a, ps.point(a), nullptr}, {b, ps.point(b), nullptr},
                                      {c, ps.point(c), nullptr}, {s2.id(), nullptr, &s2.point()}};
      RC_ASSERT(s2.side(a, b, c) == pred::mixed_sign(4, rows, true, pred::Mode::gmp));
    };
    for (std::size_t k = 0; k < as.size(); ++k) {
      const Index a = as[k], c = static_cast<Index>(m + k);
      for (Index b = 0; b < static_cast<Index>(m); ++b)
        if (b != a) check(a, b, c);
      if ((a + 1) % m != (a + 2) % m) check(a, static_cast<Index>((a + 1) % m), static_cast<Index>((a + 2) % m));
    }
  });
}

// ---- measurements (hidden: run with the tag [.bench]) ------------------------------

TEST_CASE("ffhull bench: flip counts on the thesis distributions and time on the ball", "[.bench][long]") {
  // §6.5: cube, ball (radius 0.5), box and sphere of thickness 0.01
  for (const std::string f : {"cube", "ball", "box", "sphere"}) {
    const PointSet ps = family(f, 100000, 1);
    ref::Hull3Stats st;
    const auto t0 = std::chrono::steady_clock::now();
    const auto out = ref::hull3_ffhull(ps, &st);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << f << " n=100000: hull vertices " << test::vertex_set(out).size() << ", insertions " << st.insertions
              << ", discarded early " << st.discarded_early << ", flips 2-2 " << st.flips_2_2 << ", flips 3-1 "
              << st.flips_3_1 << ", labelled non-extreme " << st.labelled_non_extreme << ", time " << sec << " s\n";
    REQUIRE(certified(ps, out) == "certified");
  }
  const PointSet ball = family("ball", 100000, 1);
  std::vector<double> t;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto out = ref::hull3_ffhull(ball);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    REQUIRE(out.size() > 4);
  }
  std::sort(t.begin(), t.end());
  std::cout << "ball n=100000: hull3_ffhull median of 3: " << t[1] << " s\n";
}

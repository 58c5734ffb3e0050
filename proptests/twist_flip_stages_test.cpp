// twist_flip_stages_test.cpp — the two stages of twist-flip (thesis §8.4.1,
// Algorithms 12 and 13; reference/hull3/twist_flip.hpp) and its kernel point.
//
// Oracles, independent of the code under test:
//   CGAL's exact kernel (proptests/support/twist_flip_oracles.hpp) on inputs
//     in general position: the link projected onto H is a simple polygon
//     turning counter-clockwise around s (Lemma 8.3); the number of twists is
//     the number of inversions of the angular order around s (Theorem 8.1:
//     bubble sort); every triangle of the result is positive and the ray from
//     the kernel point crosses exactly one triangle (Theorem 8.2 => star-
//     shaped, Theorem 8.9); TwistFlipKernel::side is the sign at a concrete
//     rational point v + t (s - v), t = 2^-100;
//   is_star_shaped of flip_flop_3d.hpp (another implementation: orientation
//     and winding around every vertex, polyhedron3.hpp) on degenerate input,
//     where only the Simulation of Simplicity decides;
//   structure: the result is a closed oriented surface over the same
//     vertices; fold flips never touch star(v) or link(v).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

#include "predicates/predicates.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/twist_flip_inputs.hpp"
#include "proptests/support/twist_flip_oracles.hpp"
#include "gen/generate.hpp"
#include "reference/canonical.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/twist_flip.hpp"
#include "reference/hull3/twist_flip_input.hpp"

using namespace flipflop;
using ref::FoldFlip;
using ref::Hull3Stats;
using ref::TwistFlip;
namespace tf = flipflop::test::tf;

namespace {

std::set<Triangle> through(const std::vector<Triangle>& tris, Index v) {
  std::set<Triangle> out;
  for (const Triangle& t : tris)
    if (t[0] == v || t[1] == v || t[2] == v) out.insert(canonical_rotation(t));
  return out;
}

std::set<Index> vertices(const std::vector<Triangle>& tris) {
  std::set<Index> out;
  for (const Triangle& t : tris) out.insert(t.begin(), t.end());
  return out;
}

// closed and coherently oriented: every directed edge once, its reverse present
bool closed_oriented(const std::vector<Triangle>& tris) {
  std::set<std::pair<Index, Index>> e;
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k)
      if (!e.insert({t[k], t[(k + 1) % 3]}).second) return false;
  for (const auto& [a, b] : e)
    if (!e.count({b, a})) return false;
  return true;
}

bool is_link_edge(const std::vector<Index>& order, Index a, Index b) {
  const std::size_t k = order.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Index p = order[i], q = order[(i + 1) % k];
    if ((p == a && q == b) || (p == b && q == a)) return true;
  }
  return false;
}

// Both stages on a special polyhedron over ps, every claim checked with CGAL;
// discards (RC_PRE) exact ties, on which the CGAL oracles claim nothing.
// Returns whether s was the point straight below v (choice (1) of
// twist_flip.hpp).
bool check_stages(const PointSet& ps, const ref::SpecialInputOptions& o) {
  const std::vector<Triangle> input = ref::special_polyhedron(ps, o);
  const Index v = ref::topmost_point(ps);
  TwistFlip tf(ps, input, v);
  const tf::P3 s = tf::secondary_point(tf.kernel().secondary());
  const tf::P3 pv = tf::point3(ps, v);

  // Theorem 8.1: the twisting stage is a bubble sort of the link, from its
  // first slot, by the angle around s in H: #twists = #inversions
  bool g1 = false, g2 = false;
  const auto start = tf::projected_link(ps, tf.order(), v, s, g1);
  RC_PRE(g1);
  const std::size_t inversions = tf::angular_inversions(start, s, g2);
  RC_PRE(g2);
  Hull3Stats st;
  tf.twisting_stage(&st);
  RC_ASSERT(st.twists == inversions);
  // Lemma 8.3: star(v) star-shaped w.r.t. s, all of its triangles positive
  bool g3 = false;
  const auto link = tf::projected_link(ps, tf.order(), v, s, g3);
  RC_ASSERT(tf::link_star_shaped(link, s));
  const std::vector<Triangle> twisted = tf.triangles();
  RC_ASSERT(closed_oriented(twisted));
  RC_ASSERT(vertices(twisted) == vertices(input));

  // Algorithm 13
  std::vector<FoldFlip> log;
  tf.flipping_stage(&st, &log);
  RC_ASSERT(st.fold_flips == log.size());
  const std::vector<Triangle> out = tf.triangles();
  RC_ASSERT(out.size() == input.size());
  RC_ASSERT(closed_oriented(out));
  RC_ASSERT(vertices(out) == vertices(input));
  // fold flips never touch star(v) or link(v)
  RC_ASSERT(through(out, v) == through(twisted, v));
  for (const FoldFlip& f : log) {
    RC_ASSERT(f.a != v && f.b != v && f.c != v && f.d != v);
    RC_ASSERT(!is_link_edge(tf.order(), f.a, f.b));
  }
  // Theorem 8.9: every triangle positive; Theorem 8.2: star-shaped w.r.t. κ
  bool g4 = false, g5 = false;
  RC_ASSERT(tf::positive_all(ps, out, v, s, g4));
  RC_ASSERT(g4);
  RC_ASSERT(tf::ray_crossings(ps, out, v, s, g5) == 1u);
  RC_ASSERT(g5);
  RC_ASSERT(ref::is_star_shaped(ps, out, tf.kernel()));
  return s.x() == pv.x() && s.y() == pv.y();
}

}  // namespace

TEST_CASE("twist_flip oracles: CGAL orientation with flipflop's sign convention", "[twist_flip]") {
  rc::prop("shewchuk_orient == orient3d_exact", [] {
    double c[4][3];
    for (auto& p : c)
      for (double& x : p) x = static_cast<double>(*test::symmetric(6)) / 4;
    const tf::P3 a(c[0][0], c[0][1], c[0][2]), b(c[1][0], c[1][1], c[1][2]), d(c[2][0], c[2][1], c[2][2]),
        e(c[3][0], c[3][1], c[3][2]);
    RC_ASSERT(tf::shewchuk_orient(a, b, d, e) == pred::orient3d_exact(c[0], c[1], c[2], c[3]));
  });
}

TEST_CASE("twist_flip: stages on general position — Lemma 8.3, Theorem 8.1 count, Theorem 8.9 (CGAL)",
          "[twist_flip]") {
  test::prop_scaled("twisting then flipping", 4, [] {
    const PointSet ps = *test::twist_flip_general_points(4, 40);
    RC_PRE(ps.size() >= 4 && dimension_problem(ps).empty());
    check_stages(ps, *test::special_options());
  });
}

TEST_CASE("twist_flip: stages with s not below v ((a + b + c + c) / 4)", "[twist_flip]") {
  // v far to the side of the others: the vertical line through v misses
  // their hull, so s is the weighted centroid of three link vertices
  test::prop_scaled("v beside the others", 4, [] {
    PointSet ps = *test::twist_flip_general_points(3, 30);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      double* p = ps.coords.data() + 3 * i;
      p[2] = std::min(p[2], 0.5 * p[2]);  // keeps the order of z, all <= max(0, .)
    }
    const auto at = static_cast<std::ptrdiff_t>(*rc::gen::inRange<std::size_t>(0, ps.size() + 1));
    const double far = 4.0 * std::sqrt(test::squared_extent(ps)) + 1.0;
    ps.coords.insert(ps.coords.begin() + 3 * at, {far, far, far});
    RC_PRE(dimension_problem(ps).empty());
    RC_ASSERT(ref::topmost_point(ps) == static_cast<Index>(at));
    RC_ASSERT(!check_stages(ps, *test::special_options()));
  });
}

TEST_CASE("twist_flip: s straight below v (choice (1)) on ball points", "[twist_flip]") {
  // 20 fixed inputs, on each of which the vertical choice succeeds
  test::prop_scaled("ball, seeds 1..20", 20, [] {
    gen::Options g;
    g.seed = static_cast<std::uint64_t>(*rc::gen::inRange(1, 21));
    const PointSet ps = gen::generate("ball", 100, g);
    RC_ASSERT(check_stages(ps, *test::special_options()));
  });
}

TEST_CASE("twist_flip: degenerate input — positive, star-shaped w.r.t. the kernel (SoS)", "[twist_flip]") {
  test::prop_scaled("all families", 4, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 30, false);
    RC_PRE(ps.size() >= 4 && dimension_problem(ps).empty());
    const ref::SpecialInputOptions o = *test::special_options();
    const std::vector<Triangle> input = ref::special_polyhedron(ps, o);
    const Index v = ref::topmost_point(ps);
    Hull3Stats st;
    const std::vector<Triangle> out = ref::twist_flip(ps, input, v, &st);
    RC_ASSERT(closed_oriented(out));
    RC_ASSERT(vertices(out) == vertices(input));
    RC_ASSERT(out.size() == input.size());
    // the same kernel as twist_flip's (the same deterministic choice of s)
    const TwistFlip again(ps, input, v);
    const ref::TwistFlipKernel& kappa = again.kernel();
    for (const Triangle& t : out) RC_ASSERT(kappa.side(t[0], t[1], t[2]) > 0);
    RC_ASSERT(ref::is_star_shaped(ps, out, kappa));
    // positive in the thesis' sense, with the plain SoS predicates
    for (const Triangle& t : out)
      if (t[0] != v && t[1] != v && t[2] != v)
        RC_ASSERT(pred::orient3d({t[0], ps.point(t[0])}, {t[1], ps.point(t[1])}, {t[2], ps.point(t[2])},
                                 {v, ps.point(v)}) > 0);
  });
}

TEST_CASE("twist_flip: the kernel point is the limit of v + t (s - v) (CGAL, t = 2^-100)", "[twist_flip]") {
  // Integer coordinates |x| <= 2^20: orient3d(a, b, c, v) is an integer, so
  // at least 1 in magnitude when not 0, and |orient3d(a, b, c, s)| < 2^72 (s
  // is in the hull of the points); orient3d(a, b, c, ·) is affine, so at
  // v + t (s - v), t = 2^-100, it is (1 - t) orient3d(a, b, c, v) +
  // t orient3d(a, b, c, s): the sign of the limit.
  rc::prop("side(a, b, c) == sign orient3d(a, b, c, v + t (s - v))", [] {
    const PointSet ps = *test::wide_integers(3, 4, 12, false);
    RC_PRE(ps.size() >= 4 && dimension_problem(ps).empty());
    const std::vector<Triangle> input = ref::special_polyhedron(ps, *test::special_options());
    const Index v = ref::topmost_point(ps);
    const TwistFlip tw(ps, input, v);
    const ref::TwistFlipKernel& kappa = tw.kernel();
    const tf::P3 s = tf::secondary_point(kappa.secondary());
    const tf::P3 pv = tf::point3(ps, v);
    const tf::FT t = tf::FT(1) / tf::FT(std::ldexp(1.0, 100));
    const tf::P3 k(pv.x() + t * (s.x() - pv.x()), pv.y() + t * (s.y() - pv.y()), pv.z() + t * (s.z() - pv.z()));
    for (Index a = 0; a < ps.size(); ++a)
      for (Index b = 0; b < ps.size(); ++b)
        for (Index c = 0; c < ps.size(); ++c) {
          if (a == b || b == c || a == c) continue;
          const int limit = (a == v || b == v || c == v)
                                ? tf::shewchuk_orient(tf::point3(ps, a), tf::point3(ps, b), tf::point3(ps, c), s)
                                : tf::shewchuk_orient(tf::point3(ps, a), tf::point3(ps, b), tf::point3(ps, c), pv);
          if (limit == 0) continue;  // an exact tie: decided by SoS only
          RC_ASSERT(kappa.side(a, b, c) == tf::shewchuk_orient(tf::point3(ps, a), tf::point3(ps, b),
                                                               tf::point3(ps, c), k));
        }
  });
}

TEST_CASE("twist_flip: a convex link needs no fold flip", "[twist_flip]") {
  // v above a convex polygon in the plane z = 0 (the points (i, i^2, 0)):
  // H is parallel to that plane, so the projection from v is a homothety and
  // the projected link a convex polygon; every triangulation of a convex
  // polygon has only positive triangles, so after the twisting stage (link in
  // counter-clockwise order) there is no fold.
  rc::prop("fold_flips == 0, star-shaped", [] {
    const int m = *rc::gen::inRange(3, 30);
    std::vector<int> xs;
    for (int i = -m; i <= m; ++i) xs.push_back(i);
    std::mt19937_64 rng(*test::any_seed());
    std::shuffle(xs.begin(), xs.end(), rng);
    xs.resize(static_cast<std::size_t>(*rc::gen::inRange(3, static_cast<int>(xs.size()) + 1)));
    PointSet ps;
    ps.dim = 3;
    for (int x : xs) ps.coords.insert(ps.coords.end(), {double(x), double(x * x), 0.0});
    const auto at = static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(xs.size()) + 1));
    ps.coords.insert(ps.coords.begin() + static_cast<std::ptrdiff_t>(3 * at),
                     {double(*test::symmetric(50)), double(*test::symmetric(50)), 1.0 + double(*test::uniform(0, 9))});
    const Index v = ref::topmost_point(ps);
    RC_ASSERT(v == at);
    const std::vector<Triangle> input = ref::special_polyhedron(ps, *test::special_options());
    Hull3Stats st;
    const std::vector<Triangle> out = ref::twist_flip(ps, input, v, &st);
    RC_ASSERT(st.fold_flips == 0u);
    RC_ASSERT(closed_oriented(out));
    RC_ASSERT(ref::is_star_shaped(ps, out, TwistFlip(ps, input, v).kernel()));
  });
}

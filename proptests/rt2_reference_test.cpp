// rt2_reference_test.cpp — the 2D regular / Delaunay triangulation reference
// (reference/rt2/rt2.hpp: ffRT §5.3, flip-flop §5.1 Algorithm 5, Lawson §3.3.1).
//
// Oracles, all independent of the code under test:
//   brute::rt2            the canonical SoS answer by enumeration (n <= 40);
//   certify::rt2          exact certification at Level::canonical (any n);
//   peers::cgal_*         CGAL's Delaunay_triangulation_2 / Regular_triangulation_2
//                         on random inputs in general position;
//   hand-built inputs     Figure 3.3's stuck configuration; bad starting
//                         triangulations built here with orient2d alone.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>

#include "proptests/support/generated.hpp"
#include "proptests/support/planar_inputs.hpp"
#include "gen/generate.hpp"
#include "io/index_io.hpp"
#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/lawson_flip.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/triangulation2.hpp"

using namespace flipflop;
using certify::Level;
using ref::FlipFlopVariant;
using ref::Rt2Stats;


namespace {

using test::spans;

rc::Gen<PointSet> gen_planar(int nmin, int nmax, bool weighted) {
  return test::gen_small_points(2, nmin, nmax, weighted, 4);
}

// A generator family, or "collinear-one-off": collinear2 plus one point off the line.
PointSet family(const std::string& name, std::size_t n, std::uint64_t seed, bool weighted, double whi) {
  if (name != "collinear-one-off") return test::generated(name, n, seed, weighted, whi);
  PointSet ps = test::generated("collinear2", n - 1, seed, weighted, whi);
  // copies: push_back below may reallocate the coordinates
  const double p[2] = {ps.point(0)[0], ps.point(0)[1]};
  const double q[2] = {ps.point(n > 2 ? 1 : 0)[0], ps.point(n > 2 ? 1 : 0)[1]};
  ps.coords.push_back(p[0] + (q[1] - p[1]) + 1);  // off the line through p and q
  ps.coords.push_back(p[1] - (q[0] - p[0]) + 3);
  if (weighted) ps.weights.push_back(whi / 2);
  return ps;
}

// weight ranges that matter for each family (coordinates of very different scales)
double weight_scale(const std::string& name) {
  if (name == "huge2") return 1e300;
  if (name == "tiny2") return 1e-300;
  if (name == "grid2" || name == "jitter2" || name == "duplicates2") return name == "duplicates2" ? 0.01 : 2.0;
  if (name == "circle-lattice") return 1e20;
  if (name == "collinear-one-off") return 1e9;
  return 0.01;
}

// Families whose every predicate needs the exact stage (all ties, or values
// beyond the filter's range) get smaller brute-force sizes.
bool expensive(const std::string& name) {
  return name == "circle-lattice" || name == "huge2" || name == "tiny2";
}

const std::vector<std::string> kFamilies = {"square", "disk",        "frame",   "circle", "grid2",
                                            "circle-lattice", "duplicates2", "jitter2", "huge2",  "tiny2",
                                            "collinear-one-off"};

// The output contract: canonical form, certified, equal to the brute-force SoS answer.
void check_answer(const PointSet& ps, const std::vector<Triangle>& out, bool with_brute) {
  REQUIRE(io::canonical_triangles(out) == out);
  const certify::Report rep = certify::rt2(ps, out, Level::canonical);
  INFO(rep.message());
  REQUIRE(rep.ok);
  if (with_brute) REQUIRE(out == brute::rt2(ps));
}

// ---- starting triangulations built here, independently of the reference ----

int orient(const PointSet& ps, Index a, Index b, Index c) {
  return pred::orient2d({a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)});
}

// The fan of the (SoS) convex hull from its first vertex: a triangulation of
// conv(S) whose vertices are the extreme points.
std::vector<Triangle> hull_fan(const PointSet& ps) {
  const std::vector<Index> h = brute::hull2(ps);
  std::vector<Triangle> t;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) t.push_back({h[0], h[i], h[i + 1]});
  return t;
}

// Insert the points of `order` one by one into the triangle containing them
// (1-3 split, no flips; located by scanning): a valid, typically very bad
// triangulation.
std::vector<Triangle> insert_without_flips(const PointSet& ps, std::vector<Triangle> t,
                                           const std::vector<Index>& order) {
  for (Index p : order) {
    std::size_t k = 0;
    while (k < t.size() && !(orient(ps, t[k][0], t[k][1], p) > 0 && orient(ps, t[k][1], t[k][2], p) > 0 &&
                             orient(ps, t[k][2], t[k][0], p) > 0))
      ++k;
    REQUIRE(k < t.size());  // every point of S lies in conv(S)
    const Triangle x = t[k];
    t[k] = {x[0], x[1], p};
    t.push_back({x[1], x[2], p});
    t.push_back({x[2], x[0], p});
  }
  return t;
}

// Three hull vertices spanning a triangle of non-zero exact area.
Triangle hull_triangle(const PointSet& ps) {
  const std::vector<Index> h = brute::hull2(ps);
  for (std::size_t i = 1; i < h.size(); ++i)
    for (std::size_t j = i + 1; j < h.size(); ++j)
      if (pred::orient2d_exact(ps.point(h[0]), ps.point(h[i]), ps.point(h[j])) > 0) return {h[0], h[i], h[j]};
  FAIL("no hull triangle");
  return {};
}

std::vector<Index> non_hull_points(const PointSet& ps) {
  const std::vector<Index> h = brute::hull2(ps);
  const std::set<Index> hs(h.begin(), h.end());
  std::vector<Index> out;
  for (Index i = 0; i < ps.size(); ++i)
    if (!hs.count(i)) out.push_back(i);
  return out;
}


PointSet with_zero_weights(PointSet ps) {
  ps.weighted = false;
  ps.weights.clear();
  return ps;
}

}  // namespace

TEST_CASE("rt2: ffRT and both flip-flop variants and Lawson equal brute force on random small inputs", "[rt2]") {
  test::prop_scaled("weighted: ffRT (Algorithm 5 and V-first) == brute::rt2, certified", 4, [] {
    const PointSet ps = *gen_planar(3, 40, true);
    RC_PRE(spans(ps));
    const auto out = ref::rt2_ffrt(ps);
    RC_ASSERT(io::canonical_triangles(out) == out);
    RC_ASSERT(certify::rt2(ps, out, Level::canonical).message() == "certified");
    RC_ASSERT(out == brute::rt2(ps));
    RC_ASSERT(ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first) == out);
  });
  test::prop_scaled("unweighted: ffRT == Lawson == brute::rt2, certified", 4, [] {
    const PointSet ps = *gen_planar(3, 40, false);
    RC_PRE(spans(ps));
    const auto out = ref::rt2_ffrt(ps);
    RC_ASSERT(certify::rt2(ps, out, Level::canonical).message() == "certified");
    RC_ASSERT(out == brute::rt2(ps));
    RC_ASSERT(ref::dt2_lawson(ps) == out);
  });
}

TEST_CASE("rt2: every generator family including the degenerate ones equals brute force", "[rt2]") {
  std::size_t cases = 0;
  for (const std::string& f : kFamilies)
    for (std::size_t n : {3, 4, 5, 7, 10, 16, 25, 40})
      for (std::uint64_t seed = 1; seed <= 4; ++seed)
        for (bool weighted : {false, true}) {
          if (expensive(f) && n > 16) continue;
          const PointSet ps = family(f, n, seed, weighted, weight_scale(f));
          if (!spans(ps)) continue;
          INFO(f << " n=" << n << " seed=" << seed << " weighted=" << weighted);
          const auto out = ref::rt2_ffrt(ps);
          check_answer(ps, out, true);
          REQUIRE(ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first) == out);
          if (!weighted) REQUIRE(ref::dt2_lawson(ps) == out);
          ++cases;
        }
  std::cout << "rt2 families vs brute force: " << cases << " inputs\n";
  REQUIRE(cases > 300);
}

TEST_CASE("rt2: larger inputs of every family are certified", "[rt2]") {
  for (const std::string& f : kFamilies)
    for (std::size_t n : {200, 1500})
      for (bool weighted : {false, true}) {
        const std::size_t m = expensive(f) && n > 200 ? 600 : n;
        const PointSet ps = family(f, m, 7, weighted, weight_scale(f));
        if (!spans(ps)) continue;
        INFO(f << " n=" << m << " weighted=" << weighted);
        const auto out = ref::rt2_ffrt(ps);
        check_answer(ps, out, false);
        REQUIRE(ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first) == out);
        if (!weighted) REQUIRE(ref::dt2_lawson(ps) == out);
      }
}

TEST_CASE("rt2: identical to CGAL on random inputs in general position", "[rt2]") {
  for (const std::string& f : {"square", "disk", "circle"})
    for (std::size_t n : {3, 10, 100, 2000})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO(f << " n=" << n << " seed=" << seed);
        const PointSet u = family(f, n, seed, false, 0);
        REQUIRE(ref::rt2_ffrt(u) == peers::cgal_delaunay2(u));
        REQUIRE(ref::dt2_lawson(u) == peers::cgal_delaunay2(u));
        for (double whi : {1e-2, 1e-4}) {
          const PointSet w = family(f, n, seed, true, whi);
          REQUIRE(ref::rt2_ffrt(w) == peers::cgal_regular2(w));
        }
      }
}

namespace {
using Location = std::pair<double, double>;

// The locations of the vertices of a triangle set.
std::set<Location> vertex_locations(const PointSet& ps, const std::vector<Triangle>& tris) {
  std::set<Location> out;
  for (const Triangle& t : tris)
    for (Index v : t) out.emplace(ps.point(v)[0], ps.point(v)[1]);
  return out;
}

// The locations of the strictly convex corners of the boundary of a
// triangulated disk (exact arithmetic: collinear boundary points and repeated
// locations do not count).
std::set<Location> strictly_extreme(const PointSet& ps, const std::vector<Triangle>& tris) {
  std::set<std::pair<Index, Index>> directed;
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i) directed.emplace(t[i], t[(i + 1) % 3]);
  std::map<Index, Index> next;
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a})) next[a] = b;
  std::vector<Location> cycle;
  Index v = next.begin()->first;
  do {
    const Location l{ps.point(v)[0], ps.point(v)[1]};
    if (cycle.empty() || cycle.back() != l) cycle.push_back(l);
    v = next.at(v);
  } while (v != next.begin()->first);
  while (cycle.size() > 1 && cycle.front() == cycle.back()) cycle.pop_back();
  std::set<Location> out;
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    const Location& p = cycle[(i + cycle.size() - 1) % cycle.size()];
    const Location& q = cycle[(i + 1) % cycle.size()];
    const double a[2] = {p.first, p.second}, b[2] = {cycle[i].first, cycle[i].second}, c[2] = {q.first, q.second};
    if (pred::orient2d_exact(a, b, c) > 0) out.insert(cycle[i]);
  }
  return out;
}
}  // namespace

TEST_CASE("rt2: on degenerate inputs the strictly extreme points equal those of CGAL", "[rt2]") {
  for (const std::string& f : {"grid2", "circle-lattice", "duplicates2", "jitter2", "collinear-one-off", "tiny2"})
    for (std::size_t n : {5, 30, 500})
      for (bool weighted : {false, true}) {
        const PointSet ps = family(f, n, 3, weighted, weight_scale(f));
        if (!spans(ps)) continue;
        INFO(f << " n=" << n << " weighted=" << weighted);
        const auto ours = ref::rt2_ffrt(ps);
        check_answer(ps, ours, false);
        const auto cgal = weighted ? peers::cgal_regular2(ps) : peers::cgal_delaunay2(ps);
        REQUIRE(strictly_extreme(ps, ours) == strictly_extreme(ps, cgal));
        // without weights every location is a vertex of both
        if (!weighted) REQUIRE(vertex_locations(ps, ours) == vertex_locations(ps, cgal));
      }
}

TEST_CASE("dt2: Lawson == flip-flop with zero weights == ffRT with zero weights byte for byte", "[rt2]") {
  std::size_t cases = 0;
  for (const std::string& f : kFamilies)
    for (std::size_t n : {4, 9, 30, 80})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        if (expensive(f) && n > 30) continue;
        const PointSet ps = family(f, n, seed, false, 0);
        if (!spans(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        const auto lawson = ref::dt2_lawson(ps);
        const auto ffrt = ref::rt2_ffrt(ps);
        // explicit zero weights take the same path as no weights
        PointSet zero = ps;
        zero.weighted = true;
        zero.weights.assign(ps.size(), 0.0);
        REQUIRE(ref::rt2_ffrt(zero) == ffrt);
        REQUIRE(ref::dt2_lawson(zero) == lawson);
        const auto ff_fan = ref::flip_flop(ps, hull_fan(ps));
        const auto ff_all = ref::flip_flop(ps, test::random_insertion(ps, seed));
        REQUIRE(lawson == ffrt);
        REQUIRE(ff_fan == ffrt);
        REQUIRE(ff_all == ffrt);
        std::ostringstream a, b;
        io::write_triangles(a, lawson);
        io::write_triangles(b, ffrt);
        REQUIRE(a.str() == b.str());
        if (f != "duplicates2") {  // distinct points: all are vertices, Lawson's theorem applies
          REQUIRE(ref::lawson(ps, test::random_insertion(ps, seed + 100)) == ffrt);
        }
        ++cases;
      }
  std::cout << "Lawson == flip-flop(w=0) == ffRT(w=0): " << cases << " inputs\n";
  REQUIRE(cases > 100);
}

// Thesis Figure 3.3 [ES92]: an outer triangle a b c of weight w1 and a twisted
// inner triangle d e f of weight w2 << w1, joined by an annulus of six
// triangles. Only six edges are locally non-regular (the "dashed" ones) and
// every one of them is unflippable, so plain V-criterion flipping is stuck;
// flip-flop labels the inner points redundant (Lemma 5.1) and removes them.
TEST_CASE("rt2: Figure 3.3 - V-criterion flipping is stuck and flip-flop reaches RT", "[rt2]") {
  PointSet ps;
  ps.dim = 2;
  ps.weighted = true;
  //            a        b         c        d       e        f
  ps.coords = {0, 10, -9, -5, 9, -5, 1, 5, -5, -1, 4, -3};
  ps.weights = {1000, 1000, 1000, 1, 1, 1};
  const Index a = 0, b = 1, c = 2, d = 3, e = 4, f = 5;
  const std::vector<Triangle> fig = {{d, e, f}, {a, b, d}, {b, c, e}, {c, a, f},
                                     {e, d, b}, {f, e, c}, {d, f, a}};
  ref::tri::Triangulation2 T = ref::tri::from_triangles(ps, fig);  // a valid triangulation
  REQUIRE(ref::tri::real_triangles(T).size() == 7);
  // the locally non-regular edges are exactly the unflippable ones
  int non_regular = 0;
  for (const auto& [u, w] : ref::tri::edges(T)) {
    const auto edge = ref::tri::find_edge(T, u, w);
    if (ref::tri::locally_regular(T, edge)) continue;
    ++non_regular;
    INFO("edge " << u << " " << w);
    REQUIRE(ref::tri::classify(T, edge).shape == ref::tri::Shape::two_two_blocked);
  }
  REQUIRE(non_regular == 6);
  // plain V-criterion flipping (Lawson with the power test) is stuck ...
  ref::tri::Triangulation2 stuck = T;
  Rt2Stats lst;
  REQUIRE_FALSE(ref::lawson_flip::run(stuck, &lst));
  REQUIRE(lst.flips_2_2 == 0);
  const auto rt = brute::rt2(ps);
  REQUIRE(rt == std::vector<Triangle>{{a, b, c}});  // d, e, f are redundant
  REQUIRE(ref::tri::real_triangles(stuck) != rt);
  REQUIRE_THROWS_AS(ref::lawson(ps, fig), std::runtime_error);
  // ... flip-flop is not
  Rt2Stats st;
  REQUIRE(ref::flip_flop(ps, fig, FlipFlopVariant::combined, &st) == rt);
  REQUIRE(st.labelled_redundant >= 1);
  REQUIRE(st.flips_3_1 == 3);  // d, e and f removed
  REQUIRE(ref::flip_flop(ps, fig, FlipFlopVariant::v_first) == rt);
  // with equal weights the same triangulation is no problem for Lawson
  PointSet equal = ps;
  equal.weights.assign(6, 1.0);
  REQUIRE(ref::lawson(equal, fig) == brute::rt2(equal));
}

TEST_CASE("rt2: flip-flop from deliberately bad triangulations reaches the same answer", "[rt2]") {
  std::size_t cases = 0, labelled = 0, lawson_stuck = 0, lawson_ok = 0;
  for (const std::string& f : kFamilies)
    for (std::size_t n : {6, 15, 40})
      for (std::uint64_t seed = 1; seed <= 2; ++seed)
        for (double whi : {weight_scale(f), 20 * weight_scale(f)}) {  // the latter: mostly redundant
          const PointSet ps = family(f, n, seed, true, whi);
          if (!spans(ps)) continue;
          INFO(f << " n=" << n << " seed=" << seed << " whi=" << whi);
          const auto want = brute::rt2(ps);
          // every point a vertex, random insertion order, no flips: many redundant vertices
          const auto all = test::random_insertion(ps, seed);
          for (auto variant : {FlipFlopVariant::combined, FlipFlopVariant::v_first}) {
            Rt2Stats st;
            REQUIRE(ref::flip_flop(ps, all, variant, &st) == want);
            labelled += st.labelled_redundant;
          }
          // only the extreme points (a convex-position subset), fanned from one
          // vertex: the others are inserted by the constructing stage first
          REQUIRE(ref::flip_flop(ps, hull_fan(ps)) == want);
          // a convex-position subset that misses extreme points: one triangle
          // of three hull vertices (of non-zero area)
          REQUIRE(ref::flip_flop(ps, {hull_triangle(ps)}) == want);
          // Lawson: right, or stuck with a redundant vertex — never a wrong answer
          std::vector<Triangle> got;
          bool stuck = false;
          try {
            got = ref::lawson(ps, all);
          } catch (const std::runtime_error&) {
            stuck = true;
          }
          if (stuck) {
            ++lawson_stuck;
          } else {
            REQUIRE(got == want);
            ++lawson_ok;
          }
          ++cases;
        }
  std::cout << "flip-flop from bad triangulations: " << cases << " inputs, " << labelled
            << " vertices labelled redundant; Lawson right " << lawson_ok << ", stuck " << lawson_stuck << "\n";
  REQUIRE(labelled > 0);
  REQUIRE(lawson_stuck > 0);
}

TEST_CASE("rt2: flip-flop from random bad triangulations - property", "[rt2]") {
  test::prop_scaled("insertion without flips in a random order, any subset of the points", 4, [] {
    const PointSet ps = *gen_planar(4, 30, true);
    RC_PRE(spans(ps));
    // a random subset of the non-extreme points inserted in a random order
    std::vector<Index> order;
    for (Index i : non_hull_points(ps))
      if (*rc::gen::arbitrary<bool>()) order.push_back(i);
    std::mt19937_64 rng(*rc::gen::arbitrary<std::uint32_t>());
    std::shuffle(order.begin(), order.end(), rng);
    const auto start = insert_without_flips(ps, hull_fan(ps), order);
    const auto want = brute::rt2(ps);
    RC_ASSERT(ref::flip_flop(ps, start) == want);
    RC_ASSERT(ref::flip_flop(ps, start, FlipFlopVariant::v_first) == want);
  });
}

TEST_CASE("rt2: invalid inputs are rejected with a reason", "[rt2]") {
  PointSet line;
  line.dim = 2;
  line.coords = {0, 0, 1, 1, 2, 2, 3, 3};
  REQUIRE_THROWS_AS(ref::rt2_ffrt(line), std::invalid_argument);
  REQUIRE_THROWS_AS(ref::dt2_lawson(line), std::invalid_argument);
  PointSet two;
  two.dim = 2;
  two.coords = {0, 0, 1, 0};
  REQUIRE_THROWS_AS(ref::rt2_ffrt(two), std::invalid_argument);
  PointSet sq;
  sq.dim = 2;
  sq.coords = {0, 0, 2, 0, 2, 2, 0, 2, 1, 0.5};
  PointSet wsq = sq;
  wsq.weighted = true;
  wsq.weights = {0, 0, 0, 0, 0.25};
  REQUIRE_THROWS_AS(ref::dt2_lawson(wsq), std::invalid_argument);  // weights: not Lawson's job
  const std::vector<Triangle> good = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  REQUIRE(ref::flip_flop(sq, good) == brute::rt2(sq));
  REQUIRE(ref::lawson(sq, good) == brute::rt2(sq));
  REQUIRE_THROWS_AS(ref::lawson(sq, {{0, 1, 2}, {0, 2, 3}}), std::invalid_argument);  // 4 missing
  auto rejects = [&](const std::vector<Triangle>& t) {
    REQUIRE_THROWS_AS(ref::flip_flop(sq, t), std::invalid_argument);
    REQUIRE_THROWS_AS(ref::lawson(sq, t), std::invalid_argument);
  };
  rejects({});                                                    // nothing
  rejects({{0, 4, 1}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});          // a clockwise triangle
  rejects({{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 1, 2}});  // overlap
  rejects({{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 1, 4}});  // duplicate triangle
  rejects({{0, 1, 4}, {2, 3, 4}});                                // bow tie at 4
  rejects({{0, 1, 7}});                                           // index out of range
  rejects({{0, 0, 1}});                                           // repeated vertex
  // an annulus: not a disk
  PointSet ring;
  ring.dim = 2;
  ring.coords = {0, 0, 6, 0, 6, 6, 0, 6, 2, 2, 4, 2, 4, 4, 2, 4};
  const std::vector<Triangle> annulus = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                         {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  REQUIRE_THROWS_AS(ref::flip_flop(ring, annulus), std::invalid_argument);
  // a disk that is not star-shaped w.r.t. the kernel point of its first triangle
  PointSet zig;
  zig.dim = 2;
  zig.coords = {0, 0, 10, 0, 10, 1, 1, 1, 1, 10, 0, 10};
  const std::vector<Triangle> ell = {{4, 5, 3}, {5, 0, 3}, {0, 1, 2}, {0, 2, 3}};  // an L shape
  REQUIRE_THROWS_AS(ref::flip_flop(zig, ell), std::invalid_argument);
}

TEST_CASE("rt2: 10^5 points with the weight ranges of thesis section 5.4 are certified", "[rt2][large][long]") {
  for (double whi : {1e-2, 1e-5, 2e-7}) {
    const PointSet ps = family("square", 100000, 1, true, whi);
    Rt2Stats st;
    const auto out = ref::rt2_ffrt(ps, &st);
    check_answer(ps, out, false);
    std::set<Index> vertices;
    for (const Triangle& t : out) vertices.insert(t.begin(), t.end());
    std::cout << "ffRT 10^5 square, w in [0," << whi << "]: " << vertices.size() << " non-redundant ("
              << 100.0 * double(vertices.size()) / 1e5 << "%), " << out.size() << " triangles; flips 2-2 "
              << st.flips_2_2 << ", 3-1 " << st.flips_3_1 << ", 1-3 " << st.flips_1_3 << " (flops " << st.flops
              << "); labelled redundant " << st.labelled_redundant << ", discarded early " << st.discarded_early
              << ", insertion rounds " << st.rounds << "\n";
    REQUIRE(st.flips_1_3 + 3 + st.discarded_early == 100000);  // every point inserted or discarded
    REQUIRE(vertices.size() == st.flips_1_3 + 3 - st.flips_3_1);
  }
  const PointSet u = family("square", 100000, 2, false, 0);
  Rt2Stats ls;
  const auto lawson = ref::dt2_lawson(u, &ls);
  check_answer(u, lawson, false);
  REQUIRE(ref::rt2_ffrt(u) == lawson);
  std::cout << "Lawson 10^5 square: " << lawson.size() << " triangles, 2-2 flips " << ls.flips_2_2 << "\n";
}

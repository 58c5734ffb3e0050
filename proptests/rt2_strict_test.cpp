// rt2_strict_test.cpp — the strict view of 2D regular and Delaunay
// triangulations (reference/rt2/strict_rt2.hpp, `flipflop dt2|rt2 --strict`):
//   * on every degenerate family (grids with equal and lattice weights,
//     cocircular lattices, duplicates with different weights, collinear sets
//     plus one point, 1e+-300 magnitudes, RapidCheck's degenerate mix): no
//     triangle of zero area, and certify::rt2 at the exact level accepts it
//     (a triangulation of conv(S), every edge weakly locally regular, every
//     missing point weakly redundant): certify::rt2_strict;
//   * unweighted: the same vertex set as CGAL's Delaunay_triangulation_2 and
//     the same number of triangles (2n - h - 2 depends only on the vertices
//     and the hull boundary), on grids exactly the count CGAL gives;
//   * deterministic and backend-independent: the strict view of every
//     algorithm's canonical answer is the same list;
//   * on input in general position it is the canonical answer itself;
//   * the certifier rejects a zero-area triangle.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <set>

#include "gen/generate.hpp"
#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/strict_rt2.hpp"

using namespace flipflop;

namespace {

bool spans(const PointSet& ps) { return ps.size() >= 3 && affine_dimension(ps) == 2; }

std::set<Index> vertices(const std::vector<Triangle>& t) {
  std::set<Index> v;
  for (const Triangle& x : t) v.insert(x.begin(), x.end());
  return v;
}

// Vertex locations (CGAL keeps one of coinciding points, not always the
// smallest index; the strict view keeps the smallest of equal weights).
std::set<std::pair<double, double>> locations(const PointSet& ps, const std::vector<Triangle>& t) {
  std::set<std::pair<double, double>> out;
  for (Index v : vertices(t)) out.insert({ps.point(v)[0], ps.point(v)[1]});
  return out;
}

bool any_flat(const PointSet& ps, const std::vector<Triangle>& t) {
  for (const Triangle& x : t)
    if (pred::orient2d_exact(ps.point(x[0]), ps.point(x[1]), ps.point(x[2])) == 0) return true;
  return false;
}

// The strict view's contract on one input; returns it.
std::vector<Triangle> check_strict(const PointSet& ps) {
  const std::vector<Triangle> canonical = ref::rt2_ffrt(ps);
  const std::vector<Triangle> s = ref::strict_rt2(ps, canonical);
  const certify::Report r = certify::rt2_strict(ps, s);
  INFO(r.message());
  REQUIRE(r.ok);
  REQUIRE(ref::strict_rt2(ps, ref::rt2_ffrt(ps, nullptr, ref::FlipFlopVariant::v_first)) == s);
  if (!any_flat(ps, canonical)) {
    // no flat triangle and no coinciding vertices: nothing to change
    std::set<std::pair<double, double>> locs;
    for (Index v : vertices(canonical)) locs.insert({ps.point(v)[0], ps.point(v)[1]});
    if (locs.size() == vertices(canonical).size()) REQUIRE(s == canonical);
  }
  if (!ps.weighted) {
    REQUIRE(ref::strict_rt2(ps, ref::dt2_lawson(ps)) == s);
    const std::vector<Triangle> cgal = peers::cgal_delaunay2(ps);
    REQUIRE(locations(ps, s) == locations(ps, cgal));
    REQUIRE(locations(ps, s).size() == vertices(s).size());
    REQUIRE(s.size() == cgal.size());
  }
  return s;
}

PointSet family(const std::string& name, std::size_t n, std::uint64_t seed, bool weighted, double whi) {
  return test::generated(name, n, seed, weighted, whi);
}

}  // namespace

TEST_CASE("rt2 strict: no zero-area triangle, certified, CGAL's vertices and count on every 2D family", "[rt2]") {
  std::size_t flat_inputs = 0, cases = 0;
  for (const std::string& f : gen::distributions()) {
    if (gen::dimension_of(f) != 2) continue;
    for (std::size_t n : {5u, 30u, 400u})
      for (bool weighted : {false, true})
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
          const double whi = f == "huge2" ? 1e300 : f == "tiny2" ? 1e-300 : f == "grid2" ? 2.0 : 0.01;
          const PointSet ps = family(f, n, seed, weighted, whi);
          if (!spans(ps)) continue;
          INFO(f << " n=" << n << " weighted=" << weighted << " seed=" << seed);
          flat_inputs += any_flat(ps, ref::rt2_ffrt(ps));
          check_strict(ps);
          ++cases;
        }
  }
  std::cout << "rt2 strict: " << cases << " family inputs, " << flat_inputs << " with zero-area canonical triangles\n";
  REQUIRE(flat_inputs > 10);  // the view really had something to remove
}

TEST_CASE("rt2 strict: integer grids, equal and lattice weights, duplicates with different weights", "[rt2]") {
  for (int k : {3, 4, 7, 12}) {
    PointSet g;
    g.dim = 2;
    for (int x = 0; x < k; ++x)
      for (int y = 0; y < k; ++y) {
        g.coords.push_back(x);
        g.coords.push_back(y);
      }
    const std::vector<Triangle> s = check_strict(g);
    REQUIRE(s.size() == static_cast<std::size_t>(2 * (k - 1) * (k - 1)));  // the unit squares split in two
    PointSet w = g;
    w.weighted = true;
    for (std::size_t i = 0; i < g.size(); ++i) w.weights.push_back(static_cast<double>((i * 7) % 3) / 4);
    check_strict(w);
    PointSet d = w;  // every point twice, the copy with another weight
    for (std::size_t i = 0; i < g.size(); ++i) {
      d.coords.push_back(g.point(i)[0]);
      d.coords.push_back(g.point(i)[1]);
      d.weights.push_back(w.weights[i] + (i % 2 ? 0.25 : -0.25));
    }
    const std::vector<Triangle> sd = check_strict(d);
    for (Index v : vertices(sd)) {  // at each location the larger weight survived
      const Index other = v < g.size() ? v + static_cast<Index>(g.size()) : v - static_cast<Index>(g.size());
      REQUIRE(d.weights[v] >= d.weights[other]);
    }
  }
  // all points redundant but three: a big triangle with heavy weights
  PointSet r;
  r.dim = 2;
  r.weighted = true;
  const double big[3][2] = {{0, 0}, {10, 0}, {0, 10}};
  for (const auto& p : big) {
    r.coords.insert(r.coords.end(), p, p + 2);
    r.weights.push_back(1000);
  }
  for (int i = 1; i < 5; ++i)
    for (int j = 1; j + i < 9; ++j) {
      r.coords.push_back(i);
      r.coords.push_back(j);
      r.weights.push_back(0);
    }
  REQUIRE(check_strict(r) == std::vector<Triangle>{{0, 1, 2}});
}

TEST_CASE("rt2 strict: RapidCheck degenerate mix", "[rt2]") {
  test::prop_scaled("strict view certified", 4, [] {
    const bool weighted = *rc::gen::arbitrary<bool>();
    const PointSet ps = *test::degenerate_points(2, 3, 60, weighted);
    RC_PRE(spans(ps));
    const std::vector<Triangle> s = ref::strict_rt2(ps, ref::rt2_ffrt(ps));
    const certify::Report r = certify::rt2_strict(ps, s);
    RC_LOG() << r.message();
    RC_ASSERT(r.ok);
    if (!ps.weighted) RC_ASSERT(locations(ps, s) == locations(ps, peers::cgal_delaunay2(ps)));
  });
}

TEST_CASE("rt2 strict: the certifier rejects a zero-area triangle", "[rt2]") {
  PointSet g;
  g.dim = 2;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      g.coords.push_back(x);
      g.coords.push_back(y);
    }
  const std::vector<Triangle> canonical = ref::rt2_ffrt(g);
  REQUIRE(any_flat(g, canonical));
  REQUIRE(certify::rt2(g, canonical, certify::Level::canonical).ok);
  REQUIRE(certify::rt2_strict(g, canonical).condition == "zero-area");
}

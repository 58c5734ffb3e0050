// peers_test.cpp — the peers (Qhull, CGAL) agree with each other and with
// flipflop's exact predicates, and their wrappers return canonical output.
//
// Oracles: Qhull vs CGAL (independent implementations); the local conditions
// of the thesis (Thm 2.1: locally convex => convex, Thm 2.2: locally regular
// => regular) checked with predicates.hpp in Mode::gmp; the `qhull` command
// line program vs libqhull_r.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

#include "peers/peers.hpp"
#include "reference/canonical.hpp"
#include "predicates/predicates.hpp"

using namespace flipflop;
namespace pp = flipflop::peers;
using pred::Mode;

namespace {

PointSet uniform_points(int dim, std::size_t n, std::uint64_t seed, double lo = 0.0,
                        double hi = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  PointSet ps;
  ps.dim = dim;
  ps.coords.resize(n * static_cast<std::size_t>(dim));
  for (double& c : ps.coords) c = u(rng);
  return ps;
}

// Every hull edge (h[i], h[i+1]) has all points on its left or on it, and
// consecutive hull vertices turn strictly left: the cycle is the convex hull,
// counter-clockwise (local convexity + one winding, thesis Thm 2.1 in 2D).
void check_hull2(const PointSet& ps, const std::vector<Index>& h) {
  REQUIRE(h.size() >= 3);
  REQUIRE(std::min_element(h.begin(), h.end()) == h.begin());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double* a = ps.point(h[i]);
    const double* b = ps.point(h[(i + 1) % h.size()]);
    const double* c = ps.point(h[(i + 2) % h.size()]);
    REQUIRE(pred::orient2d_exact(a, b, c, Mode::gmp) > 0);
    for (std::size_t p = 0; p < ps.size(); ++p)
      REQUIRE(pred::orient2d_exact(a, b, ps.point(p), Mode::gmp) >= 0);
  }
}

// Every point lies on the inner side of (or on) every facet; facets are
// counter-clockwise seen from outside (predicates.hpp: interior => > 0); the
// surface is closed (every directed edge has its reverse).
void check_hull3(const PointSet& ps, const std::vector<Triangle>& tris) {
  REQUIRE(tris.size() >= 4);
  std::set<std::pair<Index, Index>> edges;
  for (const Triangle& t : tris) {
    REQUIRE(t[0] < t[1]);
    REQUIRE(t[0] < t[2]);
    for (int k = 0; k < 3; ++k) REQUIRE(edges.insert({t[k], t[(k + 1) % 3]}).second);
    for (std::size_t p = 0; p < ps.size(); ++p)
      REQUIRE(pred::orient3d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), ps.point(p),
                                   Mode::filtered) >= 0);
  }
  REQUIRE(std::is_sorted(tris.begin(), tris.end()));
  for (const auto& e : edges) REQUIRE(edges.count({e.second, e.first}) == 1);
}

pred::WPt wpt(const PointSet& ps, Index i) { return {i, ps.point(i), ps.weight(i)}; }

// A 2D triangulation `tris` (CCW, canonical) of the weighted set `ps` is the
// regular triangulation (thesis Thm 2.2): all triangles CCW, every interior
// edge locally regular (power2d_exact <= 0 for the point across it), the
// boundary is the convex hull `hull`, and every point that is not a vertex is
// redundant (power2d_exact <= 0 against a triangle containing it).
void check_regular2(const PointSet& ps, const std::vector<Triangle>& tris,
                    const std::vector<Index>& hull, bool all_vertices) {
  REQUIRE(std::is_sorted(tris.begin(), tris.end()));
  std::map<std::pair<Index, Index>, Index> opposite;  // directed edge -> apex
  std::set<Index> vertices;
  for (const Triangle& t : tris) {
    REQUIRE(t[0] < t[1]);
    REQUIRE(t[0] < t[2]);
    REQUIRE(pred::orient2d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), Mode::gmp) > 0);
    for (int k = 0; k < 3; ++k) {
      REQUIRE(opposite.emplace(std::make_pair(t[k], t[(k + 1) % 3]), t[(k + 2) % 3]).second);
      vertices.insert(t[k]);
    }
  }
  std::set<std::pair<Index, Index>> boundary;
  for (const auto& [e, c] : opposite) {
    auto twin = opposite.find({e.second, e.first});
    if (twin == opposite.end()) {
      boundary.insert(e);
      continue;
    }
    REQUIRE(pred::power2d_exact(wpt(ps, e.first), wpt(ps, e.second), wpt(ps, c),
                                wpt(ps, twin->second), Mode::gmp) <= 0);
  }
  std::set<std::pair<Index, Index>> hull_edges;
  for (std::size_t i = 0; i < hull.size(); ++i)
    hull_edges.insert({hull[i], hull[(i + 1) % hull.size()]});
  REQUIRE(boundary == hull_edges);
  // Euler: a triangulation of V vertices with h on the hull has 2V - 2 - h triangles.
  REQUIRE(tris.size() == 2 * vertices.size() - 2 - hull.size());
  if (all_vertices) REQUIRE(vertices.size() == ps.size());
  for (Index p = 0; p < ps.size(); ++p) {
    if (vertices.count(p)) continue;
    bool located = false;
    for (const Triangle& t : tris) {
      const double *a = ps.point(t[0]), *b = ps.point(t[1]), *c = ps.point(t[2]), *x = ps.point(p);
      if (pred::orient2d_exact(a, b, x, Mode::gmp) < 0 ||
          pred::orient2d_exact(b, c, x, Mode::gmp) < 0 ||
          pred::orient2d_exact(c, a, x, Mode::gmp) < 0)
        continue;
      located = true;
      REQUIRE(pred::power2d_exact(wpt(ps, t[0]), wpt(ps, t[1]), wpt(ps, t[2]), wpt(ps, p),
                                  Mode::gmp) <= 0);
    }
    REQUIRE(located);
  }
}

}  // namespace

TEST_CASE("peers: Qhull and both CGAL 2D hulls agree and are the CCW convex hull", "[peers]") {
  rc::prop("hull2 agreement", [] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(3, 150));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    PointSet ps = uniform_points(2, n, seed);
    auto q = pp::qhull_hull2(ps);
    auto ak = pp::cgal_hull2(ps, pp::Hull2Algo::akl_toussaint);
    auto ga = pp::cgal_hull2(ps, pp::Hull2Algo::graham_andrew);
    RC_ASSERT(q == ak);
    RC_ASSERT(q == ga);
    check_hull2(ps, q);
  });
}

TEST_CASE("peers: Qhull and CGAL 3D hulls agree and are the outward-CCW convex hull",
          "[peers]") {
  rc::prop("hull3 agreement", [] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(4, 100));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    PointSet ps = uniform_points(3, n, seed, -1.0, 1.0);
    auto q = pp::qhull_hull3(ps);
    auto c = pp::cgal_hull3(ps);
    RC_ASSERT(q == c);
    check_hull3(ps, q);
    // In general position the extreme points are the hull's vertices.
    std::set<Index> verts;
    for (const auto& t : q) verts.insert(t.begin(), t.end());
    RC_ASSERT(pp::cgal_extreme_points_3(ps) == std::vector<Index>(verts.begin(), verts.end()));
  });
}

TEST_CASE("peers: cgal_hull3 reports duplicated locations under their smallest index",
          "[peers]") {
  rc::prop("hull3 duplicates", [] {
    const auto m = static_cast<std::size_t>(*rc::gen::inRange(4, 60));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    PointSet base = uniform_points(3, m, seed);
    // Every base point twice, at shuffled positions.
    std::vector<Index> origin(2 * m);
    for (std::size_t i = 0; i < 2 * m; ++i) origin[i] = static_cast<Index>(i % m);
    std::shuffle(origin.begin(), origin.end(), std::mt19937_64(seed ^ 0x5eedULL));
    PointSet ps;
    ps.dim = 3;
    for (Index o : origin) ps.coords.insert(ps.coords.end(), base.point(o), base.point(o) + 3);
    std::vector<Index> first(m, ~Index{0});
    for (Index i = static_cast<Index>(origin.size()); i-- > 0;) first[origin[i]] = i;
    std::vector<Triangle> expected;
    for (const Triangle& t : pp::cgal_hull3(base)) expected.push_back({first[t[0]], first[t[1]], first[t[2]]});
    RC_ASSERT(pp::cgal_hull3(ps) == canonical_triangles(expected));
  });
}

TEST_CASE("peers: cgal_extreme_points_3 keeps only strict vertices on a lattice", "[peers]") {
  // The 3x3x3 integer lattice: the hull mesh may use face and edge points,
  // but the strictly extreme points are the 8 corners (coordinates in {0, 2}).
  PointSet ps;
  ps.dim = 3;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) ps.coords.insert(ps.coords.end(), {double(z), double(y), double(x)});
  std::vector<Index> corners;
  for (Index i = 0; i < ps.size(); ++i) {
    const double* p = ps.point(i);
    if ((p[0] == 0 || p[0] == 2) && (p[1] == 0 || p[1] == 2) && (p[2] == 0 || p[2] == 2))
      corners.push_back(i);
  }
  REQUIRE(corners.size() == 8);
  REQUIRE(pp::cgal_extreme_points_3(ps) == corners);
}

TEST_CASE("peers: CGAL Delaunay triangulation is locally Delaunay everywhere", "[peers]") {
  rc::prop("dt2 certified", [] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(3, 80));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    PointSet ps = uniform_points(2, n, seed);
    check_regular2(ps, pp::cgal_delaunay2(ps), pp::qhull_hull2(ps), /*all_vertices=*/true);
  });
}

TEST_CASE("peers: Qhull's Delaunay triangulation (d Qbb Qt) is CGAL's on random input", "[peers]") {
  rc::prop("qhull_delaunay2 == cgal_delaunay2, certified", [] {
    // (Qhull's initial simplex of the lifted points needs 4 of them)
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(4, 200));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    PointSet ps = uniform_points(2, n, seed);
    const auto q = pp::qhull_delaunay2(ps);
    RC_ASSERT(q == pp::cgal_delaunay2(ps));
    check_regular2(ps, q, pp::qhull_hull2(ps), /*all_vertices=*/true);
  });
}

TEST_CASE("peers: CGAL regular triangulation matches flipflop's power2d weight convention",
          "[peers]") {
  // If CGAL's weight were not the squared radius w of |x - p|^2 - w, interior
  // edges would fail power2d_exact <= 0 or redundant points would not be.
  std::size_t redundant_total = 0;
  rc::prop("rt2 certified", [&redundant_total] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(3, 60));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const double wmax = *rc::gen::element(1e-4, 1e-3, 1e-2, 3e-2);
    PointSet ps = uniform_points(2, n, seed);
    ps.weighted = true;
    std::mt19937_64 rng(~seed);
    std::uniform_real_distribution<double> w(0.0, wmax);
    for (std::size_t i = 0; i < n; ++i) ps.weights.push_back(w(rng));
    auto tris = pp::cgal_regular2(ps);
    std::set<Index> used;
    for (const auto& t : tris) used.insert(t.begin(), t.end());
    redundant_total += n - used.size();
    check_regular2(ps, tris, pp::qhull_hull2(ps), /*all_vertices=*/false);
  });
  INFO("redundant points seen: " << redundant_total);
  CHECK(redundant_total > 0);  // the weights did hide points, so the check had teeth
}

TEST_CASE("peers: the qhull command line agrees with libqhull_r", "[peers]") {
  REQUIRE(std::system("command -v qhull > /dev/null 2>&1") == 0);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    PointSet ps = uniform_points(3, 500, seed);
    char in_name[] = "/tmp/flipflop_peers_XXXXXX";
    int fd = mkstemp(in_name);
    REQUIRE(fd >= 0);
    close(fd);
    {
      std::ofstream in(in_name);
      in << "3\n" << ps.size() << "\n";
      in.precision(17);
      for (std::size_t i = 0; i < ps.size(); ++i)
        in << ps.point(i)[0] << ' ' << ps.point(i)[1] << ' ' << ps.point(i)[2] << '\n';
    }
    std::string cmd = std::string("qhull i Qt < ") + in_name;
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string text;
    char buf[4096];
    for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, got);
    REQUIRE(pclose(pipe) == 0);
    std::remove(in_name);
    std::istringstream out(text);
    std::size_t count = 0;
    REQUIRE(out >> count);
    std::vector<Triangle> cli(count);
    // Qhull prints facets with inward normals (clockwise seen from outside,
    // qh_ORIENTclock = 0); flipflop's convention is counter-clockwise.
    for (auto& t : cli) REQUIRE(out >> t[0] >> t[2] >> t[1]);
    REQUIRE(canonical_triangles(cli) == pp::qhull_hull3(ps));
  }
}

TEST_CASE("peers: lower-dimensional input is reported as one-line errors", "[peers]") {
  PointSet flat;  // 20 coplanar points (z = 0)
  flat.dim = 3;
  for (int i = 0; i < 20; ++i) flat.coords.insert(flat.coords.end(), {double(i % 5), double(i / 5), 0.0});
  try {
    pp::qhull_hull3(flat);
    FAIL("qhull_hull3 accepted coplanar input");
  } catch (const std::runtime_error& e) {
    std::string msg = e.what();
    INFO(msg);
    CHECK(msg.rfind("QH", 0) == 0);  // Qhull's own error code leads
    CHECK(msg.find('\n') == std::string::npos);
  }
  CHECK_THROWS_AS(pp::cgal_hull3(flat), std::runtime_error);
  CHECK_THROWS_AS(pp::cgal_extreme_points_3(flat), std::runtime_error);

  PointSet line;  // collinear 2D points
  line.dim = 2;
  for (int i = 0; i < 10; ++i) line.coords.insert(line.coords.end(), {double(i), 2.0 * i});
  CHECK_THROWS_AS(pp::qhull_hull2(line), std::runtime_error);
  CHECK_THROWS_AS(pp::cgal_hull2(line, pp::Hull2Algo::akl_toussaint), std::runtime_error);
  CHECK_THROWS_AS(pp::cgal_hull2(line, pp::Hull2Algo::graham_andrew), std::runtime_error);
  CHECK_THROWS_AS(pp::cgal_delaunay2(line), std::runtime_error);
  CHECK_THROWS_AS(pp::qhull_delaunay2(line), std::runtime_error);
  CHECK_THROWS_AS(pp::qhull_delaunay2(flat), std::invalid_argument);  // wrong dimension
  CHECK_THROWS_AS(pp::cgal_hull3(line), std::invalid_argument);  // wrong dimension
}

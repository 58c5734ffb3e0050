// strict_view_test.cpp — the strict view of a 3D hull (strict_hull3.hpp)
// against CGAL, on every input: random, degenerate (grids, cospherical
// lattices, duplicates, points on hull edges and facets, flat-plus-one).
//
// Oracles, independent of strict_hull3's own merging:
//   * extreme points: peers::cgal_extreme_points_3 (CGAL's convex_hull_3 with
//     Epick, vertices whose facets span three planes, smallest index per
//     location), compared as sorted lists;
//   * facets: CGAL's triangles (peers::cgal_hull3) merged HERE by union-find
//     over edge-adjacent triangles whose four points are exactly coplanar
//     (orient3d_exact == 0), each class reduced to its strictly extreme
//     vertices (by CGAL's list) — compared as vertex sets;
//   * polygon order: every facet counter-clockwise seen from outside and
//     strictly convex — orient3d_exact(v_i, v_i+1, v_i+2, q) > 0 for every
//     corner and (up to three) extreme points q off its plane — starting at
//     its smallest index.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <gmpxx.h>

#include <array>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/splay_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/strict_hull3.hpp"

using namespace flipflop;

namespace {

bool spans_3d(const PointSet& ps) { return ps.size() >= 4 && affine_dimension(ps) == 3; }


// Twice the area vector (b - a) x (c - a) of a triangle, exactly (doubles
// are dyadic rationals): for the triangles of one planar polygon, all
// oriented alike, the vectors add up to twice the polygon's area vector, so
// two tilings of one polygon have equal sums, exactly.
using AreaVec = std::array<mpq_class, 3>;
AreaVec area_vec(const PointSet& ps, Index i, Index j, Index k) {
  const double *a = ps.point(i), *b = ps.point(j), *c = ps.point(k);
  mpq_class u[3], v[3];
  for (int m = 0; m < 3; ++m) {
    u[m] = mpq_class(b[m]) - mpq_class(a[m]);
    v[m] = mpq_class(c[m]) - mpq_class(a[m]);
  }
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
void add_to(AreaVec& s, const AreaVec& t) {
  for (int m = 0; m < 3; ++m) s[m] += t[m];
}

// CGAL's facets: its triangles merged across exactly coplanar edges, each
// class as the sorted set of its strictly extreme vertices, with the sum of
// the area vectors of CGAL's triangles in it.
std::map<std::vector<Index>, AreaVec> cgal_facet_areas(const PointSet& ps, const std::vector<Index>& extreme) {
  const auto tris = peers::cgal_hull3(ps);
  const std::set<Index> ext(extreme.begin(), extreme.end());
  std::vector<std::size_t> up(tris.size());
  std::iota(up.begin(), up.end(), std::size_t{0});
  auto find = [&](std::size_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  };
  std::map<std::pair<Index, Index>, std::size_t> at;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Triangle& T = tris[t];
    // CGAL's hull has no flat triangle (the merging below relies on it)
    REQUIRE_FALSE(pred::collinear3_exact(ps.point(T[0]), ps.point(T[1]), ps.point(T[2])));
    for (int e = 0; e < 3; ++e) at[{T[e], T[(e + 1) % 3]}] = t;
  }
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Triangle& T = tris[t];
    for (int e = 0; e < 3; ++e) {
      const std::size_t u = at.at({T[(e + 1) % 3], T[e]});
      for (Index d : tris[u])
        if (pred::orient3d_exact(ps.point(T[0]), ps.point(T[1]), ps.point(T[2]), ps.point(d)) != 0) goto next_edge;
      up[find(t)] = find(u);
    next_edge:;
    }
  }
  std::map<std::size_t, std::set<Index>> classes;
  std::map<std::size_t, AreaVec> areas;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (Index v : tris[t])
      if (ext.count(v)) classes[find(t)].insert(v);
    add_to(areas[find(t)], area_vec(ps, tris[t][0], tris[t][1], tris[t][2]));
  }
  std::map<std::vector<Index>, AreaVec> out;
  for (const auto& [root, vs] : classes) out[std::vector<Index>(vs.begin(), vs.end())] = areas[root];
  return out;
}

std::set<std::vector<Index>> cgal_facets(const PointSet& ps, const std::vector<Index>& extreme) {
  std::set<std::vector<Index>> out;
  for (const auto& [f, a] : cgal_facet_areas(ps, extreme)) out.insert(f);
  return out;
}

// hull3 --strict --triangulate (ref::fan_triangulated): the same extreme
// points, every triangle of non-zero area (exact) with strictly extreme
// vertices only, a closed oriented 2-manifold (every directed edge once, its
// reverse once: no T-junction) of Euler characteristic 2, the triangles of
// each polygon starting at its smallest vertex, and each polygon's area
// vector (its fan's) equal to that of CGAL's triangles in that facet,
// exactly (so the areas and the orientations agree).
void check_triangulated(const PointSet& ps, const ref::StrictHull3& h) {
  const ref::StrictHull3 t = ref::fan_triangulated(h);
  REQUIRE(t.extreme_points == h.extreme_points);
  REQUIRE(std::is_sorted(t.facets.begin(), t.facets.end()));
  const std::set<Index> ext(h.extreme_points.begin(), h.extreme_points.end());
  std::set<std::pair<Index, Index>> edges;
  std::set<Index> used;
  for (const auto& f : t.facets) {
    REQUIRE(f.size() == 3);
    REQUIRE(f[0] < f[1]);
    REQUIRE(f[0] < f[2]);
    REQUIRE_FALSE(pred::collinear3_exact(ps.point(f[0]), ps.point(f[1]), ps.point(f[2])));
    for (int e = 0; e < 3; ++e) {
      REQUIRE(ext.count(f[e]));
      used.insert(f[e]);
      REQUIRE(edges.insert({f[e], f[(e + 1) % 3]}).second);
    }
  }
  for (const auto& [a, b] : edges) REQUIRE(edges.count({b, a}));
  REQUIRE(used == ext);
  REQUIRE(static_cast<long>(used.size()) - static_cast<long>(edges.size() / 2) + static_cast<long>(t.facets.size()) == 2);
  const auto cgal = cgal_facet_areas(ps, h.extreme_points);
  for (const auto& poly : h.facets) {
    AreaVec fan;
    for (std::size_t j = 1; j + 1 < poly.size(); ++j) add_to(fan, area_vec(ps, poly[0], poly[j], poly[j + 1]));
    std::vector<Index> key = poly;
    std::sort(key.begin(), key.end());
    const AreaVec& theirs = cgal.at(key);
    INFO("polygon of " << poly.size() << " vertices starting at " << poly[0]);
    REQUIRE((theirs[0] != 0 || theirs[1] != 0 || theirs[2] != 0));
    REQUIRE(fan == theirs);
  }
}

void check_polygons(const PointSet& ps, const ref::StrictHull3& h) {
  for (const auto& f : h.facets) {
    INFO("facet of " << f.size() << " vertices starting at " << f[0]);
    REQUIRE(f.size() >= 3);
    REQUIRE(*std::min_element(f.begin(), f.end()) == f[0]);
    const double *a = ps.point(f[0]), *b = ps.point(f[1]), *c = ps.point(f[2]);
    bool planar = true, convex = true;
    for (Index v : f) planar = planar && pred::orient3d_exact(a, b, c, ps.point(v)) == 0;
    int off = 0;  // a few extreme points off the plane (all on its inner side)
    for (std::size_t j = 0; j < h.extreme_points.size() && off < 3; ++j) {
      const double* q = ps.point(h.extreme_points[j]);
      if (pred::orient3d_exact(a, b, c, q) == 0) continue;
      ++off;
      for (std::size_t i = 0; i < f.size(); ++i)
        convex = convex && pred::orient3d_exact(ps.point(f[i]), ps.point(f[(i + 1) % f.size()]),
                                                ps.point(f[(i + 2) % f.size()]), q) > 0;
    }
    REQUIRE(planar);
    REQUIRE(off > 0);
    REQUIRE(convex);
  }
  REQUIRE(std::is_sorted(h.facets.begin(), h.facets.end()));
}

void check_against_cgal(const PointSet& ps, const ref::StrictHull3& h) {
  const auto ext = peers::cgal_extreme_points_3(ps);
  REQUIRE(h.extreme_points == ext);
  std::set<std::vector<Index>> mine;
  for (auto f : h.facets) {
    std::sort(f.begin(), f.end());
    REQUIRE(mine.insert(f).second);
  }
  REQUIRE(mine == cgal_facets(ps, ext));
  check_polygons(ps, h);
}

// The cube [0,4]^3 sampled on its integer lattice (point (x,y,z) at index
// (5x + y)5 + z: points inside facets, on edges, inside), then its 8 corners
// again at indices 125..132.
PointSet lattice_cube() {
  PointSet ps;
  ps.dim = 3;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y)
      for (int z = 0; z <= 4; ++z) ps.coords.insert(ps.coords.end(), {double(x), double(y), double(z)});
  for (int c = 0; c < 8; ++c) ps.coords.insert(ps.coords.end(), {4.0 * (c & 1), 4.0 * (c >> 1 & 1), 4.0 * (c >> 2 & 1)});
  return ps;
}

// The text form read back: counts, extreme points, facets.
ref::StrictHull3 parse(const std::string& text) {
  std::istringstream in(text);
  std::size_t e = 0, f = 0;
  in >> e >> f;
  ref::StrictHull3 h;
  h.extreme_points.resize(e);
  for (auto& v : h.extreme_points) in >> v;
  std::string line;
  std::getline(in, line);
  for (std::size_t i = 0; i < f; ++i) {
    std::getline(in, line);
    std::istringstream ls(line);
    std::vector<Index> facet;
    for (Index v; ls >> v;) facet.push_back(v);
    h.facets.push_back(facet);
  }
  return h;
}

}  // namespace

TEST_CASE("strict: view equals CGAL: 4..40 points, random and degenerate", "[strict]") {
  test::prop_scaled("extreme points and facets", 8, [] {
    const PointSet ps = *test::degenerate_points(3, 4, 40, false);
    RC_PRE(spans_3d(ps));
    const auto h = ref::strict_hull3(ps, brute::hull3(ps));
    check_against_cgal(ps, h);
    check_triangulated(ps, h);
    RC_ASSERT(parse(ref::format_strict_hull3(h)) == h);
    // the view (equal to CGAL's, above) passes the strict certifier, both forms
    RC_ASSERT(certify::hull3_strict(ps, h.extreme_points, h.facets, false).ok);
    const auto t = ref::fan_triangulated(h);
    RC_ASSERT(certify::hull3_strict(ps, t.extreme_points, t.facets, true).ok);
  });
}

TEST_CASE("strict: view equals CGAL on every generator family", "[strict][long]") {
  for (const std::string& fam : test::splay_families())
    for (std::size_t n : {8u, 50u, 3000u}) {
      const PointSet ps = test::family3(fam, n, 5);
      INFO(fam << " " << n);
      if (!spans_3d(ps)) continue;
      const auto h = ref::strict_hull3(ps, ref::hull3_splay(ps));
      check_against_cgal(ps, h);
      check_triangulated(ps, h);
      if (n <= 50) REQUIRE(ref::strict_hull3(ps, brute::hull3(ps)) == h);
      INFO(certify::hull3_strict(ps, h.extreme_points, h.facets, false).message());
      REQUIRE(certify::hull3_strict(ps, h.extreme_points, h.facets, false).ok);
      const auto t = ref::fan_triangulated(h);
      REQUIRE(certify::hull3_strict(ps, t.extreme_points, t.facets, true).ok);
    }
}

TEST_CASE("strict: view: points on hull edges and facets, duplicated corners", "[strict]") {
  // The cube [0,4]^3 sampled on its integer lattice (points inside facets,
  // on edges, inside), corners repeated, in a shuffled order.
  const PointSet ps = lattice_cube();
  std::vector<std::size_t> order(ps.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 rng(3);
  std::shuffle(order.begin(), order.end(), rng);
  PointSet shuffled;
  shuffled.dim = 3;
  for (std::size_t i : order) test::add_point(shuffled, ps.point(i));
  const auto h = ref::strict_hull3(shuffled, ref::hull3_splay(shuffled));
  REQUIRE(h.extreme_points.size() == 8);  // the 8 corners, smallest copy each
  REQUIRE(h.facets.size() == 6);          // 6 squares
  for (const auto& f : h.facets) REQUIRE(f.size() == 4);
  check_against_cgal(shuffled, h);
  // an octahedron with points on its edges and facets
  PointSet oct;
  oct.dim = 3;
  oct.coords = {2, 0, 0, -2, 0, 0, 0, 2, 0, 0, -2, 0, 0, 0, 2, 0, 0, -2, 1, 1, 0, 0, 1, 1, 1, 0, 1, 0, 0, 0, 2, 0, 0, 0.5, 0.5, 1};
  const auto o = ref::strict_hull3(oct, brute::hull3(oct));
  REQUIRE(o.extreme_points == std::vector<Index>{0, 1, 2, 3, 4, 5});
  REQUIRE(o.facets.size() == 8);
  check_against_cgal(oct, o);
}

TEST_CASE("strict: view: malformed triangle lists are rejected", "[strict]") {
  const PointSet ps = test::family3("ball", 20, 1);
  auto hull = brute::hull3(ps);
  REQUIRE_NOTHROW(ref::strict_hull3(ps, hull));
  auto open = hull;
  open.pop_back();
  REQUIRE_THROWS_AS(ref::strict_hull3(ps, open), std::invalid_argument);
  auto out_of_range = hull;
  out_of_range[0][1] = 99;
  REQUIRE_THROWS_AS(ref::strict_hull3(ps, out_of_range), std::invalid_argument);
  auto twice = hull;
  twice.push_back(hull[0]);
  REQUIRE_THROWS_AS(ref::strict_hull3(ps, twice), std::invalid_argument);
  PointSet flat = ps;
  flat.dim = 2;
  REQUIRE_THROWS_AS(ref::strict_hull3(flat, hull), std::invalid_argument);
}

// certify::hull3_strict rejects each way a strict view can be wrong, naming
// the violated condition. Inputs: the lattice cube [0,4]^3 with its corners
// repeated at larger indices (squares with lattice points on their edges and
// inside), and a sphere lattice (many polygons of >= 4 vertices).
TEST_CASE("strict: the strict certifier rejects wrong views with the violated condition", "[strict]") {
  const PointSet cube = lattice_cube();
  const auto h = ref::strict_hull3(cube, brute::hull3(cube));
  auto expect = [&](const PointSet& ps, const std::vector<Index>& e, const std::vector<std::vector<Index>>& f,
                    bool tri, const std::string& condition) {
    const certify::Report r = certify::hull3_strict(ps, e, f, tri);
    INFO(r.message());
    REQUIRE_FALSE(r.ok);
    REQUIRE(r.condition == condition);
  };
  REQUIRE(certify::hull3_strict(cube, h.extreme_points, h.facets, false).ok);
  auto at = [&](int x, int y, int z) { return static_cast<Index>((x * 5 + y) * 5 + z); };
  SECTION("a facet turned inward") {
    auto f = h.facets;
    std::reverse(f[2].begin() + 1, f[2].end());
    expect(cube, h.extreme_points, f, false, "facet-polygon");
  }
  SECTION("a square split into two triangles") {
    auto f = h.facets;
    const auto sq = f[0];
    f[0] = {sq[0], sq[1], sq[2]};
    f.push_back({sq[0], sq[2], sq[3]});
    expect(cube, h.extreme_points, f, false, "maximal-facets");
    // in the triangulated view that split is allowed; the other squares are not triangles
    expect(cube, h.extreme_points, f, true, "strict-indices");
  }
  SECTION("a lattice point inside an edge listed as a vertex") {
    // (2,0,0) lies on the edge (0,0,0)-(4,0,0): inserted between them in
    // both squares of that edge, it is a straight corner
    const Index a = at(0, 0, 0), b = at(4, 0, 0), mid = at(2, 0, 0);
    auto e = h.extreme_points;
    e.insert(std::upper_bound(e.begin(), e.end(), mid), mid);
    auto f = h.facets;
    for (auto& poly : f)
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Index u = poly[i], v = poly[(i + 1) % poly.size()];
        if ((u == a && v == b) || (u == b && v == a)) {
          poly.insert(poly.begin() + static_cast<long>(i) + 1, mid);
          break;
        }
      }
    expect(cube, e, f, false, "facet-polygon");
  }
  SECTION("a corner reported by its larger duplicate") {
    const Index small = at(4, 4, 4), big = static_cast<Index>(125 + 7);
    auto e = h.extreme_points;
    std::replace(e.begin(), e.end(), small, big);
    std::sort(e.begin(), e.end());
    auto f = h.facets;
    for (auto& poly : f) std::replace(poly.begin(), poly.end(), small, big);
    expect(cube, e, f, false, "smallest-index");
  }
  SECTION("a corner missing: the view of the input without it") {
    PointSet cut;
    cut.dim = 3;
    std::vector<Index> back;
    for (Index i = 0; i < cube.size(); ++i) {
      const double* p = cube.point(i);
      if (p[0] == 4 && p[1] == 4 && p[2] == 4) continue;
      back.push_back(i);
      test::add_point(cut, p);
    }
    auto c = ref::strict_hull3(cut, brute::hull3(cut));
    for (Index& v : c.extreme_points) v = back[v];
    for (auto& poly : c.facets)
      for (Index& v : poly) v = back[v];
    std::sort(c.extreme_points.begin(), c.extreme_points.end());
    expect(cube, c.extreme_points, c.facets, false, "point-inside");
  }
  SECTION("a triangulated view with a vertex inside a facet") {
    // fan each square from its centre point instead of from a corner: the
    // centre is in one facet plane only
    auto e = h.extreme_points;
    std::vector<std::vector<Index>> f;
    for (const auto& sq : h.facets) {
      double c[3] = {0, 0, 0};
      for (Index v : sq)
        for (int j = 0; j < 3; ++j) c[j] += cube.point(v)[j] / 4;
      const Index centre = at(static_cast<int>(c[0]), static_cast<int>(c[1]), static_cast<int>(c[2]));
      e.push_back(centre);
      for (std::size_t i = 0; i < 4; ++i) {
        std::vector<Index> t = {centre, sq[i], sq[(i + 1) % 4]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        f.push_back(t);
      }
    }
    std::sort(e.begin(), e.end());
    expect(cube, e, f, true, "strictly-extreme");
  }
  SECTION("bad indices") {
    auto e = h.extreme_points;
    std::swap(e[0], e[1]);
    expect(cube, e, h.facets, false, "strict-indices");
    auto f = h.facets;
    f[0][1] = at(2, 2, 2);  // an interior point, not listed
    expect(cube, h.extreme_points, f, false, "strict-indices");
  }
}

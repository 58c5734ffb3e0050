// rtd_hull_d_test.cpp — the d-dimensional convex hull kernel
// (kernels_cpu/rtd/hull_d, Python's ConvexHull in 4D and 5D) and its
// certifier.
//
// Oracles: the definition itself (every facet has every other point strictly
// on its inner side, decided by orient_d — brute force over the facets and
// points), and the boundary facets of RT+1's canonical Delaunay triangulation
// (ref::rtd_incremental, another algorithm), which are the canonical hull's
// facets. The certifier is shown to reject each kind of wrong answer by the
// condition it violates. Case counts: RC_PARAMS max_success = 2000 under
// ctest, divided per property by prop_scaled.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/rtd/hull_d.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/neighbours.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

namespace {

using Facets = std::vector<std::vector<Index>>;

std::set<std::vector<Index>> as_sets(const Facets& fs) {
  std::set<std::vector<Index>> out;
  for (auto f : fs) {
    std::sort(f.begin(), f.end());
    out.insert(f);
  }
  return out;
}

// the boundary facets of the canonical Delaunay triangulation
std::set<std::vector<Index>> triangulation_boundary(const PointSet& ps) {
  std::map<std::vector<Index>, int> count;
  for (const auto& s : ref::rtd_incremental(ps).simplices)
    for (std::size_t i = 0; i < s.size(); ++i) {
      std::vector<Index> f;
      for (std::size_t j = 0; j < s.size(); ++j)
        if (j != i) f.push_back(s[j]);
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  std::set<std::vector<Index>> out;
  for (const auto& [f, c] : count)
    if (c == 1) out.insert(f);
  return out;
}

int orient(const PointSet& ps, const std::vector<Index>& f, Index x) {
  pred::PointId id[pred::kMaxLambdaK];
  const double* p[pred::kMaxLambdaK];
  for (std::size_t j = 0; j < f.size(); ++j) id[j] = f[j], p[j] = ps.point(f[j]);
  id[f.size()] = x, p[f.size()] = ps.point(x);
  return pred::lambda_sign(ps.dim + 1, id, p, nullptr, pred::Mode::filtered);
}

// the definition: every point off a facet strictly inside it
bool definition_holds(const PointSet& ps, const Facets& fs) {
  for (const auto& f : fs)
    for (Index x = 0; x < ps.size(); ++x)
      if (std::find(f.begin(), f.end(), x) == f.end() && orient(ps, f, x) >= 0) return false;
  return true;
}

bool spans(const PointSet& ps) {
  try {
    ref::validate_rtd_input(ps);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

int nmax_of(int d) { return d <= 3 ? 60 : d == 4 ? 36 : 24; }

PointSet prefix(const PointSet& ps, std::size_t n) {
  PointSet p;
  p.dim = ps.dim;
  p.coords = Values(std::vector<double>(ps.coords.begin(), ps.coords.begin() + static_cast<std::ptrdiff_t>(n * ps.dim)));
  return p;
}

// the points of ps at the ascending indices `at`, in that order
PointSet select(const PointSet& ps, const std::vector<Index>& at) {
  PointSet p;
  p.dim = ps.dim;
  std::vector<double> c;
  for (Index i : at) c.insert(c.end(), ps.point(i), ps.point(i) + ps.dim);
  p.coords = Values(std::move(c));
  return p;
}

// the facets' neighbours (test::neighbours_by_search; every ridge of a
// closed surface has one, so none is -1 there; -1 would not fit an Index and
// is refused as out of range)
Facets neighbours_of(const Facets& fs) {
  Facets nb;
  for (const auto& row : test::neighbours_by_search(fs)) {
    nb.emplace_back();
    for (std::int64_t g : row) nb.back().push_back(static_cast<Index>(g < 0 ? fs.size() : static_cast<std::size_t>(g)));
  }
  return nb;
}

// Batches for the in-place insertion properties: a prefix length k that
// spans R^d (and 0..extra points more, at random), then the ends of the
// batches after it, ascending, the last ps.size(); nullopt where no prefix
// spans (the one-shot property covers the rejection).
std::optional<std::pair<std::size_t, std::vector<std::size_t>>> batches(const PointSet& ps, int d, std::size_t extra,
                                                                        int max_cuts) {
  std::size_t k = static_cast<std::size_t>(d) + 1;
  while (k <= ps.size() && !spans(prefix(ps, k))) ++k;
  if (k > ps.size()) return std::nullopt;
  k = std::min(ps.size(), k + *rc::gen::inRange<std::size_t>(0, extra + 1));
  const auto cuts = *rc::gen::container<std::vector<std::size_t>>(*rc::gen::inRange(0, max_cuts + 1),
                                                                  rc::gen::inRange<std::size_t>(0, ps.size() + 1));
  std::vector<std::size_t> at;
  for (std::size_t c : cuts)
    if (c > k && c < ps.size()) at.push_back(c);
  std::sort(at.begin(), at.end());
  at.push_back(ps.size());
  return std::make_pair(k, at);
}

// f is the hull of p: the definition's facets, hull_d's, certified
void check_hull(const PointSet& p, const Facets& f) {
  RC_ASSERT(definition_holds(p, f));
  RC_ASSERT(as_sets(f) == as_sets(cpu::hull_d(p)));
  RC_ASSERT(cpu::hull_d_problem(p, f).empty());
}

}  // namespace

TEST_CASE("hull_d: a kernel seeded with a certified hull on its vertices alone, then points added in batches, "
          "equals the one-shot hull (shrinking)",
          "[hull_d]") {
  // Python's ConvexHull(incremental=True): the one-shot hull of the first
  // k points, the kernel seeded with its facets and neighbours over its
  // vertices only, then each batch appended to the kernel's points (an
  // ascending subset of the input's indices: a monotone renumbering)
  for (int d = 2; d <= 5; ++d)
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets: seeded kernel + batches == hull_d of all, "
                                                          "the definition, certified",
                      d <= 3 ? 8 : 16, [d] {
                        const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax_of(d), false);
                        const auto b = batches(ps, d, 5, 4);
                        if (!b) return;
                        const auto& [k, at] = *b;
                        Facets f = cpu::hull_d(prefix(ps, k));
                        std::vector<Index> keep;
                        for (const auto& t : f) keep.insert(keep.end(), t.begin(), t.end());
                        std::sort(keep.begin(), keep.end());
                        keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
                        for (auto& t : f)
                          for (Index& i : t) i = static_cast<Index>(std::lower_bound(keep.begin(), keep.end(), i) - keep.begin());
                        cpu::HullDIncremental inc(select(ps, keep), f, neighbours_of(f));
                        RC_ASSERT(inc.size() == keep.size());
                        std::size_t last = k;
                        for (std::size_t n : at) {
                          for (std::size_t i = last; i < n; ++i) keep.push_back(static_cast<Index>(i));
                          last = n;
                          inc.add(select(ps, keep));
                          Facets g = inc.facets();
                          for (auto& t : g)
                            for (Index& i : t) i = keep[i];
                          check_hull(prefix(ps, n), g);
                        }
                      });
}

TEST_CASE("hull_d: a seed that is not a closed surface of simplices is refused", "[hull_d]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = Values(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  const Facets f = cpu::hull_d(ps);
  const Facets nb = neighbours_of(f);
  cpu::HullDIncremental good(ps, f, nb);
  REQUIRE(as_sets(good.facets()) == as_sets(f));
  Facets swapped = nb;
  std::swap(swapped[0][0], swapped[0][1]);
  REQUIRE_THROWS_AS(cpu::HullDIncremental(ps, f, swapped), std::invalid_argument);
  REQUIRE_THROWS_AS(cpu::HullDIncremental(ps, Facets(f.begin(), f.end() - 1), Facets(nb.begin(), nb.end() - 1)),
                    std::invalid_argument);
  Facets repeated = f;
  repeated[0][1] = repeated[0][0];
  REQUIRE_THROWS_AS(cpu::HullDIncremental(ps, repeated, nb), std::invalid_argument);
  Facets far = f;
  far[1][2] = 7;
  REQUIRE_THROWS_AS(cpu::HullDIncremental(ps, far, nb), std::invalid_argument);
}

TEST_CASE("hull_d: in-place insertion in batches equals the one-shot hull and the definition (shrinking)",
          "[hull_d]") {
  for (int d = 2; d <= 6; ++d)
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets added in random batches: after every batch the "
                                                          "facets == the one-shot hull_d's and the definition's, "
                                                          "certified",
                      d <= 3 ? 8 : d <= 5 ? 16 : 40, [d] {
                        const int nmax = d == 6 ? 16 : nmax_of(d);
                        const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax, false);
                        const auto b = batches(ps, d, 3, 5);
                        if (!b) return;
                        const auto& [k, at] = *b;
                        cpu::HullDIncremental inc(prefix(ps, k));
                        for (std::size_t n : at) {
                          const PointSet p = prefix(ps, n);
                          if (n != inc.size()) inc.add(p);
                          RC_ASSERT(inc.size() == n);
                          check_hull(p, inc.facets());
                        }
                      });
}

TEST_CASE("hull_d: in-place insertion rejects bad points and keeps its state", "[hull_d]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = Values(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 2, 2, 0.25, 0.25, 0.25});
  cpu::HullDIncremental inc(prefix(ps, 4));
  const auto before = as_sets(inc.facets());
  std::vector<double> v(ps.coords.begin(), ps.coords.end());
  v[13] = std::nan("");
  PointSet bad = ps;
  bad.coords = Values(std::move(v));
  REQUIRE_THROWS_AS(inc.add(bad), std::invalid_argument);
  REQUIRE(as_sets(inc.facets()) == before);
  REQUIRE(inc.size() == 4);
  REQUIRE_THROWS_AS(inc.add(prefix(ps, 3)), std::invalid_argument);
  inc.add(ps);
  REQUIRE(as_sets(inc.facets()) == as_sets(cpu::hull_d(ps)));
  REQUIRE(as_sets(inc.facets()).size() == 6);  // (2,2,2) sees the facet x+y+z=1; the centre is inside
  REQUIRE_THROWS_AS(cpu::HullDIncremental(prefix(ps, 3)), std::invalid_argument);
}

TEST_CASE("hull_d: the facets are the definition's and the Delaunay boundary's, certified (shrinking)", "[hull_d]") {
  for (int d = 2; d <= 5; ++d)
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets: hull_d == definition == RT+1's boundary, "
                                                          "certified",
                      d <= 3 ? 8 : 16, [d] {
                        PointSet ps = *test::degenerate_points_d(d, d + 1, nmax_of(d), false);
                        if (!spans(ps)) {
                          RC_ASSERT_THROWS_AS(cpu::hull_d(ps), std::invalid_argument);
                          return;
                        }
                        const Facets f = cpu::hull_d(ps);
                        RC_ASSERT(definition_holds(ps, f));
                        RC_ASSERT(as_sets(f) == triangulation_boundary(ps));
                        RC_ASSERT(cpu::hull_d_problem(ps, f).empty());
                      });
}

TEST_CASE("hull_d: grids and points on a sphere in 4D and 5D", "[hull_d]") {
  for (int d : {4, 5}) {
    PointSet grid;
    grid.dim = d;
    std::vector<double> c;
    int n = 1;
    for (int j = 0; j < d; ++j) n *= 3;
    for (int i = 0; i < n; ++i) {
      int x = i;
      for (int j = 0; j < d; ++j, x /= 3) c.push_back(x % 3);
    }
    grid.coords = Values(std::move(c));
    const Facets f = cpu::hull_d(grid);
    INFO(d << "D grid");
    REQUIRE(definition_holds(grid, f));
    REQUIRE(cpu::hull_d_problem(grid, f).empty());
    if (d == 4) REQUIRE(as_sets(f) == triangulation_boundary(grid));
  }
  // every point a vertex: the certifier is star-shaped from an auxiliary point (the vertices' average)
  PointSet sphere;
  sphere.dim = 4;
  std::vector<double> c;
  for (int a = -2; a <= 2; ++a)
    for (int b = -2; b <= 2; ++b)
      for (int e = -2; e <= 2; ++e)
        for (int g = -2; g <= 2; ++g)
          if (a * a + b * b + e * e + g * g == 5) c.insert(c.end(), {double(a), double(b), double(e), double(g)});
  sphere.coords = Values(std::move(c));
  const Facets f = cpu::hull_d(sphere);
  REQUIRE(definition_holds(sphere, f));
  REQUIRE(cpu::hull_d_problem(sphere, f).empty());
  REQUIRE(as_sets(f) == triangulation_boundary(sphere));
}

TEST_CASE("hull_d certifier: each kind of wrong answer is rejected by its condition", "[hull_d]") {
  PointSet ps;
  ps.dim = 4;
  std::vector<double> c;
  std::uint64_t s = 12345;
  for (int i = 0; i < 200 * 4; ++i) {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17;
    c.push_back(static_cast<double>(s >> 11) * 0x1p-53);
  }
  ps.coords = Values(std::move(c));
  const Facets right = cpu::hull_d(ps);
  REQUIRE(cpu::hull_d_problem(ps, right).empty());
  auto starts = [](const std::string& why, const std::string& cond) { return why.rfind(cond + ":", 0) == 0; };
  SECTION("a facet missing") {
    Facets f = right;
    f.pop_back();
    REQUIRE(starts(cpu::hull_d_problem(ps, f), "closed-surface"));
  }
  SECTION("a facet repeating a vertex or naming a point out of range") {
    Facets f = right;
    f[3][1] = f[3][0];
    REQUIRE(starts(cpu::hull_d_problem(ps, f), "facet-indices"));
    f = right;
    f[2][2] = static_cast<Index>(ps.size());
    REQUIRE(starts(cpu::hull_d_problem(ps, f), "facet-indices"));
  }
  SECTION("every facet turned inside out") {
    Facets f = right;
    for (auto& x : f) std::swap(x[0], x[1]);
    const std::string why = cpu::hull_d_problem(ps, f);
    REQUIRE((starts(why, "convex") || starts(why, "star-shaped")));
  }
  SECTION("the hull of the points less one vertex: that vertex outside") {
    // drop the vertex of smallest index: the hull of the others, with the
    // dropped point then a non-vertex outside
    std::set<Index> verts;
    for (const auto& x : right) verts.insert(x.begin(), x.end());
    const Index gone = *verts.begin();
    PointSet rest = ps;
    std::vector<double> rc(ps.coords.begin(), ps.coords.end());
    // move the point far inside instead of removing it (indices stay): the
    // hull of that input, certified against the original points
    for (int j = 0; j < 4; ++j) rc[gone * 4 + j] = 0.5;
    rest.coords = Values(std::move(rc));
    const Facets smaller = cpu::hull_d(rest);
    const std::string why = cpu::hull_d_problem(ps, smaller);
    INFO(why);
    REQUIRE(!why.empty());
  }
}

// Every vertex of ps in turn, the largest first, up to `tries`, moved to the
// origin (inside): the hull of that input, certified against the original
// points, leaves the vertex outside — named by the walk ("points-inside",
// with the inner region `verified` says was in use), or, where it is the
// smallest point that is not a vertex of that hull, as the centre of the
// star ("star-shaped"); the walk names at least one.
template <class Verified>
void outside_vertices_named(const PointSet& ps, const std::set<Index>& verts, int tries, const Verified& verified) {
  const int d = ps.dim;
  int tried = 0, walked = 0;
  for (auto it = verts.rbegin(); it != verts.rend() && tried < tries; ++it, ++tried) {
    const Index gone = *it;
    std::vector<double> xs(ps.coords.begin(), ps.coords.end());
    for (int j = 0; j < d; ++j) xs[gone * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)] = 0.0;
    PointSet moved = ps;
    moved.coords = Values(std::move(xs));
    const Facets smaller = cpu::hull_d(moved);
    cpu::HullDCertifyStats cm;
    const std::string why = cpu::hull_d_problem(ps, smaller, &cm);
    INFO("vertex " << gone << " moved: " << why);
    if (why.rfind("points-inside: ", 0) == 0) {
      ++walked;
      REQUIRE(verified(cm));
      REQUIRE(why.rfind("points-inside: point " + std::to_string(gone) + " ", 0) == 0);
    } else {
      REQUIRE(why.rfind("star-shaped: point " + std::to_string(gone) + " ", 0) == 0);
    }
  }
  REQUIRE(walked > 0);
}

// The certifier's inner box (hull_d.cpp certify_points, reference/certify/
// inner_box.hpp): where the points outnumber the facets it is verified and
// its points take no walk — and a point outside the claimed hull is still
// found, named by the same message
TEST_CASE("hull_d: the certifier's inner box spares most walks and hides no outside point", "[hull_d]") {
  // (5D cubes of this size have more facets than points inside: no box)
  for (int d : {3, 4}) {
    INFO("d = " << d);
    const PointSet ps = test::xorshift_cube(d, 20000, -0.5);
    const Facets right = cpu::hull_d(ps);
    std::set<Index> verts;
    for (const auto& x : right) verts.insert(x.begin(), x.end());
    cpu::HullDCertifyStats cs;
    REQUIRE(cpu::hull_d_problem(ps, right, &cs).empty());
    REQUIRE(cs.box);
    const std::size_t others = ps.size() - verts.size() - 1;  // not vertices, nor the centre v
    INFO(cs.walked << " of " << others << " points walked");
    REQUIRE(cs.walked < others);  // measured: 6289 of 19,851 in 3D
    // the box of each smaller hull does not hide the vertex left outside
    outside_vertices_named(ps, verts, 8, [](const cpu::HullDCertifyStats& cm) { return cm.box; });
  }
}

// The certifier's inner ball (hull_d.cpp propose_ball, PlaneForm::ball_below):
// on input that fills a ball rather than a box (coordinates each the sum of
// four uniform numbers, about normal) it is verified and spares most walks
// the box leaves (measured on 2x10^4 normal 5D points: 10,863 walks with the
// box alone, 1433 with the ball) — and a point outside the claimed hull is
// still found, named by the same message as without it
TEST_CASE("hull_d: the certifier's inner ball spares most walks on round input and hides no outside point", "[hull_d]") {
  for (int d : {3, 4, 5}) {
    INFO("d = " << d);
    const std::size_t n = 20000;
    const PointSet cube = test::xorshift_cube(4 * d, n, -0.5);
    PointSet ps;
    ps.dim = d;
    std::vector<double> xs(n * static_cast<std::size_t>(d), 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (int j = 0; j < d; ++j)
        for (int k = 0; k < 4; ++k) xs[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)] += cube.point(i)[4 * j + k];
    ps.coords = Values(std::move(xs));
    const Facets right = cpu::hull_d(ps);
    std::set<Index> verts;
    for (const auto& x : right) verts.insert(x.begin(), x.end());
    cpu::HullDCertifyStats cs;
    REQUIRE(cpu::hull_d_problem(ps, right, &cs).empty());
    REQUIRE(cs.ball);
    const std::size_t others = ps.size() - verts.size() - 1;  // not vertices, nor the centre v
    INFO(cs.walked << " of " << others << " points walked");
    REQUIRE(cs.walked * 4 < others);
    // the ball of each smaller hull does not hide the vertex left outside
    outside_vertices_named(ps, verts, 6, [](const cpu::HullDCertifyStats& cm) { return cm.ball; });
  }
}

// 6D..9D (orientations of 7..10 points; 9 and 10: the predicates' host-only
// path): against the definition and certified
TEST_CASE("hull_d: 6D..9D sets against the definition, certified (shrinking)", "[hull_d]") {
  for (int d : {6, 7, 8, 9})
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets: hull_d == the definition, certified",
                      d <= 7 ? 64 : 32, [d] {
      const PointSet ps = *test::degenerate_points_d(d, d + 1, d + (d <= 7 ? 12 : 6), false);
      bool spanning = true;
      try {
        const Facets f = cpu::hull_d(ps);
        RC_ASSERT(definition_holds(ps, f));
        RC_ASSERT(cpu::hull_d_problem(ps, f).empty());
      } catch (const std::invalid_argument&) {
        spanning = false;
      }
      RC_ASSERT(spanning == dimension_problem(ps).empty());
    });
}

// The certifier's "points-inside" walks run in pieces of 8192 points in
// parallel (hull_d.cpp, points_inside): on 30,000 points (four pieces) the
// verdict and the message are the same at 1 and 4 threads, for the true hull
// and for the hull of all but one point outside it (the first failing point
// in Morton order named). Also in make tsan's selection.
TEST_CASE("hull_d: the parallel construction gives the same facets at 1, 2 and 4 threads", "[hull_d]") {
  // large enough that insertions walk their orphans in parallel pieces
  for (int d : {4, 5}) {
    const PointSet ps = test::xorshift_cube(d, d == 4 ? 30000 : 12000, -0.5);
    Facets one, two, four;
    cpu::HullDStats st1, st4;
    cpu::with_threads(1, [&] { one = cpu::hull_d(ps, &st1); });
    cpu::with_threads(2, [&] { two = cpu::hull_d(ps); });
    cpu::with_threads(4, [&] { four = cpu::hull_d(ps, &st4); });
    INFO("d = " << d);
    REQUIRE(st4.parallel_batches > 0);
    REQUIRE(one == two);
    REQUIRE(one == four);
    REQUIRE(cpu::hull_d_problem(ps, one).empty());
  }
}

TEST_CASE("hull_d: the parallel certifier gives one verdict and message at 1 and 4 threads", "[hull_d]") {
  const PointSet ps = test::xorshift_cube(4, 30000, -0.5);
  const Facets f = cpu::hull_d(ps);
  std::string one, four;
  cpu::with_threads(1, [&] { one = cpu::hull_d_problem(ps, f); });
  cpu::with_threads(4, [&] { four = cpu::hull_d_problem(ps, f); });
  REQUIRE(one.empty());
  REQUIRE(four.empty());
  // two points far outside, appended: the facets no longer hold every point
  PointSet out = ps;
  for (double x : {2.0, 2.0, 2.0, 2.0, -3.0, 1.0, 0.0, 0.0}) out.coords.push_back(x);
  cpu::with_threads(1, [&] { one = cpu::hull_d_problem(out, f); });
  cpu::with_threads(4, [&] { four = cpu::hull_d_problem(out, f); });
  INFO(one);
  REQUIRE(one.rfind("points-inside: point 3000", 0) == 0);
  REQUIRE(four == one);
}

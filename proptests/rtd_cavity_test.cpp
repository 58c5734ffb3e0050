// rtd_cavity_test.cpp — the d-dimensional cavity-insertion kernel
// (kernels_cpu/rtd, cpu backend of `rtd --dim 2|4|5` and of Python's 4D/5D
// Delaunay) against the exact sequential reference RT+1
// (ref::rtd_incremental): the same canonical simplices and redundant points
// for every input in d = 2..5, weighted or not, nearest- and furthest-site,
// degenerate inputs included, at two BRIO settings and two thread counts of
// its sort; consistent counters; the same rejection of bad input; and every
// answer certified by certify::rtd.
//
// Oracles: ref::rtd_incremental (tested against brute force over simplices
// and CGAL in rtd_reference_test.cpp and the oracle_* tests) and certify::rtd
// (witness-free). Case counts: RC_PARAMS max_success = 2000 under ctest,
// divided per property by prop_scaled (the divisor in each call).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "kernels_cpu/rtd/rtd_cavity.hpp"
#include "kernels_cpu/rtd/visible_region.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/neighbours.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

namespace {

std::string text_of(const ref::Rtd& r) {
  std::ostringstream os;
  write_simplices(os, r.simplices);
  os << "redundant";
  for (Index x : r.redundant) os << ' ' << x;
  return os.str();
}

std::string ref_text(const PointSet& ps, bool furthest) {
  try {
    return text_of(ref::rtd_incremental(ps, nullptr, furthest));
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

struct Setting {
  std::size_t brio;
  int threads;
  double parallel_min_ns = 40e3;
};
// {1, 1}: a cavity's cells tested one by one (visible_region); 2 and 3
// threads: the filters first, then the wave's undecided cells
// (visible_region_waves), in parallel where the work is estimated to pay
// (2 threads) or wherever there are two of them (3 threads: the parallel
// path on small inputs too), which must do the same search: {1, 3} against
// {1, 1}, the same counters
constexpr Setting kSettings[] = {{1, 1}, {64, 2}, {1, 3, 0.0}};

// the kernel's answer as text (or "error: " and the message); *out receives it
std::string cavity_text(const PointSet& ps, bool furthest, const Setting& s, cpu::RtdCavityStats* st,
                        ref::Rtd* out = nullptr) {
  cpu::RtdCavityOptions o;
  o.brio_min = s.brio;
  o.threads = s.threads;
  o.parallel_min_ns = s.parallel_min_ns;
  o.furthest = furthest;
  try {
    ref::Rtd r = cpu::rtd_cavity(ps, st, o);
    std::string text = text_of(r);
    if (out) *out = std::move(r);
    return text;
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

bool is_error(const std::string& s) { return s.rfind("error: ", 0) == 0; }

// kernel == reference in both settings; the counters add up (every point one
// of the first d+1, inserted, or discarded when located; the redundant points
// are the discarded and the removed ones); the answer certified.
template <class Assert>
void check(const PointSet& ps, bool furthest, const Assert& require) {
  const std::string expect = ref_text(ps, furthest);
  cpu::RtdCavityStats sts[std::size(kSettings)];
  for (std::size_t k = 0; k < std::size(kSettings); ++k) {
    cpu::RtdCavityStats& st = sts[k];
    ref::Rtd r;
    require(cavity_text(ps, furthest, kSettings[k], &st, &r) == expect);
    if (!is_error(expect)) {
      require(st.inserted + st.discarded == ps.size());
      require(st.discarded + st.removed == r.redundant.size());
      require(certify::rtd(ps, r.simplices, certify::Level::canonical, furthest).ok);
    }
  }
  // the same BRIO order, one thread and three: the same insertions, walks and cavities
  const cpu::RtdCavityStats &a = sts[0], &b = sts[2];
  require(a.inserted == b.inserted && a.placed == b.placed && a.discarded == b.discarded && a.removed == b.removed &&
          a.cavity == b.cavity && a.created == b.created && a.walk_steps == b.walk_steps);
}

int nmax_of(int d) { return d <= 3 ? 60 : d == 4 ? 36 : 24; }

// The first n points of ps (and their weights).
PointSet prefix(const PointSet& ps, std::size_t n) {
  PointSet p;
  p.dim = ps.dim;
  p.weighted = ps.weighted;
  p.coords = Values(std::vector<double>(ps.coords.begin(), ps.coords.begin() + static_cast<std::ptrdiff_t>(n * ps.dim)));
  if (ps.weighted)
    p.weights = Values(std::vector<double>(ps.weights.begin(), ps.weights.begin() + static_cast<std::ptrdiff_t>(n)));
  return p;
}

// the flat seed of RtdCavityIncremental's second constructor: the cells and
// their neighbours (by test::neighbours_by_search unless given)
struct FlatSeed {
  std::vector<Index> cells;
  std::vector<std::int64_t> nb;
};
FlatSeed flat_seed(const std::vector<std::vector<Index>>& cells, std::vector<std::vector<std::int64_t>> nb = {}) {
  if (nb.empty()) nb = test::neighbours_by_search(cells);
  FlatSeed f;
  for (const auto& c : cells) f.cells.insert(f.cells.end(), c.begin(), c.end());
  for (const auto& row : nb) f.nb.insert(f.nb.end(), row.begin(), row.end());
  return f;
}

// In-place insertion in batches: built from the shortest spanning prefix or a
// longer one, then the rest in `cuts` batches; after every batch the
// answer equals the one-shot kernel on the points so far, and at the end the
// reference on all of them, certified; the counters add up. seeded: the
// kernel is seeded with the one-shot kernel's answer on the prefix and the
// neighbours found by search (Python's Delaunay(incremental=True) in 2D and
// 3D: the one-shot kernels' certified answer, then in-place adds).
template <class Assert>
void check_batches(const PointSet& ps, bool furthest, const std::vector<std::size_t>& cuts, std::size_t start_extra,
                   const Assert& require, bool seeded = false, int threads = 1) {
  std::size_t k = static_cast<std::size_t>(ps.dim) + 1;
  while (k <= ps.size() && !dimension_problem(prefix(ps, k)).empty()) ++k;
  if (k > ps.size()) return;  // lower-dimensional: the one-shot test covers the rejection
  k = std::min(ps.size(), k + start_extra);
  cpu::RtdCavityOptions o;
  o.furthest = furthest;
  o.threads = threads;
  o.parallel_min_ns = 0.0;  // (threads 2: every wave of two undecided cells or more in parallel)
  const ref::Rtd first = cpu::rtd_cavity(prefix(ps, k), nullptr, o);
  const FlatSeed seed = seeded ? flat_seed(first.simplices) : FlatSeed{};
  cpu::RtdCavityIncremental inc = seeded ? cpu::RtdCavityIncremental(prefix(ps, k), seed.cells, seed.nb, o)
                                         : cpu::RtdCavityIncremental(prefix(ps, k), o);
  require(text_of(inc.result()) == text_of(first));
  std::vector<std::size_t> at;
  for (std::size_t c : cuts)
    if (c > k && c < ps.size()) at.push_back(c);
  std::sort(at.begin(), at.end());
  at.push_back(ps.size());
  for (std::size_t n : at) {
    if (n == inc.size()) continue;
    const PointSet p = prefix(ps, n);
    inc.add(p);
    require(inc.size() == n);
    require(text_of(inc.result()) == text_of(cpu::rtd_cavity(p, nullptr, o)));
  }
  const ref::Rtd r = inc.result();
  require(text_of(r) == ref_text(ps, furthest));
  require(certify::rtd(ps, r.simplices, certify::Level::canonical, furthest).ok);
  const cpu::RtdCavityStats st = inc.stats();
  require(st.inserted + st.discarded == (seeded ? ps.size() - k : ps.size()));  // a seed inserts nothing
}

}  // namespace

TEST_CASE("rtd cavity: a kernel seeded with a certified triangulation, then points added in batches, equals the "
          "one-shot kernel and the reference (shrinking)",
          "[rtd_cavity]") {
  for (int d = 2; d <= 5; ++d)
    for (bool weighted : {false, true})
      test::prop_scaled("degenerate " + std::to_string(d) + "D sets, " + (weighted ? "weighted" : "unweighted") +
                            ": seeded kernel + batches == rtd_cavity == RT+1, certified",
                        d <= 3 ? 8 : 16, [d, weighted] {
                          const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax_of(d), weighted);
                          const auto cuts = *rc::gen::container<std::vector<std::size_t>>(
                              *rc::gen::inRange(0, 5), rc::gen::inRange<std::size_t>(0, ps.size() + 1));
                          check_batches(ps, false, cuts, *rc::gen::inRange<std::size_t>(0, 6),
                                        [](bool ok) { RC_ASSERT(ok); }, true);
                        });
}

// visible_region_waves against visible_region on any graph of W links a
// cell and any visibility (not only a triangulation's: the claim is about
// the search), the filters deciding a random part of the cells: the same
// region in the same order, the same horizon calls in the same order, every
// cell decided once; stale stamps of earlier searches left in the marks.
TEST_CASE("rtd cavity: the two-pass search by waves visits as the one-by-one search (shrinking)", "[rtd_cavity]") {
  rc::prop("visible_region_waves == visible_region", [] {
    constexpr int W = 4;
    const std::uint32_t n = *rc::gen::inRange<std::uint32_t>(1, 60);
    std::vector<std::uint32_t> links;
    for (std::uint32_t k = 0; k < n * W; ++k)
      links.push_back(*rc::gen::inRange<std::uint32_t>(0, n) * W + *rc::gen::inRange<std::uint32_t>(0, W));
    const auto sees = *rc::gen::container<std::vector<bool>>(n, rc::gen::arbitrary<bool>());
    const auto filtered = *rc::gen::container<std::vector<bool>>(n, rc::gen::arbitrary<bool>());
    const std::uint32_t root = *rc::gen::inRange<std::uint32_t>(0, n);
    const auto old_marks = *rc::gen::container<std::vector<std::uint32_t>>(n, rc::gen::inRange<std::uint32_t>(0, 8));
    const std::uint32_t in = 8;  // above every old stamp
    struct Call {
      std::uint32_t t;
      int i;
      std::uint32_t l;
      bool operator==(const Call& o) const { return t == o.t && i == o.i && l == o.l; }
    };
    std::vector<std::uint32_t> mark1 = old_marks, region1;
    std::vector<Call> h1;
    std::vector<int> tested1(n, 0);
    cpu::visible_region<W>(root, links, mark1, in, region1, [&](std::uint32_t u) { ++tested1[u]; return bool(sees[u]); },
                           [&](std::uint32_t t, int i, std::uint32_t l) { h1.push_back({t, i, l}); });
    std::vector<std::uint32_t> mark2 = old_marks, region2, pending;
    std::vector<char> result;
    std::vector<Call> h2;
    std::vector<int> tested2(n, 0);
    cpu::visible_region_waves<W>(
        root, links, mark2, in, region2, pending, result,
        [&](std::uint32_t u) {
          ++tested2[u];
          return filtered[u] ? int(sees[u]) : 2;
        },
        [&](const std::uint32_t* cells, std::size_t m, char* r) {
          for (std::size_t k = 0; k < m; ++k) {
            RC_ASSERT(!filtered[cells[k]]);
            r[k] = sees[cells[k]];
          }
        },
        [&](std::uint32_t t, int i, std::uint32_t l) { h2.push_back({t, i, l}); });
    RC_ASSERT(region1 == region2);
    RC_ASSERT(h1 == h2);
    RC_ASSERT(tested1 == tested2);  // each cell tested (by the filters) at most once, the same cells
    for (std::uint32_t u : region2) RC_ASSERT(mark2[u] == in);
  });
}

TEST_CASE("rtd cavity: a seed that is not a triangulation glued along its facets is refused", "[rtd_cavity]") {
  PointSet ps;
  ps.dim = 2;
  ps.coords = Values(std::vector<double>{0, 0, 1, 0, 0, 1, 1, 1, 0.25, 0.5});
  const ref::Rtd r = cpu::rtd_cavity(ps);
  const auto nb = test::neighbours_by_search(r.simplices);
  const FlatSeed good = flat_seed(r.simplices, nb);
  cpu::RtdCavityIncremental kept(ps, good.cells, good.nb);
  REQUIRE(text_of(kept.result()) == text_of(r));
  auto refused = [&](const std::vector<std::vector<Index>>& cells, const std::vector<std::vector<std::int64_t>>& n) {
    const FlatSeed f = flat_seed(cells, n);
    REQUIRE_THROWS_AS(cpu::RtdCavityIncremental(ps, f.cells, f.nb), std::invalid_argument);
  };
  auto swapped = nb;
  std::swap(swapped[0][0], swapped[0][1]);
  refused(r.simplices, swapped);
  auto beyond = nb;  // a neighbour that is not a simplex
  beyond[0][0] = static_cast<std::int64_t>(r.simplices.size());
  refused(r.simplices, beyond);
  auto open = nb;  // one side of an inner edge claimed on the hull: the other names it still
  const auto inner = std::find_if(open[0].begin(), open[0].end(), [](std::int64_t g) { return g >= 0; });
  REQUIRE(inner != open[0].end());
  *inner = -1;
  refused(r.simplices, open);
  auto repeated = r.simplices;
  repeated[0][1] = repeated[0][0];
  refused(repeated, nb);
  auto far = r.simplices;
  far[0][2] = 9;
  refused(far, nb);
  cpu::RtdCavityOptions furthest;
  furthest.furthest = true;
  REQUIRE_THROWS_AS(cpu::RtdCavityIncremental(ps, good.cells, good.nb, furthest), std::invalid_argument);
  REQUIRE_THROWS_AS(cpu::RtdCavityIncremental(ps, std::vector<Index>(good.cells.begin(), good.cells.end() - 1), good.nb),
                    std::invalid_argument);
}

TEST_CASE("rtd cavity: degenerate and random sets in 2D..5D equal the reference, certified (shrinking)",
          "[rtd_cavity]") {
  for (int d = 2; d <= 5; ++d)
    for (bool weighted : {false, true})
      test::prop_scaled("degenerate " + std::to_string(d) + "D sets of " + std::to_string(d + 1) + ".." +
                            std::to_string(nmax_of(d)) + " points, " + (weighted ? "weighted" : "unweighted") +
                            ": cavity kernel == RT+1 byte for byte, certified",
                        d <= 3 ? 8 : 16, [d, weighted] {
                          const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax_of(d), weighted);
                          check(ps, false, [](bool ok) { RC_ASSERT(ok); });
                        });
}

// 6D..9D (power tests of 8..11 points: the predicates' host-only path from 9
// rows on): small degenerate sets, a fraction of the cases (RT+1's flips and
// the GMP stage are slow there)
TEST_CASE("rtd cavity: degenerate sets in 6D..9D equal the reference, certified (shrinking)", "[rtd_cavity]") {
  for (int d = 6; d <= 9; ++d)
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets of " + std::to_string(d + 1) + ".." +
                          std::to_string(d + 5) + " points, weighted: cavity kernel == RT+1 byte for byte, certified",
                      d <= 7 ? 20 : d == 8 ? 50 : 100, [d] {
                        const PointSet ps = *test::degenerate_points_d(d, d + 1, d + 5, true);
                        check(ps, false, [](bool ok) { RC_ASSERT(ok); });
                        check(ps, true, [](bool ok) { RC_ASSERT(ok); });
                      });
}

TEST_CASE("rtd cavity: furthest-site triangulations in 2D..5D equal the reference (shrinking)", "[rtd_cavity]") {
  for (int d = 2; d <= 5; ++d)
    test::prop_scaled("degenerate " + std::to_string(d) + "D sets, furthest site: cavity kernel == RT+1 with every "
                                                          "lifted sign negated, certified",
                      d <= 3 ? 16 : 32, [d] {
                        const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax_of(d), false);
                        check(ps, true, [](bool ok) { RC_ASSERT(ok); });
                      });
}

// Lattices, where every predicate call of the insertion is exactly
// degenerate and decided by the perturbation.
TEST_CASE("rtd cavity: integer grids in 4D and 5D, unweighted and with lattice weights, equal the reference",
          "[rtd_cavity]") {
  for (int d : {4, 5})
    for (int side : {2, 3}) {
      if (d == 5 && side == 3) continue;  // 243 points: the [long] case below
      PointSet ps;
      ps.dim = d;
      int n = 1;
      for (int j = 0; j < d; ++j) n *= side;
      std::vector<double> c, w;
      for (int i = 0; i < n; ++i) {
        int x = i;
        for (int j = 0; j < d; ++j, x /= side) c.push_back(x % side);
        w.push_back((i % 3) * 0.25);
      }
      ps.coords = Values(std::move(c));
      INFO(d << "D grid of side " << side);
      check(ps, false, [](bool ok) { REQUIRE(ok); });
      ps.weighted = true;
      ps.weights = Values(std::move(w));
      check(ps, false, [](bool ok) { REQUIRE(ok); });
    }
}

// Exact copies: 150 random 4D points each 1 to 4 times, shuffled. The copy of
// largest index is the one that can be a vertex; the others wait until it
// is in (rtd_cavity.cpp, insert_range) and are found redundant when located:
// few vertices are removed again (at most n/20 here; with every copy
// inserted as it came, 15765 of 28010 points of such an input).
TEST_CASE("rtd cavity: exact copies wait for the one that can be a vertex", "[rtd_cavity]") {
  const PointSet base = test::xorshift_cube(4, 150);
  std::vector<std::size_t> pick;
  for (std::size_t i = 0; i < base.size(); ++i)
    for (std::size_t r = 0; r <= (i * 7) % 4; ++r) pick.push_back(i);
  std::mt19937_64 rng(9);
  std::shuffle(pick.begin(), pick.end(), rng);
  PointSet ps;
  ps.dim = 4;
  std::vector<double> c;
  for (std::size_t i : pick) c.insert(c.end(), base.point(i), base.point(i) + 4);
  ps.coords = Values(std::move(c));
  check(ps, false, [](bool ok) { REQUIRE(ok); });
  for (const Setting& s : kSettings) {
    cpu::RtdCavityStats st;
    cavity_text(ps, false, s, &st);
    INFO("removed " << st.removed << ", discarded " << st.discarded);
    REQUIRE(st.removed <= ps.size() / 20);
  }
}

TEST_CASE("rtd cavity: the 3^5 grid and 3000 random 4D points equal the reference", "[rtd_cavity][long]") {
  PointSet grid;
  grid.dim = 5;
  std::vector<double> c;
  for (int i = 0; i < 243; ++i) {
    int x = i;
    for (int j = 0; j < 5; ++j, x /= 3) c.push_back(x % 3);
  }
  grid.coords = Values(std::move(c));
  check(grid, false, [](bool ok) { REQUIRE(ok); });
  const PointSet r4 = test::xorshift_cube(4, 3000);
  check(r4, false, [](bool ok) { REQUIRE(ok); });
}

TEST_CASE("rtd cavity: in-place insertion in batches equals the one-shot kernel and the reference (shrinking)",
          "[rtd_cavity]") {
  for (int d = 2; d <= 6; ++d)
    for (bool furthest : {false, true})
      test::prop_scaled("degenerate " + std::to_string(d) + "D sets" + (furthest ? ", furthest site" : "") +
                            ", added in random batches: every intermediate answer == the one-shot kernel, the last "
                            "== RT+1, certified",
                        d <= 3 ? 8 : d <= 5 ? 16 : 40, [d, furthest] {
                          const int nmax = d == 6 ? 14 : nmax_of(d);
                          const PointSet ps = *test::degenerate_points_d(d, d + 1, nmax, !furthest);
                          const auto cuts = *rc::gen::container<std::vector<std::size_t>>(
                              *rc::gen::inRange(0, 6), rc::gen::inRange<std::size_t>(0, ps.size() + 1));
                          const std::size_t extra = *rc::gen::inRange<std::size_t>(0, 4);
                          const int threads = *rc::gen::element(1, 2);
                          check_batches(ps, furthest, cuts, extra, [](bool ok) { RC_ASSERT(ok); }, false, threads);
                        });
}

// Bad added points change nothing; a point set that is not the old one
// extended is refused.
TEST_CASE("rtd cavity: in-place insertion rejects bad points and keeps its state", "[rtd_cavity]") {
  PointSet ps;
  ps.dim = 3;
  ps.coords = Values(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0.5, 0.5, 0.5});
  cpu::RtdCavityIncremental inc(prefix(ps, 5));
  const std::string before = text_of(inc.result());
  PointSet bad = ps;
  std::vector<double> v(ps.coords.begin(), ps.coords.end());
  v.back() = std::nan("");
  bad.coords = Values(std::move(v));
  REQUIRE_THROWS_AS(inc.add(bad), std::invalid_argument);
  REQUIRE(text_of(inc.result()) == before);
  REQUIRE(inc.size() == 5);
  REQUIRE_THROWS_AS(inc.add(prefix(ps, 4)), std::invalid_argument);  // fewer points than given
  PointSet other = ps;
  other.dim = 2;
  REQUIRE_THROWS_AS(inc.add(other), std::invalid_argument);
  inc.add(ps);
  REQUIRE(text_of(inc.result()) == ref_text(ps, false));
  REQUIRE_THROWS_AS(cpu::RtdCavityIncremental(prefix(ps, 3)), std::invalid_argument);  // too few to span
}

TEST_CASE("rtd cavity: bad input is rejected as the reference rejects it", "[rtd_cavity]") {
  PointSet flat;  // 4D points in a hyperplane
  flat.dim = 4;
  flat.coords = Values(std::vector<double>{0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 1, 0, 2, 3, 1, 0});
  const std::string e = cavity_text(flat, false, kSettings[0], nullptr);
  REQUIRE(is_error(e));
  REQUIRE(e == ref_text(flat, false));
  PointSet nan = flat;
  std::vector<double> v(nan.coords.begin(), nan.coords.end());
  v[4 * 4 + 3] = 5;  // now spanning
  v[2] = std::nan("");
  nan.coords = Values(std::move(v));
  REQUIRE(cavity_text(nan, false, kSettings[0], nullptr) == ref_text(nan, false));
  REQUIRE(is_error(ref_text(nan, false)));
  PointSet few;
  few.dim = 5;
  few.coords = Values(std::vector<double>(5 * 5, 1.0));
  REQUIRE(is_error(cavity_text(few, false, kSettings[0], nullptr)));
  REQUIRE(cavity_text(few, false, kSettings[0], nullptr) == ref_text(few, false));
}

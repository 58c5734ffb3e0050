// rtd_strict_test.cpp — the strict view of d-dimensional regular
// triangulations (reference/rtd/strict_rtd.hpp, `flipflop rtd --strict`) and
// its predicate pred::power_d_pulled, against independent oracles:
//   the pulled predicate   a brute-force expansion of the perturbed
//                          determinant: every term (a set of perturbed
//                          coordinate entries and at most one pulled height)
//                          with its order computed from the exponents of
//                          predicates.hpp, sorted, each coefficient the
//                          determinant (GMP rationals) of Λ with the chosen
//                          rows replaced by unit rows — no minor search;
//   the view               certify::rtd at Level::exact (a regular
//                          triangulation of the exact input, every simplex of
//                          positive volume), an exact rational volume sign,
//                          the vertex rule checked point by point with exact
//                          predicates, and the pulling triangulation's count
//                          of simplices per cube of a grid (d! per d-cube:
//                          the cone from the pulled corner over the pulling
//                          triangulations of the d facets missing it).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <gmpxx.h>

#include <algorithm>
#include <functional>
#include <random>
#include <vector>

#include "predicates/predicates.hpp"
#include "proptests/support/mpq_det.hpp"
#include "proptests/support/rtd_inputs.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/strict_rtd.hpp"

using namespace flipflop;

namespace {


// The pulled perturbation by brute force (predicates.hpp, power_d_pulled):
// coordinate j (1-based) of the point of rank i (1-based, by id) gets
// +δ^(2^(i(d+1) - j)); every height h becomes h + ε1 |x|^2 - ε2^(rank),
// ε1 >> ε2 >> δ. A term is a set of perturbed coordinate entries (distinct
// rows and columns) and one of: the heights h, the heights replaced by the
// ε1 column |x|^2, or one pulled height (another row); terms compare by their
// δ-exponent sets (as binary numbers: the largest exponent first), then h <
// ε1 < pulls, pulls by rank.
int pulled_oracle(int d, const std::vector<pred::WPt>& p) {
  const int k = d + 2;
  std::vector<int> rank(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) {
    rank[static_cast<std::size_t>(i)] = 1;
    for (int j = 0; j < k; ++j)
      if (p[static_cast<std::size_t>(j)].id < p[static_cast<std::size_t>(i)].id) ++rank[static_cast<std::size_t>(i)];
  }
  std::vector<std::vector<mpq_class>> lam(static_cast<std::size_t>(k), std::vector<mpq_class>(static_cast<std::size_t>(k)));
  for (int i = 0; i < k; ++i) {
    mpq_class h = -mpq_class(p[static_cast<std::size_t>(i)].w);
    for (int j = 0; j < d; ++j) {
      const mpq_class x(p[static_cast<std::size_t>(i)].x[j]);
      lam[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = x;
      h += x * x;
    }
    lam[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)] = h;
    lam[static_cast<std::size_t>(i)][static_cast<std::size_t>(d + 1)] = 1;
  }
  struct Term {
    std::vector<int> exps;  // δ exponents, descending
    int pulled_rank = 0;    // 0: no pulled height; -1: the ε1 column
    std::vector<int> col;   // per row: chosen column or -1
  };
  std::vector<Term> terms;
  std::vector<int> col(static_cast<std::size_t>(k), -1);
  std::vector<char> used(static_cast<std::size_t>(d + 1), 0);
  std::function<void(int)> rec = [&](int r) {
    if (r == k) {
      Term t;
      t.col = col;
      for (int i = 0; i < k; ++i) {
        const int c = col[static_cast<std::size_t>(i)];
        if (c < 0) continue;
        if (c == d) t.pulled_rank = rank[static_cast<std::size_t>(i)];
        else t.exps.push_back(rank[static_cast<std::size_t>(i)] * (d + 1) - (c + 1));
      }
      std::sort(t.exps.rbegin(), t.exps.rend());
      terms.push_back(t);
      if (t.pulled_rank == 0) {  // the same with the ε1 column
        t.pulled_rank = -1;
        terms.push_back(std::move(t));
      }
      return;
    }
    rec(r + 1);
    for (int c = 0; c <= d; ++c) {
      if (used[static_cast<std::size_t>(c)]) continue;
      used[static_cast<std::size_t>(c)] = 1;
      col[static_cast<std::size_t>(r)] = c;
      rec(r + 1);
      col[static_cast<std::size_t>(r)] = -1;
      used[static_cast<std::size_t>(c)] = 0;
    }
  };
  rec(0);
  std::sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) {
    // binary numbers with these set bits: compare from the top bit
    const std::size_t n = std::min(a.exps.size(), b.exps.size());
    for (std::size_t i = 0; i < n; ++i)
      if (a.exps[i] != b.exps[i]) return a.exps[i] < b.exps[i];
    if (a.exps.size() != b.exps.size()) return a.exps.size() < b.exps.size();
    auto order = [](int r) { return r == 0 ? -1 : r == -1 ? 0 : r; };  // h, ε1, pulls
    return order(a.pulled_rank) < order(b.pulled_rank);
  });
  for (const Term& t : terms) {
    auto m = lam;
    if (t.pulled_rank == -1)
      for (int i = 0; i < k; ++i) {
        mpq_class q = 0;
        for (int j = 0; j < d; ++j) q += lam[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] *
                                         lam[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        m[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)] = q;
      }
    bool pulled = false;
    for (int i = 0; i < k; ++i) {
      const int c = t.col[static_cast<std::size_t>(i)];
      if (c < 0) continue;
      for (int j = 0; j < k; ++j) m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = (j == c) ? 1 : 0;
      pulled = pulled || c == d;
    }
    if (const int s = test::mpq_det_sign(m)) return pulled ? -s : s;
  }
  return 0;
}

// d+2 points of small integer coordinates (and weights), some repeated: the
// exactly degenerate cases the pulls and the coordinate perturbation decide
void check_pulled(int d, const std::vector<double>& xs, const std::vector<double>& ws, const std::vector<pred::PointId>& ids) {
  std::vector<pred::WPt> p;
  for (int i = 0; i < d + 2; ++i)
    p.push_back({ids[static_cast<std::size_t>(i)], xs.data() + i * d, ws[static_cast<std::size_t>(i)]});
  const int want = pulled_oracle(d, p);
  RC_ASSERT(want != 0);
  RC_ASSERT(pred::power_d_pulled(d, p.data()) == want);
  RC_ASSERT(pred::power_d_pulled(d, p.data(), pred::Mode::gmp) == want);
  // the exact sign, where it is not 0
  std::vector<const double*> rows;
  std::vector<double> w;
  for (const auto& q : p) {
    rows.push_back(q.x);
    w.push_back(q.w);
  }
  const int exact = pred::power_d_exact(d, rows.data(), w.data());
  if (exact != 0) RC_ASSERT(want == exact);
}

// The vertex rule of strict_rtd.hpp, point by point: every vertex of the
// canonical answer V is a vertex of the view unless it coincides with a kept
// vertex of larger weight or equal weight and smaller index, or its lifted
// point lies strictly above the lifted simplex of the view that contains it.
void check_view(const PointSet& ps, const std::vector<std::vector<Index>>& canonical,
                const std::vector<std::vector<Index>>& view) {
  const int d = ps.dim;
  const certify::Report r = certify::rtd(ps, view, certify::Level::exact);
  INFO(r.message());
  REQUIRE(r.ok);
  for (const auto& t : view) REQUIRE(test::exact_volume_sign(ps, t) == 1);  // positive volume, canonical orientation
  const std::vector<Index> miss_c = non_vertices(ps.size(), canonical);
  const std::vector<Index> miss_v = non_vertices(ps.size(), view);
  std::vector<char> in_view(ps.size(), 1);
  for (Index x : miss_v) in_view[x] = 0;
  for (Index x : miss_v) {
    if (std::binary_search(miss_c.begin(), miss_c.end(), x)) continue;  // not in V
    bool explained = false;
    for (Index y = 0; y < ps.size() && !explained; ++y) {
      if (!in_view[y] || y == x) continue;
      if (!std::equal(ps.point(x), ps.point(x) + d, ps.point(y))) continue;
      explained = ps.weight(y) > ps.weight(x) || (ps.weight(y) == ps.weight(x) && y < x);
    }
    for (const auto& t : view) {
      if (explained) break;
      const double* q[8];
      bool inside = true;
      for (int i = 0; i <= d && inside; ++i) {  // x in the closed simplex: replace each vertex by x
        for (int j = 0; j <= d; ++j) q[j] = ps.point(t[static_cast<std::size_t>(j)]);
        const int full = pred::orient_d_exact(d, q);
        q[i] = ps.point(x);
        const int s = pred::orient_d_exact(d, q);
        inside = s == 0 || s == full;
      }
      if (!inside) continue;
      // orient_d-positive order of t (canonical tuples are volume-positive)
      std::vector<Index> o = t;
      switch_orientation_convention(o);
      const double* rows[8];
      double w[8];
      for (int j = 0; j <= d; ++j) {
        rows[j] = ps.point(o[static_cast<std::size_t>(j)]);
        w[j] = ps.weight(o[static_cast<std::size_t>(j)]);
      }
      rows[d + 1] = ps.point(x);
      w[d + 1] = ps.weight(x);
      explained = pred::power_d_exact(d, rows, w) < 0;  // strictly above
    }
    INFO("vertex " << x << " of the canonical answer is missing from the strict view without reason");
    REQUIRE(explained);
  }
}

void check_family(const PointSet& ps) {
  const ref::Rtd c = ref::rtd_incremental(ps);
  const auto view = ref::strict_rtd(ps, c.simplices);
  check_view(ps, c.simplices, view);
}

}  // namespace

TEST_CASE("rtd strict: power_d_pulled equals the brute-force expansion of its perturbation (d 2, 3)") {
  for (int d : {2, 3}) {
    INFO("d=" << d);
    rc::prop("pulled sign", [d] {
      const int k = d + 2;
      const int r = *rc::gen::inRange(1, 4);
      std::vector<double> xs;
      for (int i = 0; i < k; ++i) {
        const bool copy = i > 0 && *rc::gen::inRange(0, 4) == 0;  // a quarter: a copy of an earlier point
        const int src = copy ? *rc::gen::inRange(0, i) : i;
        for (int j = 0; j < d; ++j)
          xs.push_back(src == i ? static_cast<double>(*rc::gen::inRange(-r, r + 1))
                                : xs[static_cast<std::size_t>(src * d + j)]);
      }
      // weights: none, small integers, or all lifted points on one hyperplane
      // (w = |x|^2 - a.x - c: det Λ = 0, the ε1 term decides)
      const int mode = *rc::gen::inRange(0, 3);
      std::vector<int> a(static_cast<std::size_t>(d + 1));
      for (int& v : a) v = *rc::gen::inRange(-2, 3);
      std::vector<double> ws;
      for (int i = 0; i < k; ++i) {
        double w = 0;
        if (mode == 1) w = static_cast<double>(*rc::gen::inRange(0, 3));
        if (mode == 2) {
          w = -a[static_cast<std::size_t>(d)];
          for (int j = 0; j < d; ++j) {
            const double x = xs[static_cast<std::size_t>(i * d + j)];
            w += x * x - a[static_cast<std::size_t>(j)] * x;
          }
        }
        ws.push_back(w);
      }
      std::vector<pred::PointId> ids;  // distinct, in a random order
      for (int i = 0; i < k; ++i) ids.push_back(static_cast<pred::PointId>(i * 5 + *rc::gen::inRange(0, 5)));
      for (int i = k - 1; i > 0; --i)
        std::swap(ids[static_cast<std::size_t>(i)], ids[static_cast<std::size_t>(*rc::gen::inRange(0, i + 1))]);
      check_pulled(d, xs, ws, ids);
    });
  }
}

TEST_CASE("rtd strict: power_d_pulled equals the brute-force expansion in 4D on lattice tuples") {
  std::mt19937_64 g(7);
  int degenerate = 0;
  for (int it = 0; it < 300; ++it) {
    const int d = 4, k = 6;
    std::vector<double> xs, ws;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < d; ++j) xs.push_back(static_cast<double>(g() % 2));
    for (int i = 0; i < k; ++i) ws.push_back(static_cast<double>(g() % 2));
    std::vector<pred::PointId> ids(k);
    for (int i = 0; i < k; ++i) ids[static_cast<std::size_t>(i)] = static_cast<pred::PointId>(i * 3 + (g() % 3));
    std::shuffle(ids.begin(), ids.end(), g);
    std::vector<pred::WPt> p;
    std::vector<const double*> rows;
    for (int i = 0; i < k; ++i) {
      p.push_back({ids[static_cast<std::size_t>(i)], xs.data() + i * d, ws[static_cast<std::size_t>(i)]});
      rows.push_back(xs.data() + i * d);
    }
    degenerate += pred::power_d_exact(d, rows.data(), ws.data()) == 0;
    const int want = pulled_oracle(d, p);
    REQUIRE(want != 0);
    REQUIRE(pred::power_d_pulled(d, p.data()) == want);
    REQUIRE(pred::power_d_pulled(d, p.data(), pred::Mode::gmp) == want);
  }
  CHECK(degenerate > 100);  // the cases are mostly the ones the perturbation decides
}

TEST_CASE("rtd strict: grids — the pulling triangulation, d! simplices per cube, certified") {
  // {0..r}^d: r^d cubes, each cospherical; the canonical answer has flat simplices
  for (auto [d, r] : {std::pair{3, 3}, std::pair{4, 1}, std::pair{4, 2}}) {
    INFO("d=" << d << " r=" << r);
    const PointSet ps = test::rtd_grid(d, r);
    const ref::Rtd c = ref::rtd_incremental(ps);
    const auto view = ref::strict_rtd(ps, c.simplices);
    std::size_t cubes = 1, fact = 1;
    for (int i = 0; i < d; ++i) {
      cubes *= static_cast<std::size_t>(r);
      fact *= static_cast<std::size_t>(i + 1);
    }
    CHECK(view.size() == cubes * fact);
    CHECK(c.simplices.size() > view.size());  // the canonical answer's flat simplices are gone
    CHECK(!certify::rtd(ps, c.simplices, certify::Level::exact).ok);
    check_view(ps, c.simplices, view);
    // duplicated: one copy of each point remains
    const PointSet dup = test::rtd_duplicated(ps, 2);
    const ref::Rtd cd = ref::rtd_incremental(dup);
    const auto vd = ref::strict_rtd(dup, cd.simplices);
    CHECK(vd.size() == cubes * fact);
    CHECK(non_vertices(dup.size(), vd).size() == ps.size());
    check_view(dup, cd.simplices, vd);
  }
}

TEST_CASE("rtd strict: degenerate families in 3D and 4D (cospherical, ties, weighted lattices) are certified and keep the vertex rule") {
  for (int d = 3; d <= 4; ++d) {
    INFO("d=" << d);
    const PointSet sph = test::rtd_cospherical(d, 2, d == 3 ? 5 : 3, true);
    check_family(sph);
    PointSet wsph = sph;  // the centre orthogonal to every sphere point: lifted exactly on every lower facet
    wsph.weighted = true;
    wsph.weights.assign(wsph.size(), 0.0);
    wsph.weights.back() = d == 3 ? 5 : 3;
    check_family(wsph);
    for (std::uint64_t seed = 1; seed <= (d == 4 ? 4u : 10u) / test::kRtdSanitizerDivisor + 1; ++seed) {
      const PointSet lat = test::rtd_lattice(d, (d == 4 ? 20 : 30) + seed * 3, seed, 2, static_cast<int>(seed % 3));
      if (!dimension_problem(lat).empty()) continue;
      check_family(lat);
    }
  }
}

TEST_CASE("rtd strict: all lifted points on one hyperplane — every vertex kept, the Delaunay view of the same points") {
  // w = |x|^2 - a.x - c: the exact regular subdivision is one cell (conv S),
  // every lifted point on it; the canonical perturbation decides which are
  // vertices (V). The ε1 term makes the view the Delaunay triangulation of V
  // (ties pulled): the strict view of V's points unweighted, in index order.
  for (int d = 3; d <= 4; ++d)
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      INFO("d=" << d << " seed=" << seed);
      PointSet flat = test::rtd_lattice(d, d == 3 ? 25 : 18, seed, 2, 0);
      if (!dimension_problem(flat).empty()) continue;
      flat.weighted = true;
      std::vector<double> w;
      for (std::size_t i = 0; i < flat.size(); ++i) {
        double v = -3.0;  // c
        for (int j = 0; j < d; ++j) {
          const double x = flat.point(i)[j];
          v += x * x - static_cast<double>(j + 1) * x;  // a = (1, 2, ..)
        }
        w.push_back(v);
      }
      flat.weights = w;
      const ref::Rtd c = ref::rtd_incremental(flat);
      const auto view = ref::strict_rtd(flat, c.simplices);
      check_view(flat, c.simplices, view);
      // V's points, unweighted, in index order
      const std::vector<Index> miss = non_vertices(flat.size(), c.simplices);
      std::vector<Index> V;
      PointSet del;
      del.dim = d;
      std::vector<double> coords;
      for (Index i = 0; i < flat.size(); ++i)
        if (!std::binary_search(miss.begin(), miss.end(), i)) {
          V.push_back(i);
          coords.insert(coords.end(), flat.point(i), flat.point(i) + d);
        }
      del.coords = coords;
      const ref::Rtd cd = ref::rtd_incremental(del);
      auto vdel = ref::strict_rtd(del, cd.simplices);
      for (auto& t : vdel)
        for (Index& x : t) x = V[x];
      CHECK(view == vdel);
      // every location of V once
      std::size_t distinct = 0;
      for (std::size_t i = 0; i < V.size(); ++i) {
        bool earlier = false;
        for (std::size_t j = 0; j < i && !earlier; ++j)
          earlier = std::equal(flat.point(V[i]), flat.point(V[i]) + d, flat.point(V[j]));
        distinct += !earlier;
      }
      CHECK(flat.size() - non_vertices(flat.size(), view).size() == distinct);
    }
}

TEST_CASE("rtd strict: the 5-cube and 5D lattices") {
  const PointSet cube = test::rtd_grid(5, 1);
  const ref::Rtd c = ref::rtd_incremental(cube);
  const auto view = ref::strict_rtd(cube, c.simplices);
  CHECK(view.size() == 120);  // 5!
  check_view(cube, c.simplices, view);
  const PointSet lat = test::rtd_lattice(5, 14, 3, 1, 1);
  if (dimension_problem(lat).empty()) check_family(lat);
}

TEST_CASE("rtd strict: general position — the view is the canonical answer") {
  for (int d = 3; d <= 5; ++d)
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const PointSet ps = test::rtd_uniform(d, d == 5 ? 20 : 60, seed, seed % 2 ? 0.01 : 0.0);
      const ref::Rtd c = ref::rtd_incremental(ps);
      CHECK(ref::strict_rtd(ps, c.simplices) == c.simplices);
    }
}

TEST_CASE("rtd strict: d = 2 is the rt2 view, and malformed canonical lists are refused") {
  const PointSet ps = test::rtd_grid(2, 4);
  const ref::Rtd c = ref::rtd_incremental(ps);
  const auto view = ref::strict_rtd(ps, c.simplices);
  CHECK(view.size() == 32);  // 16 squares, 2 triangles each
  check_view(ps, c.simplices, view);
  const PointSet p3 = test::rtd_grid(3, 1);
  CHECK_THROWS_AS(ref::strict_rtd(p3, {{0, 1, 2, 99}}), std::invalid_argument);
  CHECK_THROWS_AS(ref::strict_rtd(p3, {{0, 1, 2}}), std::invalid_argument);
}

// oracle_sos_test.cpp — every Simulation-of-Simplicity predicate of predicates/
// against the independent oracle of proptests/support/sos_oracle.hpp (the
// perturbed determinant expanded term by term, GMP minors, exponents compared
// exactly; no code of predicates/), on every path the API offers:
//   Mode::filtered and Mode::gmp of orient2d/3d, power2d/3d, orient_d (d = 2..6),
//   power_d (d = 2..5), power_d_pulled (d = 2..5), lambda_sign (k = 2..11),
//   compare_sos, mixed_sign (an exact centroid row); the default arguments; the
//   per-input static filter overloads, fast::, after_filters; the stages
//   stage::expansion_sos and stage::gmp_sos.
// Inputs: RapidCheck's families of predicate_inputs.hpp (uniform, 1-3 ulp
// near-degenerate, exactly degenerate with scalings to 2^±1074, extreme
// magnitudes; ids small, stretched to 2^40 or near 2^64) and a deterministic
// sweep (fixed seed) of degenerate configurations — integer flats, lattice
// spheres with equal weights, lifted points on a hyperplane, duplicated and
// identical points, the same with one value moved by 1 ulp — scaled by
// 2^0, 2^±30, 2^±60, with unsorted ids up to 10^9, near 2^64, or repeated
// (the same point twice: 0).
// The last test case plants errors (power3d with its first SoS term flipped,
// two ids swapped in the perturbation order of orient_d(4), the id order of
// power_d_pulled reversed, its ε1 term flipped, orient3d with x and y
// perturbed in the wrong order) and asserts that the oracle comparison fails
// for each, on the same inputs on which the real predicates pass.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "predicates/staged.hpp"
#include "predicates/static_filter.hpp"
#include "proptests/support/predicate_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/sos_oracle.hpp"

using namespace flipflop;
using namespace flipflop::test;
using pred::Mode;
using pred::Pt;
using pred::WPt;
namespace so = flipflop::test::sos_oracle;
namespace xp = flipflop::pred::xp;

namespace {

// ---- the oracle on an Instance ----------------------------------------------------------
so::Result oracle(const Spec& s, const Instance& in) {
  std::vector<so::QRow> rows;
  for (int i = 0; i < in.k; ++i)
    rows.push_back(s.weighted() ? so::lifted_row(in.p(i), in.d, in.w[static_cast<size_t>(i)])
                                : so::coords_row(in.p(i), in.d));
  return so::sos_sign(rows, in.id);
}

so::Result oracle_pulled(const Instance& in) {
  std::vector<so::QRow> rows;
  std::vector<mpq_class> h, q;
  for (int i = 0; i < in.k; ++i) {
    rows.push_back(so::coords_row(in.p(i), in.d));
    q.push_back(so::norm2(in.p(i), in.d));
    h.push_back(q.back() - so::exact(in.w[static_cast<size_t>(i)]));
  }
  return so::pulled_sign(rows, h, q, in.id);
}

std::string term_text(const so::Result& r) {
  std::ostringstream o;
  o << "oracle sign " << r.sign << ", deciding term {";
  for (size_t i = 0; i < r.matched.size(); ++i)
    if (r.matched[i] >= 0) o << " (row " << i << ", col " << r.matched[i] << ")";
  o << " } extra " << r.extra;
  return o.str();
}

bool distinct_ids(const Instance& in) {
  for (int a = 0; a < in.k; ++a)
    for (int b = a + 1; b < in.k; ++b)
      if (in.id[static_cast<size_t>(a)] == in.id[static_cast<size_t>(b)]) return false;
  return true;
}

// Every library path for the predicate `s` on `in`, named.
std::vector<std::pair<std::string, int>> library_paths(const Spec& s, const Instance& in) {
  std::vector<std::pair<std::string, int>> out;
  const int k = in.k;
  std::vector<const double*> p;
  for (int i = 0; i < k; ++i) p.push_back(in.p(i));
  const double* w = s.weighted() ? in.w.data() : nullptr;
  out.push_back({"eval filtered", eval(s, in, true, Mode::filtered)});
  out.push_back({"eval gmp", eval(s, in, true, Mode::gmp)});
  out.push_back({"lambda_sign filtered", pred::lambda_sign(k, in.id.data(), p.data(), w, Mode::filtered)});
  out.push_back({"lambda_sign gmp", pred::lambda_sign(k, in.id.data(), p.data(), w, Mode::gmp)});
  const pred::StaticFilter f =
      pred::StaticFilter::for_points(in.x.data(), static_cast<size_t>(k), in.d, w);
  out.push_back({"lambda_sign static filter", pred::lambda_sign(&f, k, in.id.data(), p.data(), w)});
  if (distinct_ids(in)) {  // the stages take distinct ids
    out.push_back({"stage::expansion_sos", pred::stage::expansion_sos(k, in.id.data(), p.data(), w)});
    out.push_back({"stage::gmp_sos", pred::stage::gmp_sos(k, in.id.data(), p.data(), w)});
  }
  auto pt = [&](int i) { return Pt{in.id[static_cast<size_t>(i)], in.p(i)}; };
  auto wpt = [&](int i) { return WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]}; };
  const bool dd = f.dd_window();
  if (s.kind == Kind::orient2d) {
    out.push_back({"orient2d default", pred::orient2d(pt(0), pt(1), pt(2))});
    out.push_back({"orient2d(f)", pred::orient2d(f, pt(0), pt(1), pt(2))});
    out.push_back({"fast::orient2d", pred::fast::orient2d(f, pt(0), pt(1), pt(2))});
    out.push_back({"after_filters::orient2d", pred::after_filters::orient2d(pt(0), pt(1), pt(2), dd)});
    out.push_back({"after_filters::orient2d, the filter's lattice level",
                   pred::after_filters::orient2d(pt(0), pt(1), pt(2), dd, f.lattice(3, false))});
  } else if (s.kind == Kind::orient3d) {
    out.push_back({"orient3d default", pred::orient3d(pt(0), pt(1), pt(2), pt(3))});
    out.push_back({"orient3d(f)", pred::orient3d(f, pt(0), pt(1), pt(2), pt(3))});
    out.push_back({"fast::orient3d", pred::fast::orient3d(f, pt(0), pt(1), pt(2), pt(3))});
    out.push_back({"after_filters::orient3d", pred::after_filters::orient3d(pt(0), pt(1), pt(2), pt(3), dd)});
    out.push_back({"after_filters::orient3d, the filter's lattice level",
                   pred::after_filters::orient3d(pt(0), pt(1), pt(2), pt(3), dd, f.lattice(4, false))});
  } else if (s.kind == Kind::power2d) {
    out.push_back({"power2d default", pred::power2d(wpt(0), wpt(1), wpt(2), wpt(3))});
    out.push_back({"power2d(f)", pred::power2d(f, wpt(0), wpt(1), wpt(2), wpt(3))});
    out.push_back({"fast::power2d", pred::fast::power2d(f, wpt(0), wpt(1), wpt(2), wpt(3))});
    out.push_back({"after_filters::power2d", pred::after_filters::power2d(wpt(0), wpt(1), wpt(2), wpt(3), dd)});
    out.push_back({"after_filters::power2d, the filter's lattice level",
                   pred::after_filters::power2d(wpt(0), wpt(1), wpt(2), wpt(3), dd, f.lattice(4, true))});
  } else if (s.kind == Kind::power3d) {
    out.push_back({"power3d default", pred::power3d(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4))});
    out.push_back({"power3d(f)", pred::power3d(f, wpt(0), wpt(1), wpt(2), wpt(3), wpt(4))});
    out.push_back({"fast::power3d", pred::fast::power3d(f, wpt(0), wpt(1), wpt(2), wpt(3), wpt(4))});
    out.push_back({"after_filters::power3d",
                   pred::after_filters::power3d(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4), dd)});
    out.push_back({"after_filters::power3d, the filter's lattice level",
                   pred::after_filters::power3d(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4), dd, f.lattice(5, true))});
  } else if (s.kind == Kind::orient_d) {
    std::vector<Pt> pts;
    for (int i = 0; i < k; ++i) pts.push_back(pt(i));
    out.push_back({"orient_d default", pred::orient_d(s.d, pts.data())});
  } else {
    std::vector<WPt> pts;
    for (int i = 0; i < k; ++i) pts.push_back(wpt(i));
    out.push_back({"power_d default", pred::power_d(s.d, pts.data())});
  }
  return out;
}

std::vector<std::pair<std::string, int>> pulled_paths(const Instance& in) {
  std::vector<WPt> pts;
  for (int i = 0; i < in.k; ++i) pts.push_back(WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]});
  return {{"power_d_pulled filtered", pred::power_d_pulled(in.d, pts.data(), Mode::filtered)},
          {"power_d_pulled gmp", pred::power_d_pulled(in.d, pts.data(), Mode::gmp)},
          {"power_d_pulled default", pred::power_d_pulled(in.d, pts.data())}};
}

// "" when every path equals the oracle, else a report.
std::string mismatches(const Spec& s, const Instance& in, so::Result* decided = nullptr,
                       so::Result* decided_pulled = nullptr) {
  std::string bad;
  const so::Result r = oracle(s, in);
  if (decided) *decided = r;
  for (const auto& [name, v] : library_paths(s, in))
    if (v != r.sign) bad += "  " + name + " = " + std::to_string(v) + "\n";
  if (s.weighted()) {
    const so::Result rp = oracle_pulled(in);
    if (decided_pulled) *decided_pulled = rp;
    for (const auto& [name, v] : pulled_paths(in))
      if (v != rp.sign) bad += "  " + name + " = " + std::to_string(v) + " (pulled " + term_text(rp) + ")\n";
  }
  if (!bad.empty()) bad = describe(s, in) + term_text(r) + "\n" + bad;
  return bad;
}

// ---- a deterministic generator of degenerate inputs --------------------------------------
struct Det {
  std::mt19937_64 rng;
  explicit Det(std::uint64_t seed) : rng(seed) {}
  int uni(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  double ints(int lo, int hi) { return static_cast<double>(uni(lo, hi)); }
};

// Families: 0 grid, 1 integer flat, 2 lattice sphere + equal weights, 3 lifted
// on a hyperplane, 4 all points identical, 5 one duplicated point; with
// `nudge` one value is then moved by 1 ulp (near-degenerate).
Instance det_instance(const Spec& s, Det& g, int family, bool near, bool repeat = false) {
  Instance in;
  in.d = s.d;
  in.k = s.points();
  const int d = s.d, k = in.k;
  in.x.assign(static_cast<size_t>(k * d), 0.0);
  in.w.assign(static_cast<size_t>(k), 0.0);
  const bool wt = s.weighted();
  switch (family) {
    case 0:
      for (double& v : in.x) v = g.ints(-2, 2);
      if (wt) for (double& v : in.w) v = g.ints(-2, 2);
      break;
    case 1: {
      const int r = g.uni(0, d - 1);
      std::vector<double> q(static_cast<size_t>(d)), dir(static_cast<size_t>(r * d));
      for (double& v : q) v = g.ints(-8, 8);
      for (double& v : dir) v = g.ints(-3, 3);
      for (int i = 0; i < k; ++i) {  // q + Σ_t c_t dir_t: in an r-flat, r < d
        for (int j = 0; j < d; ++j) in.p(i)[j] = q[static_cast<size_t>(j)];
        for (int t = 0; t < r; ++t) {
          const double c = g.ints(-3, 3);
          for (int j = 0; j < d; ++j) in.p(i)[j] += c * dir[static_cast<size_t>(t * d + j)];
        }
      }
      if (wt) for (double& v : in.w) v = g.ints(-4, 4);
      break;
    }
    case 2: {
      const int r2 = d == 2 ? (g.uni(0, 1) ? 25 : 65) : d == 3 ? (g.uni(0, 1) ? 9 : 50) : (d <= 4 ? 9 : 4);
      const auto& sphere = lattice_sphere(d, r2);
      std::vector<int> c(static_cast<size_t>(d));
      for (int& v : c) v = g.uni(-4, 4);
      const double wall = g.ints(-3, 3);
      for (int i = 0; i < k; ++i) {
        const auto& q = sphere[static_cast<size_t>(g.uni(0, static_cast<int>(sphere.size()) - 1))];
        for (int j = 0; j < d; ++j) in.p(i)[j] = q[static_cast<size_t>(j)] + c[static_cast<size_t>(j)];
        in.w[static_cast<size_t>(i)] = wt ? wall : 0.0;
      }
      break;
    }
    case 3: {
      std::vector<double> a(static_cast<size_t>(d));
      for (double& v : a) v = g.ints(-3, 3);
      const double beta = g.ints(-5, 5);
      for (double& v : in.x) v = g.ints(-6, 6);
      for (int i = 0; i < k; ++i) {
        double w = -beta;
        for (int j = 0; j < d; ++j) w += in.p(i)[j] * (in.p(i)[j] - a[static_cast<size_t>(j)]);
        in.w[static_cast<size_t>(i)] = wt ? w : 0.0;
      }
      if (!wt)  // orientation: points on the integer hyperplane x_d = a·x + beta
        for (int i = 0; i < k; ++i) {
          double v = beta;
          for (int j = 0; j + 1 < d; ++j) v += a[static_cast<size_t>(j)] * in.p(i)[j];
          in.p(i)[d - 1] = v;
        }
      break;
    }
    case 4: {
      for (int j = 0; j < d; ++j) in.p(0)[j] = g.ints(-5, 5);
      in.w[0] = wt ? g.ints(-5, 5) : 0.0;
      for (int i = 1; i < k; ++i) {
        for (int j = 0; j < d; ++j) in.p(i)[j] = in.p(0)[j];
        in.w[static_cast<size_t>(i)] = in.w[0];
      }
      break;
    }
    default: {
      for (double& v : in.x) v = g.ints(-3, 3);
      if (wt) for (double& v : in.w) v = g.ints(-3, 3);
      const int a = g.uni(0, k - 1), b = (a + g.uni(1, k - 1)) % k;
      for (int j = 0; j < d; ++j) in.p(b)[j] = in.p(a)[j];
      in.w[static_cast<size_t>(b)] = in.w[static_cast<size_t>(a)];
      break;
    }
  }
  const int e = std::vector<int>{0, 0, -30, 30, -60, 60}[static_cast<size_t>(g.uni(0, 5))];
  for (double& v : in.x) v = std::ldexp(v, e);
  for (double& v : in.w) v = std::ldexp(v, 2 * e);
  if (near) {
    const int i = g.uni(0, k - 1), j = g.uni(0, wt ? d : d - 1);
    double& v = j < d ? in.p(i)[j] : in.w[static_cast<size_t>(i)];
    v = nudge(v, g.uni(0, 1) ? 1 : -1);
  }
  // ids: distinct and unsorted, up to 10^9, or near 2^64, or 0..k-1
  in.id.resize(static_cast<size_t>(k));
  const int idmode = g.uni(0, 2);
  for (int i = 0; i < k; ++i) {
    for (;;) {
      PointId v = idmode == 0 ? static_cast<PointId>(g.uni(0, 1000000000))
                : idmode == 1 ? ~PointId(0) - static_cast<PointId>(g.uni(0, 20))
                              : static_cast<PointId>(g.uni(0, k - 1));
      if (std::find(in.id.begin(), in.id.begin() + i, v) == in.id.begin() + i) {
        in.id[static_cast<size_t>(i)] = v;
        break;
      }
    }
  }
  if (repeat) {  // the same point twice (same id): 0
    const int a = g.uni(0, k - 1), b = (a + g.uni(1, k - 1)) % k;
    for (int j = 0; j < d; ++j) in.p(b)[j] = in.p(a)[j];
    in.w[static_cast<size_t>(b)] = in.w[static_cast<size_t>(a)];
    in.id[static_cast<size_t>(b)] = in.id[static_cast<size_t>(a)];
  }
  return in;
}

}  // namespace

// ---- the oracle itself on hand-worked values (sos_test.cpp's cases) ------------------------
TEST_CASE("oracle: the oracle reproduces hand-worked SoS signs") {
  auto o2 = [](std::vector<double> a, std::vector<double> b, std::vector<double> c, std::vector<so::Id> ids) {
    return so::sos_sign({so::coords_row(a.data(), 2), so::coords_row(b.data(), 2), so::coords_row(c.data(), 2)},
                        ids)
        .sign;
  };
  // collinear on the x-axis: the smallest id moves up by ε (its y first)
  CHECK(o2({0, 0}, {1, 0}, {2, 0}, {0, 1, 2}) == 1);
  CHECK(o2({0, 0}, {1, 0}, {2, 0}, {1, 0, 2}) == -1);
  CHECK(o2({0, 0}, {1, 0}, {2, 0}, {10, 1000, ~so::Id(0)}) == 1);
  // three copies of one point: (q1-q3) x (q2-q3) = ε^6 - ε^9 > 0
  CHECK(o2({3, -7}, {3, -7}, {3, -7}, {0, 1, 2}) == 1);
  CHECK(o2({3, -7}, {3, -7}, {3, -7}, {1, 0, 2}) == -1);
  CHECK(o2({0, 0}, {0, 0}, {2, 0}, {4, 4, 2}) == 0);  // the same point twice
  CHECK(o2({1, 1}, {0, 0}, {2, 0}, {0, 1, 2}) == 1);  // generic: the exact sign (det 2)
  // power2d, the cocircular unit square with zero weights: -1 for ids 0,1,2,3
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1}, d[2] = {1, 1};
  CHECK(so::sos_sign({so::lifted_row(a, 2, 0), so::lifted_row(b, 2, 0), so::lifted_row(c, 2, 0),
                      so::lifted_row(d, 2, 0)},
                     {0, 1, 2, 3})
            .sign == -1);
  CHECK(so::sos_sign({so::lifted_row(a, 2, 0), so::lifted_row(b, 2, 0), so::lifted_row(c, 2, 0),
                      so::lifted_row(d, 2, 0)},
                     {3, 1, 2, 0})
            .sign == -1);
  // The deciding term of the square (ids 0..3): row 0 (id 0), its height (column 2).
  const so::Result r = so::sos_sign({so::lifted_row(a, 2, 0), so::lifted_row(b, 2, 0),
                                     so::lifted_row(c, 2, 0), so::lifted_row(d, 2, 0)},
                                    {0, 1, 2, 3});
  CHECK(r.size() == 1);
  CHECK(r.matched[0] == 2);
  // power_d_pulled on the same square: det Λ = 0, the ε1 term (the unweighted
  // Λ, the same here) = 0, so the pulls decide, smallest id first: row 0's
  // height lowered, coefficient -cofactor = -orient2d(b, c, d) = +1. Check:
  // the plane through a' = (0,0,-η), b' = (1,0,1), c' = (0,1,1) is
  // h = (1+η)(x+y) - η, at d it is 2 + η > 2 = h_d: d' lies below, d is
  // inside the orthocircle of the counter-clockwise a, b, c: +1.
  {
    const std::vector<so::QRow> xy = {so::coords_row(a, 2), so::coords_row(b, 2), so::coords_row(c, 2),
                                      so::coords_row(d, 2)};
    const std::vector<mpq_class> q = {0, 1, 1, 2};
    const so::Result rp = so::pulled_sign(xy, q, q, {0, 1, 2, 3});
    CHECK(rp.sign == 1);
    CHECK(rp.extra == 2 + 0);
    CHECK(rp.size() == 0);
    // ids reversed: row 3 (d) is pulled: -cofactor of (3, h) = +orient2d(a, b, c) = +1
    // (Laplace sign (-1)^(3+2) = -1, times the pull's -1); d' moves down: inside.
    const so::Result rr = so::pulled_sign(xy, q, q, {3, 2, 1, 0});
    CHECK(rr.sign == 1);
    CHECK(rr.extra == 2 + 3);
  }
  // Same id, different points: outside the definition.
  CHECK_THROWS(o2({0, 0}, {1, 0}, {2, 0}, {4, 4, 2}));
}

// ---- RapidCheck families of predicate_inputs.hpp -----------------------------------------
TEST_CASE("oracle: every SoS predicate and path equals the oracle (random families)") {
  for (const Spec& s : all_specs()) {
    // k = 7 (orient_d(6), power_d(5)) costs most: fewer cases
    const int divisor = s.points() >= 7 ? 4 : 2;
    for (Family fam : kFamilies) {
      prop_scaled(s.name() + ", " + family_name(fam), divisor, [s, fam] {
        const Instance in = gen_instance(s, fam);
        const std::string bad = mismatches(s, in);
        RC_LOG() << bad;
        RC_ASSERT(bad.empty());
      });
    }
  }
}

namespace {

// ---- the deterministic degenerate sweep ----------------------------------------------------
// `scale`: inputs per family and predicate, relative to the Release count
// (RC_PARAMS' max_success / 2000: 1 in make test, 1/20 under the sanitizers).
void degenerate_sweep(std::uint64_t seed, double scale) {
  Det g(seed);
  for (const Spec& s : all_specs()) {
    const int base = s.points() >= 7 ? 40 : s.points() >= 6 ? 80 : 200;
    const int per_family = std::max(5, static_cast<int>(base * scale));
    int total = 0, zeros = 0, deepest = 0;
    int by_eps1 = 0, by_pull = 0, by_coords = 0;  // power_d_pulled's deciding terms
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < per_family; ++rep) {
        const Instance in = det_instance(s, g, fam, rep % 2 == 1, rep % 5 == 4);
        so::Result r, rp;
        const std::string bad = mismatches(s, in, &r, &rp);
        INFO(bad);
        CHECK(bad.empty());
        ++total;
        zeros += r.sign == 0;
        deepest = std::max(deepest, r.size());
        if (s.weighted() && rp.sign != 0) {
          by_eps1 += rp.size() == 0 && rp.extra == 1;
          by_pull += rp.size() == 0 && rp.extra >= 2;
          by_coords += rp.size() > 0;
        }
      }
    INFO(s.name() << ": " << total << " inputs, " << zeros << " with a repeated id, deepest term "
                  << deepest << " entries; pulled decided by ε1 " << by_eps1 << ", by a pull "
                  << by_pull << ", by coordinates " << by_coords);
    // the sweep reaches the repeated-id case and the deepest SoS terms (k
    // identical points: k-1 perturbed entries, one per column), and every
    // kind of term of the pulled perturbation
    CHECK(zeros > 0);
    CHECK(deepest == s.points() - 1);
    if (s.weighted()) {
      CHECK(by_eps1 > 0);
      CHECK(by_pull > 0);
      CHECK(by_coords > 0);
    }
  }
}

double release_scale() {
  return rc::detail::configuration().testParams.maxSuccess / 2000.0;
}

}  // namespace

TEST_CASE("oracle: every SoS predicate and path equals the oracle (degenerate sweep)") {
  degenerate_sweep(20261129, release_scale());
}

TEST_CASE("oracle: every SoS predicate and path equals the oracle (long degenerate sweep)", "[long]") {
  degenerate_sweep(38001, 8 * release_scale());
}

// ---- lambda_sign for k = 2..11 and compare_sos ----------------------------------------------
// k = 9..11 (orient_d in 8D..10D, power_d in 7D..9D) take lambda_sign_high:
// the filters at run time, then GMP; the oracle checks both modes there too.
TEST_CASE("oracle: lambda_sign k = 2..11 and compare_sos equal the oracle") {
  Det g(38);
  for (int k = 2; k <= pred::kMaxLambdaK; ++k)
    for (bool lifted : {false, true}) {
      if (lifted && k < 3) continue;
      const int d = lifted ? k - 2 : k - 1;
      const Spec s{lifted ? Kind::power_d : Kind::orient_d, d};
      const int reps = std::max(2, static_cast<int>((k >= 9 ? 2 : k == 8 ? 4 : 12) * release_scale()));
      for (int fam = 0; fam < 6; ++fam)
        for (int rep = 0; rep < reps; ++rep) {
          const Instance in = det_instance(s, g, fam, rep % 2 == 1);
          const so::Result r = oracle(s, in);
          std::vector<const double*> p;
          for (int i = 0; i < k; ++i) p.push_back(in.p(i));
          const double* w = lifted ? in.w.data() : nullptr;
          INFO(describe(s, in) << term_text(r));
          CHECK(pred::lambda_sign(k, in.id.data(), p.data(), w, Mode::filtered) == r.sign);
          CHECK(pred::lambda_sign(k, in.id.data(), p.data(), w, Mode::gmp) == r.sign);
        }
    }
  // compare_sos: the 1-dimensional Λ of one coordinate column
  for (int rep = 0; rep < std::max(20, static_cast<int>(400 * release_scale())); ++rep) {
    double a[3], b[3];
    for (int j = 0; j < 3; ++j) {
      a[j] = std::ldexp(g.ints(-2, 2), g.uni(-60, 60));
      b[j] = g.uni(0, 1) ? a[j] : std::ldexp(g.ints(-2, 2), g.uni(-60, 60));
    }
    const PointId ia = static_cast<PointId>(g.uni(0, 1000000000)),
                  ib = g.uni(0, 4) ? static_cast<PointId>(g.uni(0, 1000000000)) : ia;
    const int c = g.uni(0, 2);
    if (ia == ib && a[c] != b[c]) continue;
    const int expect = so::sos_sign({so::coords_row(a + c, 1), so::coords_row(b + c, 1)}, {ia, ib}).sign;
    INFO("compare_sos " << a[c] << " id " << ia << " vs " << b[c] << " id " << ib);
    CHECK(pred::compare_sos(Pt{ia, a}, Pt{ib, b}, c, Mode::filtered) == expect);
    CHECK(pred::compare_sos(Pt{ia, a}, Pt{ib, b}, c, Mode::gmp) == expect);
  }
}

// ---- the integer walk beyond 7 rows ---------------------------------------------------------
// k = 8 (staged) and 9..11 (lambda_sign_high) decide lattice calls by the walk
// of rank tests modulo p (exact_expansion.hpp int_lattice_sos_mod) where every
// minor is below 2^60 — the path of the 6D..9D grids' triangulations. The
// lattice families only (grid, integer flat, lattice sphere, lifted
// hyperplane, identical points, a duplicate), against the oracle; not vacuous:
// the walk decides most calls (int_lambda accepts, bits <= 60), many of them
// with det Λ = 0.
template <int K>
void walk_high(Det& g, bool lifted, int reps, long (&t)[3]) {
  const Spec s{lifted ? Kind::power_d : Kind::orient_d, lifted ? K - 2 : K - 1};
  for (int fam = 0; fam < 6; ++fam)
    for (int rep = 0; rep < reps; ++rep) {
      const Instance in = det_instance(s, g, fam, false);
      const so::Result r = oracle(s, in);
      std::vector<const double*> p;
      for (int i = 0; i < K; ++i) p.push_back(in.p(i));
      const double* w = lifted ? in.w.data() : nullptr;
      xp::IntLambda<K> L;
      const bool walked = !pred::repeated_id(K, in.id.data()) && xp::int_lambda<K>(p.data(), w, L) &&
                          L.bits <= xp::ModP61::kMaxBits;
      INFO(describe(s, in) << term_text(r));
      CHECK(pred::lambda_sign(K, in.id.data(), p.data(), w, Mode::filtered) == r.sign);
      CHECK(pred::lambda_sign_staged<K>(nullptr, in.id.data(), p.data(), w) == r.sign);
      if (walked) {
        const int u = pred::lambda_int_sorted<K>(in.id.data(), L);
        CHECK(u == r.sign);
        CHECK(u != 2);
      }
      ++t[0];
      t[1] += walked;
      t[2] += walked && xp::int_lattice_sign<K>(L, false) == 0;
    }
}

TEST_CASE("oracle: the integer walk decides lattice calls of 8..11 rows as the oracle") {
  Det g(811);
  long t[3] = {};
  // 24 per shape in Release; 3 under the sanitizers (100 RapidCheck cases:
  // release_scale 0.05), where the oracle's GMP searches over 9..11 rows took
  // 98 s of make asan at 6; at 3 every K, family and plain/lifted form still
  // runs (132 calls, 128 walked, 99 with det 0: the checks below hold)
  const int reps = std::max(3, static_cast<int>(24 * release_scale()));
  for (bool lifted : {false, true}) {
    walk_high<8>(g, lifted, 2 * reps, t);
    walk_high<9>(g, lifted, reps, t);
    walk_high<10>(g, lifted, reps / 2, t);
    walk_high<11>(g, lifted, reps / 3, t);
  }
  std::printf("int walk k = 8..11: %ld calls, %ld walked (%ld with det 0)\n", t[0], t[1], t[2]);
  CHECK(t[1] * 4 > t[0] * 3);
  CHECK(t[2] * 2 > t[1]);
}

// ---- the walk modulo several primes beyond 8 rows -------------------------------------------
// k = 9..11 calls off the integer lattice that the run-time filter cannot
// decide take the walk modulo primes (predicates.cpp lambda_walk_high,
// exact_expansion.hpp multiprime_walk) and one GMP minor: random doubles
// given twice or three times (ids apart), decimal tensor grids (k 0.1, k
// 0.7: rectangles' corners cospherical), with equal or different weights
// per copy. Against the oracle; not vacuous: the walk applies (at most 12
// primes) to most calls, most of them with det Λ = 0.
template <int K>
void multiprime_high(Det& g, bool lifted, int reps, long (&t)[3]) {
  const Spec s{lifted ? Kind::power_d : Kind::orient_d, lifted ? K - 2 : K - 1};
  for (int fam = 0; fam < 3; ++fam)
    for (int rep = 0; rep < reps; ++rep) {
      Instance in;
      in.d = s.d;
      in.k = K;
      in.x.assign(static_cast<size_t>(K * s.d), 0.0);
      in.w.assign(static_cast<size_t>(K), 0.0);
      const double step = g.uni(0, 1) ? 0.1 : 0.7;
      for (double& v : in.x)
        v = fam == 0 ? std::ldexp(static_cast<double>(g.rng() >> 11), -53) : g.uni(-2, 2) * step;
      if (lifted)
        for (double& v : in.w) v = fam == 2 ? g.uni(0, 2) * 0.01 : 0.0;
      // copies: 1 .. K/2 rows take another row's coordinates (and weight, or not)
      for (int c = g.uni(fam == 0 ? 1 : 0, K / 2); c > 0; --c) {
        const int a = g.uni(0, K - 1), b = g.uni(0, K - 1);
        for (int j = 0; j < s.d; ++j) in.p(a)[j] = in.p(b)[j];
        if (g.uni(0, 1)) in.w[static_cast<size_t>(a)] = in.w[static_cast<size_t>(b)];
      }
      for (int i = 0; i < K; ++i) in.id.push_back(static_cast<PointId>(g.uni(0, 1000000)));
      if (pred::repeated_id(K, in.id.data())) continue;
      const so::Result r = oracle(s, in);
      std::vector<const double*> p;
      for (int i = 0; i < K; ++i) p.push_back(in.p(i));
      const double* w = lifted ? in.w.data() : nullptr;
      INFO(describe(s, in) << term_text(r));
      CHECK(pred::lambda_sign(K, in.id.data(), p.data(), w, Mode::filtered) == r.sign);
      unsigned kr = 0, kc = 0;
      int sg = 0;
      // the rows sorted by id, as lambda_walk_high sorts them
      int order[K];
      pred::sort_rows_by_id(K, in.id.data(), order);
      std::vector<const double*> sp;
      std::vector<double> sw;
      for (int i = 0; i < K; ++i) {
        sp.push_back(p[static_cast<size_t>(order[i])]);
        sw.push_back(in.w[static_cast<size_t>(order[i])]);
      }
      const bool walked = xp::multiprime_walk<K>(sp.data(), lifted ? sw.data() : nullptr, kr, kc, sg) == 1;
      ++t[0];
      t[1] += walked;
      t[2] += walked && kr != (1u << K) - 1u;
    }
}

TEST_CASE("oracle: the walk modulo primes decides degenerate off-lattice calls of 9..11 rows as the oracle") {
  Det g(9011);
  long t[3] = {};
  const int reps = std::max(2, static_cast<int>(10 * release_scale()));
  for (bool lifted : {false, true}) {
    multiprime_high<9>(g, lifted, reps, t);
    multiprime_high<10>(g, lifted, reps, t);
    multiprime_high<11>(g, lifted, std::max(1, reps / 2), t);
  }
  std::printf("multi-prime walk k = 9..11: %ld calls, %ld walked (%ld with det 0)\n", t[0], t[1], t[2]);
  CHECK(t[1] * 2 > t[0]);
  CHECK(t[2] * 2 > t[1]);
}

// ---- mixed rows: an exact centroid (rational_point.hpp) --------------------------------------
TEST_CASE("oracle: mixed_sign with an exact centroid row equals the oracle") {
  Det g(6);
  int deep = 0;
  for (int dim = 1; dim <= 3; ++dim)
    for (int rep = 0; rep < std::max(150, static_cast<int>(300 * release_scale())); ++rep) {
      const int k = dim + 1;
      const int count = 1 << g.uni(0, 3);
      const int e = std::vector<int>{0, -60, 60, -30}[static_cast<size_t>(g.uni(0, 3))];
      // everything on an integer flat x_dim = a·x + b (degenerate), or a grid;
      // or (axis) every point row on the plane x_jc = c and the sources'
      // x_jc summing to c, so that column jc of Λ is constant on the rows
      // while the centroid row's last entry is its count: the column is then
      // not a multiple of the last one. minor_quick's constant-column rule
      // without its test that the last column is constant too answered 0
      // here (caught by this family, with point rows copied so that det Λ =
      // 0 and the SoS minors decide; it had hung ref::TwistFlip in
      // oracle_output_test)
      const bool flat = g.uni(0, 1);
      const bool axis = !flat && g.uni(0, 1) == 0;
      const int jc = g.uni(0, dim - 1);
      const double cval = g.ints(-3, 3);
      std::vector<double> a(3);
      for (double& v : a) v = g.ints(-2, 2);
      auto point = [&](double* x, int source) {
        for (int j = 0; j < dim; ++j) x[j] = g.ints(-3, 3);
        if (flat) {
          double v = a[2];
          for (int j = 0; j + 1 < dim; ++j) v += a[static_cast<size_t>(j)] * x[j];
          x[dim - 1] = v;
        }
        if (axis) x[jc] = source <= 0 ? cval : 0.0;  // source 0 carries c, the others 0
        for (int j = 0; j < dim; ++j) x[j] = std::ldexp(x[j], e);
      };
      std::vector<double> src(static_cast<size_t>(8 * 3)), xs(static_cast<size_t>(4 * 3));
      std::vector<const double*> sp;
      for (int i = 0; i < count; ++i) {
        point(&src[static_cast<size_t>(i * dim)], i);
        sp.push_back(&src[static_cast<size_t>(i * dim)]);
      }
      const pred::RationalPoint cen = pred::RationalPoint::centroid(sp.data(), count, dim);
      const int at = g.uni(0, k - 1);  // the centroid's row
      std::vector<pred::MixedRow> rows(static_cast<size_t>(k));
      std::vector<so::QRow> orows;
      std::vector<so::Id> ids;
      for (int i = 0; i < k; ++i) {
        PointId id = static_cast<PointId>(g.uni(0, 1000000000));
        while (std::find(ids.begin(), ids.end(), id) != ids.end()) ++id;
        ids.push_back(id);
        if (i == at) {
          rows[static_cast<size_t>(i)] = pred::MixedRow{id, nullptr, &cen};
          so::QRow r(static_cast<size_t>(dim), mpq_class(0));  // the centroid, by the oracle
          for (int t = 0; t < count; ++t)
            for (int j = 0; j < dim; ++j) r[static_cast<size_t>(j)] += so::exact(src[static_cast<size_t>(t * dim + j)]);
          for (auto& v : r) v /= count;
          orows.push_back(r);
        } else {
          double* x = &xs[static_cast<size_t>(i * 3)];
          const int prev = i - 1 == at ? i - 2 : i - 1;  // the point row before this one
          if (axis && prev >= 0 && g.uni(0, 1) == 0) {  // a copy of it (det Λ = 0: the SoS minors decide)
            for (int j = 0; j < dim; ++j) x[j] = xs[static_cast<size_t>(prev * 3 + j)];
          } else if (g.uni(0, 3) == 0) {  // a copy of a source point
            const int t = g.uni(0, count - 1);
            for (int j = 0; j < dim; ++j) x[j] = src[static_cast<size_t>(t * dim + j)];
          } else {
            point(x, -1);
          }
          rows[static_cast<size_t>(i)] = pred::MixedRow{id, x, nullptr};
          orows.push_back(so::coords_row(x, dim));
        }
      }
      const so::Result r = so::sos_sign(orows, ids);
      deep += r.size() >= 1;
      INFO("dim " << dim << " count " << count << " centroid row " << at << " " << term_text(r));
      CHECK(pred::mixed_sign(k, rows.data(), true, Mode::filtered) == r.sign);
      CHECK(pred::mixed_sign(k, rows.data(), true, Mode::gmp) == r.sign);
    }
  CHECK(deep > 0);
}

// ---- planted errors are caught ------------------------------------------------------------
// Each mutant is a wrapper around a library predicate with one SoS rule broken;
// the comparison with the oracle must fail on some of the sweep's inputs (the
// oracle is sensitive to that rule) while the real predicate passes on all.
TEST_CASE("oracle: the comparison catches planted SoS errors") {
  SECTION("power3d with the term of the largest id's height flipped") {
    // The first term after det Λ: the entry with the least exponent, the
    // largest id's height. Its cofactor is ± orient3d_exact of the other four
    // points; the mutant flips the answer when det Λ = 0 and that is not 0.
    const Spec s{Kind::power3d, 3};
    Det g(1);
    int real_bad = 0, mutant_bad = 0;
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < 40; ++rep) {
        Instance in = det_instance(s, g, fam, false);
        if (!distinct_ids(in)) continue;
        const int truth = oracle(s, in).sign;
        auto wpt = [&](int i) { return WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]}; };
        const int real = pred::power3d(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4));
        int mutant = real;
        const int top = static_cast<int>(std::max_element(in.id.begin(), in.id.end()) - in.id.begin());
        std::vector<const double*> others;
        for (int i = 0; i < 5; ++i)
          if (i != top) others.push_back(in.p(i));
        if (pred::power3d_exact(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4)) == 0 &&
            pred::orient3d_exact(others[0], others[1], others[2], others[3]) != 0)
          mutant = -real;
        real_bad += real != truth;
        mutant_bad += mutant != truth;
      }
    INFO("real mismatches " << real_bad << ", mutant mismatches " << mutant_bad);
    CHECK(real_bad == 0);
    CHECK(mutant_bad > 0);
  }
  SECTION("orient_d(4) with the two smallest ids swapped in the perturbation order") {
    const Spec s{Kind::orient_d, 4};
    Det g(2);
    int real_bad = 0, mutant_bad = 0;
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < 30; ++rep) {
        const Instance in = det_instance(s, g, fam, false);
        if (!distinct_ids(in)) continue;
        const int truth = oracle(s, in).sign;
        std::vector<Pt> pts, swapped;
        for (int i = 0; i < in.k; ++i) pts.push_back(Pt{in.id[static_cast<size_t>(i)], in.p(i)});
        swapped = pts;
        std::vector<int> order(static_cast<size_t>(in.k));
        for (int i = 0; i < in.k; ++i) order[static_cast<size_t>(i)] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return pts[static_cast<size_t>(a)].id < pts[static_cast<size_t>(b)].id; });
        std::swap(swapped[static_cast<size_t>(order[0])].id, swapped[static_cast<size_t>(order[1])].id);
        real_bad += pred::orient_d(4, pts.data()) != truth;
        mutant_bad += pred::orient_d(4, swapped.data()) != truth;
      }
    INFO("real mismatches " << real_bad << ", mutant mismatches " << mutant_bad);
    CHECK(real_bad == 0);
    CHECK(mutant_bad > 0);
  }
  SECTION("power_d_pulled(3) with the order of the ids reversed") {
    const Spec s{Kind::power_d, 3};
    Det g(3);
    int real_bad = 0, mutant_bad = 0;
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < 30; ++rep) {
        const Instance in = det_instance(s, g, fam, false);
        if (!distinct_ids(in)) continue;
        const int truth = oracle_pulled(in).sign;
        std::vector<WPt> pts, rev;
        for (int i = 0; i < in.k; ++i) pts.push_back(WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]});
        rev = pts;
        for (auto& q : rev) q.id = ~q.id;  // largest id pulled most, perturbed first
        real_bad += pred::power_d_pulled(3, pts.data()) != truth;
        mutant_bad += pred::power_d_pulled(3, rev.data()) != truth;
      }
    INFO("real mismatches " << real_bad << ", mutant mismatches " << mutant_bad);
    CHECK(real_bad == 0);
    CHECK(mutant_bad > 0);
  }
  SECTION("power_d_pulled(2) with the ε1 term (|x|^2) flipped") {
    // The pulled perturbation's second term: when det Λ = 0, the unweighted
    // determinant (power2d_exact with zero weights). The mutant flips the
    // answer whenever that term decides.
    const Spec s{Kind::power2d, 2};
    Det g(4);
    int real_bad = 0, mutant_bad = 0;
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < 40; ++rep) {
        const Instance in = det_instance(s, g, fam, false);
        const int truth = oracle_pulled(in).sign;
        std::vector<WPt> pts, unweighted;
        for (int i = 0; i < in.k; ++i) {
          pts.push_back(WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]});
          unweighted.push_back(WPt{in.id[static_cast<size_t>(i)], in.p(i), 0.0});
        }
        const int real = pred::power_d_pulled(2, pts.data());
        const bool eps1_decides =
            pred::power2d_exact(pts[0], pts[1], pts[2], pts[3]) == 0 &&
            pred::power2d_exact(unweighted[0], unweighted[1], unweighted[2], unweighted[3]) != 0;
        const int mutant = eps1_decides ? -real : real;
        real_bad += real != truth;
        mutant_bad += mutant != truth;
      }
    INFO("real mismatches " << real_bad << ", mutant mismatches " << mutant_bad);
    CHECK(real_bad == 0);
    CHECK(mutant_bad > 0);
  }
  SECTION("orient3d with the order of the x and y columns swapped within a row") {
    // orient3d of the points with x and y exchanged, negated (a column
    // transposition): the same exact sign, but y is perturbed before x.
    const Spec s{Kind::orient3d, 3};
    Det g(5);
    int real_bad = 0, mutant_bad = 0;
    for (int fam = 0; fam < 6; ++fam)
      for (int rep = 0; rep < 40; ++rep) {
        const Instance in = det_instance(s, g, fam, false);
        const int truth = oracle(s, in).sign;
        std::vector<std::array<double, 3>> sw(4);
        for (int i = 0; i < 4; ++i) sw[static_cast<size_t>(i)] = {in.p(i)[1], in.p(i)[0], in.p(i)[2]};
        auto pt = [&](int i) { return Pt{in.id[static_cast<size_t>(i)], in.p(i)}; };
        auto spt = [&](int i) { return Pt{in.id[static_cast<size_t>(i)], sw[static_cast<size_t>(i)].data()}; };
        real_bad += pred::orient3d(pt(0), pt(1), pt(2), pt(3)) != truth;
        mutant_bad += -pred::orient3d(spt(0), spt(1), spt(2), spt(3)) != truth;
      }
    INFO("real mismatches " << real_bad << ", mutant mismatches " << mutant_bad);
    CHECK(real_bad == 0);
    CHECK(mutant_bad > 0);
  }
}

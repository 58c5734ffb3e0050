// rtd_lattice_quotient_test.cpp — reference/lattice_quotient: an input that
// is a small-integer lattice up to one exact common factor g, run as that
// lattice by the cpu / GPU triangulation paths of `flipflop rtd|rt3|dt3` and
// Python's Delaunay.
//
// Properties:
//   * exactness: wherever lattice_quotient answers, every coordinate is
//     q * g and every weight q_w * g^2 in exact rationals (CGAL::Gmpq, built
//     from the doubles exactly), every q an integer below 2^20 in magnitude,
//     g > 0; it answers on every such lattice it should (the quotients'
//     gcd 1; weighted: also a factor of at most 2^24) and on none whose
//     values are small integers already, random, not finite or all zero;
//   * the same answer: the cpu kernels (rt2 in 2D, rt3 in 3D, the cavity
//     kernel in d = 2..5) on the quotient return the bytes they return on the
//     given values, which are the reference's (ref::rtd_incremental) on the
//     given values, certified there by certify::rtd — weighted or not,
//     factors from subnormal to 2^900; the hull kernels (hull_d in every d,
//     ffHull in 3D) likewise, certified by hull_d_problem on the given
//     values, ffHull equal to the reference ref::hull3.
//
// Oracles: CGAL::Gmpq (exact rationals) for the quotient; the reference and
// the certifier on the given values for the answer. Case counts: RC_PARAMS
// max_success (2000 under ctest) divided per property (prop_scaled).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "kernels_cpu/rt2/rt2.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rtd/hull_d.hpp"
#include "kernels_cpu/rtd/rtd_cavity.hpp"
#include "reference/hull3/hull3.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/lattice_quotient.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

namespace {

// A lattice up to a factor: n points of small integer coordinates q in
// [-r, r] (heavily degenerate: collinear, cospherical, duplicates), weights
// small integers q_w when weighted, and g = G 2^E (G odd); the values q g
// and q_w g^2, exact (q G < 2^27, q_w G^2 < 2^53, E within the range).
struct Case {
  PointSet given;
  std::vector<std::int64_t> q, qw;
  std::uint64_t G = 1;
  int E = 0;
};

rc::Gen<Case> lattice_case(int d, bool weighted, int nmax) {
  return rc::gen::exec([=] {
    Case c;
    const int n = *rc::gen::inRange(d + 1, nmax + 1);
    const int r = *rc::gen::inRange(1, 4);
    c.q = *rc::gen::container<std::vector<std::int64_t>>(static_cast<std::size_t>(n) * d, rc::gen::inRange(-r, r + 1));
    if (weighted) c.qw = *rc::gen::container<std::vector<std::int64_t>>(static_cast<std::size_t>(n), rc::gen::inRange(-4, 5));
    // G odd below 2^24 (a few bits, or many), E from subnormal factors to large ones
    const int bits = *rc::gen::inRange(0, 25);
    c.G = (*rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << bits) | 1u) & ((std::uint64_t{1} << 24) - 1);
    c.G |= 1u;
    const int lo = weighted ? -530 : -1074, hi = weighted ? 400 : 900;
    c.E = *rc::gen::oneOf(rc::gen::inRange(lo, hi + 1), rc::gen::inRange(-30, 31));
    const double g = std::ldexp(static_cast<double>(c.G), c.E);
    c.given.dim = d;
    c.given.weighted = weighted;
    std::vector<double> x(c.q.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(c.q[i]) * g;  // exact: q G < 2^27
    c.given.coords = Values(std::move(x));
    if (weighted) {
      std::vector<double> w(c.qw.size());
      for (std::size_t i = 0; i < w.size(); ++i)
        w[i] = std::ldexp(static_cast<double>(c.qw[i]) * static_cast<double>(c.G * c.G), 2 * c.E);  // exact
      c.given.weights = Values(std::move(w));
    }
    return c;
  });
}

void showValue(const Case& c, std::ostream& os) {
  os << c.given.dim << "D, g = " << c.G << " 2^" << c.E << ", q:";
  for (std::int64_t v : c.q) os << ' ' << v;
  if (c.given.weighted) {
    os << "; q_w:";
    for (std::int64_t v : c.qw) os << ' ' << v;
  }
}

bool small_integers(const PointSet& ps) {
  auto small = [](double x) { return x == std::trunc(x) && std::fabs(x) < 0x1p20; };
  for (double x : ps.coords)
    if (!small(x)) return false;
  if (ps.weighted)
    for (double w : ps.weights)
      if (!small(w)) return false;
  return true;
}

// exactly x = q g, w = q_w g^2, every q an integer below 2^20 in magnitude, g > 0
bool exact_quotient(const PointSet& given, const LatticeQuotient& lq) {
  const PointSet& p = lq.points;
  if (!(lq.factor > 0) || p.dim != given.dim || p.weighted != given.weighted || p.coords.size() != given.coords.size())
    return false;
  const CGAL::Gmpq g(lq.factor);
  auto integer = [](double x) { return x == std::trunc(x) && std::fabs(x) < 0x1p20; };
  for (std::size_t i = 0; i < p.coords.size(); ++i)
    if (!integer(p.coords[i]) || CGAL::Gmpq(p.coords[i]) * g != CGAL::Gmpq(given.coords[i])) return false;
  if (given.weighted) {
    if (p.weights.size() != given.weights.size()) return false;
    for (std::size_t i = 0; i < p.weights.size(); ++i)
      if (!integer(p.weights[i]) || CGAL::Gmpq(p.weights[i]) * g * g != CGAL::Gmpq(given.weights[i])) return false;
  }
  return true;
}

std::string text_of(const std::vector<std::vector<Index>>& simplices, const std::vector<Index>& redundant) {
  std::ostringstream os;
  write_simplices(os, simplices);
  os << "redundant";
  for (Index x : redundant) os << ' ' << x;
  return os.str();
}

template <class F>
std::string answer(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

std::string cavity(const PointSet& ps) {
  return answer([&] {
    const ref::Rtd r = cpu::rtd_cavity(ps);
    return text_of(r.simplices, r.redundant);
  });
}

// the d-specific kernel (rt2 / rt3) as text
std::string own_kernel(const PointSet& ps) {
  return answer([&] {
    std::ostringstream os;
    if (ps.dim == 2) {
      for (const Triangle& t : cpu::rt2(ps)) os << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    } else {
      const cpu::Rt3Result r = cpu::rt3(ps);
      for (const cpu::Tet& t : r.tets) os << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
      os << "redundant";
      for (Index x : r.redundant) os << ' ' << x;
    }
    return os.str();
  });
}

// hull_d's facets (in no particular order) as a sorted list of vertex sets,
// each with its orientation: the parity of the sort
std::vector<std::vector<Index>> oriented_set(std::vector<std::vector<Index>> facets) {
  for (auto& f : facets) {
    Index parity = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      for (std::size_t j = i + 1; j < f.size(); ++j) parity ^= f[i] > f[j] ? 1u : 0u;
    std::sort(f.begin(), f.end());
    f.push_back(parity);
  }
  std::sort(facets.begin(), facets.end());
  return facets;
}

template <class Assert>
void check_case(const Case& c, const Assert& require) {
  const std::optional<LatticeQuotient> lq = lattice_quotient(c.given);
  std::int64_t gcd = 0;
  for (std::int64_t v : c.q) gcd = std::gcd(gcd, v);
  const bool zero = gcd == 0;
  if (lq) require(exact_quotient(c.given, *lq), "exact quotient");
  // it must answer: not all zero, not small integers already, and (weighted)
  // the factor it finds is g itself (the quotients' gcd 1)
  if (!zero && !small_integers(c.given) && (!c.given.weighted || gcd == 1)) require(lq.has_value(), "answers");
  if (zero || small_integers(c.given)) require(!lq.has_value(), "no quotient");
  if (!lq) return;
  // the same answer on the quotient as on the given values, the reference's
  const std::string reference = answer([&] {
    const ref::Rtd r = ref::rtd_incremental(c.given);
    return text_of(r.simplices, r.redundant);
  });
  const std::string on_quotient = cavity(lq->points);
  require(on_quotient == reference, "cavity(quotient) == reference");
  require(cavity(c.given) == reference, "cavity(given) == reference");
  if (c.given.dim <= 3) require(own_kernel(lq->points) == own_kernel(c.given), "own kernel");
  if (on_quotient.rfind("error: ", 0) != 0) {
    const ref::Rtd r = cpu::rtd_cavity(lq->points);
    require(certify::rtd(c.given, r.simplices, certify::Level::canonical).ok, "certified on the given values");
    if (!c.given.weighted) {
      // the hull kernels: the same facets, certified on the given values
      const auto facets = cpu::hull_d(lq->points);
      require(oriented_set(facets) == oriented_set(cpu::hull_d(c.given)), "hull_d equal");
      require(cpu::hull_d_problem(c.given, facets).empty(), "hull_d certified on the given values");
      if (c.given.dim == 3) require(cpu::hull3_ffhull(lq->points) == ref::hull3(c.given, "ffhull"), "ffHull == reference");
    }
  }
}

}  // namespace

TEST_CASE("lattice_quotient: exact, and the kernels' answer on the quotient is the reference's on the given values",
          "[lattice_quotient]") {
  for (int d = 2; d <= 5; ++d)
    for (bool weighted : {false, true}) {
      const int nmax = d == 2 ? 80 : d == 3 ? 50 : d == 4 ? 24 : 16;
      test::prop_scaled(std::to_string(d) + "D lattices times g" + (weighted ? ", weighted" : ""), d <= 3 ? 1 : 2,
                        [=] { check_case(*lattice_case(d, weighted, nmax), [](bool ok, const char* what) {
                          if (!ok) RC_FAIL(what);
                        }); });
    }
}

TEST_CASE("lattice_quotient: grids with a step by hand, and no quotient where none applies", "[lattice_quotient]") {
  auto set = [](int d, std::vector<double> x, std::vector<double> w = {}) {
    PointSet ps;
    ps.dim = d;
    ps.coords = Values(std::move(x));
    if (!w.empty()) {
      ps.weighted = true;
      ps.weights = Values(std::move(w));
    }
    return ps;
  };
  // np.mgrid[0:0.25:0.1] in 2D: 0.2 is 2 x 0.1 exactly, so g = 0.1 (the double)
  {
    const auto lq = lattice_quotient(set(2, {0, 0, 0.1, 0, 0.2, 0, 0, 0.1, 0.1, 0.1, 0.2, 0.2}));
    REQUIRE(lq);
    CHECK(lq->factor == 0.1);
    CHECK(lq->points.coords.to_vector() == std::vector<double>{0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 2});
  }
  // np.linspace(-1, 1, 5): steps of 0.5, negative values
  {
    const auto lq = lattice_quotient(set(2, {-1, -0.5, 0, 0.5, 1, 1, -1, 0}));
    REQUIRE(lq);
    CHECK(lq->factor == 0.5);
    CHECK(lq->points.coords.to_vector() == std::vector<double>{-2, -1, 0, 1, 2, 2, -2, 0});
  }
  // integers in steps of 3000 beyond 2^20, weights multiples of 3000^2
  {
    const auto lq = lattice_quotient(set(2, {0, 3e9, 3000, -6000, 9e6, 0}, {9e6, 0, -18e6}));
    REQUIRE(lq);
    CHECK(lq->factor == 3000);
    CHECK(lq->points.coords.to_vector() == std::vector<double>{0, 1e6, 1, -2, 3000, 0});
    CHECK(lq->points.weights.to_vector() == std::vector<double>{1, 0, -2});
  }
  // subnormal steps: 3 x 2^-1074
  {
    const double t = std::ldexp(3.0, -1074);
    const auto lq = lattice_quotient(set(2, {0, t, 2 * t, 5 * t, -t, 0}));
    REQUIRE(lq);
    CHECK(lq->factor == t);
    CHECK(lq->points.coords.to_vector() == std::vector<double>{0, 1, 2, 5, -1, 0});
  }
  // none: small integers already, 0.30000000000000004 (not 3 x 0.1), a
  // quotient of 2^20, random values, NaN, infinity, all zero, a weight that
  // is not a multiple of g^2
  CHECK_FALSE(lattice_quotient(set(2, {0, 0, 1, 0, 0, 2, 4, -3})));
  CHECK_FALSE(lattice_quotient(set(2, {0, 0.1, 0.2, 0.1 + 0.2, 0, 0})));
  CHECK_FALSE(lattice_quotient(set(2, {0, 0.5, std::ldexp(1.0, 19), 0, 0, 1})));
  CHECK(lattice_quotient(set(2, {0, 0.5, std::ldexp(1.0, 18), 0, 0, 1})));
  CHECK_FALSE(lattice_quotient(set(2, {0.7390851332151607, 0.12345678901234567, 0.25, 0.5, 1, 0})));
  CHECK_FALSE(lattice_quotient(set(2, {0.5, std::numeric_limits<double>::quiet_NaN(), 0, 1, 1, 0})));
  CHECK_FALSE(lattice_quotient(set(2, {0.5, std::numeric_limits<double>::infinity(), 0, 1, 1, 0})));
  CHECK_FALSE(lattice_quotient(set(2, {0, 0, 0, 0, 0, 0})));
  CHECK_FALSE(lattice_quotient(set(2, {0, 0.5, 1, 0, 0, 1.5}, {0.125, 0, 0})));
  CHECK(lattice_quotient(set(2, {0, 0.5, 1, 0, 0, 1.5}, {0.25, 0, -0.75})));
  CHECK_FALSE(lattice_quotient(set(2, {0, 0.5, 1, 0, 0, 1.5}, {0.25, std::numeric_limits<double>::quiet_NaN(), 0})));
}

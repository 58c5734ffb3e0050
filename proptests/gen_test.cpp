// gen_test.cpp — properties of the point generators (gen/).
//
// Oracles: exact rational arithmetic (GMP) for the regions whose claim is
// exact (disk, ball, frame, box), 128-bit integers for the lattice families,
// the exact predicates (predicates.hpp, Mode::gmp) for collinear and coplanar
// sets, std::nextafter for the jitter; the shells (circle, sphere, cball) are
// checked with a tolerance of 1e-12, as their points are rounded.
#include <gmpxx.h>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "predicates/predicates.hpp"

using namespace flipflop;
using flipflop::pred::Mode;

namespace {

__extension__ typedef __int128 i128;

const std::vector<std::string> kAll = {
    "square",      "disk",        "frame",      "circle",      "cube",           "ball",
    "box",         "sphere",      "cball",      "grid2",       "grid3",          "circle-lattice",
    "sphere-lattice", "collinear2", "collinear3", "coplanar3", "duplicates2",    "duplicates3",
    "jitter2",     "jitter3",     "huge2",      "huge3",       "tiny2",          "tiny3",
    "planes3"};

// |p - (1/2, ..., 1/2)|^2, exactly.
mpq_class dist2_center(const double* p, int dim) {
  mpq_class s = 0;
  for (int c = 0; c < dim; ++c) {
    const mpq_class d = mpq_class(p[c]) - mpq_class(1, 2);
    s += d * d;
  }
  return s;
}

bool in_unit_box(const PointSet& ps) {
  for (double c : ps.coords)
    if (!(c >= 0.0 && c <= 1.0)) return false;
  return true;
}

// v as an integer; throws (a failure in Catch2 and in RapidCheck) if it is not
// an integer of magnitude below 2^53.
std::int64_t as_int(double v) {
  if (!(v == std::floor(v) && std::fabs(v) < 0x1p53))
    throw std::runtime_error("not an integer coordinate: " + std::to_string(v));
  return static_cast<std::int64_t>(v);
}

std::set<std::vector<double>> distinct(const PointSet& ps) {
  std::set<std::vector<double>> s;
  for (std::size_t i = 0; i < ps.size(); ++i) s.emplace(ps.point(i), ps.point(i) + ps.dim);
  return s;
}

}  // namespace

TEST_CASE("gen: names and dimensions") {
  CHECK(gen::distributions() == kAll);
  for (const std::string& d : kAll) {
    const int dim = gen::dimension_of(d);
    const bool three = d == "cube" || d == "ball" || d == "box" || d == "sphere" || d == "cball" ||
                       d == "sphere-lattice" || d == "coplanar3" || d.back() == '3';
    CHECK(dim == (three ? 3 : 2));
    CHECK(gen::generate(d, 17, {}).dim == dim);
    CHECK(gen::generate(d, 17, {}).size() == 17);
    CHECK(gen::generate(d, 0, {}).size() == 0);
  }
  for (auto f : {+[] { gen::dimension_of("torus"); }, +[] { gen::generate("torus", 5, {}); }}) {
    try {
      f();
      FAIL("no error for an unknown distribution");
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      CHECK(msg.find("torus") != std::string::npos);
      for (const std::string& d : kAll) CHECK(msg.find(d) != std::string::npos);
    }
  }
}

TEST_CASE("gen: invalid options are refused") {
  gen::Options o;
  for (double t : {0.0, -0.1, 0.6, std::nan("")}) {
    o.thickness = t;
    for (const char* d : {"frame", "circle", "box", "sphere"})
      CHECK_THROWS_AS(gen::generate(d, 10, o), std::invalid_argument);
    CHECK_NOTHROW(gen::generate("square", 10, o));  // no thickness there
  }
  o = {};
  o.weighted = true;
  o.wlo = 1;
  o.whi = 0;
  CHECK_THROWS_AS(gen::generate("square", 10, o), std::invalid_argument);
  o.whi = INFINITY;
  CHECK_THROWS_AS(gen::generate("square", 10, o), std::invalid_argument);
  o = {};
  o.hull_points = 11;
  CHECK_THROWS_AS(gen::generate("cball", 10, o), std::invalid_argument);
}

TEST_CASE("gen: the output depends only on (dist, n, options)") {
  rc::prop("same seed, same bits; another seed, other points", [] {
    const std::string d = *rc::gen::elementOf(kAll);
    const auto n = *rc::gen::inRange<std::size_t>(0, 300);
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    o.thickness = *rc::gen::element(0.5, 0.01, 1e-4);
    o.weighted = *rc::gen::arbitrary<bool>();
    o.wlo = *rc::gen::element(0.0, -1.0);
    o.whi = *rc::gen::element(1e-2, 1e-5, 2e-7);
    const PointSet a = gen::generate(d, n, o), b = gen::generate(d, n, o);
    RC_ASSERT(a.size() == n);
    RC_ASSERT(same_bits(a.coords, b.coords));
    RC_ASSERT(same_bits(a.weights, b.weights));
    RC_ASSERT(a.weights.size() == (o.weighted ? n : 0));
    if (n >= 20) {
      gen::Options other = o;
      other.seed = o.seed + 1;
      RC_ASSERT(!same_bits(gen::generate(d, n, other).coords, a.coords));
    }
    for (double w : a.weights) RC_ASSERT(w >= o.wlo && w <= o.whi);
  });
}

TEST_CASE("gen: square, disk, cube, ball — inside, exactly") {
  rc::prop("regions", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 200);
    for (const char* d : {"square", "cube"}) {
      const PointSet ps = gen::generate(d, n, o);
      for (double c : ps.coords) RC_ASSERT(c >= 0.0 && c < 1.0);
    }
    for (const char* d : {"disk", "ball"}) {
      const PointSet ps = gen::generate(d, n, o);
      RC_ASSERT(in_unit_box(ps));
      for (std::size_t i = 0; i < n; ++i) RC_ASSERT(dist2_center(ps.point(i), ps.dim) <= mpq_class(1, 4));
    }
  });
}

TEST_CASE("gen: frame and box — a coordinate within the band, exactly") {
  rc::prop("bands", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    o.thickness = *rc::gen::oneOf(rc::gen::element(0.5, 0.01, 1e-4, 0x1p-40),
                                  rc::gen::map(rc::gen::inRange(1, 5000), [](int k) { return k * 1e-4; }));
    const double t = o.thickness, hi = 1.0 - t;
    const auto n = *rc::gen::inRange<std::size_t>(1, 200);
    for (const char* d : {"frame", "box"}) {
      const PointSet ps = gen::generate(d, n, o);
      RC_ASSERT(in_unit_box(ps));
      for (std::size_t i = 0; i < n; ++i) {
        bool in_band = false;
        for (int c = 0; c < ps.dim; ++c) in_band = in_band || ps.point(i)[c] <= t || ps.point(i)[c] >= hi;
        RC_ASSERT(in_band);
      }
    }
  });
  // All strips are used (2D: 4 sides, 3D: 6 faces).
  gen::Options o;
  o.thickness = 0.01;
  for (const char* d : {"frame", "box"}) {
    const PointSet ps = gen::generate(d, 2000, o);
    std::set<int> sides;
    for (std::size_t i = 0; i < ps.size(); ++i)
      for (int c = 0; c < ps.dim; ++c) {
        if (ps.point(i)[c] <= 0.01) sides.insert(2 * c);
        if (ps.point(i)[c] >= 0.99) sides.insert(2 * c + 1);
      }
    CHECK(sides.size() == static_cast<std::size_t>(2 * ps.dim));
  }
}

TEST_CASE("gen: circle, sphere, cball — in their shells up to rounding") {
  const mpq_class eps(1e-12);
  rc::prop("shells", [&] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    o.thickness = *rc::gen::element(0.5, 0.1, 0.01, 1e-4);
    const auto n = *rc::gen::inRange<std::size_t>(1, 200);
    const mpq_class r_in = mpq_class(0.5) - mpq_class(o.thickness) - eps, r_out = mpq_class(0.5) + eps;
    for (const char* d : {"circle", "sphere"}) {
      const PointSet ps = gen::generate(d, n, o);
      RC_ASSERT(in_unit_box(ps));
      for (std::size_t i = 0; i < n; ++i) {
        const mpq_class s = dist2_center(ps.point(i), ps.dim);
        RC_ASSERT(s >= r_in * r_in);
        RC_ASSERT(s <= r_out * r_out);
      }
    }
    o.hull_points = *rc::gen::inRange<std::size_t>(0, n + 1);
    const std::size_t h = o.hull_points > 0 ? o.hull_points : std::min<std::size_t>(n, std::max<std::size_t>(4, n / 100));
    const PointSet ps = gen::generate("cball", n, o);
    RC_ASSERT(in_unit_box(ps));
    std::size_t on_sphere = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const mpq_class s = dist2_center(ps.point(i), 3);
      const mpq_class lo = mpq_class(1, 2) - eps, inner = mpq_class(45, 100) + eps;
      if (s >= lo * lo) {
        RC_ASSERT(s <= r_out * r_out);
        ++on_sphere;
      } else {
        RC_ASSERT(s <= inner * inner);
      }
    }
    RC_ASSERT(on_sphere == h);
  });
}

TEST_CASE("gen: grids are distinct lattice points of the smallest cube holding n") {
  rc::prop("grid", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 400);
    for (int dim : {2, 3}) {
      const PointSet ps = gen::generate(dim == 2 ? "grid2" : "grid3", n, o);
      std::int64_t s = 1;
      while (static_cast<std::size_t>(dim == 2 ? s * s : s * s * s) < n) ++s;
      for (double c : ps.coords) {
        const std::int64_t k = as_int(c);
        RC_ASSERT(k >= 0 && k < s);
      }
      RC_ASSERT(distinct(ps).size() == n);
    }
  });
}

TEST_CASE("gen: lattice points lie exactly on one circle or sphere") {
  rc::prop("lattices", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 400);
    for (int dim : {2, 3}) {
      const PointSet ps = gen::generate(dim == 2 ? "circle-lattice" : "sphere-lattice", n, o);
      RC_ASSERT(distinct(ps).size() == n);
      i128 r2 = -1;
      for (std::size_t i = 0; i < n; ++i) {
        i128 s = 0;
        for (int c = 0; c < dim; ++c) {
          const i128 k = as_int(ps.point(i)[c]);
          s += k * k;
        }
        if (r2 < 0) r2 = s;
        RC_ASSERT(s == r2);
      }
      // r2 is the square of an integer radius.
      const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(r2)));
      bool square = false;
      for (std::int64_t q = std::max<std::int64_t>(0, r - 2); q <= r + 2; ++q) square = square || static_cast<i128>(q) * q == r2;
      RC_ASSERT(square);
    }
  });
}

TEST_CASE("gen: circle-lattice beyond the largest circle adds interior lattice points") {
  const std::size_t on_circle = 236196, n = on_circle + 1000;
  const PointSet ps = gen::generate("circle-lattice", n, {});
  REQUIRE(ps.size() == n);
  std::map<i128, std::size_t> count;
  i128 r2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const i128 x = as_int(ps.point(i)[0]), y = as_int(ps.point(i)[1]);
    ++count[x * x + y * y];
    r2 = std::max(r2, x * x + y * y);
  }
  CHECK(count[r2] == on_circle);
  CHECK(distinct(ps).size() == n);
}

TEST_CASE("gen: collinear and coplanar sets are exactly degenerate") {
  rc::prop("orientation is 0", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(4, 60);
    const PointSet c2 = gen::generate("collinear2", n, o);
    const PointSet c3 = gen::generate("collinear3", n, o);
    const PointSet p3 = gen::generate("coplanar3", n, o);
    for (int k = 0; k < 20; ++k) {
      const auto i = *rc::gen::inRange<std::size_t>(0, n), j = *rc::gen::inRange<std::size_t>(0, n),
                 l = *rc::gen::inRange<std::size_t>(0, n), m = *rc::gen::inRange<std::size_t>(0, n);
      RC_ASSERT(pred::orient2d_exact(c2.point(i), c2.point(j), c2.point(l), Mode::gmp) == 0);
      // Collinear in 3D: every coordinate-plane projection is collinear.
      for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3;
        const double pi[2] = {c3.point(i)[a], c3.point(i)[b]}, pj[2] = {c3.point(j)[a], c3.point(j)[b]},
                     pl[2] = {c3.point(l)[a], c3.point(l)[b]};
        RC_ASSERT(pred::orient2d_exact(pi, pj, pl, Mode::gmp) == 0);
      }
      RC_ASSERT(pred::orient3d_exact(p3.point(i), p3.point(j), p3.point(l), p3.point(m), Mode::gmp) == 0);
    }
    // Not all on one point: the sets really span a line / a plane.
    RC_ASSERT(distinct(c2).size() > 1);
    RC_ASSERT(distinct(p3).size() > 2);
  });
}

TEST_CASE("gen: duplicates repeat every point, jitter is within 1 ulp of the lattice") {
  rc::prop("duplicates and jitter", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(2, 300);
    for (const char* d : {"duplicates2", "duplicates3"}) {
      const PointSet ps = gen::generate(d, n, o);
      std::map<std::vector<double>, std::size_t> times;
      for (std::size_t i = 0; i < n; ++i) ++times[std::vector<double>(ps.point(i), ps.point(i) + ps.dim)];
      std::size_t singles = 0;
      for (const auto& kv : times) singles += kv.second == 1 ? 1 : 0;
      RC_ASSERT(singles <= 1);  // only the last group may be cut short
      RC_ASSERT(times.size() < n);
      RC_ASSERT(in_unit_box(ps));
    }
    for (const char* d : {"jitter2", "jitter3"}) {
      const PointSet ps = gen::generate(d, n, o);
      for (double c : ps.coords) {
        const double g = std::nearbyint(c);
        RC_ASSERT(g >= 0.0);
        RC_ASSERT((c == g || c == std::nextafter(g, INFINITY) || c == std::nextafter(g, -INFINITY)));
      }
    }
  });
  // Jitter moves some coordinates off the lattice, in both directions.
  const PointSet ps = gen::generate("jitter3", 1000, {});
  int up = 0, down = 0;
  for (double c : ps.coords) {
    up += c > std::nearbyint(c);
    down += c < std::nearbyint(c);
  }
  CHECK(up > 0);
  CHECK(down > 0);
}

TEST_CASE("gen: huge and tiny are finite and in range, tiny has subnormals") {
  rc::prop("extreme magnitudes", [] {
    gen::Options o;
    o.seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 200);
    for (const char* d : {"huge2", "huge3"})
      for (double c : gen::generate(d, n, o).coords) RC_ASSERT(std::isfinite(c) && std::fabs(c) <= 0x1p997);
    for (const char* d : {"tiny2", "tiny3"})
      for (double c : gen::generate(d, n, o).coords) RC_ASSERT(std::isfinite(c) && std::fabs(c) <= 0x1p-997);
  });
  for (const char* d : {"tiny2", "tiny3"}) {
    const PointSet ps = gen::generate(d, 1000, {});
    std::size_t sub = 0;
    for (double c : ps.coords) sub += std::fpclassify(c) == FP_SUBNORMAL ? 1 : 0;
    CHECK(sub > 0);
  }
  for (const char* d : {"huge2", "huge3"}) {
    double m = 0;
    for (double c : gen::generate(d, 1000, {}).coords) m = std::max(m, std::fabs(c));
    CHECK(m > 1e299);
  }
}

// gen_planes_test.cpp — the planes3 family (gen/planes.cpp): a scanned
// building — points on nine planes, millimetre coordinates, exact duplicates,
// and any n >= 4 points spanning R^3.
//
// Oracles: 64-bit integer arithmetic on the millimetre values (each
// coordinate must be exactly the double k / 1000 for an integer k), GMP for
// the affine independence of the first four points.
#include <gmpxx.h>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "proptests/support/mpq_det.hpp"

using namespace flipflop;

namespace {

using Mm = std::array<std::int64_t, 3>;

// The millimetre integers of point i; false when a coordinate is not exactly
// the double nearest to k / 1000 for an integer k.
bool millimetres(const PointSet& ps, std::size_t i, Mm& k) {
  for (int c = 0; c < 3; ++c) {
    const double x = ps.point(i)[c];
    k[static_cast<std::size_t>(c)] = std::llround(x * 1000.0);
    if (static_cast<double>(k[static_cast<std::size_t>(c)]) / 1000.0 != x) return false;
  }
  return true;
}

// Does plane k of gen/planes.cpp (its table order) hold the point? The roof
// planes hold their points within half a millimetre: |z - 6000 - 2t/5| <=
// 1/2, i.e. |10z - 60000 - 4t| <= 5 (t = y or 20000 - y). (The planes meet:
// a point on an edge of the building is on two of them.)
bool on_plane(const Mm& p, int k) {
  const std::int64_t x = p[0], y = p[1], z = p[2];
  const auto in = [](std::int64_t v, std::int64_t lo, std::int64_t hi) { return v >= lo && v <= hi; };
  switch (k) {
    case 0: return z == 0 && in(x, 0, 30000) && in(y, 0, 20000);
    case 1: return z == 3000 && in(x, 0, 30000) && in(y, 0, 20000);
    case 2: return x == 0 && in(y, 0, 20000) && in(z, 0, 6000);
    case 3: return x == 30000 && in(y, 0, 20000) && in(z, 0, 6000);
    case 4: return y == 0 && in(x, 0, 30000) && in(z, 0, 6000);
    case 5: return y == 20000 && in(x, 0, 30000) && in(z, 0, 6000);
    case 6: return in(x, 0, 30000) && in(y, 0, 10000) && std::llabs(10 * z - 60000 - 4 * y) <= 5;
    case 7: return in(x, 0, 30000) && in(y, 10000, 20000) && std::llabs(10 * z - 60000 - 4 * (20000 - y)) <= 5;
    case 8: return x == y + 5000 && in(y, 0, 20000) && in(z, 0, 6000);
    default: return false;
  }
}

bool on_some_plane(const Mm& p) {
  for (int k = 0; k < 9; ++k)
    if (on_plane(p, k)) return true;
  return false;
}

}  // namespace

TEST_CASE("gen: planes3 is 3D and registered like the other families") {
  CHECK(gen::dimension_of("planes3") == 3);
  const auto names = gen::distributions();
  CHECK(std::find(names.begin(), names.end(), "planes3") != names.end());
  CHECK(gen::generate("planes3", 0, {}).size() == 0);
  CHECK(gen::generate("planes3", 17, {}).size() == 17);
}

TEST_CASE("gen: planes3 — millimetre points on the building's planes, duplicates, the first four affinely independent") {
  rc::prop("planes3 properties", [] {
    const auto n = *rc::gen::inRange<std::size_t>(0, 3000);
    gen::Options o;
    o.seed = *rc::gen::noShrink(rc::gen::arbitrary<std::uint64_t>());
    const PointSet ps = gen::generate("planes3", n, o);
    RC_ASSERT(ps.size() == n);
    std::vector<Mm> mm(n);
    std::size_t on_floor = 0, on_roof = 0;
    for (std::size_t i = 0; i < n; ++i) {
      RC_ASSERT(millimetres(ps, i, mm[i]));
      RC_ASSERT(on_some_plane(mm[i]));
      on_floor += on_plane(mm[i], 0);
      on_roof += on_plane(mm[i], 6) || on_plane(mm[i], 7);
    }
    if (n >= 4) {
      // the first four points: on four different planes, affinely independent (GMP)
      RC_ASSERT(on_plane(mm[0], 0));
      RC_ASSERT(on_plane(mm[1], 4));
      RC_ASSERT(on_plane(mm[2], 3));
      RC_ASSERT(on_plane(mm[3], 6));
      RC_ASSERT(test::exact_volume_sign(ps, {0, 1, 2, 3}) != 0);
    }
    const std::set<Mm> distinct(mm.begin(), mm.end());
    if (n >= 400) {  // one point in 16 a copy: none in 396 draws has probability (15/16)^396 < 1e-11
      RC_ASSERT(distinct.size() < n);
      RC_ASSERT(n - distinct.size() < n / 8);
    }
    if (n >= 1000) {  // the floor (600 of 2939 m²) and the roof (646) both well populated
      RC_ASSERT(on_floor > n / 10);
      RC_ASSERT(on_roof > n / 10);
    }
  });
}

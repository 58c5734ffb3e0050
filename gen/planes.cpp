// planes.cpp — planes3: a stand-in for a laser scan of a building, the input
// that 3D triangulation meets in practice and that uniform random points never
// show: most points on a few planes (many exactly coplanar and cospherical
// subsets), coordinates quantised to millimetres, and exact duplicates (the
// same surface point recorded by two overlapping scans).
//
// The building, in metres: a hall of 30 × 20 m (x × y), walls 6 m high, a
// gable roof with its ridge along x at y = 10 m, 10 m high (slope 2/5), a
// first floor slab at z = 3 m and one diagonal interior wall. The nine planes
// and their areas (m², rounded; they weight the choice of plane):
//   floor        z = 0                    x ∈ [0,30], y ∈ [0,20]   600
//   slab         z = 3                    x ∈ [0,30], y ∈ [0,20]   600
//   walls        x = 0, x = 30            y ∈ [0,20], z ∈ [0,6]    120 each
//                y = 0, y = 20            x ∈ [0,30], z ∈ [0,6]    180 each
//   roof         z = 6 + 2y/5             y ∈ [0,10], x ∈ [0,30]   323
//                z = 6 + 2(20 - y)/5      y ∈ [10,20]              323
//   diagonal     x = y + 5                y ∈ [0,20], z ∈ [0,6]    170
// Every point is drawn on the integer millimetre grid (uniform on the chosen
// rectangle; on a roof plane z is the height rounded to the nearest
// millimetre, half up, so roof points lie within 0.5 mm of their plane, not on
// it, as a scanner's rounded output does) and written as k / 1000 — the
// correctly rounded quotient, i.e. the double a reader of "12.345" gets; the
// axis-aligned and the diagonal planes hold their points exactly.
// From the fifth point on, one point in 16 is an exact copy of an earlier one
// (uniform among them). The first four points lie on four different planes
// (floor, wall y = 0, wall x = 30, a roof plane) and are redrawn until their
// millimetre integers are affinely independent (an exact 128-bit determinant;
// as doubles they stay independent: the determinant is at least 1 mm³ =
// 1e-9 m³, and rounding k / 1000 moves each coordinate by at most 2^-49, which
// changes a determinant of coordinates below 40 by less than 1e-11), so any
// n >= 4 points span R^3.
#include <array>

#include "gen/families.hpp"

namespace flipflop::gen::detail {

namespace {

using P = std::array<std::int64_t, 3>;  // millimetres

// round(2 t / 5), half up, for t >= 0: floor((4t + 5) / 10).
std::int64_t two_fifths(std::int64_t t) { return (4 * t + 5) / 10; }

// A point of plane `k` (the table above, in that order), uniform on the
// millimetre grid of its rectangle.
P on_plane(Rng& r, int k) {
  const auto u = [&r](std::int64_t hi) { return r.between(0, hi); };
  switch (k) {
    case 0: return {u(30000), u(20000), 0};
    case 1: return {u(30000), u(20000), 3000};
    case 2: return {0, u(20000), u(6000)};
    case 3: return {30000, u(20000), u(6000)};
    case 4: return {u(30000), 0, u(6000)};
    case 5: return {u(30000), 20000, u(6000)};
    case 6: {
      const std::int64_t y = u(10000);
      return {u(30000), y, 6000 + two_fifths(y)};
    }
    case 7: {
      const std::int64_t y = 10000 + u(10000);
      return {u(30000), y, 6000 + two_fifths(20000 - y)};
    }
    default: {
      const std::int64_t y = u(20000);
      return {y + 5000, y, u(6000)};
    }
  }
}

constexpr int kArea[9] = {600, 600, 120, 120, 180, 180, 323, 323, 170};

int pick_plane(Rng& r) {
  int total = 0;
  for (int a : kArea) total += a;
  auto x = static_cast<int>(r.below(static_cast<std::uint64_t>(total)));
  for (int k = 0; k < 9; ++k) {
    if (x < kArea[k]) return k;
    x -= kArea[k];
  }
  return 8;
}

// det[b - a, c - a, d - a] in 128-bit integers (|entries| < 2^16: exact).
i128 det(const P& a, const P& b, const P& c, const P& d) {
  i128 m[3][3];
  for (int j = 0; j < 3; ++j) {
    m[0][j] = b[j] - a[j];
    m[1][j] = c[j] - a[j];
    m[2][j] = d[j] - a[j];
  }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

void append(Coords& out, const P& p) {
  for (std::int64_t c : p) out.push_back(static_cast<double>(c) / 1000.0);
}

}  // namespace

void planes3(Rng& r, std::size_t n, Coords& out) {
  const std::size_t first = out.size() / 3;
  P start[4];
  do {
    const int planes[4] = {0, 4, 3, 6};
    for (int k = 0; k < 4; ++k) start[k] = on_plane(r, planes[k]);
  } while (det(start[0], start[1], start[2], start[3]) == 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (i < 4) {
      append(out, start[i]);
    } else if (r.below(16) == 0) {  // a copy of an earlier point
      const std::size_t j = first + static_cast<std::size_t>(r.below(i));
      const double copy[3] = {out[3 * j], out[3 * j + 1], out[3 * j + 2]};
      out.insert(out.end(), copy, copy + 3);
    } else {
      append(out, on_plane(r, pick_plane(r)));
    }
  }
}

}  // namespace flipflop::gen::detail

// degenerate.cpp — exactly degenerate inputs, and inputs at the edges of the
// double range, for testing the exact predicates and Simulation of
// Simplicity (DESIGN.md). All constructions are exact: integers below 2^53,
// scalings by powers of two, std::nextafter.
//
//   grid2/3        integer lattice points: side s = the smallest with
//                  s^d >= n, the first n of a seeded shuffle of all s^d;
//   collinear2/3   o + t·v with integer o, v (|v_i| <= 1000, v != 0) and
//                  integer t in [-10^6, 10^6]: all on one line;
//   coplanar3      (x, y, a·x + b·y + c) with integers |a|,|b|,|c| <= 10 and
//                  x, y in [-10^6, 10^6]: all on one plane;
//   duplicates2/3  uniform points of [0,1)^d, each repeated 2 to 5 times, in
//                  shuffled order;
//   jitter2/3      a grid as above with every coordinate moved by 0, +1 or -1
//                  ulp (std::nextafter), at random;
//   huge2/3        uniform in (-1, 1)^d on the grid k·2^-52, scaled by 2^997
//                  (|x| < 1.4e300): finite, but products overflow;
//   tiny2/3        the same scaled by 2^-997 (|x| < 7.5e-301), and one
//                  coordinate in eight replaced by a random subnormal.
#include <cmath>
#include <limits>

#include "gen/families.hpp"

namespace flipflop::gen::detail {

void shuffle_points(Rng& r, int dim, Coords& c, std::size_t first) {
  const auto d = static_cast<std::size_t>(dim);
  const std::size_t n = c.size() / d;
  for (std::size_t i = n; i > first + 1; --i) {
    const std::size_t j = first + r.below(i - first);
    for (std::size_t k = 0; k < d; ++k) std::swap(c[(i - 1) * d + k], c[j * d + k]);
  }
}

void grid(Rng& r, int dim, std::size_t n, Coords& out) {
  if (n == 0) return;
  std::uint64_t s = 1;
  auto power = [dim](std::uint64_t b) {
    i128 p = 1;
    for (int c = 0; c < dim; ++c) p *= b;
    return p;
  };
  while (power(s) < static_cast<i128>(n)) ++s;
  // Partial Fisher–Yates over the lattice numbers 0 .. s^d - 1.
  const auto total = static_cast<std::size_t>(power(s));
  std::vector<std::uint64_t> id(total);
  for (std::size_t i = 0; i < total; ++i) id[i] = i;
  for (std::size_t i = 0; i < n; ++i) std::swap(id[i], id[i + r.below(total - i)]);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t v = id[i];
    for (int c = 0; c < dim; ++c) {
      out.push_back(static_cast<double>(v % s));
      v /= s;
    }
  }
}

void jitter(Rng& r, int dim, std::size_t n, Coords& out) {
  const std::size_t first = out.size();
  grid(r, dim, n, out);
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i < out.size(); ++i) {
    const std::uint64_t k = r.below(3);
    if (k == 1) out[i] = std::nextafter(out[i], inf);
    if (k == 2) out[i] = std::nextafter(out[i], -inf);
  }
}

void collinear(Rng& r, int dim, std::size_t n, Coords& out) {
  std::int64_t v[3] = {0, 0, 0}, o[3] = {0, 0, 0};
  while (v[0] == 0 && v[1] == 0 && v[2] == 0)
    for (int c = 0; c < dim; ++c) v[c] = r.between(-1000, 1000);
  for (int c = 0; c < dim; ++c) o[c] = r.between(-1000000, 1000000);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t t = r.between(-1000000, 1000000);
    for (int c = 0; c < dim; ++c) out.push_back(static_cast<double>(o[c] + t * v[c]));
  }
}

void coplanar3(Rng& r, std::size_t n, Coords& out) {
  const std::int64_t a = r.between(-10, 10), b = r.between(-10, 10), c = r.between(-10, 10);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t x = r.between(-1000000, 1000000), y = r.between(-1000000, 1000000);
    out.push_back(static_cast<double>(x));
    out.push_back(static_cast<double>(y));
    out.push_back(static_cast<double>(a * x + b * y + c));
  }
}

void duplicates(Rng& r, int dim, std::size_t n, Coords& out) {
  const std::size_t first = out.size() / static_cast<std::size_t>(dim);
  std::size_t made = 0;
  double p[3];
  while (made < n) {
    for (int c = 0; c < dim; ++c) p[c] = r.unit();
    const std::size_t copies = 2 + static_cast<std::size_t>(r.below(4));
    for (std::size_t k = 0; k < copies && made < n; ++k, ++made) out.insert(out.end(), p, p + dim);
  }
  shuffle_points(r, dim, out, first);
}

void huge(Rng& r, int dim, std::size_t n, Coords& out) {
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i)
    out.push_back(r.symmetric() * 0x1p997);
}

void tiny(Rng& r, int dim, std::size_t n, Coords& out) {
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i) {
    if (r.below(8) == 0) {
      // k·2^-1074 with 1 <= k < 2^52: a subnormal, exactly; random sign.
      const double k = static_cast<double>(1 + r.below((std::uint64_t{1} << 52) - 1));
      out.push_back((r.below(2) == 0 ? 1.0 : -1.0) * k * 0x1p-1074);
    } else {
      out.push_back(r.symmetric() * 0x1p-997);
    }
  }
}

}  // namespace flipflop::gen::detail

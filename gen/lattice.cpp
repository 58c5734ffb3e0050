// lattice.cpp — integer points exactly on a circle or a sphere (cocircular
// and cospherical inputs: every point is on the hull, every empty-circle
// test through four of them is a tie that only the perturbation breaks).
//
// circle-lattice. The Gaussian integers of norm r^2, for r = p_1 ··· p_m a
// product of distinct primes p ≡ 1 (mod 4), p = π·conj(π), are exactly
//     u · Π π_i^k_i · conj(π_i)^(2-k_i),   k_i ∈ {0, 1, 2}, u ∈ {±1, ±i}
// (unique factorisation in Z[i]): 4·3^m distinct lattice points (x, y) with
// x^2 + y^2 = r^2. m is the smallest with 4·3^m >= n, at most 10
// (r = 5·13·17·29·37·41·53·61·73·89 ≈ 1.0e15 < 2^53, 236196 points);
// the first n of a seeded shuffle are returned. For n beyond 236196 all
// points of that circle are returned plus n - 236196 distinct random lattice
// points strictly inside it.
//
// sphere-lattice. A quaternion q = (a, b, c, d) of norm N = a²+b²+c²+d² maps
// to the point (a²+b²-c²-d², 2(ad+bc), 2(bd-ac)), whose squared length is
// N² (the Euler four-square identity): an integer point exactly on the sphere
// of radius N. All q of norm N are enumerated (O(N^1.5) work), duplicates
// removed; N grows until there are at least n points; the first n of a
// seeded shuffle are returned. (Not every lattice point of that sphere need
// appear; every point returned is on it.)
#include <algorithm>
#include <array>
#include <cmath>

#include "gen/families.hpp"

namespace flipflop::gen::detail {

namespace {

using P2 = std::array<std::int64_t, 2>;
using P3 = std::array<std::int64_t, 3>;

// floor(sqrt(v)) for 0 <= v < 2^62, exactly.
std::int64_t isqrt(std::int64_t v) {
  auto s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (s > 0 && s * s > v) --s;
  while ((s + 1) * (s + 1) <= v) ++s;
  return s;
}

P2 mul(P2 z, P2 w) { return {z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0]}; }

}  // namespace

void circle_lattice(Rng& r, std::size_t n, Coords& out) {
  static const std::int64_t primes[] = {5, 13, 17, 29, 37, 41, 53, 61, 73, 89};
  std::size_t m = 0, count = 4;
  while (m < 10 && count < n) {
    ++m;
    count *= 3;
  }
  std::vector<P2> pts = {{1, 0}};
  std::int64_t radius = 1;
  for (std::size_t i = 0; i < m; ++i) {
    const std::int64_t p = primes[i];
    P2 pi{0, 0};  // p = a^2 + b^2
    for (std::int64_t a = 1; a * a < p; ++a) {
      const std::int64_t b = isqrt(p - a * a);
      if (b * b == p - a * a) pi = {a, b};
    }
    const P2 conj{pi[0], -pi[1]};
    std::vector<P2> next;
    for (const P2& z : pts) {
      next.push_back(mul(z, mul(pi, pi)));
      next.push_back(mul(z, mul(pi, conj)));  // = p
      next.push_back(mul(z, mul(conj, conj)));
    }
    pts.swap(next);
    radius *= p;
  }
  std::vector<P2> all;
  for (const P2& z : pts) {  // the four units
    all.push_back({z[0], z[1]});
    all.push_back({-z[1], z[0]});
    all.push_back({-z[0], -z[1]});
    all.push_back({z[1], -z[0]});
  }
  r.shuffle(all);
  if (all.size() > n) all.resize(n);
  if (all.size() < n) {
    // Distinct random lattice points strictly inside the circle.
    const std::size_t on_circle = all.size();
    const i128 r2 = static_cast<i128>(radius) * radius;
    std::vector<P2> inside;
    while (inside.size() < n - on_circle) {
      while (inside.size() < n - on_circle) {
        const P2 q{r.between(-radius, radius), r.between(-radius, radius)};
        if (static_cast<i128>(q[0]) * q[0] + static_cast<i128>(q[1]) * q[1] < r2) inside.push_back(q);
      }
      std::sort(inside.begin(), inside.end());
      inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
    }
    all.insert(all.end(), inside.begin(), inside.end());
    r.shuffle(all);
  }
  for (const P2& q : all) {
    out.push_back(static_cast<double>(q[0]));
    out.push_back(static_cast<double>(q[1]));
  }
}

void sphere_lattice(Rng& r, std::size_t n, Coords& out) {
  if (n == 0) return;
  std::vector<P3> pts;
  for (std::int64_t norm = 1;; norm += std::max<std::int64_t>(1, norm / 2)) {
    pts.clear();
    const std::int64_t s = isqrt(norm);
    for (std::int64_t a = -s; a <= s; ++a)
      for (std::int64_t b = -s; b <= s; ++b) {
        const std::int64_t ab = a * a + b * b;
        if (ab > norm) continue;
        for (std::int64_t c = -s; c <= s; ++c) {
          const std::int64_t rest = norm - ab - c * c;
          if (rest < 0) continue;
          const std::int64_t d0 = isqrt(rest);
          if (d0 * d0 != rest) continue;
          for (const std::int64_t d : {d0, -d0}) {
            pts.push_back({a * a + b * b - c * c - d * d, 2 * (a * d + b * c), 2 * (b * d - a * c)});
            if (d0 == 0) break;
          }
        }
      }
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() >= n) break;
  }
  r.shuffle(pts);
  pts.resize(n);
  for (const P3& q : pts)
    for (std::int64_t c : q) out.push_back(static_cast<double>(c));
}

}  // namespace flipflop::gen::detail

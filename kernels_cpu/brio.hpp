// brio.hpp — the biased randomized insertion order (BRIO, Amenta–Choi–Rote)
// of the incremental triangulation kernels (kernels_cpu/rt2, kernels_cpu/rt3),
// written once: the points' bounding box from a parallel scan, each point's
// round (by a hash of its coordinates) and its cell on a space-filling curve
// of the box, one parallel radix sort of the keys (round | curve | index).
//
// Point i belongs to round r = min(R - 1, (leading zero bits of hash(i)) / 3),
// i.e. to round r with probability about 8^-r (7/8 of the points in the last
// round); the rounds are inserted from the sparsest one, each along the curve.
// R is the number of rounds of expected size >= brio_min (at most 20, < 2^5).
// The order is a heuristic for locality only: the answers never depend on it.
//
// Exact copies (coordinates and weight): with the round drawn from a hash of
// the coordinates (point_hash), copies of one point fall in one round and one
// curve cell, so they come one after the other in the order, by increasing
// index. Of such a group the copy of largest index is lowest when lifted
// (reference/rt2/rt2.hpp), so inside the hull it is the only one that can be
// a vertex; each other copy inserted before it would be inserted and removed
// again when the next comes (in a parallel round even in the other order:
// duplicates2 at 10^6, 2D, had 569526 such removals). So the triangulation
// kernels (rt2, rt3, rtd cavity) let each copy followed by a copy of larger
// index (waits_for_next) wait until the rest is in; it then goes through the
// normal insertion: inside the hull it is found redundant when located, on
// the hull's boundary (where the perturbation of the coordinates can make
// every copy a hull vertex) it is inserted like any point.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include "kernels_cpu/grid_keys.hpp"
#include "kernels_cpu/parallel.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu::brio {

// splitmix64, unit, grid_cell, morton: grid_keys.hpp (also the GPU kernels')

template <int kBits>
std::uint32_t grid(double x, double lo, double hi) {
  return grid_cell(x, lo, hi, kBits);
}

inline std::uint32_t grid15(double x, double lo, double hi) { return grid<15>(x, lo, hi); }

// The bounding box of the first D coordinates: min 0..D-1, then max 0..D-1.
template <int D>
std::array<double, 2 * D> bounding_box(const PointSet& ps) {
  const std::size_t n = ps.size();
  std::array<double, 2 * D> box;
  for (int k = 0; k < D; ++k) box[k] = HUGE_VAL, box[k + D] = -HUGE_VAL;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::array<double, 2 * D>> part(chunks, box);
  par_for(chunks, 1, [&](std::size_t clo, std::size_t chi) {
    for (std::size_t c = clo; c < chi; ++c)
      for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
        for (int k = 0; k < D; ++k) {
          part[c][k] = std::min(part[c][k], ps.point(i)[k]);
          part[c][k + D] = std::max(part[c][k + D], ps.point(i)[k]);
        }
  });
  for (const auto& b : part)
    for (int k = 0; k < D; ++k) box[k] = std::min(box[k], b[k]), box[k + D] = std::max(box[k + D], b[k + D]);
  return box;
}

// A hash of a point's d coordinates (x == 0 taken as +0, which it equals):
// equal points hash equally.
inline std::uint64_t point_hash(const double* x, int d) {
  std::uint64_t h = 0x6A09E667F3BCC909ull;
  for (int j = 0; j < d; ++j) {
    std::uint64_t b;
    const double v = x[j] == 0 ? 0.0 : x[j];
    std::memcpy(&b, &v, sizeof b);
    h = splitmix64(h ^ b);
  }
  return h;
}

// The point at one position waits for the next (see the header): x, w, id its
// d coordinates, weight and input index, y, wy, idy the next one's.
inline bool waits_for_next(const double* x, double w, Index id, const double* y, double wy, Index idy, int d) {
  for (int j = 0; j < d; ++j)
    if (x[j] != y[j]) return false;
  return w == wy && id < idy;
}

// The order: curve(point index) gives a point's curve index (< 2^30), seed(i)
// the hash that draws its round (point_hash of its coordinates); input
// indices must fit kIndexBits = 29 bits. rounds_at (optional) receives the
// first position of each round, and n.
constexpr int kIndexBits = 29;
template <class Curve, class Seed>
std::vector<Index> order(std::size_t n, std::size_t brio_min, const Curve& curve, const Seed& seed,
                         std::vector<std::size_t>* rounds_at) {
  unsigned rounds = 1;
  while (rounds < 20 && (n >> (3 * rounds)) >= std::max<std::size_t>(brio_min, 1)) ++rounds;
  constexpr std::uint64_t kLow = (std::uint64_t{1} << kIndexBits) - 1;
  std::vector<std::uint64_t> keys(n);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) {
      const std::uint64_t h = splitmix64(seed(i));
      const unsigned zeros = h == 0 ? 64u : static_cast<unsigned>(__builtin_clzll(h));
      const unsigned r = std::min(rounds - 1, zeros / 3);
      const std::uint64_t c = curve(i);
      keys[i] = (static_cast<std::uint64_t>(rounds - 1 - r) << (30 + kIndexBits)) | (c << kIndexBits) | i;
    }
  });
  // keys[i] holds i in its low bits, so the stable radix sort on the high
  // bits (the certifiers' one, here over par_for) is the sort of the whole
  // (distinct) keys
  const auto for_range = par_for_range();
  certify::detail::radix_sort_high(keys, kIndexBits, for_range);
  if (rounds_at) {
    rounds_at->clear();
    for (std::uint64_t r = 0; r < rounds; ++r)
      rounds_at->push_back(static_cast<std::size_t>(
          std::lower_bound(keys.begin(), keys.end(), r << (30 + kIndexBits)) - keys.begin()));
    rounds_at->push_back(n);
  }
  std::vector<Index> out(n);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) out[i] = static_cast<Index>(keys[i] & kLow);
  });
  return out;
}

}  // namespace flipflop::cpu::brio

// grid_keys.hpp — the point-order primitives every kernel shares: a 64-bit
// mixer, a coordinate's place in its box, its grid cell, and the Morton
// (Z-order) key of a point's cell. Header-only, no library, __host__
// __device__: kernels_cpu/brio.hpp (the BRIO order of the CPU kernels) and the
// GPU kernels (kernels_cuda/rt3/rt3.cuh) call these same functions. Only the
// locality of an order depends on them, never an answer.
#pragma once

#include <cstdint>

#include "predicates/err_double.hpp"  // FF_HD

namespace flipflop::cpu::brio {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix of 64 bits.
FF_HD inline std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// x's place in [lo, hi] as a fraction, 0 for an empty span; halves first so
// that no difference overflows near ±DBL_MAX. (In [0, 1] for x in [lo, hi].)
FF_HD inline double unit(double x, double lo, double hi) {
  const double span = hi * 0.5 - lo * 0.5;
  return span > 0 ? (x * 0.5 - lo * 0.5) / span : 0.0;
}

// Grid coordinate in [0, 2^bits) of x in [lo, hi].
FF_HD inline std::uint32_t grid_cell(double x, double lo, double hi, int bits) {
  const double cells = static_cast<double>(std::uint32_t{1} << bits);
  double u = unit(x, lo, hi);
  if (!(u >= 0)) u = 0;
  if (u > 1) u = 1;
  const double c = u * cells;
  return static_cast<std::uint32_t>(c < cells - 1 ? c : cells - 1);
}

// Morton (Z-order) index of x's cell in the box lo[0..d-1], hi[0..d-1]:
// floor(total / d) bits per axis (grid cells), interleaved from the top bit;
// below 2^total (total <= 64, d <= 16).
FF_HD inline std::uint64_t morton(const double* x, const double* lo, const double* hi, int d, int total) {
  const int bits = total / d;
  std::uint32_t cell[16];
  for (int j = 0; j < d; ++j) cell[j] = grid_cell(x[j], lo[j], hi[j], bits);
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int j = 0; j < d; ++j) key = (key << 1) | ((cell[j] >> b) & 1u);
  return key;
}

}  // namespace flipflop::cpu::brio

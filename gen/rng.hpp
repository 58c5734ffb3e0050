// rng.hpp — the one random source of gen/ (internal).
//
// std::mt19937_64 is specified bit for bit by the C++ standard; everything
// built on it here uses integer operations and correctly rounded IEEE double
// operations only, so the same seed gives the same points everywhere.
#pragma once

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace flipflop::gen::detail {

// Signed 128-bit integers for exact tests on 53-bit grids.
__extension__ typedef __int128 i128;

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : eng_(seed) {}

  std::uint64_t bits() { return eng_(); }

  // k in [0, 2^53): the top 53 bits of one output.
  std::uint64_t bits53() { return eng_() >> 11; }

  // Uniform on the grid {k 2^-53 : 0 <= k < 2^53} of [0, 1); exact.
  double unit() { return static_cast<double>(bits53()) * 0x1p-53; }

  // Uniform on the grid {k 2^-52 - 1} of [-1, 1); exact.
  double symmetric() { return static_cast<double>(bits53()) * 0x1p-52 - 1.0; }

  // Unbiased integer in [0, n), n >= 1: reject the lowest 2^64 mod n outputs.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t threshold = (0 - n) % n;
    for (;;) {
      const std::uint64_t r = eng_();
      if (r >= threshold) return r % n;
    }
  }

  // Integer in [lo, hi] (inclusive), hi - lo < 2^63.
  std::int64_t between(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo) + 1));
  }

  // Fisher–Yates (std::shuffle's sequence is implementation-defined).
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(i)]);
  }

 private:
  std::mt19937_64 eng_;
};

// SplitMix64 finalizer: a second, independent seed from the first.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace flipflop::gen::detail

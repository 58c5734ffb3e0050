// rtd_inputs.hpp — d-dimensional point sets for the rtd_* tests
// (reference/rtd/): random inputs in general position, and degenerate
// families (integer lattices, cospherical points, equal weights, duplicates).
// Deterministic: std::mt19937_64 (its sequence is fixed by the standard)
// mapped to doubles by our own arithmetic.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::test {

// Loop counts of the expensive rtd tests are divided by this under the
// sanitizers (exact GMP predicates run ~30x slower there; the Release suite
// runs the full counts), as the RapidCheck case count is (Makefile SAN_CASES).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr std::uint64_t kRtdSanitizerDivisor = 4;
#else
inline constexpr std::uint64_t kRtdSanitizerDivisor = 1;
#endif

// uniform double in [0, 1) with 53 random bits
inline double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

// n uniform points in [0,1]^d; weights uniform in [0, whi] when whi > 0
// (weighted with zero weights when whi == 0 and weighted is set).
inline PointSet rtd_uniform(int d, std::size_t n, std::uint64_t seed, double whi, bool weighted = true) {
  std::mt19937_64 g(seed);
  PointSet ps;
  ps.dim = d;
  ps.weighted = weighted;
  for (std::size_t i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) ps.coords.push_back(unit(g));
  if (weighted)
    for (std::size_t i = 0; i < n; ++i) ps.weights.push_back(whi * unit(g));
  return ps;
}

// Integer points in [0, r]^d, weights integers in [0, wmax] (all 0 when
// wmax == 0): heavy degeneracy (cospherical, coplanar subsets, duplicates).
inline PointSet rtd_lattice(int d, std::size_t n, std::uint64_t seed, int r, int wmax) {
  std::mt19937_64 g(seed);
  PointSet ps;
  ps.dim = d;
  ps.weighted = wmax > 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) ps.coords.push_back(static_cast<double>(g() % static_cast<std::uint64_t>(r + 1)));
  if (ps.weighted)
    for (std::size_t i = 0; i < n; ++i) ps.weights.push_back(static_cast<double>(g() % static_cast<std::uint64_t>(wmax + 1)));
  return ps;
}

// The full grid {0..r}^d in index order (every point once), unweighted.
inline PointSet rtd_grid(int d, int r) {
  PointSet ps;
  ps.dim = d;
  std::vector<int> c(static_cast<std::size_t>(d), 0);
  for (;;) {
    for (int j = 0; j < d; ++j) ps.coords.push_back(c[static_cast<std::size_t>(j)]);
    int j = 0;
    while (j < d && ++c[static_cast<std::size_t>(j)] > r) c[static_cast<std::size_t>(j++)] = 0;
    if (j == d) break;
  }
  return ps;
}

// Cospherical: the integer points x in [-r, r]^d with |x|^2 == r2 (exactly on
// one sphere), plus the centre (weighted `centre_weight` when weighted).
inline PointSet rtd_cospherical(int d, int r, int r2, bool with_centre) {
  PointSet ps;
  ps.dim = d;
  std::vector<int> c(static_cast<std::size_t>(d), -r);
  for (;;) {
    int s = 0;
    for (int v : c) s += v * v;
    if (s == r2)
      for (int v : c) ps.coords.push_back(v);
    int j = 0;
    while (j < d && ++c[static_cast<std::size_t>(j)] > r) c[static_cast<std::size_t>(j++)] = -r;
    if (j == d) break;
  }
  if (with_centre)
    for (int j = 0; j < d; ++j) ps.coords.push_back(0);
  return ps;
}

// Every point repeated `copies` times (interleaved), equal weights.
inline PointSet rtd_duplicated(const PointSet& base, int copies) {
  PointSet ps;
  ps.dim = base.dim;
  ps.weighted = base.weighted;
  for (int c = 0; c < copies; ++c)
    for (std::size_t i = 0; i < base.size(); ++i) {
      for (int j = 0; j < base.dim; ++j) ps.coords.push_back(base.point(i)[j]);
      if (base.weighted) ps.weights.push_back(base.weight(i));
    }
  return ps;
}

}  // namespace flipflop::test

// classify_inputs.hpp — input families for testing and timing the point
// classification (classify.hpp), shared by proptests/kernels_test.cpp and the
// CUDA test binary, plus the oracle: a plain sequential loop over
// predicates.hpp in Mode::gmp (GMP only, no filter).
//
// Families:
//   random          coordinates uniform in [-1, 1]: the filter decides nearly all.
//   lattice         small integer coordinates: many exactly coplanar (collinear)
//                   point/facet pairs, i.e. many exact zeros.
//   near_degenerate points computed on the plane (line) of their facet in
//                   floating point, then moved by at most one ulp per coordinate:
//                   mostly beyond the filter (rounding leaves them off the plane,
//                   so exact zeros are rare: see `lattice` for those).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "kernels_cuda/classify.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::kernels::testing {

enum class Family { random, lattice, near_degenerate };

inline const char* name(Family f) {
  switch (f) {
    case Family::random: return "random";
    case Family::lattice: return "lattice";
    default: return "near_degenerate";
  }
}

template <std::size_t D>
struct Input {
  PointSet pts;
  std::vector<std::array<Index, D>> facets;  // D vertex ids: triangles (3D), edges (2D)
  std::vector<Index> facet_of_point;
};
using Input3 = Input<3>;
using Input2 = Input<2>;

// n points in R^D, about n/64 facets whose vertices are the first 3·#facets
// points ("anchors", uniform random), every point assigned a random facet.
template <std::size_t D>
Input<D> make_input(Family fam, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> small(0, D == 3 ? 4 : 9);
  Input<D> in;
  in.pts.dim = static_cast<int>(D);
  in.pts.coords.resize(n * D);
  if (n == 0) return in;
  const std::size_t m = std::max<std::size_t>(1, n / 64);
  const std::size_t anchors = std::min(n, D * m);
  std::uniform_int_distribution<std::size_t> anchor(0, anchors - 1), facet(0, m - 1);
  in.facets.resize(m);
  for (auto& f : in.facets) {
    // Distinct vertices where there are enough anchors (a facet with a repeated
    // vertex makes every sign 0).
    for (std::size_t k = 0; k < D; ++k) {
      Index v;
      bool repeated;
      do {
        v = static_cast<Index>(anchor(rng));
        repeated = std::find(f.begin(), f.begin() + k, v) != f.begin() + k;
      } while (repeated && anchors >= D);
      f[k] = v;
    }
  }
  in.facet_of_point.resize(n);
  for (Index& f : in.facet_of_point) f = static_cast<Index>(facet(rng));
  for (std::size_t i = 0; i < n; ++i) {
    double* p = in.pts.coords.data() + i * D;
    if (fam == Family::lattice) {
      for (std::size_t j = 0; j < D; ++j) p[j] = small(rng);
    } else {
      for (std::size_t j = 0; j < D; ++j) p[j] = unit(rng);
    }
  }
  if (fam != Family::near_degenerate) return in;
  // Move every non-anchor point onto its facet's plane (line): p = a + Σ t_k (v_k - a),
  // rounded, then each coordinate up or down by one ulp or left as is.
  std::uniform_real_distribution<double> t(-0.5, 1.5);
  std::uniform_int_distribution<int> ulp(-1, 1);
  for (std::size_t i = anchors; i < n; ++i) {
    const auto& f = in.facets[in.facet_of_point[i]];
    const double* a = in.pts.point(f[0]);
    double* p = in.pts.coords.data() + i * D;
    double tk[D - 1];
    for (double& x : tk) x = t(rng);
    for (std::size_t j = 0; j < D; ++j) {
      double x = a[j];
      for (std::size_t k = 1; k < D; ++k) x += tk[k - 1] * (in.pts.point(f[k])[j] - a[j]);
      int step = ulp(rng);
      if (step != 0) x = std::nextafter(x, step > 0 ? HUGE_VAL : -HUGE_VAL);
      p[j] = x;
    }
  }
  return in;
}

// The oracle: one exact GMP predicate per point, sequentially.
inline std::vector<int> reference_signs(const Input3& in) {
  std::vector<int> s(in.pts.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& f = in.facets[in.facet_of_point[i]];
    s[i] = pred::orient3d_exact(in.pts.point(f[0]), in.pts.point(f[1]), in.pts.point(f[2]),
                                in.pts.point(i), pred::Mode::gmp);
  }
  return s;
}
inline std::vector<int> reference_signs(const Input2& in) {
  std::vector<int> s(in.pts.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& f = in.facets[in.facet_of_point[i]];
    s[i] = pred::orient2d_exact(in.pts.point(f[0]), in.pts.point(f[1]), in.pts.point(i),
                                pred::Mode::gmp);
  }
  return s;
}

}  // namespace flipflop::kernels::testing

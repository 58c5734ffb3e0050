// hull3_expect.hpp — the expected answer of the 3D hull kernels' tests
// (hull3_cpu_test, hull3_cuda_omp_test): the reference ffHull's canonical
// text, or "error: ..." for input it rejects.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "proptests/support/outcome.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"

namespace flipflop::test {

// the vertices of a hull's triangles
inline std::size_t vertex_count(const std::vector<Triangle>& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return v.size();
}

// CI's seed 5750008963199692262 of ghull_cuda_omp_test (stop 85), shrunk by
// RapidCheck: subnormal coordinates beside ones near 1, where the GPU hulls'
// scaled line-1 keys underflow (z * 2^-1 of the smallest subnormal is 0) and
// pick a fourth point on the plane of the first three (kernels_cuda/spread.cuh).
inline PointSet subnormal_line1_points() {
  const double tiny = std::numeric_limits<double>::denorm_min(), below1 = std::nextafter(1.0, 0.0);
  PointSet ps;
  ps.dim = 3;
  ps.coords = Values(std::vector<double>{below1, 0, 0, below1, std::nextafter(1.0, 2.0), 0, -tiny, tiny, 0,
                                         0, 1, tiny});
  return ps;
}

inline std::string hull3_reference_text(const PointSet& ps) {
  return outcome([&] { return ref::hull3_ffhull(ps); });
}

// In a sweep: the reference's text; a rejection is counted and must be of
// input that does not span R^3.
inline std::string hull3_sweep_expect(const PointSet& ps, std::size_t& rejected) {
  const std::string expect = hull3_reference_text(ps);
  if (is_error(expect)) {
    ++rejected;
    REQUIRE(!dimension_problem(ps).empty());
  }
  return expect;
}

// A pyramid whose base is `n` points drawn uniformly from the integer
// lattice of [0, 1000]^2 in the plane z = 0 (duplicates possible), apex
// (500, 500, apex_z) at index 0: apex_z > 0 makes z = 0 the bottom face,
// where every point's perturbation points inwards (most base points are
// outside a base triangle whose smallest corner index is below theirs, and
// none of them is a hull vertex but a few), apex_z < 0 the top face (the
// perturbations point outwards). The test of in_plane_tie.hpp's choice.
inline PointSet lattice_pyramid(std::size_t n, double apex_z, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, 1000);
  std::vector<double> c = {500, 500, apex_z};
  for (std::size_t i = 0; i < n; ++i) c.insert(c.end(), {double(u(rng)), double(u(rng)), 0.0});
  PointSet ps;
  ps.dim = 3;
  ps.coords = Values(std::move(c));
  return ps;
}

// An almost flat slab for the exact kernel point (§6.4.2): n points of the
// 1/64 grid of [0, 1]^2 at two heights one ulp apart (z = 1 or 1 + 2^-52:
// the centroid's z, 1 + 2^-54 or 1 + 2^-53, rounds onto a face plane), or 0
// and 2^-1074 (subnormal), many of them coplanar (the SoS decides the faces).
inline PointSet almost_flat_slab(std::uint64_t seed, bool subnormal, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> level(0, 1);
  PointSet ps;
  ps.dim = 3;
  std::vector<double> c;
  for (std::size_t i = 0; i < n; ++i) {
    const int l = level(rng);
    const double z = subnormal ? l * 4.9406564584124654e-324 : (l ? std::nextafter(1.0, 2.0) : 1.0);
    c.insert(c.end(), {std::round(unit(rng) * 64) / 64, std::round(unit(rng) * 64) / 64, z});
  }
  ps.coords = Values(std::move(c));
  return ps;
}

}  // namespace flipflop::test

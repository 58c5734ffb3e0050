// cgal_predicates.cpp — see cgal_predicates.hpp.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Warray-bounds"  // Eigen inside Epick_d (see cgal_regular_d.cpp)
#endif
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED 1
#endif
#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "peers/cgal_predicates.hpp"

namespace flipflop::peers {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// Times `reps` runs of body(i) over i < n; signs from the last run.
template <class Body>
double time_runs(std::size_t n, int reps, std::vector<int>& signs, Body&& body) {
  signs.assign(n, 0);
  std::vector<double> runs;
  for (int r = 0; r < std::max(1, reps); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i) signs[i] = body(i);
    const auto t1 = std::chrono::steady_clock::now();
    runs.push_back(std::chrono::duration<double>(t1 - t0).count());
  }
  return median_of(runs);
}

template <int D>
double orientation_d(const PredicateCalls& c, int reps, std::vector<int>& signs) {
  using KD = CGAL::Epick_d<CGAL::Dimension_tag<D>>;
  using P = typename KD::Point_d;
  std::vector<P> pts;
  pts.reserve(c.n * static_cast<std::size_t>(c.k));
  for (std::size_t i = 0; i < c.n * static_cast<std::size_t>(c.k); ++i)
    pts.emplace_back(c.coords + i * D, c.coords + (i + 1) * D);
  const auto orient = KD().orientation_d_object();
  return time_runs(c.n, reps, signs, [&](std::size_t i) {
    const auto first = pts.begin() + static_cast<std::ptrdiff_t>(i * (D + 1));
    return static_cast<int>(orient(first, first + (D + 1)));
  });
}

}  // namespace

bool cgal_epick_has(int k, int dim, bool lifted) {
  if (lifted) return (dim == 2 || dim == 3) && k == dim + 2;
  return dim >= 2 && dim <= 6 && k == dim + 1;
}

double cgal_epick_run(const PredicateCalls& c, int reps, std::vector<int>& signs) {
  if (!cgal_epick_has(c.k, c.dim, c.lifted))
    throw std::invalid_argument("cgal_epick_run: no Epick predicate for this shape");
  const std::size_t m = c.n * static_cast<std::size_t>(c.k);
  if (c.lifted && c.dim == 2) {
    std::vector<K::Weighted_point_2> w;
    w.reserve(m);
    for (std::size_t i = 0; i < m; ++i)
      w.emplace_back(K::Point_2(c.coords[2 * i], c.coords[2 * i + 1]), c.weights[i]);
    const auto side = K().power_side_of_oriented_power_circle_2_object();
    return time_runs(c.n, reps, signs, [&](std::size_t i) {
      const K::Weighted_point_2* q = w.data() + 4 * i;
      return static_cast<int>(side(q[0], q[1], q[2], q[3]));
    });
  }
  if (c.lifted) {
    std::vector<K::Weighted_point_3> w;
    w.reserve(m);
    for (std::size_t i = 0; i < m; ++i)
      w.emplace_back(K::Point_3(c.coords[3 * i], c.coords[3 * i + 1], c.coords[3 * i + 2]),
                     c.weights[i]);
    const auto side = K().power_side_of_oriented_power_sphere_3_object();
    return time_runs(c.n, reps, signs, [&](std::size_t i) {
      const K::Weighted_point_3* q = w.data() + 5 * i;
      return static_cast<int>(side(q[0], q[1], q[2], q[3], q[4]));
    });
  }
  if (c.dim == 2) {
    std::vector<K::Point_2> p;
    p.reserve(m);
    for (std::size_t i = 0; i < m; ++i) p.emplace_back(c.coords[2 * i], c.coords[2 * i + 1]);
    const auto orient = K().orientation_2_object();
    return time_runs(c.n, reps, signs, [&](std::size_t i) {
      const K::Point_2* q = p.data() + 3 * i;
      return static_cast<int>(orient(q[0], q[1], q[2]));
    });
  }
  if (c.dim == 3) {
    std::vector<K::Point_3> p;
    p.reserve(m);
    for (std::size_t i = 0; i < m; ++i)
      p.emplace_back(c.coords[3 * i], c.coords[3 * i + 1], c.coords[3 * i + 2]);
    const auto orient = K().orientation_3_object();
    return time_runs(c.n, reps, signs, [&](std::size_t i) {
      const K::Point_3* q = p.data() + 4 * i;
      return static_cast<int>(orient(q[0], q[1], q[2], q[3]));
    });
  }
  switch (c.dim) {
    case 4: return orientation_d<4>(c, reps, signs);
    case 5: return orientation_d<5>(c, reps, signs);
    default: return orientation_d<6>(c, reps, signs);
  }
}

}  // namespace flipflop::peers

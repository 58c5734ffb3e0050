// classify.cuh — the one source of the two-stage point classification
// (classify.hpp explains the task). Included by classify_omp.cpp (thrust's
// OpenMP backend, host compiler) and classify_cuda.cu (nvcc), each defining
// FF_KERNELS_NS to the namespace it implements, so that the two builds never
// share a symbol.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including classify.cuh"
#endif

#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/classify.hpp"
#include "predicates/err_double.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace detail {

// ---- Stage 1: the filter, one thread per point ------------------------------
// `K` = number of points of the determinant (3: orient2d, 4: orient3d), each
// facet holds K-1 vertex ids. The rows are (facet vertices..., point), the
// order of orient2d_exact / orient3d_exact, so the filter decides the same sign
// as predicates.hpp would. Returns +1 / -1 when certain, 0 when undecided.
template <int K>
struct FilterSign {
  const double* coords;          // point-major, K-1 coordinates per point
  const Index* facets;           // K-1 vertex ids per facet
  const Index* facet_of_point;   // facet id per point

  FF_HD int operator()(std::size_t i) const {
    constexpr int D = K - 1;
    const Index* f = facets + static_cast<std::size_t>(D) * facet_of_point[i];
    const double* rows[K];
    for (int k = 0; k < D; ++k) rows[k] = coords + static_cast<std::size_t>(D) * f[k];
    rows[D] = coords + static_cast<std::size_t>(D) * i;
    return pred::lambda_sign_filter<K>(rows, nullptr);
  }
};

struct IsUndecided {
  FF_HD bool operator()(int s) const { return s == 0; }
};

// ---- Where the data lives and how steps run ---------------------------------
// Buffers and steps: backend.cuh; the OpenMP grain size for this kernel.
constexpr std::size_t kParallelFrom = std::size_t{1} << 14;

// Host-side checks of the preconditions (classify.hpp).
template <int D>
void validate(const PointSet& pts, std::size_t n_facets, const Index* facets,
              const std::vector<Index>& facet_of_point, const char* who) {
  if (pts.dim != D)
    throw std::invalid_argument(std::string(who) + ": expected " + std::to_string(D) +
                                "D points, got " + std::to_string(pts.dim) + "D");
  if (facet_of_point.size() != pts.size())
    throw std::invalid_argument(std::string(who) + ": need one facet id per point");
  for (std::size_t k = 0; k < n_facets * D; ++k)
    if (facets[k] >= pts.size())
      throw std::invalid_argument(std::string(who) + ": facet vertex id out of range");
  for (Index f : facet_of_point)
    if (f >= n_facets) throw std::invalid_argument(std::string(who) + ": facet id out of range");
}

// Both stages. `facets` holds D vertex ids per facet.
template <int D>
std::vector<int> classify(const PointSet& pts, std::size_t n_facets, const Index* facets,
                          const std::vector<Index>& facet_of_point, kernels::ClassifyStats* stats,
                          const char* who) {
  validate<D>(pts, n_facets, facets, facet_of_point, who);
  const std::size_t n = pts.size();
  backend::Buffer<double> b_coords;
  backend::Buffer<Index> b_facets, b_fop;
  const double* coords = backend::to_device(pts.coords.data(), pts.coords.size(), b_coords);
  const Index* d_facets = backend::to_device(facets, n_facets * D, b_facets);
  const Index* d_fop = backend::to_device(facet_of_point.data(), n, b_fop);
  thrust::counting_iterator<std::size_t> first(0), last(n);

  // Stage 1: filtered signs for all points.
  backend::Buffer<int> b_sign(n);
  const FilterSign<D + 1> filter{coords, d_facets, d_fop};
  backend::run_step<kParallelFrom>(n, [&](auto policy) { thrust::transform(policy, first, last, b_sign.begin(), filter); });

  // Compact the undecided points (stream compaction keeps stage 2 small).
  backend::Buffer<std::size_t> b_undecided(n);
  std::size_t n_undecided = 0;
  backend::run_step<kParallelFrom>(n, [&](auto policy) {
    n_undecided = static_cast<std::size_t>(
        thrust::copy_if(policy, first, last, b_sign.begin(), b_undecided.begin(), IsUndecided()) -
        b_undecided.begin());
  });
  std::vector<int> sign = backend::to_host(b_sign, n);
  const std::vector<std::size_t> undecided = backend::to_host(b_undecided, n_undecided);

  // Stage 2: exact signs (GMP) for the undecided points, on the host.
  for (std::size_t i : undecided) {
    const Index* f = facets + static_cast<std::size_t>(D) * facet_of_point[i];
    if constexpr (D == 2)
      sign[i] = pred::orient2d_exact(pts.point(f[0]), pts.point(f[1]), pts.point(i),
                                     pred::Mode::gmp);
    else
      sign[i] = pred::orient3d_exact(pts.point(f[0]), pts.point(f[1]), pts.point(f[2]),
                                     pts.point(i), pred::Mode::gmp);
  }
  if (stats) *stats = {n, n_undecided};
  return sign;
}

static_assert(sizeof(Triangle) == 3 * sizeof(Index), "Triangle must be three packed ids");
static_assert(sizeof(kernels::Edge) == 2 * sizeof(Index), "Edge must be two packed ids");

}  // namespace detail

std::vector<int> classify_points_3d(const PointSet& pts, const std::vector<Triangle>& facets,
                                    const std::vector<Index>& facet_of_point,
                                    ClassifyStats* stats) {
  return detail::classify<3>(pts, facets.size(), facets.empty() ? nullptr : facets.front().data(),
                             facet_of_point, stats, "classify_points_3d");
}

std::vector<int> classify_points_2d(const PointSet& pts, const std::vector<Edge>& edges,
                                    const std::vector<Index>& edge_of_point,
                                    ClassifyStats* stats) {
  return detail::classify<2>(pts, edges.size(), edges.empty() ? nullptr : edges.front().data(),
                             edge_of_point, stats, "classify_points_2d");
}

}  // namespace flipflop::FF_KERNELS_NS

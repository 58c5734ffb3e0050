// classify.hpp — "classify points against facets", the data-parallel step of
// the certifier and of ffHull's point assignment (thesis §6.4.1–6.4.2): for
// every point i and its facet f = facet_of_point[i], the exact sign
//
//   3D: orient3d_exact(a, b, c, p_i)   for the facet triangle (a, b, c),
//   2D: orient2d_exact(u, v, p_i)      for the hull edge (u, v),
//
// unperturbed (0 = exactly on the facet's plane / line; predicates.hpp
// conventions: > 0 means inside for a facet counter-clockwise seen from outside).
//
// Two stages, as in thesis §6.4.2: a data-parallel filter (lambda_filter.hpp,
// the same __host__ __device__ functor for every backend) writes the certain
// signs and 0 where the filter cannot decide; the undecided points are
// compacted and decided on the host by predicates.hpp in Mode::gmp.
//
// Backends built from the same source (classify.cuh):
//   flipflop::kernels_omp  — thrust's OpenMP backend, compiled by the host
//                            compiler (library flipflop_kernels_omp);
//   flipflop::kernels_cuda — thrust's CUDA backend, nvcc for sm_90 (library
//                            flipflop_kernels_cuda, only where nvcc exists).
// The TBB version calling predicates.hpp directly is kernels_cpu/classify_tbb.hpp.
//
// Preconditions (checked, std::invalid_argument otherwise): the point set has
// the right dimension, facet_of_point has one entry per point, every facet id
// and every facet vertex id is in range.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::kernels {

using Edge = std::array<Index, 2>;

// What the two stages did.
struct ClassifyStats {
  std::size_t points = 0;       // entries classified
  std::size_t exact_stage = 0;  // entries the filter left undecided (GMP stage)
};

}  // namespace flipflop::kernels

namespace flipflop::kernels_omp {
using kernels::ClassifyStats;
using kernels::Edge;
std::vector<int> classify_points_3d(const PointSet& pts, const std::vector<Triangle>& facets,
                                    const std::vector<Index>& facet_of_point,
                                    ClassifyStats* stats = nullptr);
std::vector<int> classify_points_2d(const PointSet& pts, const std::vector<Edge>& edges,
                                    const std::vector<Index>& edge_of_point,
                                    ClassifyStats* stats = nullptr);
}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {
using kernels::ClassifyStats;
using kernels::Edge;
// Number of usable CUDA devices; 0 when there is none or no working driver.
int device_count();
std::vector<int> classify_points_3d(const PointSet& pts, const std::vector<Triangle>& facets,
                                    const std::vector<Index>& facet_of_point,
                                    ClassifyStats* stats = nullptr);
std::vector<int> classify_points_2d(const PointSet& pts, const std::vector<Edge>& edges,
                                    const std::vector<Index>& edge_of_point,
                                    ClassifyStats* stats = nullptr);
}  // namespace flipflop::kernels_cuda

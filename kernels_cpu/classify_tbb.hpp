// classify_tbb.hpp — "classify points against facets" with TBB: for every
// point i, the exact sign of orient3d_exact(a, b, c, p_i) for its facet
// (a, b, c) = facets[facet_of_point[i]] (2D: orient2d_exact(u, v, p_i) for its
// edge), 0 allowed. tbb::parallel_for over the points; each call goes through
// predicates.hpp in Mode::filtered (filter, then GMP where it is uncertain).
// The thrust version of the same step (OpenMP / CUDA) is
// kernels_cuda/classify.hpp; all of them equal a sequential loop in Mode::gmp
// (proptests/kernels_test.cpp).
//
// Preconditions (checked, std::invalid_argument otherwise): dimension 3 (2),
// one facet id per point, all ids in range.
#pragma once

#include <array>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::kernels_cpu {

using Edge = std::array<Index, 2>;

std::vector<int> classify_points_3d(const PointSet& pts, const std::vector<Triangle>& facets,
                                    const std::vector<Index>& facet_of_point);
std::vector<int> classify_points_2d(const PointSet& pts, const std::vector<Edge>& edges,
                                    const std::vector<Index>& edge_of_point);

}  // namespace flipflop::kernels_cpu

// ball_test.hpp — the per-point test of an exactly verified inner ball
// (inner_ball.hpp explains the set-up and the rounding argument): plain data
// and one __host__ __device__ test, without GMP, so that the GPU kernels
// (kernels_cuda/) run the same test on the ball the host verified.
#pragma once

#include <cstddef>
#include <vector>

#include "predicates/err_double.hpp"  // FF_HD
#include "reference/point_set.hpp"

namespace flipflop::certify {

template <int D>
struct BallTest {
  double s[D] = {};  // the centre
  double limit = 0;  // 0: empty ball, no point is inside

  // |p - s|^2 < r^2 certainly (inner_ball.hpp: computed + 2^-990 < r2 (1 - 2^-40))
  FF_HD bool strictly_inside(const double* p) const {
    double sum = 0x1p-990;
    for (int j = 0; j < D; ++j) {
      const double d = p[j] - s[j];
      sum += d * d;
    }
    return sum < limit;
  }
};

// The inner disk of the polygon `ccw` (input indices, counter-clockwise): a
// disk inside every edge's inner half-plane, verified exactly (GMP), empty
// when the verification fails. When the polygon is convex (weakly), the disk
// lies inside it, hence inside conv(S). Sequential; for polygons of a few
// thousand vertices (the GPU 2D hull's throw-away).
BallTest<2> inner_disk(const PointSet& ps, const std::vector<Index>& ccw);

}  // namespace flipflop::certify

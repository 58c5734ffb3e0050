// rounded_centroid.hpp — the fast kernel point of the parallel ffHull kernels
// (kernels_cpu/hull3/ffhull.cpp, kernels_cuda/hull3/hull3.cuh): the centroid
// of the initial tetrahedron (Algorithm 7 line 4) rounded to doubles, usable
// when it lies strictly inside the tetrahedron exactly (four exact orient3d),
// with SoS index n like the reference's exact centroid; then it is strictly
// inside the perturbed tetrahedron too. When it is not (an almost flat
// tetrahedron, §6.4.2's trap) the kernels fall back to the exact centroid.
#pragma once

#include <array>
#include <cmath>

#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// tet: (a, b, c) counter-clockwise seen from outside, d on its inner side.
// Sets s to the rounded centroid; true when it is strictly inside exactly.
inline bool rounded_centroid(const PointSet& ps, const std::array<Index, 4>& tet, std::array<double, 3>& s) {
  for (int j = 0; j < 3; ++j)
    s[j] = ((ps.point(tet[0])[j] + ps.point(tet[1])[j]) + (ps.point(tet[2])[j] + ps.point(tet[3])[j])) * 0.25;
  const Triangle faces[4] = {{tet[0], tet[1], tet[2]}, {tet[0], tet[2], tet[3]}, {tet[0], tet[3], tet[1]},
                             {tet[1], tet[3], tet[2]}};
  bool inside = std::isfinite(s[0]) && std::isfinite(s[1]) && std::isfinite(s[2]);
  for (const Triangle& F : faces)
    inside = inside && pred::orient3d_exact(ps.point(F[0]), ps.point(F[1]), ps.point(F[2]), s.data()) > 0;
  return inside;
}

}  // namespace flipflop::cpu

// in_plane_tie.hpp — line 8 of ffHull (Algorithm 7: insert the furthest point
// of a triangle's outside set) for the points that lie exactly in the
// triangle's plane, shared by the parallel kernels (kernels_cpu/hull3/ffhull.cpp
// and kernels_cuda/hull3/hull3.cuh, __host__ __device__).
//
// The kernels choose the point of largest rounded distance key
// (p - t0) · ((t1 - t0) × (t2 - t0)). Points in the plane have key 0 exactly
// (the floors and walls of a scanned building), and Simulation of Simplicity
// puts some of them outside. Any outside point is a correct choice
// (reference/hull3/ffhull.hpp); the furthest one under the perturbation is a
// vertex of the hull, and any other is inserted only for flip-flop to remove
// it again: on planes3 at 10^6 points, with ties broken by the smaller index
// alone, 294225 insertions for 706 hull vertices and flip-flop 81 % of the
// time. So among key-0 points the larger tie wins (then the smaller index).
//
// Why this tie is the perturbed distance's order. For p in the plane of
// (t0, t1, t2), orient3d(t0, t1, t2, p) under SoS is the sign of the first
// non-zero term in the order of the perturbations, which shrink with the
// index (DESIGN.md). With m the smallest index of the triangle and u, v the
// other corners in cyclic order:
//   * p < m: the leading term is p's own perturbation (order ε_p), larger
//     for a smaller p, and larger than any term of an index above m;
//   * p > m: the leading term is m's perturbation (order ε_m, the same for
//     every such p) times a cofactor, the orientation of (u, v, p) projected
//     onto a coordinate plane, which for p in the plane of the triangle is
//     λ_m(p), p's barycentric coordinate of m, times a constant of the
//     triangle: the larger λ_m(p), the further.
// tie = +inf for p < m (ties among them: the smaller index, as the kernels
// order equal ties), else ((u - p) × (v - p)) · n = |n|^2 λ_m(p), n the
// triangle's normal. It is rounded: it only orders a choice that any answer
// allows, so the hull does not depend on it.
#pragma once

#include <cstdint>

#include "predicates/err_double.hpp"  // FF_HD

namespace flipflop::cpu {

// t: the triangle's indices (counter-clockwise from outside, as the kernels
// keep them), c: their coordinates; p (coordinates x) in its plane.
FF_HD inline double in_plane_tie(const std::uint32_t* t, const double* const* c, std::uint32_t p, const double* x) {
  int m = 0;
  if (t[1] < t[m]) m = 1;
  if (t[2] < t[m]) m = 2;
  if (p < t[m]) return HUGE_VAL;
  const double* a = c[0];
  const double bx = c[1][0] - a[0], by = c[1][1] - a[1], bz = c[1][2] - a[2];
  const double cx = c[2][0] - a[0], cy = c[2][1] - a[1], cz = c[2][2] - a[2];
  const double nx = by * cz - bz * cy, ny = bz * cx - bx * cz, nz = bx * cy - by * cx;
  const double* u = c[(m + 1) % 3];
  const double* v = c[(m + 2) % 3];
  const double ux = u[0] - x[0], uy = u[1] - x[1], uz = u[2] - x[2];
  const double vx = v[0] - x[0], vy = v[1] - x[1], vz = v[2] - x[2];
  return (uy * vz - uz * vy) * nx + (uz * vx - ux * vz) * ny + (ux * vy - uy * vx) * nz;
}

}  // namespace flipflop::cpu

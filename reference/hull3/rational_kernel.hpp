// rational_kernel.hpp — a kernel point with exact dyadic coordinates (thesis
// §6.4: ffHull grows a polyhedron star-shaped w.r.t. "the centroid s of the
// initial tetrahedron"; §6.4.2: "the only source of inexact computation is
// computing the kernel point s. If the initial tetrahedron is almost flat, its
// centroid computed inexactly can lie outside").
//
// Here s is never rounded: the centroid of four input points is a dyadic
// rational (a sum of four doubles divided by 4), held exactly by
// pred::RationalPoint, and every predicate on it is decided exactly by
// pred::mixed_sign. In the Simulation of Simplicity s is the first auxiliary
// point of the computation: index n = ps.size(), after all inputs
// (predicates.hpp, "Points that are not inputs"), so its perturbation is
// smaller than that of every input and never changes a predicate among inputs.
//
// The trap of §6.4.2 in its exact form: the four points must be affinely
// independent *exactly*, not merely under the perturbation. If they are only
// independent under SoS (four exactly coplanar points), their exact centroid
// lies on their common plane, i.e. on the boundary of the perturbed
// tetrahedron, and whether the perturbed s is inside depends on a perturbation
// that is not the one of the inputs' tetrahedron. With exactly independent
// points the centroid is strictly inside the unperturbed tetrahedron, hence
// strictly inside the (infinitesimally close) perturbed one.
// centroid_kernel() therefore rejects four exactly coplanar points.
#pragma once

#include "predicates/rational_point.hpp"
#include "reference/hull3/kernel_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

class RationalKernel : public KernelPoint {
 public:
  // s = p, with SoS index ps.size(); ps must be 3D and outlive the kernel.
  RationalKernel(const PointSet& ps, pred::RationalPoint p);

  // sign of orient3d(a, b, c, s) under SoS (+1 or -1 for distinct a, b, c):
  // > 0 when s lies on the inner side of the triangle (a, b, c) seen
  // counter-clockwise from outside.
  int side(Index a, Index b, Index c) const override;

  const pred::RationalPoint& point() const { return p_; }
  pred::PointId id() const { return id_; }
  // side()'s per-input filter bound (+inf: none; the exact stage decides):
  // for the deterministic sensitivity test (filter_sensitivity_test.cpp)
  double static_bound() const { return static_bound_; }

 private:
  const PointSet* ps_;
  pred::RationalPoint p_;
  pred::PointId id_;
  double q_[3];         // the filter's double coordinates of s
  double static_bound_;  // side()'s per-input bound (rational_kernel.cpp); +inf: none
};

// The exact centroid of the input points a, b, c, d (a kernel point of the
// tetrahedron abcd, index ps.size()). Throws std::invalid_argument when the
// four points are exactly coplanar (see above): their centroid would not be a
// kernel point.
RationalKernel centroid_kernel(const PointSet& ps, Index a, Index b, Index c, Index d);

}  // namespace flipflop::ref

// rational_kernel.cpp — the exact kernel point of ffHull (thesis §6.4,
// §6.4.2); see rational_kernel.hpp.
#include "reference/hull3/rational_kernel.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "predicates/predicates.hpp"

namespace flipflop::ref {

RationalKernel::RationalKernel(const PointSet& ps, pred::RationalPoint p)
    : ps_(&ps), p_(std::move(p)), id_(static_cast<pred::PointId>(ps.size())) {
  if (ps.dim != 3 || p_.dim != 3) throw std::invalid_argument("RationalKernel: a 3D point set and a 3D point needed");
}

int RationalKernel::side(Index a, Index b, Index c) const {
  // det Λ of the rows a, b, c, s: orient3d(a, b, c, s), perturbed (s last in
  // the perturbation order, predicates.hpp).
  const pred::MixedRow rows[4] = {{a, ps_->point(a), nullptr},
                                  {b, ps_->point(b), nullptr},
                                  {c, ps_->point(c), nullptr},
                                  {id_, nullptr, &p_}};
  return pred::mixed_sign(4, rows, true);
}

RationalKernel centroid_kernel(const PointSet& ps, Index a, Index b, Index c, Index d) {
  if (ps.dim != 3) throw std::invalid_argument("centroid_kernel: the point set is not 3D");
  const std::size_t n = ps.size();
  for (Index v : {a, b, c, d})
    if (v >= n) throw std::invalid_argument("centroid_kernel: index " + std::to_string(v) + " out of range");
  if (pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d)) == 0)
    throw std::invalid_argument("centroid_kernel: points " + std::to_string(a) + " " + std::to_string(b) + " " +
                                std::to_string(c) + " " + std::to_string(d) +
                                " are coplanar, their centroid is not strictly inside their tetrahedron");
  const double* pts[4] = {ps.point(a), ps.point(b), ps.point(c), ps.point(d)};
  return RationalKernel(ps, pred::RationalPoint::centroid(pts, 4, 3));
}

}  // namespace flipflop::ref

// rational_kernel.cpp — the exact kernel point of ffHull (thesis §6.4,
// §6.4.2); see rational_kernel.hpp.
#include "reference/hull3/rational_kernel.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::ref {

// A per-input bound for side() (the static filter of thesis §6.4.2, "precomputed
// error bound", extended to the approximate row of s). Rows a, b, c are inputs,
// s = q + δ with q the filter's doubles and |δ_j| <= e_j (RationalPoint::approx).
// det Λ is affine in the row of s: det Λ(s) = det Λ(q) + Σ_j δ_j c_j with c_j
// the cofactors of that row, each ± a 2 x 2 determinant of differences of
// input coordinates, so |c_j| <= 2 (2M)^2 with M the largest input magnitude.
// With q's coordinates among the values of the StaticFilter (its `extra`),
// |r - det Λ(q)| <= plain bound(4) (static_filter.hpp (1')), r the exact
// result of det T(q)'s last operation, whose rounding fl(r) is the computed
// value: |fl(r)| <= (1 + u)|r| and fl(r) has the sign of r or is 0. Hence
//     |r - det Λ(s)| <= bound(4) + U,   U = 8 M^2 Σ_j e_j,
// and a computed |det T(q)| above (bound(4) + U)(1 + 2^-40) has the sign of
// det Λ(s) (non-zero, so the perturbation does not matter). U is computed
// upwards: five roundings to nearest are covered by the factor 1 + 2^-20 and
// the sum by 1 + 2^-40; M^2 Σ e
// is only used when M and Σ e are at least 2^-300 (no product underflows),
// Σ e == 0 (q exact) gives U = 0, and an overflow gives +inf (no decision).
RationalKernel::RationalKernel(const PointSet& ps, pred::RationalPoint p)
    : ps_(&ps), p_(std::move(p)), id_(static_cast<pred::PointId>(ps.size())), static_bound_(HUGE_VAL) {
  if (ps.dim != 3 || p_.dim != 3) throw std::invalid_argument("RationalKernel: a 3D point set and a 3D point needed");
  double esum = 0.0;
  for (int j = 0; j < 3; ++j) {
    q_[j] = p_.approx[j].v;
    esum += p_.approx[j].e;
  }
  const double* coords = ps.coords.data();
  const std::size_t nv = ps.size() * 3;
  double M = 0.0;
  for (std::size_t i = 0; i < nv; ++i) M = std::fmax(M, std::fabs(coords[i]));
  double U = HUGE_VAL;
  if (esum == 0.0) U = 0.0;
  else if (M >= 0x1p-300 && esum >= 0x1p-300) U = 8.0 * M * M * esum * (1.0 + 0x1p-20);
  const double b = pred::StaticFilter::for_points(coords, ps.size(), 3, nullptr, q_, 3).bound(4, false);
  if (std::isfinite(b) && std::isfinite(U)) static_bound_ = (b + U) * (1.0 + 0x1p-40);
}

int RationalKernel::side(Index a, Index b, Index c) const {
  // det Λ of the rows a, b, c, s: orient3d(a, b, c, s), perturbed (s last in
  // the perturbation order, predicates.hpp).
  const double* p[4] = {ps_->point(a), ps_->point(b), ps_->point(c), q_};
  if (const int s = pred::sign_beyond_bound<4>(p, nullptr, static_bound_)) return s;
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

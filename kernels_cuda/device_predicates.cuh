// device_predicates.cuh — the predicates the kernels of kernels_cuda/ call from
// their __host__ __device__ functors: the same signs as predicates.hpp's
// pred::orient2d / orient3d / power2d / compare_sos (Simulation of Simplicity
// on the points' ids, DESIGN.md), evaluated by predicates/staged.hpp's default
// path — the per-input static filter (when one is given), the per-call
// semi-static filter, the ErrDouble filter, the exact expansion stage, SoS —
// with no GMP, no heap and no recursion, so that nvcc compiles them for the
// device and the OpenMP build runs the very same code on the host.
//
// Stack per call: the exact stage's buffers (predicates/exact_expansion.hpp,
// "Stack per call") for K = 2..5 rows.
#pragma once

#include "predicates/predicates.hpp"
#include "predicates/staged.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::dev {

using pred::PointId;
using pred::StaticFilter;

// sign det Λ of K rows (predicates.hpp conventions), SoS on `ids`; `f` may be
// null (no per-input filter), `w` null for unlifted rows.
template <int K>
FF_HD inline int lambda(const StaticFilter* f, const PointId* ids, const double* const* p, const double* w) {
  return pred::lambda_sign_staged<K>(f, ids, p, w);
}

// orient2d(a, b, c) > 0: c left of the directed line ab (counter-clockwise).
FF_HD inline int orient2d(const StaticFilter* f, PointId ia, const double* a, PointId ib, const double* b,
                          PointId ic, const double* c) {
  const PointId id[3] = {ia, ib, ic};
  const double* p[3] = {a, b, c};
  return lambda<3>(f, id, p, nullptr);
}

// orient3d(a, b, c, d), predicates.hpp's sign convention.
FF_HD inline int orient3d(const StaticFilter* f, PointId ia, const double* a, PointId ib, const double* b,
                          PointId ic, const double* c, PointId id_, const double* d) {
  const PointId id[4] = {ia, ib, ic, id_};
  const double* p[4] = {a, b, c, d};
  return lambda<4>(f, id, p, nullptr);
}

// power2d(a, b, c, d) on weighted points, predicates.hpp's sign convention.
FF_HD inline int power2d(const StaticFilter* f, const PointId* ids, const double* const* p, const double* w) {
  return lambda<4>(f, ids, p, w);
}

// orient3d(a, b, c, s) under SoS, s the centroid of the four input points
// src[0..11] (row-major) with SoS index `is` (after every input: the exact
// kernel point of ffHull, reference/hull3/rational_kernel.hpp, whose side()
// this is): pred::mixed_sign's filter-free path — rows sorted by index, the
// centroid's row taken as (Σ src, 4), a positive multiple of (s, 1), on the
// exact expansion stage (xp::lambda_exact_mixed) — so the same sign as the
// reference's, with no GMP. The caller filters first (RationalKernel's
// per-input bound).
FF_HD inline int orient3d_centroid(PointId ia, const double* a, PointId ib, const double* b, PointId ic,
                                   const double* c, PointId is, const double* src) {
  const PointId ids[4] = {ia, ib, ic, is};
  int order[4];
  const int parity = pred::sort_rows_by_id(4, ids, order);
  if (parity == 0) return 0;
  const double* x[4] = {a, b, c, nullptr};
  pred::xp::MixedRowX rows[4];
  for (int i = 0; i < 4; ++i) {
    if (order[i] == 3) {
      rows[i].src = src;
      rows[i].count = 4;
    } else {
      rows[i].x = x[order[i]];
    }
  }
  return parity * pred::xp::lambda_exact_mixed<4>(rows, true);
}

// compare_sos(a, b, coord): the sign of a[coord] - b[coord] under the
// perturbation (never 0 for distinct ids).
FF_HD inline int compare_sos(PointId ia, const double* a, PointId ib, const double* b, int coord) {
  if (a[coord] != b[coord]) return a[coord] < b[coord] ? -1 : 1;  // the perturbation is infinitesimal
  const PointId id[2] = {ia, ib};
  const double* p[2] = {a + coord, b + coord};
  return lambda<2>(nullptr, id, p, nullptr);
}

}  // namespace flipflop::dev

// predicates.cpp — filtered and GMP predicates with Simulation of Simplicity.
// The derivation of the perturbation is in predicates.hpp.
#include "predicates.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "lambda_filter.hpp"
#include "rational_point.hpp"

namespace flipflop::pred {

namespace {

int filter_dispatch(int k, const double* const* c, const double* w) {
  switch (k) {
    case 2: return lambda_sign_filter<2>(c, w);
    case 3: return lambda_sign_filter<3>(c, w);
    case 4: return lambda_sign_filter<4>(c, w);
    case 5: return lambda_sign_filter<5>(c, w);
    case 6: return lambda_sign_filter<6>(c, w);
    case 7: return lambda_sign_filter<7>(c, w);
    case 8: return lambda_sign_filter<8>(c, w);
    default: return 0;
  }
}

// Sorts row positions by point index (insertion sort on at most 8 rows) and
// returns the parity of the permutation, or 0 if an index repeats: then two
// rows are the same point and the determinant is 0 even under perturbation.
int sort_by_id(int k, const PointId* ids, int* order) {
  for (int i = 0; i < k; ++i) order[i] = i;
  if (!ids) return 1;
  int parity = 1;
  for (int i = 1; i < k; ++i) {
    for (int j = i; j > 0 && ids[order[j - 1]] > ids[order[j]]; --j) {
      std::swap(order[j - 1], order[j]);
      parity = -parity;
    }
  }
  for (int i = 1; i < k; ++i)
    if (ids[order[i - 1]] == ids[order[i]]) return 0;
  return parity;
}

// The exact stage: sign of det of the (row-sorted) integer Λ-matrix, then the
// Simulation of Simplicity when it is 0 and a perturbation is requested.
int exact_stage(const exact::IntLambda& mat, int parity, bool sos) {
  const std::uint32_t all = (1u << mat.k) - 1u;
  int s = exact::minor_sign(mat, all, all);
  if (s != 0 || !sos) return parity * s;
  return parity * exact::sos_sign(mat);
}

}  // namespace

int lambda_sign(int k, const PointId* ids, const double* const* coords, const double* weights,
                Mode m) {
  if (k < 2 || k > 8) throw std::invalid_argument("lambda_sign: k must be in 2..8");
  if (weights && k < 3) throw std::invalid_argument("lambda_sign: a lifted matrix needs k >= 3");
  int order[8];
  const int parity = sort_by_id(k, ids, order);
  if (parity == 0) return 0;
  if (m == Mode::filtered) {
    if (int s = filter_dispatch(k, coords, weights)) return s;
  }
  const double* sorted_c[8];
  double sorted_w[8];
  for (int i = 0; i < k; ++i) {
    sorted_c[i] = coords[order[i]];
    if (weights) sorted_w[i] = weights[order[i]];
  }
  return exact_stage(exact::build_lambda(k, sorted_c, weights ? sorted_w : nullptr), parity,
                     ids != nullptr);
}

// ---- rows mixing doubles and exact rational points (rational_point.hpp) ------
RationalPoint RationalPoint::centroid(const double* const* pts, int count, int dim) {
  if (count <= 0 || (count & (count - 1)) != 0 || dim < 1 || dim > 3)
    throw std::invalid_argument("RationalPoint::centroid: count must be a power of two, dim <= 3");
  int shift = 0;
  while ((1 << shift) < count) ++shift;
  RationalPoint r;
  r.dim = dim;
  r.exact.resize(static_cast<size_t>(dim));
  for (int j = 0; j < dim; ++j) {
    exact::Dyadic sum;
    ErrDouble approx(0.0);
    for (int i = 0; i < count; ++i) {
      sum = exact::add(sum, exact::to_dyadic(pts[i][j]));
      approx = (i == 0) ? ErrDouble(pts[i][j]) : approx + ErrDouble(pts[i][j]);
    }
    sum.e -= shift;
    r.exact[static_cast<size_t>(j)] = sum;
    // division by a power of two is exact in binary64 unless it underflows;
    // the ErrDouble rule for products covers that case too.
    r.approx[j] = approx * ErrDouble(1.0 / count);
  }
  return r;
}

int mixed_sign(int k, const MixedRow* rows, bool sos) {
  if (k < 2 || k > 4) throw std::invalid_argument("mixed_sign: k must be in 2..4");
  const int dim = k - 1;
  ErrDouble approx[4 * 3];
  PointId ids[4];
  for (int i = 0; i < k; ++i) {
    ids[i] = rows[i].id;
    for (int j = 0; j < dim; ++j)
      approx[i * dim + j] = rows[i].x ? ErrDouble(rows[i].x[j]) : rows[i].r->approx[j];
  }
  int order[8];
  const int parity = sort_by_id(k, sos ? ids : nullptr, order);
  if (parity == 0) return 0;
  int s = 0;
  switch (k) {
    case 2: s = lambda_sign_filter_err<2>(approx); break;
    case 3: s = lambda_sign_filter_err<3>(approx); break;
    default: s = lambda_sign_filter_err<4>(approx); break;
  }
  if (s != 0) return s;
  std::vector<exact::Dyadic> entries(static_cast<size_t>(k * dim));
  for (int i = 0; i < k; ++i) {
    const MixedRow& row = rows[order[i]];
    for (int j = 0; j < dim; ++j)
      entries[static_cast<size_t>(i * dim + j)] =
          row.x ? exact::to_dyadic(row.x[j]) : row.r->exact[static_cast<size_t>(j)];
  }
  return exact_stage(exact::build_lambda_dyadic(k, entries), parity, sos);
}

// ---- exact (unperturbed) ----------------------------------------------------
int orient2d_exact(const double* a, const double* b, const double* c, Mode m) {
  const double* p[3] = {a, b, c};
  return lambda_sign(3, nullptr, p, nullptr, m);
}
int orient3d_exact(const double* a, const double* b, const double* c, const double* d, Mode m) {
  const double* p[4] = {a, b, c, d};
  return lambda_sign(4, nullptr, p, nullptr, m);
}
int power2d_exact(WPt a, WPt b, WPt c, WPt d, Mode m) {
  const double* p[4] = {a.x, b.x, c.x, d.x};
  const double w[4] = {a.w, b.w, c.w, d.w};
  return lambda_sign(4, nullptr, p, w, m);
}
int power3d_exact(WPt a, WPt b, WPt c, WPt d, WPt e, Mode m) {
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  return lambda_sign(5, nullptr, p, w, m);
}
int orient_d_exact(int d, const double* const* p, Mode m) {
  if (d < 1 || d > 6) throw std::invalid_argument("orient_d: d must be in 1..6");
  return lambda_sign(d + 1, nullptr, p, nullptr, m);
}
int power_d_exact(int d, const double* const* p, const double* w, Mode m) {
  if (d < 1 || d > 5) throw std::invalid_argument("power_d: d must be in 1..5");
  return lambda_sign(d + 2, nullptr, p, w, m);
}

// ---- Simulation of Simplicity ----------------------------------------------
int orient2d(Pt a, Pt b, Pt c, Mode m) {
  const PointId id[3] = {a.id, b.id, c.id};
  const double* p[3] = {a.x, b.x, c.x};
  return lambda_sign(3, id, p, nullptr, m);
}
int orient3d(Pt a, Pt b, Pt c, Pt d, Mode m) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  return lambda_sign(4, id, p, nullptr, m);
}
int power2d(WPt a, WPt b, WPt c, WPt d, Mode m) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  const double w[4] = {a.w, b.w, c.w, d.w};
  return lambda_sign(4, id, p, w, m);
}
int power3d(WPt a, WPt b, WPt c, WPt d, WPt e, Mode m) {
  const PointId id[5] = {a.id, b.id, c.id, d.id, e.id};
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  return lambda_sign(5, id, p, w, m);
}
int compare_sos(Pt a, Pt b, int coord, Mode m) {
  const PointId id[2] = {a.id, b.id};
  const double* p[2] = {a.x + coord, b.x + coord};
  return lambda_sign(2, id, p, nullptr, m);
}
int orient_d(int d, const Pt* pts, Mode m) {
  if (d < 1 || d > 6) throw std::invalid_argument("orient_d: d must be in 1..6");
  PointId id[8];
  const double* p[8];
  for (int i = 0; i <= d; ++i) {
    id[i] = pts[i].id;
    p[i] = pts[i].x;
  }
  return lambda_sign(d + 1, id, p, nullptr, m);
}
int power_d(int d, const WPt* pts, Mode m) {
  if (d < 1 || d > 5) throw std::invalid_argument("power_d: d must be in 1..5");
  PointId id[8];
  const double* p[8];
  double w[8];
  for (int i = 0; i < d + 2; ++i) {
    id[i] = pts[i].id;
    p[i] = pts[i].x;
    w[i] = pts[i].w;
  }
  return lambda_sign(d + 2, id, p, w, m);
}

int dot2d_exact(const double* a, const double* b, const double* c) {
  ErrDouble ux = ErrDouble(b[0]) - ErrDouble(a[0]), uy = ErrDouble(b[1]) - ErrDouble(a[1]);
  ErrDouble vx = ErrDouble(c[0]) - ErrDouble(b[0]), vy = ErrDouble(c[1]) - ErrDouble(b[1]);
  if (int s = sign_if_certain(ux * vx + uy * vy)) return s;
  using namespace exact;
  Dyadic dux = sub(to_dyadic(b[0]), to_dyadic(a[0])), duy = sub(to_dyadic(b[1]), to_dyadic(a[1]));
  Dyadic dvx = sub(to_dyadic(c[0]), to_dyadic(b[0])), dvy = sub(to_dyadic(c[1]), to_dyadic(b[1]));
  return sign(add(mul(dux, dvx), mul(duy, dvy)));
}

}  // namespace flipflop::pred

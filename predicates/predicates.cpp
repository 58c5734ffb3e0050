// predicates.cpp — filtered and GMP predicates with Simulation of Simplicity.
// The derivation of the perturbation is in predicates.hpp.
// The host's one instantiation of staged.hpp's exact stages (the end of this
// file; every other host translation unit sees explicit instantiation
// declarations of them instead).
#define FLIPFLOP_STAGED_INSTANTIATE 1
#include "predicates.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "lambda_filter.hpp"
#include "rational_point.hpp"
#include "staged.hpp"
#include "static_filter.hpp"

namespace flipflop::pred {

namespace {

// ---- the GMP oracle (Mode::gmp) ------------------------------------------------
// The exact stage: sign of det of the (row-sorted) integer Λ-matrix, then the
// Simulation of Simplicity when it is 0 and a perturbation is requested.
int exact_stage(const exact::IntLambda& mat, int parity, bool sos) {
  const std::uint32_t all = (1u << mat.k) - 1u;
  int s = exact::minor_sign(mat, all, all);
  if (s != 0 || !sos) return parity * s;
  return parity * exact::sos_sign(mat);
}

int gmp_sign(int k, const PointId* ids, const double* const* coords, const double* weights,
             bool sos) {
  int order[kMaxLambdaK];
  const int parity = sort_rows_by_id(k, sos ? ids : static_cast<const PointId*>(nullptr), order);
  if (parity == 0) return 0;
  const double* sorted_c[kMaxLambdaK];
  double sorted_w[kMaxLambdaK];
  for (int i = 0; i < k; ++i) {
    sorted_c[i] = coords[order[i]];
    if (weights) sorted_w[i] = weights[order[i]];
  }
  return exact_stage(exact::build_lambda(k, sorted_c, weights ? sorted_w : nullptr), parity, sos);
}

// kmax: kMaxStagedK for the single stages (their templates), kMaxLambdaK
// for the whole path
void check_k(int k, const double* weights, int kmax = kMaxStagedK) {
  if (k < 2 || k > kmax)
    throw std::invalid_argument("lambda_sign: k must be in 2.." + std::to_string(kmax));
  if (weights && k < 3) throw std::invalid_argument("lambda_sign: a lifted matrix needs k >= 3");
}

// The dynamic filter for k = 9..11 rows: det T (the k-1 translated rows,
// lambda_filter.hpp's matrix) in ErrDouble by Gaussian elimination
// (lambda_filter.hpp, det_gauss_rt), with a running error bound per value
// (err_double.hpp), so a sign it returns is certain.
int lambda_sign_filter_high(int k, const double* const* p, const double* w) {
  ErrDouble t[(kMaxLambdaK - 1) * (kMaxLambdaK - 1)];
  translated_lambda(k, p, w, t);
  return sign_if_certain(det_gauss_rt(t, k - 1));
}

}  // namespace

namespace {
// The integer-lattice stage for k = 9..11 rows (xp::int_lambda, the walk by
// ranks modulo p: staged.hpp lambda_int_sorted); 2 where it does not apply.
template <int K>
int lambda_int_high(const PointId* ids, const double* const* coords, const double* weights) {
  xp::IntLambda<K> L;
  if (!xp::int_lambda<K>(coords, weights, L)) return 2;
  return lambda_int_sorted<K>(ids, L);
}
}  // namespace

// The SoS sign for k = 9..11 rows by the walk modulo primes
// (exact_expansion.hpp multiprime_walk) to sos_search's leaf, whose minor
// alone is then evaluated in GMP — instead of det Λ in GMP and the GMP
// search with a rank test per node (points given twice in 7D: about 80 %
// of the time in GMP's allocation and products). 2 where the walk does not
// apply (more than 12 primes) or cannot decide.
template <int K>
int lambda_walk_high(const PointId* ids, const double* const* coords, const double* weights) {
#if defined(FLIPFLOP_INT128)
  int order[K];
  const int parity = sort_rows_by_id(K, ids, order);
  if (parity == 0) return 0;
  const double* sc[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sc[i] = coords[order[i]];
    if (weights) sw[i] = weights[order[i]];
  }
  unsigned kr = 0, kc = 0;
  int sg = 1;
  if (xp::multiprime_walk<K>(sc, weights ? sw : nullptr, kr, kc, sg) != 1) return 2;
  const int s = exact::minor_sign(exact::build_lambda(K, sc, weights ? sw : nullptr), kr, kc);
  return s == 0 ? 2 : parity * sg * s;  // (0: not the walk's leaf; cannot happen)
#else
  (void)ids;
  (void)coords;
  (void)weights;
  return 2;
#endif
}

int lambda_sign_high(const StaticFilter*, int k, const PointId* ids, const double* const* coords,
                     const double* weights) {
  check_k(k, weights, kMaxLambdaK);
  if (repeated_id(k, ids)) return 0;
  // lattices first (random doubles fail int_lambda's scan within a row): the
  // filter below cannot decide their zero determinants
  const int si = k == 9    ? lambda_int_high<9>(ids, coords, weights)
                 : k == 10 ? lambda_int_high<10>(ids, coords, weights)
                 : k == 11 ? lambda_int_high<11>(ids, coords, weights)
                           : 2;
  if (si != 2) return si;
  if (const int s = lambda_sign_filter_high(k, coords, weights)) return s;
  if (ids) {
    const int sw = k == 9    ? lambda_walk_high<9>(ids, coords, weights)
                   : k == 10 ? lambda_walk_high<10>(ids, coords, weights)
                   : k == 11 ? lambda_walk_high<11>(ids, coords, weights)
                             : 2;
    if (sw != 2) return sw;
  }
  return gmp_sign(k, ids, coords, weights, ids != nullptr);
}

int lambda_sign(const StaticFilter* f, int k, const PointId* ids, const double* const* coords,
                const double* weights, Mode m) {
  check_k(k, weights, kMaxLambdaK);
  if (m == Mode::gmp) {
    if (repeated_id(k, ids)) return 0;
    return gmp_sign(k, ids, coords, weights, ids != nullptr);
  }
  if (k > kMaxStagedK) return lambda_sign_high(f, k, ids, coords, weights);
  return with_k(k, [&](auto K) { return lambda_sign_staged<decltype(K)::value>(f, ids, coords, weights); });
}

int lambda_sign(int k, const PointId* ids, const double* const* coords, const double* weights,
                Mode m) {
  return lambda_sign(nullptr, k, ids, coords, weights, m);
}

// ---- each stage alone ------------------------------------------------------------
namespace stage {
int static_filter(const StaticFilter& f, int k, const double* const* p, const double* w) {
  check_k(k, w);
  return with_k(k, [&](auto K) { return static_sign<decltype(K)::value>(f, p, w); });
}
int semi_static(int k, const double* const* p, const double* w) {
  check_k(k, w);
  return with_k(k, [&](auto K) { return semi_static_sign<decltype(K)::value>(p, w); });
}
int dynamic(int k, const double* const* p, const double* w) {
  check_k(k, w);
  return with_k(k, [&](auto K) { return lambda_sign_filter<decltype(K)::value>(p, w); });
}
int expansion(int k, const double* const* p, const double* w) {
  check_k(k, w);
  return with_k(k, [&](auto K) { return xp::lambda_exact<decltype(K)::value>(p, w, false); });
}
int expansion_sos(int k, const PointId* ids, const double* const* p, const double* w) {
  check_k(k, w);
  return with_k(k, [&](auto K) {
    return lambda_exact_sorted<decltype(K)::value>(ids, p, w, ids != nullptr);
  });
}
int gmp(int k, const double* const* p, const double* w) {
  check_k(k, w, kMaxLambdaK);
  return gmp_sign(k, nullptr, p, w, false);
}
int gmp_sos(int k, const PointId* ids, const double* const* p, const double* w) {
  check_k(k, w, kMaxLambdaK);
  if (repeated_id(k, ids)) return 0;
  return gmp_sign(k, ids, p, w, ids != nullptr);
}
}  // namespace stage

// ---- rows mixing doubles and exact rational points (rational_point.hpp) ------
RationalPoint RationalPoint::centroid(const double* const* pts, int count, int dim) {
  if (count <= 0 || count > 8 || (count & (count - 1)) != 0 || dim < 1 || dim > 3)
    throw std::invalid_argument("RationalPoint::centroid: count must be a power of two <= 8, dim <= 3");
  int shift = 0;
  while ((1 << shift) < count) ++shift;
  RationalPoint r;
  r.dim = dim;
  r.count = count;
  r.exact.resize(static_cast<size_t>(dim));
  for (int j = 0; j < dim; ++j) {
    exact::Dyadic sum;
    ErrDouble approx(0.0);
    for (int i = 0; i < count; ++i) {
      if (!std::isfinite(pts[i][j]))
        throw std::invalid_argument("RationalPoint::centroid: non-finite coordinate");
      r.src[i * dim + j] = pts[i][j];
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

RationalPoint RationalPoint::project(const int* cols, int m) const {
  if (m < 1 || m > dim) throw std::invalid_argument("RationalPoint::project: bad coordinate count");
  RationalPoint r;
  r.dim = m;
  r.count = count;
  r.exact.resize(static_cast<size_t>(m));
  for (int j = 0; j < m; ++j) {
    const int c = cols[j];
    if (c < 0 || c >= dim) throw std::invalid_argument("RationalPoint::project: bad coordinate");
    r.approx[j] = approx[c];
    r.exact[static_cast<size_t>(j)] = exact[static_cast<size_t>(c)];
    for (int i = 0; i < count; ++i) r.src[i * m + j] = src[i * dim + c];
  }
  return r;
}

int mixed_sign(int k, const MixedRow* rows, bool sos, Mode m) {
  if (k < 2 || k > 4) throw std::invalid_argument("mixed_sign: k must be in 2..4");
  const int dim = k - 1;
  PointId ids[4];
  for (int i = 0; i < k; ++i) {
    ids[i] = rows[i].id;
    if (!rows[i].x && (rows[i].r == nullptr || rows[i].r->dim != dim))
      throw std::invalid_argument("mixed_sign: a rational row of the wrong dimension");
  }
  if (sos && repeated_id(k, ids)) return 0;
  if (m == Mode::filtered) {
    // one rational row (the kernel point of a hull): the semi-static filter (5)
    int nrat = 0, r = 0;
    for (int i = 0; i < k; ++i)
      if (!rows[i].x) ++nrat, r = i;
    if (nrat == 1) {
      const double* p[4];
      double q[3], err[3];
      for (int j = 0; j < dim; ++j) {
        q[j] = rows[r].r->approx[j].v;
        err[j] = rows[r].r->approx[j].e;
      }
      for (int i = 0; i < k; ++i) p[i] = rows[i].x ? rows[i].x : q;
      int s = 0;
      switch (k) {
        case 2: s = mixed_semi_static_sign<2>(p, r, err); break;
        case 3: s = mixed_semi_static_sign<3>(p, r, err); break;
        default: s = mixed_semi_static_sign<4>(p, r, err); break;
      }
      if (s != 0) return s;
    }
    ErrDouble approx[4 * 3];
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < dim; ++j)
        approx[i * dim + j] = rows[i].x ? ErrDouble(rows[i].x[j]) : rows[i].r->approx[j];
    int s = 0;
    switch (k) {
      case 2: s = lambda_sign_filter_err<2>(approx); break;
      case 3: s = lambda_sign_filter_err<3>(approx); break;
      default: s = lambda_sign_filter_err<4>(approx); break;
    }
    if (s != 0) return s;
  }
  int order[8];
  const int parity = sort_rows_by_id(k, sos ? ids : static_cast<const PointId*>(nullptr), order);
  if (parity == 0) return 0;
  if (m == Mode::filtered) {
    xp::MixedRowX xr[4];
    for (int i = 0; i < k; ++i) {
      const MixedRow& row = rows[order[i]];
      if (row.x) {
        xr[i].x = row.x;
      } else {
        xr[i].src = row.r->src;
        xr[i].count = row.r->count;
      }
    }
    switch (k) {
      case 2: return parity * xp::lambda_exact_mixed<2>(xr, sos);
      case 3: return parity * xp::lambda_exact_mixed<3>(xr, sos);
      default: return parity * xp::lambda_exact_mixed<4>(xr, sos);
    }
  }
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
  if (d < 1 || d > kMaxLambdaK - 1) throw std::invalid_argument("orient_d: d must be in 1..10");
  return lambda_sign(d + 1, nullptr, p, nullptr, m);
}
int power_d_exact(int d, const double* const* p, const double* w, Mode m) {
  if (d < 1 || d > kMaxLambdaK - 2) throw std::invalid_argument("power_d: d must be in 1..9");
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
  if (d < 1 || d > kMaxLambdaK - 1) throw std::invalid_argument("orient_d: d must be in 1..10");
  PointId id[kMaxLambdaK];
  const double* p[kMaxLambdaK];
  for (int i = 0; i <= d; ++i) {
    id[i] = pts[i].id;
    p[i] = pts[i].x;
  }
  return lambda_sign(d + 1, id, p, nullptr, m);
}
int power_d(int d, const WPt* pts, Mode m) {
  if (d < 1 || d > kMaxLambdaK - 2) throw std::invalid_argument("power_d: d must be in 1..9");
  PointId id[kMaxLambdaK];
  const double* p[kMaxLambdaK];
  double w[kMaxLambdaK];
  for (int i = 0; i < d + 2; ++i) {
    id[i] = pts[i].id;
    p[i] = pts[i].x;
    w[i] = pts[i].w;
  }
  return lambda_sign(d + 2, id, p, w, m);
}

int power_d_pulled(int d, const WPt* pts, Mode m) {
  if (d < 1 || d > 5) throw std::invalid_argument("power_d_pulled: d must be in 1..5");
  const int k = d + 2;
  PointId id[8];
  const double* p[8];
  double w[8];
  for (int i = 0; i < k; ++i) {
    id[i] = pts[i].id;
    p[i] = pts[i].x;
    w[i] = pts[i].w;
  }
  if (repeated_id(k, id)) return 0;
  // the unperturbed sign first (every stage, may be 0)
  if (const int s = lambda_sign(k, nullptr, p, w, m)) return s;
  int order[8];
  const int parity = sort_rows_by_id(k, id, order);
  const double* sp[8];
  double sw[8];
  for (int i = 0; i < k; ++i) {
    sp[i] = p[order[i]];
    sw[i] = w[order[i]];
  }
  if (m == Mode::gmp) {
    const double zero[8] = {};
    const exact::IntLambda q = exact::build_lambda(k, sp, zero);
    return parity * exact::sos_sign(exact::build_lambda(k, sp, sw), &q);
  }
  return parity * with_k(k, [&](auto K) { return xp::lambda_pulled_sos<decltype(K)::value>(sp, sw); });
}

int orient2d(const StaticFilter& f, Pt a, Pt b, Pt c) {
  const PointId id[3] = {a.id, b.id, c.id};
  const double* p[3] = {a.x, b.x, c.x};
  return lambda_sign_staged<3>(&f, id, p, static_cast<const double*>(nullptr));
}
int orient3d(const StaticFilter& f, Pt a, Pt b, Pt c, Pt d) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  return lambda_sign_staged<4>(&f, id, p, static_cast<const double*>(nullptr));
}
int power2d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  const double w[4] = {a.w, b.w, c.w, d.w};
  return lambda_sign_staged<4>(&f, id, p, w);
}
int power3d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d, WPt e) {
  const PointId id[5] = {a.id, b.id, c.id, d.id, e.id};
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  return lambda_sign_staged<5>(&f, id, p, w);
}

// The FMA instantiation of the double-double filter (dd_filter.hpp, Fma =
// true) on an x86-64 host: compiled inside functions with
// __attribute__((target("fma"))) — GCC and clang inline the default-target
// callees into them, FF_FORCEINLINE makes sure of the filter's pieces — and
// chosen per call by __builtin_cpu_supports("fma") (a load and a bit test;
// false before libgcc's constructor has run, then the plain instantiation
// answers, with the same signs). This file is compiled with
// -ffp-contract=off (predicates/CMakeLists.txt): inside a target("fma")
// function the compilers would otherwise fuse a * b + c wherever they find
// it, and Veltkamp's split (xp::Dbl::two_product, reached from the exact
// stage), the error-free transformations and the proven bounds all assume
// every operation rounded on its own. With -mfma (__FMA__) the FMA
// instantiation is the only one; elsewhere (other architectures, nvcc) the
// plain one.
#if defined(__FMA__)
#define FLIPFLOP_FMA_ALWAYS 1
#elif (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__CUDACC__)
#define FLIPFLOP_FMA_DISPATCH 1
#endif

bool host_fma() {
#if defined(FLIPFLOP_FMA_ALWAYS)
  return true;
#elif defined(FLIPFLOP_FMA_DISPATCH)
  return __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

namespace {
#if defined(FLIPFLOP_FMA_DISPATCH)
template <int K>
__attribute__((target("fma"))) int after_filters_fma(const PointId* id, const double* const* p,
                                                     const double* w, bool window, int lattice) {
  return lambda_sign_after_filters<K, PointId, true>(id, p, w, window, lattice);
}
template <int K>
__attribute__((target("fma"))) int dd_filter_fma(const double* const* p, const double* w) {
  return dd_filter_sign<K, true>(p, w);
}
#endif
template <int K>
int after_filters_any(const PointId* id, const double* const* p, const double* w, bool window, int lattice) {
#if defined(FLIPFLOP_FMA_ALWAYS)
  return lambda_sign_after_filters<K, PointId, true>(id, p, w, window, lattice);
#else
#if defined(FLIPFLOP_FMA_DISPATCH)
  if (__builtin_cpu_supports("fma")) return after_filters_fma<K>(id, p, w, window, lattice);
#endif
  return lambda_sign_after_filters<K, PointId, false>(id, p, w, window, lattice);
#endif
}
}  // namespace

// staged.hpp: lambda_sign_staged's out-of-line stages after the filters on the host
template <int K>
int lambda_sign_after_filters_host(const PointId* ids, const double* const* p, const double* w, bool window,
                                   int lattice) {
  return after_filters_any<K>(ids, p, w, window, lattice);
}
template int lambda_sign_after_filters_host<2>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<3>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<4>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<5>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<6>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<7>(const PointId*, const double* const*, const double*, bool, int);
template int lambda_sign_after_filters_host<8>(const PointId*, const double* const*, const double*, bool, int);

namespace after_filters {
int orient2d(Pt a, Pt b, Pt c, bool dd_window, int lattice) {
  const PointId id[3] = {a.id, b.id, c.id};
  const double* p[3] = {a.x, b.x, c.x};
  return after_filters_any<3>(id, p, nullptr, dd_window, lattice);
}
int orient3d(Pt a, Pt b, Pt c, Pt d, bool dd_window, int lattice) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  return after_filters_any<4>(id, p, nullptr, dd_window, lattice);
}
int power2d(WPt a, WPt b, WPt c, WPt d, bool dd_window, int lattice) {
  const PointId id[4] = {a.id, b.id, c.id, d.id};
  const double* p[4] = {a.x, b.x, c.x, d.x};
  const double w[4] = {a.w, b.w, c.w, d.w};
  return after_filters_any<4>(id, p, w, dd_window, lattice);
}
int power3d(WPt a, WPt b, WPt c, WPt d, WPt e, bool dd_window, int lattice) {
  const PointId id[5] = {a.id, b.id, c.id, d.id, e.id};
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  return after_filters_any<5>(id, p, w, dd_window, lattice);
}
}  // namespace after_filters

namespace stage {
// The double-double filter alone, its plain or its FMA instantiation (the
// latter through the target("fma") clone where the host has FMA, else the
// same code with the library's fma: the same signs either way).
int dd_filter(int k, const double* const* p, const double* w, bool fma) {
  if (k < 3 || k > 7) throw std::invalid_argument("stage::dd_filter: k = 3..7");
  check_k(k, w);
  auto run = [&](auto K) {
    constexpr int Kv = decltype(K)::value;
    if constexpr (Kv >= 3 && Kv <= 7) {
      if (!fma) return dd_filter_sign<Kv, false>(p, w);
#if defined(FLIPFLOP_FMA_DISPATCH)
      if (__builtin_cpu_supports("fma")) return dd_filter_fma<Kv>(p, w);
#endif
      return dd_filter_sign<Kv, true>(p, w);
    }
    return 2;
  };
  return with_k(k, run);
}
}  // namespace stage

bool collinear3_exact(const double* a, const double* b, const double* c) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    if (orient2d_exact(pa, pb, pc) != 0) return false;
  }
  return true;
}

int dot2d_exact(const double* a, const double* b, const double* c) {
  ErrDouble ux = ErrDouble(b[0]) - ErrDouble(a[0]), uy = ErrDouble(b[1]) - ErrDouble(a[1]);
  ErrDouble vx = ErrDouble(c[0]) - ErrDouble(b[0]), vy = ErrDouble(c[1]) - ErrDouble(b[1]);
  if (int s = sign_if_certain(ux * vx + uy * vy)) return s;
  // exactly, in unbounded-exponent expansion arithmetic (any finite input):
  // each difference is an expansion of <= 2 components, each product <= 8,
  // their sum <= 16.
  using A = xp::XDbl;
  using V = A::T;
  auto diff = [](double p, double q, V* out) {
    V hi, lo;
    A::two_sum(A::from_double(p), A::neg(A::from_double(q)), hi, lo);
    out[0] = lo;
    out[1] = hi;
  };
  auto product = [](const V* u, const V* v, V* out) {
    V s0[4], s1[4];
    const int l0 = xp::scale_zeroelim<A>(2, u, v[0], s0);
    const int l1 = xp::scale_zeroelim<A>(2, u, v[1], s1);
    return xp::sum_zeroelim<A>(l0, s0, l1, s1, out);
  };
  V dux[2], duy[2], dvx[2], dvy[2], px[8], py[8], sum[16];
  diff(b[0], a[0], dux);
  diff(b[1], a[1], duy);
  diff(c[0], b[0], dvx);
  diff(c[1], b[1], dvy);
  const int lx = product(dux, dvx, px), ly = product(duy, dvy, py);
  const int len = xp::sum_zeroelim<A>(lx, px, ly, py, sum);
  return xp::sign_of<A>(len, sum);
}

// staged.hpp's exact stages for PointId rows, K = 2..8: their one host copy
// (staged.hpp, FLIPFLOP_STAGED_INSTANTIATE). In this file rather than one of
// their own: the filters above and these stages share the inline minor
// evaluations (minor_levels over ErrDouble, ErrDD, __int128), which a second
// file compiled again (measured, g++ -O3: 58 + 39 s against 66 s in one file).
FF_STAGED_EXACT_ALL()

}  // namespace flipflop::pred

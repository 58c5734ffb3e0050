// predicates_int_lattice_test.cpp — the integer-lattice stage of the default
// predicate path (xp::int_lambda, xp::int_lattice_sign, staged.hpp's
// lambda_int_sorted) against the expansion path it short-cuts, and GMP.
//
// Inputs: k = 3..7 points, plain (k - 1 coordinates) and lifted (k - 2
// coordinates and a weight), every coordinate a small integer (bound 1, 3, 46,
// 1000, 2^20, 2^28 or 2^40: int64 and __int128 minors both occur, and
// lifted calls the path refuses) times a common
// power of two 2^e, e in [-60, 60] (weights: integers times 2^(2e), or
// 2^(2e - t) — a finer weight grid —, or 0); exactly degenerate by
// construction where the shape asks for it: duplicated points (same
// coordinates and weight, different ids), points on an integer hyperplane
// (coplanar), on a lattice sphere (x^2 + y^2 [+ z^2] = r^2 with equal weights:
// cospherical), on a line, or all weights w = |x|^2 + affine (the lifted
// points on a hyperplane). Ids distinct, in arbitrary order.
//
// Properties:
//   (a) where int_lambda accepts the call, the sign of every minor of the
//       integer Λ (int_minor_sign, on the full matrix and random row/column
//       subsets) equals the sign of the same minor of Λ as expansions
//       (MinorLaplace<Dbl> on build_lambda) — the column scaling keeps signs;
//   (b) int_lattice_sign (exact and SoS, rows sorted by id) equals the
//       expansion path: det_translated<Dbl> for the exact sign, then
//       sos_expansions<Dbl> where it is 0, and GMP's SoS sign;
//   (c) the whole staged path (lambda_sign_after_filters, plain and FMA
//       instantiations, ids in arbitrary order) equals GMP's SoS sign;
//   (d) not vacuous: int_lambda accepts most calls, both widths occur, and
//       most calls are exactly degenerate (det Λ = 0).
// A sign flip planted in int_minor_sign (orders 3 and 4) was caught by (a),
// (b) and (c); a weakened width test (int64 where __int128 is needed) by (a).
//
// The SoS stage on doubles with lazily built expansions (xp::sos_lazy) on
// degenerate calls that are not lattices: millimetre coordinates (n / 1000,
// not dyadic) on the floors and walls of a building (a constant coordinate),
// on the plane z = x, duplicated points, weights 0 or millimetre values:
//   (e) sos_lazy equals sos_expansions (the expansion search it replaces)
//       and GMP's SoS sign wherever det Λ = 0, and the whole path after the
//       filters equals GMP; not vacuous: most calls have det Λ = 0.
// A planted error in its constant-column test (only the first two kept rows
// compared) was caught by (e) and by (c) above (lambda_exact_sorted with
// dd_ran skips the integer stage and reaches sos_lazy).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

#include "predicates/exact.hpp"
#include "predicates/exact_expansion.hpp"
#include "predicates/predicates.hpp"
#include "predicates/staged.hpp"
#include "proptests/support/predicate_inputs.hpp"

namespace {

using namespace flipflop;
using namespace flipflop::test;
namespace xp = flipflop::pred::xp;
using pred::PointId;

struct LatticeCall {
  int k = 0;
  bool lifted = false;
  std::vector<double> x;  // k rows of dim coordinates
  std::vector<double> w;
  std::vector<PointId> ids;
  int dim() const { return lifted ? k - 2 : k - 1; }
};

enum class Shape { random, duplicates, coplanar, cospherical, collinear, lifted_plane };

LatticeCall gen_lattice_call(int k, bool lifted) {
  LatticeCall c;
  c.k = k;
  c.lifted = lifted;
  const int d = c.dim();
  const std::int64_t bounds[] = {1, 3, 46, 1000, std::int64_t(1) << 20, std::int64_t(1) << 28, std::int64_t(1) << 40};
  const std::int64_t R = bounds[*rc::gen::inRange(0, 7)];
  const int e = *rc::gen::inRange(-60, 61);
  const Shape shape = static_cast<Shape>(*rc::gen::inRange(0, 6));
  auto coord = [&] { return *rc::gen::inRange<std::int64_t>(-R, R + 1); };
  std::vector<std::int64_t> X(static_cast<size_t>(k * d));
  std::vector<std::int64_t> W(static_cast<size_t>(k), 0);
  for (auto& v : X) v = coord();
  const int wmode = *rc::gen::inRange(0, 3);  // 0: zero weights, 1: integers, 2: |x|^2 + affine
  const std::int64_t WR = R > (std::int64_t(1) << 20) ? R : R * R;
  if (wmode == 1)
    for (auto& v : W) v = *rc::gen::inRange<std::int64_t>(-WR, WR + 1);
  switch (shape) {
    case Shape::random: break;
    case Shape::duplicates: {
      const int n = *rc::gen::inRange(1, k);
      for (int t = 0; t < n; ++t) {
        const int a = *rc::gen::inRange(0, k), b = *rc::gen::inRange(0, k);
        for (int j = 0; j < d; ++j) X[static_cast<size_t>(a * d + j)] = X[static_cast<size_t>(b * d + j)];
        W[static_cast<size_t>(a)] = W[static_cast<size_t>(b)];
      }
      break;
    }
    case Shape::coplanar: {
      // last coordinate = Σ c_j x_j + c0 with small integer c (a hyperplane)
      if (d < 2) break;
      std::vector<std::int64_t> cf(static_cast<size_t>(d));
      for (auto& v : cf) v = *rc::gen::inRange<std::int64_t>(-2, 3);
      for (int i = 0; i < k; ++i) {
        std::int64_t s = cf[static_cast<size_t>(d - 1)];
        for (int j = 0; j + 1 < d; ++j) s += cf[static_cast<size_t>(j)] * X[static_cast<size_t>(i * d + j)];
        X[static_cast<size_t>(i * d + d - 1)] = s;
      }
      break;
    }
    case Shape::cospherical: {
      // lattice points of x^2 + y^2 [+ z^2] = r2 (predicate_inputs' spheres), equal weights
      if (d < 2 || d > 3) break;
      const auto& pts = lattice_sphere(d, d == 2 ? 25 : 9);
      const std::int64_t m = R < 5 ? 1 : R / 5;
      for (int i = 0; i < k; ++i) {
        const auto& q = pts[static_cast<size_t>(*rc::gen::inRange<size_t>(0, pts.size()))];
        for (int j = 0; j < d; ++j) X[static_cast<size_t>(i * d + j)] = m * q[static_cast<size_t>(j)];
        W[static_cast<size_t>(i)] = W[0];
      }
      break;
    }
    case Shape::collinear: {
      std::vector<std::int64_t> o(static_cast<size_t>(d)), v(static_cast<size_t>(d));
      for (int j = 0; j < d; ++j) {
        o[static_cast<size_t>(j)] = coord() / 2;
        v[static_cast<size_t>(j)] = *rc::gen::inRange<std::int64_t>(-3, 4);
      }
      for (int i = 0; i < k; ++i) {
        const std::int64_t t = *rc::gen::inRange<std::int64_t>(-4, 5);
        for (int j = 0; j < d; ++j)
          X[static_cast<size_t>(i * d + j)] = o[static_cast<size_t>(j)] + t * v[static_cast<size_t>(j)];
      }
      break;
    }
    case Shape::lifted_plane: break;  // wmode 2 below does it
  }
  if (wmode == 2 || shape == Shape::lifted_plane) {
    // w = |x|^2 - (a.x + b): the lifted points |x|^2 - w = a.x + b on a hyperplane
    const std::int64_t a = *rc::gen::inRange<std::int64_t>(-3, 4), b = *rc::gen::inRange<std::int64_t>(-5, 6);
    // in 128 bits (coordinates reach 2^40: their squares overflow int64);
    // a value beyond int64 leaves that weight 0 (still a valid call, only
    // off the hyperplane)
    for (int i = 0; i < k; ++i) {
      __int128 s = -b;
      for (int j = 0; j < d; ++j) {
        const __int128 xv = X[static_cast<size_t>(i * d + j)];
        s += xv * xv - a * xv;
      }
      const __int128 lim = static_cast<__int128>(1) << 62;
      W[static_cast<size_t>(i)] = s > -lim && s < lim ? static_cast<std::int64_t>(s) : 0;
    }
  }
  // weights on the grid 2^(2e), or a finer one 2^(2e - t)
  const int t = *rc::gen::inRange(0, 4) == 0 ? *rc::gen::inRange(1, 8) : 0;
  c.x.resize(X.size());
  for (size_t i = 0; i < X.size(); ++i) c.x[i] = std::ldexp(static_cast<double>(X[i]), e);
  c.w.resize(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) {
    std::int64_t wi = W[static_cast<size_t>(i)];
    // (only where the finer value fits in int64)
    if (t > 0 && wi > -(std::int64_t(1) << 54) && wi < (std::int64_t(1) << 54))
      wi = wi * (std::int64_t(1) << t) + *rc::gen::inRange<std::int64_t>(-1, 2);
    c.w[static_cast<size_t>(i)] = std::ldexp(static_cast<double>(wi), 2 * e - t);
  }
  c.ids = gen_distinct_ids(k);
  return c;
}

struct Tally {
  long calls = 0, accepted = 0, wide = 0, zero_det = 0, minors = 0, small_int = 0;
};

template <int K>
void check_call(const LatticeCall& c, Tally& t) {
  ++t.calls;
  const int d = c.dim();
  const double* p[K];
  for (int i = 0; i < K; ++i) p[i] = c.x.data() + i * d;
  const double* w = c.lifted ? c.w.data() : nullptr;
  const PointId* ids = c.ids.data();

  // the expansion path: rows sorted by id, det_translated, sos_expansions
  int order[K];
  const int parity = pred::sort_rows_by_id(K, ids, order);
  RC_ASSERT(parity != 0);
  const double* sp[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sp[i] = p[order[i]];
    sw[i] = w ? w[order[i]] : 0.0;
  }
  const double* swp = w ? sw : nullptr;
  const int det_x = xp::det_translated<xp::Dbl, K>(sp, swp);
  const int sos_x = det_x != 0 ? parity * det_x : parity * xp::sos_expansions<xp::Dbl, K>(sp, swp);
  const int sos_g = pred::stage::gmp_sos(K, ids, p, w);
  RC_LOG() << "k " << K << (w ? " lifted" : " plain") << ": det " << det_x << ", sos expansions " << sos_x
           << ", gmp " << sos_g << "\n";
  RC_ASSERT(sos_x == sos_g);
  t.zero_det += det_x == 0;

  xp::IntLambda<K> L;
  if (xp::int_lambda<K>(p, w, L)) {
    ++t.accepted;
    t.wide += L.wide;
    // (a) minors: the full one and random subsets, against the expansion Λ
    xp::RawLambda<xp::Dbl, K> E;
    xp::build_lambda<xp::Dbl, K>(p, w, E);
    constexpr unsigned kAll = (1u << K) - 1u;
    for (int rep = 0; rep < 6; ++rep) {
      unsigned rows = kAll, cols = kAll;
      if (rep > 0) {
        const int r = *rc::gen::inRange(1, K + 1);
        const std::vector<int> pr = gen_permutation(K), pc = gen_permutation(K);
        rows = cols = 0;
        for (int i = 0; i < r; ++i) {
          rows |= 1u << pr[static_cast<size_t>(i)];
          cols |= 1u << pc[static_cast<size_t>(i)];
        }
      }
      int si = 0;
#if defined(FLIPFLOP_INT128)
      si = L.wide ? xp::int_minor_sign<xp::int128_t, K>(L, rows, cols) : xp::int_minor_sign<long long, K>(L, rows, cols);
#else
      si = xp::int_minor_sign<long long, K>(L, rows, cols);
#endif
      const int se = xp::MinorLaplace<xp::Dbl, K>::sign(E, rows, cols);
      RC_LOG() << "minor rows " << rows << " cols " << cols << ": int " << si << ", expansions " << se << "\n";
      RC_ASSERT(si == se);
      ++t.minors;
    }
    // (b) the exact and the SoS sign on the integer Λ, rows sorted
    RC_ASSERT(xp::int_lattice_sign<K>(L, false) == parity * det_x);
    xp::IntLambda<K> S;
    RC_ASSERT(xp::int_lambda<K>(sp, swp, S));
    RC_ASSERT(parity * xp::int_lattice_sign<K>(S, true) == sos_g);
    RC_ASSERT(pred::lambda_int_sorted<K>(ids, L) == sos_g);
  }
  // (d) integers below 2^20 straight from the doubles (staged.hpp
  // lambda_small_int_sorted, the walk in binary64): where it applies, the SoS
  // sign; without ids, the exact sign of the rows in the given order
  const int small = pred::lambda_small_int_sorted<K>(ids, p, w, false, false);
  if (small != 2) {
    RC_ASSERT(small == sos_g);
    ++t.small_int;
  }
  const int small_exact = pred::lambda_small_int_sorted<K>(static_cast<const PointId*>(nullptr), p, w, false, false);
  if (small_exact != 2) RC_ASSERT(small_exact == pred::stage::gmp(K, p, w));
  // (c) the whole path after the filters, both instantiations, and the exact stage
  RC_ASSERT((pred::lambda_sign_after_filters<K, PointId, false>(ids, p, w)) == sos_g);
  RC_ASSERT((pred::lambda_sign_after_filters<K, PointId, true>(ids, p, w)) == sos_g);
  RC_ASSERT(parity * xp::lambda_exact<K>(sp, swp, true) == sos_g);
  RC_ASSERT(pred::lambda_exact_sorted<K>(ids, p, w, true, true) == sos_g);
}

// A call that needs __int128 for sure (fixed seed): integer coordinates of
// up to 2^b, weights 0, b the largest for which int_lambda's bound (log2 k!,
// the 1-column and each column's bit length; the lifted column about 2b + 3
// bits) stays within 127 bits with a margin — above 63 for every k. RapidCheck's
// ranges grow with its size parameter, so its own calls reach the largest
// bounds rarely (k = 3 plain: in 0-6 of 100 calls), and the tally's `wide`
// check would otherwise depend on the seed.
LatticeCall wide_call(int k, bool lifted) {
  LatticeCall c;
  c.k = k;
  c.lifted = lifted;
  std::mt19937_64 g(static_cast<std::uint64_t>(k) * 2 + lifted);
  constexpr int kLogFact[8] = {0, 0, 1, 3, 5, 7, 10, 13};
  int b = lifted ? 27 : 52;
  auto estimate = [&](int bb) { return kLogFact[k] + 1 + c.dim() * (bb + 1) + (lifted ? 2 * bb + 5 : 0); };
  while (estimate(b) > 124) --b;
  const std::int64_t R = std::int64_t(1) << b;
  std::uniform_int_distribution<std::int64_t> u(-R, R);
  for (int i = 0; i < k * c.dim(); ++i) c.x.push_back(static_cast<double>(u(g)));
  c.w.assign(static_cast<size_t>(k), 0.0);
  for (int i = 0; i < k; ++i) c.ids.push_back(static_cast<PointId>(1000 - 7 * i));
  return c;
}

template <int K>
void lattice_property(bool lifted) {
  Tally t;
  const std::string name = "k = " + std::to_string(K) + (lifted ? " lifted" : " plain");
  rc::prop(name, [&] {
    if (t.calls == 0) check_call<K>(wide_call(K, lifted), t);
    const LatticeCall c = gen_lattice_call(K, lifted);
    check_call<K>(c, t);
  });
  if (t.calls == 0) return;  // Catch ran another section this time
  std::printf("int lattice %-14s calls %6ld accepted %6ld (__int128 %5ld) det 0 %6ld minors %6ld small integers %6ld\n",
              name.c_str(), t.calls, t.accepted, t.wide, t.zero_det, t.minors, t.small_int);
  CHECK(t.accepted * 2 > t.calls);
  CHECK(t.zero_det * 4 > t.calls);
  CHECK(t.wide > 0);
}

}  // namespace

TEST_CASE("int lattice: minors, exact and SoS signs equal the expansion path and GMP",
          "[predicates][stages][int_lattice]") {
  lattice_property<3>(false);
  lattice_property<4>(false);
  lattice_property<5>(false);
  lattice_property<6>(false);
  lattice_property<7>(false);
  lattice_property<3>(true);
  lattice_property<4>(true);
  lattice_property<5>(true);
  lattice_property<6>(true);
  lattice_property<7>(true);
}

// ---- (e) sos_lazy on millimetre (non-dyadic) degenerate calls ----
namespace {

double gen_mm(int bound) { return *rc::gen::inRange(-bound, bound + 1) / 1000.0; }

template <int K>
void planes_call(bool lifted, long& calls, long& zero, long& walked, long& first_decided) {
  const int d = lifted ? K - 2 : K - 1;
  std::vector<double> x(static_cast<size_t>(K * d)), w(static_cast<size_t>(K), 0.0);
  const int bound = *rc::gen::element(50, 5000, 50000);
  for (double& v : x) v = gen_mm(bound);
  const int shape = *rc::gen::inRange(0, 5);
  if (shape == 0) {  // a floor or a wall: coordinate j = c for every point
    const int j = *rc::gen::inRange(0, d);
    const double c = *rc::gen::arbitrary<bool>() ? 0.0 : gen_mm(bound);
    for (int i = 0; i < K; ++i) x[static_cast<size_t>(i * d + j)] = c;
  } else if (shape == 1 && d >= 2) {  // the plane x_last = x_0 (exact)
    for (int i = 0; i < K; ++i) x[static_cast<size_t>(i * d + d - 1)] = x[static_cast<size_t>(i * d)];
  }
  if (shape == 4) {  // a tensor grid of non-dyadic spacing (np.mgrid step s): k s rounded, k = -2 .. 2
    const double step = *rc::gen::element(0.1, 0.7, 0.3, 1.1e-3, 123.456);
    for (double& v : x) v = *rc::gen::inRange(-2, 3) * step;
  }
  if (*rc::gen::arbitrary<bool>())
    for (double& v : w) v = shape == 4 ? *rc::gen::inRange(0, 3) * 0.01 : gen_mm(bound);
  if (shape == 2 || (shape == 4 && *rc::gen::arbitrary<bool>())) {  // duplicated points: 1 .. K/2 copies, of the weight too or not (sos_search's eq)
    const int copies = *rc::gen::inRange(1, K / 2 + 1);
    for (int t = 0; t < copies; ++t) {
      const int a = *rc::gen::inRange(0, K), b = *rc::gen::inRange(0, K);
      for (int j = 0; j < d; ++j) x[static_cast<size_t>(a * d + j)] = x[static_cast<size_t>(b * d + j)];
      if (*rc::gen::arbitrary<bool>()) w[static_cast<size_t>(a)] = w[static_cast<size_t>(b)];
    }
  }
  const std::vector<PointId> ids = gen_distinct_ids(K);
  const double* p[K];
  for (int i = 0; i < K; ++i) p[i] = x.data() + i * d;
  const double* wp = lifted ? w.data() : nullptr;
  int order[K];
  const int parity = pred::sort_rows_by_id(K, ids.data(), order);
  const double* sp[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sp[i] = p[order[i]];
    sw[i] = w[static_cast<size_t>(order[i])];
  }
  const double* swp = lifted ? sw : nullptr;
  const int g = pred::stage::gmp_sos(K, ids.data(), p, wp);
  const int exact = pred::stage::gmp(K, p, wp);  // no perturbation: may be 0
  ++calls;
  RC_ASSERT((pred::lambda_sign_after_filters<K, PointId, true>(ids.data(), p, wp)) == g);
  RC_ASSERT((pred::lambda_sign_after_filters<K, PointId, false>(ids.data(), p, wp)) == g);
  // without ids (the exact sign; K >= 6 asks the walk whether det Λ = 0 first)
  RC_ASSERT((pred::lambda_sign_after_filters<K, PointId, true>(nullptr, p, wp)) == exact);
#if defined(FLIPFLOP_INT128)
  RC_ASSERT((!xp::det_zero_by_walk<K>(p, wp) || exact == 0));
#endif
  if (xp::det_translated<xp::Dbl, K>(sp, swp) != 0) return;
  ++zero;
  xp::Range range;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < d; ++j) range.add(sp[i][j]);
    if (lifted) range.add(sw[i]);
  }
  const int lazy = xp::sos_lazy<K>(sp, swp, range);
  const int expansions = xp::sos_expansions<xp::Dbl, K>(sp, swp);
  RC_LOG() << "k " << K << (lifted ? " lifted" : " plain") << " shape " << shape << ": sos_lazy " << lazy
           << ", sos_expansions " << expansions << ", gmp " << g << " (parity " << parity << ")\n";
  RC_ASSERT(lazy == expansions);
  RC_ASSERT(parity * lazy == g);
#if defined(FLIPFLOP_INT128)
  // lambda_exact's walk before the exact determinant: 2, or det Λ = 0 and the answer
  const int first = xp::sos_walk_first<K>(sp, swp);
  RC_ASSERT((first == 2 || parity * first == g));
  first_decided += first != 2;
  unsigned kr = 0, kc = 0;
  int sg = 0;
  // the walk on its own (sos_lazy asks it only where its cheap search stops):
  // its leaf's minor is not 0, and its sign with the walk's is the answer
  if (xp::multiprime_walk<K>(sp, swp, kr, kc, sg) == 1) {
    ++walked;
    xp::RawLambda<xp::Dbl, K> L;
    xp::build_lambda<xp::Dbl, K>(sp, swp, L);
    const int leaf = xp::MinorOf<xp::Dbl, K>::sign(L, kr, kc);
    RC_LOG() << "multi-prime walk: leaf rows " << kr << " columns " << kc << " sign " << sg << " minor " << leaf
             << "\n";
    RC_ASSERT(leaf != 0);
    RC_ASSERT(parity * sg * leaf == g);
    // the leaf's minor as sos_walk_first decides it (ErrDouble, translated
    // where the 1-column is kept, else the expansion minor)
    RC_ASSERT(xp::lambda_minor_sign<K>(sp, swp, kr, kc) == leaf);
    RC_ASSERT(xp::det_zero_by_walk<K>(sp, swp));  // det Λ = 0 here, and the walk applies
  }
#endif
}

template <int K>
void planes_property(bool lifted) {
  long calls = 0, zero = 0, walked = 0, first_decided = 0;
  const std::string name = "k = " + std::to_string(K) + (lifted ? " lifted" : " plain");
#if defined(FLIPFLOP_INT128)
  const long long certificates0 = xp::walk_counts().certificates;
#endif
  rc::prop(name, [&] { planes_call<K>(lifted, calls, zero, walked, first_decided); });
  if (calls == 0) return;
  long long certificates = 0;
#if defined(FLIPFLOP_INT128)
  certificates = xp::walk_counts().certificates - certificates0;
#endif
  std::printf("sos_lazy %-14s calls %6ld det 0 %6ld decided by the multi-prime walk %6ld (before the exact "
              "determinant: %6ld; dependences shown over Z: %lld)\n",
              name.c_str(), calls, zero, walked, first_decided, certificates);
  CHECK(zero * 2 > calls);
#if defined(FLIPFLOP_INT128)
  CHECK(walked * 2 > zero);         // the walk, not the search, decides most of them
  CHECK(first_decided * 2 > zero);  // and lambda_exact's walk-first does too
  // from 5 rows the walk's dependences need more than one prime, and the
  // integer certificates (multiprime_walk's exact_dependence) stand in for
  // them on these grids: the path the GMP comparison above covers
  if (K >= 5) CHECK(certificates > 0);
#endif
}

}  // namespace

TEST_CASE("sos_lazy: millimetre floors, walls, planes and duplicates equal sos_expansions and GMP",
          "[predicates][stages][int_lattice]") {
  planes_property<3>(false);
  planes_property<4>(false);
  planes_property<5>(false);
  planes_property<6>(false);
  planes_property<7>(false);
  planes_property<4>(true);
  planes_property<5>(true);
  planes_property<6>(true);
  planes_property<7>(true);
  planes_property<8>(true);
}

#if defined(FLIPFLOP_INT128)
// The multi-prime walk's moduli 2^61 - c are primes: Miller-Rabin with the
// first 12 prime bases is deterministic below 2^64 (3.3 * 10^24); the
// arithmetic is the walk's own (PseudoMersenne61::mul), checked here against
// __int128 remainders first.
TEST_CASE("multi-prime walk: the moduli are primes, their products reduced right", "[predicates][int_lattice]") {
  std::mt19937_64 g(5);
  for (int q = 0; q < xp::kMultiprimeCount; ++q) {
    xp::PseudoMersenne61 F;
    F.c = xp::kMultiprimeC[q];
    F.p = xp::PseudoMersenne61::kM + 1ull - F.c;
    for (int t = 0; t < 2000; ++t) {
      const unsigned long long a = t < 2 ? F.p - 1 : g() % F.p, b = t < 1 ? F.p - 1 : g() % F.p;
      REQUIRE(F.mul(a, b) == static_cast<unsigned long long>(static_cast<xp::uint128_t>(a) * b % F.p));
      // the row operation a x - b y in one reduction, against __int128 remainders
      const unsigned long long x = t < 3 ? F.p - 1 : g() % F.p, y = t < 4 ? (t & 1u ? 0 : F.p - 1) : g() % F.p;
      const xp::uint128_t ax = static_cast<xp::uint128_t>(a) * x % F.p, by = static_cast<xp::uint128_t>(b) * y % F.p;
      REQUIRE(F.cross(a, x, b, y) == static_cast<unsigned long long>((ax + F.p - by) % F.p));
    }
    auto pw = [&](unsigned long long a, unsigned long long e) {
      unsigned long long r = 1;
      for (; e; e >>= 1, a = F.mul(a, a))
        if (e & 1u) r = F.mul(r, a);
      return r;
    };
    unsigned long long d = F.p - 1;
    int s = 0;
    while (!(d & 1u)) {
      d >>= 1;
      ++s;
    }
    for (unsigned long long a : {2ull, 3ull, 5ull, 7ull, 11ull, 13ull, 17ull, 19ull, 23ull, 29ull, 31ull, 37ull}) {
      unsigned long long x = pw(a, d);
      bool witness = x != 1 && x != F.p - 1;
      for (int r = 1; r < s && witness; ++r) {
        x = F.mul(x, x);
        witness = x != F.p - 1;
      }
      INFO("2^61 - " << F.c << ", base " << a);
      CHECK(!witness);
    }
    CHECK(F.pow2(61) == F.c % F.p);
    CHECK(F.pow2(200) == pw(2, 200));
  }
}

// The walk's first prime (2^61 - 1) claims a dependence that the integers
// deny: det = 2^61 - 1 exactly, rows apart by 2^-43, equal in binary64's
// elimination (below its 2^-40). The
// candidate integer vector (1, -1) that binary64 suggests must be refused
// by the exact test (multiprime_walk's exact_dependence), and the second
// prime then finds the rows independent: the walk must not report det = 0.
// Hand-derived: A D - B C = (C + 512) D - (D + 1) C = 512 D - C = 2^61 +
// 2^52 - 2^52 - 1. Accepting the candidate unverified fails here.
TEST_CASE("multi-prime walk: a dependence modulo the first prime alone is not taken", "[predicates][int_lattice]") {
  const double C = 4503599627370497.0;                  // 2^52 + 1
  const double D = 4503599627370496.0 + 8796093022208.0;  // 2^52 + 2^43
  const double r0[2] = {C + 512.0, D + 1.0}, r1[2] = {C, D}, r2[2] = {0.0, 0.0};
  REQUIRE(r0[0] - 512.0 == C);  // every value an exact double (below 2^53)
  REQUIRE(r0[1] - 1.0 == D);
  const double* p[3] = {r0, r1, r2};
  const long long before = xp::walk_counts().certificates;
  unsigned kr = 0, kc = 0;
  int sg = 1;
  const int w = xp::multiprime_walk<3>(p, nullptr, kr, kc, sg);
  CHECK(xp::walk_counts().certificates == before);
  CHECK((w == 2 || (kr == 7u && kc == 7u)));  // never a leaf below det Λ
  CHECK(!xp::det_zero_by_walk<3>(p, nullptr));
  CHECK(pred::stage::gmp(3, p, nullptr) == 1);  // det Λ = A D - B C > 0
  // a true dependence of the same size is shown over Z: with the last point
  // at the origin, D's rows are the points, and q3 - 2 q0 + q1 = 0 (q0 = q1 +
  // (2^20, 1, 0), q3 = q1 + 2 (2^20, 1, 0): rows apart by 2^-32, above
  // binary64's 2^-40 for a zero); two primes needed (55 + 55 + 3 bits), none asked
  const double q0[3] = {C + 1048576.0, D + 1.0, 1.0}, q1[3] = {C, D, 1.0}, q3[3] = {C + 2097152.0, D + 2.0, 1.0},
               q4[3] = {0.0, 0.0, 0.0};
  const double* q[4] = {q0, q1, q3, q4};
  const long long before2 = xp::walk_counts().certificates;
  CHECK(xp::det_zero_by_walk<4>(q, nullptr));
  CHECK(xp::walk_counts().certificates > before2);
  CHECK(pred::stage::gmp(4, q, nullptr) == 0);
}
#endif

// Values the path must refuse: a decimal fraction (long mantissa), a spread
// beyond the int64 entry bounds, non-finite values; and a value it must take
// (the 3D Delaunay grid's cell).
TEST_CASE("int lattice: acceptance", "[predicates][stages][int_lattice]") {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1}, e[3] = {1, 1, 1};
  const double* p[5] = {a, b, c, d, e};
  const double w0[5] = {0, 0, 0, 0, 0};
  xp::IntLambda<5> L;
  REQUIRE(xp::int_lambda<5>(p, w0, L));
  CHECK(!L.wide);
  CHECK(xp::int_lattice_sign<5>(L, false) == 0);  // the cube's vertices are cospherical
  const double f[3] = {8.732, 0, 0};
  const double* q[5] = {a, b, c, d, f};
  CHECK(!xp::int_lambda<5>(q, w0, L));
  const double g[3] = {std::ldexp(1.0, 40), 0, 0};
  const double* r[5] = {a, b, c, d, g};
  CHECK(!xp::int_lambda<5>(r, w0, L));  // 2^40: lifted entries beyond int64
  xp::IntLambda<4> L4;
  const double* r4[4] = {a, b, c, g};
  CHECK(xp::int_lambda<4>(r4, nullptr, L4));  // plain: 2^40 is fine
  const double h[3] = {HUGE_VAL, 0, 0};
  const double* s[4] = {a, b, c, h};
  CHECK(!xp::int_lambda<4>(s, nullptr, L4));
  const double wsub[5] = {0, 0, 0, 0, 4.9e-324};
  CHECK(!xp::int_lambda<5>(p, wsub, L));
}

// xp::small_integer_minor (the SoS minors' near-lattice stage of minor_quick
// and sos_lazy) against the exact expansion minor (MinorLaplace<XDbl>), on
// the Λ of near-lattice points: small integer coordinates (and integer
// weights), each value moved with some probability by 1..4 ulps, a zero to
// ±1..4 subnormal steps, or by ±2^-e for e in {2, 4, 10, 20, 30, 45, 55}
// (tails at and beyond the stage's 2^-40 limit, which it must refuse or
// decide correctly); equal rows and columns from copied points. Every answer
// other than 2 must be the exact sign. Not vacuous: many minors decided, zero
// and non-zero among them, and among those some whose entries were not all
// integers (the tail rule). Planted errors caught here: the tail limit lifted
// to 1 with the d != 0 bound test removed; the dominant tail's sign flipped.
// Not caught (this family has no such entries): the ordering margin of a
// tail's parts (te - 3) widened to te + 3.
template <class A, int K>
void near_lattice_minors(std::mt19937_64& g, long (&tally)[4]) {
  const bool lifted = (g() & 1) != 0 && K >= 4;
  const int nc = lifted ? K - 2 : K - 1;
  std::vector<double> x(static_cast<size_t>(K * nc)), w(static_cast<size_t>(K), 0.0);
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1)); };
  bool moved_any = false;
  for (int i = 0; i < K; ++i) {
    const int copy = i > 0 && uni(0, 4) == 0 ? uni(0, i - 1) : -1;
    for (int j = 0; j < nc; ++j) {
      double& v = x[static_cast<size_t>(i * nc + j)];
      v = copy >= 0 ? x[static_cast<size_t>(copy * nc + j)] : uni(-2, 2);
      if (copy >= 0 || uni(0, 3) != 0) continue;
      moved_any = true;
      const int kind = uni(0, 2);
      if (kind == 0) {
        for (int u = uni(1, 4); u > 0; --u) v = std::nextafter(v, (g() & 1) ? 1e9 : -1e9);
      } else if (kind == 1) {
        v = (v == 0.0 ? 0.0 : v) + ((g() & 1) ? 1 : -1) * uni(1, 4) * 0x1p-1074;
      } else {
        const int e = std::vector<int>{2, 4, 10, 20, 30, 45, 55}[static_cast<size_t>(uni(0, 6))];
        v += ((g() & 1) ? 1 : -1) * std::ldexp(1.0, -e);
      }
    }
    if (lifted) w[static_cast<size_t>(i)] = copy >= 0 ? w[static_cast<size_t>(copy)] : uni(-3, 3);
  }
  const double* p[K];
  for (int i = 0; i < K; ++i) p[i] = x.data() + i * nc;
  // the Dbl Λ inside its window only (ulp moves of a zero are subnormals),
  // as lambda_exact and sos_lazy use it
  if (!A::kExtended && !xp::call_range<K>(p, lifted ? w.data() : nullptr).fits(lifted ? K : K - 1)) return;
  xp::RawLambda<A, K> L;
  xp::build_lambda<A, K>(p, lifted ? w.data() : nullptr, L);
  xp::RawLambda<xp::XDbl, K> X;
  xp::build_lambda<xp::XDbl, K>(p, lifted ? w.data() : nullptr, X);
  constexpr unsigned kAll = (1u << K) - 1u;
  for (int rep = 0; rep < 8; ++rep) {
    const int r = uni(1, K);
    unsigned rows = 0, cols = 0;
    while (__builtin_popcount(rows) < r) rows |= 1u << uni(0, K - 1);
    while (__builtin_popcount(cols) < r) cols |= 1u << uni(0, K - 1);
    if (rep == 0) rows = cols = kAll;
    const int q = xp::small_integer_minor<A, K>(L, xp::Kept<K>(rows, cols));
    if (q == 2) continue;
    const int exact = xp::MinorLaplace<xp::XDbl, K>::sign(X, rows, cols);
    INFO("K " << K << (lifted ? " lifted" : " plain") << " rows " << rows << " cols " << cols);
    REQUIRE(q == exact);
    ++tally[0];
    tally[1] += q == 0;
    tally[2] += moved_any;
    tally[3] += moved_any && q != 0;
  }
}

TEST_CASE("small_integer_minor: near-lattice minors equal the exact expansion minor",
          "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x5a11);
  long dbl[4] = {}, xdbl[4] = {};
  for (int n = 0; n < 1500; ++n) {
    near_lattice_minors<xp::Dbl, 4>(g, dbl);
    near_lattice_minors<xp::Dbl, 5>(g, dbl);
    near_lattice_minors<xp::Dbl, 6>(g, dbl);
    near_lattice_minors<xp::Dbl, 7>(g, dbl);
    near_lattice_minors<xp::XDbl, 4>(g, xdbl);
    near_lattice_minors<xp::XDbl, 5>(g, xdbl);
    near_lattice_minors<xp::XDbl, 6>(g, xdbl);
    near_lattice_minors<xp::XDbl, 7>(g, xdbl);
  }
  std::printf("small_integer_minor: Dbl decided %ld (zero %ld, moved %ld, moved non-zero %ld); "
              "XDbl decided %ld (zero %ld, moved %ld, moved non-zero %ld)\n",
              dbl[0], dbl[1], dbl[2], dbl[3], xdbl[0], xdbl[1], xdbl[2], xdbl[3]);
  for (const long* t : {dbl, xdbl}) {
    CHECK(t[0] > 5000);
    CHECK(t[1] > 500);
    CHECK(t[3] > 500);
  }
}

// Perturbed lattices, whole points moved (the inputs of issue 39's perturbed
// grids): K points of {0, 1, 2}^d plus an offset (0, 1 or 2^20), some
// repeated, and each point moved with probability 1/4 by 1..3 ulp in every
// coordinate (a zero becomes a subnormal: outside the Dbl window), or its
// weight by 1..3 ulp. Against GMP (pred::exact::minor_sign on the exact
// integer Λ, pred::stage::gmp_sos):
//   * MinorLaplace<XDbl> (and <Dbl> inside the window) on the full Λ and on
//     random row/column subsets — its binary64 levels over the rows of
//     one-component values (double_levels_exact), the others as expansions,
//     the rows' permutation sign;
//   * det_translated<XDbl> / <Dbl> from the narrowest base row, with its
//     sign (-1)^(K-1-b);
//   * the SoS sign of the whole path after the filters (staged.hpp: calls
//     with 1..K-3 moved rows skip the dynamic filter), of lambda_exact_sorted
//     and of sos_expansions<XDbl> (minor_quick skips the ErrDouble minor for
//     near-integer minors), rows sorted by id.
// Not vacuous: the tally counts calls with moved rows and det Λ = 0 (the SoS
// decides), with moved rows and det Λ != 0, and calls outside the window.
// Planted errors caught here: the permutation sign of the binary64 prefix
// dropped, the base row's sign dropped, double_levels_exact's 53 bits raised
// to 120, minor_quick answering 0 for the near-integer minors it sends past
// the ErrDouble minor.
namespace {

// A random minor of a K-row Λ: r = 1..K rows and as many columns (masks).
template <int K>
void random_minor(std::mt19937_64& g, unsigned& rows, unsigned& cols) {
  const int r = 1 + static_cast<int>(g() % K);
  rows = cols = 0;
  while (__builtin_popcount(rows) < r) rows |= 1u << (g() % K);
  while (__builtin_popcount(cols) < r) cols |= 1u << (g() % K);
}

// A call's rows: the points x (weights w, null for a plain call), K
// distinct ids in arbitrary order (a shuffled 0..K-1 times 10, plus 0..9),
// and its exact Λ for GMP.
template <int K>
struct CallRows {
  const double* p[K];
  const double* wp;
  PointId ids[K];
  pred::exact::IntLambda G;
  CallRows(const double (&x)[K][K], const double* w, std::mt19937_64& g) : wp(w) {
    for (int i = 0; i < K; ++i) p[i] = x[i];
    std::vector<int> perm(static_cast<size_t>(K));
    for (int i = 0; i < K; ++i) perm[static_cast<size_t>(i)] = i;
    std::shuffle(perm.begin(), perm.end(), g);
    for (int i = 0; i < K; ++i) ids[i] = static_cast<PointId>(10 * perm[static_cast<size_t>(i)] + g() % 10);
    G = pred::exact::build_lambda(K, p, wp);
  }
};

template <int K>
void perturbed_lattice_call(std::mt19937_64& g, long (&tally)[5]) {
  const bool lifted = K >= 4 && (g() & 1) != 0;
  const int nc = lifted ? K - 2 : K - 1;
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1)); };
  const double offset = std::vector<double>{0.0, 1.0, 0x1p20}[static_cast<size_t>(uni(0, 2))];
  double x[K][K], w[K];
  int moved = 0;
  for (int i = 0; i < K; ++i) {
    const int copy = i > 0 && uni(0, 5) == 0 ? uni(0, i - 1) : -1;
    for (int j = 0; j < nc; ++j) x[i][j] = copy >= 0 ? x[copy][j] : offset + uni(0, 2);
    w[i] = copy >= 0 ? w[copy] : (uni(0, 2) == 0 ? uni(0, 2) : 0.0);
    if (copy >= 0 || uni(0, 3) != 0) continue;
    ++moved;
    auto move = [&](double& v) {
      for (int u = uni(1, 3); u > 0; --u) v = std::nextafter(v, (g() & 1) ? 1e9 : -1e9);
    };
    if (lifted && uni(0, 4) == 0) {
      move(w[i]);
    } else {
      for (int j = 0; j < nc; ++j) move(x[i][j]);
    }
  }
  const CallRows<K> call(x, lifted ? w : nullptr, g);
  const double* const* p = call.p;
  const double* wp = call.wp;
  const PointId* ids = call.ids;
  const pred::exact::IntLambda& G = call.G;
  constexpr unsigned kAll = (1u << K) - 1u;
  const int det = pred::exact::minor_sign(G, kAll, kAll);
  const bool window = xp::call_range<K>(p, wp).fits(lifted ? K : K - 1);
  INFO("K " << K << (lifted ? " lifted" : " plain") << " offset " << offset << " moved " << moved << " window "
            << window);
  // minors
  xp::RawLambda<xp::XDbl, K> X;
  xp::build_lambda<xp::XDbl, K>(p, wp, X);
  xp::RawLambda<xp::Dbl, K> D;
  if (window) xp::build_lambda<xp::Dbl, K>(p, wp, D);
  for (int rep = 0; rep < 4; ++rep) {
    unsigned rows = kAll, cols = kAll;
    if (rep > 0) random_minor<K>(g, rows, cols);
    const int ref = pred::exact::minor_sign(G, rows, cols);
    INFO("rows " << rows << " cols " << cols);
    REQUIRE((xp::MinorLaplace<xp::XDbl, K>::sign(X, rows, cols)) == ref);
    if (window) REQUIRE((xp::MinorLaplace<xp::Dbl, K>::sign(D, rows, cols)) == ref);
  }
  // the exact determinant from the narrowest base row
  REQUIRE((xp::det_translated<xp::XDbl, K>(p, wp)) == det);
  if (window) REQUIRE((xp::det_translated<xp::Dbl, K>(p, wp)) == det);
  // the SoS sign: the staged path after the filters, the exact stage, the
  // XDbl search (rows sorted by id)
  const int sos = pred::stage::gmp_sos(K, ids, p, wp);
  REQUIRE((pred::lambda_sign_after_filters<K, PointId, false>(ids, p, wp)) == sos);
  REQUIRE(pred::lambda_exact_sorted<K>(ids, p, wp, true) == sos);
  int order[K];
  const int parity = pred::sort_rows_by_id(K, ids, order);
  const double* sp[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sp[i] = p[order[i]];
    sw[i] = w[order[i]];
  }
  if (det == 0) REQUIRE(parity * xp::sos_expansions<xp::XDbl, K>(sp, lifted ? sw : nullptr) == sos);
  ++tally[0];
  tally[1] += moved > 0 && det == 0;
  tally[2] += moved > 0 && det != 0;
  tally[3] += !window;
  tally[4] += moved >= 1 && moved <= K - 3;
}

}  // namespace

TEST_CASE("perturbed lattices: binary64 Laplace levels, the narrowest base row and the near-lattice SoS equal GMP",
          "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x9e3779b9);
  long t[5] = {};
  for (int n = 0; n < 400; ++n) {
    perturbed_lattice_call<4>(g, t);
    perturbed_lattice_call<5>(g, t);
    perturbed_lattice_call<6>(g, t);
    perturbed_lattice_call<7>(g, t);
  }
  std::printf("perturbed lattices: calls %ld, moved with det 0 %ld, moved with det != 0 %ld, "
              "outside the Dbl window %ld, 1..K-3 moved rows %ld\n",
              t[0], t[1], t[2], t[3], t[4]);
  CHECK(t[1] > 200);
  CHECK(t[2] > 200);
  CHECK(t[3] > 200);
  CHECK(t[4] > 400);
}

// xp::int_lattice_sos_mod (the SoS sign of an integer Λ by the greedy walk of
// rank tests modulo p = 2^31 - 1 or 2^61 - 1) against sos_search on the exact
// integer minors (xp::int_lattice_sos_search, the memo search it replaces),
// on integer matrices with a 1-column built to be deeply degenerate: the
// rows on an affine flat of dimension 0 .. K-2 (a base row plus small
// integer combinations of flat generators), then with some probability a
// column made constant, zero, a copy or the sum of two others, a row copied,
// or a column replaced by the rows' squared norms (a lifted Λ). Entries from
// a bound R in {1, 2, 3, 46, 1000}: both primes' ranges (int_lambda's bound
// lf(K) + B <= 30, <= 60) and beyond (the dispatcher int_lattice_sign_as then
// takes sos_search). The walk's lemma needs nothing of a Λ but the 1-column,
// so any such matrix is a valid input. Not vacuous: most calls have det = 0,
// many make the reference search read more than K minors (perturbations
// beyond the first row), and both primes run.
// Planted errors caught here: the column options tried in increasing order
// (0 .. K-2); the re-pivot after removing a pivot column skipped. A minor that
// is a multiple of the prime does not occur by chance; the test after this
// one builds one.
namespace {

int bit_len(unsigned long long v) {
  int b = 0;
  while (v) ++b, v >>= 1;
  return b;
}

template <int K>
xp::IntLambda<K> degenerate_int_lambda(std::mt19937_64& g) {
  auto uni = [&](long long lo, long long hi) {
    return lo + static_cast<long long>(g() % static_cast<std::uint64_t>(hi - lo + 1));
  };
  const long long R = std::vector<long long>{1, 2, 3, 46, 1000}[static_cast<size_t>(uni(0, 4))];
  constexpr int C = K - 1;  // columns before the 1-column
  long long base[C], gen[K][C];
  const int q = static_cast<int>(uni(0, K - 2));  // the flat's dimension
  for (int j = 0; j < C; ++j) base[j] = uni(-R, R);
  for (int k = 0; k < q; ++k)
    for (int j = 0; j < C; ++j) gen[k][j] = uni(-1, 1) * (uni(0, 2) == 0 ? uni(-R, R) : 1);
  xp::IntLambda<K> L;
  for (int i = 0; i < K; ++i) {
    for (int j = 0; j < C; ++j) L.a[i][j] = base[j];
    for (int k = 0; k < q; ++k) {
      const long long c = uni(-2, 2);
      for (int j = 0; j < C; ++j) L.a[i][j] += c * gen[k][j];
    }
    L.a[i][K - 1] = 1;
  }
  for (int e = static_cast<int>(uni(0, 3)); e > 0; --e) {
    const int j = static_cast<int>(uni(0, C - 1)), a = static_cast<int>(uni(0, C - 1)),
              b = static_cast<int>(uni(0, C - 1));
    switch (uni(0, 5)) {
      case 0: for (int i = 0; i < K; ++i) L.a[i][j] = L.a[0][j]; break;              // constant
      case 1: for (int i = 0; i < K; ++i) L.a[i][j] = 0; break;                      // zero
      case 2: for (int i = 0; i < K; ++i) L.a[i][j] = L.a[i][a]; break;              // a copy
      case 3: for (int i = 0; i < K; ++i) L.a[i][j] = L.a[i][a] + L.a[i][b]; break;  // a sum
      case 4: {                                                                      // a copied row
        const int r = static_cast<int>(uni(0, K - 1)), s = static_cast<int>(uni(0, K - 1));
        for (int t = 0; t < K; ++t) L.a[r][t] = L.a[s][t];
        break;
      }
      default:  // lifted: column C-1 the squared norm of the others
        if (C >= 2)
          for (int i = 0; i < K; ++i) {
            long long s = 0;
            for (int t = 0; t < C - 1; ++t) s += L.a[i][t] * L.a[i][t];
            L.a[i][C - 1] = s;
          }
    }
  }
  int bits = xp::log2_factorial_ceil(K);  // int_lambda's bound: lf(K) + the columns' bit lengths
  for (int j = 0; j < K; ++j) {
    unsigned long long any = 0;
    for (int i = 0; i < K; ++i) any |= static_cast<unsigned long long>(L.a[i][j] < 0 ? -L.a[i][j] : L.a[i][j]);
    bits += bit_len(any);
  }
  L.bits = bits;
  L.wide = bits > 63;
  return L;
}

template <class I, int K>
void greedy_against_search(const xp::IntLambda<K>& L, long (&tally)[7]) {
  constexpr unsigned kAll = (1u << K) - 1u;
  const int det = xp::int_minor_sign<I, K>(L, kAll, kAll);
  int asked = 0;
  const int ref = det != 0 ? det : xp::sos_search<K>(true, [&](unsigned kr, unsigned kc) -> int {
    ++asked;
    return xp::int_minor_sign<I, K>(L, kr, kc);
  });
  REQUIRE(ref != 0);
  INFO("K " << K << " bits " << L.bits << " det " << det);
  if (L.bits <= xp::ModP31::kMaxBits) {
    REQUIRE((xp::int_lattice_sos_mod<xp::ModP31, K>(L)) == ref);
    ++tally[3];
  }
#if defined(FLIPFLOP_INT128)
  if (L.bits <= xp::ModP61::kMaxBits) {
    REQUIRE((xp::int_lattice_sos_mod<xp::ModP61, K>(L)) == ref);
    ++tally[4];
  }
#endif
  // the walk in binary64 (Bareiss), where its bound on the minors holds
  const int by_double = xp::int_lattice_sos_dbl<K>(L, true);
  if (by_double != 2) {
    REQUIRE(by_double == ref);
    REQUIRE((xp::int_lattice_sos_dbl<K>(L, false)) == det);
    ++tally[6];
  }
  REQUIRE((xp::int_lattice_sign_as<I, K>(L, true)) == ref);
  REQUIRE((xp::int_lattice_sign_as<I, K>(L, false)) == det);
  ++tally[0];
  tally[1] += det == 0;
  tally[2] += asked > K;
  tally[5] += L.bits > 60;
}

template <int K>
void greedy_property(std::mt19937_64& g, long (&tally)[7]) {
  const xp::IntLambda<K> L = degenerate_int_lambda<K>(g);
#if defined(FLIPFLOP_INT128)
  if (L.wide) return greedy_against_search<xp::int128_t, K>(L, tally);
#else
  if (L.wide) return;
#endif
  greedy_against_search<long long, K>(L, tally);
}

}  // namespace

TEST_CASE("int lattice: the SoS walk by ranks modulo p equals sos_search on the exact minors",
          "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x31e7);
  long t[7] = {};
  for (int n = 0; n < 3000; ++n) {
    greedy_property<2>(g, t);
    greedy_property<3>(g, t);
    greedy_property<4>(g, t);
    greedy_property<5>(g, t);
    greedy_property<6>(g, t);
    greedy_property<7>(g, t);
  }
  std::printf("int lattice SoS walk: calls %ld det 0 %ld deep %ld (P31 %ld, P61 %ld, beyond 60 bits %ld, binary64 %ld)\n",
              t[0], t[1], t[2], t[3], t[4], t[5], t[6]);
  CHECK(t[1] * 2 > t[0]);
  CHECK(t[6] > 2000);          // the binary64 walk decided many calls
  CHECK(t[6] < t[0] - 1000);   // and its bound sent many to the primes
  CHECK(t[2] * 5 > t[1]);
  CHECK(t[3] > 2000);
  CHECK(t[4] > t[3] + 1000);
  CHECK(t[5] > 100);
}

// staged.hpp lambda_small_int_sorted (integer coordinates and weights below
// 2^20 in magnitude, the walk in binary64 straight from the doubles) against
// GMP with SoS (stage::gmp_sos) and, without ids, GMP's exact sign: calls of
// k = 3..8 rows on small grids (coordinates in -s..s, many exactly
// degenerate), integer weights or none, distinct random ids; then values at
// the edge of its domain (2^20 - 1 accepted; 2^20, 0.5, NaN, infinity
// refused: 2, the int64 stage decides those).
namespace {
std::vector<PointId> distinct_ids(std::mt19937_64& g, int k) {
  std::vector<PointId> ids;
  while (static_cast<int>(ids.size()) < k) {
    const PointId v = static_cast<PointId>(g() % 1000);
    if (std::find(ids.begin(), ids.end(), v) == ids.end()) ids.push_back(v);
  }
  return ids;
}
template <int K>
void small_int_calls(std::mt19937_64& g, bool lifted, long (&t)[4]) {
  constexpr int kMaxD = K - 1;
  const int d = lifted ? K - 2 : K - 1;
  for (int rep = 0; rep < 400; ++rep) {
    const long long side = 1 + static_cast<long long>(g() % 3);
    const bool big = g() % 8 == 0;  // some coordinates near the domain's edge
    double x[K][kMaxD], w[K];
    const double* p[K];
    const std::vector<PointId> ids = distinct_ids(g, K);
    for (int i = 0; i < K; ++i) {
      for (int j = 0; j < d; ++j) {
        x[i][j] = static_cast<double>(static_cast<long long>(g() % static_cast<std::uint64_t>(2 * side + 1)) - side);
        if (big && j == 0) x[i][j] += 0x1p20 - 1 - static_cast<double>(side);
      }
      w[i] = lifted && g() % 2 ? static_cast<double>(static_cast<long long>(g() % 5) - 2) : 0.0;
      p[i] = x[i];
    }
    const double* wp = lifted ? w : nullptr;
    const int s = pred::lambda_small_int_sorted<K>(ids.data(), p, wp, false, false);
    const int e = pred::lambda_small_int_sorted<K>(static_cast<const PointId*>(nullptr), p, wp, false, false);
    // told that every value is a small integer (true here): the same answers
    REQUIRE(pred::lambda_small_int_sorted<K>(ids.data(), p, wp, true, false) == s);
    REQUIRE(pred::lambda_small_int_sorted<K>(static_cast<const PointId*>(nullptr), p, wp, true, false) == e);
    INFO("k " << K << (lifted ? " lifted" : " plain") << " side " << side << " big " << big);
    ++t[0];
    if (s != 2) {
      REQUIRE(s == pred::stage::gmp_sos(K, ids.data(), p, wp));
      ++t[1];
    }
    if (e != 2) {
      const int ge = pred::stage::gmp(K, p, wp);
      REQUIRE(e == ge);
      t[2] += ge == 0;
    }
    // the whole staged path with the filter of these points: small
    // integers, so the integer walk goes first where K >= kLatticeFirstK
    // (staged.hpp), the float filters first below; the SoS sign either way
    auto staged_with_filter = [&] {
      std::vector<double> flat;
      for (int i = 0; i < K; ++i) flat.insert(flat.end(), x[i], x[i] + d);
      const pred::StaticFilter f = pred::StaticFilter::for_points(flat.data(), K, d, wp);
      return std::make_pair(f.small_integers(), pred::lambda_sign_staged<K>(&f, ids.data(), p, wp));
    };
    {
      const auto [small, sg] = staged_with_filter();
      REQUIRE(small);
      REQUIRE(sg == pred::stage::gmp_sos(K, ids.data(), p, wp));
    }
    // StaticFilter::walk_bounded: where the filter of these points says the
    // walk's bound holds for every call of K rows, it holds for this one
    // with any row last (Hadamard's product recomputed here by the walk's
    // own function, on each choice of D), and the walk told so gives the
    // same signs; on the small grids (no coordinate near 2^20) it is said
    {
      std::vector<double> flat;
      for (int i = 0; i < K; ++i) flat.insert(flat.end(), x[i], x[i] + d);
      const pred::StaticFilter f = pred::StaticFilter::for_points(flat.data(), K, d, wp);
      const bool bounded = f.walk_bounded(K, lifted);
      // the kernels build their filters from representatives (parallel.hpp:
      // the largest magnitude, the lowest set bit, a zero), without the
      // values' signs or spread: the flag must come out the same from them
      {
        double mx = 0.0, mw = 0.0;
        for (double v : flat) mx = std::max(mx, std::fabs(v));
        for (int i = 0; i < K; ++i) mw = std::max(mw, std::fabs(w[i]));
        const double reps[3] = {mx, 1.0, 0.0}, wreps[3] = {mw, 1.0, 0.0};
        const pred::StaticFilter r = pred::StaticFilter::for_points(reps, 3, 1, lifted ? wreps : nullptr);
        REQUIRE(r.small_integers());
        REQUIRE(r.walk_bounded(K, lifted) == bounded);
      }
      // (side <= 3: H^2 within the bound's computation below 2^51 for these)
      if (!big && K >= 3 && (K <= 6 || (K == 7 && !lifted))) REQUIRE(bounded);
      if (bounded) {
        ++t[3];
        for (int last = 0; last < K; ++last) {
          const double* q[K];
          double qw[K];
          for (int i = 0, r = 0; i < K; ++i)
            if (i != last) q[r] = p[i], qw[r++] = w[i];
          q[K - 1] = p[last], qw[K - 1] = w[last];
          double m[K - 1][K - 1];
          REQUIRE(pred::xp::small_integer_differences<K>(q, lifted ? qw : nullptr, m));
          REQUIRE(pred::xp::dbl_walk_hadamard_sq<K>(m) < 0x1p51);
        }
        REQUIRE(pred::lambda_small_int_sorted<K>(ids.data(), p, wp, true, true) == s);
        REQUIRE(pred::lambda_small_int_sorted<K>(static_cast<const PointId*>(nullptr), p, wp, true, true) == e);
      }
    }
    // out of the domain: refused, and no lattice filter
    const double saved = x[0][0];
    for (double v : {0x1p20, -0x1p20, 0.5, std::nan(""), HUGE_VAL}) {
      x[0][0] = v;
      REQUIRE(pred::lambda_small_int_sorted<K>(ids.data(), p, wp, false, false) == 2);
      if (std::isfinite(v)) {
        const auto [small, sg] = staged_with_filter();
        REQUIRE_FALSE(small);
        REQUIRE(sg == pred::stage::gmp_sos(K, ids.data(), p, wp));
      }
    }
    x[0][0] = saved;
  }
}
}  // namespace

TEST_CASE("int lattice: small integers straight from the doubles equal GMP", "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x5a11);
  long t[4] = {};
  for (bool lifted : {false, true}) {
    small_int_calls<3>(g, lifted, t);
    small_int_calls<4>(g, lifted, t);
    small_int_calls<5>(g, lifted, t);
    small_int_calls<6>(g, lifted, t);
    small_int_calls<7>(g, lifted, t);
    small_int_calls<8>(g, lifted, t);
  }
  std::printf("int lattice small integers: %ld calls, %ld decided with SoS, %ld exactly degenerate, %ld with the "
              "walk's bound known from the filter\n", t[0], t[1], t[2], t[3]);
  CHECK(t[3] * 2 > t[0]);  // the filter's walk_bounded said for most of them
  CHECK(t[1] * 5 > t[0] * 4);  // the bound refuses only some of the near-2^20 coordinates' calls
  CHECK(t[2] * 20 > t[0]);  // about a tenth of the calls: det 0 exactly
}

// xp::int_lattice_sos_dbl at the edge of its bound: matrices whose
// Hadamard product H^2 (exact_expansion.hpp, the binary64 walk) lies within
// a factor 8 below 2^51, where products of two minors come within a few bits
// of 2^53 and a rounded product or quotient would flip a zero test or a
// sign; half of them with a row an affine combination of two others (det Λ
// = 0: the SoS search), against the exact integer minors.
#if defined(FLIPFLOP_INT128)
TEST_CASE("int lattice: the binary64 walk at the edge of its bound", "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x5e1d);
  long decided = 0, near = 0, zero = 0;
  auto edge = [&](auto k_tag) {
    constexpr int K = decltype(k_tag)::value, W = K - 1;
    // entries up to M: H^2 about (W M^2 / 3)^W, aimed just below 2^51
    const double target = std::pow(2.0, 51.0 / W);
    const long long M = static_cast<long long>(std::sqrt(3.0 * target / W)) + 1;
    for (int rep = 0; rep < 3000; ++rep) {
      const long long m = M - static_cast<long long>(g() % static_cast<std::uint64_t>(M / 4 + 1));
      xp::IntLambda<K> L;
      for (int i = 0; i < K; ++i) {
        for (int j = 0; j < W; ++j)
          L.a[i][j] = static_cast<long long>(g() % static_cast<std::uint64_t>(2 * m + 1)) - m;
        L.a[i][K - 1] = 1;
      }
      if (g() % 2) {  // row r = 2 row a - row b (coefficients summing to 1)
        const int r = static_cast<int>(g() % K), a = static_cast<int>(g() % K), b = static_cast<int>(g() % K);
        if (r != a && r != b && a != b)
          for (int j = 0; j < W; ++j) L.a[r][j] = 2 * L.a[a][j] - L.a[b][j];
      }
      int bits = xp::log2_factorial_ceil(K);
      for (int j = 0; j < K; ++j) {
        unsigned long long any = 0;
        for (int i = 0; i < K; ++i)
          any |= static_cast<unsigned long long>(L.a[i][j] < 0 ? -L.a[i][j] : L.a[i][j]);
        bits += bit_len(any);
      }
      L.bits = bits;
      L.wide = bits > 63;
      double h2 = 1.0;
      for (int j = 0; j < W; ++j) {
        double sq = 0.0;
        for (int i = 0; i < W; ++i) {
          const double d = static_cast<double>(L.a[i][j] - L.a[K - 1][j]);
          sq += d * d;
        }
        h2 *= std::max(1.0, sq);
      }
      constexpr unsigned kAll = (1u << K) - 1u;
      const int det = xp::int_minor_sign<xp::int128_t, K>(L, kAll, kAll);
      const int ref = det != 0 ? det : xp::int_lattice_sos_search<xp::int128_t, K>(L);
      const int by_double = xp::int_lattice_sos_dbl<K>(L, true);
      INFO("K " << K << " h2 " << h2 << " det " << det);
      if (h2 >= 0x1p51) {
        REQUIRE(by_double == 2);
        continue;
      }
      REQUIRE(by_double == ref);
      REQUIRE((xp::int_lattice_sos_dbl<K>(L, false)) == det);
      ++decided;
      near += h2 >= 0x1p48;
      zero += det == 0;
    }
  };
  edge(std::integral_constant<int, 3>{});
  edge(std::integral_constant<int, 4>{});
  edge(std::integral_constant<int, 5>{});
  edge(std::integral_constant<int, 6>{});
  edge(std::integral_constant<int, 7>{});
  std::printf("int lattice binary64 walk at its bound: %ld decided, %ld with H^2 >= 2^48, %ld with det 0\n", decided,
              near, zero);
  CHECK(decided > 4000);
  CHECK(near > 2000);
  CHECK(zero > 400);
}
#endif

// The prime must exceed every minor: here det Λ = 0 (three collinear points,
// columns x, y, 1) and sos_search's first non-zero leaf is the minor on rows
// {1, 2}, columns {0, 2}, equal to -p for p = 2^31 - 1. Modulo that p it
// vanishes and the walk takes the next leaf, of the other sign; int_lambda's
// bound (bits = 38 here) keeps the dispatcher off that prime.
TEST_CASE("int lattice: the SoS walk's prime bound", "[predicates][stages][int_lattice]") {
  constexpr long long p = (1ll << 31) - 1;
  xp::IntLambda<3> L;
  const long long rows[3][3] = {{0, 0, 1}, {p, 1, 1}, {2 * p, 2, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) L.a[i][j] = rows[i][j];
  L.bits = xp::log2_factorial_ceil(3) + bit_len(static_cast<unsigned long long>(2 * p)) + 2 + 1;
  CHECK(L.bits > xp::ModP31::kMaxBits);
  const int ref = xp::int_lattice_sos_search<long long, 3>(L);
  CHECK(ref == 1);
  CHECK((xp::int_lattice_sos_mod<xp::ModP31, 3>(L)) == -ref);  // the prime too small: wrong
#if defined(FLIPFLOP_INT128)
  CHECK((xp::int_lattice_sos_mod<xp::ModP61, 3>(L)) == ref);
#endif
  CHECK((xp::int_lattice_sign_as<long long, 3>(L, true)) == ref);
}

// xp::mod_det_sign (the leaf minor's sign from its residue modulo p, where
// the walk's leaf minor would need __int128) against det_by_minors on
// __int128, on r x r integer matrices (r = 1..6) whose entries keep every
// minor below 2^30 (both primes) or 2^60 (p = 2^61 - 1), singular ones among
// them (a row a combination of two others), negative determinants as often
// as positive ones.
#if defined(FLIPFLOP_INT128)
TEST_CASE("int lattice: determinant signs from residues modulo p", "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0xde7);
  long tally[3] = {};  // positive, negative, zero
  for (int n = 0; n < 20000; ++n) {
    const int r = 1 + static_cast<int>(g() % 6);
    const bool wide = (g() & 1) != 0;
    // entries below 2^e with lf(r) + r e <= 30 (or 60): |every minor| < 2^30 (2^60)
    const int e = ((wide ? 60 : 30) - xp::log2_factorial_ceil(r)) / r;
    const long long bound = (1ll << e) - 1;
    long long a[36];
    std::uniform_int_distribution<long long> u(-bound, bound);
    for (int i = 0; i < r * r; ++i) a[i] = u(g);
    if (r >= 3 && g() % 3 == 0) {  // singular: row 0 = row 1 - row 2, rows 1 and 2 halved first
      for (int j = 0; j < r; ++j) {
        a[r + j] /= 2;
        a[2 * r + j] /= 2;
        a[j] = a[r + j] - a[2 * r + j];
      }
    }
    xp::int128_t t[36];
    unsigned long long m31[36], m61[36];
    for (int i = 0; i < r * r; ++i) {
      t[i] = a[i];
      m31[i] = xp::mod_of<xp::ModP31>(a[i]);
      m61[i] = xp::mod_of<xp::ModP61>(a[i]);
    }
    const xp::int128_t d = xp::int_det_of_order<1, 6, xp::int128_t>(t, r);
    const int s = (d > 0) - (d < 0);
    INFO("r " << r << " e " << e);
    if (!wide) REQUIRE(xp::mod_det_sign<xp::ModP31>(m31, r) == s);
    REQUIRE(xp::mod_det_sign<xp::ModP61>(m61, r) == s);
    ++tally[s > 0 ? 0 : s < 0 ? 1 : 2];
  }
  std::printf("mod_det_sign: positive %ld negative %ld zero %ld\n", tally[0], tally[1], tally[2]);
  CHECK(tally[0] > 5000);
  CHECK(tally[1] > 5000);
  CHECK(tally[2] > 1000);
}
#endif

// The factor of every integer-stage minor bound, lf(k) = ceil(log2 k!), for
// every row count the stage takes (up to 11), against k! computed here: the
// smallest b with 2^b >= k!. (It stopped at 8 rows while the stage grew to
// 11: a bound 3..10 bits short for 9..11 rows.)
TEST_CASE("int lattice: lf(k) = ceil(log2 k!) for every row count", "[predicates][stages][int_lattice]") {
  unsigned long long f = 1;
  for (int k = 1; k <= xp::kIntLambdaMaxK; ++k) {
    f *= static_cast<unsigned long long>(k);
    int b = 0;
    while ((1ull << b) < f) ++b;
    INFO("k " << k << ", k! " << f);
    CHECK(xp::log2_factorial_ceil(k) == b);
  }
}

// The near-lattice polynomial stage (near_lattice.hpp: every value split as
// n + a 2^-60 + b 2^-1074, minors as polynomials in the two units, the
// leading coefficient's sign) against GMP on lattices with points moved by
// some ulp. K = 3..8 points, plain and lifted, on {0..2}^d plus an offset
// (0, 1, -3, 2^10 or 2^20: ulps 2^-52 .. 2^-32), some points copied, some
// on a plane (a constant coordinate); each point moved with probability 1/3
// by 1..3 ulp in every coordinate, or in one, or its weight (a moved 0 is a
// subnormal: the η unit), weights 0 or small integers. Properties:
//   (a) every minor NlMinors decides (the full Λ and random row/column
//       subsets, asked in a random order so that the row-set cache is hit
//       and missed) has the sign of pred::exact::minor_sign on the exact Λ;
//   (b) near_lattice_sign (exact and SoS, rows sorted by id) equals GMP's
//       exact and SoS signs wherever it decides, and so does the whole path
//       after the filters and lambda_exact_sorted;
//   (c) not vacuous: most calls decided, det Λ = 0 among them (the SoS
//       search runs on the stage's minors), calls with both units, with two
//       or more moved rows, with five or six, and refusals (seven moved
//       rows, int64 overflow) all occur.
// Planted errors caught here: the monomials read ε's degree first (the
// subnormal unit η ordered like ε); the moved rows' permutation sign
// dropped; the Laplace sign of the column subset's positions dropped.
namespace {

template <int K>
void near_lattice_poly_call(std::mt19937_64& g, long (&tally)[9]) {
  const bool lifted = K >= 4 && (g() & 1) != 0;
  const int nc = lifted ? K - 2 : K - 1;
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1)); };
  const double offset = std::vector<double>{0.0, 1.0, -3.0, 0x1p10, 0x1p20}[static_cast<size_t>(uni(0, 4))];
  const int flat = uni(0, 3) == 0 ? uni(0, nc - 1) : -1;  // a constant coordinate
  double x[K][K], w[K];
  int moved = 0;
  bool subnormal = false, ulp_unit = false;
  for (int i = 0; i < K; ++i) {
    const int copy = i > 0 && uni(0, 6) == 0 ? uni(0, i - 1) : -1;
    for (int j = 0; j < nc; ++j) x[i][j] = copy >= 0 ? x[copy][j] : (j == flat ? offset : offset + uni(0, 2));
    w[i] = copy >= 0 ? w[copy] : (uni(0, 2) == 0 ? uni(0, 3) : 0.0);
    if (copy >= 0 || uni(0, 2) != 0) continue;
    ++moved;
    auto move = [&](double& v) {
      for (int u = uni(1, 3); u > 0; --u) v = std::nextafter(v, (g() & 1) ? 1e9 : -1e9);
      subnormal |= std::fabs(v) < 0x1p-1000 && v != 0.0;
      ulp_unit |= std::fabs(v) >= 0x1p-1000;
    };
    const int how = uni(0, 5);
    if (lifted && how == 0) {
      move(w[i]);
    } else if (how == 1) {
      move(x[i][uni(0, nc - 1)]);
    } else {
      for (int j = 0; j < nc; ++j) move(x[i][j]);
    }
  }
  const CallRows<K> c(x, lifted ? w : nullptr, g);
  constexpr unsigned kAll = (1u << K) - 1u;
  INFO("K " << K << (lifted ? " lifted" : " plain") << " offset " << offset << " moved " << moved);
  xp::NlMinors<K> N;
  if (!xp::nl_build<K>(c.p, c.wp, N.L)) {
    // refused: more than xp::kNlMaxMoved (6) moved rows (copies of moved
    // points count), or a lifted coefficient beyond int64 (a ~ 2^29 at the
    // offset 2^20)
    int rows_moved = 0;
    for (int i = 0; i < K; ++i) {
      bool mv = lifted && w[i] != std::rint(w[i]);
      for (int j = 0; j < nc; ++j) mv = mv || x[i][j] != std::rint(x[i][j]);
      rows_moved += mv;
    }
    REQUIRE((rows_moved > xp::kNlMaxMoved || (lifted && offset == 0x1p20)));
    ++tally[7];
    return;
  }
  // (a) minors, the full Λ first, then random subsets (cache hits and misses)
  for (int rep = 0; rep < 6; ++rep) {
    unsigned rows = kAll, cols = kAll;
    if (rep > 0) random_minor<K>(g, rows, cols);
    const int s = N.sign(rows, cols);
    if (s == 2) continue;
    INFO("rows " << rows << " cols " << cols);
    REQUIRE(s == pred::exact::minor_sign(c.G, rows, cols));
    ++tally[0];
  }
  // (b) exact and SoS signs, rows sorted by id
  const int det = pred::exact::minor_sign(c.G, kAll, kAll);
  const int sos = pred::stage::gmp_sos(K, c.ids, c.p, c.wp);
  int order[K];
  const int parity = pred::sort_rows_by_id(K, c.ids, order);
  const double* sp[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sp[i] = c.p[order[i]];
    sw[i] = w[order[i]];
  }
  const int e = xp::near_lattice_sign<K>(sp, lifted ? sw : nullptr, false);
  const int ss = xp::near_lattice_sign<K>(sp, lifted ? sw : nullptr, true);
  if (e != 2) REQUIRE(e * parity == det);
  if (ss != 2) {
    REQUIRE(ss * parity == sos);
    ++tally[1];
    tally[2] += det == 0;
    tally[3] += subnormal && ulp_unit;
    tally[4] += moved >= 2;
    tally[5] += det == 0 && moved >= 1;
    int rows_moved = 0;  // (five and six: beyond stop 81's Leibniz branches)
    for (int i = 0; i < K; ++i) rows_moved += N.L.moved[i];
    tally[8] += rows_moved >= 5;
  } else {
    ++tally[6];
  }
  REQUIRE(pred::lambda_exact_sorted<K>(c.ids, c.p, c.wp, true) == sos);
  REQUIRE((pred::lambda_sign_after_filters<K, PointId, false>(c.ids, c.p, c.wp)) == sos);
}

// one call of each K, in order
template <int... K>
void near_lattice_poly_calls(std::mt19937_64& g, long (&tally)[9], std::integer_sequence<int, K...>) {
  (near_lattice_poly_call<K>(g, tally), ...);
}

}  // namespace

TEST_CASE("near-lattice polynomial stage: minors, exact and SoS signs equal GMP",
          "[predicates][stages][int_lattice]") {
  std::mt19937_64 g(0x6e6c);
  long t[9] = {};
  for (int n = 0; n < 300; ++n) near_lattice_poly_calls(g, t, std::integer_sequence<int, 3, 4, 5, 6, 7, 8>{});
  std::printf("near-lattice polynomials: minors decided %ld; calls decided %ld (det 0: %ld, both units %ld, "
              "2+ moved rows %ld, moved with det 0 %ld, 5+ moved rows %ld), undecided %ld, refused %ld\n",
              t[0], t[1], t[2], t[3], t[4], t[5], t[8], t[6], t[7]);
  CHECK(t[0] > 4000);
  CHECK(t[1] > 1200);
  CHECK(t[2] > 300);
  CHECK(t[3] > 50);
  CHECK(t[4] > 400);
  CHECK(t[5] > 100);
  CHECK(t[7] > 0);
  CHECK(t[8] > 10);
}

TEST_CASE("near-lattice polynomial stage: the split of a value", "[predicates][stages][int_lattice]") {
  long long n, a, b;
  REQUIRE(xp::nl_split(3.0, n, a, b));
  CHECK((n == 3 && a == 0 && b == 0));
  REQUIRE(xp::nl_split(std::nextafter(1.0, 2.0), n, a, b));  // 1 + 2^-52
  CHECK((n == 1 && a == 256 && b == 0));
  REQUIRE(xp::nl_split(std::nextafter(1.0, 0.0), n, a, b));  // 1 - 2^-53
  CHECK((n == 1 && a == -128 && b == 0));
  REQUIRE(xp::nl_split(-2 * std::numeric_limits<double>::denorm_min(), n, a, b));
  CHECK((n == 0 && a == 0 && b == -2));
  REQUIRE(xp::nl_split(std::nextafter(0x1p20, 0.0), n, a, b));  // 2^20 - 2^-33
  CHECK((n == 1048576 && a == -(1LL << 27) && b == 0));
  CHECK(!xp::nl_split(0.5, n, a, b));        // not near an integer
  CHECK(!xp::nl_split(1e-300, n, a, b));     // a remainder of neither unit
  CHECK(!xp::nl_split(0x1p27, n, a, b));     // beyond 2^26
  CHECK(!xp::nl_split(std::nan(""), n, a, b));
  CHECK(xp::nl_split(1.0 + 0x1p-20, n, a, b));   // a = 2^40: the bound
  CHECK(!xp::nl_split(1.0 + 0x1p-19, n, a, b));  // a = 2^41
}

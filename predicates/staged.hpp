// staged.hpp — the default evaluation of every predicate, stage by stage,
// header-only and __host__ __device__ (the CUDA kernels and their thrust/OpenMP
// build call it directly; predicates.cpp dispatches to it):
//
//   1. static filter      per-input bound (static_filter.hpp), when a
//                         StaticFilter of the input is given;
//   2. semi-static filter per-call bound from the column magnitudes
//                         (static_filter.hpp); for orient2d/3d with a
//                         static filter, the permanent bound of
//                         plain_filters instead (Shewchuk's errbound A);
//      integer lattice   (k <= 7) when every value of the call is an
//                         integer multiple of a common power of two within
//                         the bounds of xp::int_lambda: det Λ and the SoS
//                         minors exactly in int64 / __int128 (exact, so it
//                         decides — also 0 — and ends the path);
//   3. double-double filter (k <= 5) a priori bounded (dd_filter.hpp):
//                         decides near-degenerate calls; where it ran and
//                         failed the next stage is 4;
//      dynamic filter     ErrDouble running error bound (lambda_filter.hpp);
//   4. double-double      the same determinant on double-double values with
//                         a proven running error bound (err_dd.hpp,
//                         xp::lambda_sign_dd, inside the exact stage's double
//                         window): decides near-degenerate calls, whose
//                         determinant is of order u times its terms;
//                         skipped where stage 3 ran and failed (dd_ran);
//      exact              expansion arithmetic (exact_expansion.hpp), rows
//                         sorted by point index: Shewchuk's adaptive stages
//                         for orient2d/3d, the exact stage B of power2d/3d
//                         when the translated coordinates are exact
//                         (lifted_adaptive), else the whole translated matrix;
//   5. SoS                when the exact determinant is 0 and ids are given,
//                         the perturbation terms on double minors first
//                         (exact for small integers; else exact zero tests —
//                         zero or constant columns, equal rows — and the
//                         ErrDouble filter), each undecided minor on
//                         expansions (xp::sos_lazy).
//
// Stages 1-3 return a sign only when it is certain; 4-5 always decide. No
// stage allocates memory or recurses. GMP (Mode::gmp in predicates.hpp) is the
// independent oracle the property tests compare every stage with.
#pragma once

#include <type_traits>

#include "predicates/dd_filter.hpp"
#include "predicates/exact_expansion.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::pred {

// Sorts row positions by point index and returns the parity of the
// permutation, or 0 if an index repeats (two rows are the same point: the
// determinant is 0 even under the perturbation; `order` is then the identity).
// Without branches on the ids: the parity is that of the number of inverted
// pairs (what the insertion sort this replaces counted, one adjacent swap per
// inversion), and with distinct ids each row's rank — the number of smaller
// ids — is its place (order[rank] = row). The insertion sort's
// compare-and-swap chain mispredicted on ids in random order: on the 3^5
// grid's power5d calls (7 rows) its lines were the hottest of
// lambda_small_int_sorted in perf.
template <class Id>
FF_HD inline int sort_rows_by_id(int k, const Id* ids, int* order) {
  for (int i = 0; i < k; ++i) order[i] = i;
  if (!ids) return 1;
  int inversions = 0;
  bool repeat = false;
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j) {
      inversions += ids[i] > ids[j];
      repeat |= ids[i] == ids[j];
    }
  if (repeat) return 0;
  for (int i = 0; i < k; ++i) {
    int rank = 0;
    for (int j = 0; j < k; ++j) rank += ids[j] < ids[i];
    order[rank] = i;
  }
  return (inversions & 1) ? -1 : 1;
}

template <class Id>
FF_HD inline bool repeated_id(int k, const Id* ids) {
  if (!ids) return false;
  for (int i = 1; i < k; ++i)
    for (int j = 0; j < i; ++j)
      if (ids[i] == ids[j]) return true;
  return false;
}

// The rows (p, w) sorted by id into (sp, sw); returns the permutation's
// parity, or 0 if an id repeats (sort_rows_by_id). ids null: as given.
template <int K, class Id>
FF_HD inline int sorted_rows(const Id* ids, const double* const* p, const double* w, const double** sp,
                             double* sw) {
  int order[K];
  const int parity = sort_rows_by_id(K, ids, order);
  for (int i = 0; i < K; ++i) {
    sp[i] = p[order[i]];
    sw[i] = w ? w[order[i]] : 0.0;
  }
  return parity;
}

// Stages 4-5: exact sign (sos = false, may be 0) or SoS sign of det Λ with the
// rows in the given order (the rows are sorted by id internally). Called, not
// inlined, on the device (FF_DEVICE_NOINLINE).
// `dd_ran`: the double-double filter has run on these points and failed
// (xp::lambda_exact then skips its own double-double stage).
template <int K, class Id>
FF_HD FF_DEVICE_NOINLINE int lambda_exact_sorted(const Id* ids, const double* const* p, const double* w,
                                     bool sos, bool dd_ran = false) {
  const double* sp[K];
  double sw[K];
  const int parity = sorted_rows<K>(sos ? ids : static_cast<const Id*>(nullptr), p, w, sp, sw);
  if (parity == 0) return 0;
  return parity * xp::lambda_exact<K>(sp, w ? sw : nullptr, sos, dd_ran);
}

#if !defined(__CUDA_ARCH__)
// stage(sp, sw) on the rows sorted by id as lambda_exact_sorted sorts them,
// its sign times the sort's parity: 0 for a repeated id, 2 where the stage
// gives 2 (does not decide).
template <int K, class Id, class Stage>
inline int stage_sorted(const Id* ids, const double* const* p, const double* w, Stage&& stage) {
  const double* sp[K];
  double sw[K];
  const int parity = sorted_rows<K>(ids, p, w, sp, sw);
  if (parity == 0) return 0;
  const int s = stage(static_cast<const double* const*>(sp), w ? static_cast<const double*>(sw) : nullptr);
  return s == 2 ? 2 : parity * s;
}

// xp::near_lattice_sign (exact, SoS with ids), rows sorted by id.
template <int K, class Id>
inline int near_lattice_sorted(const Id* ids, const double* const* p, const double* w) {
  return stage_sorted<K>(ids, p, w, [&](const double* const* sp, const double* sw) {
    return xp::near_lattice_sign<K>(sp, sw, ids != nullptr);
  });
}

#if defined(__SIZEOF_INT128__)
// xp::sos_walk_first, rows sorted by id (SoS, ids not null; inside the Dbl
// window): 2 where det Λ is not 0 or the walk does not apply.
template <int K, class Id>
inline int walk_first_sorted(const Id* ids, const double* const* p, const double* w) {
  return stage_sorted<K>(ids, p, w, [](const double* const* sp, const double* sw) {
    const xp::Range range = xp::call_range<K>(sp, sw);
    if (!range.finite || !range.fits(sw ? K : K - 1)) return 2;
    return xp::sos_walk_first<K>(sp, sw);
  });
}
#endif
#endif

// The exact (SoS with ids) sign on the integer Λ of xp::int_lambda, rows
// sorted by id as lambda_exact_sorted sorts them. A call of its own on the
// device (FF_DEVICE_NOINLINE): its minors' buffers and the SoS memo stay out
// of the caller's frame (ptx_stack.py, predicates_cuda.cu, K = 5: the
// deepest chain 35.9 KB before the integer stage, 37.7 KB with it inlined,
// 36.4 KB with this call). 2 where it cannot decide (K >= 8, minors beyond
// 60 bits: xp::int_lattice_sign).
template <int K, class Id>
FF_HD FF_DEVICE_NOINLINE int lambda_int_sorted(const Id* ids, const xp::IntLambda<K>& L) {
  int order[K];
  const int parity = sort_rows_by_id(K, ids, order);
  if (parity == 0) return 0;
  xp::IntLambda<K> S;
  S.wide = L.wide;
  S.bits = L.bits;
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) S.a[i][j] = L.a[order[i]][j];
  const int s = xp::int_lattice_sign<K>(S, ids != nullptr);
  return s == 2 ? 2 : parity * s;
}

// The exact (SoS with ids) sign where every coordinate and weight of the call
// is an integer below 2^20 (xp::small_integer_differences), by the walk in
// binary64 on the id-sorted rows straight from the doubles; 2 where that does
// not apply (the integer stage below then decides). 3^5 grid Delaunay
// (rtd --dim 5, compute + certify, one thread): 1296 -> 1174 M instructions
// (callgrind) against the scan and build of Λ in int64 before the same walk.
// `known`: every value is known to be such an integer (the tests skipped);
// `bounded` (with known): the walk's bound is known to hold as well
// (StaticFilter::walk_bounded), and it is not computed.
template <int K, class Id>
FF_HD FF_DEVICE_NOINLINE int lambda_small_int_sorted(const Id* ids, const double* const* p, const double* w,
                                                     bool known, bool bounded) {
  const double* sp[K];
  double sw[K];
  const int parity = sorted_rows<K>(ids, p, w, sp, sw);
  if (parity == 0) return 0;
  double m[K - 1][K - 1];
  if (known)
    xp::small_integer_differences<K, true>(sp, w ? sw : nullptr, m);
  else if (!xp::small_integer_differences<K>(sp, w ? sw : nullptr, m))
    return 2;
  const int s = xp::int_lattice_sos_dbl_rows<K>(m, ids != nullptr, known && bounded);
  return s == 2 ? 2 : parity * s;
}

// The same sign with Λ built from the rows already sorted by id (after
// xp::int_lambda_scan(p, w, S)): lambda_int_sorted without building Λ in the
// given order and copying it. 2 where int_lambda_build's bound fails or the
// walk cannot decide (the caller's other stages then decide).
template <int K, class Id>
FF_HD FF_DEVICE_NOINLINE int lambda_int_build_sorted(const Id* ids, const double* const* p, const double* w,
                                                     const xp::IntScan& S) {
  const double* sp[K];
  double sw[K];
  const int parity = sorted_rows<K>(ids, p, w, sp, sw);
  if (parity == 0) return 0;
  xp::IntLambda<K> L;
  if (!xp::int_lambda_build<K>(sp, w ? sw : nullptr, S, L)) return 2;
  const int s = xp::int_lattice_sign<K>(L, ids != nullptr);
  return s == 2 ? 2 : parity * s;
}

template <int K, class Id>
FF_HD inline int lambda_sign_staged(const StaticFilter* f, const Id* ids, const double* const* p, const double* w);

// An input of small integers (StaticFilter::small_integers: a k^d grid)
// sends its calls of kLatticeFirstK rows or more to the integer walk before
// the float filters, telling it that every value is a small integer (no
// per-value tests): most calls are exactly degenerate there, which no filter
// decides, and the walk decides the others about as cheaply. Callgrind, one
// thread, `flipflop rtd` compute and certify (2026-12-03), before -> after:
// 3^5 grid 1091 -> 936 M instructions, 6^4 grid 1211 -> 1120 M, 2^6 grid
// 622 -> 505 M. From 6 rows: 6^4 grid 1135 M (its orient4d calls, 5 rows,
// are degenerate too); without the `known` flag (each value tested): 3^5
// 1012 M, and the 6^4 grid's power4d calls were cheaper through the filters.
// Below 5 rows (2D, 3D) the plain filters are a few dozen instructions.
inline constexpr int kLatticeFirstK = 5;

// The SoS sign of K points on a plane x_c = c0 (a constant coordinate column:
// det Λ = 0 exactly), rows sorted by id here. The search (xp::sos_search)
// asks first for the minors that drop the first row (the smallest index) and
// one column, the columns from K-2 down to 0; every one of them that keeps
// column c is 0 (on the other rows column c is c0 times the 1-column). So,
// with c the largest constant coordinate column, the first minor that can be
// non-zero drops column c, and its sign in the expansion is (-1)^c: it is the
// determinant of the other K-1 rows without column c — Λ of those points
// projected along x_c (a lifted column |x|^2 - w differs from the projected
// points' by c0^2 times the 1-column: the same determinant) — decided here by
// the staged path of K-1 rows, filters first, exactly (no ids: may be 0).
// Where it is 0 the whole search decides (xp::lambda_exact). On points on
// coordinate planes in millimetres (a building's floors and walls), per call:
// power3d 295 -> 59 ns, orient3d 172 -> 60 ns. Host only (the device runs the
// search: one frame less on its stack).
template <int K, class Id>
FF_HD int flat_sign_sorted(const Id* ids, const double* const* p, const double* w) {
  const double* sp[K];
  double sw[K];
  const int parity = sorted_rows<K>(ids, p, w, sp, sw);
  if (parity == 0) return 0;
#if !defined(__CUDA_ARCH__)
  if constexpr (K >= 4) {
    const int ncoord = w ? K - 2 : K - 1;
    const int c = xp::last_constant_column<K>(sp, ncoord);
    if (c >= 0) {
      double q[K - 1][K];  // each row's ncoord - 1 coordinates
      const double* qp[K - 1];
      for (int i = 1; i < K; ++i) {
        int t = 0;
        for (int j = 0; j < ncoord; ++j)
          if (j != c) q[i - 1][t++] = sp[i][j];
        qp[i - 1] = q[i - 1];
      }
      const int s = lambda_sign_staged<K - 1, Id>(nullptr, static_cast<const Id*>(nullptr), qp,
                                                  w ? sw + 1 : static_cast<const double*>(nullptr));
      if (s != 0) return (c & 1) ? -parity * s : parity * s;
    }
  }
#endif
  return parity * xp::lambda_exact<K>(sp, w ? sw : nullptr, true, true);
}

// The default path after the static and semi-static filters (fast.hpp calls
// it when both have failed inline). For 3 <= K <= 5 the double-double filter
// (dd_filter.hpp) comes first; where it ran (inside its window) and could not
// decide, the dynamic filter is skipped: its error bound, of order u times the
// terms, is far above the double-double one (u^2 times the column bounds), so
// it would fail too — undecided calls there are (near-)zero determinants.
// `window`: every input value is known to lie in the double-double filter's
// window (StaticFilter::dd_window()); Fma: dd_filter_sign's choice of
// two_product (predicates.cpp instantiates it inside a target("fma")
// function on a host with FMA, hence FF_FORCEINLINE).
// `lattice` (with ids; StaticFilter::lattice of the caller's filter): 1 every
// value is known to be a small integer, 2 the binary64 walk's bound is known
// to hold too (lambda_small_int_sorted's `known` and `bounded`); 0 neither.
template <int K, class Id, bool Fma = false>
FF_HD FF_FORCEINLINE int lambda_sign_after_filters(const Id* ids, const double* const* p, const double* w,
                                                   bool window = false, int lattice = 0) {
  if (repeated_id(K, ids)) return 0;
  if constexpr (K <= xp::kIntLambdaMaxK) {
    // Integer lattices (small integers, dyadic grids: the exactly degenerate
    // inputs): det Λ and the perturbation's minors exactly in int64 /
    // __int128 (xp::int_lambda), cheaper than the filters below, which
    // cannot decide a zero determinant. Other inputs fail its test within
    // the first row (random doubles: full mantissas). A call that needs
    // __int128 (full-mantissa doubles that happen to fit, e.g. orient2d of
    // points in [0, 1)) is near-degenerate rather than on a lattice more
    // often than not: the double-double filter, cheaper than 128-bit
    // minors, is tried first there and the integer matrix kept for what it
    // leaves. K = 8 (and 9..11, predicates.cpp lambda_sign_high): only the
    // walk by ranks modulo p, where every minor is below 2^60; the stages
    // below take the rest.
    if (const int s = lambda_small_int_sorted<K>(ids, p, w, ids && lattice >= 1, ids && lattice >= 2); s != 2)
      return s;
    xp::IntScan S;
    if (xp::int_lambda_scan<K>(p, w, S)) {
      if constexpr (K >= 3 && K <= 5) {
        if (S.wide) {
          const int s = dd_filter_sign<K, Fma>(p, w, window);
          if (s == 1 || s == -1) return s;
        }
      }
      const int s = lambda_int_build_sorted<K>(ids, p, w, S);
      if (s != 2) return s;  // (K <= 7 always decides where the build's bound holds)
    }
  }
  // A constant coordinate column (points on a plane x_j = c) or two equal
  // points (exact copies in the input): det Λ = 0 exactly, which no filter
  // decides; the exact stage goes to the perturbation at once
  // (xp::lambda_exact tests both again).
  if (xp::constant_column<K>(p, w ? K - 2 : K - 1)) return ids ? flat_sign_sorted<K>(ids, p, w) : 0;
  if (xp::equal_points<K>(p, w)) return lambda_exact_sorted<K>(ids, p, w, ids != nullptr, true);
  if constexpr (K >= 3 && K <= 5) {
#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
    if constexpr (K >= 4)
      if (ids)
        if (const int s = walk_first_sorted<K>(ids, p, w); s != 2) return s;
#endif
    const int s = dd_filter_sign<K, Fma>(p, w, window);
    if (s == 1 || s == -1) return s;
    if (s == 0) return lambda_exact_sorted<K>(ids, p, w, ids != nullptr, true);
  }
  if constexpr (K >= 6) {
    // 5D and 6D orientations, 4D and 5D power tests: on lattice input (small
    // integers, the exactly degenerate calls) the exact stage evaluates the
    // determinant in plain doubles, exactly (xp::lattice_doubles) — cheaper
    // than the dynamic filter's 2^(K-1) ErrDouble minors, which cannot decide
    // a zero determinant anyway
    double a[K][K];
    if (xp::lattice_doubles<K>(p, w, xp::call_range<K>(p, w), a))
      return lambda_exact_sorted<K>(ids, p, w, ids != nullptr);
    // A lattice with a few points moved by some ulp: when 1..K-3 of the rows
    // are not small integers, the call is near-degenerate in the lattice's
    // way (the static filter decided the calls whose lattice determinant is
    // not 0), which the dynamic filter's ErrDouble minors hardly ever decide
    // (1-3 % of such calls on a 3^5 grid with 20 % of the points moved by
    // 2 ulp); the exact stage, whose Laplace levels run over the integer
    // rows in binary64 (xp::MinorLaplace), is as cheap. Measured on that grid
    // (rtd, compute + certify): 3.78 -> 2.86 s, the grid + 1: 1.68 -> 1.27 s.
    // Six and seven rows first through the double-double filter of
    // dd_filter_sign_wide (2^±100 window, subnormal moved zeros set to 0 with
    // their own bound): such a call's det Λ, when not 0, is of order u times
    // its terms, far above that filter's u^2 (callgrind, the 3^5 grid with
    // 20 % of its points moved by 2 ulp, `rtd` compute + certify on one
    // thread: 103,550 translated expansion determinants of 7 rows, 52,600
    // instructions each, 5.4 of the run's 13.3 G instructions, two thirds of
    // them for a det Λ that is not 0). Undecided (det Λ = 0 or tiny
    // contributions alone): the exact stage, as before.
    const int moved = xp::non_integer_rows<K>(p, w);
    if (moved >= 1 && moved <= K - 3) {
#if !defined(__CUDA_ARCH__)
      // On the host the polynomial stage (near_lattice.hpp) first: exact,
      // det Λ and the perturbation's minors in one pass over int64
      // coefficients. `rtd --dim 5`, compute on one thread, with an earlier
      // version of the stage (no m = 2 branch): behind the double-double
      // filter 0.85 s on the 3^5 grid with 20 % moved by 2 ulp and 0.49 s
      // on the same + 1; in front of it 0.79 s and 0.56 s. With the m = 2
      // branch in front: 0.69 s and 0.46 s (the filter's share of the calls
      // it decides is then below the stage's). The filter and the expansion
      // stages take what this stage refuses (five moved rows, 2^50).
      if (const int s = near_lattice_sorted<K>(ids, p, w); s != 2) return s;
#endif
      if constexpr (K <= 7) {
        const int s = dd_filter_sign<K, Fma>(p, w);
        if (s == 1 || s == -1) return s;
      }
      return lambda_exact_sorted<K>(ids, p, w, ids != nullptr);
    }
  }
#if !defined(__CUDA_ARCH__) && defined(__SIZEOF_INT128__)
  if constexpr (K >= 6) {
    // Six rows and more, off the integer lattice (tensor grids of decimal
    // spacing, np.linspace grids): the calls the static filters leave are
    // mostly exact zeros, on which the dynamic filter's 2^(K-1) ErrDouble
    // minors and the double-double filter are spent for nothing. The walk
    // modulo primes first: where det Λ is not 0 its first prime says so
    // after one elimination, and the filters run as before. `rtd --dim 5`,
    // one thread, 3^5 grid of step 0.1 (perf): minor_levels<6, 6, ErrDouble>
    // was 21 % of the run, the double-double filter 5 %.
    if (ids) {
      if (const int s = walk_first_sorted<K>(ids, p, w); s != 2) return s;
    } else if (xp::det_zero_by_walk<K>(p, w)) {
      return 0;  // (the exact sign: the projections of flat_sign_sorted)
    }
  }
#endif
  if (const int s = lambda_sign_filter<K>(p, w)) return s;
  return lambda_exact_sorted<K>(ids, p, w, ids != nullptr);
}

#if !defined(__CUDACC__) && !defined(THRUST_DEVICE_SYSTEM)
// Host builds: lambda_sign_after_filters<K> for PointId rows, K = 2..8, out
// of line in predicates.cpp (after_filters_any: its FMA instantiation where
// the host has FMA, the same signs), compiled once there instead of in every
// translation unit that calls lambda_sign_staged. The kernels' thrust/OpenMP
// build (THRUST_DEVICE_SYSTEM) keeps the device's inline path, so that it
// runs the code the GPU runs.
template <int K>
int lambda_sign_after_filters_host(const PointId* ids, const double* const* p, const double* w, bool window,
                                   int lattice);
#endif

// lambda_sign_staged's call of the stages after the filters: out of line on
// the host for PointId rows (above), inline otherwise (the device, other ids).
template <int K, class Id>
FF_HD FF_FORCEINLINE int after_filters_call(const Id* ids, const double* const* p, const double* w, bool window,
                                            int lattice) {
#if !defined(__CUDACC__) && !defined(THRUST_DEVICE_SYSTEM)
  if constexpr (std::is_same_v<Id, PointId>) return lambda_sign_after_filters_host<K>(ids, p, w, window, lattice);
#endif
  return lambda_sign_after_filters<K>(ids, p, w, window, lattice);
}

// The whole default path for K points. `f` may be null (no static filter);
// `ids` may be null (exact sign, may be 0).
template <int K, class Id>
FF_HD inline int lambda_sign_staged(const StaticFilter* f, const Id* ids, const double* const* p,
                                    const double* w) {
  if constexpr (K > kMaxStagedK) {
    // 9..11 rows (hulls beyond 7D, triangulations beyond 6D): host only
    static_assert(K <= kMaxLambdaK, "lambda_sign_staged: at most kMaxLambdaK rows");
    if (!ids) return lambda_sign_high(f, K, nullptr, p, w);
    PointId id[K];
    for (int i = 0; i < K; ++i) id[i] = static_cast<PointId>(ids[i]);
    return lambda_sign_high(f, K, id, p, w);
  } else {
    if (repeated_id(K, ids)) return 0;
    const int lattice = f && ids ? f->lattice(K, w != nullptr) : 0;
    if constexpr (K >= kLatticeFirstK)
      if (lattice >= 1)
        if (const int s = lambda_small_int_sorted<K>(ids, p, w, true, lattice >= 2); s != 2) return s;
    if constexpr (K == 3 || K == 4) {
      // orient2d, orient3d: the static and the permanent filter in one
      // evaluation (static_filter.hpp, plain_filters)
      if (f && !w) {
        if (const int s = plain_filters<K>(*f, p)) return s;
        return after_filters_call<K>(ids, p, w, f->dd_window(), lattice);
      }
    }
    if (const int s = static_semi_static_sign<K>(f, p, w)) return s;
    return after_filters_call<K>(ids, p, w, f && f->dd_window(), lattice);
  }
}

// Calls f(std::integral_constant<int, K>{}) for the run-time k, 2 <= k <= 8
// (8 for anything larger: callers check k first). Host code: the templates
// above take K at compile time.
template <class F>
inline auto with_k(int k, F&& f) {
  switch (k) {
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
    case 4: return f(std::integral_constant<int, 4>{});
    case 5: return f(std::integral_constant<int, 5>{});
    case 6: return f(std::integral_constant<int, 6>{});
    case 7: return f(std::integral_constant<int, 7>{});
    default: return f(std::integral_constant<int, 8>{});
  }
}

// Host builds: the exact stages above (4-5 and the integer lattice's, the
// bulk of the code a K instantiates) are compiled once, for PointId rows and
// K = 2..8, at the end of predicates/predicates.cpp; every other host
// translation unit calls them there (explicit instantiation declarations:
// none of these templates is inline). nvcc instantiates them where they are
// used, as before.
#define FF_STAGED_EXACT(EXT, K)                                                                             \
  EXT template int flat_sign_sorted<K, PointId>(const PointId*, const double* const*, const double*);         \
  EXT template int lambda_exact_sorted<K, PointId>(const PointId*, const double* const*, const double*, bool, \
                                                   bool);                                                     \
  EXT template int lambda_small_int_sorted<K, PointId>(const PointId*, const double* const*, const double*, bool,   \
                                                       bool);                                                     \
  EXT template int lambda_int_build_sorted<K, PointId>(const PointId*, const double* const*, const double*,   \
                                                       const xp::IntScan&);
// EXT = extern: the declarations; empty: the definitions (predicates.cpp)
#define FF_STAGED_EXACT_ALL(EXT)                                                                         \
  FF_STAGED_EXACT(EXT, 2)                                                                                \
  FF_STAGED_EXACT(EXT, 3)                                                                                \
  FF_STAGED_EXACT(EXT, 4)                                                                                \
  FF_STAGED_EXACT(EXT, 5)                                                                                \
  FF_STAGED_EXACT(EXT, 6)                                                                                \
  FF_STAGED_EXACT(EXT, 7)                                                                                \
  FF_STAGED_EXACT(EXT, 8)
#if !defined(__CUDACC__) && !defined(FLIPFLOP_STAGED_INSTANTIATE)
FF_STAGED_EXACT_ALL(extern)
#endif

}  // namespace flipflop::pred

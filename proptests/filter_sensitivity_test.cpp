// filter_sensitivity_test.cpp — deterministic sensitivity of the filters'
// error bounds (issue 38, item 5): for each bound, a targeted input set at the
// bound's edge, found by a deterministic search (fixed seed, printed), on
// which
//   (1) the true bound never answers a wrong sign (checked against GMP on
//       every input of the set where the filter decides), and
//   (2) the bound divided by a documented factor F answers a wrong sign on at
//       least one input of the set — on every run, since the set is the same.
// F is the tightest power of two the search reaches (measured; the table
// kCaught below). Where F > 2, either the bound is loose by construction
// (argued at kCaught for orient2d's static and semi-static bounds, and why
// the static bounds loosen with k) or this search does not come closer: the
// printed "max |det|/bound among wrong signs" is the measured ratio (a wrong
// sign at ratio r means a bound weakened by any factor > 1/r errs).
//
// Bounds, each with its soundness tests elsewhere:
//   static      StaticFilter (static_filter.hpp (1)-(4)), k = 3..8 plain and
//               lifted; weakened through StaticFilter::scaled_for_testing,
//               the filter itself answering (stage::static_filter). Soundness:
//               predicates_stages_test (a), (e) and its 2^-20 search.
//   semi-static semi_static_sign, k = 3..8 plain and lifted: bound
//               bound_constant(N) Π_c m_c of this call (filter_detail, the
//               library's own functions); that the recomputed bound decides
//               exactly where stage::semi_static does is asserted on every
//               input. Soundness: predicates_stages_test (a), window edges.
//   permanent   plain_filters' per-call bound (static_filter.hpp (6),
//               Shewchuk's errbound A), orient2d and orient3d: C per + 2^-1073
//               recomputed here (the permanent as plain_filters computes it);
//               agreement with plain_filters (static part disabled by a
//               huge but finite StaticFilter bound) asserted on every input.
//   dynamic     the ErrDouble running bound (err_double.hpp, lambda_filter.hpp
//               lambda_sign_filter), k = 3..8 plain and lifted: the ErrDouble
//               determinant recomputed from its entries (det_by_minors, the
//               library's); agreement with stage::dynamic asserted.
//   kernel point  RationalKernel::side()'s per-input bound (reference/hull3/
//               rational_kernel.cpp: (bound(4) + 8 M^2 Σ e_j)(1 + 2^-40)),
//               read from the kernel (RationalKernel::static_bound); side()
//               itself (the true bound, then the exact mixed predicate) is checked
//               against GMP with SoS on every input. Soundness:
//               ffhull_reference_test "the kernel point's static bound ...".
//   dd a-priori  dd_filter_sign<K, false> (dd_filter.hpp), k = 3..5 plain and
//               lifted: (β u^2 per + |l| + 2^-1072)(1 + 2^-40), recomputed
//               with the library's DDv, Mag, det_small, dd_beta; agreement
//               with dd_filter_sign asserted. Soundness: stages (b'').
//   dd running  xp::lambda_sign_dd<K> (err_dd.hpp's ErrDD running bound),
//               k = 3..5: (e + |l|)(1 + 2^-40); agreement asserted.
//               Soundness: stages (b'') (a running bound weakened 4x was
//               caught there on an exactly degenerate 50-bit family).
//   plane form  PlaneForm<D>::sign (plane_form.hpp), D = k - 1 = 2..7:
//               orient_d of a fixed D-tuple (rows 0..D-1) and x (the last
//               row) as a dot product, Σ w_j |a_j| (1 + 2^-40) + D 2^-1072,
//               recomputed from the form's public n, w, base; agreement
//               with sign() asserted. Soundness: predicates_stages_test
//               "PlaneForm" (D = 2..9, random, near- and exactly degenerate).
//   dd wide     dd_filter_sign_wide<K, false> (dd_filter.hpp), k = 6, 7 plain
//               and lifted: (c per + |l| + 2^-1072 + tail)(1 + 2^-40), the
//               parts the filter reports (DdWideParts); "weakened" divides c
//               per. Starting sets add its own inputs, lattices with values
//               moved by 1-4 ulp (families 4, 5). Soundness: stages "the
//               double-double filter of 6 and 7 rows" (with the tiny values'
//               bound left out, falsified there).
// Not covered here (no targeted set yet): mixed_semi_static_sign (5) (the
// kernel point's per-call filter of predicates.cpp), the adaptive stages' bounds (xp::orient_adaptive,
// xp::lifted_adaptive) and the kernels' device copies
// (kernels_cuda/static_filter.cuh), which share the headers' formulas.
//
// The search. Per bound and shape: starting inputs from four families —
// (0) near-degenerate: the last point an affine combination of the others
// computed in doubles (lifted: weights putting the lifted points near a
// hyperplane, computed in doubles), then ulp nudges; (1) "corners": every
// point but the last near +M s, the last near -M s (s a sign vector, M just
// above a power of two), so every difference is near 2M, the magnitude the
// static bound charges, and T is nearly of rank one; (2) the same with the
// last coordinate column a copy of the first plus a constant (exactly
// degenerate where that sum is exact); (3) corners at 2^e plus a few
// thousand ulps (differences just above 2^(e+1), rounding by up to u 2M) —
// then hill climbing by ulp moves of one or two coordinates or weights,
// keeping a move when it does not lower (|a| - fixed - 2 max(0, sgn(a) x)) /
// bound (a the filter's double value, fixed the threshold's part that is not
// the error bound (|l| of the double-double filters, else 0), x det Λ in
// long double: an estimate for the climb only, every wrong sign is decided
// by GMP, stage::gmp / mixed_sign).
// The score is a ratio to the bound, so the climb visits the same inputs
// whatever constant factor the bound has: a library bound weakened by the
// factor of kCaught errs on the set's best input and fails "true bound
// wrong == 0". splitmix64 from kSeed; no std:: distribution (their output
// is implementation-defined); binary64 and x87 long double arithmetic give the
// same values at -O0 and -O3 on x86-64, so the set is the same in every build.
// The double-double bounds' climb estimates det Λ in binary128 (GCC's
// __float128: x86-64).
// The factors reached: kCaught below (2x: orient2d's permanent, static and
// semi-static bounds, the ErrDouble bounds of orient2d, orient3d, power1d and
// power2d, PlaneForm's for D = 2, 3; 4-64x for most bounds at k = 3, 4; up to 2^20
// for the static bound at k = 8), with the kept inputs (kKept) of longer runs.
// Cost: 24 restarts x 4000 steps per bound and shape: about 26 s in Release
// (one core) for the nine test cases, 0.3-6 s each; tagged [long] (not in
// the sanitizer builds: a smaller budget there would change the set, and the
// sets' sensitivity is a property of the arithmetic, not of memory use).
// Longer runs with other seeds: fuzz/filter_sensitivity.sh (Params below:
// soundness on every set, and each input that comes closer to a bound's
// edge than the fixed set printed, to be added to it).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "predicates/dd_filter.hpp"
#include "predicates/err_dd.hpp"
#include "predicates/exact_expansion.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/plane_form.hpp"
#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "predicates/staged.hpp"
#include "predicates/static_filter.hpp"
#include "proptests/support/predicate_inputs.hpp"  // set_last_row_affine
#include "reference/hull3/rational_kernel.hpp"
#include "reference/point_set.hpp"

namespace pred = flipflop::pred;
namespace fd = flipflop::pred::filter_detail;
namespace stage = flipflop::pred::stage;
using pred::ErrDouble;
using pred::StaticFilter;

namespace {

constexpr std::uint64_t kSeed = 0x38f5e7u;  // printed by every test case
constexpr int kRestarts = 24, kSteps = 4000;

// The run's search parameters: kSeed, kRestarts and kSteps (the fixed sets
// of CI and of kCaught), or, for the longer runs with other seeds of
// fuzz/filter_sensitivity.sh, the environment's FLIPFLOP_SENSITIVITY_SEED
// (a number, or "random": drawn from std::random_device and printed),
// FLIPFLOP_SENSITIVITY_RESTARTS and FLIPFLOP_SENSITIVITY_STEPS. Soundness
// (the true bound never wrong, the recomputed rule the library's) is asserted
// on every run; "weakened by F caught" only on the fixed sets, whose
// factors kCaught lists (another set may come less close to the edge, or
// closer: then it prints "closer than the fixed set", an input to keep).
struct Params {
  std::uint64_t seed = kSeed;
  int restarts = kRestarts, steps = kSteps;
  bool fixed() const { return seed == kSeed && restarts == kRestarts && steps == kSteps; }
};
const Params& params() {
  static const Params p = [] {
    Params q;
    auto positive = [](const char* name, int fallback) {
      const char* v = std::getenv(name);
      if (v == nullptr || *v == 0) return fallback;
      const long x = std::strtol(v, nullptr, 10);
      if (x <= 0 || x > 1000000) throw std::invalid_argument(std::string(name) + ": a count in 1..1000000");
      return static_cast<int>(x);
    };
    if (const char* v = std::getenv("FLIPFLOP_SENSITIVITY_SEED"); v != nullptr && *v != 0) {
      if (std::string(v) == "random") {
        std::random_device rd;
        q.seed = (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
      } else {
        q.seed = std::strtoull(v, nullptr, 0);
      }
    }
    q.restarts = positive("FLIPFLOP_SENSITIVITY_RESTARTS", kRestarts);
    q.steps = positive("FLIPFLOP_SENSITIVITY_STEPS", kSteps);
    return q;
  }();
  return p;
}

struct Rng {  // splitmix64
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)
  double sym() { return 2.0 * unit() - 1.0; }                              // [-1, 1)
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
};

double ulps(double v, int n) {
  for (int i = 0; i < std::abs(n); ++i) v = std::nextafter(v, n > 0 ? HUGE_VAL : -HUGE_VAL);
  return v;
}

// k points of nc coordinates (k - 1 plain, k - 2 lifted) and weights.
struct Input {
  int k = 3;
  bool lifted = false;
  int nc = 2;
  std::vector<double> x, w;
  const double* p(int i) const { return x.data() + i * nc; }
  double* p(int i) { return x.data() + i * nc; }
  void rows(const double** out) const {
    for (int i = 0; i < k; ++i) out[i] = p(i);
  }
  const double* wp() const { return lifted ? w.data() : nullptr; }
  // the rows in hexadecimal floating point (exact), weights after '|'
  std::string text() const {
    std::string t;
    char buf[40];
    for (int i = 0; i < k; ++i) {
      t += i ? "; " : "";
      for (int j = 0; j < nc; ++j) std::snprintf(buf, sizeof buf, j ? " %a" : "%a", p(i)[j]), t += buf;
      if (lifted) std::snprintf(buf, sizeof buf, " | %a", w[static_cast<std::size_t>(i)]), t += buf;
    }
    return t;
  }
};

Input empty(int k, bool lifted) {
  Input in;
  in.k = k;
  in.lifted = lifted;
  in.nc = lifted ? k - 2 : k - 1;
  in.x.assign(static_cast<std::size_t>(k * in.nc), 0.0);
  in.w.assign(static_cast<std::size_t>(k), 0.0);
  return in;
}

enum class Bound { static_bound, semi_static, permanent, dynamic, dd_apriori, dd_running, plane_form, dd_wide };
const char* name_of(Bound b) {
  switch (b) {
    case Bound::static_bound: return "static";
    case Bound::semi_static: return "semi-static";
    case Bound::permanent: return "permanent";
    case Bound::dd_apriori: return "dd a-priori";
    case Bound::dd_running: return "dd running";
    case Bound::plane_form: return "plane form";
    case Bound::dd_wide: return "dd wide";
    default: return "dynamic";
  }
}

// The filter's double value a of det Λ and its threshold (it answers sgn a
// iff |a| > bound; +inf: it cannot decide), and what the library's filter
// answered on the input (asserted equal to that rule).
// The double-double filters answer sgn h iff |h| > threshold = (bound' +
// |l| + ...)(1 + 2^-40): there `bound` is the error bound's part (times 1 +
// 2^-40), `fixed` the rest, and "weakened by F" divides `bound` only.
struct Eval {
  double a = 0.0, bound = HUGE_VAL;
  double fixed = 0.0;
  double threshold = -1.0;  // the library's comparison value where it is not bound + fixed
  int library = 0;
};

template <int K>
Eval evaluate(const Input& in, Bound b) {
  constexpr int N = K - 1;
  const double* p[K];
  in.rows(p);
  const double* w = in.wp();
  Eval e;
  if (b == Bound::plane_form) {
    // PlaneForm<D> of rows 0..D-1 (D = K - 1) and x = the last row: s =
    // Σ n_j a_j, a_j = fl(x_j - t0_j), against Σ w_j |a_j| (1 + 2^-40) + D
    // 2^-1072, as PlaneForm::sign computes them (plane_form.hpp); "weakened"
    // divides Σ w_j |a_j| (1 + 2^-40)
    if constexpr (K >= 3) {
      constexpr int D = K - 1;
      const pred::PlaneForm<D> f(p);
      const double* x = p[K - 1];
      double sum = 0.0, wsum = 0.0;
      for (int j = 0; j < D; ++j) {
        const double a = x[j] - f.base[j];
        sum += f.n[j] * a;
        wsum += f.w[j] * std::fabs(a);
      }
      e.a = sum;
      e.bound = std::fabs(sum) <= 0x1.fffffffffffffp+1023 ? wsum * (1.0 + 0x1p-40) : HUGE_VAL;
      e.fixed = D * 0x1p-1072;
      e.library = f.sign(x);
    }
    return e;
  }
  if (b == Bound::dynamic) {
    // lambda_sign_filter's entries, then det_by_minors (lambda_filter.hpp)
    ErrDouble t[N * N];
    const double* base = p[K - 1];
    for (int i = 0; i < N; ++i) {
      if (!w) {
        for (int j = 0; j < N; ++j) t[i * N + j] = ErrDouble(p[i][j]) - ErrDouble(base[j]);
      } else {
        ErrDouble lift(0.0);
        for (int j = 0; j < N - 1; ++j) {
          const ErrDouble d = ErrDouble(p[i][j]) - ErrDouble(base[j]);
          t[i * N + j] = d;
          lift = (j == 0) ? d * d : lift + d * d;
        }
        t[i * N + N - 1] = lift - (ErrDouble(w[i]) - ErrDouble(w[K - 1]));
      }
    }
    const ErrDouble r = pred::det_by_minors<N>(t);
    e.a = r.v;
    e.bound = r.e * (1.0 + 0x1p-40);
    e.library = stage::dynamic(K, p, w);
    return e;
  }
  if (b == Bound::dd_wide) {
    // dd_filter_sign_wide<K, false> (k = 6, 7) reports what it compared
    // (DdWideParts): the sign parity x sgn h beyond (c per + |l| + 2^-1072 +
    // tail)(1 + 2^-40); "weakened" divides the c per part (the a-priori
    // bound), |l|, 2^-1072 and the tiny values' bound tail are `fixed`
    if constexpr (K == 6 || K == 7) {
      pred::DdWideParts parts;
      e.library = pred::dd_filter_sign_wide<K, false>(p, w, &parts);
      if (e.library == 2) return e;  // outside the window: no bound
      e.a = parts.parity * parts.h;
      e.threshold = (parts.c_per + std::fabs(parts.l) + 0x1p-1072 + parts.tail) * (1.0 + 0x1p-40);
      e.bound = parts.c_per * (1.0 + 0x1p-40);
      e.fixed = (std::fabs(parts.l) + 0x1p-1072 + parts.tail) * (1.0 + 0x1p-40);
    }
    return e;
  }
  if (b == Bound::dd_apriori || b == Bound::dd_running) {
    if constexpr (K >= 3 && K <= 5) {
      if (b == Bound::dd_apriori) {
        // dd_filter_sign<K, false>'s entries, magnitudes and threshold
        using V = pred::DDv<false>;
        V t[N * N];
        pred::Mag m[N * N];
        pred::dd_filter_entries<K, false>(p, w, t, m);
        const double c = pred::dd_beta(N, w != nullptr) * 0x1p-106;
        const double per = pred::det_small<N, pred::Mag>(m).v;
        const V det = pred::det_small<N, V>(t);
        e.a = det.h;
        e.threshold = (c * per + std::fabs(det.l) + 0x1p-1072) * (1.0 + 0x1p-40);
        e.bound = c * per * (1.0 + 0x1p-40);
        e.fixed = (std::fabs(det.l) + 0x1p-1072) * (1.0 + 0x1p-40);
        e.library = pred::dd_filter_sign<K, false>(p, w);
        if (e.library == 2) e.bound = HUGE_VAL;  // outside the window
      } else {
        // xp::lambda_sign_dd<K>'s entries and running bound (err_dd.hpp)
        pred::ErrDD t[N * N];
        const int ncoord = w ? N - 1 : N;
        for (int i = 0; i < N; ++i) {
          for (int j = 0; j < ncoord; ++j) t[i * N + j] = pred::ErrDD::difference(p[i][j], p[K - 1][j]);
          if (w) {
            pred::ErrDD lift = -pred::ErrDD::difference(w[i], w[K - 1]);
            for (int j = 0; j < ncoord; ++j) lift = lift + t[i * N + j] * t[i * N + j];
            t[i * N + N - 1] = lift;
          }
        }
        const pred::ErrDD det = pred::det_by_minors<N, pred::ErrDD>(t);
        e.a = det.h;
        e.threshold = (det.e + std::fabs(det.l)) * (1.0 + 0x1p-40);
        e.bound = det.e * (1.0 + 0x1p-40);
        e.fixed = std::fabs(det.l) * (1.0 + 0x1p-40);
        const int s = pred::xp::lambda_sign_dd<K>(p, w);
        e.library = s == 2 ? 0 : s;
      }
    }
    return e;
  }
  double t[N * N], mag[N];
  fd::differences<K>(p, w, t, mag);
  e.a = fd::det_plain<N>(t);
  if (b == Bound::static_bound) {
    const StaticFilter f = StaticFilter::for_points(in.x.data(), static_cast<std::size_t>(K), in.nc, w);
    e.bound = f.bound(K, w != nullptr);
    e.library = stage::static_filter(f, K, p, w);
  } else if (b == Bound::semi_static) {
    constexpr int B = fd::window_exponent(N);
    double prod = fd::bound_constant(N, w != nullptr);
    for (int c = 0; c < N; ++c) {
      if (!(mag[c] >= fd::pow2i(-B) && mag[c] <= fd::pow2i(B))) prod = HUGE_VAL;
      prod *= mag[c];
    }
    e.bound = prod;
    e.library = stage::semi_static(K, p, w);
  } else {  // permanent: plain_filters, K = 3, 4
    if constexpr (K == 3 || K == 4) {
      double per = 0.0;
      double a[9];
      for (int i = 0; i < N * N; ++i) a[i] = std::fabs(t[i]);
      if constexpr (N == 2) per = a[0] * a[3] + a[1] * a[2];
      else
        per = (a[6] * (a[1] * a[5] + a[2] * a[4]) + a[7] * (a[0] * a[5] + a[2] * a[3])) +
              a[8] * (a[0] * a[4] + a[1] * a[3]);
      e.bound = fd::permanent_constant(N) * per + 0x1p-1073;
      // the static part disabled: a finite bound no determinant exceeds
      StaticFilter f = StaticFilter::for_points(in.x.data(), static_cast<std::size_t>(K), in.nc, nullptr);
      if (!(f.bound(K, false) < HUGE_VAL)) {
        e.bound = HUGE_VAL;  // plain_filters then uses the semi-static filter
        e.library = 0;
      } else {
        f = f.scaled_for_testing(0x1p300);
        if (f.bound(K, false) < HUGE_VAL) e.library = pred::plain_filters<K>(f, p);
        else e.bound = HUGE_VAL, e.library = 0;
      }
    }
  }
  return e;
}

Eval evaluate(const Input& in, Bound b) {
  return pred::with_k(in.k, [&](auto K) { return evaluate<decltype(K)::value>(in, b); });
}

// det Λ (= det T of the exact differences, the lifted column Σ d^2 - Δw) in
// long double, Gaussian elimination with partial pivoting: the climb's
// estimate of the exact value.
long double approx_exact(const Input& in) {
  const int N = in.k - 1;
  long double m[8][8];
  const double* base = in.p(N);
  for (int i = 0; i < N; ++i) {
    long double lift = 0.0L;
    for (int j = 0; j < in.nc; ++j) {
      const long double d = static_cast<long double>(in.p(i)[j]) - base[j];
      m[i][j] = d;
      lift += d * d;
    }
    if (in.lifted) m[i][N - 1] = lift - (static_cast<long double>(in.w[i]) - in.w[N]);
  }
  long double det = 1.0L;
  for (int c = 0; c < N; ++c) {
    int piv = c;
    for (int r = c + 1; r < N; ++r)
      if (std::fabs(m[r][c]) > std::fabs(m[piv][c])) piv = r;
    if (m[piv][c] == 0.0L) return 0.0L;
    if (piv != c) {
      for (int j = 0; j < N; ++j) std::swap(m[piv][j], m[c][j]);
      det = -det;
    }
    det *= m[c][c];
    for (int r = c + 1; r < N; ++r) {
      const long double f = m[r][c] / m[c][c];
      for (int j = c; j < N; ++j) m[r][j] -= f * m[c][j];
    }
  }
  return det;
}

// The same in binary128 (GCC's __float128, software): for the double-double
// filters, whose errors are of order u^2 times the terms.
__float128 approx_exact_q(const Input& in) {
  const int N = in.k - 1;
  __float128 m[8][8];
  const double* base = in.p(N);
  for (int i = 0; i < N; ++i) {
    __float128 lift = 0;
    for (int j = 0; j < in.nc; ++j) {
      const __float128 d = static_cast<__float128>(in.p(i)[j]) - base[j];
      m[i][j] = d;
      lift += d * d;
    }
    if (in.lifted) m[i][N - 1] = lift - (static_cast<__float128>(in.w[i]) - in.w[N]);
  }
  __float128 det = 1;
  for (int c = 0; c < N; ++c) {
    int piv = c;
    auto mag = [](__float128 v) { return v < 0 ? -v : v; };
    for (int r = c + 1; r < N; ++r)
      if (mag(m[r][c]) > mag(m[piv][c])) piv = r;
    if (m[piv][c] == 0) return 0;
    if (piv != c) {
      for (int j = 0; j < N; ++j) std::swap(m[piv][j], m[c][j]);
      det = -det;
    }
    det *= m[c][c];
    for (int r = c + 1; r < N; ++r) {
      const __float128 f = m[r][c] / m[c][c];
      for (int j = c; j < N; ++j) m[r][j] -= f * m[c][j];
    }
  }
  return det;
}

int sgn(double v) { return (v > 0) - (v < 0); }

struct Search {
  long evaluated = 0, decided = 0, gmp_calls = 0;
  long wrong_true = 0;           // the true bound answered a wrong sign (must stay 0)
  long library_mismatch = 0;     // recomputed rule != the library's answer (must stay 0)
  double best_wrong = 0.0;       // max |a| / bound over inputs where sgn a != the exact sign
  Input best;                    // that input
  std::string mismatch_example;
};

// Records one input: the true filter's answer against GMP, the recomputed rule
// against the library, and a wrong sign's ratio. Returns the climb score.
double record(const Input& in, Bound b, Search& s) {
  const Eval e = evaluate(in, b);
  ++s.evaluated;
  if (!std::isfinite(e.bound) || !std::isfinite(e.a) || e.bound <= 0.0) return -HUGE_VAL;
  const int rule = fd::sign_beyond(e.a, e.threshold >= 0.0 ? e.threshold : e.bound + e.fixed);
  if (rule != e.library) {
    if (s.library_mismatch++ == 0)
      s.mismatch_example = std::string(name_of(b)) + " k=" + std::to_string(in.k) + ": rule " +
                           std::to_string(rule) + ", library " + std::to_string(e.library);
  }
  const double ratio = (std::fabs(e.a) - e.fixed) / e.bound;  // wrong sign: a bound / F errs iff F ratio > 1
  double score;
  if (b == Bound::dd_apriori || b == Bound::dd_running || b == Bound::dd_wide) {
    // the double-double value's error is of order u^2 times the terms:
    // the estimate in binary128 (113 bits), a + l against it
    const __float128 x = approx_exact_q(in);
    const __float128 same = sgn(e.a) * x;
    score = static_cast<double>((static_cast<__float128>(std::fabs(e.a)) - e.fixed -
                                 2 * (same > 0 ? same : static_cast<__float128>(0))) / e.bound);
  } else {
    const long double x = approx_exact(in);
    const long double same = sgn(e.a) * x;  // > 0: x has a's sign
    score = static_cast<double>((std::fabs(static_cast<long double>(e.a)) - 2.0L * std::max(0.0L, same)) /
                                e.bound);
  }
  const bool candidate = e.a != 0.0 && score > 0.0 && ratio > 0x1p-30;
  if (rule != 0 || candidate) {
    const double* p[8];
    in.rows(p);
    const int g = stage::gmp(in.k, p, in.wp());
    ++s.gmp_calls;
    if (rule != 0) {
      ++s.decided;
      if (rule != g) ++s.wrong_true;
    }
    if (e.a != 0.0 && sgn(e.a) != g && ratio > 0.0 && ratio > s.best_wrong) {
      s.best_wrong = ratio;
      s.best = in;
    }
  }
  return score;
}

// Starting inputs.
Input start(int k, bool lifted, int family, Rng& r) {
  Input in = empty(k, lifted);
  const int nc = in.nc;
  if (family >= 4) {
    // (the 6- and 7-row double-double filter's own inputs) a lattice with
    // some values moved: coordinates in {0, 1, 2} (family 5: {1, 2, 3}, no
    // moved zeros), a third of them moved by 1-4 ulp (a moved 0 is a
    // subnormal, set to 0 by the filter with its own bound); lifted: weights
    // in {0, 1, 2}, moved alike
    auto value = [&] {
      double v = static_cast<double>(r.below(3) + (family == 5 ? 1 : 0));
      if (r.below(3) == 0) v = ulps(v, (r.next() & 1 ? 1 : -1) * (1 + r.below(4)));
      return v;
    };
    for (double& v : in.x) v = value();
    if (lifted)
      for (double& v : in.w) v = value();
    return in;
  }
  const int e = r.below(41) - 20;
  const double M = std::ldexp(1.0 + 0x1p-20 * r.unit(), e);  // just above 2^e
  if (family == 0) {
    for (double& v : in.x) v = M * r.sym();
    if (!lifted) flipflop::test::set_last_row_affine(in.x.data(), k, nc, [&] { return r.sym(); });
  } else {
    // corners: rows 0..k-2 near M s, the last near -M s; T nearly of rank
    // one. Family 3: M = 2^e exactly and every magnitude 2^e plus a few
    // thousand ulps (the differences just above 2^(e+1) round by up to
    // u 2^(e+1) = u 2M, the most the static bound allows an entry)
    const double spread = std::ldexp(1.0, -53 / std::max(1, k - 2) - r.below(4));
    double s[8];
    for (int j = 0; j < nc; ++j) s[j] = (r.next() & 1) ? 1.0 : -1.0;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < nc; ++j) {
        const double mag = family == 3 ? std::ldexp(1.0 + std::ldexp(static_cast<double>(r.below(4096)), -52), e)
                                       : M * (1.0 - spread * r.unit());
        in.p(i)[j] = (i == k - 1 ? -s[j] : s[j]) * mag;
      }
    if (family == 2 && nc >= 2) {
      // the last column = the first + c, exactly where the sum is exact
      const double c = std::ldexp(std::floor(r.unit() * 8.0), e - 4);
      for (int i = 0; i < k; ++i) in.p(i)[nc - 1] = in.p(i)[0] + c;
    }
  }
  if (lifted) {
    // weights putting the lifted points near the hyperplane h = α.x + β
    double alpha[8];
    for (int j = 0; j < nc; ++j) alpha[j] = M * r.sym();
    const double beta = M * M * r.sym();
    for (int i = 0; i < k; ++i) {
      double v = -beta;
      for (int j = 0; j < nc; ++j) v += in.p(i)[j] * (in.p(i)[j] - alpha[j]);
      in.w[static_cast<std::size_t>(i)] = v;
    }
  }
  for (double& v : in.x)
    if (r.below(3) == 0) v = ulps(v, r.below(5) - 2);
  return in;
}

void mutate(Input& in, Rng& r) {
  const int nx = static_cast<int>(in.x.size()), nv = nx + (in.lifted ? in.k : 0);
  const int i = r.below(nv);
  double& v = i < nx ? in.x[static_cast<std::size_t>(i)] : in.w[static_cast<std::size_t>(i - nx)];
  const int kind = r.below(4);
  if (kind < 3) v = ulps(v, (r.next() & 1 ? 1 : -1) * (1 + r.below(kind == 0 ? 64 : 4)));
  else v = v * (1.0 + std::ldexp(r.sym(), -10 - r.below(40)));
}

// Inputs kept from longer runs with other seeds (fuzz/filter_sensitivity.sh:
// "closer than the fixed set", the seed in the comment): each is recorded in
// its bound's set after the search, on every run, so the fixed set's factor
// (kCaught) is the closest any run has come. The rows in hexadecimal
// floating point, weights after '|' (Input::text).
struct KeptInput {
  Bound b;
  int k;
  bool lifted;
  const char* text;
};
const KeptInput kKept[] = {
#include "proptests/filter_sensitivity_kept.inc"
};

Input parse_input(int k, bool lifted, const char* text) {
  Input in = empty(k, lifted);
  const char* c = text;
  auto number = [&] {
    char* end = nullptr;
    const double v = std::strtod(c, &end);
    if (end == c) throw std::invalid_argument(std::string("kKept: not a number at '") + c + "'");
    c = end;
    return v;
  };
  auto expect = [&](char want) {
    while (*c == ' ') ++c;
    if (*c != want) throw std::invalid_argument(std::string("kKept: '") + want + "' expected at '" + c + "'");
    ++c;
  };
  for (int i = 0; i < k; ++i) {
    if (i) expect(';');
    for (int j = 0; j < in.nc; ++j) in.p(i)[j] = number();
    if (lifted) expect('|'), in.w[static_cast<std::size_t>(i)] = number();
  }
  while (*c == ' ') ++c;
  if (*c != 0) throw std::invalid_argument(std::string("kKept: trailing text '") + c + "'");
  return in;
}

Search search(int k, bool lifted, Bound b, int restarts, int steps) {
  Search s;
  Rng r{params().seed ^ (static_cast<std::uint64_t>(k) << 8) ^ (lifted ? 0x80u : 0u) ^
        (static_cast<std::uint64_t>(b) << 16)};
  for (int rs = 0; rs < restarts; ++rs) {
    Input cur = start(k, lifted, b == Bound::dd_wide ? rs % 6 : rs % 4, r);
    double cs = record(cur, b, s);
    for (int it = 0; it < steps; ++it) {
      Input nxt = cur;
      mutate(nxt, r);
      if (r.below(4) == 0) mutate(nxt, r);
      const double ns = record(nxt, b, s);
      if (ns >= cs) {
        cur = nxt;
        cs = ns;
      }
    }
  }
  for (const KeptInput& e : kKept)
    if (e.b == b && e.k == k && e.lifted == lifted) {
      const Input in = parse_input(k, lifted, e.text);
      REQUIRE(in.text() == e.text);  // read back exactly
      record(in, b, s);
    }
  return s;
}

// ---- the kernel point's bound (RationalKernel::side) ---------------------------------
// Seven points: 0..3 the sources of the centroid kernel s (near alternate
// corners of [-M, M]^3, so the query differences reach 2M as the bound
// assumes, and the centroid's sum rounds), 4 = a, 5 = b, 6 = c, c near the
// reflection 2q - a (the plane (a, b, c) passes within ulps of s). The climb
// moves any coordinate by ulps.
struct KernelSearch {
  long evaluated = 0, decided = 0, side_wrong = 0;
  double best_wrong = 0.0;
  std::vector<double> best;
};

struct KernelEval {
  double a = 0.0, bound = HUGE_VAL, score = -HUGE_VAL;
};

KernelEval kernel_eval(const std::vector<double>& coords, KernelSearch& ks) {
  namespace ref = flipflop::ref;
  KernelEval out;
  flipflop::PointSet ps;
  ps.dim = 3;
  ps.coords = flipflop::Values(coords);
  const double* src[4] = {ps.point(0), ps.point(1), ps.point(2), ps.point(3)};
  const pred::RationalPoint sp = pred::RationalPoint::centroid(src, 4, 3);
  const ref::RationalKernel kern(ps, sp);
  ++ks.evaluated;
  // the bound side() uses (rational_kernel.cpp: (bound(4) + U)(1 + 2^-40))
  double q[3];
  for (int j = 0; j < 3; ++j) q[j] = sp.approx[j].v;
  if (!std::isfinite(kern.static_bound())) return out;
  out.bound = kern.static_bound();
  const double* p[4] = {ps.point(4), ps.point(5), ps.point(6), q};
  double t[9];
  fd::differences<4, false>(p, nullptr, t, nullptr);
  out.a = fd::det_plain<3>(t);
  // the climb's estimate of det Λ(s): s exactly (a sum of four doubles / 4)
  // in long double
  long double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const long double sj = (static_cast<long double>(src[0][j]) + src[1][j] + src[2][j] + src[3][j]) / 4.0L;
      m[i][j] = static_cast<long double>(ps.point(static_cast<std::size_t>(4 + i))[j]) - sj;
    }
  const long double x = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const long double same = sgn(out.a) * x;
  out.score = static_cast<double>((std::fabs(static_cast<long double>(out.a)) - 2.0L * std::max(0.0L, same)) /
                                  out.bound);
  const double ratio = std::fabs(out.a) / out.bound;
  const int rule = fd::sign_beyond(out.a, out.bound);
  if (rule != 0 || (out.a != 0.0 && out.score > 0.0 && ratio > 0x1p-30)) {
    const pred::MixedRow rows[4] = {{4, ps.point(4), nullptr}, {5, ps.point(5), nullptr},
                                    {6, ps.point(6), nullptr}, {kern.id(), nullptr, &sp}};
    const int g = pred::mixed_sign(4, rows, false, pred::Mode::gmp);  // exact, may be 0
    const int gs = pred::mixed_sign(4, rows, true, pred::Mode::gmp);  // under SoS
    // side() itself: the true bound, then the exact predicate
    if (kern.side(4, 5, 6) != gs) ++ks.side_wrong;
    if (rule != 0) {
      ++ks.decided;
      if (rule != g) ++ks.side_wrong;
    }
    if (out.a != 0.0 && sgn(out.a) != g && ratio > ks.best_wrong) {
      ks.best_wrong = ratio;
      ks.best = coords;
    }
  }
  return out;
}

std::vector<double> kernel_start(Rng& r, int family) {
  const int e = r.below(41) - 20;
  const double M = std::ldexp(1.0, e);
  std::vector<double> c;
  if (family == 1) {
    // the sources a small tetrahedron near the corner -M(1, 1, 1) (so the
    // query differences reach 2M, as the bound charges), a, b near the
    // opposite corner and c = a + α (b - a) + β (q - a) with β small: near
    // that corner too, the plane (a, b, c) through q
    const double spread = std::ldexp(1.0, -8 - r.below(20));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) c.push_back(-M * (1.0 - spread * r.unit()));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 3; ++j) c.push_back(M * (1.0 - spread * r.unit()));
    const double alpha = r.sym(), beta = spread * r.unit();
    for (int j = 0; j < 3; ++j) {
      const double qj = ((c[static_cast<std::size_t>(j)] + c[static_cast<std::size_t>(3 + j)]) +
                         (c[static_cast<std::size_t>(6 + j)] + c[static_cast<std::size_t>(9 + j)])) / 4.0;
      const double aj = c[static_cast<std::size_t>(12 + j)], bj = c[static_cast<std::size_t>(15 + j)];
      c.push_back(std::fmin(M, aj + alpha * (bj - aj) + beta * (qj - aj)));
    }
    return c;
  }
  const double signs[12] = {-1, -1, -1, 1, 1, -1, 1, -1, 1, -1, 1, 1};
  for (double sg : signs) c.push_back(sg * M * (0.75 + 0.25 * r.unit()));
  for (int i = 0; i < 6; ++i) c.push_back(M * r.sym());  // a, b
  // c = 2q - a, q the centroid's double value
  for (int j = 0; j < 3; ++j) {
    const double qj = ((c[static_cast<std::size_t>(j)] + c[static_cast<std::size_t>(3 + j)]) +
                       (c[static_cast<std::size_t>(6 + j)] + c[static_cast<std::size_t>(9 + j)])) / 4.0;
    c.push_back(2.0 * qj - c[static_cast<std::size_t>(12 + j)]);
  }
  return c;
}

// Family 2: from an orient3d input (p0, p1, p2, base) at the static bound's
// edge (the static search's best): a = p0, b = p1, c = p2 and the sources a
// tiny tetrahedron around base (offsets ±2^-30 M summing to 0), so s = base:
// det Λ(s) is that input's determinant and the threshold is bound(4) + U.
std::vector<double> kernel_from_orient3d(const Input& in, Rng& r) {
  double M = 0.0;
  for (double v : in.x) M = std::fmax(M, std::fabs(v));
  const double d = std::ldexp(M, -30 - r.below(8));
  const double off[4][3] = {{d, d, d}, {-d, -d, d}, {-d, d, -d}, {d, -d, -d}};
  std::vector<double> c;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) c.push_back(in.p(3)[j] + off[i][j]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.push_back(in.p(i)[j]);
  return c;
}

KernelSearch kernel_search(int restarts, int steps, const Input& orient3d_edge) {
  KernelSearch ks;
  Rng r{params().seed ^ 0x6b65726eull};
  for (int rs = 0; rs < restarts; ++rs) {
    std::vector<double> cur = rs % 3 == 2 ? kernel_from_orient3d(orient3d_edge, r) : kernel_start(r, rs % 3);
    double cs = kernel_eval(cur, ks).score;
    for (int it = 0; it < steps; ++it) {
      std::vector<double> nxt = cur;
      const int moves = 1 + r.below(2);
      for (int m = 0; m < moves; ++m) {
        double& v = nxt[static_cast<std::size_t>(r.below(21))];
        v = ulps(v, (r.next() & 1 ? 1 : -1) * (1 + r.below(r.below(3) == 0 ? 256 : 4)));
      }
      const double ns = kernel_eval(nxt, ks).score;
      if (ns >= cs) {
        cur = nxt;
        cs = ns;
      }
    }
  }
  return ks;
}

// The factor F by which each bound, divided, answers a wrong sign on the set
// (the set's largest wrong |a| / bound exceeds 1/F), measured with kSeed,
// kRestarts and kSteps and the kept inputs kKept (the printed ratios; a power
// of two but where noted). 2026-12-04: fourteen runs of fuzz/filter_sensitivity.sh
// (four with 96 restarts, six with 256, four with 512; 4000 steps) came closer
// than CI's own set on 47 of the 61 shapes; their inputs are kept, and the factors
// below fell by 2-256x there (the ErrDouble bounds of orient3d, power1d and
// power2d and PlaneForm D = 2, 3 to 2x, the running double-double bound at
// k = 3, 4 to 4x, at k = 5 lifted 2^23 -> 2^15), and orient2d's a-priori
// double-double bound and the 6- and 7-row double-double filter, not caught
// before, are caught at 16x and 128-512x.
// Caught at F = 2 or within: permanent k = 3, dynamic k = 3 plain (ratio 2/3:
// 2 of the 3 roundings of orient2d's errbound A aligned), dynamic k = 3
// lifted, k = 4 plain and lifted (ratios 0.51, 0.52, 0.53: kept inputs),
// PlaneForm D = 2, 3 (0.51, 0.58, kept), static and semi-static k = 3 plain
// (ratio 0.6666666). Those two were caught only just over 2x (ratio
// 0.4999999) while the bound charged the last rounding: with every |t| near
// its column bound 2M (M just above 2^e), fl(det) = fl(t00 t11) - fl(t01 t10)
// is a difference of two doubles in [2^(2e+2), 2^(2e+3)), a multiple of
// 8u 2^(2e), so a wrong sign has |fl det| <= 16u 2^(2e); the bound was 32u M^2
// (1 + O(u)) and is 24u M^2 (1 + O(u)) since static_filter.hpp (1') leaves
// out the last rounding, which cannot change a sign (2026-12-05).
// For k >= 4 the static and semi-static bounds charge N! terms each as large
// as Π_c m_c with N + (N-1) + N(N-1)/2 - 1 roundings; entries that large in every
// column force T near rank one (one sign per column: |t_ic| near 2M needs
// p_i[c] near -base[c]), whose minors cancel, so most charged roundings act
// on small values: the measured ratios fall with N (orient3d 0.14, orient6d
// 4e-5), the factor to the true worst case is unknown but large. The
// kernel-point bound adds U = 8 M^2 Σ e_j to the static orient3d bound; its
// wrong signs come from the static part (family 2 above): 0.11, 16x (the
// issue's random inputs: 64x in 2 of 3 runs). The double-double bounds (β u^2
// times the permanent, β up to 72; the running bound of err_dd.hpp): the
// ratio is (|h| - the threshold's |l| part) / the bound part, the climb's
// estimate in binary128 (only 2^7 finer than u^2, so the climb is coarse
// there): caught at 4x (running, k = 3, 4) and 32x (a-priori, k = 4);
// at k = 5 only at 2^14-2^20; orient2d's a-priori bound at 16x (a kept
// input; CI's own set holds no wrong sign of h); for both bounds of power1d
// (k = 3 lifted) no set holds a wrong sign of h at all (0 below: not
// caught). The 6- and 7-row filter: CI's own set (96,024
// inputs per shape, 49,823-56,750 decided, each equal to GMP) holds no
// wrong sign of h — the climb's binary128 estimate cannot steer towards
// |det Λ| ~ u^2 per, and the moved lattices' integer rows are exact in
// binary64 —; the kept inputs of the longer runs (moved lattices, one near
// 2^8, subnormal moved zeros) are caught at 128-512x.
// PlaneForm: ratios 0.51, 0.58, 0.29, 0.26, 0.26, 0.18 for D = 2..7 (2x, 2x, 4x, 4x, 4x, 8x; all
// from kept inputs, where CI's own set had 0.39, 0.30, 0.21, 0.17, 0.22, 0.032), after its weights were
// tightened to (1 + 2u) e_j + (u + γ_D)|n_j| + eta (0.23-0.17 with the former
// e_j + 2(u + γ_D)|n_j|); for D >= 4 the cofactors' ErrDouble running bounds
// e_j dominate the weights, and those are caught at 4-16x by the dynamic
// rows above (k = D), which bounds how close this search comes.
struct Expect {
  Bound b;
  int k;
  bool lifted;
  double factor;
};
const Expect kCaught[] = {
    {Bound::static_bound, 3, false, 2},          {Bound::static_bound, 3, true, 4},
    {Bound::static_bound, 4, false, 8},          {Bound::static_bound, 4, true, 16},
    {Bound::static_bound, 5, false, 256},        {Bound::static_bound, 5, true, 256},
    {Bound::static_bound, 6, false, 2048},       {Bound::static_bound, 6, true, 2048},
    {Bound::static_bound, 7, false, 16384},      {Bound::static_bound, 7, true, 32768},
    {Bound::static_bound, 8, false, 0x1p17},     {Bound::static_bound, 8, true, 0x1p18},
    {Bound::semi_static, 3, false, 2},           {Bound::semi_static, 3, true, 4},
    {Bound::semi_static, 4, false, 8},           {Bound::semi_static, 4, true, 8},
    {Bound::semi_static, 5, false, 32},          {Bound::semi_static, 5, true, 32},
    {Bound::semi_static, 6, false, 128},         {Bound::semi_static, 6, true, 256},
    {Bound::semi_static, 7, false, 1024},        {Bound::semi_static, 7, true, 1024},
    {Bound::semi_static, 8, false, 4096},        {Bound::semi_static, 8, true, 8192},
    {Bound::permanent, 3, false, 2},             {Bound::permanent, 4, false, 4},
    {Bound::dynamic, 3, false, 2},               {Bound::dynamic, 3, true, 2},
    {Bound::dynamic, 4, false, 2},               {Bound::dynamic, 4, true, 2},
    {Bound::dynamic, 5, false, 4},               {Bound::dynamic, 5, true, 4},
    {Bound::dynamic, 6, false, 4},               {Bound::dynamic, 6, true, 8},
    {Bound::dynamic, 7, false, 8},               {Bound::dynamic, 7, true, 8},
    {Bound::dynamic, 8, false, 16},              {Bound::dynamic, 8, true, 8},
    // 0: the set holds no wrong sign of the double-double value at all
    {Bound::dd_apriori, 3, false, 16},           {Bound::dd_apriori, 3, true, 0},
    {Bound::dd_apriori, 4, false, 32},           {Bound::dd_apriori, 4, true, 32},
    {Bound::dd_apriori, 5, false, 0x1p20},       {Bound::dd_apriori, 5, true, 0x1p20},
    {Bound::dd_running, 3, false, 4},            {Bound::dd_running, 3, true, 0},
    {Bound::dd_running, 4, false, 4},            {Bound::dd_running, 4, true, 4},
    {Bound::dd_running, 5, false, 8192},         {Bound::dd_running, 5, true, 16384},
    {Bound::plane_form, 3, false, 2},            {Bound::plane_form, 4, false, 2},
    {Bound::plane_form, 5, false, 4},            {Bound::plane_form, 6, false, 4},
    {Bound::plane_form, 7, false, 4},            {Bound::plane_form, 8, false, 4},
    {Bound::dd_wide, 6, false, 64},              {Bound::dd_wide, 6, true, 128},
    {Bound::dd_wide, 7, false, 256},             {Bound::dd_wide, 7, true, 512},
};
constexpr double kKernelCaught = 16;

double caught_factor(Bound b, int k, bool lifted) {
  for (const Expect& e : kCaught)
    if (e.b == b && e.k == k && e.lifted == lifted) return e.factor;
  return 0.0;
}
bool caught_listed(Bound b, int k, bool lifted) {
  for (const Expect& e : kCaught)
    if (e.b == b && e.k == k && e.lifted == lifted) return true;
  return false;
}

// One test case per bound; the sets are those of the search above (seed
// printed). "Weakened" is the bound divided by the factor of kCaught: for the
// static filter the filter itself, StaticFilter::scaled_for_testing(1/F), for
// the others the recomputed rule (which equals the library's answer on every
// input of the set, asserted).
void check_bound(Bound b) {
  const Params& P = params();
  std::printf("filter sensitivity (%s): seed 0x%llx, %d restarts x %d steps%s\n", name_of(b),
              static_cast<unsigned long long>(P.seed), P.restarts, P.steps,
              P.fixed() ? " (the fixed set)" : " (another set: soundness only)");
  for (int k = 3; k <= 8; ++k)
    for (bool lifted : {false, true}) {
      if (b == Bound::permanent && (lifted || k > 4)) continue;
      if ((b == Bound::dd_apriori || b == Bound::dd_running) && k > 5) continue;
      if (b == Bound::dd_wide && (k < 6 || k > 7)) continue;
      if (b == Bound::plane_form && lifted) continue;
      const Search s = search(k, lifted, b, P.restarts, P.steps);
      const double F = caught_factor(b, k, lifted);
      std::printf("sensitivity %-11s k=%d %-7s evaluated %6ld decided %6ld (GMP %6ld): max |det|/bound among "
                  "wrong signs %.9g (1/%.4g); weakened %gx caught: %s; true bound wrong %ld\n",
                  name_of(b), k, lifted ? "lifted" : "plain", s.evaluated, s.decided, s.gmp_calls, s.best_wrong,
                  s.best_wrong > 0 ? 1.0 / s.best_wrong : HUGE_VAL, F, F == 0.0 ? "none listed" : s.best_wrong * F > 1.0 ? "yes" : "NO",
                  s.wrong_true);
      INFO(name_of(b) << " k=" << k << (lifted ? " lifted" : " plain") << ": " << s.mismatch_example);
      CHECK(s.wrong_true == 0);        // the true bound: no wrong sign on the set
      CHECK(s.library_mismatch == 0);  // the recomputed rule is the library's
      CHECK(s.best_wrong <= 1.0);
      REQUIRE(caught_listed(b, k, lifted));
      if (!P.fixed()) {
        // another set: closer than the fixed one when it catches F / 2
        if (s.best_wrong > 0.0 && (F == 0.0 || s.best_wrong * F > 2.0))
          std::printf("sensitivity %-11s k=%d %-7s closer than the fixed set (listed %gx): %s\n", name_of(b), k,
                      lifted ? "lifted" : "plain", F, s.best.text().c_str());
        continue;
      }
      if (F > 0.0) CHECK(s.best_wrong * F > 1.0);  // the weakened bound: a wrong sign
      if (b == Bound::static_bound && s.best_wrong > 0.0) {
        const Input& in = s.best;
        const double* p[8];
        in.rows(p);
        const StaticFilter f = StaticFilter::for_points(in.x.data(), static_cast<std::size_t>(k), in.nc, in.wp());
        const int g = stage::gmp(k, p, in.wp());
        const int weak = stage::static_filter(f.scaled_for_testing(1.0 / F), k, p, in.wp());
        CHECK(stage::static_filter(f, k, p, in.wp()) == 0);
        CHECK(weak != 0);
        CHECK(weak != g);
      }
    }
}

}  // namespace

TEST_CASE("filters: deterministic sensitivity of the static filter's bound", "[predicates][sensitivity][long]") {
  check_bound(Bound::static_bound);
}
TEST_CASE("filters: deterministic sensitivity of the semi-static filter's bound",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::semi_static);
}
TEST_CASE("filters: deterministic sensitivity of the permanent (errbound A) bound of orient2d/3d",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::permanent);
}
TEST_CASE("filters: deterministic sensitivity of the ErrDouble running bound", "[predicates][sensitivity][long]") {
  check_bound(Bound::dynamic);
}
TEST_CASE("filters: deterministic sensitivity of the double-double filter's a-priori bound",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::dd_apriori);
}
TEST_CASE("filters: deterministic sensitivity of PlaneForm's per-tuple bound (orient_d as a linear form)",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::plane_form);
}
TEST_CASE("filters: deterministic sensitivity of the 6- and 7-row double-double filter's a-priori bound",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::dd_wide);
}
TEST_CASE("filters: deterministic sensitivity of the double-double stage's running bound",
          "[predicates][sensitivity][long]") {
  check_bound(Bound::dd_running);
}

TEST_CASE("filters: deterministic sensitivity of the kernel point's bound (RationalKernel::side)",
          "[predicates][sensitivity][ffhull][long]") {
  const Params& P = params();
  std::printf("kernel point sensitivity: seed 0x%llx, %d restarts x %d steps%s\n",
              static_cast<unsigned long long>(P.seed), P.restarts, P.steps,
              P.fixed() ? " (the fixed set)" : " (another set: soundness only)");
  const Search edge = search(4, false, Bound::static_bound, P.restarts, P.steps);
  REQUIRE(edge.best_wrong > 0.0);  // (the kernel search starts a third of its climbs from that input)
  const KernelSearch ks = kernel_search(P.restarts, P.steps, edge.best);
  const double factor = ks.best_wrong > 0 ? std::exp2(std::ceil(-std::log2(ks.best_wrong))) : HUGE_VAL;
  std::printf("sensitivity kernel point evaluated %6ld decided %6ld: max |det|/bound among wrong signs %.4g -> "
              "caught at %g x; side() wrong %ld\n",
              ks.evaluated, ks.decided, ks.best_wrong, factor, ks.side_wrong);
  CHECK(ks.side_wrong == 0);         // side() (the true bound, then exact) equals GMP with SoS
  CHECK(ks.best_wrong <= 1.0);
  if (P.fixed()) {
    CHECK(ks.best_wrong * kKernelCaught > 1.0);  // the bound / 16: a wrong sign
  } else if (ks.best_wrong * kKernelCaught > 2.0) {
    // (kKept holds no kernel-point inputs: this seed reproduces it)
    std::string t;
    char buf[40];
    for (double v : ks.best) std::snprintf(buf, sizeof buf, t.empty() ? "%a" : " %a", v), t += buf;
    std::printf("sensitivity kernel point closer than the fixed set (listed %gx; not kept: rerun seed 0x%llx): %s\n",
                kKernelCaught, static_cast<unsigned long long>(P.seed), t.c_str());
  }
}

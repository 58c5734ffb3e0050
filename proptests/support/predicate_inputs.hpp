// predicate_inputs.hpp — RapidCheck input families for the property tests of
// predicates/ (predicates_test.cpp, sos_test.cpp).
//
// The instances and the calling interface are in predicate_call.hpp.
//
// Families (the generators below, all drawn with RapidCheck inside a property):
//   uniform           random doubles in [-1, 1] (53-bit grid).
//   near_degenerate   a degenerate configuration computed in doubles (points in
//                     a lower-dimensional flat, lifted points on a hyperplane,
//                     points on a sphere with equal weights), then every value
//                     moved by 0 or ±1..3 ulps with std::nextafter.
//   exact_degenerate  small-integer configurations that are exactly degenerate
//                     (grids, integer flats, lattice points on x²+y² = 25 or 65
//                     and on integer spheres, weights w = |x|² - α·x - β,
//                     duplicated points), and of random doubles (points on
//                     coordinate hyperplanes, duplicated points), optionally
//                     scaled by an exact power of
//                     two down to subnormals or up to ~1e300 (coordinates by 2^s,
//                     weights by 2^(2s), which keeps the degeneracy exact).
//   extreme           each value independently 0, subnormal (4.9e-324, 1e-310,
//                     random), ~1e-300, ~1, ~1e300 or ±DBL_MAX; weights all zero,
//                     all equal, or independently extreme.
#pragma once

#include <rapidcheck.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "proptests/support/predicate_call.hpp"

namespace flipflop::test {

using pred::Mode;
using pred::PointId;

// A uniformly random permutation of 0..k-1 (Fisher–Yates).
inline std::vector<int> gen_permutation(int k) {
  std::vector<int> perm(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) perm[static_cast<size_t>(i)] = i;
  for (int i = k - 1; i > 0; --i) {
    const int j = *rc::gen::inRange(0, i + 1);
    std::swap(perm[static_cast<size_t>(i)], perm[static_cast<size_t>(j)]);
  }
  return perm;
}

// ---- scalar generators ----------------------------------------------------------

// A double in [-1, 1] on the grid 2^-53 (every such value is exact).
inline double gen_unit() {
  const std::int64_t m = *rc::gen::inRange<std::int64_t>(-(std::int64_t(1) << 53),
                                                          (std::int64_t(1) << 53) + 1);
  return std::ldexp(static_cast<double>(m), -53);
}

// Moves v by `ulps` units in the last place (sign gives the direction).
inline double nudge(double v, int ulps) {
  const double to = ulps > 0 ? std::numeric_limits<double>::infinity()
                             : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(ulps); ++i) v = std::nextafter(v, to);
  return v;
}

// 0 (half of the time) or ±1..3 ulps.
inline double gen_nudged(double v) {
  const int ulps = *rc::gen::weightedElement<int>(
      {{6, 0}, {1, 1}, {1, 2}, {1, 3}, {1, -1}, {1, -2}, {1, -3}});
  const double r = nudge(v, ulps);
  return std::isfinite(r) ? r : v;
}

// One value of very different magnitude classes, random sign.
inline double gen_extreme_value() {
  const int cls = *rc::gen::inRange(0, 11);
  double v = 0.0;
  switch (cls) {
    case 0: v = 0.0; break;
    case 1: v = 4.9e-324; break;  // the smallest subnormal, 2^-1074
    case 2: v = 1e-310; break;    // a subnormal
    case 3:                       // a random subnormal
      v = std::ldexp(static_cast<double>(*rc::gen::inRange<std::int64_t>(1, std::int64_t(1) << 52)),
                     -1074);
      break;
    case 4: v = DBL_MIN; break;  // the smallest normal
    case 5: v = 1e-300 * (1.0 + std::fabs(gen_unit())); break;
    case 6: v = gen_unit(); break;
    case 7: v = 1e300 * (1.0 + std::fabs(gen_unit())); break;
    case 8: v = 1e300; break;
    case 9: v = DBL_MAX; break;
    default: v = std::ldexp(1.0 + std::fabs(gen_unit()), *rc::gen::inRange(-1074, 1023)); break;
  }
  return *rc::gen::arbitrary<bool>() ? -v : v;
}

// The affine map i -> offset + stride i of distinct ids for n points: small
// ids, huge ids, or ids near 2^64 - 1.
struct IdStretch {
  PointId stride = 1, offset = 0;
  PointId operator()(std::uint64_t i) const { return offset + stride * static_cast<PointId>(i); }
};
inline IdStretch gen_id_stretch(std::uint64_t n) {
  const int mode = *rc::gen::inRange(0, 3);
  IdStretch m;
  if (mode == 1) {
    m.stride = *rc::gen::inRange<PointId>(1, PointId(1) << 40);
    m.offset = *rc::gen::inRange<PointId>(0, PointId(1) << 20);
  } else if (mode == 2) {
    m.stride = *rc::gen::inRange<PointId>(1, 1000);
    m.offset = std::numeric_limits<PointId>::max() - m.stride * static_cast<PointId>(n);
  }
  return m;
}

// k distinct ids: a permutation of 0..k-1 stretched by gen_id_stretch.
inline std::vector<PointId> gen_distinct_ids(int k) {
  const std::vector<int> perm = gen_permutation(k);
  const IdStretch m = gen_id_stretch(static_cast<std::uint64_t>(k));
  std::vector<PointId> ids(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i)
    ids[static_cast<size_t>(i)] = m(static_cast<std::uint64_t>(perm[static_cast<size_t>(i)]));
  return ids;
}

// ---- instance generators -----------------------------------------------------------

enum class Family { uniform, near_degenerate, exact_degenerate, extreme };
constexpr Family kFamilies[] = {Family::uniform, Family::near_degenerate,
                                Family::exact_degenerate, Family::extreme};

inline const char* family_name(Family f) {
  switch (f) {
    case Family::uniform: return "uniform";
    case Family::near_degenerate: return "near-degenerate";
    case Family::exact_degenerate: return "exactly degenerate";
    case Family::extreme: return "extreme magnitudes";
  }
  return "?";
}

inline Instance empty_instance(const Spec& s) {
  Instance in;
  in.d = s.d;
  in.k = s.points();
  in.x.assign(static_cast<size_t>(in.k * in.d), 0.0);
  in.w.assign(static_cast<size_t>(in.k), 0.0);
  in.id = gen_distinct_ids(in.k);
  return in;
}

// Every point of `in` an affine combination of r+1 base points (r < d): the
// points lie in an r-flat, so any d+1 of them are affinely dependent.
inline void fill_flat_near(Instance& in) {
  const int d = in.d;
  const int r = *rc::gen::inRange(0, d);
  std::vector<double> base(static_cast<size_t>((r + 1) * d));
  for (double& b : base) b = gen_unit();
  for (int i = 0; i < in.k; ++i) {
    for (int j = 0; j < d; ++j) in.p(i)[j] = base[static_cast<size_t>(j)];
    for (int t = 1; t <= r; ++t) {
      const double c = 2.0 * gen_unit();
      for (int j = 0; j < d; ++j)
        in.p(i)[j] += c * (base[static_cast<size_t>(t * d + j)] - base[static_cast<size_t>(j)]);
    }
  }
}

inline Instance gen_uniform(const Spec& s) {
  Instance in = empty_instance(s);
  for (double& v : in.x) v = gen_unit();
  if (s.weighted())
    for (double& v : in.w) v = gen_unit();
  return in;
}

inline Instance gen_near_degenerate(const Spec& s) {
  Instance in = empty_instance(s);
  const int mode = s.weighted() ? *rc::gen::inRange(0, 3) : 0;
  if (mode == 0) {
    // orientation: points in a flat; power: x in a flat (the lifted points lie
    // in a vertical hyperplane), weights arbitrary.
    fill_flat_near(in);
    if (s.weighted())
      for (double& v : in.w) v = gen_unit();
  } else if (mode == 1) {
    // lifted points on the hyperplane h = α·x + β: w = |x|² - α·x - β.
    for (double& v : in.x) v = gen_unit();
    std::vector<double> alpha(static_cast<size_t>(s.d));
    for (double& a : alpha) a = gen_unit();
    const double beta = gen_unit();
    for (int i = 0; i < in.k; ++i) {
      double w = -beta;
      for (int j = 0; j < s.d; ++j) w += in.p(i)[j] * (in.p(i)[j] - alpha[static_cast<size_t>(j)]);
      in.w[static_cast<size_t>(i)] = w;
    }
  } else {
    // cospherical points, all weights equal (0 half of the time).
    std::vector<double> center(static_cast<size_t>(s.d));
    for (double& c : center) c = gen_unit();
    const double radius = 0.1 + std::fabs(gen_unit());
    const double wall = *rc::gen::arbitrary<bool>() ? 0.0 : gen_unit();
    for (int i = 0; i < in.k; ++i) {
      std::vector<double> u(static_cast<size_t>(s.d));
      double norm2 = 0.0;
      for (double& c : u) {
        c = gen_unit();
        norm2 += c * c;
      }
      if (norm2 < 1e-6) {
        u.assign(u.size(), 0.0);
        u[0] = 1.0;
        norm2 = 1.0;
      }
      const double scale = radius / std::sqrt(norm2);
      for (int j = 0; j < s.d; ++j)
        in.p(i)[j] = center[static_cast<size_t>(j)] + scale * u[static_cast<size_t>(j)];
      in.w[static_cast<size_t>(i)] = wall;
    }
  }
  for (double& v : in.x) v = gen_nudged(v);
  if (s.weighted())
    for (double& v : in.w) v = gen_nudged(v);
  return in;
}

// Integer points of R^d with |p|² = r2, enumerated once per (d, r2).
inline const std::vector<std::vector<int>>& lattice_sphere(int d, int r2) {
  static std::map<std::pair<int, int>, std::vector<std::vector<int>>> cache;
  auto it = cache.find({d, r2});
  if (it != cache.end()) return it->second;
  int bound = 0;
  while ((bound + 1) * (bound + 1) <= r2) ++bound;
  std::vector<std::vector<int>> out;
  std::vector<int> c(static_cast<size_t>(d), -bound);
  for (;;) {
    int n2 = 0;
    for (int v : c) n2 += v * v;
    if (n2 == r2) out.push_back(c);
    int j = 0;
    while (j < d && c[static_cast<size_t>(j)] == bound) c[static_cast<size_t>(j++)] = -bound;
    if (j == d) break;
    ++c[static_cast<size_t>(j)];
  }
  return cache.emplace(std::make_pair(d, r2), std::move(out)).first->second;
}

// Small-integer configurations (exactly degenerate in most draws), then
// scaled by an exact power of two.
inline Instance gen_exact_degenerate(const Spec& s) {
  Instance in = empty_instance(s);
  const int d = s.d;
  auto ints = [](int lo, int hi) { return static_cast<double>(*rc::gen::inRange(lo, hi + 1)); };
  const int mode = *rc::gen::inRange(0, s.weighted() ? 5 : 3);
  switch (mode) {
    case 0:  // a tiny grid: many collinear / coplanar / cocircular draws
      for (double& v : in.x) v = ints(-2, 2);
      if (s.weighted())
        for (double& v : in.w) v = ints(-2, 2);
      break;
    case 1: {  // an integer r-flat, r < d (collinear, coplanar, identical points)
      if (*rc::gen::inRange(0, 2) == 1) {
        // or points on coordinate hyperplanes x_c = const in random doubles
        // (the floors and walls of a building: staged.hpp's flat_sign_sorted),
        // each column constant with probability 1/3, at least one
        std::vector<int> fixed(static_cast<size_t>(d));
        for (int& f : fixed) f = *rc::gen::inRange(0, 3) == 0;
        fixed[static_cast<size_t>(*rc::gen::inRange(0, d))] = 1;
        for (int j = 0; j < d; ++j) {
          const double c = gen_unit();
          for (int i = 0; i < in.k; ++i) in.p(i)[j] = fixed[static_cast<size_t>(j)] ? c : gen_unit();
        }
        if (s.weighted()) {
          const double common = *rc::gen::inRange(0, 2) == 1 ? gen_unit() : 0.0;
          const bool equal = *rc::gen::inRange(0, 2) == 1;
          for (double& v : in.w) v = equal ? common : gen_unit();
        }
        break;
      }
      const int r = *rc::gen::inRange(0, d);
      std::vector<double> q(static_cast<size_t>(d)), dir(static_cast<size_t>(r * d));
      for (double& v : q) v = ints(-8, 8);
      for (double& v : dir) v = ints(-3, 3);
      for (int i = 0; i < in.k; ++i) {
        for (int j = 0; j < d; ++j) in.p(i)[j] = q[static_cast<size_t>(j)];
        for (int t = 0; t < r; ++t) {
          const double c = ints(-3, 3);
          for (int j = 0; j < d; ++j) in.p(i)[j] += c * dir[static_cast<size_t>(t * d + j)];
        }
      }
      if (s.weighted())
        for (double& v : in.w) v = ints(-4, 4);
      break;
    }
    case 2: {  // duplicated points (same coordinates and weight)
      // small integers (the integer stage decides them), or random doubles
      // of full mantissa (exact copies in real data: only the equal rows
      // make det Λ = 0, staged.hpp's equal_points shortcut); weighted, the
      // copy has another weight one time in four (equal coordinates, rows
      // not equal: the shortcut must not apply)
      const bool full = *rc::gen::inRange(0, 2) == 1;
      for (double& v : in.x) v = full ? gen_unit() : ints(-8, 8);
      if (s.weighted())
        for (double& v : in.w) v = full ? gen_unit() : ints(-8, 8);
      const int a = *rc::gen::inRange(0, in.k);
      const int b = (a + *rc::gen::inRange(1, in.k)) % in.k;
      for (int j = 0; j < d; ++j) in.p(b)[j] = in.p(a)[j];
      const bool other_weight = s.weighted() && *rc::gen::inRange(0, 4) == 0;
      if (!other_weight) in.w[static_cast<size_t>(b)] = in.w[static_cast<size_t>(a)];
      break;
    }
    case 3: {  // lattice points on a circle / sphere, translated, equal weights
      int r2 = 9;
      if (d == 2) r2 = *rc::gen::element(25, 65);
      if (d == 3) r2 = *rc::gen::element(9, 25, 50);
      const auto& sphere = lattice_sphere(d, r2);
      std::vector<int> center(static_cast<size_t>(d));
      for (int& c : center) c = *rc::gen::inRange(-4, 5);
      const double wall = ints(-3, 3);
      for (int i = 0; i < in.k; ++i) {
        const auto& q = sphere[static_cast<size_t>(*rc::gen::inRange<size_t>(0, sphere.size()))];
        for (int j = 0; j < d; ++j)
          in.p(i)[j] = static_cast<double>(q[static_cast<size_t>(j)] + center[static_cast<size_t>(j)]);
        in.w[static_cast<size_t>(i)] = wall;
      }
      break;
    }
    default: {  // lifted points on an integer hyperplane: w = |x|² - α·x - β
      std::vector<double> alpha(static_cast<size_t>(d));
      for (double& a : alpha) a = ints(-3, 3);
      const double beta = ints(-5, 5);
      for (double& v : in.x) v = ints(-6, 6);
      for (int i = 0; i < in.k; ++i) {
        double w = -beta;
        for (int j = 0; j < d; ++j) w += in.p(i)[j] * (in.p(i)[j] - alpha[static_cast<size_t>(j)]);
        in.w[static_cast<size_t>(i)] = w;  // an integer < 2^10: exact
      }
      break;
    }
  }
  // Exact scaling: coordinates by 2^e, weights by 2^(2e) (heights |x|² - w
  // scale by 2^(2e) too, so the determinant only changes by a positive factor).
  // Integers here are below 2^6 (coordinates) and 2^10 (weights), so every
  // scaled value is exact, subnormals included (case 2's random doubles may
  // round when scaled into the subnormals: a copy still rounds as its
  // original, so the copies stay equal).
  const int e = s.weighted() ? *rc::gen::element(0, 0, 0, -537, -530, -300, 300, 500)
                             : *rc::gen::element(0, 0, 0, -1074, -1060, -1030, -1000, -600, 600,
                                                 1000, 1010);
  for (double& v : in.x) v = std::ldexp(v, e);
  for (double& v : in.w) v = std::ldexp(v, 2 * e);
  return in;
}

inline Instance gen_extreme(const Spec& s) {
  Instance in = empty_instance(s);
  for (double& v : in.x) v = gen_extreme_value();
  if (s.weighted()) {
    const int mode = *rc::gen::inRange(0, 3);
    const double common = mode == 1 ? gen_extreme_value() : 0.0;
    for (double& v : in.w) v = mode == 2 ? gen_extreme_value() : common;
  }
  return in;
}

inline Instance gen_instance(const Spec& s, Family f) {
  switch (f) {
    case Family::uniform: return gen_uniform(s);
    case Family::near_degenerate: return gen_near_degenerate(s);
    case Family::exact_degenerate: return gen_exact_degenerate(s);
    case Family::extreme: return gen_extreme(s);
  }
  return gen_uniform(s);
}

inline Instance gen_any(const Spec& s) {
  return gen_instance(s, *rc::gen::elementOf(std::vector<Family>(std::begin(kFamilies),
                                                                  std::end(kFamilies))));
}

// k rows of nc doubles (row-major at x): row k-1 replaced by the affine
// combination Σ_{i<k-1} λ_i row_i, λ_0..λ_{k-3} = draw() in that order and
// λ_{k-2} = 1 - their sum — k points on one hyperplane up to the rounding of
// the combination (near-degenerate orientation inputs; k <= 9).
template <class Draw>
void set_last_row_affine(double* x, int k, int nc, Draw&& draw) {
  double lam[8], sum = 0.0;
  for (int i = 0; i + 2 < k; ++i) sum += (lam[i] = draw());
  lam[k - 2] = 1.0 - sum;
  for (int j = 0; j < nc; ++j) {
    double v = 0.0;
    for (int i = 0; i + 1 < k; ++i) v += lam[i] * x[i * nc + j];
    x[(k - 1) * nc + j] = v;
  }
}

}  // namespace flipflop::test

// bench_predicates.cpp — `flipflop bench predicates [--n N] [--reps R] [--seed S]
// [--csv]`: the cost of exactness, stage by stage (predicates/staged.hpp).
//
// For each predicate (orient2d..orient6d: k = d+1 points in R^d; power2d..
// power5d: k = d+2 weighted points, the lifted test) and four input families,
// n calls on fresh points each, the median over R runs of (time of the n
// calls) / n, in ns, of
//   flipflop_ns    the default path as the algorithms call it: for orient2d,
//                  orient3d, power2d and power3d the typed functions of
//                  predicates/fast.hpp (the static filter inlined, the rest
//                  out of line), otherwise pred::lambda_sign(&filter, k, ids,
//                  p, w); point ids 0..k-1: static filter, semi-static filter, dynamic filter,
//                  exact stage and, where the determinant is 0 (the degenerate
//                  family), Simulation of Simplicity — a question CGAL does not
//                  answer (it returns 0 there);
//   static_ns      stage::static_filter alone, with the StaticFilter::for_points
//                  of all the family's points, built before timing (the
//                  per-input bound: CGAL's static filters, thesis §6.4.2);
//   dynamic_ns     stage::dynamic alone, the ErrDouble running-error filter;
//   expansion_ns   stage::expansion_sos alone: the exact sign, and the SoS sign
//                  where it is 0, in Shewchuk's expansion arithmetic ([She97]
//                  "Adaptive Precision Floating-Point Arithmetic and Fast
//                  Robust Geometric Predicates", predicates.c), unbounded
//                  exponents outside the double window;
//   cgal_epick_ns  CGAL's Exact_predicates_inexact_constructions_kernel
//                  (peers/cgal_predicates): Orientation_2/_3, Epick_d<Dimension_
//                  tag<d>> orientation in 4..6 D, power_side_of_oriented_power_
//                  circle_2 / _sphere_3 with the weights; an empty field where
//                  Epick has no such predicate (power4d, power5d), never a guess;
//   gmp_ns         stage::gmp_sos alone: the same question in GMP (the oracle,
//                  and the exact stage of the path before the staged one);
// then static_decides / dynamic_decides, the fractions of the n calls that the
// static / the dynamic filter decides alone (each run on its own, not after
// the other). The semi-static filter is not a column; it is checked below.
//
// Checks, on every call, before flipflop's stages are timed (CGAL: the signs of
// its timed runs, checked before the row is printed). A disagreement throws:
// exit code 3 and a message naming the stage, call and signs, never a row.
//   - static, semi-static and dynamic filters, when they decide, and the default
//     path and the expansion stage always, against stage::gmp;
//   - with point ids 0..k-1, the default path with SoS and stage::expansion_sos
//     against stage::gmp_sos;
//   - CGAL against stage::gmp times (-1)^d, d the dimension of the points.
//     flipflop's sign is that of det Λ, rows (p_i, 1) with the 1-column last
//     (the lifted column h_i = |p_i|^2 - w_i before it in a power test):
//     Shewchuk's convention, orient2d > 0 iff counter-clockwise, incircle > 0
//     iff inside. Orientation, k = d + 1: subtract row 0 from the others and
//     expand along the 1-column, whose only 1 left is at (0, d):
//     det Λ = (-1)^d det[p_i - p_0]_{i=1..d}, and det[p_i - p_0] is what CGAL's
//     Orientation_2/_3 and Epick_d's Orientation_of_points take the sign of.
//     Power test, k = d + 2, t the last point: subtracting row t leaves its 1
//     at (d+1, d+1), so det Λ = det[p_i - t, h_i - h_t]; h_i - h_t = |p_i -
//     t|^2 + 2 t.(p_i - t) - w_i + w_t, and the middle term is a combination
//     of the first d columns: det Λ = det[p_i - t, |p_i - t|^2 - w_i + w_t],
//     which CGAL returns in 2D and negates in 3D (kernel_ftC2.h / kernel_ftC3.h,
//     power_side_of_oriented_power_circleC2 / _sphereC3): (-1)^d again.
//     So CGAL = (-1)^d flipflop on every call, 0 exactly where it is 0.
//
// Families:
//   random           coordinates uniform in [0, 1] (weights in [0, 0.01]).
//   near-degenerate  orient: the last point on the line through the first two;
//                    power: all points on one sphere (rounded rational
//                    parametrisation in 2D and 3D, a normalised direction in
//                    higher d), zero weights; then every value moved by 0..3
//                    ulps: the filters fail on many calls.
//   degenerate       exactly degenerate small integers: orient, the last point
//                    p0 + t (p1 - p0) with integer t; power, weights
//                    w = |x|^2 - a.x - b (the lifted points on one hyperplane):
//                    every call has determinant 0, no filter decides and every
//                    call reaches the exact stage.
//   extreme          every value of a random magnitude class (subnormal, ~1e-300,
//                    ~1, ~1e300) and sign, mixed within each call: outside the
//                    double window of the exact stage (its unbounded-exponent
//                    arithmetic); the static filter is off (subnormals).
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/timing.hpp"
#include "peers/cgal_predicates.hpp"
#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::bench::detail {

namespace {

using pred::Mode;
using pred::PointId;

struct Kind {
  const char* name;
  int k;        // points per call
  int dim;      // coordinates per point
  bool lifted;  // power predicate (weights, lifted height)
};

const Kind kKinds[] = {
    {"orient2d", 3, 2, false}, {"orient3d", 4, 3, false}, {"orient4d", 5, 4, false},
    {"orient5d", 6, 5, false}, {"orient6d", 7, 6, false}, {"power2d", 4, 2, true},
    {"power3d", 5, 3, true},   {"power4d", 6, 4, true},   {"power5d", 7, 5, true},
};

enum class Family { random, near, degenerate, extreme };
const Family kFamilies[] = {Family::random, Family::near, Family::degenerate, Family::extreme};
const char* family_name(Family f) {
  switch (f) {
    case Family::random: return "random";
    case Family::near: return "near-degenerate";
    case Family::degenerate: return "degenerate";
    default: return "extreme";
  }
}

// n calls' worth of points: call i uses points i*k .. i*k+k-1.
struct Calls {
  Kind kind;
  std::size_t n = 0;
  std::vector<double> coords;   // n * k * dim
  std::vector<double> weights;  // n * k (lifted kinds)
  std::vector<const double*> rows;  // n * k row pointers
  const double* const* p(std::size_t call) const { return rows.data() + call * kind.k; }
  const double* w(std::size_t call) const {
    return kind.lifted ? weights.data() + call * kind.k : nullptr;
  }
};

double jitter(double x, std::mt19937_64& rng) {
  const int ulps = static_cast<int>(rng() % 7) - 3;  // -3..3
  for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? HUGE_VAL : -HUGE_VAL);
  return x;
}

double extreme_value(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(1.0, 2.0);
  double v = 0.0;
  switch (rng() % 4) {
    case 0: v = std::ldexp(static_cast<double>(rng() >> 12), -1074); break;  // subnormal
    case 1: v = 1e-300 * unit(rng); break;
    case 2: v = unit(rng); break;
    default: v = 1e300 * unit(rng); break;
  }
  return (rng() & 1) ? -v : v;
}

Calls make_calls(const Kind& kind, Family fam, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), t(-0.5, 1.5), wdist(0.0, 0.01),
      s(-2.0, 2.0), center(0.25, 0.75), radius(0.1, 0.25);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_int_distribution<int> small(-8, 8), tint(-2, 2), coef(-3, 3);
  Calls c;
  c.kind = kind;
  c.n = n;
  const int k = kind.k, dim = kind.dim;
  c.coords.resize(n * k * dim);
  c.weights.assign(kind.lifted ? n * k : 0, 0.0);
  for (std::size_t call = 0; call < n; ++call) {
    auto P = [&](int j) { return c.coords.data() + (call * k + j) * dim; };
    double* W = kind.lifted ? c.weights.data() + call * k : nullptr;
    switch (fam) {
      case Family::random:
        for (int j = 0; j < k; ++j) {
          for (int d = 0; d < dim; ++d) P(j)[d] = unit(rng);
          if (W) W[j] = wdist(rng);
        }
        break;
      case Family::near:
        if (!kind.lifted) {
          for (int j = 0; j + 1 < k; ++j)
            for (int d = 0; d < dim; ++d) P(j)[d] = unit(rng);
          const double tt = t(rng);
          for (int d = 0; d < dim; ++d) P(k - 1)[d] = jitter(P(0)[d] + tt * (P(1)[d] - P(0)[d]), rng);
        } else {
          double cx[8], r = radius(rng);
          for (int d = 0; d < dim; ++d) cx[d] = center(rng);
          for (int j = 0; j < k; ++j) {
            double q[8];
            if (dim == 2) {
              const double u = s(rng);
              q[0] = (1 - u * u) / (1 + u * u);
              q[1] = 2 * u / (1 + u * u);
            } else if (dim == 3) {
              const double u = s(rng), v = s(rng), den = 1 + u * u + v * v;
              q[0] = 2 * u / den;
              q[1] = 2 * v / den;
              q[2] = (u * u + v * v - 1) / den;
            } else {
              double norm = 0.0;
              for (int d = 0; d < dim; ++d) {
                q[d] = gauss(rng);
                norm += q[d] * q[d];
              }
              norm = std::sqrt(norm);
              for (int d = 0; d < dim; ++d) q[d] /= norm;
            }
            for (int d = 0; d < dim; ++d) P(j)[d] = jitter(cx[d] + r * q[d], rng);
          }
        }
        break;
      case Family::degenerate:
        if (!kind.lifted) {
          for (int j = 0; j + 1 < k; ++j)
            for (int d = 0; d < dim; ++d) P(j)[d] = small(rng);
          const int tt = tint(rng);
          for (int d = 0; d < dim; ++d) P(k - 1)[d] = P(0)[d] + tt * (P(1)[d] - P(0)[d]);
        } else {
          int a[8];
          for (int d = 0; d < dim; ++d) a[d] = coef(rng);
          const int b = coef(rng);
          for (int j = 0; j < k; ++j) {
            double sq = 0.0, lin = b;
            for (int d = 0; d < dim; ++d) {
              P(j)[d] = small(rng);
              sq += P(j)[d] * P(j)[d];
              lin += a[d] * P(j)[d];
            }
            W[j] = sq - lin;  // |x|^2 - w = a.x + b: one hyperplane
          }
        }
        break;
      case Family::extreme:
        for (int j = 0; j < k; ++j) {
          for (int d = 0; d < dim; ++d) P(j)[d] = extreme_value(rng);
          if (W) W[j] = extreme_value(rng);
        }
        break;
    }
  }
  c.rows.resize(n * k);
  for (std::size_t i = 0; i < n * k; ++i) c.rows[i] = c.coords.data() + i * dim;
  return c;
}

volatile long g_sink = 0;  // keeps the timed loops from being optimised away

// Median over reps of the ns per call of body(i), i < n.
template <class Body>
double ns_per_call(std::size_t n, int reps, Body&& body) {
  std::vector<double> runs;
  for (int r = 0; r < reps; ++r) {
    long sum = 0;
    runs.push_back(seconds([&] {
      for (std::size_t i = 0; i < n; ++i) sum += body(i);
    }));
    g_sink = g_sink + sum;
  }
  return median(runs) / static_cast<double>(n) * 1e9;
}

struct Row {
  double flipflop = 0, stat = 0, dyn = 0, expansion = 0, cgal = -1, gmp = 0;
  double static_decides = 0, dynamic_decides = 0;
};

[[noreturn]] void disagree(const Kind& kind, Family f, const char* what, std::size_t i, int got,
                          int want) {
  throw std::runtime_error(std::string("flipflop bench predicates: ") + kind.name + ", " +
                           family_name(f) + ": " + what + " differs from GMP on call " +
                           std::to_string(i) + " (sign " + std::to_string(got) + ", expected " +
                           std::to_string(want) + ")");
}

// The default path as the algorithms call it (see flipflop_ns above).
inline int default_path(const pred::StaticFilter& f, const Kind& kind, const PointId* id, const double* const* p,
                        const double* w) {
  if (!kind.lifted && kind.k == 3) return pred::fast::orient2d(f, {id[0], p[0]}, {id[1], p[1]}, {id[2], p[2]});
  if (!kind.lifted && kind.k == 4 && kind.dim == 3)
    return pred::fast::orient3d(f, {id[0], p[0]}, {id[1], p[1]}, {id[2], p[2]}, {id[3], p[3]});
  if (kind.lifted && kind.dim == 2)
    return pred::fast::power2d(f, {id[0], p[0], w[0]}, {id[1], p[1], w[1]}, {id[2], p[2], w[2]}, {id[3], p[3], w[3]});
  if (kind.lifted && kind.dim == 3)
    return pred::fast::power3d(f, {id[0], p[0], w[0]}, {id[1], p[1], w[1]}, {id[2], p[2], w[2]},
                               {id[3], p[3], w[3]}, {id[4], p[4], w[4]});
  return pred::lambda_sign(&f, kind.k, id, p, w);
}

Row measure(const Kind& kind, Family fam, const Args& a) {
  const Calls c = make_calls(kind, fam, a.n, a.seed);
  const int k = kind.k;
  const pred::StaticFilter filter = pred::StaticFilter::for_points(
      c.coords.data(), c.n * k, kind.dim, kind.lifted ? c.weights.data() : nullptr);
  PointId ids[8];
  for (int j = 0; j < k; ++j) ids[j] = static_cast<PointId>(j);
  // ---- agreement with GMP, every call (nothing timed yet) ----
  std::vector<int> exact(c.n);
  std::size_t st_dec = 0, dyn_dec = 0;
  for (std::size_t i = 0; i < c.n; ++i) {
    const double* const* p = c.p(i);
    const double* w = c.w(i);
    exact[i] = pred::stage::gmp(k, p, w);
    const int st = pred::stage::static_filter(filter, k, p, w);
    const int ss = pred::stage::semi_static(k, p, w);
    const int dy = pred::stage::dynamic(k, p, w);
    if (st != 0 && st != exact[i]) disagree(kind, fam, "the static filter", i, st, exact[i]);
    if (ss != 0 && ss != exact[i]) disagree(kind, fam, "the semi-static filter", i, ss, exact[i]);
    if (dy != 0 && dy != exact[i]) disagree(kind, fam, "the dynamic filter", i, dy, exact[i]);
    st_dec += st != 0;
    dyn_dec += dy != 0;
    const int ex = pred::stage::expansion(k, p, w);
    if (ex != exact[i]) disagree(kind, fam, "the expansion stage", i, ex, exact[i]);
    const int ff = pred::lambda_sign(&filter, k, nullptr, p, w);
    if (ff != exact[i]) disagree(kind, fam, "the default path", i, ff, exact[i]);
    const int sos = pred::stage::gmp_sos(k, ids, p, w);
    const int ex_sos = pred::stage::expansion_sos(k, ids, p, w);
    if (ex_sos != sos) disagree(kind, fam, "the expansion stage with SoS", i, ex_sos, sos);
    const int ff_sos = pred::lambda_sign(&filter, k, ids, p, w);
    if (ff_sos != sos) disagree(kind, fam, "the default path with SoS", i, ff_sos, sos);
    const int typed = default_path(filter, kind, ids, p, w);
    if (typed != sos) disagree(kind, fam, "the typed default path (fast.hpp) with SoS", i, typed, sos);
  }
  Row r;
  r.static_decides = static_cast<double>(st_dec) / static_cast<double>(c.n);
  r.dynamic_decides = static_cast<double>(dyn_dec) / static_cast<double>(c.n);
  // ---- times ----
  r.flipflop = ns_per_call(c.n, a.reps, [&](std::size_t i) { return default_path(filter, kind, ids, c.p(i), c.w(i)); });
  r.stat = ns_per_call(c.n, a.reps, [&](std::size_t i) {
    return pred::stage::static_filter(filter, k, c.p(i), c.w(i));
  });
  r.dyn = ns_per_call(c.n, a.reps, [&](std::size_t i) {
    return pred::stage::dynamic(k, c.p(i), c.w(i));
  });
  r.expansion = ns_per_call(c.n, a.reps, [&](std::size_t i) {
    return pred::stage::expansion_sos(k, ids, c.p(i), c.w(i));
  });
  r.gmp = ns_per_call(c.n, a.reps, [&](std::size_t i) {
    return pred::stage::gmp_sos(k, ids, c.p(i), c.w(i));
  });
  if (peers::cgal_epick_has(k, kind.dim, kind.lifted)) {
    peers::PredicateCalls pc;
    pc.k = k;
    pc.dim = kind.dim;
    pc.lifted = kind.lifted;
    pc.n = c.n;
    pc.coords = c.coords.data();
    pc.weights = kind.lifted ? c.weights.data() : nullptr;
    std::vector<int> cg;
    const double s = peers::cgal_epick_run(pc, a.reps, cg);  // points converted before timing
    // CGAL's sign is (-1)^d times flipflop's (header comment), on every call.
    const int convention = kind.dim % 2 == 0 ? 1 : -1;
    for (std::size_t i = 0; i < c.n; ++i)
      if (cg[i] != convention * exact[i])
        disagree(kind, fam, "CGAL Epick", i, cg[i], convention * exact[i]);
    r.cgal = s / static_cast<double>(c.n) * 1e9;
  }
  return r;
}

std::string field(double v) {
  if (v < 0) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

}  // namespace

int bench_predicates(const Args& a) {
  if (a.csv) {
    std::printf(
        "predicate,input,flipflop_ns,static_ns,dynamic_ns,expansion_ns,cgal_epick_ns,gmp_ns,"
        "static_decides,dynamic_decides\n");
  } else {
    std::printf("flipflop bench predicates: %zu calls per run, median of %d runs, seed %llu (ns per call)\n",
                a.n, a.reps, a.seed);
    std::printf("machine: %s\n", machine_line().c_str());
    std::printf("%-9s %-16s %10s %9s %9s %10s %10s %10s %8s %8s\n", "predicate", "input", "flipflop",
                "static", "dynamic", "expansion", "cgal", "gmp", "static%", "dyn%");
  }
  for (const Kind& kind : kKinds)
    for (Family fam : kFamilies) {
      const Row r = measure(kind, fam, a);
      if (a.csv) {
        std::printf("%s,%s,%s,%s,%s,%s,%s,%s,%.4f,%.4f\n", kind.name, family_name(fam),
                    field(r.flipflop).c_str(), field(r.stat).c_str(), field(r.dyn).c_str(),
                    field(r.expansion).c_str(), field(r.cgal).c_str(), field(r.gmp).c_str(),
                    r.static_decides, r.dynamic_decides);
      } else {
        std::printf("%-9s %-16s %10.1f %9.1f %9.1f %10.1f %10s %10.1f %7.1f%% %7.1f%%\n", kind.name,
                    family_name(fam), r.flipflop, r.stat, r.dyn, r.expansion,
                    r.cgal < 0 ? "-" : field(r.cgal).c_str(), r.gmp, 100 * r.static_decides,
                    100 * r.dynamic_decides);
      }
      std::fflush(stdout);
    }
  return 0;
}

}  // namespace flipflop::bench::detail

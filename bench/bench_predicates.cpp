// bench_predicates.cpp — `flipflop bench predicates`: the cost of exactness.
//
// For each predicate of predicates.hpp (unperturbed *_exact forms) and two
// input families, the median time per call of Mode::filtered (ErrDouble filter,
// GMP only where the filter is uncertain) and of Mode::gmp (GMP always), their
// ratio, and the share of calls the filter alone decides (lambda_filter.hpp on
// the same inputs: the filter predicates.cpp runs first).
//
// Families:
//   random           coordinates uniform in [0, 1] (weights in [0, 0.01]).
//   near-degenerate  the last point is computed on the line through the first
//                    two (orient*), or all points on one circle / sphere
//                    (power*, zero weights), then every coordinate moved by
//                    -1, 0 or +1 ulp: the filter fails on most calls.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench/timing.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::bench::detail {

namespace {

using pred::Mode;

struct Kind {
  const char* name;
  int k;        // points per call
  int dim;      // coordinates per point
  bool lifted;  // power predicate (weights, lifted height)
};

const Kind kKinds[] = {
    {"orient2d", 3, 2, false}, {"orient3d", 4, 3, false}, {"power2d", 4, 2, true},
    {"power3d", 5, 3, true},   {"orient4d", 5, 4, false}, {"orient5d", 6, 5, false},
    {"orient6d", 7, 6, false},
};

// n calls' worth of points: call i uses points i*k .. i*k+k-1.
struct Calls {
  Kind kind;
  std::size_t n = 0;
  std::vector<double> coords;   // n * k * dim
  std::vector<double> weights;  // n * k (lifted kinds)
  const double* point(std::size_t call, int j) const {
    return coords.data() + (call * kind.k + static_cast<std::size_t>(j)) * kind.dim;
  }
  const double* weight(std::size_t call) const {
    return kind.lifted ? weights.data() + call * kind.k : nullptr;
  }
};

double jitter(double x, std::mt19937_64& rng) {
  switch (rng() % 3) {
    case 0: return std::nextafter(x, -HUGE_VAL);
    case 1: return std::nextafter(x, HUGE_VAL);
    default: return x;
  }
}

Calls make_calls(const Kind& kind, bool near_degenerate, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), t(-0.5, 1.5), w(0.0, 0.01),
      s(-2.0, 2.0), center(0.25, 0.75), radius(0.1, 0.25);
  Calls c;
  c.kind = kind;
  c.n = n;
  c.coords.resize(n * kind.k * kind.dim);
  c.weights.assign(kind.lifted ? n * kind.k : 0, 0.0);
  for (std::size_t call = 0; call < n; ++call) {
    auto P = [&](int j) { return c.coords.data() + (call * kind.k + j) * kind.dim; };
    if (!near_degenerate) {
      for (int j = 0; j < kind.k; ++j)
        for (int d = 0; d < kind.dim; ++d) P(j)[d] = unit(rng);
      if (kind.lifted)
        for (int j = 0; j < kind.k; ++j) c.weights[call * kind.k + j] = w(rng);
    } else if (!kind.lifted) {
      for (int j = 0; j + 1 < kind.k; ++j)
        for (int d = 0; d < kind.dim; ++d) P(j)[d] = unit(rng);
      const double tt = t(rng);
      for (int d = 0; d < kind.dim; ++d)
        P(kind.k - 1)[d] = jitter(P(0)[d] + tt * (P(1)[d] - P(0)[d]), rng);
    } else {
      // Rational parametrisation of the unit circle / sphere (inverse
      // stereographic projection), scaled and shifted, rounded, jittered.
      double cx[3], r = radius(rng);
      for (double& x : cx) x = center(rng);
      for (int j = 0; j < kind.k; ++j) {
        const double u = s(rng), v = s(rng);
        double q[3];
        if (kind.dim == 2) {
          q[0] = (1 - u * u) / (1 + u * u);
          q[1] = 2 * u / (1 + u * u);
        } else {
          const double den = 1 + u * u + v * v;
          q[0] = 2 * u / den;
          q[1] = 2 * v / den;
          q[2] = (u * u + v * v - 1) / den;
        }
        for (int d = 0; d < kind.dim; ++d) P(j)[d] = jitter(cx[d] + r * q[d], rng);
      }
    }
  }
  return c;
}

int call_exact(const Calls& c, std::size_t i, Mode m) {
  const double* p[8] = {};
  for (int j = 0; j < c.kind.k; ++j) p[j] = c.point(i, j);
  if (c.kind.lifted) {
    const double* w = c.weight(i);
    if (c.kind.dim == 2)
      return pred::power2d_exact({0, p[0], w[0]}, {1, p[1], w[1]}, {2, p[2], w[2]},
                                 {3, p[3], w[3]}, m);
    return pred::power3d_exact({0, p[0], w[0]}, {1, p[1], w[1]}, {2, p[2], w[2]},
                               {3, p[3], w[3]}, {4, p[4], w[4]}, m);
  }
  switch (c.kind.dim) {
    case 2: return pred::orient2d_exact(p[0], p[1], p[2], m);
    case 3: return pred::orient3d_exact(p[0], p[1], p[2], p[3], m);
    default: return pred::orient_d_exact(c.kind.dim, p, m);
  }
}

// Does the filter alone decide call i?
bool filter_decides(const Calls& c, std::size_t i) {
  const double* p[8] = {};
  for (int j = 0; j < c.kind.k; ++j) p[j] = c.point(i, j);
  const double* w = c.weight(i);
  switch (c.kind.k) {
    case 3: return pred::lambda_sign_filter<3>(p, w) != 0;
    case 4: return pred::lambda_sign_filter<4>(p, w) != 0;
    case 5: return pred::lambda_sign_filter<5>(p, w) != 0;
    case 6: return pred::lambda_sign_filter<6>(p, w) != 0;
    default: return pred::lambda_sign_filter<7>(p, w) != 0;
  }
}

volatile long g_sink = 0;  // keeps the timed loops from being optimised away

double median_ns_per_call(const Calls& c, Mode m, int reps) {
  std::vector<double> runs;
  for (int r = 0; r < reps; ++r) {
    long sum = 0;
    runs.push_back(seconds([&] {
      for (std::size_t i = 0; i < c.n; ++i) sum += call_exact(c, i, m);
    }));
    g_sink = g_sink + sum;
  }
  return median(runs) / static_cast<double>(c.n) * 1e9;
}

}  // namespace

int bench_predicates(const Args& a) {
  std::printf("flipflop bench predicates: %zu calls per run, median of %d runs, seed %llu\n",
              a.n, a.reps, a.seed);
  std::printf("%-9s %-16s %14s %14s %10s %15s\n", "predicate", "input", "filtered ns", "gmp ns",
              "gmp/filt", "filter decides");
  for (const Kind& kind : kKinds) {
    for (bool near : {false, true}) {
      Calls c = make_calls(kind, near, a.n, a.seed);
      std::size_t decided = 0;
      for (std::size_t i = 0; i < c.n; ++i) decided += filter_decides(c, i);
      // Both modes must agree on every call before their times mean anything.
      for (std::size_t i = 0; i < c.n; ++i)
        if (call_exact(c, i, Mode::filtered) != call_exact(c, i, Mode::gmp)) {
          std::fprintf(stderr, "flipflop bench: %s: filtered and gmp signs differ on call %zu\n",
                       kind.name, i);
          return 3;
        }
      const double f = median_ns_per_call(c, Mode::filtered, a.reps);
      const double g = median_ns_per_call(c, Mode::gmp, a.reps);
      std::printf("%-9s %-16s %14.1f %14.1f %10.1f %14.2f%%\n", kind.name,
                  near ? "near-degenerate" : "random", f, g, g / f,
                  100.0 * static_cast<double>(decided) / static_cast<double>(c.n));
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace flipflop::bench::detail

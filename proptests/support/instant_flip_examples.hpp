// instant_flip_examples.hpp — small constructed inputs for the chapter 9 tests:
// the "mother of all examples" (a non-regular triangulation of six points),
// lattice and cospherical point sets, and the concrete weight perturbation
// used to check perturbation orders independently of failure_time.cpp.
#pragma once

#include <gmpxx.h>

#include <vector>

#include "instant_flip_oracles.hpp"

namespace flipflop::test_if {

// Six points: an outer triangle 0 1 2 and an inner triangle 3 4 5 (point 3+i
// near i), both symmetric about the same vertical axis (no rotation).
inline PointSet mother_points() {
  PointSet ps;
  ps.dim = 2;
  ps.weighted = true;
  // outer triangle, centroid (6, 4); inner triangle mirror-symmetric about
  // x = 6 like the outer one (dyadic coordinates: every value exact)
  ps.coords = {0, 0, 12, 0, 6, 12, 4, 2.75, 8, 2.75, 6, 6.5};
  ps.weights.assign(6, 0.0);
  return ps;
}

// The twisted triangulation: the inner triangle, and around it each outer
// edge (i, i+1) with the inner vertex near i, then (i+1, inner i, inner i+1).
// It is not regular for any weights (the classical cyclic-dependence
// argument), so no time line of it is well-separated and no perturbation of a
// flat lifting makes it regular.
inline SimplexSet mother_twisted() {
  SimplexSet T;
  T.insert(sorted({3, 4, 5}));
  for (Index i = 0; i < 3; ++i) {
    const Index j = (i + 1) % 3;
    T.insert(sorted({i, j, static_cast<Index>(3 + i)}));
    T.insert(sorted({j, static_cast<Index>(3 + i), static_cast<Index>(3 + j)}));
  }
  return T;
}

// Weights lifting every point onto the plane h = 0: w = |x|^2 (exact for
// these dyadic coordinates). Every ridge is flat.
inline std::vector<double> flat_weights(const PointSet& ps) {
  std::vector<double> w(ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p) {
    double s = 0;
    for (int j = 0; j < ps.dim; ++j) s += ps.point(p)[j] * ps.point(p)[j];
    w[p] = s;
  }
  return w;
}

// The weight perturbation of thesis §9.2.2 with concrete values: point p's
// lifted height is raised by 2^(-bits·(rank(p)+1)) (this project's sign:
// + on the height). For inputs with small integer-like coordinates and
// bits = 40, the concrete value decides like the symbolic one.
inline std::vector<mpq_class> perturbed_heights(const PointSet& ps, const std::vector<double>& w,
                                                const std::vector<Index>& order, unsigned bits = 40) {
  std::vector<mpq_class> h = heights_q(ps, to_q(w));
  for (std::size_t r = 0; r < order.size(); ++r) {
    mpz_class den = 1;
    mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), static_cast<mp_bitcnt_t>(bits * (r + 1)));
    h[order[r]] += mpq_class(1, den);
  }
  return h;
}

// A grid of side k in R^d (integer coordinates 0..k-1) and 2^d generic far
// corners (so that no simplex of a triangulation is flat: collinear grid
// points are interior).
inline PointSet lattice_points(int d, int k) {
  PointSet ps;
  ps.dim = d;
  ps.weighted = true;
  std::vector<int> c(static_cast<std::size_t>(d), 0);
  while (true) {
    for (int x : c) ps.coords.push_back(x);
    int i = 0;
    while (i < d && ++c[static_cast<std::size_t>(i)] == k) c[static_cast<std::size_t>(i++)] = 0;
    if (i == d) break;
  }
  for (int m = 0; m < (1 << d); ++m)
    for (int j = 0; j < d; ++j) {
      const double lo = -3.0 - 0.125 * (m + 1) - 0.0625 * j, hi = k + 2.0 + 0.25 * (m + 1) + 0.0625 * j;
      ps.coords.push_back((m >> j) & 1 ? hi : lo);
    }
  ps.weights.assign(ps.size(), 0.0);
  return ps;
}

// Integer points on the circle x^2 + y^2 = 5525 (no three collinear).
inline PointSet circle_points() {
  PointSet ps;
  ps.dim = 2;
  ps.weighted = true;
  for (int x = -75; x <= 75; ++x)
    for (int y = -75; y <= 75; ++y)
      if (x * x + y * y == 5525) ps.coords.insert(ps.coords.end(), {double(x), double(y)});
  ps.weights.assign(ps.size(), 0.0);
  return ps;
}

// Integer points on the sphere x^2 + y^2 + z^2 = 1225, chosen greedily so that
// no four are coplanar (general position in R^3), at most `limit`.
inline PointSet sphere_points(std::size_t limit) {
  PointSet all;
  all.dim = 3;
  for (int x = -35; x <= 35; ++x)
    for (int y = -35; y <= 35; ++y)
      for (int z = -35; z <= 35; ++z)
        if (x * x + y * y + z * z == 1225) all.coords.insert(all.coords.end(), {double(x), double(y), double(z)});
  PointSet ps;
  ps.dim = 3;
  ps.weighted = true;
  for (std::size_t p = 0; p < all.size() && ps.size() < limit; ++p) {
    PointSet trial = ps;
    trial.coords.insert(trial.coords.end(), all.point(p), all.point(p) + 3);
    const Index q = static_cast<Index>(trial.size() - 1);
    bool ok = true;
    for (Index i = 0; i < q && ok; ++i)
      for (Index j = i + 1; j < q && ok; ++j)
        for (Index k = j + 1; k < q && ok; ++k) ok = orient_q(trial, {i, j, k, q}) != 0;
    if (ok) ps = trial;
  }
  ps.weights.assign(ps.size(), 0.0);
  return ps;
}

}  // namespace flipflop::test_if

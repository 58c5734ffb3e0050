// families.hpp — RapidCheck generators of point sets for the property suite
// (proptests/invariance_test.cpp), covering the degenerate families of the
// foundation issue.
//
//   family_points      (family, n, seed) -> gen::generate: every distribution
//                      of gen/ of the dimension (thesis distributions and the
//                      degenerate families grid, circle/sphere lattice,
//                      collinear, coplanar, duplicates, 1-ulp jitter, huge,
//                      tiny + subnormal), optionally weighted;
//   small_integers     coordinates in [-r, r], r <= 4: heavy degeneracy (many
//                      collinear / cocircular / coplanar subsets, duplicates),
//                      small integer weights, possibly all equal;
//   duplicated_except  d+1 .. d+3 distinct points, every other point a copy of
//                      one of them ("all points duplicated except 3");
//   flat_plus_one      all points on one line (plane in 3D) but one;
//   huge_tiny_mix      each point drawn at scale 2^997, 2^-997, 1, 0 or as
//                      subnormals: products overflow and underflow in one set;
//   wide_integers      integers in [-2^20, 2^20]: almost surely in general
//                      position (for the translation / permutation properties,
//                      which need it), integer weights up to 2^38.
// degenerate_points mixes all of them; general_position_candidates mixes
// the ones that are usually in general position (the properties check it
// exactly and discard the others).
// In R^d (d = 2..5, the d-dimensional regular triangulations) the same
// roles are played by degenerate_points_d / general_position_candidates_d /
// integer_candidates_d, which add
//   uniform_d          dyadic coordinates k·2^-20 in [0, 1)^d, weights
//                      k·2^-40 in [0, f] with f in {0, 1e-3, 1e-2, 0.1};
//   hyperplane_plus_one all points on an integer hyperplane but one;
//   cospherical_d      integer points of the sphere |x|^2 = 9 (and its
//                      centre): every d+2 of them on one sphere,
// and use gen/'s families where they exist (d = 2, 3).
//
// Shrinking. The family generators draw their seed without shrinking (a new
// seed is a new input, not a smaller one); instead the mixers
// (degenerate_points, general_position_candidates, integer_candidates) wrap
// their generators in `thinned`, which draws one "keep" flag per point that
// shrinks from true to false: RapidCheck's minimal counterexample is a subset
// (in index order, so the SoS order of the kept points is unchanged) that
// still fails and from which no single point can be removed. Coordinates of
// small_integers shrink towards 0.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <iomanip>
#include <ostream>
#include <random>
#include <utility>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "proptests/support/generated.hpp"
#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"

namespace flipflop {
// RapidCheck prints counterexamples with showValue (found by ADL).
inline void showValue(const PointSet& ps, std::ostream& os) {
  os << ps.size() << " points (dim " << ps.dim << (ps.weighted ? ", weighted" : "") << "):"
     << std::setprecision(17);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    os << " (";
    for (int c = 0; c < ps.dim; ++c) os << (c ? " " : "") << ps.point(i)[c];
    if (ps.weighted) os << "; w " << ps.weights[i];
    os << ")";
  }
}
}  // namespace flipflop

namespace flipflop::test {

// A 64-bit seed: uniform whatever RapidCheck's size, never shrunk.
inline rc::Gen<std::uint64_t> any_seed() {
  return rc::gen::noShrink(rc::gen::resize(100, rc::gen::arbitrary<std::uint64_t>()));
}

// Uniform in [lo, hi] whatever RapidCheck's size; shrinks towards lo.
template <typename T>
rc::Gen<T> uniform(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi + 1));
}

// An integer in [-m, m], uniform; shrinks towards 0 (magnitude, then sign).
inline rc::Gen<std::int64_t> symmetric(std::int64_t m) {
  return rc::gen::exec([m] {
    const std::int64_t a = *uniform<std::int64_t>(0, m);
    return *rc::gen::arbitrary<bool>() ? -a : a;
  });
}

// A point count in [nmin, nmax] that grows with RapidCheck's size (cheap
// cases first) and shrinks towards nmin.
inline rc::Gen<int> point_count(int nmin, int nmax) { return rc::gen::inRange(nmin, nmax + 1); }

// ---- plumbing -----------------------------------------------------------------

inline void add_point(PointSet& ps, const double* x) { ps.coords.insert(ps.coords.end(), x, x + ps.dim); }

// n points in [lo, lo + 1)^d from a fixed xorshift64 sequence (the same
// points on every run and build): large deterministic inputs.
inline PointSet xorshift_cube(int d, std::size_t n, double lo = 0.0) {
  PointSet ps;
  ps.dim = d;
  std::vector<double> c;
  c.reserve(n * static_cast<std::size_t>(d));
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(d); ++i) {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17;
    c.push_back(static_cast<double>(s >> 11) * 0x1p-53 + lo);
  }
  ps.coords = Values(std::move(c));
  return ps;
}

// The points of `keep` (in index order), weights included.
inline PointSet subset(const PointSet& ps, const std::vector<bool>& keep) {
  PointSet out;
  out.dim = ps.dim;
  out.weighted = ps.weighted;
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (keep[i]) {
      add_point(out, ps.point(i));
      if (ps.weighted) out.weights.push_back(ps.weights[i]);
    }
  return out;
}

// A flag that is true and shrinks to false.
inline rc::Gen<bool> kept() {
  return [](const rc::Random&, int) {
    return rc::shrinkable::shrinkRecur(true, [](bool b) { return b ? rc::seq::just(false) : rc::Seq<bool>(); });
  };
}

// g, with a keep flag per point: shrinking removes points (see the header).
inline rc::Gen<PointSet> thinned(rc::Gen<PointSet> g) {
  return rc::gen::exec([g] {
    const PointSet ps = *g;
    const auto keep = *rc::gen::container<std::vector<bool>>(ps.size(), kept());
    return subset(ps, keep);
  });
}

// Squared extent of the set (max over coordinates of (max - min)^2), in
// floating point, at most DBL_MAX; 1 when all points coincide.
inline double squared_extent(const PointSet& ps) {
  double e = 0;
  for (int c = 0; c < ps.dim; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      lo = std::min(lo, ps.point(i)[c]);
      hi = std::max(hi, ps.point(i)[c]);
    }
    if (hi > lo) e = std::max(e, std::min(DBL_MAX, (hi - lo) * (hi - lo)));
  }
  return e > 0 ? e : 1.0;
}

// ---- generators ---------------------------------------------------------------

inline std::vector<std::string> families(int dim) {
  std::vector<std::string> out;
  for (const std::string& d : gen::distributions())
    if (gen::dimension_of(d) == dim) out.push_back(d);
  return out;
}

// The deterministic sweeps of the kernel tests: f(family, n, seed, points) for
// gen::generate(family, n, seed) over every family of the dimension, every
// size and the seeds 1..seeds.
template <class F>
void for_each_family_input(int dim, std::initializer_list<std::size_t> sizes, std::uint64_t seeds, F&& f) {
  for (const std::string& fam : families(dim))
    for (std::size_t n : sizes)
      for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        gen::Options o;
        o.seed = seed;
        f(fam, n, seed, gen::generate(fam, n, o));
      }
}

// (family, n, seed) -> gen::generate. Weighted: weights uniform in
// [0, f · extent^2] with f in {0, 1e-6, 1e-3, 0.1} (all zero, few, some, many
// redundant points), drawn by gen::generate from its second engine.
// The deterministic form: family `fam`, n points, `seed`; when weighted,
// weights uniform in [0, f · extent^2].
inline PointSet family_input(const std::string& fam, std::size_t n, std::uint64_t seed, bool weighted, double f) {
  gen::Options o;
  o.seed = seed;
  PointSet ps = gen::generate(fam, n, o);
  if (weighted) {
    o.weighted = true;
    o.wlo = 0;
    o.whi = f * squared_extent(ps);
    ps = gen::generate(fam, n, o);
  }
  return ps;
}

inline rc::Gen<PointSet> family_points(const std::vector<std::string>& fams, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const std::string fam = *rc::gen::elementOf(fams);
    const int n = *point_count(nmin, nmax);
    const std::uint64_t seed = *any_seed();
    const double f = weighted ? *rc::gen::element(0.0, 1e-6, 1e-3, 0.1) : 0.0;
    return family_input(fam, static_cast<std::size_t>(n), seed, weighted, f);
  });
}
inline rc::Gen<PointSet> family_points(int dim, int nmin, int nmax, bool weighted) {
  return family_points(families(dim), nmin, nmax, weighted);
}

// Integer weights in [0, wmax] (all equal with probability 1/4).
inline std::vector<double> integer_weights(std::size_t n, std::int64_t wmax) {
  std::vector<double> w;
  const bool equal = *uniform(0, 3) == 0;
  const auto common = static_cast<double>(*uniform<std::int64_t>(0, wmax));
  for (std::size_t i = 0; i < n; ++i) w.push_back(equal ? common : static_cast<double>(*uniform<std::int64_t>(0, wmax)));
  return w;
}

// Coordinates in [-r, r], r in [1, 4]; weights (when weighted) in [0, r].
inline rc::Gen<PointSet> small_integers(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *point_count(nmin, nmax);
    const std::int64_t r = *uniform<std::int64_t>(1, 4);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n * dim; ++i) ps.coords.push_back(static_cast<double>(*symmetric(r)));
    if (weighted) {
      ps.weighted = true;
      ps.weights = integer_weights(ps.size(), r);
    }
    return ps;
  });
}

// d+1 .. d+3 distinct small-integer points, the others copies of them, in
// random order; weights per point (copies of a location may differ in
// weight, or not).
inline rc::Gen<PointSet> duplicated_except(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = std::max(*point_count(nmin, nmax), dim + 1);
    const int base = std::min(n, dim + 1 + *uniform(0, 2));
    std::vector<std::int64_t> b;
    for (int i = 0; i < base * dim; ++i) b.push_back(*symmetric(8));
    PointSet ps;
    ps.dim = dim;
    std::vector<int> which;
    for (int i = 0; i < n; ++i) which.push_back(i < base ? i : *uniform(0, base - 1));
    // Fisher–Yates with std::mt19937_64 (its sequence is fixed by the standard)
    std::mt19937_64 rng(*any_seed());
    for (int i = n - 1; i > 0; --i)
      std::swap(which[static_cast<std::size_t>(i)], which[rng() % static_cast<std::uint64_t>(i + 1)]);
    for (int w : which)
      for (int c = 0; c < dim; ++c) ps.coords.push_back(static_cast<double>(b[static_cast<std::size_t>(w * dim + c)]));
    if (weighted) {
      ps.weighted = true;
      ps.weights = integer_weights(ps.size(), 16);
    }
    return ps;
  });
}

// All points on a line (2D) or a plane (3D) with integer coordinates, and one
// point off it at a random position in the order.
inline rc::Gen<PointSet> flat_plus_one(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = std::max(*point_count(nmin, nmax), dim + 1);
    const int odd = *uniform(0, n - 1);
    std::int64_t o[3], u[3], v[3];
    for (int c = 0; c < 3; ++c) o[c] = *symmetric(100), u[c] = *symmetric(5), v[c] = *symmetric(5);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n; ++i) {
      const std::int64_t s = *symmetric(20), t = dim == 3 ? *symmetric(20) : 0;
      for (int c = 0; c < dim; ++c) {
        std::int64_t x = o[c] + s * u[c] + t * v[c];
        if (i == odd) x = *symmetric(200);
        ps.coords.push_back(static_cast<double>(x));
      }
    }
    if (weighted) {
      ps.weighted = true;
      ps.weights = integer_weights(ps.size(), 400);
    }
    return ps;
  });
}

// Each point at one scale: k·2^-52 (|k| < 2^52) times 2^997 (products
// overflow), 2^-997 (products underflow), 1, 0, or 2^-1060 (rounded to a
// subnormal). Weights: a quarter-multiple of the squared x of a random point
// of the set (clamped to the double range).
inline rc::Gen<PointSet> huge_tiny_mix(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *point_count(nmin, nmax);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n; ++i) {
      const int scale = *uniform(0, 4);
      for (int c = 0; c < dim; ++c) {
        const double u = static_cast<double>(*symmetric((std::int64_t{1} << 52) - 1)) * 0x1p-52;
        const double s[] = {0x1p997, 0x1p-997, 1.0, 0.0, 0x1p-1060};
        ps.coords.push_back(u * s[scale]);
      }
    }
    if (weighted) {
      ps.weighted = true;
      for (int i = 0; i < n; ++i) {
        const double* p = ps.point(static_cast<std::size_t>(*uniform(0, n - 1)));
        const double w = std::min(DBL_MAX, p[0] * p[0]);
        ps.weights.push_back(w * (static_cast<double>(*uniform(0, 4)) * 0.25));
      }
    }
    return ps;
  });
}

// Integers in [-2^20, 2^20]; weights (when weighted) integers in [0, 2^38],
// all zero with probability 1/4.
inline rc::Gen<PointSet> wide_integers(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *point_count(nmin, nmax);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n * dim; ++i) ps.coords.push_back(static_cast<double>(*symmetric(std::int64_t{1} << 20)));
    if (weighted) {
      ps.weighted = true;
      const bool zero = *uniform(0, 3) == 0;
      for (int i = 0; i < n; ++i)
        ps.weights.push_back(zero ? 0.0 : static_cast<double>(*uniform<std::int64_t>(0, std::int64_t{1} << 38)));
    }
    return ps;
  });
}

// One of the generators, chosen with the given weights (shrinks towards the
// first).
inline rc::Gen<PointSet> one_of(std::vector<std::pair<int, rc::Gen<PointSet>>> gens) {
  return rc::gen::exec([gens] {
    int total = 0;
    for (const auto& g : gens) total += g.first;
    int pick = *uniform(0, total - 1);
    std::size_t i = 0;
    while (pick >= gens[i].first) pick -= gens[i++].first;
    return *gens[i].second;
  });
}

// Every family above, n in [nmin, nmax], thinned.
inline rc::Gen<PointSet> degenerate_points(int dim, int nmin, int nmax, bool weighted) {
  return thinned(one_of({
      {6, family_points(dim, nmin, nmax, weighted)},
      {3, small_integers(dim, nmin, nmax, weighted)},
      {1, duplicated_except(dim, nmin, nmax, weighted)},
      {1, flat_plus_one(dim, nmin, nmax, weighted)},
      {1, huge_tiny_mix(dim, nmin, nmax, weighted)},
  }));
}

// Inputs that are usually in general position (the properties decide it
// exactly and discard the others): wide integers, the random thesis
// distributions, circle lattices in 2D (no three points collinear; every
// four cocircular, which only the triangulations care about), small integer
// sets of few points.
inline rc::Gen<PointSet> general_position_candidates(int dim, int nmin, int nmax, bool weighted) {
  const std::vector<std::string> random2 = {"square", "disk", "frame", "circle"};
  const std::vector<std::string> random3 = {"cube", "ball", "box", "sphere", "cball"};
  std::vector<std::pair<int, rc::Gen<PointSet>>> gens = {
      {6, wide_integers(dim, nmin, nmax, weighted)},
      {3, family_points(dim == 2 ? random2 : random3, nmin, nmax, weighted)},
      {1, small_integers(dim, dim + 1, dim + 3, weighted)},
  };
  if (dim == 2) gens.push_back({2, family_points({"circle-lattice"}, nmin, nmax, weighted)});
  return thinned(one_of(gens));
}

// Integer inputs only (translation property), usually in general position:
// wide integers, circle lattices (2D), small integer sets of few points.
inline rc::Gen<PointSet> integer_candidates(int dim, int nmin, int nmax, bool weighted) {
  std::vector<std::pair<int, rc::Gen<PointSet>>> gens = {
      {6, wide_integers(dim, nmin, nmax, weighted)},
      {1, small_integers(dim, dim + 1, dim + 3, weighted)},
  };
  if (dim == 2) gens.push_back({2, family_points({"circle-lattice"}, nmin, nmax, weighted)});
  return thinned(one_of(gens));
}

// ---- d-dimensional point sets (d = 2..5) --------------------------------------

// Dyadic coordinates k·2^-20 in [0, 1)^d (exact, almost surely in general
// position); weights k·2^-40 in [0, f], f in {0, 1e-3, 1e-2, 0.1}.
inline rc::Gen<PointSet> uniform_d(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *point_count(nmin, nmax);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n * dim; ++i)
      ps.coords.push_back(std::ldexp(static_cast<double>(*uniform<std::int64_t>(0, (1 << 20) - 1)), -20));
    if (weighted) {
      ps.weighted = true;
      const double f = *rc::gen::element(0.0, 1e-3, 1e-2, 0.1);
      const auto top = static_cast<std::int64_t>(std::ldexp(f, 40));
      for (int i = 0; i < n; ++i) ps.weights.push_back(std::ldexp(static_cast<double>(*uniform<std::int64_t>(0, top)), -40));
    }
    return ps;
  });
}

// All points on the integer hyperplane x_k = c + Σ_{j != k} a_j x_j (small
// integers a_j and c, free coordinates integers in [-8, 8]), and one point
// moved off it along x_k, at a random position in the order. Integer weights.
inline rc::Gen<PointSet> hyperplane_plus_one(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = std::max(*point_count(nmin, nmax), dim + 1);
    const int odd = *uniform(0, n - 1);
    const int k = *uniform(0, dim - 1);
    std::vector<std::int64_t> a(static_cast<std::size_t>(dim));
    for (auto& x : a) x = *symmetric(2);
    const std::int64_t c = *symmetric(10);
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n; ++i) {
      std::vector<double> x(static_cast<std::size_t>(dim));
      std::int64_t sum = c;
      for (int j = 0; j < dim; ++j)
        if (j != k) {
          const std::int64_t v = *symmetric(8);
          x[static_cast<std::size_t>(j)] = static_cast<double>(v);
          sum += a[static_cast<std::size_t>(j)] * v;
        }
      x[static_cast<std::size_t>(k)] = static_cast<double>(sum);
      if (i == odd) x[static_cast<std::size_t>(k)] += static_cast<double>(*uniform<std::int64_t>(1, 5));
      add_point(ps, x.data());
    }
    if (weighted) {
      ps.weighted = true;
      ps.weights = integer_weights(ps.size(), 40);
    }
    return ps;
  });
}

// The integer points of the sphere |x|^2 = 9 in R^d (cached per d).
inline const std::vector<std::vector<double>>& sphere9_points(int dim) {
  static std::vector<std::vector<double>> cache[16];  // dim <= 15
  auto& pts = cache[dim];
  if (pts.empty()) {
    std::vector<int> x(static_cast<std::size_t>(dim), -3);
    for (;;) {
      int r = 0;
      for (int v : x) r += v * v;
      if (r == 9) pts.emplace_back(x.begin(), x.end());
      int j = 0;
      while (j < dim && x[static_cast<std::size_t>(j)] == 3) x[static_cast<std::size_t>(j++)] = -3;
      if (j == dim) break;
      ++x[static_cast<std::size_t>(j)];
    }
  }
  return pts;
}

// n integer points of |x|^2 = 9 (repeats possible), the centre with
// probability 1/2; weights all 0 (cospherical: every lifted point on one
// hyperplane) or small integers.
inline rc::Gen<PointSet> cospherical_d(int dim, int nmin, int nmax, bool weighted) {
  return rc::gen::exec([=] {
    const int n = *point_count(nmin, nmax);
    const auto& sphere = sphere9_points(dim);
    const bool centre = *rc::gen::arbitrary<bool>();
    PointSet ps;
    ps.dim = dim;
    for (int i = 0; i < n; ++i) {
      if (centre && i == n / 2) {
        const std::vector<double> o(static_cast<std::size_t>(dim), 0.0);
        add_point(ps, o.data());
      } else {
        add_point(ps, sphere[static_cast<std::size_t>(*uniform<std::size_t>(0, sphere.size() - 1))].data());
      }
    }
    if (weighted) {
      ps.weighted = true;
      ps.weights = integer_weights(ps.size(), 3);
    }
    return ps;
  });
}

// Every d-dimensional family, thinned: gen/'s families where d = 2, 3, and
// the generators above.
inline rc::Gen<PointSet> degenerate_points_d(int dim, int nmin, int nmax, bool weighted) {
  std::vector<std::pair<int, rc::Gen<PointSet>>> gens = {
      {4, uniform_d(dim, nmin, nmax, weighted)},
      {3, small_integers(dim, nmin, nmax, weighted)},
      {1, duplicated_except(dim, nmin, nmax, weighted)},
      {1, hyperplane_plus_one(dim, nmin, nmax, weighted)},
      {2, cospherical_d(dim, nmin, nmax, weighted)},
      {1, huge_tiny_mix(dim, nmin, nmax, weighted)},
  };
  if (dim <= 3) gens.push_back({3, family_points(dim, nmin, nmax, weighted)});
  return thinned(one_of(gens));
}

// Usually in general position (coordinates and lifted points): wide
// integers, uniform dyadics, small integer sets of few points.
inline rc::Gen<PointSet> general_position_candidates_d(int dim, int nmin, int nmax, bool weighted) {
  return thinned(one_of({
      {4, wide_integers(dim, nmin, nmax, weighted)},
      {4, uniform_d(dim, nmin, nmax, weighted)},
      {1, small_integers(dim, dim + 1, dim + 3, weighted)},
  }));
}

// Integer input, usually in general position.
inline rc::Gen<PointSet> integer_candidates_d(int dim, int nmin, int nmax, bool weighted) {
  return thinned(one_of({
      {6, wide_integers(dim, nmin, nmax, weighted)},
      {1, small_integers(dim, dim + 1, dim + 3, weighted)},
  }));
}

// A dimension d in [dmin, dmax] (shrinks towards dmin), then g(d, n range of
// d, weighted or not at random). nmax_of(d) bounds n per dimension.
inline rc::Gen<PointSet> any_dimension(rc::Gen<PointSet> (*g)(int, int, int, bool), int dmin, int dmax,
                                       int (*nmax_of)(int)) {
  return rc::gen::exec([=] {
    const int d = *uniform(dmin, dmax);
    return *g(d, d + 1, nmax_of(d), *rc::gen::arbitrary<bool>());
  });
}

}  // namespace flipflop::test

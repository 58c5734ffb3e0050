// planar_inputs.hpp — shared inputs of the 2D triangulation and certifier tests.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <ostream>
#include <random>
#include <vector>

#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/dimension.hpp"
#include "reference/point_set.hpp"

namespace flipflop {
// counterexamples printed by RapidCheck
inline void showValue(const PointSet& ps, std::ostream& os) {
  os << ps.size() << " points:";
  for (std::size_t i = 0; i < ps.size(); ++i) {
    os << " (";
    for (int j = 0; j < ps.dim; ++j) os << (j ? " " : "") << ps.point(i)[j];
    if (ps.weighted) os << " w=" << ps.weights[i];
    os << ")";
  }
}
}  // namespace flipflop

namespace flipflop::test {

inline bool spans(const PointSet& ps) {
  return ps.size() >= static_cast<std::size_t>(ps.dim) + 1 && dimension_problem(ps).empty();
}

// Small sets: integer coordinates in [0, r] (collinear, cocircular and
// duplicate points) with small integer weights, or random doubles with weights.
inline rc::Gen<PointSet> gen_small_points(int dim, int nmin, int nmax, bool weighted, int rmax = 5) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(nmin, nmax + 1);
    const bool integer = *rc::gen::arbitrary<bool>();
    const int r = *rc::gen::inRange(1, rmax + 1);
    PointSet ps;
    ps.dim = dim;
    ps.weighted = weighted;
    for (int i = 0; i < dim * n; ++i)
      ps.coords.push_back(integer ? double(*rc::gen::inRange(0, r + 1))
                                  : *rc::gen::inRange(-1000000, 1000001) / 1048576.0);
    for (int i = 0; weighted && i < n; ++i)
      ps.weights.push_back(integer ? double(*rc::gen::inRange(0, 4)) : *rc::gen::inRange(0, 1000) / 4096.0);
    return ps;
  });
}

inline int orient_sos(const PointSet& ps, Index a, Index b, Index c) {
  return pred::orient2d({a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)});
}

// A triangulation of conv(S) with every point a vertex: the fan of the
// (perturbed) hull, then the other points inserted in a random order by 1-3
// splits, no flips — a deliberately bad starting triangulation.
inline std::vector<Triangle> random_insertion(const PointSet& ps, std::uint64_t seed) {
  const std::vector<Index> h = brute::hull2(ps);
  std::vector<Triangle> t;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) t.push_back({h[0], h[i], h[i + 1]});
  std::vector<Index> order;
  for (Index i = 0; i < ps.size(); ++i)
    if (std::find(h.begin(), h.end(), i) == h.end()) order.push_back(i);
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  for (Index p : order) {
    std::size_t k = 0;
    while (!(orient_sos(ps, t[k][0], t[k][1], p) > 0 && orient_sos(ps, t[k][1], t[k][2], p) > 0 &&
             orient_sos(ps, t[k][2], t[k][0], p) > 0))
      ++k;
    const Triangle x = t[k];
    t[k] = {x[0], x[1], p};
    t.push_back({x[1], x[2], p});
    t.push_back({x[2], x[0], p});
  }
  return t;
}

}  // namespace flipflop::test

// strict_rtd.cpp — the strict view of a d-dimensional regular triangulation
// (see strict_rtd.hpp for the rule and why it holds).
#include "reference/rtd/strict_rtd.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "predicates/predicates.hpp"
#include "reference/rt2/strict_rt2.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::ref {

std::vector<std::vector<Index>> strict_rtd(const PointSet& ps, const std::vector<std::vector<Index>>& canonical) {
  const int d = ps.dim;
  if (d < 2 || d > 5) throw std::invalid_argument("strict view: the dimension must be 2 to 5");  // power_d_pulled: d <= 5
  std::vector<Index> V;
  for (const auto& t : canonical) {
    if (t.size() != static_cast<std::size_t>(d + 1))
      throw std::invalid_argument("strict view: a simplex of " + std::to_string(t.size()) + " vertices in R^" +
                                  std::to_string(d));
    for (Index x : t) {
      if (x >= ps.size())
        throw std::invalid_argument("strict view: simplex vertex " + std::to_string(x) + " is not an input point");
      V.push_back(x);
    }
  }
  std::sort(V.begin(), V.end());
  V.erase(std::unique(V.begin(), V.end()), V.end());
  if (V.size() < static_cast<std::size_t>(d + 1))
    throw std::invalid_argument("strict view: fewer than d+1 vertices");

  if (d == 2) {  // the view of rt2|dt2 --strict (canonical_d.hpp: the same canonical form)
    std::vector<Triangle> tris;
    tris.reserve(canonical.size());
    for (const auto& t : canonical) tris.push_back({t[0], t[1], t[2]});
    std::vector<std::vector<Index>> out;
    for (const Triangle& t : strict_rt2(ps, tris)) out.push_back({t[0], t[1], t[2]});
    return out;
  }

  // The vertices alone, in index order: the ranks of their indices — which
  // is all the perturbations use — are unchanged.
  PointSet sub;
  sub.dim = d;
  sub.weighted = ps.weighted;
  std::vector<double> coords, weights;
  coords.reserve(V.size() * static_cast<std::size_t>(d));
  for (Index v : V) {
    coords.insert(coords.end(), ps.point(v), ps.point(v) + d);
    if (ps.weighted) weights.push_back(ps.weight(v));
  }
  sub.coords = std::move(coords);
  if (ps.weighted) sub.weights = std::move(weights);

  const rtd::TriangulationD T = build_rtd(sub, nullptr, /*pulled=*/true);
  std::vector<std::vector<Index>> out;
  for (std::vector<Index> t : rtd::real_simplices(T)) {  // canonical, in sub's indices
    const double* p[rtd::kMaxDim + 1];
    for (int i = 0; i <= d; ++i) p[i] = sub.point(t[static_cast<std::size_t>(i)]);
    if (pred::orient_d_exact(d, p) == 0) continue;  // flat: on the hull boundary (strict_rtd.hpp, 2.)
    for (Index& x : t) x = V[x];                    // increasing: the canonical form is kept
    out.push_back(std::move(t));
  }
  return out;  // sorted: the map is increasing
}

}  // namespace flipflop::ref

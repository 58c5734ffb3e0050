// rtd_oracles.hpp — exact oracles for d-dimensional regular triangulations
// and the instant flip, shared by the property suite (regressions.hpp), the
// instant-flip tests and the fuzzer (fuzz/rtd_check.cpp); no RapidCheck.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::test {

using Simplices = std::vector<std::vector<Index>>;

// Calls f(tuple) for every increasing k-subset of 0..n-1 until f returns
// false; returns false when it was stopped.
template <class F>
bool for_each_subset(std::size_t n, int k, F f) {
  const auto K = static_cast<std::size_t>(k);
  if (n < K) return true;
  std::vector<Index> t(K);
  std::iota(t.begin(), t.end(), Index{0});
  for (;;) {
    if (!f(t)) return false;
    std::size_t i = K;
    while (i > 0 && t[i - 1] == n - K + (i - 1)) --i;
    if (i == 0) return true;
    ++t[i - 1];
    for (std::size_t j = i; j < K; ++j) t[j] = t[j - 1] + 1;
  }
}

// The binary exponent of the largest squared coordinate extent (0 when all
// points coincide): the scale of weights that matter for these points.
inline int squared_extent_exponent(const PointSet& ps) {
  double ext = 0;
  for (int c = 0; c < ps.dim; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < ps.size(); ++i) lo = std::min(lo, ps.point(i)[c]), hi = std::max(hi, ps.point(i)[c]);
    if (hi > lo) ext = std::max(ext, std::min(DBL_MAX, (hi - lo) * (hi - lo)));
  }
  return ext > 0 ? std::ilogb(ext) : 0;
}

// Exact (unperturbed) orientation and lifted power test of the points t.
inline int orient_exact(const PointSet& ps, const std::vector<Index>& t) {
  const double* x[pred::kMaxLambdaK];
  for (std::size_t i = 0; i < t.size(); ++i) x[i] = ps.point(t[i]);
  return pred::orient_d_exact(ps.dim, x);
}

inline int power_exact(const PointSet& ps, const std::vector<Index>& t) {
  const double* x[pred::kMaxLambdaK];
  double w[pred::kMaxLambdaK];
  for (std::size_t i = 0; i < t.size(); ++i) x[i] = ps.point(t[i]), w[i] = ps.weight(t[i]);
  return pred::power_d_exact(ps.dim, x, w);
}

inline std::set<Index> simplex_vertices(const Simplices& s) {
  std::set<Index> v;
  for (const auto& t : s) v.insert(t.begin(), t.end());
  return v;
}

// RT(V ⊕ U) of the points V by a fresh construction on the subset (indices in
// increasing order: the Simulation of Simplicity orders them alike), mapped
// back to input indices.
inline Simplices fresh_on(const PointSet& ps, const std::vector<double>& u, const std::vector<Index>& V) {
  PointSet sub;
  sub.dim = ps.dim;
  sub.weighted = true;
  for (Index v : V) {
    sub.coords.insert(sub.coords.end(), ps.point(v), ps.point(v) + ps.dim);
    sub.weights.push_back(u[v]);
  }
  Simplices out;
  for (auto t : ref::rtd_incremental(sub).simplices) {
    for (Index& x : t) x = V[x];
    out.push_back(t);
  }
  return canonical_simplices(std::move(out), Orientation::volume);  // a relabelling keeps the (geometric) orientation
}

// What any regular triangulation of a subset of V for the weights U (under
// any perturbation) satisfies, checked exactly on its simplices of non-zero
// volume: when there is no flat simplex, it tiles the hull of its vertices
// (certify::rtd_detail::tiling_problem); every interior ridge between two
// such simplices is convex or flat (power_d_exact <= 0 for the positively
// oriented C1 and the opposite vertex); every point of V that is not a
// vertex lies in such a simplex (they cover the hull) whose lifted
// hyperplane does not pass strictly below its lifted point; no vertex is
// outside V. Empty when all holds.
inline std::string weak_regularity_problem(const PointSet& pu, Simplices out, const std::vector<Index>& V) {
  const std::set<Index> vs = simplex_vertices(out), allowed(V.begin(), V.end());
  for (Index x : vs)
    if (!allowed.count(x)) return "vertex " + std::to_string(x) + " is not a vertex of RT(S+W)";
  Simplices full;  // the simplices of non-zero volume, positively oriented
  for (auto t : out) {
    const int o = orient_exact(pu, t);
    if (o < 0) std::swap(t[0], t[1]);
    if (o != 0) full.push_back(t);
  }
  if (full.size() == out.size())
    if (std::string why = certify::rtd_detail::tiling_problem(pu, full); !why.empty()) return "not a tiling: " + why;
  std::map<std::vector<Index>, std::vector<std::size_t>> by_ridge;
  for (std::size_t s = 0; s < full.size(); ++s)
    for (std::size_t i = 0; i < full[s].size(); ++i) {
      std::vector<Index> f = full[s];
      f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
      std::sort(f.begin(), f.end());
      by_ridge[f].push_back(s);
    }
  for (const auto& [f, ss] : by_ridge) {
    if (ss.size() != 2) continue;
    std::vector<Index> t = full[ss[0]];
    for (Index b : full[ss[1]])
      if (!std::binary_search(f.begin(), f.end(), b)) t.push_back(b);
    if (power_exact(pu, t) > 0) return "a reflex interior ridge";
  }
  for (Index x : V) {
    if (vs.count(x)) continue;
    bool ok = false, found = false;
    for (const auto& t : full) {
      bool inside = true;
      for (std::size_t i = 0; i < t.size() && inside; ++i) {
        std::vector<Index> q = t;
        q[i] = x;
        inside = orient_exact(pu, q) >= 0;
      }
      if (!inside) continue;
      std::vector<Index> q = t;
      q.push_back(x);
      found = true;
      ok = power_exact(pu, q) <= 0;
      break;  // the lifted surface is one continuous function: any containing simplex decides
    }
    if (!found) return "point " + std::to_string(x) + " of RT(S+W) lies in no simplex";
    if (!ok) return "point " + std::to_string(x) + " of RT(S+W) left out although not redundant";
  }
  return "";
}

}  // namespace flipflop::test

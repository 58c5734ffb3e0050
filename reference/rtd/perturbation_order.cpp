// perturbation_order.cpp — thesis §9.2.3, Algorithm 15 (see the header).
#include "reference/rtd/perturbation_order.hpp"

#include <functional>
#include <queue>
#include <string>

namespace flipflop::ref {

namespace {

std::string ridge_name(const RidgeLink& r, int d) {
  std::string s = "ridge {";
  for (int i = 0; i < d; ++i) s += (i ? " " : "") + std::to_string(r.v[static_cast<std::size_t>(i)]);
  return s + "} with link {" + std::to_string(r.a) + " " + std::to_string(r.b) + "}";
}

}  // namespace

PerturbationOrderResult find_perturbation_order(const PointSet& ps, const std::vector<double>& w,
                                                const std::vector<std::vector<Index>>& simplices) {
  const int d = ps.dim;
  const std::size_t n = ps.size();
  const MovingModel mm(ps, w, w);  // only t = 0 is used
  const std::vector<RidgeLink> ridges = interior_ridges(d, n, simplices);

  PerturbationOrderResult res;
  res.interior_ridges = ridges.size();

  // Lines 1-9. For a flat ridge F: S_p(F), S_n(F) by the signs of c_F(p).
  struct Flat {
    std::vector<Index> neg;  // S_n(F)
    bool perturbed = false;
  };
  std::vector<Flat> flat;
  std::vector<std::size_t> neg_degree(n, 0);
  std::vector<std::vector<std::size_t>> pos_ridges(n);
  for (const RidgeLink& r : ridges) {
    const RidgeMotion m = ridge_motion(mm, r.v.data(), r.a, r.b);
    const int s = exact_sign(m, 0);
    if (s > 0) continue;  // convex: perturbed(F) = true (line 9)
    if (s < 0) {
      res.reason = ridge_name(r, d) + " is reflex under W: the triangulation is not regular";
      return res;
    }
    Flat f;
    const std::size_t id = flat.size();
    for (int i = 0; i < m.rows(); ++i) {
      const Index p = m.pts[static_cast<std::size_t>(i)];
      const int c = coefficient_sign(m, i);
      if (c < 0) {
        f.neg.push_back(p);
        ++neg_degree[p];  // line 6
      } else if (c > 0) {
        pos_ridges[p].push_back(id);  // line 7
      }
    }
    flat.push_back(std::move(f));
  }
  res.flat_ridges = flat.size();

  // Line 10: Q <- points with negDegree 0 (smallest index first).
  std::priority_queue<Index, std::vector<Index>, std::greater<Index>> q;
  for (std::size_t p = 0; p < n; ++p)
    if (neg_degree[p] == 0) q.push(static_cast<Index>(p));
  std::vector<Index> order;
  order.reserve(n);
  while (!q.empty()) {  // lines 11-19
    const Index p = q.top();
    q.pop();
    order.push_back(p);
    for (std::size_t id : pos_ridges[p]) {
      Flat& f = flat[id];
      if (f.perturbed) continue;
      f.perturbed = true;
      for (Index x : f.neg)
        if (--neg_degree[x] == 0) q.push(x);
    }
  }
  if (order.size() == n) {
    res.order = PerturbationOrder::from_order(std::move(order));
    return res;
  }
  // Theorem 9.5: the points left cannot be ordered.
  for (std::size_t p = 0; p < n; ++p)
    if (neg_degree[p] > 0) res.blocked_points.push_back(static_cast<Index>(p));
  std::size_t unresolved = 0;
  for (const Flat& f : flat) unresolved += f.perturbed ? 0 : 1;
  res.reason = "no perturbation order makes the triangulation strongly regular: " +
               std::to_string(unresolved) + " of " + std::to_string(flat.size()) +
               " flat ridges cannot be made convex (" + std::to_string(res.blocked_points.size()) +
               " points blocked; Theorem 9.5)";
  return res;
}

}  // namespace flipflop::ref

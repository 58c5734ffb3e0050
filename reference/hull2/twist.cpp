// twist.cpp — the twist algorithm, thesis §8.3, Algorithm 11 (see twist.hpp).
#include "reference/hull2/twist.hpp"

#include <deque>
#include <utility>

#include "reference/checked.hpp"

namespace flipflop::ref {

Twist::Twist(const StarKernel& s, std::vector<Index> polygon) : s_(s), order_(std::move(polygon)) {
  require_polygon(s_.points(), order_, "twist");
  pos_.assign(s_.points().size(), 0);
  for (std::size_t k = 0; k < order_.size(); ++k) pos_[order_[k]] = k;
}

bool Twist::is_edge(Index p, Index q) const {
  const std::size_t n = order_.size();
  if (p >= pos_.size() || q >= pos_.size() || order_[pos_[p]] != p || order_[pos_[q]] != q) return false;
  return (pos_[p] + 1) % n == pos_[q];
}

bool Twist::needs_twist(Index p, Index q) const {
  // line 5: if q is the first vertex of P then continue
  if (pos_[q] == 0) return false;
  const PointSet& ps = s_.points();
  const int o = s_.orient(p, q);  // orientation of △spq
  // line 6: (s.y - p.y)(s.y - q.y) < 0 — p and q on opposite sides of the
  // horizontal line through s — and △spq, △s'pq differ in orientation, with
  // orient2d(s', p, q) = sign(p.y - q.y) for s' = (+∞, s.y) (line 1).
  const bool opposite_sides = s_.compare_y(p) != s_.compare_y(q);
  const bool crosses_gamma = opposite_sides && o != compare_coord(ps, p, q, 1);
  if (crosses_gamma) return o > 0;  // lines 7-9: twist if △spq is counter-clockwise
  return o < 0;                     // lines 10-13: twist if △spq is clockwise
}

std::vector<std::size_t> Twist::applicable() const {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k + 1 < order_.size(); ++k)
    if (needs_twist(order_[k], order_[k + 1])) out.push_back(k);
  return out;
}

void Twist::swap_at(std::size_t k) {
  const Index p = order_[k], q = order_[k + 1];
  // Theorem 8.1: a twist swaps one adjacent pair out of g-order (one inversion
  // of the bubble sort), decided here by the independent comparator.
  FF_CHECK(s_.angle_less(q, p), "twist on an edge p -> q with g(p) < g(q)");
  std::swap(order_[k], order_[k + 1]);
  pos_[p] = k + 1;
  pos_[q] = k;
}

void Twist::apply(std::size_t k) {
  if (k + 1 >= order_.size()) throw std::invalid_argument("Twist::apply: no edge at this position");
  FF_CHECK(needs_twist(order_[k], order_[k + 1]), "twist on an edge that fails the local check");
  swap_at(k);
}

void Twist::run(Hull2Stats* stats) {
  const std::size_t n = order_.size();
  std::size_t twists = 0, checks = 0;
  // line 1 (s' = (+∞, s.y)) is folded into needs_twist.
  // line 2: Q <- all oriented edges of P
  std::deque<std::pair<Index, Index>> queue;
  for (std::size_t k = 0; k < n; ++k) queue.emplace_back(order_[k], order_[(k + 1) % n]);
  while (!queue.empty()) {  // line 3
    const auto [p, q] = queue.front();  // line 4
    queue.pop_front();
    // An edge pushed earlier may have been destroyed by a later twist; it is
    // not an edge of P any more and there is nothing to check.
    if (!is_edge(p, q)) continue;
    ++checks;
    if (!needs_twist(p, q)) continue;  // lines 5-7, 10-11
    const std::size_t k = pos_[p];
    swap_at(k);  // lines 8, 12: twist p -> q, now ... r, q, p, t ...
    ++twists;
    // lines 9, 13: push r -> q and p -> t, the edges adjacent to q -> p
    const Index r = order_[(k + n - 1) % n], t = order_[(k + 2) % n];
    queue.emplace_back(r, q);
    queue.emplace_back(p, t);
  }
  if (stats) {
    stats->twists += twists;
    stats->twist_checks += checks;
  }
}

std::vector<Index> twist_to_star(const PointSet& ps, std::vector<Index> polygon,
                                 const pred::RationalPoint& kernel, Hull2Stats* stats) {
  require_polygon(ps, polygon, "twist_to_star");
  Twist tw(StarKernel(ps, kernel), std::move(polygon));
  tw.run(stats);
  // Theorem 8.1 (needs the kernel strictly inside the hull of the vertices)
  FF_CHECK(is_star_shaped(tw.kernel(), tw.order()),
           "twist result is not star-shaped w.r.t. its kernel (is the kernel inside the hull?)");
  return tw.order();
}

}  // namespace flipflop::ref

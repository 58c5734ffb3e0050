// flip_pop.cpp — flip-pop, thesis §4.1, Algorithm 1 (see flip_pop.hpp).
#include "reference/hull2/flip_pop.hpp"

#include <stdexcept>

#include "reference/checked.hpp"

namespace flipflop::ref {

FlipPop::FlipPop(const StarKernel& s, const std::vector<Index>& polygon) : ps_(&s.points()), s_(s) {
  require_polygon(*ps_, polygon, "flip_pop");
  link(polygon);
  FF_CHECK(structure_holds(), "flip-pop input is not a counter-clockwise polygon star-shaped w.r.t. its kernel");
}

FlipPop::FlipPop(const PointSet& ps, const ChainPolygon& chains)
    : ps_(&ps), left_(chains.left), right_(chains.right) {
  require_polygon(ps, chains.polygon, "flip_pop (chains)");
  link(chains.polygon);
  if (!on_polygon(left_) || !on_polygon(right_) || left_ == right_)
    throw std::invalid_argument("flip_pop (chains): v_l and v_r must be two vertices of the polygon");
  FF_CHECK(structure_holds(), "flip-pop input chains are not x-monotone between v_l and v_r");
}

void FlipPop::link(const std::vector<Index>& polygon) {
  const std::size_t n = ps_->size(), m = polygon.size();
  prev_.assign(n, 0);
  next_.assign(n, 0);
  on_.assign(n, 0);
  removed_.assign(n, 0);
  for (std::size_t k = 0; k < m; ++k) {
    const Index v = polygon[k];
    prev_[v] = polygon[(k + m - 1) % m];
    next_[v] = polygon[(k + 1) % m];
    on_[v] = 1;
  }
  input_order_ = polygon;
  size_ = m;
}

bool FlipPop::removable(Index v) const {
  if (!on_polygon(v)) return false;
  const PointSet& ps = *ps_;
  const Index j = prev_[v], k = next_[v];  // line 4: edges p_j -> v and v -> p_k
  if (s_) {
    // line 5, kernel point s: v ∈ △ s p_j p_k strictly (SoS: never on an edge).
    // The three edge tests, cheapest first (the two with s hold on any star-
    // shaped polygon; they are evaluated anyway, as the thesis' test reads).
    return orient(ps, j, k, v) > 0 && s_->orient(j, v) > 0 && s_->orient(v, k) > 0;
  }
  // line 5, chain kernels (0, ∓∞): v strictly inside the vertical strip of p_j
  // p_k and strictly on the kernel side of the line p_j p_k. v_l and v_r end
  // both chains and are extreme: never candidates (§4.2).
  if (v == left_ || v == right_) return false;
  return compare_coord(ps, j, v, 0) == compare_coord(ps, v, k, 0) && orient(ps, j, k, v) > 0;
}

std::vector<Index> FlipPop::applicable() const {
  std::vector<Index> out;
  for (Index v : polygon())
    if (removable(v)) out.push_back(v);
  return out;
}

void FlipPop::apply(Index v) {
  FF_CHECK(on_polygon(v), "2-1 flip on a vertex that is not on the polygon (a removed vertex reappeared)");
  FF_CHECK(removable(v), "2-1 flip on a vertex that fails the local check p_i ∈ △ s p_j p_k");
  // line 6: replace p_j -> v -> p_k by p_j -> p_k
  const Index j = prev_[v], k = next_[v];
  next_[j] = k;
  prev_[k] = j;
  on_[v] = 0;
  removed_[v] = 1;
  --size_;
  FF_CHECK(structure_holds(), "the polygon is no longer star-shaped w.r.t. its kernel after a 2-1 flip");
  FF_CHECK(no_removed_vertex(), "a removed vertex is on the polygon again");
}

void FlipPop::run(Hull2Stats* stats) {
  std::size_t flips = 0, rounds = 0;
  // line 1: label all the vertices as unchecked
  std::vector<char> unchecked(ps_->size(), 0);
  std::vector<Index> pass = polygon(), next_pass;
  for (Index v : pass) unchecked[v] = 1;
  // lines 2-10: repeat passes over the unchecked vertices until none is left.
  // The labels form the candidate container of the sequential workflow
  // (Fig 3.1): a vertex labelled unchecked during a pass that has not reached
  // it yet is handled in this pass, otherwise in the next.
  while (!pass.empty()) {
    ++rounds;
    next_pass.clear();
    for (Index v : pass) {  // line 3
      if (!on_[v] || !unchecked[v]) continue;
      const Index j = prev_[v], k = next_[v];  // line 4
      if (removable(v)) {                      // line 5
        apply(v);                              // line 6
        ++flips;
        for (Index u : {j, k})  // line 7: label p_j and p_k as unchecked
          if (!unchecked[u]) {
            unchecked[u] = 1;
            next_pass.push_back(u);
          }
      } else {
        unchecked[v] = 0;  // line 9: label p_i as checked
      }
    }
    pass.swap(next_pass);
  }
  // line 10: every vertex is checked — no valid candidate is left
  FF_CHECK(applicable().empty(), "flip-pop stopped with a valid candidate left");
  if (stats) {
    stats->flips_2_1 += flips;
    stats->rounds += rounds;
    stats->polygon_vertices += input_order_.size();
  }
}

std::vector<Index> FlipPop::polygon() const {
  std::vector<Index> out;
  if (size_ == 0) return out;
  Index start = 0;
  for (Index v : input_order_)
    if (on_[v]) {
      start = v;
      break;
    }
  out.reserve(size_);
  Index v = start;
  do {
    out.push_back(v);
    v = next_[v];
  } while (v != start && out.size() <= size_);
  return out;
}

bool FlipPop::no_removed_vertex() const {
  for (Index u : polygon())
    if (removed_[u]) return false;
  return true;
}

bool FlipPop::structure_holds() const {
  const std::vector<Index> poly = polygon();
  if (poly.size() != size_) return false;
  if (s_) return is_star_shaped(*s_, poly);
  // chains: v_r -> ... -> v_l strictly decreasing in x, v_l -> ... -> v_r increasing
  if (!on_polygon(left_) || !on_polygon(right_)) return false;
  for (Index v = right_; v != left_; v = next_[v])
    if (compare_coord(*ps_, next_[v], v, 0) >= 0) return false;
  for (Index v = left_; v != right_; v = next_[v])
    if (compare_coord(*ps_, next_[v], v, 0) <= 0) return false;
  return true;
}

std::vector<Index> flip_pop(const PointSet& ps, std::vector<Index> star_polygon_ccw,
                            const pred::RationalPoint& kernel, Hull2Stats* stats) {
  require_polygon(ps, star_polygon_ccw, "flip_pop");
  FlipPop fp(StarKernel(ps, kernel), star_polygon_ccw);
  fp.run(stats);
  std::vector<Index> hull = rotate_to_smallest(fp.polygon());
  if (stats) stats->hull_vertices = hull.size();
  return hull;
}

std::vector<Index> flip_pop(const PointSet& ps, const ChainPolygon& chains, Hull2Stats* stats) {
  FlipPop fp(ps, chains);
  fp.run(stats);
  std::vector<Index> hull = rotate_to_smallest(fp.polygon());
  if (stats) stats->hull_vertices = hull.size();
  return hull;
}

}  // namespace flipflop::ref

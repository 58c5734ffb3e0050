// twist.hpp — the twist algorithm, thesis §8.3, Algorithm 11: an arbitrary,
// possibly self-intersecting polygon and a point s inside the hull of its
// vertices -> a polygon star-shaped w.r.t. s, by twists only.
//
// Coherent orientation (§8.1): the polygon is the vertex ordering
// <p_0, ..., p_{n-1}> with oriented edges p_i -> p_{i+1} (p_n = p_0); a twist on
// the edge p -> q (§8.2) swaps p and q in the ordering, which keeps the polygon
// coherently oriented. "The first vertex" is the one at position 0.
//
// Framework of §3.2:
//   geometric structure  a coherently oriented polygon (a vertex ordering);
//   local operation      twist;
//   candidate            an oriented edge p -> q;
//   criterion            twist p -> q iff (1) q is not the first vertex and
//                        (2) g(p) > g(q), g(p) in [0, 2π) being the angle of p
//                        around s counted counter-clockwise from the ray γ
//                        from s in the +x direction;
//   local check          Alg 11 line 6: p -> q crosses γ iff p, q lie on
//                        opposite sides of the horizontal line through s and
//                        △spq, △s'pq (s' = (+∞, s.y)) differ in orientation;
//                        then g(p) > g(q) iff △spq is counter-clockwise, else
//                        iff it is clockwise.
// Theorem 8.1: this is bubble sort of the ordering by g (every twist swaps one
// adjacent inverted pair), so it terminates, in any order of the twists (free
// execution order, §8.3 last paragraph), with the vertices sorted by g: a
// counter-clockwise polygon star-shaped w.r.t. s when s is strictly inside the
// hull. The number of twists is the number of inversions, Θ(n^2) in the worst
// case (e.g. an input polygon in random order).
//
// Simulation of Simplicity: s is an exact rational point with SoS index n
// (polygon.hpp), y comparisons use the same perturbation, and orient2d(s', p, q)
// for s' at +∞ on the horizontal line through s is the sign of p.y - q.y of the
// perturbed points (the term in s'.x dominates). So "no three points on a
// line" (§8.3) holds for the perturbed points, and the output is consistent
// with flip-pop on the same perturbation (§8.3: "the same perturbation order
// must be maintained").
//
// Checked build: every twist is taken on an edge with g(p) > g(q) by the
// independent comparator StarKernel::angle_less (so it removes one inversion);
// the result is star-shaped w.r.t. s (Theorem 8.1).
#pragma once

#include <cstddef>
#include <vector>

#include "reference/hull2/polygon.hpp"

namespace flipflop::ref {

class Twist {
 public:
  Twist(const StarKernel& s, std::vector<Index> polygon);

  // Alg 11 lines 5-13 for the edge p -> q (which must be an edge of the
  // polygon): true iff it is to be twisted.
  bool needs_twist(Index p, Index q) const;
  // Is p -> q an edge of the current polygon?
  bool is_edge(Index p, Index q) const;
  // The positions k (0 <= k < n-1) whose edge order[k] -> order[k+1] is to be
  // twisted now (the valid candidates; the closing edge ends at the first
  // vertex and is never one).
  std::vector<std::size_t> applicable() const;
  // Twist the edge order[k] -> order[k+1] (must be applicable).
  void apply(std::size_t k);
  // Algorithm 11: a FIFO queue of edges. Adds twists and twist_checks to *stats.
  void run(Hull2Stats* stats);

  const std::vector<Index>& order() const { return order_; }
  const StarKernel& kernel() const { return s_; }

 private:
  void swap_at(std::size_t k);

  StarKernel s_;
  std::vector<Index> order_;
  std::vector<std::size_t> pos_;  // pos_[v] = position of vertex v in order_
};

// Twist a polygon (any vertex ordering of distinct input points, at least 3)
// into a counter-clockwise polygon star-shaped w.r.t. `kernel`, which must lie
// strictly inside the hull of the polygon's vertices (SoS index ps.size()).
// Returns the ordering sorted by g, starting at the vertex with the smallest
// g. Throws std::invalid_argument on a malformed polygon. Adds to *stats.
std::vector<Index> twist_to_star(const PointSet& ps, std::vector<Index> polygon,
                                 const pred::RationalPoint& kernel, Hull2Stats* stats = nullptr);

}  // namespace flipflop::ref

// flip_pop.hpp — flip-pop, thesis §4.1, Algorithm 1 (sequential workflow).
//
// Framework of §3.2:
//   geometric structure  a polygon P star-shaped w.r.t. a kernel point s;
//   local operation      2-1 flip on a vertex p_i: its two edges p_j p_i and
//                        p_i p_k become the one edge p_j p_k;
//   candidate            a vertex with its two incident edges;
//   criterion/local check  p_i ∈ △ s p_j p_k (Alg 1 line 5). The polygon stays
//                        star-shaped w.r.t. s after the flip, so no other check
//                        is needed.
// A removed vertex lies strictly inside △ s p_j p_k, hence inside the polygon,
// and never comes back; at termination every vertex is convex, so the star-
// shaped polygon is convex: the hull of its vertices (§4.1, last paragraphs).
// Every flip is decided by the perturbed predicates of polygon.hpp, so the
// result is the canonical (SoS) hull of the polygon's vertices whatever order
// the flips are taken in — free execution order, which FlipPop exposes
// (applicable / apply) and proptests/hull2_orders_test.cpp explores
// exhaustively.
//
// Two kinds of kernel:
//   * a point s strictly inside (StarKernel, polygon.hpp): flip_pop() below;
//   * Graham-sorting's chains (§4.2): the polygon <v_r, upper chain, v_l, lower
//     chain> whose upper chain is star-shaped w.r.t. the kernel point (0, -∞)
//     and lower chain w.r.t. (0, +∞). Then p_i ∈ △ s p_j p_k reads: p_i lies
//     strictly between p_j and p_k in x and strictly on the side of the line
//     p_j p_k towards s, i.e. orient2d(p_j, p_k, p_i) > 0 for both chains (the
//     upper chain runs towards -x, whose left is down; the lower towards +x,
//     whose left is up). v_l and v_r are extreme and never flipped (§4.2:
//     "no flips can be applied on them"), so flip-pop works on the two chains
//     separately.
//
// Checked build (reference/checked.hpp): the input is star-shaped; after every
// flip the polygon is still star-shaped (or the chains x-monotone), the flipped
// vertex passed the local check, and no removed vertex is on the polygon.
#pragma once

#include <optional>
#include <vector>

#include "reference/hull2/polygon.hpp"

namespace flipflop::ref {

// Graham-sorting's polygon <v_r, S_a (x descending), v_l, S_b (x ascending)>
// with its chain kernels (0, -∞) and (0, +∞) (Alg 3 line 6).
struct ChainPolygon {
  std::vector<Index> polygon;
  Index left = 0, right = 0;  // v_l and v_r
};

class FlipPop {
 public:
  // A counter-clockwise polygon star-shaped w.r.t. the kernel point s.
  FlipPop(const StarKernel& s, const std::vector<Index>& polygon);
  // Graham-sorting's chains.
  FlipPop(const PointSet& ps, const ChainPolygon& chains);

  // Alg 1 lines 4-5: with p_j p_i and p_i p_k the edges at v, is v ∈ △ s p_j p_k?
  bool removable(Index v) const;
  // Every vertex that passes the local check now (the valid candidates).
  std::vector<Index> applicable() const;
  // Alg 1 line 6: the 2-1 flip on v (v must pass the local check).
  void apply(Index v);
  // Algorithm 1: the sequential workflow (Fig 3.1) with the unchecked labels
  // kept in a queue; adds flips_2_1, rounds (passes of the repeat loop) and
  // polygon_vertices to *stats.
  void run(Hull2Stats* stats);

  bool on_polygon(Index v) const { return v < on_.size() && on_[v]; }
  Index prev(Index v) const { return prev_[v]; }
  Index next(Index v) const { return next_[v]; }
  std::size_t size() const { return size_; }
  // The current polygon, counter-clockwise, from the first surviving vertex of
  // the input polygon.
  std::vector<Index> polygon() const;
  // The geometric structure is intact: star-shaped w.r.t. s, or both chains
  // strictly x-monotone between v_l and v_r.
  bool structure_holds() const;
  // No vertex removed by a flip is on the polygon (it never reappears).
  bool no_removed_vertex() const;

 private:
  void link(const std::vector<Index>& polygon);

  const PointSet* ps_;
  std::optional<StarKernel> s_;  // set: a kernel point; empty: Graham's chains
  Index left_ = 0, right_ = 0;
  std::vector<Index> prev_, next_;
  std::vector<char> on_, removed_;
  std::vector<Index> input_order_;
  std::size_t size_ = 0;
};

// flip-pop on a counter-clockwise polygon star-shaped w.r.t. `kernel` (a point
// that is not an input: SoS index ps.size()). Returns the canonical hull of the
// polygon's vertices (counter-clockwise, smallest index first). Precondition
// is_star_shaped(ps, polygon, kernel), checked in the checked build; throws
// std::invalid_argument on a malformed polygon (fewer than 3 vertices, indices
// out of range or repeated). Adds to *stats; sets stats->hull_vertices.
std::vector<Index> flip_pop(const PointSet& ps, std::vector<Index> star_polygon_ccw,
                            const pred::RationalPoint& kernel, Hull2Stats* stats = nullptr);

// flip-pop on Graham's chain polygon (Alg 3 line 7, Alg 4 line 19).
std::vector<Index> flip_pop(const PointSet& ps, const ChainPolygon& chains, Hull2Stats* stats = nullptr);

}  // namespace flipflop::ref

// twist_flip.hpp — twist-flip, thesis §8.4.1: a coherently oriented polyhedron
// whose topmost vertex v is joined to every other vertex -> a polyhedron
// star-shaped w.r.t. v (Theorem 8.9), by twists (§8.2) then 2-2 flips of
// folds. Twisting stage: Algorithm 12; flipping stage: Algorithm 13; proof:
// Lemmas 8.3-8.8, Theorem 8.9. Then hull3_twist_flip: twist-flip followed by
// flip-flop (§6.2 Algorithm 6, flip_flop_3d.hpp) computes the 3D hull.
//
// ---------------------------------------------------------------------------
// Conventions (this project's, not the thesis' mirror image)
// ---------------------------------------------------------------------------
// A triangle (a, b, c) is counter-clockwise seen from outside; orient3d(a, b,
// c, p) > 0 (predicates.hpp) says that p is on its inner side. The thesis
// calls a triangle "counter-clockwise w.r.t. p" when p is on its positive
// side; here that is orient3d(a, b, c, p) > 0. Hence:
//   * a triangle of P \ star(v) is POSITIVE iff orient3d(a, b, c, v) > 0;
//   * a triangle (v, p, q) of star(v) is POSITIVE iff orient3d(v, p, q, s) > 0,
//     s the secondary kernel (below).
// When all triangles are positive the result is star-shaped w.r.t. v and
// oriented counter-clockwise seen from outside — the input flip_flop_3d wants.
// The input may be coherently oriented either way: twisting makes the link
// counter-clockwise around s whatever it was (Theorem 8.1).
//
// ---------------------------------------------------------------------------
// Topmost vertex and secondary kernel (exact, Simulation of Simplicity)
// ---------------------------------------------------------------------------
// "Topmost" is decided by pred::compare_sos on z: v is above every other
// vertex of the perturbed configuration (a tie in z goes to the smaller index,
// which has the larger perturbation).
//
// The secondary kernel s (§8.4.1: "shoot a ray from v to the interior of
// CH(link(v)), and select an arbitrary point s != v on the ray"), in this
// order of preference, with three link vertices a, b, c such that
// orient3d_exact(v, a, b, c) != 0:
//   (1) the double point (v.x, v.y, z) straight below v — the vertical ray —
//       with a, b, c the link vertices whose directions from v's vertical
//       line are closest to three directions 120 degrees apart and z halfway
//       between v and the plane of abc, all proposed in floating point (IEEE
//       +, -, *, /, sqrt: the same on every machine), accepted only when an
//       exact check confirms that it lies in the open cone from v over the
//       triangle abc (on the side of each plane vab, vbc, vca where the third
//       vertex is). Then the angular order around s in H is the order of the
//       directions of the points around v's vertical line, which
//       hull3_twist_flip starts from: the twisting stage has next to nothing
//       to do there;
//   (2) otherwise the exact dyadic point (a + b + c + c) / 4 ("s can be the
//       centroid of any three different vertices of link(v)"; a centroid of
//       three points is not dyadic, this weighted one is, and it lies in the
//       relative interior of the triangle abc just the same), a, b, c the
//       link vertices at positions 0, k/3, 2k/3 of the input's link cycle,
//       else the first suitable triple in link order.
// Either way s is an exact point (pred::RationalPoint) in the open cone from v
// over abc, hence strictly below v, and the ray from v through s enters the
// interior of CH(link(v)). s takes part in the perturbation with index n =
// ps.size(), the first auxiliary point (predicates.hpp). Why this is valid in
// the perturbed configuration: "s in the open cone from v over abc" is an open
// condition, kept by every small enough perturbation, and so is "s below v".
// The projection of §8.4.1 (p -> p* = ray(v, p) ∩ H, H the horizontal plane
// through s) is then defined for every vertex (all are below v), s lies
// strictly inside the hull of the projected link (inside the projected
// triangle a*b*c*), and every predicate below is the sign of one real
// configuration in general position.
// If the polyhedron's vertices are exactly coplanar no such triple exists:
// std::invalid_argument (the hull of such a set is not a polyhedron anyway).
//
// ---------------------------------------------------------------------------
// Predicates (all exact, SoS; proofs of the sign identities in twist_flip.cpp)
// ---------------------------------------------------------------------------
// Twisting stage, Alg 12 line 6 (the projected edge p*q* crosses the ray γ
// from s in the +x direction inside H; s' = (+∞, s.y, s.z)):
//   side of p w.r.t. the plane △vss'  = orient2d of the (y, z) projections of
//                                       (v, s, p) = sign(p*.y - s.y);
//   orientation of △vpq w.r.t. s      = orient3d(v, p, q, s)
//                                     = orient2d(s, p*, q*) inside H;
//   orientation of △vpq w.r.t. s'     = -orient2d of the (y, z) projections
//                                       of (v, p, q) = sign(p*.y - q*.y).
// Flipping stage, Alg 13: positive(a, b, c) = orient3d(a, b, c, v) > 0; line
// 8 ("△bas is clockwise w.r.t. v") = orient3d(b, a, s, v) < 0.
//
// ---------------------------------------------------------------------------
// The kernel point for flip-flop (TwistFlipKernel)
// ---------------------------------------------------------------------------
// The result is star-shaped w.r.t. v, a vertex ON the surface; flip-flop needs
// a point strictly inside the kernel. TwistFlipKernel is the symbolic point
//        κ = v + η (s - v),   η > 0 infinitesimal,
// η smaller than every term of the perturbation (κ is the auxiliary point
// after s, index n + 1, placed on the segment vs). orient3d(a, b, c, ·) is an
// affine function of its last point, so
//   orient3d(a, b, c, κ) = (1 - η) orient3d(a, b, c, v) + η orient3d(a, b, c, s):
//   * v not in {a, b, c}: orient3d(a, b, c, v) is a non-zero polynomial in the
//     perturbation parameter (SoS), which dominates the η term: side = the SoS
//     sign of orient3d(a, b, c, v);
//   * v in {a, b, c}: orient3d(a, b, c, v) = 0 (a repeated point), side = the
//     SoS sign of orient3d(a, b, c, s).
// Claim: if every triangle of P is positive (the state Theorem 8.9 ends in),
// κ is strictly inside the kernel of P. Proof (Lemma 8.8 with v' = κ): the
// triangles of P \ star(v) have v, hence κ, on their inner side (first case);
// the triangles (v, p, q) of star(v) have s, hence κ, on their inner side
// (second case); so every triangle has κ strictly on its inner side. A
// horizontal ray from κ meets only star(v) (κ is above every vertex but v),
// and exactly one of its triangles, since star(v) is star-shaped w.r.t. κ
// (its cross-section is the link polygon of §8.4.1, star-shaped w.r.t. the
// projection of κ, Lemma 8.3). By Theorem 8.2 P is star-shaped w.r.t. κ, and
// as κ is strictly on the inner side of every triangle it is an interior
// point of the kernel (the intersection of those half-spaces).
//
// ---------------------------------------------------------------------------
// Data (§8.2: a twist is a combinatorial swap)
// ---------------------------------------------------------------------------
// As every vertex but v is on link(v), the polyhedron is star(v) plus a
// triangulated disk T (the projected triangulation of §8.4.1, all vertices on
// its boundary). Positions 0..k-1 of the link cycle are fixed slots; order[i]
// is the point at slot i, so star(v) = {(v, order[i], order[i+1])}. A twist on
// the link edge order[i] -> order[i+1] swaps the two points in every triangle,
// i.e. swaps order[i] and order[i+1]: T, stored over slots, does not change.
// The flipping stage works on T over points, with a map from directed edges to
// triangles. "The first vertex of link(v)" (Alg 12 line 5) is slot 0, which
// initially holds p of the first triangle (v, p, q) of the input list.
//
// Checked build (reference/checked.hpp): every twist removes an inversion of
// the angular order around s (an independent comparator); after the twisting
// stage star(v) is star-shaped w.r.t. s (Lemma 8.3); every flipped edge is an
// inner edge of T whose new edge is not in P (Lemma 8.7) and no flip creates
// two negative triangles (Fig 8.9: case (b) never happens); at the end every
// triangle is positive (Theorem 8.9).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "predicates/rational_point.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "reference/hull3/kernel_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// κ = v + η (s - v) (header comment): side(a, b, c) = SoS sign of
// orient3d(a, b, c, v) when v is not in {a, b, c}, else of orient3d(a, b, c, s);
// 0 when a, b, c are not distinct. s: an exact point with SoS index
// ps.size(), such that every triangle (v, p, q) of star(v) has s on its
// inner side (TwistFlip::kernel() provides one). Keeps a pointer to ps.
class TwistFlipKernel : public KernelPoint {
 public:
  TwistFlipKernel(const PointSet& ps, Index v, const pred::RationalPoint& s);
  int side(Index a, Index b, Index c) const override;

  Index top() const { return v_; }
  const pred::RationalPoint& secondary() const { return s_; }

 private:
  const PointSet* ps_;
  Index v_;
  pred::RationalPoint s_;
};

// One fold flip of the flipping stage: the fold a-b with its positive
// triangle (a, b, c) and negative triangle (b, a, d), replaced by (a, d, c)
// and (b, c, d) (Alg 13 lines 7-9).
struct FoldFlip {
  Index a, b, c, d;
};

class TwistFlip {
 public:
  // Validates the precondition; throws std::invalid_argument (one line) when
  // ps is not 3D, the triangles are not a closed coherently oriented
  // triangulated sphere over indices of ps, v is not its topmost vertex
  // (compare_sos on z), v is not adjacent to every other vertex, or the
  // vertices are coplanar. Chooses s (header comment). Keeps a pointer to ps.
  TwistFlip(const PointSet& ps, const std::vector<Triangle>& polyhedron, Index v);

  // Algorithm 12, once. Adds to stats->twists.
  void twisting_stage(Hull3Stats* stats = nullptr);
  // Algorithm 13, once, after the twisting stage (its precondition, Lemma
  // 8.3; std::logic_error otherwise). Adds to stats->fold_flips; appends
  // every flip to *log when given.
  void flipping_stage(Hull3Stats* stats = nullptr, std::vector<FoldFlip>* log = nullptr);

  // The current polyhedron: star(v) as (v, p, q) first, then T.
  std::vector<Triangle> triangles() const;
  // link(v) in slot order: order()[i] -> order()[i+1] are its edges.
  const std::vector<Index>& order() const { return order_; }
  Index top() const { return v_; }
  // κ for s (header comment): strictly inside the kernel of triangles() once
  // both stages have run (Theorem 8.9); s depends only on the input.
  const TwistFlipKernel& kernel() const { return kernel_; }

  // Alg 12 lines 5-13 for the link edge p -> q: true iff it is to be twisted.
  bool needs_twist(Index p, Index q) const;

 private:
  struct Prepared;  // the validated input: link cycle, T over slots, s
  static Prepared prepare(const PointSet& ps, const std::vector<Triangle>& polyhedron, Index v);
  static pred::RationalPoint secondary_kernel(const PointSet& ps, const std::vector<Index>& link, Index v);
  TwistFlip(const PointSet& ps, Index v, Prepared prep);

  int side_of_gamma_plane(Index p) const;  // orientation of △vss' w.r.t. p
  int orient_vpq_s(Index p, Index q) const;
  int orient_vpq_s_far(Index p, Index q) const;
  bool positive(Index a, Index b, Index c) const;
  bool link_is_star_shaped() const;  // checked build: Lemma 8.3

  const PointSet* ps_;
  Index v_;
  std::vector<Index> order_;                  // link(v): point at each slot
  std::vector<std::uint32_t> pos_;            // slot of each point (link points only)
  std::vector<std::array<std::uint32_t, 3>> disk_;  // T over slots (twisting stage)
  std::vector<Triangle> tris_;                // T over points (flipping stage)
  bool twisted_ = false;                      // twisting stage done
  bool flipped_ = false;                      // flipping stage done: T is in tris_
  TwistFlipKernel kernel_;
  pred::RationalPoint s_yz_;                  // s seen through (y, z) only
};

// Twist-flip (§8.4.1): the input polyhedron (precondition as TwistFlip) ->
// a polyhedron over the same vertices, every triangle positive, star-shaped
// w.r.t. v (Theorem 8.9); TwistFlip(...).kernel() is a point strictly inside
// its kernel. Resets *stats; sets twists and fold_flips.
std::vector<Triangle> twist_flip(const PointSet& ps, const std::vector<Triangle>& polyhedron, Index v,
                                 Hull3Stats* stats = nullptr);

// The 3D hull by twist-flip then flip-flop: v = the topmost point, link(v) =
// the other points in angular order around v's vertical line (exact sort,
// twist_flip_input.hpp), the rest of the sphere a zigzag triangulation of the
// disk bounded by the link (no interior vertices); twist-flip; flip_flop_3d
// with TwistFlipKernel. Returns the canonical SoS hull (= brute::hull3(ps)).
// Throws std::invalid_argument for input that is not 3D, or with
// dimension_problem(ps) when the points do not span 3D. Resets *stats; sets
// twists, fold_flips and the fields flip_flop_3d reports.
std::vector<Triangle> hull3_twist_flip(const PointSet& ps, Hull3Stats* stats = nullptr);

}  // namespace flipflop::ref

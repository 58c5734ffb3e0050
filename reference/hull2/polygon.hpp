// polygon.hpp — what the 2D hull algorithms of thesis chapters 4 and 8 share:
// their statistics, the exact perturbed predicates on input points and on a
// kernel point, and the star-shapedness test.
//
// A polygon is a plain array of input indices, read cyclically; it is
// counter-clockwise where a function says so.
//
// Kernel point (thesis §2.1: P is star-shaped w.r.t. s if for any point p on P
// the segment ps meets P only at p). Flip-pop (§4.1) and twist (§8.3) take s as
// an exact rational point that is not an input: a pred::RationalPoint with SoS
// index n = ps.size(), after all inputs (predicates.hpp, "Points that are not
// inputs"), used only through pred::mixed_sign — never a rounded double (thesis
// §6.4.2). Every predicate below is a sign under the one Simulation of
// Simplicity of the computation, so all of them describe one configuration in
// general position, the kernel point included, and the hull is unique.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// Counters of the 2D hull algorithms. flip_pop and twist_to_star ADD to the
// counters they touch (so that a pipeline can pass one struct through its
// stages); the hull2_* entry points reset the struct first.
struct Hull2Stats {
  std::size_t flips_2_1 = 0;         // 2-1 flips (Alg 1 line 6)
  std::size_t rounds = 0;            // passes of flip-pop's repeat loop (Alg 1 lines 2-10)
  std::size_t discarded_early = 0;   // Graham-insertion: points proved interior (Alg 4 line 17)
  std::size_t insertions = 0;        // Graham-insertion: points inserted (Alg 4 line 10)
  std::size_t insertion_rounds = 0;  // Graham-insertion: iterations of Alg 4 lines 7-18
  std::size_t twists = 0;            // twists (Alg 11 lines 8 and 12)
  std::size_t twist_checks = 0;      // edges popped and checked (Alg 11 line 4)
  std::size_t input_vertices = 0;    // points of the input
  std::size_t polygon_vertices = 0;  // vertices of the polygon flip-pop starts from
  std::size_t hull_vertices = 0;     // vertices of the result
};

// ---- perturbed predicates on input points ----------------------------------
// orient2d(a, b, c) > 0 iff a, b, c are counter-clockwise (SoS, never 0 for
// distinct indices).
int orient(const PointSet& ps, Index a, Index b, Index c);
// Sign of a.x - b.x (coord 0) or a.y - b.y (coord 1) under the perturbation.
int compare_coord(const PointSet& ps, Index a, Index b, int coord);

// The leftmost and the rightmost input point under the perturbation (by
// pred::compare_sos on x): both are vertices of the hull (Alg 3 / Alg 4 line 1).
std::pair<Index, Index> leftmost_rightmost(const PointSet& ps);

// ---- the kernel point ------------------------------------------------------
// Predicates between input points and the kernel point s (SoS index n).
class StarKernel {
 public:
  StarKernel(const PointSet& ps, const pred::RationalPoint& s);

  // orient2d(s, p, q) under the perturbation.
  int orient(Index p, Index q) const;
  // Sign of p.y - s.y under the perturbation (never 0): > 0 means p lies above
  // the horizontal line through s.
  int compare_y(Index p) const;
  // g(p) < g(q), thesis §8.3: g(p) is the angle in [0, 2π) by which the ray γ
  // from s in the +x direction turns counter-clockwise to reach p. Written
  // independently of Algorithm 11's test: the upper half-plane (g in (0, π))
  // comes first, then orient2d(s, p, q) orders two points of one half-plane.
  bool angle_less(Index p, Index q) const;

  const PointSet& points() const { return *ps_; }
  const pred::RationalPoint& point() const { return s_; }
  pred::PointId id() const { return id_; }

 private:
  const PointSet* ps_;
  pred::RationalPoint s_;
  pred::RationalPoint s_y_;  // s seen through its y coordinate only (a 1D point)
  pred::PointId id_;
};

// An exact kernel point strictly inside the hull of a point set that spans the
// plane: (a + b + c + c) / 4 for the leftmost point a, the rightmost point b
// and the point c farthest (in floating point) from the line ab among those
// exactly off it. It is strictly inside the non-degenerate triangle abc, hence
// strictly inside the perturbed hull. Throws std::invalid_argument when the
// points do not span the plane.
pred::RationalPoint interior_kernel(const PointSet& ps);

// ---- star-shapedness -------------------------------------------------------
// Exact test (thesis Thm 8.2 in R^2): a counter-clockwise polygon is star-
// shaped w.r.t. s iff (1) every edge p->q has orient2d(s, p, q) > 0 and (2) the
// ray γ from s in the +x direction crosses exactly one edge. With (1), an edge
// crosses γ iff it goes from below s to above s, and their number is the
// winding number of the polygon around s. Also false for fewer than 3
// vertices, indices out of range or repeated.
bool is_star_shaped(const PointSet& ps, const std::vector<Index>& polygon,
                    const pred::RationalPoint& kernel);
bool is_star_shaped(const StarKernel& kernel, const std::vector<Index>& polygon);

// ---- plumbing ----------------------------------------------------------------
// Throws std::invalid_argument naming `who` unless ps is 2D and polygon has at
// least 3 vertices, all indices of ps, none repeated.
void require_polygon(const PointSet& ps, const std::vector<Index>& polygon, const char* who);
// Throws std::invalid_argument naming `who` unless ps is 2D and spans the plane
// (at least 3 points, not all collinear): the hull of such input is a polygon.
void require_planar_input(const PointSet& ps, const char* who);
// Some three points of `cycle` are not collinear (exactly). For a cycle that
// holds every extreme point of the input (a hull computed without first
// checking the input's dimension), false exactly when the whole input lies on
// one line.
bool cycle_spans_plane(const PointSet& ps, const std::vector<Index>& cycle);
// The cycle rotated to start at its smallest index (DESIGN.md, canonical 2D hull).
std::vector<Index> rotate_to_smallest(std::vector<Index> cycle);

}  // namespace flipflop::ref

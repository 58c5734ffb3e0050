// initial_stars.hpp — the cheap approximation that feeds star splaying, and
// the pipeline hull3_splay (thesis ch. 7: gHull's Stages 2-5 with an exact,
// sequential approximation in place of the digital Voronoi diagram).
//
// gHull (§7.1) builds stars from an approximation of the hull, keeps the
// points outside the approximation with stars built from a nearby triangle
// (Stage 4, Algorithm 10) and lets star splaying repair the rest (Stage 5).
// Here the approximation is the hull of a *sample*, computed by the same
// pipeline recursively (a ladder of samples, each 1/8 of the previous one;
// at most 32 points: a tetrahedron):
//
//   1. S = the ≺-least point of the set (star_splaying.hpp) plus a
//      pseudo-random eighth of the others (a fixed seed: the output is the
//      canonical hull whatever the sample; only the work depends on it).
//   2. H = conv(S) by this pipeline (SoS hull of S, same perturbation).
//   3. Every vertex of H gets its star in H. Every other point p is located
//      against H from the fixed vertex r = the ≺-least point (§7.1 Stage 4,
//      Algorithm 10 walks in the same way): if p is beyond a triangle of r's
//      star it is outside; otherwise a walk over the triangles of H not
//      incident to r (centrally projected from r they triangulate the
//      cross-section of r's cone; a remembering stochastic walk on
//      orient3d(r, x, y, p), with an exhaustive scan as the fallback after
//      a step bound) finds the triangle (a, b, c) whose cone from r holds p.
//      p beneath it: p is strictly inside the tetrahedron (r, a, b, c) and
//      dies with that certificate; p beyond it, or beyond a triangle met on
//      the way: p is outside H and gets its star in conv(H ∪ {p}): the cone
//      over the horizon of the triangles of H it sees.
//   4. Star splaying (star_splaying.hpp) turns these stars into the hull.
//
// Every star built so is convex or dead with a valid certificate, and
// satisfies the lexicographic precondition: the ≺-least point is in every
// sample, so it is a vertex of H and of conv(H ∪ {p}), and a vertex of a
// polytope that is not its ≺-least vertex has a neighbour ≺ it (the simplex
// method's argument for the linear functional "perturbed x"). All decisions
// are SoS predicates; the sample choice and the visiting order (a Morton
// order of the coordinates, for short walks) are heuristics that only change
// the work.
#pragma once

#include <vector>

#include "reference/hull3/hull3_stats.hpp"
#include "reference/hull3/star_splaying.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// The canonical SoS hull of ps by star splaying from the stars above. Throws
// std::invalid_argument for ps.dim != 3 or lower-dimensional input
// (dimension_problem). `stats` (reset) sums splay_insertions and
// splay_removals over all levels of the sample ladder; dead_stars counts the
// dead stars of the last level (the points that are not hull vertices).
std::vector<Triangle> hull3_splay(const PointSet& ps, Hull3Stats* stats = nullptr);

// The initial stars hull3_splay gives star splaying for all points of ps
// (same errors). star_splaying(ps, initial_stars(ps)) == hull3_splay(ps).
std::vector<Star> initial_stars(const PointSet& ps);

namespace splay {
// Step 3 alone: the stars of the points `idx` (each index once) from `hull`,
// the canonical SoS hull of a subset of idx that holds the ≺-least point of
// idx.
std::vector<Star> stars_from_hull(const PointSet& ps, const std::vector<Index>& idx,
                                  const std::vector<Triangle>& hull);
}  // namespace splay

}  // namespace flipflop::ref

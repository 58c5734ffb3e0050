// hull3.hpp — the reference 3D convex hull: the public entry points of the
// algorithms of thesis chapters 6-8, exact and canonical.
//
//   ffhull      ffHull, §6.4 Algorithm 7: initial tetrahedron, exact kernel
//               point, furthest-point insertion with early removal, then
//               flip-flop (§6.2 Algorithm 6)                  (ffhull.hpp)
//   splay       star splaying (§3.3.2, Shewchuk) from initial stars of a
//               cheap approximation   (star_splaying.hpp, initial_stars.hpp)
//   twist-flip  a polyhedron whose topmost vertex is joined to all others,
//               made star-shaped by twist-flip (§8.4.1 Algorithms 12, 13),
//               then flip-flop                                 (twist_flip.hpp)
//
// Every function returns the canonical hull (DESIGN.md): triangles counter-
// clockwise seen from outside, each rotated to start at its smallest index,
// sorted — the unique hull under the Simulation of Simplicity of
// predicates.hpp, equal to brute::hull3. On degenerate input it may hold
// points that are not strictly extreme exactly as the perturbation decides;
// strict_hull3 (strict_hull3.hpp) gives the strictly extreme points and the
// coplanar facets merged into polygons. Input that does not span R^3 (fewer
// than 4 points, all coplanar, collinear or equal) is rejected with
// std::invalid_argument naming its dimension. *stats, if given, is reset and
// filled with the algorithm's counts (hull3_stats.hpp).
#pragma once

#include <string>
#include <vector>

#include "reference/hull3/hull3_stats.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// By name: one of hull3_algorithms(); throws std::invalid_argument otherwise.
std::vector<Triangle> hull3(const PointSet& ps, const std::string& algo, Hull3Stats* stats = nullptr);
std::vector<std::string> hull3_algorithms();  // {"ffhull", "splay", "twist-flip"}

}  // namespace flipflop::ref

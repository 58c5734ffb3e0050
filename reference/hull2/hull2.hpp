// hull2.hpp — the reference 2D convex hull: the public entry points of the
// algorithms of thesis chapter 4 and §8.3, exact and canonical.
//
//   hull2_graham_sort    Graham-sorting, §4.2 Algorithm 3 (graham_sorting.hpp)
//   hull2_graham_insert  Graham-insertion, §4.3 Algorithm 4 (graham_insertion.hpp)
//   hull2_twist          the input polygon <0, 1, ..., n-1> and an exact kernel
//                        point strictly inside the hull (interior_kernel,
//                        polygon.hpp) -> twist (§8.3 Algorithm 11, twist.hpp)
//                        -> flip-pop (§4.1 Algorithm 1, flip_pop.hpp).
//                        Θ(n^2) twists on input in random order (bubble sort,
//                        Thm 8.1): meant for small inputs and almost star-shaped
//                        polygons.
// Library calls on user structures: flip_pop (flip_pop.hpp), twist_to_star
// (twist.hpp), is_star_shaped (polygon.hpp).
//
// Every function returns the canonical hull (DESIGN.md): counter-clockwise,
// starting at the smallest index, the unique hull of the input under the
// Simulation of Simplicity of predicates.hpp — equal to brute::hull2. On
// degenerate input it may hold points that are not strictly extreme (points
// on a hull edge, copies of a vertex) exactly as the perturbation decides.
// Input that does not span the plane (fewer than 3 points, all collinear) is
// rejected with std::invalid_argument. *stats, if given, is reset and filled.
#pragma once

#include <string>
#include <vector>

#include "reference/hull2/flip_pop.hpp"
#include "reference/hull2/graham_insertion.hpp"
#include "reference/hull2/graham_sorting.hpp"
#include "reference/hull2/polygon.hpp"
#include "reference/hull2/twist.hpp"

namespace flipflop::ref {

std::vector<Index> hull2_graham_sort(const PointSet& ps, Hull2Stats* stats = nullptr);
std::vector<Index> hull2_graham_insert(const PointSet& ps, Hull2Stats* stats = nullptr);
std::vector<Index> hull2_twist(const PointSet& ps, Hull2Stats* stats = nullptr);

// By name: "graham-sort", "graham-insert" or "twist" (hull2_algorithms());
// throws std::invalid_argument for another name.
std::vector<Index> hull2(const PointSet& ps, const std::string& algo, Hull2Stats* stats = nullptr);
std::vector<std::string> hull2_algorithms();

}  // namespace flipflop::ref

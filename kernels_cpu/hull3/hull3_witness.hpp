// hull3_witness.hpp — what the multithreaded ffHull (ffhull.hpp) hands the
// witness-checked certifier (certify_hull3.hpp, cpu::certify_hull3_witnessed)
// so that every input point is checked with a constant number of exact
// predicates instead of being located by a walk.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::cpu {

constexpr std::uint32_t kNoFacet = ~std::uint32_t{0};

struct Hull3Witness {
  // The interior point s: the centroid of these four input points (the
  // kernel's initial tetrahedron, thesis §6.4 Algorithm 7 line 4), SoS index
  // n; rounded to doubles in the order tet[0..3] when that point is strictly
  // inside the tetrahedron exactly, else exact (never rounded otherwise,
  // §6.4.2). The kernel's kernel point is this very point, so its cones are
  // the certifier's.
  std::array<Index, 4> tet{};
  // The canonical output the witness is about (the facets it indexes).
  std::vector<Triangle> facets;
  // Per input point: the index in `facets` of a facet whose cone from s
  // contains the point and beneath which it lies; kNoFacet for the hull's
  // vertices and, when `ball`, for points strictly inside the inner ball.
  std::vector<std::uint32_t> facet;
  // The certifier builds the inner ball of the facets (reference/certify/
  // inner_ball.hpp, verified exactly) and accepts a non-vertex without a
  // facet when it lies strictly inside that ball.
  bool ball = false;
};

// The rule the kernel and the witnessed certifier share for `ball`
// (certify::hull3's: the ball's exact set-up, one GMP test per facet, pays
// when the points to locate outnumber the facets eightfold).
inline bool worth_inner_ball(std::size_t non_vertices, std::size_t facets) { return non_vertices >= 8 * facets; }

}  // namespace flipflop::cpu

// hull3_witness.hpp — what the multithreaded ffHull (ffhull.hpp) hands the
// witness-checked certifier (certify_hull3.hpp, cpu::certify_hull3_witnessed)
// so that every input point is checked with a constant number of exact
// predicates instead of being located by a walk.
//
// A non-vertex carries one of three certificates (the certifier tries them in
// this order): a final facet (`facet`), a tetrahedron (s, a, b, c) that holds
// it (`beneath`: the record of its early removal in the construction rounds,
// thesis §6.4 Algorithm 7 line 14), or none when it lies strictly inside the
// inner ball or the witness' box. Only the points with neither a record nor
// the ball or box are located by a walk over the final hull's cones
// (ffhull.cpp: make_witness).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reference/certify/inner_box.hpp"
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
  // vertices, for points with a record in `beneath` and, when `ball`, for
  // points strictly inside the inner ball.
  std::vector<std::uint32_t> facet;
  // Per input point (or empty: no records): its early-removal record, the
  // index in `made` of a triangle (a, b, c) of the surface under
  // construction (counter-clockwise seen from outside, so s is on its inner
  // side) such that the point lies strictly inside the tetrahedron
  // (s, a, b, c) under the perturbation: in the triangle's cone from s and on
  // the inner side of its plane, the two facts the kernel's removal test
  // established. a, b, c are vertices of that surface, hence never removed
  // early themselves (they carry no record). kNoFacet where there is no
  // record. An index (4 bytes a point) rather than the triangle (12): the
  // triangles are few where most points are removed early (10^6 ball:
  // 32 k triangles for 1 M points), and the records are the construction's
  // own, handed over without a pass (issue 11's memory bound).
  std::vector<std::uint32_t> beneath;
  // The triangles the construction made, in order (ffhull.cpp: Made); the
  // records index it.
  std::vector<Triangle> made;
  bool has_record(std::size_t p) const { return !beneath.empty() && beneath[p] != kNoFacet; }
  // the record of p (has_record(p), beneath[p] < made.size())
  const Triangle& record(std::size_t p) const { return made[beneath[p]]; }
  // The certifier builds the inner ball of the facets (reference/certify/
  // inner_ball.hpp, verified exactly) and accepts a non-vertex without a
  // facet when it lies strictly inside that ball.
  bool ball = false;
  // An axis-aligned box (empty: none) that the certifier verifies exactly
  // against every facet (reference/certify/inner_box.hpp) and then accepts a
  // non-vertex without a facet or record in when the point lies strictly
  // inside it. The kernel drops the points strictly inside its box in round 0
  // without a record (ffhull.cpp: inner_region, construct) and hands the box on
  // when it certifies enough points to pay for its 8 tests per facet
  // (worth_box).
  certify::BoxTest3 box;
};

// The rule the kernel and the witnessed certifier share for `ball`
// (certify::hull3's: the ball's exact set-up, one GMP test per facet, pays
// when the points to locate outnumber the facets eightfold).
inline bool worth_inner_ball(std::size_t non_vertices, std::size_t facets) { return non_vertices >= 8 * facets; }
// The rule for handing on the box: its verification is 8 exact orient3d per
// facet; a point it certifies would otherwise cost a record's or a facet's
// four (or a walk), so it pays from two such points per facet on.
inline bool worth_box(std::size_t certified, std::size_t facets) { return certified >= 2 * facets; }

}  // namespace flipflop::cpu

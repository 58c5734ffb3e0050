// ffrt.hpp — ffRT, thesis §5.3: compute RT(S ⊕ W) of a weighted planar point
// set in two stages.
//
// Constructing stage (Figure 5.3 (a), (b)): an initial triangle of three input
// points and its kernel point s (the exact centroid (a + b + 2c)/4, SoS index
// n) give an extended triangulation (one real, three virtual triangles). Every
// point not yet inserted is associated with the triangle it lies in — possibly
// a virtual one. A point is excluded from further consideration once it is
// inserted, or once it is proved redundant by the three vertices of the real
// triangle it is associated with (inside that triangle and its lifted point
// above their lifted plane). In each round, for each triangle, one of its
// points — the one of smallest index — is inserted by a 1-3 flip, and the
// others are re-associated with one of the three new triangles. No flips: the
// result is an extended triangulation containing every non-redundant point.
//
// Flipping stage (Figure 5.3 (c)): flip-flop (flip_flop_2d.hpp) with the
// virtual-edge rules of §2.2; when every edge is locally regular the link of v
// is CH(S) and the real triangles are RT(S ⊕ W).
#pragma once

#include <array>
#include <vector>

#include "reference/rt2/triangulation2.hpp"

namespace flipflop::ref::ffrt {

// The first three of `candidates` (in order) that span a triangle exactly:
// the first point, the first point at a different location, the first point
// off their line; returned counter-clockwise. Throws std::invalid_argument
// when the candidates are collinear.
std::array<Index, 3> initial_triangle(const PointSet& ps, const std::vector<Index>& candidates);

// The constructing stage on an existing extended triangulation: every point of
// `points` (none of them a vertex) is located by scanning the triangles, then
// the rounds described above insert them or, when `discard_redundant`,
// exclude the ones their real triangle proves redundant (counted in
// stats->discarded_early). Counts 1-3 flips and rounds.
void insert_points(tri::Triangulation2& T, const std::vector<Index>& points, bool discard_redundant,
                   Rt2Stats* stats);

// The triangle containing the point p (not a vertex) that lies at the same
// location as the vertex m: searched first around m (p is infinitesimally
// close to m under the perturbation), then among all triangles.
std::int32_t locate_near(const tri::Triangulation2& T, Index p, Index m);

// The constructing stage from scratch on the points `candidates` (ascending
// indices): initial_triangle, make_initial, insert_points of the others.
tri::Triangulation2 construct(const PointSet& ps, const std::vector<Index>& candidates, bool discard_redundant,
                              Rt2Stats* stats);

// Both stages on all points of ps; canonical real triangles.
std::vector<Triangle> ffrt(const PointSet& ps, FlipFlopVariant variant, Rt2Stats* stats);

}  // namespace flipflop::ref::ffrt

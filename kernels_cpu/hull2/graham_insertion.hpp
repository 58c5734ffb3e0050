// graham_insertion.hpp — parallel Graham's scan via insertion ("Graham-
// insertion"), thesis §4.3 Algorithm 4, in rounds on oneTBB (the reference's
// sequential run of the same algorithm: reference/hull2/graham_insertion.hpp).
//
//   lines 1-6   v_l, v_r: the first and last point in x under the
//               perturbation (a parallel reduction); P = <v_r, v_l>; each
//               other point is associated with the edge v_r -> v_l when it is
//               beyond it (orient2d(v_r, v_l, u) < 0: △ v_r v_l u clockwise,
//               u above the line), else with v_l -> v_r (below). Every point
//               is right beyond its edge: its x lies between the ends'.
//   lines 7-11  one round: every edge p -> q with associated points gets one
//               of them, r, inserted (p -> r, r -> q) — the approximately
//               furthest (the largest rounded cross product (q - p) x (p - u),
//               ties: the first in the layout), found per edge by a
//               reduction over fixed pieces of its points combined in order;
//               the new polygon is laid out by a prefix sum over the edges.
//   lines 12-17 every other point u of that edge goes to p -> r when its x
//               lies between p's and r's (x_less under the perturbation),
//               else to r -> q, and stays when it is beyond that edge, else
//               it lies inside the quadrilateral (v_l, v_r, p, r or r, q) of
//               inner points of the hull and is dropped (proved non-
//               extreme). The points are kept grouped by edge: per-piece
//               counts per child edge, a scan in (edge, child, piece) order,
//               a parallel scatter — stable, so the layout depends on
//               nothing but the input.
//   line 19     when no point is left, P is two x-monotone chains, star-
//               shaped w.r.t. (0, ∓∞): flip-pop on each (graham_sorting.hpp's
//               chunked flip_pop_chain) gives the hull.
//
// Why the answer is the reference's byte for byte: every decision (above or
// below, which band, beyond or beneath, the flips) is an exact SoS predicate
// on the input indices; which associated point is inserted is free (§4.3;
// the reference's InsertionChoice tests show every rule gives one hull); a
// dropped point is strictly inside a polygon of input points, so it is no
// vertex of the SoS hull; and flip-pop returns the SoS hull of the chains'
// vertices whatever the order of its flips.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels_cpu/hull2/graham_sorting.hpp"

namespace flipflop::cpu::hull2 {

struct InsertionCounts {
  std::size_t insertions = 0;  // points inserted into an edge (Alg 4 line 10)
  std::size_t rounds = 0;      // iterations of lines 7-18
  std::size_t dropped = 0;     // points proved non-extreme (line 17)
};

// Algorithm 4 on `pts` (at least 2 points, distinct indices, any order): the
// SoS hull counter-clockwise, starting at v_r (not rotated), like
// graham_sorting(). `f` must be valid for every coordinate of `pts`.
std::vector<Index> graham_insertion(std::vector<Pt2> pts, const pred::StaticFilter& f, std::size_t chunk,
                                    ScanCounts& scan, InsertionCounts& counts, StageClock* clock = nullptr);

}  // namespace flipflop::cpu::hull2

// graham_sorting.hpp — parallel Graham's scan ("Graham-sorting"), thesis §4.2
// Algorithm 3, with the chunked local flipping of §4.2 on oneTBB.
//
//   line 1     v_l, v_r: the first and last point after sorting by x (the
//              sort of lines 4-5 is done once, on all points, by par_sort:
//              chunks sorted in parallel, then parallel merge rounds);
//   lines 2-3  S_a above v_l v_r (orient2d(v_l, v_r, p) > 0), S_b below:
//              labels in parallel, then a stable parallel selection
//              (par_select), so both keep the x order;
//   line 6     P = <v_r, S_a (x descending), v_l, S_b (x ascending)>;
//   line 7     flip-pop (§4.1) on each chain, kernel (0, -∞) for the upper
//              and (0, +∞) for the lower chain: p_i with neighbours p_j, p_k
//              is flipped away iff orient2d(p_j, p_k, p_i) > 0
//              (reference/hull2/flip_pop.hpp). The CPU analogue of the
//              shared-memory variant of §4.2 (Fig 4.3): the chain is cut into
//              fixed chunks, and each chunk is flipped by one task until no
//              vertex of it can be flipped, its two end vertices held (their
//              outer neighbours belong to other chunks) — in a chunk, a stack
//              scan in which every pop is a 2-1 flip of the current polygon
//              (Alg 1 line 6) on the vertex between the stack's top-but-one
//              and the next vertex. A last sequential pass of the same scan
//              over the concatenated survivors flips the rest.
//
// Why every split gives the same polygon: flip-pop's result is the canonical
// hull of the polygon's vertices whatever order the flips are taken in (free
// execution order, flip_pop.hpp; every decision is an exact SoS predicate on
// the input indices), so the chunk size and the thread count cannot change
// it; the chunk size is fixed anyway.
//
// Predicates: orient2d with a static filter computed for the points handed in
// (predicates/static_filter.hpp), then the staged SoS predicate with each
// point's input index; x order by the doubles, equal x by pred::compare_sos.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "predicates/static_filter.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu::hull2 {

// A point with its input index (its Simulation-of-Simplicity index); x and y
// adjacent, so &x is the coordinate pointer the predicates take.
struct Pt2 {
  double x, y;
  Index i;
};

struct ScanCounts {
  std::size_t flips_2_1 = 0;  // vertices flipped away (Alg 1 line 6)
  std::size_t passes = 0;     // flip-pop passes: the chunk pass and the final pass, per chain
};

// Algorithm 3 on `pts` (at least 2 points, distinct indices, any order): the
// SoS hull counter-clockwise, starting at v_r (not rotated). `f` must be valid
// for every coordinate of `pts`.
// `chunk`: vertices per chunk of the parallel flip-pop pass (>= 1).
// `clock`, if given, marks the stages "sort by x" and "split and flip-pop".
std::vector<Index> graham_sorting(std::vector<Pt2> pts, const pred::StaticFilter& f, std::size_t chunk,
                                  ScanCounts& counts, StageClock* clock = nullptr);

// The static filter for the coordinates of pts (a parallel scan).
pred::StaticFilter static_filter_of(const std::vector<Pt2>& pts);

// ---- shared with graham_insertion.hpp ---------------------------------------
// orient2d(a, b, c) under SoS: the static filter, then the staged predicate.
int orient(const pred::StaticFilter& f, const Pt2& a, const Pt2& b, const Pt2& c);
// a before b in x under the perturbation (a strict total order on distinct
// indices).
bool x_less(const Pt2& a, const Pt2& b);
// Flip-pop on one chain v_r ... v_l (upper, x descending) or v_l ... v_r
// (lower, x ascending), whose two ends are extreme and never flipped: fixed
// chunks in parallel, then a final pass (line 7 above).
std::vector<Pt2> flip_pop_chain(std::vector<Pt2> chain, const pred::StaticFilter& f, std::size_t chunk,
                                ScanCounts& counts);

}  // namespace flipflop::cpu::hull2

// throw_away.hpp — Akl–Toussaint-style throw-away of interior points, the
// first parallel pass of the cpu 2D hull (Akl & Toussaint 1978; thesis §4.4
// compares with CGAL's ch_akl_toussaint). Thesis §4.2/§4.3 discard non-extreme
// points by flips (Alg 1) and by early removal (Alg 4 line 17); this pass
// discards most of them before any sort, in one read of the input.
//
// The throw-away polygon. Sample every (n/s)-th input point (s <= 2^17, fixed
// by n only, never by the thread count), take the exact SoS hull V of the sample (graham_sorting.hpp)
// and, as the centre c, the sample point nearest to V's centroid. Every V_j
// and c are *input points*. A point p is discarded iff for one j
//
//     orient2d(c, V_j, p) > 0,  orient2d(V_j, V_j+1, p) > 0,  orient2d(V_j+1, c, p) > 0
//
// hold exactly (unperturbed): then p lies in the open triangle c V_j V_j+1,
// an open set inside the hull of the input, so p is strictly inside the hull;
// under the infinitesimal perturbation it stays strictly inside, so it is no
// vertex of the canonical (SoS) hull, and removing it does not change the
// hull of the rest. Survivors keep their input indices (the perturbation is
// keyed by them). Which j is tried is a floating-point guess (the wedge of p's
// pseudo-angle around c, by a bucket table); a wrong guess only keeps p. A
// point is kept whenever a test is in doubt.
//
// The filter. Only points inside the bounding box [x0, x1] x [y0, y1] of c and
// V are tested, so every difference of the three determinants (rows q - p,
// q ∈ {c, V_j, V_j+1}) is at most W_x = fl(x1 - x0) and W_y = fl(y1 - y0) in
// magnitude (rounding is monotone). These are column bounds in the sense of
// predicates/static_filter.hpp (1)-(3): with W_x, W_y in the semi-static
// window [2^-480, 2^480], fl(det) > C_2 W_x W_y (C_2 = bound_constant(2),
// computed as there) proves det > 0 — one bound for the whole pass, the
// per-call semi-static filter's without its per-call magnitudes.
#pragma once

#include <cstddef>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::cpu::hull2 {

struct ThrowAwayResult {
  std::vector<Index> survivors;     // input indices, increasing
  std::size_t polygon_vertices = 0;  // vertices of V (0: no polygon, nothing discarded)
};

// The points of ps (2D) not proved strictly inside the throw-away polygon.
// Inputs of fewer than `from` points are kept whole; `sample`: the sample
// size (0: min(2^17, max(n / 64, 1024)); at most n).
ThrowAwayResult throw_away(const PointSet& ps, std::size_t from = 1024, std::size_t sample = 0);

}  // namespace flipflop::cpu::hull2

// ffhull.hpp — multithreaded ffHull for the 3D convex hull: thesis §6.4
// Algorithm 7 in the round structure of §6.4.1 ("GPU/parallel version"), on
// oneTBB.
//
// What runs in parallel (tbb::parallel_for / parallel_reduce inside one
// tbb::task_arena of `threads` threads):
//   * line 1, the initial tetrahedron: extreme points along x, then the point
//     furthest from the line ab, then the one furthest from the plane abc,
//     found by deterministic parallel reductions (approximate distances; the
//     four points are then checked affinely independent *exactly*);
//   * the per-input static filter bound (predicates/static_filter.hpp) from a
//     parallel scan of the coordinates;
//   * line 5, association of every point with the cone of a face of the
//     tetrahedron (three kernel-side predicates per point) and line 14's early
//     removal of points inside the tetrahedron (s, face);
//   * lines 6-14 in rounds (§6.4.1): in one round every triangle with
//     associated points is split by its (approximately, see below) furthest
//     point at once — the furthest point is a parallel reduction over the
//     triangle's points, the 1-3 splits write disjoint slots (the triangle's
//     own slot and two slots numbered by its rank in the round), adjacency is
//     repaired in a second parallel pass; then every associated point is
//     reassigned to one of the three new cones and tested for early removal
//     in parallel, and the points are regrouped by triangle with a stable
//     counting scatter (per-chunk counts, a scan, a parallel scatter).
// Line 15, flip-flop (Algorithm 6), two ways with the same output
// (Hull3Options::flip_flop):
//   * the reference's FIFO run (ff3::run, reference/hull3/flip_flop_3d.hpp),
//     sequential, with the same decisions in the same order (ffhull.cpp:
//     FlipFlop::run), on the reference's Polyhedron3 filled from the flat
//     arrays, with this kernel's fast kernel point, the static filter and
//     one edge lookup per step;
//   * rounds (§6.4.1, the labelling of §3.3.1; FlipFlop::run_rounds): all
//     candidate edges checked in parallel, each flip claiming the triangles
//     it replaces by an atomic minimum of its number, the flips that won all
//     their claims performed in parallel and stitched to their neighbours,
//     the edges they queue and the losers checked in the next round (10^6
//     ball: 52 rounds, 1.3x the FIFO run's checks). An earlier attempt that
//     claimed the quads' four vertices needed a round per incident edge of
//     the construction's high-degree vertices (3416 rounds on the 10^6 ball,
//     60x slower); claiming triangles lets the flips around one vertex run
//     together (their degree and corner updates are atomic).
// On this 2-core machine the rounds did not beat the FIFO run (measured in
// the README's 3D-hull section), so `automatic` takes them only with at
// least 4 threads on at least 4 cores.
//
// Why the answer equals the reference byte for byte: under the Simulation of
// Simplicity the hull is unique (DESIGN.md), and flip-flop returns the SoS
// hull of the vertices of any polyhedron star-shaped w.r.t. a point strictly
// inside its kernel whose vertices include every extreme point (Theorem 6.12).
// Which point is inserted into a triangle (line 8) does not change that: any
// point of the triangle's cone beyond it keeps the surface star-shaped, and a
// point is only dropped when it lies inside a tetrahedron spanned by the
// kernel point and a triangle of the surface, i.e. inside the hull of inputs
// (with the kernel point strictly inside the perturbed hull). So "furthest" is
// taken from double-precision distances (ties: the smaller index) and the
// tetrahedron need not be the reference's; every *decision* (cone, side,
// removal, flips) is an exact SoS predicate.
//
// The kernel point: the centroid of the tetrahedron rounded to doubles when
// that point is strictly inside the tetrahedron exactly (checked with exact
// orient3d), with SoS index n = ps.size() like the reference's exact centroid;
// otherwise (almost flat tetrahedra, §6.4.2's trap) the reference's exact
// RationalKernel. Either is strictly inside the perturbed tetrahedron.
//
// The witness (Hull3Options::witness): the certifier's interior point s is
// the kernel point itself — the witness hands over the initial tetrahedron,
// and the certifier rounds its centroid by the same rule — so the cones of
// the final hull from s are the kernel's. A point removed early (line 14)
// keeps the proof of its removal: the triangle (a, b, c) whose tetrahedron
// with s held it (hull3_witness.hpp: `beneath`), four predicates for the
// certifier and no walk. After flip-flop every other non-vertex (removed by
// a 3-1 flip) is located by a stochastic visibility walk over the final
// hull's cones (exact SoS orient3d with s, in parallel over the points)
// started at the facet a cube map of directions from s gives (certify_hull3_surface.hpp's
// DirectionTable with about one cell per facet: 2.1 steps per point on 10^6
// points of a 1e-4 sphere shell). Starting instead from the triangle each
// point was last associated with in the construction rounds (where it was
// inserted, or whose cone it was in when removed early) was measured worse:
// 33 steps per point on that shell (most points are removed while the
// surface is still coarse, and flip-flop reshapes it), 6.6 on the 10^6 ball.
// Points strictly inside the inner ball the certifier will verify
// (inner_ball.hpp, when it pays: hull3_witness.hpp) need no facet. The point
// lies beneath the facet found because the hull contains it; the certifier
// checks both.
//
// Input that does not span R^3 is rejected with the reference's
// std::invalid_argument (dimension_problem(ps)).
#pragma once

#include <vector>

#include "kernels_cpu/hull3/hull3_witness.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "kernels_cpu/stage_times.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// Line 15, flip-flop: the FIFO run, or rounds (ffhull.cpp: run_rounds);
// automatic: rounds with at least 4 threads on at least 4 cores. The output
// is the same.
enum class FlipFlopRun { automatic, fifo, rounds };

struct Hull3Options {
  int threads = 0;  // worker threads; 0: the runtime's default
  FlipFlopRun flip_flop = FlipFlopRun::automatic;
  // when set, filled with the seconds of each stage: initial tetrahedron,
  // inner box and ball (ffhull.cpp: inner_region, sample_ball) and static
  // filter, construction rounds, flip-flop, canonical output
  StageTimes* times = nullptr;
  // when set, filled with the witness for cpu::certify_hull3_witnessed
  // (hull3_witness.hpp): s's tetrahedron, the output, and per point the
  // record of its early removal or a facet whose cone from s contains it and
  // beneath which it lies (stages "witness: inner ball", "witness: walks")
  Hull3Witness* witness = nullptr;
};

// The canonical SoS convex hull (identical to ref::hull3_ffhull(ps)). stats,
// if given, is reset and filled: insertions (= 1-3 flips), discarded early,
// rounds (construction rounds), and flip-flop's 2-2/3-1 flips and labels.
std::vector<Triangle> hull3_ffhull(const PointSet& ps, const Hull3Options& opt = {},
                                   ref::Hull3Stats* stats = nullptr);

}  // namespace flipflop::cpu

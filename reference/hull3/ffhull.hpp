// ffhull.hpp — ffHull: thesis §6.4, Algorithm 7 (sequential version).
//
// Two stages: construct a polyhedron star-shaped w.r.t. a kernel point s
// whose vertex set contains every extreme point (lines 1-14), then flip-flop
// (line 15, Algorithm 6, flip_flop_3d.hpp) transforms it into the hull.
//
// The rules this implementation fixes where the thesis leaves a choice:
//
//  * Line 1, the initial tetrahedron: four points that are extreme under the
//    Simulation of Simplicity *and* affinely independent exactly. Each is the
//    unique maximiser of a linear functional f over the perturbed points:
//    exact values f·p compared exactly (GMP), exact ties broken by the
//    perturbation (the perturbation of point i is dominated by its
//    z-coordinate term, larger for smaller i — predicates.hpp — so among exact
//    ties the smallest index wins when the first non-zero of (f_z, f_y, f_x)
//    is positive, the largest index otherwise). A strict maximiser of a linear
//    functional is a vertex of the perturbed hull. The functionals:
//      a: f = -e_x;  b: f = +e_x  (x(a) < x(b) exactly: the input is 3D);
//      c: the first of ±(b-a)×e_x, ±(b-a)×e_y, ±(b-a)×e_z whose maximum
//         exceeds its value on the line ab (then c is off the line, exactly);
//      d: f = ±(b-a)×(c-a), the sign whose maximum exceeds its value on the
//         plane abc (then d is off the plane, exactly).
//  * Line 4, the kernel point: s = the exact centroid of a, b, c, d
//    (RationalKernel, SoS index n = ps.size()). §6.4.2 names the trap of an
//    inexact centroid, which can fall outside an almost flat tetrahedron;
//    here s is exact, and the four points are independent exactly (not only
//    under the perturbation), so s is strictly inside the tetrahedron both
//    before and after the infinitesimal perturbation (rational_kernel.hpp).
//  * Line 8, the furthest point of a triangle abc: the largest distance to the
//    plane of abc, i.e. the largest |orient3d(a, b, c, p)|, compared exactly
//    (a floating-point filter with a proven error bound, then GMP); exact ties
//    broken by the smaller index.
//  * Lines 6-10 ("foreach triangle associated by some points"): triangles are
//    processed in FIFO order of creation, which performs the rounds of the
//    pseudocode one after another.
//  * Line 14: a point on the inner side of its new triangle (with s) is
//    discarded (Hull3Stats::discarded_early) — also right after line 5.
//
// Input of fewer than 4 points, or whose points are all coplanar, collinear or
// equal, is rejected with std::invalid_argument carrying dimension_problem(ps).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reference/hull3/hull3_stats.hpp"
#include "reference/hull3/rational_kernel.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// The canonical SoS convex hull (identical to brute::hull3(ps)).
std::vector<Triangle> hull3_ffhull(const PointSet& ps, Hull3Stats* stats = nullptr);

namespace ffhull {

// Line 1: the initial tetrahedron (rule above), ordered so that (a, b, c) is
// counter-clockwise seen from outside, i.e. d on its inner side. Throws
// std::invalid_argument with dimension_problem(ps) for lower-dimensional input.
std::array<Index, 4> initial_tetrahedron(const PointSet& ps);

// How the constructing stage picks and keeps points (tests build many
// different star-shaped polyhedra of one point set with it).
struct BuildOptions {
  bool furthest = true;        // line 8: the furthest point; false: a random associated point
  bool discard_inside = true;  // lines 13-14; false: inner points are inserted too (dents)
  std::uint64_t seed = 0;      // for furthest == false
};

// Lines 1-14 with the kernel `s` (strictly inside the tetrahedron tet, whose
// first three points are counter-clockwise seen from outside): a surface
// star-shaped w.r.t. s whose vertices include every extreme point.
std::vector<Triangle> construct(const PointSet& ps, const KernelPoint& s, const std::array<Index, 4>& tet,
                                const BuildOptions& opt, Hull3Stats* stats);

}  // namespace ffhull

}  // namespace flipflop::ref

// certify_rt2.hpp — the exact certifier of a 2D regular / Delaunay
// triangulation (reference/certify, certify::rt2: Thm 2.2, every edge locally
// regular and every missing point redundant) with its per-triangle,
// per-vertex and per-point checks and its tables split over oneTBB tasks and
// the input's static filter (coordinates and weights) from a parallel scan.
// It needs no witnesses from the algorithm that produced the triangulation,
// so it also serves third-party outputs (`flipflop certify rt2|dt2`, e.g.
// CGAL's triangles). The kernel's own output is certified faster from its
// witness (the second certify_rt2 below, `flipflop rt2|dt2`). The verdict and its message are the sequential
// certifier's (certify.hpp, Speedups: the first failing triangle, vertex or
// point in the sequential order is reported).
#pragma once

#include <vector>

#include "kernels_cpu/rt2/rt2.hpp"  // Rt2Witness
#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

// threads: worker threads (0: the runtime's default).
certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                            int threads = 0);

// The witness-checked certifier of the kernel's own output (cpu::rt2 with a
// Rt2Witness): tris — the output about to be written — is RT(S ⊕ W) of ps
// (at Level::canonical: the one under SoS, in canonical form) when the
// witness passes, with a constant number of predicates per point and per
// edge, all checks in parallel and in the kernel's spatial order. Conditions
// in order (the first violated one is named; within one, the smallest slot
// or position):
//   input-dimension          the points span the plane (as certify::rt2)
//   witness-size             the arrays' sizes agree with ps
//   witness-points           pts is the input, permuted: each input index
//                            once, with its coordinates and weight bit for bit
//   triangle-indices         a used slot has three distinct positions (the
//                            virtual vertex allowed), an unused one none
//   triangle-orientation     every real triangle counter-clockwise (SoS)
//   neighbour-links          every edge of a real triangle has a twin in a
//                            used slot; between real triangles the links are
//                            symmetric and the twin is the same edge reversed
//   vertex-fan               a position that is a corner of a real triangle
//                            is a vertex (its `at` is a real triangle with it
//                            as a corner); around each vertex the triangles
//                            linked through its edges form one fan, a cycle
//                            or a path between two hull edges; the fans hold
//                            every corner of every real triangle
//   boundary                 the hull edges form one closed cycle
//   boundary-is-hull         that cycle is the convex hull of all input points
//                            (certify::hull2: convex, winding once)
//   locally-regular          every interior edge (Thm 2.2): one power test of
//                            the neighbour's opposite vertex
//   missing-point-witness    every other position lies in its witness triangle
//                            (a real triangle; 3 orient, SoS)
//   missing-point-redundant  and is redundant there (1 power test)
//   canonical-output         tris is the witnessed triangle set (input
//                            indices), at Level::canonical in canonical form
//                            (DESIGN.md); at Level::exact in any rotation and
//                            order
// Why these suffice is written out in certify_rt2.cpp.
certify::Report certify_rt2(const PointSet& ps, const std::vector<Triangle>& tris, certify::Level level,
                            const Rt2Witness& witness, int threads = 0);

}  // namespace flipflop::cpu

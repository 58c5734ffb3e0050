// peers.hpp — the programs a user would pick instead of flipflop, wrapped so
// that they return flipflop's canonical index output (DESIGN.md, "Canonical
// output"): 0-based input indices; a 2D hull counter-clockwise starting at its
// smallest index; triangles counter-clockwise (seen from outside for a 3D
// hull), rotated so the smallest index comes first, sorted lexicographically.
//
// The peers decide with their own arithmetic and their own rules for
// degeneracies — Qhull with floating point and facet merging, CGAL with exact
// predicates but without flipflop's Simulation of Simplicity — so on
// degenerate input (collinear / coplanar / cocircular points, duplicates)
// their answers may legitimately differ from flipflop's unique SoS answer.
// On input in general position they must agree with it exactly.
//
// Duplicated points: a location held by several input points is reported
// under the index of the copy the peer keeps (Qhull, CGAL 2D hulls and
// triangulations), except where the wrapper has to map locations back to
// indices itself (cgal_hull3, cgal_extreme_points_3): there it is the SMALLEST
// index holding that location.
#pragma once

#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::peers {

// ---- Qhull (libqhull_r, reentrant C API) -----------------------------------
// Vertices of the 2D hull ("qhull" default options: Qhull merges coplanar
// facets, so collinear boundary points are not vertices).
std::vector<Index> qhull_hull2(const PointSet& pts);
// Facets of the 3D hull ("qhull Qt": merged facets triangulated).
std::vector<Triangle> qhull_hull3(const PointSet& pts);
// Delaunay triangulation of 2D points ("qhull d Qbb Qt": qdelaunay's options
// with triangulated output; scipy.spatial.Delaunay adds Qc Qz Q12): the
// lower facets of the lifted hull,
// counter-clockwise. Qhull merges cocircular facets and triangulates them
// its own way; duplicated points are kept once.
std::vector<Triangle> qhull_delaunay2(const PointSet& pts);
// Errors reported by Qhull (too few points, lower-dimensional input, e.g.
// QH6154 "initial simplex is flat") are thrown as std::runtime_error holding
// the first line of Qhull's message.

// ---- CGAL 2D convex hull ------------------------------------------------------
enum class Hull2Algo { akl_toussaint, graham_andrew };
// Exact predicates (Epick). Only strictly convex vertices are reported.
// Throws std::runtime_error when all points are collinear.
std::vector<Index> cgal_hull2(const PointSet& pts, Hull2Algo algo);

// ---- CGAL 3D convex hull ------------------------------------------------------
// CGAL::convex_hull_3 (quickhull, Epick exact predicates) into a Surface_mesh.
// Coplanar facets come triangulated in CGAL's own (arbitrary) way. Throws
// std::runtime_error when the hull is not a closed polyhedron (fewer than four
// affinely independent points).
std::vector<Triangle> cgal_hull3(const PointSet& pts);
// The strictly extreme points of the input: the vertices of convex_hull_3
// whose incident facets span at least three distinct planes (a vertex of the
// mesh lying in the relative interior of a hull facet or edge is dropped).
// Sorted by index; throws like cgal_hull3.
std::vector<Index> cgal_extreme_points_3(const PointSet& pts);

// ---- CGAL 2D triangulations ----------------------------------------------------
// Delaunay triangulation (Delaunay_triangulation_2, Epick); finite faces only.
// Cocircular points are triangulated in CGAL's own way.
std::vector<Triangle> cgal_delaunay2(const PointSet& pts);
// Regular triangulation (Regular_triangulation_2, Epick) of a weighted 2D set:
// CGAL's Weighted_point weight is the squared radius, the same w as in
// flipflop's power distance |x - p|^2 - w (predicates.hpp, power2d).
// Redundant (hidden) points are not vertices. Finite faces only.
// build_seconds (optional): the construction alone (CGAL's spatially sorted
// range insertion), without copying the input and sorting the output.
std::vector<Triangle> cgal_regular2(const PointSet& weighted, double* build_seconds = nullptr);

}  // namespace flipflop::peers

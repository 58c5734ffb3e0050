// triangulation3.hpp — the 3D Delaunay / regular triangulators a user would
// pick instead of `flipflop dt3|rt3` (DESIGN.md "Benchmarks"), wrapped to
// return flipflop's canonical tetrahedron output (reference/rtd/
// canonical_d.hpp; DESIGN.md "Canonical output"): each tetrahedron a
// quadruple of 0-based input indices, positively oriented in the volume
// convention (det[p1 - p0, p2 - p0, p3 - p0] > 0, CGAL's orientation),
// smallest index first, the other three ascending but for the last two
// swapped when that restores the orientation; the list sorted.
//
// Each peer decides with its own arithmetic and breaks ties its own way: CGAL
// with exact predicates (Epick) and its symbolic perturbation, TetGen with
// Shewchuk's adaptive exact predicates and its own perturbation, Qhull in
// floating point with facet merging ("Qt" then triangulates merged facets,
// possibly into flat tetrahedra). So on degenerate input (5 cospherical or 4
// coplanar points, duplicates) their answers may legitimately differ from
// flipflop's unique Simulation-of-Simplicity answer, and from each other; on
// input in general position the exact ones (CGAL, TetGen) must equal it, and
// Qhull does unless rounding misleads it.
//
// Hidden points. A regular triangulation leaves out its redundant points: CGAL
// hides them and they are vertices of no tetrahedron here. A duplicated
// location is a vertex once, under the index of the copy the peer keeps (its
// own choice: CGAL's range insertion writes the index of each copy into the
// one vertex in turn, so the last copy in its spatial order wins; TetGen and
// Qhull keep the copy they met first). Under flipflop's perturbation the
// copies are distinct points, and each vertex or redundant by its own
// perturbed height.
//
// Timing (the bench's rows): each function copies the input into the peer's
// types, runs the peer, and puts its tetrahedra in canonical form — the
// orientation from one exact orientation test where the peer's invariant
// fixes it for every cell (CGAL, TetGen), from an exact test per tetrahedron
// where it does not (Qhull); the list by a counting sort on the smallest
// index. build_seconds (optional) receives the peer's construction alone.
#pragma once

#include <array>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::peers {

using Tet = std::array<Index, 4>;

// The canonical form (header) of volume-positive tetrahedra, sorted (a
// counting sort by smallest index, then each bucket sorted).
std::vector<Tet> canonical_tets(std::vector<Tet> volume_positive);

struct Cgal3Options {
  // false: the sequential triangulation (Sequential_tag). true: Parallel_tag
  // — the triangulation data structure with a lock data structure over the
  // input's bounding box (a 50^3 grid of locks), insertion by
  // tbb::parallel_for after 100 points inserted sequentially — on `threads`
  // threads (a tbb::task_arena; 0: TBB's default, the machine's cores).
  bool parallel = false;
  int threads = 0;
  double* build_seconds = nullptr;  // the construction alone
};

// CGAL::Delaunay_triangulation_3 (Exact_predicates_inexact_constructions_kernel)
// of the points (weights ignored), built by range insertion of (point, index)
// pairs: CGAL's spatial sort (Hilbert order), then insertion with the previous
// vertex as the hint. Throws std::runtime_error when the points do not span
// R^3.
std::vector<Tet> cgal_delaunay3(const PointSet& ps, const Cgal3Options& o = {});

// CGAL::Regular_triangulation_3 (Epick) of the weighted points, the same way.
// CGAL's weight is the squared radius: power(x, (p, w)) = |x - p|^2 - w, the
// same w as flipflop's. Unweighted input has weights 0 (the Delaunay
// triangulation). Throws std::runtime_error when the triangulation is
// lower-dimensional.
std::vector<Tet> cgal_regular3(const PointSet& ps, const Cgal3Options& o = {});

// Qhull (libqhull_r) "d Qt Qbb": the Delaunay triangulation as the lower hull
// of the points lifted to the paraboloid, the lifted coordinate scaled to the
// others' range (Qbb), merged facets triangulated (Qt) — the options and the
// engine behind scipy.spatial.Delaunay (which adds Qc Qz Q12). Weights
// ignored. Each tetrahedron oriented by an exact orientation test (CGAL's); a
// flat one (Qt on merged facets) keeps Qhull's order. Qhull's errors are
// thrown as std::runtime_error holding its first line.
std::vector<Tet> qhull_delaunay3(const PointSet& ps, double* build_seconds = nullptr);

// TetGen 1.5 (Debian's libtet), tetrahedralize() with the switches "Q"
// (quiet; no -p: the Delaunay tetrahedralization of the points). Weights
// ignored. Throws std::runtime_error when TetGen fails, and when this build
// has no TetGen (tetgen_available() false).
std::vector<Tet> tetgen_delaunay3(const PointSet& ps, double* build_seconds = nullptr);
bool tetgen_available();

}  // namespace flipflop::peers

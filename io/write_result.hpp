// write_result.hpp — results written in the format the output file's
// extension names (DESIGN.md "The command-line tool": "-o FILE picks the
// format by extension ... an unknown extension is an error").
//
//   (none), .txt, .idx, "-"  index text: the canonical format (index_io.hpp,
//                            canonical_d.hpp, strict_hull3.hpp); written by
//                            the caller, which owns that text
//   .off .obj                polygon meshes through CGAL's writers
//                            (CGAL::IO::write_OFF / write_OBJ, polygon soups)
//   .ply                     CGAL's Surface_mesh PLY writer, binary little
//                            endian (ASCII with `ascii`), with the per-vertex
//                            property `uint input_index`
//   .stl                     CGAL's STL writer (binary; ASCII with `ascii`);
//                            STL holds triangles only: polygons are
//                            fan-triangulated from their first vertex,
//                            leaving out triangles of zero area (exact
//                            orientation), so that a convex polygon is
//                            covered exactly once
//   .vtu                     VTK XML unstructured grid (ASCII): VTK_POLYGON,
//                            VTK_TRIANGLE or VTK_TETRA cells, point data
//                            `input_index` (Int64)
//   .npy                     numpy (format 1.0, little-endian int64): the
//                            index array of the canonical answer, shape
//                            (cells, k) when every cell has k vertices, or
//                            (k,) for a single cycle (the 2D hull)
//   .svg                     2D results only: every input point, the cells
//                            (triangles or the hull polygon), the points
//                            `marked` (redundant points) drawn as red crosses
//
// Mesh formats (.off .obj .ply .stl .vtu) hold only the points that are
// vertices of some cell, in increasing input index: the i-th vertex of the
// file is the i-th smallest input index used (PLY and VTU also carry that
// index); 2D points get z = 0. Coordinates are written with 17 significant
// digits (ASCII) or as the input's doubles (binary): the geometry is the
// input's exactly. A format that cannot hold the result (d-simplices for
// d >= 3 in a surface format, d >= 4 in VTU, a 3D result in SVG, polygons of
// different sizes in NPY) is refused with std::invalid_argument naming the
// formats that can; nothing is written then.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::io {

enum class Format { index, off, obj, ply, stl, vtu, npy, svg };

// The format of an output path by its extension (case-insensitive); ""/"-"
// (standard output) is index text. Throws std::invalid_argument
// "PATH: unknown output extension '.EXT' (known: ...)".
Format output_format(const std::string& path);
const char* format_name(Format f);

// What the cells are: `cycle` (the 2D hull: one polygon, NPY shape (k,)),
// `polygons` (triangles of a 2D triangulation or of a 3D hull, strict hull
// polygons; in 2D or 3D) or `simplices` (d-simplices of a d-dimensional
// triangulation, d = ps.dim).
enum class CellKind { cycle, polygons, simplices };

// Writes `cells` (input indices) over the points of `ps` to `path` in format
// f (not Format::index). Throws std::invalid_argument when f cannot hold the
// result, std::runtime_error "PATH: cannot write: ..." when the file cannot
// be written.
void write_cells(const std::string& path, Format f, const PointSet& ps, const std::vector<std::vector<Index>>& cells,
                 CellKind kind, const std::vector<Index>& marked = {}, bool ascii = false);

// The .npy index array of `cells` (format 1.0, little-endian int64): shape
// (cells, k) when every cell has k vertices, (k,) for one cycle (the 2D
// hull), as write_cells writes Format::npy. The cells must all have the same
// size.
void write_npy_indices(std::ostream& os, const std::vector<std::vector<Index>>& cells, bool one_cycle);
// The same (cells, k) array from `count` cells of k vertices stored flat
// (cell i is flat[i*k .. i*k+k-1]), without a vector per cell.
void write_npy_indices(std::ostream& os, const Index* flat, std::size_t count, std::size_t k);

// Fan triangulation of convex polygons from their first vertex, leaving out
// the triangles whose three points are collinear (exact orient test in the
// polygons' plane; 2D or 3D points). Orientation kept.
std::vector<std::vector<Index>> fan_triangulate(const PointSet& ps, const std::vector<std::vector<Index>>& polygons);

}  // namespace flipflop::io

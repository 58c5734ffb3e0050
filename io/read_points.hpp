// read_points.hpp — reading point files (.xyz, .off, .ply).
//
// DESIGN.md "Input files". The format is chosen by the extension, ignoring
// case:
//   .xyz  one point per line, white-space separated columns x y [z] [w]
//         (exactly dim columns, plus the weight last when weighted); '#'
//         starts a comment; blank lines are ignored. Numbers are parsed with
//         std::from_chars (correctly rounded), so files written by
//         write_points() read back bit for bit.
//   .off  3D vertices, read with CGAL's point reader (CGAL::IO::read_OFF);
//   .ply  3D vertices (ASCII or binary), read with CGAL's PLY reader
//         (CGAL::IO::read_PLY_with_properties); a weight comes from a vertex
//         property named `w` or `weight`.
// Before CGAL reads a file, a streaming scan checks the header and (ASCII)
// every vertex line, so that a problem is reported with its line, and a
// binary PLY is checked against its size (problems name the vertex number).
// For dim == 2 the z coordinate of every .off/.ply vertex must be 0.
//
// Every problem throws InputError with one line "FILE:LINE: problem" (or
// "FILE: problem"): unreadable file, no points, malformed number, wrong column
// count, NaN or Inf, fewer than dim + 1 points, unknown extension.
#pragma once

#include <string>

#include "io/input_error.hpp"
#include "reference/point_set.hpp"

namespace flipflop::io {

// dim is 2 to 9 (.off and .ply: 2 or 3). The result has dim, weighted, coords
// (and weights) set.
PointSet read_points(const std::string& path, int dim, bool weighted);

}  // namespace flipflop::io

// index_io.hpp — index output: canonical form, writing, and reading back
// (ours or a third party's, for the certifier).
//
// Canonical output (DESIGN.md): two backends agree when their canonical files
// are byte-identical.
//   2D hull    one vertex index per line, counter-clockwise, starting at the
//              smallest index;
//   triangles  "i j k" per line, orientation kept (counter-clockwise seen from
//              outside for a 3D hull, counter-clockwise for a 2D
//              triangulation), each rotated so that its smallest index comes
//              first, lines sorted lexicographically.
// Rotating a cycle keeps its orientation; nothing here reorders vertices in
// any other way.
//
// The readers skip blank lines and '#' comments and throw InputError
// "FILE:LINE: problem" for a token that is not an index (a non-negative
// integer below 2^32), a negative index, or a wrong number of indices on a
// line. Whether the indices name existing points is the certifier's check.
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.hpp"
#include "reference/canonical.hpp"
#include "reference/point_set.hpp"

namespace flipflop::io {

// The canonical form (reference/canonical.hpp), re-exported for writers' users.
using ::flipflop::canonical_hull2;
using ::flipflop::canonical_triangles;

// One index per line.
void write_hull2(std::ostream& os, const std::vector<Index>& cycle);
// "i j k" per line.
void write_triangles(std::ostream& os, const std::vector<Triangle>& triangles);
// "i j k l" per line (reference/rtd/canonical_d.hpp's text of 3-simplices),
// from flat tetrahedra (kernels_cpu/rt3's output) without a vector each.
void write_tetrahedra(std::ostream& os, const std::vector<std::array<Index, 4>>& tets);

// One index per line (a 2D hull cycle).
std::vector<Index> read_index_cycle(const std::string& path);

// "i j k" per line. Also reads the output of `qhull i Qt`: a first line with
// a single integer, the facet count, followed by one facet "i j k" per line;
// the count must match the facets that follow. Qhull lists 3-d facets
// clockwise seen from outside; they are returned reversed, counter-clockwise.
std::vector<Triangle> read_triangles(const std::string& path);

// The strict view of a 3D hull (`flipflop hull3 --strict`, format in
// reference/hull3/strict_hull3.hpp): a line "E F", E lines of one index, F
// lines of at least 3 indices each. Counts that do not match the lines that
// follow, and facets of fewer than 3 indices, are an InputError naming the
// line. Returns (extreme points, facets) as written (not validated further:
// that is the certifier's job).
std::pair<std::vector<Index>, std::vector<std::vector<Index>>> read_strict_hull3(const std::string& path);

}  // namespace flipflop::io

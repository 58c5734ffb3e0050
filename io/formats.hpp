// formats.hpp — the per-format readers behind read_points() (internal).
// Each reads and checks one format completely, including check_count().
#pragma once

#include <cstddef>
#include <string>

#include "reference/point_set.hpp"

namespace flipflop::io::detail {

// .xyz holds up to kMaxXyzColumns columns: d <= 5 coordinates and a weight.
inline constexpr int kMaxXyzColumns = 10;  // 9 coordinates and a weight

PointSet read_xyz(const std::string& path, int dim, bool weighted);

// The .xyz reader's sizes (read_xyz.cpp): bytes read at a time, text per
// parallel task, the longest line (text.hpp LineReader::max_line). Tests make
// them small so that block and piece boundaries fall inside the numbers and
// lines of small files; block is raised to at least 2 max_line.
struct XyzLayout {
  std::size_t block = std::size_t{8} << 20;
  std::size_t piece = std::size_t{64} << 10;
  std::size_t max_line = std::size_t{1} << 16;
};
PointSet read_xyz(const std::string& path, int dim, bool weighted, const XyzLayout& layout);
PointSet read_off(const std::string& path, int dim, bool weighted);
PointSet read_ply(const std::string& path, int dim, bool weighted);
PointSet read_npy(const std::string& path, int dim, bool weighted);

// Name of coordinate column c of a dim-dimensional point ("x", "y", "z"; for
// dim > 3 "x1".."x9"), or "w" for the weight column (c == dim).
const char* column_name(int c, int dim);

// Throws InputError(path, line, ...) when ps holds no points or fewer than
// dim + 1 ("2 points, at least 3 needed"); line 0 names no line.
void check_count(const PointSet& ps, const std::string& path, std::size_t line);

// Appends one point (and its weight) to ps; throws when the count would no
// longer fit an Index.
void append_point(PointSet& ps, const double* x, double w, const std::string& path,
                  std::size_t line);

}  // namespace flipflop::io::detail

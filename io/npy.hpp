// npy.hpp — the layout of a .npy point file without reading its data: what
// io::read_points reads (numpy format 1.0, 2.0, 3.0; little-endian float64,
// C order, shape (n, d) or (n, d + 1) with the weight last), for readers
// that map or stream the rows themselves (distributed/: each MPI rank maps
// only its own rows of a directory of .npy shards).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace flipflop::io {

struct NpyLayout {
  std::uint64_t rows = 0;         // n
  int cols = 0;                   // d, or d + 1 with a weight column
  std::uint64_t data_offset = 0;  // bytes before the first value
};

// Reads and checks the header of `path` for `dim` coordinates (and a weight
// column when `weighted`), and that the file holds all the rows the header
// announces. Throws InputError with one line "PATH: problem" otherwise (the
// messages of io::read_points for .npy). Zero rows are allowed here; the
// caller decides whether that is an error.
NpyLayout npy_layout(const std::string& path, int dim, bool weighted);

// "NaN in row R, column C (x)" (C 1-based; the column's name for `dim`
// coordinates, "w" for the weight column), or the same with "Inf": the one
// line every reader gives for a non-finite value (without the file name).
std::string nonfinite_problem(double value, std::uint64_t row, int column, int dim);

}  // namespace flipflop::io

// write_points.hpp — writing point files, and checked file output.
//
// Points are written as .xyz with the shortest decimal that reads back to the
// same double (std::to_chars), so write_points() followed by read_points()
// is the identity, bit for bit, subnormals and ±1e300 included.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

#include "reference/point_set.hpp"

namespace flipflop::io {

// .xyz: "x y [z] [w]" per line, shortest round-trip decimals.
void write_points(std::ostream& os, const PointSet& ps);

// .npy (NumPy format 1.0): little-endian float64 of shape (n, d), or
// (n, d + 1) with the weight last — what io::read_npy reads back, bit for bit.
void write_points_npy(std::ostream& os, const PointSet& ps);

// The start of a .npy file (format 1.0): magic, version, header length and
// the header dict for `descr` ('<f8', '<i8', ...) and `shape` ("(3,)",
// "(10, 2)"), padded so that the data starts at a multiple of 64 bytes.
void write_npy_header(std::ostream& os, const char* descr, const std::string& shape);

// Opens `path`, lets `body` write, flushes and closes; throws
// std::runtime_error("PATH: cannot write: REASON") — one line — when the file
// cannot be opened or any write, the flush or the close fails.
void write_file(const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace flipflop::io

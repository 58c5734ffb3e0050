// fuzz_input.hpp — decoding fuzz bytes into small, mostly degenerate point
// sets, and reporting a violated property; shared by the fuzz targets.
//
// Point-set byte layout (decode_points; missing bytes read as 0, so every
// byte string decodes to some input):
//   byte     n = min_n + byte mod (max_n - min_n + 1); decoding stops early
//            (after at least min_n points) when the bytes run out, so that
//            short inputs are small point sets
//   byte     scale: even → none; odd → every coordinate times 2^e and every
//            weight times 2^(2e), e = 16·((int8)byte >> 1) in [-1024, 1008]
//            (power-of-two scaling keeps every exact degeneracy, also the
//            power-circle ones; an overflow to Inf skips the input)
//   per point: a mode byte, its operand bytes, then one weight byte when
//   weighted (w = (int8)byte / 4: quarters, exact):
//     0  small integers in [-8, 7] (one byte per coordinate): collinear,
//        coplanar and duplicate points are frequent
//     1  int8 coordinates
//     2  a copy of an earlier point (byte: which)
//     3  an earlier point (byte: which) moved by -2..+2 ulps per coordinate
//        (one byte per coordinate, std::nextafter)
//     4  a + t·(b - a) for earlier points a, b (two bytes) and t = (int8)/4:
//        on their line, exactly when the products are exact
//     5  raw little-endian binary64 per coordinate (non-finite → 0)
//     6  one special magnitude per coordinate: 0, 2^-1074, 1e-310, DBL_MIN,
//        1e-300, 0.1, 1, 3, 1e15, 2^53, 1e300, DBL_MAX/8, 0.5, 1e-15, 7,
//        1e-3 (bits 0-3), sign (bit 4), factor 1..8 (bits 5-7)
//     7  an integer point on the circle x²+y² = 25 (2D, 12 of them) or the
//        sphere x²+y²+z² = 9 (3D, 30 of them; in d > 3 its coordinates in
//        three consecutive places chosen by the byte): cocircular / cospherical
// Modes 2-4 fall back to mode 0 when there are not enough earlier points.
// fuzz/make_seed_corpus.py writes seeds in this layout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::fuzz {

struct ByteReader {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos = 0;
  std::uint8_t byte() { return pos < size ? data[pos++] : 0; }
  bool at_end() const { return pos >= size; }
};

// Returns false (and leaves `out` unspecified) when a scaled value is not
// finite: the input is then skipped.
bool decode_points(ByteReader& r, int dim, bool weighted, std::size_t min_n, std::size_t max_n,
                   PointSet& out);

// The point set as an .xyz text with hexadecimal floats (exact), for reports.
std::string describe(const PointSet& ps);
std::string describe(const std::vector<Index>& cycle);
std::string describe(const std::vector<Triangle>& tris);

// Prints "TARGET: WHAT" and the details to stderr and aborts (libFuzzer then
// saves the input as a crash reproducer; the replay test fails).
[[noreturn]] void fail(const char* target, const std::string& what, const std::string& details = "");

}  // namespace flipflop::fuzz

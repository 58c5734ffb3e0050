// read_points_check.cpp — fuzz_read_points: any bytes as a point file.
//
// Byte 0 chooses how the rest is read: bits 0-1 the extension (0 .xyz,
// 1 .off, 2 .ply, 3 an upper/mixed-case spelling of one of them chosen by
// bits 4-5: the readers ignore case), bit 2 the dimension (3, else 2), bit 3
// weighted. The remaining bytes are the file. io::read_points must either
//   * return a valid PointSet: the requested dim and weighted flag, at least
//     dim + 1 points, coords and weights of matching sizes, every value
//     finite — and writing it as .xyz (io::write_points) and reading it back
//     gives the same values bit for bit (the documented round trip); or
//   * throw io::InputError whose message is one line naming the file
//     (e.file() is the path and what() contains it).
// Any other exception, a crash, a hang or a sanitizer report is a bug.
#include <cmath>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "fuzz/input_error_check.hpp"
#include "fuzz/temp_file.hpp"
#include "io/io.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_read_points";

std::string extension(std::uint8_t b) {
  static const char* plain[3] = {".xyz", ".off", ".ply"};
  static const char* odd[3] = {".XYZ", ".Off", ".pLy"};
  return (b & 3) < 3 ? plain[b & 3] : odd[((b >> 4) & 3) % 3];
}

void check_valid(const PointSet& ps, int dim, bool weighted, const std::string& path) {
  const std::string where = " (file " + path + ")";
  if (ps.dim != dim) fail(kTarget, "wrong dimension " + std::to_string(ps.dim) + where);
  if (ps.weighted != weighted) fail(kTarget, "wrong weighted flag" + where);
  const std::size_t n = ps.size();
  if (ps.coords.size() != n * static_cast<std::size_t>(dim))
    fail(kTarget, "coords size is not a multiple of dim" + where);
  if (ps.weights.size() != (weighted ? n : 0)) fail(kTarget, "weights size does not match" + where);
  if (n < static_cast<std::size_t>(dim) + 1)
    fail(kTarget, "returned " + std::to_string(n) + " points, fewer than dim + 1" + where);
  for (double v : ps.coords)
    if (!std::isfinite(v)) fail(kTarget, "returned a non-finite coordinate" + where, describe(ps));
  for (double w : ps.weights)
    if (!std::isfinite(w)) fail(kTarget, "returned a non-finite weight" + where, describe(ps));
}

void check_round_trip(const PointSet& ps, int dim, bool weighted) {
  std::ostringstream os;
  io::write_points(os, ps);
  const std::string text = os.str();
  TempFile back("roundtrip", ".xyz", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  PointSet again;
  try {
    again = io::read_points(back.path(), dim, weighted);
  } catch (const std::exception& e) {
    fail(kTarget, std::string("write_points output does not read back: ") + e.what(), describe(ps));
  }
  if (!same_bits(ps.coords, again.coords) || !same_bits(ps.weights, again.weights) ||
      again.dim != ps.dim || again.weighted != ps.weighted)
    fail(kTarget, "write_points + read_points changed the points", describe(ps) + describe(again));
}

}  // namespace

bool check_read_points_input(const std::uint8_t* data, std::size_t size) {
  const std::uint8_t mode = size > 0 ? data[0] : 0;
  const int dim = (mode & 4) ? 3 : 2;
  const bool weighted = (mode & 8) != 0;
  TempFile file("points", extension(mode), size > 0 ? data + 1 : data, size > 0 ? size - 1 : 0);
  PointSet ps;
  try {
    ps = io::read_points(file.path(), dim, weighted);
  } catch (const io::InputError& e) {
    check_input_error(kTarget, e, file.path());
    return true;
  } catch (const std::exception& e) {
    fail(kTarget, std::string("exception other than io::InputError: ") + e.what());
  } catch (...) {
    fail(kTarget, "non-standard exception");
  }
  check_valid(ps, dim, weighted, file.path());
  check_round_trip(ps, dim, weighted);
  return true;
}

}  // namespace flipflop::fuzz

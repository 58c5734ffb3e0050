// read_off.cpp — the .off reader: CGAL's point reader, checked line by line.
//
// CGAL::IO::read_OFF (Point_set_processing_3, read_off_points.h) reads the
// vertices. It is lenient: a vertex line it cannot parse is skipped without a
// word, which would shift every later vertex. So a streaming scan first checks
// the file against exactly the rules CGAL applies, and reports the first
// violation with its line:
//   * a line that is empty or starts with '#' is skipped (CGAL's rule);
//   * the first other line is the keyword OFF or NOFF, alone (COFF, 4OFF,
//     binary OFF and counts on the keyword line are not read by CGAL's point
//     reader and are refused with a message saying so);
//   * the next line holds the counts "V F E";
//   * then V vertex lines "x y z" or "x y z nx ny nz" (always 6 for NOFF),
//     a '#' comment may end a line; lines holding only white space or a
//     comment are skipped (CGAL skips them too).
// Every coordinate must be a finite decimal number; for dim == 2, z must be 0.
// Faces are not read.
#include <CGAL/IO/read_off_points.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string_view>

#include "io/cgal_sink.hpp"
#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace flipflop::io::detail {

namespace {

using Point_3 = CGAL::Simple_cartesian<double>::Point_3;

bool ends_with_off(std::string_view s) { return s.size() >= 3 && s.substr(s.size() - 3) == "OFF"; }

}  // namespace

PointSet read_off(const std::string& path, int dim, bool weighted) {
  if (weighted)
    throw InputError(path,
                     "an .off file carries no weights; give weighted points as .xyz with the "
                     "weight as the last column");
  PointSet ps;
  ps.dim = dim;
  ps.weighted = false;

  // ---- The scan -----------------------------------------------------------
  LineReader in(path);
  enum class State { keyword, counts, vertices } state = State::keyword;
  bool noff = false;
  long long nv = 0;
  std::size_t counts_line = 0, seen = 0;
  std::string_view line;
  std::string_view tok[8];
  while (state != State::vertices || seen < static_cast<std::size_t>(nv)) {
    if (!in.next(line)) break;
    if (line.empty() || line[0] == '#') continue;
    const std::size_t ln = in.line_number();
    const std::string_view data = line.substr(0, line.find('#'));
    if (state == State::keyword) {
      // CGAL reads the first white-space separated word of the raw line.
      std::string_view word;
      if (split(line, &word, 1) == 0) throw InputError(path, ln, "expected the keyword OFF, found a blank line");
      if (word != "OFF" && word != "NOFF") {
        if (ends_with_off(word))
          throw InputError(path, ln,
                           "unsupported OFF variant " + show(word) +
                               "; CGAL's point reader reads OFF and NOFF files");
        throw InputError(path, ln, "not an OFF file: expected the keyword OFF, found " + show(word));
      }
      noff = word == "NOFF";
      const std::size_t k = split(data, tok, 8);
      if (k > 1)
        throw InputError(path, ln,
                         tok[1] == "BINARY"
                             ? std::string("binary OFF is not supported; write the file as text")
                             : std::string("the counts \"V F E\" must be on their own line after "
                                           "the keyword (CGAL's point reader)"));
      state = State::counts;
    } else if (state == State::counts) {
      const std::size_t k = split(data, tok, 8);
      long long c[3] = {0, 0, 0};
      for (std::size_t i = 0; i < k && i < 3; ++i)
        if (!parse_integer(tok[i], 0, std::numeric_limits<long>::max(), c[i]))
          throw InputError(path, ln, "expected the counts \"V F E\", found " + show(tok[i]));
      if (k != 3)
        throw InputError(path, ln,
                         "expected the 3 counts \"V F E\", found " + std::to_string(k) +
                             (k == 1 ? " number" : " numbers"));
      nv = c[0];
      counts_line = ln;
      state = State::vertices;
    } else {
      const std::size_t k = split(data, tok, 8);
      if (k == 0) continue;
      if (k != 6 && (noff || k != 3))
        throw InputError(path, ln,
                         std::string(noff ? "expected 6 numbers (x y z nx ny nz)"
                                          : "expected 3 numbers (x y z) or 6 (x y z nx ny nz)") +
                             ", found " + std::to_string(k));
      double v[6];
      for (std::size_t c = 0; c < k; ++c) {
        const Num s = parse_real(tok[c], v[c]);
        if (s != Num::ok)
          throw InputError(path, ln,
                           describe(s, tok[c]) + " in column " + std::to_string(c + 1) + " (" +
                               (c < 3 ? column_name(static_cast<int>(c), 3) : "normal") + ")");
      }
      if (dim == 2 && v[2] != 0.0)
        throw InputError(path, ln,
                         "z = " + show(tok[2]) + " is not 0 (vertex " + std::to_string(seen) +
                             "); a 2D input needs z = 0 for every vertex");
      ++seen;
    }
  }
  if (state != State::vertices) {
    if (in.line_number() == 0) throw InputError(path, "empty file, no points");
    throw InputError(path, in.line_number(), "end of file inside the OFF header");
  }
  if (seen < static_cast<std::size_t>(nv))
    throw InputError(path, in.line_number(),
                     "end of file after " + std::to_string(seen) + " of the " + std::to_string(nv) +
                         " vertices declared on line " + std::to_string(counts_line));
  // CGAL's OFF point reader counts vertices in an int.
  if (nv > std::numeric_limits<int>::max())
    throw InputError(path, counts_line,
                     "more than " + std::to_string(std::numeric_limits<int>::max()) +
                         " vertices (CGAL's OFF point reader counts in int); use .xyz");
  if (nv == 0) throw InputError(path, counts_line, "no points (the header declares 0 vertices)");

  // ---- CGAL reads the vertices the scan has checked ------------------------
  const auto n = static_cast<std::size_t>(nv);
  ps.coords.reserve(n * static_cast<std::size_t>(dim));
  auto put = [&ps, dim](const Point_3& p) {
    const double x[3] = {p.x(), p.y(), p.z()};
    ps.coords.insert(ps.coords.end(), x, x + dim);
  };
  std::size_t count = 0;
  std::ifstream is(path);
  try {
    CGAL::IO::read_OFF<Point_3>(is, CgalSink<Point_3, decltype(put)>(n, &count, put));
  } catch (const Enough&) {
  }
  if (count != n)
    throw InputError(path, "CGAL's OFF reader delivered " + std::to_string(count) + " of " +
                               std::to_string(n) + " vertices");
  check_count(ps, path, counts_line);
  return ps;
}

}  // namespace flipflop::io::detail

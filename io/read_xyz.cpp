// read_xyz.cpp — the .xyz reader: one point per line, streamed.
//
// Lines are read through a bounded buffer (text.hpp) and checked as they
// come, so the first bad line stops the reading: a huge file of garbage costs
// one buffer, not the file.
#include <string_view>

#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace flipflop::io::detail {

PointSet read_xyz(const std::string& path, int dim, bool weighted) {
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;
  const std::size_t cols = static_cast<std::size_t>(dim) + (weighted ? 1 : 0);
  std::string layout;  // "x y z w", "x1 x2 x3 x4 w"
  for (int c = 0; c < static_cast<int>(cols); ++c) layout += (c ? " " : "") + std::string(column_name(c, dim));

  LineReader in(path, '#');
  std::string_view line;
  std::string_view tok[kMaxXyzColumns + 1];
  double x[kMaxXyzColumns];
  while (in.next(line)) {
    const std::size_t k = split(line, tok, kMaxXyzColumns + 1);
    if (k == 0) continue;  // blank or comment
    if (k != cols)
      throw InputError(path, in.line_number(),
                       "expected " + std::to_string(cols) + " columns (" + layout + "), found " +
                           std::to_string(k));
    for (std::size_t c = 0; c < cols; ++c) {
      const Num s = parse_real(tok[c], x[c]);
      if (s != Num::ok)
        throw InputError(path, in.line_number(),
                         describe(s, tok[c]) + " in column " + std::to_string(c + 1) + " (" +
                             column_name(static_cast<int>(c), dim) + ")");
    }
    append_point(ps, x, weighted ? x[dim] : 0.0, path, in.line_number());
  }
  if (in.line_number() == 0) throw InputError(path, "empty file, no points");
  check_count(ps, path, in.line_number());
  return ps;
}

}  // namespace flipflop::io::detail

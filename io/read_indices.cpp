// read_indices.cpp — reading index cycles and triangle lists (index_io.hpp), streamed.
#include "io/index_io.hpp"

#include <charconv>
#include <limits>
#include <string_view>
#include <utility>

#include "io/text.hpp"

namespace flipflop::io {

namespace {

using detail::LineReader;
using detail::show;
using detail::split;

// Parses a 0-based point index.
Index parse_index(const LineReader& in, std::string_view tok) {
  unsigned long long v = 0;
  const bool negative = !tok.empty() && tok[0] == '-';
  const std::string_view digits = negative ? tok.substr(1) : tok;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  const bool integer = !digits.empty() && r.ptr == digits.data() + digits.size() &&
                       (r.ec == std::errc() || r.ec == std::errc::result_out_of_range);
  if (!integer) throw InputError(in.path(), in.line_number(), show(tok) + " is not an index (a non-negative integer)");
  if (negative)
    throw InputError(in.path(), in.line_number(), "negative index " + show(tok));
  if (r.ec != std::errc() || v > std::numeric_limits<Index>::max())
    throw InputError(in.path(), in.line_number(),
                     "index " + show(tok) + " exceeds the largest index " +
                         std::to_string(std::numeric_limits<Index>::max()));
  return static_cast<Index>(v);
}

std::string found(std::size_t k) {
  return "found " + std::to_string(k) + (k == 1 ? " token" : " tokens");
}

}  // namespace

std::vector<Index> read_index_cycle(const std::string& path) {
  LineReader in(path, '#');
  std::vector<Index> out;
  std::string_view line, tok[2];
  while (in.next(line)) {
    const std::size_t k = split(line, tok, 2);
    if (k == 0) continue;
    if (k != 1) throw InputError(path, in.line_number(), "expected 1 index per line, " + found(k));
    out.push_back(parse_index(in, tok[0]));
  }
  return out;
}

std::vector<Triangle> read_triangles(const std::string& path) {
  LineReader in(path, '#');
  std::vector<Triangle> out;
  std::string_view line, tok[4];
  bool first = true;
  bool qhull = false;
  std::size_t announced = 0, header_line = 0;
  while (in.next(line)) {
    const std::size_t k = split(line, tok, 4);
    if (k == 0) continue;
    if (first && k == 1) {
      // `qhull i` output: the facet count, then one facet per line.
      first = false;
      qhull = true;
      announced = parse_index(in, tok[0]);
      header_line = in.line_number();
      continue;
    }
    first = false;
    if (k != 3)
      throw InputError(path, in.line_number(),
                       "expected 3 indices \"i j k\" per line, " + found(k) +
                           (qhull && k > 3 ? " (a non-simplicial Qhull facet: run qhull with Qt)"
                                           : ""));
    Triangle t{parse_index(in, tok[0]), parse_index(in, tok[1]), parse_index(in, tok[2])};
    // `qhull i` prints each 3-d facet clockwise seen from outside (its vertex
    // order follows the inward normal); flipflop's convention is
    // counter-clockwise, so Qhull's facets are reversed on reading. Checked in
    // proptests/cli_test.cpp and peers_test.cpp against libqhull_r.
    if (qhull) std::swap(t[1], t[2]);
    out.push_back(t);
  }
  if (qhull && out.size() != announced)
    throw InputError(path, in.line_number() > 0 ? in.line_number() : 1,
                     "the Qhull facet count on line " + std::to_string(header_line) + " is " +
                         std::to_string(announced) + ", but " + std::to_string(out.size()) +
                         " facets follow");
  return out;
}

}  // namespace flipflop::io

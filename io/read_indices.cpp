// read_indices.cpp — reading index cycles and triangle lists (index_io.hpp), streamed.
#include "io/index_io.hpp"

#include <charconv>
#include <string>
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

std::pair<std::vector<Index>, std::vector<std::vector<Index>>> read_strict_hull3(const std::string& path) {
  LineReader in(path, '#');
  std::pair<std::vector<Index>, std::vector<std::vector<Index>>> out;
  std::string_view line;
  std::vector<std::string_view> tok(64);
  std::size_t extreme = 0, facets = 0;
  bool header = false;
  while (in.next(line)) {
    std::size_t k = split(line, tok.data(), tok.size());
    if (k > tok.size()) {  // a long facet: split again with room for every token
      tok.resize(k);
      k = split(line, tok.data(), tok.size());
    }
    if (k == 0) continue;
    if (!header) {
      if (k != 2) throw InputError(path, in.line_number(), "expected the counts \"E F\" on the first line, " + found(k));
      extreme = parse_index(in, tok[0]);
      facets = parse_index(in, tok[1]);
      header = true;
      continue;
    }
    if (out.first.size() < extreme) {
      if (k != 1) throw InputError(path, in.line_number(), "expected 1 extreme point index per line, " + found(k));
      out.first.push_back(parse_index(in, tok[0]));
      continue;
    }
    if (out.second.size() == facets)
      throw InputError(path, in.line_number(), "more facets than the " + std::to_string(facets) + " announced");
    if (k < 3) throw InputError(path, in.line_number(), "expected a facet of at least 3 indices, " + found(k));
    std::vector<Index> f(k);
    for (std::size_t i = 0; i < k; ++i) f[i] = parse_index(in, tok[i]);
    out.second.push_back(std::move(f));
  }
  if (!header) throw InputError(path, 1, "empty: expected the counts \"E F\"");
  if (out.first.size() != extreme || out.second.size() != facets)
    throw InputError(path, in.line_number() > 0 ? in.line_number() : 1,
                     "announced " + std::to_string(extreme) + " extreme points and " + std::to_string(facets) +
                         " facets, found " + std::to_string(out.first.size()) + " and " +
                         std::to_string(out.second.size()));
  return out;
}

}  // namespace flipflop::io

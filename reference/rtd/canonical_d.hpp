// canonical_d.hpp — the canonical form of d-dimensional simplex output
// (DESIGN.md "Canonical output": "d-dimensional: one simplex per line,
// positively oriented, sorted the same way"), the one definition used by
// every d-dimensional algorithm, peer, writer and the certifier.
//
// Two orientation conventions meet here (Orientation below):
//  * Orientation::orient_d — the predicates' (pred::orient_d, Shewchuk's):
//    the sign of det[[p_0 1]; ...; [p_d 1]], the 1-column LAST. Every
//    algorithm of reference/rtd keeps its simplices positive in this one.
//  * Orientation::volume — the output's: the sign of
//    det[p_1 - p_0, ..., p_d - p_0], the convention of CGAL's Orientation_d,
//    VTK and every mesh format (positive volume).
// They differ by (-1)^d: subtracting row 0 from the others leaves rows
// [p_0 1] and [p_i - p_0 0]; expanding along the last column, the only
// non-zero entry is the 1 of row 0 at column d, with cofactor sign
// (-1)^(0+d), so det[[p_i 1]] = (-1)^d det[p_1 - p_0, ..., p_d - p_0]. In
// even d (2D: counter-clockwise) the conventions agree; in odd d a tuple
// positive in one is negative in the other, and swapping two entries (an odd
// permutation) converts it.
//
// A simplex is given as a POSITIVELY ORIENTED tuple in one of the two
// conventions; canonical_simplex first converts it to the volume convention
// (odd d, orient_d given: swap the last two entries). Its canonical tuple:
// the smallest index first, the others ascending; when that order is an odd
// permutation of the (volume-positive) tuple, the LAST TWO entries are
// swapped (an odd permutation restores the orientation). Orientation is a
// property of the parity of the ordering, so this needs no predicate: of the
// two orderings "smallest first, the rest ascending" and "the same with the
// last two swapped" exactly one is an even permutation of the volume-positive
// tuple, and that one is the canonical tuple.
// A list is canonical when every tuple is and the list is sorted
// lexicographically (no duplicates).
//
// For d = 2 this is canonical_triangles of reference/canonical.hpp: the
// positively oriented (counter-clockwise) triangle rotated to its smallest
// index is (m, x, y) with x < y or, if that is clockwise, (m, y, x) — the
// rule above (a rotation of a triangle is even).
//
// Text format: one simplex per line, d+1 indices separated by single spaces,
// '\n' after each line; nothing else.
#pragma once

#include <algorithm>
#include <cstddef>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop {

// Parity of the permutation sorting `s` (true = odd). Entries distinct.
inline bool odd_sorting_parity(std::vector<Index> s) {
  bool odd = false;
  for (std::size_t i = 0; i < s.size(); ++i)  // selection sort, counting swaps
    for (std::size_t j = i + 1; j < s.size(); ++j)
      if (s[j] < s[i]) {
        std::swap(s[i], s[j]);
        odd = !odd;
      }
  return odd;
}

// The orientation convention of a tuple (header).
enum class Orientation {
  orient_d,  // det[[p_i 1]] > 0, the predicates' (1-column last)
  volume     // det[p_1 - p_0, ..., p_d - p_0] > 0, the output's
};

// The conventions differ in odd d (header): a tuple positive in one is
// positive in the other after an odd permutation. Converts in place, either
// way (an involution): swaps the last two entries when d = size - 1 is odd.
inline void switch_orientation_convention(std::vector<Index>& t) {
  if (t.size() >= 2 && (t.size() - 1) % 2 == 1) std::swap(t[t.size() - 1], t[t.size() - 2]);
}

// The canonical tuple (volume convention) of a positively oriented simplex
// tuple t[0..k-1] given in convention `given`, in place (k >= 2; no
// allocation: the kernels canonicalise millions of tuples).
inline void canonicalize(Index* t, std::size_t k, Orientation given) {
  if (given == Orientation::orient_d && (k - 1) % 2 == 1) std::swap(t[k - 1], t[k - 2]);
  bool odd = false;
  for (std::size_t a = 1; a < k; ++a)  // insertion sort, counting swaps
    for (std::size_t b = a; b > 0 && t[b] < t[b - 1]; --b) {
      std::swap(t[b], t[b - 1]);
      odd = !odd;
    }
  if (odd) std::swap(t[k - 1], t[k - 2]);
}
inline std::vector<Index> canonical_simplex(const std::vector<Index>& positive, Orientation given) {
  std::vector<Index> c = positive;
  if (c.size() >= 2) canonicalize(c.data(), c.size(), given);
  return c;
}

// Is a tuple in canonical form (given that it is positively oriented, which
// this does not check)? Smallest first, the middle ascending, the last two in
// either order but the whole above the first.
inline bool is_canonical_shape(const std::vector<Index>& t) {
  if (t.size() < 2) return false;
  std::vector<Index> s = t;
  if (s.size() >= 2 && s[s.size() - 1] < s[s.size() - 2]) std::swap(s[s.size() - 1], s[s.size() - 2]);
  for (std::size_t i = 1; i < s.size(); ++i)
    if (!(s[i - 1] < s[i])) return false;
  return true;
}

// The indices 0..n-1 that are vertices of no simplex (sorted): the points a
// regular triangulation left out as redundant.
inline std::vector<Index> non_vertices(std::size_t n, const std::vector<std::vector<Index>>& simplices) {
  std::vector<char> is_vertex(n, 0);
  for (const auto& t : simplices)
    for (Index x : t) is_vertex[x] = 1;
  std::vector<Index> out;
  for (Index i = 0; i < n; ++i)
    if (!is_vertex[i]) out.push_back(i);
  return out;
}

inline std::vector<std::vector<Index>> canonical_simplices(std::vector<std::vector<Index>> positive,
                                                          Orientation given) {
  for (auto& t : positive) t = canonical_simplex(t, given);
  std::sort(positive.begin(), positive.end());
  return positive;
}

// Writer: one simplex per line.
inline void write_simplices(std::ostream& out, const std::vector<std::vector<Index>>& simplices) {
  for (const auto& t : simplices) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (i) out << ' ';
      out << t[i];
    }
    out << '\n';
  }
}

inline std::string simplices_text(const std::vector<std::vector<Index>>& simplices) {
  std::ostringstream o;
  write_simplices(o, simplices);
  return o.str();
}

// Reader: every non-empty line holds exactly d+1 non-negative integers (the
// tuple as written, not re-canonicalised). Throws std::invalid_argument with
// the line number on anything else.
inline std::vector<std::vector<Index>> read_simplices(std::istream& in, int d) {
  std::vector<std::vector<Index>> out;
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream ls(line);
    std::vector<Index> t;
    std::string tok;
    while (ls >> tok) {
      if (tok.empty() || tok.find_first_not_of("0123456789") != std::string::npos || tok.size() > 10)
        throw std::invalid_argument("simplex line " + std::to_string(lineno) + ": '" + tok +
                                    "' is not a point index");
      unsigned long long v = std::stoull(tok);
      if (v >= 0xffffffffULL)
        throw std::invalid_argument("simplex line " + std::to_string(lineno) + ": index " + tok + " is too large");
      t.push_back(static_cast<Index>(v));
    }
    if (t.size() != static_cast<std::size_t>(d + 1))
      throw std::invalid_argument("simplex line " + std::to_string(lineno) + " has " + std::to_string(t.size()) +
                                  " indices, a " + std::to_string(d) + "-simplex has " + std::to_string(d + 1));
    out.push_back(std::move(t));
  }
  return out;
}

inline std::vector<std::vector<Index>> parse_simplices(const std::string& text, int d) {
  std::istringstream in(text);
  return read_simplices(in, d);
}

}  // namespace flipflop

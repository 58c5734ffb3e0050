// index_io.cpp — canonical form and writers of index output.
#include <algorithm>
#include <ostream>

#include "io/decimal.hpp"
#include "io/index_io.hpp"

namespace flipflop::io {

std::vector<Index> canonical_hull2(std::vector<Index> ccw_cycle) {
  std::rotate(ccw_cycle.begin(), std::min_element(ccw_cycle.begin(), ccw_cycle.end()),
              ccw_cycle.end());
  return ccw_cycle;
}

std::vector<Triangle> canonical_triangles(std::vector<Triangle> triangles) {
  for (Triangle& t : triangles) {
    // (a b c), (b c a), (c a b) are the same oriented triangle.
    if (t[1] < t[0] && t[1] < t[2])
      t = {t[1], t[2], t[0]};
    else if (t[2] < t[0] && t[2] < t[1])
      t = {t[2], t[0], t[1]};
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

void write_hull2(std::ostream& os, const std::vector<Index>& cycle) {
  std::string out;
  for (Index i : cycle) {
    detail::put_decimal(out, i);
    out += '\n';
    detail::drain(os, out, false);
  }
  detail::drain(os, out, true);
}

void write_triangles(std::ostream& os, const std::vector<Triangle>& triangles) {
  std::string out;
  for (const Triangle& t : triangles) {
    detail::put_decimal(out, t[0]);
    out += ' ';
    detail::put_decimal(out, t[1]);
    out += ' ';
    detail::put_decimal(out, t[2]);
    out += '\n';
    detail::drain(os, out, false);
  }
  detail::drain(os, out, true);
}

}  // namespace flipflop::io

// index_io.cpp — canonical form and writers of index output.
#include <ostream>

#include "io/decimal.hpp"
#include "io/index_io.hpp"

namespace flipflop::io {

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

void write_tetrahedra(std::ostream& os, const std::vector<std::array<Index, 4>>& tets) {
  std::string out;
  for (const auto& t : tets) {
    for (std::size_t j = 0; j < 4; ++j) {
      if (j) out += ' ';
      detail::put_decimal(out, t[j]);
    }
    out += '\n';
    detail::drain(os, out, false);
  }
  detail::drain(os, out, true);
}

}  // namespace flipflop::io

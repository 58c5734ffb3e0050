// outcome.hpp — what a backend answers, as the text the command line writes
// (canonical output, DESIGN.md), or "error: <message>" when it rejects the
// input with std::invalid_argument: two backends agree when these strings are
// equal (the cpu-vs-reference tests).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/index_io.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test {

inline std::string canonical_text(const std::vector<Index>& cycle) {  // a 2D hull
  std::ostringstream os;
  io::write_hull2(os, cycle);
  return os.str();
}
inline std::string canonical_text(const std::vector<Triangle>& tris) {  // triangles
  std::ostringstream os;
  io::write_triangles(os, tris);
  return os.str();
}

template <class F>
std::string outcome(F&& f) {
  try {
    return canonical_text(f());
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

inline bool is_error(const std::string& outcome_text) { return outcome_text.rfind("error: ", 0) == 0; }

}  // namespace flipflop::test

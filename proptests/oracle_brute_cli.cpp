// oracle_brute_cli.cpp — the SoS brute force of support/sos_brute.hpp (decided
// only by the independent oracle support/sos_oracle.hpp: GMP on the definition,
// no code of predicates/, reference/ or the canonical-form headers) as a small
// command-line program, so that tests outside C++ (python/tests/
// test_oracle_degenerate.py: the Python bindings on degenerate input) can
// check their answers against it. A test-support program, not installed.
//
//   oracle_brute_cli KIND FILE
//
// KIND   hull2  FILE has 2 columns; prints the counter-clockwise hull cycle
//               from the smallest index, one vertex per line
//        hull3  3 columns; prints the canonical facets "i j k" (ccw seen
//               from outside, smallest first, lines sorted)
//        dt     d = 2..9 columns; the Delaunay triangulation (weights 0)
//        rt     d + 1 columns, the last one the weight (d = 2..9); the
//               regular triangulation (lifted height |x|^2 - w)
//        dt-furthest  d = 2..9 columns; the furthest-site Delaunay
//               triangulation (the upper hull of the same lifted points)
//        dt, dt-furthest and rt print the canonical simplices (positively oriented,
//        smallest first, lines sorted), then one line "redundant:" followed
//        by the indices of the points in no simplex.
// FILE   one point per line, whitespace-separated decimal or hexadecimal
//        floating-point values (strtod: every double round-trips); blank
//        lines and lines starting with '#' are skipped.
// Exit 0 with the answer; 2 on bad usage or input; 3 when the points do not
// span R^d (exact affine rank: no hull or triangulation is defined).
// Cost: O(n^(d+2)) SoS determinants in GMP; meant for n <= ~12.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "proptests/support/sos_brute.hpp"

namespace sb = flipflop::test::sos_brute;

namespace {

int usage(const std::string& why) {
  std::cerr << "oracle_brute_cli: " << why << "\nusage: oracle_brute_cli hull2|hull3|dt|dt-furthest|rt FILE\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return usage("two arguments needed");
  const std::string kind = argv[1];
  if (kind != "hull2" && kind != "hull3" && kind != "dt" && kind != "dt-furthest" && kind != "rt")
    return usage("unknown kind '" + kind + "'");
  std::ifstream f(argv[2]);
  if (!f) return usage(std::string("cannot read ") + argv[2]);
  std::vector<std::vector<double>> rows;
  std::string line;
  int lineno = 0;
  while (std::getline(f, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<double> r;
    const char* s = line.c_str();
    for (;;) {
      while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
      if (*s == '\0') break;
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(s, &end);
      if (end == s || errno == ERANGE || !std::isfinite(v))
        return usage("line " + std::to_string(lineno) + ": not a finite double");
      r.push_back(v);
      s = end;
    }
    if (!rows.empty() && r.size() != rows[0].size())
      return usage("line " + std::to_string(lineno) + ": another number of columns");
    rows.push_back(std::move(r));
  }
  if (rows.empty()) return usage("no points");
  const int cols = static_cast<int>(rows[0].size());
  const bool weighted = kind == "rt";
  sb::Input in;
  in.d = weighted ? cols - 1 : cols;
  const int want_lo = kind == "hull2" ? 2 : kind == "hull3" ? 3 : 2;
  const int want_hi = kind == "hull2" ? 2 : kind == "hull3" ? 3 : 9;  // power tests of up to 11 rows (sos_oracle)
  if (in.d < want_lo || in.d > want_hi)
    return usage(kind + ": " + std::to_string(in.d) + " coordinate columns (" + std::to_string(want_lo) + ".." +
                 std::to_string(want_hi) + " needed)");
  for (const auto& r : rows) {
    for (int j = 0; j < in.d; ++j) in.x.push_back(r[static_cast<std::size_t>(j)]);
    in.w.push_back(weighted ? r[static_cast<std::size_t>(in.d)] : 0.0);
  }
  if (!sb::spans(in)) {
    std::cerr << "oracle_brute_cli: the points do not span R^" << in.d << "\n";
    return 3;
  }
  if (kind == "hull2") {
    std::cout << sb::cycle_text(sb::hull2(in));
  } else if (kind == "hull3") {
    std::cout << sb::text(sb::hull3(in));
  } else {
    const sb::Rt r = sb::rt(in, kind == "dt-furthest");
    std::cout << sb::text(r.simplices) << "redundant:";
    for (auto v : r.redundant) std::cout << ' ' << v;
    std::cout << '\n';
  }
  return 0;
}

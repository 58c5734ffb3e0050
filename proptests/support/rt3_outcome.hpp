// rt3_outcome.hpp — what a 3D triangulation backend answers, as one string the
// tests compare byte for byte: the canonical tetrahedra (write_simplices), then
// "redundant" and the redundant input indices; or "error: " and the input
// problem (the message without its backend prefix, "rt3 (cpu): ", "rtd: ").
// Shared by rt3_cpu_test.cpp (kernels_cpu/rt3) and rt3_cuda_omp_test.cpp
// (kernels_cuda/rt3), both against ref::rtd_incremental.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/index_io.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#include "proptests/support/outcome.hpp"  // is_error
#include "reference/point_set.hpp"
#include "reference/rtd/canonical_d.hpp"  // write_simplices
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::test {

inline std::string rt3_text(const std::vector<std::vector<Index>>& simplices, const std::vector<Index>& redundant) {
  std::ostringstream os;
  write_simplices(os, simplices);
  os << "redundant";
  for (Index r : redundant) os << ' ' << r;
  return os.str();
}

inline std::string rt3_problem(const std::string& what) {
  const auto colon = what.find(": ");
  return "error: " + (colon == std::string::npos ? what : what.substr(colon + 2));
}

inline std::vector<std::vector<Index>> as_simplices(const std::vector<cpu::Tet>& tets) {
  std::vector<std::vector<Index>> out;
  out.reserve(tets.size());
  for (const cpu::Tet& t : tets) out.emplace_back(t.begin(), t.end());
  return out;
}

inline std::string rt3_text(const cpu::Rt3Result& r) { return rt3_text(as_simplices(r.tets), r.redundant); }

// The reference's answer: RT+1 (ref::rtd_incremental, d = 3).
inline std::string rt3_ref_text(const PointSet& ps) {
  try {
    const ref::Rtd r = ref::rtd_incremental(ps);
    return rt3_text(r.simplices, r.redundant);
  } catch (const std::invalid_argument& e) {
    // the reference's messages: "rtd: a coordinate is not finite", or the
    // dimension problem itself
    const std::string w = e.what();
    return w.rfind("rtd: ", 0) == 0 ? rt3_problem(w) : "error: " + w;
  }
}

// A kernel's answer: f() returns a cpu::Rt3Result or throws std::invalid_argument.
template <class F>
std::string rt3_outcome(F&& f) {
  try {
    return rt3_text(f());
  } catch (const std::invalid_argument& e) {
    return rt3_problem(e.what());
  }
}

// The number of redundant points in a text (the entries after "redundant").
inline std::size_t rt3_redundant_count(const std::string& text) {
  const auto at = text.rfind("redundant");
  std::size_t k = 0;
  for (std::size_t i = at; i < text.size(); ++i) k += text[i] == ' ';
  return k;
}

inline PointSet with_weights(PointSet ps, std::vector<double> w) {
  ps.weighted = true;
  ps.weights = Values(std::move(w));
  return ps;
}

// The named degenerate 3D inputs both kernels' tests run (each with its own
// structure): a 7^3 lattice unweighted, with equal and with lattice weights
// (every cell cospherical: visibility decided by SoS alone), points on two
// planes, and 60 lattice points each twice, unweighted and with different
// weights on the copies.
inline std::vector<std::pair<std::string, PointSet>> rt3_degenerate_inputs(const PointSet& grid343) {
  std::vector<std::pair<std::string, PointSet>> in;
  in.emplace_back("grid, unweighted", grid343);
  in.emplace_back("grid, equal weights", with_weights(grid343, std::vector<double>(grid343.size(), 0.25)));
  std::vector<double> lw(grid343.size());
  for (std::size_t i = 0; i < lw.size(); ++i) lw[i] = static_cast<double>(i % 3) / 4;
  in.emplace_back("grid, lattice weights", with_weights(grid343, lw));
  PointSet planes;
  planes.dim = 3;
  std::vector<double> c;
  for (int i = 0; i < 100; ++i) c.insert(c.end(), {double(i % 10), double(i / 10), 0.0});
  for (int i = 0; i < 100; ++i) c.insert(c.end(), {double(i % 10) + 0.5, 0.0, double(i / 10) + 1});
  planes.coords = Values(std::move(c));
  in.emplace_back("points on two planes", planes);
  PointSet dup;
  dup.dim = 3;
  std::vector<double> d, w;
  for (int i = 0; i < 60; ++i) {
    const double x = i % 5, y = (i / 5) % 3, z = i % 2;
    d.insert(d.end(), {x, y, z, x, y, z});  // each point twice
    w.insert(w.end(), {0.0, 0.1 * (i % 4)});
  }
  dup.coords = Values(std::move(d));
  in.emplace_back("duplicates", dup);
  in.emplace_back("duplicates with different weights", with_weights(dup, w));
  return in;
}

}  // namespace flipflop::test

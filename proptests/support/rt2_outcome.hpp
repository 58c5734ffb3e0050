// rt2_outcome.hpp — what the 2D regular triangulation tests compare: the
// reference's answer as canonical text (outcome.hpp) with the rejection
// message stripped of the backend's name, and the number of vertices of an
// answer (rt2_cpu_test, rt2_cuda_omp_test, kernels_cuda/rt2_cuda_test).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "proptests/support/outcome.hpp"
#include "reference/rt2/rt2.hpp"

namespace flipflop::test {

// The rejection message without its "error: WHO: " prefix (the reference
// names itself "rt2 (ffRT)", the backends "rt2 (cpu)", "rt2 (omp)", "rt2
// (cuda)"; the problem must agree).
inline std::string problem_of(const std::string& text) {
  if (!is_error(text)) return text;
  const std::size_t colon = text.find(": ", 7);
  return colon == std::string::npos ? text : "error: " + text.substr(colon + 2);
}

inline std::string ref_text(const PointSet& ps) { return problem_of(outcome([&] { return ref::rt2_ffrt(ps); })); }

inline std::size_t vertex_count(const std::vector<Triangle>& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return v.size();
}

}  // namespace flipflop::test

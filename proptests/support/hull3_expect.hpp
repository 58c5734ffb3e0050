// hull3_expect.hpp — the expected answer of the 3D hull kernels' tests
// (hull3_cpu_test, hull3_cuda_omp_test): the reference ffHull's canonical
// text, or "error: ..." for input it rejects.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>

#include "proptests/support/outcome.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"

namespace flipflop::test {

inline std::string hull3_reference_text(const PointSet& ps) {
  return outcome([&] { return ref::hull3_ffhull(ps); });
}

// In a sweep: the reference's text; a rejection is counted and must be of
// input that does not span R^3.
inline std::string hull3_sweep_expect(const PointSet& ps, std::size_t& rejected) {
  const std::string expect = hull3_reference_text(ps);
  if (is_error(expect)) {
    ++rejected;
    REQUIRE(!dimension_problem(ps).empty());
  }
  return expect;
}

}  // namespace flipflop::test

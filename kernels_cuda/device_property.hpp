// device_property.hpp — the lines and properties of the GPU test programs
// (rt2_cuda_test.cpp, rt3_cuda_test.cpp): RapidCheck without Catch (RC_PARAMS
// applies; shrinking on failure), one "ok  NAME" or "FAIL NAME" line per check.
#pragma once

#include <rapidcheck.h>

#include <cstdio>
#include <string>

#include "proptests/support/rc_check.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels_cuda {

inline bool report(const std::string& name, bool passed, const std::string& message = {}) {
  std::printf("%s %s\n", passed ? "ok  " : "FAIL", name.c_str());
  if (!passed && !message.empty()) std::printf("%s\n", message.c_str());
  return passed;
}

// kernel(ps) == reference(ps) (their texts) for the generated point sets
// (test::check_scaled: the case count divided by divisor).
template <class Kernel, class Reference>
bool property(const std::string& name, int divisor, rc::Gen<PointSet> points, Kernel kernel, Reference reference) {
  const test::ScaledResult r = test::check_scaled(name, divisor, [points, kernel, reference] {
    const PointSet ps = *points;
    RC_ASSERT(kernel(ps) == reference(ps));
  });
  return report(name, r.ok, r.message);
}

}  // namespace flipflop::kernels_cuda

// rc_check.hpp — run one RapidCheck property with a fraction of the configured
// number of cases (RC_PARAMS' max_success / divisor, at least 1), without
// Catch2: the result and, on failure, RapidCheck's counterexample message.
// prop_scaled (rc_scaled.hpp) wraps it in a Catch2 SECTION; standalone test
// programs (kernels_cuda/*_test.cpp) print the message themselves.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

namespace flipflop::test {

struct ScaledResult {
  bool ok = true;
  std::string message;  // RapidCheck's report when !ok
};

template <typename Testable>
ScaledResult check_scaled(const std::string& description, int divisor, Testable&& testable) {
  using namespace rc::detail;
  TestParams params = configuration().testParams;
  params.maxSuccess = std::max(1, params.maxSuccess / std::max(1, divisor));
  TestMetadata metadata;
  metadata.id = description;
  metadata.description = description;
  const auto result = checkTestable(std::forward<Testable>(testable), metadata, params);
  ScaledResult r;
  if (!result.template is<SuccessResult>()) {
    std::ostringstream ss;
    printResultMessage(result, ss);
    r.ok = false;
    r.message = ss.str();
  }
  return r;
}

}  // namespace flipflop::test

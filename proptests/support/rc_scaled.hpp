// rc_scaled.hpp — rc::prop with a fraction of the configured number of cases.
//
// rc::prop (rapidcheck/catch.h) runs RC_PARAMS' max_success cases. A few
// properties are much more expensive per case (the SoS oracle with
// multi-hundred-kilobit numbers); prop_scaled runs max_success / divisor of
// them (at least 1) and otherwise behaves exactly like rc::prop: one Catch2
// SECTION, the RapidCheck counterexample printed on failure.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <utility>

namespace flipflop::test {

template <typename Testable>
void prop_scaled(const std::string& description, int divisor, Testable&& testable) {
  SECTION(description) {
    using namespace rc::detail;
    TestParams params = configuration().testParams;
    params.maxSuccess = std::max(1, params.maxSuccess / std::max(1, divisor));
    TestMetadata metadata;
    metadata.id = description;
    metadata.description = description;
    const auto result = checkTestable(std::forward<Testable>(testable), metadata, params);
    if (result.template is<SuccessResult>()) {
      SUCCEED();
    } else {
      std::ostringstream ss;
      printResultMessage(result, ss);
      INFO(ss.str() << "\n");
      FAIL();
    }
  }
}

}  // namespace flipflop::test

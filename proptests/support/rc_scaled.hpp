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

#include "proptests/support/rc_check.hpp"

namespace flipflop::test {

template <typename Testable>
void prop_scaled(const std::string& description, int divisor, Testable&& testable) {
  SECTION(description) {
    const ScaledResult r = check_scaled(description, divisor, std::forward<Testable>(testable));
    if (r.ok) {
      SUCCEED();
    } else {
      INFO(r.message << "\n");
      FAIL();
    }
  }
}

}  // namespace flipflop::test

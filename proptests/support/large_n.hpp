// large_n.hpp — the size of a large-input test case: `release` points in
// make test, `tsan` under ThreadSanitizer (make tsan runs these cases for
// their parallel paths; FLIPFLOP_TEST_UNDER_TSAN is set by proptests/
// CMakeLists.txt there). `tsan` still spans several kChunk pieces
// (kernels_cpu/parallel.hpp) at a fraction of TSan's cost, which is 5-20x
// Release's.
#pragma once

#include <cstddef>

namespace flipflop::test {

constexpr std::size_t large_n(std::size_t release, [[maybe_unused]] std::size_t tsan) {
#ifdef FLIPFLOP_TEST_UNDER_TSAN
  return tsan;
#else
  return release;
#endif
}

// Whether this build runs under ThreadSanitizer (FLIPFLOP_TEST_UNDER_TSAN).
constexpr bool under_tsan() { return large_n(0, 1) == 1; }

}  // namespace flipflop::test

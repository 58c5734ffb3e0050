// fuzz_main.cpp — the libFuzzer entry point of every fuzz target: calls the
// check selected by -DFLIPFLOP_FUZZ_CHECK (checks.hpp). Built with clang++
// -fsanitize=fuzzer,address,undefined (fuzz/CMakeLists.txt); run e.g.
//   build-fz-clang/fuzz/fuzz_hull2 -max_total_time=60 fuzz/corpus/hull2
// or all of them: fuzz/run_all.sh.
#include <cstddef>
#include <cstdint>

#include "fuzz/checks.hpp"

#ifndef FLIPFLOP_FUZZ_CHECK
#error "define FLIPFLOP_FUZZ_CHECK to a check of fuzz/checks.hpp"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  flipflop::fuzz::FLIPFLOP_FUZZ_CHECK(data, size);
  return 0;
}

// fuzz_predicates.cpp — libFuzzer entry point for the predicates
// (predicates_check.hpp). Build with clang++ -fsanitize=fuzzer,address,undefined
// (fuzz/CMakeLists.txt); run e.g.
//   ./fuzz_predicates -max_total_time=60 fuzz/corpus/predicates
#include <cstddef>
#include <cstdint>

#include "fuzz/predicates_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  flipflop::fuzz::check_predicates_input(data, size);
  return 0;
}

// checks.hpp — the property each fuzz target checks, one function per target.
//
// A check decodes the bytes into one input, runs the code under test and
// verifies the property documented in its source file; it returns false when
// the input was skipped (e.g. a decoded value is not finite), true when it was
// checked, and never returns on a violation (fuzz_input.hpp: fail() aborts).
// The same function is called by the libFuzzer entry point (fuzz_main.cpp,
// clang builds) and by the corpus replay (replay_main.cpp, every build, ctest
// fuzz_<name>_replay); fuzz/CMakeLists.txt selects it with
// -DFLIPFLOP_FUZZ_CHECK=<function>.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flipflop::fuzz {

bool check_predicates_input(const std::uint8_t* data, std::size_t size);    // predicates_check.cpp
bool check_read_points_input(const std::uint8_t* data, std::size_t size);   // read_points_check.cpp
bool check_read_indices_input(const std::uint8_t* data, std::size_t size);  // read_indices_check.cpp
bool check_hull2_input(const std::uint8_t* data, std::size_t size);         // hull2_check.cpp
bool check_certify_input(const std::uint8_t* data, std::size_t size);       // certify_check.cpp
bool check_kernels_input(const std::uint8_t* data, std::size_t size);       // kernels_check.cpp
bool check_rt2_input(const std::uint8_t* data, std::size_t size);           // rt2_check.cpp
bool check_hull3_input(const std::uint8_t* data, std::size_t size);         // hull3_check.cpp
bool check_rtd_input(const std::uint8_t* data, std::size_t size);           // rtd_check.cpp
bool check_rt3_input(const std::uint8_t* data, std::size_t size);           // rt3_check.cpp

}  // namespace flipflop::fuzz

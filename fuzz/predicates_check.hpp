// predicates_check.hpp — the property checked by the fuzz target
// fuzz_predicates and by its corpus replay (ctest fuzz_predicates_replay).
//
// Input bytes are decoded into one predicate instance (see predicates_check.cpp
// for the byte layout) and checked:
//   1. Mode::filtered == Mode::gmp for the exact and the SoS variant;
//   2. SoS is non-zero when the ids are distinct, zero when an id repeats;
//   3. SoS equals the exact sign whenever that is non-zero;
//   4. swapping the first two arguments negates both signs.
// Non-finite decoded values are skipped (the API requires finite inputs).
// A violation prints the decoded instance (hexadecimal floats) and aborts.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flipflop::fuzz {

// Returns false when the input was skipped (non-finite values), true when it
// was checked; never returns on a violation.
bool check_predicates_input(const std::uint8_t* data, std::size_t size);

}  // namespace flipflop::fuzz

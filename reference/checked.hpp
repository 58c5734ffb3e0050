// checked.hpp — invariant checks of the reference algorithms ("checked build").
//
// The reference algorithms assert, after every operation, the invariants their
// proofs rest on (a valid triangulation or star-shaped polygon; the V-criterion
// lowers the lifted surface; a removed vertex never reappears; ...). Those
// checks cost far more than the operations, so they are compiled only into the
// `flipflop_reference_checked` library (FLIPFLOP_CHECKED=1), which the
// proptests/*_checked_test.cpp executables link instead of flipflop_reference.
//
//   FF_CHECKED          true in the checked build (use in `if constexpr`)
//   FF_CHECK(cond, msg) in the checked build: throws InvariantViolation with
//                       msg when cond is false; otherwise compiles to nothing
//                       (cond is not evaluated).
#pragma once

#include <stdexcept>
#include <string>

#ifndef FLIPFLOP_CHECKED
#define FLIPFLOP_CHECKED 0
#endif

namespace flipflop {

inline constexpr bool FF_CHECKED = FLIPFLOP_CHECKED != 0;

struct InvariantViolation : std::logic_error {
  using std::logic_error::logic_error;
};

}  // namespace flipflop

#if FLIPFLOP_CHECKED
#define FF_CHECK(cond, msg)                                                                    \
  do {                                                                                         \
    if (!(cond))                                                                               \
      throw ::flipflop::InvariantViolation(std::string(__FILE__) + ":" + std::to_string(__LINE__) + \
                                           ": invariant violated: " + (msg));                  \
  } while (0)
#else
#define FF_CHECK(cond, msg) \
  do {                      \
  } while (0)
#endif

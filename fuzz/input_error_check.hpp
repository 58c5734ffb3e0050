// input_error_check.hpp — what the reader fuzz targets require of a rejected
// file: io::InputError naming the file (e.file() == path, what() contains it)
// in a message of one line (DESIGN.md "Input files").
#pragma once

#include <string>

#include "fuzz/fuzz_input.hpp"
#include "io/input_error.hpp"

namespace flipflop::fuzz {

inline void check_input_error(const char* target, const io::InputError& e, const std::string& path) {
  const std::string msg = e.what();
  if (e.file() != path) fail(target, "InputError names file '" + e.file() + "', not " + path);
  if (msg.find(path) == std::string::npos) fail(target, "InputError message does not name the file: " + msg);
  if (msg.find('\n') != std::string::npos || msg.find('\r') != std::string::npos)
    fail(target, "InputError message is not one line: " + msg);
}

}  // namespace flipflop::fuzz

// input_error.cpp — formats "FILE:LINE: problem" on one line.
#include "io/input_error.hpp"

namespace flipflop::io {
namespace {

// A message is one line: line breaks and other control bytes become spaces.
std::string one_line(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

}  // namespace

InputError::InputError(const std::string& file, std::size_t line, const std::string& problem)
    : std::runtime_error(one_line(line > 0 ? file + ":" + std::to_string(line) + ": " + problem
                                           : file + ": " + problem)),
      file_(file),
      line_(line) {}

InputError::InputError(const std::string& file, const std::string& problem)
    : InputError(file, 0, problem) {}

}  // namespace flipflop::io

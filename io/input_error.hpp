// input_error.hpp — the one exception type for bad input files.
//
// Every problem with an input file (points or index output) is reported as
// one line "FILE:LINE: problem", or "FILE: problem" where no line applies
// (a binary PLY names the vertex number inside `problem` instead). The
// command-line tool prints what() and exits 2 (DESIGN.md, "Input files").
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace flipflop::io {

struct InputError : std::runtime_error {
  // line == 0: no line applies.
  InputError(const std::string& file, std::size_t line, const std::string& problem);
  InputError(const std::string& file, const std::string& problem);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }

 private:
  std::string file_;
  std::size_t line_ = 0;
};

}  // namespace flipflop::io

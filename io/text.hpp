// text.hpp — the small text tools shared by the readers (internal to io/).
//
// LineReader streams a file line by line through a fixed buffer: memory stays
// bounded by the buffer whatever the file holds (a 2 GB file of garbage gives
// one error about its first line, quickly). Numbers are parsed with
// std::from_chars, which rounds correctly, so the writers' shortest round-trip
// output (std::to_chars) reads back bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace flipflop::io::detail {

class LineReader {
 public:
  // Longest line kept (without a comment tail); a longer one is an error.
  static constexpr std::size_t max_line = std::size_t{1} << 16;

  // comment == '\0': no comment character. Otherwise everything from the
  // first `comment` of a line on is dropped (and never buffered beyond
  // max_line). Throws InputError when the file cannot be opened.
  explicit LineReader(const std::string& path, char comment = '\0');
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // The next line without its '\n' (a '\r' before it is kept: tokens treat it
  // as white space). The view lives until the next call. False at end of file.
  bool next(std::string_view& line);

  // 1-based number of the line last returned (0 before the first).
  std::size_t line_number() const { return line_no_; }
  // Bytes consumed: the offset of the first byte after the last line returned.
  std::uint64_t offset() const { return offset_; }
  const std::string& path() const { return path_; }

 private:
  bool refill();  // false at end of file
  void skip_rest_of_line();

  std::string path_;
  char comment_;
  std::FILE* file_ = nullptr;
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
  bool eof_ = false;
  bool skip_pending_ = false;
  std::size_t line_no_ = 0;
  std::uint64_t offset_ = 0;
};

bool is_space(char c);

// Splits `line` at white space; stores at most `max` tokens in `out` and
// returns how many tokens there are in all.
std::size_t split(std::string_view line, std::string_view* out, std::size_t max);

// A token quoted for an error message: printable ASCII kept, other bytes as
// \xNN, cut after 40 characters — the message stays one line.
std::string show(std::string_view token);

enum class Num { ok, malformed, nan, inf, overflow };

// Decimal floating-point token ([+-]digits[.digits][e[+-]digits], also
// "nan"/"inf" which are reported as such). A value below the smallest
// subnormal rounds to a signed zero as every correctly rounded parser does;
// overflow is reported. T is float or double.
template <class T>
Num parse_real(std::string_view token, T& out);

// What went wrong with a number, for a message: "NaN", "Inf",
// "malformed number 'abc'", "number '1e999' overflows to Inf".
std::string describe(Num status, std::string_view token, const char* type = "double");

// Integer token within [lo, hi]; false if not an integer or out of range.
bool parse_integer(std::string_view token, long long lo, long long hi, long long& out);

}  // namespace flipflop::io::detail

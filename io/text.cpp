// text.cpp — bounded line reading, tokens and exact number parsing.
#include "io/text.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <system_error>

#include "io/input_error.hpp"

namespace flipflop::io::detail {

namespace {
constexpr std::size_t kChunk = std::size_t{1} << 20;  // bytes read at a time
}

LineReader::LineReader(const std::string& path, char comment)
    : path_(path), comment_(comment), buf_(kChunk + max_line + 1) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "cannot read: is a directory");
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
}

LineReader::~LineReader() {
  if (file_ != nullptr) std::fclose(file_);
}

// Moves the unread tail to the front and appends up to kChunk bytes.
bool LineReader::refill() {
  if (eof_) return false;
  if (pos_ > 0) {
    std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
  }
  const std::size_t room = buf_.size() - end_;
  const std::size_t got = std::fread(buf_.data() + end_, 1, room, file_);
  end_ += got;
  if (got < room) {
    if (std::ferror(file_)) throw InputError(path_, std::string("cannot read: ") + std::strerror(errno));
    eof_ = true;
  }
  return got > 0;
}

// Drops bytes up to and including the next '\n' (a long comment tail).
void LineReader::skip_rest_of_line() {
  for (;;) {
    const char* start = buf_.data() + pos_;
    const void* nl = std::memchr(start, '\n', end_ - pos_);
    if (nl != nullptr) {
      const std::size_t n = static_cast<const char*>(nl) - start + 1;
      pos_ += n;
      offset_ += n;
      return;
    }
    offset_ += end_ - pos_;
    pos_ = end_;
    if (!refill()) return;
  }
}

bool LineReader::next(std::string_view& line) {
  if (skip_pending_) {
    skip_pending_ = false;
    skip_rest_of_line();
  }
  for (;;) {
    const char* start = buf_.data() + pos_;
    const std::size_t avail = end_ - pos_;
    const void* nl = std::memchr(start, '\n', avail);
    std::size_t len = 0, used = 0;
    if (nl != nullptr && static_cast<std::size_t>(static_cast<const char*>(nl) - start) <= max_line) {
      len = static_cast<const char*>(nl) - start;
      used = len + 1;
    } else if (nl != nullptr || avail > max_line) {
      // No end of line within max_line bytes: acceptable only if a comment
      // starts in time; its tail is skipped without being buffered.
      const void* hash = comment_ != '\0' ? std::memchr(start, comment_, max_line) : nullptr;
      if (hash == nullptr)
        throw InputError(path_, line_no_ + 1,
                         "line longer than " + std::to_string(max_line) +
                             " characters (not a text file of points?)");
      len = static_cast<const char*>(hash) - start;
      used = len;
      skip_pending_ = true;
    } else if (eof_ || !refill()) {
      if (avail == 0) return false;
      len = used = avail;  // last line without '\n'
    } else {
      continue;
    }
    line = std::string_view(start, len);
    pos_ += used;
    offset_ += used;
    ++line_no_;
    if (comment_ != '\0') line = line.substr(0, line.find(comment_));
    return true;
  }
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::size_t split(std::string_view line, std::string_view* out, std::size_t max) {
  std::size_t count = 0, i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && is_space(line[i])) ++i;
    if (i == n) break;
    const std::size_t b = i;
    while (i < n && !is_space(line[i])) ++i;
    if (count < max) out[count] = line.substr(b, i - b);
    ++count;
  }
  return count;
}

std::string show(std::string_view token) {
  static const char* hex = "0123456789abcdef";
  std::string s = "'";
  std::size_t shown = 0;
  for (char ch : token) {
    if (shown == 40) {
      s += "...";
      break;
    }
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f && c != '\'') {
      s += ch;
    } else {
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 15];
    }
    ++shown;
  }
  return s + "'";
}

namespace {

template <class T>
T strto(const std::string& s);
template <>
double strto<double>(const std::string& s) {
  return std::strtod(s.c_str(), nullptr);
}
template <>
float strto<float>(const std::string& s) {
  return std::strtof(s.c_str(), nullptr);
}

}  // namespace

template <class T>
Num parse_real(std::string_view token, T& out) {
  std::string_view t = token;
  // from_chars does not take a leading '+'; accept one before a digit or '.'.
  if (t.size() > 1 && t[0] == '+' && t[1] != '+' && t[1] != '-') t.remove_prefix(1);
  if (t.empty()) return Num::malformed;
  T v{};
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v, std::chars_format::general);
  if (r.ptr != t.data() + t.size()) return Num::malformed;
  if (r.ec == std::errc::result_out_of_range) {
    // Out of range: either below the smallest subnormal (rounds to ±0 or the
    // nearest subnormal, correctly, with strtod) or above the largest finite.
    const T w = strto<T>(std::string(t));
    if (std::isinf(w)) return Num::overflow;
    out = w;
    return Num::ok;
  }
  if (r.ec != std::errc()) return Num::malformed;
  if (std::isnan(v)) return Num::nan;
  if (std::isinf(v)) return Num::inf;
  out = v;
  return Num::ok;
}

template Num parse_real<double>(std::string_view, double&);
template Num parse_real<float>(std::string_view, float&);

std::string describe(Num status, std::string_view token, const char* type) {
  switch (status) {
    case Num::nan:
      return "NaN (" + show(token) + ")";
    case Num::inf:
      return "Inf (" + show(token) + ")";
    case Num::overflow:
      return "number " + show(token) + " overflows to Inf as a " + type;
    case Num::malformed:
      return "malformed number " + show(token);
    case Num::ok:
      break;
  }
  return "number " + show(token);
}

bool parse_integer(std::string_view token, long long lo, long long hi, long long& out) {
  std::string_view t = token;
  if (t.size() > 1 && t[0] == '+' && t[1] != '-') t.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || t.empty()) return false;
  if (v < lo || v > hi) return false;
  out = v;
  return true;
}

}  // namespace flipflop::io::detail

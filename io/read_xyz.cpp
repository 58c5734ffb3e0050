// read_xyz.cpp — the .xyz reader: one point per line, parsed in parallel
// straight into the point set.
//
// The file is read in blocks of `block` bytes (XyzLayout; fread into one
// reused buffer, the unfinished last line of a block moved to the front of
// the next). The complete lines of a block are cut into pieces of about
// `piece` bytes at line starts; a first parallel pass counts each piece's
// lines, which bounds its points, so that the second parallel pass parses
// every piece into its own slice of the final coordinate array — no
// intermediate copy of the text or of the values. Blank and comment lines
// leave a gap at the end of their piece's slice, closed by a sequential move
// afterwards (nothing moves when there are none). The coordinate array is
// reserved once from the file size and the first full block's points per
// byte, so it is not regrown and copied as it fills; memory is the point set
// plus one block.
//
// A line is parsed by std::from_chars straight from the buffer (parse_fast);
// anything it does not accept outright — a '+' sign, an exponent out of
// range, NaN/Inf, a stray character, a wrong column count — is handed to the
// tokenising parse_line, which decides exactly as the sequential reader (and
// whose answer therefore stands). Errors are the sequential reader's (text.hpp
// LineReader's line rules): the first bad line in file order stops the
// reading after its block, a line that fails is parsed again sequentially for
// its message, so the message does not depend on how the block was split; a
// line longer than `max_line` (LineReader::max_line) is an error unless a '#'
// starts within that many bytes (then its tail is skipped without being
// buffered, however long); a file of garbage costs one block, not the file.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <new>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"
#include "kernels_cpu/tsan.hpp"

namespace flipflop::io::detail {

namespace {

static_assert(XyzLayout{}.max_line == LineReader::max_line, "the .xyz reader keeps LineReader's line limit");

enum class LineStatus : std::uint8_t { blank, ok, bad };

// Parses one line (its comment already cut off) into x[0..cols); the status,
// and for `bad` nothing else (the message comes from line_error).
LineStatus parse_line(std::string_view line, std::size_t cols, double* x) {
  std::string_view tok[kMaxXyzColumns + 1];
  const std::size_t k = split(line, tok, kMaxXyzColumns + 1);
  if (k == 0) return LineStatus::blank;  // blank or comment
  if (k != cols) return LineStatus::bad;
  for (std::size_t c = 0; c < cols; ++c)
    if (parse_real(tok[c], x[c]) != Num::ok) return LineStatus::bad;
  return LineStatus::ok;
}

// The text of a line [b, e) (without its '\n') that counts: up to the first
// '#'; null when the line is too long (LineReader's rule: longer than
// max_line bytes and no '#' within the first max_line).
const char* content_end(const char* b, const char* e, std::size_t max_line) {
  const std::size_t scan = std::min<std::size_t>(static_cast<std::size_t>(e - b), max_line);
  const void* hash = std::memchr(b, '#', scan);
  if (hash != nullptr) return static_cast<const char*>(hash);
  return static_cast<std::size_t>(e - b) > max_line ? nullptr : e;
}

// parse_line's answer for the line [b, e) without its '\n': the common case
// (cols finite numbers that std::from_chars reads completely, white space
// between, nothing but white space or a comment after) directly from the
// buffer; every other line through content_end and parse_line. Accepting
// only what from_chars reads to a white space, '#' or the line's end, with
// errc{} and a finite value, is accepting tokens on which parse_real's
// from_chars call returns the same value (no '+', no out-of-range).
LineStatus parse_fast(const char* b, const char* e, std::size_t cols, std::size_t max_line, double* x) {
  if (static_cast<std::size_t>(e - b) <= max_line) {
    const char* p = b;
    std::size_t c = 0;
    for (;; ++c) {
      while (p != e && is_space(*p)) ++p;
      if (p == e || *p == '#') {
        if (c == 0) return LineStatus::blank;
        if (c == cols) return LineStatus::ok;
        break;
      }
      if (c == cols) break;
      const auto r = std::from_chars(p, e, x[c], std::chars_format::general);
      if (r.ec != std::errc() || !std::isfinite(x[c])) break;
      p = r.ptr;
      if (p != e && !is_space(*p) && *p != '#') break;
    }
  }
  const char* ce = content_end(b, e, max_line);
  if (ce == nullptr) return LineStatus::bad;
  return parse_line(std::string_view(b, static_cast<std::size_t>(ce - b)), cols, x);
}

[[noreturn]] void long_line_error(const std::string& path, std::size_t line_no, std::size_t max_line) {
  throw InputError(path, line_no,
                   "line longer than " + std::to_string(max_line) + " characters (not a text file of points?)");
}

// The sequential reader's message for a bad line [b, e) numbered line_no.
[[noreturn]] void line_error(const char* b, const char* e, const std::string& path, std::size_t line_no,
                             std::size_t cols, int dim, std::size_t max_line) {
  const char* ce = content_end(b, e, max_line);
  if (ce == nullptr) long_line_error(path, line_no, max_line);
  const std::string_view line(b, static_cast<std::size_t>(ce - b));
  std::string layout;  // "x y z w", "x1 x2 x3 x4 w"
  for (int c = 0; c < static_cast<int>(cols); ++c) layout += (c ? " " : "") + std::string(column_name(c, dim));
  std::string_view tok[kMaxXyzColumns + 1];
  const std::size_t k = split(line, tok, kMaxXyzColumns + 1);
  if (k != cols)
    throw InputError(path, line_no,
                     "expected " + std::to_string(cols) + " columns (" + layout + "), found " + std::to_string(k));
  for (std::size_t c = 0; c < cols; ++c) {
    double x = 0;
    const Num s = parse_real(tok[c], x);
    if (s != Num::ok)
      throw InputError(path, line_no,
                       describe(s, tok[c]) + " in column " + std::to_string(c + 1) + " (" +
                           column_name(static_cast<int>(c), dim) + ")");
  }
  throw InputError(path, line_no, "unreadable line");  // not reached: parse_line and this agree
}

// One piece of a block: bytes [b, e) (whole lines), its line count, the
// index of its first point in the point set (an upper bound until the gaps
// are closed), the points it gave and its first bad line (piece-local
// index), if any.
struct Piece {
  std::size_t b = 0, e = 0;
  std::size_t lines = 0;
  std::size_t first_point = 0;
  std::size_t points = 0;
  std::size_t bad = kNoBad;
  static constexpr std::size_t kNoBad = ~std::size_t{0};
};

// Calls f(b, e) for each line of [b, e) (the last one need not end in '\n');
// stops early when f returns false.
template <class F>
void for_each_line(const char* b, const char* e, const F& f) {
  while (b != e) {
    const void* nl = std::memchr(b, '\n', static_cast<std::size_t>(e - b));
    const char* le = nl != nullptr ? static_cast<const char*>(nl) : e;
    if (!f(b, le)) return;
    b = nl != nullptr ? le + 1 : e;
  }
}

class XyzReader {
 public:
  XyzReader(const std::string& path, int dim, bool weighted, const XyzLayout& layout)
      : path_(path), dim_(static_cast<std::size_t>(dim)), cols_(dim_ + (weighted ? 1 : 0)), max_line_(layout.max_line),
        block_(std::max(layout.block, 2 * layout.max_line)), piece_(std::max<std::size_t>(layout.piece, 1)) {
    ps_.dim = dim;
    ps_.weighted = weighted;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "cannot read: is a directory");
    file_ = std::fopen(path.c_str(), "rb");
    if (file_ == nullptr) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
    const auto size = std::filesystem::file_size(path, ec);
    file_size_ = ec ? 0 : static_cast<std::uint64_t>(size);
  }
  ~XyzReader() { std::fclose(file_); }
  XyzReader(const XyzReader&) = delete;
  XyzReader& operator=(const XyzReader&) = delete;

  PointSet read() {
    // a small file in one read, with a buffer of its size (still at least
    // 2 max_line: long_line looks for a '#' within max_line bytes of a full buffer)
    std::vector<char> buf(std::clamp<std::size_t>(static_cast<std::size_t>(std::min<std::uint64_t>(file_size_, block_)) + 1,
                                                  2 * max_line_, block_));
    std::size_t have = 0;  // bytes in buf: the unfinished line of the last block, then new ones
    bool eof = false;
    while (!eof || have > 0) {
      if (!eof) have += fill(buf.data() + have, buf.size() - have, eof);
      if (have == 0) break;
      std::size_t end = have;  // the block's complete lines: up to the last '\n'
      if (!eof) {
        const char* last = static_cast<const char*>(memrchr(buf.data(), '\n', have));
        if (last == nullptr) {  // no line end in a full buffer: a line longer than max_line
          have = long_line(buf, have, eof);
          continue;
        }
        end = static_cast<std::size_t>(last - buf.data()) + 1;
      }
      parse_block(buf.data(), end);
      std::memmove(buf.data(), buf.data() + end, have - end);
      have -= end;
    }
    if (line_no_ == 0) throw InputError(path_, "empty file, no points");
    check_count(ps_, path_, line_no_);
    return std::move(ps_);
  }

 private:
  // Reads up to `room` bytes into `to`; sets eof at the end of the file.
  std::size_t fill(char* to, std::size_t room, bool& eof) {
    const std::size_t got = std::fread(to, 1, room, file_);
    if (got < room) {
      if (std::ferror(file_)) throw InputError(path_, std::string("cannot read: ") + std::strerror(errno));
      eof = true;
    }
    return got;
  }

  // buf[0, have) is the start of a line with no '\n' in it and buf is full:
  // the line is longer than max_line. Accepted only when a '#' starts within
  // max_line bytes; then its text before the '#' is one line and the rest up
  // to the '\n' is skipped block by block. Returns the bytes after that '\n',
  // moved to the front of buf.
  std::size_t long_line(std::vector<char>& buf, std::size_t have, bool& eof) {
    const void* hash = std::memchr(buf.data(), '#', max_line_);
    if (hash == nullptr) long_line_error(path_, line_no_ + 1, max_line_);
    const char* b = buf.data();
    const char* h = static_cast<const char*>(hash);
    double x[kMaxXyzColumns];
    ++line_no_;
    const LineStatus s = parse_line(std::string_view(b, static_cast<std::size_t>(h - b)), cols_, x);
    if (s == LineStatus::bad) line_error(b, h, path_, line_no_, cols_, static_cast<int>(dim_), max_line_);
    if (s == LineStatus::ok) append_point(ps_, x, ps_.weighted ? x[dim_] : 0.0, path_, line_no_);
    for (;;) {
      const void* nl = std::memchr(buf.data(), '\n', have);
      if (nl != nullptr) {
        const std::size_t after = static_cast<std::size_t>(static_cast<const char*>(nl) - buf.data()) + 1;
        std::memmove(buf.data(), buf.data() + after, have - after);
        return have - after;
      }
      if (eof) return 0;
      have = fill(buf.data(), buf.size(), eof);
    }
  }

  // Parses the whole lines of text[0, end) (the last one may lack its '\n'
  // only at the end of the file) into the point set.
  void parse_block(const char* text, std::size_t end) {
    const std::size_t np = (end + piece_ - 1) / piece_;
    pieces_.assign(np, Piece{});
    {
      tsan::ForkJoin fj;  // pass 1: piece boundaries at line starts, line counts
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, np), [&](const tbb::blocked_range<std::size_t>& r) {
        fj.task_begin();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          Piece& p = pieces_[i];
          p.b = line_start(text, end, i * piece_);
          p.e = line_start(text, end, std::min(end, (i + 1) * piece_));
          p.lines = static_cast<std::size_t>(std::count(text + p.b, text + p.e, '\n'));
          if (p.e == end && p.e > p.b && text[end - 1] != '\n') ++p.lines;  // the file's last line
        }
        fj.task_end();
      });
      fj.joined();
    }
    const std::size_t before = ps_.size();
    std::size_t bound = before, lines = 0;
    for (Piece& p : pieces_) p.first_point = bound, bound += p.lines, lines += p.lines;
    reserve(end, lines);
    ps_.coords.vec().resize(bound * dim_);
    if (ps_.weighted) ps_.weights.vec().resize(bound);
    double* coords = ps_.coords.vec().data();
    double* weights = ps_.weighted ? ps_.weights.vec().data() : nullptr;
    {
      tsan::ForkJoin fj;  // pass 2: every piece into its slice
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, np), [&](const tbb::blocked_range<std::size_t>& r) {
        fj.task_begin();
        for (std::size_t i = r.begin(); i != r.end(); ++i) parse_piece(text, pieces_[i], coords, weights);
        fj.task_end();
      });
      fj.joined();
    }
    // the first bad line in file order; then close the gaps
    std::size_t line = line_no_, to = before;
    for (const Piece& p : pieces_) {
      if (p.bad != Piece::kNoBad) report(text, p, line + 1);
      if (to != p.first_point && p.points > 0) {
        std::memmove(coords + to * dim_, coords + p.first_point * dim_, p.points * dim_ * sizeof(double));
        if (weights) std::memmove(weights + to, weights + p.first_point, p.points * sizeof(double));
      }
      to += p.points;
      line += p.lines;
    }
    line_no_ = line;
    if (to > std::numeric_limits<Index>::max()) too_many(text, before);
    ps_.coords.vec().resize(to * dim_);
    if (weights) ps_.weights.vec().resize(to);
  }

  // The first line start at or after `at` within text[0, end) (end if none).
  static std::size_t line_start(const char* text, std::size_t end, std::size_t at) {
    if (at == 0 || at >= end) return std::min(at, end);
    if (text[at - 1] == '\n') return at;
    const void* nl = std::memchr(text + at, '\n', end - at);
    return nl != nullptr ? static_cast<std::size_t>(static_cast<const char*>(nl) - text) + 1 : end;
  }

  void parse_piece(const char* text, Piece& p, double* coords, double* weights) const {
    double x[kMaxXyzColumns];
    std::size_t local = 0;
    for_each_line(text + p.b, text + p.e, [&](const char* b, const char* e) {
      const LineStatus s = parse_fast(b, e, cols_, max_line_, x);
      if (s == LineStatus::bad) {
        p.bad = local;
        return false;
      }
      if (s == LineStatus::ok) {
        const std::size_t i = p.first_point + p.points++;
        std::memcpy(coords + i * dim_, x, dim_ * sizeof(double));
        if (weights) weights[i] = x[dim_];
      }
      ++local;
      return true;
    });
  }

  // Throws the message of the bad line of piece p, whose first line is
  // numbered first_line.
  [[noreturn]] void report(const char* text, const Piece& p, std::size_t first_line) const {
    std::size_t local = 0;
    for_each_line(text + p.b, text + p.e, [&](const char* b, const char* e) {
      if (local == p.bad) line_error(b, e, path_, first_line + local, cols_, static_cast<int>(dim_), max_line_);
      ++local;
      return true;
    });
    throw InputError(path_, first_line + p.bad, "unreadable line");  // not reached
  }

  // More points than an Index holds: the error names the line of the first
  // point too many (read again sequentially; `before` points came earlier).
  [[noreturn]] void too_many(const char* text, std::size_t before) const {
    const std::size_t limit = std::numeric_limits<Index>::max();
    std::size_t count = before, line = line_no_;
    for (const Piece& p : pieces_) line -= p.lines;
    double x[kMaxXyzColumns];
    for (const Piece& p : pieces_)
      for_each_line(text + p.b, text + p.e, [&](const char* b, const char* e) {
        ++line;
        if (parse_fast(b, e, cols_, max_line_, x) == LineStatus::ok && count++ == limit)
          throw InputError(path_, line, "more than " + std::to_string(limit) + " points");
        return true;
      });
    throw InputError(path_, line, "more than " + std::to_string(limit) + " points");
  }

  // Reserves the coordinate array once, from the first block of at least
  // half a block: its lines per byte times the file's size, and a
  // margin (a reserved page that is never written is never resident).
  void reserve(std::size_t bytes, std::size_t lines) {
    if (reserved_ || file_size_ == 0 || bytes < block_ / 2) return;
    reserved_ = true;
    const double est = static_cast<double>(lines) / static_cast<double>(bytes) * static_cast<double>(file_size_);
    const auto want = static_cast<std::size_t>(std::min(est * 1.25 + 1024, 4294967296.0));  // at most 2^32 points
    try {
      ps_.coords.vec().reserve(want * dim_);
      if (ps_.weighted) ps_.weights.vec().reserve(want);
    } catch (const std::bad_alloc&) {  // no room for the estimate: grow as the points come
    }
  }

  std::string path_;
  std::size_t dim_, cols_;
  std::size_t max_line_, block_, piece_;
  std::FILE* file_ = nullptr;
  std::uint64_t file_size_ = 0;
  bool reserved_ = false;
  std::size_t line_no_ = 0;  // lines parsed so far
  std::vector<Piece> pieces_;
  PointSet ps_;
};

}  // namespace

PointSet read_xyz(const std::string& path, int dim, bool weighted, const XyzLayout& layout) {
  return XyzReader(path, dim, weighted, layout).read();
}

PointSet read_xyz(const std::string& path, int dim, bool weighted) { return read_xyz(path, dim, weighted, {}); }

}  // namespace flipflop::io::detail

// read_xyz.cpp — the .xyz reader: one point per line, parsed in parallel
// batches.
//
// Lines are read through a bounded buffer (text.hpp) into batches of about
// kBatchBytes of text; each batch is parsed in parallel chunks (oneTBB), then
// its points are appended in line order. The first bad line stops the
// reading after its batch: a huge file of garbage costs one batch, not the
// file. Errors are those of the sequential reader, for the first bad line in
// file order: a line that fails is parsed again sequentially to produce its
// message, so the message does not depend on how the batch was split.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"
#include "kernels_cpu/tsan.hpp"

namespace flipflop::io::detail {

namespace {

constexpr std::size_t kBatchBytes = std::size_t{32} << 20;  // text per batch
constexpr std::size_t kGrain = 4096;                        // lines per parallel task

enum class LineStatus : std::uint8_t { blank, ok, bad };

// Parses one line into x[0..cols); the status, and for `bad` nothing else
// (the message comes from line_error).
LineStatus parse_line(std::string_view line, std::size_t cols, double* x) {
  std::string_view tok[kMaxXyzColumns + 1];
  const std::size_t k = split(line, tok, kMaxXyzColumns + 1);
  if (k == 0) return LineStatus::blank;  // blank or comment
  if (k != cols) return LineStatus::bad;
  for (std::size_t c = 0; c < cols; ++c)
    if (parse_real(tok[c], x[c]) != Num::ok) return LineStatus::bad;
  return LineStatus::ok;
}

// The sequential reader's message for a bad line.
[[noreturn]] void line_error(std::string_view line, const std::string& path, std::size_t line_no, std::size_t cols,
                             int dim) {
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

// A batch of lines: their text back to back, where each starts, and the
// number of the first.
struct Batch {
  std::string text;
  std::vector<std::size_t> start;  // lines + 1 offsets
  std::size_t first_line = 0;
  std::size_t lines() const { return start.size() - 1; }
  std::string_view line(std::size_t i) const { return {text.data() + start[i], start[i + 1] - start[i]}; }
};

}  // namespace

PointSet read_xyz(const std::string& path, int dim, bool weighted) {
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;
  const std::size_t cols = static_cast<std::size_t>(dim) + (weighted ? 1 : 0);

  LineReader in(path, '#');
  std::string_view line;
  Batch b;
  std::vector<double> values;
  std::vector<LineStatus> status;
  bool more = true;
  while (more) {
    b.text.clear();
    b.start.assign(1, 0);
    b.first_line = in.line_number() + 1;
    while (b.text.size() < kBatchBytes && (more = in.next(line))) {
      b.text.append(line.data(), line.size());
      b.start.push_back(b.text.size());
    }
    const std::size_t n = b.lines();
    if (n == 0) break;
    values.resize(n * cols);
    status.resize(n);
    tsan::ForkJoin fj;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
      fj.task_begin();
      for (std::size_t i = r.begin(); i != r.end(); ++i) status[i] = parse_line(b.line(i), cols, &values[i * cols]);
      fj.task_end();
    });
    fj.joined();
    for (std::size_t i = 0; i < n; ++i) {
      if (status[i] == LineStatus::blank) continue;
      if (status[i] == LineStatus::bad) line_error(b.line(i), path, b.first_line + i, cols, dim);
      const double* x = &values[i * cols];
      append_point(ps, x, weighted ? x[dim] : 0.0, path, b.first_line + i);
    }
  }
  if (in.line_number() == 0) throw InputError(path, "empty file, no points");
  check_count(ps, path, in.line_number());
  return ps;
}

}  // namespace flipflop::io::detail

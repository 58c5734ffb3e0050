// shards.hpp — the input of a distributed run: one .npy file or a directory
// of .npy shards, read in place.
//
// The rows of the shards, in shard-name order (byte-wise comparison of the
// file names; other files in the directory are ignored), are the input's
// points: global row g is SoS index g (DESIGN.md "Beyond one machine"), the
// index the single-process `flipflop hull2|hull3` gives the same point when
// the shards are concatenated in that order. Every shard is checked as
// io::read_points checks a .npy file (io/npy.hpp: dtype, order, shape,
// truncation); a rank then maps only the rows it owns (MappedRows), block by
// block, and gives the pages back when a block is done, so that its resident
// memory is one block of coordinates plus what it keeps (the blocks' hull
// vertices).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace flipflop::dist {

struct Shard {
  std::string path;
  std::uint64_t first_row = 0;  // global row of the shard's row 0
  std::uint64_t rows = 0;
  std::uint64_t data_offset = 0;  // bytes before the shard's first value
};

struct ShardSet {
  int dim = 0;
  std::vector<Shard> shards;
  std::uint64_t rows = 0;  // all shards together
};

// INPUT: a .npy file, or a directory whose *.npy files (sorted by name) are
// the shards. Throws io::InputError (one line naming the file) for an
// unreadable input, a directory without .npy files, or a shard that
// io::read_points would refuse for its header or size.
ShardSet open_shards(const std::string& input, int dim);

// The global rows [begin, end) cut at shard boundaries: (shard, first row in
// the shard, count) in global order.
struct Piece {
  std::size_t shard = 0;
  std::uint64_t row = 0;  // first row within the shard
  std::uint64_t count = 0;
};
std::vector<Piece> pieces(const ShardSet& s, std::uint64_t begin, std::uint64_t end);

// Single rows of a shard read with pread (the final hull's vertices, spread
// over the shard) without mapping the pages around them. Throws
// io::InputError when the file cannot be opened or a row read.
class ShardRows {
 public:
  ShardRows(const Shard& shard, int dim);
  ~ShardRows();
  ShardRows(const ShardRows&) = delete;
  ShardRows& operator=(const ShardRows&) = delete;
  void read(std::uint64_t row, double* out) const;  // dim doubles

 private:
  const Shard* shard_;
  int dim_;
  int fd_;
};

// Rows [row, row + count) of one shard, mapped read-only (mmap). data() is
// the first row's first coordinate, count * dim doubles in C order; when the
// rows are not 8-byte aligned in the file they are copied into memory
// instead. release(first, n) returns the pages of rows [first, first + n)
// (relative to `row`) to the kernel (madvise MADV_DONTNEED; the mapping
// stays valid: the pages are read again from the file on the next access).
class MappedRows {
 public:
  MappedRows(const Shard& shard, int dim, std::uint64_t row, std::uint64_t count);
  ~MappedRows();
  MappedRows(const MappedRows&) = delete;
  MappedRows& operator=(const MappedRows&) = delete;

  const double* data() const { return data_; }
  void release(std::uint64_t first, std::uint64_t n) const;

 private:
  void* map_ = nullptr;
  std::size_t map_len_ = 0;
  std::vector<double> copy_;
  const double* data_ = nullptr;
  int dim_ = 0;
};

}  // namespace flipflop::dist

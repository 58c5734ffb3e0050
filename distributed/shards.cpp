// shards.cpp — see shards.hpp.
#include "distributed/shards.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/input_error.hpp"
#include "io/npy.hpp"

namespace flipflop::dist {

namespace fs = std::filesystem;

ShardSet open_shards(const std::string& input, int dim) {
  ShardSet s;
  s.dim = dim;
  std::vector<std::string> paths;
  std::error_code ec;
  if (fs::is_directory(input, ec)) {
    for (const auto& e : fs::directory_iterator(input, ec)) {
      const std::string name = e.path().filename().string();
      if (name.size() > 4 && name.compare(name.size() - 4, 4, ".npy") == 0 && !e.is_directory())
        paths.push_back(e.path().string());
    }
    if (ec) throw io::InputError(input, "cannot list the directory: " + ec.message());
    if (paths.empty()) throw io::InputError(input, "no .npy shards in the directory");
    std::sort(paths.begin(), paths.end());
  } else {
    if (!fs::exists(input, ec)) throw io::InputError(input, "cannot open");
    const std::string ext = fs::path(input).extension().string();
    if (ext != ".npy" && ext != ".NPY")
      throw io::InputError(input, "expected a .npy file or a directory of .npy shards");
    paths.push_back(input);
  }
  for (const std::string& p : paths) {
    const io::NpyLayout lay = io::npy_layout(p, dim, false);
    Shard sh;
    sh.path = p;
    sh.first_row = s.rows;
    sh.rows = lay.rows;
    sh.data_offset = lay.data_offset;
    s.rows += lay.rows;
    s.shards.push_back(sh);
  }
  return s;
}

std::vector<Piece> pieces(const ShardSet& s, std::uint64_t begin, std::uint64_t end) {
  std::vector<Piece> out;
  for (std::size_t k = 0; k < s.shards.size(); ++k) {
    const Shard& sh = s.shards[k];
    const std::uint64_t lo = std::max(begin, sh.first_row), hi = std::min(end, sh.first_row + sh.rows);
    if (lo < hi) out.push_back({k, lo - sh.first_row, hi - lo});
  }
  return out;
}

ShardRows::ShardRows(const Shard& shard, int dim) : shard_(&shard), dim_(dim), fd_(::open(shard.path.c_str(), O_RDONLY)) {
  if (fd_ < 0) throw io::InputError(shard.path, std::string("cannot open: ") + std::strerror(errno));
}

ShardRows::~ShardRows() { ::close(fd_); }

void ShardRows::read(std::uint64_t row, double* out) const {
  const std::size_t bytes = static_cast<std::size_t>(dim_) * sizeof(double);
  const ssize_t r = ::pread(fd_, out, bytes, static_cast<off_t>(shard_->data_offset + row * bytes));
  if (r != static_cast<ssize_t>(bytes)) throw io::InputError(shard_->path, "cannot read row " + std::to_string(row));
}

MappedRows::MappedRows(const Shard& shard, int dim, std::uint64_t row, std::uint64_t count) : dim_(dim) {
  const std::uint64_t row_bytes = static_cast<std::uint64_t>(dim) * sizeof(double);
  const std::uint64_t offset = shard.data_offset + row * row_bytes, bytes = count * row_bytes;
  if (count == 0) {
    data_ = copy_.data();
    return;
  }
  const int fd = ::open(shard.path.c_str(), O_RDONLY);
  if (fd < 0) throw io::InputError(shard.path, std::string("cannot open: ") + std::strerror(errno));
  if (offset % alignof(double) != 0) {
    // an unusual header length: the rows are not aligned for doubles
    copy_.resize(static_cast<std::size_t>(count) * static_cast<std::size_t>(dim));
    std::uint64_t done = 0;
    char* dst = reinterpret_cast<char*>(copy_.data());
    while (done < bytes) {
      const ssize_t r = ::pread(fd, dst + done, static_cast<std::size_t>(bytes - done), static_cast<off_t>(offset + done));
      if (r <= 0) {
        ::close(fd);
        throw io::InputError(shard.path, "npy data is truncated");
      }
      done += static_cast<std::uint64_t>(r);
    }
    ::close(fd);
    data_ = copy_.data();
    return;
  }
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  const std::uint64_t start = offset / page * page;
  map_len_ = static_cast<std::size_t>(offset + bytes - start);
  map_ = ::mmap(nullptr, map_len_, PROT_READ, MAP_PRIVATE, fd, static_cast<off_t>(start));
  const int err = errno;
  ::close(fd);
  if (map_ == MAP_FAILED) {
    map_ = nullptr;
    throw io::InputError(shard.path, std::string("cannot map rows: ") + std::strerror(err));
  }
  ::madvise(map_, map_len_, MADV_SEQUENTIAL);
  data_ = reinterpret_cast<const double*>(static_cast<const char*>(map_) + (offset - start));
}

MappedRows::~MappedRows() {
  if (map_) ::munmap(map_, map_len_);
}

void MappedRows::release(std::uint64_t first, std::uint64_t n) const {
  if (!map_ || n == 0) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto row_bytes = static_cast<std::uintptr_t>(dim_) * sizeof(double);
  auto lo = reinterpret_cast<std::uintptr_t>(data_) + static_cast<std::uintptr_t>(first) * row_bytes;
  auto hi = lo + static_cast<std::uintptr_t>(n) * row_bytes;
  lo = (lo + page - 1) / page * page;  // whole pages inside the rows only
  hi = hi / page * page;
  if (lo < hi) ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
}

}  // namespace flipflop::dist

// temp_file.cpp — see temp_file.hpp.
#include "fuzz/temp_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "fuzz/fuzz_input.hpp"

namespace flipflop::fuzz {

TempFile::TempFile(const std::string& tag, const std::string& ext, const std::uint8_t* data,
                   std::size_t size) {
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  path_ = (dir / ("flipflop-fuzz-" + std::to_string(::getpid()) + "-" + tag + ext)).string();
  std::FILE* f = std::fopen(path_.c_str(), "wb");
  const bool ok = f && (size == 0 || std::fwrite(data, 1, size, f) == size);
  if (f && std::fclose(f) != 0) fail("fuzz harness", "cannot close " + path_);
  if (!ok) fail("fuzz harness", "cannot write " + path_);
}

TempFile::~TempFile() { std::remove(path_.c_str()); }

}  // namespace flipflop::fuzz

// temp_file.hpp — a per-process scratch file for the reader fuzz targets,
// which must hand the readers a real file (the format follows the extension).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace flipflop::fuzz {

// Writes the bytes to <temp dir>/flipflop-fuzz-<pid>-<tag><ext> and removes
// the file again when destroyed. Aborts (fail()) when the file cannot be
// written: that is the harness failing, not the code under test.
class TempFile {
 public:
  TempFile(const std::string& tag, const std::string& ext, const std::uint8_t* data, std::size_t size);
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace flipflop::fuzz

// replay_predicates.cpp — runs the fuzz check (predicates_check.hpp) over every
// file of the given files or directories, without libFuzzer, so that the
// default (g++) build and ctest exercise the seed corpus and any crash
// reproducers added to it. Exit status 0 when every input passed (a violation
// aborts); 1 when no input was found or a path is unreadable.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/predicates_check.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::vector<fs::path> files;
  for (int a = 1; a < argc; ++a) {
    const fs::path p(argv[a]);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      for (const auto& entry : fs::directory_iterator(p))
        if (entry.is_regular_file()) files.push_back(entry.path());
    } else if (fs::is_regular_file(p, ec)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "replay_predicates: cannot read %s\n", argv[a]);
      return 1;
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "usage: replay_predicates FILE_OR_DIR...  (no input found)\n");
    return 1;
  }
  std::size_t checked = 0;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    if (flipflop::fuzz::check_predicates_input(bytes.data(), bytes.size())) ++checked;
  }
  std::printf("replay_predicates: %zu inputs, %zu checked, %zu skipped (non-finite)\n",
              files.size(), checked, files.size() - checked);
  return 0;
}

// replay_main.cpp — runs one fuzz check (checks.hpp, selected by
// -DFLIPFLOP_FUZZ_CHECK, named by -DFLIPFLOP_FUZZ_NAME) over every file of
// the given files or directories, without libFuzzer, so that the default
// (g++) build and ctest exercise the seed corpus and every crash reproducer
// saved into it. Exit status 0 when every input passed (a violation aborts);
// 1 when no input was found or a path is unreadable.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/checks.hpp"

#if !defined(FLIPFLOP_FUZZ_CHECK) || !defined(FLIPFLOP_FUZZ_NAME)
#error "define FLIPFLOP_FUZZ_CHECK and FLIPFLOP_FUZZ_NAME (fuzz/CMakeLists.txt)"
#endif

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const char* name = FLIPFLOP_FUZZ_NAME;
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
      std::fprintf(stderr, "%s: cannot read %s\n", name, argv[a]);
      return 1;
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s FILE_OR_DIR...  (no input found)\n", name);
    return 1;
  }
  std::size_t checked = 0;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: cannot read %s\n", name, f.c_str());
      return 1;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    // A failing check names the input on stderr before it aborts.
    std::fprintf(stderr, "%s: %s\n", name, f.filename().c_str());
    if (flipflop::fuzz::FLIPFLOP_FUZZ_CHECK(bytes.data(), bytes.size())) ++checked;
  }
  std::printf("%s: %zu inputs, %zu checked, %zu skipped\n", name, files.size(), checked,
              files.size() - checked);
  return 0;
}

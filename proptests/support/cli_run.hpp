// cli_run.hpp — running the built command-line tool from a test (the
// command-line contract tests: cli_test.cpp, rt3_cli_test.cpp): a temporary
// directory, one run's exit code, stdout and stderr, and the contract's
// one-line error.
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace flipflop::test::cli {

namespace fs = std::filesystem;

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A fresh directory under the system's temporary one, removed at the end.
struct TempDir {
  fs::path dir;
  explicit TempDir(const std::string& prefix = "flipflop_cli_") {
    dir = fs::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" + std::to_string(std::rand()));
    fs::create_directories(dir);
  }
  ~TempDir() { fs::remove_all(dir); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  fs::path file(const std::string& name, const std::string& content) const {
    fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
};

// A shell command line, its stdout and stderr through files in t.
inline Run run_command(const TempDir& t, const std::string& command) {
  const fs::path out = t.dir / "stdout.txt", err = t.dir / "stderr.txt";
  const std::string cmd = command + " > " + out.string() + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// FLIPFLOP_BINARY ARGS.
inline Run run(const TempDir& t, const std::string& args) { return run_command(t, std::string(FLIPFLOP_BINARY) + " " + args); }

inline int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// The contract for bad input and bad usage: exit code 2, one line on stderr
// containing `what`, nothing on stdout.
inline void expect_one_line_error(const Run& r, const std::string& what) {
  INFO("stderr: " << r.err << " stdout: " << r.out);
  CHECK(r.code == 2);
  CHECK(lines(r.err) == 1);
  CHECK(r.err.find(what) != std::string::npos);
  CHECK(r.out.empty());
}

// The same, the message also naming the input (`name`: a file, file:line).
inline void expect_input_error(const Run& r, const std::string& name, const std::string& what) {
  INFO("stderr: " << r.err);
  CHECK(r.err.find(name) != std::string::npos);
  expect_one_line_error(r, what);
}

}  // namespace flipflop::test::cli

// progress.hpp — the progress line of long runs: `flipflop KIND: STAGE (T s)`
// on standard error, rewritten in place every 0.2 s once the run has taken
// more than a second, and only when standard error is a terminal (never in
// pipes, files or tests). It names the current stage (read, compute, certify,
// write) and the time since the start; it does not estimate what remains.
// The line is erased when the run ends, so the terminal keeps only the
// command's real output (and --stats lines).
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace flipflop::cli {

class Progress {
 public:
  // enabled: print at all (callers pass isatty(stderr)); what: the command.
  Progress(bool enabled, std::string what);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // The stage now running ("reading", "computing", "certifying", ...).
  void stage(std::string name);

  // Is standard error a terminal?
  static bool stderr_is_terminal();

 private:
  void run();

  const std::string what_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex m_;
  std::condition_variable cv_;
  std::string stage_;
  bool done_ = false;
  bool shown_ = false;  // a line was printed (and must be erased)
  std::thread thread_;
};

}  // namespace flipflop::cli

// progress.cpp — the progress line (progress.hpp).
#include "cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace flipflop::cli {

Progress::Progress(bool enabled, std::string what) : what_(std::move(what)) {
  if (enabled) thread_ = std::thread([this] { run(); });
}

Progress::~Progress() {
  {
    std::lock_guard<std::mutex> lock(m_);
    done_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Progress::stage(std::string name) {
  std::lock_guard<std::mutex> lock(m_);
  stage_ = std::move(name);
}

bool Progress::stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

void Progress::run() {
  using namespace std::chrono;
  std::unique_lock<std::mutex> lock(m_);
  // nothing for the first second: short runs stay silent
  if (cv_.wait_until(lock, start_ + seconds(1), [this] { return done_; })) return;
  while (!done_) {
    const double t = duration<double>(steady_clock::now() - start_).count();
    // \r and "erase to end of line" (ANSI, every terminal emulator) rewrite the line
    std::fprintf(stderr, "\r\033[K%s: %s (%.1f s)", what_.c_str(), stage_.c_str(), t);
    std::fflush(stderr);
    shown_ = true;
    cv_.wait_for(lock, milliseconds(200), [this] { return done_; });
  }
  if (shown_) {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }
}

}  // namespace flipflop::cli

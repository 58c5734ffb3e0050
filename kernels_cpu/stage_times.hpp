// stage_times.hpp — wall-clock seconds per stage of a kernel, on request
// (the benchmark's time by stage: `flipflop bench hull2|hull3 --stages`).
// A kernel takes a StageTimes* in its options; when it is null, StageClock
// marks cost one branch.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace flipflop::cpu {

struct StageTimes {
  std::vector<std::pair<std::string, double>> stages;  // in the order first seen
  // add s seconds to stage `name` (a repeated name accumulates)
  void add(const std::string& name, double s) {
    for (auto& [n, t] : stages)
      if (n == name) {
        t += s;
        return;
      }
    stages.emplace_back(name, s);
  }
};

// mark(name): the time since the previous mark (or construction) is stage
// `name`'s.
class StageClock {
 public:
  explicit StageClock(StageTimes* times) : times_(times), last_(std::chrono::steady_clock::now()) {}
  void mark(const char* name) {
    if (!times_) return;
    const auto now = std::chrono::steady_clock::now();
    times_->add(name, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  StageTimes* times_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace flipflop::cpu

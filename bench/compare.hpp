// compare.hpp — rows of a side-by-side benchmark (internal to bench/): each
// row is run R times on one input, its canonical outputs compared with the
// first row's, and the table or the CSV of DESIGN.md "Benchmarks" printed
// (name,median_s,min_s,max_s,size,identical).
#pragma once

#include <malloc.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "bench/timing.hpp"

namespace flipflop::bench::detail {

template <class Output>
struct Peer {
  std::string name;
  std::function<Output(const PointSet&)> run;
  // when set, the row's time of a run is what it returns after the run (a
  // GPU kernel's time without the host-device transfers), not the wall time
  std::function<double()> self_time = {};
};

struct Row {
  std::string name;
  std::vector<double> times;
  std::string error;  // non-empty when the peer failed
  std::size_t size = 0;
};

// --run: the row's name starts with one of the prefixes (case-insensitive); a
// prefix ending in '$' matches the whole name only ("flipflop:cuda$" chooses
// flipflop:cuda and not flipflop:cuda-omp).
inline bool chosen(const Args& a, const std::string& name) {
  if (a.run.empty()) return true;
  const auto same = [](char x, char y) { return std::tolower(x) == std::tolower(y); };
  for (const std::string& p : a.run) {
    const bool whole = !p.empty() && p.back() == '$';
    const std::size_t len = whole ? p.size() - 1 : p.size();
    if (whole ? len == name.size() : len <= name.size())
      if (std::equal(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(len), name.begin(), same)) return true;
  }
  return false;
}

// Resident memory of this process from /proc/self/status (Linux), in bytes:
// key "VmRSS:" (now) or "VmHWM:" (the peak); -1 when unavailable.
inline long long proc_status_bytes(const char* key) {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long long kb = -1;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, key, std::strlen(key)) == 0) kb = std::atoll(line + std::strlen(key));
  std::fclose(f);
  return kb < 0 ? -1 : kb * 1024;
}

// The peak resident memory of a row above what the process held before it:
// begin() returns freed heap memory to the system (malloc_trim) and resets the
// kernel's peak to the current resident size (writing 5 to
// /proc/self/clear_refs, Linux >= 4.0); extra() reads the peak since minus
// that base. -1 when the kernel does not allow the reset.
struct PeakMemory {
  long long base = -1;
  void begin() {
    malloc_trim(0);
    base = -1;
    std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
    if (!f) return;
    const bool ok = std::fputs("5", f) >= 0;
    if (std::fclose(f) != 0 || !ok) return;
    base = proc_status_bytes("VmRSS:");
  }
  long long extra() const {
    const long long peak = proc_status_bytes("VmHWM:");
    return base < 0 || peak < 0 ? -1 : std::max(0LL, peak - base);
  }
};

// memory: the table gets a column "peak MB", each row's peak resident memory
// above the process's before it (PeakMemory; the input, the earlier rows'
// kept outputs excluded), the maximum over its runs. Not in the CSV, whose
// columns are fixed.
template <class Output>
inline int compare_peers(const Args& a, const PointSet& pts, const std::vector<Peer<Output>>& all_peers,
                  const char* size_label, bool memory = false) {
  std::vector<Peer<Output>> peers;
  for (const Peer<Output>& p : all_peers)
    if (chosen(a, p.name)) peers.push_back(p);
  if (peers.empty()) throw Usage("--run matches no row");
  std::vector<Row> rows;
  std::vector<long long> peak;  // per row (memory)
  std::vector<Output> outputs;
  std::vector<std::string> output_names;
  for (const Peer<Output>& p : peers) {
    Row row{p.name, {}, {}, 0};
    Output out;
    PeakMemory mem;
    if (memory) mem.begin();
    try {
      for (int r = 0; r < a.reps; ++r) {
        out = Output();  // the previous run's output freed outside the timing
        const double wall = seconds([&] { out = p.run(pts); });
        row.times.push_back(p.self_time ? p.self_time() : wall);
      }
      row.size = out.size();
      outputs.push_back(std::move(out));
      output_names.push_back(p.name);
    } catch (const std::exception& e) {
      row.error = e.what();
      row.times.clear();
    }
    peak.push_back(memory ? mem.extra() : -1);
    rows.push_back(std::move(row));
  }
  double fastest = 0;
  for (const Row& r : rows)
    if (r.error.empty() && (fastest == 0 || median(r.times) < fastest)) fastest = median(r.times);

  if (a.csv) {  // DESIGN.md "Benchmarks": identical = the first successful row's canonical output
    std::printf("name,median_s,min_s,max_s,size,identical\n");
    std::size_t k = 0;
    for (const Row& r : rows) {
      if (!r.error.empty()) {
        std::printf("%s,,,,,failed\n", r.name.c_str());
        continue;
      }
      const auto [lo, hi] = std::minmax_element(r.times.begin(), r.times.end());
      std::printf("%s,%.6f,%.6f,%.6f,%zu,%d\n", r.name.c_str(), median(r.times), *lo, *hi, r.size,
                  outputs[k] == outputs[0] ? 1 : 0);
      ++k;
    }
    return 0;
  }
  std::printf("%-40s %12s %12s %12s %12s %10s%s\n", "peer", "median s", "min s", "max s",
              size_label, "/fastest", memory ? "    peak MB" : "");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    if (!r.error.empty()) {
      std::printf("%-40s failed: %s\n", r.name.c_str(), r.error.c_str());
      continue;
    }
    const auto [lo, hi] = std::minmax_element(r.times.begin(), r.times.end());
    std::printf("%-40s %12.4f %12.4f %12.4f %12zu %10.2f", r.name.c_str(), median(r.times), *lo,
                *hi, r.size, median(r.times) / fastest);
    if (memory && peak[i] >= 0) std::printf(" %10.1f", static_cast<double>(peak[i]) / 1e6);
    if (memory && peak[i] < 0) std::printf(" %10s", "?");
    std::printf("\n");
  }
  if (outputs.size() >= 2) {
    std::string differing;
    for (std::size_t i = 1; i < outputs.size(); ++i)
      if (outputs[i] != outputs[0]) differing += " " + output_names[i];
    if (differing.empty())
      std::printf("canonical outputs identical across %zu peers\n", outputs.size());
    else
      std::printf("canonical outputs differ from %s's:%s\n", output_names[0].c_str(),
                  differing.c_str());
  }
  return 0;
}

}  // namespace flipflop::bench::detail

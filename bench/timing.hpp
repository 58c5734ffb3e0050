// timing.hpp — medians of repeated runs (internal to bench/).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::bench::detail {

// Wall-clock seconds of one call of f, by std::chrono::steady_clock.
template <class F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

// The median of a sample (mean of the two middle values for an even count).
inline double median(std::vector<double> v) {
  if (v.empty()) throw std::logic_error("median of no runs");
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// A usage error: printed as one line, exit code 2.
struct Usage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Options shared by the experiments.
struct Args {
  std::string experiment;
  std::string dist;
  std::size_t n = 0;
  int reps = 5;
  unsigned long long seed = 1;
  double thickness = 0.01;
  bool weighted = false;
  double wlo = 0, whi = 0;
  std::size_t hull_points = 0;
  bool csv = false;  // CSV rows instead of the table (DESIGN.md "Benchmarks")
  std::vector<std::string> run;  // --run: row name prefixes (case-insensitive); empty: every row
  bool stages = false;  // --stages: time by stage of flipflop:cpu (hull2, hull3)
  int threads = 0;      // rt3|dt3: --threads N for flipflop:cpu and the CGAL parallel rows (0: all cores)
  int dim = 0;          // instant-flip: --dim d (2..5)
  double step = 0.01;   // instant-flip: --step s
};

int bench_predicates(const Args& a);
int bench_peers(const Args& a);
int bench_stages(const Args& a);  // hull2|hull3|rt2|dt2|rt3|dt3 --stages
// The machine, as one line: CPU model, logical processors, data cache sizes,
// load average
// (bench_rt3.cpp); printed beside every table.
std::string machine_line();
int bench_instant_flip(const Args& a);
int bench_rt3(const Args& a);         // rt3|dt3 (bench_rt3.cpp)
// The input of a hull/triangulation experiment: gen::generate with the
// options of `a`, checked to have the experiment's dimension.
PointSet generated_input(const Args& a);

}  // namespace flipflop::bench::detail

// bench.cpp — command-line parsing and dispatch of `flipflop bench`.
#include "bench/bench.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "bench/timing.hpp"

namespace flipflop::bench {

namespace {

using detail::Args;
using detail::Usage;

const char* kUsage =
    "usage: flipflop bench predicates [--n N] [--reps R] [--seed S] [--csv]\n"
    "       flipflop bench hull2|hull3|dt2|rt2 --dist NAME --n N [--reps R] [--seed S]\n"
    "                      [--thickness T] [--weights LO,HI] [--hull-points H]\n"
    "                      [--run PREFIX,...]  (rows whose name starts with a prefix, any case;\n"
    "                      a trailing '$': the whole name) [--csv]\n"
    "       flipflop bench hull2|hull3|rt2|dt2 --stages --dist NAME --n N [...]  (time by stage of flipflop:cpu:\n"
    "                      read .xyz/.npy, the kernel's stages, certify, write)\n"
    "       flipflop bench rt3|dt3 --dist NAME --n N [--reps R] [--seed S] [--weights LO,HI] (rt3)\n"
    "                      [--threads T] [--run PREFIX,...] [--csv] [--stages]  (3D regular / Delaunay:\n"
    "                      flipflop:cpu, flipflop:reference, flipflop:cuda-omp|cuda[:no-transfers], cgal:delaunay_triangulation_3[:parallel] (dt3),\n"
    "                      cgal:regular_triangulation_3[:parallel], qhull and tetgen (dt3))\n"
    "       flipflop bench instant-flip --dim d --n N [--step S] [--reps R] [--seed S] [--run P,...] [--csv]\n"
    "                      (RT(S+W) -> RT(S+U) in place, U = max(0, W + delta), against fresh builds)\n";

unsigned long long to_count(const std::string& opt, const std::string& s) {
  char* end = nullptr;
  errno = 0;
  unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || s[0] == '-' || *end != '\0' || errno != 0)
    throw Usage(opt + " expects a non-negative integer, got '" + s + "'");
  return v;
}

double to_double(const std::string& opt, const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !(v == v)) throw Usage(opt + " expects a number, got '" + s + "'");
  return v;
}

Args parse(int argc, char** argv) {
  if (argc < 2) throw Usage("missing experiment (predicates, hull2, hull3, dt2, rt2, dt3, rt3, instant-flip)");
  Args a;
  a.experiment = argv[1];
  bool have_n = false;
  for (int i = 2; i < argc; ++i) {
    const std::string opt = argv[i];
    if (opt == "--csv" || opt == "--stages") {  // the flags without a value
      (opt == "--csv" ? a.csv : a.stages) = true;
      continue;
    }
    if (i + 1 >= argc) throw Usage("option " + opt + " needs a value");
    const std::string val = argv[++i];
    if (opt == "--n") {
      a.n = static_cast<std::size_t>(to_count(opt, val));
      have_n = true;
    } else if (opt == "--reps") {
      a.reps = static_cast<int>(to_count(opt, val));
      if (a.reps < 1 || a.reps > 1000) throw Usage("--reps must be in 1..1000");
    } else if (opt == "--seed") {
      a.seed = to_count(opt, val);
    } else if (opt == "--dist") {
      a.dist = val;
    } else if (opt == "--thickness") {
      a.thickness = to_double(opt, val);
    } else if (opt == "--run") {
      std::size_t start = 0;
      while (start <= val.size()) {
        const std::size_t comma = std::min(val.find(',', start), val.size());
        if (comma > start) a.run.push_back(val.substr(start, comma - start));
        start = comma + 1;
      }
      if (a.run.empty()) throw Usage("--run expects comma-separated row name prefixes");
    } else if (opt == "--threads") {
      a.threads = static_cast<int>(to_count(opt, val));
      if (a.threads > 1024) throw Usage("--threads must be at most 1024");
    } else if (opt == "--dim") {
      a.dim = static_cast<int>(to_count(opt, val));
    } else if (opt == "--step") {
      a.step = to_double(opt, val);
      if (!(a.step >= 0)) throw Usage("--step must be non-negative");
    } else if (opt == "--hull-points") {
      a.hull_points = static_cast<std::size_t>(to_count(opt, val));
    } else if (opt == "--weights") {
      const auto comma = val.find(',');
      if (comma == std::string::npos) throw Usage("--weights expects LO,HI");
      a.wlo = to_double(opt, val.substr(0, comma));
      a.whi = to_double(opt, val.substr(comma + 1));
      a.weighted = true;
    } else {
      throw Usage("unknown option " + opt);
    }
  }
  if (a.experiment == "predicates") {
    if (!have_n) a.n = 50000;
    if (a.n == 0) throw Usage("--n must be positive");
    return a;
  }
  if (a.experiment == "instant-flip") {
    if (a.dim < 2 || a.dim > 5) throw Usage("instant-flip needs --dim d (2..5)");
    if (!have_n || a.n < static_cast<std::size_t>(a.dim) + 1) throw Usage("instant-flip needs --n N (at least d+1)");
    return a;
  }
  if (a.experiment != "hull2" && a.experiment != "hull3" && a.experiment != "dt2" &&
      a.experiment != "rt2" && a.experiment != "dt3" && a.experiment != "rt3")
    throw Usage("unknown experiment '" + a.experiment + "' (predicates, hull2, hull3, dt2, rt2, dt3, rt3, instant-flip)");
  if (a.dist.empty()) throw Usage(a.experiment + " needs --dist NAME");
  if (!have_n || a.n == 0) throw Usage(a.experiment + " needs --n N (positive)");
  if (a.experiment == "rt2" && !a.weighted) {
    // The thesis' middle setting (§5.4): about 20-30 % of the points redundant.
    a.weighted = true;
    a.wlo = 0;
    a.whi = 1e-5;
  }
  if (a.experiment == "rt3" && !a.weighted) {
    // In [0,1]^3 with 10^5 uniform points (spacing n^(-1/3) ≈ 0.02, its
    // square 4.6e-4) about 30 % of the points redundant (measured;
    // docs/performance/rt3.md), as the thesis' middle 2D setting.
    a.weighted = true;
    a.wlo = 0;
    a.whi = 1e-3;
  }
  if (a.experiment != "rt2" && a.experiment != "rt3" && a.weighted)
    throw Usage("--weights applies to rt2 and rt3 only");
  if (a.threads != 0 && a.experiment != "rt3" && a.experiment != "dt3")
    throw Usage("--threads applies to rt3 and dt3 only");
  return a;
}

}  // namespace

int run(int argc, char** argv) {
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("%s", kUsage);
    return 0;
  }
  try {
    Args a = parse(argc, argv);
    if (a.csv) {
      // What a second machine needs to compare the figures (issue 40): the
      // command and the machine (CPU model, logical processors, cache sizes,
      // load average at the start), as comment lines before the CSV header;
      // the peers' times are rows of the same run
      std::string cmd = "flipflop bench";
      for (int i = 1; i < argc; ++i) cmd += std::string(" ") + argv[i];
      std::printf("# %s\n# machine: %s\n", cmd.c_str(), detail::machine_line().c_str());
      std::fflush(stdout);
    }
    if (a.experiment == "predicates") return detail::bench_predicates(a);
    if (a.experiment == "instant-flip") return detail::bench_instant_flip(a);
    if (a.stages) return detail::bench_stages(a);
    if (a.experiment == "rt3" || a.experiment == "dt3") return detail::bench_rt3(a);
    return detail::bench_peers(a);
  } catch (const Usage& e) {
    std::fprintf(stderr, "flipflop bench: error: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::invalid_argument& e) {  // e.g. an unknown distribution
    std::fprintf(stderr, "flipflop bench: error: %s\n", e.what());
    return 2;
  } catch (const std::runtime_error& e) {  // a peer or stage disagreed: no result is printed
    std::fprintf(stderr, "%s\n", e.what());
    return 3;
  }
}

}  // namespace flipflop::bench

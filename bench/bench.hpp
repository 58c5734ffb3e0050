// bench.hpp — `flipflop bench ...`: timings of flipflop's building blocks and
// of the peers a user would pick instead (DESIGN.md, "Benchmarks").
//
//   flipflop bench predicates [--n N] [--reps R] [--seed S] [--csv]
//                  (each stage of the staged predicates alone, CGAL Epick and
//                  GMP; columns and input families in bench_predicates.cpp)
//   flipflop bench hull2|hull3|dt2|rt2 --dist NAME --n N [--reps R] [--seed S]
//                  [--thickness T] [--weights LO,HI] [--hull-points H] [--run P,...] [--csv]
//   flipflop bench rt3|dt3 --dist NAME --n N [--reps R] [--seed S] [--weights LO,HI]
//                  [--threads T] [--run P,...] [--csv] [--stages]
//                  (3D regular / Delaunay triangulation; rows in bench_rt3.cpp)
//
// Every number printed is measured in this process: medians of R runs timed
// with std::chrono::steady_clock; input generation is never timed.
#pragma once

namespace flipflop::bench {

// argv[0] is the program name, argv[1] the experiment, then its options.
// Returns 0 on success, 2 on a usage error (one line on stderr).
int run(int argc, char** argv);

}  // namespace flipflop::bench

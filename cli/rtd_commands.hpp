// rtd_commands.hpp — the d-dimensional regular-triangulation subcommands of
// the flipflop tool (thesis ch. 9), callable from tests:
//
//   flipflop rtd IN --dim d -o OUT [--backend cpu|reference] [--threads N] [--strict] [--stats]
//       IN: d coordinates and a weight per line (.xyz; for d = 2, 3 also .off
//       and .ply as io/read_points.hpp reads them). OUT: the canonical simplex
//       list of RT(S ⊕ W) (canonical_d.hpp), certified (certify_rtd.hpp)
//       before it is written. Redundant points are listed on stderr.
//       d = 3 runs the cpu backend by default (kernels_cpu/rt3: run_rt3 of
//       rt3_commands.hpp, the same bytes as `flipflop rt3`); every d has
//       --backend reference (RT+1, rt_incremental.hpp), the only one for
//       d != 3 (--backend cpu there is a usage error).
//
//   flipflop instant-flip POINTS --dim d --from W.xyz --to U.xyz -o OUT
//                        [--stats] [--timeline]
//       POINTS: d coordinates per line; W.xyz, U.xyz: the same points, in
//       the same order, bit for bit, with their weight as a last column.
//       Builds RT(S ⊕ W) (rt_incremental.hpp) and updates it in place to
//       RT(S ⊕ U) by the monotonic instant flip with insertions (Algorithm 14
//       extended, ref::DynamicRegularTriangulation: any W and U; points
//       redundant under W may become vertices and vice versa), then writes
//       the canonical simplex list of RT(S ⊕ U) after certifying it — byte
//       for byte what `flipflop rtd` writes for U. --timeline prints the time
//       lines (§9.3) of the start and the final triangulation on stderr
//       (under the perturbation order of Algorithm 15 when one exists).
//
// OUT empty or "-" writes to standard output. Errors: UsageError (bad usage
// or input, one line, exit 2), InternalError (a result that failed its
// certification, exit 3; nothing is written).
#pragma once

#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::cli {

struct RtdArgs {
  std::string in, out;
  int dim = 0;  // 2..9
  bool stats = false;
  bool strict = false;  // the strict view (reference/rtd/strict_rtd.hpp)
  bool ascii = false;  // .ply/.stl output in ASCII
  std::string backend;  // "cpu" (d = 3 only: kernels_cpu/rt3, rt3_commands.hpp) or "reference"; empty: cpu
                        // for d = 3, reference otherwise
  int threads = 0;      // cpu backend: worker threads (0: all cores)
};

struct InstantFlipArgs {
  std::string points, from, to, out;
  int dim = 0;  // 2..5
  bool stats = false, timeline = false;
  bool ascii = false;  // .ply/.stl output in ASCII
  int threads = 0;     // workers of the parallel scan (0: all cores)
};

int run_rtd(const RtdArgs& a);
int run_instant_flip(const InstantFlipArgs& a);

// On standard error: "CMD: N redundant points (not vertices): i j k ..." (the
// first 50), nothing when there are none — rtd's, instant-flip's and rt3's report.
void report_redundant(const char* cmd, const std::vector<Index>& redundant);

}  // namespace flipflop::cli

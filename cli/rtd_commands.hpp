// rtd_commands.hpp — the d-dimensional regular-triangulation subcommands of
// the flipflop tool (thesis ch. 9), callable from tests:
//
//   flipflop rtd IN --dim d -o OUT [--stats]
//       IN: d coordinates and a weight per line (.xyz; for d = 2, 3 also .off
//       and .ply as io/read_points.hpp reads them). OUT: the canonical simplex
//       list of RT(S ⊕ W) (canonical_d.hpp), certified (certify_rtd.hpp)
//       before it is written. Redundant points are listed on stderr.
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

namespace flipflop::cli {

struct RtdArgs {
  std::string in, out;
  int dim = 0;  // 2..5
  bool stats = false;
  bool strict = false;  // the strict view (reference/rtd/strict_rtd.hpp)
  bool ascii = false;  // .ply/.stl output in ASCII
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

}  // namespace flipflop::cli

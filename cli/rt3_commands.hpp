// rt3_commands.hpp — the 3D regular / Delaunay triangulation subcommands of
// the flipflop tool, callable from tests:
//
//   flipflop rt3 IN [-o OUT] [--backend cpu|reference] [--threads N] [--strict] [--stats] [--ascii]
//       IN: x y z w per line (.xyz, .npy (n, 4), .ply with a weight
//       property). OUT: the canonical tetrahedron list of RT(S ⊕ W)
//       (canonical_d.hpp: one "i j k l" per line, positive volume, smallest
//       index first, sorted), or by extension .vtu (VTK_TETRA cells) or .npy
//       (int64 (m, 4)); the surface formats cannot hold tetrahedra and are
//       refused before any work.
//   flipflop dt3 IN ...  the same for x y z (weights 0: the Delaunay
//       triangulation).
//   flipflop rtd --dim 3 IN ... the same as rt3 (run_rtd hands d = 3 with
//       the cpu backend, its default, to run_rt3; byte for byte rt3's output).
//
// Backends: "cpu" (the default) — kernels_cpu/rt3 (cpu::rt3, oneTBB) with
// the kernel's Rt3Witness, certified by cpu::certify_rt3 from that witness
// on the same threads; "reference" — ref::rtd_incremental (RT+1, sequential)
// certified by certify::rtd, as `flipflop rtd`. Both write the same bytes.
// --strict: the strict view (reference/rtd/strict_rtd.hpp: no tetrahedron of
// zero volume), derived by the reference's strict rule (sequential) from the
// certified canonical answer of the chosen backend and certified in turn at
// Level::exact (certify::rtd), as `rtd --strict`.
// The result is certified before anything is written; points that are not
// vertices (redundant) are listed on standard error, as `rtd` lists them.
//
// Errors: UsageError (bad usage or input, one line, exit 2) — unreadable or
// malformed files, NaN/Inf, fewer than 4 points, a missing weight column
// (rt3), input that does not span R^3 (coplanar, collinear, one point);
// InternalError (a result that failed its certification, exit 3; nothing is
// written).
#pragma once

#include <string>

namespace flipflop::cli {

struct Rt3Args {
  std::string kind = "rt3";  // "rt3", "dt3" (unweighted) or "rtd" (rtd --dim 3: weighted, as rt3)
  std::string in, out;
  std::string backend;  // "cpu" or "reference"; empty: cpu
  int threads = 0;      // cpu backend: worker threads of the kernel and its certifier (0: all cores)
  bool strict = false;  // the strict view (reference/rtd/strict_rtd.hpp)
  bool stats = false;   // counts and stage timings to standard error
  bool ascii = false;   // accepted as for every kind (the formats of tetrahedra have one encoding)
};

int run_rt3(const Rt3Args& a);

}  // namespace flipflop::cli

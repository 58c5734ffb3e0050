// hull2.hpp — the multithreaded 2D convex hull (cpu backend of `flipflop
// hull2`), on oneTBB:
//
//   1. throw_away.hpp   Akl–Toussaint-style first pass: every point proved
//                       strictly inside a polygon of input points is dropped
//                       (parallel selection, survivors keep their indices);
//   2. graham_sorting.hpp  parallel Graham-sorting (thesis §4.2 Algorithm 3)
//                       on the survivors, with flip-pop (§4.1 Algorithm 1)
//                       in chunks of the chains in parallel, then a final
//                       pass (the CPU analogue of §4.2's shared-memory
//                       variant) — or graham_insertion.hpp, parallel
//                       Graham-insertion (§4.3 Algorithm 4) in rounds, then
//                       the same flip-pop.
//
// The result is the canonical hull (DESIGN.md): counter-clockwise from the
// smallest index, the unique SoS hull — identical to ref::hull2(ps, algo) for
// every algorithm and every thread count (step 1 removes no vertex of the SoS
// hull; step 2 is flip-pop, whose result does not depend on the order of its
// flips). Input that does not span the plane is rejected with the reference's
// std::invalid_argument (ref::require_planar_input).
#pragma once

#include <cstddef>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/hull2/polygon.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

struct Hull2Options {
  int threads = 0;  // worker threads; 0: the runtime's default
  // Tuning; the result does not depend on them (the tests vary them to reach
  // every path on small inputs):
  std::size_t throw_away_from = 1024;  // fewer points: no throw-away pass
  std::size_t sample = 0;              // throw-away sample size; 0: min(2^17, max(n / 64, 1024))
  std::size_t scan_chunk = 4096;       // vertices per chunk of the parallel flip-pop pass (>= 1)
  // when set, filled with the seconds of each stage: throw-away, sort by x,
  // split and flip-pop, output
  StageTimes* times = nullptr;
};

// stats, if given, is reset and filled: input_vertices, discarded_early (by
// the throw-away), polygon_vertices (the chains' polygon), flips_2_1, rounds
// (flip-pop passes), hull_vertices.
std::vector<Index> hull2_graham_sort(const PointSet& ps, const Hull2Options& opt = {}, ref::Hull2Stats* stats = nullptr);

// The same hull by parallel Graham-insertion (graham_insertion.hpp, thesis
// §4.3 Algorithm 4) on the throw-away's survivors: identical output. stats
// as above, plus insertions and insertion_rounds; discarded_early counts the
// points dropped by the throw-away and by the insertion rounds.
std::vector<Index> hull2_graham_insert(const PointSet& ps, const Hull2Options& opt = {}, ref::Hull2Stats* stats = nullptr);

}  // namespace flipflop::cpu

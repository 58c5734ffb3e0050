// hull3_stats.hpp — counts reported by the 3D hull algorithms (API and
// `flipflop hull3 --stats`). Every algorithm resets the fields it reports and
// leaves the others 0.
#pragma once

#include <cstdint>

namespace flipflop::ref {

struct Hull3Stats {
  // flip-flop (§6.2 Algorithm 6) and twist-flip's flipping stage
  std::uint64_t flips_2_2 = 0;        // 2-2 flips (edge flips)
  std::uint64_t flips_3_1 = 0;        // 3-1 flips (a vertex removed)
  std::uint64_t flips_1_3 = 0;        // 1-3 flips (a point inserted into a triangle)
  std::uint64_t labelled_non_extreme = 0;  // vertices labelled non-extreme (Lemma 6.5)
  // ffHull (§6.4 Algorithm 7)
  std::uint64_t discarded_early = 0;  // points removed as interior before insertion
  std::uint64_t insertions = 0;       // furthest-point insertions
  // star splaying (§3.3.2)
  std::uint64_t splay_insertions = 0;     // insertions of a vertex into a star
  std::uint64_t splay_removals = 0;       // vertices removed from a star
  std::uint64_t dead_stars = 0;           // stars of non-extreme points (death certificates)
  // twist-flip (§8.4.1 Algorithms 12 and 13)
  std::uint64_t twists = 0;           // twisting stage
  std::uint64_t fold_flips = 0;       // flipping stage (2-2 flips of folds)
  std::uint64_t rounds = 0;           // queue passes / rounds where the algorithm has them
  // the GPU ffHull (kernels_cuda/hull3): runs whose kernel point is the exact
  // centroid (an initial tetrahedron whose rounded centroid is not strictly
  // inside, §6.4.2), decided on the device by the exact expansion stage
  std::uint64_t exact_kernel_point = 0;
  // the GPU ffHull: runs that ran the reference's sequential rule for their
  // four initial points — work handed back to the host. Since the floating
  // keys' misses are repaired by exact reductions (kernels_cuda/spread.cuh),
  // the rule only runs to reject input that does not span R^3: a returned
  // hull counts 0, and the tests check that it does.
  std::uint64_t handed_back = 0;
};

}  // namespace flipflop::ref

// ghull.hpp — gHull for the 3D convex hull as a data-parallel (GPU) kernel:
// thesis ch. 7, the five stages of §7.1 with the implementation of §7.2.
//
// One algorithm source (ghull.cuh, with digital_voronoi.cuh for Stage 1 and
// the dual of Stage 2; thrust primitives over __host__ __device__ functors,
// cuda::atomic_ref), two builds, as hull3.hpp's ffHull:
//   flipflop::kernels_omp  — thrust's OpenMP backend (`--backend cuda-omp`);
//   flipflop::kernels_cuda — nvcc for sm_90 (`--backend cuda`).
//
// The answer is the canonical SoS hull, byte for byte the reference's
// (ref::hull3_ffhull(ps) == ref::hull3_splay(ps)). The digital stages (the
// restricted Voronoi diagram, the depth test) only decide where star splaying
// starts and which points it sees; every decision about the output is an exact
// SoS orient3d, and a point the digital depth test drops is verified exactly
// against the final hull (ghull.cuh, "Stage 6") — so no rounding in the
// digital space can change the answer.
//
// Errors: as hull3.hpp (std::invalid_argument for input that is not 3D, not
// finite or does not span R^3; kernels::DeviceMemoryError).
#pragma once

#include <cstdint>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/hull3/star_splaying.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels {

struct GhullOptions {
  // Stage 1's grid: each side of the box B has grid x grid pixels (0: chosen
  // from n, a power of two in [64, 1024]; the thesis uses 1024). At most 2048.
  std::uint32_t grid = 0;
  // Stage 4's depth maps: render x render pixels per side (0: grid / 2; the
  // thesis uses 512 with a 1024 grid).
  std::uint32_t render = 0;
  // Stage 1's Parallel Banding Algorithm: bands per column and row of a
  // side (0: grid / 32, one thread per 32 pixels of a line in each step).
  // Every count gives the same diagram; only the parallelism changes.
  std::uint32_t bands = 0;
  // The points are scaled into this fraction of B (§7.3.2, the slicing
  // problem's remedy; the thesis uses 0.8).
  double fill = 0.8;
  // For the tests of Stage 6 only: the depth test drops every point, so that
  // the points outside CH(S') reach the verification as misses.
  bool drop_all = false;
};

struct GhullStats {
  std::uint64_t grid = 0, render = 0;         // the sizes used
  std::uint64_t bands = 0;                    // Stage 1: PBA's bands per line used
  std::uint64_t captured = 0;                 // |S'|: points whose digital Voronoi cell meets B's boundary
  std::uint64_t working_pairs = 0;            // Stage 2: (point, neighbour) pairs of the dual
  std::uint64_t approx_vertices = 0;          // Stage 3: vertices of CH(S')
  std::uint64_t depth_candidates = 0;         // Stage 4: points the digital depth test keeps (Lemma 7.1)
  std::uint64_t added = 0;                    // Stage 4: candidates outside CH(S') (new stars)
  std::uint64_t depth_misses = 0;             // Stage 6: dropped points found outside the hull (re-added)
  std::uint64_t splay_rounds = 0;             // Algorithm 9 rounds, Stages 3 and 5 (and 6's re-runs)
  std::uint64_t splay_insertions = 0;         // successful insertions (Case 2)
  std::uint64_t dead_stars = 0;               // stars that died (Case 3) or were created dead
  std::uint64_t edge_list_growths = 0;        // Algorithm 9 lines 7-8
  // Work handed to the host or the reference: 1 when Stage 0 ran the
  // reference's sequential rule for its four spanning points, else 0. Since
  // the floating keys' misses are repaired by exact reductions (spread.cuh),
  // that rule only runs to reject input that does not span R^3, so a
  // returned hull counts 0; the counter stays as the check. Every stage runs
  // on the device otherwise; Stage 6 checks on the host the few triangles
  // its device filter leaves undecided for its inner ball and box (no point
  // is decided there).
  std::uint64_t handed_back = 0;
};

}  // namespace flipflop::kernels

namespace flipflop::kernels_omp {
std::vector<Triangle> hull3_ghull(const PointSet& ps, const kernels::GhullOptions& opt = {},
                                  kernels::GhullStats* stats = nullptr, cpu::StageTimes* times = nullptr);
}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {
std::vector<Triangle> hull3_ghull(const PointSet& ps, const kernels::GhullOptions& opt = {},
                                  kernels::GhullStats* stats = nullptr, cpu::StageTimes* times = nullptr);
}  // namespace flipflop::kernels_cuda

// The stages on their own, for the tests (OpenMP build only).
namespace flipflop::kernels_omp::ghull_stages {

// Stage 1 (§7.1, §7.2 "Voronoi Construction"). `scaled`: 3 doubles per point,
// the points in grid units, inside (0, grid)^3. Face f = 2 * axis + side is
// the plane X_axis = 0 (side 0) or X_axis = grid (side 1); its pixel (u, v)
// spans the other two axes in increasing order (axis 0: (1, 2); 1: (0, 2);
// 2: (0, 1)), u along the first; pixel index f * grid^2 + v * grid + u.
// Returns per pixel the label (a point index) of its nearest site, or ~0u
// where the face has no site at all; `sites` (optional) receives per pixel
// the point projected onto it (the one nearest the face, ties to the smaller
// index), or ~0u. Of several sites at the least distance, the label is the
// one whose pixel (u, v) is least, u first. `bands`: the Parallel Banding
// Algorithm's bands per column and row (0: the kernel's default, grid / 32;
// any count gives the same labels).
std::vector<std::uint32_t> digital_voronoi(const std::vector<double>& scaled, std::uint32_t grid,
                                           std::vector<std::uint32_t>* sites = nullptr, std::uint32_t bands = 0);

// The squared distance, in the exact integer units Stage 1 compares, from
// pixel `pixel` of face `face` to the site of point p (scaled as above).
std::int64_t site_distance(const std::vector<double>& scaled, std::uint32_t grid, std::uint32_t face,
                           std::uint32_t pixel, std::uint32_t p);

// Stage 2's dual: the working sets, as CSR over the n points: the neighbours
// of point p are nbr[off[p] .. off[p + 1]), ascending, without p; every pair
// of distinct labels meeting at a grid vertex of B's surface (3 or 4 labels
// at the vertex) is a pair both ways.
void working_sets(const std::vector<std::uint32_t>& labels, std::uint32_t grid, std::uint32_t n,
                  std::vector<std::uint32_t>& off, std::vector<std::uint32_t>& nbr);

// Stages 0-3 of hull3_ghull(ps, opt): the stars of S' as Stage 2 made them
// (apex, link or certificate: reference/hull3/star_splaying.hpp's Star), and
// the triangles of the alive stars after Stage 3 (CH(S'), canonical).
struct Approximation {
  std::vector<ref::Star> stars;
  std::vector<Triangle> hull;
};
Approximation approximation(const PointSet& ps, const kernels::GhullOptions& opt = {});

}  // namespace flipflop::kernels_omp::ghull_stages

// hull3.hpp — ffHull for the 3D convex hull as a data-parallel (GPU) kernel:
// thesis §6.4 Algorithm 7 in the round structure of §6.4.1, with the
// flip-flop of Algorithm 6 in parallel rounds (checking kernel, claims by
// atomic minimum, flipping kernel, §6.4.1 last paragraph).
//
// One algorithm source (hull3.cuh, thrust primitives over __host__ __device__
// functors), two builds:
//   flipflop::kernels_omp  — thrust's OpenMP backend, the host compiler
//                            (library flipflop_kernels_omp);
//   flipflop::kernels_cuda — thrust's CUDA backend, nvcc for sm_90 (library
//                            flipflop_kernels_cuda, only where nvcc exists).
//
// The answer is the reference's, byte for byte: ref::hull3_ffhull(ps) (the
// canonical SoS hull, DESIGN.md). Why any furthest-point choice, any initial
// tetrahedron and any order of flips give it: kernels_cpu/hull3/ffhull.hpp
// (Theorem 6.12 under the Simulation of Simplicity); why the parallel rounds
// are such an order: hull3.cuh, "flip-flop".
//
// Input that does not span R^3 (or has fewer than 4 points, or is not 3D) is
// rejected with the reference's std::invalid_argument. An input whose
// buffers do not fit in (device) memory: kernels::DeviceMemoryError.
//
// stats (reset, then filled): insertions (= flips_1_3), discarded_early,
// flips_2_2, flips_3_1, labelled_non_extreme, and rounds = construction
// rounds + flip-flop rounds. times: seconds per stage ("upload",
// "tetrahedron", "construction", "flip-flop", "output", "download").
#pragma once

#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels_omp {
std::vector<Triangle> hull3_ffhull(const PointSet& ps, ref::Hull3Stats* stats = nullptr,
                                   cpu::StageTimes* times = nullptr);
}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {
// Number of usable CUDA devices; 0 when there is none or no working driver.
int device_count();
std::vector<Triangle> hull3_ffhull(const PointSet& ps, ref::Hull3Stats* stats = nullptr,
                                   cpu::StageTimes* times = nullptr);
}  // namespace flipflop::kernels_cuda

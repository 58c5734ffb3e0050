// rt2.hpp — the GPU ffRT of thesis chapter 5 (§5.3 constructing stage in
// parallel insertion rounds, §5.1 Algorithm 5 flip-flop in parallel rounds,
// §5.4 "ffRT-GPU"): the regular (weighted Delaunay) triangulation of a planar
// point set, written once in thrust (rt2.cuh) and built twice:
//   flipflop::kernels_omp  — thrust's OpenMP backend, host compiler
//                            (library flipflop_kernels_omp);
//   flipflop::kernels_cuda — thrust's CUDA backend, nvcc for sm_90 (library
//                            flipflop_kernels_cuda).
//
// The answer is ref::rt2_ffrt(ps)'s, byte for byte: the canonical
// counter-clockwise real triangles (DESIGN.md) of THE regular triangulation
// under flipflop's Simulation of Simplicity — unique, so neither the order of
// insertions nor the order of flips can change it (rt2.cuh, "Why the answer
// is the reference's"). Weights from ps (0 when unweighted: Delaunay).
//
// Input that does not span the plane: the reference's std::invalid_argument
// (ref::require_plane, "rt2 (omp): <problem>" / "rt2 (cuda): <problem>").
// Input that cannot fit (device memory, or more points than 32-bit triangle
// ids reach): kernels::DeviceMemoryError with one line.
//
// stats (reset and filled when given): flips_1_3 (points inserted besides the
// initial three), flips_2_2, flips_3_1 (vertices removed), discarded_early
// (points a real triangle proved redundant before insertion, §5.3), rounds
// (insertion rounds), candidates (edges checked), labelled_redundant (vertices
// labelled by Algorithm 5 line 18). times (when given): seconds per stage —
// upload, sort, insertion rounds, flip-flop, output, download.
#pragma once

#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/point_set.hpp"
#include "reference/rt2/triangulation2.hpp"  // ref::Rt2Stats

namespace flipflop::kernels_omp {

std::vector<Triangle> rt2_ffrt(const PointSet& ps, ref::Rt2Stats* stats = nullptr, cpu::StageTimes* times = nullptr);

}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {

int device_count();  // classify_cuda.cu
std::vector<Triangle> rt2_ffrt(const PointSet& ps, ref::Rt2Stats* stats = nullptr, cpu::StageTimes* times = nullptr);

}  // namespace flipflop::kernels_cuda

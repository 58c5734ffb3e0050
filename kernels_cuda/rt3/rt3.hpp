// rt3.hpp — the GPU 3D regular (weighted Delaunay) triangulation, written
// once in thrust (rt3.cuh) and built twice:
//   flipflop::kernels_omp  — thrust's OpenMP backend, host compiler
//                            (library flipflop_kernels_omp; `--backend cuda-omp`);
//   flipflop::kernels_cuda — thrust's CUDA backend, nvcc for sm_90 (library
//                            flipflop_kernels_cuda; `--backend cuda`).
//
// The answer is kernels_cpu/rt3's and ref::rtd_incremental's (d = 3) byte for
// byte: the canonical tetrahedra (DESIGN.md) of THE regular triangulation
// under flipflop's Simulation of Simplicity, and the same redundant points —
// unique, so neither which points a round inserts nor in which order can
// change it (rt3.cuh, "Why the answer is the reference's"). Weights from ps
// (0 when unweighted: Delaunay).
//
// Input that is not 3D, not finite, or does not span R^3:
// std::invalid_argument, "rt3 (omp): <problem>" / "rt3 (cuda): <problem>"
// (reference/dimension.hpp's exact test, as kernels_cpu/rt3). Input that
// cannot fit (device memory, or more tetrahedra than 32-bit links reach):
// kernels::DeviceMemoryError with one line. The kernel never hands work
// back to the host or to the reference: every round, its exact second pass
// included, runs on the device (rt3.cuh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels_cpu/rt3/rt3.hpp"  // Rt3Result, Rt3Witness
#include "kernels_cpu/stage_times.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels {

// Counters of one run (reset and filled when asked for; --stats prints them).
struct Rt3GpuStats {
  std::uint64_t levels = 0;         // BRIO levels (samples of doubling size, located and inserted in turn)
  std::uint64_t rounds = 0;         // insertion rounds
  std::uint64_t inserted = 0;       // points made vertices (the first four included)
  std::uint64_t discarded = 0;      // points a real tetrahedron proved redundant when located (§5.3)
  std::uint64_t attempts = 0;       // cavities computed (one point per tetrahedron and round)
  std::uint64_t lost = 0;           // of those: a claim held by another insertion of the round, retried
  std::uint64_t overflowed = 0;     // of those: the cavity exceeded the round's per-insertion capacity, retried
  std::uint64_t exact_items = 0;    // items of the exact second passes (the filters could not decide them)
  std::uint64_t cavity_tets = 0;    // tetrahedra replaced by the insertions
  std::uint64_t created_tets = 0;   // tetrahedra created
  std::uint64_t slots = 0;          // tetrahedron slots used at the end
  std::uint64_t max_capacity = 0;   // the largest per-insertion cavity capacity a round used
};

// Tuning; the answer does not depend on it (tests vary it).
struct Rt3GpuOptions {
  // bytes of cavity scratch a round may use (the winners whose scratch fits
  // it take part, at least one); 0: max(64 MiB, 256 bytes per point)
  std::size_t scratch_bytes = 0;
};

}  // namespace flipflop::kernels

namespace flipflop::kernels_omp {

// witness, when given, receives the kernel's final extended triangulation in
// its own (Morton) order, the certificate cpu::certify_rt3 checks.
cpu::Rt3Result rt3(const PointSet& ps, kernels::Rt3GpuStats* stats = nullptr, cpu::StageTimes* times = nullptr,
                   cpu::Rt3Witness* witness = nullptr, const kernels::Rt3GpuOptions& opt = {});

}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {

cpu::Rt3Result rt3(const PointSet& ps, kernels::Rt3GpuStats* stats = nullptr, cpu::StageTimes* times = nullptr,
                   cpu::Rt3Witness* witness = nullptr, const kernels::Rt3GpuOptions& opt = {});

}  // namespace flipflop::kernels_cuda

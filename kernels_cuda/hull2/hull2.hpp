// hull2.hpp — the GPU 2D convex hull: parallel Graham's scan ("Graham-
// sorting", thesis §4.2 Algorithm 3, or "Graham-insertion", §4.3 Algorithm 4)
// with parallel flip-pop (§4.1 Algorithm 2)
// and the chunked local flipping of §4.2 (the shared-memory variant), written
// once as thrust steps over __host__ __device__ functors (hull2.cuh):
//
//   flipflop::kernels_omp::hull2_graham_sort   thrust's OpenMP backend, host
//                                              compiler (runs anywhere);
//   flipflop::kernels_cuda::hull2_graham_sort  thrust's CUDA backend, nvcc
//                                              for sm_90 (needs a device).
//
// The result is the canonical SoS hull (DESIGN.md): counter-clockwise from
// the smallest index — identical to ref::hull2(ps, "graham-sort") and to
// cpu::hull2_graham_sort. Input that does not span the plane is rejected with
// the reference's std::invalid_argument. kernels::DeviceMemoryError when the
// device buffers (about 40 bytes per point, sized once from n) cannot be had;
// kernels::NoDeviceError (CUDA build) without a usable device.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "kernels_cuda/kernel_errors.hpp"
#include "reference/hull2/polygon.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels {

struct Hull2GpuOptions {
  // Tuning; the result does not depend on them (the tests vary them):
  bool throw_away = true;     // drop points proved inside a polygon of input points first (hull2.cuh)
  std::size_t chunk = 256;    // vertices per chunk of the chunked flip-pop pass (>= 3)
  // when set, filled with the seconds of each stage: upload, throw-away, sort
  // by x, split, flip-pop, download (the transfers are the CUDA build's
  // host-device copies; ~0 in the OpenMP build, which reads in place)
  cpu::StageTimes* times = nullptr;
};

}  // namespace flipflop::kernels

namespace flipflop::kernels_omp {
// stats, if given, is reset and filled: input_vertices, discarded_early (by
// the throw-away), polygon_vertices, flips_2_1, rounds (flip-pop passes:
// chunked and labelled passes), hull_vertices.
std::vector<Index> hull2_graham_sort(const PointSet& ps, const kernels::Hull2GpuOptions& opt = {},
                                     ref::Hull2Stats* stats = nullptr);
// The same hull by Graham-insertion (Algorithm 4) on the throw-away's
// survivors; stats as above, plus insertions, insertion_rounds, and the points
// dropped by the insertion rounds counted in discarded_early.
std::vector<Index> hull2_graham_insert(const PointSet& ps, const kernels::Hull2GpuOptions& opt = {},
                                       ref::Hull2Stats* stats = nullptr);
}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {
int device_count();
std::vector<Index> hull2_graham_sort(const PointSet& ps, const kernels::Hull2GpuOptions& opt = {},
                                     ref::Hull2Stats* stats = nullptr);
std::vector<Index> hull2_graham_insert(const PointSet& ps, const kernels::Hull2GpuOptions& opt = {},
                                       ref::Hull2Stats* stats = nullptr);
}  // namespace flipflop::kernels_cuda

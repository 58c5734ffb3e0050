// gpu.hpp — one entry per problem for the two builds of the kernels_cuda/
// algorithms, by backend name, for the command line, the benchmark and the
// Python package:
//   "cuda-omp"  the OpenMP build (kernels_omp): runs on any multicore CPU;
//   "cuda"      the CUDA build (kernels_cuda, nvcc, sm_90) on the GPU;
//               kernels::NoDeviceError (one line) without a usable device or
//               in a flipflop built without nvcc.
// Anything else: std::invalid_argument.
#pragma once

#include <string>
#include <vector>

#include "kernels_cuda/hull2/hull2.hpp"
#include "kernels_cuda/hull3/hull3.hpp"
#include "kernels_cuda/kernel_errors.hpp"
#include "kernels_cuda/rt2/rt2.hpp"
#include "kernels_cuda/rt3/rt3.hpp"
#include "reference/hull2/polygon.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels {

// The backends whose kernels are built here ("cuda-omp", and "cuda" when nvcc
// built the CUDA library; "cuda" still needs a device at run time).
std::vector<std::string> gpu_backends_built();
bool is_gpu_backend(const std::string& backend);

// algo: "graham-sort" (Algorithm 3) or "graham-insert" (Algorithm 4)
std::vector<Index> hull2_gpu(const std::string& backend, const PointSet& ps, const Hull2GpuOptions& opt = {},
                             ref::Hull2Stats* stats = nullptr, const std::string& algo = "graham-sort");

// ffHull (§6.4): the 3D convex hull
std::vector<Triangle> hull3_gpu(const std::string& backend, const PointSet& ps, ref::Hull3Stats* stats = nullptr,
                                cpu::StageTimes* times = nullptr);

// ffRT (§5.3): the regular triangulation of ps (Delaunay when unweighted)
std::vector<Triangle> rt2_gpu(const std::string& backend, const PointSet& ps, ref::Rt2Stats* stats = nullptr,
                              cpu::StageTimes* times = nullptr);

// The 3D regular triangulation (Delaunay when unweighted), kernels_cuda/rt3;
// witness (when given): the certificate of cpu::certify_rt3
cpu::Rt3Result rt3_gpu(const std::string& backend, const PointSet& ps, Rt3GpuStats* stats = nullptr,
                       cpu::StageTimes* times = nullptr, cpu::Rt3Witness* witness = nullptr);

}  // namespace flipflop::kernels

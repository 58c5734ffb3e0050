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
#include <thread>
#include <vector>

#include "kernels_cuda/hull2/hull2.hpp"
#include "kernels_cuda/hull3/ghull.hpp"
#include "kernels_cuda/hull3/hull3.hpp"
#include "kernels_cuda/kernel_errors.hpp"
#include "kernels_cuda/rt2/rt2.hpp"
#include "kernels_cuda/rt3/rt3.hpp"
#include "reference/hull2/polygon.hpp"
#include "reference/point_set.hpp"

namespace flipflop::kernels_cuda {
void start_device();  // classify_cuda.cu: cudaFree(nullptr)
}  // namespace flipflop::kernels_cuda

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

// gHull (ch. 7): the 3D convex hull by star splaying from the digital
// restricted Voronoi diagram (kernels_cuda/hull3/ghull.hpp)
std::vector<Triangle> hull3_ghull_gpu(const std::string& backend, const PointSet& ps, const GhullOptions& opt = {},
                                     GhullStats* stats = nullptr, cpu::StageTimes* times = nullptr);

// ffRT (§5.3): the regular triangulation of ps (Delaunay when unweighted)
std::vector<Triangle> rt2_gpu(const std::string& backend, const PointSet& ps, ref::Rt2Stats* stats = nullptr,
                              cpu::StageTimes* times = nullptr);

// The CUDA driver's and context's start-up (0.3–0.45 s at a process's first
// GPU call, measured on H100/H200 machines), begun in a thread when the
// backend is "cuda" and this build has the CUDA kernels, so that it overlaps
// whatever the caller does before the kernel (the command line: reading the
// input); wait() joins it and returns its seconds (0 when none was begun). The
// kernel's first CUDA call waits for a start-up still under way, so wait()
// only moves that time to where it is reported.
class DeviceStart {
 public:
  explicit DeviceStart(const std::string& backend);
  ~DeviceStart();
  DeviceStart(const DeviceStart&) = delete;
  DeviceStart& operator=(const DeviceStart&) = delete;
  double wait();
  bool started() const { return started_; }

 private:
  std::thread thread_;
  double seconds_ = 0;
  bool started_ = false;
};

// The 3D regular triangulation (Delaunay when unweighted), kernels_cuda/rt3;
// witness (when given): the certificate of cpu::certify_rt3
cpu::Rt3Result rt3_gpu(const std::string& backend, const PointSet& ps, Rt3GpuStats* stats = nullptr,
                       cpu::StageTimes* times = nullptr, cpu::Rt3Witness* witness = nullptr);

}  // namespace flipflop::kernels

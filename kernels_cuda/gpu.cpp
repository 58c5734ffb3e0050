// gpu.cpp — the backend dispatch of gpu.hpp. FLIPFLOP_HAVE_KERNELS_CUDA is set
// (CMake) when the nvcc build, flipflop_kernels_cuda, is linked.
#include "kernels_cuda/gpu.hpp"

#include <chrono>
#include <stdexcept>

namespace flipflop::kernels {

namespace {

#ifndef FLIPFLOP_HAVE_KERNELS_CUDA
[[noreturn]] void no_cuda_build() {
  throw NoDeviceError("--backend cuda: this flipflop was built without the CUDA algorithm kernels (no nvcc, or "
                      "no GPU at configure time: -DFLIPFLOP_CUDA_ALGORITHMS=ON); use --backend cuda-omp or cpu");
}
#endif

template <class Omp, class Cuda>
auto dispatch(const std::string& backend, Omp&& omp, [[maybe_unused]] Cuda&& cuda) {
  if (backend == "cuda-omp") return omp();
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
  if (backend == "cuda") return cuda();
#else
  if (backend == "cuda") no_cuda_build();
#endif
  throw std::invalid_argument("unknown GPU backend '" + backend + "' (cuda, cuda-omp)");
}

}  // namespace

std::vector<std::string> gpu_backends_built() {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
  return {"cuda", "cuda-omp"};
#else
  return {"cuda-omp"};
#endif
}

bool is_gpu_backend(const std::string& backend) { return backend == "cuda" || backend == "cuda-omp"; }

DeviceStart::DeviceStart([[maybe_unused]] const std::string& backend) {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
  if (backend != "cuda") return;
  started_ = true;
  thread_ = std::thread([this] {
    const auto t0 = std::chrono::steady_clock::now();
    kernels_cuda::start_device();
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  });
#endif
}

DeviceStart::~DeviceStart() {
  if (thread_.joinable()) thread_.join();
}

double DeviceStart::wait() {
  if (thread_.joinable()) thread_.join();
  return seconds_;
}

std::vector<Index> hull2_gpu(const std::string& backend, const PointSet& ps, const Hull2GpuOptions& opt,
                             ref::Hull2Stats* stats, const std::string& algo) {
  if (algo != "graham-sort" && algo != "graham-insert")
    throw std::invalid_argument("the GPU 2D hull computes graham-sort and graham-insert, not '" + algo + "'");
  const bool insert = algo == "graham-insert";
  return dispatch(
      backend,
      [&] {
        return insert ? kernels_omp::hull2_graham_insert(ps, opt, stats) : kernels_omp::hull2_graham_sort(ps, opt, stats);
      },
      [&] {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
        return insert ? kernels_cuda::hull2_graham_insert(ps, opt, stats)
                      : kernels_cuda::hull2_graham_sort(ps, opt, stats);
#else
        return std::vector<Index>{};
#endif
      });
}

std::vector<Triangle> hull3_gpu(const std::string& backend, const PointSet& ps, ref::Hull3Stats* stats,
                                cpu::StageTimes* times) {
  return dispatch(
      backend, [&] { return kernels_omp::hull3_ffhull(ps, stats, times); },
      [&] {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
        return kernels_cuda::hull3_ffhull(ps, stats, times);
#else
        return std::vector<Triangle>{};
#endif
      });
}

std::vector<Triangle> hull3_ghull_gpu(const std::string& backend, const PointSet& ps, const GhullOptions& opt,
                                     GhullStats* stats, cpu::StageTimes* times) {
  return dispatch(
      backend, [&] { return kernels_omp::hull3_ghull(ps, opt, stats, times); },
      [&] {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
        return kernels_cuda::hull3_ghull(ps, opt, stats, times);
#else
        return std::vector<Triangle>{};
#endif
      });
}

std::vector<Triangle> rt2_gpu(const std::string& backend, const PointSet& ps, ref::Rt2Stats* stats,
                              cpu::StageTimes* times) {
  return dispatch(
      backend, [&] { return kernels_omp::rt2_ffrt(ps, stats, times); },
      [&] {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
        return kernels_cuda::rt2_ffrt(ps, stats, times);
#else
        return std::vector<Triangle>{};
#endif
      });
}

cpu::Rt3Result rt3_gpu(const std::string& backend, const PointSet& ps, Rt3GpuStats* stats, cpu::StageTimes* times,
                       cpu::Rt3Witness* witness) {
  return dispatch(
      backend, [&] { return kernels_omp::rt3(ps, stats, times, witness); },
      [&] {
#ifdef FLIPFLOP_HAVE_KERNELS_CUDA
        return kernels_cuda::rt3(ps, stats, times, witness);
#else
        return cpu::Rt3Result{};
#endif
      });
}

}  // namespace flipflop::kernels

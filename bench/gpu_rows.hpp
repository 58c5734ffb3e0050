// gpu_rows.hpp — the benchmark rows of the GPU backends built here
// (kernels::gpu_backends_built), for every `flipflop bench` kind that has a
// GPU kernel (bench_peers.cpp: hull2, hull3, rt2|dt2; bench_rt3.cpp: rt3|dt3).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bench/compare.hpp"
#include "kernels_cpu/stage_times.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif

namespace flipflop::bench::detail {

#ifdef FLIPFLOP_HAVE_KERNELS_GPU
// The rows of the GPU backends built here (kernels::gpu_backends_built):
// "flipflop:cuda-omp", and for the CUDA build "flipflop:cuda" (wall time,
// transfers included) and "flipflop:cuda:no-transfers" (the stages without
// the upload and download, as the thesis reports GPU times). `run(backend,
// times)` computes the canonical output and fills times when it is not null.
template <class Output, class Run>
void add_gpu_rows(std::vector<Peer<Output>>& rows, Run run, const std::string& suffix = "") {
  for (const std::string& b : kernels::gpu_backends_built()) {
    rows.push_back({"flipflop:" + b + suffix, [run, b](const PointSet&) { return run(b, nullptr); }});
    if (b != "cuda") continue;
    auto times = std::make_shared<cpu::StageTimes>();
    rows.push_back({"flipflop:cuda" + suffix + ":no-transfers",
                    [run, times](const PointSet&) {
                      *times = {};
                      return run("cuda", times.get());
                    },
                    [times] {
                      double t = 0;
                      for (const auto& [name, s] : times->stages)
                        if (name != "upload" && name != "download") t += s;
                      return t;
                    }});
  }
}
#endif

}  // namespace flipflop::bench::detail

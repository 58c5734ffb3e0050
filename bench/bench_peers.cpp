// bench_peers.cpp — `flipflop bench hull2|hull3|dt2|rt2`: flipflop's
// reference algorithms next to the peers a user would pick instead (DESIGN.md
// "Benchmarks"), side by side, in one process, on one generated input
// (gen/generate.hpp; generation not timed).
//
//   hull2  flipflop:cpu (kernels_cpu/hull2: throw-away and parallel
//          Graham-sorting, all cores), flipflop:cpu:graham-insert (the same
//          with parallel Graham-insertion), flipflop:reference:graham-sort and
//          :graham-insert; qhull (libqhull_r), cgal:ch_akl_toussaint,
//          cgal:ch_graham_andrew
//          flipflop:cuda-omp (kernels_cuda/hull2 in thrust's OpenMP build),
//          flipflop:cuda and flipflop:cuda:no-transfers (the CUDA build, with
//          and without the host-device copies; rows of a build with nvcc),
//          and the same rows with :graham-insert (Algorithm 4);
//   hull3  flipflop:cpu (kernels_cpu/hull3, multithreaded ffHull, all cores),
//          flipflop:reference:ffhull, :splay (:twist-flip, quadratic, for
//          n <= 20000); qhull (libqhull_r, Qt), cgal:convex_hull_3
//   dt2    flipflop:cpu (kernels_cpu/rt2: BRIO order, incremental flipping,
//          parallel sort and output), flipflop:territories and :batches
//          (the same with parallel insertion), flipflop:reference:ffrt and
//          :lawson;
//          cgal:delaunay_triangulation_2 (range insertion, spatially sorted),
//          qhull (libqhull_r, d Qbb Qt)
//          (hull3, dt2 and rt2: flipflop:cuda-omp, flipflop:cuda[:no-transfers],
//          the GPU ffHull and ffRT of kernels_cuda/hull3 and rt2, as for hull2)
//   rt2    flipflop:cpu, flipflop:territories, flipflop:batches,
//          flipflop:reference:ffrt;
//          cgal:regular_triangulation_2 (range insertion, spatially sorted)
//
// A timed run is one call: for a peer, the peers/ wrapper (copying the points
// into the peer's types, the peer's computation, and sorting its output into
// canonical order); for flipflop, the exact reference algorithm returning its
// canonical output (not certified inside the timing); flipflop:cpu likewise,
// with TBB's default number of threads (the machine's cores). The peers' canonical outputs are compared with each other and the
// result of that comparison is printed (in general position they must agree;
// on degenerate input each peer breaks ties its own way, and flipflop's
// algorithms agree with each other byte for byte).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/compare.hpp"
#include "bench/timing.hpp"
#include "gen/generate.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#include "bench/gpu_rows.hpp"
#endif
#include "peers/peers.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/rt2/rt2.hpp"

namespace flipflop::bench::detail {

namespace {


}  // namespace

PointSet generated_input(const Args& a) {
  const int need = a.experiment == "hull3" || a.experiment == "rt3" || a.experiment == "dt3" ? 3 : 2;
  if (gen::dimension_of(a.dist) != need)
    throw Usage("distribution '" + a.dist + "' is not " + std::to_string(need) + "D (" +
                a.experiment + ")");
  gen::Options o;
  o.seed = a.seed;
  o.thickness = a.thickness;
  o.weighted = a.weighted;
  o.wlo = a.wlo;
  o.whi = a.whi;
  o.hull_points = a.hull_points;
  return gen::generate(a.dist, a.n, o);
}

int bench_peers(const Args& a) {
  PointSet pts;
  const double gen_s = seconds([&] { pts = generated_input(a); });
  if (!a.csv) {
    std::printf("flipflop bench %s: dist %s, n %zu, seed %llu", a.experiment.c_str(), a.dist.c_str(),
                pts.size(), a.seed);
    if (a.weighted) std::printf(", weights in [%g, %g]", a.wlo, a.whi);
    std::printf(", median of %d runs (input generated in %.3f s, not timed)\n", a.reps, gen_s);
    std::printf("machine: %s\n", machine_line().c_str());
  }

  using Cycle = std::vector<Index>;
  using Tris = std::vector<Triangle>;
  if (a.experiment == "hull2") {
    std::vector<Peer<Cycle>> rows = {
        {"flipflop:cpu", [](const PointSet& p) { return cpu::hull2_graham_sort(p); }},
        {"flipflop:cpu:graham-insert", [](const PointSet& p) { return cpu::hull2_graham_insert(p); }}};
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    for (const char* algo : {"graham-sort", "graham-insert"})
      add_gpu_rows(
          rows,
          [&pts, algo](const std::string& b, cpu::StageTimes* t) {
            kernels::Hull2GpuOptions o;
            o.times = t;
            return kernels::hull2_gpu(b, pts, o, nullptr, algo);
          },
          std::string(algo) == "graham-insert" ? ":graham-insert" : "");
#endif
    rows.insert(rows.end(),
                {{"flipflop:reference:graham-sort", [](const PointSet& p) { return ref::hull2_graham_sort(p); }},
                 {"flipflop:reference:graham-insert", [](const PointSet& p) { return ref::hull2_graham_insert(p); }},
                 {"qhull", peers::qhull_hull2},
                 {"cgal:ch_akl_toussaint",
                  [](const PointSet& p) { return peers::cgal_hull2(p, peers::Hull2Algo::akl_toussaint); }},
                 {"cgal:ch_graham_andrew",
                  [](const PointSet& p) { return peers::cgal_hull2(p, peers::Hull2Algo::graham_andrew); }}});
    return compare_peers<Cycle>(a, pts, rows, "vertices");
  }
  if (a.experiment == "hull3") {
    std::vector<Peer<Tris>> rows = {{"flipflop:cpu", [](const PointSet& p) { return cpu::hull3_ffhull(p); }}};
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    add_gpu_rows(rows,
                 [&pts](const std::string& b, cpu::StageTimes* t) { return kernels::hull3_gpu(b, pts, nullptr, t); });
    // gHull (thesis ch. 7) beside the GPU ffHull, as §7.4 compares them
    add_gpu_rows(
        rows,
        [&pts](const std::string& b, cpu::StageTimes* t) { return kernels::hull3_ghull_gpu(b, pts, {}, nullptr, t); },
        ":ghull");
#endif
    rows.insert(rows.end(), {{"flipflop:reference:ffhull", [](const PointSet& p) { return ref::hull3(p, "ffhull"); }},
                             {"flipflop:reference:splay", [](const PointSet& p) { return ref::hull3(p, "splay"); }}});
    // twist-flip's twisting stage is a bubble sort (thesis Thm 8.1): O(n^2)
    if (pts.size() <= 20000)
      rows.push_back({"flipflop:reference:twist-flip", [](const PointSet& p) { return ref::hull3(p, "twist-flip"); }});
    rows.push_back({"qhull", peers::qhull_hull3});  // libqhull_r, Qt
    rows.push_back({"cgal:convex_hull_3", peers::cgal_hull3});
    return compare_peers<Tris>(a, pts, rows, "triangles");
  }
  std::vector<Peer<Tris>> rows = {{"flipflop:cpu", [](const PointSet& p) { return cpu::rt2(p); }}};
  // the cpu kernel with its parallel insertion (`--algo territories|batches`);
  // named so that the prefix flipflop:cpu does not select them
  for (const auto& [name, how] : {std::pair{"flipflop:territories", cpu::Rt2Options::Insertion::territories},
                                  std::pair{"flipflop:batches", cpu::Rt2Options::Insertion::batches}})
    rows.push_back({name, [how = how](const PointSet& p) {
                      cpu::Rt2Options o;
                      o.insertion = how;
                      return cpu::rt2(p, o);
                    }});
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  add_gpu_rows(rows, [&pts](const std::string& b, cpu::StageTimes* t) { return kernels::rt2_gpu(b, pts, nullptr, t); });
#endif
  rows.push_back({"flipflop:reference:ffrt", [](const PointSet& p) { return ref::rt2_ffrt(p); }});
  if (a.experiment == "dt2")
    rows.insert(rows.end(), {{"flipflop:reference:lawson", [](const PointSet& p) { return ref::dt2_lawson(p); }},
                             {"cgal:delaunay_triangulation_2", peers::cgal_delaunay2},
                             {"qhull", peers::qhull_delaunay2}});
  else
    rows.push_back({"cgal:regular_triangulation_2", [](const PointSet& p) { return peers::cgal_regular2(p); }});
  return compare_peers<Tris>(a, pts, rows, "triangles");
}

}  // namespace flipflop::bench::detail

// demo.cpp — `flipflop demo`: the main job on built-in generated data.
//
// For each job: generate the input (thesis distributions, §4.4, §5.4, §6.5),
// compute the answer with every program available, certify every answer
// exactly, and print the timings. A row is printed only for an answer that was
// computed and certified in this run. flipflop's rows are its sequential exact
// reference (thesis algorithms where they exist, the brute-force definition on
// small degenerate inputs otherwise), certified at the canonical level. The
// GPU kernels (kernels_cuda/) run as flipflop:cuda where this flipflop was
// built with them and a device is usable (else one line says why not), and
// always as flipflop:cuda-omp, the same kernels on thrust's OpenMP backend.
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "gen/generate.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif
#include "peers/peers.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/strict_rt2.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::cli {

namespace {
using Clock = std::chrono::steady_clock;

struct Row {
  std::string job, program;
  std::size_t n = 0, size = 0;
  double t_compute = 0, t_certify = 0;
  std::string verdict;
};

void print_row(const Row& r) {
  std::printf("%-30s %-32s %9zu %9zu %10.3f %10.3f  %s\n", r.job.c_str(), r.program.c_str(), r.n, r.size,
              r.t_compute, r.t_certify, r.verdict.c_str());
  std::fflush(stdout);
}

template <class Result>
bool run_one(const std::string& job, const std::string& program, const PointSet& ps,
             const std::function<Result()>& compute,
             const std::function<certify::Report(const Result&, certify::Level)>& check, certify::Level level) {
  Row row;
  row.job = job;
  row.program = program;
  row.n = ps.size();
  auto t0 = Clock::now();
  Result res = compute();
  row.t_compute = std::chrono::duration<double>(Clock::now() - t0).count();
  row.size = res.size();
  auto t1 = Clock::now();
  certify::Report rep = check(res, level);
  row.t_certify = std::chrono::duration<double>(Clock::now() - t1).count();
  row.verdict = rep.ok ? (level == certify::Level::canonical ? "certified (canonical)" : "certified (exact)")
                       : "NOT certified: " + rep.message();
  print_row(row);
  return rep.ok;
}

#ifdef FLIPFLOP_HAVE_KERNELS_GPU
// The GPU kernels' rows of a job: "cuda" (the device; a first call includes
// the CUDA context's start), then "cuda-omp". Without a usable device the
// cuda row is not printed; the reason is kept for one line at the end.
template <class Result>
bool run_gpu(const std::string& job, const std::string& algo, const PointSet& ps,
             const std::function<Result(const std::string&)>& compute,
             const std::function<certify::Report(const Result&, certify::Level)>& check, std::string& no_cuda) {
  bool ok = true;
  for (const std::string backend : {"cuda", "cuda-omp"}) {
    if (backend == "cuda" && !no_cuda.empty()) continue;
    try {
      ok &= run_one<Result>(job, "flipflop:" + backend + " (" + algo + ")", ps, [&] { return compute(backend); }, check,
                            certify::Level::canonical);
    } catch (const kernels::NoDeviceError& e) {
      no_cuda = e.what();
    }
  }
  return ok;
}
#endif

}  // namespace

int run_demo() {
  using certify::Level;
  bool all_ok = true;
  std::printf("flipflop demo: every answer below was computed in this run and checked by the exact certifier.\n");
  std::printf("Times in seconds (one run each; `flipflop bench` reports medians).\n\n");
  std::printf("%-30s %-32s %9s %9s %10s %10s  %s\n", "job", "program", "points", "size", "compute", "certify",
              "verdict");

  using Tris = std::vector<Triangle>;
  using Cycle = std::vector<Index>;
  std::string no_cuda;  // why flipflop:cuda did not run, when it did not
  auto h3 = [](const PointSet& ps) {
    return std::function<certify::Report(const Tris&, Level)>(
        [&ps](const Tris& t, Level l) { return certify::hull3(ps, t, l); });
  };
  auto h2 = [](const PointSet& ps) {
    return std::function<certify::Report(const Cycle&, Level)>(
        [&ps](const Cycle& c, Level l) { return certify::hull2(ps, c, l); });
  };
  auto r2 = [](const PointSet& ps) {
    return std::function<certify::Report(const Tris&, Level)>(
        [&ps](const Tris& t, Level l) { return certify::rt2(ps, t, l); });
  };

  // 3D hulls (thesis §6.5)
  for (auto [dist, n] : {std::pair<const char*, std::size_t>{"ball", 200000}, {"sphere", 100000}}) {
    gen::Options o;
    PointSet ps = gen::generate(dist, n, o);
    std::string job = std::string("hull3 ") + dist;
    all_ok &= run_one<Tris>(job, "flipflop:cpu (TBB ffHull)", ps, [&] { return cpu::hull3_ffhull(ps); }, h3(ps),
                            Level::canonical);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    all_ok &= run_gpu<Tris>(job, "GPU ffHull", ps,
                            [&](const std::string& b) { return kernels::hull3_gpu(b, ps); }, h3(ps), no_cuda);
#endif
    all_ok &= run_one<Tris>(job, "flipflop ffHull", ps, [&] { return ref::hull3(ps, "ffhull"); }, h3(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "flipflop star splaying", ps, [&] { return ref::hull3(ps, "splay"); }, h3(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "Qhull (qhull Qt)", ps, [&] { return peers::qhull_hull3(ps); }, h3(ps), Level::exact);
    all_ok &= run_one<Tris>(job, "CGAL convex_hull_3", ps, [&] { return peers::cgal_hull3(ps); }, h3(ps), Level::exact);
  }
  // 2D hulls (thesis §4.4)
  {
    gen::Options o;
    PointSet ps = gen::generate("disk", 1000000, o);
    all_ok &= run_one<Cycle>("hull2 disk", "flipflop:cpu (TBB Graham)", ps, [&] { return cpu::hull2_graham_sort(ps); },
                             h2(ps), Level::canonical);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    all_ok &= run_gpu<Cycle>("hull2 disk", "GPU Graham", ps,
                             [&](const std::string& b) { return kernels::hull2_gpu(b, ps); }, h2(ps), no_cuda);
#endif
    all_ok &= run_one<Cycle>("hull2 disk", "flipflop graham-insert", ps, [&] { return ref::hull2_graham_insert(ps); },
                             h2(ps), Level::canonical);
    all_ok &= run_one<Cycle>("hull2 disk", "flipflop graham-sort", ps, [&] { return ref::hull2_graham_sort(ps); },
                             h2(ps), Level::canonical);
    all_ok &= run_one<Cycle>("hull2 disk", "Qhull", ps, [&] { return peers::qhull_hull2(ps); }, h2(ps), Level::exact);
    all_ok &= run_one<Cycle>("hull2 disk", "CGAL ch_akl_toussaint", ps,
                             [&] { return peers::cgal_hull2(ps, peers::Hull2Algo::akl_toussaint); }, h2(ps),
                             Level::exact);
  }
  // 2D regular triangulation (thesis §5.4), weights in [0, 1e-5]
  {
    gen::Options o;
    o.weighted = true;
    o.wlo = 0;
    o.whi = 1e-5;
    PointSet ps = gen::generate("square", 100000, o);
    all_ok &= run_one<Tris>("rt2 square w[0,1e-5]", "flipflop:cpu (incremental)", ps, [&] { return cpu::rt2(ps); },
                            r2(ps), Level::canonical);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    all_ok &= run_gpu<Tris>("rt2 square w[0,1e-5]", "GPU ffRT", ps,
                            [&](const std::string& b) { return kernels::rt2_gpu(b, ps); }, r2(ps), no_cuda);
#endif
    all_ok &= run_one<Tris>("rt2 square w[0,1e-5]", "flipflop ffRT", ps, [&] { return ref::rt2_ffrt(ps); }, r2(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>("rt2 square w[0,1e-5]", "CGAL Regular_triangulation_2", ps,
                            [&] { return peers::cgal_regular2(ps); }, r2(ps), Level::exact);
  }
  // Degenerate input: flipflop's unique answer under Simulation of Simplicity
  // (exact brute-force reference, certified canonical), next to the peers'
  // answers (certified exact: correct, but each with its own tie-breaking).
  {
    gen::Options o;
    PointSet ps = gen::generate("sphere-lattice", 120, o);
    const std::string job = "hull3 cospherical lattice";
    all_ok &= run_one<Tris>(job, "flipflop ffHull", ps, [&] { return ref::hull3(ps, "ffhull"); }, h3(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "flipflop twist-flip", ps, [&] { return ref::hull3(ps, "twist-flip"); }, h3(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "flipflop reference (brute)", ps, [&] { return brute::hull3(ps); }, h3(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "Qhull (qhull Qt)", ps, [&] { return peers::qhull_hull3(ps); }, h3(ps), Level::exact);
    all_ok &= run_one<Tris>(job, "CGAL convex_hull_3", ps, [&] { return peers::cgal_hull3(ps); }, h3(ps), Level::exact);
  }
  {
    gen::Options o;
    PointSet ps = gen::generate("grid2", 144, o);
    const std::string job = "dt2 integer grid";
    all_ok &= run_one<Tris>(job, "flipflop:cpu (incremental)", ps, [&] { return cpu::rt2(ps); }, r2(ps),
                            Level::canonical);
    all_ok &= run_one<Tris>(job, "flipflop ffRT", ps, [&] { return ref::rt2_ffrt(ps); }, r2(ps), Level::canonical);
    all_ok &= run_one<Tris>(job, "flipflop Lawson", ps, [&] { return ref::dt2_lawson(ps); }, r2(ps), Level::canonical);
    // the strict view: no zero-area triangle (dt2 --strict), certified as such
    all_ok &= run_one<Tris>(
        job, "flipflop ffRT --strict", ps, [&] { return ref::strict_rt2(ps, ref::rt2_ffrt(ps)); },
        std::function<certify::Report(const Tris&, Level)>([&ps](const Tris& t, Level) {
          return certify::rt2_strict(ps, t);
        }),
        Level::exact);
    all_ok &= run_one<Tris>(job, "CGAL Delaunay_triangulation_2", ps, [&] { return peers::cgal_delaunay2(ps); },
                            r2(ps), Level::exact);
  }
  // 3D regular triangulation (thesis ch. 9): RT+1, then the monotonic instant
  // flip to new weights, certified against the definition (Thm 2.2).
  {
    gen::Options o;
    o.weighted = true;
    o.wlo = 0;
    o.whi = 1e-4;
    PointSet ps = gen::generate("cube", 20000, o);
    using Simplices = std::vector<std::vector<Index>>;
    auto rd = [](const PointSet& p) {
      return std::function<certify::Report(const Simplices&, Level)>(
          [&p](const Simplices& t, Level) { return certify::rtd(p, t); });
    };
    all_ok &= run_one<Simplices>("rtd d=3 cube w[0,1e-4]", "flipflop RT+1", ps,
                                 [&] { return ref::rtd_incremental(ps).simplices; }, rd(ps), Level::canonical);
    // From the Delaunay triangulation (weights W = 0: every point a vertex)
    // to the weights above (U): vertices that become redundant leave by
    // (d+1)-1 flips; the instant flip inserts none, and needs none here.
    PointSet p0 = ps;
    std::fill(p0.weights.begin(), p0.weights.end(), 0.0);
    all_ok &= run_one<Simplices>("rtd d=3 cube w=0 -> w[0,1e-4]", "flipflop instant flip", ps,
                                 [&] {
                                   ref::rtd::TriangulationD T = ref::build_rtd(p0);
                                   ref::instant_flip(T, p0.weights.to_vector(), ps.weights.to_vector());
                                   return ref::rtd::real_simplices(T);
                                 },
                                 rd(ps), Level::canonical);
  }
  if (!no_cuda.empty()) std::printf("\nflipflop:cuda not run: %s\n", no_cuda.c_str());
  std::printf("\n%s\n", all_ok ? "all answers certified" : "SOME ANSWERS WERE NOT CERTIFIED (see above)");
  return all_ok ? 0 : 1;
}

}  // namespace flipflop::cli

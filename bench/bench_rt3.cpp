// bench_rt3.cpp — `flipflop bench rt3|dt3`: the 3D regular / Delaunay
// triangulation, flipflop's multithreaded kernel and its reference next to
// the triangulators a user would pick instead (DESIGN.md "Benchmarks"), in one
// process on one generated input (gen/generate.hpp; generation not timed).
//
// Rows (a timed run is one call returning the canonical tetrahedron list,
// reference/rtd/canonical_d.hpp: for a peer the peers/ wrapper — copying the
// points into its types, its construction, its tetrahedra oriented and put in
// canonical order, peers/triangulation3.hpp):
//   flipflop:cpu                         cpu::rt3 (kernels_cpu/rt3), --threads
//                                        threads (default: the machine's cores)
//   flipflop:cuda-omp, flipflop:cuda, flipflop:cuda:no-transfers
//                                        kernels_cuda/rt3 in thrust's OpenMP
//                                        build, and the CUDA build where nvcc
//                                        built it (bench/gpu_rows.hpp)
//   flipflop:reference                   ref::rtd_incremental with d = 3
//                                        (Edelsbrunner–Shah's RT+1, exact,
//                                        sequential), for n <= kReferenceLimit
//                                        only (a note says when it is skipped)
//   cgal:delaunay_triangulation_3        (dt3) Epick, range insertion of
//                                        (point, index) pairs (spatially sorted)
//   cgal:delaunay_triangulation_3:parallel  (dt3) the same with Parallel_tag: a
//                                        lock grid over the bounding box, TBB
//                                        insertion on --threads threads
//   cgal:regular_triangulation_3         Regular_triangulation_3, the same way
//   cgal:regular_triangulation_3:parallel  (for dt3 with zero weights)
//   qhull                                (dt3) libqhull_r "d Qt Qbb" (scipy's
//                                        engine and options)
//   tetgen                               (dt3) TetGen 1.5 tetrahedralize "Q",
//                                        where the build found libtet
// `identical` (CSV) / the closing line (table): each row's tetrahedra
// compared with the first row's (flipflop:cpu's unless --run leaves it out),
// as for the other kinds: the reference row's 1 is the kernel's agreement with
// the reference. On input in general position (the random families: cube,
// ball, box, sphere, cball) every row must agree; on the degenerate families
// (grids, lattices, planes3, duplicates, ...) each peer breaks ties its own
// way and a note says so.
//
// `flipflop bench rt3|dt3 --stages`: bench_stages.cpp.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/compare.hpp"
#include "bench/gpu_rows.hpp"
#include "bench/timing.hpp"
#include "io/read_points.hpp"
#include "io/write_points.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#include "peers/triangulation3.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::bench::detail {

namespace {

using Tets = std::vector<cpu::Tet>;

// The reference (exact staged predicates, sequential, on its general
// d-dimensional structure) runs up to this many points: 1.7 s for 20000
// uniform points on the quiet 2-core development VM; larger inputs would
// dominate the benchmark.
constexpr std::size_t kReferenceLimit = 20000;

bool general_position_family(const std::string& dist) {
  for (const char* d : {"cube", "ball", "box", "sphere", "cball"})
    if (dist == d) return true;
  return false;
}

Tets as_tets(const std::vector<std::vector<Index>>& s) {
  Tets out(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) std::copy(s[i].begin(), s[i].end(), out[i].begin());
  return out;
}

}  // namespace

// The machine, as one line (timing.hpp): CPU model, logical processors,
// data cache sizes, load average.
std::string machine_line() {
  std::string model = "unknown CPU";
  int cpus = 0;
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    ++cpus;
    const auto colon = line.find(':');
    if (colon != std::string::npos) model = line.substr(colon + 2);
  }
  std::string load = "?";
  std::ifstream avg("/proc/loadavg");
  if (avg) {
    std::string one, five, fifteen;
    avg >> one >> five >> fifteen;
    load = one + " " + five + " " + fifteen;
  }
  // the data caches of CPU 0 as the kernel reports them (L1d, L2, L3: the
  // sizes another machine of the same kind most often differs in)
  std::string caches;
  for (int i = 0; i < 8; ++i) {
    const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/";
    std::ifstream level(dir + "level"), type(dir + "type"), size(dir + "size");
    std::string l, t, z;
    if (!(level >> l) || !(type >> t) || !(size >> z)) break;
    if (t == "Instruction") continue;
    caches += std::string(caches.empty() ? "" : " ") + "L" + l + (t == "Data" ? "d" : "") + " " + z;
  }
  return model + ", " + std::to_string(cpus) + " logical processors" + (caches.empty() ? "" : ", caches " + caches) +
         ", load average " + load;
}

int bench_rt3(const Args& a) {
  PointSet pts;
  const double gen_s = seconds([&] { pts = generated_input(a); });
  const bool dt = a.experiment == "dt3";
  const bool general = general_position_family(a.dist);
  const int threads = a.threads;
  std::string note;
  if (!general)
    note = "note: " + a.dist +
           " is a degenerate family (coplanar / cospherical points, duplicates): each peer breaks ties its own way, "
           "so a peer's identical = 0 is expected; flipflop's rows must still agree";
  if (pts.size() > kReferenceLimit && chosen(a, "flipflop:reference"))
    note += std::string(note.empty() ? "" : "\n") + "note: flipflop:reference skipped: n = " +
            std::to_string(pts.size()) + " > " + std::to_string(kReferenceLimit) +
            " (exact sequential reference; bench it with a smaller --n)";
  if (!a.csv) {
    std::printf("flipflop bench %s: dist %s, n %zu, seed %llu", a.experiment.c_str(), a.dist.c_str(), pts.size(),
                a.seed);
    if (a.weighted) std::printf(", weights in [%g, %g]", a.wlo, a.whi);
    std::printf(", median of %d runs (input generated in %.3f s, not timed), %s threads\n", a.reps, gen_s,
                threads > 0 ? std::to_string(threads).c_str() : "all");
    std::printf("machine: %s\n", machine_line().c_str());
  }

  std::vector<Peer<Tets>> rows;
  auto redundant = std::make_shared<long long>(-1);  // flipflop:cpu's count of redundant points
  rows.push_back({"flipflop:cpu", [threads, redundant](const PointSet& p) {
                    cpu::Rt3Options o;
                    o.threads = threads;
                    cpu::Rt3Result r = cpu::rt3(p, o);
                    *redundant = static_cast<long long>(r.redundant.size());
                    return std::move(r.tets);
                  }});
  if (pts.size() <= kReferenceLimit)
    rows.push_back({"flipflop:reference", [](const PointSet& p) { return as_tets(ref::rtd_incremental(p).simplices); }});
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  add_gpu_rows(rows, [&pts](const std::string& b, cpu::StageTimes* t) { return kernels::rt3_gpu(b, pts, nullptr, t).tets; });
#endif
  if (dt) {
    rows.push_back({"cgal:delaunay_triangulation_3", [](const PointSet& p) { return peers::cgal_delaunay3(p); }});
    rows.push_back({"cgal:delaunay_triangulation_3:parallel", [threads](const PointSet& p) {
                      peers::Cgal3Options o;
                      o.parallel = true;
                      o.threads = threads;  // 0: TBB's default, all cores
                      return peers::cgal_delaunay3(p, o);
                    }});
  }
  rows.push_back({"cgal:regular_triangulation_3", [](const PointSet& p) { return peers::cgal_regular3(p); }});
  rows.push_back({"cgal:regular_triangulation_3:parallel", [threads](const PointSet& p) {
                    peers::Cgal3Options o;
                    o.parallel = true;
                    o.threads = threads;
                    return peers::cgal_regular3(p, o);
                  }});
  if (dt) {
    rows.push_back({"qhull", [](const PointSet& p) { return peers::qhull_delaunay3(p); }});
    if (peers::tetgen_available())
      rows.push_back({"tetgen", [](const PointSet& p) { return peers::tetgen_delaunay3(p); }});
    else if (chosen(a, "tetgen"))
      note += std::string(note.empty() ? "" : "\n") + "note: tetgen: not in this build (Debian: libtet1.5-dev)";
  }
  if (!note.empty() && !a.csv) std::printf("%s\n", note.c_str());
  const int rc = compare_peers<Tets>(a, pts, rows, "tetrahedra", /*memory=*/!a.csv);
  if (!note.empty() && a.csv) std::fprintf(stderr, "%s\n", note.c_str());  // the CSV on stdout stays plain
  if (!a.csv && *redundant >= 0)
    std::printf("redundant points (flipflop:cpu): %lld of %zu (%.1f %%)\n", *redundant, pts.size(),
                100.0 * static_cast<double>(*redundant) / static_cast<double>(pts.size()));
  return rc;
}

}  // namespace flipflop::bench::detail

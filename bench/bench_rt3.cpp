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
//   flipflop bench rt3|dt3 --stages   a whole `flipflop rt3|dt3` run by stage on
//                                     flipflop:cpu: read .xyz / .npy, the
//                                     kernel's stages (Rt3Options::times), the
//                                     witness-checked certificate
//                                     (cpu::certify_rt3), write.
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

// The tetrahedra, "a b c d\n" per line (canonical_d.hpp's text format).
void write_tets(const std::string& path, const Tets& tets) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("bench --stages: cannot write " + path);
  std::vector<char> buf(1 << 16);
  std::size_t at = 0;
  for (const cpu::Tet& t : tets) {
    if (at + 48 > buf.size()) {
      std::fwrite(buf.data(), 1, at, f);
      at = 0;
    }
    at += static_cast<std::size_t>(std::snprintf(buf.data() + at, 48, "%u %u %u %u\n", t[0], t[1], t[2], t[3]));
  }
  std::fwrite(buf.data(), 1, at, f);
  std::fclose(f);
}

}  // namespace

// The machine, as one line: CPU model, logical processors, load average.
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
  return model + ", " + std::to_string(cpus) + " logical processors, load average " + load;
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

int bench_rt3_stages(const Args& a) {
  const PointSet pts = generated_input(a);
  const auto dir = std::filesystem::temp_directory_path() / ("flipflop-bench-rt3-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  struct Cleanup {
    std::filesystem::path d;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(d, ec);
    }
  } cleanup{dir};
  const std::string xyz = (dir / "in.xyz").string(), npy = (dir / "in.npy").string(), out = (dir / "out.txt").string();
  io::write_file(xyz, [&](std::ostream& os) { io::write_points(os, pts); });
  io::write_file(npy, [&](std::ostream& os) { io::write_points_npy(os, pts); });

  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> times;
  auto add = [&](const std::string& name, double s) {
    if (!times.count(name)) order.push_back(name);
    times[name].push_back(s);
  };
  std::size_t size = 0;
  for (int r = 0; r < a.reps; ++r) {
    double total = 0;
    PointSet in;
    add("read .xyz", seconds([&] { in = io::read_points(xyz, pts.dim, pts.weighted); }));
    if (!same_bits(in.coords, pts.coords) || !same_bits(in.weights, pts.weights))
      throw std::runtime_error("bench --stages: .xyz read back differs");
    double t = seconds([&] { in = io::read_points(npy, pts.dim, pts.weighted); });
    add("read .npy", t);
    total += t;
    if (!same_bits(in.coords, pts.coords) || !same_bits(in.weights, pts.weights))
      throw std::runtime_error("bench --stages: .npy read back differs");
    cpu::StageTimes st;
    cpu::Rt3Options o;
    o.threads = a.threads;
    o.times = &st;
    cpu::Rt3Witness witness;
    cpu::Rt3Result res;
    t = seconds([&] { res = cpu::rt3(in, o, nullptr, &witness); });
    total += t;
    size = res.tets.size();
    for (const auto& [name, s] : st.stages) add("compute: " + name, s);
    certify::Report rep;
    t = seconds([&] { rep = cpu::certify_rt3(in, witness, res.tets, certify::Level::canonical, a.threads); });
    if (!rep.ok) throw std::runtime_error("bench --stages: the result failed certification: " + rep.message());
    add("certify", t);
    total += t;
    t = seconds([&] { write_tets(out, res.tets); });
    add("write", t);
    total += t;
    add("total (.npy)", total);
  }
  if (a.csv) {
    std::printf("stage,median_s,min_s,max_s,size\n");
    for (const std::string& name : order) {
      const auto [lo, hi] = std::minmax_element(times[name].begin(), times[name].end());
      std::printf("%s,%.6f,%.6f,%.6f,%zu\n", name.c_str(), median(times[name]), *lo, *hi, size);
    }
    return 0;
  }
  std::printf("flipflop bench %s --stages: dist %s, n %zu, seed %llu, median of %d runs, flipflop:cpu, %zu tetrahedra\n",
              a.experiment.c_str(), a.dist.c_str(), pts.size(), a.seed, a.reps, size);
  std::printf("machine: %s\n", machine_line().c_str());
  const double total = median(times["total (.npy)"]);
  std::printf("%-46s %12s %12s %12s %8s\n", "stage", "median s", "min s", "max s", "share");
  for (const std::string& name : order) {
    const auto [lo, hi] = std::minmax_element(times[name].begin(), times[name].end());
    std::printf("%-46s %12.4f %12.4f %12.4f", name.c_str(), median(times[name]), *lo, *hi);
    if (name != "read .xyz") std::printf(" %7.1f%%", 100.0 * median(times[name]) / total);
    std::printf("\n");
  }
  return 0;
}

}  // namespace flipflop::bench::detail

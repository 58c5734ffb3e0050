// bench_stages.cpp — `flipflop bench hull2|hull3|rt2|dt2|rt3|dt3 --stages`:
// where the time of a whole `flipflop hull2|...|dt3` run on the multithreaded
// backend goes, stage by stage, each the median of --reps runs:
//
//   read .xyz / read .npy   the generated input written to a temporary file
//                           once (not timed), then read back by io::read_points
//                           (parallel text parser / one-copy binary reader);
//                           the points read must equal the generated ones bit
//                           for bit;
//   the kernel's stages     cpu::Hull2Options::times / Hull3Options::times /
//                           Rt2Options::times / Rt3Options::times
//                           (throw-away, sort, flip-pop; initial tetrahedron,
//                           construction rounds, flip-flop; BRIO sort,
//                           insertion, output; the canonical output);
//   certify                 cpu::certify_hull2 / cpu::certify_hull3_witnessed
//                           / cpu::certify_rt2 / cpu::certify_rt3 (hull3 and
//                           the triangulations: with the kernel's witness)
//                           at the canonical level (must
//                           pass); for hull3 also the witness-free
//                           cpu::certify_hull3 on the same output (what
//                           `flipflop certify hull3` runs; a peer row, not in
//                           the total);
//   write                   the index text to a temporary file.
// rt3|dt3's kernel and certifier run on --threads threads (default: all).
//
// The last row, "total (.npy)", is read .npy + compute + certify + write of
// each run (median over runs), what `flipflop hull3 in.npy -o out` spends
// outside process start-up.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/timing.hpp"
#include "io/index_io.hpp"
#include "io/read_points.hpp"
#include "io/write_points.hpp"
#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/certify_rt2.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"

namespace flipflop::bench::detail {

namespace {

// A temporary directory removed at the end of the benchmark.
struct TempDir {
  std::filesystem::path dir;
  TempDir() {
    dir = std::filesystem::temp_directory_path() / ("flipflop-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

}  // namespace

constexpr const char* kWitnessFree = "certify without witness (not in the total)";

int bench_stages(const Args& a) {
  const bool h3 = a.experiment == "hull3", tri = a.experiment == "rt2" || a.experiment == "dt2",
             tet = a.experiment == "rt3" || a.experiment == "dt3";
  const PointSet pts = generated_input(a);
  TempDir tmp;
  const std::string xyz = (tmp.dir / "in.xyz").string(), npy = (tmp.dir / "in.npy").string(),
                    out = (tmp.dir / "out.txt").string();
  io::write_file(xyz, [&](std::ostream& os) { io::write_points(os, pts); });
  io::write_file(npy, [&](std::ostream& os) { io::write_points_npy(os, pts); });

  std::vector<std::string> order;  // stage names in first-seen order
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
    std::vector<Index> cycle;
    std::vector<Triangle> tris;
    cpu::Hull3Witness witness;
    cpu::Rt2Witness rt2_witness;  // rt2|dt2: certified from the kernel's witness, as `flipflop rt2|dt2` does
    cpu::Rt3Witness rt3_witness;  // rt3|dt3: likewise
    cpu::Rt3Result rt3_result;
    if (tet) {
      cpu::Rt3Options o;
      o.threads = a.threads;
      o.times = &st;
      t = seconds([&] { rt3_result = cpu::rt3(in, o, nullptr, &rt3_witness); });
      size = rt3_result.tets.size();
    } else if (tri) {
      cpu::Rt2Options o;
      o.times = &st;
      t = seconds([&] { tris = cpu::rt2(in, o, nullptr, &rt2_witness); });
      size = tris.size();
    } else if (h3) {
      cpu::Hull3Options o;
      o.times = &st;
      o.witness = &witness;
      t = seconds([&] { tris = cpu::hull3_ffhull(in, o); });
      size = tris.size();
    } else {
      cpu::Hull2Options o;
      o.times = &st;
      t = seconds([&] { cycle = cpu::hull2_graham_sort(in, o); });
      size = cycle.size();
    }
    total += t;
    for (const auto& [name, s] : st.stages) add("compute: " + name, s);
    certify::Report rep;
    t = seconds([&] {
      rep = tet  ? cpu::certify_rt3(in, rt3_witness, rt3_result.tets, certify::Level::canonical, a.threads)
            : tri ? cpu::certify_rt2(in, tris, certify::Level::canonical, rt2_witness)
            : h3 ? cpu::certify_hull3_witnessed(in, tris, certify::Level::canonical, witness)
                 : cpu::certify_hull2(in, cycle, certify::Level::canonical);
    });
    if (!rep.ok) throw std::runtime_error("bench --stages: the result failed certification: " + rep.message());
    add("certify", t);
    total += t;
    if (h3) {
      add(kWitnessFree, seconds([&] { rep = cpu::certify_hull3(in, tris, certify::Level::canonical); }));
      if (!rep.ok) throw std::runtime_error("bench --stages: the result failed certification: " + rep.message());
    }
    t = seconds([&] {
      io::write_file(out, [&](std::ostream& os) {
        tet              ? io::write_tetrahedra(os, rt3_result.tets)
        : h3 || tri      ? io::write_triangles(os, tris)
                         : io::write_hull2(os, cycle);
      });
    });
    add("write", t);
    total += t;
    add("total (.npy)", total);
  }
  if (a.csv) {
    std::printf("stage,median_s,min_s,max_s,size\n");
    for (const std::string& name : order) {
      const auto [lo, hi] = std::minmax_element(times[name].begin(), times[name].end());
      // RFC 4180: a name with a comma is quoted (hull3's first stage has two)
      std::string field = name;
      if (name.find_first_of(",\"") != std::string::npos) {
        field = "\"";
        for (char c : name) field += c == '"' ? std::string("\"\"") : std::string(1, c);
        field += '"';
      }
      std::printf("%s,%.6f,%.6f,%.6f,%zu\n", field.c_str(), median(times[name]), *lo, *hi, size);
    }
    return 0;
  }
  std::printf("flipflop bench %s --stages: dist %s, n %zu, seed %llu, median of %d runs, flipflop:cpu, %zu %s\n",
              a.experiment.c_str(), a.dist.c_str(), pts.size(), a.seed, a.reps, size,
              tet ? "tetrahedra" : h3 || tri ? "triangles" : "vertices");
  std::printf("machine: %s\n", machine_line().c_str());
  const double total = median(times["total (.npy)"]);
  std::printf("%-46s %12s %12s %12s %8s\n", "stage", "median s", "min s", "max s", "share");
  for (const std::string& name : order) {
    const auto [lo, hi] = std::minmax_element(times[name].begin(), times[name].end());
    const bool in_total = name != "read .xyz" && name != kWitnessFree && name.rfind("compute: ", 0) != 0;
    std::printf("%-46s %12.4f %12.4f %12.4f", name.c_str(), median(times[name]), *lo, *hi);
    if (name.rfind("compute: ", 0) == 0 || in_total) std::printf(" %7.1f%%", 100.0 * median(times[name]) / total);
    std::printf("\n");
  }
  return 0;
}

}  // namespace flipflop::bench::detail

// rt3_commands.cpp — `flipflop rt3|dt3` and `flipflop rtd --dim 3` (see the header).
#include "cli/rt3_commands.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/rtd_commands.hpp"
#include "io/index_io.hpp"
#include "io/input_error.hpp"
#include "io/read_points.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/strict_rtd.hpp"

namespace flipflop::cli {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

using Tets = std::vector<cpu::Tet>;

Tets as_tets(const std::vector<std::vector<Index>>& simplices) {
  Tets t;
  t.reserve(simplices.size());
  for (const auto& s : simplices) t.push_back({s.at(0), s.at(1), s.at(2), s.at(3)});
  return t;
}

std::vector<std::vector<Index>> as_cells(const Tets& tets) {
  std::vector<std::vector<Index>> c;
  c.reserve(tets.size());
  for (const cpu::Tet& t : tets) c.push_back({t[0], t[1], t[2], t[3]});
  return c;
}

// Tetrahedra fit the index text, .vtu and .npy; any other format is refused
// here, before the work, with io::write_cells' own message (it refuses a
// format that cannot hold 3-simplices before it writes anything).
void refuse_formats_without_tetrahedra(const std::string& path, io::Format f) {
  if (f == io::Format::index || f == io::Format::vtu || f == io::Format::npy) return;
  PointSet none;
  none.dim = 3;
  write_result_file(path, f, [](std::ostream&) {}, none, {}, io::CellKind::simplices, {}, false);
  throw UsageError(path + ": " + io::format_name(f) + " cannot hold tetrahedra (.vtu, .txt, .idx or .npy)");
}

std::string threads_note(const std::string& backend, int threads) {
  return backend == "cpu" && threads ? " (" + std::to_string(threads) + " threads)" : std::string();
}

}  // namespace

int run_rt3(const Rt3Args& a) {
  const std::string& kind = a.kind;
  const bool weighted = kind != "dt3";
  const std::string backend = a.backend.empty() ? "cpu" : a.backend;
  const bool gpu = backend == "cuda" || backend == "cuda-omp";
  if (backend != "cpu" && backend != "reference" && !gpu)
    throw UsageError(kind + " backends: cpu (kernels_cpu/rt3, the default), reference, cuda and cuda-omp; got '" +
                     backend + "'");
  if (a.threads < 0) throw UsageError("--threads must be positive, got " + std::to_string(a.threads));
  if (a.threads != 0 && backend != "cpu")
    throw UsageError("--threads applies to the multithreaded backend (--backend cpu), not '" + backend + "'");
#ifndef FLIPFLOP_HAVE_KERNELS_GPU
  if (gpu)
    throw UsageError("--backend " + backend + ": this flipflop was built without the GPU kernels (kernels_cuda/: "
                     "thrust headers and OpenMP)");
#endif
  const io::Format fmt = output_format_of(a.out);  // an unknown extension fails before any work
  refuse_formats_without_tetrahedra(a.out, fmt);

#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  // --backend cuda: the CUDA start-up in a thread while the input is read (issue 36 item 4)
  kernels::DeviceStart device(backend);
#endif
  std::optional<Progress> progress(std::in_place, Progress::stderr_is_terminal(), "flipflop " + kind);
  progress->stage("reading " + a.in);
  const auto t_read0 = Clock::now();
  PointSet ps;
  try {
    // x y z w (rt3, rtd --dim 3) or x y z (dt3); .xyz, .npy, .off, .ply
    ps = io::read_points(a.in, 3, weighted);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  if (std::string why = dimension_problem(ps); !why.empty()) throw UsageError(a.in + ": " + why);
  const double t_read = seconds_since(t_read0);

  double t_device = 0;  // the CUDA start-up, overlapped with the reading
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  t_device = device.wait();
#endif
  // ---- the canonical answer, certified -------------------------------------------
  progress->stage("computing (" + std::to_string(ps.size()) + " points, backend " + backend + ")");
  const auto t0 = Clock::now();
  // a lattice up to one exact common factor (steps of 0.5, 0.25, ...) runs
  // as that small-integer lattice: the same index answer, by the argument of
  // reference/lattice_quotient.hpp; `ps` stays for the output's coordinates,
  // and the reference backend reads the values as given
  const std::optional<LatticeQuotient> quotient = backend != "reference" ? lattice_quotient(ps) : std::nullopt;
  const PointSet& pk = quotient ? quotient->points : ps;
  Tets tets;
  std::vector<Index> redundant;
  cpu::Rt3Stats kst;
  cpu::StageTimes stages;
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  kernels::Rt3GpuStats gst;
#endif
  ref::RtdStats rst;
  std::string certified_by;
  double t_compute = 0, t_certify = 0;
  try {
    if (gpu) {
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
      // kernels_cuda/rt3: insertion rounds on the device, and the witness
      // the cpu kernel's certifier checks
      auto witness = std::make_unique<cpu::Rt3Witness>();
      cpu::Rt3Result r = kernels::rt3_gpu(backend, pk, &gst, &stages, witness.get());
      t_compute = seconds_since(t0);
      progress->stage("certifying");
      const auto t1 = Clock::now();
      const certify::Report rep = cpu::certify_rt3(pk, *witness, r.tets, certify::Level::canonical);
      t_certify = seconds_since(t1);
      witness.reset();
      if (rep.condition == "input-dimension") throw UsageError(a.in + ": " + rep.detail);
      if (!rep.ok) throw InternalError("the " + kind + " result failed certification: " + rep.message());
      tets = std::move(r.tets);
      redundant = std::move(r.redundant);
      certified_by = "canonical, cpu::certify_rt3 from the kernel's witness";
#endif
    } else if (backend == "cpu") {
      // kernels_cpu/rt3: BRIO order, incremental insertion, parallel output,
      // and the witness its certifier checks
      cpu::Rt3Options o;
      o.threads = a.threads;
      o.times = &stages;
      auto witness = std::make_unique<cpu::Rt3Witness>();
      cpu::Rt3Result r = cpu::rt3(pk, o, &kst, witness.get());
      t_compute = seconds_since(t0);
      progress->stage("certifying");
      const auto t1 = Clock::now();
      const certify::Report rep = cpu::certify_rt3(pk, *witness, r.tets, certify::Level::canonical, a.threads);
      t_certify = seconds_since(t1);
      witness.reset();  // (per point 24 bytes and per slot 32: freed before the output is formatted)
      if (rep.condition == "input-dimension") throw UsageError(a.in + ": " + rep.detail);
      if (!rep.ok) throw InternalError("the " + kind + " result failed certification: " + rep.message());
      tets = std::move(r.tets);
      redundant = std::move(r.redundant);
      certified_by = "canonical, cpu::certify_rt3 from the kernel's witness";
    } else {
      // reference/rtd: RT+1 (sequential), certified as `flipflop rtd`
      ref::Rtd r = ref::rtd_incremental(pk, &rst);
      t_compute = seconds_since(t0);
      progress->stage("certifying");
      const auto t1 = Clock::now();
      const certify::Report rep = certify::rtd(pk, r.simplices, certify::Level::canonical);
      t_certify = seconds_since(t1);
      if (!rep.ok) throw InternalError("the " + kind + " result failed certification: " + rep.message());
      tets = as_tets(r.simplices);
      redundant = std::move(r.redundant);
      certified_by = "canonical, certify::rtd";
    }
  } catch (const std::invalid_argument& e) {  // input the algorithms reject (does not span R^3, ...)
    throw UsageError(a.in + ": " + e.what());
  }
  certified_by += quotient_note(quotient);
  const std::size_t canonical_count = tets.size(), canonical_redundant = redundant.size();

  // ---- the strict view: the reference's rule, from the certified answer ------------
  double t_strict = 0, t_strict_certify = 0;
  if (a.strict) {
    progress->stage("the strict view");
    const auto t2 = Clock::now();
    std::vector<std::vector<Index>> view;
    try {
      view = ref::strict_rtd(pk, as_cells(tets));
    } catch (const std::invalid_argument& e) {
      throw InternalError("the strict view of the " + kind + " result: " + std::string(e.what()));
    }
    t_strict = seconds_since(t2);
    const auto t3 = Clock::now();
    const certify::Report rs = certify::rtd(pk, view, certify::Level::exact);
    t_strict_certify = seconds_since(t3);
    if (!rs.ok) throw InternalError("the strict view of the " + kind + " result failed certification: " + rs.message());
    redundant = non_vertices(pk.size(), view);
    tets = as_tets(view);
  }

  // ---- output --------------------------------------------------------------------
  progress->stage("writing " + (a.out.empty() ? std::string("the result") : a.out));
  const auto t4 = Clock::now();
  // (from the flat tetrahedra: at 10^7 points a vector per tetrahedron cost
  // 3.8 GB of fresh memory and most of the write time)
  write_result_file(
      a.out, fmt, [&](std::ostream& os) { io::write_tetrahedra(os, tets); }, ps, tets.empty() ? nullptr : tets[0].data(),
      tets.size(), 4, io::CellKind::simplices, redundant, a.ascii);
  const double t_write = seconds_since(t4);
  progress.reset();  // the progress line erased before the reports below

  const std::string name = kind + (a.strict ? " --strict" : "");
  report_redundant(name.c_str(), redundant);
  if (a.stats) {
    // the style of hull2|hull3|rt2|dt2 --stats: what ran, sizes and times;
    // then the counts; then the kernel's stages (Rt3Options::times)
    std::cerr << kind << ": backend " << backend << threads_note(backend, a.threads) << ", " << ps.size()
              << " points, " << canonical_count << " tetrahedra, " << canonical_redundant << " redundant; compute "
              << t_compute << " s, certify " << t_certify << " s (" << certified_by << "); read " << t_read
              << " s, write " << t_write << " s\n";
    if (gpu) {
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
      std::cerr << kind << ": BRIO levels " << gst.levels << ", insertion rounds " << gst.rounds << ", inserted " << gst.inserted
                << " (the first four included), discarded when located " << gst.discarded << ", cavities "
                << gst.attempts << " (lost a claim " << gst.lost << ", overflowed " << gst.overflowed
                << ", largest capacity " << gst.max_capacity << "), tetrahedra replaced " << gst.cavity_tets
                << ", created " << gst.created_tets << ", exact-pass items " << gst.exact_items << ", slots "
                << gst.slots << "\n";
      const char* sep = ": stages ";
      std::cerr << kind;
      for (const auto& [stage, s] : stages.stages) std::cerr << std::exchange(sep, ", ") << stage << " " << s << " s";
      std::cerr << " (kernels_cuda/rt3, backend " << backend << ")\n";
      if (t_device > 0)
        std::cerr << kind << ": CUDA start-up " << t_device << " s, in a thread while the input was read (read "
                  << t_read << " s)\n";
#endif
    } else if (backend == "cpu") {
      std::cerr << kind << ": inserted " << kst.inserted << " (placed outside the hull " << kst.placed
                << "), discarded when located " << kst.discarded << ", removed by later insertions " << kst.removed
                << ", tetrahedra replaced " << kst.cavity_tets << ", created " << kst.created_tets
                << ", walk steps " << kst.walk_steps << ", slots " << kst.slots << "\n";
      const char* sep = ": stages ";
      std::cerr << kind;
      for (const auto& [stage, s] : stages.stages) std::cerr << std::exchange(sep, ", ") << stage << " " << s << " s";
      std::cerr << " (kernels_cpu/rt3, multithreaded)\n";
    } else {
      std::cerr << kind << ": flips";
      for (int k = 1; k <= 4; ++k) std::cerr << " " << k << "-" << (5 - k) << ":" << rst.flips[k];
      std::cerr << ", queue pushes " << rst.queue_pushes << ", pops " << rst.queue_pops << "\n";
    }
    if (a.strict)
      std::cerr << kind << " --strict: " << tets.size() << " tetrahedra (canonical answer: " << canonical_count
                << "), " << redundant.size() << " points not vertices; strict view " << t_strict
                << " s (reference/rtd/strict_rtd.hpp, sequential, from the " << backend
                << " backend's certified canonical answer), certify " << t_strict_certify << " s (exact)\n";
  }
  return 0;
}

}  // namespace flipflop::cli

// rtd_commands.cpp — `flipflop rtd` and `flipflop instant-flip` (see the header).
#include "cli/rtd_commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <optional>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/rt3_commands.hpp"
#include "io/input_error.hpp"
#include "io/read_points.hpp"
#include "io/write_points.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "kernels_cpu/rtd/certify_rtd.hpp"
#include "kernels_cpu/rtd/instant_flip.hpp"
#include "reference/rtd/dynamic_rt.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/perturbation_order.hpp"
#include "kernels_cpu/rtd/rtd_cavity.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/strict_rtd.hpp"
#include "reference/rtd/timeline.hpp"

namespace flipflop::cli {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// rtd: 2..9 (ref::rtd::kMaxDim); the instant flip: 2..5 (its moving model)
void check_dim(int d, int max) {
  if (d < 2 || d > max)
    throw UsageError("--dim " + std::to_string(d) + " is not supported (2.." + std::to_string(max) + ")");
}


PointSet read_d(const std::string& path, int d, bool weighted) {
  try {
    // io/read_points: .xyz in d = 2..9, .off/.ply in 2 and 3 dimensions
    return io::read_points(path, d, weighted);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
}

// reference/dimension.hpp: exact affine dimension in any d.
void check_spans(const PointSet& ps, const std::string& path) {
  if (std::string why = dimension_problem(ps); !why.empty()) throw UsageError(path + ": " + why);
}

// Runs f; a std::invalid_argument (input the algorithms reject: lower-
// dimensional, degenerate for the instant flip) becomes a UsageError naming
// the file.
template <class F>
auto with_input_errors(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw UsageError(path + ": " + e.what());
  }
}

void write_result(const std::string& path, io::Format f, const PointSet& ps,
                  const std::vector<std::vector<Index>>& simplices, const std::vector<Index>& redundant, bool ascii) {
  write_result_file(
      path, f, [&](std::ostream& os) { write_simplices(os, simplices); }, ps, simplices, io::CellKind::simplices,
      redundant, ascii);
}

// certify::rtd's checks on `threads` workers (kernels_cpu/rtd/certify_rtd.hpp;
// 0: the runtime's default): the same verdict and message at any count
void certify_or_throw(const PointSet& ps, const std::vector<std::vector<Index>>& simplices,
                      const std::string& what, int threads = 0) {
  const certify::Report r = cpu::certify_rtd(ps, simplices, certify::Level::canonical, false, threads);
  if (!r.ok) throw InternalError(what + " failed certification: " + r.message());
}

// the first `limit` indices, " ..." after them
std::string index_list(const std::vector<Index>& v, std::size_t limit = 50) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < limit; ++i) s += " " + std::to_string(v[i]);
  if (v.size() > limit) s += " ...";
  return s;
}

}  // namespace

void report_redundant(const char* cmd, const std::vector<Index>& redundant) {
  if (!redundant.empty())
    std::cerr << cmd << ": " << redundant.size() << " redundant point"
              << (redundant.size() == 1 ? "" : "s") << " (not vertices):" << index_list(redundant)
              << "\n";
}

int run_rtd(const RtdArgs& a) {
  check_dim(a.dim, ref::rtd::kMaxDim);
  // the backend: cpu — kernels_cpu/rt3 for d = 3 (multithreaded), the cavity
  // kernel kernels_cpu/rtd for d = 2, 4..9 (BRIO sort, each cavity's exact
  // tests where they pay, and certification on --threads workers; the points
  // inserted one after another); both return the reference's
  // answer byte for byte and are the default for d = 3..9 — or the reference
  // (RT+1) itself, the default for d = 2, sequential throughout
  const std::string backend = !a.backend.empty() ? a.backend : a.dim == 2 ? "reference" : "cpu";
  if (a.threads != 0 && backend != "cpu")
    throw UsageError("--threads applies to the multithreaded backend (--backend cpu); rtd --dim " +
                     std::to_string(a.dim) + " --backend " + backend + " runs on one thread");
  if (backend == "cpu" && a.dim == 3) {
    Rt3Args r;
    r.kind = "rtd";
    r.in = a.in;
    r.out = a.out;
    r.backend = "cpu";
    r.threads = a.threads;
    r.strict = a.strict;
    r.stats = a.stats;
    r.ascii = a.ascii;
    return run_rt3(r);
  }
  const io::Format fmt = output_format_of(a.out);
  const PointSet ps = read_d(a.in, a.dim, true);
  check_spans(ps, a.in);
  const auto t0 = Clock::now();
  // a lattice up to one exact common factor runs as that small-integer
  // lattice: the same index answer (reference/lattice_quotient.hpp); `ps`
  // stays for the output's coordinates, the reference reads the values as given
  const std::optional<LatticeQuotient> quotient = backend == "cpu" ? lattice_quotient(ps) : std::nullopt;
  const PointSet& pk = quotient ? quotient->points : ps;
  ref::RtdStats st;
  cpu::RtdCavityStats cst;
  const ref::Rtd rt = with_input_errors(a.in, [&] {
    cpu::RtdCavityOptions o;
    o.threads = a.threads;
    return backend == "cpu" ? cpu::rtd_cavity(pk, &cst, o) : ref::rtd_incremental(pk, &st);
  });
  const double t_compute = seconds_since(t0);
  const auto t1 = Clock::now();
  // the reference backend is certified by the sequential certifier
  if (backend == "cpu") certify_or_throw(pk, rt.simplices, "the rtd result", a.threads);
  else if (const certify::Report r = certify::rtd(pk, rt.simplices); !r.ok)
    throw InternalError("the rtd result failed certification: " + r.message());
  const double t_certify = seconds_since(t1);
  if (a.strict) {
    // derived from the certified canonical answer, certified in turn at the
    // exact level (no simplex of zero volume, a regular triangulation of the
    // exact input)
    const std::vector<std::vector<Index>> view = ref::strict_rtd(pk, rt.simplices);
    const certify::Report r = backend == "cpu" ? cpu::certify_rtd(pk, view, certify::Level::exact, false, a.threads)
                                               : certify::rtd(pk, view, certify::Level::exact);
    if (!r.ok) throw InternalError("the strict view of the rtd result failed certification: " + r.message());
    const std::vector<Index> missing = non_vertices(pk.size(), view);
    write_result(a.out, fmt, ps, view, missing, a.ascii);
    report_redundant("rtd --strict", missing);
    if (a.stats)
      std::cerr << "rtd --strict: " << view.size() << " simplices (canonical answer: " << rt.simplices.size()
                << "), " << missing.size() << " points not vertices\n";
    return 0;
  }
  write_result(a.out, fmt, ps, rt.simplices, rt.redundant, a.ascii);
  report_redundant("rtd", rt.redundant);
  if (a.stats) {
    std::cerr << "rtd: " << ps.size() << " points in R^" << a.dim << ", " << rt.simplices.size()
              << " simplices, " << rt.redundant.size() << " redundant; ";
    if (backend == "cpu") {
      std::cerr << "backend cpu (cavity insertion): inserted " << cst.inserted << " (placed outside the hull "
                << cst.placed << "), discarded " << cst.discarded << ", removed " << cst.removed
                << ", simplices replaced " << cst.cavity << ", created " << cst.created << ", walk steps "
                << cst.walk_steps;
    } else {
      std::cerr << "backend reference (RT+1): flips";
      for (int k = 1; k <= a.dim + 1; ++k) std::cerr << " " << k << "-" << (a.dim + 2 - k) << ":" << st.flips[k];
      std::cerr << ", queue pushes " << st.queue_pushes << ", pops " << st.queue_pops;
    }
    std::cerr << quotient_note(quotient);
    std::cerr << "; compute " << t_compute << " s, certify " << t_certify << " s\n";
  }
  return 0;
}

int run_instant_flip(const InstantFlipArgs& a) {
  check_dim(a.dim, 5);
  const io::Format fmt = output_format_of(a.out);
  if (a.from.empty() || a.to.empty()) throw UsageError("instant-flip needs --from W.xyz and --to U.xyz");
  const PointSet pts = read_d(a.points, a.dim, false);
  const PointSet pw = read_d(a.from, a.dim, true);
  const PointSet pu = read_d(a.to, a.dim, true);
  for (const auto* other : {&pw, &pu}) {
    const std::string& path = other == &pw ? a.from : a.to;
    if (other->size() != pts.size())
      throw UsageError(path + ": " + std::to_string(other->size()) + " points, but " + a.points +
                       " has " + std::to_string(pts.size()) +
                       " (W and U must hold the points of POINTS, in order)");
    for (std::size_t i = 0; i < pts.coords.size(); ++i)
      if (std::memcmp(&pts.coords[i], &other->coords[i], sizeof(double)) != 0)
        throw UsageError(path + ": point " + std::to_string(i / static_cast<std::size_t>(a.dim)) +
                         " differs from point " + std::to_string(i / static_cast<std::size_t>(a.dim)) +
                         " of " + a.points + " (W and U must hold the points of POINTS, in order)");
  }
  check_spans(pts, a.points);

  // RT(S ⊕ W) with its redundant points tracked, then in place to U.
  const std::vector<double> w = pw.weights.to_vector(), u = pu.weights.to_vector();
  const auto t0 = Clock::now();
  ref::DynamicRegularTriangulation rt =
      with_input_errors(a.from, [&] { return ref::DynamicRegularTriangulation(pts, w); });
  const double t_build = seconds_since(t0);
  const std::vector<std::vector<Index>> start = rt.simplices();
  const ref::MovingModel mm(pts, w, u);
  std::optional<ref::PerturbationOrder> order;  // for the time lines only
  if (a.timeline) {
    ref::PerturbationOrderResult po = with_input_errors(
        a.from, [&] { return ref::find_perturbation_order(pts, w, start); });
    order = po.order ? *po.order : ref::PerturbationOrder::identity(pts.size());
    std::cerr << "instant-flip: start, RT(S+W)"
              << (po.order ? "" : " (no perturbation order: " + po.reason + "; index order shown)") << "\n"
              << ref::format_timeline(ref::build_timeline(mm, start, *order));
  }

  // Algorithm 14 with insertions (dynamic_rt.hpp).
  const auto t2 = Clock::now();
  const ref::WeightUpdateStats st = with_input_errors(a.to, [&] { return cpu::set_weights(rt, u, a.threads); });
  const double t_flip = seconds_since(t2);
  const std::vector<std::vector<Index>> result = rt.simplices();
  const auto t3 = Clock::now();
  certify_or_throw(pu, result, "the instant-flip result");
  const double t_certify = seconds_since(t3);
  if (a.timeline)
    std::cerr << "instant-flip: final, RT(S+U)\n"
              << ref::format_timeline(ref::build_timeline(mm, result, *order));
  const std::vector<Index> redundant = rt.redundant();
  write_result(a.out, fmt, pu, result, redundant, a.ascii);
  report_redundant("instant-flip", redundant);
  if (a.stats) {
    const ref::InstantFlipStats& is = st.instant;
    std::cerr << "instant-flip: " << pts.size() << " points in R^" << a.dim << ", "
              << start.size() << " -> " << result.size() << " simplices; flips";
    for (int k = 1; k <= a.dim + 1; ++k)
      std::cerr << " " << k << "-" << (a.dim + 2 - k) << ":" << st.flips(k);
    std::cerr << " (" << st.total_flips() << " in all, " << is.inserted_vertices + st.repair_flips[1]
              << " vertices inserted, " << is.removed_vertices + st.repair_removed
              << " removed); queue: " << is.initial_ridges << " ridges and " << is.initial_points
              << " points examined, " << is.pushes << " pushes, " << is.pops << " pops, " << is.stale
              << " stale, " << is.deferred << " deferred, max " << is.max_queue
              << "; SoS check after it: " << st.checked_ridges << " ridges, " << st.checked_points
              << " points, " << (st.total_flips() - is.total_flips()) << " flips"
              << (st.rebuilt ? "; rebuilt by RT+1 (" + st.rebuild_reason + ")" : std::string())
              << "; build " << t_build << " s, instant flip " << t_flip << " s, certify " << t_certify
              << " s\n";
  }
  return 0;
}

}  // namespace flipflop::cli

// commands.cpp — gen, hull2/hull3/rt2/dt2 and certify.
#include "cli/commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>

#include "gen/generate.hpp"
#include "io/index_io.hpp"
#include "io/read_points.hpp"
#include "io/write_points.hpp"
#include "io/write_result.hpp"
#include "cli/progress.hpp"

#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/rt2/certify_rt2.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#include "kernels_cpu/rtd/certify_rtd.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/hull3/strict_hull3.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/strict_rt2.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"

namespace flipflop::cli {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Input dimension and weights per kind.
int dim_of(const std::string& kind) { return kind == "hull3" ? 3 : 2; }
bool weighted(const std::string& kind) { return kind == "rt2"; }

PointSet read_input(const std::string& path, const std::string& kind) {
  PointSet ps = io::read_points(path, dim_of(kind), weighted(kind));
  if (std::string why = dimension_problem(ps); !why.empty()) throw UsageError(path + ": " + why);
  return ps;
}

// The brute-force reference enumerates all candidate simplices (O(n^3) for
// hull2, O(n^4) otherwise): exact, but only for small inputs.
std::size_t brute_limit(const std::string& kind) { return kind == "hull2" ? 5000 : 300; }

void write_output(const std::string& path, const std::function<void(std::ostream&)>& body) {
  if (path.empty() || path == "-") {
    body(std::cout);
    std::cout.flush();
    if (!std::cout) throw UsageError("cannot write to standard output");
    return;
  }
  io::write_file(path, body);
}

}  // namespace

io::Format output_format_of(const std::string& path) {
  try {
    return io::output_format(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

void write_result_file(const std::string& path, io::Format f, const std::function<void(std::ostream&)>& index_text,
                       const PointSet& ps, const std::vector<std::vector<Index>>& cells, io::CellKind kind,
                       const std::vector<Index>& marked, bool ascii) {
  if (f == io::Format::index) return write_output(path, index_text);
  try {
    io::write_cells(path, f, ps, cells, kind, marked, ascii);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
}

void write_result_file(const std::string& path, io::Format f, const std::function<void(std::ostream&)>& index_text,
                       const PointSet& ps, const Index* flat, std::size_t count, std::size_t k, io::CellKind kind,
                       const std::vector<Index>& marked, bool ascii) {
  if (f == io::Format::npy) {
    try {
      return io::write_file(path, [&](std::ostream& os) { io::write_npy_indices(os, flat, count, k); });
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());
    }
  }
  std::vector<std::vector<Index>> cells;
  if (f != io::Format::index) {
    cells.reserve(count);
    for (std::size_t i = 0; i < count; ++i) cells.emplace_back(flat + i * k, flat + (i + 1) * k);
  }
  write_result_file(path, f, index_text, ps, cells, kind, marked, ascii);
}

namespace {
// The algorithms the GPU backends (kernels_cuda/, "cuda" and "cuda-omp")
// compute.
std::vector<std::string> gpu_algorithms(const std::string& kind) {
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  if (kind == "hull2") return {"graham-sort", "graham-insert"};
  if (kind == "rt2" || kind == "dt2") return {"ffrt"};
  if (kind == "hull3") return {"ffhull", "ghull"};
#else
  (void)kind;
#endif
  return {};
}
bool is_gpu(const std::string& backend) { return backend == "cuda" || backend == "cuda-omp"; }
}  // namespace

std::vector<std::string> available_backends(const std::string& kind) {
  std::vector<std::string> b = {"reference"};
  if (kind == "hull3" || kind == "hull2" || kind == "rt2" || kind == "dt2") b.insert(b.begin(), "cpu");
  // "cuda" is offered wherever the kernels are: without nvcc or a device it
  // fails with one line (exit 2), never silently runs elsewhere
  if (!gpu_algorithms(kind).empty()) b.insert(b.end(), {"cuda", "cuda-omp"});
  return b;
}

namespace {
// The algorithms the cpu backend computes (kernels_cpu/hull2: parallel
// Graham-sorting and Graham-insertion, kernels_cpu/hull3: parallel ffHull,
// kernels_cpu/rt2: incremental flipping in BRIO order, which only it has).
std::vector<std::string> cpu_algorithms(const std::string& kind) {
  if (kind == "hull3") return {"ffhull"};
  if (kind == "hull2") return {"graham-sort", "graham-insert"};
  if (kind == "rt2" || kind == "dt2") return {"incremental", "territories", "batches"};
  return {};
}
// The reference's default algorithm (when --backend reference is asked for
// without --algo).
std::string reference_default_algorithm(const std::string& kind) {
  if (kind == "rt2" || kind == "dt2") return "ffrt";
  return default_algorithm(kind);
}
bool cpu_computes(const std::string& kind, const std::string& algo) {
  const auto algos = cpu_algorithms(kind);
  return std::find(algos.begin(), algos.end(), algo) != algos.end();
}
}  // namespace

// an algorithm only the GPU backends compute (gHull)
bool gpu_only(const std::string& kind, const std::string& algo) {
  const auto g = gpu_algorithms(kind);
  if (std::find(g.begin(), g.end(), algo) == g.end()) return false;
  if (kind != "hull3") return false;
  const auto r = ref::hull3_algorithms();
  return std::find(r.begin(), r.end(), algo) == r.end();
}
std::string default_backend(const std::string& kind, const std::string& algo) {
  if (gpu_only(kind, algo)) return "cuda-omp";
  return cpu_computes(kind, algo) ? "cpu" : "reference";
}

std::vector<std::string> available_algorithms(const std::string& kind) {
  std::vector<std::string> algos;
  if (kind == "hull2") algos = ref::hull2_algorithms();
  if (kind == "rt2") algos = {"incremental", "territories", "batches", "ffrt", "ffrt-vfirst"};
  if (kind == "dt2") algos = {"incremental", "territories", "batches", "ffrt", "ffrt-vfirst", "lawson"};
  if (kind == "hull3") algos = ref::hull3_algorithms();
  // the GPU backends' own algorithms (gHull: kernels_cuda/hull3/ghull.hpp)
  for (const std::string& x : gpu_algorithms(kind))
    if (std::find(algos.begin(), algos.end(), x) == algos.end()) algos.push_back(x);
  algos.push_back("brute");
  return algos;
}
std::string default_algorithm(const std::string& kind) { return available_algorithms(kind).front(); }

int run_gen(const GenArgs& a) {
  if (a.list) {
    for (const std::string& d : gen::distributions())
      std::cout << d << " (" << gen::dimension_of(d) << "D)\n";
    return 0;
  }
  if (a.dist.empty() || a.n == 0 || a.out.empty())
    throw UsageError("gen needs DIST, N > 0 and -o FILE (flipflop gen --list shows the distributions)");
  gen::Options o;
  o.seed = a.seed;
  o.thickness = a.thickness;
  o.hull_points = a.hull_points;
  if (!a.weights.empty()) {
    double lo = 0, hi = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(a.weights.c_str(), "%lf %c %lf %c", &lo, &comma, &hi, &extra) != 3 || comma != ',' ||
        !(lo <= hi))
      throw UsageError("--weights expects LO,HI with LO <= HI, got '" + a.weights + "'");
    o.weighted = true;
    o.wlo = lo;
    o.whi = hi;
  }
  PointSet ps = gen::generate(a.dist, a.n, o);
  // .npy: float64 (n, d[+1]), read back without parsing; anything else: .xyz text
  const bool npy = a.out.size() >= 4 && a.out.compare(a.out.size() - 4, 4, ".npy") == 0;
  write_output(a.out, [&](std::ostream& os) { npy ? io::write_points_npy(os, ps) : io::write_points(os, ps); });
  return 0;
}

namespace {

// The counts an algorithm reports (the others stay 0 and are left out).
std::string hull3_counts(const ref::Hull3Stats& st) {
  const std::pair<const char*, std::uint64_t> all[] = {
      {"2-2 flips", st.flips_2_2},        {"3-1 flips", st.flips_3_1},
      {"1-3 flips", st.flips_1_3},        {"labelled non-extreme", st.labelled_non_extreme},
      {"insertions", st.insertions},      {"discarded early", st.discarded_early},
      {"splay insertions", st.splay_insertions}, {"splay removals", st.splay_removals},
      {"dead stars", st.dead_stars},      {"twists", st.twists},
      {"fold flips", st.fold_flips},      {"rounds", st.rounds}};
  std::string out;
  for (const auto& [name, value] : all) {
    if (value == 0) continue;
    if (!out.empty()) out += ", ";
    out += std::string(name) + " " + std::to_string(value);
  }
  return out.empty() ? "no operations" : out;
}

}  // namespace

std::string quotient_note(const std::optional<LatticeQuotient>& quotient) {
  if (!quotient) return {};
  std::ostringstream os;
  os.precision(17);
  os << "; computed and certified on the small-integer lattice x / " << quotient->factor
     << " (exact, the same answer: reference/lattice_quotient.hpp)";
  return os.str();
}

int run_compute(const ComputeArgs& a) {
  if (a.strict && a.kind == "hull2") throw UsageError("--strict applies to hull3, rt2 and dt2");
  if (a.triangulate && (!a.strict || a.kind != "hull3"))
    throw UsageError("--triangulate applies to the strict view of a 3D hull (hull3 --strict)");
  const io::Format fmt = output_format_of(a.out);  // an unknown extension fails before any work
  Progress progress(Progress::stderr_is_terminal(), "flipflop " + a.kind);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  // --backend cuda: the CUDA start-up in a thread while the input is read (issue 36 item 4)
  kernels::DeviceStart device(a.backend);
#endif
  progress.stage("reading " + a.in);
  const auto t_read0 = Clock::now();
  const PointSet given = read_input(a.in, a.kind);
  const double t_read = seconds_since(t_read0);
  const std::string algo = !a.algo.empty()            ? a.algo
                           : a.backend == "reference" ? reference_default_algorithm(a.kind)
                           : is_gpu(a.backend)        ? gpu_algorithms(a.kind).front()
                                                      : default_algorithm(a.kind);
  const std::string backend = a.backend.empty() ? default_backend(a.kind, algo) : a.backend;
  if (backend == "reference" && (a.kind == "rt2" || a.kind == "dt2") && cpu_computes(a.kind, algo))
    throw UsageError("--algo " + algo + " is the cpu backend's (kernels_cpu/rt2); the reference computes ffrt, "
                     "ffrt-vfirst" + std::string(a.kind == "dt2" ? ", lawson" : "") + " and brute");
  if (backend == "reference" && gpu_only(a.kind, algo))
    throw UsageError("--algo " + algo + " is the GPU backends' (--backend cuda or cuda-omp), not the reference's");
  if (backend == "cpu" && !cpu_computes(a.kind, algo)) {
    std::string list;
    for (const std::string& x : cpu_algorithms(a.kind)) list += (list.empty() ? "" : ", ") + x;
    throw UsageError("the cpu backend computes --algo " + list + " only, got '" + algo + "' (use --backend reference)");
  }
  if (is_gpu(backend)) {
    const auto algos = gpu_algorithms(a.kind);
    if (std::find(algos.begin(), algos.end(), algo) == algos.end()) {
      std::string list;
      for (const std::string& x : algos) list += (list.empty() ? "" : ", ") + x;
      throw UsageError("the " + backend + " backend computes --algo " + list + " only, got '" + algo + "'");
    }
  }
  if (a.threads != 0 && backend != "cpu")
    throw UsageError("--threads applies to the multithreaded backend (--backend cpu), not '" + backend + "'");
  // the cpu and GPU backends run a lattice up to one exact common factor
  // (steps of 0.5, 0.25, ...) as that small-integer lattice: the same index
  // answer (reference/lattice_quotient.hpp), computed and certified there;
  // `given` stays for the output's coordinates; the reference reads the
  // values as given. (Its one pass is counted in the compute time.)
  const auto t_quotient0 = Clock::now();
  const std::optional<LatticeQuotient> quotient = backend != "reference" ? lattice_quotient(given) : std::nullopt;
  const PointSet& ps = quotient ? quotient->points : given;
  const double t_quotient = seconds_since(t_quotient0);
  if (algo == "brute" && ps.size() > brute_limit(a.kind))
    throw UsageError(a.in + ": " + std::to_string(ps.size()) + " points exceed the limit of " +
                     std::to_string(brute_limit(a.kind)) + " of the brute-force reference ('--algo brute')");
  double t_device = 0;  // the CUDA start-up, overlapped with the reading
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  t_device = device.wait();
#endif
  progress.stage("computing (" + std::to_string(ps.size()) + " points, backend " + backend + ")");
  const auto t0 = Clock::now();
  std::vector<Index> cycle;
  std::vector<Triangle> tris;
  cpu::Hull3Witness hull3_witness;  // filled by the cpu hull3 kernel for its certifier
  std::string counts;
  std::string exact_kernel;  // the GPU hull3's runs with the exact kernel point (--stats)
  std::optional<cpu::Rt2Witness> rt2_witness;  // the cpu rt2 kernel's certificate
  cpu::StageTimes gpu_times;                   // the GPU backends' stages (--stats)
  if (a.kind == "hull2" && algo != "brute") {
    // kernels_cpu/hull2: throw-away and parallel Graham-sorting, byte-identical
    // to the reference
    ref::Hull2Stats st;
    if (backend == "cpu") {
      cpu::Hull2Options o;
      o.threads = a.threads;
      cycle = algo == "graham-insert" ? cpu::hull2_graham_insert(ps, o, &st) : cpu::hull2_graham_sort(ps, o, &st);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    } else if (is_gpu(backend)) {
      // kernels_cuda/hull2: Graham-sorting or -insertion with parallel
      // flip-pop, on thrust
      kernels::Hull2GpuOptions o;
      o.times = &gpu_times;
      cycle = kernels::hull2_gpu(backend, ps, o, &st, algo);
#endif
    } else {
      cycle = ref::hull2(ps, algo, &st);
    }
    counts = "2-1 flips " + std::to_string(st.flips_2_1) + ", flip-pop passes " + std::to_string(st.rounds) +
             ", points discarded early " + std::to_string(st.discarded_early) + ", insertions " +
             std::to_string(st.insertions) + ", twists " + std::to_string(st.twists);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  } else if ((a.kind == "rt2" || a.kind == "dt2") && is_gpu(backend)) {
    // kernels_cuda/rt2: ffRT's insertion rounds and parallel flip-flop rounds
    ref::Rt2Stats st;
    tris = kernels::rt2_gpu(backend, ps, &st, &gpu_times);
    counts = "1-3 flips " + std::to_string(st.flips_1_3) + ", 2-2 flips " + std::to_string(st.flips_2_2) +
             ", 3-1 flips " + std::to_string(st.flips_3_1) + ", discarded early " + std::to_string(st.discarded_early) +
             ", insertion rounds " + std::to_string(st.rounds);
#endif
  } else if ((a.kind == "rt2" || a.kind == "dt2") && backend == "cpu") {
    // kernels_cpu/rt2: BRIO order, incremental flipping, byte-identical to
    // the reference
    ref::Rt2Stats st;
    cpu::Rt2Options o;
    o.threads = a.threads;
    // stage 2b: parallel insertion (kernels_cpu/rt2/rt2.hpp)
    if (algo == "territories") o.insertion = cpu::Rt2Options::Insertion::territories;
    if (algo == "batches") o.insertion = cpu::Rt2Options::Insertion::batches;
    tris = cpu::rt2(ps, o, &st, &rt2_witness.emplace());
    counts = "1-3 flips " + std::to_string(st.flips_1_3) + ", 2-2 flips " + std::to_string(st.flips_2_2) +
             ", 3-1 flips " + std::to_string(st.flips_3_1) + ", discarded early " + std::to_string(st.discarded_early);
  } else if ((a.kind == "rt2" || a.kind == "dt2") && algo != "brute") {
    // ffRT (§5.3): 1-3 insertions with the virtual vertex, then flip-flop
    // (Algorithm 5: combined V/D criterion, or V-criterion first); Lawson
    // (§3.3.1) for unweighted input.
    ref::Rt2Stats st;
    if (algo == "lawson") tris = ref::dt2_lawson(ps, &st);
    else
      tris = ref::rt2_ffrt(ps, &st,
                           algo == "ffrt-vfirst" ? ref::FlipFlopVariant::v_first : ref::FlipFlopVariant::combined);
    counts = "2-2 flips " + std::to_string(st.flips_2_2) + ", 3-1 flips " + std::to_string(st.flips_3_1) +
             " (D-criterion flips among them " + std::to_string(st.flops) + "), 1-3 flips " +
             std::to_string(st.flips_1_3) + ", labelled redundant " + std::to_string(st.labelled_redundant) + ", discarded early " +
             std::to_string(st.discarded_early) + ", rounds " + std::to_string(st.rounds);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  } else if (a.kind == "hull3" && is_gpu(backend)) {
    // kernels_cuda/hull3: ffHull's construction rounds and parallel flip-flop rounds
    ref::Hull3Stats st;
    if (algo == "ghull") {
      // kernels_cuda/hull3/ghull: gHull's five stages (thesis ch. 7) and the exact verification
      kernels::GhullStats g;
      tris = kernels::hull3_ghull_gpu(backend, ps, {}, &g, &gpu_times);
      counts = "grid " + std::to_string(g.grid) + ", bands " + std::to_string(g.bands) + ", captured (|S'|) " +
               std::to_string(g.captured) +
               ", working pairs " + std::to_string(g.working_pairs) + ", CH(S') vertices " +
               std::to_string(g.approx_vertices) + ", depth-test candidates " + std::to_string(g.depth_candidates) +
               ", added " + std::to_string(g.added) + ", depth misses " + std::to_string(g.depth_misses) +
               ", splay rounds " + std::to_string(g.splay_rounds) + ", splay insertions " +
               std::to_string(g.splay_insertions) + ", dead stars " + std::to_string(g.dead_stars) +
               ", edge-list growths " + std::to_string(g.edge_list_growths);
      exact_kernel = "handed back: " + std::to_string(g.handed_back) +
                     " (1: the spanning points came from the reference's sequential rule)";
    } else {
      tris = kernels::hull3_gpu(backend, ps, &st, &gpu_times);
      counts = hull3_counts(st);
      exact_kernel = "exact kernel point: " + std::to_string(st.exact_kernel_point) +
                     " (an almost flat initial tetrahedron: the exact centroid's side tests on the device)\n" +
                     a.kind + ": handed back: " + std::to_string(st.handed_back) +
                     " (1: the initial tetrahedron came from the reference's sequential rule)";
    }
#endif
  } else if (a.kind == "hull3" && backend == "cpu") {
    // kernels_cpu/hull3: parallel ffHull, byte-identical to the reference,
    // with the witness its certifier checks
    ref::Hull3Stats st;
    cpu::Hull3Options o;
    o.threads = a.threads;
    o.witness = &hull3_witness;
    tris = cpu::hull3_ffhull(ps, o, &st);
    counts = hull3_counts(st);
  } else if (a.kind == "hull3" && algo != "brute") {
    ref::Hull3Stats st;
    tris = ref::hull3(ps, algo, &st);
    counts = hull3_counts(st);
  } else if (a.kind == "hull2") cycle = brute::hull2(ps);
  else if (a.kind == "hull3") tris = brute::hull3(ps);
  else tris = brute::rt2(ps);
  const double t_compute = seconds_since(t0) + t_quotient;

  // Never print a result that was not checked: certify the canonical answer.
  progress.stage("certifying");
  const auto t1 = Clock::now();
  // (the cpu backends: the checks split over the same threads)
  // (the GPU backends: the multithreaded certifier on the host)
  const bool parallel_certifier = backend == "cpu" || is_gpu(backend);
  certify::Report r = a.kind == "hull2" && parallel_certifier
                          ? cpu::certify_hull2(ps, cycle, certify::Level::canonical, a.threads)
                      : a.kind == "hull2" ? certify::hull2(ps, cycle, certify::Level::canonical)
                      : a.kind == "hull3" && backend == "cpu"
                          ? cpu::certify_hull3_witnessed(ps, tris, certify::Level::canonical, hull3_witness, a.threads)
                      : a.kind == "hull3" && parallel_certifier
                          ? cpu::certify_hull3(ps, tris, certify::Level::canonical, a.threads)
                      : a.kind == "hull3" ? certify::hull3(ps, tris, certify::Level::canonical)
                      : rt2_witness ? cpu::certify_rt2(ps, tris, certify::Level::canonical, *rt2_witness, a.threads)
                      : parallel_certifier ? cpu::certify_rt2(ps, tris, certify::Level::canonical, a.threads)
                                          : certify::rt2(ps, tris, certify::Level::canonical);
  const double t_certify = seconds_since(t1);
  rt2_witness.reset();
  hull3_witness = cpu::Hull3Witness{};  // (per point 8 bytes, freed before the output is formatted)
  if (!r.ok) throw InternalError("the " + a.kind + " result failed certification: " + r.message());

  // The strict views are derived from the certified canonical answer; the
  // triangulations' view is certified in turn (no zero-area triangle, a
  // regular triangulation of the exact input at Level::exact).
  ref::StrictHull3 strict;
  const bool strict_hull = a.strict && a.kind == "hull3";
  if (strict_hull) strict = ref::strict_hull3(ps, tris);
  if (a.triangulate) strict = ref::fan_triangulated(strict);
  if (a.strict && a.kind != "hull3") {
    tris = ref::strict_rt2(ps, tris);
    const certify::Report rs = certify::rt2_strict(ps, tris);
    if (!rs.ok) throw InternalError("the strict view of the " + a.kind + " result failed certification: " + rs.message());
  }
  progress.stage("writing " + (a.out.empty() ? std::string("the result") : a.out));
  const auto t2 = Clock::now();
  std::vector<std::vector<Index>> cells;  // (not for the index format, written from the result itself)
  if (fmt != io::Format::index) {
    if (strict_hull) cells = strict.facets;
    else if (a.kind == "hull2") cells = {cycle};
    else
      for (const Triangle& t : tris) cells.push_back({t[0], t[1], t[2]});
  }
  const std::vector<Index> redundant =
      a.kind == "rt2" && fmt == io::Format::svg ? non_vertices(ps.size(), cells) : std::vector<Index>{};
  write_result_file(
      a.out, fmt,
      [&](std::ostream& os) {
        if (strict_hull) os << ref::format_strict_hull3(strict);
        else if (a.kind == "hull2") io::write_hull2(os, cycle);
        else io::write_triangles(os, tris);
      },
      given, cells, a.kind == "hull2" ? io::CellKind::cycle : io::CellKind::polygons, redundant, a.ascii);
  const double t_write = seconds_since(t2);
  if (a.stats) {
    std::cerr << a.kind << ": backend " << backend << (backend == "cpu" && a.threads ? " (" + std::to_string(a.threads) + " threads)" : std::string()) << ", algo " << algo << ", " << ps.size() << " points, "
              << (a.kind == "hull2" ? cycle.size() : tris.size())
              << (a.kind == "hull2" ? " vertices" : " triangles") << "; compute " << t_compute << " s, certify "
              << t_certify << " s (canonical)"
              << quotient_note(quotient) << "; read " << t_read << " s, write " << t_write << " s\n";
    if (!counts.empty()) std::cerr << a.kind << ": " << counts << "\n";
    if (!exact_kernel.empty()) std::cerr << a.kind << ": " << exact_kernel << "\n";
    if (t_device > 0)
      std::cerr << a.kind << ": CUDA start-up " << t_device << " s, in a thread while the input was read (read "
                << t_read << " s)\n";
    if (!gpu_times.stages.empty()) {
      // the GPU kernels' stages (kernels_cuda/: upload and download timed
      // apart from the device work)
      const char* sep = ": stages ";
      std::cerr << a.kind;
      for (const auto& [name, s] : gpu_times.stages) std::cerr << std::exchange(sep, ", ") << name << " " << s << " s";
      std::cerr << "\n";
    }
  }
  return 0;
}

namespace {

// certify rtd at either level (reference/rtd/certify_rtd.hpp); also
// certify rt3|dt3 (d = 3; dt3: no weight column).
int certify_rtd_file(const CertifyArgs& a) {
  const bool three = a.kind == "rt3" || a.kind == "dt3";
  if (three && a.dim != 0 && a.dim != 3) throw UsageError("certify " + a.kind + " is 3D (--dim 3 or none)");
  const int dim = three ? 3 : a.dim;
  if (dim < 2 || dim > 9) throw UsageError("certify rtd needs --dim d (2 to 9)");
  const PointSet ps = io::read_points(a.points, dim, a.kind != "dt3");
  // input that does not span R^d has no triangulation to certify: a usage
  // error (one line, exit 2) whatever the output holds
  if (std::string why = dimension_problem(ps); !why.empty()) throw UsageError(a.points + ": " + why);
  std::ifstream in(a.output);
  if (!in) throw UsageError(a.output + ": cannot read");
  std::vector<std::vector<Index>> simplices;
  try {
    simplices = read_simplices(in, dim);
  } catch (const std::invalid_argument& e) {
    throw UsageError(a.output + ": " + e.what());
  }
  // --strict: the exact level, which refuses every simplex of zero volume
  // (the strict view's defining property) — the same check, named as asked
  const certify::Report r = cpu::certify_rtd(ps, simplices, a.canonical ? certify::Level::canonical : certify::Level::exact,
                                             false, a.threads);
  const char* level = a.canonical ? "canonical" : a.strict ? "strict" : "exact";
  if (r.condition == "input-dimension") throw UsageError(a.points + ": " + r.detail);
  if (!r.ok) {
    std::cout << "NOT certified (" << a.kind << ", " << level << "): " << r.message() << "\n";
    return 1;
  }
  std::cout << "certified (" << a.kind << ", " << level << "): " << ps.size() << " points in R^" << dim << ", "
            << simplices.size() << (three ? " tetrahedra\n" : " simplices\n");
  return 0;
}

}  // namespace

int run_certify(const CertifyArgs& a) {
  const bool rtd_kind = a.kind == "rtd" || a.kind == "rt3" || a.kind == "dt3";
  if (rtd_kind && a.strict && a.canonical)
    throw UsageError("--canonical does not apply to the strict views (certified at the exact level)");
  if (rtd_kind) return certify_rtd_file(a);
  if (a.dim != 0) throw UsageError("--dim applies to certify rtd");
  if (a.strict && a.kind == "hull2") throw UsageError("--strict applies to certify hull3, rt2 and dt2");
  if (a.strict && a.canonical)
    throw UsageError("--canonical does not apply to the strict views (certified at the exact level)");
  if (a.triangulate && (!a.strict || a.kind != "hull3"))
    throw UsageError("--triangulate applies to the strict view of a 3D hull (certify hull3 --strict)");
  const PointSet ps = io::read_points(a.points, dim_of(a.kind), weighted(a.kind));
  const certify::Level level = a.canonical ? certify::Level::canonical : certify::Level::exact;
  certify::Report r;
  std::size_t count = 0;
  std::string what = a.kind == "hull2" ? " vertices" : " triangles";
  const std::string view = a.strict ? "strict" : a.canonical ? "canonical" : "exact";
  if (a.strict && a.kind == "hull3") {
    // the strict view: strictly extreme points and convex polygons (or their
    // fan triangles with --triangulate)
    const auto [extreme, facets] = io::read_strict_hull3(a.output);
    count = facets.size();
    what = a.triangulate ? " triangles" : " facets";
    r = certify::hull3_strict(ps, extreme, facets, a.triangulate);
  } else if (a.strict) {
    const std::vector<Triangle> tris = io::read_triangles(a.output);
    count = tris.size();
    r = certify::rt2_strict(ps, tris);
  } else if (a.kind == "hull2") {
    std::vector<Index> cycle = io::read_index_cycle(a.output);
    count = cycle.size();
    r = cpu::certify_hull2(ps, cycle, level, a.threads);
  } else {
    std::vector<Triangle> tris = io::read_triangles(a.output);
    count = tris.size();
    r = a.kind == "hull3" ? cpu::certify_hull3(ps, tris, level, a.threads) : cpu::certify_rt2(ps, tris, level, a.threads);
  }
  if (r.condition == "input-dimension") throw UsageError(a.points + ": " + r.detail);
  if (!r.ok) {
    std::cout << "NOT certified (" << a.kind << ", " << view << "): " << r.message() << "\n";
    return 1;
  }
  std::cout << "certified (" << a.kind << ", " << view << "): " << ps.size() << " points, " << count << what << "\n";
  return 0;
}

}  // namespace flipflop::cli

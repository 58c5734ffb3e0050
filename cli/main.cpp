// main.cpp — the `flipflop` command-line tool (DESIGN.md, "The command-line tool").
//
//   flipflop gen DIST N [--seed S] [--thickness T] [--weights LO,HI] [--hull-points H] -o FILE
//   flipflop hull2|hull3|rt2|dt2 IN [-o OUT] [--backend B] [--algo A] [--stats] [--strict (hull3, rt2, dt2)]
//                                [--threads N (cpu backend)]
//   flipflop rt3|dt3 IN [-o OUT] [--backend cpu|reference|cuda|cuda-omp] [--threads N] [--strict] [--stats]
//   flipflop rtd IN --dim d [-o OUT] [--backend cpu|reference] [--threads N (cpu backend)] [--strict] [--stats]
//   flipflop instant-flip POINTS --dim d --from W.xyz --to U.xyz [-o OUT] [--stats] [--timeline] [--threads N]
//   flipflop certify hull2|hull3|rt2|dt2 POINTS OUTPUT [--canonical] [--threads N]
//                    [--strict (hull3, rt2, dt2) [--triangulate (hull3)]]
//   flipflop certify rtd POINTS OUTPUT --dim d [--canonical | --strict] [--threads N]
//   flipflop certify rt3|dt3 POINTS OUTPUT [--canonical | --strict] [--threads N]   (certify rtd --dim 3)
//   flipflop bench ...
//   flipflop demo
//
// Exit codes: 0 success (certified); 1 certification failed (certify); 2 bad
// input or usage (one line on stderr); 3 internal error (a computed result that
// failed its own certification is never printed).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "bench/bench.hpp"
#include "cli/commands.hpp"
#include "cli/rt3_commands.hpp"
#include "cli/rtd_commands.hpp"
#include "reference/rtd/triangulation_d.hpp"

int main(int argc, char** argv) {
  using namespace flipflop::cli;
  CLI::App app{"flipflop: convex hulls and regular triangulations by local transformation, "
               "with exact, certified output"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "all subcommands' options");

  // ---- gen ----------------------------------------------------------------
  GenArgs g;
  auto* gen = app.add_subcommand("gen", "generate a point set (thesis distributions and degenerate families)");
  gen->add_option("DIST", g.dist, "distribution name (flipflop gen --list)");
  gen->add_option("N", g.n, "number of points");
  gen->add_option("--seed", g.seed, "random seed (output is deterministic for a seed)");
  gen->add_option("--thickness", g.thickness, "shell/band thickness of frame, circle, box, sphere");
  gen->add_option("--weights", g.weights, "weights uniform in LO,HI (adds a weight column)");
  gen->add_option("--hull-points", g.hull_points, "controlled ball: number of points on the sphere");
  gen->add_option("-o,--output", g.out, "output file: .npy (float64, shape (n, d) or (n, d+1)) or .xyz text");
  gen->add_flag("--list", g.list, "list the distributions and exit");

  // ---- hull2 / hull3 / rt2 / dt2 -----------------------------------------------
  ComputeArgs c;
  const char* compute_help[] = {"2D convex hull (input columns x y)", "3D convex hull (input columns x y z)",
                                "2D regular triangulation (input columns x y w)",
                                "2D Delaunay triangulation (input columns x y)"};
  const char* kinds[] = {"hull2", "hull3", "rt2", "dt2"};
  std::vector<CLI::App*> compute_cmds;
  for (int k = 0; k < 4; ++k) {
    auto* cmd = app.add_subcommand(kinds[k], compute_help[k]);
    cmd->add_option("IN", c.in, "input point file (.xyz, .off, .ply)")->required();
    cmd->add_option("-o,--output", c.out,
                    "output file, format by extension: .txt/.idx/none index text (default: standard output), "
                    ".off .obj .ply .stl .vtu meshes, .npy index array, .svg picture (2D)");
    cmd->add_flag("--ascii", c.ascii, ".ply and .stl output in ASCII (default binary)");
    cmd->add_option("--backend", c.backend,
                    "backend computing the result (default " + default_backend(kinds[k], default_algorithm(kinds[k])) +
                        ")")
        ->check(CLI::IsMember(available_backends(kinds[k])));
    cmd->add_option("--threads", c.threads, "worker threads of the cpu backend (default: all cores)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--algo", c.algo, "algorithm (default " + default_algorithm(kinds[k]) + ")")
        ->check(CLI::IsMember(available_algorithms(kinds[k])));
    cmd->add_flag("--stats", c.stats, "print counts and timings to standard error");
    if (std::string(kinds[k]) == "rt2" || std::string(kinds[k]) == "dt2")
      cmd->add_flag("--strict", c.strict,
                    "write the strict view: a regular triangulation of the exact input without zero-area triangles");
    if (std::string(kinds[k]) == "hull3") {
      cmd->add_flag("--strict", c.strict,
                    "write the strict view: strictly extreme points and coplanar facets merged into polygons");
      cmd->add_flag("--triangulate", c.triangulate,
                    "with --strict: each polygon fan-triangulated from its smallest vertex (no zero-area triangle)");
    }
    compute_cmds.push_back(cmd);
  }

  // ---- rt3 / dt3 (kernels_cpu/rt3) ------------------------------------------------
  Rt3Args t3;
  const char* kinds3[] = {"rt3", "dt3"};
  const char* help3[] = {"3D regular triangulation (input columns x y z w)",
                         "3D Delaunay triangulation (input columns x y z)"};
  std::vector<CLI::App*> rt3_cmds;
  for (int k = 0; k < 2; ++k) {
    auto* cmd = app.add_subcommand(kinds3[k], help3[k]);
    cmd->add_option("IN", t3.in, "input point file (.xyz, .npy, .off, .ply)")->required();
    cmd->add_option("-o,--output", t3.out,
                    "output file, format by extension: .txt/.idx/none tetrahedron list (default: standard output), "
                    ".vtu tetrahedral mesh, .npy index array");
    cmd->add_flag("--ascii", t3.ascii, "accepted for symmetry (.vtu is ASCII, .npy binary)");
    cmd->add_option("--backend", t3.backend,
                    "cpu (default: kernels_cpu/rt3, multithreaded, certified from its witness), reference "
                    "(RT+1, sequential), cuda (kernels_cuda/rt3 on the GPU) or cuda-omp (the same code on "
                    "thrust's OpenMP backend); the same bytes")
        ->check(CLI::IsMember({"cpu", "reference", "cuda", "cuda-omp"}));
    cmd->add_option("--threads", t3.threads, "worker threads of the cpu backend and its certifier (default: all cores)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--stats", t3.stats, "print counts and stage timings to standard error");
    cmd->add_flag("--strict", t3.strict,
                  "the strict view: no tetrahedron of zero volume (as rtd --strict), derived sequentially by the "
                  "reference's rule from the backend's certified canonical answer, certified at the exact level");
    rt3_cmds.push_back(cmd);
  }

  // ---- rtd / instant-flip (thesis ch. 9) -----------------------------------------
  RtdArgs r;
  auto* rtd = app.add_subcommand("rtd", "d-dimensional regular triangulation (input: d coordinates and a weight per line)");
  rtd->add_option("IN", r.in, "input point file (.xyz)")->required();
  rtd->add_option("--dim", r.dim, "dimension d (2 to " + std::to_string(flipflop::ref::rtd::kMaxDim) + ")")
      ->required()
      ->check(CLI::Range(2, flipflop::ref::rtd::kMaxDim));
  rtd->add_option("-o,--output", r.out,
                  "output file, format by extension: .txt/.idx/none simplex list (default: standard output), "
                  ".vtu (d <= 3), .npy, and for d = 2 also .off .obj .ply .stl .svg");
  rtd->add_flag("--ascii", r.ascii, ".ply and .stl output in ASCII (default binary)");
  rtd->add_option("--backend", r.backend,
                  "cpu (d = 3: kernels_cpu/rt3, multithreaded, as flipflop rt3; d = 2, 4..9: kernels_cpu/rtd, "
                  "cavity insertion, one point after another, each cavity's exact tests shared by the threads "
                  "where they pay; the default for d = 3..9) or reference (RT+1, the default for d = 2); the "
                  "same answer byte for byte")
      ->check(CLI::IsMember({"cpu", "reference"}));
  rtd->add_option("--threads", r.threads, "cpu backend: worker threads (d = 3: the whole kernel; other d: the BRIO sort, the cavities' exact tests on degenerate input and the certifier; the same answer at any count; default: all cores)")
      ->check(CLI::PositiveNumber);
  rtd->add_flag("--stats", r.stats, "print counts and timings to standard error");
  rtd->add_flag("--strict", r.strict,
                "the strict view: no simplex of zero volume (the exact regular subdivision's pulling refinement; "
                "d = 2: as rt2 --strict), certified at the exact level");
  InstantFlipArgs f;
  auto* iflip = app.add_subcommand(
      "instant-flip", "RT(S+W) -> RT(S+U) by the monotonic instant flip (thesis §9.2, Algorithm 14)");
  iflip->add_option("POINTS", f.points, "the points (.xyz, d coordinates per line)")->required();
  iflip->add_option("--dim", f.dim, "dimension d (2 to 5)")->required()->check(CLI::Range(2, 5));
  iflip->add_option("--from", f.from, "the points with their start weights W as a last column")->required();
  iflip->add_option("--to", f.to, "the points with their target weights U as a last column")->required();
  iflip->add_option("-o,--output", f.out,
                    "output of RT(S+U), format by extension as for rtd (default: standard output, simplex list)");
  iflip->add_flag("--ascii", f.ascii, ".ply and .stl output in ASCII (default binary)");
  iflip->add_flag("--stats", f.stats, "print flips by type and queue operations to standard error");
  iflip->add_flag("--timeline", f.timeline, "print the time lines (§9.3) of the start and the result to standard error");
  iflip->add_option("--threads", f.threads, "worker threads of the parallel ridge scan (default: all cores; same output)")
      ->check(CLI::Range(0, 1024));

  // ---- certify ---------------------------------------------------------------
  CertifyArgs v;
  auto* cert = app.add_subcommand("certify", "check an output against its input exactly; exit 0 when certified");
  cert->add_option("KIND", v.kind, "hull2, hull3, rt2, dt2, rtd, or rt3|dt3 (certify rtd --dim 3; dt3 unweighted)")
      ->required()
      ->check(CLI::IsMember({"hull2", "hull3", "rt2", "dt2", "rtd", "rt3", "dt3"}));
  cert->add_option("--dim", v.dim,
                   "rtd: the dimension d (2 to " + std::to_string(flipflop::ref::rtd::kMaxDim) +
                       "; points: d coordinates and a weight per line)")
      ->check(CLI::Range(2, flipflop::ref::rtd::kMaxDim));
  cert->add_option("POINTS", v.points, "input point file")->required();
  cert->add_option("OUTPUT", v.output, "index output to check (flipflop's or another program's, e.g. qhull i Qt)")
      ->required();
  cert->add_option("--threads", v.threads, "worker threads of the parallel checks (default: all cores; same verdict and message)")
      ->check(CLI::Range(1, 1024));
  cert->add_flag("--strict", v.strict,
                 "the output is a strict view (hull3 --strict: extreme points and polygons; rt2|dt2 --strict: "
                 "no zero-area triangle; rtd --strict: no zero-volume simplex), certified at the exact level");
  cert->add_flag("--triangulate", v.triangulate, "with certify hull3 --strict: the view of hull3 --strict --triangulate");
  cert->add_flag("--canonical", v.canonical,
                 "also require flipflop's unique answer under Simulation of Simplicity, in canonical form");

  // ---- bench / demo ---------------------------------------------------------------
  auto* bench = app.add_subcommand("bench", "side-by-side timings against Qhull and CGAL (flipflop bench --help)");
  bench->prefix_command();
  bench->set_help_flag();
  auto* demo = app.add_subcommand("demo", "run the main job on built-in generated data, certified, with timings");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    while (!msg.empty() && msg.back() == '\n') msg.pop_back();
    std::cerr << "flipflop: error: " << msg << " (see flipflop --help)\n";
    return 2;
  }

  try {
    if (gen->parsed()) return run_gen(g);
    for (int k = 0; k < 4; ++k)
      if (compute_cmds[static_cast<std::size_t>(k)]->parsed()) {
        c.kind = kinds[k];
        return run_compute(c);
      }
    for (int k = 0; k < 2; ++k)
      if (rt3_cmds[static_cast<std::size_t>(k)]->parsed()) {
        t3.kind = kinds3[k];
        return run_rt3(t3);
      }
    if (rtd->parsed()) return run_rtd(r);
    if (iflip->parsed()) return run_instant_flip(f);
    if (cert->parsed()) return run_certify(v);
    if (bench->parsed()) {
      std::vector<std::string> rest = bench->remaining();
      std::vector<char*> args = {argv[0]};
      for (std::string& s : rest) args.push_back(s.data());
      return flipflop::bench::run(static_cast<int>(args.size()), args.data());
    }
    if (demo->parsed()) return run_demo();
  } catch (const UsageError& e) {
    std::cerr << "flipflop: error: " << e.what() << "\n";
    return 2;
  } catch (const InternalError& e) {
    std::cerr << "flipflop: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "flipflop: error: " << e.what() << "\n";
    return 2;
  }
  return 2;
}

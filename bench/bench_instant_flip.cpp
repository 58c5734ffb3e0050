// bench_instant_flip.cpp — `flipflop bench instant-flip --dim d --n N --step s`:
// the in-place update RT(S ⊕ W) -> RT(S ⊕ U) by the monotonic instant flip
// with insertions (reference/rtd/dynamic_rt.hpp; issue 16) next to fresh
// constructions of RT(S ⊕ U), the choice a user has without it.
//
// Input (generation not timed): n points uniform in the unit cube of R^d,
// W uniform in [0, ½h²] with h = n^(-1/d) (the spacing of the points: a few
// per cent redundant), U = max(0, W + δ), δ uniform in [-s, s]·½h² — the
// step of an optimal-transport iteration. Rows:
//   flipflop:instant-flip        DynamicRegularTriangulation::set_weights(U), its
//                                scan on all cores (kernels_cpu/rtd/instant_flip.hpp)
//                                on RT(S ⊕ W) built before the timing (each
//                                run is restored by an untimed set_weights(W))
//   flipflop:reference:rt+1      a fresh RT+1 build of S ⊕ U (build_rtd)
//   cgal:regular_triangulation   a fresh CGAL build of S ⊕ U:
//                                Regular_triangulation_2 / _3 (spatially sorted
//                                range insertion), the dD Regular_triangulation
//                                for d = 4, 5
// Every row times the construction or update alone; the canonical output
// (canonical_d.hpp) is made after the timing and compared across rows
// (`identical`).
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "bench/compare.hpp"
#include "bench/timing.hpp"
#include "peers/cgal_regular_d.hpp"
#include "peers/peers.hpp"
#include "kernels_cpu/rtd/instant_flip.hpp"
#include "reference/rtd/dynamic_rt.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::bench::detail {

namespace {

using Simplices = std::vector<std::vector<Index>>;

struct Weights {
  PointSet pw, pu;  // the points with W and with U
};

Weights generate(const Args& a) {
  std::mt19937_64 rng(a.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  Weights g;
  g.pw.dim = a.dim;
  g.pw.weighted = true;
  g.pw.coords.resize(a.n * static_cast<std::size_t>(a.dim));
  for (double& x : g.pw.coords) x = unit(rng);
  const double h = std::pow(static_cast<double>(a.n), -1.0 / a.dim), half_h2 = 0.5 * h * h;
  g.pw.weights.resize(a.n);
  for (double& w : g.pw.weights) w = half_h2 * unit(rng);
  g.pu = g.pw;
  for (double& u : g.pu.weights) u = std::max(0.0, u + a.step * half_h2 * sym(rng));
  return g;
}

}  // namespace

int bench_instant_flip(const Args& a) {
  const Weights g = generate(a);
  const std::vector<double> w = g.pw.weights.to_vector(), u = g.pu.weights.to_vector();
  ref::DynamicRegularTriangulation rt(g.pw, w);  // the start: not timed
  double t_instant = 0, t_rt1 = 0, t_cgal = 0;
  ref::WeightUpdateStats last;
  std::vector<Peer<Simplices>> rows = {
      {"flipflop:instant-flip",
       [&](const PointSet&) {
         t_instant = seconds([&] { last = cpu::set_weights(rt, u, 0); });
         Simplices out = rt.simplices();
         cpu::set_weights(rt, w, 0);  // back to the start for the next run
         return out;
       },
       [&] { return t_instant; }},
      {"flipflop:reference:rt+1",
       [&](const PointSet& pu) {
         ref::rtd::TriangulationD T;
         t_rt1 = seconds([&] { T = ref::build_rtd(pu); });
         return ref::rtd::real_simplices(T);
       },
       [&] { return t_rt1; }},
      {"cgal:regular_triangulation",
       [&](const PointSet& pu) {
         if (pu.dim == 2) {
           Simplices out;
           for (const Triangle& t : peers::cgal_regular2(pu, &t_cgal)) out.push_back({t[0], t[1], t[2]});
           return out;
         }
         if (pu.dim == 3) return peers::cgal_regular_3(pu, nullptr, &t_cgal);
         return peers::cgal_regular_d(pu, nullptr, &t_cgal);
       },
       [&] { return t_cgal; }}};
  if (!a.csv) {
    std::printf("flipflop bench instant-flip: d %d, n %zu, step %g, seed %llu, median of %d runs\n", a.dim, a.n,
                a.step, a.seed, a.reps);
    std::printf("machine: %s\n", machine_line().c_str());
  }
  const int rc = compare_peers<Simplices>(a, g.pu, rows, "simplices");
  if (chosen(a, "flipflop:instant-flip"))
    std::fprintf(stderr,
                 "instant-flip: %llu flips (%llu insertions, %llu removals), %llu events popped, %llu ridges "
                 "and %llu points entered the moving model; SoS check: %llu ridges, %llu points, %llu flips%s\n",
                 static_cast<unsigned long long>(last.total_flips()),
                 static_cast<unsigned long long>(last.instant.inserted_vertices + last.repair_flips[1]),
                 static_cast<unsigned long long>(last.instant.removed_vertices + last.repair_removed),
                 static_cast<unsigned long long>(last.instant.pops),
                 static_cast<unsigned long long>(last.instant.initial_ridges),
                 static_cast<unsigned long long>(last.instant.initial_points),
                 static_cast<unsigned long long>(last.checked_ridges),
                 static_cast<unsigned long long>(last.checked_points),
                 static_cast<unsigned long long>(last.total_flips() - last.instant.total_flips()),
                 last.rebuilt ? (", rebuilt: " + last.rebuild_reason).c_str() : "");
  return rc;
}

}  // namespace flipflop::bench::detail

// hull3_check.cpp — fuzz_hull3: the 3D hull algorithms of reference/hull3
// (ffHull §6.4 Alg 7 + flip-flop §6.2 Alg 6; star splaying §3.3.2 from the
// initial stars of ch. 7; twist-flip §8.4.1 Algs 12-13 + flip-flop) against
// each other, the definition, the certifier and the strict view.
//
// A 3D point set of 1..24 points (fuzz_input.hpp: lattice points,
// cospherical points, duplicates, collinear and coplanar runs, ulp jitter,
// huge / tiny / subnormal magnitudes, power-of-two scalings). Checked:
//   * input that does not span R^3: every algorithm throws
//     std::invalid_argument (and nothing else);
//   * otherwise every algorithm returns, without throwing, the same
//     canonical triangles, equal to brute::hull3 (the definition, for
//     n <= 16), accepted by certify::hull3 at Level::canonical and
//     Level::exact;
//   * the counters obey their lemmas (as proptests' hull3_counts): ffHull
//     inserts or discards every point but its tetrahedron (4 + insertions +
//     discarded_early = n, insertions = flips_1_3), flip-flop removes a
//     vertex per 3-1 flip (V = 4 + insertions - flips_3_1 for ffHull,
//     V = n - flips_3_1 for twist-flip, whose polyhedron holds every point),
//     labels at most the vertices it removes; star splaying leaves exactly
//     the non-extreme points dead (dead_stars + V = n);
//   * the strict view of the answer (strict_hull3.hpp): every facet polygon
//     has at least three vertices, lies in one plane and has every input
//     point on its inner side (exact orient3d); its extreme points are
//     exactly the vertices of its facets, each the smallest index at its
//     location, and at each location some copy is a vertex of the SoS hull
//     (the perturbation picks among copies). (Equality with CGAL's extreme
//     points and merged facets is a property test: proptests/strict_*.)
// The multithreaded ffHull of kernels_cpu/hull3 (the cpu backend) is run at
// 1 and 2 threads and must equal the reference byte for byte (triangle for
// triangle), with ffHull's counters' lemmas, and reject the same inputs; so
// must the data-parallel ffHull of kernels_cuda/hull3 in its OpenMP build
// (kernels_omp, FLIPFLOP_HAVE_KERNELS_OMP), and gHull (kernels_cuda/hull3/
// ghull.hpp) on a 4-pixel and the default grid.
// When the build has the by-name entry point (reference/hull3/hull3.hpp,
// part flipflop_hull3; FLIPFLOP_FUZZ_HULL3_BY_NAME) the algorithms are run
// through ref::hull3(ps, name), whose list must be exactly these three.
#include <algorithm>
#include <exception>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
#include "kernels_cuda/hull3/ghull.hpp"
#include "kernels_cuda/hull3/hull3.hpp"
#endif
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/strict_hull3.hpp"
#include "reference/hull3/twist_flip.hpp"
#ifdef FLIPFLOP_FUZZ_HULL3_BY_NAME
#include "reference/hull3/hull3.hpp"
#endif

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_hull3";
constexpr std::size_t kMaxPoints = 24;
constexpr std::size_t kMaxBrute = 16;

using Tris = std::vector<Triangle>;

struct Algorithm {
  const char* name;
  Tris (*run)(const PointSet&, ref::Hull3Stats*);
};

const Algorithm kAlgorithms[] = {
    {"ffhull", [](const PointSet& ps, ref::Hull3Stats* st) { return ref::hull3_ffhull(ps, st); }},
    {"splay", [](const PointSet& ps, ref::Hull3Stats* st) { return ref::hull3_splay(ps, st); }},
    {"twist-flip", [](const PointSet& ps, ref::Hull3Stats* st) { return ref::hull3_twist_flip(ps, st); }},
};

int orient_exact(const PointSet& ps, Index a, Index b, Index c, Index d) {
  return pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d));
}

std::size_t vertex_count(const Tris& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return v.size();
}

// The counters' lemmas (header comment).
void check_counts(const PointSet& ps, const std::string& algo, const ref::Hull3Stats& st, std::size_t V) {
  const std::size_t n = ps.size();
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok) fail(kTarget, algo + ": counters: " + what, describe(ps));
  };
  if (algo == "ffhull") {
    expect(st.insertions == st.flips_1_3, "insertions != 1-3 flips");
    expect(4 + st.insertions + st.discarded_early == n, "4 + insertions + discarded_early != n");
    expect(4 + st.insertions == V + st.flips_3_1, "4 + insertions - 3-1 flips != hull vertices");
    expect(st.labelled_non_extreme <= st.flips_3_1, "more labelled than removed vertices");
  } else if (algo == "twist-flip") {
    expect(V + st.flips_3_1 == n, "n - 3-1 flips != hull vertices");
    expect(st.flips_1_3 + st.insertions + st.discarded_early == 0, "points inserted or discarded");
    expect(st.labelled_non_extreme <= st.flips_3_1, "more labelled than removed vertices");
  } else if (algo == "splay") {
    expect(st.dead_stars + V == n, "dead stars + hull vertices != n");
    expect(st.flips_2_2 + st.flips_3_1 + st.flips_1_3 == 0, "flips counted");
  }
}

// The strict view must consist of planar polygons whose planes have every
// input point on the inner side (closed), with at least three vertices, every
// vertex listed among the extreme points, and the extreme points must be
// exactly the vertices used by the facets.
void check_strict(const PointSet& ps, const Tris& answer) {
  const ref::StrictHull3 s = ref::strict_hull3(ps, answer);
  std::set<Index> used;
  for (const auto& f : s.facets) {
    if (f.size() < 3) fail(kTarget, "strict facet with fewer than 3 vertices", describe(ps));
    for (Index v : f) used.insert(v);
    // the plane of the facet: its first three vertices are not collinear in
    // a strictly convex polygon; every vertex lies in that plane and every
    // input point on its inner side (orient3d >= 0 for CCW-from-outside).
    for (Index v : f)
      if (orient_exact(ps, f[0], f[1], f[2], v) != 0) fail(kTarget, "strict facet not planar", describe(ps));
    for (Index p = 0; p < ps.size(); ++p)
      if (orient_exact(ps, f[0], f[1], f[2], p) < 0)
        fail(kTarget, "a point lies outside a strict facet's plane", describe(ps));
  }
  const std::set<Index> extreme(s.extreme_points.begin(), s.extreme_points.end());
  if (extreme != used) fail(kTarget, "strict extreme points differ from the strict facets' vertices", describe(ps));
  // Each extreme point is the smallest index at its location, and some index
  // at that location (not necessarily the smallest: the perturbation picks
  // among copies) is a vertex of the SoS hull.
  auto same = [&](Index a, Index b) { return std::equal(ps.point(a), ps.point(a) + 3, ps.point(b)); };
  std::set<Index> hull;
  for (const Triangle& t : answer) hull.insert(t.begin(), t.end());
  for (Index v : s.extreme_points) {
    for (Index u = 0; u < v; ++u)
      if (same(u, v)) fail(kTarget, "a strict extreme point is not the smallest index at its location", describe(ps));
    bool located = false;
    for (Index u : hull) located |= same(u, v);
    if (!located) fail(kTarget, "no vertex of the SoS hull at a strict extreme point", describe(ps));
  }
}

// The algorithms with their names: ref::hull3 by name when built (which
// must list exactly the algorithms above: a new one needs its counters'
// lemmas here), else the functions above.
std::vector<std::pair<std::string, std::function<Tris(const PointSet&, ref::Hull3Stats*)>>> entry_points() {
  std::vector<std::pair<std::string, std::function<Tris(const PointSet&, ref::Hull3Stats*)>>> out;
#ifdef FLIPFLOP_FUZZ_HULL3_BY_NAME
  std::vector<std::string> names;
  for (const Algorithm& a : kAlgorithms) names.push_back(a.name);
  if (ref::hull3_algorithms() != names) fail(kTarget, "ref::hull3_algorithms() lists other algorithms");
  for (const std::string& name : names)
    out.emplace_back(name, [name](const PointSet& ps, ref::Hull3Stats* st) { return ref::hull3(ps, name, st); });
#else
  for (const Algorithm& a : kAlgorithms) out.emplace_back(a.name, a.run);
#endif
  return out;
}

// The parallel backends that must equal the reference: the cpu backend at
// 1 and 2 threads, and kernels_omp when built.
std::vector<std::pair<std::string, std::function<Tris(const PointSet&, ref::Hull3Stats*)>>> backends() {
  std::vector<std::pair<std::string, std::function<Tris(const PointSet&, ref::Hull3Stats*)>>> out;
  for (int threads : {1, 2})
    out.emplace_back("cpu (" + std::to_string(threads) + " threads)", [threads](const PointSet& ps, ref::Hull3Stats* st) {
      cpu::Hull3Options o;
      o.threads = threads;
      return cpu::hull3_ffhull(ps, o, st);
    });
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  out.emplace_back("kernels_omp", [](const PointSet& ps, ref::Hull3Stats* st) { return kernels_omp::hull3_ffhull(ps, st); });
#endif
  return out;
}

}  // namespace

bool check_hull3_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  PointSet ps;
  if (!decode_points(r, 3, false, 1, kMaxPoints, ps)) return false;
  static const auto entries = entry_points();

  if (affine_dimension(ps) < 3) {
    for (const auto& [name, run] : entries) {
      try {
        const Tris t = run(ps, nullptr);
        fail(kTarget, name + " returned a hull of lower-dimensional input", describe(ps) + describe(t));
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail(kTarget, name + " threw the wrong exception on lower-dimensional input: " + e.what(), describe(ps));
      }
    }
    for (const auto& [name, run] : backends()) {
      try {
        const Tris t = run(ps, nullptr);
        fail(kTarget, name + " returned a hull of lower-dimensional input", describe(ps) + describe(t));
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail(kTarget, name + " threw the wrong exception on lower-dimensional input: " + e.what(), describe(ps));
      }
    }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
    try {
      const Tris t = kernels_omp::hull3_ghull(ps);
      fail(kTarget, "kernels_omp ghull returned a hull of lower-dimensional input", describe(ps) + describe(t));
    } catch (const std::invalid_argument&) {
    } catch (const std::exception& e) {
      fail(kTarget, std::string("kernels_omp ghull threw the wrong exception on lower-dimensional input: ") + e.what(),
           describe(ps));
    }
#endif
    return true;
  }

  Tris answer;
  bool first = true;
  for (const auto& [name, run] : entries) {
    Tris got;
    ref::Hull3Stats st;
    try {
      got = run(ps, &st);
    } catch (const std::exception& e) {
      fail(kTarget, name + " threw: " + e.what(), describe(ps));
    }
    if (first) answer = got;
    else if (got != answer)
      fail(kTarget, name + " differs from ffhull", describe(ps) + name + " " + describe(got) + "\nffhull " + describe(answer));
    first = false;
    check_counts(ps, name, st, vertex_count(answer));
  }
  for (const auto& [name, run] : backends()) {
    Tris got;
    ref::Hull3Stats st;
    try {
      got = run(ps, &st);
    } catch (const std::exception& e) {
      fail(kTarget, name + " threw: " + e.what(), describe(ps));
    }
    if (got != answer)
      fail(kTarget, name + " differs from ffhull", describe(ps) + name + " " + describe(got) + "\nffhull " + describe(answer));
    check_counts(ps, "ffhull", st, vertex_count(answer));
    if (st.handed_back != 0) fail(kTarget, name + " handed work back to the host (issue 36)", describe(ps));
  }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  // gHull (kernels_cuda/hull3/ghull.hpp) on a coarse and the default digital
  // space: the same triangles; every hull vertex is in CH(S'), added or
  // found by the verification; no work handed back (issue 36)
  for (const std::uint32_t grid : {4u, 0u}) {
    kernels::GhullOptions o;
    o.grid = grid;
    kernels::GhullStats gs;
    Tris got;
    try {
      got = kernels_omp::hull3_ghull(ps, o, &gs);
    } catch (const std::exception& e) {
      fail(kTarget, std::string("kernels_omp ghull threw: ") + e.what(), describe(ps));
    }
    if (got != answer)
      fail(kTarget, "kernels_omp ghull (grid " + std::to_string(grid) + ") differs from ffhull",
           describe(ps) + "ghull " + describe(got) + "\nffhull " + describe(answer));
    if (gs.handed_back != 0 || gs.approx_vertices + gs.added + gs.depth_misses < vertex_count(answer) ||
        gs.captured > ps.size() || gs.added > gs.depth_candidates)
      fail(kTarget, "kernels_omp ghull's counters are inconsistent", describe(ps));
  }
#endif
  if (ps.size() <= kMaxBrute && brute::hull3(ps) != answer)
    fail(kTarget, "ffhull differs from brute::hull3", describe(ps) + describe(answer));
  for (auto level : {certify::Level::canonical, certify::Level::exact}) {
    const certify::Report rep = certify::hull3(ps, answer, level);
    if (!rep.ok)
      fail(kTarget, std::string("certify::hull3 rejected the answer: ") + rep.message(), describe(ps) + describe(answer));
  }
  check_strict(ps, answer);
  return true;
}

}  // namespace flipflop::fuzz

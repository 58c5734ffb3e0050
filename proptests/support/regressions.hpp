// regressions.hpp — the named checks of the property suite and the files that
// keep their failures.
//
// A *check* is a function (points, params) -> Outcome (pass / fail with a
// message / skip when its precondition does not hold). Every property of
// proptests/invariance_test.cpp is one check run on generated input
// (support/families.hpp), and proptests/regression_test.cpp replays every
// saved input through every check of its dimension. The checks, for every
// algorithm and backend present (the property letters are those of issue 6):
//
//   hull2_canonical  (a)(b) every ref::hull2 algorithm (twist only up to 300
//                    points: Θ(n^2)), the cpu backend (kernels_cpu/hull2)
//                    and brute::hull2 (n <= 40) return
//                    byte-identical canonical text, certified at
//                    Level::canonical; CGAL's hulls are certified at
//                    Level::exact (a peer is not SoS-canonical). Input that
//                    does not span the plane is rejected by every algorithm.
//   hull2_scale      (c) the same output after x -> 2^k x.
//   hull2_translate  (c) integer input in general position: the same output
//                    after an integer translation.
//   hull2_permute    (c) input in general position: permuting the input
//                    permutes the output (mapped back: the same).
//   hull2_counts     (d) the counters obey their lemmas (see the check).
//   rt2_*            the same for the 2D regular / Delaunay triangulations
//                    (reference/rt2/rt2.hpp: ffRT, flip-flop, Lawson; brute::rt2
//                    for n <= 12; CGAL at Level::exact), when rt2.hpp exists.
//   hull3_canonical, hull3_scale, hull3_translate, hull3_permute: the same
//                    for the 3D hull: ffHull, star splaying and twist-flip
//                    (reference/hull3, when the test links them) and
//                    brute::hull3 (n <= 12); CGAL certified at Level::exact
//                    and equal on input in general position; the cpu
//                    kernel's witness passes cpu::certify_hull3_witnessed.
//   hull3_counts     (d) ffHull's, twist-flip's and star splaying's counters,
//                    and flip-flop in random orders from several star-shaped
//                    polyhedra (see the check).
//   rtd_*            the same for the d-dimensional regular triangulation
//                    (d = 2..5; reference/rtd: RT+1 rtd_incremental and
//                    build_rtd, rt2_ffrt for d = 2, the definition brute_rtd
//                    for small n), certified by certify::rtd; general
//                    position means no d+1 points on a hyperplane and no d+2
//                    lifted points on one, exactly.
//   instant_flip_canonical, instant_flip_scale: the instant flip (§9.2.1,
//                    Alg 14) from RT(S ⊕ W) to target weights U drawn from
//                    the seed: RT(S ⊕ U) where no point reappears, Lemma 9.4
//                    along the run, the counters; invariant when x -> 2^k x,
//                    W, U -> 2^2k W, U (see the checks).
// A check applies to one dimension or a range (NamedCheck::applies).
//   classify2, classify3: kernels_cpu (TBB) and kernels_omp (when built) equal
//                    a Mode::gmp loop, also after scaling, permutation and
//                    (integer input) translation.
//
// Why scaling by 2^k preserves every answer (also on degenerate input).
// x -> s·x with s = 2^k is exact in binary64 as long as no value leaves the
// normal range (exact_scale_range); a weight w -> s^2·w is exact likewise, and
// then the lifted height |s x|^2 - s^2 w = s^2 (|x|^2 - w) scales by s^2
// exactly. Every predicate is the sign of det Λ (predicates.hpp) whose column
// j holds, in every row, coordinate j of the point: the scaled Λ-matrix is Λ
// with column j multiplied by c_j > 0 (s for a coordinate, s^2 for the lifted
// height, 1 for the constant column). Each term of the SoS expansion,
// cof_T = ± det of Λ with the rows and columns of the matching T deleted, is a
// minor whose column set C gives it the factor Π_{j∈C} c_j > 0: every term
// keeps its sign, and the dominance order of the terms depends only on point
// indices and column numbers, so the first non-zero term — and the perturbed
// sign — is the same. Kernel points (exact affine combinations of inputs)
// scale with the input. So every decision of every algorithm is the same and
// the output is identical, degenerate input included. (Floating-point
// heuristics, such as Graham-insertion's "furthest point", may choose
// differently after overflow; the output may not depend on them.)
//
// Why translation and permutation need general position. Translating is a
// column operation on Λ (add t_j times the constant column to column j): det Λ
// is unchanged but the minors that delete the constant column are not, so SoS
// terms change; and SoS is keyed by index, so a permutation changes which
// term dominates. On degenerate input the answer legitimately depends on
// frame and order (DESIGN.md). In general position — every exact orient2d of
// three points, power2d of four (triangulations) and orient3d of four (3D) is
// non-zero (in R^d: orient_d of d+1 points and power_d of d+2), checked
// exactly — no answer consults the perturbation, so the
// output is the exact geometric answer: invariant and equivariant.
//
// Saving. check_or_save(outcome, points, property, params), called inside a
// RapidCheck property, discards the case on `skip` and, on `fail`, writes the
// input as FLIPFLOP_SOURCE_DIR/proptests/regressions/<property>/<hash>.xyz
// (or under $FLIPFLOP_REGRESSIONS_DIR) before failing the case. The file is
// one '#' header line "flipflop-regression property=... dim=... weighted=...
// scale=... shift=...,...,... seed=..." (the check's parameters) followed by
// io::write_points (shortest round-trip decimals: read back bit for bit);
// <hash> is FNV-1a of the whole text. While RapidCheck shrinks, every failing
// candidate replaces the file this process wrote last for that property, so
// what stays is the minimal counterexample (the last failing evaluation). A
// file that already existed is never removed.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/io.hpp"
#include "kernels_cpu/classify_tbb.hpp"
#include "kernels_cuda/classify.hpp"
#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3_stats.hpp"
#include "reference/rtd/canonical_d.hpp"
#if __has_include("reference/rt2/rt2.hpp") && __has_include("reference/rt2/ffrt.hpp") && \
    __has_include("reference/rt2/flip_flop_2d.hpp")
#define FLIPFLOP_TEST_HAVE_RT2 1
#include "reference/rt2/ffrt.hpp"
#include "reference/rt2/flip_flop_2d.hpp"
#include "reference/rt2/rt2.hpp"
#endif
// The reference parts (reference/hull3, reference/rtd: libraries of their
// own, always linked through flipflop_all).
#define FLIPFLOP_TEST_HAVE_HULL3 1
#define FLIPFLOP_TEST_HAVE_RTD 1
#ifdef FLIPFLOP_TEST_HAVE_HULL3
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/rational_kernel.hpp"
#include "reference/hull3/twist_flip.hpp"
// the multithreaded hulls (kernels_cpu/hull2, kernels_cpu/hull3, linked through flipflop_all)
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#endif
#ifdef FLIPFLOP_TEST_HAVE_RTD
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "rtd_brute.hpp"
#include "rtd_oracles.hpp"
#endif

namespace flipflop::test {

// ============================================================================
// Outcomes and parameters
// ============================================================================

struct Outcome {
  enum class Kind { pass, fail, skip };
  Kind kind = Kind::pass;
  std::string message;
  static Outcome pass() { return {}; }
  static Outcome fail(std::string m) { return {Kind::fail, std::move(m)}; }
  static Outcome skip(std::string m) { return {Kind::skip, std::move(m)}; }
};

// The random choices of a check besides its points.
struct Params {
  int scale = 0;                         // k: coordinates x 2^k, weights x 2^(2k) (clamped, see scale_exponent)
  std::array<std::int64_t, 3> shift{};  // integer translation, |t| <= 2^20 (coordinate j: shift[j % 3])
  std::uint64_t seed = 0;                // permutation, flip orders, facets of the classification
};

inline void showValue(const Params& p, std::ostream& os) {
  os << "scale=" << p.scale << " shift=" << p.shift[0] << "," << p.shift[1] << "," << p.shift[2] << " seed=" << p.seed;
}

// Fails the enclosing check with a message built by <<.
#define FF_EXPECT(cond, msg)                                 \
  do {                                                       \
    if (!(cond)) {                                           \
      std::ostringstream ff_os_;                             \
      ff_os_ << msg << " [line " << __LINE__ << "]";         \
      return ::flipflop::test::Outcome::fail(ff_os_.str());  \
    }                                                        \
  } while (0)

// ============================================================================
// Transformations
// ============================================================================

// The exponents k for which x·2^k is exact for every coordinate and w·2^(2k)
// for every weight, and no normal value leaves the normal range: for a normal
// v = m·2^e (e = ilogb v), -1022 <= e + k <= 1023. A subnormal v is exact
// when scaled up (k >= 0) and not beyond 2^1023. 0 scales to 0.
inline std::pair<int, int> exact_scale_range(const PointSet& ps) {
  int lo = -100000, hi = 100000;
  auto bound = [&](double v, int factor) {  // v · 2^(factor·k) must be exact and in range
    if (v == 0) return;
    const int e = std::ilogb(v);
    const int l = std::fabs(v) >= DBL_MIN ? -1022 - e : 0, h = 1023 - e;  // factor·k in [l, h]
    lo = std::max(lo, factor == 1 ? l : (l >= 0 ? (l + 1) / 2 : -((-l) / 2)));
    hi = std::min(hi, factor == 1 ? h : (h >= 0 ? h / 2 : -((-h + 1) / 2)));
  };
  for (double x : ps.coords) bound(x, 1);
  if (ps.weighted)
    for (double w : ps.weights) bound(w, 2);
  return {lo, hi};
}

// k clamped into exact_scale_range (which always holds 0).
inline int scale_exponent(const PointSet& ps, int k) {
  const auto [lo, hi] = exact_scale_range(ps);
  return std::min(std::max(k, lo), hi);
}

inline PointSet scaled(const PointSet& ps, int k) {
  PointSet out = ps;
  for (double& x : out.coords) x = std::ldexp(x, k);
  for (double& w : out.weights) w = std::ldexp(w, 2 * k);
  return out;
}

// All coordinates integers of magnitude at most 2^52 (so that adding a shift
// of magnitude at most 2^20 is exact).
inline bool integer_input(const PointSet& ps) {
  for (double x : ps.coords)
    if (x != std::trunc(x) || std::fabs(x) > 0x1p52) return false;
  return true;
}

// Coordinates + shift (weights unchanged: the power distance is translation
// invariant — the lifted heights undergo an affine map that keeps every
// orientation of lifted points). Precondition: integer_input.
inline PointSet translated(const PointSet& ps, const std::array<std::int64_t, 3>& t) {
  PointSet out = ps;
  const auto d = static_cast<std::size_t>(ps.dim);
  for (std::size_t i = 0; i < out.coords.size(); ++i) out.coords[i] += static_cast<double>(t[i % d % 3]);
  return out;
}

// perm[j] = the input index placed at position j (Fisher–Yates with
// std::mt19937_64, whose sequence the standard fixes).
inline std::vector<Index> permutation(std::size_t n, std::uint64_t seed) {
  std::vector<Index> p(n);
  std::iota(p.begin(), p.end(), Index{0});
  std::mt19937_64 rng(seed);
  for (std::size_t i = n; i > 1; --i) std::swap(p[i - 1], p[rng() % i]);
  return p;
}

inline PointSet permuted(const PointSet& ps, const std::vector<Index>& perm) {
  PointSet out;
  out.dim = ps.dim;
  out.weighted = ps.weighted;
  for (Index i : perm) {
    out.coords.insert(out.coords.end(), ps.point(i), ps.point(i) + ps.dim);
    if (ps.weighted) out.weights.push_back(ps.weights[i]);
  }
  return out;
}

inline std::vector<Index> map_back(std::vector<Index> v, const std::vector<Index>& perm) {
  for (Index& i : v) i = perm[i];
  return canonical_hull2(v);
}
inline std::vector<Triangle> map_back(std::vector<Triangle> v, const std::vector<Index>& perm) {
  for (Triangle& t : v)
    for (Index& i : t) i = perm[i];
  return canonical_triangles(v);
}
inline std::vector<std::vector<Index>> map_back(std::vector<std::vector<Index>> v, const std::vector<Index>& perm) {
  for (auto& t : v)
    for (Index& i : t) i = perm[i];
  return canonical_simplices(std::move(v), Orientation::volume);  // the same points in the same order: still positive
}

// ============================================================================
// Exact general position
// ============================================================================

inline bool spans(const PointSet& ps) { return dimension_problem(ps).empty(); }

// No three points collinear (orient2d_exact != 0); with `power`, also no four
// on a common orthocircle (power2d_exact != 0; cocircular for zero weights).
inline bool general_position_2d(const PointSet& ps, bool power) {
  const std::size_t n = ps.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) {
        if (pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)) == 0) return false;
        if (!power) continue;
        for (std::size_t d = c + 1; d < n; ++d) {
          auto W = [&](std::size_t i) { return pred::WPt{i, ps.point(i), ps.weight(i)}; };
          if (pred::power2d_exact(W(a), W(b), W(c), W(d)) == 0) return false;
        }
      }
  return true;
}

// No four points coplanar.
inline bool general_position_3d(const PointSet& ps) {
  const std::size_t n = ps.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d)
          if (pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d)) == 0) return false;
  return true;
}

// ============================================================================
// Output as text (what "byte-identical" compares)
// ============================================================================

inline std::string text(const std::vector<Index>& cycle) {
  std::ostringstream os;
  io::write_hull2(os, cycle);
  return os.str();
}
inline std::string text(const std::vector<Triangle>& tris) {
  std::ostringstream os;
  io::write_triangles(os, tris);
  return os.str();
}
// d-dimensional simplices (canonical_d.hpp)
using Simplices = std::vector<std::vector<Index>>;
inline std::string text(const Simplices& s) { return simplices_text(s); }

inline std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s.size() > 400 ? s.substr(0, 400) + "..." : s;
}

// ============================================================================
// 2D hulls
// ============================================================================

struct Hull2Algorithm {
  std::string name;
  std::function<std::vector<Index>(const PointSet&, ref::Hull2Stats*)> run;
};

inline constexpr std::size_t kTwistMax = 300;      // twist is Θ(n^2)
inline constexpr std::size_t kBruteHull2Max = 40;  // brute::hull2 is O(n^3)

// Every reference 2D hull algorithm (ref::hull2_algorithms(): new ones join
// automatically), the cpu backend (kernels_cpu/hull2, 2 threads, its
// throw-away forced with a 16-point sample and flip-pop chunks of 3 so that
// small inputs reach every stage) and brute::hull2 for small n.
inline std::vector<Hull2Algorithm> hull2_algorithms(std::size_t n) {
  std::vector<Hull2Algorithm> out;
  for (const std::string& name : ref::hull2_algorithms())
    if (name != "twist" || n <= kTwistMax)
      out.push_back({name, [name](const PointSet& ps, ref::Hull2Stats* st) { return ref::hull2(ps, name, st); }});
  out.push_back({"cpu", [](const PointSet& ps, ref::Hull2Stats* st) {
                   cpu::Hull2Options o;
                   o.threads = 2;
                   o.throw_away_from = 0;
                   o.sample = 16;
                   o.scan_chunk = 3;
                   return cpu::hull2_graham_sort(ps, o, st);
                 }});
  if (n <= kBruteHull2Max)
    out.push_back({"brute", [](const PointSet& ps, ref::Hull2Stats*) { return brute::hull2(ps); }});
  return out;
}

// A transformation check: every algorithm on `ps` and on `other`; the outputs
// on `other` mapped back by `back` must equal those on `ps`.
template <typename Algorithms, typename Back>
Outcome same_answers(const Algorithms& algos, const PointSet& ps, const PointSet& other, Back back,
                     const char* what) {
  for (const auto& a : algos) {
    const std::string x = text(a.run(ps, nullptr));
    const std::string y = text(back(a.run(other, nullptr)));
    FF_EXPECT(x == y, a.name << ": output changes under " << what << ": " << one_line(x) << " vs " << one_line(y));
  }
  return Outcome::pass();
}

// Every algorithm (but those `skip` names) rejects input that does not span
// the plane with std::invalid_argument.
template <class Algos, class Skip>
Outcome expect_flat_input_rejected(const PointSet& ps, const Algos& algos, Skip skip) {
  for (const auto& a : algos) {
    if (skip(a)) continue;
    bool threw = false;
    try {
      a.run(ps, nullptr);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    FF_EXPECT(threw, a.name << ": input that does not span the plane was not rejected");
  }
  return Outcome::pass();
}

inline Outcome hull2_canonical(const PointSet& ps, const Params&) {
  const auto algos = hull2_algorithms(ps.size());
  if (!spans(ps))  // brute: defined under SoS for any input; not an algorithm's contract
    return expect_flat_input_rejected(ps, algos, [](const auto& a) { return a.name == "brute"; });
  std::string first;
  for (const auto& a : algos) {
    const auto h = a.run(ps, nullptr);
    const std::string t = text(h);
    if (first.empty()) {
      first = t;
      const certify::Report r = certify::hull2(ps, h, certify::Level::canonical);
      FF_EXPECT(r.ok, a.name << ": not certified canonical: " << r.message());
    }
    FF_EXPECT(t == first, a.name << " differs from " << algos.front().name << ": " << one_line(t) << " vs "
                                 << one_line(first));
  }
  for (auto algo : {peers::Hull2Algo::akl_toussaint, peers::Hull2Algo::graham_andrew}) {
    const certify::Report r = certify::hull2(ps, peers::cgal_hull2(ps, algo), certify::Level::exact);
    FF_EXPECT(r.ok, "CGAL 2D hull not certified exact: " << r.message());
  }
  return Outcome::pass();
}

inline Outcome hull2_scale(const PointSet& ps, const Params& p) {
  if (!spans(ps)) return Outcome::skip("does not span the plane");
  const int k = scale_exponent(ps, p.scale);
  return same_answers(hull2_algorithms(ps.size()), ps, scaled(ps, k), [](auto v) { return v; },
                      ("scaling by 2^" + std::to_string(k)).c_str());
}

inline Outcome hull2_translate(const PointSet& ps, const Params& p) {
  if (!integer_input(ps)) return Outcome::skip("not integer input");
  if (!spans(ps) || !general_position_2d(ps, false)) return Outcome::skip("not in general position");
  return same_answers(hull2_algorithms(ps.size()), ps, translated(ps, p.shift), [](auto v) { return v; },
                      "integer translation");
}

inline Outcome hull2_permute(const PointSet& ps, const Params& p) {
  if (!spans(ps) || !general_position_2d(ps, false)) return Outcome::skip("not in general position");
  const auto perm = permutation(ps.size(), p.seed);
  return same_answers(hull2_algorithms(ps.size()), ps, permuted(ps, perm),
                      [&](const auto& v) { return map_back(v, perm); }, "a permutation of the input");
}

// The counters' lemmas (thesis ch. 4, §8.3), and flip-pop in a random order:
//   every algorithm: hull_vertices = |output|, input_vertices = n, and
//     flips_2_1 + hull_vertices = polygon_vertices (each 2-1 flip removes one
//     polygon vertex for good, Alg 1; the survivors are the hull);
//   graham-sort: the polygon holds every point (Alg 3 line 6);
//   graham-insert: insertions + discarded_early + 2 = n (every point other
//     than v_l, v_r is inserted or proved interior, Alg 4) and the polygon is
//     v_l, v_r and the inserted points;
//   twist: twists = inversions of the input order <0..n-1> w.r.t. the angle
//     around the kernel point (Thm 8.1: bubble sort), polygon = all points;
//   flip-pop from the angular polygon, taking a random applicable flip each
//     time: a removed vertex is never on the polygon again, the polygon stays
//     star-shaped, flips = n - |hull|, and the result is the hull.
inline Outcome hull2_counts(const PointSet& ps, const Params& p) {
  if (!spans(ps)) return Outcome::skip("does not span the plane");
  const std::size_t n = ps.size();
  std::vector<Index> hull;
  for (const auto& a : hull2_algorithms(n)) {
    if (a.name == "brute") continue;
    ref::Hull2Stats st;
    const auto h = a.run(ps, &st);
    hull = h;
    FF_EXPECT(st.hull_vertices == h.size(), a.name << ": hull_vertices " << st.hull_vertices << " != " << h.size());
    FF_EXPECT(st.input_vertices == n, a.name << ": input_vertices " << st.input_vertices);
    FF_EXPECT(st.flips_2_1 + st.hull_vertices == st.polygon_vertices,
              a.name << ": flips " << st.flips_2_1 << " + hull " << st.hull_vertices << " != polygon "
                     << st.polygon_vertices);
    if (a.name == "graham-sort" || a.name == "twist")
      FF_EXPECT(st.polygon_vertices == n, a.name << ": polygon of " << st.polygon_vertices << " of " << n << " points");
    if (a.name == "cpu")  // every point is thrown away or goes into the chains' polygon
      FF_EXPECT(st.discarded_early + st.polygon_vertices == n,
                "cpu: discarded " << st.discarded_early << " + polygon " << st.polygon_vertices << " != " << n);
    if (a.name == "graham-insert") {
      FF_EXPECT(st.insertions + st.discarded_early + 2 == n,
                "graham-insert: inserted " << st.insertions << " + dropped " << st.discarded_early << " + 2 != " << n);
      FF_EXPECT(st.insertions + 2 == st.polygon_vertices, "graham-insert: polygon " << st.polygon_vertices);
    }
    if (a.name == "twist") {
      const ref::StarKernel k(ps, ref::interior_kernel(ps));
      std::size_t inversions = 0;
      for (Index i = 0; i < n; ++i)
        for (Index j = i + 1; j < n; ++j) inversions += k.angle_less(j, i);
      FF_EXPECT(st.twists == inversions, "twist: " << st.twists << " twists, " << inversions << " inversions");
    }
  }
  // flip-pop in a random order
  const pred::RationalPoint s = ref::interior_kernel(ps);
  const ref::StarKernel k(ps, s);
  std::vector<Index> star(n);
  std::iota(star.begin(), star.end(), Index{0});
  std::sort(star.begin(), star.end(), [&](Index a, Index b) { return k.angle_less(a, b); });
  ref::FlipPop fp(k, star);
  std::mt19937_64 rng(p.seed);
  std::vector<Index> removed;
  for (auto cand = fp.applicable(); !cand.empty(); cand = fp.applicable()) {
    const Index v = cand[rng() % cand.size()];
    fp.apply(v);
    removed.push_back(v);
    for (Index r : removed) FF_EXPECT(!fp.on_polygon(r), "flip-pop: removed vertex " << r << " is back on the polygon");
    FF_EXPECT(removed.size() <= n - 3, "flip-pop: more flips than the polygon allows");
  }
  FF_EXPECT(fp.structure_holds(), "flip-pop: the polygon is no longer star-shaped");
  FF_EXPECT(removed.size() + hull.size() == n, "flip-pop: " << removed.size() << " flips, hull " << hull.size());
  FF_EXPECT(canonical_hull2(fp.polygon()) == hull, "flip-pop in a random order: " << one_line(text(fp.polygon())));
  return Outcome::pass();
}

// ============================================================================
// 2D regular / Delaunay triangulations
// ============================================================================
#ifdef FLIPFLOP_TEST_HAVE_RT2

inline constexpr std::size_t kBruteRt2Max = 12;  // brute::rt2 is O(n^4)

inline bool zero_weights(const PointSet& ps) {
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (ps.weight(i) != 0) return false;
  return true;
}

inline PointSet without_weights(PointSet ps) {
  ps.weighted = false;
  ps.weights.clear();
  return ps;
}

// The fan of the (SoS) hull polygon from its first vertex: a triangulation of
// conv(S) whose vertices are the hull vertices; triangles along collinear
// boundary points are flat but positive under the perturbation.
inline std::vector<Triangle> hull_fan(const PointSet& ps) {
  const auto h = ref::hull2_graham_sort(ps);
  std::vector<Triangle> out;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) out.push_back({h[0], h[i], h[i + 1]});
  return out;
}

// A triangulation of all points, independent of the reference: the sweep by
// perturbed x (pred::compare_sos), each point joined to the edges of the
// current hull it sees (orient2d < 0), as in Graham's / Andrew's scans.
inline std::vector<Triangle> sweep_triangulation(const PointSet& ps) {
  const Index n = static_cast<Index>(ps.size());
  auto P = [&](Index i) { return pred::Pt{i, ps.point(i)}; };
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return pred::compare_sos(P(a), P(b), 0) < 0; });
  std::vector<Index> H = {order[0], order[1], order[2]};  // counter-clockwise hull
  if (pred::orient2d(P(H[0]), P(H[1]), P(H[2])) < 0) std::swap(H[1], H[2]);
  std::vector<Triangle> out = {{H[0], H[1], H[2]}};
  for (Index k = 3; k < n; ++k) {
    const Index p = order[k];
    const std::size_t m = H.size();
    std::vector<char> vis(m);
    for (std::size_t i = 0; i < m; ++i) vis[i] = pred::orient2d(P(H[i]), P(H[(i + 1) % m]), P(p)) < 0;
    std::size_t first = 0;  // the first visible edge of the visible chain
    while (!(vis[first] && !vis[(first + m - 1) % m])) ++first;
    std::size_t last = first;
    while (vis[(last + 1) % m]) last = (last + 1) % m;
    std::vector<Index> next = {H[first], p};
    for (std::size_t i = first;; i = (i + 1) % m) {
      out.push_back({H[(i + 1) % m], H[i], p});
      if (i == last) break;
    }
    for (std::size_t i = (last + 1) % m; i != first; i = (i + 1) % m) next.push_back(H[i]);
    H = next;
  }
  return canonical_triangles(out);
}

struct Rt2Algorithm {
  std::string name;
  std::function<std::vector<Triangle>(const PointSet&, ref::Rt2Stats*)> run;
  // the triangulation it starts from (empty: ffRT's initial triangle of three points)
  std::function<std::vector<Triangle>(const PointSet&)> initial;
};

// Every reference algorithm that applies to the input, the cpu backend, and
// brute::rt2 for small n. Lawson from a triangulation of all points is not here: it may
// legitimately fail (rt2_counts / rt2_canonical check it separately).
inline std::vector<Rt2Algorithm> rt2_algorithms(const PointSet& ps) {
  using ref::FlipFlopVariant;
  std::vector<Rt2Algorithm> out = {
      {"ffrt", [](const PointSet& q, ref::Rt2Stats* st) { return ref::rt2_ffrt(q, st); }, nullptr},
      {"ffrt v-first",
       [](const PointSet& q, ref::Rt2Stats* st) { return ref::rt2_ffrt(q, st, FlipFlopVariant::v_first); }, nullptr},
      {"flip-flop from the hull fan",
       [](const PointSet& q, ref::Rt2Stats* st) { return ref::flip_flop(q, hull_fan(q), FlipFlopVariant::combined, st); },
       hull_fan},
      {"flip-flop v-first from the hull fan",
       [](const PointSet& q, ref::Rt2Stats* st) { return ref::flip_flop(q, hull_fan(q), FlipFlopVariant::v_first, st); },
       hull_fan},
      // the cpu backend (kernels_cpu/rt2), 2 threads, BRIO rounds down to
      // single points (every round path on small inputs)
      {"cpu",
       [](const PointSet& q, ref::Rt2Stats* st) {
         cpu::Rt2Options o;
         o.threads = 2;
         o.brio_min = 1;
         return cpu::rt2(q, o, st);
       },
       nullptr},
  };
  if (zero_weights(ps))
    out.push_back({"dt2-lawson", [](const PointSet& q, ref::Rt2Stats* st) { return ref::dt2_lawson(q, st); }, nullptr});
  else {
    // flip-flop from the Delaunay triangulation of the same points: it must
    // remove the redundant ones (3-1 flips, the D-criterion)
    auto delaunay = [](const PointSet& q) { return ref::rt2_ffrt(without_weights(q)); };
    out.push_back({"flip-flop from the Delaunay triangulation",
                   [delaunay](const PointSet& q, ref::Rt2Stats* st) {
                     return ref::flip_flop(q, delaunay(q), ref::FlipFlopVariant::combined, st);
                   },
                   delaunay});
  }
  if (ps.size() <= kBruteRt2Max)
    out.push_back({"brute", [](const PointSet& q, ref::Rt2Stats*) { return brute::rt2(q); }, nullptr});
  return out;
}

inline std::set<Index> vertices(const std::vector<Triangle>& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return v;
}

// Edges with one triangle: the boundary of the triangulated disk.
inline std::size_t boundary_edges(const std::vector<Triangle>& tris) {
  std::map<std::pair<Index, Index>, int> count;
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i) ++count[std::minmax(t[i], t[(i + 1) % 3])];
  std::size_t b = 0;
  for (const auto& e : count) b += e.second == 1;
  return b;
}

inline Outcome rt2_canonical(const PointSet& ps, const Params&) {
  if (!spans(ps))  // brute: defined for any input; fans need a hull
    return expect_flat_input_rejected(ps, rt2_algorithms(ps),
                                      [](const auto& a) { return a.name == "brute" || a.initial; });
  const auto answer = ref::rt2_ffrt(ps);
  const std::string first = text(answer);
  const certify::Report r = certify::rt2(ps, answer, certify::Level::canonical);
  FF_EXPECT(r.ok, "ffrt: not certified canonical: " << r.message());
  for (const auto& a : rt2_algorithms(ps)) {
    const std::string t = text(a.run(ps, nullptr));
    FF_EXPECT(t == first, a.name << " differs from ffrt: " << one_line(t) << " vs " << one_line(first));
  }
  // Lawson from a triangulation of all points succeeds iff no point is
  // redundant (Lemma 5.1: Lawson gets stuck exactly on a redundant vertex;
  // without one, Thm 2.2), and then returns the answer.
  const bool all_vertices = vertices(answer).size() == ps.size();
  try {
    const std::string t = text(ref::lawson(ps, sweep_triangulation(ps)));
    FF_EXPECT(all_vertices, "lawson returned a triangulation although a point is redundant");
    FF_EXPECT(t == first, "lawson from the sweep triangulation differs: " << one_line(t));
  } catch (const std::runtime_error& e) {
    FF_EXPECT(!all_vertices, "lawson got stuck although no point is redundant: " << e.what());
  }
  const auto cgal = ps.weighted ? peers::cgal_regular2(ps) : peers::cgal_delaunay2(ps);
  const certify::Report rc = certify::rt2(ps, cgal, certify::Level::exact);
  FF_EXPECT(rc.ok, "CGAL's triangulation not certified exact: " << rc.message());
  return Outcome::pass();
}

inline Outcome rt2_scale(const PointSet& ps, const Params& p) {
  if (!spans(ps)) return Outcome::skip("does not span the plane");
  const int k = scale_exponent(ps, p.scale);
  return same_answers(rt2_algorithms(ps), ps, scaled(ps, k), [](auto v) { return v; },
                      ("scaling by 2^" + std::to_string(k) + " (weights by 2^" + std::to_string(2 * k) + ")").c_str());
}

inline Outcome rt2_translate(const PointSet& ps, const Params& p) {
  if (!integer_input(ps)) return Outcome::skip("not integer input");
  if (!spans(ps) || !general_position_2d(ps, true)) return Outcome::skip("not in general position");
  return same_answers(rt2_algorithms(ps), ps, translated(ps, p.shift), [](auto v) { return v; },
                      "integer translation");
}

inline Outcome rt2_permute(const PointSet& ps, const Params& p) {
  if (!spans(ps) || !general_position_2d(ps, true)) return Outcome::skip("not in general position");
  const auto perm = permutation(ps.size(), p.seed);
  return same_answers(rt2_algorithms(ps), ps, permuted(ps, perm),
                      [&](const auto& v) { return map_back(v, perm); }, "a permutation of the input");
}

// The counters' lemmas (thesis §2.2-§2.3, §5.1-§5.3). The extended
// triangulation is a sphere: with V vertices (v included) it has F = 2V - 4
// triangles, real ones plus one virtual triangle per boundary edge. A 1-3 flip
// adds a vertex and 2 triangles, a 3-1 flip removes one vertex and 2
// triangles, a 2-2 flip changes neither; a removed vertex never reappears.
// From an initial triangulation T0 (ffRT: one triangle, 3 + 1 vertices):
//   |vertices(out)| = |vertices(T0)| + flips_1_3 - flips_3_1,
//   |out| + |boundary(out)| = |T0| + |boundary(T0)| + 2 (flips_1_3 - flips_3_1),
//   n = |vertices(T0)| + flips_1_3 + discarded_early (every other point is
//     inserted or proved redundant by its triangle, §5.3),
//   labelled_redundant <= flips_3_1 (each labelled vertex is removed,
//     Thm 5.5), flops <= flips_2_2 + flips_3_1;
// dt2-lawson and Lawson never remove a vertex (flips_3_1 = 0). In ffRT's
// final state no labelled vertex and no removed vertex is a vertex, and the
// removed vertices are exactly flips_3_1 many (none removed twice). Starting
// from the answer itself, Lawson and flip-flop flip nothing.
inline Outcome rt2_counts(const PointSet& ps, const Params&) {
  if (!spans(ps)) return Outcome::skip("does not span the plane");
  const std::size_t n = ps.size();
  const auto answer = ref::rt2_ffrt(ps);
  for (const auto& a : rt2_algorithms(ps)) {
    if (a.name == "brute") continue;
    ref::Rt2Stats st;
    const auto out = a.run(ps, &st);
    std::size_t v0 = 3, f0 = 4;
    if (a.initial) {
      const auto t0 = a.initial(ps);
      v0 = vertices(t0).size();
      f0 = t0.size() + boundary_edges(t0);
    }
    const std::size_t v = vertices(out).size(), f = out.size() + boundary_edges(out);
    FF_EXPECT(v + st.flips_3_1 == v0 + st.flips_1_3,
              a.name << ": " << v << " vertices from " << v0 << " with " << st.flips_1_3 << " 1-3 and "
                     << st.flips_3_1 << " 3-1 flips");
    FF_EXPECT(f + 2 * st.flips_3_1 == f0 + 2 * st.flips_1_3,
              a.name << ": " << f << " extended triangles from " << f0 << " with " << st.flips_1_3 << " 1-3 and "
                     << st.flips_3_1 << " 3-1 flips");
    FF_EXPECT(v0 + st.flips_1_3 + st.discarded_early == n,
              a.name << ": " << v0 << " + inserted " << st.flips_1_3 << " + discarded " << st.discarded_early
                     << " != " << n);
    FF_EXPECT(st.labelled_redundant <= st.flips_3_1, a.name << ": labelled " << st.labelled_redundant);
    FF_EXPECT(st.flops <= st.flips_2_2 + st.flips_3_1, a.name << ": flops " << st.flops);
    if (a.name == "dt2-lawson") FF_EXPECT(st.flips_3_1 == 0, "dt2-lawson removed a vertex");
  }
  {  // ffRT's final state
    ref::Rt2Stats st;
    std::vector<Index> all(n);
    std::iota(all.begin(), all.end(), Index{0});
    ref::ff::State s = ref::ff::make_state(ref::ffrt::construct(ps, all, true, &st));
    ref::ff::run(s, ref::FlipFlopVariant::combined, &st);
    std::size_t removed = 0;
    for (Index i = 0; i < n; ++i) {
      FF_EXPECT(!(s.labelled[i] && s.T.is_vertex(i)), "ffrt: labelled vertex " << i << " is in the output");
      FF_EXPECT(!(s.T.removed[i] && s.T.is_vertex(i)), "ffrt: removed vertex " << i << " reappeared");
      removed += s.T.removed[i] != 0;
    }
    FF_EXPECT(removed == st.flips_3_1, "ffrt: " << removed << " vertices removed by " << st.flips_3_1 << " 3-1 flips");
    FF_EXPECT(ref::tri::real_triangles(s.T) == answer, "ffrt stages differ from rt2_ffrt");
  }
  {  // from the answer, nothing to do
    ref::Rt2Stats st;
    FF_EXPECT(ref::flip_flop(ps, answer, ref::FlipFlopVariant::combined, &st) == answer, "flip-flop moved the answer");
    FF_EXPECT(st.flips_2_2 + st.flips_3_1 + st.flips_1_3 + st.labelled_redundant == 0,
              "flip-flop from the answer: " << st.flips_2_2 << " 2-2, " << st.flips_3_1 << " 3-1, " << st.flips_1_3
                                            << " 1-3 flips, " << st.labelled_redundant << " labels");
    FF_EXPECT(st.discarded_early + vertices(answer).size() == n, "flip-flop from the answer: missing points not discarded");
    if (vertices(answer).size() == n) {
      ref::Rt2Stats sl;
      FF_EXPECT(ref::lawson(ps, answer, &sl) == answer && sl.flips_2_2 == 0, "lawson moved the answer");
    }
  }
  if (vertices(answer).size() == n) {  // Lawson from the sweep: vertices kept, F constant
    ref::Rt2Stats st;
    const auto out = ref::lawson(ps, sweep_triangulation(ps), &st);
    FF_EXPECT(out.size() + boundary_edges(out) == 2 * n - 2 && st.flips_1_3 + st.flips_3_1 == 0,
              "lawson: " << out.size() << " triangles, " << boundary_edges(out) << " boundary edges for " << n
                         << " vertices");
  }
  return Outcome::pass();
}

#endif  // FLIPFLOP_TEST_HAVE_RT2

// ============================================================================
// 3D hulls
// ============================================================================

inline constexpr std::size_t kBruteHull3Max = 12;  // brute::hull3 is O(n^4)

struct Hull3Algorithm {
  std::string name;
  std::function<std::vector<Triangle>(const PointSet&, ref::Hull3Stats*)> run;
};

// The canonical 3D hull algorithms present: the reference's
// (ref::hull3_algorithms(): ffHull, star splaying, twist-flip + flip-flop;
// when the test links them), the cpu backend's multithreaded ffHull and brute
// force for n <= kBruteHull3Max.
inline std::vector<Hull3Algorithm> hull3_algorithms(std::size_t n) {
  std::vector<Hull3Algorithm> out;
#ifdef FLIPFLOP_TEST_HAVE_HULL3
  for (const std::string& name : ref::hull3_algorithms())  // new algorithms join automatically
    out.push_back({name, [name](const PointSet& q, ref::Hull3Stats* st) { return ref::hull3(q, name, st); }});
  // the cpu backend (kernels_cpu/hull3), with 2 threads
  out.push_back({"cpu", [](const PointSet& q, ref::Hull3Stats* st) {
                   cpu::Hull3Options o;
                   o.threads = 2;
                   return cpu::hull3_ffhull(q, o, st);
                 }});
#endif
  if (n <= kBruteHull3Max)
    out.push_back({"brute", [](const PointSet& q, ref::Hull3Stats*) { return brute::hull3(q); }});
  return out;
}

inline std::set<Index> hull_vertices(const std::vector<Triangle>& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return v;
}

// Every algorithm returns the same canonical text, certified canonical;
// brute force is the definition (n <= 12). CGAL's hull is certified at
// Level::exact and, in general position, equal. Input that does not span
// R^3 is rejected by every algorithm (brute force is defined for any input).
inline Outcome hull3_canonical(const PointSet& ps, const Params&) {
  const auto algos = hull3_algorithms(ps.size());
  if (algos.empty()) return Outcome::skip("no 3D hull algorithm for this size in this build");
  if (!spans(ps)) return expect_flat_input_rejected(ps, algos, [](const auto& a) { return a.name == "brute"; });
  const auto h = algos.front().run(ps, nullptr);
  const std::string first = text(h);
  const certify::Report r = certify::hull3(ps, h, certify::Level::canonical);
  FF_EXPECT(r.ok, algos.front().name << ": not certified canonical: " << r.message());
  for (const auto& a : algos) {
    const std::string t = text(a.run(ps, nullptr));
    FF_EXPECT(t == first, a.name << " differs from " << algos.front().name << ": " << one_line(t) << " vs "
                                 << one_line(first));
  }
#ifdef FLIPFLOP_TEST_HAVE_HULL3
  {  // the cpu kernel's witness passes the witnessed certifier (kernels_cpu/hull3/certify_hull3.hpp)
    cpu::Hull3Witness w;
    cpu::Hull3Options o;
    o.threads = 2;
    o.witness = &w;
    const auto hw = cpu::hull3_ffhull(ps, o);
    const certify::Report rw = cpu::certify_hull3_witnessed(ps, hw, certify::Level::canonical, w, 2);
    FF_EXPECT(rw.ok, "cpu: the witnessed certifier rejects the kernel's output: " << rw.message());
  }
#endif
  const auto cgal = peers::cgal_hull3(ps);
  const certify::Report rc = certify::hull3(ps, cgal, certify::Level::exact);
  FF_EXPECT(rc.ok, "CGAL's 3D hull not certified exact: " << rc.message());
  if (general_position_3d(ps)) FF_EXPECT(cgal == h, "CGAL's 3D hull of points in general position differs");
  return Outcome::pass();
}

inline Outcome hull3_scale(const PointSet& ps, const Params& p) {
  const auto algos = hull3_algorithms(ps.size());
  if (algos.empty() || !spans(ps)) return Outcome::skip("no algorithm for this size, or not spanning R^3");
  const int k = scale_exponent(ps, p.scale);
  return same_answers(algos, ps, scaled(ps, k), [](auto v) { return v; }, ("scaling by 2^" + std::to_string(k)).c_str());
}

inline Outcome hull3_translate(const PointSet& ps, const Params& p) {
  const auto algos = hull3_algorithms(ps.size());
  if (algos.empty() || !integer_input(ps)) return Outcome::skip("not integer input (or no algorithm for this size)");
  if (!spans(ps) || !general_position_3d(ps)) return Outcome::skip("not in general position");
  return same_answers(algos, ps, translated(ps, p.shift), [](auto v) { return v; }, "integer translation");
}

inline Outcome hull3_permute(const PointSet& ps, const Params& p) {
  const auto algos = hull3_algorithms(ps.size());
  if (algos.empty()) return Outcome::skip("no 3D hull algorithm for this size in this build");
  if (!spans(ps) || !general_position_3d(ps)) return Outcome::skip("not in general position");
  const auto perm = permutation(ps.size(), p.seed);
  return same_answers(algos, ps, permuted(ps, perm), [&](const auto& v) { return map_back(v, perm); },
                      "a permutation of the input");
}

#ifdef FLIPFLOP_TEST_HAVE_HULL3
// The counters' lemmas (thesis §6.2-6.4, §3.3.2, §8.4.1), V = hull vertices:
//   ffhull (Alg 7): every point but the initial tetrahedron is inserted
//     (a 1-3 flip, line 9) or discarded as interior (lines 13-14):
//     insertions = flips_1_3, 4 + insertions + discarded_early = n; flip-flop
//     (Alg 6) adds no vertex and each 3-1 flip removes one for good:
//     V = 4 + insertions - flips_3_1; a vertex is labelled at most once and
//     every labelled vertex is removed (Lemma 6.5, Thm 6.2):
//     labelled_non_extreme <= flips_3_1;
//   twist-flip: every point is a vertex of the polyhedron flip-flop starts
//     from (v joined to all others): V = n - flips_3_1, no 1-3 flip;
//   splay: a star dies only with a death certificate (the point is not
//     extreme) and every alive star at the end is a hull vertex (the
//     consistent stars form one polytope, star_splaying.hpp): dead_stars +
//     V = n; no flips;
//   flip-flop in a random order (free execution order, §3.2; Thm 6.12) from
//     ffHull's constructed polyhedron and from one built by inserting every
//     point in a random order (dents included): the same hull; a removed
//     vertex never reappears; removed vertices = flips_3_1; no labelled or
//     removed vertex is a hull vertex; V = |vertices(start)| - flips_3_1.
inline Outcome hull3_counts(const PointSet& ps, const Params& p) {
  if (!spans(ps)) return Outcome::skip("does not span R^3");
  const std::size_t n = ps.size();
  const auto answer = ref::hull3_ffhull(ps);
  const std::size_t V = hull_vertices(answer).size();
  {
    ref::Hull3Stats st;
    ref::hull3_ffhull(ps, &st);
    FF_EXPECT(st.insertions == st.flips_1_3, "ffhull: " << st.insertions << " insertions, " << st.flips_1_3 << " 1-3 flips");
    FF_EXPECT(4 + st.insertions + st.discarded_early == n,
              "ffhull: 4 + inserted " << st.insertions << " + discarded " << st.discarded_early << " != " << n);
    FF_EXPECT(4 + st.insertions == V + st.flips_3_1,
              "ffhull: " << V << " hull vertices from " << 4 + st.insertions << " with " << st.flips_3_1 << " 3-1 flips");
    FF_EXPECT(st.labelled_non_extreme <= st.flips_3_1, "ffhull: labelled " << st.labelled_non_extreme);
    FF_EXPECT(st.splay_insertions + st.dead_stars + st.twists + st.fold_flips == 0, "ffhull: counts of other algorithms");
  }
  {
    ref::Hull3Stats st;
    ref::hull3_twist_flip(ps, &st);
    FF_EXPECT(V + st.flips_3_1 == n, "twist-flip: " << V << " hull vertices with " << st.flips_3_1 << " 3-1 flips of " << n);
    FF_EXPECT(st.flips_1_3 + st.insertions + st.discarded_early == 0, "twist-flip: points inserted or discarded");
    FF_EXPECT(st.labelled_non_extreme <= st.flips_3_1, "twist-flip: labelled " << st.labelled_non_extreme);
  }
  {
    ref::Hull3Stats st;
    ref::hull3_splay(ps, &st);
    FF_EXPECT(st.dead_stars + V == n, "splay: " << st.dead_stars << " dead stars, " << V << " hull vertices of " << n);
    FF_EXPECT(st.flips_2_2 + st.flips_3_1 + st.flips_1_3 == 0, "splay: flips counted");
  }
  // flip-flop in a random order
  const std::array<Index, 4> tet = ref::ffhull::initial_tetrahedron(ps);
  const ref::RationalKernel s = ref::centroid_kernel(ps, tet[0], tet[1], tet[2], tet[3]);
  for (bool furthest : {true, false}) {
    ref::ffhull::BuildOptions opt;
    opt.furthest = furthest;
    opt.discard_inside = furthest;
    opt.seed = p.seed;
    ref::Hull3Stats bs;
    const auto start = ref::ffhull::construct(ps, s, tet, opt, &bs);
    const std::size_t v0 = hull_vertices(start).size();
    if (!furthest) FF_EXPECT(v0 == n && bs.discarded_early == 0, "ffhull::construct without discarding: " << v0 << " vertices");
    ref::ff3::State st = ref::ff3::make_state(ps, s, ref::poly::build(n, start));
    std::mt19937_64 rng(p.seed);
    std::string reappeared;
    ref::Hull3Stats fs;
    ref::ff3::run(st, &fs, [&](const std::vector<ref::ff3::Candidate>& C) {
      for (Index i = 0; i < n; ++i)
        if (st.removed[i] && st.P.is_vertex(i)) reappeared = std::to_string(i);
      return static_cast<std::size_t>(rng() % C.size());
    });
    const char* what = furthest ? "flip-flop in a random order from ffHull's polyhedron"
                                : "flip-flop in a random order from a random star-shaped polyhedron";
    FF_EXPECT(reappeared.empty(), what << ": removed vertex " << reappeared << " is back");
    FF_EXPECT(canonical_triangles(ref::poly::triangles(st.P)) == answer, what << ": not the hull");
    std::size_t removed = 0;
    for (Index i = 0; i < n; ++i) {
      removed += st.removed[i] != 0;
      FF_EXPECT(!((st.removed[i] || st.labelled[i]) && st.P.is_vertex(i)), what << ": vertex " << i << " removed or labelled");
    }
    FF_EXPECT(removed == fs.flips_3_1, what << ": " << removed << " removed by " << fs.flips_3_1 << " 3-1 flips");
    FF_EXPECT(v0 == V + fs.flips_3_1, what << ": " << V << " hull vertices from " << v0);
    FF_EXPECT(fs.labelled_non_extreme <= fs.flips_3_1 && fs.flips_1_3 == 0, what << ": labelled " << fs.labelled_non_extreme);
  }
  return Outcome::pass();
}
#endif  // FLIPFLOP_TEST_HAVE_HULL3

// ============================================================================
// d-dimensional regular triangulations and the instant flip
// ============================================================================



// The points span R^d: some d+1 of them have a non-zero exact orientation
// (dimension_problem for d <= 3; for d > 3 every (d+1)-subset is tried).
inline bool spans_d(const PointSet& ps) {
  if (ps.dim <= 3) return spans(ps);
  return !for_each_subset(ps.size(), ps.dim + 1, [&](const std::vector<Index>& t) { return orient_exact(ps, t) == 0; });
}

// No d+1 points on a hyperplane (exact orient_d != 0); with `power`, also no
// d+2 lifted points on a hyperplane (exact power_d != 0).
inline bool general_position_d(const PointSet& ps, bool power) {
  const int d = ps.dim;
  if (!for_each_subset(ps.size(), d + 1, [&](const std::vector<Index>& t) { return orient_exact(ps, t) != 0; }))
    return false;
  return !power || for_each_subset(ps.size(), d + 2, [&](const std::vector<Index>& t) { return power_exact(ps, t) != 0; });
}

inline PointSet with_weights(PointSet ps, const std::vector<double>& w) {
  ps.weighted = true;
  ps.weights = w;
  return ps;
}

inline std::vector<double> weights_of(const PointSet& ps) {
  std::vector<double> w;
  for (std::size_t i = 0; i < ps.size(); ++i) w.push_back(ps.weight(i));
  return w;
}

#ifdef FLIPFLOP_TEST_HAVE_RTD

inline std::size_t brute_rtd_max(int d) { return d == 2 ? 12 : d == 3 ? 10 : 9; }  // O(n^(d+2))

struct RtdAlgorithm {
  std::string name;
  std::function<Simplices(const PointSet&, ref::RtdStats*)> run;
};

// RT+1 (rtd_incremental and its structure build_rtd), for d = 2 the 2D
// reference ffRT (the same canonical text, rt_incremental.hpp), and the
// definition (support/rtd_brute.hpp) for small n.
inline std::vector<RtdAlgorithm> rtd_algorithms(const PointSet& ps) {
  std::vector<RtdAlgorithm> out = {
      {"rtd_incremental", [](const PointSet& q, ref::RtdStats* st) { return ref::rtd_incremental(q, st).simplices; }},
      {"build_rtd", [](const PointSet& q, ref::RtdStats* st) { return ref::rtd::real_simplices(ref::build_rtd(q, st)); }},
  };
#ifdef FLIPFLOP_TEST_HAVE_RT2
  if (ps.dim == 2)
    out.push_back({"rt2_ffrt", [](const PointSet& q, ref::RtdStats*) {
                     Simplices s;
                     for (const Triangle& t : ref::rt2_ffrt(q)) s.push_back({t[0], t[1], t[2]});
                     return s;
                   }});
#endif
  if (ps.size() <= brute_rtd_max(ps.dim))
    out.push_back({"brute", [](const PointSet& q, ref::RtdStats*) { return brute_rtd(q); }});
  return out;
}

// (a)(b): certified by certify::rtd (canonical), every algorithm the same
// text, the redundant points exactly the non-vertices. Input that does not
// span R^d is rejected by every algorithm.
inline Outcome rtd_canonical(const PointSet& ps, const Params&) {
  const auto algos = rtd_algorithms(ps);
  if (!spans_d(ps)) return expect_flat_input_rejected(ps, algos, [](const auto& a) { return a.name == "brute"; });
  const ref::Rtd answer = ref::rtd_incremental(ps);
  const certify::Report r = certify::rtd(ps, answer.simplices);
  FF_EXPECT(r.ok, "rtd_incremental: not certified: " << r.message());
  const std::set<Index> v = simplex_vertices(answer.simplices);
  std::vector<Index> missing;
  for (Index i = 0; i < ps.size(); ++i)
    if (!v.count(i)) missing.push_back(i);
  FF_EXPECT(missing == answer.redundant, "rtd_incremental: the redundant list is not the non-vertices");
  const std::string first = text(answer.simplices);
  for (const auto& a : algos) {
    const std::string t = text(a.run(ps, nullptr));
    FF_EXPECT(t == first, a.name << " differs from rtd_incremental: " << one_line(t) << " vs " << one_line(first));
  }
  return Outcome::pass();
}

inline Outcome rtd_scale(const PointSet& ps, const Params& p) {
  if (!spans_d(ps)) return Outcome::skip("does not span R^d");
  const int k = scale_exponent(ps, p.scale);
  return same_answers(rtd_algorithms(ps), ps, scaled(ps, k), [](auto v) { return v; },
                      ("scaling by 2^" + std::to_string(k) + " (weights by 2^" + std::to_string(2 * k) + ")").c_str());
}

inline Outcome rtd_translate(const PointSet& ps, const Params& p) {
  if (!integer_input(ps)) return Outcome::skip("not integer input");
  if (!spans_d(ps) || !general_position_d(ps, true)) return Outcome::skip("not in general position");
  return same_answers(rtd_algorithms(ps), ps, translated(ps, p.shift), [](auto v) { return v; }, "integer translation");
}

inline Outcome rtd_permute(const PointSet& ps, const Params& p) {
  if (!spans_d(ps) || !general_position_d(ps, true)) return Outcome::skip("not in general position");
  const auto perm = permutation(ps.size(), p.seed);
  return same_answers(rtd_algorithms(ps), ps, permuted(ps, perm), [&](const auto& v) { return map_back(v, perm); },
                      "a permutation of the input");
}

// The counters of RT+1 (rt_incremental.hpp, [ES92]): the first d+1 points
// form a simplex, every other point is placed (outside the hull), inserted
// by a 1-(d+1) flip or proved redundant by its simplex (redundant for good:
// more points only lower the lower hull):
//   insertions = d+1 + placed + flips[1],
//   insertions + (redundant - removed) = n,
// a vertex leaves only by a (d+1)-1 flip: removed = flips[d+1]; the output
// has n - redundant vertices; no k-(d+2-k) flip with k outside 1..d+1; the
// queue runs empty (pops = pushes). The instant flip from RT(S ⊕ W) to the
// same weights flips nothing (no ridge moves: no failure time in (0, 1));
// on degenerate coordinates it may instead throw as documented.
inline Outcome rtd_counts(const PointSet& ps, const Params&) {
  if (!spans_d(ps)) return Outcome::skip("does not span R^d");
  const std::size_t n = ps.size();
  const auto d = static_cast<std::uint64_t>(ps.dim);
  ref::RtdStats st;
  const ref::Rtd out = ref::rtd_incremental(ps, &st);
  FF_EXPECT(st.insertions == d + 1 + st.placed + st.flips[1],
            "insertions " << st.insertions << " != d+1 + placed " << st.placed << " + 1-(d+1) flips " << st.flips[1]);
  FF_EXPECT(st.insertions + st.redundant - st.removed == n,
            "inserted " << st.insertions << " + redundant " << st.redundant << " - removed " << st.removed << " != " << n);
  FF_EXPECT(st.removed == st.flips[d + 1], "removed " << st.removed << " != (d+1)-1 flips " << st.flips[d + 1]);
  FF_EXPECT(st.redundant == out.redundant.size() && simplex_vertices(out.simplices).size() == n - st.redundant,
            "redundant " << st.redundant << ", listed " << out.redundant.size());
  FF_EXPECT(st.flips[0] == 0, "0-(d+2) flips");
  for (std::uint64_t k = d + 2; k < 7; ++k) FF_EXPECT(st.flips[k] == 0, k << "-flips in dimension " << d);
  FF_EXPECT(st.queue_pops == st.queue_pushes, "queue: " << st.queue_pushes << " pushes, " << st.queue_pops << " pops");
  const PointSet pw = with_weights(ps, weights_of(ps));  // T keeps a pointer to it
  ref::rtd::TriangulationD T = ref::build_rtd(pw);
  ref::InstantFlipStats fs;
  try {
    fs = ref::instant_flip(T, pw.weights.to_vector(), pw.weights.to_vector());
  } catch (const std::logic_error& e) {  // std::invalid_argument included
    // documented for degenerate coordinates only (instant_flip.hpp)
    FF_EXPECT(!general_position_d(ps, false), "instant flip from W to W threw: " << e.what());
    return Outcome::pass();
  }
  FF_EXPECT(fs.total_flips() == 0 && fs.pushes == 0, "instant flip from W to W: " << fs.total_flips() << " flips");
  FF_EXPECT(ref::rtd::real_simplices(T) == out.simplices, "instant flip from W to W changed the triangulation");
  return Outcome::pass();
}

// ---- the instant flip (thesis §9.2.1, Algorithm 14) ---------------------------

// The target weights U, from the seed (coordinates are never touched): with
// E = 2^e the binade of the squared extent of the set,
//   kind 0: u_i = w_i + δ_i, δ_i = k_i·E/2^10, k_i in [-256, 256];
//   kind 1: u_i = k_i·E/2^10, k_i in [0, 1024] (many points redundant);
//   kind 2: U = W permuted (kind 1 when all weights are equal);
//   kind 3: U = 0, Delaunay (kind 0 when W = 0).
// All values finite unless w_i + δ_i overflows (the checks skip the input).
inline std::vector<double> target_weights(const PointSet& ps, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5bd1e995u);
  const std::size_t n = ps.size();
  const int e = squared_extent_exponent(ps);
  auto pick = [&](std::int64_t lo, std::int64_t hi) {
    return static_cast<double>(lo + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(hi - lo + 1)));
  };
  bool equal = true, zero = true;
  for (std::size_t i = 0; i < n; ++i) equal &= ps.weight(i) == ps.weight(0), zero &= ps.weight(i) == 0;
  std::uint64_t kind = seed % 4;
  if (kind == 2 && equal) kind = 1;
  if (kind == 3 && zero) kind = 0;
  std::vector<double> u(n, 0.0);
  if (kind == 0)
    for (std::size_t i = 0; i < n; ++i) u[i] = ps.weight(i) + std::ldexp(pick(-256, 256), e - 10);
  if (kind == 1)
    for (std::size_t i = 0; i < n; ++i) u[i] = std::ldexp(pick(0, 1024), e - 10);
  if (kind == 2) {
    const auto perm = permutation(n, seed);
    for (std::size_t i = 0; i < n; ++i) u[i] = ps.weight(perm[i]);
  }
  return u;
}

struct InstantFlipRun {
  enum class Kind { ok, invalid_argument, logic_error } kind = Kind::ok;
  std::string what;                  // the exception's message
  Simplices start, out;              // RT(S ⊕ W); the result
  std::vector<Index> start_vertices;
  ref::InstantFlipStats stats;
  std::vector<Index> reappearing;    // reappearing_points(result, U)
  std::string lemma;                 // a violated Lemma 9.4 consequence (with lemmas)
};

inline std::set<std::vector<Index>> ridges_of(const Simplices& s) {
  std::set<std::vector<Index>> r;
  for (const auto& t : s)
    for (std::size_t i = 0; i < t.size(); ++i) {
      std::vector<Index> f;
      for (std::size_t j = 0; j < t.size(); ++j)
        if (j != i) f.push_back(t[j]);
      std::sort(f.begin(), f.end());
      r.insert(f);
    }
  return r;
}

// T = build_rtd(S ⊕ W), then instant_flip(T, W, U). With `lemmas`, every
// flip is checked against Lemma 9.4 ("any ridge appears at most once", also
// with insertion events: instant_flip.hpp) and its consequences (§9.2.1): a
// ridge (real, as a vertex set) that has left never comes back, a removed
// vertex never comes back (the times a point is a vertex form one interval),
// and a simplex of both RT(S ⊕ W) and the result is never removed in between.
inline InstantFlipRun run_instant_flip(const PointSet& ps, const std::vector<double>& u, bool lemmas) {
  InstantFlipRun R;
  const PointSet pw = with_weights(ps, weights_of(ps));  // T keeps a pointer to it
  ref::rtd::TriangulationD T = ref::build_rtd(pw);
  R.start = ref::rtd::real_simplices(T);
  R.start_vertices = ref::rtd::vertices(T);
  std::set<std::vector<Index>> present = ridges_of(R.start), gone;
  const std::set<std::vector<Index>> start_set(R.start.begin(), R.start.end());
  std::set<std::vector<Index>> start_left;  // simplices of RT(S ⊕ W) removed at some point
  std::set<Index> removed;
  ref::InstantFlipOptions opt;
  if (lemmas)
    opt.on_flip = [&](const ref::rtd::TriangulationD& now, const ref::InstantFlipEvent& ev) {
      if (!R.lemma.empty()) return;
      if (ev.removed != ref::rtd::kNoVertex) removed.insert(ev.removed);
      for (Index x : removed)
        if (now.is_vertex(x)) R.lemma = "removed vertex " + std::to_string(x) + " is back";
      const Simplices s = ref::rtd::real_simplices(now);
      const std::set<std::vector<Index>> r = ridges_of(s), sset(s.begin(), s.end());
      for (const auto& f : present)
        if (!r.count(f)) gone.insert(f);
      for (const auto& f : r)
        if (gone.count(f)) R.lemma = "a ridge appeared twice (Lemma 9.4)";
      present = r;
      for (const auto& t : start_set)
        if (!sset.count(t)) start_left.insert(t);
    };
  try {
    R.stats = ref::instant_flip(T, pw.weights.to_vector(), u, opt);
  } catch (const std::invalid_argument& e) {
    R.kind = InstantFlipRun::Kind::invalid_argument;
    R.what = e.what();
    return R;
  } catch (const std::logic_error& e) {
    R.kind = InstantFlipRun::Kind::logic_error;
    R.what = e.what();
    return R;
  }
  R.out = ref::rtd::real_simplices(T);
  R.reappearing = ref::reappearing_points(T, u);
  if (R.lemma.empty())
    for (const auto& t : R.out)
      if (start_set.count(t) && start_left.count(t)) R.lemma = "a simplex of RT(S+W) and RT(S+U) was modified";
  return R;
}



// (a)(b)(d) for the instant flip from RT(S ⊕ W) (W: the input's weights) to
// U = target_weights(seed). Coordinates in general position (no d+1 points
// on a hyperplane, exactly): the weight perturbation of §9.2.2 under the
// index order decides every sign like the Simulation of Simplicity
// (failure_time.hpp), so the run must succeed and end at RT(S ⊕ U) (fresh
// construction, certified): the redundant points enter by insertion events.
// The counters: every pop is a flip, stale or deferred, the queue runs empty,
// a vertex enters only by a 1-(d+1) flip and leaves only by a (d+1)-1 flip,
// a removed vertex never comes back; Lemma 9.4 as restated for insertions
// (run_instant_flip). Degenerate coordinates: the documented exceptions
// (std::invalid_argument: a zero-volume simplex met; std::logic_error:
// simultaneous events left unflippable) or a triangulation that passes
// weak_regularity_problem with every point of S — never a wrong answer.
inline Outcome instant_flip_canonical(const PointSet& ps, const Params& p) {
  if (!spans_d(ps)) return Outcome::skip("does not span R^d");
  const std::vector<double> u = target_weights(ps, p.seed);
  for (double x : u)
    if (!std::isfinite(x)) return Outcome::skip("target weight overflows");
  const PointSet pu = with_weights(ps, u);
  const bool general = general_position_d(ps, false);
  const InstantFlipRun R = run_instant_flip(ps, u, general);
  using Kind = InstantFlipRun::Kind;
  std::vector<Index> all(ps.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<Index>(i);
  if (!general) {
    if (R.kind != Kind::ok) return Outcome::pass();
    const std::string why = weak_regularity_problem(pu, R.out, all);
    FF_EXPECT(why.empty(), "instant flip on degenerate coordinates: " << why << ": " << one_line(text(R.out)));
    return Outcome::pass();
  }
  FF_EXPECT(R.kind == Kind::ok, "instant flip threw on coordinates in general position: " << R.what);
  FF_EXPECT(R.lemma.empty(), "instant flip: " << R.lemma);
  const ref::InstantFlipStats& st = R.stats;
  const auto d = static_cast<std::size_t>(ps.dim);
  FF_EXPECT(st.pops == st.total_flips() + st.stale + st.deferred,
            "pops " << st.pops << " != flips " << st.total_flips() << " + stale " << st.stale << " + deferred " << st.deferred);
  FF_EXPECT(st.pushes == st.pops, "pushes " << st.pushes << " != pops " << st.pops);
  FF_EXPECT(st.removed_vertices == st.flips[d + 1], "removed " << st.removed_vertices << " != (d+1)-1 flips");
  FF_EXPECT(st.inserted_vertices == st.flips[1], "inserted " << st.inserted_vertices << " != 1-(d+1) flips");
  FF_EXPECT(simplex_vertices(R.out).size() + st.removed_vertices == R.start_vertices.size() + st.inserted_vertices,
            simplex_vertices(R.out).size() << " vertices from " << R.start_vertices.size() << " with "
                                           << st.removed_vertices << " removed and " << st.inserted_vertices
                                           << " inserted");
  const std::string got = text(R.out);
  const ref::Rtd full = ref::rtd_incremental(pu);
  FF_EXPECT(R.out == full.simplices, "not RT(S+U): " << one_line(got));
  FF_EXPECT(R.reappearing.empty(), "a non-vertex is not redundant under U");
  const certify::Report r = certify::rtd(pu, R.out);
  FF_EXPECT(r.ok, "not certified: " << r.message());
  return Outcome::pass();
}

// (c) Coordinates x 2^k, W and U x 2^(2k): every lifted height scales by
// 2^(2k), every orientation minor M_r by a positive power of two, A_F, B_F
// and D_F of a ridge by one common positive factor, the time comparison
// B_F A_G - A_F B_G and the perturbation coefficients c_G(p) D_F - c_F(p) D_G
// (failure_time.hpp) by positive factors: every SoS sign and every decision
// is the same, degenerate input included — the same triangulation, counts
// and outcome (the same exception type when it throws).
inline Outcome instant_flip_scale(const PointSet& ps, const Params& p) {
  if (!spans_d(ps)) return Outcome::skip("does not span R^d");
  const std::vector<double> u = target_weights(ps, p.seed);
  for (double x : u)
    if (!std::isfinite(x)) return Outcome::skip("target weight overflows");
  const PointSet pu = with_weights(ps, u);
  const auto [lo, hi] = exact_scale_range(pu);
  const int k = std::min(std::max(scale_exponent(ps, p.scale), lo), hi);  // both ranges hold 0
  std::vector<double> su = u;
  for (double& x : su) x = std::ldexp(x, 2 * k);
  const InstantFlipRun A = run_instant_flip(ps, u, false), B = run_instant_flip(scaled(ps, k), su, false);
  FF_EXPECT(A.kind == B.kind, "outcome changes under scaling by 2^" << k << ": '" << A.what << "' vs '" << B.what << "'");
  FF_EXPECT(A.out == B.out, "result changes under scaling by 2^" << k << ": " << one_line(text(A.out)) << " vs "
                                                                  << one_line(text(B.out)));
  for (std::size_t j = 0; j < 8; ++j) FF_EXPECT(A.stats.flips[j] == B.stats.flips[j], j << "-flips change under scaling");
  FF_EXPECT(A.stats.pushes == B.stats.pushes && A.stats.pops == B.stats.pops && A.stats.stale == B.stats.stale &&
                A.stats.deferred == B.stats.deferred,
            "queue counts change under scaling by 2^" << k);
  return Outcome::pass();
}

#endif  // FLIPFLOP_TEST_HAVE_RTD

// ============================================================================
// Point classification kernels
// ============================================================================

// Facets (triangles / edges of distinct point indices, about n/4 of them) and
// a facet for every point, drawn with std::mt19937_64(seed).
struct ClassifyInput {
  PointSet pts;
  std::vector<std::array<Index, 3>> facets;  // 2D: the first two entries
  std::vector<Index> facet_of_point;
};

inline ClassifyInput classify_input(const PointSet& ps, std::uint64_t seed) {
  ClassifyInput in;
  in.pts = ps;
  const std::size_t n = ps.size(), m = std::max<std::size_t>(1, n / 4);
  std::mt19937_64 rng(seed);
  for (std::size_t f = 0; f < m; ++f) {
    std::array<Index, 3> t{};
    for (int k = 0; k < ps.dim; ++k) {
      bool repeated;
      do {
        t[static_cast<std::size_t>(k)] = static_cast<Index>(rng() % n);
        repeated = std::find(t.begin(), t.begin() + k, t[static_cast<std::size_t>(k)]) != t.begin() + k;
      } while (repeated);
    }
    in.facets.push_back(t);
  }
  for (std::size_t i = 0; i < n; ++i) in.facet_of_point.push_back(static_cast<Index>(rng() % m));
  return in;
}

// The oracle: one Mode::gmp predicate per point.
inline std::vector<int> classify_gmp(const ClassifyInput& in) {
  std::vector<int> s;
  for (std::size_t i = 0; i < in.pts.size(); ++i) {
    const auto& f = in.facets[in.facet_of_point[i]];
    const PointSet& p = in.pts;
    s.push_back(p.dim == 3 ? pred::orient3d_exact(p.point(f[0]), p.point(f[1]), p.point(f[2]), p.point(i), pred::Mode::gmp)
                           : pred::orient2d_exact(p.point(f[0]), p.point(f[1]), p.point(i), pred::Mode::gmp));
  }
  return s;
}

struct ClassifyBackend {
  std::string name;
  std::function<std::vector<int>(const ClassifyInput&)> run;
};

inline std::vector<ClassifyBackend> classify_backends() {
  std::vector<ClassifyBackend> out;
  out.push_back({"kernels_cpu (TBB)", [](const ClassifyInput& in) {
                   if (in.pts.dim == 3) return kernels_cpu::classify_points_3d(in.pts, in.facets, in.facet_of_point);
                   std::vector<kernels_cpu::Edge> e;
                   for (const auto& f : in.facets) e.push_back({f[0], f[1]});
                   return kernels_cpu::classify_points_2d(in.pts, e, in.facet_of_point);
                 }});
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  out.push_back({"kernels_omp (thrust OpenMP)", [](const ClassifyInput& in) {
                   if (in.pts.dim == 3) return kernels_omp::classify_points_3d(in.pts, in.facets, in.facet_of_point);
                   std::vector<kernels::Edge> e;
                   for (const auto& f : in.facets) e.push_back({f[0], f[1]});
                   return kernels_omp::classify_points_2d(in.pts, e, in.facet_of_point);
                 }});
#endif
  return out;
}

// Exact (unperturbed) signs: every backend equals the oracle, on the input
// and after scaling by 2^k (det scales by 2^(dk) > 0), a permutation (facet
// ids relabelled: the signs are permuted) and, for integer input, a
// translation (det unchanged). No general position needed: no perturbation.
inline Outcome classify(const PointSet& ps, const Params& p) {
  if (ps.size() < static_cast<std::size_t>(ps.dim)) return Outcome::skip("fewer points than a facet has vertices");
  const ClassifyInput in = classify_input(ps, p.seed);
  const std::vector<int> expected = classify_gmp(in);
  ClassifyInput sc = in;
  sc.pts = scaled(ps, scale_exponent(ps, p.scale));
  FF_EXPECT(classify_gmp(sc) == expected, "Mode::gmp signs change under scaling");
  const auto perm = permutation(ps.size(), p.seed ^ 0x9e3779b97f4a7c15u);
  std::vector<Index> inv(perm.size());
  for (Index j = 0; j < perm.size(); ++j) inv[perm[j]] = j;
  ClassifyInput pm;
  pm.pts = permuted(ps, perm);
  for (auto f : in.facets) {
    for (int k = 0; k < ps.dim; ++k) f[static_cast<std::size_t>(k)] = inv[f[static_cast<std::size_t>(k)]];
    pm.facets.push_back(f);
  }
  for (Index j = 0; j < perm.size(); ++j) pm.facet_of_point.push_back(in.facet_of_point[perm[j]]);
  std::vector<int> expected_pm;
  for (Index j = 0; j < perm.size(); ++j) expected_pm.push_back(expected[perm[j]]);
  for (const auto& b : classify_backends()) {
    FF_EXPECT(b.run(in) == expected, b.name << " differs from Mode::gmp");
    FF_EXPECT(b.run(sc) == expected, b.name << " differs after scaling");
    FF_EXPECT(b.run(pm) == expected_pm, b.name << " is not permutation-equivariant");
    if (integer_input(ps)) {
      ClassifyInput tr = in;
      tr.pts = translated(ps, p.shift);
      FF_EXPECT(b.run(tr) == expected, b.name << " differs after an integer translation");
    }
  }
  return Outcome::pass();
}

// ============================================================================
// The registry
// ============================================================================

struct NamedCheck {
  const char* name;
  int dim;  // the dimensions it applies to: dim .. max(dim, dim_max)
  Outcome (*run)(const PointSet&, const Params&);
  int dim_max = 0;
  bool applies(int d) const { return d >= dim && d <= std::max(dim, dim_max); }
};

inline const std::vector<NamedCheck>& all_checks() {
  static const std::vector<NamedCheck> checks = {
      {"hull2_canonical", 2, hull2_canonical},
      {"hull2_scale", 2, hull2_scale},
      {"hull2_translate", 2, hull2_translate},
      {"hull2_permute", 2, hull2_permute},
      {"hull2_counts", 2, hull2_counts},
#ifdef FLIPFLOP_TEST_HAVE_RT2
      {"rt2_canonical", 2, rt2_canonical},
      {"rt2_scale", 2, rt2_scale},
      {"rt2_translate", 2, rt2_translate},
      {"rt2_permute", 2, rt2_permute},
      {"rt2_counts", 2, rt2_counts},
#endif
      {"hull3_canonical", 3, hull3_canonical},
      {"hull3_scale", 3, hull3_scale},
      {"hull3_translate", 3, hull3_translate},
      {"hull3_permute", 3, hull3_permute},
#ifdef FLIPFLOP_TEST_HAVE_HULL3
      {"hull3_counts", 3, hull3_counts},
#endif
#ifdef FLIPFLOP_TEST_HAVE_RTD
      {"rtd_canonical", 2, rtd_canonical, 5},
      {"rtd_scale", 2, rtd_scale, 5},
      {"rtd_translate", 2, rtd_translate, 5},
      {"rtd_permute", 2, rtd_permute, 5},
      {"rtd_counts", 2, rtd_counts, 5},
      {"instant_flip_canonical", 2, instant_flip_canonical, 5},
      {"instant_flip_scale", 2, instant_flip_scale, 5},
#endif
      {"classify2", 2, classify},
      {"classify3", 3, classify},
  };
  return checks;
}

inline const NamedCheck* find_check(const std::string& name) {
  for (const NamedCheck& c : all_checks())
    if (name == c.name) return &c;
  return nullptr;
}

// Runs a check; an exception escaping it is a failure (never a crash).
inline Outcome run_check(const NamedCheck& c, const PointSet& ps, const Params& p) {
  if (!c.applies(ps.dim)) return Outcome::skip("wrong dimension");
  try {
    return c.run(ps, p);
  } catch (const std::exception& e) {
    return Outcome::fail(std::string("exception: ") + e.what());
  }
}

// ============================================================================
// Saving and loading regression inputs
// ============================================================================

inline std::string regressions_dir() {
  if (const char* d = std::getenv("FLIPFLOP_REGRESSIONS_DIR")) return d;
#ifdef FLIPFLOP_SOURCE_DIR
  return std::string(FLIPFLOP_SOURCE_DIR) + "/proptests/regressions";
#else
  return "proptests/regressions";
#endif
}

inline constexpr const char* kHeaderTag = "flipflop-regression";

inline std::string regression_text(const std::string& property, const PointSet& ps, const Params& p) {
  std::ostringstream os;
  os << "# " << kHeaderTag << " property=" << property << " dim=" << ps.dim << " weighted=" << (ps.weighted ? 1 : 0)
     << " scale=" << p.scale << " shift=" << p.shift[0] << "," << p.shift[1] << "," << p.shift[2]
     << " seed=" << p.seed << "\n";
  io::write_points(os, ps);
  return os.str();
}

inline std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603u;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211u;
  return h;
}

// Writes the file (if not there yet) and returns its path; *created says
// whether this call created it.
inline std::string save_regression(const std::string& property, const PointSet& ps, const Params& p,
                                   bool* created = nullptr) {
  const std::string body = regression_text(property, ps, p);
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(body)));
  const std::filesystem::path dir = std::filesystem::path(regressions_dir()) / property;
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / (std::string(hash) + ".xyz");
  const bool fresh = !std::filesystem::exists(path);
  if (fresh) io::write_file(path.string(), [&](std::ostream& os) { os << body; });
  if (created) *created = fresh;
  return path.string();
}

// Off in the replay (the inputs are already saved).
inline bool& saving_enabled() {
  static bool on = true;
  return on;
}

// property -> the file this process created for it last
inline std::map<std::string, std::string>& saved_last() {
  static std::map<std::string, std::string> last;
  return last;
}

// Call before each RapidCheck property: files saved from now on replace only
// each other (two properties may share a check).
inline void begin_property() { saved_last().clear(); }

// Saves a failing input, replacing the one this process saved last for the
// same property (RapidCheck's shrinking: the last failure is the smallest).
inline std::string save_failure(const std::string& property, const PointSet& ps, const Params& p) {
  auto& last = saved_last();
  bool created = false;
  const std::string path = save_regression(property, ps, p, &created);
  auto it = last.find(property);
  if (it != last.end() && it->second != path) std::filesystem::remove(it->second);
  if (created) last[property] = path;
  else if (it != last.end() && it->second != path) last.erase(it);
  return path;
}

// Inside a RapidCheck property: discard on skip; on failure save the input
// (see the header) and fail the case.
inline void check_or_save(const Outcome& o, const PointSet& ps, const std::string& property, const Params& p = {}) {
  if (o.kind == Outcome::Kind::skip) RC_DISCARD(o.message);
  if (o.kind == Outcome::Kind::pass) return;
  std::string where = "not saved";
  if (saving_enabled()) {
    try {
      where = "saved as " + save_failure(property, ps, p);
    } catch (const std::exception& e) {
      where = std::string("could not save: ") + e.what();
    }
  }
  RC_FAIL(property + ": " + o.message + " [" + where + "]");
}
inline void check_or_save(bool cond, const PointSet& ps, const std::string& property, const std::string& what = "",
                          const Params& p = {}) {
  check_or_save(cond ? Outcome::pass() : Outcome::fail(what), ps, property, p);
}

// The property named `name` on the generated input (the body of a property).
inline void check_property(const std::string& name, const PointSet& ps, const Params& p) {
  const NamedCheck* c = find_check(name);
  RC_ASSERT(c != nullptr);
  RC_PRE(ps.size() >= static_cast<std::size_t>(ps.dim) + 1);  // what the point readers accept
  check_or_save(run_check(*c, ps, p), ps, name, p);
}

// The points of a saved file in R^d, d > 3 (io::read_points reads 2D and 3D
// only): '#' lines skipped, d (+1 weight) decimals per line, read exactly
// (std::strtod rounds correctly; the writer wrote shortest round-trip
// decimals).
inline PointSet read_points_d(const std::string& path, int dim, bool weighted) {
  std::ifstream is(path);
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(is, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> v;
    std::string tok;
    while (ls >> tok) {
      char* end = nullptr;
      v.push_back(std::strtod(tok.c_str(), &end));
      if (end != tok.c_str() + tok.size() || !std::isfinite(v.back()))
        throw std::runtime_error(path + ":" + std::to_string(lineno) + ": bad number '" + tok + "'");
    }
    if (v.size() != static_cast<std::size_t>(dim + (weighted ? 1 : 0)))
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": wrong number of columns");
    ps.coords.insert(ps.coords.end(), v.begin(), v.begin() + dim);
    if (weighted) ps.weights.push_back(v.back());
  }
  return ps;
}

struct Regression {
  std::string path, property;
  PointSet points;
  Params params;
};

// Parses the header line; throws std::runtime_error naming the file.
inline Regression load_regression(const std::string& path) {
  std::ifstream is(path);
  std::string line;
  if (!is || !std::getline(is, line)) throw std::runtime_error(path + ": cannot read");
  std::istringstream hs(line);
  std::string hash_sign, tag, kv;
  hs >> hash_sign >> tag;
  if (hash_sign != "#" || tag != kHeaderTag) throw std::runtime_error(path + ": no '# " + kHeaderTag + "' header");
  Regression r;
  r.path = path;
  int dim = 0, weighted = 0;
  while (hs >> kv) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw std::runtime_error(path + ": bad header field '" + kv + "'");
    const std::string k = kv.substr(0, eq), v = kv.substr(eq + 1);
    if (k == "property") r.property = v;
    else if (k == "dim") dim = std::stoi(v);
    else if (k == "weighted") weighted = std::stoi(v);
    else if (k == "scale") r.params.scale = std::stoi(v);
    else if (k == "seed") r.params.seed = std::stoull(v);
    else if (k == "shift") {
      char c1, c2;
      std::istringstream ss(v);
      if (!(ss >> r.params.shift[0] >> c1 >> r.params.shift[1] >> c2 >> r.params.shift[2]))
        throw std::runtime_error(path + ": bad shift '" + v + "'");
    } else
      throw std::runtime_error(path + ": unknown header field '" + k + "'");
  }
  r.points = dim > 3 ? read_points_d(path, dim, weighted != 0) : io::read_points(path, dim, weighted != 0);
  return r;
}

// Every saved input, sorted by path.
inline std::vector<std::string> regression_files() {
  std::vector<std::string> out;
  const std::filesystem::path dir = regressions_dir();
  if (!std::filesystem::exists(dir)) return out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".xyz") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace flipflop::test

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
//                    points: Θ(n^2)) and brute::hull2 (n <= 40) return
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
//                    (reference/rt2.hpp: ffRT, flip-flop, Lawson; brute::rt2
//                    for n <= 12; CGAL at Level::exact), when rt2.hpp exists.
//   hull3_canonical, hull3_scale, hull3_translate, hull3_permute: brute::hull3
//                    (n <= 12), CGAL certified at Level::exact and equal to
//                    brute on input in general position.
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
// non-zero, checked exactly — no answer consults the perturbation, so the
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
#include "reference/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2.hpp"
#if __has_include("reference/rt2.hpp") && __has_include("reference/ffrt.hpp") && \
    __has_include("reference/flip_flop_2d.hpp")
#define FLIPFLOP_TEST_HAVE_RT2 1
#include "reference/ffrt.hpp"
#include "reference/flip_flop_2d.hpp"
#include "reference/rt2.hpp"
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
  std::array<std::int64_t, 3> shift{};  // integer translation, |t| <= 2^20
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
  for (std::size_t i = 0; i < out.coords.size(); ++i) out.coords[i] += static_cast<double>(t[i % d]);
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
// automatically), and brute::hull2 for small n.
inline std::vector<Hull2Algorithm> hull2_algorithms(std::size_t n) {
  std::vector<Hull2Algorithm> out;
  for (const std::string& name : ref::hull2_algorithms())
    if (name != "twist" || n <= kTwistMax)
      out.push_back({name, [name](const PointSet& ps, ref::Hull2Stats* st) { return ref::hull2(ps, name, st); }});
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

// Every reference algorithm that applies to the input, and brute::rt2 for
// small n. Lawson from a triangulation of all points is not here: it may
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
  std::function<std::vector<Triangle>(const PointSet&, void*)> run;
};

// The canonical 3D hull algorithms present: brute force (the reference's own
// 3D algorithms join here when they exist).
inline std::vector<Hull3Algorithm> hull3_algorithms() {
  return {{"brute", [](const PointSet& q, void*) { return brute::hull3(q); }}};
}

inline Outcome hull3_canonical(const PointSet& ps, const Params&) {
  if (!spans(ps) || ps.size() > kBruteHull3Max) return Outcome::skip("not a small 3D set spanning space");
  const auto h = brute::hull3(ps);
  const certify::Report r = certify::hull3(ps, h, certify::Level::canonical);
  FF_EXPECT(r.ok, "brute::hull3 not certified canonical: " << r.message());
  const auto cgal = peers::cgal_hull3(ps);
  const certify::Report rc = certify::hull3(ps, cgal, certify::Level::exact);
  FF_EXPECT(rc.ok, "CGAL's 3D hull not certified exact: " << rc.message());
  if (general_position_3d(ps)) FF_EXPECT(cgal == h, "CGAL's 3D hull of points in general position differs");
  return Outcome::pass();
}

inline Outcome hull3_scale(const PointSet& ps, const Params& p) {
  if (!spans(ps) || ps.size() > kBruteHull3Max) return Outcome::skip("not a small 3D set spanning space");
  const int k = scale_exponent(ps, p.scale);
  return same_answers(hull3_algorithms(), ps, scaled(ps, k), [](auto v) { return v; },
                      ("scaling by 2^" + std::to_string(k)).c_str());
}

inline Outcome hull3_translate(const PointSet& ps, const Params& p) {
  if (!integer_input(ps) || ps.size() > kBruteHull3Max) return Outcome::skip("not small integer input");
  if (!spans(ps) || !general_position_3d(ps)) return Outcome::skip("not in general position");
  return same_answers(hull3_algorithms(), ps, translated(ps, p.shift), [](auto v) { return v; },
                      "integer translation");
}

inline Outcome hull3_permute(const PointSet& ps, const Params& p) {
  if (ps.size() > kBruteHull3Max) return Outcome::skip("too large for brute::hull3");
  if (!spans(ps) || !general_position_3d(ps)) return Outcome::skip("not in general position");
  const auto perm = permutation(ps.size(), p.seed);
  return same_answers(hull3_algorithms(), ps, permuted(ps, perm),
                      [&](const auto& v) { return map_back(v, perm); }, "a permutation of the input");
}

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
  int dim;
  Outcome (*run)(const PointSet&, const Params&);
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
  if (ps.dim != c.dim) return Outcome::skip("wrong dimension");
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
  RC_PRE(ps.size() >= static_cast<std::size_t>(ps.dim) + 1);  // what io::read_points accepts
  check_or_save(run_check(*c, ps, p), ps, name, p);
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
  r.points = io::read_points(path, dim, weighted != 0);
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

// rtd_check.cpp — fuzz_rtd: the d-dimensional regular triangulation RT+1
// (reference/rtd/rt_incremental.hpp, [ES92], thesis §9.1) against the
// definition, the 2D reference and the certifier, and the monotonic instant
// flip (reference/rtd/instant_flip.hpp, thesis §9.2.1 Algorithm 14) against
// a fresh construction.
//
// Byte layout: byte 0: bits 0-1 d - 2 (d = 2..5), bit 2 weighted (W), bits
// 3-4 the kind of the target weights U (below). Then a d-dimensional point
// set of 1..16 / 12 / 10 / 8 points for d = 2 / 3 / 4 / 5 (fuzz_input.hpp:
// small integers, duplicates, ulp jitter, points on lines, raw and extreme
// magnitudes, cospherical lattice points, quarter weights, power-of-two
// scalings). Then one byte k_i per point for U; with E = 2^e the binade of
// the squared extent of the set: kind 0 u_i = w_i + k_i·E/64 (int8 k_i),
// kind 1 u_i = |k_i|·E/128, kind 2 u_i = w_(k_i mod n), kind 3 u_i = 0.
// Checked:
//   * input that does not span R^d: rtd_incremental and build_rtd throw
//     std::invalid_argument (nothing else);
//   * otherwise rtd_incremental returns, without throwing, canonical
//     simplices that certify::rtd accepts, equal to the definition
//     (proptests/support/rtd_brute.hpp: every (d+1)-subset whose lifted
//     hyperplane has every other lifted point strictly above), to build_rtd's
//     and, for d = 2, to ref::rt2_ffrt's; its redundant list is exactly the
//     non-vertices and its counters obey RT+1's bookkeeping (insertions =
//     d+1 + placed + 1-(d+1) flips; insertions + redundant - removed = n;
//     removed = (d+1)-1 flips; the queue runs empty); its strict view
//     (reference/rtd/strict_rtd.hpp) is certified at the exact level;
//   * where the set is a small-integer lattice times one double g
//     (reference/lattice_quotient.hpp), the quotient is exact and the cavity
//     kernel on it returns RT+1's answer on the given values;
//   * the cavity-insertion kernel (kernels_cpu/rtd/rtd_cavity.hpp) returns
//     the same simplices and redundant points, nearest- and furthest-site
//     (the furthest-site answer of RT+1 certified with the negation); the
//     hull kernel (kernels_cpu/rtd/hull_d.hpp) returns the boundary facets
//     of the (unweighted) triangulation, and its certifier accepts them;
//   * the instant flip from T = build_rtd(S ⊕ W) to U, with insertion
//     events (a redundant point enters by a 1-(d+1) flip when it becomes
//     non-redundant). Coordinates in general position (no d+1 points on a
//     hyperplane, exactly): it must not throw; the result is RT(S ⊕ U)
//     itself (a fresh rtd_incremental), certified, with no non-vertex left
//     non-redundant (reappearing_points empty); along the run no ridge
//     (vertex set) comes back after it left (Lemma 9.4 as restated for
//     insertions in instant_flip.hpp), no removed vertex comes back, and a
//     simplex of both T and the result is never removed; the counters add
//     up (pops = flips + stale + deferred = pushes; removed = (d+1)-1 flips;
//     inserted = 1-(d+1) flips; vertices at the end = vertices of T -
//     removed + inserted). Degenerate coordinates: the documented exceptions
//     (std::invalid_argument, std::logic_error) or a result that is weakly
//     regular for U, checked exactly where simplices have volume (a tiling
//     when none is flat; no reflex interior ridge; every point of S that is
//     not a vertex not strictly below the lifted triangulation) — never a
//     wrong answer.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <exception>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/checks.hpp"
#include "kernels_cpu/rtd/hull_d.hpp"
#include "kernels_cpu/rtd/rtd_cavity.hpp"
#include "fuzz/fuzz_input.hpp"
#include "proptests/support/rtd_oracles.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/rtd_brute.hpp"
#include "reference/lattice_quotient.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/strict_rtd.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_rtd";
constexpr std::size_t kMaxPoints[] = {16, 12, 10, 8};  // d = 2..5

using test::for_each_subset;
using test::orient_exact;
using test::power_exact;
using test::Simplices;
using test::simplex_vertices;
using test::weak_regularity_problem;

std::string describe(const Simplices& s) { return simplices_text(s); }

[[noreturn]] void fail_on(const PointSet& ps, const std::vector<double>& u, const std::string& what,
                          const std::string& more = "") {
  std::string us = "# U:";
  char buf[40];
  for (double x : u) std::snprintf(buf, sizeof buf, " %a", x), us += buf;
  fail(kTarget, what, fuzz::describe(ps) + us + "\n" + more);
}


std::set<std::vector<Index>> ridges_of(const Simplices& s) {
  std::set<std::vector<Index>> r;
  for (const auto& t : s)
    for (std::size_t i = 0; i < t.size(); ++i) {
      std::vector<Index> f = t;
      f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
      std::sort(f.begin(), f.end());
      r.insert(f);
    }
  return r;
}

PointSet with_weights(PointSet ps, const std::vector<double>& w) {
  ps.weighted = true;
  ps.weights = w;
  return ps;
}

// The target weights (header comment); empty when a value is not finite.
std::vector<double> target_weights(ByteReader& r, const PointSet& ps, int kind) {
  const std::size_t n = ps.size();
  const int e = test::squared_extent_exponent(ps);
  std::vector<double> u(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const int k = static_cast<std::int8_t>(r.byte());
    if (kind == 0) u[i] = ps.weight(i) + std::ldexp(k, e - 6);
    if (kind == 1) u[i] = std::ldexp(std::abs(k), e - 7);
    if (kind == 2) u[i] = ps.weight(static_cast<std::size_t>(k + 128) % n);
    if (!std::isfinite(u[i])) return {};
  }
  return u;
}

template <class F>
auto must_return(const PointSet& ps, const std::vector<double>& u, const std::string& what, F f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::exception& e) {
    fail_on(ps, u, what + " threw: " + e.what());
  }
}

// ---- RT+1 ---------------------------------------------------------------------

ref::Rtd check_rt_incremental(const PointSet& ps) {
  const int d = ps.dim;
  const std::size_t n = ps.size();
  ref::RtdStats st;
  const ref::Rtd R = must_return(ps, {}, "rtd_incremental", [&] { return ref::rtd_incremental(ps, &st); });
  const certify::Report rep = certify::rtd(ps, R.simplices);
  if (!rep.ok) fail_on(ps, {}, "certify::rtd rejected rtd_incremental: " + rep.message(), describe(R.simplices));
  {  // the strict view (strict_rtd.hpp): certified at the exact level (no zero-volume simplex)
    const Simplices view = must_return(ps, {}, "strict_rtd", [&] { return ref::strict_rtd(ps, R.simplices); });
    const certify::Report rs = certify::rtd(ps, view, certify::Level::exact);
    if (!rs.ok) fail_on(ps, {}, "certify::rtd (exact) rejected the strict view: " + rs.message(), describe(view));
  }
  if (test::brute_rtd(ps) != R.simplices)
    fail_on(ps, {}, "rtd_incremental differs from the definition (brute_rtd)",
            "rtd_incremental:\n" + describe(R.simplices) + "brute_rtd:\n" + describe(test::brute_rtd(ps)));
  if (ref::rtd::real_simplices(must_return(ps, {}, "build_rtd", [&] { return ref::build_rtd(ps); })) != R.simplices)
    fail_on(ps, {}, "build_rtd differs from rtd_incremental");
  if (const auto lq = lattice_quotient(ps)) {
    // a lattice with a step (reference/lattice_quotient.hpp): the quotient is
    // exact (every x = q g, every w = q_w g^2: g = G 2^e with G < 2^53, q_w G^2
    // < 2^53 where a weight is not 0) and the kernel on it returns RT+1's
    // answer on the given values
    int e = 0;
    const double G = std::ldexp(std::frexp(lq->factor, &e), 53);
    for (std::size_t i = 0; i < ps.coords.size(); ++i) {
      const double q = lq->points.coords[i];
      if (q != std::trunc(q) || !(std::fabs(q) < 0x1p20) || std::fma(q, lq->factor, -ps.coords[i]) != 0.0)
        fail_on(ps, {}, "lattice_quotient: a coordinate is not q g");
    }
    if (ps.weighted)
      for (std::size_t i = 0; i < ps.size(); ++i) {
        const double q = lq->points.weights[i];
        if (q != std::trunc(q) || !(std::fabs(q) < 0x1p20) ||
            (q != 0.0 && std::ldexp(q * G * G, 2 * (e - 53)) != ps.weights[i]) || (q == 0.0 && ps.weights[i] != 0.0))
          fail_on(ps, {}, "lattice_quotient: a weight is not q_w g^2");
      }
    const ref::Rtd Q = must_return(ps, {}, "rtd_cavity on the quotient", [&] { return cpu::rtd_cavity(lq->points); });
    if (Q.simplices != R.simplices || Q.redundant != R.redundant)
      fail_on(ps, {}, "the cavity kernel on lattice_quotient's lattice differs from RT+1 on the given values",
              "on the quotient:\n" + describe(Q.simplices) + "rtd_incremental:\n" + describe(R.simplices));
  }
  for (bool furthest : {false, true}) {
    cpu::RtdCavityOptions o;
    o.furthest = furthest;
    o.brio_min = 1 + ps.size() % 5;
    const ref::Rtd C = must_return(ps, {}, "rtd_cavity", [&] { return cpu::rtd_cavity(ps, nullptr, o); });
    const ref::Rtd E = furthest ? must_return(ps, {}, "rtd_incremental (furthest)",
                                              [&] { return ref::rtd_incremental(ps, nullptr, true); })
                                : R;
    if (C.simplices != E.simplices || C.redundant != E.redundant)
      fail_on(ps, {}, std::string("the cavity kernel differs from RT+1") + (furthest ? " (furthest site)" : ""),
              "rtd_cavity:\n" + describe(C.simplices) + "rtd_incremental:\n" + describe(E.simplices));
    if (furthest && !certify::rtd(ps, E.simplices, certify::Level::canonical, true).ok)
      fail_on(ps, {}, "certify::rtd rejected the furthest-site RT+1");
  }
  {  // the hull kernel: the boundary of the unweighted triangulation
    PointSet plain = ps;
    plain.weighted = false;
    plain.weights = Values();
    const Simplices T = ps.weighted ? must_return(ps, {}, "rtd_incremental (unweighted)",
                                                  [&] { return ref::rtd_incremental(plain).simplices; })
                                    : R.simplices;
    std::map<std::vector<Index>, int> count;
    for (const auto& t : T)
      for (std::size_t i = 0; i < t.size(); ++i) {
        std::vector<Index> f = t;
        f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
        std::sort(f.begin(), f.end());
        ++count[f];
      }
    std::set<std::vector<Index>> boundary, hull;
    for (const auto& [f, c] : count)
      if (c == 1) boundary.insert(f);
    const Simplices H = must_return(ps, {}, "hull_d", [&] { return cpu::hull_d(plain); });
    for (std::vector<Index> f : H) {
      std::sort(f.begin(), f.end());
      hull.insert(f);
    }
    if (hull != boundary) fail_on(ps, {}, "hull_d differs from the triangulation's boundary");
    if (const std::string why = cpu::hull_d_problem(plain, H); !why.empty())
      fail_on(ps, {}, "hull_d_problem rejected hull_d: " + why);
  }
  if (d == 2) {
    Simplices t;
    for (const Triangle& x : must_return(ps, {}, "rt2_ffrt", [&] { return ref::rt2_ffrt(ps); })) t.push_back({x[0], x[1], x[2]});
    if (t != R.simplices) fail_on(ps, {}, "rtd_incremental differs from rt2_ffrt", describe(R.simplices) + "rt2_ffrt:\n" + describe(t));
  }
  const std::set<Index> v = simplex_vertices(R.simplices);
  std::vector<Index> missing;
  for (Index i = 0; i < n; ++i)
    if (!v.count(i)) missing.push_back(i);
  if (missing != R.redundant) fail_on(ps, {}, "the redundant list is not the non-vertices");
  const auto D = static_cast<std::uint64_t>(d);
  if (st.insertions != D + 1 + st.placed + st.flips[1] || st.insertions + st.redundant - st.removed != n ||
      st.removed != st.flips[D + 1] || st.redundant != missing.size() || st.queue_pops != st.queue_pushes)
    fail_on(ps, {}, "RT+1's counters do not add up");
  return R;
}

// ---- the instant flip ------------------------------------------------------------


void check_instant_flip(const PointSet& ps, const std::vector<double>& u) {
  const int d = ps.dim;
  const bool general =
      for_each_subset(ps.size(), d + 1, [&](const std::vector<Index>& t) { return orient_exact(ps, t) != 0; });
  std::vector<double> w(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) w[i] = ps.weight(i);
  const PointSet pw = with_weights(ps, w), pu = with_weights(ps, u);  // T keeps a pointer to pw
  ref::rtd::TriangulationD T = must_return(ps, u, "build_rtd", [&] { return ref::build_rtd(pw); });
  const Simplices start = ref::rtd::real_simplices(T);
  const std::vector<Index> V = ref::rtd::vertices(T);

  // Lemma 9.4 and its consequences, along the run (general position only)
  std::set<std::vector<Index>> present = ridges_of(start), gone, start_left;
  const std::set<std::vector<Index>> start_set(start.begin(), start.end());
  std::set<Index> removed;
  std::string lemma;
  ref::InstantFlipOptions opt;
  if (general)
    opt.on_flip = [&](const ref::rtd::TriangulationD& now, const ref::InstantFlipEvent& ev) {
      if (!lemma.empty()) return;
      if (ev.removed != ref::rtd::kNoVertex) removed.insert(ev.removed);
      for (Index x : removed)
        if (now.is_vertex(x)) lemma = "removed vertex " + std::to_string(x) + " is a vertex again";
      const Simplices s = ref::rtd::real_simplices(now);
      const std::set<std::vector<Index>> r = ridges_of(s), sset(s.begin(), s.end());
      for (const auto& f : present)
        if (!r.count(f)) gone.insert(f);
      for (const auto& f : r)
        if (gone.count(f)) lemma = "a ridge came back after it left (Lemma 9.4)";
      present = r;
      for (const auto& t : start_set)
        if (!sset.count(t)) start_left.insert(t);
    };
  ref::InstantFlipStats st;
  try {
    st = ref::instant_flip(T, w, u, opt);
  } catch (const std::logic_error& e) {  // std::invalid_argument included
    if (general) fail_on(ps, u, std::string("instant_flip threw on coordinates in general position: ") + e.what());
    return;  // documented for degenerate coordinates
  } catch (const std::exception& e) {
    fail_on(ps, u, std::string("instant_flip threw an undocumented exception: ") + e.what());
  }
  const Simplices out = ref::rtd::real_simplices(T);
  if (!general) {
    std::vector<Index> all(ps.size());
    std::iota(all.begin(), all.end(), Index{0});
    const std::string why = weak_regularity_problem(pu, out, all);
    if (!why.empty()) fail_on(ps, u, "instant flip on degenerate coordinates: " + why, describe(out));
    return;
  }
  if (!lemma.empty()) fail_on(ps, u, "instant flip: " + lemma);
  for (const auto& t : out)
    if (start_set.count(t) && start_left.count(t))
      fail_on(ps, u, "instant flip: a simplex of both build_rtd(S+W) and the result was removed on the way");
  const auto D = static_cast<std::size_t>(d);
  if (st.pops != st.total_flips() + st.stale + st.deferred || st.pushes != st.pops ||
      st.removed_vertices != st.flips[D + 1] || st.inserted_vertices != st.flips[1] ||
      simplex_vertices(out).size() + st.removed_vertices != V.size() + st.inserted_vertices)
    fail_on(ps, u, "instant flip: the counters do not add up");
  const ref::Rtd full = ref::rtd_incremental(pu);
  if (out != full.simplices)
    fail_on(ps, u, "instant flip differs from a fresh rtd_incremental(S+U)",
            "instant flip:\n" + describe(out) + "fresh:\n" + describe(full.simplices));
  if (!ref::reappearing_points(T, u).empty())
    fail_on(ps, u, "instant flip: a point that is not a vertex is non-redundant under U");
  const certify::Report rep = certify::rtd(pu, out);
  if (!rep.ok) fail_on(ps, u, "certify::rtd rejected the instant flip's result: " + rep.message());
}

// Exact: some d+1 points span R^d.
bool spans(const PointSet& ps) {
  return !for_each_subset(ps.size(), ps.dim + 1,
                          [&](const std::vector<Index>& t) { return orient_exact(ps, t) == 0; });
}

}  // namespace

bool check_rtd_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  const std::uint8_t flags = r.byte();
  const int d = 2 + (flags & 3);
  const bool weighted = (flags & 4) != 0;
  const int kind = (flags >> 3) & 3;
  PointSet ps;
  if (!decode_points(r, d, weighted, 1, kMaxPoints[d - 2], ps)) return false;

  if (!spans(ps)) {
    for (const char* name : {"rtd_incremental", "build_rtd"}) {
      try {
        if (name[0] == 'r') ref::rtd_incremental(ps);
        else ref::build_rtd(ps);
        fail_on(ps, {}, std::string(name) + " returned a triangulation of lower-dimensional input");
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail_on(ps, {}, std::string(name) + " threw the wrong exception on lower-dimensional input: " + e.what());
      }
    }
    return true;
  }
  check_rt_incremental(ps);
  const std::vector<double> u = target_weights(r, ps, kind);
  if (!u.empty()) check_instant_flip(ps, u);
  return true;
}

}  // namespace flipflop::fuzz

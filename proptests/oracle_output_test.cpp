// oracle_output_test.cpp — the reference's canonical OUTPUT against a brute
// force decided only by the independent SoS oracle (proptests/support/
// sos_brute.hpp over sos_oracle.hpp: the perturbed determinants expanded
// term by term in GMP, no code of predicates/, of reference/brute_force.* or
// of the canonical-form headers). The library is called only for the answer
// being checked; the comparison is the canonical text, byte for byte.
//
//   hull2   ref::hull2 "graham-sort", "graham-insert", "twist"
//   hull3   ref::hull3 "ffhull", "splay", "twist-flip"
//   rt2     ref::rt2_ffrt (both flip-flop variants), ref::dt2_lawson (zero
//           weights), ref::rtd_incremental (d = 2) — triangles and the
//           redundant points
//   rtd     ref::rtd_incremental, d = 3, 4, 5 — simplices and redundant points
// Input that does not span R^d (exact affine rank, computed here) must be
// rejected with std::invalid_argument by every entry point.
//
// Inputs (ids = input indices 0..n-1, PointSet's comment): a deterministic
// sweep (fixed seeds) of degenerate families — integer grids (with repeated
// points), lattice weights, lattice spheres with equal weights, points on a
// hyperplane with a few off it (or none: rejected), exact duplicates (same or
// different weights), weights that put every lifted point on one hyperplane —
// and uniform random doubles, a quarter of them scaled by 2^40 and 2^-40
// (weights by 2^±80: exact); plus RapidCheck properties on small integer
// inputs. Cases per run (Release, FLIPFLOP_RC_CASES = 2000): hull2 3200,
// hull3 1440, rt2 2400, rtd d = 3/4/5 896/320/128 (+160/96/64 [long]); RapidCheck
// hull2 1000, hull3 500, rt2 1000, rt3 250, rt4 125, rt5 50. About 12 s, the
// [long] case 8 s more; the sweeps are divided by 32 under the sanitizers.
// The last test cases plant errors: the library's answer, after it is
// returned, replaced by another valid answer of a degenerate input (the other
// diagonal of a cocircular square and of a square with coplanar lifted
// corners, a point on a hull edge added to / dropped from the cycle, the other
// diagonal of a cube face, the 2-3 flip of a cospherical bipyramid, another
// Delaunay triangulation of cospherical lattice points in R^4): the comparison
// must fail for every entry point; and the definition evaluated with the ids
// reversed must disagree with the library on the degenerate sweep.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "proptests/support/predicate_inputs.hpp"  // lattice_sphere (input generation only)
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/sos_brute.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;
namespace sb = flipflop::test::sos_brute;
using sb::Input;
using sb::Tuple;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int kSweepDivisor = 32;  // the driver runs at -O0 there: ~13x slower (measured)
#else
constexpr int kSweepDivisor = 1;
#endif

PointSet to_ps(const Input& in, bool weighted) {
  PointSet ps;
  ps.dim = in.d;
  ps.weighted = weighted;
  ps.coords = Values(in.x);
  if (weighted) ps.weights = Values(in.w);
  return ps;
}
bool zero_weights(const Input& in) {
  for (double w : in.w)
    if (w != 0) return false;
  return true;
}

std::string describe(const Input& in, bool weighted) {
  std::ostringstream o;
  o << "d=" << in.d << " n=" << in.n() << " points (index: coordinates; weight):\n";
  char buf[64];
  for (int i = 0; i < in.n(); ++i) {
    o << "  " << i << ":";
    for (int j = 0; j < in.d; ++j) {
      std::snprintf(buf, sizeof buf, " %.17g", in.p(i)[j]);
      o << buf;
    }
    if (weighted) {
      std::snprintf(buf, sizeof buf, "; %.17g", in.w[static_cast<size_t>(i)]);
      o << buf;
    }
    o << '\n';
  }
  return o.str();
}

std::vector<Tuple> tuples(const std::vector<Triangle>& ts) {
  std::vector<Tuple> out;
  for (const Triangle& t : ts) out.push_back({t[0], t[1], t[2]});
  return out;
}
std::vector<Tuple> tuples(const std::vector<std::vector<Index>>& ts) {
  std::vector<Tuple> out;
  for (const auto& t : ts) out.push_back(Tuple(t.begin(), t.end()));
  return out;
}

std::string mismatch(const std::string& who, const std::string& want, const std::string& got) {
  if (want == got) return "";
  return who + ":\n expected by the definition:\n" + want + " library:\n" + got;
}

template <class F>
std::string expect_rejected(const std::string& who, F&& f) {
  try {
    f();
  } catch (const std::invalid_argument&) {
    return "";
  } catch (const std::exception& e) {
    return who + ": input that does not span threw " + e.what() + " (not std::invalid_argument)\n";
  }
  return who + ": input that does not span was accepted\n";
}

template <class F>
std::string guarded(const std::string& who, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    return who + " threw: " + e.what() + "\n";
  }
}

// The planted-error tests (below) change the library's answer here, after it
// is returned and before it is compared; empty everywhere else.
std::function<void(std::vector<Tuple>&)> g_tamper;
struct Tampering {
  explicit Tampering(std::function<void(std::vector<Tuple>&)> f) { g_tamper = std::move(f); }
  ~Tampering() { g_tamper = nullptr; }
};
std::string lib_text(std::vector<Tuple> t) {
  if (g_tamper) g_tamper(t);
  return sb::text(t);
}
std::string lib_cycle(const std::vector<Index>& c) {
  std::vector<Tuple> v{Tuple(c.begin(), c.end())};
  if (g_tamper) g_tamper(v);
  return sb::cycle_text(v[0]);
}

// ---- the checks: "" when the library equals the definition, else a report ----------------
std::string check_hull2(const Input& in) {
  const PointSet ps = to_ps(in, false);
  std::string bad;
  if (!sb::spans(in)) {
    for (const std::string& a : ref::hull2_algorithms())
      bad += expect_rejected("hull2 " + a, [&] { ref::hull2(ps, a); });
  } else {
    const std::string want = sb::cycle_text(sb::hull2(in));
    for (const std::string& a : ref::hull2_algorithms())
      bad += guarded("hull2 " + a, [&] {
        const std::vector<Index> got = ref::hull2(ps, a);
        return mismatch("hull2 " + a, want, lib_cycle(got));
      });
  }
  return bad.empty() ? "" : describe(in, false) + bad;
}

std::string check_hull3(const Input& in) {
  const PointSet ps = to_ps(in, false);
  std::string bad;
  if (!sb::spans(in)) {
    for (const std::string& a : ref::hull3_algorithms())
      bad += expect_rejected("hull3 " + a, [&] { ref::hull3(ps, a); });
  } else {
    const std::string want = sb::text(sb::hull3(in));
    for (const std::string& a : ref::hull3_algorithms())
      bad += guarded("hull3 " + a, [&] { return mismatch("hull3 " + a, want, lib_text(tuples(ref::hull3(ps, a)))); });
  }
  return bad.empty() ? "" : describe(in, false) + bad;
}

// rt2 (d = 2: ffRT both variants, Lawson when unweighted, RT+1) or rtd (RT+1).
std::string check_rt(const Input& in) {
  const PointSet ps = to_ps(in, true);
  const bool unweighted = zero_weights(in);
  const PointSet ps0 = to_ps(in, false);
  std::string bad;
  if (!sb::spans(in)) {
    bad += expect_rejected("rtd_incremental", [&] { ref::rtd_incremental(ps); });
    if (in.d == 2) {
      bad += expect_rejected("rt2_ffrt", [&] { ref::rt2_ffrt(ps); });
      if (unweighted) bad += expect_rejected("dt2_lawson", [&] { ref::dt2_lawson(ps0); });
    }
  } else {
    const sb::Rt r = sb::rt(in);
    const std::string want = sb::text(r.simplices), want_red = sb::cycle_text(r.redundant);
    bad += guarded("rtd_incremental", [&] {
      const ref::Rtd got = ref::rtd_incremental(ps);
      return mismatch("rtd_incremental", want, lib_text(tuples(got.simplices))) +
             mismatch("rtd_incremental redundant", want_red,
                      sb::cycle_text(Tuple(got.redundant.begin(), got.redundant.end())));
    });
    if (in.d == 2) {
      bad += guarded("rt2_ffrt", [&] { return mismatch("rt2_ffrt", want, lib_text(tuples(ref::rt2_ffrt(ps)))); });
      bad += guarded("rt2_ffrt v_first", [&] {
        return mismatch("rt2_ffrt v_first", want,
                        lib_text(tuples(ref::rt2_ffrt(ps, nullptr, ref::FlipFlopVariant::v_first))));
      });
      if (unweighted)
        bad += guarded("dt2_lawson", [&] { return mismatch("dt2_lawson", want, lib_text(tuples(ref::dt2_lawson(ps0)))); });
    }
  }
  return bad.empty() ? "" : describe(in, true) + bad;
}

// The furthest-site triangulation (RT+1 with every power sign negated,
// ref::rtd_incremental's `furthest`; weights kept: heights -(|x|^2 - w))
// against the brute force's upper hull, and certify::rtd's furthest mode:
// it accepts that answer and rejects the (lower) regular triangulation where
// the two differ.
std::string check_furthest(const Input& in) {
  const PointSet ps = to_ps(in, true);
  std::string bad;
  if (!sb::spans(in)) {
    bad += expect_rejected("rtd_incremental furthest", [&] { ref::rtd_incremental(ps, nullptr, true); });
  } else {
    const sb::Rt r = sb::rt(in, /*furthest=*/true);
    const std::string want = sb::text(r.simplices), want_red = sb::cycle_text(r.redundant);
    bad += guarded("rtd_incremental furthest", [&] {
      const ref::Rtd got = ref::rtd_incremental(ps, nullptr, true);
      std::string out = mismatch("rtd_incremental furthest", want, lib_text(tuples(got.simplices))) +
                        mismatch("rtd_incremental furthest redundant", want_red,
                                 sb::cycle_text(Tuple(got.redundant.begin(), got.redundant.end())));
      const certify::Report c = certify::rtd(ps, got.simplices, certify::Level::canonical, true);
      if (!c.ok) out += "  certify::rtd (furthest) rejects it: " + c.message() + "\n";
      const ref::Rtd lower = ref::rtd_incremental(ps);
      const bool same = tuples(lower.simplices) == tuples(got.simplices);
      if (!same && certify::rtd(ps, lower.simplices, certify::Level::canonical, true).ok)
        out += "  certify::rtd (furthest) accepts the lower regular triangulation\n";
      return out;
    });
  }
  return bad.empty() ? "" : describe(in, true) + bad;
}

// ---- deterministic degenerate families ---------------------------------------------------
struct Gen {
  std::mt19937_64 g;
  explicit Gen(std::uint64_t seed) : g(seed) {}
  int pick(int lo, int hi) { return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1)); }
  double unit() { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
};

constexpr int kFamilies = 8;
const char* family_name(int f) {
  static const char* names[kFamilies] = {"grid {0,1,2}^d, zero weights",
                                         "grid {0,1,2}^d, lattice weights {0,1,2}",
                                         "lattice sphere, equal weights",
                                         "integer hyperplane, 0-2 points off it",
                                         "exact duplicates (same or other weight)",
                                         "lifted points on one hyperplane",
                                         "uniform doubles, small weights",
                                         "grid {-1,0,1}^d with every point of a line/plane"};
  return names[f];
}

Input family_input(int f, int d, int n, std::uint64_t seed) {
  Gen g(seed * 131 + static_cast<std::uint64_t>(f) * 7 + static_cast<std::uint64_t>(d));
  Input in;
  in.d = d;
  in.w.assign(static_cast<size_t>(n), 0.0);
  auto add = [&](const std::vector<int>& p) {
    for (int v : p) in.x.push_back(v);
  };
  auto rand_pt = [&](int lo, int hi) {
    std::vector<int> p(static_cast<size_t>(d));
    for (int& v : p) v = g.pick(lo, hi);
    return p;
  };
  switch (f) {
    case 0:
    case 1:
      for (int i = 0; i < n; ++i) add(rand_pt(0, 2));
      if (f == 1)
        for (double& w : in.w) w = g.pick(0, 2);
      break;
    case 2: {
      static const int r2[6] = {0, 0, 25, 9, 4, 4};
      std::vector<std::vector<int>> s = test::lattice_sphere(d, r2[d]);  // a copy: shuffled below
      for (size_t i = s.size(); i > 1; --i) std::swap(s[i - 1], s[g.g() % i]);  // shuffle
      for (int i = 0; i < n; ++i) add(s[static_cast<size_t>(i) % s.size()]);
      const double w = g.pick(-2, 2);
      for (double& v : in.w) v = w;
      break;
    }
    case 3: {
      std::vector<int> a(static_cast<size_t>(d - 1));
      for (int& v : a) v = g.pick(-1, 1);
      const int c = g.pick(-1, 1);
      const int off = g.pick(0, 2);
      for (int i = 0; i < n; ++i) {
        std::vector<int> p = rand_pt(-2, 2);
        int s = c;
        for (int j = 0; j < d - 1; ++j) s += a[static_cast<size_t>(j)] * p[static_cast<size_t>(j)];
        p[static_cast<size_t>(d - 1)] = i < off ? s + g.pick(1, 2) * (g.pick(0, 1) ? 1 : -1) : s;
        add(p);
      }
      for (double& w : in.w) w = g.pick(0, 1);
      break;
    }
    case 4: {
      const int k = std::max(d + 1, n / 2);
      std::vector<std::vector<int>> base;
      for (int i = 0; i < k; ++i) base.push_back(rand_pt(-3, 3));
      for (int i = 0; i < n; ++i) {
        const int b = i < k ? i : g.pick(0, k - 1);
        add(base[static_cast<size_t>(b)]);
        in.w[static_cast<size_t>(i)] = i < k ? g.pick(0, 1) : in.w[static_cast<size_t>(b)] + (g.pick(0, 2) == 0);
      }
      // shuffle the points (copies not always after their original)
      for (int i = n - 1; i > 0; --i) {
        const int j = g.pick(0, i);
        for (int t = 0; t < d; ++t)
          std::swap(in.x[static_cast<size_t>(i * d + t)], in.x[static_cast<size_t>(j * d + t)]);
        std::swap(in.w[static_cast<size_t>(i)], in.w[static_cast<size_t>(j)]);
      }
      break;
    }
    case 5: {  // w = |x|² - (a·x + b): every lifted point on the hyperplane h = a·x + b
      std::vector<int> a = rand_pt(-1, 1);
      const int b = g.pick(-2, 2);
      for (int i = 0; i < n; ++i) {
        std::vector<int> p = rand_pt(-2, 2);
        add(p);
        int q = 0, l = b;
        for (int j = 0; j < d; ++j) q += p[static_cast<size_t>(j)] * p[static_cast<size_t>(j)], l += a[static_cast<size_t>(j)] * p[static_cast<size_t>(j)];
        in.w[static_cast<size_t>(i)] = q - l;
      }
      break;
    }
    case 6:
      for (int i = 0; i < n * d; ++i) in.x.push_back(2 * g.unit() - 1);
      for (double& w : in.w) w = 0.1 * g.unit();
      break;
    default: {  // a full grid line (2D) / plane (d >= 3) plus random grid points
      const int m = std::min(n, d == 2 ? 3 : 9);
      for (int i = 0; i < m; ++i) {
        std::vector<int> p(static_cast<size_t>(d), 0);
        p[0] = i % 3 - 1;
        if (d >= 3) p[1] = i / 3 - 1;
        add(p);
      }
      for (int i = m; i < n; ++i) add(rand_pt(-1, 1));
      // move the line/plane to a random place among the indices
      for (int i = n - 1; i > 0; --i) {
        const int j = g.pick(0, i);
        for (int t = 0; t < d; ++t)
          std::swap(in.x[static_cast<size_t>(i * d + t)], in.x[static_cast<size_t>(j * d + t)]);
      }
      break;
    }
  }
  // an exact power-of-two scale (x by 2^e, w by 2^(2e): every sign kept)
  // on a quarter of the cases each way: the filters see other magnitudes
  static const int exps[4] = {0, 0, 40, -40};
  const int e = exps[g.g() % 4];
  for (double& v : in.x) v = std::ldexp(v, e);
  for (double& v : in.w) v = std::ldexp(v, 2 * e);
  return in;
}

enum class Kind { hull2, hull3, rt, furthest };
std::string check(Kind k, const Input& in) {
  return k == Kind::hull2   ? check_hull2(in)
         : k == Kind::hull3 ? check_hull3(in)
         : k == Kind::rt    ? check_rt(in)
                            : check_furthest(in);
}

// Every family, n = nlo..nhi, `seeds` seeds each; counts the cases and the
// non-spanning (rejected) ones.
void sweep(Kind k, int d, int nlo, int nhi, int seeds) {
  int cases = 0, rejected = 0;
  seeds = std::max(1, seeds / kSweepDivisor);
  for (int f = 0; f < kFamilies; ++f)
    for (int n = nlo; n <= nhi; ++n)
      for (int s = 0; s < seeds; ++s) {
        const Input in = family_input(f, d, n, static_cast<std::uint64_t>(s));
        const std::string bad = check(k, in);
        ++cases;
        rejected += !sb::spans(in);
        INFO("family " << f << " (" << family_name(f) << "), seed " << s);
        if (!bad.empty()) FAIL_CHECK(bad);
      }
  INFO(cases << " cases, " << rejected << " rejected as not spanning");
  SUCCEED();
}

// RapidCheck: n points with integer coordinates in [lo, hi], weights in
// [0, wmax] (0: unweighted).
Input rc_input(int d, int nlo, int nhi, int lo, int hi, int wmax) {
  const int n = *rc::gen::inRange(nlo, nhi + 1);
  Input in;
  in.d = d;
  in.x = *rc::gen::container<std::vector<double>>(
      static_cast<size_t>(n * d), rc::gen::map(rc::gen::inRange(lo, hi + 1), [](int v) { return double(v); }));
  in.w = *rc::gen::container<std::vector<double>>(
      static_cast<size_t>(n), rc::gen::map(rc::gen::inRange(0, wmax + 1), [](int v) { return double(v); }));
  return in;
}

}  // namespace

// ---- the brute force's own sanity: hand-checked answers -------------------------------------
TEST_CASE("oracle: the SoS brute force gives the hand-derived answers of a square and a tetrahedron") {
  Input sq{2, {0, 0, 1, 0, 1, 1, 0, 1}, {0, 0, 0, 0}};
  REQUIRE(sb::cycle_text(sb::hull2(sq)) == "0\n1\n2\n3\n");
  Input tet{3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0, 0}};
  // ccw seen from outside: the face z = 0 is seen from below as 0, 2, 1
  REQUIRE(sb::text(sb::hull3(tet)) == "0 1 3\n0 2 1\n0 3 2\n1 2 3\n");
  // one tetrahedron, positive volume (det[p1-p0, p2-p0, p3-p0] = 1 for 0 1 2 3)
  REQUIRE(sb::text(sb::rt(tet).simplices) == "0 1 2 3\n");
  Input tri{2, {0, 0, 1, 0, 0, 1, 0.25, 0.25}, {0, 0, 0, 5}};  // point 3: heavy, inside
  const sb::Rt r = sb::rt(tri);
  REQUIRE(sb::text(r.simplices) == "0 1 3\n0 3 2\n1 2 3\n");
  Input tri_light{2, {0, 0, 1, 0, 0, 1, 0.25, 0.25}, {0, 0, 0, -5}};  // lifted far above: redundant
  REQUIRE(sb::text(sb::rt(tri_light).simplices) == "0 1 2\n");
  REQUIRE(sb::rt(tri_light).redundant == Tuple{3});
}

// ---- deterministic sweeps --------------------------------------------------------------------
TEST_CASE("oracle: hull2 of every algorithm equals the SoS definition on degenerate and random sets") {
  sweep(Kind::hull2, 2, 3, 12, 40);
}

TEST_CASE("oracle: hull3 of every algorithm equals the SoS definition on degenerate and random sets") {
  sweep(Kind::hull3, 3, 4, 12, 20);
}

TEST_CASE("oracle: rt2/dt2 (ffRT and Lawson and RT+1) equal the SoS lower hull on degenerate and random sets") {
  sweep(Kind::rt, 2, 3, 12, 30);
}

TEST_CASE("oracle: rtd (RT+1) equals the SoS lower hull on degenerate and random sets in d = 3") {
  sweep(Kind::rt, 3, 4, 10, 16);
}

TEST_CASE("oracle: rtd (RT+1) equals the SoS lower hull on degenerate and random sets in d = 4 and 5") {
  sweep(Kind::rt, 4, 5, 9, 8);
  sweep(Kind::rt, 5, 6, 9, 4);
}

TEST_CASE("oracle: the furthest-site triangulation (RT+1, power signs negated) equals the SoS upper hull in d = 2 to 5") {
  sweep(Kind::furthest, 2, 3, 11, 20);
  sweep(Kind::furthest, 3, 4, 9, 10);
  sweep(Kind::furthest, 4, 5, 8, 4);
  sweep(Kind::furthest, 5, 6, 8, 2);
}

TEST_CASE("oracle: rtd (RT+1) equals the SoS lower hull in a larger sweep in d = 3 to 5", "[long]") {
  sweep(Kind::rt, 3, 11, 12, 10);
  sweep(Kind::rt, 4, 10, 11, 6);
  sweep(Kind::rt, 5, 10, 11, 4);
}

// ---- RapidCheck: small integer inputs (many exact degeneracies) -----------------------------
TEST_CASE("oracle: random small integer inputs of every kind equal the SoS definition") {
  test::prop_scaled("hull2", 2, [] {
    const Input in = rc_input(2, 3, 10, -2, 2, 0);
    const std::string bad = check_hull2(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
  test::prop_scaled("hull3", 4, [] {
    const Input in = rc_input(3, 4, 10, -1, 2, 0);
    const std::string bad = check_hull3(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
  test::prop_scaled("rt2", 2, [] {
    const Input in = rc_input(2, 3, 10, -2, 2, *rc::gen::element(0, 2));
    const std::string bad = check_rt(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
  test::prop_scaled("rt3", 8, [] {
    const Input in = rc_input(3, 4, 9, -1, 1, *rc::gen::element(0, 1));
    const std::string bad = check_rt(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
  test::prop_scaled("rt4", 16, [] {
    const Input in = rc_input(4, 5, 8, 0, 1, *rc::gen::element(0, 1));
    const std::string bad = check_rt(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
  test::prop_scaled("rt5", 40, [] {
    const Input in = rc_input(5, 6, 8, 0, 1, *rc::gen::element(0, 1));
    const std::string bad = check_rt(in);
    if (!bad.empty()) RC_FAIL(bad);
  });
}

// ---- planted errors: the comparison must fail ---------------------------------------------------
namespace {
// Replace the simplices `from` by `to` when the answer holds all of `from`
// (the answer stays a valid triangulation / hull of the exact input); true
// if it did.
bool replace(std::vector<Tuple>& ts, const std::vector<Tuple>& from, const std::vector<Tuple>& to) {
  for (const Tuple& t : from)
    if (std::find(ts.begin(), ts.end(), t) == ts.end()) return false;
  std::vector<Tuple> out;
  for (const Tuple& t : ts)
    if (std::find(from.begin(), from.end(), t) == from.end()) out.push_back(t);
  for (const Tuple& t : to) out.push_back(t);
  std::sort(out.begin(), out.end());
  ts = out;
  return true;
}
// A tamper that swaps the two alternatives a <-> b (whichever is present).
std::function<void(std::vector<Tuple>&)> swap_alternatives(std::vector<Tuple> a, std::vector<Tuple> b, int* done) {
  return [a, b, done](std::vector<Tuple>& ts) {
    if (replace(ts, a, b) || replace(ts, b, a)) ++*done;
  };
}
// Canonical tuples of the positive orientation of each of `ts` (the brute
// force's own orientation, so the planted answers are written correctly).
std::vector<Tuple> positive(const Input& in, std::vector<Tuple> ts) {
  const int vol = in.d % 2 == 0 ? 1 : -1;  // volume = (-1)^d Λ
  for (Tuple& t : ts) {
    if (vol * sb::orient(in, t) < 0) std::swap(t[0], t[1]);
    t = sb::canonical(t);
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}
}  // namespace

TEST_CASE("oracle: a planted error (another valid answer of a degenerate set) is caught") {
  int done = 0;
  std::string report;
  SECTION("dt2 (ffRT, Lawson, RT+1): the other diagonal of a cocircular square") {
    const Input in{2, {0, 0, 1, 0, 1, 1, 0, 1}, {0, 0, 0, 0}};
    REQUIRE(check_rt(in).empty());
    Tampering t(swap_alternatives(positive(in, {{0, 1, 2}, {0, 2, 3}}), positive(in, {{0, 1, 3}, {1, 2, 3}}), &done));
    report = check_rt(in);
    CHECK(done == 4);  // rtd_incremental, ffRT twice, Lawson
  }
  SECTION("rt2 with lattice weights: the other diagonal of a square whose lifted corners are coplanar") {
    // w = |x|² - (x + 2y): all four lifted corners on the plane h = x + 2y
    const Input in{2, {0, 0, 2, 0, 2, 2, 0, 2}, {0, 2, 2, -4}};
    REQUIRE(check_rt(in).empty());
    Tampering t(swap_alternatives(positive(in, {{0, 1, 2}, {0, 2, 3}}), positive(in, {{0, 1, 3}, {1, 2, 3}}), &done));
    report = check_rt(in);
    CHECK(done == 3);  // rtd_incremental, ffRT twice (weighted: no Lawson)
  }
  SECTION("hull2: a point on a hull edge added to or dropped from the cycle") {
    const Input in{2, {0, 0, 2, 0, 2, 2, 0, 2, 1, 0}, {0, 0, 0, 0, 0}};  // 4: the middle of edge 0-1
    REQUIRE(check_hull2(in).empty());
    Tampering t([&](std::vector<Tuple>& c) {
      Tuple out;
      const bool has4 = std::find(c[0].begin(), c[0].end(), 4u) != c[0].end();
      for (auto v : c[0]) {
        if (v == 4) continue;
        out.push_back(v);
        if (!has4 && v == 0) out.push_back(4);  // 0 -> 4 -> 1 is counter-clockwise
      }
      c[0] = out;
      ++done;
    });
    report = check_hull2(in);
    CHECK(done == 3);
  }
  SECTION("hull3: the other diagonal of a square face of a cube") {
    Input in{3, {}, {}};
    for (int i = 0; i < 8; ++i) {
      in.x.push_back(i & 1);
      in.x.push_back((i >> 1) & 1);
      in.x.push_back((i >> 2) & 1);
      in.w.push_back(0);
    }
    REQUIRE(check_hull3(in).empty());
    // face z = 0 (points 0 1 2 3), counter-clockwise seen from below: 0 2 3 1
    Tampering t(swap_alternatives({{0, 2, 1}, {1, 2, 3}}, {{0, 2, 3}, {0, 3, 1}}, &done));
    report = check_hull3(in);
    CHECK(done == 3);
  }
  SECTION("rtd d = 3: the 2-3 flip of a cospherical bipyramid") {
    // (5,0,0), (-3,4,0), (-3,-4,0), (0,0,5), (0,0,-5): all on the sphere of
    // radius 5; the apex-apex segment crosses the triangle's interior, so
    // {2 tetrahedra on the triangle} and {3 around the axis} both
    // triangulate it and both are Delaunay in exact arithmetic
    const Input in{3, {5, 0, 0, -3, 4, 0, -3, -4, 0, 0, 0, 5, 0, 0, -5}, {0, 0, 0, 0, 0}};
    REQUIRE(check_rt(in).empty());
    Tampering t(swap_alternatives(positive(in, {{0, 1, 2, 3}, {0, 1, 2, 4}}),
                                  positive(in, {{3, 4, 0, 1}, {3, 4, 1, 2}, {3, 4, 2, 0}}), &done));
    report = check_rt(in);
    CHECK(done == 1);
  }
  SECTION("rtd d = 4: another Delaunay triangulation of cospherical lattice points") {
    // lattice points of the sphere |x|² = 4 in R^4 (equal weights): the
    // first sweep input whose answer differs from the definition's answer
    // for the reversed perturbation order (ids n-1-i: another valid
    // triangulation of the same points) gets that answer planted
    const int n = 8;
    std::vector<Tuple> other;
    Input in;
    for (std::uint64_t seed = 0; seed < 40 && other.empty(); ++seed) {
      in = family_input(2, 4, n, seed);
      if (!sb::spans(in)) continue;
      Input rev = in;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < 4; ++j) rev.x[static_cast<size_t>(i * 4 + j)] = in.p(n - 1 - i)[j];
        rev.w[static_cast<size_t>(i)] = in.w[static_cast<size_t>(n - 1 - i)];
      }
      std::vector<Tuple> o = sb::rt(rev).simplices;
      for (Tuple& t : o) {
        for (auto& v : t) v = static_cast<std::uint32_t>(n - 1) - v;
        t = sb::canonical(t);
      }
      std::sort(o.begin(), o.end());
      if (sb::text(o) != sb::text(sb::rt(in).simplices)) other = o;
    }
    REQUIRE(!other.empty());
    REQUIRE(check_rt(in).empty());
    Tampering t([&](std::vector<Tuple>& ts) {
      ts = other;
      ++done;
    });
    report = check_rt(in);
    CHECK(done == 1);
  }
  INFO(report);
  CHECK(report.find("expected by the definition") != std::string::npos);
}

TEST_CASE("oracle: a planted perturbation-order error (ids reversed) is caught by the degenerate sweep") {
  // The brute force run on the points in reverse order, its indices mapped
  // back: the definition with the SoS ids n-1-i instead of i. Every answer
  // is still a valid hull / regular triangulation of the exact input, so
  // only the perturbation order tells it from the library's; the degenerate
  // families must expose it.
  auto reversed = [](const Input& in) {
    Input r = in;
    const int n = in.n(), d = in.d;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < d; ++j) r.x[static_cast<size_t>(i * d + j)] = in.p(n - 1 - i)[j];
      r.w[static_cast<size_t>(i)] = in.w[static_cast<size_t>(n - 1 - i)];
    }
    return r;
  };
  auto back = [](std::vector<Tuple> ts, int n) {  // relabel, re-canonicalise
    for (Tuple& t : ts) {
      for (auto& v : t) v = static_cast<std::uint32_t>(n - 1) - v;
      t = sb::canonical(t);
    }
    std::sort(ts.begin(), ts.end());
    return ts;
  };
  int cases = 0, cases3 = 0, caught_hull2 = 0, caught_hull3 = 0, caught_rt = 0;
  for (int f = 0; f < kFamilies; ++f)
    for (int s = 0; s < 3; ++s) {
      if (const Input in = family_input(f, 2, 8, static_cast<std::uint64_t>(s)); sb::spans(in)) {
        ++cases;
        const int n = in.n();
        // hull2: the reversed cycle relabelled is still counter-clockwise
        Tuple c = sb::hull2(reversed(in));
        for (auto& v : c) v = static_cast<std::uint32_t>(n - 1) - v;
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        const std::vector<Index> lib = ref::hull2(to_ps(in, false), "graham-sort");
        caught_hull2 += !mismatch("", sb::cycle_text(c), sb::cycle_text(Tuple(lib.begin(), lib.end()))).empty();
        const std::vector<Tuple> t = back(sb::rt(reversed(in)).simplices, n);
        caught_rt += !mismatch("", sb::text(t), sb::text(tuples(ref::rt2_ffrt(to_ps(in, true))))).empty();
      }
      const Input in3 = family_input(f, 3, 9, static_cast<std::uint64_t>(s));
      if (!sb::spans(in3)) continue;
      ++cases3;
      const std::vector<Tuple> h = back(sb::hull3(reversed(in3)), in3.n());
      caught_hull3 += !mismatch("", sb::text(h), sb::text(tuples(ref::hull3(to_ps(in3, false), "ffhull")))).empty();
    }
  INFO(cases << " 2D cases, " << cases3 << " 3D cases; caught: hull2 " << caught_hull2 << ", rt2 " << caught_rt
             << ", hull3 " << caught_hull3);
  CHECK(caught_hull2 > 0);
  CHECK(caught_rt > 0);
  CHECK(caught_hull3 > 0);
}

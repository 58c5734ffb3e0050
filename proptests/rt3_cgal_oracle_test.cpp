// rt3_cgal_oracle_test.cpp — the 3D Delaunay / regular triangulation against
// triangulators that share no code with flipflop (DESIGN.md "Oracles"):
//   CGAL       Delaunay_triangulation_3 and Regular_triangulation_3 (Epick:
//              exact predicates), sequential and with Parallel_tag on two
//              threads (peers/triangulation3.hpp);
//   TetGen     tetrahedralize "Q" (Shewchuk's exact predicates), where the
//              build has it;
//   Qhull      "d Qt Qbb" (floating point: on random input of this size it
//              has never been misled; a failure here would name Qhull);
//   GMP        the sign of every tetrahedron's volume, det[p1 - p0, p2 - p0,
//              p3 - p0] over mpq (proptests/support/mpq_det.hpp).
// On input in general position — uniform random doubles in a cube or a ball,
// weights uniform random doubles: five cospherical points, four coplanar ones
// or a tie of power distances occur with probability zero — the regular
// triangulation is unique, so every exact triangulator must return exactly
// ref::rtd_incremental's canonical simplices (d = 3) and cpu::rt3's
// tetrahedra: the same set, the same orientations (positive volume), the same
// hidden (redundant) points.
//
// Sizes: 4 to 2000 points, log-uniform (most cases small, every size
// reached); a [long] case runs 20000.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "kernels_cpu/rt3/rt3.hpp"
#include "peers/triangulation3.hpp"
#include "proptests/support/mpq_det.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;

namespace {

using Tets = std::vector<peers::Tet>;

// n uniform random points (doubles in [0, 1)) in the unit cube or in the ball
// of radius 1/2 around its centre (by rejection); when whi > 0, weights
// uniform in [0, whi · s^2] with s = n^(-1/3) the typical spacing, so that
// whi ≈ 1 hides a good share of the points.
PointSet random_input(std::size_t n, std::uint64_t seed, bool ball, double whi) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointSet ps;
  ps.dim = 3;
  while (ps.size() < n) {
    const double p[3] = {u(g), u(g), u(g)};
    if (ball) {
      double r2 = 0;
      for (double c : p) r2 += (c - 0.5) * (c - 0.5);
      if (r2 > 0.25) continue;
    }
    ps.coords.insert(ps.coords.end(), p, p + 3);
  }
  if (whi > 0) {
    ps.weighted = true;
    const double s2 = std::pow(static_cast<double>(n), -2.0 / 3.0);
    for (std::size_t i = 0; i < n; ++i) ps.weights.push_back(whi * s2 * u(g));
  }
  return ps;
}

struct Case {
  PointSet ps;
  std::string what;
};

// A random case: 4..2000 points, log-uniform in n; cube or ball; weighted
// (whi in {0.05, 0.5, 2}) or not.
rc::Gen<Case> random_case(bool weighted) {
  return rc::gen::exec([weighted] {
    const double t = *rc::gen::inRange(0, 1001) / 1000.0;
    const auto n = static_cast<std::size_t>(std::floor(4.0 * std::pow(500.0, t)));  // 4 .. 2000
    const std::uint64_t seed = *rc::gen::noShrink(rc::gen::arbitrary<std::uint64_t>());
    const bool ball = *rc::gen::arbitrary<bool>();
    const double whi = weighted ? *rc::gen::element(0.05, 0.5, 2.0) : 0.0;
    return Case{random_input(n, seed, ball, whi), "n=" + std::to_string(n) + " seed=" + std::to_string(seed) +
                                                       (ball ? " ball" : " cube") + " whi=" + std::to_string(whi)};
  });
}

Tets as_tets(const std::vector<std::vector<Index>>& s) {
  Tets out(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) std::copy(s[i].begin(), s[i].end(), out[i].begin());
  return out;
}

// Every tetrahedron has positive volume, decided over GMP rationals.
bool all_positive(const PointSet& ps, const Tets& tets) {
  for (const peers::Tet& t : tets)
    if (test::exact_volume_sign(ps, std::vector<Index>(t.begin(), t.end())) != 1) return false;
  return true;
}

// The input indices that are vertices of no tetrahedron.
std::vector<Index> hidden(const PointSet& ps, const Tets& tets) {
  std::vector<char> used(ps.size(), 0);
  for (const peers::Tet& t : tets)
    for (Index v : t) used[v] = 1;
  std::vector<Index> out;
  for (Index i = 0; i < ps.size(); ++i)
    if (!used[i]) out.push_back(i);
  return out;
}

peers::Cgal3Options parallel2() {
  peers::Cgal3Options o;
  o.parallel = true;
  o.threads = 2;
  return o;
}

}  // namespace

TEST_CASE("oracle: canonical_tets is canonical_d.hpp's canonical form of volume-positive tetrahedra") {
  rc::prop("any even or odd permutation of distinct indices", [] {
    const auto a = *rc::gen::container<std::vector<Index>>(4, rc::gen::inRange<Index>(0, 50));
    std::vector<Index> s = a;
    std::sort(s.begin(), s.end());
    RC_PRE(std::adjacent_find(s.begin(), s.end()) == s.end());
    const Tets got = peers::canonical_tets({{a[0], a[1], a[2], a[3]}});
    const std::vector<Index> want = canonical_simplex(a, Orientation::volume);
    RC_ASSERT(std::vector<Index>(got[0].begin(), got[0].end()) == want);
  });
  // the list sorted as canonical_simplices sorts it
  const std::vector<std::vector<Index>> in = {{5, 1, 2, 3}, {0, 9, 8, 7}, {4, 3, 2, 1}, {1, 2, 3, 0}, {0, 1, 3, 2}};
  Tets arr;
  for (const auto& t : in) arr.push_back({t[0], t[1], t[2], t[3]});
  CHECK(peers::canonical_tets(arr) == as_tets(canonical_simplices(in, Orientation::volume)));
}

TEST_CASE("oracle: CGAL Delaunay_triangulation_3 (sequential and parallel) equals the reference on random input, every tetrahedron of positive volume") {
  rc::prop("dt3 == CGAL", [] {
    const Case c = *random_case(false);
    RC_TAG(c.ps.size() < 100 ? "n < 100" : "n >= 100");
    const Tets ref = as_tets(ref::rtd_incremental(c.ps).simplices);
    RC_ASSERT(!ref.empty());
    RC_ASSERT(all_positive(c.ps, ref));
    RC_ASSERT(peers::cgal_delaunay3(c.ps) == ref);
    RC_ASSERT(peers::cgal_delaunay3(c.ps, parallel2()) == ref);
    RC_ASSERT(hidden(c.ps, ref).empty());  // unweighted: every point a vertex
  });
}

TEST_CASE("oracle: CGAL Regular_triangulation_3 (sequential and parallel) equals the reference on random weighted input, hidden points included") {
  std::size_t redundant = 0, points = 0;
  rc::prop("rt3 == CGAL", [&] {
    const Case c = *random_case(true);
    const ref::Rtd r = ref::rtd_incremental(c.ps);
    const Tets ref = as_tets(r.simplices);
    RC_ASSERT(all_positive(c.ps, ref));
    const Tets seq = peers::cgal_regular3(c.ps), par = peers::cgal_regular3(c.ps, parallel2());
    RC_ASSERT(seq == ref);
    RC_ASSERT(par == ref);
    RC_ASSERT(hidden(c.ps, seq) == r.redundant);
    redundant += r.redundant.size();
    points += c.ps.size();
  });
  INFO(redundant << " of " << points << " points redundant");
  CHECK(redundant > points / 50);  // the weights really hide points
}

TEST_CASE("oracle: cpu::rt3 equals CGAL's Delaunay and regular triangulations on random input") {
  rc::prop("cpu::rt3 == CGAL", [] {
    const bool weighted = *rc::gen::arbitrary<bool>();
    const Case c = *random_case(weighted);
    cpu::Rt3Options o;
    o.threads = *rc::gen::element(1, 2, 4);
    const cpu::Rt3Result got = cpu::rt3(c.ps, o);
    const Tets cg = weighted ? peers::cgal_regular3(c.ps) : peers::cgal_delaunay3(c.ps);
    RC_ASSERT(got.tets == cg);
    RC_ASSERT(got.redundant == hidden(c.ps, cg));
    RC_ASSERT(all_positive(c.ps, got.tets));
  });
}

TEST_CASE("oracle: TetGen's Delaunay tetrahedralization equals the reference on random input") {
  // make deps installs TetGen (libtet1.5-dev): a build without it fails here
  // rather than count an oracle that did not run as passed
  INFO("this build has no TetGen: install libtet1.5-dev (make deps) and reconfigure");
  REQUIRE(peers::tetgen_available());
  rc::prop("dt3 == TetGen", [] {
    const Case c = *random_case(false);
    RC_ASSERT(peers::tetgen_delaunay3(c.ps) == as_tets(ref::rtd_incremental(c.ps).simplices));
  });
}

TEST_CASE("oracle: Qhull d Qt Qbb equals the reference on random input") {
  rc::prop("dt3 == Qhull", [] {
    const Case c = *random_case(false);
    RC_PRE(c.ps.size() >= 5);  // Qhull needs more than d + 1 points for a 4-d hull
    RC_ASSERT(peers::qhull_delaunay3(c.ps) == as_tets(ref::rtd_incremental(c.ps).simplices));
  });
}

TEST_CASE("oracle: 20000 random points, cube and ball, weighted and not: every triangulator agrees", "[long]") {
  for (const bool ball : {false, true})
    for (const double whi : {0.0, 0.5}) {
      const PointSet ps = random_input(20000, ball ? 7 : 3, ball, whi);
      INFO((ball ? "ball" : "cube") << " whi=" << whi);
      const ref::Rtd r = ref::rtd_incremental(ps);
      const Tets ref = as_tets(r.simplices);
      CHECK(all_positive(ps, ref));
      CHECK(cpu::rt3(ps).tets == ref);
      CHECK(peers::cgal_regular3(ps) == ref);
      CHECK(peers::cgal_regular3(ps, parallel2()) == ref);
      if (whi == 0) {
        CHECK(peers::cgal_delaunay3(ps) == ref);
        CHECK(peers::cgal_delaunay3(ps, parallel2()) == ref);
        if (peers::tetgen_available()) CHECK(peers::tetgen_delaunay3(ps) == ref);
        CHECK(peers::qhull_delaunay3(ps) == ref);
      } else {
        CHECK(!r.redundant.empty());
      }
    }
}

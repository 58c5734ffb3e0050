// ffhull_orders_test.cpp — EVERY ORDER, exhaustively: flip-flop for 3D convex
// hull (thesis §6.2, Algorithm 6) has free execution order (§3.2), so every
// order in which its applicable operations can be taken must terminate at the
// same hull (Theorem 6.12) — the brute-force SoS answer.
//
// For inputs of at most 7 points (random sets and degenerate ones: cube
// corners, coplanar points, duplicates) a depth-first search explores the
// whole state space reachable from a star-shaped starting polyhedron in
// which every point is a vertex: from each state every applicable operation
// (ff3::applicable: each edge on which Algorithm 6's local check acts — a 3-1
// flip, a 2-2 flip or a label) is taken, states memoised on the canonical
// triangle set and the labels of its vertices. A state met again while it is
// on the DFS stack is a cycle, a path that never terminates. Every terminal
// state must be final (all edges convex, no labelled vertex: Theorem 6.2) and
// equal brute::hull3. Larger inputs take random orders through ff3::run's
// chooser.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "gen/generate.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/ffhull_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/polyhedron3.hpp"

using namespace flipflop;
namespace ff3 = flipflop::ref::ff3;
namespace poly = flipflop::ref::poly;
using test::spans3;

namespace {

struct Result {
  std::size_t states = 0, moves = 0, terminals = 0, max_states = 0;
  bool cycle = false;
  std::set<std::vector<Triangle>> finals;
  std::vector<std::string> bad_terminal;
};

enum : int { kOnStack = 1, kDone = 2 };

using Key = std::pair<std::vector<Triangle>, std::vector<std::uint8_t>>;

Key key(const ff3::State& st) {
  std::vector<std::uint8_t> labels(st.labelled.size(), 0);
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = st.labelled[v] && st.P.is_vertex(static_cast<Index>(v));
  return {canonical_triangles(poly::triangles(st.P)), labels};
}

void dfs(const ff3::State& st, std::map<Key, int>& memo, Result& r, std::size_t max_states) {
  const Key k = key(st);
  auto [it, fresh] = memo.emplace(k, kOnStack);
  if (!fresh) {
    if (it->second == kOnStack) r.cycle = true;
    return;
  }
  ++r.states;
  if (r.states > max_states) return;
  const std::vector<ff3::Candidate> moves = ff3::applicable(st);  // Algorithm 6, lines 5-19 on every edge
  if (moves.empty()) {
    ++r.terminals;
    r.finals.insert(k.first);
    if (std::string p = ff3::final_problem(st); !p.empty()) r.bad_terminal.push_back(p);
  }
  for (const ff3::Candidate& m : moves) {
    ++r.moves;
    ff3::State next = st;
    ff3::apply(next, m.u, m.w, m.d, nullptr, nullptr);
    dfs(next, memo, r, max_states);
  }
  memo[k] = kDone;
}

// Explores every order from `surface`; checks the outcome.
Result explore(const PointSet& ps, const ref::KernelPoint& s, const std::vector<Triangle>& surface) {
  REQUIRE(ref::is_star_shaped(ps, surface, s));
  const ff3::State st = ff3::make_state(ps, s, poly::build(ps.size(), surface));
  std::map<Key, int> memo;
  Result r;
  const std::size_t max_states = 200000;
  dfs(st, memo, r, max_states);
  REQUIRE(r.states <= max_states);
  REQUIRE_FALSE(r.cycle);
  INFO((r.bad_terminal.empty() ? std::string() : r.bad_terminal.front()));
  REQUIRE(r.bad_terminal.empty());
  REQUIRE(r.finals.size() == 1);
  REQUIRE(*r.finals.begin() == test::brute_hull_of_vertices(ps, surface));
  return r;
}

PointSet points(std::initializer_list<double> c) {
  PointSet ps;
  ps.dim = 3;
  ps.coords = c;
  return ps;
}

// Degenerate inputs of at most 7 points.
std::vector<std::pair<std::string, PointSet>> degenerate_inputs() {
  return {
      {"7 cube corners", points({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1})},
      {"6 cube corners + center", points({0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 0, 0, 2, 2, 2, 2, 1, 1, 1})},
      {"5 coplanar (square + center) + 2 apexes",
       points({0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 0, 1, 1, 3, 1, 1, -1})},
      {"coplanar face with interior points", points({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 2, 1, 0, 1, 2, 0, 1, 1, 5})},
      {"tetrahedron with duplicates", points({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 1})},
      {"duplicated interior point", points({0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 1, 1, 1, 1, 1, 1, 4, 0, 0})},
      {"octahedron minus one + center",
       points({1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0})},
  };
}

void add(Result& total, const Result& r) {
  total.states += r.states, total.moves += r.moves, total.terminals += r.terminals;
  total.max_states = std::max(total.max_states, r.states);
}

void explore_all_starts(const PointSet& ps, Result& total, std::size_t& starts) {
  std::set<std::vector<Triangle>> seen;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    // every point a vertex (dents included), around the centroid of a random
    // tetrahedron: Algorithm 7's construction in random order
    const test::StarStart start = test::random_start(ps, seed);
    if (seen.insert(canonical_triangles(start.surface)).second) {
      add(total, explore(ps, start.s, start.surface));
      ++starts;
    }
    // the central projection from that kernel: every point in its own
    // direction (when the projection is exactly star-shaped)
    double c[3] = {0, 0, 0};
    const auto t = test::random_tetrahedron(ps, seed);
    for (Index v : t)
      for (int j = 0; j < 3; ++j) c[j] += ps.point(v)[j] / 4;
    std::vector<Triangle> proj;
    try {
      proj = canonical_triangles(test::central_projection_surface(ps, c));
    } catch (const std::runtime_error&) {
      continue;
    }
    if (!ref::is_star_shaped(ps, proj, start.s) || !seen.insert(proj).second) continue;
    add(total, explore(ps, start.s, proj));
    ++starts;
  }
}

}  // namespace

TEST_CASE("ffhull orders: every order terminates at the same hull on degenerate inputs", "[ffhull][orders]") {
  Result total;
  std::size_t starts = 0;
  for (const auto& [name, ps] : degenerate_inputs()) {
    INFO(name);
    REQUIRE(spans3(ps));
    explore_all_starts(ps, total, starts);
  }
  std::cout << "ffhull orders (degenerate): " << starts << " starts, " << total.states << " states, " << total.moves
            << " moves, " << total.terminals << " terminals, at most " << total.max_states << " states from one start\n";
  REQUIRE(starts >= 10);
}

TEST_CASE("ffhull orders: every order terminates at the same hull on random inputs", "[ffhull][orders]") {
  Result total;
  std::size_t starts = 0;
  for (const std::string f : {"cube", "ball", "sphere", "grid3", "duplicates3", "sphere-lattice", "jitter3"})
    for (std::size_t n : {5, 6, 7})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(f, n, o);
        if (!spans3(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        explore_all_starts(ps, total, starts);
      }
  std::cout << "ffhull orders (random): " << starts << " starts, " << total.states << " states, " << total.moves
            << " moves, " << total.terminals << " terminals, at most " << total.max_states << " states from one start\n";
  REQUIRE(starts >= 60);
  test::prop_scaled("small integer sets of 4..7 points: every order reaches brute::hull3", 40, [] {
    const PointSet ps = *test::small_integers(3, 4, 7, false);
    RC_PRE(spans3(ps));
    const test::StarStart start = test::random_start(ps, *test::any_seed());
    const ff3::State st = ff3::make_state(ps, start.s, poly::build(ps.size(), start.surface));
    std::map<Key, int> memo;
    Result r;
    dfs(st, memo, r, 200000);
    RC_ASSERT(r.states <= 200000u);
    RC_ASSERT(!r.cycle);
    RC_ASSERT(r.bad_terminal.empty());
    RC_ASSERT(r.finals.size() == 1u);
    RC_ASSERT(*r.finals.begin() == brute::hull3(ps));
  });
}

TEST_CASE("ffhull orders: random orders on larger inputs reach the same hull", "[ffhull][orders]") {
  // ff3::run with a chooser taking a random applicable operation each step
  std::size_t runs = 0;
  for (const std::string f : {"ball", "cube", "sphere", "grid3", "duplicates3", "coplanar3", "sphere-lattice"})
    for (std::size_t n : {12, 40}) {
      gen::Options o;
      o.seed = 5;
      PointSet ps = gen::generate(f, n, o);
      if (f == "coplanar3") ps.coords.insert(ps.coords.end(), {0.5, 0.25, 1e3});  // one point off the plane
      if (!spans3(ps)) continue;
      INFO(f << " n=" << n);
      const auto expect = brute::hull3(ps);
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const test::StarStart start = test::random_start(ps, seed);
        ff3::State st = ff3::make_state(ps, start.s, poly::build(ps.size(), start.surface));
        std::mt19937_64 rng(seed);
        ref::Hull3Stats stats;
        ff3::run(st, &stats, [&](const std::vector<ff3::Candidate>& c) { return rng() % c.size(); });
        REQUIRE(canonical_triangles(poly::triangles(st.P)) == expect);
        ++runs;
      }
    }
  REQUIRE(runs >= 20);
}

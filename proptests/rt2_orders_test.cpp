// rt2_orders_test.cpp — EVERY ORDER, exhaustively: Lawson's flip algorithm
// (§3.3.1) and flip-flop (§5.1, Algorithm 5) have free execution order, so
// every order in which the applicable candidates can be taken must terminate
// at the same canonical triangulation — the brute-force SoS answer.
//
// For inputs of at most 7 points (random weighted sets and degenerate
// families) a depth-first search explores the whole state space reachable
// from a starting triangulation: from each state, every applicable move is
// taken (Lawson: every locally non-Delaunay edge; flip-flop: every edge on
// which Algorithm 5's local check acts — a 3-1 flip, a 2-2 flip or a label),
// states memoised on the canonical extended triangulation (+ labels). A
// state met again while it is still on the DFS stack is a cycle: a path that
// never terminates. Every terminal state must equal brute::rt2.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "proptests/support/generated.hpp"
#include "proptests/support/planar_inputs.hpp"
#include "gen/generate.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/brute_force.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/ffrt.hpp"
#include "reference/rt2/flip_flop_2d.hpp"
#include "reference/rt2/lawson_flip.hpp"
#include "reference/rt2/triangulation2.hpp"

using namespace flipflop;
namespace tri = flipflop::ref::tri;
namespace ff = flipflop::ref::ff;


namespace {

using test::spans;

bool has_duplicates(const PointSet& ps) {
  std::set<std::pair<double, double>> seen;
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (!seen.emplace(ps.point(i)[0], ps.point(i)[1]).second) return true;
  return false;
}

// ---- the search ----------------------------------------------------------------

struct Result {
  std::size_t states = 0, moves = 0, terminals = 0;
  bool cycle = false;
  bool lemma52_violated = false;  // Lawson: a locally non-regular edge that cannot be flipped
  std::set<std::vector<Triangle>> finals;
  std::vector<std::string> bad_terminal;  // terminal states that are not regular
};

enum : int { kOnStack = 1, kDone = 2 };

void lawson_dfs(const tri::Triangulation2& T, std::map<std::vector<Triangle>, int>& memo, Result& r) {
  auto [it, fresh] = memo.emplace(tri::all_triangles(T), kOnStack);
  if (!fresh) {
    if (it->second == kOnStack) r.cycle = true;
    return;
  }
  ++r.states;
  std::vector<tri::Edge> moves;
  for (const auto& [u, w] : tri::edges(T)) {
    const tri::Edge e = tri::find_edge(T, u, w);
    const auto m = ref::lawson_flip::decide(T, e);
    if (m == ref::lawson_flip::Move::flip22) moves.push_back(e);
    if (m == ref::lawson_flip::Move::stuck) r.lemma52_violated = true;
  }
  if (moves.empty()) {
    ++r.terminals;
    r.finals.insert(tri::real_triangles(T));
    if (!ref::lawson_flip::all_locally_regular(T)) r.bad_terminal.push_back("Lawson terminal not regular");
  }
  for (const tri::Edge e : moves) {
    ++r.moves;
    tri::Triangulation2 next = T;
    ref::lawson_flip::apply(next, e, nullptr, nullptr);
    lawson_dfs(next, memo, r);
  }
  memo[tri::all_triangles(T)] = kDone;
}

using FFKey = std::pair<std::vector<Triangle>, std::vector<std::uint8_t>>;

FFKey ff_key(const ff::State& s) {
  std::vector<std::uint8_t> labels(s.labelled.size(), 0);
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.labelled[v] && s.T.is_vertex(static_cast<Index>(v));
  return {tri::all_triangles(s.T), labels};
}

void ff_dfs(const ff::State& s, std::map<FFKey, int>& memo, Result& r) {
  const FFKey key = ff_key(s);
  auto [it, fresh] = memo.emplace(key, kOnStack);
  if (!fresh) {
    if (it->second == kOnStack) r.cycle = true;
    return;
  }
  ++r.states;
  std::vector<std::pair<tri::Edge, ff::Decision>> moves;
  for (const auto& [u, w] : tri::edges(s.T)) {
    const tri::Edge e = tri::find_edge(s.T, u, w);
    const ff::Decision d = ff::decide(s, e);  // Algorithm 5, lines 5-19
    if (d.action != ff::Action::none) moves.emplace_back(e, d);
  }
  if (moves.empty()) {
    ++r.terminals;
    r.finals.insert(tri::real_triangles(s.T));
    for (Index v = 0; v < s.T.n; ++v)
      if (s.labelled[v] && s.T.is_vertex(v)) r.bad_terminal.push_back("terminal with a labelled vertex");
    if (!ref::lawson_flip::all_locally_regular(s.T)) r.bad_terminal.push_back("terminal not regular");
  }
  for (const auto& [e, d] : moves) {
    ++r.moves;
    ff::State next = s;
    ff::apply(next, e, d, nullptr, nullptr);
    ff_dfs(next, memo, r);
  }
  memo[key] = kDone;
}

void require_one_answer(const Result& r, const PointSet& ps) {
  INFO("states " << r.states << ", moves " << r.moves << ", terminals " << r.terminals);
  REQUIRE_FALSE(r.cycle);
  REQUIRE_FALSE(r.lemma52_violated);
  REQUIRE(r.bad_terminal.empty());
  REQUIRE(r.finals.size() == 1);
  REQUIRE(*r.finals.begin() == brute::rt2(ps));
}

// ---- starting triangulations ------------------------------------------------------

// ffRT's constructing stage (§5.3) with the initial triangle taken from the
// points in the order given by `rotate` (different kernels and stars).
tri::Triangulation2 constructed(const PointSet& ps, bool discard, std::size_t rotate) {
  std::vector<Index> all(ps.size());
  std::iota(all.begin(), all.end(), Index{0});
  std::rotate(all.begin(), all.begin() + static_cast<long>(rotate % all.size()), all.end());
  const auto init = ref::ffrt::initial_triangle(ps, all);
  tri::Triangulation2 T = tri::make_initial(ps, init[0], init[1], init[2]);
  std::vector<Index> rest;
  for (Index i = 0; i < ps.size(); ++i)
    if (i != init[0] && i != init[1] && i != init[2]) rest.push_back(i);
  ref::ffrt::insert_points(T, rest, discard, nullptr);
  return T;
}

using test::random_insertion;

// ---- inputs -------------------------------------------------------------------------

rc::Gen<PointSet> gen_small(bool weighted, bool integer) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(4, 8);
    const int r = *rc::gen::inRange(1, 4);
    PointSet ps;
    ps.dim = 2;
    ps.weighted = weighted;
    for (int i = 0; i < 2 * n; ++i)
      ps.coords.push_back(integer ? double(*rc::gen::inRange(0, r + 1)) : *rc::gen::inRange(-1000, 1001) / 1024.0);
    for (int i = 0; weighted && i < n; ++i)
      ps.weights.push_back(integer ? double(*rc::gen::inRange(0, 4)) : *rc::gen::inRange(0, 400) / 1024.0);
    return ps;
  });
}

PointSet family(const std::string& name, std::size_t n, std::uint64_t seed, bool weighted, double whi) {
  return test::generated(name, n, seed, weighted, whi);
}

struct Totals {
  std::size_t inputs = 0, searches = 0, states = 0, moves = 0, largest = 0;
  void add(const Result& r) {
    ++searches;
    states += r.states;
    moves += r.moves;
    largest = std::max(largest, r.states);
  }
};

// Starting triangulations: ffRT's constructing stage with three different
// initial triangles, and three random insertion orders (every point a vertex).
constexpr int kStarts = 6;
tri::Triangulation2 start(const PointSet& ps, int k, std::uint64_t seed, bool discard) {
  if (k < 3) return constructed(ps, discard, seed + static_cast<std::uint64_t>(k));
  return tri::from_triangles(ps, random_insertion(ps, seed * 3 + static_cast<std::uint64_t>(k)));
}

void explore_lawson(const PointSet& ps, std::uint64_t seed, Totals& tot) {
  ++tot.inputs;
  for (int k = 0; k < kStarts; ++k) {
    std::map<std::vector<Triangle>, int> memo;
    Result r;
    lawson_dfs(start(ps, k, seed, false), memo, r);
    require_one_answer(r, ps);
    tot.add(r);
  }
}

void explore_flip_flop(const PointSet& ps, std::uint64_t seed, Totals& tot) {
  ++tot.inputs;
  for (int k = 0; k < kStarts; ++k) {
    std::map<FFKey, int> memo;
    Result r;
    ff_dfs(ff::make_state(start(ps, k, seed, true)), memo, r);
    require_one_answer(r, ps);
    tot.add(r);
  }
}

}  // namespace

TEST_CASE("orders: Lawson - every order of flipping locally non-Delaunay edges ends at the Delaunay triangulation",
          "[rt2][orders]") {
  Totals tot;
  test::prop_scaled("random sets of 4..7 points, zero weights", 1, [&] {
    const PointSet ps = *gen_small(false, *rc::gen::arbitrary<bool>());
    RC_PRE(spans(ps) && !has_duplicates(ps));  // Lawson needs every point non-redundant
    explore_lawson(ps, *rc::gen::inRange<std::uint64_t>(0, 1000), tot);
  });
  for (const std::string& f : {"grid2", "circle-lattice", "jitter2", "square"})
    for (std::size_t n : {4, 5, 6, 7})
      for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const PointSet ps = family(f, n, seed, false, 0);
        if (!spans(ps) || has_duplicates(ps)) continue;
        INFO(f << " n=" << n << " seed=" << seed);
        explore_lawson(ps, seed, tot);
      }
  std::cout << "Lawson, every order: " << tot.inputs << " inputs, " << tot.searches << " searches, " << tot.states
            << " states (largest " << tot.largest << "), " << tot.moves << " flips explored\n";
  REQUIRE(tot.inputs > 50);
}

TEST_CASE("orders: flip-flop - every order of the candidates of Algorithm 5 ends at the regular triangulation",
          "[rt2][orders]") {
  Totals tot;
  test::prop_scaled("random weighted sets of 4..7 points", 1, [&] {
    const PointSet ps = *gen_small(true, *rc::gen::arbitrary<bool>());
    RC_PRE(spans(ps));
    explore_flip_flop(ps, *rc::gen::inRange<std::uint64_t>(0, 1000), tot);
  });
  for (const std::string& f : {"grid2", "circle-lattice", "duplicates2", "jitter2", "square"})
    for (std::size_t n : {4, 5, 6, 7})
      for (std::uint64_t seed = 1; seed <= 8; ++seed)
        for (double whi : {0.0, 0.05, 3.0}) {
          const PointSet ps = family(f, n, seed, whi > 0, f == "circle-lattice" ? whi * 1e10 : whi);
          if (!spans(ps)) continue;
          INFO(f << " n=" << n << " seed=" << seed << " whi=" << whi);
          explore_flip_flop(ps, seed, tot);
        }
  // Figure 3.3 (see rt2_reference_test.cpp): six points, every path from the stuck triangulation
  PointSet fig;
  fig.dim = 2;
  fig.weighted = true;
  fig.coords = {0, 10, -9, -5, 9, -5, 1, 5, -5, -1, 4, -3};
  fig.weights = {1000, 1000, 1000, 1, 1, 1};
  const tri::Triangulation2 T =
      tri::from_triangles(fig, {{3, 4, 5}, {0, 1, 3}, {1, 2, 4}, {2, 0, 5}, {4, 3, 1}, {5, 4, 2}, {3, 5, 0}});
  std::map<FFKey, int> memo;
  Result r;
  ff_dfs(ff::make_state(T), memo, r);
  require_one_answer(r, fig);
  tot.add(r);
  std::cout << "flip-flop, every order: " << tot.inputs << " inputs, " << tot.searches << " searches, " << tot.states
            << " states (largest " << tot.largest << "), " << tot.moves << " moves explored (Figure 3.3: " << r.states
            << " states)\n";
  REQUIRE(tot.inputs > 100);
}

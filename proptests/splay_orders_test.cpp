// splay_orders_test.cpp — EVERY ORDER of splaying insertions, exhaustively:
// star splaying has free execution order (thesis §3.2, §3.3.2), so every
// order in which the insertions that inconsistency enforcement demands can
// be carried out must terminate at the same hull — the brute-force SoS hull.
//
// For inputs of at most 7 points a depth-first search explores the whole
// state space reachable from initial stars (the pipeline's, and random valid
// stars up to 6 points): 5-6 points of every generator family and 7 points
// of cube (random), grid3 and sphere-lattice (degenerate), plus RapidCheck's
// random and degenerate sets of 4-6 points (families.hpp). From each
// state, every insertion <s, p> demanded by any inconsistent candidate edge
// (splay::demanded) that changes the state is a move, taken alone (one
// insertion per move: finer than the sequential workflow, which applies an
// edge's insertions together, and than the parallel one). States are
// memoised on their stars. Checked on the way:
//   * progress: a state with an inconsistent edge has a move (the argument
//     of star_splaying.cpp, `demanded`);
//   * no cycle (cones only grow);
//   * every certificate of a star that dies holds;
//   * every terminal state is consistent and its triangles are brute::hull3.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <unordered_map>
#include <set>

#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "proptests/support/splay_inputs.hpp"
#include "reference/brute_force.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/star_splaying.hpp"

using namespace flipflop;
namespace splay = flipflop::ref::splay;

namespace {

using Key = std::vector<Index>;

// The stars, link rotated to its smallest vertex, certificates sorted (a
// certificate is used as a set of insertions).
Key key_of(const splay::State& st) {
  Key k;
  for (Index v = 0; v < st.status.size(); ++v) {
    k.push_back(static_cast<Index>(st.status[v]));
    if (st.status[v] == splay::Status::alive) {
      const auto& L = st.link[v];
      const auto m = std::min_element(L.begin(), L.end()) - L.begin();
      k.push_back(static_cast<Index>(L.size()));
      for (std::size_t i = 0; i < L.size(); ++i) k.push_back(L[(static_cast<std::size_t>(m) + i) % L.size()]);
    } else if (st.status[v] == splay::Status::dead) {
      auto c = st.cert[v];
      std::sort(c.begin(), c.end());
      k.insert(k.end(), c.begin(), c.end());
    }
  }
  return k;
}

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = k.size();
    for (Index x : k) h = h * 0x100000001b3ULL ^ x;
    return h;
  }
};
using Memo = std::unordered_map<Key, int, KeyHash>;

struct Result {
  std::size_t states = 0, moves = 0, terminals = 0;
  bool cycle = false, stuck = false, bad_certificate = false, inconsistent_terminal = false;
  std::set<std::vector<Triangle>> finals;
};

enum : int { kOnStack = 1, kDone = 2 };

void dfs(const splay::State& st, Memo& memo, Result& r) {
  const Key key = key_of(st);
  auto [it, fresh] = memo.emplace(key, kOnStack);
  if (!fresh) {
    if (it->second == kOnStack) r.cycle = true;
    return;
  }
  ++r.states;
  std::set<std::pair<Index, Index>> demanded;
  for (const auto& [v, u] : splay::candidates(st))
    for (const auto& x : splay::demanded(st, v, u)) demanded.insert({x.star, x.point});
  std::size_t moves = 0;
  for (const auto& [s, p] : demanded) {
    splay::State next = st;
    const splay::Outcome o = splay::insert(next, s, p);
    if (o == splay::Outcome::unchanged) continue;
    if (o == splay::Outcome::died && !ref::is_death_certificate(*st.ps, s, next.cert[s])) r.bad_certificate = true;
    ++moves;
    ++r.moves;
    dfs(next, memo, r);
  }
  if (demanded.empty()) {
    ++r.terminals;
    if (!splay::consistent(st)) r.inconsistent_terminal = true;
    r.finals.insert(splay::triangles(st));
  } else if (moves == 0) {
    r.stuck = true;
  }
  memo[key] = kDone;
}

struct Totals {
  std::size_t searches = 0, states = 0, moves = 0, largest = 0;
};

void explore(const PointSet& ps, const std::vector<ref::Star>& stars, Totals& tot) {
  const auto expected = brute::hull3(ps);
  Memo memo;
  Result r;
  dfs(splay::make_state(ps, stars, true), memo, r);
  INFO("states " << r.states << ", moves " << r.moves << ", terminals " << r.terminals);
  REQUIRE_FALSE(r.cycle);
  REQUIRE_FALSE(r.stuck);
  REQUIRE_FALSE(r.bad_certificate);
  REQUIRE_FALSE(r.inconsistent_terminal);
  REQUIRE(r.finals.size() == 1);
  REQUIRE(*r.finals.begin() == expected);
  ++tot.searches;
  tot.states += r.states;
  tot.moves += r.moves;
  tot.largest = std::max(tot.largest, r.states);
}

// The pipeline's stars and random valid stars (up to 6 points: random stars
// of 7 points reach tens of thousands of states on degenerate input, each
// costing exact SoS evaluations).
void explore_all(const PointSet& ps, std::uint64_t seed, Totals& tot) {
  explore(ps, ref::initial_stars(ps), tot);
  if (ps.size() <= 6) explore(ps, test::random_stars(ps, seed), tot);
}

bool spans_3d(const PointSet& ps) { return ps.size() >= 4 && affine_dimension(ps) == 3; }

}  // namespace

TEST_CASE("splay: every order of splaying insertions reaches the brute-force hull: generator families", "[splay][orders][long]") {
  Totals tot;
  // 7 points: a random, a lattice and a cospherical family (each search
  // reaches 4 000 - 25 000 states); 5 and 6 points: every family.
  const std::set<std::string> seven = {"cube", "grid3", "sphere-lattice"};
  for (const std::string& fam : test::splay_families())
    for (std::size_t n = 5; n <= (seven.count(fam) ? 7u : 6u); ++n)
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const PointSet ps = test::family3(fam, n, seed);
        INFO(fam << " n " << n << " seed " << seed);
        if (!spans_3d(ps)) continue;
        explore_all(ps, seed, tot);
      }
  WARN("searches " << tot.searches << ", states " << tot.states << ", moves " << tot.moves << ", largest "
                   << tot.largest);
}

TEST_CASE("splay: every order of splaying insertions reaches the brute-force hull: random and degenerate sets", "[splay][orders]") {
  Totals tot;
  test::prop_scaled("one terminal hull, = brute::hull3", 4, [&] {
    const PointSet ps = *test::degenerate_points(3, 4, 6, false);  // 7 points: the families above
    RC_PRE(spans_3d(ps));
    explore_all(ps, *test::any_seed(), tot);
  });
  WARN("searches " << tot.searches << ", states " << tot.states << ", moves " << tot.moves << ", largest "
                   << tot.largest);
}

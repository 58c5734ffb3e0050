// hull2_orders_test.cpp — free execution order, exhaustively (thesis §3.1 item
// 3, §4.1, §8.3): for small inputs, EVERY order in which the applicable local
// operations can be taken ends at the same canonical structure.
//
//   flip-pop (Algorithm 1), n <= 12: every sequence of 2-1 flips from a star-shaped
//     polygon (or Graham's chains) ends at brute::hull2; along every path a
//     removed vertex never reappears (each step removes exactly the flipped
//     vertex and adds none) and every path has the same length.
//   twist (Algorithm 11), n <= 7: the thesis states free execution order (§8.3, last
//     paragraph); every sequence of twists ends at the same ordering — the
//     vertices sorted by angle around s (an independent std::sort), which is
//     star-shaped — after exactly as many twists as the initial ordering has
//     inversions (Theorem 8.1: bubble sort).
//
// The state space is searched depth-first, memoised on the canonical state:
// the vertex cycle for flip-pop (a 2-1 flip only deletes, so the cycle is
// determined by the surviving vertices), the vertex ordering for twist.
#include <catch2/catch.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "gen/generate.hpp"
#include "reference/brute_force.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

// What a state leads to: the terminal structures over all paths, the shortest
// and the longest path, and the number of distinct paths (orders).
template <class Terminal>
struct Outcome {
  std::set<Terminal> terminals;
  std::size_t min_steps = 0, max_steps = 0;
  double paths = 0;
};

template <class Terminal>
void merge(Outcome<Terminal>& into, const Outcome<Terminal>& child, bool first) {
  into.terminals.insert(child.terminals.begin(), child.terminals.end());
  into.min_steps = first ? child.min_steps + 1 : std::min(into.min_steps, child.min_steps + 1);
  into.max_steps = first ? child.max_steps + 1 : std::max(into.max_steps, child.max_steps + 1);
  into.paths += child.paths;
}

// ---- flip-pop ------------------------------------------------------------------
struct FlipPopSearch {
  std::map<std::vector<Index>, Outcome<std::vector<Index>>> memo;
  std::size_t transitions = 0;

  const Outcome<std::vector<Index>>& explore(const ref::FlipPop& state) {
    const std::vector<Index> key = state.polygon();
    if (auto it = memo.find(key); it != memo.end()) return it->second;
    Outcome<std::vector<Index>> out;
    const std::vector<Index> moves = state.applicable();
    if (moves.empty()) {
      out.terminals.insert(ref::rotate_to_smallest(key));
      out.paths = 1;
    }
    const std::set<Index> before(key.begin(), key.end());
    for (std::size_t m = 0; m < moves.size(); ++m) {
      ref::FlipPop child = state;
      child.apply(moves[m]);
      ++transitions;
      // a removed vertex never reappears: the step deletes exactly the flipped vertex
      const std::vector<Index> after = child.polygon();
      std::set<Index> expected = before;
      expected.erase(moves[m]);
      REQUIRE(std::set<Index>(after.begin(), after.end()) == expected);
      REQUIRE(!child.on_polygon(moves[m]));
      REQUIRE(child.structure_holds());  // still star-shaped (or x-monotone chains)
      merge(out, explore(child), m == 0);
    }
    return memo.emplace(key, std::move(out)).first->second;
  }
};

// ---- twist -----------------------------------------------------------------------
struct TwistSearch {
  std::map<std::vector<Index>, Outcome<std::vector<Index>>> memo;
  std::size_t transitions = 0;

  const Outcome<std::vector<Index>>& explore(const ref::Twist& state) {
    const std::vector<Index>& key = state.order();
    if (auto it = memo.find(key); it != memo.end()) return it->second;
    Outcome<std::vector<Index>> out;
    const std::vector<std::size_t> moves = state.applicable();
    if (moves.empty()) {
      out.terminals.insert(key);
      out.paths = 1;
    }
    for (std::size_t m = 0; m < moves.size(); ++m) {
      const std::size_t k = moves[m];
      // a twist swaps an adjacent pair that is out of angular order (independent comparator)
      REQUIRE(state.kernel().angle_less(key[k + 1], key[k]));
      ref::Twist child = state;
      child.apply(k);
      ++transitions;
      merge(out, explore(child), m == 0);
    }
    return memo.emplace(key, std::move(out)).first->second;
  }
};

// ---- inputs ----------------------------------------------------------------------
PointSet from_coords(std::vector<double> c) {
  PointSet ps;
  ps.dim = 2;
  ps.coords = std::move(c);
  return ps;
}

// n points of one small family; `family` names a generator family or one of
// "int2" (integer coordinates in [-2, 2]) and "line+" (points on one line and
// one or two off it).
PointSet small_input(const std::string& family, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  if (family == "int2") {
    std::vector<double> c;
    for (std::size_t i = 0; i < 2 * n; ++i) c.push_back(double(int(rng() % 5) - 2));
    return from_coords(c);
  }
  if (family == "line+") {
    std::vector<double> c;
    const std::size_t off = 1 + rng() % 2;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = double(int(rng() % 9) - 4);
      if (i < n - off) {
        c.push_back(t);
        c.push_back(2 * t + 1);  // on the line y = 2x + 1
      } else {
        c.push_back(t);
        c.push_back(double(int(rng() % 9) - 4));
      }
    }
    // shuffle the points so that the off-line ones are anywhere in the order
    for (std::size_t i = n; i > 1; --i) {
      const std::size_t j = rng() % i;
      std::swap(c[2 * (i - 1)], c[2 * j]);
      std::swap(c[2 * (i - 1) + 1], c[2 * j + 1]);
    }
    return from_coords(c);
  }
  gen::Options o;
  o.seed = seed;
  return gen::generate(family, n, o);
}

const std::vector<std::string> kFamilies = {"square", "disk", "frame", "circle", "grid2", "circle-lattice",
                                            "duplicates2", "jitter2", "huge2", "tiny2", "int2", "line+"};

// A kernel strictly inside: (a + b + c + c)/4 of a random exactly non-degenerate triangle.
pred::RationalPoint random_kernel(const PointSet& ps, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const double* a = ps.point(rng() % ps.size());
    const double* b = ps.point(rng() % ps.size());
    const double* c = ps.point(rng() % ps.size());
    if (pred::orient2d_exact(a, b, c) == 0) continue;
    const double* pts[4] = {a, b, c, c};
    return pred::RationalPoint::centroid(pts, 4, 2);
  }
  return ref::interior_kernel(ps);
}

std::vector<Index> angular_sort(const ref::StarKernel& k, std::vector<Index> v) {
  std::sort(v.begin(), v.end(), [&](Index p, Index q) { return k.angle_less(p, q); });
  return v;
}

}  // namespace

TEST_CASE("flip-pop: every order of 2-1 flips ends at the canonical hull (n <= 12)", "[hull2][flip-pop][orders]") {
  // The states are subsets of the polygon's vertices (at most 2^(n-3)), so the
  // search goes beyond 7 points: with few interior points there are few orders.
  std::size_t inputs = 0, searches = 0, states = 0, transitions = 0;
  double orders = 0;
  for (const std::string& fam : kFamilies)
    for (std::size_t n = 3; n <= 12; ++n)
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const PointSet ps = small_input(fam, n, seed);
        if (!dimension_problem(ps).empty()) continue;
        ++inputs;
        INFO(fam << " n=" << n << " seed=" << seed);
        const std::vector<Index> hull = brute::hull2(ps);
        std::vector<Index> all(n);
        std::iota(all.begin(), all.end(), Index{0});
        std::mt19937_64 rng(seed * 7919 + n);

        auto check = [&](const ref::FlipPop& start) {
          FlipPopSearch search;
          const auto& out = search.explore(start);
          REQUIRE(out.terminals == std::set<std::vector<Index>>{hull});
          REQUIRE(out.min_steps == out.max_steps);
          REQUIRE(out.max_steps == start.size() - hull.size());
          ++searches;
          states += search.memo.size();
          transitions += search.transitions;
          orders += out.paths;
        };
        // star-shaped polygons around two kernels
        for (int k = 0; k < 2; ++k) {
          const pred::RationalPoint s = k == 0 ? ref::interior_kernel(ps) : random_kernel(ps, rng);
          const ref::StarKernel sk(ps, s);
          check(ref::FlipPop(sk, angular_sort(sk, all)));
        }
        // Graham-sorting's chains and Graham-insertion's chains (smallest-index rule)
        check(ref::FlipPop(ps, ref::graham_sorting_polygon(ps)));
        ref::InsertionOptions o;
        o.choice = ref::InsertionChoice::smallest_index;
        check(ref::FlipPop(ps, ref::graham_insertion_polygon(ps, nullptr, o)));
      }
  std::cout << "flip-pop orders: " << inputs << " inputs, " << searches << " searches, " << states
            << " states, " << transitions << " transitions, " << orders << " flip orders\n";
  REQUIRE(inputs >= 550);
}

TEST_CASE("twist: every order of twists ends at the same star-shaped polygon (n <= 7)", "[hull2][twist][orders]") {
  std::size_t inputs = 0, searches = 0, states = 0, transitions = 0;
  double orders = 0;
  for (const std::string& fam : kFamilies)
    for (std::size_t n = 3; n <= 7; ++n)
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const PointSet ps = small_input(fam, n, seed);
        if (!dimension_problem(ps).empty()) continue;
        ++inputs;
        INFO(fam << " n=" << n << " seed=" << seed);
        std::mt19937_64 rng(seed * 104729 + n);
        const pred::RationalPoint s = seed == 1 ? ref::interior_kernel(ps) : random_kernel(ps, rng);
        const ref::StarKernel sk(ps, s);
        std::vector<Index> all(n);
        std::iota(all.begin(), all.end(), Index{0});
        const std::vector<Index> sorted = angular_sort(sk, all);
        REQUIRE(ref::is_star_shaped(sk, sorted));

        // the input order, a random order and the reversed angular order (every inversion)
        std::vector<Index> shuffled = all;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        std::vector<Index> reversed(sorted.rbegin(), sorted.rend());
        for (const auto& start : {all, shuffled, reversed}) {
          std::size_t inversions = 0;
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) inversions += sk.angle_less(start[j], start[i]);
          TwistSearch search;
          const auto& out = search.explore(ref::Twist(sk, start));
          REQUIRE(out.terminals == std::set<std::vector<Index>>{sorted});
          REQUIRE(out.min_steps == inversions);
          REQUIRE(out.max_steps == inversions);
          ++searches;
          states += search.memo.size();
          transitions += search.transitions;
          orders += out.paths;
        }
      }
  std::cout << "twist orders: " << inputs << " inputs, " << searches << " searches, " << states << " states, "
            << transitions << " transitions, " << orders << " twist orders\n";
  REQUIRE(inputs >= 150);
}

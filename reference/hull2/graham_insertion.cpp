// graham_insertion.cpp — Graham-insertion, thesis §4.3, Algorithm 4 (see graham_insertion.hpp).
#include "reference/hull2/graham_insertion.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "reference/checked.hpp"

namespace flipflop::ref {

namespace {

constexpr Index kNone = std::numeric_limits<Index>::max();

// Floating-point preference among the points associated with the edge p -> q
// (InsertionChoice::furthest): larger is better. Only a heuristic.
struct Preference {
  double distance;    // -cross(q - p, u - p): positive for points beyond the edge
  double off_middle;  // |u.x - (p.x + q.x) / 2|: smaller is better
};

Preference preference(const PointSet& ps, Index p, Index q, Index u) {
  const double* P = ps.point(p);
  const double* Q = ps.point(q);
  const double* U = ps.point(u);
  double d = -((Q[0] - P[0]) * (U[1] - P[1]) - (Q[1] - P[1]) * (U[0] - P[0]));
  double m = std::fabs(U[0] - (P[0] / 2 + Q[0] / 2));
  if (!std::isfinite(d)) d = 0;  // overflow (huge coordinates): no preference
  if (!std::isfinite(m)) m = 0;
  return {d, m};
}

bool better(const Preference& a, Index ia, const Preference& b, Index ib) {
  if (a.distance != b.distance) return a.distance > b.distance;
  if (a.off_middle != b.off_middle) return a.off_middle < b.off_middle;
  return ia < ib;
}

}  // namespace

ChainPolygon graham_insertion_polygon(const PointSet& ps, Hull2Stats* stats, const InsertionOptions& options) {
  if (ps.dim != 2 || ps.size() < 2) throw std::invalid_argument("graham_insertion: at least 2 points in 2D are needed");
  const Index n = static_cast<Index>(ps.size());
  std::size_t insertions = 0, rounds = 0, discarded = 0;
  std::mt19937_64 rng(options.seed);

  // line 1: {v_l, v_r} <- the leftmost and rightmost points of S
  const auto lr_pair = leftmost_rightmost(ps);
  const Index vl = lr_pair.first, vr = lr_pair.second;
  // line 3: P <- <v_r, v_l>: the edges v_r -> v_l (upper) and v_l -> v_r (lower).
  // An edge is named by its first vertex: p names p -> next[p].
  std::vector<Index> next(n, kNone);
  next[vr] = vl;
  next[vl] = vr;
  auto beyond = [&](Index a, Index b, Index c) { return orient(ps, a, b, c) < 0; };  // △abc clockwise
  auto x_between = [&](Index u, Index a, Index b) {  // (u.x - a.x)(u.x - b.x) < 0, perturbed
    return compare_coord(ps, u, a, 0) != compare_coord(ps, u, b, 0);
  };

  // line 2: S <- S \ {v_l, v_r}; lines 4-6: associate every point with an edge
  std::vector<Index> S, edge_of(n, kNone);
  S.reserve(n);
  for (Index p = 0; p < n; ++p) {
    if (p == vl || p == vr) continue;
    S.push_back(p);
    edge_of[p] = beyond(vr, vl, p) ? vr : vl;  // line 5 : line 6
    FF_CHECK(beyond(edge_of[p], next[edge_of[p]], p), "a point is beyond neither v_r -> v_l nor v_l -> v_r");
  }

  // checked build: the structure after each iteration
  [[maybe_unused]] auto chains_monotone = [&] {  // v_r -> v_l decreasing in x, v_l -> v_r increasing
    for (Index v = vr; v != vl; v = next[v])
      if (compare_coord(ps, next[v], v, 0) >= 0) return false;
    for (Index v = vl; v != vr; v = next[v])
      if (compare_coord(ps, next[v], v, 0) <= 0) return false;
    return true;
  };
  [[maybe_unused]] auto all_right_beyond = [&] {
    for (Index u : S)
      if (!x_between(u, edge_of[u], next[edge_of[u]]) || !beyond(edge_of[u], next[edge_of[u]], u)) return false;
    return true;
  };

  std::vector<Index> chosen(n, kNone), touched;
  std::vector<Preference> chosen_pref(n);
  std::vector<std::size_t> seen(n, 0);
  std::vector<char> inserted(n, 0);
  std::vector<Index> kept;
  while (!S.empty()) {  // lines 7-18
    ++rounds;
    // lines 8-9: for each edge p -> q, choose a point r associated with it
    touched.clear();
    for (Index u : S) {
      const Index e = edge_of[u];
      if (chosen[e] == kNone) {
        touched.push_back(e);
        chosen[e] = u;
        seen[e] = 1;
        if (options.choice == InsertionChoice::furthest) chosen_pref[e] = preference(ps, e, next[e], u);
        continue;
      }
      switch (options.choice) {
        case InsertionChoice::furthest: {
          const Preference pu = preference(ps, e, next[e], u);
          if (better(pu, u, chosen_pref[e], chosen[e])) chosen[e] = u, chosen_pref[e] = pu;
          break;
        }
        case InsertionChoice::smallest_index:
          if (u < chosen[e]) chosen[e] = u;
          break;
        case InsertionChoice::random:  // reservoir sampling: uniform among the associated points
          if (std::uniform_int_distribution<std::size_t>(0, seen[e])(rng) == 0) chosen[e] = u;
          ++seen[e];
          break;
      }
    }
    // lines 10-11: replace p -> q with p -> r and r -> q; S <- S \ {r}
    for (Index p : touched) {
      const Index r = chosen[p], q = next[p];
      next[p] = r;
      next[r] = q;
      inserted[r] = 1;
      ++insertions;
    }
    // lines 12-17: re-associate or drop every other point
    kept.clear();
    for (Index u : S) {
      if (inserted[u]) continue;
      const Index p = edge_of[u];  // line 13: u was associated with p -> q,
      const Index r = next[p];     // and r has been inserted into it
      const Index e = x_between(u, p, r) ? p : r;  // line 14: p -> r, else line 15: r -> q
      if (beyond(e, next[e], u)) {                 // line 16
        edge_of[u] = e;
        kept.push_back(u);
      } else {  // line 17: u is inside the triangle p r q, hence not extreme
        FF_CHECK(orient(ps, p, r, u) > 0 && orient(ps, r, next[r], u) > 0 && orient(ps, next[r], p, u) > 0,
                 "a dropped point is not strictly inside the triangle p r q");
        ++discarded;
      }
    }
    for (Index p : touched) chosen[p] = kNone;
    S.swap(kept);
    FF_CHECK(chains_monotone(), "the chains are not strictly x-monotone");
    FF_CHECK(all_right_beyond(), "a remaining point is not right beyond its edge");
  }

  ChainPolygon out;
  out.left = vl;
  out.right = vr;
  Index v = vr;
  do {
    out.polygon.push_back(v);
    v = next[v];
  } while (v != vr);
  if (stats) {
    stats->insertions += insertions;
    stats->insertion_rounds += rounds;
    stats->discarded_early += discarded;
  }
  return out;
}

std::vector<Index> graham_insertion(const PointSet& ps, Hull2Stats* stats, const InsertionOptions& options) {
  const ChainPolygon chains = graham_insertion_polygon(ps, stats, options);
  return flip_pop(ps, chains, stats);  // line 19
}

}  // namespace flipflop::ref

// ffrt.cpp — ffRT (thesis §5.3); see ffrt.hpp.
#include "reference/rt2/ffrt.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "predicates/predicates.hpp"
#include "reference/checked.hpp"
#include "reference/rt2/flip_flop_2d.hpp"

namespace flipflop::ref::ffrt {

using tri::kNone;
using tri::Triangulation2;

namespace {

constexpr Index kNoVertex = ~Index{0};

bool is_real(const Triangulation2& T, std::int32_t t) {
  const Triangle& x = T.tv[static_cast<std::size_t>(t)];
  return !T.is_virtual(x[0]) && !T.is_virtual(x[1]) && !T.is_virtual(x[2]);
}

// §5.3: "proved to be redundant by the three vertices of the triangle it is
// associated with": p lies in the real triangle t and p^+ lies above the plane
// of its lifted vertices, hence above the lower hull (cf. Lemma 5.1).
bool proved_redundant(const Triangulation2& T, std::int32_t t, Index p) {
  if (!is_real(T, t)) return false;
  const Triangle& x = T.tv[static_cast<std::size_t>(t)];
  return tri::power(T, x[0], x[1], x[2], p) < 0;
}

struct Split {
  std::int32_t t0, t1, t2;  // (a, b, r), (b, c, r), (c, a, r)
  Index a, b, c, r;
};

}  // namespace

std::array<Index, 3> initial_triangle(const PointSet& ps, const std::vector<Index>& candidates) {
  if (candidates.empty()) throw std::invalid_argument("ffRT: no points");
  const Index a = candidates[0];
  Index b = kNoVertex, c = kNoVertex;
  std::size_t k = 1;
  for (; k < candidates.size(); ++k) {
    const Index i = candidates[k];
    if (ps.point(i)[0] != ps.point(a)[0] || ps.point(i)[1] != ps.point(a)[1]) {
      b = i;
      break;
    }
  }
  int o = 0;
  for (++k; b != kNoVertex && k < candidates.size(); ++k) {
    o = pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(candidates[k]));
    if (o != 0) {
      c = candidates[k];
      break;
    }
  }
  if (c == kNoVertex) throw std::invalid_argument("ffRT: the points are collinear (no initial triangle)");
  if (o < 0) std::swap(b, c);
  return {a, b, c};
}

void insert_points(Triangulation2& T, const std::vector<Index>& points, bool discard_redundant, Rt2Stats* stats) {
  if constexpr (FF_CHECKED) {
    const std::string problem = tri::validity_problem(T);
    FF_CHECK(problem.empty(), "constructing stage input: " + problem);
  }
  std::vector<std::int32_t> loc(T.n, kNone);
  std::vector<Index> active;
  active.reserve(points.size());
  // associate every point with the triangle it lies in (one scan each)
  for (Index p : points) {
    if (T.is_vertex(p)) throw std::logic_error("insert_points: point " + std::to_string(p) + " is a vertex");
    std::int32_t found = kNone;
    for (std::size_t t = 0; t < T.tv.size() && found == kNone; ++t)
      if (T.alive[t] && tri::contains(T, static_cast<std::int32_t>(t), p)) found = static_cast<std::int32_t>(t);
    if (found == kNone) throw std::logic_error("insert_points: point " + std::to_string(p) + " is in no triangle");
    if (discard_redundant && proved_redundant(T, found, p)) {
      if (stats) ++stats->discarded_early;
      continue;
    }
    loc[p] = found;
    active.push_back(p);
  }
  std::vector<Index> best;      // per triangle: the point to insert this round
  std::vector<std::int32_t> split_of;  // per triangle: index into splits, or kNone
  std::vector<Split> splits;
  std::vector<Index> next;
  while (!active.empty()) {
    if (stats) ++stats->rounds;
    best.assign(T.tv.size(), kNoVertex);
    for (Index p : active) {
      Index& b = best[static_cast<std::size_t>(loc[p])];
      b = std::min(b, p);  // one point per triangle: the one of smallest index
    }
    splits.clear();
    split_of.assign(T.tv.size(), kNone);
    for (Index p : active) {
      const std::int32_t t = loc[p];
      if (best[static_cast<std::size_t>(t)] != p) continue;
      const Triangle old = T.tv[static_cast<std::size_t>(t)];
      const auto nt = tri::flip13(T, t, p);  // 1-3 flip
      if (stats) ++stats->flips_1_3;
      if constexpr (FF_CHECKED) {
        const std::string problem = tri::validity_problem(T);
        FF_CHECK(problem.empty(), "after inserting " + std::to_string(p) + ": " + problem);
      }
      split_of[static_cast<std::size_t>(t)] = static_cast<std::int32_t>(splits.size());
      splits.push_back({nt[0], nt[1], nt[2], old[0], old[1], old[2], p});
    }
    next.clear();
    for (Index p : active) {
      const std::int32_t t = loc[p];
      const Split& s = splits[static_cast<std::size_t>(split_of[static_cast<std::size_t>(t)])];
      if (s.r == p) continue;  // inserted
      // re-associate with (a, b, r), (b, c, r) or (c, a, r): the rays r->a,
      // r->b, r->c split the old triangle
      std::int32_t nt;
      if (tri::orient(T, s.r, s.b, p) < 0) nt = tri::orient(T, s.r, s.a, p) > 0 ? s.t0 : s.t2;
      else nt = tri::orient(T, s.r, s.c, p) < 0 ? s.t1 : s.t2;
      FF_CHECK(tri::contains(T, nt, p), "re-associated point " + std::to_string(p) + " is not in its triangle");
      if (discard_redundant && proved_redundant(T, nt, p)) {
        if (stats) ++stats->discarded_early;
        loc[p] = kNone;
        continue;
      }
      loc[p] = nt;
      next.push_back(p);
    }
    active.swap(next);
  }
}

std::int32_t locate_near(const Triangulation2& T, Index p, Index m) {
  // the triangles around m
  std::int32_t t = T.vtri[m];
  if (t != kNone) {
    const std::int32_t start = t;
    do {
      if (tri::contains(T, t, p)) return t;
      const Triangle& x = T.tv[static_cast<std::size_t>(t)];
      const int k = x[0] == m ? 0 : x[1] == m ? 1 : 2;
      t = T.tn[static_cast<std::size_t>(t)][static_cast<std::size_t>(k == 2 ? 0 : k + 1)];
    } while (t != start);
  }
  for (std::size_t u = 0; u < T.tv.size(); ++u)
    if (T.alive[u] && tri::contains(T, static_cast<std::int32_t>(u), p)) return static_cast<std::int32_t>(u);
  throw std::logic_error("locate: point " + std::to_string(p) + " is in no triangle");
}

Triangulation2 construct(const PointSet& ps, const std::vector<Index>& candidates, bool discard_redundant,
                         Rt2Stats* stats) {
  const auto init = initial_triangle(ps, candidates);
  Triangulation2 T = tri::make_initial(ps, init[0], init[1], init[2]);
  std::vector<Index> rest;
  rest.reserve(candidates.size());
  for (Index i : candidates)
    if (i != init[0] && i != init[1] && i != init[2]) rest.push_back(i);
  // all of them lie in the four triangles of the initial extended triangulation
  insert_points(T, rest, discard_redundant, stats);
  return T;
}

std::vector<Triangle> ffrt(const PointSet& ps, FlipFlopVariant variant, Rt2Stats* stats) {
  std::vector<Index> all(ps.size());
  std::iota(all.begin(), all.end(), Index{0});
  ff::State s = ff::make_state(construct(ps, all, true, stats));  // constructing stage
  ff::run(s, variant, stats);                                       // flipping stage
  return tri::real_triangles(s.T);
}

}  // namespace flipflop::ref::ffrt

// certify_detail.hpp — combinatorial helpers shared by the certifiers.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::certify::detail {

inline std::uint64_t edge_key(Index a, Index b) { return (std::uint64_t(a) << 32) | b; }

inline std::string tri_str(const Triangle& t) {
  return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + ")";
}
inline std::string edge_str(Index a, Index b) {
  return "(" + std::to_string(a) + "," + std::to_string(b) + ")";
}

// Directed edge (t[k], t[k+1]) of triangle t → its triangle id; one entry per
// directed edge. Returns the offending edge in `dup` when an edge repeats.
struct DirectedEdges {
  std::unordered_map<std::uint64_t, std::uint32_t> tri_of;

  // false when a directed edge appears twice (dup_* tell where)
  bool build(const std::vector<Triangle>& tris, Index& dup_a, Index& dup_b, std::uint32_t& t1,
             std::uint32_t& t2) {
    tri_of.reserve(tris.size() * 3 * 2);
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        Index a = tris[t][k], b = tris[t][(k + 1) % 3];
        auto [it, inserted] = tri_of.emplace(edge_key(a, b), t);
        if (!inserted) {
          dup_a = a;
          dup_b = b;
          t1 = it->second;
          t2 = t;
          return false;
        }
      }
    }
    return true;
  }
  // triangle holding the directed edge (a, b), or -1
  long find(Index a, Index b) const {
    auto it = tri_of.find(edge_key(a, b));
    return it == tri_of.end() ? -1 : static_cast<long>(it->second);
  }
};

inline Index third_vertex(const Triangle& t, Index a, Index b) {
  for (Index v : t)
    if (v != a && v != b) return v;
  return t[0];
}

// Union-find over triangle ids, for connectivity.
struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Link edges around each vertex: triangle (a,b,c) contributes b→c at a,
// c→a at b and a→b at c. Stored in CSR form: for vertex v, entries
// [start[v], start[v+1]) of `from`/`to`.
struct VertexLinks {
  std::vector<std::uint32_t> start;
  std::vector<std::pair<Index, Index>> edge;  // (from, to), sorted by from per vertex

  void build(std::size_t n, const std::vector<Triangle>& tris) {
    start.assign(n + 1, 0);
    for (const Triangle& t : tris)
      for (Index v : t) ++start[v + 1];
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    edge.resize(tris.size() * 3);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const Triangle& t : tris)
      for (int k = 0; k < 3; ++k) edge[fill[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
    for (std::size_t v = 0; v < n; ++v)
      std::sort(edge.begin() + start[v], edge.begin() + start[v + 1]);
  }
  std::uint32_t degree(Index v) const { return start[v + 1] - start[v]; }

  // The link vertex following `u` around v, or -1 if there is none.
  long next(Index v, Index u) const {
    auto b = edge.begin() + start[v], e = edge.begin() + start[v + 1];
    auto it = std::lower_bound(b, e, std::make_pair(u, Index(0)));
    return (it != e && it->first == u) ? static_cast<long>(it->second) : -1;
  }

  // Follows the link of v from `first` for at most degree(v) steps, writing the
  // visited vertices (first included) into `out`. Returns true when the walk
  // came back to `first` (a cycle), false when it ended at a vertex without a
  // successor (a path, as around a boundary vertex).
  bool walk(Index v, Index first, std::vector<Index>& out) const {
    out.clear();
    long cur = first;
    for (std::uint32_t steps = 0; steps <= degree(v); ++steps) {
      out.push_back(static_cast<Index>(cur));
      cur = next(v, static_cast<Index>(cur));
      if (cur < 0) return false;
      if (cur == static_cast<long>(first)) return true;
    }
    return false;
  }
};

// Number of full turns of a sequence of directions that rotates by less than a
// half-turn, in one sense, at each step. half(x) tells whether direction x is in
// the half-open half-turn [ref, ref + π) (0) or in [ref + π, ref + 2π) (1);
// every completed turn crosses from 1 back to 0 exactly once.
template <class Half>
int count_turns(const std::vector<Index>& seq, bool cyclic, Half half) {
  int turns = 0;
  const std::size_t m = seq.size();
  const std::size_t steps = cyclic ? m : (m == 0 ? 0 : m - 1);
  int prev = m ? half(seq[0]) : 0;
  for (std::size_t k = 0; k < steps; ++k) {
    int next = half(seq[(k + 1) % m]);
    if (prev == 1 && next == 0) ++turns;
    prev = next;
  }
  return turns;
}

// A locality-preserving order of the given points (Morton order of their
// bounding-box-normalised coordinates), so that point-location walks started
// from the previous answer stay short.
inline void morton_sort(const PointSet& ps, std::vector<Index>& pts) {
  if (pts.empty()) return;
  const int d = ps.dim;
  double lo[3], hi[3];
  for (int j = 0; j < d; ++j) lo[j] = hi[j] = ps.point(pts[0])[j];
  for (Index p : pts)
    for (int j = 0; j < d; ++j) {
      lo[j] = std::min(lo[j], ps.point(p)[j]);
      hi[j] = std::max(hi[j], ps.point(p)[j]);
    }
  const int bits = d == 2 ? 16 : 10;
  auto key = [&](Index p) {
    std::uint64_t k = 0;
    std::uint32_t cell[3] = {0, 0, 0};
    for (int j = 0; j < d; ++j) {
      double span = hi[j] - lo[j];
      double t = (std::isfinite(span) && span > 0) ? (ps.point(p)[j] - lo[j]) / span : 0.0;
      if (!(t >= 0)) t = 0;  // NaN guard (cannot happen for finite input)
      cell[j] = static_cast<std::uint32_t>(std::min(t, 1.0) * ((1u << bits) - 1));
    }
    for (int b = bits - 1; b >= 0; --b)
      for (int j = 0; j < d; ++j) k = (k << 1) | ((cell[j] >> b) & 1u);
    return k;
  };
  std::vector<std::pair<std::uint64_t, Index>> keyed;
  keyed.reserve(pts.size());
  for (Index p : pts) keyed.emplace_back(key(p), p);
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = keyed[i].second;
}

// The smallest i in [0, n) with fails(i), n when there is none. With
// for_range (a certify::Speedups::for_range) the indices are split into pieces
// run in any order, possibly at once; a piece stops at its first failure or
// once a smaller failing index is known, so the answer is the sequential
// scan's whatever the schedule. fails must be safe to call concurrently.
template <class ForRange, class Fails>
std::size_t smallest_failing(std::size_t n, const ForRange& for_range, const Fails& fails) {
  std::atomic<std::size_t> first{n};
  auto body = [&](std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      if (i >= first.load(std::memory_order_relaxed)) return;  // a smaller failure is known
      if (!fails(i)) continue;
      std::size_t cur = first.load();
      while (i < cur && !first.compare_exchange_weak(cur, i)) {
      }
      return;
    }
  };
  if (for_range) for_range(n, body);
  else body(0, n);
  return first.load();
}

// A small deterministic generator for the stochastic walks (Devillers–Pion–
// Teillaud "remembering stochastic walk" picks a random violated edge).
struct XorShift {
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  std::uint32_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<std::uint32_t>(s >> 11);
  }
};

// Common index checks: every index < n, three distinct per triangle.
inline std::string check_triangle_indices(const std::vector<Triangle>& tris, std::size_t n) {
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (Index v : tris[t])
      if (v >= n)
        return "triangle " + std::to_string(t) + " " + tri_str(tris[t]) + " names point " +
               std::to_string(v) + " but the input has " + std::to_string(n) + " points";
    if (tris[t][0] == tris[t][1] || tris[t][1] == tris[t][2] || tris[t][0] == tris[t][2])
      return "triangle " + std::to_string(t) + " " + tri_str(tris[t]) + " repeats a vertex";
  }
  return {};
}

// Canonical form (DESIGN.md): each triangle rotated so its smallest index comes
// first, lines sorted, no repeats.
inline std::string check_canonical_triangles(const std::vector<Triangle>& tris) {
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Triangle& x = tris[t];
    if (!(x[0] < x[1] && x[0] < x[2]))
      return "triangle " + std::to_string(t) + " " + tri_str(x) +
             " is not rotated to start at its smallest index";
    if (t > 0 && !(tris[t - 1] < x))
      return "triangles " + std::to_string(t - 1) + " and " + std::to_string(t) +
             " are not in strictly increasing order";
  }
  return {};
}

}  // namespace flipflop::certify::detail

// certify_detail.hpp — combinatorial helpers shared by the certifiers.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
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

// The smallest i in [0, n) with fails(i), n when there is none. With
// for_range (a certify::Speedups::for_range) the indices are split into pieces
// run in any order, possibly at once; a piece stops at its first failure or
// once a smaller failing index is known, so the answer is the sequential
// scan's whatever the schedule. make_fails(lo) gives the test of the piece
// that starts at lo (a piece may carry state from one index to the next, e.g.
// where a walk stopped, as long as fails(i) does not depend on it); it must be
// safe to call concurrently, and so must the tests.
template <class ForRange, class MakeFails>
std::size_t smallest_failing_by_piece(std::size_t n, const ForRange& for_range, const MakeFails& make_fails) {
  std::atomic<std::size_t> first{n};
  auto body = [&](std::size_t lo, std::size_t hi) {
    auto&& fails = make_fails(lo);
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
// The same with one stateless test fails(i).
template <class ForRange, class Fails>
std::size_t smallest_failing(std::size_t n, const ForRange& for_range, const Fails& fails) {
  return smallest_failing_by_piece(n, for_range, [&](std::size_t) -> const Fails& { return fails; });
}

// body(lo, hi) over [0, n) through for_range when there is one, else at once.
template <class ForRange, class Body>
void for_pieces(std::size_t n, const ForRange& for_range, const Body& body) {
  if (for_range) for_range(n, body);
  else body(0, n);
}

constexpr std::uint32_t kNoTriangle = ~std::uint32_t{0};

// Union-find over triangle ids, for connectivity; unite and find may run
// concurrently (lock-free: a root is linked under a root of smaller id by a
// compare-and-swap that fails when it has stopped being a root, so every
// parent has a smaller id and no cycle forms; find halves paths, replacing a
// parent by an ancestor). The partition after all unions does not depend on
// their order.
struct UnionFind {
  std::vector<std::atomic<std::uint32_t>> parent;
  explicit UnionFind(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i].store(static_cast<std::uint32_t>(i), std::memory_order_relaxed);
  }
  std::uint32_t find(std::uint32_t x) {
    for (;;) {
      std::uint32_t p = parent[x].load(std::memory_order_relaxed);
      if (p == x) return x;
      const std::uint32_t g = parent[p].load(std::memory_order_relaxed);
      if (g != p) parent[x].compare_exchange_weak(p, g, std::memory_order_relaxed);
      x = g;
    }
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a), b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      std::uint32_t root = a;
      if (parent[a].compare_exchange_strong(root, b)) return;
    }
  }
};

// The triangles around each vertex, in CSR form: triangle t = (a, b, c)
// contributes the link edge b→c at a, c→a at b and a→b at c, each with its
// corner 3 t + k (t[k] the vertex). For vertex v, entries [start[v],
// start[v+1]) of `link`, sorted by (from, corner). An entry (from = u) at v
// is also the directed edge (v, u) of its triangle and an entry (to = u) the
// directed edge (u, v), so the directed edges and their twins are found among
// a vertex's few entries, and a repeated directed edge is two entries with
// one `from`. Built by a counting sort on the vertex, the scatter through
// for_range (positions taken by atomic increments; the per-vertex sort then
// makes the result independent of the schedule).
struct VertexLinks {
  struct Link {
    Index from, to;
    std::uint32_t corner;
    std::uint32_t tri() const { return corner / 3; }
    bool operator<(const Link& o) const { return from != o.from ? from < o.from : corner < o.corner; }
  };
  std::vector<std::uint32_t> start;
  std::vector<Link> link;
  static constexpr std::ptrdiff_t kShortLink = 32;  // longer vertex links are sorted and searched in O(log)

  template <class ForRange>
  void build(std::size_t n, const std::vector<Triangle>& tris, const ForRange& for_range) {
    std::vector<std::atomic<std::uint32_t>> fill(n + 1);  // value-initialised: zeros
    for_pieces(tris.size(), for_range, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t t = lo; t < hi; ++t)
        for (Index v : tris[t]) fill[v + 1].fetch_add(1, std::memory_order_relaxed);
    });
    start.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) {
      start[v + 1] = start[v] + fill[v + 1].load(std::memory_order_relaxed);
      fill[v].store(start[v], std::memory_order_relaxed);
    }
    link.resize(tris.size() * 3);
    for_pieces(tris.size(), for_range, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t t = lo; t < hi; ++t)
        for (int k = 0; k < 3; ++k)
          link[fill[tris[t][k]].fetch_add(1, std::memory_order_relaxed)] = {
              tris[t][(k + 1) % 3], tris[t][(k + 2) % 3], static_cast<std::uint32_t>(3 * t + k)};
    });
    for_pieces(n, for_range, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t v = lo; v < hi; ++v) {
        // insertion sort for the handful of entries most vertices have; a
        // vertex of large degree (a fan over many coplanar points) by
        // std::sort, not in quadratic time
        const auto b = link.begin() + start[v], e = link.begin() + start[v + 1];
        if (e - b > kShortLink) {
          std::sort(b, e);
          continue;
        }
        for (auto i = b; i != e; ++i)
          for (auto j = i; j != b && *j < *(j - 1); --j) std::iter_swap(j, j - 1);
      }
    });
  }
  std::uint32_t degree(Index v) const { return start[v + 1] - start[v]; }
  Index first_from(Index v) const { return link[start[v]].from; }

  // The entry with from == u at v — the directed edge (v, u) — (the first
  // one, of the smallest triangle, if it repeats), or nullptr.
  const Link* entry(Index v, Index u) const {
    const Link* b = link.data() + start[v];
    const Link* e = link.data() + start[v + 1];
    if (e - b > kShortLink) {  // a large degree: binary search (sorted by from first)
      b = std::lower_bound(b, e, u, [](const Link& l, Index x) { return l.from < x; });
      return b != e && b->from == u ? b : nullptr;
    }
    for (; b != e && b->from <= u; ++b)
      if (b->from == u) return b;
    return nullptr;
  }
  // The link vertex following `u` around v, or -1 if there is none.
  long next(Index v, Index u) const {
    const Link* l = entry(v, u);
    return l ? static_cast<long>(l->to) : -1;
  }

  // The first repeated directed edge in the order of a scan over the triangles
  // and their edges (t, k) (edge k of t: (t[k], t[k+1])), as a map from edge
  // keys would meet it: the directed edge (a, b) whose second occurrence comes
  // first, t1 the triangle of its first occurrence and t2 of its second.
  // False when no directed edge repeats.
  template <class ForRange>
  bool repeated_edge(const std::vector<Triangle>& tris, const ForRange& for_range, Index& a, Index& b,
                     std::uint32_t& t1, std::uint32_t& t2) const {
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    std::atomic<std::uint32_t> first{kNone};  // the corner of the second occurrence
    for_pieces(start.size() - 1, for_range, [&](std::size_t lo, std::size_t hi) {
      std::uint32_t best = kNone;
      for (std::size_t v = lo; v < hi; ++v)
        for (std::uint32_t i = start[v] + 1; i < start[v + 1]; ++i)
          if (link[i].from == link[i - 1].from && (i == start[v] + 1 || link[i - 2].from != link[i].from))
            best = std::min(best, link[i].corner);
      std::uint32_t cur = first.load();
      while (best < cur && !first.compare_exchange_weak(cur, best)) {
      }
    });
    const std::uint32_t c = first.load();
    if (c == kNone) return false;
    t2 = c / 3;
    a = tris[t2][c % 3], b = tris[t2][(c % 3 + 1) % 3];
    t1 = entry(a, b)->tri();
    return true;
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

inline Index third_vertex(const Triangle& t, Index a, Index b) {
  for (Index v : t)
    if (v != a && v != b) return v;
  return t[0];
}

// The triangle across each edge: across[t][k] is the triangle holding the
// directed edge (t[k+1], t[k]), the twin of edge k of t, or kNoTriangle; every
// pair of twins is united in uf. Directed edges must not repeat
// (VertexLinks::repeated_edge). Through for_range, over the vertices: at v,
// the twin of the entry (from = u) is the entry (to = u), among v's own.
template <class ForRange>
std::vector<std::array<std::uint32_t, 3>> neighbours(const std::vector<Triangle>& tris, const VertexLinks& links,
                                                     UnionFind& uf, const ForRange& for_range) {
  std::vector<std::array<std::uint32_t, 3>> across(tris.size());
  for_pieces(links.start.size() - 1, for_range, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t v = lo; v < hi; ++v) {
      const VertexLinks::Link* b = links.link.data() + links.start[v];
      const VertexLinks::Link* e = links.link.data() + links.start[v + 1];
      for (const VertexLinks::Link* l = b; l != e; ++l) {
        const VertexLinks::Link* twin = b;
        while (twin != e && twin->to != l->from) ++twin;
        across[l->tri()][l->corner % 3] = twin == e ? kNoTriangle : twin->tri();
        if (twin != e && v < l->from) uf.unite(l->tri(), twin->tri());
      }
    }
  });
  return across;
}

// A table of start triangles for point-location walks, a hint only: every
// stride-th triangle is put into the cell cell_of(its centroid) when that cell
// is still empty; empty cells then take the previous filled cell's (the
// first ones triangle 0).
template <class CellOf>
std::vector<std::uint32_t> start_cells(std::size_t cells, const PointSet& ps, const std::vector<Triangle>& tris,
                                       std::size_t stride, const CellOf& cell_of) {
  std::vector<std::uint32_t> cell(cells, kNoTriangle);
  const int d = ps.dim;
  for (std::size_t t = 0; t < tris.size(); t += stride) {
    double c[3];
    for (int j = 0; j < d; ++j) c[j] = (ps.point(tris[t][0])[j] + ps.point(tris[t][1])[j] + ps.point(tris[t][2])[j]) / 3;
    std::uint32_t& slot = cell[cell_of(c)];
    if (slot == kNoTriangle) slot = static_cast<std::uint32_t>(t);
  }
  std::uint32_t last = 0;
  for (std::uint32_t& slot : cell) {
    if (slot == kNoTriangle) slot = last;
    last = slot;
  }
  return cell;
}

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

// body(c, lo, hi) for every chunk c = [lo, hi) = [c size, min(n, (c + 1) size))
// of [0, n), through for_range: a piece runs the chunks that start in it, so
// the chunks are the same whatever the split (for steps that need fixed
// chunks, as a stable parallel scatter does).
template <class ForRange, class Body>
void for_chunks(std::size_t n, std::size_t size, const ForRange& for_range, const Body& body) {
  for_pieces(n, for_range, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = (lo + size - 1) / size; c * size < hi; ++c) body(c, c * size, std::min(n, (c + 1) * size));
  });
}

// A stable LSD radix sort of 64-bit keys on their bits [lo_bit, 64), 8-bit
// digits, through for_range over fixed chunks: per chunk a digit histogram,
// their prefix sums in (digit, chunk) order, then a stable scatter per chunk,
// so the order does not depend on the split. The bits below lo_bit keep the
// input order among equal high parts (e.g. a position stored there, the keys
// built in that order: the result is then the sorted order of the whole keys).
template <class ForRange>
void radix_sort_high(std::vector<std::uint64_t>& v, int lo_bit, const ForRange& for_range) {
  const std::size_t m = v.size();
  constexpr std::size_t kSize = std::size_t{1} << 16;
  const std::size_t chunks = (m + kSize - 1) / kSize;
  std::vector<std::uint64_t> tmp(m);
  std::vector<std::size_t> at(chunks * 256);
  for (int shift = lo_bit; shift < 64; shift += 8) {
    std::fill(at.begin(), at.end(), 0);
    for_chunks(m, kSize, for_range, [&](std::size_t c, std::size_t a, std::size_t b) {
      for (std::size_t i = a; i < b; ++i) ++at[c * 256 + ((v[i] >> shift) & 255u)];
    });
    std::size_t sum = 0;
    for (std::size_t digit = 0; digit < 256; ++digit)
      for (std::size_t c = 0; c < chunks; ++c) {
        const std::size_t count = at[c * 256 + digit];
        at[c * 256 + digit] = sum;
        sum += count;
      }
    for_chunks(m, kSize, for_range, [&](std::size_t c, std::size_t a, std::size_t b) {
      for (std::size_t i = a; i < b; ++i) tmp[at[c * 256 + ((v[i] >> shift) & 255u)]++] = v[i];
    });
    v.swap(tmp);
  }
}

// A locality-preserving order of the given points (Morton order of their
// bounding-box-normalised coordinates), so that point-location walks started
// from the previous answer stay short. Points of one Morton key keep their
// order in `pts` (with pts increasing: sorted by (key, index)). The keys are
// computed through for_range and sorted by radix_sort_high (each key above
// its position in `pts`), so the order does not depend on the split.
// d = 1..16 (32 / d bits per axis; 16 in 2D).
template <class ForRange>
void morton_sort(const PointSet& ps, std::vector<Index>& pts, const ForRange& for_range) {
  if (pts.empty()) return;
  const int d = ps.dim;
  constexpr int kMax = 16;  // keys of at most 32 bits: 32 / d bits per axis
  if (d < 1 || d > kMax) throw std::invalid_argument("morton_sort: dimension 1..16");
  double lo[kMax], hi[kMax];
  for (int j = 0; j < d; ++j) lo[j] = hi[j] = ps.point(pts[0])[j];
  {  // the box, by pieces
    const std::size_t m = pts.size();
    const std::size_t pieces = (m + 65535) / 65536;
    std::vector<std::array<double, 2 * kMax>> part(pieces);
    for_chunks(m, 65536, for_range, [&](std::size_t c, std::size_t a, std::size_t b) {
      auto& box = part[c];
      for (int j = 0; j < d; ++j) box[j] = box[kMax + j] = ps.point(pts[a])[j];
      for (std::size_t i = a; i < b; ++i)
        for (int j = 0; j < d; ++j) {
          box[j] = std::min(box[j], ps.point(pts[i])[j]);
          box[kMax + j] = std::max(box[kMax + j], ps.point(pts[i])[j]);
        }
    });
    for (const auto& box : part)
      for (int j = 0; j < d; ++j) lo[j] = std::min(lo[j], box[j]), hi[j] = std::max(hi[j], box[kMax + j]);
  }
  const int bits = d == 2 ? 16 : 32 / d;  // 2D 16, 3D 10, 4D 8, ... 9D 3
  auto key = [&](Index p) {
    std::uint32_t k = 0;
    std::uint32_t cell[kMax] = {};
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
  const std::size_t m = pts.size();
  std::vector<std::uint64_t> keys(m);
  for_pieces(m, for_range, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) keys[i] = (static_cast<std::uint64_t>(key(pts[i])) << 32) | i;
  });
  radix_sort_high(keys, 32, for_range);
  std::vector<Index> sorted(m);
  for_pieces(m, for_range, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) sorted[i] = pts[keys[i] & 0xFFFFFFFFu];
  });
  pts.swap(sorted);
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

// Common index checks: every index < n, three distinct per triangle; the
// first failing triangle is reported (the triangles checked through
// for_range).
template <class ForRange>
std::string check_triangle_indices(const std::vector<Triangle>& tris, std::size_t n, const ForRange& for_range) {
  auto problem = [&](std::size_t t) -> std::string {
    for (Index v : tris[t])
      if (v >= n)
        return "triangle " + std::to_string(t) + " " + tri_str(tris[t]) + " names point " + std::to_string(v) +
               " but the input has " + std::to_string(n) + " points";
    if (tris[t][0] == tris[t][1] || tris[t][1] == tris[t][2] || tris[t][0] == tris[t][2])
      return "triangle " + std::to_string(t) + " " + tri_str(tris[t]) + " repeats a vertex";
    return {};
  };
  const std::size_t bad = smallest_failing(tris.size(), for_range, [&](std::size_t t) {
    for (Index v : tris[t])
      if (v >= n) return true;
    return tris[t][0] == tris[t][1] || tris[t][1] == tris[t][2] || tris[t][0] == tris[t][2];
  });
  return bad < tris.size() ? problem(bad) : std::string();
}

// Canonical form (DESIGN.md): each triangle rotated so its smallest index comes
// first, lines sorted, no repeats (the first failing triangle, through
// for_range).
template <class ForRange>
std::string check_canonical_triangles(const std::vector<Triangle>& tris, const ForRange& for_range) {
  auto rotated = [&](std::size_t t) { return tris[t][0] < tris[t][1] && tris[t][0] < tris[t][2]; };
  auto ordered = [&](std::size_t t) { return t == 0 || tris[t - 1] < tris[t]; };
  const std::size_t t =
      smallest_failing(tris.size(), for_range, [&](std::size_t i) { return !rotated(i) || !ordered(i); });
  if (t == tris.size()) return {};
  if (!rotated(t))
    return "triangle " + std::to_string(t) + " " + tri_str(tris[t]) + " is not rotated to start at its smallest index";
  return "triangles " + std::to_string(t - 1) + " and " + std::to_string(t) + " are not in strictly increasing order";
}

}  // namespace flipflop::certify::detail

// strict_rt2.cpp — the strict view of a 2D regular triangulation (see
// strict_rt2.hpp for the rule and why it holds).
#include "reference/rt2/strict_rt2.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "predicates/predicates.hpp"
#include "reference/canonical.hpp"
#include "reference/rt2/rt2.hpp"

namespace flipflop::ref {

namespace {

std::uint64_t key(Index u, Index v) { return (static_cast<std::uint64_t>(u) << 32) | v; }

// A triangle list with the map directed edge -> triangle (each triangle
// counter-clockwise: (a, b, c) holds a->b, b->c, c->a).
struct Mesh {
  const PointSet& ps;
  std::vector<Triangle> t;
  std::vector<char> alive;
  std::unordered_map<std::uint64_t, std::size_t> at;

  Mesh(const PointSet& p, const std::vector<Triangle>& tris) : ps(p) {
    for (const Triangle& x : tris) add(x);
  }
  int orient(Index a, Index b, Index c) const { return pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)); }
  std::size_t add(Triangle x) {
    if (orient(x[0], x[1], x[2]) < 0) std::swap(x[1], x[2]);
    const std::size_t i = t.size();
    t.push_back(x);
    alive.push_back(1);
    for (int e = 0; e < 3; ++e)
      if (!at.emplace(key(x[e], x[(e + 1) % 3]), i).second)
        throw std::invalid_argument("strict view: the triangles are not a triangulation (directed edge " +
                                    std::to_string(x[e]) + "->" + std::to_string(x[(e + 1) % 3]) + " twice)");
    return i;
  }
  void remove(std::size_t i) {
    alive[i] = 0;
    for (int e = 0; e < 3; ++e) at.erase(key(t[i][e], t[i][(e + 1) % 3]));
  }
  // the triangle across directed edge u->v (holding v->u), -1 on the boundary
  long across(Index u, Index v) const {
    const auto it = at.find(key(v, u));
    return it == at.end() ? -1 : static_cast<long>(it->second);
  }
  // the vertex of triangle i that is not u or v
  Index third(std::size_t i, Index u, Index v) const {
    for (Index x : t[i])
      if (x != u && x != v) return x;
    return t[i][0];
  }
  std::vector<Triangle> live() const {
    std::vector<Triangle> out;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (alive[i]) out.push_back(t[i]);
    return out;
  }
};

// Step 0: marks the vertices of T that coincide with a kept one (largest
// weight, then smallest index) in `drop`; true when it marked any.
bool mark_coinciding_vertices(const PointSet& ps, const std::vector<Triangle>& T, std::vector<char>& drop) {
  std::map<std::pair<double, double>, Index> keeper;  // location -> kept vertex (== on doubles: -0 = +0)
  bool any = false;
  std::vector<Index> verts;
  for (const Triangle& t : T) verts.insert(verts.end(), t.begin(), t.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (Index v : verts) {
    const std::pair<double, double> loc{ps.point(v)[0], ps.point(v)[1]};
    auto [it, fresh] = keeper.emplace(loc, v);
    if (fresh) continue;
    any = true;
    const Index k = it->second;  // k < v (increasing order)
    if (ps.weight(v) > ps.weight(k)) {
      drop[k] = 1;
      it->second = v;
    } else {
      drop[v] = 1;
    }
  }
  return any;
}

// The canonical answer for the points not dropped, in input indices.
std::vector<Triangle> canonical_without(const PointSet& ps, const std::vector<char>& drop) {
  PointSet sub;
  sub.dim = 2;
  sub.weighted = ps.weighted;
  std::vector<Index> back;
  for (Index i = 0; i < ps.size(); ++i) {
    if (drop[i]) continue;
    back.push_back(i);
    sub.coords.insert(sub.coords.end(), ps.point(i), ps.point(i) + 2);
    if (ps.weighted) sub.weights.push_back(ps.weights[i]);
  }
  std::vector<Triangle> out = rt2_ffrt(sub);
  for (Triangle& t : out)
    for (Index& x : t) x = back[x];
  return out;
}

// Step 1: flat triangles removed (strict_rt2.hpp).
void remove_flat_triangles(Mesh& m) {
  auto middle_first = [&](const Triangle& t) {  // (m, a, c): m strictly between a and c
    Triangle s = t;
    std::sort(s.begin(), s.end(), [&](Index u, Index v) {
      const double *p = m.ps.point(u), *q = m.ps.point(v);
      return p[0] != q[0] ? p[0] < q[0] : p[1] < q[1];
    });
    return Triangle{s[1], s[0], s[2]};
  };
  for (;;) {
    std::vector<std::pair<Triangle, std::size_t>> flat;
    for (std::size_t i = 0; i < m.t.size(); ++i)
      if (m.alive[i] && m.orient(m.t[i][0], m.t[i][1], m.t[i][2]) == 0) flat.push_back({m.t[i], i});
    if (flat.empty()) return;
    std::sort(flat.begin(), flat.end());
    bool progress = false;
    for (const auto& [tri, i] : flat) {
      if (!m.alive[i]) continue;
      const Triangle mac = middle_first(tri);
      const Index mid = mac[0];
      // the long edge as it runs in triangle i (counter-clockwise)
      Index a = mac[1], c = mac[2];
      if (m.at.count(key(a, c)) == 0 || m.at.at(key(a, c)) != i) std::swap(a, c);
      const long g = m.across(a, c);
      if (g < 0) {  // on the boundary: m becomes a boundary vertex
        m.remove(i);
        progress = true;
        continue;
      }
      const std::size_t gi = static_cast<std::size_t>(g);
      const Index d = m.third(gi, a, c);
      if (m.orient(a, c, d) == 0) {
        // a flat neighbour: when ac is its long edge too (d strictly inside
        // ac, on the other side under the perturbation), flip the zero-area
        // quadrilateral a -> d -> c -> mid to the diagonal mid-d: two flat
        // triangles whose long edges (a-d or mid-c, ...) now border the
        // non-flat triangles beyond, removed in a later pass. Otherwise its
        // own long edge comes first (a later pass).
        const Triangle other = middle_first(m.t[gi]);
        if (other[0] != d) continue;
        m.remove(i);
        m.remove(gi);
        m.add({a, d, mid});  // the cycles keep every outer directed edge: a->d, d->c of the
        m.add({d, c, mid});  // neighbour, c->mid, mid->a of triangle i
        progress = true;
        continue;
      }
      m.remove(i);
      m.remove(gi);
      m.add({a, mid, d});
      m.add({mid, c, d});
      progress = true;
    }
    if (!progress)
      throw std::runtime_error("strict view: " + std::to_string(flat.size()) +
                               " flat triangles share their long edges and cannot be removed by flips");
  }
}

// Step 1b: boundary vertices strictly inside a hull edge whose lifted point
// is strictly above the lifted edge are exactly (strictly) redundant — the
// perturbation can push a point of a hull edge outside the hull and make it a
// vertex, the exact input cannot: marked in `drop`; true when any.
// For p -> m -> c consecutive on the (counter-clockwise) boundary, collinear,
// and d the apex of the triangle on p -> m (off the line), every plane
// through the lifted p and c contains the lifted line pc, so power2d(p, c,
// d, m) < 0 (p, c, d counter-clockwise) says exactly that the lifted m lies
// strictly above it. Zero weights never: the paraboloid is strictly convex.
bool mark_redundant_boundary(const Mesh& m, std::vector<char>& drop) {
  if (!m.ps.weighted) return false;
  auto W = [&](Index i) { return pred::WPt{i, m.ps.point(i), m.ps.weight(i)}; };
  std::unordered_map<Index, Index> next;
  std::unordered_map<Index, std::size_t> tri_of;
  for (const auto& [k, i] : m.at) {
    const Index u = static_cast<Index>(k >> 32), v = static_cast<Index>(k & 0xffffffffu);
    if (m.at.count(key(v, u))) continue;
    next[u] = v;
    tri_of[u] = i;
  }
  bool any = false;
  for (const auto& [p, mid] : next) {
    const auto it = next.find(mid);
    if (it == next.end()) continue;
    const Index c = it->second;
    if (m.orient(p, mid, c) != 0) continue;
    const Index d = m.third(tri_of.at(p), p, mid);
    if (pred::power2d_exact(W(p), W(c), W(d), W(mid)) < 0) {
      drop[mid] = 1;
      any = true;
    }
  }
  return any;
}

// Step 2: Lawson's flips to weak regularity (strict_rt2.hpp).
void lawson_weak(Mesh& m) {
  auto W = [&](Index i) { return pred::WPt{i, m.ps.point(i), m.ps.weight(i)}; };
  std::deque<std::pair<Index, Index>> queue;
  {
    std::vector<std::pair<Index, Index>> edges;
    for (const auto& [k, i] : m.at) {
      const Index u = static_cast<Index>(k >> 32), v = static_cast<Index>(k & 0xffffffffu);
      if (u < v && m.at.count(key(v, u))) edges.emplace_back(u, v);
      (void)i;
    }
    std::sort(edges.begin(), edges.end());
    queue.assign(edges.begin(), edges.end());
  }
  while (!queue.empty()) {
    const auto [u, v] = queue.front();
    queue.pop_front();
    const auto i1 = m.at.find(key(u, v)), i2 = m.at.find(key(v, u));
    if (i1 == m.at.end() || i2 == m.at.end()) continue;  // no longer an interior edge
    const std::size_t t1 = i1->second, t2 = i2->second;
    const Index c = m.third(t1, u, v), d = m.third(t2, u, v);
    // u, v strictly on opposite sides of cd: the quadrilateral u d v c is strictly convex
    if (!(m.orient(c, d, u) * m.orient(c, d, v) < 0)) continue;
    if (pred::power2d_exact(W(u), W(v), W(c), W(d)) <= 0) continue;  // weakly regular
    m.remove(t1);
    m.remove(t2);
    m.add({u, d, c});
    m.add({d, v, c});
    for (const auto& e : {std::pair<Index, Index>{u, d}, {d, v}, {v, c}, {c, u}})
      queue.emplace_back(std::min(e.first, e.second), std::max(e.first, e.second));
  }
}

}  // namespace

std::vector<Triangle> strict_rt2(const PointSet& ps, const std::vector<Triangle>& canonical) {
  if (ps.dim != 2) throw std::invalid_argument("strict view: 2D points expected");
  for (const Triangle& t : canonical)
    for (Index x : t)
      if (x >= ps.size()) throw std::invalid_argument("strict view: index " + std::to_string(x) + " out of range");
  // Steps 0 and 1b drop exactly redundant points and recompute the canonical
  // answer of the rest; each round drops at least one point, so at most n
  // rounds (in practice one or two).
  std::vector<char> drop(ps.size(), 0);
  std::vector<Triangle> T = canonical;
  for (;;) {
    if (mark_coinciding_vertices(ps, T, drop)) {
      T = canonical_without(ps, drop);
      continue;
    }
    Mesh m(ps, T);
    remove_flat_triangles(m);
    if (mark_redundant_boundary(m, drop)) {
      T = canonical_without(ps, drop);
      continue;
    }
    lawson_weak(m);
    return canonical_triangles(m.live());
  }
}

}  // namespace flipflop::ref

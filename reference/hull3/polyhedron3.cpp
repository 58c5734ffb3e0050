// polyhedron3.cpp — the triangle-array polyhedron of flip-flop / ffHull
// (thesis §6.4.1) and the star-shapedness test of Lemma 6.1; see
// polyhedron3.hpp.
#include "reference/hull3/polyhedron3.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace flipflop::ref::poly {

namespace {

std::uint64_t key(Index u, Index w) { return (static_cast<std::uint64_t>(u) << 32) | w; }

std::string tstr(const Triangle& t) {
  return "(" + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + ")";
}

int position(const Triangle& t, Index v) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == v) return k;
  return -1;
}

// In triangle nb, the edge x -> y now has `to` across it.
void relink(Polyhedron3& P, std::uint32_t nb, Index x, Index y, std::uint32_t to) {
  for (int k = 0; k < 3; ++k)
    if (P.tri[nb][k] == x && P.tri[nb][(k + 1) % 3] == y) {
      P.adj[nb][k] = to;
      return;
    }
  throw std::logic_error("polyhedron3: neighbour without the shared edge");
}

std::uint32_t alloc(Polyhedron3& P) {
  if (!P.free_slots.empty()) {
    std::uint32_t t = P.free_slots.back();
    P.free_slots.pop_back();
    P.alive[t] = 1;
    return t;
  }
  P.tri.push_back({});
  P.adj.push_back({kNone, kNone, kNone});
  P.alive.push_back(1);
  return static_cast<std::uint32_t>(P.tri.size() - 1);
}

void release(Polyhedron3& P, std::uint32_t t) {
  P.alive[t] = 0;
  P.free_slots.push_back(t);
}

struct UnionFind {
  std::vector<std::uint32_t> p;
  explicit UnionFind(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { p[find(a)] = find(b); }
};

}  // namespace

void Polyhedron3::no_twin() { throw std::logic_error("polyhedron3: adjacency without the twin edge"); }

std::string surface_problem(std::size_t n, const std::vector<Triangle>& tris) {
  if (tris.size() < 4)
    return "a closed surface needs at least 4 triangles, got " + std::to_string(tris.size());
  for (const Triangle& t : tris) {
    for (Index v : t)
      if (v >= n) return "triangle " + tstr(t) + " has index " + std::to_string(v) + " >= " + std::to_string(n);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "triangle " + tstr(t) + " repeats a vertex";
  }
  std::unordered_map<std::uint64_t, std::uint32_t> de;
  de.reserve(tris.size() * 3);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = tris[t][k], b = tris[t][(k + 1) % 3];
      if (!de.emplace(key(a, b), t).second)
        return "directed edge " + std::to_string(a) + " " + std::to_string(b) + " appears in triangles " +
               tstr(tris[de[key(a, b)]]) + " and " + tstr(tris[t]) +
               " (inconsistent orientation or more than two triangles on an edge)";
    }
  UnionFind uf(tris.size());
  std::vector<std::uint32_t> deg(n, 0);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = tris[t][k], b = tris[t][(k + 1) % 3];
      ++deg[a];
      auto it = de.find(key(b, a));
      if (it == de.end())
        return "edge " + std::to_string(a) + " " + std::to_string(b) + " of triangle " + tstr(tris[t]) +
               " has no opposite triangle (the surface has a hole)";
      uf.unite(t, it->second);
    }
  for (std::uint32_t t = 1; t < tris.size(); ++t)
    if (uf.find(t) != uf.find(0)) return "the surface is not connected: " + tstr(tris[t]) + " vs " + tstr(tris[0]);
  // every vertex link one cycle: walking around v from one triangle must visit
  // all deg(v) triangles of v
  std::vector<std::uint8_t> seen(n, 0);
  long V = 0;
  for (std::uint32_t t0 = 0; t0 < tris.size(); ++t0)
    for (Index v : tris[t0]) {
      if (seen[v]) continue;
      seen[v] = 1;
      ++V;
      std::uint32_t t = t0, steps = 0;
      do {
        const int k = position(tris[t], v);
        const Index y = tris[t][(k + 2) % 3];
        t = de.find(key(v, y))->second;  // the triangle (v, y, .) next around v
        ++steps;
      } while (t != t0 && steps <= deg[v]);
      if (steps != deg[v])
        return "the triangles around vertex " + std::to_string(v) +
               " do not form a single cycle (the surface is pinched there)";
    }
  const long F = static_cast<long>(tris.size()), E = F * 3 / 2;
  if (V - E + F != 2)
    return "V - E + F = " + std::to_string(V) + " - " + std::to_string(E) + " + " + std::to_string(F) + " = " +
           std::to_string(V - E + F) + ", a sphere has 2";
  return {};
}

Polyhedron3 build(std::size_t n, const std::vector<Triangle>& tris) {
  if (std::string why = surface_problem(n, tris); !why.empty()) throw std::invalid_argument("surface: " + why);
  Polyhedron3 P;
  P.n = n;
  P.tri = tris;
  P.adj.assign(tris.size(), {kNone, kNone, kNone});
  P.alive.assign(tris.size(), 1);
  P.corner.assign(n, kNone);
  P.deg.assign(n, 0);
  std::unordered_map<std::uint64_t, std::uint32_t> de;
  de.reserve(tris.size() * 3);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) de.emplace(key(tris[t][k], tris[t][(k + 1) % 3]), t);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = tris[t][k], b = tris[t][(k + 1) % 3];
      P.adj[t][k] = de.at(key(b, a));
      P.corner[a] = t;
      ++P.deg[a];
    }
  return P;
}

std::vector<Triangle> triangles(const Polyhedron3& P) {
  std::vector<Triangle> out;
  out.reserve(P.num_triangles());
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    if (P.alive[t]) out.push_back(P.tri[t]);
  return out;
}

DEdge find_edge(const Polyhedron3& P, Index u, Index w) {
  if (!P.is_vertex(u) || !P.is_vertex(w)) return {};
  // around the endpoint of smaller degree: proving that two vertices are not
  // adjacent walks a whole star (flip-flop asks for edges flipped away since
  // they were queued: 3 in 4 of its searches on 10^6 sphere-shell points)
  const bool from_u = P.deg[u] <= P.deg[w];
  const Index v = from_u ? u : w;
  const std::uint32_t t0 = P.corner[v];
  std::uint32_t t = t0;
  do {
    const int k = position(P.tri[t], v);
    // around u: u -> w is (k, k + 1); around w: u -> w is (k + 2, k)
    if (from_u ? P.tri[t][(k + 1) % 3] == w : P.tri[t][(k + 2) % 3] == u) return {t, from_u ? k : (k + 2) % 3};
    t = P.adj[t][(k + 2) % 3];
  } while (t != t0);
  return {};
}

std::vector<Index> link(const Polyhedron3& P, Index v) {
  std::vector<Index> out;
  if (!P.is_vertex(v)) return out;
  const std::uint32_t t0 = P.corner[v];
  std::uint32_t t = t0;
  do {
    const int k = position(P.tri[t], v);
    out.push_back(P.tri[t][(k + 1) % 3]);
    t = P.adj[t][(k + 2) % 3];
  } while (t != t0 && out.size() <= P.deg[v]);
  return out;
}

std::vector<std::pair<Index, Index>> edges(const Polyhedron3& P) {
  std::vector<std::pair<Index, Index>> out;
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    if (P.alive[t])
      for (int k = 0; k < 3; ++k)
        if (P.tri[t][k] < P.tri[t][(k + 1) % 3]) out.emplace_back(P.tri[t][k], P.tri[t][(k + 1) % 3]);
  return out;
}

DEdge flip22(Polyhedron3& P, DEdge e) {
  const std::uint32_t t1 = e.t;
  const DEdge f = P.twin(e);
  const std::uint32_t t2 = f.t;
  const Index a = P.tail(e), b = P.head(e), c = P.apex(e), d = P.apex(f);
  const std::uint32_t n_bc = P.adj[t1][(e.k + 1) % 3], n_ca = P.adj[t1][(e.k + 2) % 3];
  const std::uint32_t n_ad = P.adj[t2][(f.k + 1) % 3], n_db = P.adj[t2][(f.k + 2) % 3];
  P.tri[t1] = {a, d, c};
  P.adj[t1] = {n_ad, t2, n_ca};
  P.tri[t2] = {d, b, c};
  P.adj[t2] = {n_db, n_bc, t1};
  relink(P, n_ad, d, a, t1);
  relink(P, n_bc, c, b, t2);
  P.corner[a] = t1, P.corner[c] = t1, P.corner[d] = t1, P.corner[b] = t2;
  --P.deg[a], --P.deg[b], ++P.deg[c], ++P.deg[d];
  return {t1, 1};
}

std::uint32_t flip31(Polyhedron3& P, Index a) {
  if (P.deg[a] != 3) throw std::logic_error("polyhedron3: 3-1 flip of a vertex of degree " + std::to_string(P.deg[a]));
  if (P.num_triangles() <= 4) throw std::logic_error("polyhedron3: 3-1 flip on a tetrahedron");
  std::uint32_t ts[3];
  ts[0] = P.corner[a];
  for (int i = 1; i < 3; ++i) ts[i] = P.adj[ts[i - 1]][(position(P.tri[ts[i - 1]], a) + 2) % 3];
  // ts: (a, b, c), (a, c, d), (a, d, b); outer neighbours across b->c, c->d, d->b
  Index L[3];
  std::uint32_t outer[3];
  for (int i = 0; i < 3; ++i) {
    const int k = position(P.tri[ts[i]], a);
    L[i] = P.tri[ts[i]][(k + 1) % 3];
    outer[i] = P.adj[ts[i]][(k + 1) % 3];
  }
  const std::uint32_t t = ts[0];
  P.tri[t] = {L[0], L[1], L[2]};
  P.adj[t] = {outer[0], outer[1], outer[2]};
  relink(P, outer[1], L[2], L[1], t);
  relink(P, outer[2], L[0], L[2], t);
  release(P, ts[1]);
  release(P, ts[2]);
  for (Index v : L) {
    P.corner[v] = t;
    --P.deg[v];
  }
  P.corner[a] = kNone;
  P.deg[a] = 0;
  return t;
}

std::array<std::uint32_t, 3> split13(Polyhedron3& P, std::uint32_t t, Index p) {
  if (P.is_vertex(p)) throw std::logic_error("polyhedron3: 1-3 split by a vertex");
  const Index a = P.tri[t][0], b = P.tri[t][1], c = P.tri[t][2];
  const std::uint32_t n_ab = P.adj[t][0], n_bc = P.adj[t][1], n_ca = P.adj[t][2];
  const std::uint32_t t2 = alloc(P), t3 = alloc(P);
  P.tri[t] = {a, b, p};
  P.adj[t] = {n_ab, t2, t3};
  P.tri[t2] = {b, c, p};
  P.adj[t2] = {n_bc, t3, t};
  P.tri[t3] = {c, a, p};
  P.adj[t3] = {n_ca, t, t2};
  relink(P, n_bc, c, b, t2);
  relink(P, n_ca, a, c, t3);
  P.corner[a] = t, P.corner[b] = t, P.corner[p] = t, P.corner[c] = t2;
  ++P.deg[a], ++P.deg[b], ++P.deg[c];
  P.deg[p] = 3;
  return {t, t2, t3};
}

std::string structure_problem(const Polyhedron3& P) {
  std::vector<std::uint32_t> deg(P.n, 0);
  for (std::uint32_t t = 0; t < P.tri.size(); ++t) {
    if (!P.alive[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t o = P.adj[t][k];
      if (o >= P.tri.size() || !P.alive[o]) return "triangle " + tstr(P.tri[t]) + " has a dead neighbour";
      const Index a = P.tri[t][k], b = P.tri[t][(k + 1) % 3];
      bool back = false;
      for (int j = 0; j < 3; ++j)
        back |= P.tri[o][j] == b && P.tri[o][(j + 1) % 3] == a && P.adj[o][j] == t;
      if (!back) return "adjacency of " + tstr(P.tri[t]) + " and " + tstr(P.tri[o]) + " is not mutual";
      ++deg[a];
    }
  }
  for (Index v = 0; v < P.n; ++v) {
    if (deg[v] != P.deg[v]) return "degree of " + std::to_string(v) + " is wrong";
    if (deg[v] == 0) continue;
    const std::uint32_t c = P.corner[v];
    if (c >= P.tri.size() || !P.alive[c] || position(P.tri[c], v) < 0)
      return "corner of " + std::to_string(v) + " is wrong";
    if (link(P, v).size() != deg[v]) return "link of " + std::to_string(v) + " is not one cycle";
  }
  return {};
}

bool in_cone(const KernelPoint& s, Index a, Index b, Index c, Index p) {
  // p strictly inside C_s(abc): on the same side of each plane (s, a, b),
  // (s, b, c), (s, c, a) as the triangle's third vertex. orient3d(a, b, p, s)
  // has the sign of orient3d(a, b, c, s) exactly when p is on c's side of the
  // plane (s, a, b); likewise for the other two planes. Comparing with
  // o = orient3d(a, b, c, s) makes the test independent of the orientation of
  // (a, b, c) (for o < 0 the three half-spaces with sign +1 would bound the
  // opposite cone). Under SoS no sign is 0.
  const int o = s.side(a, b, c);
  return s.side(a, b, p) == o && s.side(b, c, p) == o && s.side(c, a, p) == o;
}

std::string star_problem(const Polyhedron3& P, const KernelPoint& s) {
  // (1) every cone is proper with the triangle's orientation: s on the inner
  // side of every triangle (§6.4.1: "the kernel point s is beneath t").
  for (std::uint32_t t = 0; t < P.tri.size(); ++t)
    if (P.alive[t] && s.side(P.tri[t][0], P.tri[t][1], P.tri[t][2]) <= 0)
      return "triangle " + tstr(P.tri[t]) + " does not face away from the kernel point";
  // (2) the projection from s winds once around every vertex v. Seen along
  // the axis s -> v, rot(x, y) = sign orient3d(v, x, y, s) = s.side(v, x, y)
  // is > 0 when y follows x counter-clockwise by less than a half turn; by (1)
  // each consecutive pair of the link does. The turns are counted as the
  // number of steps u_i -> u_{i+1} that reach or pass the direction of u_0.
  for (Index v = 0; v < P.n; ++v) {
    if (!P.is_vertex(v)) continue;
    const std::vector<Index> L = link(P, v);
    int turns = 1;  // the last step arrives at u_0
    for (std::size_t i = 1; i + 1 < L.size(); ++i)
      if (s.side(v, L[i], L[0]) > 0 && s.side(v, L[0], L[i + 1]) > 0) ++turns;
    if (turns != 1)
      return "seen from the kernel point the surface winds " + std::to_string(turns) + " times around vertex " +
             std::to_string(v);
  }
  return {};
}

}  // namespace flipflop::ref::poly

// triangulation2.cpp — the extended triangulation, its predicates with the
// virtual vertex, flips and validity check (see triangulation2.hpp).
#include "reference/rt2/triangulation2.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "predicates/predicates.hpp"

namespace flipflop::ref::tri {

namespace {

inline int nx(int i) { return i == 2 ? 0 : i + 1; }  // i + 1 mod 3
inline int pv(int i) { return i == 0 ? 2 : i - 1; }  // i + 2 mod 3

int index_of(const Triangle& t, Index x) {
  for (int k = 0; k < 3; ++k)
    if (t[static_cast<std::size_t>(k)] == x) return k;
  return -1;
}

// index_of for a vertex that must be there (the structure is corrupt otherwise)
int corner(const Triangle& t, Index x) {
  const int k = index_of(t, x);
  if (k < 0) throw std::logic_error("triangulation2: vertex not in its triangle");
  return k;
}

Index at(const Triangle& t, int k) { return t[static_cast<std::size_t>(k)]; }
std::int32_t& nb(Triangulation2& T, std::int32_t t, int k) {
  return T.tn[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
}
std::int32_t nb(const Triangulation2& T, std::int32_t t, int k) {
  return T.tn[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
}
const Triangle& tri(const Triangulation2& T, std::int32_t t) { return T.tv[static_cast<std::size_t>(t)]; }

std::string vstr(const Triangulation2& T, Index x) {
  return T.is_virtual(x) ? std::string("v") : std::to_string(x);
}
std::string tstr(const Triangulation2& T, const Triangle& t) {
  return "(" + vstr(T, t[0]) + " " + vstr(T, t[1]) + " " + vstr(T, t[2]) + ")";
}

std::int32_t new_slot(Triangulation2& T) {
  if (!T.free_slots.empty()) {
    const std::int32_t t = T.free_slots.back();
    T.free_slots.pop_back();
    T.alive[static_cast<std::size_t>(t)] = 1;
    return t;
  }
  T.tv.push_back({0, 0, 0});
  T.tn.push_back({kNone, kNone, kNone});
  T.alive.push_back(1);
  return static_cast<std::int32_t>(T.tv.size() - 1);
}

void free_slot(Triangulation2& T, std::int32_t t) {
  T.alive[static_cast<std::size_t>(t)] = 0;
  T.tn[static_cast<std::size_t>(t)] = {kNone, kNone, kNone};
  T.free_slots.push_back(t);
}

// In triangle `u`, replace the neighbour pointer `from` by `to`.
void repoint(Triangulation2& T, std::int32_t u, std::int32_t from, std::int32_t to) {
  for (int k = 0; k < 3; ++k)
    if (nb(T, u, k) == from) {
      nb(T, u, k) = to;
      return;
    }
}

std::uint64_t key(const Triangulation2& T, Index a, Index b) {
  return static_cast<std::uint64_t>(a) * (static_cast<std::uint64_t>(T.n) + 1) + b;
}

// Fill tn, vtri and deg from tv (all slots alive). Throws std::invalid_argument
// when a directed edge appears twice or has no twin.
void build_adjacency(Triangulation2& T) {
  const std::size_t nt = T.tv.size();
  T.tn.assign(nt, {kNone, kNone, kNone});
  T.alive.assign(nt, 1);
  T.free_slots.clear();
  T.vtri.assign(static_cast<std::size_t>(T.n) + 1, kNone);
  T.deg.assign(static_cast<std::size_t>(T.n) + 1, 0);
  T.removed.assign(static_cast<std::size_t>(T.n) + 1, 0);
  std::unordered_map<std::uint64_t, std::pair<std::int32_t, int>> half;
  half.reserve(nt * 3);
  for (std::size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const Index a = at(T.tv[t], nx(i)), b = at(T.tv[t], pv(i));
      if (!half.emplace(key(T, a, b), std::make_pair(static_cast<std::int32_t>(t), i)).second)
        throw std::invalid_argument("triangulation: the edge " + vstr(T, a) + " -> " + vstr(T, b) +
                                    " appears in two triangles (overlap or duplicate)");
    }
  for (std::size_t t = 0; t < nt; ++t) {
    for (int i = 0; i < 3; ++i) {
      const Index a = at(T.tv[t], nx(i)), b = at(T.tv[t], pv(i));
      auto it = half.find(key(T, b, a));
      if (it == half.end())
        throw std::invalid_argument("triangulation: the edge " + vstr(T, a) + " " + vstr(T, b) +
                                    " has a triangle on one side only");
      T.tn[t][static_cast<std::size_t>(i)] = it->second.first;
      const Index x = at(T.tv[t], i);
      T.vtri[x] = static_cast<std::int32_t>(t);
      ++T.deg[x];  // on a closed surface: triangles at x = edges at x
    }
  }
}

}  // namespace

// ---- combinatorics ----------------------------------------------------------

Index org(const Triangulation2& T, Edge e) { return at(tri(T, e.t), nx(e.i)); }
Index dst(const Triangulation2& T, Edge e) { return at(tri(T, e.t), pv(e.i)); }
Index apex(const Triangulation2& T, Edge e) { return at(tri(T, e.t), e.i); }

Edge twin(const Triangulation2& T, Edge e) {
  const std::int32_t u = nb(T, e.t, e.i);
  const Index a = org(T, e), b = dst(T, e);
  for (int j = 0; j < 3; ++j)
    if (at(tri(T, u), nx(j)) == b && at(tri(T, u), pv(j)) == a) return {u, j};
  throw std::logic_error("triangulation2: neighbour does not share the edge");
}

Quad quad(const Triangulation2& T, Edge e) {
  return {org(T, e), dst(T, e), apex(T, e), apex(T, twin(T, e))};
}

Edge find_edge(const Triangulation2& T, Index a, Index b) {
  if (a == b || a > T.n || b > T.n || !T.is_vertex(a) || !T.is_vertex(b)) return {};
  // walk around the endpoint with the smaller degree (never around v if avoidable)
  Index x = a, y = b;
  if (T.is_virtual(x) || (!T.is_virtual(y) && T.deg[y] < T.deg[x])) std::swap(x, y);
  const std::int32_t start = T.vtri[x];
  std::int32_t t = start;
  do {
    const int k = corner(tri(T, t), x);
    if (at(tri(T, t), nx(k)) == y) return {t, pv(k)};  // x -> y, opposite tv[t][k+2]
    t = nb(T, t, pv(k));                               // across x -> tv[t][k+1]
  } while (t != start);
  return {};
}

std::vector<Index> link(const Triangulation2& T, Index x) {
  std::vector<Index> out;
  const std::int32_t start = T.vtri[x];
  if (start == kNone) return out;
  std::int32_t t = start;
  const std::size_t limit = T.tv.size() + 1;
  do {
    const int k = corner(tri(T, t), x);
    out.push_back(at(tri(T, t), nx(k)));
    t = nb(T, t, nx(k));  // across tv[t][k+2] -> x: the next triangle counter-clockwise
  } while (t != start && out.size() <= limit);
  return out;
}

std::vector<std::pair<Index, Index>> edges(const Triangulation2& T) {
  std::vector<std::pair<Index, Index>> out;
  for (std::size_t t = 0; t < T.tv.size(); ++t) {
    if (!T.alive[t]) continue;
    for (int i = 0; i < 3; ++i) {
      const Index a = at(T.tv[t], nx(i)), b = at(T.tv[t], pv(i));
      if (a < b) out.emplace_back(a, b);  // the twin b -> a has b > a
    }
  }
  return out;
}

// ---- predicates ---------------------------------------------------------------

namespace {
const double* P(const Triangulation2& T, Index i) { return T.ps->point(i); }

// orient2d(x, y, s) under SoS, s the kernel point (SoS index n).
int orient_kernel(const Triangulation2& T, Index x, Index y) {
  const pred::MixedRow rows[3] = {{x, P(T, x), nullptr}, {y, P(T, y), nullptr}, {T.n, nullptr, &T.kernel}};
  return pred::mixed_sign(3, rows, true);
}
}  // namespace

int orient(const Triangulation2& T, Index a, Index b, Index c) {
  if (T.is_virtual(a)) return orient(T, b, c, a);  // cyclic rotations keep the sign
  if (T.is_virtual(b)) return orient(T, c, a, b);
  if (T.is_virtual(c)) return orient_kernel(T, b, a);  // orient(a, b, v) := orient(b, a, s)
  return pred::orient2d({a, P(T, a)}, {b, P(T, b)}, {c, P(T, c)});
}

bool contains(const Triangulation2& T, std::int32_t t, Index p) {
  const Triangle& x = tri(T, t);
  return orient(T, x[0], x[1], p) > 0 && orient(T, x[1], x[2], p) > 0 && orient(T, x[2], x[0], p) > 0;
}

int power(const Triangulation2& T, Index a, Index b, Index c, Index d) {
  const PointSet& ps = *T.ps;
  auto W = [&](Index i) { return pred::WPt{i, ps.point(i), ps.weight(i)}; };
  return pred::power2d(W(a), W(b), W(c), W(d));
}

bool locally_regular(const Triangulation2& T, Edge e) {
  const Quad q = quad(T, e);  // triangles (a, b, c) and (b, a, d)
  // §2.2: "A ridge incident to exactly one virtual facet is always locally regular".
  if (T.is_virtual(q.c) || T.is_virtual(q.d)) return true;
  // §2.2: a ridge G = p v with virtual facets C1 = (p, v, c), C2 = (v, p, d),
  // F1 = p c, F2 = p d: locally regular iff F1 and s lie on the same side of
  // the line through F2.
  if (T.is_virtual(q.a) || T.is_virtual(q.b)) {
    // a -> b with b = v: C1 = (a, v, c), C2 = (v, a, d); with a = v the roles of
    // c and d swap: C1 = (v, b, c) has F1 = b c, C2 = (b, v, d) has F2 = b d.
    const Index p = T.is_virtual(q.b) ? q.a : q.b;
    return orient(T, p, q.d, q.c) == orient_kernel(T, p, q.d);
  }
  // Two real triangles: d^+ strictly below the plane of a^+ b^+ c^+ means the
  // lifted edge a^+ b^+ is reflex: locally non-regular.
  return power(T, q.a, q.b, q.c, q.d) < 0;
}

EdgeShape classify(const Triangulation2& T, Edge e) {
  const Quad q = quad(T, e);
  // Algorithm 5 line 6: a 3-1 edge. A degree-3 vertex a has the link b, c, d
  // (counter-clockwise); the 3-1 flip exists iff the triangle (b, c, d) it
  // leaves is positive (§2.3: the induced subcomplex is a triangulation of
  // conv{a, b, c, d}; on the projective sphere the positive triangle is the
  // one on the left of b -> c -> d, which is then the star of a).
  if (T.deg[q.a] == 3 && orient(T, q.b, q.c, q.d) > 0) return {Shape::three_one, q.a};
  if (T.deg[q.b] == 3 && orient(T, q.c, q.a, q.d) > 0) return {Shape::three_one, q.b};
  // Line 11: a not in triangle bcd and b not in triangle acd, i.e. the
  // quadrilateral a d b c is convex at a and at b (it always is at c and d):
  // exactly when both new triangles (c, a, d) and (d, b, c) are positive.
  const int at_a = orient(T, q.c, q.a, q.d);
  const int at_b = orient(T, q.d, q.b, q.c);
  if (at_a > 0 && at_b > 0) return {Shape::two_two, q.a};
  // Lines 16-17: unflippable; the reflex corner lies in the triangle of the other three.
  return {Shape::two_two_blocked, at_a < 0 ? q.a : q.b};
}

// ---- flips ------------------------------------------------------------------------

Edge flip22(Triangulation2& T, Edge e) {
  const std::int32_t t = e.t;
  const Edge f = twin(T, e);
  const std::int32_t u = f.t;
  const Index a = org(T, e), b = dst(T, e), c = apex(T, e), d = apex(T, f);
  // outer neighbours: t = (a, b, c), u = (b, a, d) rotated as tv[u][f.i] = d
  const std::int32_t n_bc = nb(T, t, nx(e.i)), n_ca = nb(T, t, pv(e.i));
  const std::int32_t n_ad = nb(T, u, nx(f.i)), n_db = nb(T, u, pv(f.i));
  // t := (c, a, d): opposite c is a -> d, opposite a is d -> c, opposite d is c -> a
  T.tv[static_cast<std::size_t>(t)] = {c, a, d};
  T.tn[static_cast<std::size_t>(t)] = {n_ad, u, n_ca};
  // u := (d, b, c): opposite d is b -> c, opposite b is c -> d, opposite c is d -> b
  T.tv[static_cast<std::size_t>(u)] = {d, b, c};
  T.tn[static_cast<std::size_t>(u)] = {n_bc, t, n_db};
  repoint(T, n_ad, u, t);
  repoint(T, n_bc, t, u);
  T.vtri[a] = t;
  T.vtri[b] = u;
  T.vtri[c] = t;
  T.vtri[d] = t;
  --T.deg[a];
  --T.deg[b];
  ++T.deg[c];
  ++T.deg[d];
  return {t, 1};  // d -> c
}

std::int32_t flip31(Triangulation2& T, Index x) {
  // the three triangles around x, counter-clockwise: (x, b, c), (x, c, d), (x, d, b)
  const std::int32_t t0 = T.vtri[x];
  const int k0 = corner(tri(T, t0), x);
  const Index b = at(tri(T, t0), nx(k0)), c = at(tri(T, t0), pv(k0));
  const std::int32_t t1 = nb(T, t0, nx(k0));  // across c -> x
  const int k1 = corner(tri(T, t1), x);
  const Index d = at(tri(T, t1), pv(k1));
  const std::int32_t t2 = nb(T, t1, nx(k1));  // across d -> x
  const int k2 = corner(tri(T, t2), x);
  const std::int32_t n_bc = nb(T, t0, k0), n_cd = nb(T, t1, k1), n_db = nb(T, t2, k2);
  // t0 := (b, c, d): opposite b is c -> d, opposite c is d -> b, opposite d is b -> c
  T.tv[static_cast<std::size_t>(t0)] = {b, c, d};
  T.tn[static_cast<std::size_t>(t0)] = {n_cd, n_db, n_bc};
  repoint(T, n_cd, t1, t0);
  repoint(T, n_db, t2, t0);
  free_slot(T, t1);
  free_slot(T, t2);
  T.vtri[b] = T.vtri[c] = T.vtri[d] = t0;
  T.vtri[x] = kNone;
  T.deg[x] = 0;
  T.removed[x] = 1;
  --T.deg[b];
  --T.deg[c];
  --T.deg[d];
  return t0;
}

std::array<std::int32_t, 3> flip13(Triangulation2& T, std::int32_t t, Index p) {
  const Triangle old = tri(T, t);
  const Index a = old[0], b = old[1], c = old[2];
  const std::int32_t n_a = nb(T, t, 0), n_b = nb(T, t, 1), n_c = nb(T, t, 2);
  const std::int32_t t1 = new_slot(T), t2 = new_slot(T);
  // t := (a, b, p): opposite a is b -> p (t1), opposite b is p -> a (t2), opposite p is a -> b
  T.tv[static_cast<std::size_t>(t)] = {a, b, p};
  T.tn[static_cast<std::size_t>(t)] = {t1, t2, n_c};
  // t1 := (b, c, p): opposite b is c -> p (t2), opposite c is p -> b (t), opposite p is b -> c
  T.tv[static_cast<std::size_t>(t1)] = {b, c, p};
  T.tn[static_cast<std::size_t>(t1)] = {t2, t, n_a};
  // t2 := (c, a, p): opposite c is a -> p (t), opposite a is p -> c (t1), opposite p is c -> a
  T.tv[static_cast<std::size_t>(t2)] = {c, a, p};
  T.tn[static_cast<std::size_t>(t2)] = {t, t1, n_b};
  repoint(T, n_a, t, t1);
  repoint(T, n_b, t, t2);
  T.vtri[p] = t;
  T.vtri[c] = t1;
  T.deg[p] = 3;
  ++T.deg[a];
  ++T.deg[b];
  ++T.deg[c];
  return {t, t1, t2};
}

// ---- construction -------------------------------------------------------------

Triangulation2 make_initial(const PointSet& ps, Index a, Index b, Index c) {
  Triangulation2 T;
  T.ps = &ps;
  T.n = static_cast<Index>(ps.size());
  if (pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)) <= 0)
    throw std::logic_error("make_initial: the initial triangle must be counter-clockwise, not flat");
  const double* pts[4] = {ps.point(a), ps.point(b), ps.point(c), ps.point(c)};
  T.kernel = pred::RationalPoint::centroid(pts, 4, 2);  // barycentric (1/4, 1/4, 1/2): strictly inside
  const Index v = T.n;
  // the real triangle and, for each edge p -> q of P, the virtual (q, p, v)
  T.tv = {{a, b, c}, {b, a, v}, {c, b, v}, {a, c, v}};
  build_adjacency(T);
  return T;
}

Triangulation2 from_triangles(const PointSet& ps, const std::vector<Triangle>& tris) {
  Triangulation2 T;
  T.ps = &ps;
  T.n = static_cast<Index>(ps.size());
  if (tris.empty()) throw std::invalid_argument("triangulation: no triangles");
  auto P2 = [&](Index i) { return pred::Pt{i, ps.point(i)}; };
  int kernel_from = -1;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const Triangle& t = tris[k];
    for (Index x : t)
      if (x >= T.n)
        throw std::invalid_argument("triangulation: index " + std::to_string(x) + " out of range (" +
                                    std::to_string(T.n) + " points)");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw std::invalid_argument("triangulation: triangle " + tstr(T, t) + " repeats a vertex");
    if (pred::orient2d(P2(t[0]), P2(t[1]), P2(t[2])) <= 0)
      throw std::invalid_argument("triangulation: triangle " + tstr(T, t) + " is not counter-clockwise");
    if (kernel_from < 0 && pred::orient2d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2])) > 0)
      kernel_from = static_cast<int>(k);
  }
  if (kernel_from < 0) throw std::invalid_argument("triangulation: every triangle is flat");
  const Triangle& kt = tris[static_cast<std::size_t>(kernel_from)];
  const double* pts[4] = {ps.point(kt[0]), ps.point(kt[1]), ps.point(kt[2]), ps.point(kt[2])};
  T.kernel = pred::RationalPoint::centroid(pts, 4, 2);
  // close the disk with virtual triangles (q, p, v) on its boundary edges p -> q
  T.tv = tris;
  {
    std::unordered_map<std::uint64_t, int> count;
    count.reserve(tris.size() * 3);
    for (const Triangle& t : tris)
      for (int i = 0; i < 3; ++i) ++count[key(T, at(t, nx(i)), at(t, pv(i)))];
    for (const Triangle& t : tris)
      for (int i = 0; i < 3; ++i) {
        const Index p = at(t, nx(i)), q = at(t, pv(i));
        if (count.find(key(T, q, p)) == count.end()) T.tv.push_back({q, p, T.n});
      }
  }
  build_adjacency(T);
  const std::string problem = validity_problem(T);
  if (!problem.empty()) throw std::invalid_argument("triangulation: " + problem);
  return T;
}

// ---- output / checks ---------------------------------------------------------------

namespace {
std::vector<Triangle> canonical(std::vector<Triangle> ts) {
  for (Triangle& t : ts) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(ts.begin(), ts.end());
  return ts;
}
}  // namespace

std::vector<Triangle> real_triangles(const Triangulation2& T) {
  std::vector<Triangle> out;
  for (std::size_t t = 0; t < T.tv.size(); ++t)
    if (T.alive[t] && index_of(T.tv[t], T.n) < 0) out.push_back(T.tv[t]);
  return canonical(std::move(out));
}

std::vector<Triangle> all_triangles(const Triangulation2& T) {
  std::vector<Triangle> out;
  for (std::size_t t = 0; t < T.tv.size(); ++t)
    if (T.alive[t]) out.push_back(T.tv[t]);
  return canonical(std::move(out));
}

std::string validity_problem(const Triangulation2& T) {
  const std::size_t nv = static_cast<std::size_t>(T.n) + 1;
  if (T.vtri.size() != nv || T.deg.size() != nv || T.removed.size() != nv) return "per-vertex arrays have the wrong size";
  std::vector<std::size_t> count(nv, 0);
  std::size_t faces = 0;
  // -- combinatorics: triangles, neighbour symmetry
  for (std::size_t t = 0; t < T.tv.size(); ++t) {
    if (!T.alive[t]) continue;
    ++faces;
    const Triangle& x = T.tv[t];
    for (Index v : x)
      if (v > T.n) return "triangle " + std::to_string(t) + " has vertex " + std::to_string(v) + " out of range";
    if (x[0] == x[1] || x[1] == x[2] || x[0] == x[2]) return "triangle " + tstr(T, x) + " repeats a vertex";
    for (Index v : x) {
      if (T.removed[v]) return "removed vertex " + vstr(T, v) + " reappears in triangle " + tstr(T, x);
      ++count[v];
    }
    for (int i = 0; i < 3; ++i) {
      const std::int32_t u = T.tn[t][static_cast<std::size_t>(i)];
      if (u < 0 || static_cast<std::size_t>(u) >= T.tv.size() || !T.alive[static_cast<std::size_t>(u)])
        return "triangle " + tstr(T, x) + " has a dead neighbour";
      const Index a = at(x, nx(i)), b = at(x, pv(i));
      const Triangle& y = T.tv[static_cast<std::size_t>(u)];
      bool ok = false;
      for (int j = 0; j < 3 && !ok; ++j)
        ok = at(y, nx(j)) == b && at(y, pv(j)) == a &&
             T.tn[static_cast<std::size_t>(u)][static_cast<std::size_t>(j)] == static_cast<std::int32_t>(t);
      if (!ok) return "triangles " + tstr(T, x) + " and " + tstr(T, y) + " are not mutual neighbours across " +
                      vstr(T, a) + " " + vstr(T, b);
    }
  }
  // -- every vertex: one cycle of triangles (a sphere is a closed 2-manifold)
  std::size_t vertices = 0;
  for (Index v = 0; v <= T.n; ++v) {
    const std::int32_t start = T.vtri[v];
    if (start == kNone) {
      if (count[v]) return "vertex " + vstr(T, v) + " is in triangles but has no vertex-to-triangle entry";
      continue;
    }
    ++vertices;
    if (static_cast<std::size_t>(start) >= T.tv.size() || !T.alive[static_cast<std::size_t>(start)] ||
        index_of(T.tv[static_cast<std::size_t>(start)], v) < 0)
      return "vertex-to-triangle entry of " + vstr(T, v) + " is wrong";
    std::size_t steps = 0;
    std::int32_t t = start;
    do {
      const int k = index_of(tri(T, t), v);
      if (k < 0) return "the fan of " + vstr(T, v) + " leaves its star";
      t = nb(T, t, nx(k));
      ++steps;
    } while (t != start && steps <= count[v]);
    if (t != start || steps != count[v])
      return "the triangles around " + vstr(T, v) + " do not form one cycle (a pinched or split fan)";
    if (T.deg[v] != count[v]) return "stored degree of " + vstr(T, v) + " is wrong";
    if (count[v] < 3) return "vertex " + vstr(T, v) + " has degree " + std::to_string(count[v]);
  }
  if (!T.is_vertex(T.n)) return "the virtual vertex is missing";
  if ((3 * faces) % 2 != 0) return "odd number of half-edges";
  const long euler = static_cast<long>(vertices) - static_cast<long>(3 * faces / 2) + static_cast<long>(faces);
  if (euler != 2) return "V - E + F = " + std::to_string(euler) + ", not 2: not a disk closed by v";
  // -- geometry: positive triangles, every link winds once around its vertex
  for (std::size_t t = 0; t < T.tv.size(); ++t) {
    if (!T.alive[t]) continue;
    const Triangle& x = T.tv[t];
    if (orient(T, x[0], x[1], x[2]) <= 0)
      return "triangle " + tstr(T, x) +
             (index_of(x, T.n) >= 0 ? " is not positive (the polygon is not star-shaped w.r.t. the kernel point)"
                                    : " is not counter-clockwise");
  }
  for (Index v = 0; v <= T.n; ++v) {
    if (!T.is_vertex(v)) continue;
    const std::vector<Index> L = link(T, v);
    Index r = T.n;
    for (Index q : L)
      if (!T.is_virtual(q)) {
        r = q;
        break;
      }
    // Directions around v measured from the direction of r: "upper" is the
    // half-turn [0, pi). Each step (v, q_i, q_i+1) turns counter-clockwise by
    // less than pi, so it passes the direction of r exactly when it goes from
    // the lower to the upper half: these passages count the winding.
    auto upper = [&](Index q) { return q == r || orient(T, v, r, q) > 0; };
    int winding = 0;
    for (std::size_t i = 0; i < L.size(); ++i)
      if (!upper(L[i]) && upper(L[(i + 1) % L.size()])) ++winding;
    if (winding != 1)
      return "the link of " + vstr(T, v) + " winds " + std::to_string(winding) + " times around it" +
             (T.is_virtual(v) ? " (the polygon is not star-shaped w.r.t. the kernel point)" : "");
  }
  return {};
}

}  // namespace flipflop::ref::tri

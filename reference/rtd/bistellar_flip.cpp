// bistellar_flip.cpp — the bistellar flips k-(d+2-k) on the d-dimensional
// triangulation, thesis §2.3 (Radon partition, Thm 2.3; flippability [ES92]
// as quoted in §9.1). See bistellar_flip.hpp for the derivations.
#include "reference/rtd/bistellar_flip.hpp"

#include <stdexcept>
#include <string>

namespace flipflop::ref::rtd {

FlipShape flip_shape(const TriangulationD& T, RidgeD r) {
  FlipShape sh;
  const int d = T.d;
  sh.S = points(T, r);
  if (!interior(T, r)) return sh;  // §2.3: a ridge on the boundary is unflippable
  sh.interior = true;
  const Index a = link_a(T, r), b = link_b(T, r);
  // U = {b} ∪ {c_j : orient(C1[c_j := b]) < 0}; a = c_{r.i} is in U (b lies
  // across F from a: C1[a := b] is C2 reversed).
  Index t[kMaxDim + 1];
  sh.U[static_cast<std::size_t>(sh.nu++)] = b;
  sh.cur[0] = r.s;  // S \ {b} = C1
  bool all_present = true;
  for (int j = 0; j <= d; ++j) {
    const Index c = T.vertex(r.s, j);
    bool in_u;
    if (j == r.i) {
      in_u = true;
    } else {
      for (int q = 0; q <= d; ++q) t[q] = T.vertex(r.s, q);
      t[j] = b;
      in_u = orient(T, t) < 0;
    }
    if (!in_u) {
      sh.V[static_cast<std::size_t>(sh.nv++)] = c;
      continue;
    }
    // the current simplex S \ {c}: C2 for c = a; otherwise the neighbour of
    // C1 across the facet opposite c when it contains b — i.e. the reflex
    // facet R = F \ {c} has exactly the three link vertices c, a, b [ES92].
    const std::int32_t nb = T.neighbor(r.s, j);
    const bool present = j == r.i || index_of(T, nb, b) >= 0;
    if (!present) all_present = false;
    sh.cur[static_cast<std::size_t>(sh.nu)] = nb;
    sh.U[static_cast<std::size_t>(sh.nu++)] = c;
  }
  (void)a;
  sh.k = sh.nu;
  // nv >= 1 always: the d+2 points cannot all lie in U (that would be the
  // whole sphere, impossible with all of S real).
  sh.flippable = all_present && sh.nv >= 1;
  return sh;
}

FlipResult flip(TriangulationD& T, RidgeD r) { return flip(T, flip_shape(T, r)); }

FlipResult flip(TriangulationD& T, const FlipShape& sh) {
  if (!sh.interior || !sh.flippable)
    throw std::logic_error("rtd::flip: the ridge is not flippable (" +
                           std::string(sh.interior ? "its induced subcomplex is not convex" : "not an interior ridge") + ")");
  const int d = T.d;
  FlipResult res;
  res.k = sh.nu;
  // Old simplex O_z = S \ {z} for z in U (slot sh.cur[index of z]).
  // New simplex N_y = S \ {y} for y in V. For z in U, y in V the facet
  // S \ {y, z} of N_y is the facet of O_z opposite y: its outside neighbour
  // is re-attached. Capture those neighbours before freeing O_*.
  struct Ext {
    std::int32_t t;  // outside simplex
    int back;        // its position whose neighbour was O_z
  };
  Ext ext[kMaxDim + 2][kMaxDim + 2];
  for (int u = 0; u < sh.nu; ++u) {
    const std::int32_t o = sh.cur[static_cast<std::size_t>(u)];
    for (int v = 0; v < sh.nv; ++v) {
      const int i = index_of(T, o, sh.V[static_cast<std::size_t>(v)]);
      if (i < 0) throw std::logic_error("rtd::flip: induced subcomplex does not match the Radon partition");
      ext[u][v] = {T.neighbor(o, i), mirror_index(T, o, i)};
    }
  }
  for (int u = 0; u < sh.nu; ++u) free_slot(T, sh.cur[static_cast<std::size_t>(u)]);

  // Orientation of the new tuples (combinatorial): with S = (s_0..s_{d+1}) =
  // points(T, F), the ordered tuple S without s_i is positive iff
  // (i + d) is even for s_i in V (the Radon coefficients (-1)^i orient(S \ s_i)
  // have one sign on U and the other on V, and S without s_{d+1} = b is C1 up
  // to an even permutation, positive).
  std::int32_t nslot[kMaxDim + 2];
  for (int v = 0; v < sh.nv; ++v) {
    const Index y = sh.V[static_cast<std::size_t>(v)];
    int iy = -1;
    for (int q = 0; q < d + 2; ++q)
      if (sh.S[static_cast<std::size_t>(q)] == y) iy = q;
    Index t[kMaxDim + 1];
    int k = 0;
    for (int q = 0; q < d + 2; ++q)
      if (q != iy) t[k++] = sh.S[static_cast<std::size_t>(q)];
    if ((iy + d) % 2 != 0) std::swap(t[0], t[1]);
    const std::int32_t s = new_slot(T);
    for (int q = 0; q <= d; ++q) set_vertex(T, s, q, t[q]);
    nslot[v] = s;
    res.created.push_back(s);
  }
  // neighbours
  for (int v = 0; v < sh.nv; ++v) {
    const std::int32_t s = nslot[v];
    for (int q = 0; q <= d; ++q) {
      const Index z = T.vertex(s, q);
      int zu = -1, zv = -1;
      for (int u = 0; u < sh.nu; ++u)
        if (sh.U[static_cast<std::size_t>(u)] == z) zu = u;
      for (int w = 0; w < sh.nv; ++w)
        if (sh.V[static_cast<std::size_t>(w)] == z) zv = w;
      if (zv >= 0) {
        set_neighbor(T, s, q, nslot[zv]);  // facet S \ {y, z} shared by N_y and N_z
      } else {
        const Ext e = ext[zu][v];
        set_neighbor(T, s, q, e.t);
        set_neighbor(T, e.t, e.back, s);
        res.boundary.push_back({s, q});
      }
    }
    for (int q = 0; q <= d; ++q) T.vsimplex[T.vertex(s, q)] = s;
  }
  if (sh.nv == 1) {  // (d+1)-1 flip: V = {x} is removed (§2.3)
    res.removed = sh.V[0];
    T.vsimplex[res.removed] = kNone;
  }
  return res;
}

FlipResult insert_in_simplex(TriangulationD& T, std::int32_t s, Index p) {
  const int d = T.d;
  FlipResult res;
  res.k = 1;
  res.inserted = p;
  Index t[kMaxDim + 1];
  for (int q = 0; q <= d; ++q) t[q] = T.vertex(s, q);
  std::int32_t ext[kMaxDim + 1];
  int back[kMaxDim + 1];
  for (int i = 0; i <= d; ++i) {
    ext[i] = T.neighbor(s, i);
    back[i] = mirror_index(T, s, i);
  }
  free_slot(T, s);
  // N_i = t with t_i := p: positive (p strictly inside t, so p lies on t_i's
  // side of the facet opposite t_i). N_i and N_j share the facet opposite t_j
  // in N_i (= opposite t_i in N_j).
  std::int32_t ns[kMaxDim + 1];
  for (int i = 0; i <= d; ++i) {
    ns[i] = new_slot(T);
    for (int q = 0; q <= d; ++q) set_vertex(T, ns[i], q, q == i ? p : t[q]);
    res.created.push_back(ns[i]);
  }
  for (int i = 0; i <= d; ++i) {
    for (int j = 0; j <= d; ++j) {
      if (j == i) {
        set_neighbor(T, ns[i], i, ext[i]);
        set_neighbor(T, ext[i], back[i], ns[i]);
        res.boundary.push_back({ns[i], i});
      } else {
        set_neighbor(T, ns[i], j, ns[j]);
      }
    }
  }
  for (int i = 0; i <= d; ++i)
    for (int q = 0; q <= d; ++q) T.vsimplex[T.vertex(ns[i], q)] = ns[i];
  return res;
}

FlipResult remove_vertex(TriangulationD& T, Index x) {
  if (x >= T.n || !T.is_vertex(x)) throw std::logic_error("rtd::remove_vertex: " + std::to_string(x) + " is not a vertex");
  const std::vector<std::int32_t> st = star(T, x);
  if (st.size() != static_cast<std::size_t>(T.d + 1))
    throw std::logic_error("rtd::remove_vertex: vertex " + std::to_string(x) + " has degree " +
                           std::to_string(st.size()) + ", a (d+1)-1 flip needs " + std::to_string(T.d + 1));
  const std::int32_t s = st[0];
  const int ix = index_of(T, s, x);
  const RidgeD r{s, ix == 0 ? 1 : 0};  // a ridge containing x
  const FlipShape sh = flip_shape(T, r);
  if (!sh.flippable || sh.nv != 1 || sh.V[0] != x)
    throw std::logic_error("rtd::remove_vertex: no (d+1)-1 flip removes vertex " + std::to_string(x));
  return flip(T, sh);
}

}  // namespace flipflop::ref::rtd

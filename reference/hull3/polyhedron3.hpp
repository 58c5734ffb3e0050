// polyhedron3.hpp — the geometric structure of flip-flop for 3D convex hull
// (thesis §6.1-6.2) and ffHull (§6.4): a closed triangulated surface over input
// indices, every triangle counter-clockwise seen from outside, stored as in
// §6.4.1 — "an array of triangles, each containing the indices of its three
// vertices and the indices of the triangles sharing its three edges".
//
// Local operations (§6.2, §6.4): the 2-2 flip of an edge, the 3-1 flip that
// removes a vertex of degree 3, the 1-3 split that inserts a point into a
// triangle (Algorithm 7 line 9). Slots of removed triangles are reused.
//
// Star-shapedness (Lemma 6.1: the cones C_s(t) of the triangles from the
// kernel point s do not overlap) is checked in O(F) predicates by the test of
// the certifier (reference/certify/certify_hull3.cpp): every triangle faces away from
// s (its cone is a proper cone, s on its inner side), and the central
// projection from s winds exactly once around every vertex. Then the
// projection onto the sphere of directions is a local homeomorphism of a
// closed connected surface, i.e. a covering of the sphere, which is simply
// connected: a homeomorphism, so no two cones overlap.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/hull3/kernel_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref::poly {

constexpr std::uint32_t kNone = ~std::uint32_t{0};

// A directed edge: triangle t, position k; the edge runs from tri[t][k] to
// tri[t][(k+1)%3].
struct DEdge {
  std::uint32_t t = kNone;
  int k = 0;
  bool valid() const { return t != kNone; }
};

struct Polyhedron3 {
  std::size_t n = 0;                            // index universe (vertices are < n)
  std::vector<Triangle> tri;                    // slots; dead ones have alive == 0
  std::vector<std::array<std::uint32_t, 3>> adj;  // adj[t][k]: across edge k of t
  std::vector<std::uint8_t> alive;
  std::vector<std::uint32_t> free_slots;
  std::vector<std::uint32_t> corner;  // per index: one live triangle containing it, or kNone
  std::vector<std::uint32_t> deg;     // per index: degree (0 when not a vertex)

  bool is_vertex(Index v) const { return v < n && deg[v] != 0; }
  std::size_t num_triangles() const { return tri.size() - free_slots.size(); }

  // the vertex tri[e.t][e.k], the head of e, and the third vertex of e's triangle
  Index tail(DEdge e) const { return tri[e.t][e.k]; }
  Index head(DEdge e) const { return tri[e.t][(e.k + 1) % 3]; }
  Index apex(DEdge e) const { return tri[e.t][(e.k + 2) % 3]; }
  // the same edge, directed the other way, in the neighbouring triangle
  // (inline: flip-flop asks for it at every step)
  DEdge twin(DEdge e) const {
    const std::uint32_t o = adj[e.t][e.k];
    const Index a = tail(e), b = head(e);
    for (int k = 0; k < 3; ++k)
      if (tri[o][k] == b && tri[o][(k + 1) % 3] == a) return {o, k};
    no_twin();
  }

 private:
  [[noreturn]] static void no_twin();
};

// Why `tris` is not a closed, coherently oriented 2-manifold of genus 0 over
// indices < n (one line), or "" when it is one. Conditions as in certify::hull3:
// indices, distinct vertices, each directed edge once, each edge with its
// opposite, every vertex link one cycle, connected, V - E + F = 2.
std::string surface_problem(std::size_t n, const std::vector<Triangle>& tris);

// Builds the structure; throws std::invalid_argument with surface_problem()
// when the triangles are not such a surface.
Polyhedron3 build(std::size_t n, const std::vector<Triangle>& tris);

// The live triangles (slot order).
std::vector<Triangle> triangles(const Polyhedron3& P);

// The directed edge u -> w (in the triangle having it), or an invalid one
// when u and w are not adjacent. O(min(deg u, deg w)).
DEdge find_edge(const Polyhedron3& P, Index u, Index w);

// The link of v: its neighbours counter-clockwise seen from outside.
std::vector<Index> link(const Polyhedron3& P, Index v);

// Every undirected edge once, as (u, w) with u < w.
std::vector<std::pair<Index, Index>> edges(const Polyhedron3& P);

// 2-2 flip of edge e = ab with triangles (a, b, c) and (b, a, d): replaced by
// (a, d, c) and (d, b, c). The caller guarantees that c and d are not adjacent
// (flip-flop only flips flippable edges, Lemma 6.3). Returns the directed edge
// d -> c.
DEdge flip22(Polyhedron3& P, DEdge e);

// 3-1 flip removing the degree-3 vertex a with link (b, c, d): its three
// triangles are replaced by (b, c, d). Returns the new triangle.
std::uint32_t flip31(Polyhedron3& P, Index a);

// 1-3 split of triangle t = (a, b, c) by the point p (not a vertex):
// (a, b, p), (b, c, p), (c, a, p), in this order; returns their slots.
std::array<std::uint32_t, 3> split13(Polyhedron3& P, std::uint32_t t, Index p);

// Internal consistency of the structure (adjacency symmetric, corners and
// degrees right, links cycles); "" when consistent. For checked builds.
std::string structure_problem(const Polyhedron3& P);

// ---- geometry with respect to a kernel point ---------------------------------

// p in the interior of the cone C_s(△abc) (§6.1, Figure 6.2): the convex
// hull of the rays sa, sb, sc, whatever the orientation of (a, b, c). Under
// SoS p is never on its boundary. Four predicates.
bool in_cone(const KernelPoint& s, Index a, Index b, Index c, Index p);

// Why P is not star-shaped w.r.t. s (Lemma 6.1, via the covering argument
// above), or "" when it is.
std::string star_problem(const Polyhedron3& P, const KernelPoint& s);

}  // namespace flipflop::ref::poly

// bistellar_flip.hpp — the bistellar flips k-(d+2-k), k = 1..d+1, on the
// d-dimensional triangulation (triangulation_d.hpp), thesis §2.3.
//
// The flip on d+2 points S (thesis §2.3, Radon's theorem [Rad21], Thm 2.3):
// S has a unique affine dependence sum λ_x x = 0, sum λ_x = 0 (under SoS no
// λ_x is 0); U and V are the sets of positive and negative λ. The only two
// triangulations of S are T_U = {S \ {x} : x in U} and T_V; a flip replaces
// one by the other, a k-(d+2-k) flip when |U| = k. A 1-(d+1) flip inserts a
// vertex, a (d+1)-1 flip removes one.
//
// Flipping a ridge F with link {a, b} (C1 = F + a, C2 = F + b): S = S_F. C1 =
// S \ {b} and C2 = S \ {a}, so a and b lie in the same part, call it U: the
// current side. With C1 = (c_0..c_d) positive, the Radon coefficient of c_i
// has the sign of (-1)^d orient_d(C1 with c_i replaced by b) and that of b
// the sign of (-1)^(d+1); hence
//       U = {b} ∪ {c_i : orient_d(C1[c_i := b]) < 0}
// — the vertices of C1 whose opposite facet b sees, plus b (a is one of them).
//
// Flippability (thesis §2.3: "If the underlying space of T_F is convex ... F
// is flippable"; §9.1, [ES92]: "A facet R of F ... is said to be convex in F
// if there exists a hyperplane through R so that F, a, and b lie on the same
// side of the hyperplane; otherwise it is reflex in F. F is flippable if
// every reflex facet in it has exactly three link vertices"). The facet
// R = F \ {x} is reflex in F exactly when x is in U (then conv{x, a, b} meets
// aff R: that is the Radon partition restricted to the 2D quotient by R).
// R has exactly the three link vertices x, a, b iff the simplex S \ {x} =
// R + a + b exists, i.e. iff the neighbour of C1 across the facet opposite x
// contains b. So F is flippable iff every S \ {x}, x in U, is a simplex of T:
// the current side T_U is present — the induced subcomplex is a triangulation
// of conv(S_F), i.e. convex (§2.3). Only interior ridges (S_F real) are
// flippable (§2.3: boundary ridges are unflippable); ridges involving v are
// changed only by placing (rt_incremental.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref::rtd {

// The shape of the flip on an interior ridge.
struct FlipShape {
  bool interior = false;   // S_F has no v
  bool flippable = false;  // every S \ {x}, x in U, is a simplex of T
  int k = 0;               // |U|: a k-(d+2-k) flip (0 when not interior)
  PointTuple S{};          // S_F = points(T, F)
  PointTuple U{}, V{};     // the Radon parts (first nu / nv entries)
  int nu = 0, nv = 0;
  // when flippable: the k current simplices, cur[j] = the slot of S \ {U[j]}
  std::array<std::int32_t, kMaxDim + 2> cur{};
};

// Classifies the flip on ridge r (d+2 orient_d calls at most, plus O(d^2)
// neighbour look-ups).
FlipShape flip_shape(const TriangulationD& T, RidgeD r);

// What a flip did.
struct FlipResult {
  int k = 0;                          // k-(d+2-k) flip (1: insertion)
  std::vector<std::int32_t> created;  // the d+2-k new simplices (slots)
  // The boundary ridges of the new induced subcomplex (Algorithm 14 line 10):
  // the facets of created simplices whose neighbour is not a created simplex,
  // k(d+2-k) of them, each as seen from its created simplex.
  std::vector<RidgeD> boundary;
  Index removed = kNoVertex;          // (d+1)-1 flip: the removed vertex
  Index inserted = kNoVertex;         // 1-(d+1) flip: the inserted vertex
};

// Performs the flip on ridge r. Precondition: flip_shape(T, r).flippable
// (throws std::logic_error otherwise). New tuples are positive; neighbour
// links outside the induced subcomplex are re-attached.
FlipResult flip(TriangulationD& T, RidgeD r);
// The same with a precomputed shape (must be flip_shape(T, r) of the current T).
FlipResult flip(TriangulationD& T, const FlipShape& shape);

// The 1-(d+1) flip: inserts real point p (not a vertex) into the REAL simplex
// s, which must strictly contain it (not checked here: see locate); s is
// freed and the d+1 new simplices are `created`, `boundary` their facets
// opposite p (the link of p).
FlipResult insert_in_simplex(TriangulationD& T, std::int32_t s, Index p);

// The (d+1)-1 flip removing real vertex x of degree d+1 whose star is
// interior (no virtual simplex): finds the ridge and flips it. Throws
// std::logic_error when that flip does not exist.
FlipResult remove_vertex(TriangulationD& T, Index x);

}  // namespace flipflop::ref::rtd

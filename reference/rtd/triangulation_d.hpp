// triangulation_d.hpp — the array-based d-dimensional extended triangulation
// (2 <= d <= 5) shared by RT+1 (rt_incremental.hpp, [ES92]), the bistellar
// flips (bistellar_flip.hpp, thesis §2.3) and the monotonic instant flip
// (thesis §9.2, Algorithm 14).
//
// ============================================================================
// The structure (thesis §2.1, "extended triangulation")
// ============================================================================
// Vertices 0..n-1 are the input points; vertex n is the virtual vertex v.
// A simplex is a tuple of d+1 vertex indices stored in a slot; slot s holds
//     vertex(s, 0..d)    its vertices, and
//     neighbor(s, i)     the simplex across the facet opposite vertex(s, i)
//                        (the facet is the tuple without entry i).
// Real simplices (no v) are positively oriented: orient_d of their tuple is
// > 0 under Simulation of Simplicity (predicates.hpp; one perturbation of
// the d coordinates and the lifted height, the input index is the SoS index).
// They triangulate conv(V) of their vertex set V (the real part is ALWAYS
// convex between operations: RT+1 grows it by placing, see below). Every
// facet f of conv(V) — a facet of exactly one real simplex — carries one
// virtual simplex (v, f): the region outside conv(V) seen through f. The
// whole is a triangulation of the d-sphere: every facet of every simplex is
// shared by exactly two simplices, so no code meets a "boundary" case.
//
// Orientation of virtual simplices (combinatorial, never computed). The model
// of thesis §2.1 / triangulation2.hpp: v is the antipode of an interior
// (kernel) point in the oriented projective space, "a point on ray s->p
// extremely far away from p". Hence replacing v in a virtual tuple by a point
// q strictly inside conv(V) gives a NEGATIVE tuple, and replacing it by a
// point p beyond the facet gives a POSITIVE one (that is the real simplex
// (p, f) placing p creates). Across every facet the two tuples induce
// opposite orientations on the shared facet (an oriented pseudomanifold), for
// virtual and real simplices alike.
//
// ============================================================================
// Ridges, links, S_F (thesis §2.3, §9.2 Eq. 9.1)
// ============================================================================
// A ridge F is the facet of slot s opposite vertex(s, i): RidgeD{s, i}. Its
// link vertices are a = vertex(s, i) (in C1 = s) and b, the vertex of
// C2 = neighbor(s, i) opposite F. S_F is the ordered point set of F plus its
// link: points(T, F) = <f_1, ..., f_d, a, b> where (f_1..f_d, a) is C1 up to
// an even permutation (so it is positive when C1 is real).
//   * interior ridge: S_F has no v (both C1 and C2 real). Only interior
//     ridges are flippable (§2.3: "A ridge on the boundary of T is considered
//     unflippable"); local regularity of a real ridge is the power test
//     power_d(S_F) < 0: b's lifted point strictly ABOVE the hyperplane of the
//     lifted C1 (predicates.hpp: power_d > 0 iff the last point is below).
//     In the thesis' lifted language (§9.2): convex iff power_d(S_F) < 0,
//     reflex iff > 0 (the thesis' Orient^{d+1}(S_F) is -power_d of this
//     order); SoS never gives flat.
//   * a real ridge with link {a, v}: a facet of conv(V); locally regular by
//     definition (§2.2: "A ridge incident to exactly one virtual facet is
//     always locally regular").
//   * a ridge containing v, F = (v, G), with real link a, b: the (d-2)-face G
//     of the hull boundary between the hull facets (G, a) and (G, b); locally
//     regular iff b lies strictly on the inner side of the hyperplane of
//     (G, a) (§2.2: "F1 and s lie on the same side of the hyperplane through
//     F2"), i.e. the hull is convex at G. Decided by a real orient_d.
//
// Slots are reused; gen[s] changes whenever slot s is freed, so a remembered
// ridge (RidgeRef) can be checked for "still in T with the same link"
// (Algorithm 14 line 8) in O(1).
//
// ============================================================================
// Validity (checked builds and from_simplices)
// ============================================================================
// validity_problem() checks: neighbour links are symmetric and share exactly
// the d facet vertices; real tuples positive (SoS); across every facet the
// two tuples induce opposite orientations; vertsimplex[] points to live
// simplices containing the vertex; the virtual simplices are exactly the
// facets of the real part that have no real neighbour, and the hull is
// locally convex at every ridge containing v. (The global statement — the
// real simplices tile conv(V) — is certified by certify_rtd.hpp's tiling
// argument; from_simplices runs it on its input.)
//
// Lifetime: a TriangulationD keeps a pointer to its PointSet, which must
// outlive it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref::rtd {

inline constexpr int kMaxDim = 9;        // d = 2..9 (power_d: d + 2 <= pred::kMaxLambdaK rows)
inline constexpr std::int32_t kNone = -1;
inline constexpr Index kNoVertex = static_cast<Index>(-1);

// A simplex tuple (first d+1 entries used) and an S_F tuple (first d+2 used).
using Tuple = std::array<Index, kMaxDim + 1>;
using PointTuple = std::array<Index, kMaxDim + 2>;

struct TriangulationD {
  const PointSet* ps = nullptr;
  int d = 0;                             // dimension, 2..kMaxDim
  Index n = 0;                           // input points; vertex n is v
  std::vector<Index> verts;              // (d+1) per slot
  std::vector<std::int32_t> nbrs;        // (d+1) per slot: across the facet opposite verts[.]
  std::vector<std::uint32_t> gen;        // per slot: changes when the slot is freed
  std::vector<std::uint8_t> alive;       // per slot: in use
  std::vector<std::int32_t> free_slots;  // dead slots for reuse
  std::vector<std::int32_t> vsimplex;    // n+1: a live simplex containing the vertex, kNone if not a vertex
  std::size_t live = 0;                  // live simplices (real and virtual)
  bool pulled = false;                   // power() under pred::power_d_pulled (strict_rtd.hpp)
  bool furthest = false;                 // power() negated: the furthest-site triangulation (rt_incremental.hpp)

  int width() const { return d + 1; }
  Index virtual_vertex() const { return n; }
  bool is_virtual(Index x) const { return x == n; }
  bool is_vertex(Index x) const { return vsimplex[x] != kNone; }
  std::size_t slots() const { return alive.size(); }
  Index vertex(std::int32_t s, int i) const {
    return verts[static_cast<std::size_t>(s) * static_cast<std::size_t>(d + 1) + static_cast<std::size_t>(i)];
  }
  std::int32_t neighbor(std::int32_t s, int i) const {
    return nbrs[static_cast<std::size_t>(s) * static_cast<std::size_t>(d + 1) + static_cast<std::size_t>(i)];
  }
  const Index* tuple(std::int32_t s) const {
    return verts.data() + static_cast<std::size_t>(s) * static_cast<std::size_t>(d + 1);
  }
};

// The facet of slot s opposite its vertex i.
struct RidgeD {
  std::int32_t s = kNone;
  int i = 0;
  bool valid() const { return s != kNone; }
};

// A ridge remembered across flips: valid again (recall) only if slot s still
// holds the same simplex (same generation) and the link vertex across is
// still b — "F in T(S) with the same link vertices" (Algorithm 14 line 8).
struct RidgeRef {
  std::int32_t s = kNone;
  int i = 0;
  std::uint32_t gen = 0;
  Index a = kNoVertex, b = kNoVertex;
};

// ---- combinatorics ----------------------------------------------------------
// Position of x in slot s, or -1.
int index_of(const TriangulationD& T, std::int32_t s, Index x);
// Does slot s contain v?
bool is_virtual_simplex(const TriangulationD& T, std::int32_t s);
// Position in neighbor(s, i) of the facet shared with s (its opposite vertex).
int mirror_index(const TriangulationD& T, std::int32_t s, int i);
// The same ridge seen from the other simplex.
RidgeD twin(const TriangulationD& T, RidgeD r);
// Link vertices: a in C1 = r.s, b in C2 = neighbor(r.s, r.i).
Index link_a(const TriangulationD& T, RidgeD r);
Index link_b(const TriangulationD& T, RidgeD r);
// S_F = <f_1..f_d, a, b> with (f_1..f_d, a) an even permutation of C1's tuple.
PointTuple points(const TriangulationD& T, RidgeD r);
// Is S_F free of v (both simplices real)? Only such ridges are flippable.
bool interior(const TriangulationD& T, RidgeD r);
// Every ridge once (from the slot of smaller index), real and virtual.
std::vector<RidgeD> ridges(const TriangulationD& T);
// Live simplices containing vertex x (its star), by a walk over the facets
// containing x from vsimplex[x]. Empty when x is not a vertex.
std::vector<std::int32_t> star(const TriangulationD& T, Index x);
// The live slot whose vertex set is {vs[0..d]} (any order), or kNone.
std::int32_t find_simplex(const TriangulationD& T, const Index* vs);
// The ridge with vertex set {ridge[0..d-1]} and link {a, b}, seen from the
// simplex containing a (RidgeD{s, index of a}), or an invalid RidgeD.
RidgeD find_ridge(const TriangulationD& T, const Index* ridge, Index a, Index b);
RidgeRef remember(const TriangulationD& T, RidgeD r);
RidgeD recall(const TriangulationD& T, const RidgeRef& ref);
// Live real simplices, canonical (canonical_d.hpp: positively oriented,
// smallest index first, sorted) — the output format.
std::vector<std::vector<Index>> real_simplices(const TriangulationD& T);
// Vertices (real), ascending.
std::vector<Index> vertices(const TriangulationD& T);

// ---- predicates (SoS; the rules of the header comment) ----------------------
pred::WPt wpt(const TriangulationD& T, Index x);  // x real
pred::Pt pt(const TriangulationD& T, Index x);    // x real
// orient_d of d+1 REAL vertices in the given order.
int orient(const TriangulationD& T, const Index* tuple);
// power_d of d+2 REAL vertices: > 0 iff the last lifted point is strictly
// below the hyperplane of the first d+1 lifted (those positively oriented);
// pred::power_d_pulled when T.pulled.
int power(const TriangulationD& T, const Index* tuple);
// Locally regular (§2.2, rules above)?
bool locally_regular(const TriangulationD& T, RidgeD r);
// Is real point p (not a vertex of s) strictly inside real simplex s?
bool contains(const TriangulationD& T, std::int32_t s, Index p);

// ---- construction / output ----------------------------------------------------
// One real simplex on the d+1 given input points (reordered to be positive
// under SoS) and its d+1 virtual simplices. ps.dim must be 2..kMaxDim.
TriangulationD make_simplex(const PointSet& ps, const Index* pts);
// The extended triangulation of a triangulation of the convex hull of its
// vertices (simplices of input indices, any orientation: each is reordered to
// be positive under SoS). Throws std::invalid_argument naming the problem
// unless the simplices tile the convex hull of their vertices (the structural
// conditions of certify_rtd.hpp: no regularity required).
TriangulationD from_simplices(const PointSet& ps, const std::vector<std::vector<Index>>& simplices);

// Point location by a visibility walk from slot `start` (Edelsbrunner's
// acyclicity theorem for regular triangulations makes it terminate; in a
// non-regular triangulation, where it may cycle, an exhaustive scan takes
// over after 2·live+64 steps; every decision is an exact SoS orient_d). Returns a real simplex strictly containing
// p, or — when p lies outside conv(V) — a virtual simplex (v, f) whose facet
// f sees p (p strictly beyond f). `steps` (optional) counts visited simplices.
// p must not be a vertex.
std::int32_t locate(const TriangulationD& T, Index p, std::int32_t start, std::size_t* steps = nullptr);

// Empty when valid (header comment), otherwise the first problem.
std::string validity_problem(const TriangulationD& T);

// ---- slot management (used by bistellar_flip.cpp) -----------------------------
std::int32_t new_slot(TriangulationD& T);
void free_slot(TriangulationD& T, std::int32_t s);
void set_vertex(TriangulationD& T, std::int32_t s, int i, Index x);
void set_neighbor(TriangulationD& T, std::int32_t s, int i, std::int32_t t);

}  // namespace flipflop::ref::rtd

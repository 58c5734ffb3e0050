// triangulation2.hpp — the array-based 2D extended triangulation shared by
// Lawson's flip algorithm (§3.3.1), flip-flop (§5.1, Algorithm 5) and ffRT
// (§5.3) of the reference.
//
// ============================================================================
// The structure (thesis §2.1, "extended triangulation")
// ============================================================================
// Vertices 0..n-1 are the input points; vertex n is the virtual vertex v.
// Triangles are vertex triples, counter-clockwise, in an array; tn[t][i] is
// the triangle across the edge opposite tv[t][i], i.e. across the directed
// edge tv[t][i+1] -> tv[t][i+2] (indices mod 3). The real triangles (no v)
// cover a polygon P that is star-shaped w.r.t. the kernel point s; for every
// edge p -> q of P (real triangle on its left) there is the virtual triangle
// (q, p, v): the cone from s through p and q minus the triangle s p q. Every
// edge has two triangles; the whole is a triangulation of the sphere
// (V - E + F = 2), so the reference never meets a "boundary" case.
//
// ============================================================================
// Predicates with the virtual vertex (thesis §2.2)
// ============================================================================
// v has no coordinates and never enters a determinant. The model that makes
// every rule below one consistent geometry is the oriented projective plane
// (Stolfi): a real point p is (p, 1) on the front sheet and v is the kernel
// point on the back sheet, (-s, -1), i.e. s's antipode when the plane is
// wrapped onto a sphere around s. Then
//
//     orient(p, q, v) := det[p 1; q 1; -s -1] = -orient(p, q, s) = orient(q, p, s),
//
// which says: v lies on the far side of every edge p -> q of P as seen from s
// ("v lies on ray s->p extremely far away from p", §2.1). With this one rule
// all orientation questions of the flips (is a triangle positive, is a
// quadrilateral convex, does a point lie in a triangle) are answered for real
// and virtual simplices alike, from orient2d of real points and orient2d of
// two real points and s. Local regularity (§2.2) is the thesis' definition:
//   - an edge with exactly one virtual triangle is locally regular;
//   - an edge p v with two virtual triangles (p, v, c) and (v, p, d) is locally
//     regular iff c and s lie on the same side of the line p d (F1 = pc,
//     F2 = pd; such an edge is locally non-regular iff P is reflex at p);
//   - an edge with two real triangles (a, b, c), (b, a, d) is locally
//     non-regular iff power2d(a, b, c, d) > 0 (d^+ below the plane of
//     a^+ b^+ c^+; with zero weights: d inside the circumcircle).
//
// Perturbation: one Simulation of Simplicity with δ = 3 (x, y, lifted
// height), input index = SoS index (predicates.hpp). The kernel point s is
// the exact dyadic centroid (p0 + p1 + 2 p2) / 4 of a triangle of input
// points (a pred::RationalPoint, never rounded — thesis §6.4.2) with SoS
// index n, the first index after the inputs. (v is vertex n and s has SoS
// index n; they never meet: v is not a point.)
//
// ============================================================================
// Validity (used by input validation and by FF_CHECK in the checked build)
// ============================================================================
// validity_problem() certifies the local-to-global conditions: the triangles
// form a closed oriented surface with V - E + F = 2 in which the triangles
// around every vertex form one cycle (a sphere); every triangle is positive;
// and the link of every vertex winds exactly once around it. Under the model
// above the triangulation is then a degree-one covering of the projective
// sphere by positive triangles, i.e. an embedding: the real triangles tile P
// and P is star-shaped w.r.t. s (the link of v is P, winding once around s).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "predicates/rational_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// Counters reported by the 2D regular-triangulation algorithms (--stats).
struct Rt2Stats {
  std::size_t flips_2_2 = 0;           // 2-2 flips (V- and D-criterion)
  std::size_t flips_3_1 = 0;           // 3-1 flips: vertices removed
  std::size_t flips_1_3 = 0;           // 1-3 flips: points inserted (constructing stage)
  std::size_t labelled_redundant = 0;  // Algorithm 5 line 18
  std::size_t discarded_early = 0;     // points proved redundant by their triangle (§5.3)
  std::size_t rounds = 0;              // insertion rounds of the constructing stage (§5.3)
  std::size_t flops = 0;               // flips decided by the D-criterion ("flops", §5 intro);
                                       // included in flips_2_2 / flips_3_1
  std::size_t candidates = 0;          // edges popped from Q (Algorithm 5 line 4)
  std::size_t phases = 0;              // FlipFlopVariant::v_first: V / label / D passes
  std::size_t retried = 0;             // cpu::rt2 stage 2b: points deferred by their territory or
                                       // losing a batch's labels, tried again
};

// How the V- and D-criterion are combined (§5.1).
enum class FlipFlopVariant {
  combined,  // Algorithm 5: the D-criterion has priority
  v_first    // flip by the V-criterion until stuck, then label and remove by the
             // D-criterion; repeat (§5.1, paragraph after Algorithm 5)
};

namespace tri {

inline constexpr std::int32_t kNone = -1;

struct Triangulation2 {
  const PointSet* ps = nullptr;
  Index n = 0;                                   // input points; vertex n is v
  pred::RationalPoint kernel;                    // s, SoS index n
  std::vector<Triangle> tv;                      // vertex triples, counter-clockwise
  std::vector<std::array<std::int32_t, 3>> tn;  // tn[t][i]: across the edge opposite tv[t][i]
  std::vector<std::uint8_t> alive;               // slot in use
  std::vector<std::int32_t> free_slots;          // dead slots for reuse
  std::vector<std::int32_t> vtri;                // n+1: a triangle at each vertex, kNone if none
  std::vector<std::uint32_t> deg;                // n+1: vertex degrees
  std::vector<std::uint8_t> removed;             // n+1: removed by a 3-1 flip (never to reappear)

  Index virtual_vertex() const { return n; }
  bool is_virtual(Index x) const { return x == n; }
  bool is_vertex(Index x) const { return vtri[x] != kNone; }
};

// The directed edge tv[t][i+1] -> tv[t][i+2] of triangle t (opposite tv[t][i]).
struct Edge {
  std::int32_t t = kNone;
  int i = 0;
  bool valid() const { return t != kNone; }
};

// The four vertices of an edge and its link: e = a -> b, triangles (a, b, c)
// and (b, a, d) (§2.3: S_F, the induced-subcomplex of e).
struct Quad {
  Index a, b, c, d;
};

// ---- combinatorics ----------------------------------------------------------
Index org(const Triangulation2& T, Edge e);
Index dst(const Triangulation2& T, Edge e);
Index apex(const Triangulation2& T, Edge e);
Edge twin(const Triangulation2& T, Edge e);
Quad quad(const Triangulation2& T, Edge e);
// Some half-edge of the edge {a, b}, or an invalid Edge when it is not an edge.
Edge find_edge(const Triangulation2& T, Index a, Index b);
// The link of vertex x in counter-clockwise order (triangles (x, q_i, q_{i+1})).
std::vector<Index> link(const Triangulation2& T, Index x);
// Every edge once, as (min, max) vertex pairs, in triangle-array order.
std::vector<std::pair<Index, Index>> edges(const Triangulation2& T);

// ---- predicates (the rules of the header comment) ------------------------------
// orient2d under SoS of three vertices, at most one of them v.
int orient(const Triangulation2& T, Index a, Index b, Index c);
// Is the real point p (not a vertex of t) inside triangle t? (three orients)
bool contains(const Triangulation2& T, std::int32_t t, Index p);
// power2d(a, b, c, d) under SoS: > 0 iff d^+ lies below the plane of a^+ b^+ c^+
// ((a, b, c) counter-clockwise). Real vertices only.
int power(const Triangulation2& T, Index a, Index b, Index c, Index d);
// §2.2: is the edge locally regular?
bool locally_regular(const Triangulation2& T, Edge e);

// §2.3 / Algorithm 5 lines 6, 11, 16: the shape of an edge's induced subcomplex.
enum class Shape {
  three_one,         // `inner` has degree 3 and lies in the triangle of the other three
  two_two,           // the quadrilateral a d b c is convex: a 2-2 flip exists
  two_two_blocked    // unflippable 2-2 edge; `inner` (a or b) lies in the triangle of the others
};
struct EdgeShape {
  Shape shape;
  Index inner;  // three_one, two_two_blocked: the vertex inside the other three
};
EdgeShape classify(const Triangulation2& T, Edge e);

// ---- flips (§2.3) ---------------------------------------------------------------
// 2-2 flip of edge e = a -> b (triangles (a,b,c), (b,a,d) become (c,a,d),
// (d,b,c)); returns the new edge d -> c. Precondition: classify(e) == two_two.
Edge flip22(Triangulation2& T, Edge e);
// 3-1 flip removing the degree-3 vertex x; returns the new triangle.
std::int32_t flip31(Triangulation2& T, Index x);
// 1-3 flip inserting point p into triangle t = (a, b, c): t becomes (a, b, p)
// and the new triangles (b, c, p), (c, a, p) are returned as {t, t1, t2}.
std::array<std::int32_t, 3> flip13(Triangulation2& T, std::int32_t t, Index p);

// ---- construction ------------------------------------------------------------
// The extended triangulation of one counter-clockwise input triangle (a, b, c)
// (exactly non-degenerate) and v: one real and three virtual triangles; the
// kernel point is (a + b + 2c) / 4.
Triangulation2 make_initial(const PointSet& ps, Index a, Index b, Index c);
// The extended triangulation of a user's triangulation (real triangles,
// counter-clockwise): virtual triangles are added along its boundary and the
// kernel point is (a + b + 2c) / 4 for the first triangle (a, b, c) of the list
// with non-zero exact area. Throws std::invalid_argument naming the problem
// unless the triangles form a valid triangulation of a disk whose union is
// star-shaped w.r.t. that kernel point — e.g. any triangulation of a convex
// polygon, such as conv(S).
Triangulation2 from_triangles(const PointSet& ps, const std::vector<Triangle>& tris);

// ---- output / checks ---------------------------------------------------------
// The real triangles in canonical form (DESIGN.md: rotated to the smallest
// index, sorted).
std::vector<Triangle> real_triangles(const Triangulation2& T);
// All triangles (virtual ones with vertex n) in canonical form: a key of the
// whole state for the exhaustive order search.
std::vector<Triangle> all_triangles(const Triangulation2& T);
// Empty when valid (see the header comment), otherwise the first problem.
std::string validity_problem(const Triangulation2& T);

}  // namespace tri
}  // namespace flipflop::ref

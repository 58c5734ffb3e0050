// star_splaying.hpp — Shewchuk's star splaying for the 3D convex hull
// (thesis §3.3.2, Figure 3.4; [She05]); the sequential workflow of §3.2 (a
// container of candidate edges); the "hull approximation" and "hull
// completion" stages of gHull (ch. 7, Stages 3 and 5, Algorithm 9 run one
// candidate at a time).
//
// Geometric structure (§3.3.2). Every point v has a *star*: either a convex
// star — a cyclic link u_0 .. u_{k-1} such that the triangles (v, u_i, u_i+1)
// are counter-clockwise seen from outside and every link vertex lies strictly
// on the inner side of every triangle it is not a vertex of, i.e. the cone
// v + R+(link - v) is a pointed convex cone — or a *dead* star: v was found
// not extreme, and its death certificate is four points whose tetrahedron
// holds v strictly inside.
//
// Local operation: splaying = inserting a point p into the convex star of v
// (beneath-beyond, Figure 3.4): p beneath every triangle (Case 1) -> nothing
// changes; p beyond some but not all (Case 2) -> the beyond triangles, which
// form one run, are replaced by two triangles incident to p and the link
// vertices strictly inside the run are removed; p beyond all (Case 3) -> the
// star dies, with the certificate {p, u_0, u_i, u_i+1} where u_0, u_i, u_i+1
// is the cone of the fan from u_0 that holds the direction v - p.
//
// Local check and criterion (inconsistency enforcement). A link vertex u of
// the star of v (a candidate edge vu) is consistent when u's star is alive,
// holds v, and both stars agree on the two triangles at vu. Otherwise:
//   * u dead: insert u's death certificate into the star of v;
//   * v not in u's star: insert v into it; if that fails (v strictly inside
//     u's cone), insert the three link vertices of u whose fan cone holds v
//     into the star of v instead;
//   * the stars disagree at vu: insert the two link neighbours of u in v's
//     star into u's star and those of v in u's star into v's star.
// Each case makes at least one insertion succeed (star_splaying.cpp proves
// it where `demanded` builds the list), cones only grow, so the algorithm
// terminates; at the end all alive stars are consistent.
//
// Why the result is the hull (Shewchuk's precondition). Consistent convex
// stars form closed locally convex surfaces, i.e. boundaries of convex
// polytopes, possibly several. Let ≺ be the lexicographic order of the
// perturbed points: under the Simulation of Simplicity the first
// coordinates of distinct points already differ, so ≺ is the order of
// compare_sos on x (predicates.hpp). If the initial star of every point v but
// the ≺-least one *encloses* a point u ≺ v (u lies in v's closed cone), then,
// since cones only grow, every final alive star does too; but the ≺-least
// vertex w of a final polytope K has every point of its cone ≻ w (the cone is
// w plus positive combinations of the ≺-positive vectors K - w). So every
// polytope's ≺-least vertex is the ≺-least input point: there is one
// polytope. Its vertices include every extreme point (extreme points never
// die: a death certificate proves the point interior), so it is the convex
// hull — the canonical SoS hull, since every decision is an SoS predicate.
// star_splaying() checks this precondition on its input (and rejects stars
// that violate it): a link vertex ≺ the apex, or else a point ≺ the apex
// strictly inside the cone (a scan of the points, only for stars without a
// preceding link vertex). Validating a star of k link vertices costs O(k²)
// predicates (every link vertex against every triangle).
//
// Every geometric decision is orient3d / compare_sos under SoS
// (predicates.hpp), exact on every input, degenerate included.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "reference/hull3/hull3_stats.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// The star of one point, as star_splaying takes it and as splay::stars
// returns it.
struct Star {
  Index apex = 0;
  // Alive: the cyclic link, counter-clockwise seen from outside: the star's
  // triangles are (apex, link[i], link[(i+1) % k]).
  std::vector<Index> link;
  // Dead: `link` is empty and the apex lies strictly inside the tetrahedron
  // of `certificate` (under SoS): the apex is not extreme.
  bool dead = false;
  std::array<Index, 4> certificate{};
};

// Star splaying of user stars: `initial` holds exactly one star per point of
// ps (any order), each a convex star or a dead star with a valid certificate,
// satisfying the lexicographic precondition above. Returns the canonical SoS
// hull (canonical.hpp order), the same as brute::hull3. Throws
// std::invalid_argument (one line naming the first problem) for ps.dim != 3,
// lower-dimensional input (dimension_problem), or a star that is missing,
// repeated, out of range, not convex, clockwise, with a repeated link vertex,
// with an invalid certificate or violating the precondition. `stats`, when
// given, is reset and receives splay_insertions (successful insertions, Case
// 2), splay_removals (link vertices removed by them) and dead_stars (dead
// stars at the end, those given dead included).
std::vector<Triangle> star_splaying(const PointSet& ps, std::vector<Star> initial, Hull3Stats* stats = nullptr);

// Does `cert` prove `v` non-extreme: is v strictly inside the tetrahedron of
// the four (distinct, different from v) points, under SoS?
bool is_death_certificate(const PointSet& ps, Index v, const std::array<Index, 4>& cert);

// a ≺ b: the lexicographic order of the perturbed points (compare_sos on x).
bool lex_precedes(const PointSet& ps, Index a, Index b);

// ---- The algorithm's pieces, for the pipeline (initial_stars.cpp) and for
// tests that drive the free execution order themselves ------------------------
namespace splay {

enum class Status : std::uint8_t { none, alive, dead };  // none: takes no part

struct State {
  const PointSet* ps = nullptr;
  std::vector<Status> status;                 // per point of ps
  std::vector<std::vector<Index>> link;       // alive stars' links
  std::vector<std::array<Index, 4>> cert;     // dead stars' certificates
};

// An insertion <s, p>: point p into the star of s (§3.3.2, "virtual
// insertion" of the parallel workflow).
struct Insertion {
  Index star;
  Index point;
};

enum class Outcome { unchanged, splayed, died };

// A directed candidate edge (v, u): u is a link vertex of v's star.
using Edge = std::pair<Index, Index>;

// State with the given stars (points without a star take no part). With
// `validate`, every star is checked as star_splaying documents (the
// precondition relative to the participating points) and
// std::invalid_argument names the first problem.
State make_state(const PointSet& ps, const std::vector<Star>& stars, bool validate);

// Splaying (Figure 3.4): insert p into the star of s. Returns unchanged when
// s is not alive, p == s, p is already a link vertex, or p is beneath every
// triangle (Case 1). `touched` (optional) receives the candidate edges whose
// consistency may have changed.
Outcome insert(State& st, Index s, Index p, Hull3Stats* stats = nullptr, std::vector<Edge>* touched = nullptr);

// The local check and criterion on candidate edge (v, u): the insertions
// inconsistency enforcement demands there; empty iff (v, u) is consistent
// or no longer a candidate (v not alive, u not in v's link).
std::vector<Insertion> demanded(const State& st, Index v, Index u);

// All current candidate edges (v, u), v alive, u in v's link.
std::vector<Edge> candidates(const State& st);

// The sequential workflow: every candidate edge is flagged; a flagged edge is
// taken from the container and its demanded insertions are applied until it
// is consistent (flagging the edges they touch) — until no edge is flagged.
// `choose` (optional) picks which flagged edge to take next, by position in
// the list it is given; without it the container is a FIFO queue.
using Chooser = std::function<std::size_t(const std::vector<Edge>& flagged)>;
void run(State& st, Hull3Stats* stats = nullptr, const Chooser& choose = nullptr);

// True when every alive star is consistent with its neighbours (no candidate
// edge demands an insertion).
bool consistent(const State& st);

// The triangles of the alive stars, canonical (each once; st consistent).
std::vector<Triangle> triangles(const State& st);

// The stars of the participating points.
std::vector<Star> stars(const State& st);

}  // namespace splay
}  // namespace flipflop::ref

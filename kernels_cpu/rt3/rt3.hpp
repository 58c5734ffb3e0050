// rt3.hpp — the multithreaded 3D regular / Delaunay triangulation (cpu
// backend of `flipflop rt3|dt3` and of `flipflop rtd --dim 3`), on oneTBB.
//
// Stages (StageTimes names in brackets):
//   1. [sort]    the per-input static filter from a parallel scan
//                (parallel.hpp); the points in a biased randomized insertion
//                order (BRIO, Amenta–Choi–Rote): rounds of geometrically
//                growing size taken by a hash of the index, each round along
//                a 3D Hilbert curve — keys computed in parallel, one parallel
//                radix sort; the points copied in that order into one flat
//                array (x, y, z, w, index) for locality;
//   2. [insert]  incremental insertion on the extended triangulation of
//                thesis §2.1 (the virtual vertex v closes the hull into a
//                triangulated 3-sphere, as reference/rtd): each point is
//                located by a remembering visibility walk from the last
//                point's tetrahedron; a point in a real tetrahedron whose
//                lifted point lies above that tetrahedron's lifted hyperplane
//                is redundant and never inserted (ffRT's early discard,
//                §5.3); otherwise the tetrahedra whose lifted hyperplane
//                passes strictly above its lifted point — and, outside the
//                hull, the virtual tetrahedra whose hull facet it sees — are
//                replaced by the cone from it over their boundary (rt3.cpp
//                explains why this is exactly the result of Edelsbrunner–
//                Shah's 1-4 flip followed by their 2-3 / 3-2 / 4-1 flips,
//                the reference's RT+1);
//   2b.[insert]  (Insertion::parallel; automatic with more than one thread)
//                the first parallel_from points as in 2, then each BRIO round
//                cut into pieces along its Hilbert curve, the pieces inserted
//                as in 2 by concurrent tasks. The points are cut into lock
//                cells (runs of up to 512 points along the Hilbert curve); a
//                task reads a tetrahedron only while it holds the cells of
//                all its real corners (one compare-exchange per cell, a few
//                per insertion) and gives them up when the insertion is done;
//                an insertion that meets a cell another task holds gives up
//                before writing anything and is deferred, and the deferred
//                points are inserted as in 2 after the round (§3.3.1's
//                conflict resolution on the induced subcomplex, with claims
//                in place of priorities; rt3.cpp argues the exclusion);
//   3. [output]  the real tetrahedra in canonical form (DESIGN.md), mapped to
//                input indices in parallel, sorted in parallel; the redundant
//                points (input indices, ascending);
//   4. [witness] (when asked for) the certificate of Rt3Witness: for each
//                vertex an incident real tetrahedron, for each point that is
//                not a vertex the real tetrahedron containing it, by parallel
//                visibility walks.
// Parallelism: stages 1, 2b, 3 and 4 run on all threads. Neither the
// tetrahedra nor the redundant points depend on the thread count or the
// insertion order (the answer is unique); the slots of the witness do.
// Tetrahedra are flat arrays: four vertex slots and four neighbour links per
// slot (link 4t + i: the facet opposite corner i, stored as 4u + j where j
// is the corner of u opposite the same facet), freed slots reused; the
// virtual vertex is position n. Predicates are predicates/fast.hpp's
// (per-input static filter inlined, then the staged exact path with
// Simulation of Simplicity).
//
// Why the answer is the reference's byte for byte: under the Simulation of
// Simplicity (one perturbation with δ = 4 — x, y, z and the lifted height —
// index = SoS index, as in reference/rtd) the perturbed weighted points are
// in general position and their regular triangulation is unique
// (DESIGN.md); every decision here is an exact SoS predicate (orient3d,
// power3d) and every insertion returns the regular triangulation of the
// points inserted so far, so the final one is RT(S ⊕ W) under SoS, which is
// ref::rtd_incremental's answer for d = 3.
//
// Input that does not span R^3 is rejected with std::invalid_argument
// ("rt3 (cpu): <problem>", reference/dimension.hpp's exact test).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

struct Rt3Options {
  int threads = 0;  // worker threads; 0: the runtime's default
  // Tuning; the result does not depend on it (tests vary it):
  std::size_t brio_min = 256;  // BRIO rounds stop below this many points (>= 1)
  // Stage 2: sequential: one point after the other; parallel: the first
  // parallel_from points one by one, then each BRIO round cut into pieces
  // along its Hilbert curve (at least min_piece points each, at most 8 per
  // thread), the pieces inserted by concurrent tasks that claim the lock
  // cells of every tetrahedron they read (an insertion that meets another
  // task's claim is deferred and done one by one after the round);
  // automatic: parallel when more than one thread runs. The tetrahedra do
  // not depend on these settings; the witness's slots do.
  enum class Insertion { automatic, sequential, parallel };
  Insertion insertion = Insertion::automatic;
  std::size_t parallel_from = 4096;
  std::size_t min_piece = 256;
  // Test hook: in parallel rounds every k-th claim a task tries fails as if
  // another task held the tetrahedron (0: never), so that the give-up and
  // deferral paths run deterministically.
  std::size_t fail_claims_every = 0;
  // when set, filled with the seconds of each stage: sort, insert, output, witness
  StageTimes* times = nullptr;
};

// Counters of one run (for --stats and the tests).
struct Rt3Stats {
  std::uint64_t inserted = 0;      // points made vertices (the first four included)
  std::uint64_t placed = 0;        // of those: located outside the current hull
  std::uint64_t discarded = 0;     // points found redundant when located (never vertices)
  std::uint64_t removed = 0;       // vertices made redundant by a later insertion (the 4-1 flips)
  std::uint64_t cavity_tets = 0;   // tetrahedra (real and virtual) replaced, over all insertions
  std::uint64_t created_tets = 0;  // tetrahedra created, over all insertions
  std::uint64_t walk_steps = 0;    // tetrahedra visited by point location
  std::uint64_t slots = 0;         // tetrahedron slots allocated at the end (peak)
  std::uint64_t parallel_rounds = 0;  // BRIO rounds inserted in parallel pieces
  std::uint64_t deferred = 0;      // of their insertions: met another piece's claim, done one by one after
};

// A point in the kernel's insertion order: coordinates, weight, input index
// (= SoS index).
struct Rt3Point {
  double xyz[3];
  double w;
  Index id;
  // the kernel's lock cell of the point (parallel rounds; rt3.cpp), kept in
  // the record its predicates read anyway; not part of the certificate
  std::uint32_t cell = 0;
};

// A tetrahedron of input indices (canonical in rt3()'s output: positively
// oriented in the volume convention, smallest index first — canonical_d.hpp).
using Tet = std::array<Index, 4>;

// What the kernel hands its certifier (cpu::certify_rt3, certify_rt3.hpp):
// its final extended triangulation in its own (spatial) order, and for every
// input point that is not a vertex the tetrahedron that proves it redundant.
// Positions are indices into pts; the virtual vertex of the extended
// triangulation (thesis §2.1) is position pts.size().
struct Rt3Witness {
  // the input points in insertion (BRIO) order: position k is input point
  // pts[k].id, a permutation of the input
  std::vector<Rt3Point> pts;
  // per tetrahedron slot t, corners tv[4t..4t+3] (positions). A real slot
  // (no virtual corner) is positively oriented in the predicates' convention:
  // pred::orient3d(corners in this order) > 0 under SoS (Orientation::orient_d
  // of canonical_d.hpp). A slot with the virtual vertex as a corner is
  // virtual: replacing that corner by a point strictly beyond the slot's hull
  // facet gives a positive tuple (reference/rtd/triangulation_d.hpp's rule).
  // An unused slot holds four kNoSlot.
  std::vector<std::uint32_t> tv;
  // tn[4t + i] = 4u + j: slot u is the neighbour across the facet of t
  // opposite corner i, and j is u's corner opposite that same facet.
  std::vector<std::uint32_t> tn;
  // per position k: for a vertex, a real tetrahedron with k as a corner; for
  // any other point, the real tetrahedron that contains it under SoS and
  // under whose lifted hyperplane its lifted point is not (it is redundant
  // there)
  std::vector<std::uint32_t> at;
  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
};

struct Rt3Result {
  std::vector<Tet> tets;         // canonical (volume-positive, smallest index first, sorted)
  std::vector<Index> redundant;  // input indices that are not vertices, ascending
};

// RT(S ⊕ W) of the weighted points ps (ps.dim == 3; weights 0 when
// unweighted: the Delaunay triangulation) under flipflop's SoS — identical
// to ref::rtd_incremental(ps). stats, if given, is reset and filled. witness,
// if given, receives the kernel's final triangulation (stage [witness]).
// Throws std::invalid_argument for input that is not 3D, not finite, or does
// not span R^3.
Rt3Result rt3(const PointSet& ps, const Rt3Options& opt = {}, Rt3Stats* stats = nullptr,
              Rt3Witness* witness = nullptr);

// scipy's `neighbors` of rt3's canonical output `tets`, read off the witness
// the same call filled (its links) instead of matching facets: nb[4k + j] is
// the index in tets of the tetrahedron across the facet opposite vertex
// tets[k][j], -1 on the hull. Each real slot's canonical tuple is looked up
// in tets (OutputIndex, witnessed_output.hpp), then each of its links is
// read; parallel, O(m) apart from the short binary searches. Call it on a
// certified pair (certify_rt3 with this witness): a witnessed tetrahedron
// missing from tets, one missing from the witness or witnessed twice throws
// std::logic_error.
std::vector<std::int64_t> rt3_neighbors(const Rt3Witness& witness, const std::vector<Tet>& tets, int threads = 0);

}  // namespace flipflop::cpu

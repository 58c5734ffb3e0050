// rt2.hpp — the multithreaded 2D regular / Delaunay triangulation (cpu
// backend of `flipflop rt2|dt2`), on oneTBB.
//
// Stages (StageTimes names in brackets):
//   1. [sort]     the per-input static filter from a parallel scan; the points
//                 in a biased randomized insertion order (BRIO, Amenta–Choi–
//                 Rote): rounds of geometrically growing size taken by a hash
//                 of the index, each round along a Hilbert curve — keys
//                 computed in parallel, one parallel radix sort; the points copied
//                 in that order into one flat array (x, y, w, index) for
//                 locality;
//   2. [insert]   (Insertion::sequential, the default) incremental
//                 flipping (Edelsbrunner–Shah 1996; thesis §2.3's
//                 flips on the extended triangulation of §2.1): each point is
//                 located by a remembering visibility walk from the previous
//                 point's triangle; a point in a real triangle whose lifted
//                 point lies above that triangle's lifted plane is redundant
//                 and never inserted (ffRT's early discard, §5.3); otherwise a
//                 1-3 flip inserts it — into a virtual triangle when it lies
//                 outside the current hull, whose visible edges are then
//                 absorbed by 2-2 flips of virtual edges (§2.2's rule for two
//                 virtual triangles) — and the edges of its link are made
//                 locally regular by 2-2 flips and 3-1 flips (a vertex
//                 becoming redundant is removed), Algorithm 5's V- and
//                 D-criterion restricted to the link of the new point;
//   2b.[insert]   (Insertion::territories or batches) the first points as
//                 in 2, then each BRIO round in parallel (ffRT's insertion
//                 rounds, §5.3), each point by a Bowyer–Watson step: its
//                 cavity (the triangles whose lifted plane is above its
//                 lifted point) replaced by the fan from it. territories:
//                 the round's Hilbert curve cut into pieces, each piece one
//                 task owning the triangles around its stretch and inserting
//                 its points in order while their walks, cavities and rings
//                 stay in its own triangles, the others deferred and then
//                 inserted as in 2. batches: every point of a batch located
//                 in parallel, the redundant ones discarded, the cavity and
//                 the ring around it labelled by an atomic minimum of the
//                 point's priority (§3.3.1's conflict resolution over the
//                 induced subcomplex); the points that hold all their labels
//                 replace their cavities in parallel (slots by prefix sums),
//                 the others wait for the next batch. Points outside the
//                 current hull: inserted as in 2 (rare after the first
//                 rounds);
//   3. [output]   the real triangles in canonical form (DESIGN.md), mapped to
//                 input indices in parallel, sorted in parallel;
//   4. [witness]  (when asked for) the certificate of Rt2Witness: for each
//                 vertex an incident triangle (a parallel pass over the
//                 triangles, the smallest slot by an atomic minimum), for
//                 each point that is not a vertex the triangle containing it,
//                 by parallel visibility walks over the points in insertion
//                 order, each from the previous point's triangle (a piece's
//                 first point from the triangle where it was found redundant
//                 or removed, when that slot still holds a real triangle).
// Triangles are flat arrays: three vertex slots and three twin half-edges per
// triangle (half-edge 3t + i is the edge opposite corner i, its twin stored as
// 3u + j), freed slots reused; the virtual vertex is vertex n. Predicates are
// predicates/fast.hpp's (per-input static filter inlined, then the staged
// exact path with Simulation of Simplicity).
//
// Why the answer is the reference's byte for byte: under the Simulation of
// Simplicity (one perturbation with δ = 3, index = SoS index, as in
// reference/rt2) the perturbed weighted points are in general position and
// their regular triangulation is unique (DESIGN.md); every decision here is
// an exact SoS predicate, and the flipping insertion returns the regular
// triangulation of the points inserted so far after every step (Edelsbrunner
// & Shah, "Incremental topological flipping works for regular
// triangulations", Algorithmica 15 (1996), Lemma 4.2 and Thm 4.3: while a
// link edge of the new point is locally non-regular, one of them is
// flippable by a 2-2 or a 3-1 flip; the flips terminate). A point discarded
// as redundant stays redundant (the lower hull of the lifted points only
// moves down as points are added), so the final triangulation is RT(S ⊕ W)
// under SoS, which is ref::rt2_ffrt's and ref::dt2_lawson's answer.
//
// Parallelism: stages 1, 2b, 3 and 4 (and certification from the witness,
// cpu::certify_rt2) run on all threads; stage 2 is sequential. 2 is the
// default: on the 2-core machine measured 2b is not faster (README "The
// multithreaded 2D triangulation"): batches lose the Hilbert order's cache
// locality (a batch is spread over the whole plane so that few cavities
// meet, so nearly every triangle it touches is a cache miss: about 5x the
// work of 2 at one thread); territories keep it but do about 1.5x the work
// of 2 at one thread. Neither the output nor the witness depends on the
// thread count.
//
// Input that does not span the plane is rejected with the reference's
// std::invalid_argument (ref::require_plane, "rt2 (cpu): <problem>").
#pragma once

#include <cstdint>
#include <vector>

#include "kernels_cpu/stage_times.hpp"
#include "reference/point_set.hpp"
#include "reference/rt2/triangulation2.hpp"  // ref::Rt2Stats

namespace flipflop::cpu {

struct Rt2Options {
  int threads = 0;  // worker threads; 0: the runtime's default
  // Tuning; the result does not depend on it (tests vary it):
  std::size_t brio_min = 256;  // BRIO rounds stop below this many points (>= 1)
  // Stage 2: sequential: one point after the other (`--algo incremental`);
  // territories and batches: the first parallel_from points (in BRIO order)
  // one by one, the rest in parallel (stage 2b, `--algo territories|batches`).
  // The triangles are the same for all; the slots of the witness depend on
  // these settings, never on the threads.
  enum class Insertion { sequential, territories, batches };
  Insertion insertion = Insertion::sequential;
  std::size_t parallel_from = 4096;  // >= 1; also caps the territory size (stage 2b)
  // when set, filled with the seconds of each stage: sort, insert, output
  StageTimes* times = nullptr;
};

// A point in the kernel's insertion order: coordinates, weight, input index
// (= SoS index).
struct Rt2Point {
  double xy[2];
  double w;
  Index id;
};

// What the kernel hands its certifier (cpu::certify_rt2 with a witness,
// certify_rt2.hpp): its final triangulation in its own (spatial) order, and
// for every input point that is not a vertex the triangle that proves it
// redundant. Positions are indices into pts; the virtual vertex of the
// extended triangulation (thesis §2.1) is position pts.size().
struct Rt2Witness {
  // the input points in insertion (BRIO) order: position k is input point
  // pts[k].id, a permutation of the input
  std::vector<Rt2Point> pts;
  // per triangle slot t, corners tv[3t..3t+2] (positions) counter-clockwise;
  // a slot with the virtual vertex as a corner is virtual (outside the hull),
  // an unused slot holds three kNoSlot
  std::vector<std::uint32_t> tv;
  // half-edge 3t + i is the edge of slot t opposite corner i, from corner
  // i + 1 to corner i + 2; tn[3t + i] is its twin 3u + j (the same edge,
  // reversed, in the neighbouring slot u). A real triangle's edge whose twin
  // lies in a virtual triangle is a hull edge.
  std::vector<std::uint32_t> tn;
  // per position k: for a vertex, a real triangle with k as a corner; for any
  // other point, the real triangle that contains it under SoS and under
  // whose lifted plane its lifted point is not (it is redundant there)
  std::vector<std::uint32_t> at;
  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
};

// RT(S ⊕ W) of the weighted planar points ps (weights 0 when unweighted: the
// Delaunay triangulation) under flipflop's SoS, canonical counter-clockwise
// triangles — identical to ref::rt2_ffrt(ps). stats, if given, is reset and
// filled: flips_1_3 (insertions), flips_2_2, flips_3_1 (vertices removed),
// discarded_early (points found redundant when located), rounds (1).
// witness, if given, receives the kernel's final triangulation (Rt2Witness;
// its `at` found by a parallel walk, stage [witness] of opt.times).
std::vector<Triangle> rt2(const PointSet& ps, const Rt2Options& opt = {}, ref::Rt2Stats* stats = nullptr,
                          Rt2Witness* witness = nullptr);

}  // namespace flipflop::cpu

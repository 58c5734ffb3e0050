// rtd_cavity.hpp — the d-dimensional regular / Delaunay triangulation by
// cavity insertion (cpu backend of `flipflop rtd --dim 2|4|5` and of Python's
// `Delaunay` in 4D and 5D), the d-dimensional twin of kernels_cpu/rt3's
// insertion step. Sequential: the BRIO sort runs on oneTBB, the insertion on
// one thread.
//
// Stages:
//   1. the per-input static filter; the points in a biased randomized
//      insertion order (BRIO, kernels_cpu/brio.hpp) along a Morton curve of
//      the bounding box (floor(30 / d) bits per axis);
//   2. incremental insertion on the extended triangulation of thesis §2.1
//      (the virtual vertex v closes the hull into a triangulated d-sphere, as
//      reference/rtd): each point is located by a visibility walk from the
//      last point's simplex; a point in a real simplex whose lifted point lies
//      above that simplex's lifted hyperplane is redundant and never inserted
//      (ffRT's early discard, §5.3); otherwise the simplices whose lifted
//      hyperplane passes strictly above its lifted point — and,
//      outside the hull, the virtual simplices whose hull facet it sees — are
//      replaced by the cone from it over their boundary. rtd_cavity.cpp says
//      why this is Edelsbrunner–Shah's 1-(d+1) flip followed by their
//      monotonic k-(d+2-k) flips composed, the reference's RT+1
//      (reference/rtd/rt_incremental.cpp), and hence the same answer;
//   3. the real simplices in canonical form (canonical_d.hpp), sorted; the
//      redundant points (input indices that are vertices of no simplex).
//
// Why the answer is the reference's byte for byte: every decision is an exact
// SoS predicate of the same perturbation (orient_d, power_d with the input
// index as SoS index; predicates.hpp), under which the perturbed weighted
// points are in general position and their regular triangulation is unique;
// every insertion returns the regular triangulation of the points inserted so
// far, so the last one is RT(S ⊕ W) — ref::rtd_incremental's answer. Tested
// at every dimension against the reference (proptests/rtd_cavity_test.cpp).
//
// The caller certifies the result (certify::rtd): the kernel returns no
// witness.
#pragma once

#include <cstdint>
#include <memory>

#include "reference/point_set.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::cpu {

struct RtdCavityOptions {
  // BRIO rounds stop below this many points (tuning; the answer does not
  // depend on it). 8 rather than 64: on integer grids the first points are
  // then spread over the box, and later ones fall inside the hull more often
  // (created simplices, 64 -> 8: 3^5 grid 108,424 -> 87,470, 2^7 grid
  // 583,672 -> 508,814; rtd_cavity 130 -> 107 ms and 1.45 -> 1.24 s);
  // random points do the same work either way (20,000 in 4D: 3,026,237 and
  // 3,023,334 created).
  std::size_t brio_min = 8;
  bool furthest = false;      // the furthest-site triangulation (ref::rtd_incremental's `furthest`)
  // workers (0: the runtime's default) of the BRIO sort and of each cavity's
  // exact tests (rtd_cavity.cpp, visible_region_waves); the insertions are
  // sequential, and 1 tests a cavity's cells one by one. The answer does not
  // depend on it.
  int threads = 0;
  // with more than one thread, a wave's exact tests run in parallel where
  // their work, estimated from the cost per cell of a timed sequential
  // batch, is at least this many nanoseconds (tuning: the fork and join of
  // two threads cost a few microseconds on the 2-core VM); 0 sends every
  // wave of two cells or more (tests)
  double parallel_min_ns = 40e3;
};

struct RtdCavityStats {
  std::uint64_t inserted = 0;    // points made vertices (the first d+1 included)
  std::uint64_t placed = 0;      // of those: outside the hull when inserted
  std::uint64_t discarded = 0;   // points found redundant when located (never inserted)
  std::uint64_t removed = 0;     // vertices a later cavity removed (redundant)
  std::uint64_t cavity = 0;      // simplices removed by cavities (real and virtual)
  std::uint64_t created = 0;     // simplices created by cones
  std::uint64_t walk_steps = 0;  // simplices visited by the walks
};

// RT(S ⊕ W) of ps (dim 2..9; unweighted: Delaunay), as ref::rtd_incremental
// returns it (canonical simplices, sorted redundant points). Input that the
// reference rejects is rejected with the reference's std::invalid_argument
// (ref::validate_rtd_input); more than 2^29 points: std::length_error.
ref::Rtd rtd_cavity(const PointSet& ps, RtdCavityStats* stats = nullptr, const RtdCavityOptions& options = {});

// The same kernel kept between calls, for in-place insertion (Python's
// Delaunay(..., incremental=True).add_points): the extended triangulation,
// its links and the points' positions stay; add() inserts only the new
// points (BRIO order among themselves, walks from the last simplex), so a
// batch costs about what those insertions cost, not a rebuild. result() is
// rtd_cavity of all the points given so far, byte for byte (the regular
// triangulation under SoS is unique whatever the insertion order; SoS
// indices are the input indices, so appending keeps every earlier point's).
// The caller certifies each result.
class RtdCavityIncremental {
 public:
  // As rtd_cavity(ps, ..., options), kept.
  explicit RtdCavityIncremental(const PointSet& ps, const RtdCavityOptions& options = {});
  // Seeded with the regular triangulation of ps, the caller's certified
  // one: its real simplices, d + 1 corners each in one flat array,
  // positively oriented in the output's convention (det[p1-p0, ..., pd-p0]
  // > 0: the canonical form's, canonical_d.hpp), and neighbors[k (d+1) + j],
  // the simplex across the facet opposite corner j of simplex k (-1: a hull
  // facet). Checked only to be d + 1 distinct in-range
  // indices per simplex glued along their facets, the hull facets along
  // their ridges (std::invalid_argument otherwise), so that each result
  // after add() must be certified as it is anyway. No predicate; the points
  // that are vertices of no simplex are the redundant ones. (The hull
  // ridges are matched in pairs, as an insertion's cone is: one held by four
  // hull facets is not refused here, and the certificate after add()
  // catches what it breaks.) Not for the
  // furthest-site triangulation (std::invalid_argument).
  RtdCavityIncremental(const PointSet& ps, const std::vector<Index>& simplices,
                       const std::vector<std::int64_t>& neighbors, const RtdCavityOptions& options = {});
  ~RtdCavityIncremental();
  RtdCavityIncremental(RtdCavityIncremental&&) noexcept;
  RtdCavityIncremental& operator=(RtdCavityIncremental&&) noexcept;

  // `all`: the size() points given so far, unchanged and in the same order,
  // followed by the new ones (same dimension, weighted alike). Validated as
  // rtd_cavity's input before anything changes (std::invalid_argument,
  // nothing changed). An exception during the insertion itself (more
  // simplices than 32-bit links hold) leaves the object unusable: every later
  // call throws std::logic_error.
  void add(const PointSet& all);
  ref::Rtd result() const;      // canonical simplices, sorted redundant points
  std::size_t size() const;     // points given so far
  RtdCavityStats stats() const; // summed over the construction and every add (removed: not kept)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flipflop::cpu

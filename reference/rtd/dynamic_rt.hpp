// dynamic_rt.hpp — a regular triangulation whose weights change: the in-place
// update that an optimal-transport loop (Mérigot; Lévy) needs at every Newton
// or gradient step, by the monotonic instant flip with insertions (thesis
// §9.2, Algorithm 14, extended: instant_flip.hpp).
//
//   DynamicRegularTriangulation rt(points, w);   // RT(S ⊕ W), built by RT+1
//   WeightUpdateStats st = rt.set_weights(u);    // now RT(S ⊕ U), in place
//   rt.simplices();                              // canonical output
//
// set_weights(u) keeps THE regular triangulation of the whole point set under
// flipflop's Simulation of Simplicity (predicates.hpp): after it,
// simplices() is byte for byte what rtd_incremental (and `flipflop rtd`)
// computes for S ⊕ U, for any W and U — points may enter and leave. Three
// steps:
//   1. the instant flip from W to U (index perturbation order), every
//      redundant point tracked in its simplex (point_buckets.hpp) and
//      inserted at its time by a 1-(d+1) flip;
//   2. verification under SoS at U (Theorem 2.2: every ridge locally
//      regular, every non-vertex above its simplex). Only the simplices that
//      step 1 created, or where it met a (d+2)-set not strictly convex at U,
//      can fail it (InstantFlipTrace): where the perturbation order and SoS
//      resolve a flat set differently. Those are repaired by monotonic SoS
//      flips and insertions (each lowers the perturbed lifted surface, so
//      they terminate);
//   3. only if step 1 meets coordinates not in general position (a
//      zero-volume simplex: failure times need the thesis' general position
//      in R^d, §9.2) or the SoS flips of step 2 get stuck (possible in d >= 3
//      for non-regular intermediate triangulations, [Joe89]), the
//      triangulation is rebuilt by RT+1; stats.rebuilt says so and why.
// Each step ends with a triangulation that is verified, never returned
// unverified: RT+1 verifies itself, step 2 checks every ridge and point it
// could not rule out.
//
// Cost: step 1 examines every interior ridge and tracked point once with the
// exact sign at U (filtered: pred::power_d_exact), plus the events in
// O(log n) each; steps 2-3 are local.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "reference/point_set.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/point_buckets.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref {

struct WeightUpdateStats {
  InstantFlipStats instant;               // step 1
  std::uint64_t repair_flips[8] = {};     // step 2: k-(d+2-k) SoS flips; [1]: insertions
  std::uint64_t repair_removed = 0;       // step 2: (d+1)-1 flips
  std::uint64_t checked_ridges = 0;       // step 2: ridges verified under SoS
  std::uint64_t checked_points = 0;       // step 2: tracked points verified under SoS
  bool rebuilt = false;                   // step 3 ran
  std::string rebuild_reason;             // why
  std::uint64_t flips(int k) const { return instant.flips[k] + repair_flips[k]; }
  std::uint64_t total_flips() const {
    std::uint64_t s = instant.total_flips();
    for (std::uint64_t f : repair_flips) s += f;
    return s;
  }
};

// How step 1 runs (tests vary them: every order reaches the same result).
struct WeightUpdateOptions {
  PerturbationOrder order;    // the instant flip's perturbation order; empty: the index order
  std::uint64_t tie_seed = 0;  // InstantFlipOptions::tie_seed
  decltype(InstantFlipOptions::for_range) for_range;  // InstantFlipOptions::for_range
};

class DynamicRegularTriangulation {
 public:
  // RT(S ⊕ w) of the points of `points` (its weights are ignored), 2 <= d <= 5,
  // built by RT+1 (rt_incremental.hpp). Throws std::invalid_argument for
  // input RT+1 rejects (not spanning R^d, non-finite values) or w of the
  // wrong size.
  DynamicRegularTriangulation(const PointSet& points, const std::vector<double>& w);
  DynamicRegularTriangulation(const DynamicRegularTriangulation&) = delete;
  DynamicRegularTriangulation& operator=(const DynamicRegularTriangulation&) = delete;
  DynamicRegularTriangulation(DynamicRegularTriangulation&&) noexcept = default;
  DynamicRegularTriangulation& operator=(DynamicRegularTriangulation&&) noexcept = default;

  // Updates the triangulation in place to RT(S ⊕ u) (the steps of the header
  // comment). u: one finite weight per point (std::invalid_argument
  // otherwise, and nothing changes).
  WeightUpdateStats set_weights(const std::vector<double>& u, const WeightUpdateOptions& options = {});

  int dim() const { return ps_->dim; }
  std::size_t size() const { return ps_->size(); }
  const Values& weights() const { return ps_->weights; }
  // The points with the current weights (the triangulation points to it).
  const PointSet& points() const { return *ps_; }
  const rtd::TriangulationD& triangulation() const { return T_; }
  // Canonical simplices (canonical_d.hpp) and the redundant points, sorted.
  std::vector<std::vector<Index>> simplices() const { return rtd::real_simplices(T_); }
  std::vector<Index> redundant() const;

 private:
  void rebuild(WeightUpdateStats& st, std::string reason);
  bool repair(WeightUpdateStats& st, const InstantFlipTrace& trace);

  std::unique_ptr<PointSet> ps_;  // stable address: T_.ps points to it
  rtd::TriangulationD T_;
  rtd::PointBuckets B_;           // every non-vertex in its simplex
};

}  // namespace flipflop::ref

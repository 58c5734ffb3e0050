// perturbation_order.hpp — finding a perturbation order, thesis §9.2.3,
// Algorithm 15.
//
// A weakly regular triangulation T(S ⊕ W) has flat ridges:
// Orient^{d+1}(S_F, 0) = 0 (failure_time.hpp). The weight perturbation of
// §9.2.2 turns each into a convex or a reflex ridge; Algorithm 15 finds a
// perturbation order under which every flat ridge becomes convex, i.e. under
// which T is *strongly* regular — the valid input of the monotonic instant
// flip (Algorithm 14) — or shows that none exists (Theorem 9.5).
//
// By Eq. 9.4, Orient^{d+1}(S*_F, 0) = 0 + Σ_p c_F(p) ε_p; its sign is that of
// c_F(p) for the most dominant p with c_F(p) != 0. S_p(F) (S_n(F)) are the
// points of S_F with c_F(p) > 0 (< 0). F becomes convex iff a point of S_p(F)
// precedes every point of S_n(F) in the order. (This project perturbs the
// lifted height, not the weight, by +ε — the Simulation of Simplicity's sign,
// failure_time.hpp — so S_p and S_n are the mirror images of the thesis'.)
//
// Algorithm 15 (lines 1-19): negDegree(p) counts the not yet perturbed flat
// ridges with p in S_n; posRidges(p) lists the flat ridges with p in S_p. A
// point is appended to the order once its negDegree is 0; appending p
// "perturbs" every flat ridge of posRidges(p), releasing its S_n points.
// The queue Q pops the point of smallest index first (the thesis leaves the
// choice free): then the result is the lexicographically smallest valid
// order, and it is the index order — the Simulation of Simplicity's —
// whenever the index order is valid. Points that are not vertices of T
// belong to no ridge and keep negDegree 0.
//
// Theorem 9.5: the order is correct whenever one exists; if points remain
// with negDegree > 0, no order exists. (Example: a non-regular triangulation
// whose vertices are all lifted onto one hyperplane — every ridge is flat, and
// no perturbation makes a non-regular triangulation regular.)
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "reference/point_set.hpp"
#include "reference/rtd/failure_time.hpp"

namespace flipflop::ref {

struct PerturbationOrderResult {
  // Set iff every ridge of T is convex under it (Algorithm 15 succeeded).
  std::optional<PerturbationOrder> order;
  // Empty on success; otherwise one line: a reflex ridge (T is not even
  // weakly regular), or the flat ridges no order can make convex.
  std::string reason;
  std::size_t interior_ridges = 0;
  std::size_t flat_ridges = 0;
  // On failure by Theorem 9.5: the points whose negDegree stayed positive.
  std::vector<Index> blocked_points;
};

// ps.dim = d (1..5), w: ps.size() weights, simplices: T, d+1 indices per
// simplex (any vertex order). Throws std::invalid_argument
// for malformed input (see interior_ridges, ridge_motion).
PerturbationOrderResult find_perturbation_order(const PointSet& ps, const std::vector<double>& w,
                                                const std::vector<std::vector<Index>>& simplices);

}  // namespace flipflop::ref

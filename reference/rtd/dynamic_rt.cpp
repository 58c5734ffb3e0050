// dynamic_rt.cpp — in-place weight updates of a regular triangulation: the
// instant flip with insertions, SoS verification and repair. See
// dynamic_rt.hpp.
#include "reference/rtd/dynamic_rt.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>

#include "reference/checked.hpp"
#include "reference/rtd/bistellar_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::ref {

namespace {

PointSet with_weights(const PointSet& points, const std::vector<double>& w) {
  if (w.size() != points.size())
    throw std::invalid_argument("dynamic regular triangulation: " + std::to_string(points.size()) +
                                " points but " + std::to_string(w.size()) + " weights");
  PointSet ps;
  ps.dim = points.dim;
  ps.weighted = true;
  ps.coords = points.coords;
  ps.weights = w;
  return ps;
}

}  // namespace

DynamicRegularTriangulation::DynamicRegularTriangulation(const PointSet& points,
                                                         const std::vector<double>& w)
    : ps_(std::make_unique<PointSet>(with_weights(points, w))),
      T_(build_rtd(*ps_)),
      B_(rtd::track_all(T_)) {}

std::vector<Index> DynamicRegularTriangulation::redundant() const {
  std::vector<Index> out;
  for (Index x = 0; x < T_.n; ++x)
    if (!T_.is_vertex(x)) out.push_back(x);
  return out;
}

void DynamicRegularTriangulation::rebuild(WeightUpdateStats& st, std::string reason) {
  T_ = build_rtd(*ps_);
  B_ = rtd::track_all(T_);
  st.rebuilt = true;
  st.rebuild_reason = std::move(reason);
}

WeightUpdateStats DynamicRegularTriangulation::set_weights(const std::vector<double>& u,
                                                           const WeightUpdateOptions& options) {
  if (u.size() != ps_->size())
    throw std::invalid_argument("set_weights: " + std::to_string(ps_->size()) + " points but " +
                                std::to_string(u.size()) + " weights");
  for (std::size_t p = 0; p < u.size(); ++p)
    if (!std::isfinite(u[p]))
      throw std::invalid_argument("set_weights: weight of point " + std::to_string(p) + " is not finite");
  WeightUpdateStats st;
  // Step 1: the instant flip (T_ is RT(S ⊕ W) under SoS, verified: no
  // start check needed; what it cannot rule out is in the trace).
  InstantFlipTrace trace;
  InstantFlipOptions opt;
  opt.points = &B_;
  opt.check_start = false;
  opt.trace = &trace;
  opt.order = options.order;
  opt.tie_seed = options.tie_seed;
  opt.for_range = options.for_range;
  std::vector<double> w = ps_->weights.to_vector();
  try {
    st.instant = instant_flip(T_, w, u, opt);
  } catch (const InvariantViolation&) {
    throw;  // a bug, not a degenerate input (checked builds)
  } catch (const std::invalid_argument& e) {  // zero-volume simplex: coordinates not in general position
    ps_->weights = u;
    rebuild(st, std::string("instant flip: ") + e.what());
    return st;
  } catch (const std::logic_error& e) {  // unflippable minimum (degenerate coordinates, §9.2.2)
    ps_->weights = u;
    rebuild(st, std::string("instant flip: ") + e.what());
    return st;
  }
  ps_->weights = u;
  // Step 2 (step 3 when it gets stuck).
  if (!repair(st, trace))
    rebuild(st, "SoS repair: a locally non-regular ridge is unflippable and no flip is left");
  FF_CHECK(rtd::validity_problem(T_).empty(), "set_weights: " + rtd::validity_problem(T_));
  return st;
}

// Step 2: every simplex of the trace that is still in T is checked under SoS
// at U — its tracked points (above the lifted simplex: power_d < 0) and its
// interior ridges (locally regular, Theorem 2.2); a point below is inserted
// (1-(d+1) flip), a non-regular flippable ridge flipped, and the simplices
// these create are checked in turn. Ridges found unflippable wait until the
// other work is done and are retried while some flip succeeds.
bool DynamicRegularTriangulation::repair(WeightUpdateStats& st, const InstantFlipTrace& trace) {
  rtd::TriangulationD& T = T_;
  const int d = T.d;
  struct SlotRef {
    std::int32_t s;
    std::uint32_t gen;
  };
  std::deque<SlotRef> to_check;
  for (std::size_t i = 0; i < trace.slots.size(); ++i) to_check.push_back({trace.slots[i], trace.gens[i]});
  std::vector<rtd::RidgeRef> stuck;
  std::vector<Index> moved;
  auto live = [&](SlotRef r) {
    return T.alive[static_cast<std::size_t>(r.s)] && T.gen[static_cast<std::size_t>(r.s)] == r.gen;
  };
  auto settle = [&](const rtd::FlipResult& fr) {
    if (fr.removed != rtd::kNoVertex) {
      moved.push_back(fr.removed);
      ++st.repair_removed;
    }
    rtd::redistribute(T, B_, moved, fr.created);
    moved.clear();
    for (std::int32_t c : fr.created) to_check.push_back({c, T.gen[static_cast<std::size_t>(c)]});
    ++st.repair_flips[fr.k];
  };
  // Flips ridge r when locally non-regular and flippable; true when flipped.
  auto try_flip = [&](rtd::RidgeD r, bool* unflippable) {
    ++st.checked_ridges;
    if (rtd::locally_regular(T, r)) return false;
    const rtd::FlipShape shape = rtd::flip_shape(T, r);
    if (!shape.flippable) {
      *unflippable = true;
      return false;
    }
    for (int j = 0; j < shape.nu; ++j) rtd::take_points(B_, shape.cur[static_cast<std::size_t>(j)], moved);
    settle(rtd::flip(T, shape));
    return true;
  };
  std::vector<Index> pts;
  for (;;) {
    while (!to_check.empty()) {
      const SlotRef sr = to_check.front();
      to_check.pop_front();
      if (!live(sr) || rtd::is_virtual_simplex(T, sr.s)) continue;
      const std::int32_t s = sr.s;
      // its points: one strictly below the lifted simplex is inserted
      pts.clear();
      B_.points_of(s, pts);
      Index below = rtd::kNoVertex;
      for (Index p : pts) {
        ++st.checked_points;
        Index S[rtd::kMaxDim + 2];
        for (int i = 0; i <= d; ++i) S[i] = T.vertex(s, i);
        S[d + 1] = p;
        if (rtd::power(T, S) > 0) {
          below = p;
          break;
        }
      }
      if (below != rtd::kNoVertex) {
        rtd::remove_point(B_, below);
        rtd::take_points(B_, s, moved);
        settle(rtd::insert_in_simplex(T, s, below));
        continue;
      }
      // its interior ridges
      for (int i = 0; i <= d; ++i) {
        const rtd::RidgeD r{s, i};
        if (!rtd::interior(T, r)) continue;
        bool unflippable = false;
        if (try_flip(r, &unflippable)) break;  // s is gone; the created simplices are queued
        if (unflippable) stuck.push_back(rtd::remember(T, r));
      }
    }
    // retry the unflippable ridges once the rest is done
    bool progress = false, pending = false;
    std::vector<rtd::RidgeRef> again;
    again.swap(stuck);
    for (const rtd::RidgeRef& ref : again) {
      const rtd::RidgeD r = rtd::recall(T, ref);
      if (!r.valid()) continue;
      bool unflippable = false;
      if (try_flip(r, &unflippable)) {
        progress = true;
      } else if (unflippable) {
        pending = true;
        stuck.push_back(ref);
      }
    }
    if (!pending && to_check.empty()) return true;
    if (!progress && to_check.empty()) return false;
  }
}

}  // namespace flipflop::ref

// timeline.cpp — the time line of thesis §9.3 (see the header).
#include "reference/rtd/timeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace flipflop::ref {

namespace {

// Strict order of nodes by changing time; -∞ first; ties (one flip) by S_F.
struct ByTime {
  const PerturbationOrder* order;
  bool operator()(const TimelineNode& x, const TimelineNode& y) const {
    if (x.minus_infinity != y.minus_infinity) return x.minus_infinity;
    if (!x.minus_infinity) {
      const int c = compare_times(x.motion, y.motion, *order);
      if (c != 0) return c < 0;
    }
    return x.motion.pts < y.motion.pts;
  }
};

}  // namespace

Timeline build_timeline(const MovingModel& mm, const std::vector<std::vector<Index>>& simplices,
                        const PerturbationOrder& order) {
  if (order.size() != mm.size())
    throw std::invalid_argument("time line: perturbation order and point set differ in size");
  Timeline tl;
  tl.dim = mm.dim();
  const std::vector<RidgeLink> ridges =
      interior_ridges(mm.dim(), mm.size(), simplices, &tl.boundary_ridges);
  tl.nodes.reserve(ridges.size());
  for (const RidgeLink& r : ridges) {
    TimelineNode n;
    n.motion = ridge_motion(mm, r.v.data(), r.a, r.b);
    const int dir = n.motion.direction();
    if (dir == 0) {
      // parallel: always convex (σ = +) or always reflex (σ = -), τ = -∞
      n.minus_infinity = true;
      n.direction = perturbed_sign(n.motion, 0, order);
      n.time = -std::numeric_limits<double>::infinity();
    } else {
      n.direction = dir;
      n.time = approximate_time(n.motion);
    }
    (n.direction > 0 ? tl.positive : tl.negative) += 1;
    tl.nodes.push_back(std::move(n));
  }
  std::sort(tl.nodes.begin(), tl.nodes.end(), ByTime{&order});

  for (std::size_t i = 0; i < tl.nodes.size(); ++i) {
    const TimelineNode& n = tl.nodes[i];
    if (n.direction > 0) tl.max_positive = static_cast<long>(i);
    if (n.direction < 0 && tl.min_negative < 0) tl.min_negative = static_cast<long>(i);
  }
  tl.well_separated = true;
  if (tl.min_negative >= 0) {
    const TimelineNode& neg = tl.nodes[static_cast<std::size_t>(tl.min_negative)];
    if (neg.minus_infinity) {
      tl.well_separated = false;  // always reflex
    } else if (tl.max_positive > tl.min_negative) {
      // sorted: a positive node after the first negative one; equal times
      // (compare_times == 0) still satisfy τ(N+) <= τ(N-)
      const TimelineNode& pos = tl.nodes[static_cast<std::size_t>(tl.max_positive)];
      tl.well_separated = compare_times(pos.motion, neg.motion, order) == 0;
    }
  }
  return tl;
}

bool well_separated_within(const Timeline& tl, double lo, double hi, const PerturbationOrder& order) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi)
    throw std::invalid_argument("well_separated_within: need finite lo <= hi");
  if (!tl.well_separated) return false;
  // τ(max N+) <= hi: the last positive ridge is convex at hi (or τ = -∞).
  if (tl.max_positive >= 0) {
    const TimelineNode& pos = tl.nodes[static_cast<std::size_t>(tl.max_positive)];
    if (!pos.minus_infinity && perturbed_sign_at(pos.motion, hi, order) < 0) return false;
  }
  // lo <= τ(min N-): the first negative ridge is still convex at lo.
  if (tl.min_negative >= 0) {
    const TimelineNode& neg = tl.nodes[static_cast<std::size_t>(tl.min_negative)];
    if (perturbed_sign_at(neg.motion, lo, order) < 0) return false;
  }
  return true;
}

namespace {

std::string time_text(const TimelineNode& n) {
  if (n.minus_infinity) return "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", n.time);
  return buf;
}

std::string node_text(const TimelineNode& n, int d) {
  std::string s = time_text(n);
  s.resize(std::max<std::size_t>(s.size(), 24), ' ');
  s += n.direction > 0 ? " +  " : " -  ";
  s += "ridge";
  for (int i = 0; i < d; ++i) s += " " + std::to_string(n.motion.pts[static_cast<std::size_t>(i)]);
  s += " | link " + std::to_string(n.motion.link_a()) + " " + std::to_string(n.motion.link_b());
  return s;
}

}  // namespace

std::string format_timeline(const Timeline& tl) {
  std::string out = "# time line (thesis §9.3): changing time, direction (+ reflex->convex,"
                    " - convex->reflex), ridge | link\n";
  for (const TimelineNode& n : tl.nodes) out += node_text(n, tl.dim) + "\n";
  out += "# " + std::to_string(tl.nodes.size()) + " nodes (" + std::to_string(tl.positive) +
         " positive, " + std::to_string(tl.negative) + " negative), " +
         std::to_string(tl.boundary_ridges) + " boundary ridges\n";
  const std::string lo =
      tl.max_positive < 0 ? "-inf" : time_text(tl.nodes[static_cast<std::size_t>(tl.max_positive)]);
  const std::string hi =
      tl.min_negative < 0 ? "+inf" : time_text(tl.nodes[static_cast<std::size_t>(tl.min_negative)]);
  if (tl.well_separated)
    out += "# well-separated (Theorem 9.6): regular for V(t), t in [" + lo + ", " + hi + "]\n";
  else
    out += "# not well-separated: the last positive node (" + lo +
           ") lies after the first negative node (" + hi + ")\n";
  return out;
}

}  // namespace flipflop::ref

// timeline.hpp — the time line of a triangulation in the extended moving
// model, thesis §9.3 (Theorem 9.6).
//
// The weights move as V(t) = (1-t) W + t U for all real t. Every interior
// ridge F (with its link: the same vertices with another link is another
// ridge) is a node of the time line:
//   * changing direction σ(F) = sign(Orient^{d+1}(S_F,1) - Orient^{d+1}(S_F,0))
//     = sign(D) (failure_time.hpp): + reflex -> convex, - convex -> reflex;
//   * changing time τ(F) = -A/D, when F is flat (Eq. 9.3).
// A ridge with D = 0 is always convex (σ = +, τ = -∞) or always reflex
// (σ = -, τ = -∞); under the weight perturbation of §9.2.2 no ridge is always
// flat. Nodes are ordered by τ with the exact comparison of failure_time.hpp
// (compare_times: ties only between nodes of one flip).
//
// Well-separated (§9.3): there is a time t with τ(N+) <= t <= τ(N-) for every
// positive node N+ and negative node N-. At such a t every ridge is convex
// (positive ones have become convex, negative ones are not yet reflex), so by
// Theorem 9.6 (with Theorem 2.2, local regularity everywhere implies
// regularity) the triangulation is RT(S ⊕ V(t)): the time line is a
// regularity certificate, valid for the perturbed weights (a node with τ = -∞
// and σ = - is always reflex and rules out every t). During the monotonic
// instant flip every intermediate triangulation has a well-separated time
// line (Lemma 9.10) at the time of the last flip.
//
// format_timeline() prints it for debugging (flipflop instant-flip --timeline).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "reference/rtd/failure_time.hpp"

namespace flipflop::ref {

struct TimelineNode {
  RidgeMotion motion;      // S_F = (ridge vertices, link a, link b)
  int direction = 0;       // σ: +1 or -1
  bool minus_infinity = false;  // τ = -∞ (D = 0)
  double time = 0.0;       // τ rounded (for display); -inf when minus_infinity
};

struct Timeline {
  int dim = 0;
  std::vector<TimelineNode> nodes;  // sorted by changing time, -∞ first
  std::size_t boundary_ridges = 0;  // convex by default, not nodes
  std::size_t positive = 0, negative = 0;
  // Theorem 9.6: true iff some t has τ(N+) <= t <= τ(N-) for all N+, N-.
  bool well_separated = false;
  // The witness interval [τ(max positive node), τ(min negative node)] as node
  // positions in `nodes`; -1 when there is no positive (negative) node (the
  // interval is then unbounded on that side).
  long max_positive = -1, min_negative = -1;
};

// The time line of the triangulation `simplices` (d+1 indices per simplex,
// any order) of the points of mm (dim d) between weights w (t = 0) and u (t = 1), under the
// perturbation order `order`. The nodes refer to mm (exact values are
// computed on demand): keep mm alive while the time line is used.
Timeline build_timeline(const MovingModel& mm, const std::vector<std::vector<Index>>& simplices,
                        const PerturbationOrder& order);

// Whether the time line is well-separated at some time in [lo, hi]
// (lo, hi finite doubles, lo <= hi), comparing the perturbed changing times
// with lo and hi exactly.
bool well_separated_within(const Timeline& tl, double lo, double hi, const PerturbationOrder& order);

// A text view: one line per node in time order ("τ σ ridge | link"), then a
// summary with the well-separation verdict and its witness interval.
std::string format_timeline(const Timeline& tl);

}  // namespace flipflop::ref

// pseudo_angle.hpp — a monotone stand-in for the polar angle, used only to
// *guess* where a point lies around a centre (a fan sector, a wedge); every
// guess is then verified or replaced by exact predicates, so its rounding
// never matters (certify_hull2.cpp, kernels_cpu/hull2/throw_away.cpp).
#pragma once

namespace flipflop {

// The "diamond angle" of (dx, dy): increases with the angle from the +x axis,
// counter-clockwise, through [0, 4) (1 at +y, 2 at -x, 3 at -y); one
// division, no libm. NaN for (0, 0) and for non-finite input.
inline double pseudo_angle(double dx, double dy) {
  if (dy >= 0) return dx >= 0 ? dy / (dx + dy) : 1 - dx / (dy - dx);
  return dx < 0 ? 2 - dy / (-dx - dy) : 3 + dx / (dx - dy);
}

}  // namespace flipflop

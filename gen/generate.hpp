// generate.hpp — the input distributions of the thesis' experiments and the
// degenerate families the tests need.
//
// Thesis §4.4, §5.4, §6.5, §7.4: coordinates in [0, 1].
//   2D  square  uniform in [0,1]^2
//       disk    uniform in the disk of center (0.5,0.5), radius 0.5
//       frame   uniform in [0,1]^2 minus the inner square: a band of width
//               `thickness` along the boundary
//       circle  uniform (by area) in the annulus of center (0.5,0.5), outer
//               radius 0.5, inner radius 0.5 - thickness
//   3D  cube, ball (radius 0.5, center (0.5,0.5,0.5)), box (the shell of
//       thickness `thickness` inside [0,1]^3), sphere (spherical shell, outer
//       radius 0.5, inner 0.5 - thickness, uniform by volume), cball (the
//       "controlled ball" of §7.4: h points on the sphere of radius 0.5 and
//       n - h uniform inside the ball of radius 0.45; h = hull_points, by
//       default max(4, n/100))
// Degenerate families (integer or exactly constructed coordinates, not in
// [0,1]; degenerate.cpp and lattice.cpp document each):
//   grid2 grid3 circle-lattice sphere-lattice collinear2 collinear3 coplanar3
//   duplicates2 duplicates3 jitter2 jitter3 huge2 huge3 tiny2 tiny3
//   planes3 (a scanned building: points on nine planes of a 30 × 20 × 10 m
//   hall, millimetre coordinates, one point in 16 an exact duplicate;
//   planes.cpp)
//
// Determinism: the output depends only on (dist, n, options), on every
// machine. The only source of randomness is std::mt19937_64 (its output
// sequence is fixed by the C++ standard) mapped to numbers by our own code
// (rng.hpp); only +, -, *, /, sqrt and std::nextafter are used on doubles,
// all correctly rounded by IEEE 754 — no <random> distributions, no libm
// transcendental functions.
//
// Weights: when o.weighted, point i gets a weight uniform in [wlo, whi],
// drawn from a second engine (so the points do not depend on the weights).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::gen {

struct Options {
  std::uint64_t seed = 1;
  double thickness = 0.01;      // frame, circle, box, sphere: in (0, 0.5]
  bool weighted = false;
  double wlo = 0, whi = 0;      // weight range, wlo <= whi
  std::size_t hull_points = 0;  // cball: h; 0 means max(4, n/100)
};

// n points of distribution `dist`. Throws std::invalid_argument for an
// unknown name (the message lists the valid ones) or invalid options.
PointSet generate(const std::string& dist, std::size_t n, const Options& o);

// All distribution names, in the order above.
std::vector<std::string> distributions();

// 2 or 3; throws std::invalid_argument for an unknown name.
int dimension_of(const std::string& dist);

}  // namespace flipflop::gen

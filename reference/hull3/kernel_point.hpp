// kernel_point.hpp — the kernel point of a star-shaped polyhedron, as the 3D
// hull algorithms see it (thesis §6.1: flip-flop needs a point s strictly
// inside the kernel of the polyhedron; §6.4.2: it must be handled exactly).
//
// Every predicate the 3D algorithms evaluate on the kernel point involves it
// and three input points, and orient3d is alternating, so one primitive is
// enough: side(a, b, c) = sign of orient3d(a, b, c, s) under the Simulation of
// Simplicity of predicates.hpp (> 0 when s is on the inner side of the
// triangle (a, b, c) counter-clockwise seen from outside). It is never 0 for
// distinct a, b, c: s takes part in the perturbation with an index after all
// inputs (the first auxiliary point of a computation, index n).
//
// Implementations: RationalKernel (an exact dyadic point, e.g. the centroid of
// four affinely independent input points — ffhull.hpp) and the symbolic
// kernel of twist-flip (a point infinitesimally close to a vertex,
// twist_flip.hpp).
#pragma once

#include "reference/point_set.hpp"

namespace flipflop::ref {

class KernelPoint {
 public:
  virtual ~KernelPoint() = default;
  // sign of orient3d(a, b, c, s) under SoS; +1 or -1 for distinct a, b, c.
  virtual int side(Index a, Index b, Index c) const = 0;
};

}  // namespace flipflop::ref

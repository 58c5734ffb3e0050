// twist_flip_input.hpp — valid special inputs of twist-flip (thesis §8.4.1):
// a coherently oriented triangulated sphere over ALL points of a 3D point set
// whose topmost point v is joined to every other point.
//
// Construction. link(v) is a cycle through the other k = n - 1 points, star(v)
// the triangles (v, L_i, L_{i+1}); the rest of the sphere is a triangulation
// of the k-gon L_0 .. L_{k-1} without interior vertices (a disk: the
// projected triangulation T of §8.4.1, every vertex on its boundary). In
// slot order a triangle with slots x < y < z is written (L_z, L_y, L_x), so it
// holds L_{i+1} -> L_i on the link and every chord once in each direction:
// the sphere is coherently oriented (§8.1). Then
//   * optionally random twists (§8.2: a twist swaps two adjacent vertices in
//     every triangle and keeps the polyhedron coherently oriented) on edges
//     not incident to v — v stays topmost and joined to all;
//   * optionally every triangle reversed (the other coherent orientation).
// The geometry plays no role except in LinkOrder::angular, which sorts the
// link exactly (SoS predicates) by angle around the vertical line through v:
// the "cheap cyclic order" hull3_twist_flip starts from. Random choices come
// from std::mt19937_64 (sequence fixed by the C++ standard) and our own
// mapping to integers, so the output depends only on (ps, options).
#pragma once

#include <cstdint>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::ref {

enum class LinkOrder {
  random,   // a random cyclic order
  angular,  // by angle around v's vertical line (counter-clockwise seen from
            // above, from the +x direction), decided exactly (SoS)
};

enum class DiskTriangulation {
  fan,     // all chords from L_0
  zigzag,  // L_0 L_1 L_{k-1} L_2 L_{k-2} ... strip
  random,  // random apex for every chord, recursively
};

struct SpecialInputOptions {
  std::uint64_t seed = 1;
  LinkOrder link = LinkOrder::random;
  DiskTriangulation disk = DiskTriangulation::random;
  std::size_t twists = 0;  // random twists on edges not incident to v
  bool reversed = false;   // every triangle reversed
};

// The topmost point of ps: the largest z under pred::compare_sos (a tie goes
// to the smaller index). ps must be 3D and non-empty.
Index topmost_point(const PointSet& ps);

// A special polyhedron over all points of ps, v = topmost_point(ps). Throws
// std::invalid_argument when ps is not 3D or has fewer than 4 points.
std::vector<Triangle> special_polyhedron(const PointSet& ps, const SpecialInputOptions& o);

}  // namespace flipflop::ref

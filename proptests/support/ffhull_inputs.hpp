// ffhull_inputs.hpp — inputs of the flip-flop 3D / ffHull tests
// (proptests/ffhull_*_test.cpp): star-shaped polyhedra of a point set built
// in different ways, the polyhedron of thesis Figure 6.1, and an exact
// self-intersection witness for triangulated surfaces.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "peers/peers.hpp"
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/rational_kernel.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test {

inline bool spans3(const PointSet& ps) { return ps.dim == 3 && ps.size() >= 4 && dimension_problem(ps).empty(); }

// The points of ps with the given (sorted) indices, in index order: the
// relative index order, hence every SoS sign, is unchanged (predicates.hpp).
inline PointSet sub_points(const PointSet& ps, const std::vector<Index>& idx) {
  PointSet out;
  out.dim = ps.dim;
  for (Index i : idx) out.coords.insert(out.coords.end(), ps.point(i), ps.point(i) + ps.dim);
  return out;
}

inline std::vector<Index> vertex_set(const std::vector<Triangle>& tris) {
  std::set<Index> v;
  for (const Triangle& t : tris) v.insert(t.begin(), t.end());
  return {v.begin(), v.end()};
}

// brute::hull3 of the vertices of a surface, in the indices of ps.
inline std::vector<Triangle> brute_hull_of_vertices(const PointSet& ps, const std::vector<Triangle>& tris) {
  const std::vector<Index> V = vertex_set(tris);
  std::vector<Triangle> h = brute::hull3(sub_points(ps, V));
  for (Triangle& t : h)
    for (Index& x : t) x = V[x];
  return canonical_triangles(h);
}

// The kernel ffHull uses: the exact centroid of its initial tetrahedron.
inline ref::RationalKernel ffhull_kernel(const PointSet& ps) {
  const auto tet = ref::ffhull::initial_tetrahedron(ps);
  return ref::centroid_kernel(ps, tet[0], tet[1], tet[2], tet[3]);
}

// A star-shaped polyhedron around ffHull's kernel built by Algorithm 7's
// constructing stage with other choices: a random associated point instead of
// the furthest, inner points inserted as dents instead of discarded.
inline std::vector<Triangle> random_star_polyhedron(const PointSet& ps, const ref::KernelPoint& s, bool furthest,
                                                    bool discard_inside, std::uint64_t seed) {
  ref::ffhull::BuildOptions o;
  o.furthest = furthest;
  o.discard_inside = discard_inside;
  o.seed = seed;
  return ref::ffhull::construct(ps, s, ref::ffhull::initial_tetrahedron(ps), o, nullptr);
}

// Four exactly affinely independent points of ps chosen at random (seeded),
// ordered like ffhull::initial_tetrahedron: (a, b, c) counter-clockwise seen
// from outside, d on its inner side. ps must span R^3.
inline std::array<Index, 4> random_tetrahedron(const PointSet& ps, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto n = static_cast<Index>(ps.size());
  for (;;) {
    std::array<Index, 4> t;
    for (Index& x : t) x = static_cast<Index>(rng() % n);
    const int o = pred::orient3d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), ps.point(t[3]));
    if (o == 0) continue;
    if (o < 0) std::swap(t[1], t[2]);
    return t;
  }
}

// A star-shaped polyhedron whose every point is a vertex, around the centroid
// of a random tetrahedron (not necessarily of extreme points): Algorithm 7's
// constructing stage from that tetrahedron, random insertion order, inner
// points inserted as dents. Returns the kernel too.
struct StarStart {
  ref::RationalKernel s;
  std::vector<Triangle> surface;
};
inline StarStart random_start(const PointSet& ps, std::uint64_t seed) {
  const auto t = random_tetrahedron(ps, seed);
  ref::RationalKernel s = ref::centroid_kernel(ps, t[0], t[1], t[2], t[3]);
  ref::ffhull::BuildOptions o;
  o.furthest = false;
  o.discard_inside = false;
  o.seed = seed;
  std::vector<Triangle> surface = ref::ffhull::construct(ps, s, t, o, nullptr);
  return {std::move(s), std::move(surface)};
}

// A polyhedron star-shaped w.r.t. (about) the centroid c by central
// projection: CGAL's hull of the points moved onto the unit sphere around c
// (in floating point), taken as a surface over the original points. Points
// projecting onto the same direction are represented once; the result is not
// star-shaped in rare rounding cases — callers check it exactly.
inline std::vector<Triangle> central_projection_surface(const PointSet& ps, const double c[3]) {
  PointSet q;
  q.dim = 3;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    double d[3], len = 0;
    for (int j = 0; j < 3; ++j) d[j] = ps.point(i)[j] - c[j], len += d[j] * d[j];
    len = std::sqrt(len);
    for (int j = 0; j < 3; ++j) q.coords.push_back(len > 0 ? d[j] / len : 0.0);
  }
  return peers::cgal_hull3(q);
}

// ---- Figure 6.1 ------------------------------------------------------------
// "A tetrahedron gabc is initialized where △abc is equilateral and horizontal.
// Another equilateral and horizontal triangle △def is embedded into △abc and
// lower than △abc. After twisting △def a bit, all dashed edges are reflex but
// flipping them creates self-intersection." With integer (exact) coordinates:
// abc of circumradius 1000 at height 0 (rounded to integers: equilateral up to
// rounding), g = (0, 0, -1500) below it, def of circumradius 500 at height
// -100 inside the tetrahedron, twisted by -10 degrees (coordinates rounded);
// the face abc is replaced by the band of six triangles between abc and def
// and the triangle def: a twisted dent. Indices a b c d e f g = 0..6.
struct Figure61 {
  PointSet ps;
  std::vector<Triangle> surface;
  double kernel[3];  // a point of the kernel of the surface (exact: an integer)
};

inline Figure61 figure_6_1() {
  Figure61 f;
  f.ps.dim = 3;
  f.ps.coords = {1000, 0,    0,    -500, 866,  0,    -500, -866, 0,    // a b c
                 492,  -87,  -100, -171, 470,  -100, -321, -383, -100,  // d e f
                 0,    0,    -1500};                                   // g
  f.surface = {{0, 6, 1}, {1, 6, 2}, {2, 6, 0},                          // tetrahedron sides
               {0, 1, 3}, {1, 4, 3}, {1, 2, 4}, {2, 5, 4}, {2, 0, 5}, {0, 3, 5},  // band
               {3, 4, 5}};                                               // def
  f.kernel[0] = 0, f.kernel[1] = 0, f.kernel[2] = -1000;
  return f;
}

// An exact witness that a triangulated surface intersects itself: an edge
// crossing a triangle that shares no vertex with it (its endpoints strictly
// on both sides of the triangle's plane, the segment's line strictly inside
// the triangle). For two triangles meeting in at most one vertex that do
// intersect beyond it (in non-degenerate position) such an edge exists.
inline bool self_intersects(const PointSet& ps, const std::vector<Triangle>& tris) {
  auto O = [&](Index a, Index b, Index c, Index d) {
    return pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d));
  };
  std::set<std::pair<Index, Index>> E;
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) E.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  for (const auto& [p, q] : E)
    for (const Triangle& t : tris) {
      if (std::count(t.begin(), t.end(), p) || std::count(t.begin(), t.end(), q)) continue;
      const int o1 = O(t[0], t[1], t[2], p), o2 = O(t[0], t[1], t[2], q);
      if (o1 * o2 >= 0) continue;
      const int s1 = O(p, q, t[0], t[1]), s2 = O(p, q, t[1], t[2]), s3 = O(p, q, t[2], t[0]);
      if (s1 != 0 && s1 == s2 && s2 == s3) return true;
    }
  return false;
}

}  // namespace flipflop::test

// cgal_hull.cpp — CGAL's convex hulls as peers (2D: ch_akl_toussaint,
// ch_graham_andrew; 3D: convex_hull_3), all with Epick, whose predicates are
// exact (filtered, then exact arithmetic). One translation unit for all CGAL
// hull code keeps the build short.
#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/ch_akl_toussaint.h>
#include <CGAL/ch_graham_andrew.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstring>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "reference/canonical.hpp"
#include "peers/peers.hpp"

namespace flipflop::peers {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;

void require_dim(const PointSet& pts, int dim, const char* who) {
  if (pts.dim != dim)
    throw std::invalid_argument(std::string(who) + ": expected " + std::to_string(dim) +
                                "D points, got " + std::to_string(pts.dim) + "D");
}

// Hash of a location; +0.0 folds -0.0 into 0.0 so that equal points (which
// compare equal as doubles) hash equally.
struct LocationHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::size_t h = 0;
    for (double c : p) {
      double z = c + 0.0;
      std::uint64_t bits;
      std::memcpy(&bits, &z, sizeof bits);
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

std::array<double, 3> location(const P3& p) { return {p.x(), p.y(), p.z()}; }

// The hull of `pts` as a closed triangulated Surface_mesh plus, per mesh vertex,
// the smallest input index at its location.
struct Hull3 {
  Mesh mesh;
  Mesh::Property_map<Mesh::Vertex_index, Index> index;
};

Hull3 hull3(const PointSet& pts, const char* who) {
  require_dim(pts, 3, who);
  std::vector<P3> points;
  points.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double* p = pts.point(i);
    points.emplace_back(p[0], p[1], p[2]);
  }
  Hull3 h;
  CGAL::convex_hull_3(points.begin(), points.end(), h.mesh);
  if (h.mesh.number_of_faces() < 4 || !CGAL::is_closed(h.mesh) ||
      !CGAL::is_triangle_mesh(h.mesh))
    throw std::runtime_error(std::string(who) +
                             ": input is lower-dimensional (fewer than four affinely "
                             "independent points)");
  // Mesh vertices carry coordinates only: map locations back to indices by one
  // scan of the input in index order, so the smallest index at a location wins.
  constexpr Index kUnset = ~Index{0};
  h.index = h.mesh.add_property_map<Mesh::Vertex_index, Index>("v:input_index", kUnset).first;
  std::unordered_map<std::array<double, 3>, Mesh::Vertex_index, LocationHash> at;
  at.reserve(2 * h.mesh.number_of_vertices());
  for (Mesh::Vertex_index v : h.mesh.vertices()) at.emplace(location(h.mesh.point(v)), v);
  std::size_t found = 0;
  for (std::size_t i = 0; i < points.size() && found < at.size(); ++i) {
    auto it = at.find(location(points[i]));
    if (it != at.end() && h.index[it->second] == kUnset) {
      h.index[it->second] = static_cast<Index>(i);
      ++found;
    }
  }
  if (found != h.mesh.number_of_vertices())
    throw std::logic_error(std::string(who) + ": a hull vertex is not an input point");
  return h;
}

// The three vertices of a triangular face, in the face's (outward,
// counter-clockwise) order.
std::array<Mesh::Vertex_index, 3> face_vertices(const Mesh& m, Mesh::Face_index f) {
  Mesh::Halfedge_index e = m.halfedge(f);
  return {m.target(e), m.target(m.next(e)), m.target(m.next(m.next(e)))};
}

}  // namespace

std::vector<Index> cgal_hull2(const PointSet& pts, Hull2Algo algo) {
  require_dim(pts, 2, "cgal_hull2");
  std::vector<P2> points;
  points.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) points.emplace_back(pts.point(i)[0], pts.point(i)[1]);
  // The algorithms run on indices; the adapter reads their points through a
  // property map (CGAL's documented way of keeping indices).
  std::vector<std::size_t> ids(points.size());
  std::iota(ids.begin(), ids.end(), std::size_t{0});
  using Traits = CGAL::Convex_hull_traits_adapter_2<K, CGAL::Pointer_property_map<P2>::type>;
  Traits traits(CGAL::make_property_map(points));
  std::vector<std::size_t> out;
  if (algo == Hull2Algo::akl_toussaint)
    CGAL::ch_akl_toussaint(ids.begin(), ids.end(), std::back_inserter(out), traits);
  else
    CGAL::ch_graham_andrew(ids.begin(), ids.end(), std::back_inserter(out), traits);
  if (out.size() < 3)
    throw std::runtime_error("cgal_hull2: input is lower-dimensional (all points collinear)");
  std::vector<Index> cycle(out.begin(), out.end());  // counter-clockwise
  return canonical_hull2(std::move(cycle));
}

std::vector<Triangle> cgal_hull3(const PointSet& pts) {
  Hull3 h = hull3(pts, "cgal_hull3");
  std::vector<Triangle> tris;
  tris.reserve(h.mesh.number_of_faces());
  for (Mesh::Face_index f : h.mesh.faces()) {
    auto v = face_vertices(h.mesh, f);
    tris.push_back({h.index[v[0]], h.index[v[1]], h.index[v[2]]});
  }
  return canonical_triangles(std::move(tris));
}

std::vector<Index> cgal_extreme_points_3(const PointSet& pts) {
  Hull3 h = hull3(pts, "cgal_extreme_points_3");
  const Mesh& m = h.mesh;
  std::vector<Index> extreme;
  for (Mesh::Vertex_index v : m.vertices()) {
    // Distinct supporting planes among the facets around v (exact test): one
    // plane = v inside a hull facet, two = inside a hull edge, >= 3 = a vertex.
    std::vector<std::array<P3, 3>> planes;
    for (Mesh::Face_index f : CGAL::faces_around_target(m.halfedge(v), m)) {
      auto fv = face_vertices(m, f);
      std::array<P3, 3> tri = {m.point(fv[0]), m.point(fv[1]), m.point(fv[2])};
      bool known = false;
      for (const auto& pl : planes) {
        bool same = true;
        for (const P3& q : tri) same = same && CGAL::coplanar(pl[0], pl[1], pl[2], q);
        if (same) {
          known = true;
          break;
        }
      }
      if (!known) planes.push_back(tri);
      if (planes.size() >= 3) break;
    }
    if (planes.size() >= 3) extreme.push_back(h.index[v]);
  }
  std::sort(extreme.begin(), extreme.end());
  return extreme;
}

}  // namespace flipflop::peers

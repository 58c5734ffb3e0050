// cgal_triangulation.cpp — CGAL's 2D Delaunay and regular triangulations as
// peers (Epick: exact predicates). Input indices ride along as vertex info.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_face_base_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "reference/canonical.hpp"
#include "peers/peers.hpp"

namespace flipflop::peers {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

void require_dim(const PointSet& pts, const char* who) {
  if (pts.dim != 2)
    throw std::invalid_argument(std::string(who) + ": expected 2D points, got " +
                                std::to_string(pts.dim) + "D");
}

// Finite faces (CGAL stores faces counter-clockwise) as index triangles.
template <class T>
std::vector<Triangle> finite_triangles(const T& t) {
  std::vector<Triangle> tris;
  tris.reserve(t.number_of_faces());
  for (auto f : t.finite_face_handles())
    tris.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return canonical_triangles(std::move(tris));
}

}  // namespace

std::vector<Triangle> cgal_delaunay2(const PointSet& pts) {
  require_dim(pts, "cgal_delaunay2");
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
  std::vector<std::pair<K::Point_2, Index>> input;
  input.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    input.emplace_back(K::Point_2(pts.point(i)[0], pts.point(i)[1]), static_cast<Index>(i));
  DT dt(input.begin(), input.end());  // spatially sorted insertion
  if (dt.dimension() < 2)
    throw std::runtime_error("cgal_delaunay2: input is lower-dimensional (all points collinear)");
  return finite_triangles(dt);
}

std::vector<Triangle> cgal_regular2(const PointSet& weighted, double* build_seconds) {
  require_dim(weighted, "cgal_regular2");
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<
      Index, K, CGAL::Regular_triangulation_vertex_base_2<K>>;
  using Fb = CGAL::Regular_triangulation_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using RT = CGAL::Regular_triangulation_2<K, Tds>;
  std::vector<std::pair<RT::Weighted_point, Index>> input;
  input.reserve(weighted.size());
  for (std::size_t i = 0; i < weighted.size(); ++i) {
    // CGAL's weight is the squared radius: power(x, (p, w)) = |x - p|^2 - w.
    input.emplace_back(
        RT::Weighted_point(K::Point_2(weighted.point(i)[0], weighted.point(i)[1]),
                           weighted.weight(i)),
        static_cast<Index>(i));
  }
  const auto t0 = std::chrono::steady_clock::now();
  RT rt(input.begin(), input.end());
  if (build_seconds)
    *build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rt.dimension() < 2)
    throw std::runtime_error(
        "cgal_regular2: the regular triangulation is lower-dimensional (its non-redundant "
        "points are collinear)");
  return finite_triangles(rt);
}

}  // namespace flipflop::peers

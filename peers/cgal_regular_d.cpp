// cgal_regular_d.cpp — CGAL's dD Regular_triangulation (Epick_d) and
// Regular_triangulation_3 as peers. See cgal_regular_d.hpp.
//
// Orientation: the output is positive in the volume convention
// (det[p_1 - p_0, ..., p_d - p_0] > 0, reference/rtd/canonical_d.hpp), in
// which the reference simplex (0, e_1, ..., e_d) is positive (det I = 1).
// CGAL's Orientation_d documents the same convention; rather than rely on
// it, CGAL's sign of that reference simplex is asked at run time, and a
// cell's volume sign is CGAL's sign times that one — on points in general
// position, where both are non-zero.
// GCC's -Warray-bounds misfires inside Eigen's fixed-capacity matrices that
// Epick_d instantiates (a false positive in third-party code, reported at
// the instantiation point, so it cannot be scoped to the includes).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED 1  // Epick_d's linear algebra (Eigen 3, linked by peers/CMakeLists.txt)
#endif
#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "peers/cgal_regular_d.hpp"
#include "reference/rtd/canonical_d.hpp"

namespace flipflop::peers {

namespace {


template <int D>
std::vector<std::vector<Index>> regular_d(const PointSet& ps, std::vector<Index>* redundant, double* build_seconds) {
  using K = CGAL::Epick_d<CGAL::Dimension_tag<D>>;
  using Traits = CGAL::Regular_triangulation_traits_adapter<K>;
  using Vb = CGAL::Triangulation_vertex<Traits, Index>;
  using Cb = CGAL::Triangulation_full_cell<Traits>;
  using Tds = CGAL::Triangulation_data_structure<typename K::Dimension, Vb, Cb>;
  using RT = CGAL::Regular_triangulation<K, Tds>;
  using Point = typename K::Point_d;
  using WPoint = typename K::Weighted_point_d;

  const auto t0 = std::chrono::steady_clock::now();
  RT rt(D);
  typename RT::Vertex_handle hint;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* x = ps.point(i);
    WPoint wp(Point(D, x, x + D), ps.weight(i));
    auto v = hint == typename RT::Vertex_handle() ? rt.insert(wp) : rt.insert(wp, hint);
    if (v != typename RT::Vertex_handle()) {
      v->data() = static_cast<Index>(i);
      hint = v;
    }
  }
  if (build_seconds)
    *build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rt.current_dimension() < D)
    throw std::runtime_error("cgal_regular_d: the regular triangulation is lower-dimensional");
  auto ori = K().orientation_d_object();
  std::vector<Point> ref;
  {
    std::vector<double> e(D, 0.0);
    ref.emplace_back(D, e.begin(), e.end());
    for (int j = 0; j < D; ++j) {
      std::fill(e.begin(), e.end(), 0.0);
      e[static_cast<std::size_t>(j)] = 1.0;
      ref.emplace_back(D, e.begin(), e.end());
    }
  }
  const int ratio = static_cast<int>(ori(ref.begin(), ref.end()));  // the volume sign of ref is +1
  std::vector<std::vector<Index>> out;
  for (auto c = rt.finite_full_cells_begin(); c != rt.finite_full_cells_end(); ++c) {
    std::vector<Index> t;
    std::vector<Point> pts;
    for (int j = 0; j <= D; ++j) {
      t.push_back(c->vertex(j)->data());
      pts.push_back(c->vertex(j)->point().point());
    }
    const int sign = static_cast<int>(ori(pts.begin(), pts.end())) * ratio;
    if (sign == 0) throw std::runtime_error("cgal_regular_d: a flat cell (degenerate input)");
    if (sign < 0) std::swap(t[0], t[1]);
    out.push_back(std::move(t));
  }
  out = canonical_simplices(std::move(out), Orientation::volume);
  if (redundant) *redundant = non_vertices(ps.size(), out);
  return out;
}

template <int D>
int orientation_d(const PointSet& ps, const std::vector<Index>& tuple) {
  using K = CGAL::Epick_d<CGAL::Dimension_tag<D>>;
  using Point = typename K::Point_d;
  std::vector<Point> pts;
  for (Index i : tuple) pts.emplace_back(D, ps.point(i), ps.point(i) + D);
  return static_cast<int>(K().orientation_d_object()(pts.begin(), pts.end()));
}

// f(std::integral_constant<int, D>) for D = d in 2..5 (Epick_d's fixed
// dimension tags), else std::invalid_argument naming `who`.
template <class F>
auto with_dimension(int d, const char* who, F f) {
  switch (d) {
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
    case 4: return f(std::integral_constant<int, 4>{});
    case 5: return f(std::integral_constant<int, 5>{});
    default:
      throw std::invalid_argument(std::string(who) + ": expected 2..5-dimensional points, got " + std::to_string(d) + "D");
  }
}

}  // namespace

int cgal_orientation_d(const PointSet& ps, const std::vector<Index>& tuple) {
  if (tuple.size() != static_cast<std::size_t>(ps.dim + 1))
    throw std::invalid_argument("cgal_orientation_d: a " + std::to_string(ps.dim) + "-simplex has " +
                                std::to_string(ps.dim + 1) + " vertices");
  return with_dimension(ps.dim, "cgal_orientation_d", [&](auto D) { return orientation_d<D()>(ps, tuple); });
}

std::vector<std::vector<Index>> cgal_regular_d(const PointSet& ps, std::vector<Index>* redundant,
                                               double* build_seconds) {
  return with_dimension(ps.dim, "cgal_regular_d", [&](auto D) { return regular_d<D()>(ps, redundant, build_seconds); });
}

std::vector<std::vector<Index>> cgal_regular_3(const PointSet& ps, std::vector<Index>* redundant,
                                               double* build_seconds) {
  if (ps.dim != 3)
    throw std::invalid_argument("cgal_regular_3: expected 3D points, got " + std::to_string(ps.dim) + "D");
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
  using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
  using RT = CGAL::Regular_triangulation_3<K, Tds>;
  std::vector<std::pair<RT::Weighted_point, Index>> input;
  input.reserve(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* x = ps.point(i);
    input.emplace_back(RT::Weighted_point(K::Point_3(x[0], x[1], x[2]), ps.weight(i)), static_cast<Index>(i));
  }
  const auto t0 = std::chrono::steady_clock::now();
  RT rt(input.begin(), input.end());
  if (build_seconds)
    *build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rt.dimension() < 3)
    throw std::runtime_error("cgal_regular_3: the regular triangulation is lower-dimensional");
  // the volume sign of (0, e1, e2, e3) is +1; ask CGAL for its own
  const int ratio = static_cast<int>(CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0),
                                                      K::Point_3(0, 0, 1)));
  std::vector<std::vector<Index>> out;
  for (auto c : rt.finite_cell_handles()) {
    std::vector<Index> t;
    for (int j = 0; j < 4; ++j) t.push_back(c->vertex(j)->info());
    const int sign = static_cast<int>(CGAL::orientation(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                                                        c->vertex(2)->point().point(), c->vertex(3)->point().point())) *
                     ratio;
    if (sign == 0) throw std::runtime_error("cgal_regular_3: a flat cell (degenerate input)");
    if (sign < 0) std::swap(t[0], t[1]);
    out.push_back(std::move(t));
  }
  out = canonical_simplices(std::move(out), Orientation::volume);
  if (redundant) *redundant = non_vertices(ps.size(), out);
  return out;
}

}  // namespace flipflop::peers

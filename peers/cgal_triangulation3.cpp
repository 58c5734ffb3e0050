// cgal_triangulation3.cpp — CGAL's Delaunay_triangulation_3 and
// Regular_triangulation_3, sequential and parallel, as peers
// (triangulation3.hpp), and the canonical form of tetrahedron lists.
//
// Orientation. Triangulation_3 keeps every finite cell positively oriented in
// CGAL's orientation (CGAL manual, "3D Triangulation Data Structure":
// orientation(v0, v1, v2, v3) == POSITIVE for every finite cell), so one cell
// settles the sign for all: its CGAL orientation times CGAL's orientation of
// the reference simplex (0, e1, e2, e3), whose volume sign is +1 by
// definition. (proptests/rt3_cgal_oracle_test.cpp checks every cell's
// orientation against the exact answer.)
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/bounding_box.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "peers/triangulation3.hpp"

#ifndef CGAL_LINKED_WITH_TBB
#error "peers/cgal_triangulation3.cpp needs CGAL with TBB (CGAL::TBB_support, peers/CMakeLists.txt)"
#endif

namespace flipflop::peers {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Seconds since t0.
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The volume sign of CGAL's POSITIVE (+1 where CGAL's orientation is the
// volume convention, as documented).
int volume_sign_of_positive() {
  return static_cast<int>(
      CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1)));
}

// The finite cells of t as canonical tetrahedra of input indices (vertex info).
template <class T, class PointOf>
std::vector<Tet> finite_tets(const T& t, PointOf point_of, const char* who) {
  std::vector<Tet> out;
  out.reserve(t.number_of_finite_cells());
  for (auto c : t.finite_cell_handles())
    out.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  if (out.empty()) return out;
  auto c = *t.finite_cell_handles().begin();
  const int sign = static_cast<int>(CGAL::orientation(point_of(c->vertex(0)), point_of(c->vertex(1)),
                                                      point_of(c->vertex(2)), point_of(c->vertex(3)))) *
                   volume_sign_of_positive();
  if (sign == 0) throw std::runtime_error(std::string(who) + ": a flat cell");
  if (sign < 0)
    for (Tet& x : out) std::swap(x[0], x[1]);
  return canonical_tets(std::move(out));
}

// Builds T from the (point, index) range: sequentially, or with a lock data
// structure on o.threads threads (Cgal3Options).
template <class T, class Input>
std::vector<Tet> build(const PointSet& ps, const std::vector<Input>& input, const Cgal3Options& o, const char* who) {
  auto point_of = [](auto v) -> K::Point_3 {
    if constexpr (std::is_same_v<typename T::Point, K::Point_3>)
      return v->point();
    else
      return v->point().point();
  };
  auto t0 = std::chrono::steady_clock::now();
  if constexpr (std::is_same_v<typename T::Triangulation_data_structure::Concurrency_tag, CGAL::Parallel_tag>) {
    CGAL::Bbox_3 box;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const double* x = ps.point(i);
      box += CGAL::Bbox_3(x[0], x[1], x[2], x[0], x[1], x[2]);
    }
    t0 = std::chrono::steady_clock::now();
    typename T::Lock_data_structure locks(box, 50);
    std::vector<Tet> out;
    auto run = [&] {
      T t(input.begin(), input.end(), &locks);
      if (o.build_seconds) *o.build_seconds = since(t0);
      if (t.dimension() < 3)
        throw std::runtime_error(std::string(who) + ": the triangulation is lower-dimensional (the points do not span R^3)");
      out = finite_tets(t, point_of, who);
    };
    if (o.threads > 0) {  // exactly o.threads, also beyond the cores (kernels_cpu/parallel.hpp's with_threads)
      tbb::global_control allow(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(o.threads));
      tbb::task_arena arena(o.threads);
      arena.execute(run);
    } else {
      run();
    }
    return out;
  } else {
    T t(input.begin(), input.end());
    if (o.build_seconds) *o.build_seconds = since(t0);
    if (t.dimension() < 3)
      throw std::runtime_error(std::string(who) + ": the triangulation is lower-dimensional (the points do not span R^3)");
    return finite_tets(t, point_of, who);
  }
}

template <class Tag>
std::vector<Tet> delaunay(const PointSet& ps, const Cgal3Options& o) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
  using Cb = CGAL::Delaunay_triangulation_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, Tag>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, Index>> input;
  input.reserve(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* x = ps.point(i);
    input.emplace_back(K::Point_3(x[0], x[1], x[2]), static_cast<Index>(i));
  }
  return build<DT>(ps, input, o, "cgal_delaunay3");
}

template <class Tag>
std::vector<Tet> regular(const PointSet& ps, const Cgal3Options& o) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
  using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, Tag>;
  using RT = CGAL::Regular_triangulation_3<K, Tds>;
  std::vector<std::pair<typename RT::Weighted_point, Index>> input;
  input.reserve(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* x = ps.point(i);
    input.emplace_back(typename RT::Weighted_point(K::Point_3(x[0], x[1], x[2]), ps.weight(i)), static_cast<Index>(i));
  }
  return build<RT>(ps, input, o, "cgal_regular3");
}

void require_3d(const PointSet& ps, const char* who) {
  if (ps.dim != 3)
    throw std::invalid_argument(std::string(who) + ": expected 3D points, got " + std::to_string(ps.dim) + "D");
}

}  // namespace

std::vector<Tet> canonical_tets(std::vector<Tet> tets) {
  Index n = 0;
  for (Tet& t : tets) {
    // Parity of the sorting permutation (canonical_d.hpp's rule, on arrays):
    // a sorting network of 5 compare-exchanges, each swap one transposition.
    bool odd = false;
    auto cx = [&](int i, int j) {
      if (t[j] < t[i]) {
        std::swap(t[i], t[j]);
        odd = !odd;
      }
    };
    cx(0, 1), cx(2, 3), cx(0, 2), cx(1, 3), cx(1, 2);
    if (odd) std::swap(t[2], t[3]);
    n = std::max(n, t[0] + 1);
  }
  // counting sort by the smallest index, then each bucket in order
  std::vector<std::size_t> start(static_cast<std::size_t>(n) + 1, 0);
  for (const Tet& t : tets) ++start[t[0] + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<Tet> out(tets.size());
  {
    std::vector<std::size_t> at(start.begin(), start.end() - 1);
    for (const Tet& t : tets) out[at[t[0]]++] = t;
  }
  for (std::size_t b = 0; b + 1 < start.size(); ++b)
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(start[b]), out.begin() + static_cast<std::ptrdiff_t>(start[b + 1]));
  return out;
}

std::vector<Tet> cgal_delaunay3(const PointSet& ps, const Cgal3Options& o) {
  require_3d(ps, "cgal_delaunay3");
  return o.parallel ? delaunay<CGAL::Parallel_tag>(ps, o) : delaunay<CGAL::Sequential_tag>(ps, o);
}

std::vector<Tet> cgal_regular3(const PointSet& ps, const Cgal3Options& o) {
  require_3d(ps, "cgal_regular3");
  return o.parallel ? regular<CGAL::Parallel_tag>(ps, o) : regular<CGAL::Sequential_tag>(ps, o);
}

}  // namespace flipflop::peers

// module.cpp — flipflop._flipflop, the compiled half of the Python package
// (python/flipflop/__init__.py is the public half: argument checking, the
// scipy-like classes, derived floating-point attributes).
//
// Every function takes C-contiguous float64 numpy arrays (checked and made
// so by the Python half), reads them in place through a borrowing PointSet
// (no copy: reference/values.hpp; the arrays must not be written by another
// thread during the call), releases the GIL while computing, and returns new numpy arrays (int64
// indices). Results are certified at the canonical level before they are
// returned, as on the command line: a result that fails is never returned
// (RuntimeError). Input the algorithms reject (too few points,
// lower-dimensional input, an unknown name) raises std::invalid_argument,
// which nanobind turns into ValueError.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "kernels_cpu/rt2/certify_rt2.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#include "predicates/predicates.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/hull3/strict_hull3.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/strict_rt2.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "kernels_cpu/rtd/instant_flip.hpp"
#include "reference/rtd/dynamic_rt.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace nb = nanobind;
using namespace flipflop;

namespace {

using Points = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using Vector = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using Cells = nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using IndexArray = nb::ndarray<nb::numpy, std::int64_t>;

PointSet point_set(const Points& p, const std::optional<Vector>& w) {
  PointSet ps;
  ps.dim = static_cast<int>(p.shape(1));
  // Read in place (reference/values.hpp): the array is C-contiguous float64
  // and nanobind holds a reference to it for the whole call.
  ps.coords = Values::borrow(p.data(), p.shape(0) * p.shape(1));
  if (w) {
    if (w->shape(0) != p.shape(0))
      throw std::invalid_argument(std::to_string(w->shape(0)) + " weights for " + std::to_string(p.shape(0)) +
                                  " points");
    ps.weighted = true;
    ps.weights = Values::borrow(w->data(), w->shape(0));
  }
  const PointSet& read = ps;  // const: reading a borrowed array never copies it
  for (double x : read.coords)
    if (!std::isfinite(x)) throw std::invalid_argument("the points hold NaN or infinite coordinates");
  for (double x : read.weights)
    if (!std::isfinite(x)) throw std::invalid_argument("the weights hold NaN or infinite values");
  return ps;
}

// For the tests: whether point_set reads the arrays in place (no copy).
bool reads_in_place(const Points& p, const std::optional<Vector>& w) {
  const PointSet ps = point_set(p, w);
  return ps.coords.borrowed() && ps.coords.data() == p.data() &&
         (!w || (ps.weights.borrowed() && ps.weights.data() == w->data()));
}

void require_spanning(const PointSet& ps) {
  if (std::string why = dimension_problem(ps); !why.empty()) throw std::invalid_argument(why);
}

// A new int64 array owning its data.
IndexArray index_array(std::vector<std::int64_t> v, std::size_t rows, std::size_t cols, bool one_dim = false) {
  auto* heap = new std::vector<std::int64_t>(std::move(v));
  nb::capsule owner(heap, [](void* p) noexcept { delete static_cast<std::vector<std::int64_t>*>(p); });
  if (one_dim) {
    const std::size_t shape[1] = {rows};
    return IndexArray(heap->data(), 1, shape, owner);
  }
  const std::size_t shape[2] = {rows, cols};
  return IndexArray(heap->data(), 2, shape, owner);
}

template <class Cell>
IndexArray cells_array(const std::vector<Cell>& cells, std::size_t k) {
  std::vector<std::int64_t> v;
  v.reserve(cells.size() * k);
  for (const auto& c : cells)
    for (std::size_t j = 0; j < k; ++j) v.push_back(static_cast<std::int64_t>(c[j]));
  return index_array(std::move(v), cells.size(), k);
}

IndexArray list_array(const std::vector<Index>& l) {
  std::vector<std::int64_t> v(l.begin(), l.end());
  return index_array(std::move(v), l.size(), 0, true);
}

void check_certified(const certify::Report& r, const char* what) {
  if (!r.ok) throw std::runtime_error(std::string("the ") + what + " result failed certification: " + r.message());
}

std::vector<std::vector<Index>> cell_lists(const Cells& c, std::size_t n) {
  std::vector<std::vector<Index>> out(c.shape(0));
  for (std::size_t i = 0; i < c.shape(0); ++i)
    for (std::size_t j = 0; j < c.shape(1); ++j) {
      const std::int64_t x = c.data()[i * c.shape(1) + j];
      if (x < 0 || static_cast<std::size_t>(x) >= n)
        throw std::invalid_argument("simplex " + std::to_string(i) + " names point " + std::to_string(x) +
                                    " but there are " + std::to_string(n) + " points");
      out[i].push_back(static_cast<Index>(x));
    }
  return out;
}

std::vector<Triangle> triangles_of(const std::vector<std::vector<Index>>& cells) {
  std::vector<Triangle> t;
  for (const auto& c : cells) {
    if (c.size() != 3) throw std::invalid_argument("expected triangles (3 indices per row)");
    t.push_back({c[0], c[1], c[2]});
  }
  return t;
}

// ---- hulls -------------------------------------------------------------------

IndexArray hull2(const Points& p, const std::string& backend, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 2) throw std::invalid_argument("hull2 expects points of shape (n, 2)");
  std::vector<Index> cycle;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (backend == "cpu") {
      cpu::Hull2Options o;
      o.threads = threads;
      cycle = cpu::hull2_graham_sort(ps, o);
      check_certified(cpu::certify_hull2(ps, cycle, certify::Level::canonical, threads), "hull2");
    } else if (backend == "reference") {
      cycle = ref::hull2(ps, ref::hull2_algorithms().front());
      check_certified(certify::hull2(ps, cycle, certify::Level::canonical), "hull2");
    } else {
      throw std::invalid_argument("hull2 backends: 'cpu', 'reference'; got '" + backend + "'");
    }
  }
  return list_array(cycle);
}

IndexArray hull3(const Points& p, const std::string& backend, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 3) throw std::invalid_argument("hull3 expects points of shape (n, 3)");
  std::vector<Triangle> tris;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (backend == "cpu") {  // certified from the kernel's witness, as `flipflop hull3`
      cpu::Hull3Options o;
      o.threads = threads;
      cpu::Hull3Witness witness;
      o.witness = &witness;
      tris = cpu::hull3_ffhull(ps, o);
      check_certified(cpu::certify_hull3_witnessed(ps, tris, certify::Level::canonical, witness, threads), "hull3");
    } else if (backend == "reference") {
      tris = ref::hull3(ps, "ffhull");
      check_certified(certify::hull3(ps, tris, certify::Level::canonical), "hull3");
    } else {
      throw std::invalid_argument("hull3 backends: 'cpu', 'reference'; got '" + backend + "'");
    }
  }
  return cells_array(tris, 3);
}

// The strict view: (extreme points, facets as lists) — polygons, or with
// `triangulate` triangles fanned from the smallest vertex.
std::pair<IndexArray, std::vector<std::vector<Index>>> hull3_strict(const Points& p, bool triangulate) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 3) throw std::invalid_argument("hull3 expects points of shape (n, 3)");
  ref::StrictHull3 h;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    const std::vector<Triangle> tris = cpu::hull3_ffhull(ps);
    check_certified(cpu::certify_hull3(ps, tris, certify::Level::canonical), "hull3");
    h = ref::strict_hull3(ps, tris);
    if (triangulate) h = ref::fan_triangulated(h);
  }
  return {list_array(h.extreme_points), h.facets};
}

// ---- triangulations ------------------------------------------------------------

// (simplices, redundant) of RT(S ⊕ W) (W = 0 without weights): d = 2 by the
// cpu backend (kernels_cpu/rt2) or ffRT (the 2D reference), d = 3..5 by
// RT+1; all canonical.
std::pair<IndexArray, IndexArray> triangulate(const Points& p, const std::optional<Vector>& w,
                                              const std::string& backend, bool strict, int threads) {
  const PointSet ps = point_set(p, w);
  const int d = ps.dim;
  if (d < 2 || d > 5) throw std::invalid_argument("Delaunay expects points of shape (n, d) with d = 2..5");
  if (!(backend == "reference" || (backend == "cpu" && d == 2)))
    throw std::invalid_argument("Delaunay backends: 'cpu' (2D), 'reference'; got '" + backend + "'");
  if (strict && d != 2)
    throw std::invalid_argument("Delaunay: the strict view (no zero-volume simplex) exists for 2D input only");
  std::vector<std::vector<Index>> simplices;
  std::vector<Index> redundant;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (d == 2) {
      cpu::Rt2Options o;
      o.threads = threads;
      std::vector<Triangle> tris;
      if (backend == "cpu") {  // certified from the kernel's witness, as `flipflop rt2|dt2`
        cpu::Rt2Witness witness;
        tris = cpu::rt2(ps, o, nullptr, &witness);
        check_certified(cpu::certify_rt2(ps, tris, certify::Level::canonical, witness, threads), "Delaunay");
      } else {
        tris = ref::rt2_ffrt(ps);
        check_certified(certify::rt2(ps, tris, certify::Level::canonical), "Delaunay");
      }
      if (strict) {
        tris = ref::strict_rt2(ps, tris);
        check_certified(certify::rt2_strict(ps, tris), "strict Delaunay");
      }
      for (const Triangle& t : tris) simplices.push_back({t[0], t[1], t[2]});
      redundant = non_vertices(ps.size(), simplices);
    } else {
      ref::Rtd r = ref::rtd_incremental(ps);
      check_certified(certify::rtd(ps, r.simplices), "Delaunay");
      simplices = std::move(r.simplices);
      redundant = std::move(r.redundant);
    }
  }
  return {cells_array(simplices, static_cast<std::size_t>(d + 1)), list_array(redundant)};
}

// neighbors[i][j]: the simplex across the facet opposite vertex j of
// simplex i, -1 on the boundary (scipy's convention).
IndexArray neighbors(const Cells& c) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  if (k < 2 || k > 6) throw std::invalid_argument("neighbors expects simplices of shape (m, k) with k = 2..6");
  std::vector<std::int64_t> nb(m * k, -1);
  {
    nb::gil_scoped_release nogil;
    // every (simplex, opposite vertex) with its facet's sorted vertices; after
    // sorting by facet, the two simplices sharing a facet are adjacent
    struct Side {
      std::array<std::int64_t, 5> facet{};  // unused tail entries stay 0
      std::size_t slot;                     // i * k + j
    };
    std::vector<Side> sides(m * k);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0; j < k; ++j) {
        Side& s = sides[i * k + j];
        s.slot = i * k + j;
        std::size_t f = 0;
        for (std::size_t l = 0; l < k; ++l)
          if (l != j) s.facet[f++] = c.data()[i * k + l];
        std::sort(s.facet.begin(), s.facet.begin() + static_cast<std::ptrdiff_t>(f));
      }
    std::sort(sides.begin(), sides.end(),
              [](const Side& a, const Side& b) { return a.facet != b.facet ? a.facet < b.facet : a.slot < b.slot; });
    for (std::size_t a = 0; a + 1 < sides.size(); ++a)
      if (sides[a].facet == sides[a + 1].facet) {
        nb[sides[a].slot] = static_cast<std::int64_t>(sides[a + 1].slot / k);
        nb[sides[a + 1].slot] = static_cast<std::int64_t>(sides[a].slot / k);
        ++a;  // a facet of a valid triangulation has at most two simplices
      }
  }
  return index_array(std::move(nb), m, k);
}

// Exact point location: for each query, a simplex that contains it (closed;
// among several, the first found by a walk that starts where the previous
// query ended, else by a scan in index order), -1 when outside all.
// Simplices of zero volume contain nothing (the canonical answer may hold
// them; they cover no area).
IndexArray find_simplex(const Points& p, const Cells& c, const Cells& nbr, const Points& q) {
  const PointSet ps = point_set(p, std::nullopt);
  const std::size_t m = c.shape(0), k = c.shape(1), d = k - 1;
  if (q.shape(1) != d) throw std::invalid_argument("query points must have the points' dimension");
  for (std::size_t i = 0; i < q.shape(0) * q.shape(1); ++i)
    if (!std::isfinite(q.data()[i])) throw std::invalid_argument("the query points hold NaN or infinite coordinates");
  std::vector<std::int64_t> out(q.shape(0), -1);
  {
    nb::gil_scoped_release nogil;
    auto vtx = [&](std::size_t s, std::size_t j) { return ps.point(static_cast<std::size_t>(c.data()[s * k + j])); };
    // sign of det[[v_i 1]] with vertex j replaced by x (-1 for x = null: the simplex itself)
    auto orient = [&](std::size_t s, long j, const double* x) {
      const double* rows[6];
      for (std::size_t l = 0; l < k; ++l) rows[l] = static_cast<long>(l) == j ? x : vtx(s, l);
      return pred::orient_d_exact(static_cast<int>(d), rows);
    };
    std::vector<int> own(m);
    for (std::size_t s = 0; s < m; ++s) own[s] = orient(s, -1, nullptr);
    std::size_t cur = 0;
    for (std::size_t qi = 0; qi < q.shape(0); ++qi) {
      const double* x = q.data() + qi * d;
      long found = -1;
      bool outside = false;
      for (std::size_t steps = 0; steps < 4 * m + 16 && found < 0 && !outside; ++steps) {
        if (own[cur] == 0) {  // flat: step to any neighbour
          long next = -1;
          for (std::size_t j = 0; j < k && next < 0; ++j) next = static_cast<long>(nbr.data()[cur * k + j]);
          if (next < 0) break;
          cur = static_cast<std::size_t>(next);
          continue;
        }
        long exit_facet = -1;
        for (std::size_t j = 0; j < k && exit_facet < 0; ++j)
          if (orient(cur, static_cast<long>(j), x) * own[cur] < 0) exit_facet = static_cast<long>(j);
        if (exit_facet < 0) {
          found = static_cast<long>(cur);
          break;
        }
        const std::int64_t next = nbr.data()[cur * k + static_cast<std::size_t>(exit_facet)];
        if (next < 0) outside = true;
        else cur = static_cast<std::size_t>(next);
      }
      if (found < 0 && !outside)  // the walk did not settle: scan
        for (std::size_t s = 0; s < m && found < 0; ++s) {
          if (own[s] == 0) continue;
          bool in = true;
          for (std::size_t j = 0; j < k && in; ++j) in = orient(s, static_cast<long>(j), x) * own[s] >= 0;
          if (in) found = static_cast<long>(s);
        }
      out[qi] = found;
    }
  }
  return index_array(std::move(out), q.shape(0), 0, true);
}

// ---- certify ---------------------------------------------------------------------

std::pair<bool, std::pair<std::string, std::string>> certify_cells(const std::string& kind, const Points& p,
                                                                   const Cells& c, const std::optional<Vector>& w,
                                                                   bool canonical) {
  const PointSet ps = point_set(p, w);
  const std::vector<std::vector<Index>> cells = cell_lists(c, ps.size());
  const certify::Level level = canonical ? certify::Level::canonical : certify::Level::exact;
  certify::Report r;
  {
    nb::gil_scoped_release nogil;
    if (kind == "hull2") {
      if (ps.dim != 2) throw std::invalid_argument("hull2 expects points of shape (n, 2)");
      std::vector<Index> cycle;
      for (const auto& row : cells)
        for (Index x : row) cycle.push_back(x);
      r = cpu::certify_hull2(ps, cycle, level);
    } else if (kind == "hull3") {
      if (ps.dim != 3) throw std::invalid_argument("hull3 expects points of shape (n, 3)");
      r = cpu::certify_hull3(ps, triangles_of(cells), level);
    } else if (kind == "delaunay" && ps.dim == 2) {
      r = certify::rt2(ps, triangles_of(cells), level);
    } else if (kind == "delaunay") {
      r = certify::rtd(ps, cells, level);
    } else {
      throw std::invalid_argument("kind must be 'hull2', 'hull3' or 'delaunay'; got '" + kind + "'");
    }
  }
  return {r.ok, {r.condition, r.detail}};
}

// Orientation made positive, exactly, so that another program's unoriented
// output can be certified: 'hull3' triangles outward (the side away from an
// input point off their plane), 'delaunay' simplices of positive volume.
IndexArray orient_cells(const std::string& kind, const Points& p, const Cells& c) {
  const PointSet ps = point_set(p, std::nullopt);
  std::vector<std::vector<Index>> cells = cell_lists(c, ps.size());
  {
    nb::gil_scoped_release nogil;
    for (auto& t : cells) {
      int s = 0;
      if (kind == "hull3") {
        if (ps.dim != 3 || t.size() != 3) throw std::invalid_argument("hull3 expects triangles over 3D points");
        for (std::size_t i = 0; i < ps.size() && s == 0; ++i)
          s = pred::orient3d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), ps.point(i));
        // s > 0: the point is on the inner side of (t0, t1, t2) oriented
        // outward (certify_hull3.cpp: orient3d(a, b, c, interior) > 0)
      } else if (kind == "delaunay") {
        if (t.size() != static_cast<std::size_t>(ps.dim + 1)) throw std::invalid_argument("simplices need d+1 indices");
        const double* rows[6];
        for (std::size_t l = 0; l < t.size(); ++l) rows[l] = ps.point(t[l]);
        s = pred::orient_d_exact(ps.dim, rows) * (ps.dim % 2 == 0 ? 1 : -1);  // volume convention (canonical_d.hpp)
      } else {
        throw std::invalid_argument("kind must be 'hull3' or 'delaunay'; got '" + kind + "'");
      }
      if (s < 0) std::swap(t[0], t[1]);
    }
  }
  return cells_array(cells, c.shape(1));
}

// ---- generators, instant flip --------------------------------------------------------

std::pair<nb::ndarray<nb::numpy, double>, std::optional<nb::ndarray<nb::numpy, double>>> generate(
    const std::string& dist, std::size_t n, std::uint64_t seed, double thickness, std::optional<std::pair<double, double>> weights) {
  gen::Options o;
  o.seed = seed;
  o.thickness = thickness;
  if (weights) {
    o.weighted = true;
    o.wlo = weights->first;
    o.whi = weights->second;
  }
  auto* ps = new PointSet(gen::generate(dist, n, o));
  nb::capsule owner(ps, [](void* q) noexcept { delete static_cast<PointSet*>(q); });
  const std::size_t shape[2] = {ps->size(), static_cast<std::size_t>(ps->dim)};
  nb::ndarray<nb::numpy, double> pts(ps->coords.data(), 2, shape, owner);
  std::optional<nb::ndarray<nb::numpy, double>> w;
  if (ps->weighted) {
    const std::size_t wshape[1] = {ps->size()};
    w = nb::ndarray<nb::numpy, double>(ps->weights.data(), 1, wshape, owner);
  }
  return {pts, w};
}

// RT(S ⊕ W) -> RT(S ⊕ U) by the monotonic instant flip with insertions
// (thesis §9.2, Algorithm 14 extended; ref::DynamicRegularTriangulation), as
// `flipflop instant-flip`: (simplices, total flips), for any W and U.
std::pair<IndexArray, std::uint64_t> instant_flip(const Points& p, const Vector& w, const Vector& u) {
  const PointSet pw = point_set(p, w), pu = point_set(p, u);
  const PointSet pts = point_set(p, std::nullopt);
  std::vector<std::vector<Index>> result;
  std::uint64_t flips = 0;
  {
    nb::gil_scoped_release nogil;
    require_spanning(pts);
    ref::DynamicRegularTriangulation rt(pts, pw.weights.to_vector());
    flips = cpu::set_weights(rt, pu.weights.to_vector(), 0).total_flips();
    result = rt.simplices();
    check_certified(certify::rtd(pu, result), "instant flip");
  }
  return {cells_array(result, static_cast<std::size_t>(p.shape(1) + 1)), flips};
}

}  // namespace

NB_MODULE(_flipflop, m) {
  m.doc() = "flipflop's compiled core (use the flipflop package, not this module)";
  m.attr("__version__") = FLIPFLOP_VERSION;
  m.def("hull2", &hull2, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3", &hull3, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3_strict", &hull3_strict, nb::arg("points"), nb::arg("triangulate"));
  m.def("triangulate", &triangulate, nb::arg("points"), nb::arg("weights").none(), nb::arg("backend"),
        nb::arg("strict"), nb::arg("threads"));
  m.def("neighbors", &neighbors, nb::arg("simplices"));
  m.def("find_simplex", &find_simplex, nb::arg("points"), nb::arg("simplices"), nb::arg("neighbors"),
        nb::arg("queries"));
  m.def("certify", &certify_cells, nb::arg("kind"), nb::arg("points"), nb::arg("cells"), nb::arg("weights").none(),
        nb::arg("canonical"));
  m.def("orient", &orient_cells, nb::arg("kind"), nb::arg("points"), nb::arg("cells"));
  m.def("generate", &generate, nb::arg("dist"), nb::arg("n"), nb::arg("seed"), nb::arg("thickness"),
        nb::arg("weights").none());
  m.def("distributions", &gen::distributions);
  m.def("dimension_of", &gen::dimension_of);
  m.def("_reads_in_place", &reads_in_place, nb::arg("points"), nb::arg("weights").none());
  m.def("instant_flip", &instant_flip, nb::arg("points"), nb::arg("w"), nb::arg("u"));
}

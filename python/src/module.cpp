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
#include <cstring>
#include <limits>
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
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
#include "kernels_cuda/gpu.hpp"
#endif
#include "predicates/predicates.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"
#include "reference/hull3/hull3.hpp"
#include "reference/hull3/strict_hull3.hpp"
#include "reference/rt2/rt2.hpp"
#include "reference/rt2/strict_rt2.hpp"
#include "reference/rtd/strict_rtd.hpp"
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

// Whether no value is NaN or infinite: x * 0 is (+-)0 for finite x and NaN
// for NaN and +-inf, so the sum of the x * 0 is 0 exactly when all are
// finite. Four independent sums (no reassociation needed) let the loop
// vectorise without -ffast-math: 10^6 3D points in 1.4 ms, where the
// branching std::isfinite loop took 2.1 ms and a test of the exponent bits
// 2.5 ms (64-bit integer compares are not in the x86-64 baseline's SSE2).
bool all_finite(const double* x, std::size_t n) {
  double acc[4] = {0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (std::size_t l = 0; l < 4; ++l) acc[l] += x[i + l] * 0.0;
  for (; i < n; ++i) acc[0] += x[i] * 0.0;
  return acc[0] + acc[1] + acc[2] + acc[3] == 0;
}

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
  if (!all_finite(p.data(), p.shape(0) * p.shape(1)))
    throw std::invalid_argument("the points hold NaN or infinite coordinates");
  if (w && !all_finite(w->data(), w->shape(0))) throw std::invalid_argument("the weights hold NaN or infinite values");
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

// The GPU kernels (kernels_cuda/) this extension has: "cuda-omp" (their
// thrust/OpenMP build) where the CUDA toolkit's headers and OpenMP were found
// at build time, and "cuda" where nvcc built them (not in this package's
// build). Where the kernels are built, both names are GPU backends
// (kernels::is_gpu_backend): "cuda" without nvcc's build or without a usable
// device raises the command line's one line (NoDeviceError: RuntimeError).
std::vector<std::string> gpu_backends() {
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  return kernels::gpu_backends_built();
#else
  return {};
#endif
}
bool gpu_backend(const std::string& backend) {
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  return kernels::is_gpu_backend(backend);
#else
  (void)backend;
  return false;
#endif
}
// "'cpu', 'reference'" and the GPU backends, for the error messages
std::string backend_list(const char* first) {
  std::string s = first;
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  s += ", 'cuda-omp', 'cuda'";
#endif
  return s;
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

// ---- derived attributes (scipy.spatial's), computed once in C++ ---------------

// The simplex across each facet, scipy's `neighbors`: out[i * k + j] is the
// other simplex holding the facet of simplex i opposite its vertex j, -1 when
// none. vertex(i, l) is vertex l of simplex i, a bucket id below `buckets`.
// Each facet is filed under its smallest vertex (a counting sort: no hashing,
// no global sort); within a bucket the entries, already in slot order, are
// sorted stably by their other vertices, and two equal neighbours are paired
// — as a global sort by (facet, slot) would pair them, so any input, valid or
// not, gets the same answer as that sort. The buckets hold a few entries each
// (a vertex's facets where it is the smallest), so this is linear in m * k in
// practice; 2 * 10^6 triangles of a 2D triangulation: about 0.1 s, where the
// global sort of (facet, slot) records took 3.8 s.
template <std::size_t K, class Slot, class Vertex>
std::vector<std::int64_t> facet_neighbors_in(std::size_t m, std::size_t buckets, const Vertex& vertex) {
  constexpr std::size_t R = K - 2;
  struct Entry {
    std::array<std::uint32_t, R> rest;  // the facet's vertices after the smallest, sorted
    Slot slot;                          // i * K + j
  };
  // the facet of simplex i opposite vertex j, sorted
  const auto facet = [&](std::size_t i, std::size_t j, std::array<std::uint32_t, K - 1>& f) {
    std::size_t c = 0;
    for (std::size_t l = 0; l < K; ++l)
      if (l != j) f[c++] = static_cast<std::uint32_t>(vertex(i, l));
    if constexpr (K == 3) {
      if (f[1] < f[0]) std::swap(f[0], f[1]);
    } else if constexpr (K > 3) {
      std::sort(f.begin(), f.end());
    }
  };
  std::vector<Slot> start(buckets + 1, 0);
  std::array<std::uint32_t, K - 1> f;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < K; ++j) {
      facet(i, j, f);
      ++start[f[0] + 1];
    }
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<Slot> cursor(start.begin(), start.end() - 1);
  std::vector<Entry> e(m * K);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < K; ++j) {
      facet(i, j, f);
      Entry& x = e[cursor[f[0]]++];
      for (std::size_t r = 0; r < R; ++r) x.rest[r] = f[r + 1];
      x.slot = static_cast<Slot>(i * K + j);
    }
  std::vector<std::int64_t> out(m * K, -1);
  // written out: std::array's operators call memcmp (11 % of the time)
  const auto by_rest = [](const Entry& a, const Entry& b) {
    for (std::size_t r = 0; r < R; ++r)
      if (a.rest[r] != b.rest[r]) return a.rest[r] < b.rest[r];
    return false;
  };
  const auto same = [](const Entry& a, const Entry& b) {
    for (std::size_t r = 0; r < R; ++r)
      if (a.rest[r] != b.rest[r]) return false;
    return true;
  };
  for (std::size_t b = 0; b < buckets; ++b) {
    Entry* lo = e.data() + start[b];
    Entry* hi = e.data() + start[b + 1];
    if (hi - lo <= 16) {  // insertion sort (stable), the common case
      for (Entry* x = lo + 1; x < hi; ++x)
        for (Entry* y = x; y > lo && by_rest(*y, *(y - 1)); --y) std::swap(*y, *(y - 1));
    } else {
      std::stable_sort(lo, hi, by_rest);
    }
    for (Entry* x = lo; x + 1 < hi; ++x)
      if (same(*x, *(x + 1))) {
        out[x->slot] = static_cast<std::int64_t>((x + 1)->slot / K);
        out[(x + 1)->slot] = static_cast<std::int64_t>(x->slot / K);
        ++x;  // a facet of a valid triangulation has at most two simplices
      }
  }
  return out;
}

template <class Vertex>
std::vector<std::int64_t> facet_neighbors(std::size_t m, std::size_t k, std::size_t buckets, const Vertex& vertex) {
  const bool small = m * k <= std::numeric_limits<std::uint32_t>::max();
  switch (k) {
    case 2: return small ? facet_neighbors_in<2, std::uint32_t>(m, buckets, vertex)
                         : facet_neighbors_in<2, std::uint64_t>(m, buckets, vertex);
    case 3: return small ? facet_neighbors_in<3, std::uint32_t>(m, buckets, vertex)
                         : facet_neighbors_in<3, std::uint64_t>(m, buckets, vertex);
    case 4: return facet_neighbors_in<4, std::uint64_t>(m, buckets, vertex);
    case 5: return facet_neighbors_in<5, std::uint64_t>(m, buckets, vertex);
    case 6: return facet_neighbors_in<6, std::uint64_t>(m, buckets, vertex);
    default: throw std::invalid_argument("neighbors expects simplices of shape (m, k) with k = 2..6");
  }
}

// The indices 0..n-1 that the cells use (used = true: a hull's vertices) or
// that none uses (used = false: a triangulation's redundant points), sorted.
template <class Cells>
std::vector<Index> points_used(std::size_t n, const Cells& cells, bool used = true) {
  std::vector<std::uint8_t> mark(n, 0);
  for (const auto& t : cells)
    for (Index x : t) mark[x] = 1;
  std::vector<Index> v;
  for (std::size_t p = 0; p < n; ++p)
    if (static_cast<bool>(mark[p]) == used) v.push_back(static_cast<Index>(p));
  return v;
}

// neighbors of hull facets (closed surfaces), bucketed by the rank of their
// vertices among the hull's vertices (a binary search: the hull's vertices
// are few compared with the points, and bucketing by point index would
// clear a counter per input point)
template <std::size_t K>
std::vector<std::int64_t> hull_neighbors(const std::vector<std::array<Index, K>>& facets,
                                         const std::vector<Index>& vertices) {
  std::vector<std::uint32_t> rank(facets.size() * K);
  for (std::size_t i = 0; i < facets.size(); ++i)
    for (std::size_t j = 0; j < K; ++j)
      rank[i * K + j] = static_cast<std::uint32_t>(std::lower_bound(vertices.begin(), vertices.end(), facets[i][j]) -
                                                   vertices.begin());
  return facet_neighbors(facets.size(), K, vertices.size(),
                         [&](std::size_t i, std::size_t l) { return rank[i * K + l]; });
}

// scipy's floating-point hull attributes from the exact facets: equations
// ([unit outward normal, offset] per facet, normal . x + offset <= 0 inside),
// volume and area (2D: area and perimeter). One pass over the facets.
//
// Overflow and underflow: the points are scaled by 2^shift, a power of two
// that brings the largest coordinate magnitude of the hull's vertices (the
// largest of all points: a convex function's maximum over the hull is
// attained at a vertex) into [1/2, 1), exactly (two multiplications, as 2^shift
// alone may not be a double). Normals, areas and volumes are computed from the
// scaled points and scaled back with ldexp, so a 1e-300 or 1e+300 input gets
// unit normals, and its area and volume overflow to inf or underflow to 0
// only where the true value is not a double. The offset uses the unscaled
// point. The volume sums signed tetrahedra from the first vertex o (on the
// hull: every tetrahedron (o, facet) is non-negative, no cancellation);
// normals by `normalise`: facets of zero area (the canonical hull's on
// coplanar input) get NaN normals.
struct HullMeasures {
  std::vector<double> equations;  // (m, d + 1), row-major
  double volume = 0, area = 0;
};

class Scaled {
 public:
  Scaled(const PointSet& ps, const std::vector<Index>& vertices) : ps_(ps) {
    double big = 0;
    for (Index v : vertices)
      for (int c = 0; c < ps.dim; ++c) big = std::max(big, std::fabs(ps.point(v)[c]));
    int e = 0;
    if (big > 0) std::frexp(big, &e);
    shift_ = -e;
    s1_ = std::ldexp(1.0, shift_ / 2);
    s2_ = std::ldexp(1.0, shift_ - shift_ / 2);
  }
  double at(Index p, int c) const { return ps_.point(p)[c] * s1_ * s2_; }
  // x computed from scaled coordinates as a quantity of length^power: unscaled
  double unscale(double x, int power) const { return std::ldexp(x, -power * shift_); }

 private:
  const PointSet& ps_;
  int shift_ = 0;
  double s1_ = 1, s2_ = 1;
};

// Neumaier's compensated sum (the facets' areas and volumes: one rounding
// error in total rather than one per facet).
struct Sum {
  double s = 0, c = 0;
  void add(double x) {
    const double t = s + x;
    c += std::fabs(s) >= std::fabs(x) ? (s - t) + x : (x - t) + s;
    s = t;
  }
  double value() const { return s + c; }
};

// |n| returned and n / |n| written to unit without overflow or underflow in
// the squares: n is first scaled by the power of two that brings its largest
// component into [1/2, 1) (exact). A facet of tiny but non-zero area keeps a
// unit normal; n = 0 (a facet of zero area in floating point) gives NaN, as
// numpy's 0/0.
template <int D>
double normalise(const double (&n)[D], double* unit) {
  double m = 0;
  for (int i = 0; i < D; ++i) m = std::max(m, std::fabs(n[i]));
  if (m == 0) {
    for (int i = 0; i < D; ++i) unit[i] = std::numeric_limits<double>::quiet_NaN();
    return 0;
  }
  int e = 0;
  std::frexp(m, &e);
  double w[D], sq = 0;
  for (int i = 0; i < D; ++i) w[i] = std::ldexp(n[i], -e), sq += w[i] * w[i];
  const double l = std::sqrt(sq);
  for (int i = 0; i < D; ++i) unit[i] = w[i] / l;
  return std::ldexp(l, e);
}

HullMeasures hull3_measures(const PointSet& ps, const std::vector<Triangle>& tris, const std::vector<Index>& vertices) {
  const Scaled sc(ps, vertices);
  HullMeasures h;
  h.equations.resize(tris.size() * 4);
  const Index o = vertices.front();
  const double o0 = sc.at(o, 0), o1 = sc.at(o, 1), o2 = sc.at(o, 2);
  Sum area, volume;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Index a = tris[i][0], b = tris[i][1], c = tris[i][2];
    const double A[3] = {sc.at(a, 0), sc.at(a, 1), sc.at(a, 2)}, B[3] = {sc.at(b, 0), sc.at(b, 1), sc.at(b, 2)},
                 C[3] = {sc.at(c, 0), sc.at(c, 1), sc.at(c, 2)};
    // (b - a) x (c - a): outward, twice the facet's area
    const double u0 = B[0] - A[0], u1 = B[1] - A[1], u2 = B[2] - A[2];
    const double v0 = C[0] - A[0], v1 = C[1] - A[1], v2 = C[2] - A[2];
    const double n[3] = {u1 * v2 - u2 * v1, u2 * v0 - u0 * v2, u0 * v1 - u1 * v0};
    double* eq = &h.equations[i * 4];
    area.add(0.5 * normalise(n, eq));
    // det[a - o, b - o, c - o] / 6: the tetrahedron (o, a, b, c)
    const double a0 = A[0] - o0, a1 = A[1] - o1, a2 = A[2] - o2, b0 = B[0] - o0, b1 = B[1] - o1, b2 = B[2] - o2;
    const double c0 = C[0] - o0, c1 = C[1] - o1, c2 = C[2] - o2;
    volume.add((a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0)) / 6);
    const double* pa = ps.point(a);
    eq[3] = -(eq[0] * pa[0] + eq[1] * pa[1] + eq[2] * pa[2]);
  }
  h.area = sc.unscale(area.value(), 2);
  h.volume = sc.unscale(volume.value(), 3);
  return h;
}

// 2D: the counter-clockwise cycle; edge i = (cycle[i], cycle[i + 1]).
HullMeasures hull2_measures(const PointSet& ps, const std::vector<Index>& cycle) {
  const Scaled sc(ps, cycle);
  HullMeasures h;
  const std::size_t k = cycle.size();
  h.equations.resize(k * 3);
  const Index o = cycle.front();
  const double o0 = sc.at(o, 0), o1 = sc.at(o, 1);
  Sum perimeter, area;
  for (std::size_t i = 0; i < k; ++i) {
    const Index a = cycle[i], b = cycle[(i + 1) % k];
    const double A[2] = {sc.at(a, 0), sc.at(a, 1)}, B[2] = {sc.at(b, 0), sc.at(b, 1)};
    const double n[2] = {B[1] - A[1], A[0] - B[0]};  // the edge turned clockwise: outward
    double* eq = &h.equations[i * 3];
    perimeter.add(normalise(n, eq));
    const double a0 = A[0] - o0, a1 = A[1] - o1, b0 = B[0] - o0, b1 = B[1] - o1;
    area.add(0.5 * (a0 * b1 - b0 * a1));
    const double* pa = ps.point(a);
    eq[2] = -(eq[0] * pa[0] + eq[1] * pa[1]);
  }
  h.area = sc.unscale(perimeter.value(), 1);
  h.volume = sc.unscale(area.value(), 2);
  return h;
}

using DoubleArray = nb::ndarray<nb::numpy, double>;

DoubleArray double_array(std::vector<double> v, std::size_t rows, std::size_t cols) {
  auto* heap = new std::vector<double>(std::move(v));
  nb::capsule owner(heap, [](void* p) noexcept { delete static_cast<std::vector<double>*>(p); });
  const std::size_t shape[2] = {rows, cols};
  return DoubleArray(heap->data(), 2, shape, owner);
}

// (simplices, vertices, neighbors, equations, volume, area): a ConvexHull's
// attributes, in the order python/flipflop/__init__.py unpacks them
using HullTuple = std::tuple<IndexArray, IndexArray, IndexArray, DoubleArray, double, double>;

// ---- hulls -------------------------------------------------------------------

HullTuple hull2(const Points& p, const std::string& backend, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 2) throw std::invalid_argument("hull2 expects points of shape (n, 2)");
  std::vector<Index> cycle;
  std::vector<std::int64_t> edges, nbr;
  HullMeasures ms;
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
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    } else if (gpu_backend(backend)) {  // Graham-sorting with parallel flip-pop, as `flipflop hull2 --backend`
      cycle = kernels::hull2_gpu(backend, ps);
      check_certified(cpu::certify_hull2(ps, cycle, certify::Level::canonical, threads), "hull2");
#endif
    } else {
      throw std::invalid_argument("hull2 backends: " + backend_list("'cpu', 'reference'") + "; got '" + backend + "'");
    }
    // edge i = (cycle[i], cycle[i + 1]); across its vertex 0 lies edge i + 1,
    // across its vertex 1 edge i - 1
    const std::size_t k = cycle.size();
    edges.resize(2 * k);
    nbr.resize(2 * k);
    for (std::size_t i = 0; i < k; ++i) {
      edges[2 * i] = cycle[i], edges[2 * i + 1] = cycle[(i + 1) % k];
      nbr[2 * i] = static_cast<std::int64_t>((i + 1) % k), nbr[2 * i + 1] = static_cast<std::int64_t>((i + k - 1) % k);
    }
    ms = hull2_measures(ps, cycle);
  }
  const std::size_t k = cycle.size();
  return {index_array(std::move(edges), k, 2), list_array(cycle), index_array(std::move(nbr), k, 2),
          double_array(std::move(ms.equations), k, 3), ms.volume, ms.area};
}

// The attributes of a certified 3D hull `tris` (inside the GIL's release).
struct Hull3Attributes {
  std::vector<Index> vertices;
  std::vector<std::int64_t> neighbors;
  HullMeasures measures;
  Hull3Attributes(const PointSet& ps, const std::vector<Triangle>& tris)
      : vertices(points_used(ps.size(), tris)), neighbors(hull_neighbors(tris, vertices)),
        measures(hull3_measures(ps, tris, vertices)) {}
  Hull3Attributes() = default;
};

HullTuple hull3_tuple(const std::vector<Triangle>& tris, Hull3Attributes& a) {
  const std::size_t m = tris.size();
  return {cells_array(tris, 3), list_array(a.vertices), index_array(std::move(a.neighbors), m, 3),
          double_array(std::move(a.measures.equations), m, 4), a.measures.volume, a.measures.area};
}

HullTuple hull3(const Points& p, const std::string& backend, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 3) throw std::invalid_argument("hull3 expects points of shape (n, 3)");
  std::vector<Triangle> tris;
  Hull3Attributes attributes;
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
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    } else if (gpu_backend(backend)) {  // ffHull's GPU rounds, certified as `flipflop hull3 --backend cuda`
      tris = kernels::hull3_gpu(backend, ps);
      check_certified(cpu::certify_hull3(ps, tris, certify::Level::canonical, threads), "hull3");
#endif
    } else {
      throw std::invalid_argument("hull3 backends: " + backend_list("'cpu', 'reference'") + "; got '" + backend + "'");
    }
    attributes = Hull3Attributes(ps, tris);
  }
  return hull3_tuple(tris, attributes);
}

// The strict view: the hull's attributes over the fan-triangulated facets
// (vertices: the extreme points) and the facets as polygons.
std::pair<HullTuple, std::vector<std::vector<Index>>> hull3_strict(const Points& p, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 3) throw std::invalid_argument("hull3 expects points of shape (n, 3)");
  ref::StrictHull3 h;
  std::vector<Triangle> fan;
  Hull3Attributes attributes;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    cpu::Hull3Options o;
    o.threads = threads;
    cpu::Hull3Witness witness;
    o.witness = &witness;
    const std::vector<Triangle> tris = cpu::hull3_ffhull(ps, o);
    check_certified(cpu::certify_hull3_witnessed(ps, tris, certify::Level::canonical, witness, threads), "hull3");
    h = ref::strict_hull3(ps, tris);
    for (const auto& f : ref::fan_triangulated(h).facets) fan.push_back({f[0], f[1], f[2]});
    attributes = Hull3Attributes(ps, fan);
  }
  return {hull3_tuple(fan, attributes), std::move(h.facets)};
}

// ---- triangulations ------------------------------------------------------------

// (simplices, redundant) of RT(S ⊕ W) (W = 0 without weights): d = 2 by the
// cpu backend (kernels_cpu/rt2) or ffRT (the 2D reference), d = 3 by the cpu
// backend (kernels_cpu/rt3, certified from its witness by cpu::certify_rt3,
// as `flipflop rt3|dt3`) or RT+1, d = 4, 5 by RT+1; all canonical. The
// strict views are derived from the certified canonical answer by the
// reference's rules (strict_rt2, strict_rtd), whichever backend computed it.
std::pair<IndexArray, IndexArray> triangulate(const Points& p, const std::optional<Vector>& w,
                                              const std::string& backend, bool strict, int threads) {
  const PointSet ps = point_set(p, w);
  const int d = ps.dim;
  if (d < 2 || d > 5) throw std::invalid_argument("Delaunay expects points of shape (n, d) with d = 2..5");
  if (!(backend == "reference" || (backend == "cpu" && (d == 2 || d == 3)) || (gpu_backend(backend) && d == 2)))
    throw std::invalid_argument("Delaunay backends: 'cpu' (2D, 3D), 'reference'" +
                                (backend_list("").empty() ? std::string() : backend_list("") + " (2D)") + "; got '" +
                                backend + "'");
  std::vector<std::vector<Index>> simplices;
  std::vector<Triangle> tris;  // d = 2 (not copied into `simplices`: 2 * 10^6 small vectors took 0.2 s)
  std::vector<cpu::Tet> tets;  // d = 3, the cpu backend's canonical answer (likewise)
  bool flat_tets = false;      // the answer is in `tets`
  std::vector<Index> redundant;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (d == 2) {
      cpu::Rt2Options o;
      o.threads = threads;
      if (backend == "cpu") {  // certified from the kernel's witness, as `flipflop rt2|dt2`
        cpu::Rt2Witness witness;
        tris = cpu::rt2(ps, o, nullptr, &witness);
        check_certified(cpu::certify_rt2(ps, tris, certify::Level::canonical, witness, threads), "Delaunay");
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
      } else if (gpu_backend(backend)) {  // ffRT's GPU rounds, certified as `flipflop rt2 --backend cuda`
        tris = kernels::rt2_gpu(backend, ps);
        check_certified(cpu::certify_rt2(ps, tris, certify::Level::canonical, threads), "Delaunay");
#endif
      } else {
        tris = ref::rt2_ffrt(ps);
        check_certified(certify::rt2(ps, tris, certify::Level::canonical), "Delaunay");
      }
      if (strict) {
        tris = ref::strict_rt2(ps, tris);
        check_certified(certify::rt2_strict(ps, tris), "strict Delaunay");
      }
      redundant = points_used(ps.size(), tris, false);
    } else if (d == 3 && backend == "cpu") {
      cpu::Rt3Options o;
      o.threads = threads;
      cpu::Rt3Result r;
      {  // certified from the kernel's witness, as `flipflop rt3|dt3` (the witness freed after)
        cpu::Rt3Witness witness;
        r = cpu::rt3(ps, o, nullptr, &witness);
        check_certified(cpu::certify_rt3(ps, witness, r.tets, certify::Level::canonical, threads), "Delaunay");
      }
      if (strict) {  // `rt3 --strict`: the reference's rule from the certified answer, certified at the exact level
        std::vector<std::vector<Index>> canonical;
        canonical.reserve(r.tets.size());
        for (const cpu::Tet& t : r.tets) canonical.push_back({t[0], t[1], t[2], t[3]});
        r.tets = {};
        simplices = ref::strict_rtd(ps, canonical);
        check_certified(certify::rtd(ps, simplices, certify::Level::exact), "strict Delaunay");
        redundant = non_vertices(ps.size(), simplices);
      } else {
        tets = std::move(r.tets);
        redundant = std::move(r.redundant);
        flat_tets = true;
      }
    } else {
      ref::Rtd r = ref::rtd_incremental(ps);
      check_certified(certify::rtd(ps, r.simplices), "Delaunay");
      simplices = std::move(r.simplices);
      redundant = std::move(r.redundant);
      if (strict) {  // `rtd --strict`: certified at the exact level (no zero-volume simplex)
        simplices = ref::strict_rtd(ps, simplices);
        check_certified(certify::rtd(ps, simplices, certify::Level::exact), "strict Delaunay");
        redundant = non_vertices(ps.size(), simplices);
      }
    }
  }
  return {d == 2      ? cells_array(tris, 3)
          : flat_tets ? cells_array(tets, 4)
                      : cells_array(simplices, static_cast<std::size_t>(d + 1)),
          list_array(redundant)};
}

// neighbors[i][j]: the simplex across the facet opposite vertex j of
// simplex i, -1 on the boundary (scipy's convention); facet_neighbors with
// the point indices as buckets.
IndexArray neighbors(const Cells& c) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  if (k < 2 || k > 6) throw std::invalid_argument("neighbors expects simplices of shape (m, k) with k = 2..6");
  std::vector<std::int64_t> nb;
  {
    nb::gil_scoped_release nogil;
    const std::int64_t* x = c.data();
    std::int64_t top = -1;
    for (std::size_t i = 0; i < m * k; ++i) {
      if (x[i] < 0 || x[i] > std::numeric_limits<Index>::max())
        throw std::invalid_argument("neighbors: simplex " + std::to_string(i / k) + " names point " +
                                    std::to_string(x[i]));
      top = std::max(top, x[i]);
    }
    nb = facet_neighbors(m, k, static_cast<std::size_t>(top + 1), [&](std::size_t i, std::size_t l) { return x[i * k + l]; });
  }
  return index_array(std::move(nb), m, k);
}

// The queries' visiting order for find_simplex: along a Morton (Z-order)
// curve of their coordinates, quantised to 63 / d bits per axis over their
// bounding box, so that consecutive walks start near their targets. Only
// the speed depends on it (and, for a query on a face shared by several
// simplices, which of them is returned).
std::vector<std::size_t> morton_order(const double* q, std::size_t n, std::size_t d) {
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  if (n < 2) return order;
  const unsigned bits = static_cast<unsigned>(63 / d);
  double lo[6], hi[6];
  for (std::size_t j = 0; j < d; ++j) lo[j] = hi[j] = q[j];
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) {
      lo[j] = std::min(lo[j], q[i * d + j]);
      hi[j] = std::max(hi[j], q[i * d + j]);
    }
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(n);
  const double top = std::ldexp(1.0, static_cast<int>(bits)) - 1;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t key = 0;
    for (std::size_t j = 0; j < d; ++j) {
      // halves first: no overflow for coordinates near +-1.8e308
      const double span = hi[j] * 0.5 - lo[j] * 0.5;
      const double t = span > 0 ? (q[i * d + j] * 0.5 - lo[j] * 0.5) / span : 0.0;
      const auto cell = static_cast<std::uint64_t>(std::min(std::max(t, 0.0), 1.0) * top);
      for (unsigned b = 0; b < bits; ++b) key |= ((cell >> b) & 1u) << (b * d + j);
    }
    keyed[i] = {key, i};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

// Exact point location: for each query, a simplex that contains it (closed;
// among several, the one a visibility walk reaches first, else the first of
// a scan in index order), -1 when outside all. Simplices of zero volume
// contain nothing (the canonical answer may hold them; they cover no volume).
//
// The walk: from the current simplex, cross a facet that has the query
// strictly on its far side (exact orient_d, ties broken by moving the query
// infinitesimally into the hull: `side` below), until none has: the simplex
// contains the query. The queries are visited in Morton order (above), each
// walk starting where the previous one ended. flipflop's simplices are all
// positively oriented under the Simulation of Simplicity, the zero-volume
// ones included, so a flat simplex is crossed as in the perturbed
// triangulation: with the orientation sign of the others (a query off the
// flat simplex's hyperplane is strictly on one side of each of its
// non-degenerate facets, the same side as in the perturbed configuration).
// The walk then follows a visibility walk in the perturbed triangulation, a
// regular one, whose in-front relation is acyclic (Edelsbrunner 1990): it
// ends, after a number of steps about the number of simplices between
// start and target. A query that leaves through a boundary facet (one
// without a neighbour, non-degenerate, the query strictly beyond) is outside
// the hull: the hyperplane of a non-degenerate boundary facet supports the
// hull. (Before the sign rule for flat simplices, the tie-breaking and the
// Morton order, queries outside a grid's hull or on its lattice each ran
// into the step limit and the scan: 3 ms a query on 15^3 points.) Where no
// facet of a flat simplex is strictly seen (degenerate facets only), the walk
// steps on to a neighbour (not the one it came from, where it can); a walk
// that does not settle within 4m + 16 steps ends in the scan, which decides
// every query exactly.
IndexArray find_simplex(const Points& p, const Cells& c, const Cells& nbr, const Points& q) {
  const PointSet ps = point_set(p, std::nullopt);
  const std::size_t m = c.shape(0), k = c.shape(1), d = k - 1;
  if (q.shape(1) != d) throw std::invalid_argument("query points must have the points' dimension");
  if (nbr.shape(0) != m || nbr.shape(1) != k) throw std::invalid_argument("neighbors must have the simplices' shape");
  for (std::size_t i = 0; i < q.shape(0) * q.shape(1); ++i)
    if (!std::isfinite(q.data()[i])) throw std::invalid_argument("the query points hold NaN or infinite coordinates");
  std::vector<std::int64_t> out(q.shape(0), -1);
  if (m == 0) return index_array(std::move(out), q.shape(0), 0, true);
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
    int positive = 0;  // the sign of every simplex of non-zero volume (all are positive in one convention)
    for (std::size_t s = 0; s < m; ++s) {
      own[s] = orient(s, -1, nullptr);
      if (positive == 0) positive = own[s];
    }
    if (positive == 0) positive = d % 2 == 0 ? 1 : -1;  // (all flat: the volume convention's, canonical_d.hpp)
    // The query as the walk sees it: x' = (1 - e - ... - e^(d+1)) x + e v_0 +
    // e^2 v_1 + ... + e^(d+1) v_d, the v_l the vertices of the first simplex of non-zero
    // volume and e > 0 infinitesimal (but far larger than the input's SoS
    // perturbation). By linearity in x's row, orient with x' is orient with x
    // where that is not 0, else the first non-zero orient with x replaced by
    // v_0, v_1, ...: non-zero for every facet whose vertices span a
    // hyperplane (the v_l span R^d), 0 only for a degenerate facet. x' is a
    // convex combination with positive weights of x and d+1 affinely
    // independent points of the hull: inside the hull (strictly) whenever x is
    // in it (closed), and outside when x is outside. So the walk moves among
    // the facets' hyperplanes as in general position, and leaving through a
    // boundary facet proves x outside even when x lies in that facet's
    // hyperplane (x on the hull's boundary is found in a simplex).
    std::size_t ref = 0;
    while (ref + 1 < m && own[ref] == 0) ++ref;
    auto side = [&](std::size_t s, std::size_t j, const double* x) {
      if (const int o = orient(s, static_cast<long>(j), x); o != 0) return o;
      if (own[ref] == 0) return 0;
      for (std::size_t l = 0; l < k; ++l)
        if (const int o = orient(s, static_cast<long>(j), vtx(ref, l)); o != 0) return o;
      return 0;
    };
    const auto neighbour = [&](std::size_t s, std::size_t j) { return nbr.data()[s * k + j]; };
    std::size_t cur = 0, prev = m;  // prev: where the walk came from (m: nowhere)
    for (const std::size_t qi : morton_order(q.data(), q.shape(0), d)) {
      const double* x = q.data() + qi * d;
      long found = -1;
      bool outside = false;
      for (std::size_t steps = 0; steps < 4 * m + 16; ++steps) {
        // the simplex's sign; a flat one's under SoS (header)
        const int sign = own[cur] != 0 ? own[cur] : positive;
        long exit_facet = -1;
        for (std::size_t j = 0; j < k && exit_facet < 0; ++j)
          if (side(cur, j, x) * sign < 0) exit_facet = static_cast<long>(j);
        if (exit_facet < 0 && own[cur] != 0) {
          found = static_cast<long>(cur);
          break;
        }
        std::int64_t next = -1;
        if (exit_facet >= 0) {
          next = neighbour(cur, static_cast<std::size_t>(exit_facet));
          if (next < 0) {
            outside = true;
            break;
          }
        } else {  // a flat simplex with the query in its hyperplane: on to a neighbour
          for (std::size_t j = 0; j < k && (next < 0 || static_cast<std::size_t>(next) == prev); ++j)
            next = neighbour(cur, (j + steps) % k);
          if (next < 0) break;
        }
        prev = cur;
        cur = static_cast<std::size_t>(next);
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
  m.def("gpu_backends", &gpu_backends);
  m.def("hull2", &hull2, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3", &hull3, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3_strict", &hull3_strict, nb::arg("points"), nb::arg("threads"));
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

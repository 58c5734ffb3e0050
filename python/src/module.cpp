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
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <gmp.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include "gen/generate.hpp"
#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/parallel.hpp"
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
#include "predicates/expansion.hpp"
#include "predicates/lambda_filter.hpp"
#include "predicates/near_lattice.hpp"
#include "predicates/predicates.hpp"
#include "reference/canonical.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/lattice_quotient.hpp"
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
#include "kernels_cpu/rtd/hull_d.hpp"
#include "kernels_cpu/rtd/certify_rtd.hpp"
#include "kernels_cpu/rtd/rtd_cavity.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace nb = nanobind;
using namespace flipflop;

namespace {

// The largest dimension of every class (ref::rtd::kMaxDim: Delaunay, Voronoi
// and ConvexHull in 2D..9D); the fixed-size buffers below hold d + 1 rows.
constexpr int kMaxD = 9;
static_assert(kMaxD == ref::rtd::kMaxDim, "module.cpp buffers: the reference's largest dimension");

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
// global sort of (facet, slot) records took 3.8 s (sequential; in parallel
// below).
template <std::size_t K, class Slot, class Vertex>
std::vector<std::int64_t> facet_neighbors_in(std::size_t m, std::size_t buckets, const Vertex& vertex) {
  constexpr std::size_t R = K - 2;
  struct Entry {
    std::array<std::uint32_t, R> rest;  // the facet's vertices after the smallest, sorted
    std::uint32_t first;                // the smallest
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
  // In parallel (oneTBB), with the sequential order kept: pieces of
  // simplices count their entries per coarse bucket (the top bits of the
  // smallest vertex, at most 1024 buckets) and write them to their own
  // stretch of each (bucket-major offsets: within a coarse bucket, slot
  // order); each coarse bucket is then counting-sorted on the rest of its
  // smallest vertex (stable), and each run of one smallest vertex sorted
  // stably and paired, all buckets apart.
  int shift = 0;
  while ((buckets >> shift) > 1024) ++shift;
  const std::size_t B = ((buckets + (std::size_t{1} << shift) - 1) >> shift) + 1;
  const std::size_t per = std::max<std::size_t>(std::size_t{1} << 12, (m + 63) / 64), pieces = (m + per - 1) / per;
  // fn(c, slot, f) for every facet f of piece c's simplices, in slot order,
  // the pieces in parallel
  const auto each_facet = [&](const auto& fn) {
    cpu::par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
      std::array<std::uint32_t, K - 1> f;
      for (std::size_t c = lo; c < hi; ++c)
        for (std::size_t i = c * per; i < std::min(m, (c + 1) * per); ++i)
          for (std::size_t j = 0; j < K; ++j) {
            facet(i, j, f);
            fn(c, i * K + j, f);
          }
    });
  };
  std::vector<std::size_t> at(pieces * B, 0);  // counts, then write positions
  each_facet([&](std::size_t c, std::size_t, const auto& f) { ++at[c * B + (f[0] >> shift)]; });
  const std::vector<std::size_t> bucket = cpu::bucket_major_positions(at, pieces, B);
  std::vector<Entry> e(m * K);
  each_facet([&](std::size_t c, std::size_t slot, const auto& f) {
    Entry& x = e[at[c * B + (f[0] >> shift)]++];
    for (std::size_t r = 0; r < R; ++r) x.rest[r] = f[r + 1];
    x.first = f[0];
    x.slot = static_cast<Slot>(slot);
  });
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
  cpu::par_for(B, 1, [&](std::size_t blo, std::size_t bhi) {
    std::vector<std::size_t> cnt;
    std::vector<Entry> tmp;
    for (std::size_t b = blo; b < bhi; ++b) {
      const std::size_t first = bucket[b], n = bucket[b + 1] - first;
      if (n == 0) continue;
      const std::size_t base = b << shift;
      cnt.assign((std::size_t{1} << shift) + 1, 0);
      for (std::size_t q = 0; q < n; ++q) ++cnt[e[first + q].first - base + 1];
      for (std::size_t v = 1; v < cnt.size(); ++v) cnt[v] += cnt[v - 1];
      tmp.resize(n);
      for (std::size_t q = 0; q < n; ++q) tmp[cnt[e[first + q].first - base]++] = e[first + q];
      for (std::size_t run = 0; run < n;) {
        std::size_t end = run + 1;
        while (end < n && tmp[end].first == tmp[run].first) ++end;
        Entry* lo = tmp.data() + run;
        Entry* hi = tmp.data() + end;
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
        run = end;
      }
    }
  });
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
    case 7: return facet_neighbors_in<7, std::uint64_t>(m, buckets, vertex);
    case 8: return facet_neighbors_in<8, std::uint64_t>(m, buckets, vertex);
    case 9: return facet_neighbors_in<9, std::uint64_t>(m, buckets, vertex);
    case 10: return facet_neighbors_in<10, std::uint64_t>(m, buckets, vertex);
    default: throw std::invalid_argument("neighbors expects simplices of shape (m, k) with k = 2..10");
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

// The attributes of a certified 2D hull cycle (inside the GIL's release):
// edge i = (cycle[i], cycle[i + 1]); across its vertex 0 lies edge i + 1,
// across its vertex 1 edge i - 1.
struct Hull2Attributes {
  std::vector<std::int64_t> edges, nbr;
  HullMeasures measures;
  Hull2Attributes(const PointSet& ps, const std::vector<Index>& cycle) : measures(hull2_measures(ps, cycle)) {
    const std::size_t k = cycle.size();
    edges.resize(2 * k);
    nbr.resize(2 * k);
    for (std::size_t i = 0; i < k; ++i) {
      edges[2 * i] = cycle[i], edges[2 * i + 1] = cycle[(i + 1) % k];
      nbr[2 * i] = static_cast<std::int64_t>((i + 1) % k), nbr[2 * i + 1] = static_cast<std::int64_t>((i + k - 1) % k);
    }
  }
  Hull2Attributes() = default;
};

HullTuple hull2_tuple(const std::vector<Index>& cycle, Hull2Attributes& a) {
  const std::size_t k = cycle.size();
  return {index_array(std::move(a.edges), k, 2), list_array(cycle), index_array(std::move(a.nbr), k, 2),
          double_array(std::move(a.measures.equations), k, 3), a.measures.volume, a.measures.area};
}

HullTuple hull2(const Points& p, const std::string& backend, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  if (ps.dim != 2) throw std::invalid_argument("hull2 expects points of shape (n, 2)");
  std::vector<Index> cycle;
  Hull2Attributes attributes;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (backend == "cpu") {
      // a lattice up to one exact common factor as that small-integer
      // lattice: the same cycle (reference/lattice_quotient.hpp); the
      // attributes below read the given values
      const std::optional<LatticeQuotient> quotient = lattice_quotient(ps);
      const PointSet& pk = quotient ? quotient->points : ps;
      cpu::Hull2Options o;
      o.threads = threads;
      cycle = cpu::hull2_graham_sort(pk, o);
      check_certified(cpu::certify_hull2(pk, cycle, certify::Level::canonical, threads), "hull2");
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
    attributes = Hull2Attributes(ps, cycle);
  }
  return hull2_tuple(cycle, attributes);
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
      // a lattice up to one exact common factor as that small-integer
      // lattice: the same triangles (reference/lattice_quotient.hpp); the
      // attributes below read the given values
      const std::optional<LatticeQuotient> quotient = lattice_quotient(ps);
      const PointSet& pk = quotient ? quotient->points : ps;
      cpu::Hull3Options o;
      o.threads = threads;
      cpu::Hull3Witness witness;
      o.witness = &witness;
      tris = cpu::hull3_ffhull(pk, o);
      check_certified(cpu::certify_hull3_witnessed(pk, tris, certify::Level::canonical, witness, threads), "hull3");
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

// The canonical RT(S ⊕ W) r (any d; furthest: the furthest-site one)
// certified by certify::rtd's checks on `threads` workers (cpu::certify_rtd;
// throws if it fails), then, with strict, its strict view (`rtd --strict`:
// certified at the exact level, no zero-volume simplex), into (simplices,
// redundant).
// neighbors (optional, not with strict): the facet table the certificate
// matched (certify::rtd's `neighbors`), scipy's neighbors of the simplices.
void certified_rtd(const PointSet& ps, ref::Rtd r, bool strict, bool furthest, int threads,
                   std::vector<std::vector<Index>>& simplices, std::vector<Index>& redundant,
                   std::vector<std::int64_t>* neighbors = nullptr) {
  check_certified(cpu::certify_rtd(ps, r.simplices, certify::Level::canonical, furthest, threads,
                                   strict ? nullptr : neighbors),
                  furthest ? "furthest-site Delaunay" : "Delaunay");
  simplices = std::move(r.simplices);
  redundant = std::move(r.redundant);
  if (strict) {
    simplices = ref::strict_rtd(ps, simplices);
    check_certified(cpu::certify_rtd(ps, simplices, certify::Level::exact, false, threads), "strict Delaunay");
    redundant = non_vertices(ps.size(), simplices);
  }
}

// (simplices, redundant) of RT(S ⊕ W) (W = 0 without weights): d = 2 by the
// cpu backend (kernels_cpu/rt2) or ffRT (the 2D reference), d = 3 by the cpu
// backend (kernels_cpu/rt3, certified from its witness by cpu::certify_rt3,
// as `flipflop rt3|dt3`) or RT+1, d = 4, 5 by the cpu backend (the cavity
// kernel kernels_cpu/rtd, as `flipflop rtd --dim 4|5`) or RT+1, certified by
// cpu::certify_rtd (certify::rtd on oneTBB); all canonical. The strict views are derived from the
// certified canonical answer by the reference's rules (strict_rt2,
// strict_rtd), whichever backend computed it. furthest: the furthest-site
// triangulation (any d, every power sign negated: the cavity kernel's or
// ref::rtd_incremental's `furthest`), certified by certify::rtd with the same
// negation; not with strict.
// neighbors (optional): where the cpu backend's 3D kernel computed the
// answer (not strict, not furthest), scipy's `neighbors` of the simplices,
// read off the kernel's certified witness (cpu::rt3_neighbors: linear and
// parallel; matching the facets of 6.7 million tetrahedra took 2.5 s); where
// certify::rtd certified the answer (d >= 4, furthest-site in any d; not
// strict), the facet table its certificate matched (the 3^5 grid's
// _flipflop.neighbors took 6 ms of a 0.12 s Delaunay); otherwise left empty.
std::pair<IndexArray, IndexArray> triangulate_into(const Points& p, const std::optional<Vector>& w,
                                                   const std::string& backend, bool strict, int threads,
                                                   bool furthest, std::vector<std::int64_t>* neighbors) {
  const PointSet given = point_set(p, w);
  // a lattice up to one exact common factor (np.linspace(0, 1, 5), steps of
  // 0.5 or 0.1 with three values a row) runs as that small-integer lattice:
  // the same index answer (reference/lattice_quotient.hpp), which is all this
  // returns; the reference backend reads the values as given
  const std::optional<LatticeQuotient> quotient = backend != "reference" ? lattice_quotient(given) : std::nullopt;
  const PointSet& ps = quotient ? quotient->points : given;
  const int d = ps.dim;
  if (d < 2 || d > ref::rtd::kMaxDim) throw std::invalid_argument("Delaunay expects points of shape (n, d) with d = 2..9");
  if (furthest && (strict || (backend != "reference" && backend != "cpu")))
    throw std::invalid_argument("the furthest-site triangulation is computed by the 'cpu' or the 'reference' "
                                "backend, without strict");
  if (!(backend == "reference" || backend == "cpu" || (gpu_backend(backend) && (d == 2 || d == 3))))
    throw std::invalid_argument("Delaunay backends: 'cpu', 'reference'" +
                                (backend_list("").empty() ? std::string() : backend_list("") + " (2D, 3D)") +
                                "; got '" + backend + "'");
  std::vector<std::vector<Index>> simplices;
  std::vector<Triangle> tris;  // d = 2 (not copied into `simplices`: 2 * 10^6 small vectors took 0.2 s)
  std::vector<cpu::Tet> tets;  // d = 3, the cpu backend's canonical answer (likewise)
  bool flat_tets = false;      // the answer is in `tets`
  std::vector<Index> redundant;
  {
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    if (furthest) {
      cpu::RtdCavityOptions o;
      o.furthest = true;
      o.threads = threads;
      certified_rtd(ps, backend == "cpu" ? cpu::rtd_cavity(ps, nullptr, o) : ref::rtd_incremental(ps, nullptr, true),
                    false, true, threads, simplices, redundant, neighbors);
    } else if (d == 2) {
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
    } else if (d == 3 && (backend == "cpu" || gpu_backend(backend))) {
      cpu::Rt3Options o;
      o.threads = threads;
      cpu::Rt3Result r;
      {  // certified from the kernel's witness, as `flipflop rt3|dt3` (the witness freed after)
        cpu::Rt3Witness witness;
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
        if (gpu_backend(backend))  // kernels_cuda/rt3's rounds, as `flipflop rt3 --backend cuda`
          r = kernels::rt3_gpu(backend, ps, nullptr, nullptr, &witness);
        else
#endif
          r = cpu::rt3(ps, o, nullptr, &witness);
        check_certified(cpu::certify_rt3(ps, witness, r.tets, certify::Level::canonical, threads), "Delaunay");
        if (neighbors && !strict) *neighbors = cpu::rt3_neighbors(witness, r.tets, threads);
      }
      if (strict) {  // `rt3 --strict`: the reference's rule from the certified answer, certified at the exact level
        std::vector<std::vector<Index>> canonical;
        canonical.reserve(r.tets.size());
        for (const cpu::Tet& t : r.tets) canonical.push_back({t[0], t[1], t[2], t[3]});
        r.tets = {};
        simplices = ref::strict_rtd(ps, canonical);
        check_certified(cpu::certify_rtd(ps, simplices, certify::Level::exact, false, threads), "strict Delaunay");
        redundant = non_vertices(ps.size(), simplices);
      } else {
        tets = std::move(r.tets);
        redundant = std::move(r.redundant);
        flat_tets = true;
      }
    } else {
      cpu::RtdCavityOptions o;
      o.threads = threads;
      certified_rtd(ps, backend == "cpu" ? cpu::rtd_cavity(ps, nullptr, o) : ref::rtd_incremental(ps), strict, false,
                    threads, simplices, redundant, neighbors);
    }
  }
  return {d == 2 && !furthest ? cells_array(tris, 3)
          : flat_tets ? cells_array(tets, 4)
                      : cells_array(simplices, static_cast<std::size_t>(d + 1)),
          list_array(redundant)};
}

std::pair<IndexArray, IndexArray> triangulate(const Points& p, const std::optional<Vector>& w,
                                              const std::string& backend, bool strict, int threads,
                                              bool furthest) {
  return triangulate_into(p, w, backend, strict, threads, furthest, nullptr);
}

// (simplices, redundant, neighbors or None): triangulate's answer and, where
// the kernel's witness gives them (triangulate_into), the neighbours.
std::tuple<IndexArray, IndexArray, std::optional<IndexArray>> triangulate_with_neighbors(
    const Points& p, const std::optional<Vector>& w, const std::string& backend, bool strict, int threads,
    bool furthest) {
  std::vector<std::int64_t> nb;
  auto [simplices, redundant] = triangulate_into(p, w, backend, strict, threads, furthest, &nb);
  std::optional<IndexArray> out;
  if (!nb.empty()) {
    const std::size_t m = simplices.shape(0);
    out = index_array(std::move(nb), m, simplices.shape(1));
  }
  return {std::move(simplices), std::move(redundant), std::move(out)};
}

// In-place insertion for Delaunay(..., incremental=True).add_points: the
// cavity-insertion kernel (kernels_cpu/rtd, every d = 2..9) kept between
// calls (cpu::RtdCavityIncremental); add() inserts only the new points into
// the kept triangulation. Every result is certified by certify::rtd (and
// with strict its strict view derived), as `triangulate`'s; it is
// triangulate's answer for all the points given so far, byte for byte (the
// canonical answer does not depend on the insertion order).
class IncrementalTriangulation {
 public:
  IncrementalTriangulation(const Points& p, const std::optional<Vector>& w, bool strict, int threads, bool furthest)
      : strict_(strict), furthest_(furthest) {
    const PointSet ps = point_set(p, w);
    if (ps.dim < 2 || ps.dim > ref::rtd::kMaxDim)
      throw std::invalid_argument("Delaunay expects points of shape (n, d) with d = 2..9");
    if (furthest && strict) throw std::invalid_argument("the furthest-site triangulation has no strict view");
    cpu::RtdCavityOptions o;
    o.threads = threads;
    o.furthest = furthest;
    threads_ = threads;
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    kernel_ = std::make_unique<cpu::RtdCavityIncremental>(ps, o);
    finish(ps);
  }

  // Seeded with the regular triangulation of p (and w), certified by the
  // caller (Python's Delaunay(incremental=True) in 2D and 3D: its one-shot
  // call's certified answer): s its simplices (canonical: positive in the
  // det convention), nb their neighbours (-1: a hull facet). Nothing is
  // certified here and result() is refused until an add, whose result is
  // certified as every result is. No strict view, no furthest site.
  IncrementalTriangulation(const Points& p, const std::optional<Vector>& w, int threads, const Cells& s,
                           const Cells& nb)
      : strict_(false), furthest_(false), threads_(threads) {
    const PointSet ps = point_set(p, w);
    const std::size_t d = static_cast<std::size_t>(ps.dim), m = s.shape(0);
    if (ps.dim < 2 || ps.dim > ref::rtd::kMaxDim || s.shape(1) != d + 1 || nb.shape(0) != m || nb.shape(1) != d + 1)
      throw std::invalid_argument("Delaunay expects points (n, d), d = 2..9, seed simplices and neighbours (m, d+1)");
    std::vector<Index> simplices(m * (d + 1));
    std::vector<std::int64_t> neighbors(nb.data(), nb.data() + m * (d + 1));
    for (std::size_t k = 0; k < m * (d + 1); ++k) {
      const std::int64_t x = s.data()[k], g = neighbors[k];
      if (x < 0 || static_cast<std::size_t>(x) >= ps.size())
        throw std::invalid_argument("Delaunay: a seed simplex names point " + std::to_string(x));
      if (g < -1 || g >= static_cast<std::int64_t>(m))
        throw std::invalid_argument("Delaunay: a seed neighbour is out of range: " + std::to_string(g));
      simplices[k] = static_cast<Index>(x);
    }
    cpu::RtdCavityOptions o;
    o.threads = threads;
    nb::gil_scoped_release nogil;
    kernel_ = std::make_unique<cpu::RtdCavityIncremental>(ps, simplices, neighbors, o);
  }

  // p (and w): the points given so far, unchanged, followed by the new ones.
  void add(const Points& p, const std::optional<Vector>& w) {
    const PointSet ps = point_set(p, w);
    nb::gil_scoped_release nogil;
    kernel_->add(ps);
    finish(ps);
  }

  std::pair<IndexArray, IndexArray> result() const {
    if (simplices_.empty()) throw std::logic_error("Delaunay: a seeded triangulation has no result before an add");
    return {cells_array(simplices_, simplices_.empty() ? 0 : simplices_[0].size()), list_array(redundant_)};
  }

  // the neighbours the certificate matched (scipy's convention, -1 on the
  // hull), None for the strict view
  std::optional<IndexArray> neighbors() const {
    if (simplices_.empty()) throw std::logic_error("Delaunay: a seeded triangulation has no result before an add");
    if (neighbors_.empty()) return std::nullopt;
    std::vector<std::int64_t> copy = neighbors_;
    return index_array(std::move(copy), simplices_.size(), simplices_[0].size());
  }

  std::size_t size() const { return kernel_->size(); }

 private:
  void finish(const PointSet& ps) {
    neighbors_.clear();
    certified_rtd(ps, kernel_->result(), strict_, furthest_, threads_, simplices_, redundant_, &neighbors_);
  }

  bool strict_, furthest_;
  int threads_ = 0;
  std::unique_ptr<cpu::RtdCavityIncremental> kernel_;
  std::vector<std::vector<Index>> simplices_;
  std::vector<Index> redundant_;
  std::vector<std::int64_t> neighbors_;  // from the certificate (not strict)
};

// The facets of the convex hull in R^d, d = 2..9 (kernels_cpu/rtd/hull_d:
// beneath-beyond in Quickhull's order, exact under SoS, its orphans' walks
// and the certifier in parallel pieces), certified by cpu::hull_d_problem
// (closed convex surface star-shaped from a point that is not a vertex,
// every other point inside by a box, a ball or a walk): (m, d) rows oriented
// so that orient_d(facet, x) < 0 for x inside. threads: the workers of
// both (0: the runtime's default). One thread instead of two on small 4D
// inputs was measured (2026-12-05, AMD EPYC 2-core VM): 300 and 1296 points
// 6-12 % faster, 10^4 even, 2000 5D points 6 % slower (the certificate of
// 3960 facets); not made a default.
IndexArray hull_d(const Points& p, int threads) {
  const PointSet given = point_set(p, std::nullopt);
  // a lattice up to one exact common factor as that small-integer lattice:
  // the same facets (reference/lattice_quotient.hpp), which is all this returns
  const std::optional<LatticeQuotient> quotient = lattice_quotient(given);
  const PointSet& ps = quotient ? quotient->points : given;
  if (ps.dim < 2 || ps.dim > 9) throw std::invalid_argument("ConvexHull expects points of shape (n, d) with d = 2..9");
  if (threads < 0) throw std::invalid_argument("threads: 0 (all) or a positive count");
  std::vector<std::vector<Index>> facets;
  {
    nb::gil_scoped_release nogil;
    cpu::with_threads(threads, [&] {
      facets = cpu::hull_d(ps);  // rejects input that does not span R^d (dimension_problem's message)
      if (const std::string why = cpu::hull_d_problem(ps, facets); !why.empty())
        throw std::runtime_error("the ConvexHull result failed certification: " + why);
    });
  }
  return cells_array(facets, static_cast<std::size_t>(ps.dim));
}

// The attributes of a certified hull in R^d, d = 4..9 (Python's _hull_d),
// from its facets outward in the det convention (det[f1-f0, ..., x-f0] > 0
// for x beyond): (facets, vertices, neighbors, equations, volume, area) as
// hull2 / hull3 give them. Facets canonical: ascending but for a swap of the
// last two where the sort's permutation is odd, rows sorted. Equations,
// area and volume in floating point on the points scaled by a power of two
// (exact), 2^-e with 2^(e-1) <= max |vertex coordinate| < 2^e: the normal's
// components are the signed (d-1)-minors of [f1-f0, ..., f_{d-1}-f0],
// |normal| = (d-1)! times the
// facet's area, normal . (f0 - o) = d! times the volume of the cone from the
// first vertex o; sums compensated (Neumaier); a zero-area facet's equation
// is NaN. (-1)^(d-1+c) det(U without column c): cpu::det_gauss_double.
HullTuple hull_d_attributes(const Points& p, const Cells& f) {
  const std::size_t n = p.shape(0), d = p.shape(1), m = f.shape(0);
  if (d < 2 || d > 9 || f.shape(1) != d)
    throw std::invalid_argument("hull_d_attributes expects points (n, d), d = 2..9, and facets (m, d)");
  std::vector<std::int64_t> facets(f.data(), f.data() + m * d), vertices, nbr;
  std::vector<double> equations(m * (d + 1));
  double volume = 0.0, area = 0.0;
  {
    nb::gil_scoped_release nogil;
    for (std::int64_t x : facets)
      if (x < 0 || static_cast<std::size_t>(x) >= n) throw std::invalid_argument("hull_d_attributes: a facet names point " + std::to_string(x));
    for (std::size_t k = 0; k < m; ++k) {  // ascending, the permutation's parity kept by the last two
      std::int64_t* r = facets.data() + k * d;
      bool odd = false;
      for (std::size_t a = 1; a < d; ++a)
        for (std::size_t b = a; b > 0 && r[b] < r[b - 1]; --b) std::swap(r[b], r[b - 1]), odd = !odd;
      if (odd) std::swap(r[d - 2], r[d - 1]);
    }
    std::vector<std::size_t> order(m);
    for (std::size_t k = 0; k < m; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::lexicographical_compare(facets.begin() + static_cast<std::ptrdiff_t>(a * d),
                                          facets.begin() + static_cast<std::ptrdiff_t>((a + 1) * d),
                                          facets.begin() + static_cast<std::ptrdiff_t>(b * d),
                                          facets.begin() + static_cast<std::ptrdiff_t>((b + 1) * d));
    });
    {
      std::vector<std::int64_t> sorted(m * d);
      for (std::size_t k = 0; k < m; ++k)
        std::copy_n(facets.begin() + static_cast<std::ptrdiff_t>(order[k] * d), d, sorted.begin() + static_cast<std::ptrdiff_t>(k * d));
      facets = std::move(sorted);
    }
    vertices = facets;
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    nbr = facet_neighbors(m, d, n, [&](std::size_t i, std::size_t l) { return facets[i * d + l]; });
    const double* a = p.data();
    double big = 0.0;
    for (std::int64_t v : vertices)
      for (std::size_t j = 0; j < d; ++j) big = std::max(big, std::fabs(a[static_cast<std::size_t>(v) * d + j]));
    int e = 0;
    std::frexp(big > 0 ? big : 1.0, &e);
    // x 2^-e: a multiplication by the power of two where 2^-e is a normal
    // double (the same correctly rounded value as ldexp, which was a sixth of
    // this call's time in 5D), ldexp beyond
    const double pow2 = (e > -1000 && e < 1000) ? std::ldexp(1.0, -e) : 0.0;
    auto P = [&](std::int64_t v, std::size_t j) {
      const double x = a[static_cast<std::size_t>(v) * d + j];
      return pow2 != 0.0 ? x * pow2 : std::ldexp(x, -e);
    };
    double fact = 1.0;  // (d-1)!
    for (std::size_t k = 2; k < d; ++k) fact *= static_cast<double>(k);
    double sa = 0.0, ca = 0.0, sv = 0.0, cv = 0.0;  // Neumaier sums of the sizes and cones
    auto add = [](double& sum, double& c, double x) {
      const double t = sum + x;
      c += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
      sum = t;
    };
    // per facet (in parallel pieces): its equation, its size and its cone's
    // (then summed in facet order, as one loop would)
    std::vector<double> sizes(m), cones(m);
    cpu::par_for(m, 256, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const std::int64_t* r = facets.data() + k * d;
        double U[8][9];  // rows f_i - f_0, i = 1..d-1
        for (std::size_t i = 1; i < d; ++i)
          for (std::size_t j = 0; j < d; ++j) U[i - 1][j] = P(r[i], j) - P(r[0], j);
        double nrm[9], size2 = 0.0;
        for (std::size_t c = 0; c < d; ++c) {  // (-1)^(d-1+c) det(U without column c)
          double M[64];
          const std::size_t s = d - 1;
          for (std::size_t i = 0; i < s; ++i)
            for (std::size_t j = 0, q = 0; j < d; ++j)
              if (j != c) M[i * s + q++] = U[i][j];
          const double det = cpu::det_gauss_double(M, static_cast<int>(s));
          nrm[c] = (d - 1 + c) % 2 == 0 ? det : -det;
          size2 += nrm[c] * nrm[c];
        }
        const double size = std::sqrt(size2);
        double* eq = equations.data() + k * (d + 1);
        double off = 0.0, cone = 0.0;
        for (std::size_t c = 0; c < d; ++c) {
          eq[c] = nrm[c] / size;
          off -= eq[c] * a[static_cast<std::size_t>(r[0]) * d + c];
          cone += nrm[c] * (P(r[0], c) - P(vertices[0], c));
        }
        eq[d] = off;
        sizes[k] = size, cones[k] = cone;
      }
    });
    for (std::size_t k = 0; k < m; ++k) add(sa, ca, sizes[k]), add(sv, cv, cones[k]);
    area = std::ldexp((sa + ca) / fact, static_cast<int>(d - 1) * e);
    volume = std::ldexp((sv + cv) / (fact * static_cast<double>(d)), static_cast<int>(d) * e);
  }
  const std::size_t nv = vertices.size();
  return {index_array(std::move(facets), m, d), index_array(std::move(vertices), nv, 0, true), index_array(std::move(nbr), m, d),
          double_array(std::move(equations), m, d + 1), volume, area};
}

// In-place insertion for ConvexHull(..., incremental=True).add_points: the
// hull kernel (kernels_cpu/rtd/hull_d, every d = 2..9) kept between calls
// (cpu::HullDIncremental); add() inserts only the new points. Each result is
// put in the canonical form of the one-shot call and certified as it is:
// 2D the counter-clockwise cycle from its smallest index (cpu::certify_hull2),
// 3D the canonical counter-clockwise triangles (cpu::certify_hull3), then
// the same attributes as hull2 / hull3; 4D..9D the facets in hull_d's
// convention, certified by hull_d_problem, for Python's _hull_d to finish.
//
// What is certified after an add: the hull of S' = (the vertices of the last
// certified hull) ∪ (the new points), on S' alone, so that an add costs
// O(hull + new points), not O(all points). Sound: the last certificate
// showed every earlier point a vertex of, or (under SoS) strictly inside,
// conv(old vertices), so conv(all points) = conv(S'), and a point strictly
// inside stays strictly inside a larger hull, never a vertex; the canonical
// hull of all the points is then the canonical hull of S'. S' keeps the
// input order (a monotone renumbering), under which every SoS sign is the
// same (the perturbation depends on the order of the indices only:
// predicates.hpp), and so is the canonical form (smallest index first,
// sorted). The construction certifies on all its points.
class IncrementalHull {
 public:
  IncrementalHull(const Points& p, int threads) : threads_(threads) {
    const PointSet ps = point_set(p, std::nullopt);
    if (ps.dim < 2 || ps.dim > 9) throw std::invalid_argument("ConvexHull expects points of shape (n, d) with d = 2..9");
    nb::gil_scoped_release nogil;
    require_spanning(ps);
    kernel_ = std::make_unique<cpu::HullDIncremental>(ps);
    finish(ps);
  }

  // Seeded with the hull of p, certified by the caller (Python's ConvexHull:
  // its one-shot call's certified hull, on its vertices only): f its facets
  // in hull_d's convention (orient_d(facet, x) < 0 inside), nb their
  // neighbours (nb[k][j] across the ridge opposite vertex j). Nothing is
  // certified here and attributes() / facets() are refused until an add,
  // whose result is certified on p and the new points (finish(): sound, as
  // p's hull was certified). On a kernel over the vertices only (every
  // point of p on the hull), the first add costs O(hull + new points), with
  // no construction and no ridge matching.
  IncrementalHull(const Points& p, int threads, const Cells& f, const Cells& nb) : threads_(threads) {
    const PointSet ps = point_set(p, std::nullopt);
    const std::size_t d = static_cast<std::size_t>(ps.dim), m = f.shape(0);
    if (ps.dim < 2 || ps.dim > 9 || f.shape(1) != d || nb.shape(0) != m || nb.shape(1) != d)
      throw std::invalid_argument("ConvexHull expects points (n, d), d = 2..9, seed facets and neighbours (m, d)");
    auto rows = [&](const Cells& a, std::size_t bound, const char* what) {
      std::vector<std::vector<Index>> r(m, std::vector<Index>(d));
      for (std::size_t k = 0; k < m; ++k)
        for (std::size_t c = 0; c < d; ++c) {
          const std::int64_t x = a.data()[k * d + c];
          if (x < 0 || static_cast<std::size_t>(x) >= bound)
            throw std::invalid_argument(std::string("ConvexHull: a seed ") + what + " is out of range: " + std::to_string(x));
          r[k][c] = static_cast<Index>(x);
        }
      return r;
    };
    const std::vector<std::vector<Index>> facets = rows(f, ps.size(), "facet's point"), neighbors = rows(nb, m, "neighbour");
    nb::gil_scoped_release nogil;
    kernel_ = std::make_unique<cpu::HullDIncremental>(ps, facets, neighbors);
    std::vector<Index> v;
    for (const auto& t : facets) v.insert(v.end(), t.begin(), t.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    vertices_ = std::move(v);
  }

  // p: the points given so far, unchanged, followed by the new ones.
  void add(const Points& p) {
    const PointSet ps = point_set(p, std::nullopt);
    nb::gil_scoped_release nogil;
    const std::size_t first = kernel_->size();
    kernel_->add(ps);
    finish(ps, first);
  }

  // 2D and 3D: hull2's / hull3's attribute tuple
  HullTuple attributes() {
    if (!finished_) throw std::logic_error("ConvexHull: a seeded hull has no attributes before an add");
    if (!facets_.empty()) throw std::logic_error("ConvexHull: attributes() is for 2D and 3D hulls");
    if (!cycle_.empty()) {
      Hull2Attributes a = a2_;
      return hull2_tuple(cycle_, a);
    }
    Hull3Attributes a = a3_;
    return hull3_tuple(tris_, a);
  }
  // 4D..9D: the certified facets
  IndexArray facets() const {
    if (!finished_) throw std::logic_error("ConvexHull: a seeded hull has no facets before an add");
    if (facets_.empty()) throw std::logic_error("ConvexHull: facets() is for hulls in 4D..9D");
    return cells_array(facets_, facets_[0].size());
  }
  std::size_t size() const { return kernel_->size(); }

 private:
  // first: the points certified before (0 at construction: all of ps)
  void finish(const PointSet& ps, std::size_t first = 0) {
    finished_ = false;
    std::vector<std::vector<Index>> f = kernel_->facets();
    // S' (above): sub[j] the input index of position j, ascending; pos the inverse
    std::vector<Index> sub;
    if (first != 0) {
      sub = vertices_;
      for (std::size_t i = first; i < ps.size(); ++i) sub.push_back(static_cast<Index>(i));
    }
    PointSet part;
    if (first != 0) {
      part.dim = ps.dim;
      std::vector<double> c;
      c.reserve(sub.size() * static_cast<std::size_t>(ps.dim));
      for (Index i : sub) c.insert(c.end(), ps.point(i), ps.point(i) + ps.dim);
      part.coords = Values(std::move(c));
    }
    const PointSet& cps = first != 0 ? part : ps;
    auto local = [&](Index i) {  // input index -> index in cps
      return first != 0 ? static_cast<Index>(std::lower_bound(sub.begin(), sub.end(), i) - sub.begin()) : i;
    };
    if (ps.dim == 2) {
      // an edge (a, b) has the inside on its right (orient2d(a, b, x) < 0):
      // clockwise, so b's counter-clockwise successor is a
      std::unordered_map<Index, Index> next;
      Index start = f[0][0];
      for (const auto& e : f) {
        next[e[1]] = e[0];
        start = std::min(start, e[0]);
      }
      std::vector<Index> cycle{start};
      for (Index v = next.at(start); v != start && cycle.size() <= f.size(); v = next.at(v)) cycle.push_back(v);
      std::vector<Index> lc(cycle.size());
      for (std::size_t k = 0; k < cycle.size(); ++k) lc[k] = local(cycle[k]);
      check_certified(cpu::certify_hull2(cps, lc, certify::Level::canonical, threads_), "hull2");
      a2_ = Hull2Attributes(ps, cycle);
      vertices_ = cycle;
      std::sort(vertices_.begin(), vertices_.end());
      cycle_ = std::move(cycle);
    } else if (ps.dim == 3) {
      // orient3d(a, b, c, x) < 0 inside is det[b-a, c-a, x-a] > 0 inside:
      // (a, c, b) is counter-clockwise seen from outside
      std::vector<Triangle> tris, lt;
      tris.reserve(f.size());
      for (const auto& t : f) tris.push_back({t[0], t[2], t[1]});
      tris = canonical_triangles(std::move(tris));
      lt.reserve(tris.size());
      for (const Triangle& t : tris) lt.push_back({local(t[0]), local(t[1]), local(t[2])});
      check_certified(cpu::certify_hull3(cps, lt, certify::Level::canonical, threads_), "hull3");
      a3_ = Hull3Attributes(ps, tris);
      vertices_ = a3_.vertices;
      tris_ = std::move(tris);
    } else {
      std::vector<std::vector<Index>> lf = f;
      for (auto& x : lf)
        for (Index& i : x) i = local(i);
      if (const std::string why = cpu::hull_d_problem(cps, lf); !why.empty())
        throw std::runtime_error("the ConvexHull result failed certification: " + why);
      std::vector<Index> v;
      for (const auto& x : f) v.insert(v.end(), x.begin(), x.end());
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
      vertices_ = std::move(v);
      facets_ = std::move(f);
    }
    finished_ = true;
  }

  int threads_;
  std::unique_ptr<cpu::HullDIncremental> kernel_;
  std::vector<Index> cycle_;  // 2D
  Hull2Attributes a2_;
  std::vector<Triangle> tris_;  // 3D
  Hull3Attributes a3_;
  std::vector<std::vector<Index>> facets_;  // 4D..9D
  std::vector<Index> vertices_;             // of the last certified hull, ascending
  bool finished_ = false;                   // the attributes are those of a certified hull
};

// neighbors[i][j]: the simplex across the facet opposite vertex j of
// simplex i, -1 on the boundary (scipy's convention); facet_neighbors with
// the point indices as buckets.
IndexArray neighbors(const Cells& c) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  if (k < 2 || k > 10) throw std::invalid_argument("neighbors expects simplices of shape (m, k) with k = 2..10");
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
  double lo[kMaxD], hi[kMaxD];
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

// Exact point location: for each query, a simplex that contains it (closed),
// -1 when outside all. Among several (a query on a shared face), the one of
// positive volume holding x' below — the query moved infinitesimally towards
// the first simplex of positive volume — strictly inside: unique, so the
// same for any batch of queries, any visiting order and any thread count.
// Simplices of zero volume contain nothing (the canonical answer may hold
// them; they cover no volume).
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
// every query exactly by the walk's own test (x' strictly inside a simplex of
// positive volume).
//   Why x' is strictly inside exactly one simplex of positive volume: such a
// simplex has no degenerate facet, so x' is strictly on one side of each of
// its facets' hyperplanes; these simplices tile the hull with disjoint
// interiors, and x' lies in the hull's interior whenever x is in the hull.
using Signs = nb::ndarray<const std::int8_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

// Every index of the rows of c names one of n points (what: the caller, for
// the message; std::invalid_argument naming the first that does not).
void check_indices(const Cells& c, std::size_t n, const char* what) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  for (std::size_t i = 0; i < m * k; ++i)
    if (c.data()[i] < 0 || static_cast<std::uint64_t>(c.data()[i]) >= n)
      throw std::invalid_argument(std::string(what) + "simplex " + std::to_string(i / k) + " names point " +
                                  std::to_string(c.data()[i]));
}

// The exact sign of det[[v_0 1] ... [v_d 1]] of every simplex (0: zero
// volume), in parallel pieces; find_simplex's, which Python computes once per
// triangulation and passes back (on near-degenerate input these signs are
// exact-stage calls: 65 ms of a 90 ms find_simplex on a perturbed 3^5 grid).
std::vector<std::int8_t> signs_of(const PointSet& ps, const Cells& c) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  if (k < 2 || k > static_cast<std::size_t>(kMaxD) + 1) throw std::invalid_argument("simplices need 2..10 vertices");
  check_indices(c, ps.size(), "");
  std::vector<std::int8_t> own(m);
  cpu::par_for(m, 256, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t s = lo; s < hi; ++s) {
      const double* rows[kMaxD + 1];
      for (std::size_t l = 0; l < k; ++l) rows[l] = ps.point(static_cast<std::size_t>(c.data()[s * k + l]));
      own[s] = static_cast<std::int8_t>(pred::orient_d_exact(static_cast<int>(k - 1), rows));
    }
  });
  return own;
}

nb::ndarray<nb::numpy, std::int8_t> simplex_signs(const Points& p, const Cells& c) {
  const PointSet ps = point_set(p, std::nullopt);
  if (c.shape(1) != static_cast<std::size_t>(ps.dim) + 1) throw std::invalid_argument("simplices need d+1 indices");
  std::vector<std::int8_t> v;
  {
    nb::gil_scoped_release nogil;
    v = signs_of(ps, c);
  }
  auto* heap = new std::vector<std::int8_t>(std::move(v));
  nb::capsule owner(heap, [](void* x) noexcept { delete static_cast<std::vector<std::int8_t>*>(x); });
  return nb::ndarray<nb::numpy, std::int8_t>(heap->data(), {heap->size()}, owner);
}

// Delaunay.equations: per simplex the unit normal and offset of the
// hyperplane through its lifted vertices z = (x, 2^-e (|x|^2 - w)) (e: the
// lift exponent, Python's paraboloid_scale = 2^-e; |x|^2 summed as
// 2^e |2^-e x|^2, as lift_points), the normal pointing down (up for the
// furthest site): n_k = (-1)^(k+d+1) det(M without column k) for M = the
// rows z_j - z_0 scaled by a power of two (exact), normalised; offset -n.z_0.
// Floating point (cpu::det_gauss_double); NaN for a simplex whose lifted
// vertices span no hyperplane. In parallel pieces.
DoubleArray lifted_equations(const Points& p, const std::optional<Vector>& w, const Cells& c, int e, bool furthest) {
  const PointSet ps = point_set(p, w);
  const std::size_t m = c.shape(0), k = c.shape(1), d = static_cast<std::size_t>(ps.dim);
  if (k != d + 1 || d > static_cast<std::size_t>(kMaxD)) throw std::invalid_argument("equations: simplices need d+1 indices");
  check_indices(c, ps.size(), "equations: ");
  std::vector<double> out(m * (d + 2));
  {
    nb::gil_scoped_release nogil;
    const double scale = std::ldexp(1.0, -e);
    cpu::par_for(m, 256, [&](std::size_t lo, std::size_t hi) {
      double z[kMaxD + 1][kMaxD + 1], M[kMaxD][kMaxD + 1], sub[kMaxD * kMaxD], n[kMaxD + 1];
      for (std::size_t s = lo; s < hi; ++s) {
        for (std::size_t j = 0; j <= d; ++j) {
          const std::size_t i = static_cast<std::size_t>(c.data()[s * k + j]);
          const double* x = ps.point(i);
          double h = 0.0;
          for (std::size_t l = 0; l < d; ++l) {
            const double t = std::ldexp(x[l], -e);
            h += t * t;
            z[j][l] = x[l];
          }
          z[j][d] = std::ldexp(h, e) - (ps.weighted ? ps.weights[i] * scale : 0.0);
        }
        double big = 0.0;
        for (std::size_t r = 0; r < d; ++r)
          for (std::size_t l = 0; l <= d; ++l) {
            M[r][l] = z[r + 1][l] - z[0][l];
            big = std::max(big, std::fabs(M[r][l]));
          }
        int e2 = 0;
        std::frexp(big, &e2);
        for (std::size_t r = 0; r < d; ++r)
          for (std::size_t l = 0; l <= d; ++l) M[r][l] = std::ldexp(M[r][l], -e2);
        double norm2 = 0.0;
        for (std::size_t col = 0; col <= d; ++col) {
          for (std::size_t r = 0; r < d; ++r)
            for (std::size_t l = 0, q = 0; l <= d; ++l)
              if (l != col) sub[r * d + q++] = M[r][l];
          const double det = d > 0 ? cpu::det_gauss_double(sub, static_cast<int>(d)) : 1.0;
          n[col] = ((col + d + 1) % 2 == 0 ? det : -det) * (furthest ? -1.0 : 1.0);
          norm2 += n[col] * n[col];
        }
        const double norm = std::sqrt(norm2);
        double* o = out.data() + s * (d + 2);
        double off = 0.0;
        for (std::size_t l = 0; l <= d; ++l) {
          o[l] = n[l] / norm;
          off -= o[l] * z[0][l];
        }
        o[d + 1] = off;
      }
    });
  }
  return double_array(std::move(out), m, d + 2);
}

// Delaunay.vertex_neighbor_vertices: (indptr, indices) over n points, each
// vertex's neighbours (the other vertices of its simplices) ascending, a
// point of no simplex with none. A counting sort of the (vertex, other)
// pairs by vertex, then each vertex's run sorted and made unique, in
// parallel pieces.
std::pair<IndexArray, IndexArray> vertex_neighbours(const Cells& c, std::size_t n) {
  const std::size_t m = c.shape(0), k = c.shape(1);
  check_indices(c, n, "vertex_neighbor_vertices: ");
  std::vector<std::int64_t> start(n + 1, 0), pairs(m * k * (k - 1)), indptr(n + 1, 0), out;
  {
    nb::gil_scoped_release nogil;
    const std::int64_t* S = c.data();
    for (std::size_t i = 0; i < m * k; ++i) start[static_cast<std::size_t>(S[i]) + 1] += static_cast<std::int64_t>(k - 1);
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t s = 0; s < m; ++s)
      for (std::size_t a = 0; a < k; ++a)
        for (std::size_t b = 0; b < k; ++b)
          if (a != b) pairs[static_cast<std::size_t>(fill[static_cast<std::size_t>(S[s * k + a])]++)] = S[s * k + b];
    std::vector<std::int64_t> len(n, 0);
    cpu::par_for(n, 1024, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t v = lo; v < hi; ++v) {
        auto b = pairs.begin() + start[v], e = pairs.begin() + start[v + 1];
        std::sort(b, e);
        len[v] = std::unique(b, e) - b;
      }
    });
    for (std::size_t v = 0; v < n; ++v) indptr[v + 1] = indptr[v] + len[v];
    out.resize(static_cast<std::size_t>(indptr[n]));
    cpu::par_for(n, 1024, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t v = lo; v < hi; ++v)
        std::copy_n(pairs.begin() + start[v], len[v], out.begin() + indptr[v]);
    });
  }
  const std::size_t total = out.size();
  return {index_array(std::move(indptr), n + 1, 0, true), index_array(std::move(out), total, 0, true)};
}

// The exact power_d sign (no perturbation; pred::power_d_exact, may be 0)
// of each row of d+2 point indices: det Λ with rows (p, |p|^2 - w, 1), the
// 1-column last (weights: null for Delaunay). In parallel pieces.
nb::ndarray<nb::numpy, std::int8_t> power_signs(const Points& p, const std::optional<Vector>& w, const Cells& c) {
  const PointSet ps = point_set(p, w);
  const std::size_t m = c.shape(0), k = c.shape(1), d = static_cast<std::size_t>(ps.dim);
  if (k != d + 2 || d < 1 || d > 9) throw std::invalid_argument("power_signs: rows of d+2 point indices, d = 1..9");
  check_indices(c, ps.size(), "power_signs: ");
  auto* heap = new std::vector<std::int8_t>(m);
  {
    nb::gil_scoped_release nogil;
    cpu::par_for(m, 256, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t s = lo; s < hi; ++s) {
        const double* rows[11];
        double wt[11];
        for (std::size_t l = 0; l < k; ++l) {
          const std::size_t i = static_cast<std::size_t>(c.data()[s * k + l]);
          rows[l] = ps.point(i);
          wt[l] = ps.weight(i);
        }
        (*heap)[s] = static_cast<std::int8_t>(pred::power_d_exact(static_cast<int>(d), rows, wt));
      }
    });
  }
  nb::capsule owner(heap, [](void* x) noexcept { delete static_cast<std::vector<std::int8_t>*>(x); });
  return nb::ndarray<nb::numpy, std::int8_t>(heap->data(), {heap->size()}, owner);
}

// Delaunay.transform, scipy's barycentric transforms: per simplex (v_0..v_d),
// T with column j = v_j - v_d; the (d+1, d) block [T^-1; v_d], row-major,
// simplex after simplex. NaN rows where the simplex is exactly flat (signs,
// simplex_signs' exact orientations, 0), where T's entries are not finite,
// or where T is singular in floating point (a zero pivot). T is scaled by
// 2^-e first (its largest |entry| in [1/2, 1): exact, so no intermediate
// over- or underflows), inverted by Gauss–Jordan elimination with partial
// pivoting in double, and the inverse scaled by 2^-e (T^-1 = (2^-e T)^-1
// 2^-e). In parallel pieces; the same values at any thread count.
DoubleArray barycentric_transforms(const Points& p, const Cells& c, const Signs& signs) {
  const PointSet ps = point_set(p, std::nullopt);
  const std::size_t m = c.shape(0), k = c.shape(1), d = k - 1;
  if (k != static_cast<std::size_t>(ps.dim) + 1 || d > static_cast<std::size_t>(kMaxD))
    throw std::invalid_argument("transform: simplices need d+1 indices");
  if (signs.shape(0) != m) throw std::invalid_argument("transform: one sign per simplex");
  check_indices(c, ps.size(), "transform: ");
  std::vector<double> out(m * k * d);
  {
    nb::gil_scoped_release nogil;
    cpu::par_for(m, 256, [&](std::size_t lo, std::size_t hi) {
      double a[kMaxD][2 * kMaxD];  // [T | I], reduced to [I | T^-1]
      for (std::size_t s = lo; s < hi; ++s) {
        double* o = out.data() + s * k * d;
        const double* r = ps.point(static_cast<std::size_t>(c.data()[s * k + d]));
        for (std::size_t j = 0; j < d; ++j) o[d * d + j] = r[j];
        bool ok = signs.data()[s] != 0;
        double big = 0.0;
        for (std::size_t j = 0; j < d && ok; ++j) {  // column j: v_j - r
          const double* v = ps.point(static_cast<std::size_t>(c.data()[s * k + j]));
          for (std::size_t i = 0; i < d; ++i) {
            a[i][j] = v[i] - r[i];
            big = std::max(big, std::fabs(a[i][j]));
          }
        }
        ok = ok && std::isfinite(big) && big > 0.0;
        int e = 0;
        if (ok) std::frexp(big, &e);
        for (std::size_t i = 0; i < d && ok; ++i)
          for (std::size_t j = 0; j < d; ++j) {
            a[i][j] = std::ldexp(a[i][j], -e);
            a[i][d + j] = i == j ? 1.0 : 0.0;
          }
        for (std::size_t col = 0; col < d && ok; ++col) {
          std::size_t piv = col;
          for (std::size_t i = col + 1; i < d; ++i)
            if (std::fabs(a[i][col]) > std::fabs(a[piv][col])) piv = i;
          if (a[piv][col] == 0.0 || !std::isfinite(a[piv][col])) {
            ok = false;
            break;
          }
          if (piv != col)
            for (std::size_t j = 0; j < 2 * d; ++j) std::swap(a[piv][j], a[col][j]);
          const double inv = 1.0 / a[col][col];
          for (std::size_t j = 0; j < 2 * d; ++j) a[col][j] *= inv;
          for (std::size_t i = 0; i < d; ++i) {
            if (i == col || a[i][col] == 0.0) continue;
            const double f = a[i][col];
            for (std::size_t j = 0; j < 2 * d; ++j) a[i][j] -= f * a[col][j];
          }
        }
        for (std::size_t i = 0; i < d; ++i)
          for (std::size_t j = 0; j < d; ++j) {
            const double x = ok ? std::ldexp(a[i][d + j], -e) : std::nan("");
            o[i * d + j] = x;
          }
        if (!ok)
          for (std::size_t j = 0; j < d; ++j) o[d * d + j] = std::nan("");
      }
    });
  }
  auto* heap = new std::vector<double>(std::move(out));
  nb::capsule owner(heap, [](void* x) noexcept { delete static_cast<std::vector<double>*>(x); });
  const std::size_t shape[3] = {m, k, d};
  return DoubleArray(heap->data(), 3, shape, owner);
}

IndexArray find_simplex(const Points& p, const Cells& c, const Cells& nbr, const Points& q,
                        std::optional<Signs> signs, int threads) {
  const PointSet ps = point_set(p, std::nullopt);
  const std::size_t m = c.shape(0), k = c.shape(1), d = k - 1;
  if (q.shape(1) != d) throw std::invalid_argument("query points must have the points' dimension");
  if (nbr.shape(0) != m || nbr.shape(1) != k) throw std::invalid_argument("neighbors must have the simplices' shape");
  if (signs && signs->shape(0) != m) throw std::invalid_argument("signs must hold one sign per simplex");
  for (std::size_t i = 0; i < q.shape(0) * q.shape(1); ++i)
    if (!std::isfinite(q.data()[i])) throw std::invalid_argument("the query points hold NaN or infinite coordinates");
  std::vector<std::int64_t> out(q.shape(0), -1);
  if (m == 0) return index_array(std::move(out), q.shape(0), 0, true);
  {
    nb::gil_scoped_release nogil;
    auto vtx = [&](std::size_t s, std::size_t j) { return ps.point(static_cast<std::size_t>(c.data()[s * k + j])); };
    // sign of det[[v_i 1]] with vertex j replaced by x (-1 for x = null: the simplex itself)
    auto orient = [&](std::size_t s, long j, const double* x) {
      const double* rows[kMaxD + 1];
      for (std::size_t l = 0; l < k; ++l) rows[l] = static_cast<long>(l) == j ? x : vtx(s, l);
      return pred::orient_d_exact(static_cast<int>(d), rows);
    };
    std::vector<std::int8_t> own;
    if (signs) {
      own.assign(signs->data(), signs->data() + m);
      for (std::int8_t x : own)
        if (x < -1 || x > 1) throw std::invalid_argument("signs must be -1, 0 or 1");
    } else {
      own = signs_of(ps, c);
    }
    int positive = 0;  // the sign of every simplex of non-zero volume (all are positive in one convention)
    for (std::size_t s = 0; s < m && positive == 0; ++s) positive = own[s];
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
    // the points' bounding box: a query strictly outside it in some
    // coordinate is strictly outside the hull (exact comparisons), -1 without
    // a walk (on a grid every query outside the hull is; its walk along the
    // flat boundary simplices was most of the time)
    double lo[kMaxD], hi[kMaxD];
    for (std::size_t j = 0; j < d; ++j) lo[j] = hi[j] = ps.point(0)[j];
    for (std::size_t i = 1; i < ps.size(); ++i)
      for (std::size_t j = 0; j < d; ++j) lo[j] = std::min(lo[j], ps.point(i)[j]), hi[j] = std::max(hi[j], ps.point(i)[j]);
    // One query: the walk from `cur` (updated: where it ended), else the
    // scan. The answer does not depend on where the walk starts (header:
    // the simplex of positive volume holding x' strictly inside), so the
    // queries run in parallel pieces of the Morton order, each piece's walks
    // chained, with the same answer at any thread count.
    auto locate = [&](const double* x, std::size_t& cur) -> std::int64_t {
      bool boxed = true;
      for (std::size_t j = 0; j < d; ++j) boxed &= x[j] >= lo[j] && x[j] <= hi[j];
      if (!boxed) return -1;
      std::size_t prev = m;  // where the walk came from (m: nowhere)
      for (std::size_t steps = 0; steps < 4 * m + 16; ++steps) {
        // the simplex's sign; a flat one's under SoS (header)
        const int sign = own[cur] != 0 ? own[cur] : positive;
        long exit_facet = -1;
        for (std::size_t j = 0; j < k && exit_facet < 0; ++j)
          if (side(cur, j, x) * sign < 0) exit_facet = static_cast<long>(j);
        if (exit_facet < 0 && own[cur] != 0) return static_cast<std::int64_t>(cur);
        std::int64_t next = -1;
        if (exit_facet >= 0) {
          next = neighbour(cur, static_cast<std::size_t>(exit_facet));
          if (next < 0) return -1;  // beyond a boundary facet: outside the hull
        } else {  // a flat simplex with the query in its hyperplane: on to a neighbour
          for (std::size_t j = 0; j < k && (next < 0 || static_cast<std::size_t>(next) == prev); ++j)
            next = neighbour(cur, (j + steps) % k);
          if (next < 0) break;
        }
        prev = cur;
        cur = static_cast<std::size_t>(next);
      }
      // the walk did not settle: the scan, by the walk's own test (x'
      // strictly inside, never 0 on a simplex of positive volume), so that
      // it finds the walk's answer
      for (std::size_t s = 0; s < m; ++s) {
        if (own[s] == 0) continue;
        bool in = true;
        for (std::size_t j = 0; j < k && in; ++j) in = side(s, j, x) * own[s] > 0;
        if (in) return static_cast<std::int64_t>(s);
      }
      return -1;
    };
    const std::vector<std::size_t> order = morton_order(q.data(), q.shape(0), d);
    const std::size_t nq = order.size();
    // pieces of at least 64 queries, about four per worker
    const std::size_t workers =
        static_cast<std::size_t>(threads > 0 ? threads : tbb::info::default_concurrency());
    const std::size_t pieces = own[ref] == 0 ? 1 : std::max<std::size_t>(1, std::min(4 * workers, nq / 64));
    auto run_pieces = [&](std::size_t first, std::size_t last) {
      for (std::size_t piece = first; piece < last; ++piece) {
        std::size_t cur = ref;
        for (std::size_t i = nq * piece / pieces; i < nq * (piece + 1) / pieces; ++i)
          out[order[i]] = locate(q.data() + order[i] * d, cur);
      }
    };
    if (pieces == 1)  // (all flat: nothing is found, each query scans)
      run_pieces(0, 1);
    else
      cpu::with_threads(threads, [&] { cpu::par_for(pieces, 1, run_pieces); });
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
      r = cpu::certify_rtd(ps, cells, level);
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
        const double* rows[kMaxD + 1];
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
    check_certified(cpu::certify_rtd(pu, result), "instant flip");
  }
  return {cells_array(result, static_cast<std::size_t>(p.shape(1) + 1)), flips};
}


// ---- Voronoi / power diagrams: the dual of the certified triangulation --------
//
// voronoi(points, weights, simplices, threads) takes the canonical (certified)
// regular triangulation computed by `triangulate` and returns the diagram's
// vertices and topology (python/flipflop/voronoi.py documents the rules):
//
// * Every simplex of positive volume has one exact centre (circumcentre; with
//   weights the power centre, where |c - p|^2 - w is equal for its d + 1
//   vertices). It is computed exactly in integers (below) and rounded
//   correctly to doubles (round_ratio). Simplices of zero volume (the
//   canonical answer may hold them on degenerate input) have none: their
//   group is -1.
// * The positive simplices of the canonical answer are the positive
//   simplices of a triangulation refining the exact regular subdivision (the
//   lower hull of the lifted points, unperturbed): each lies in one cell of
//   it, and its centre is that cell's centre (the limit of the perturbed
//   lower facet's hyperplane is the unperturbed hyperplane through its lifted
//   vertices, which spans d + 1 affinely independent points and supports the
//   lifted set). Two cells never share a centre (two supporting hyperplanes
//   of the same slope are equal), so simplices with equal exact centres are
//   exactly the simplices of one cell: one Voronoi vertex per cell. They are
//   grouped by their rounded centres (equal exact centres round equally)
//   and then compared exactly within each run of equal rounded centres.
// * "Infinite groups": the exact facets of the convex hull, each with the
//   points lying on its hyperplane (found from the boundary facets of the
//   triangulation, joined across ridges while coplanar (exact orient), and
//   the zero-volume simplices lying in that hyperplane next to them, which
//   hold the points of the hull facet that the perturbation moved inwards).
// * Regions and ridges (5 and 6 in voronoi_core): Q is the lower hull of the
//   lifted points with its vertical rays (the furthest-site diagram passes
//   the furthest-site triangulation, the upper hull's: everything below
//   holds with "upper" for "lower" — the arguments are combinatorial on the
//   cells, the hull facets and the exact centres, none of which tells the
//   two apart). Point i has a cell with interior
//   iff P_i is a vertex of Q (no third point lies in every cell and hull
//   facet around it); (i, j) is a ridge iff P_i, P_j are vertices of Q, some
//   cell holds both, and no third VERTEX of Q lies in every cell and hull
//   facet holding both (then the smallest face of Q holding them is the edge
//   P_iP_j). Points whose lifted point lies on a face of Q without being a
//   vertex (exact weight ties; the perturbation keeps them in the
//   triangulation) are ignored by the ridge test, and the ridges that pass
//   "through" them, for which the triangulation has no edge, are found from
//   them (the pairs of vertices of Q on a line through the point, either
//   side of it, in the face of Q its cells meet in).

struct Mpz {
  mpz_t v;
  Mpz() { mpz_init(v); }
  ~Mpz() { mpz_clear(v); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
};

// sign(M) * round-to-nearest-even(|M| / D * 2^E) as a double, D > 0: exact.
// |M| 2^s / D = q + r / D with q in [2^54, 2^56) (s chosen from the bit
// lengths), so q's bits are the value's leading 55 or 56 bits and r != 0 is
// the sticky bit. The value lies in [2^t, 2^(t+1)) with t = bits(q) - 1 + E - s;
// a double keeps p = 53 of those bits when t >= -1022, t + 1075 below
// (subnormals: the last kept bit is 2^-1074). Rounding the kept bits by the
// dropped ones (more than half, or exactly half with a non-zero sticky bit or
// an odd last kept bit: up) is IEEE's round-to-nearest-even; the rounded
// integer (at most 2^p, p <= 53) times a power of two is then a double
// exactly, or beyond the largest finite double, where ldexp gives +-inf,
// which is also the correctly rounded result (the value is at least
// (2 - 2^-53) 2^1023). p < 0 means a value below 2^-1075: zero.
double round_ratio(const mpz_t M, const mpz_t D, long E, mpz_t q, mpz_t r, mpz_t tmp) {
  const int sg = mpz_sgn(M);
  if (sg == 0) return 0.0;
  const long a = static_cast<long>(mpz_sizeinbase(M, 2)), b = static_cast<long>(mpz_sizeinbase(D, 2));
  const long s = 55 - (a - b);  // |M| 2^s / D in [2^(54), 2^(56))
  if (s >= 0) {
    mpz_abs(q, M);
    mpz_mul_2exp(q, q, static_cast<mp_bitcnt_t>(s));
    mpz_tdiv_qr(q, r, q, D);
  } else {
    mpz_mul_2exp(tmp, D, static_cast<mp_bitcnt_t>(-s));
    mpz_abs(q, M);
    mpz_tdiv_qr(q, r, q, tmp);
  }
  const std::uint64_t qv = mpz_get_ui(q);
  const bool sticky = mpz_sgn(r) != 0;
  const int nb = 64 - __builtin_clzll(qv);  // 55 or 56
  const long t = nb - 1 + E - s;
  const long p = t >= -1022 ? 53 : t + 1075;
  if (p < 0) return sg < 0 ? -0.0 : 0.0;
  const int drop = nb - static_cast<int>(p);  // >= 2
  std::uint64_t keep = drop >= 64 ? 0 : qv >> drop;
  const std::uint64_t rem = qv & ((std::uint64_t(1) << drop) - 1), half = std::uint64_t(1) << (drop - 1);
  if (rem > half || (rem == half && (sticky || (keep & 1)))) ++keep;
  const double x = std::ldexp(static_cast<double>(keep), static_cast<int>(std::max(-100000L, std::min(100000L, E - s + drop))));
  return sg < 0 ? -x : x;
}

// x = mant * 2^exp with |mant| < 2^53 an odd integer (x != 0): the
// largest exponent, so the exact solvers' integers carry no trailing zeros
// (an integer coordinate's unit is 1, a subnormal's 2^-1074 at the least)
inline void split_double(double x, std::int64_t& mant, long& ex) {
  int e;
  const double m = std::frexp(x, &e);
  mant = static_cast<std::int64_t>(std::ldexp(m, 53));
  ex = static_cast<long>(e) - 53;
  const int tz = __builtin_ctzll(static_cast<std::uint64_t>(mant));
  mant >>= tz;  // exact: the low tz bits are zero (arithmetic shift keeps the sign)
  ex += tz;
}

// Inputs whose magnitudes fall into two clusters far apart (a lattice with
// zeros moved by some ulp: subnormals beside values near 1): one common unit
// 2^E makes every integer of the plain solver below as long as the whole
// range (1,076 bits), and GMP's cost grows with that. SplitCentre writes
// every value as a polynomial in eps = 2^-T instead, with integer
// coefficients of the cluster's own size: a coordinate x = a_0 2^E_H (the
// large cluster, E_H its least exponent) or a_1 eps 2^E_H = a_1 2^E_L (the
// tiny one, E_L its least exponent, T = E_H - E_L); a weight (units
// 2^(2 E_H)) a_0 or a_2 eps^2. The same elimination then runs in Z[eps]:
// Bareiss' divisions and the back-substitution's are exact there too (the
// identities they rest on are polynomial identities in the entries, and
// their quotients are minors and Cramer numerators of the polynomial
// matrix, which have integer coefficients), done from the lowest
// coefficient up (q_j = (t_(j+l) - sum_(i<j) q_i p_(l+j-i)) / p_l, p_l the
// divisor's lowest non-zero coefficient: exact). Evaluating at eps = 2^-T is
// a ring homomorphism, so the results evaluate to the plain solver's
// determinant and numerators; multiplied by eps^-K (K the largest degree)
// they become integers, M_l and D with c_l = M_l / D 2^E_H, and D = 0 there
// means zero volume whatever the polynomial was.
constexpr int kPolyLen = 2 * kMaxD + 3;  // degrees <= 2 d + 2 (row b: 2, each elimination step: + 1 or 2)
struct Poly {
  Mpz c[kPolyLen];
  int deg = -1;  // -1: zero; coefficients above deg are not read
  void trim() {
    while (deg >= 0 && mpz_sgn(c[deg].v) == 0) --deg;
  }
  void clear() { deg = -1; }
  void set(const Poly& o) {
    deg = o.deg;
    for (int i = 0; i <= deg; ++i) mpz_set(c[i].v, o.c[i].v);
  }
  void swap(Poly& o) {
    const int n = std::max(deg, o.deg);
    for (int i = 0; i <= n; ++i) mpz_swap(c[i].v, o.c[i].v);
    std::swap(deg, o.deg);
  }
  void zero_to(int n) {  // deg = n, coefficients 0..n zero
    for (int i = 0; i <= n; ++i) mpz_set_ui(c[i].v, 0);
    deg = n;
  }
};
// out = a b - e f (out distinct from the operands)
inline void poly_mul_sub(Poly& out, const Poly& a, const Poly& b, const Poly& e, const Poly& f) {
  const int n1 = a.deg < 0 || b.deg < 0 ? -1 : a.deg + b.deg, n2 = e.deg < 0 || f.deg < 0 ? -1 : e.deg + f.deg;
  out.zero_to(std::max(n1, n2));
  if (n1 >= 0)
    for (int i = 0; i <= a.deg; ++i)
      if (mpz_sgn(a.c[i].v))
        for (int j = 0; j <= b.deg; ++j) mpz_addmul(out.c[i + j].v, a.c[i].v, b.c[j].v);
  if (n2 >= 0)
    for (int i = 0; i <= e.deg; ++i)
      if (mpz_sgn(e.c[i].v))
        for (int j = 0; j <= f.deg; ++j) mpz_submul(out.c[i + j].v, e.c[i].v, f.c[j].v);
  out.trim();
}
// q = t / p, exact in Z[eps] (p != 0; q distinct from t and p); acc scratch
inline void poly_divexact(Poly& q, const Poly& t, const Poly& p, mpz_t acc) {
  if (t.deg < 0) {
    q.clear();
    return;
  }
  int l = 0;
  while (mpz_sgn(p.c[l].v) == 0) ++l;
  const int qd = t.deg - p.deg;
  for (int j = 0; j <= qd; ++j) {
    mpz_set(acc, t.c[j + l].v);
    for (int i = std::max(0, j - (p.deg - l)); i < j; ++i) mpz_submul(acc, q.c[i].v, p.c[l + j - i].v);
    mpz_divexact(q.c[j].v, acc, p.c[l].v);
  }
  q.deg = qd;
  q.trim();
}

// The elimination both exact solvers run (CentreSolver over Z, SplitCentre
// over Z[eps]; CentreSolver's comment derives it): fraction-free (Bareiss)
// elimination of X = [V | b] (d x (d + 1)) with row swaps where a pivot is
// 0, then fraction-free back-substitution N'_i = (X[i][d] det V' -
// sum_(j > i) X[i][j] N'_j) / X[i][i]. Dn = det V'; false when det V = 0.
// R supplies the ring's operations on its elements El: is_zero, swap,
// set, mul_sub (out = a b - e f), mul, submul (acc -= a b) and divexact
// (q = t / p, exact); t is scratch.
template <class R, class El>
bool bareiss_cramer(R& r, int d, El (*X)[kMaxD + 1], El* N, El& Dn, El& t) {
  for (int k = 0; k < d; ++k) {
    if (r.is_zero(X[k][k])) {
      int rr = k + 1;
      while (rr < d && r.is_zero(X[rr][k])) ++rr;
      if (rr == d) return false;
      for (int j = k; j <= d; ++j) r.swap(X[k][j], X[rr][j]);
    }
    for (int i = k + 1; i < d; ++i)
      for (int j = k + 1; j <= d; ++j) {
        r.mul_sub(t, X[i][j], X[k][k], X[i][k], X[k][j]);
        if (k > 0)
          r.divexact(X[i][j], t, X[k - 1][k - 1]);
        else
          r.swap(X[i][j], t);
      }
  }
  r.set(Dn, X[d - 1][d - 1]);
  for (int i = d - 1; i >= 0; --i) {
    r.mul(t, X[i][d], Dn);
    for (int j = i + 1; j < d; ++j) r.submul(t, X[i][j], N[j]);
    r.divexact(N[i], t, X[i][i]);
  }
  return true;
}

struct IntRing {
  static bool is_zero(const Mpz& a) { return mpz_sgn(a.v) == 0; }
  static void swap(Mpz& a, Mpz& b) { mpz_swap(a.v, b.v); }
  static void set(Mpz& a, const Mpz& b) { mpz_set(a.v, b.v); }
  static void mul_sub(Mpz& out, const Mpz& a, const Mpz& b, const Mpz& e, const Mpz& f) {
    mpz_mul(out.v, a.v, b.v);
    mpz_submul(out.v, e.v, f.v);
  }
  static void mul(Mpz& out, const Mpz& a, const Mpz& b) { mpz_mul(out.v, a.v, b.v); }
  static void submul(Mpz& acc, const Mpz& a, const Mpz& b) { mpz_submul(acc.v, a.v, b.v); }
  static void divexact(Mpz& q, const Mpz& t, const Mpz& p) { mpz_divexact(q.v, t.v, p.v); }
};

struct SplitCentre {
  int d = 2;
  Poly P[kMaxD + 1][kMaxD], W[kMaxD + 1], X[kMaxD][kMaxD + 1], N[kMaxD], Dn, t, u, z;  // z: always zero
  Mpz acc;
  long EH = 0, T = 0;

  // Whether the values split into two clusters (a gap of at least kGap
  // binary orders between consecutive magnitudes); E_H and T when they do
  static constexpr int kGap = 128;
  bool classify(const double* const* p, const double* w) {
    int es[(kMaxD + 1) * kMaxD];
    int n = 0;
    for (int k = 0; k <= d; ++k)
      for (int l = 0; l < d; ++l)
        if (p[k][l] != 0) std::frexp(p[k][l], &es[n++]);
    if (n < 2) return false;
    std::sort(es, es + n);
    int cut = -1, best = kGap - 1;  // the split: es[cut] below, es[cut + 1] above
    for (int i = 0; i + 1 < n; ++i)
      if (es[i + 1] - es[i] > best) best = es[i + 1] - es[i], cut = i;
    if (cut < 0) return false;
    const int split_e = es[cut + 1];
    long eh = std::numeric_limits<long>::max(), el = std::numeric_limits<long>::max();
    std::int64_t mant;
    long ex;
    for (int k = 0; k <= d; ++k)
      for (int l = 0; l < d; ++l)
        if (p[k][l] != 0) {
          int e;
          std::frexp(p[k][l], &e);
          split_double(p[k][l], mant, ex);
          long& least = e >= split_e ? eh : el;
          least = std::min(least, ex);
        }
    EH = eh, T = eh - el;
    if (w)
      for (int k = 0; k <= d; ++k)
        if (w[k] != 0) {
          split_double(w[k], mant, ex);
          if (ex < 2 * el) return false;  // finer than eps^2 units: the plain solver
        }
    return true;
  }

  // a double as a polynomial: coordinates (scale 1) a_0 or a_1 eps, weights
  // (scale 2) a_0 or a_2 eps^2
  void load(Poly& out, double x, int scale) {
    out.clear();
    if (x == 0) return;
    std::int64_t mant;
    long ex;
    split_double(x, mant, ex);
    const long sh0 = ex - scale * EH;
    const int k = sh0 >= 0 ? 0 : scale;
    const long sh = sh0 + k * T;  // >= 0: classify's choice of E_L
    out.zero_to(k);
    mpz_set_si(out.c[k].v, static_cast<long>(mant));
    mpz_mul_2exp(out.c[k].v, out.c[k].v, static_cast<mp_bitcnt_t>(sh));
  }

  // 1: M, Dn (D > 0) and E filled; 0: zero volume
  int solve(const double* const* p, const double* w, Mpz* M, mpz_t D, long& E) {
    for (int k = 0; k <= d; ++k) {
      for (int l = 0; l < d; ++l) load(P[k][l], p[k][l], 1);
      if (w) load(W[k], w[k], 2);
    }
    for (int k = 1; k <= d; ++k) {
      Poly& b = X[k - 1][d];
      b.clear();
      for (int l = 0; l < d; ++l) {
        Poly& v = X[k - 1][l];  // P_k - P_0
        const int n = std::max(P[k][l].deg, P[0][l].deg);
        v.zero_to(n);
        for (int i = 0; i <= P[k][l].deg; ++i) mpz_add(v.c[i].v, v.c[i].v, P[k][l].c[i].v);
        for (int i = 0; i <= P[0][l].deg; ++i) mpz_sub(v.c[i].v, v.c[i].v, P[0][l].c[i].v);
        v.trim();
        poly_mul_sub(t, v, v, z, z);
        add_into(b, t);
      }
      if (w) {
        sub_into(b, W[k]);
        add_into(b, W[0]);
      }
    }
    if (!bareiss_cramer(*this, d, X, N, Dn, t)) return 0;
    // M_l = N_l + P0_l 2 Dn, D = 2 Dn; times eps^-K into integers
    for (int i = 0; i <= Dn.deg; ++i) mpz_mul_2exp(Dn.c[i].v, Dn.c[i].v, 1);
    int K = Dn.deg;
    for (int l = 0; l < d; ++l) {
      poly_mul_sub(t, P[0][l], Dn, z, z);
      add_into(N[l], t);
      K = std::max(K, N[l].deg);
    }
    auto to_int = [&](const Poly& a, mpz_t out) {
      mpz_set_ui(out, 0);
      for (int i = 0; i <= a.deg; ++i) {  // Horner in 2^T: sum a_i 2^(T (deg - i)), a_0 the leading term
        if (i > 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(T));
        mpz_add(out, out, a.c[i].v);
      }
      mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(T * (K - std::max(a.deg, 0))));
    };
    to_int(Dn, D);
    if (mpz_sgn(D) == 0) return 0;
    for (int l = 0; l < d; ++l) to_int(N[l], M[l].v);
    if (mpz_sgn(D) < 0) {
      mpz_neg(D, D);
      for (int l = 0; l < d; ++l) mpz_neg(M[l].v, M[l].v);
    }
    E = EH;
    return 1;
  }

  // the ring Z[eps] for bareiss_cramer (u, z, acc: scratch)
  static bool is_zero(const Poly& a) { return a.deg < 0; }
  static void swap(Poly& a, Poly& b) { a.swap(b); }
  static void set(Poly& a, const Poly& b) { a.set(b); }
  void mul_sub(Poly& out, const Poly& a, const Poly& b, const Poly& e, const Poly& f) { poly_mul_sub(out, a, b, e, f); }
  void mul(Poly& out, const Poly& a, const Poly& b) { poly_mul_sub(out, a, b, z, z); }
  void submul(Poly& acc_p, const Poly& a, const Poly& b) {
    poly_mul_sub(u, a, b, z, z);
    sub_into(acc_p, u);
  }
  void divexact(Poly& q, const Poly& t_p, const Poly& p) { poly_divexact(q, t_p, p, acc.v); }

 private:
  // a += b, or a -= b
  static void add_into(Poly& a, const Poly& b, bool subtract = false) {
    if (b.deg > a.deg) {
      for (int i = a.deg + 1; i <= b.deg; ++i) mpz_set_ui(a.c[i].v, 0);
      a.deg = b.deg;
    }
    for (int i = 0; i <= b.deg; ++i) (subtract ? mpz_sub : mpz_add)(a.c[i].v, a.c[i].v, b.c[i].v);
    a.trim();
  }
  static void sub_into(Poly& a, const Poly& b) { add_into(a, b, true); }
};

// The exact centre of a simplex of d + 1 points (weights optional):
// c_l = M[l] / D * 2^E with D > 0, or D = 0 for a simplex of zero volume.
// All coordinates are integers times 2^E and all weights integers times 2^(2E)
// (E the least exponent among them; a weight's halved, rounded down), so in
// units of 2^E: v_k = P_k - P_0 (k = 1..d) and b_k = |v_k|^2 - (W_k - W_0) are
// integers and the centre is P_0 + x with 2 v_k . x = b_k, solved exactly:
// y = 2 x solves V y = b, and by Cramer's rule y_l = N_l / det V with N_l
// the determinant of V with column l replaced by b. One fraction-free
// (Bareiss) elimination of the augmented matrix X = [V | b], rows swapped
// where a pivot is 0, gives both: its last pivot X[d-1][d-1] is det V' and
// X[d-1][d] is N'_(d-1) (V' = V with its rows permuted, N' accordingly: the
// swaps change every determinant's sign together, so y_l = N'_l / det V').
// Each row i of the eliminated X is a combination of the equations, so
// sum_(j >= i) X[i][j] y_j = X[i][d]; with y_j = N'_j / det V' this is
// fraction-free back-substitution,
//   N'_i = (X[i][d] det V' - sum_(j > i) X[i][j] N'_j) / X[i][i],
// an exact division (N'_i is an integer; X[i][i] is a non-zero pivot). This
// costs one elimination instead of the d + 1 of d + 1 determinants (5D:
// 40 + 15 multiplications of big integers instead of 180).
struct CentreSolver {
  int d = 2;
  Mpz P[kMaxD + 1][kMaxD], W[kMaxD + 1], X[kMaxD][kMaxD + 1], M[kMaxD], Dn, t, q, r, tmp;
  long E = 0;

  std::unique_ptr<SplitCentre> split;  // made on first use
  bool used_split = false;             // the last solve's path (for the tests)

  // false: zero volume
  bool solve(const double* const* p, const double* w) {
    if (!split) split = std::make_unique<SplitCentre>();
    split->d = d;
    used_split = split->classify(p, w);
    if (used_split) return split->solve(p, w, M, Dn.v, E) == 1;
    E = std::numeric_limits<long>::max();
    std::int64_t mant;
    long ex;
    for (int k = 0; k <= d; ++k)
      for (int l = 0; l < d; ++l)
        if (p[k][l] != 0) {
          split_double(p[k][l], mant, ex);
          E = std::min(E, ex);
        }
    if (w)
      for (int k = 0; k <= d; ++k)
        if (w[k] != 0) {
          split_double(w[k], mant, ex);
          E = std::min(E, ex >= 0 ? ex / 2 : -((-ex + 1) / 2));  // floor(ex / 2)
        }
    if (E == std::numeric_limits<long>::max()) E = 0;
    for (int k = 0; k <= d; ++k) {
      for (int l = 0; l < d; ++l) {
        if (p[k][l] == 0) {
          mpz_set_ui(P[k][l].v, 0);
          continue;
        }
        split_double(p[k][l], mant, ex);
        mpz_set_si(P[k][l].v, static_cast<long>(mant));
        mpz_mul_2exp(P[k][l].v, P[k][l].v, static_cast<mp_bitcnt_t>(ex - E));
      }
      if (w) {
        if (w[k] == 0) {
          mpz_set_ui(W[k].v, 0);
        } else {
          split_double(w[k], mant, ex);
          mpz_set_si(W[k].v, static_cast<long>(mant));
          mpz_mul_2exp(W[k].v, W[k].v, static_cast<mp_bitcnt_t>(ex - 2 * E));
        }
      }
    }
    for (int k = 1; k <= d; ++k) {
      mpz_t& b = X[k - 1][d].v;
      mpz_set_ui(b, 0);
      for (int l = 0; l < d; ++l) {
        mpz_sub(X[k - 1][l].v, P[k][l].v, P[0][l].v);
        mpz_addmul(b, X[k - 1][l].v, X[k - 1][l].v);
      }
      if (w) {
        mpz_sub(b, b, W[k].v);
        mpz_add(b, b, W[0].v);
      }
    }
    IntRing ring;
    if (!bareiss_cramer(ring, d, X, M, Dn, t)) return false;  // M[l] = N'_l, Dn = det V'
    // x_l = y_l / 2 = M_l / (2 Dn); M_l = N'_l + P0_l * 2 Dn
    mpz_mul_2exp(Dn.v, Dn.v, 1);
    for (int l = 0; l < d; ++l) mpz_addmul(M[l].v, P[0][l].v, Dn.v);
    if (mpz_sgn(Dn.v) < 0) {
      mpz_neg(Dn.v, Dn.v);
      for (int l = 0; l < d; ++l) mpz_neg(M[l].v, M[l].v);
    }
    return true;
  }

  void rounded(double* out) {
    for (int l = 0; l < d; ++l) out[l] = round_ratio(M[l].v, Dn.v, E, q.v, r.v, tmp.v);
  }
};


// A floating-point filter for the centres in 2D and 3D: the same Cramer
// formulas in long double (x87's 64-bit significand) with a running error
// bound per value (Wilkinson's running error analysis): for each operation
// a o b with operands a~, b~ known to within ea, eb, the result is within
// the propagated bound (|a~| eb + |b~| ea + ea eb for products, ea + eb for
// sums, (|a~| eb + |b~| ea) / (|b~| (|b~| - eb)) for quotients) plus U |r~|,
// U = LDBL_EPSILON = twice the unit roundoff (which also covers the ratio of
// the exact result to the computed one). Under- and overflow cannot occur:
// the values are polynomials of degree <= 4 (then one quotient) in doubles,
// inside 2^(+-4400), and long double reaches 2^(+-16382). The bounds
// themselves are computed in rounded arithmetic, < 60 operations on
// non-negative numbers, each off by a factor (1 +- 2^-64) at most: the
// final bound is inflated by (1 + 2^-50). The centre c = p0 + x lies in
// [s - e, s + e] (s its long double approximation); it rounds to the double
// h nearest s when that interval lies strictly between the midpoints of h
// and its two neighbouring doubles (computed exactly: they have 54
// significant bits; s - mid is exact by Sterbenz's lemma), for h normal
// and away from overflow; else the exact path decides. A simplex whose
// determinant's bound does not exclude zero also goes the exact way.
#if LDBL_MANT_DIG >= 64 && LDBL_MAX_EXP >= 16384
#define FLIPFLOP_VORONOI_FILTER 1
struct Ev {
  long double v, e;
};
constexpr long double kU = LDBL_EPSILON;
inline Ev ev_sub(Ev a, Ev b) {
  const long double v = a.v - b.v;
  return {v, a.e + b.e + kU * std::fabs(v)};
}
inline Ev ev_add(Ev a, Ev b) {
  const long double v = a.v + b.v;
  return {v, a.e + b.e + kU * std::fabs(v)};
}
inline Ev ev_mul(Ev a, Ev b) {
  const long double v = a.v * b.v;
  return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kU * std::fabs(v)};
}
inline Ev ev_det2(Ev a, Ev b, Ev c, Ev dd) { return ev_sub(ev_mul(a, dd), ev_mul(b, c)); }
inline Ev ev_det3(const Ev (*r)[3]) {
  const Ev c0 = ev_det2(r[1][1], r[1][2], r[2][1], r[2][2]);
  const Ev c1 = ev_det2(r[1][0], r[1][2], r[2][0], r[2][2]);
  const Ev c2 = ev_det2(r[1][0], r[1][1], r[2][0], r[2][1]);
  return ev_add(ev_sub(ev_mul(r[0][0], c0), ev_mul(r[0][1], c1)), ev_mul(r[0][2], c2));
}

// The double nearest to c, where the exact value lies within e of c (long
// double), when that interval lies strictly between the midpoints around
// it (computed exactly: 54 significant bits), for a normal double away from
// overflow; else false.
bool rounds_to(long double c, long double e, double& out) {
  if (!std::isfinite(c) || !std::isfinite(e)) return false;
  const double h = static_cast<double>(c);  // round to nearest
  const double ah = std::fabs(h);
  if (!(ah >= 0x1p-1000 && ah <= 0x1p1000)) return false;  // zero, subnormal range, overflow: exact
  const long double lo = (static_cast<long double>(h) + static_cast<long double>(std::nextafter(h, -INFINITY))) / 2;
  const long double hi = (static_cast<long double>(h) + static_cast<long double>(std::nextafter(h, INFINITY))) / 2;
  if (!(c - lo > e && hi - c > e)) return false;
  out = h;
  return true;
}

// true: out[] holds the correctly rounded centre (the simplex has positive volume)
bool centre_filtered(int d, const double* const* p, const double* w, double* out) {
  Ev V[3][3], B[3];
  for (int k = 1; k <= d; ++k) {
    Ev b{0.0L, 0.0L};
    for (int l = 0; l < d; ++l) {
      V[k - 1][l] = ev_sub({p[k][l], 0.0L}, {p[0][l], 0.0L});
      b = ev_add(b, ev_mul(V[k - 1][l], V[k - 1][l]));
    }
    if (w) b = ev_sub(b, ev_sub({w[k], 0.0L}, {w[0], 0.0L}));
    B[k - 1] = b;
  }
  Ev D, N[3];
  if (d == 2) {
    D = ev_det2(V[0][0], V[0][1], V[1][0], V[1][1]);
    N[0] = ev_det2(B[0], V[0][1], B[1], V[1][1]);
    N[1] = ev_det2(V[0][0], B[0], V[1][0], B[1]);
  } else {
    D = ev_det3(V);
    for (int l = 0; l < 3; ++l) {
      Ev M[3][3];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) M[r][c] = c == l ? B[r] : V[r][c];
      N[l] = ev_det3(M);
    }
  }
  D.v *= 2, D.e *= 2;  // exact
  const long double infl = 1.0L + std::ldexp(1.0L, -50);
  const long double De = D.e * infl;
  if (!(std::fabs(D.v) > De)) return false;
  for (int l = 0; l < d; ++l) {
    // x = N / D, then c = p0 + x
    const long double xv = N[l].v / D.v;
    const long double xe =
        (std::fabs(N[l].v) * De + std::fabs(D.v) * N[l].e * infl) / (std::fabs(D.v) * (std::fabs(D.v) - De)) +
        kU * std::fabs(xv);
    const Ev c = ev_add({p[0][l], 0.0L}, {xv, xe * infl});
    if (!rounds_to(c.v, c.e * infl, out[l])) return false;
  }
  return true;
}

// d = 4..9: the system 2 V x = B (row k: 2 (p_k - p_0) . x = |p_k - p_0|^2
// - w_k + w_0; c = p_0 + x) solved by Gaussian elimination with partial
// pivoting on the long double approximations, each value carried with a
// running error bound as above. Elimination in exact arithmetic along the
// same pivot sequence gives the exact solution (any order does, with
// non-zero pivots), so each bound compares a computed value with the exact
// value of the same expression. Every bound is computed in rounded
// arithmetic from a few non-negative terms (< 16 roundings, each within a
// factor 1 +- 2^-64) and multiplied by kUp = 1 + 2^-58 at once, so it is an
// upper bound whatever the length of the chain (d = 9: about 300
// operations); a quotient's denominator |b| (|b| - e_b) is multiplied by
// kDown = 1 - 2^-58 instead. A pivot whose bound does not exclude zero, a
// non-finite value or a centre near a rounding midpoint goes the exact way.
constexpr long double kUp = 1.0L + 0x1p-58L, kDown = 1.0L - 0x1p-58L;
inline Ev eg_sub(Ev a, Ev b) {
  const long double v = a.v - b.v;
  return {v, (a.e + b.e + kU * std::fabs(v)) * kUp};
}
inline Ev eg_mul(Ev a, Ev b) {
  const long double v = a.v * b.v;
  return {v, (std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kU * std::fabs(v)) * kUp};
}
// a / b where |b.v| > b.e (checked by the caller)
inline Ev eg_div(Ev a, Ev b) {
  const long double v = a.v / b.v;
  const long double den = std::fabs(b.v) * (std::fabs(b.v) - b.e) * kDown;
  return {v, ((std::fabs(a.v) * b.e + std::fabs(b.v) * a.e) / den + kU * std::fabs(v)) * kUp};
}

// Gaussian elimination with partial pivoting on the long double
// approximations of A = [M | rhs] (d rows), every value with its running
// bound (eg_*); x the solution. False where a pivot's bound does not
// exclude zero or a value is not finite. A is overwritten.
bool ev_solve(int d, Ev (*A)[kMaxD + 1], Ev* x) {
  for (int col = 0; col < d; ++col) {
    int piv = col;
    for (int r = col + 1; r < d; ++r)
      if (std::fabs(A[r][col].v) > std::fabs(A[piv][col].v)) piv = r;
    if (!(std::fabs(A[piv][col].v) > A[piv][col].e) || !std::isfinite(A[piv][col].v)) return false;
    if (piv != col)
      for (int j = col; j <= d; ++j) std::swap(A[piv][j], A[col][j]);
    for (int r = col + 1; r < d; ++r) {
      const Ev f = eg_div(A[r][col], A[col][col]);
      for (int j = col + 1; j <= d; ++j) A[r][j] = eg_sub(A[r][j], eg_mul(f, A[col][j]));
    }
  }
  for (int i = d - 1; i >= 0; --i) {
    Ev t = A[i][d];
    for (int j = i + 1; j < d; ++j) t = eg_sub(t, eg_mul(A[i][j], x[j]));
    x[i] = eg_div(t, A[i][i]);
  }
  return true;
}

// Sum2 of Ogita, Rump and Oishi (2005) over error-free transformations
// (pred::xp::Dbl's two_sum and two_product, [She97]: exact for finite values
// without overflow, two_product's low part exact unless it underflows — each
// such loss a few units of 2^-1074 — and, without an FMA, for factors below
// 2^995, which the caller checks): the computed sum of n doubles is within u
// |sum| + gamma_(n-1)^2 sum |p_i| of the exact one (u = 2^-53; Proposition
// 4.5), bounded here by 2^-52 |res| + 4 (n 2^-52)^2 sum |p_i| (the factor 4
// covers 1 / (1 - u) and the rounding of sum |p_i|) plus 2^-1060 for the
// low parts that underflow (at most 100 products).
using pred::xp::Dbl;
struct Sum2 {
  double s = 0.0, sigma = 0.0, abs = 0.0;
  int n = 0;
  void add(double x) {
    double t;
    Dbl::two_sum(s, x, s, t);
    sigma += t;
    abs += std::fabs(x);
    ++n;
  }
  long double result() const { return static_cast<long double>(s + sigma); }
  long double bound() const {
    const long double res = std::fabs(static_cast<long double>(s + sigma));
    const long double g = static_cast<long double>(n) * 0x1p-52L;
    return (0x1p-52L * res + 4 * g * g * static_cast<long double>(abs) + 0x1p-1060L) * kUp;
  }
};

// d = 4..9 (module comment above): the long double solution x~ decides the
// centre where it can. Where it cannot (its bound is too wide for the
// rounding: many slivers in 5D and 6D), one step of refinement: x~ rounded to
// doubles x_d, the residual r = B - 2 V x_d as an exact sum of products of
// doubles (each V_kl = p_kl - p_0l exactly two doubles by two_sum) summed by
// Sum2 with its bound, then 2 V delta = r solved as before (exactly,
// delta = x - x_d, x the exact solution), and c = p_0 + x_d + delta with
// p_0 + x_d exact by two_sum. The residual's bound is that of Sum2, the
// rest running bounds, so the refined centre's bound is about cond^2 u_ld^2
// |x| plus the final roundings (2^-63 |c|), not cond u_ld |x|.
bool centre_filtered_gauss(int d, const double* const* p, const double* w, double* out) {
  Ev A[kMaxD][kMaxD + 1], V2[kMaxD][kMaxD];
  for (int k = 1; k <= d; ++k) {
    Ev b{0.0L, 0.0L};
    for (int l = 0; l < d; ++l) {
      const Ev v = eg_sub({p[k][l], 0.0L}, {p[0][l], 0.0L});
      A[k - 1][l] = V2[k - 1][l] = {2 * v.v, 2 * v.e};  // exact
      const Ev sq = eg_mul(v, v);
      const long double t = b.v + sq.v;
      b = {t, (b.e + sq.e + kU * std::fabs(t)) * kUp};
    }
    if (w) b = eg_sub(b, eg_sub({w[k], 0.0L}, {w[0], 0.0L}));
    A[k - 1][d] = b;
  }
  Ev x[kMaxD];
  if (!ev_solve(d, A, x)) return false;
  double c[kMaxD];
  bool all = true;
  for (int l = 0; l < d && all; ++l) {
    const long double cv = static_cast<long double>(p[0][l]) + x[l].v;
    all = rounds_to(cv, (x[l].e + kU * std::fabs(cv)) * kUp, c[l]);
  }
  if (all) {
    for (int l = 0; l < d; ++l) out[l] = c[l];
    return true;
  }
  // refinement
  // every factor of the residual's products below 2^995 (two_product
  // without an FMA splits them; differences of the coordinates below 2^994)
  double xd[kMaxD];
  for (int l = 0; l < d; ++l) {
    xd[l] = static_cast<double>(x[l].v);
    if (!(std::fabs(xd[l]) < 0x1p994) || !(std::fabs(p[0][l]) < 0x1p993)) return false;
    for (int k = 1; k <= d; ++k)
      if (!(std::fabs(p[k][l]) < 0x1p993)) return false;
  }
  for (int k = 1; k <= d; ++k) {
    Sum2 r;
    for (int l = 0; l < d; ++l) {
      double vh, vl, ph, pl;
      Dbl::two_sum(p[k][l], -p[0][l], vh, vl);
      Dbl::two_product(vh, vh, ph, pl), r.add(ph), r.add(pl);   // vh^2
      Dbl::two_product(vh, vl, ph, pl), r.add(2 * ph), r.add(2 * pl);  // 2 vh vl
      Dbl::two_product(vl, vl, ph, pl), r.add(ph), r.add(pl);   // vl^2
      Dbl::two_product(vh, xd[l], ph, pl), r.add(-2 * ph), r.add(-2 * pl);  // -2 vh x_d
      Dbl::two_product(vl, xd[l], ph, pl), r.add(-2 * ph), r.add(-2 * pl);  // -2 vl x_d
    }
    if (w) {
      double wh, wl;
      Dbl::two_sum(w[k], -w[0], wh, wl);
      r.add(-wh), r.add(-wl);
    }
    const long double rv = r.result(), re = r.bound();
    if (!std::isfinite(rv) || !std::isfinite(re)) return false;
    for (int l = 0; l < d; ++l) A[k - 1][l] = V2[k - 1][l];
    A[k - 1][d] = {rv, re};
  }
  Ev delta[kMaxD];
  if (!ev_solve(d, A, delta)) return false;
  for (int l = 0; l < d; ++l) {
    double s0, t0;
    Dbl::two_sum(p[0][l], xd[l], s0, t0);  // p_0 + x_d exactly
    const long double tail = static_cast<long double>(t0) + delta[l].v;
    const long double cv = static_cast<long double>(s0) + tail;
    const long double e = (delta[l].e + kU * std::fabs(tail) + kU * std::fabs(cv)) * kUp;
    if (!rounds_to(cv, e, c[l])) return false;
  }
  for (int l = 0; l < d; ++l) out[l] = c[l];
  return true;
}

// The centre of a simplex of a lattice moved by some ulp (its slivers defeat
// the filters above: a simplex flat on the lattice and of volume O(ulp)
// once moved, its centre far out), from the exact minors of the lifted
// matrix as polynomials in ε = 2^-60 and η = 2^-1074 (predicates/
// near_lattice.hpp: each value n + a ε + b η with small integers n, a, b).
// With Λ the (D + 1) x (D + 2) matrix of rows (p_k, |p_k|^2 - w_k, 1), the
// centre c solves |p_k|^2 - w_k = 2 p_k . c + t for every k, so by Cramer's
// rule 2 c_l = (-1)^(D - 1 - l) M_l / M_h, M_l the minor of Λ without
// column l and M_h without the heights' column (the orientation: 0 exactly
// when its polynomial is 0, the zero-volume answer). Each coordinate is
// then rounded in one of two ways:
//  * a filter: a minor's polynomial is η^j A(ε) + R with j its least
//    η-degree; A(ε) = Σ_i a_i 2^(-60 i) has at most eight int64
//    coefficients (i < 8), summed in long double (each term exact: a 64-bit
//    significand, no underflow) within 8 u Σ |terms| (u = 2^-64), and
//    |R| <= η^j η Σ |c| over R's coefficients (each term of R is some
//    c ε^i η^j' with j' > j). Where M_l and M_h have the same j, the
//    quotient's error follows as for the ev_ quotients and rounds_to decides
//    unless the centre lies within about 2^-62 of its size from a midpoint
//    between doubles;
//  * else exactly: both polynomials times 2^(60 i_max + 1074 j_max) are
//    integers X_l and X_h (GMP, a few hundred to a few thousand bits), and
//    c_l = ±X_l / (2 X_h) is rounded by round_ratio (ties to even, overflow,
//    subnormals), as the exact solver rounds its own fraction of the same
//    value. On the moved lattices (issue 39) centres often fall on or within
//    2^-60 of a midpoint: their values are half-integers plus multiples of
//    the moves.
// 1: out[0..D-1] hold the correctly rounded centre; 0: zero volume; -1: not
// computed here (a value that does not split, an overflow, more than six
// moved points): the exact solver's case.
struct NlValue {
  bool zero = true;
  int j = 0;
  long double a = 0, e = 0;
};

bool nl_value(const pred::xp::NlAcc& acc, NlValue& v) {
  if (acc.over) return false;
  int j = 8;
  for (std::uint64_t u = acc.used; u; u &= u - 1) {
    const int e = __builtin_ctzll(u);
    if (acc.c[e] != 0) j = std::min(j, e & 7);
  }
  v = NlValue{};
  if (j == 8) return true;  // the zero polynomial
  long double a = 0, abs_sum = 0, rest = 0;
  for (std::uint64_t u = acc.used; u; u &= u - 1) {
    const int e = __builtin_ctzll(u);
    const long double c = static_cast<long double>(acc.c[e]);  // exact: 64 bits
    if ((e & 7) == j) {
      const long double t = std::ldexp(c, -60 * (e >> 3));  // exact
      a += t;
      abs_sum += std::fabs(t);
    } else {
      rest += std::fabs(c);
    }
  }
  v.zero = false;
  v.j = j;
  v.a = a;
  // summation (8 terms at most) and the η^(j + 1) tail; the bounds' own
  // rounding covered by the factor 2
  v.e = 2 * (8 * 0x1p-64L * abs_sum + std::ldexp(rest, -1074));
  return true;
}

// acc's polynomial at ε = 2^-60, η = 2^-1074, times 2^(60 i_max + 1074 j_max):
// an integer (acc not overflowed)
void nl_scaled(const pred::xp::NlAcc& acc, int imax, int jmax, mpz_t out, mpz_t t) {
  mpz_set_ui(out, 0);
  for (std::uint64_t u = acc.used; u; u &= u - 1) {
    const int e = __builtin_ctzll(u);
    if (acc.c[e] == 0) continue;
    mpz_set_si(t, static_cast<long>(acc.c[e]));
    mpz_mul_2exp(t, t, static_cast<mp_bitcnt_t>(60 * (imax - (e >> 3)) + 1074 * (jmax - (e & 7))));
    mpz_add(out, out, t);
  }
}

struct NlCentreScratch {
  Mpz xl, xh, t, q, r, tmp;
};

template <int D>
int nl_centre(const double* const* p, const double* w, double* out, NlCentreScratch& sc) {
  static_assert(std::numeric_limits<long>::digits >= 63, "mpz_set_si takes the int64 coefficients");
  constexpr int K = D + 2;
  static constexpr double kOrigin[K] = {};  // Λ's unused row K - 1 (not in any minor asked)
  const double* rows[K];
  double wt[K];
  for (int k = 0; k <= D; ++k) {
    rows[k] = p[k];
    wt[k] = w ? w[k] : 0.0;
  }
  rows[K - 1] = kOrigin;
  wt[K - 1] = 0.0;
  pred::xp::NlMinors<K> N;  // (on the stack, as in the predicates' near_lattice_sign)
  if (!pred::xp::nl_build<K>(rows, wt, N.L)) return -1;
  constexpr unsigned kRows = (1u << (K - 1)) - 1u, kAll = (1u << K) - 1u;
  pred::xp::NlAcc hacc;
  NlValue h;
  if (!N.poly(kRows, kAll & ~(1u << (K - 2)), hacc) || !nl_value(hacc, h)) return -1;
  if (h.zero) return 0;
  auto degrees = [](const pred::xp::NlAcc& acc, int& imax, int& jmax) {
    for (std::uint64_t u = acc.used; u; u &= u - 1) {
      const int e = __builtin_ctzll(u);
      if (acc.c[e] != 0) imax = std::max(imax, e >> 3), jmax = std::max(jmax, e & 7);
    }
  };
  double c[D];
  for (int l = 0; l < D; ++l) {
    pred::xp::NlAcc acc;
    NlValue m;
    if (!N.poly(kRows, kAll & ~(1u << l), acc) || !nl_value(acc, m)) return -1;
    if (m.zero) {
      c[l] = 0.0;
      continue;
    }
    const bool negate = ((D - 1 - l) & 1) != 0;
    if (m.j == h.j && std::fabs(h.a) > h.e) {
      const long double q = (negate ? -m.a : m.a) / (2 * h.a);
      const long double ah = std::fabs(h.a);
      const long double e =
          ((std::fabs(m.a) * h.e + ah * m.e) / (ah * (ah - h.e)) / 2 + 2 * 0x1p-64L * std::fabs(q)) * (1 + 0x1p-50L);
      if (rounds_to(q, e, c[l])) continue;
    }
    int imax = 0, jmax = 0;
    degrees(hacc, imax, jmax);
    degrees(acc, imax, jmax);
    nl_scaled(acc, imax, jmax, sc.xl.v, sc.t.v);
    nl_scaled(hacc, imax, jmax, sc.xh.v, sc.t.v);
    // a non-zero polynomial can still vanish at the units (a_0 + a_1 2^-60 =
    // 0 with |a_1| = 2^60 |a_0|): zero volume after all, the exact solver's
    // to say
    if (mpz_sgn(sc.xh.v) == 0) return -1;
    if (negate) mpz_neg(sc.xl.v, sc.xl.v);
    if (mpz_sgn(sc.xh.v) < 0) {
      mpz_neg(sc.xh.v, sc.xh.v);
      mpz_neg(sc.xl.v, sc.xl.v);
    }
    c[l] = round_ratio(sc.xl.v, sc.xh.v, -1, sc.q.v, sc.r.v, sc.tmp.v);  // X_l / (2 X_h)
  }
  for (int l = 0; l < D; ++l) out[l] = c[l];
  return 1;
}

int nl_centre_d(int d, const double* const* p, const double* w, double* out, NlCentreScratch& sc) {
  switch (d) {
    case 2: return nl_centre<2>(p, w, out, sc);
    case 3: return nl_centre<3>(p, w, out, sc);
    case 4: return nl_centre<4>(p, w, out, sc);
    case 5: return nl_centre<5>(p, w, out, sc);
    default: return -1;
  }
}
#endif

// The centre of a simplex of a small-integer lattice (every coordinate an
// integer below 2^20 in magnitude, weights, if any, integers below 2^40) in
// 64-bit integers: the same system as CentreSolver's, 2 v_k . x = b_k with
// v_k = p_k - p_0 and b_k = |v_k|^2 - (w_k - w_0) (k = 1..D), by Cramer's
// rule. The Laplace minors over column subsets of the D x (D + 1) matrix
// [2V | b] (pred::minor_levels, rows 0..|S|-1) hold det 2V (columns 0..D-1)
// and, for each l, the minor without column l, which is det of 2V with
// column l replaced by b after D - 1 - l transpositions (b moved from last to
// place l): x_l = N_l / det 2V, and c_l = (p_0l det + N_l) / det. Exactness:
// every minor is below Hadamard's bound H = prod_j max(1, |column j|), every
// product in the expansion below max|entry| H and every partial sum below
// (D + 1) max|entry| H, which must be below 2^61 (a factor 4 above the
// roundings of its computation in binary64; int64 holds 2^63). With det and
// the numerator below 2^53, binary64 holds them exactly and the division is
// correctly rounded, as CentreSolver::rounded (an exact 0 written as +0).
// Returns 1 (written), 0 (zero volume: det 2V = 2^D det V = 0, exactly), or
// -1 where a bound fails (the general path decides). The 6^4 grid: 35,352
// simplices, 20,352 of zero volume, each an exact orientation and the rest a
// long double solve before.
// (-1)^negative a / b 2^e correctly rounded to binary64 (to nearest, ties to
// even), for a < 2^120 and 0 < b < 2^64; false where the result would leave
// [2^-1000, 2^1000] (no subnormal or overflow case: the caller's general path
// decides). The quotient q = floor(A / B) of A / B = a / b 2^s in [2^55,
// 2^57) carries the remainder's being non-zero in its lowest bit (a sticky
// bit below the round bit: at least 56 bits, three beyond the 53 kept), so
// the one rounding of q's conversion to binary64 is the rounding of a / b 2^s;
// the power of two after it is exact inside that range.
inline bool rounded_ratio(bool negative, unsigned __int128 a, unsigned long long b, int e, double& out) {
  if (a == 0) {
    out = 0.0;
    return true;
  }
  auto bits = [](unsigned __int128 x) {
    const auto hi = static_cast<unsigned long long>(x >> 64);
    return hi != 0 ? 128 - __builtin_clzll(hi) : 64 - __builtin_clzll(static_cast<unsigned long long>(x));
  };
  const int la = bits(a), lb = 64 - __builtin_clzll(b);
  const int s = 56 + lb - la;  // A / B in (2^55, 2^57)
  unsigned __int128 A = a, B = b;
  if (s >= 0) {
    if (la + s > 126) return false;
    A <<= s;
  } else {
    B <<= -s;  // (lb - s = la - 56 <= 64 bits)
  }
  const unsigned __int128 q = A / B;
  const unsigned long long sticky = A - q * B != 0 ? 1u : 0u;
  const double v = static_cast<double>(static_cast<long long>(static_cast<unsigned long long>(q) | sticky));
  const int x = e - s;  // the result: v 2^x, v in [2^55, 2^57]
  if (x + 55 < -1000 || x + 57 > 1000) return false;
  out = negative ? -std::ldexp(v, x) : std::ldexp(v, x);
  return true;
}

// factor (optional): the centre of points x g for the given points x (a
// lattice_quotient's, g = *factor > 0: every weight w g^2), that is g times
// this lattice's centre, rounded once (rounded_ratio on g's odd mantissa
// times the numerator).
template <int D>
int lattice_centre(const double* const* p, const double* w, double* out, const double* factor = nullptr) {
  constexpr int N = D + 1;  // columns of [2V | b]; row D is 0 and never read (levels up to D)
  long long t[N * N] = {};
  for (int k = 1; k <= D; ++k) {
    long long b = 0;
    for (int l = 0; l < D; ++l) {
      const long long v = static_cast<long long>(p[k][l]) - static_cast<long long>(p[0][l]);
      t[(k - 1) * N + l] = 2 * v;
      b += v * v;
    }
    if (w) b -= static_cast<long long>(w[k]) - static_cast<long long>(w[0]);
    t[(k - 1) * N + D] = b;
  }
  double h = 1.0, mx = 1.0;
  for (int j = 0; j < N; ++j) {
    double sq = 0.0;
    for (int i = 0; i < D; ++i) {
      const double x = static_cast<double>(t[i * N + j]);
      sq += x * x;
      mx = std::max(mx, std::fabs(x));
    }
    h *= std::max(1.0, std::sqrt(sq));
  }
  if (!(N * mx * h < 0x1p61)) return -1;
  long long m[1 << N];
  pred::minor_levels<N, D, long long>(t, m);
  const long long det = m[(1 << D) - 1];
  if (det == 0) return 0;
  constexpr long long kExact = 1LL << 53;
  if (det >= kExact || det <= -kExact) return -1;
  double c[D];
  for (int l = 0; l < D; ++l) {
    long long nl = m[((1 << N) - 1) & ~(1 << l)];
    if ((D - 1 - l) & 1) nl = -nl;
    const __int128 num = static_cast<__int128>(static_cast<long long>(p[0][l])) * det + nl;
    if (num >= kExact || num <= -kExact) return -1;
    if (factor) {
      // g = G 2^E (G odd, below 2^53): g num / det = (G |num|) / |det| 2^E
      int E = 0;
      const double frac = std::frexp(*factor, &E);  // g = frac 2^E, frac in [1/2, 1)
      const auto G = static_cast<unsigned long long>(std::ldexp(frac, 53));  // exact: 53 bits
      const unsigned __int128 a = static_cast<unsigned __int128>(G) * static_cast<unsigned long long>(num < 0 ? -num : num);
      if (!rounded_ratio((num < 0) != (det < 0), a, static_cast<unsigned long long>(det < 0 ? -det : det), E - 53, c[l]))
        return -1;
      continue;
    }
    c[l] = num == 0 ? 0.0 : static_cast<double>(static_cast<long long>(num)) / static_cast<double>(det);
  }
  for (int l = 0; l < D; ++l) out[l] = c[l];
  return 1;
}

// lattice_centre for the run-time dimension (2..6; -1 beyond: minor_levels
// takes up to 7 columns)
inline int lattice_centre_d(int d, const double* const* p, const double* w, double* out,
                            const double* factor = nullptr) {
  switch (d) {
    case 2: return lattice_centre<2>(p, w, out, factor);
    case 3: return lattice_centre<3>(p, w, out, factor);
    case 4: return lattice_centre<4>(p, w, out, factor);
    case 5: return lattice_centre<5>(p, w, out, factor);
    case 6: return lattice_centre<6>(p, w, out, factor);
    default: return -1;
  }
}

// An exact centre kept for comparison: c_l = M[l] / D * 2^E.
struct ExactCentre {
  int d = 0;
  Mpz M[kMaxD], D;
  long E = 0;
  void take(CentreSolver& s) {
    d = s.d;
    for (int l = 0; l < d; ++l) mpz_set(M[l].v, s.M[l].v);
    mpz_set(D.v, s.Dn.v);
    E = s.E;
  }
  bool equals(const ExactCentre& o) const {
    Mpz x, y;
    const long e = std::min(E, o.E);
    for (int l = 0; l < d; ++l) {
      mpz_mul(x.v, M[l].v, o.D.v);
      mpz_mul_2exp(x.v, x.v, static_cast<mp_bitcnt_t>(E - e));
      mpz_mul(y.v, o.M[l].v, D.v);
      mpz_mul_2exp(y.v, y.v, static_cast<mp_bitcnt_t>(o.E - e));
      if (mpz_cmp(x.v, y.v) != 0) return false;
    }
    return true;
  }
};

// Compressed lists: offsets (size + 1) and values.
struct Csr {
  std::vector<std::int64_t> off{0}, val;
  void close() { off.push_back(static_cast<std::int64_t>(val.size())); }
};

// Whether sorted list `set` holds x.
inline bool holds(const std::int64_t* b, const std::int64_t* e, std::int64_t x) { return std::binary_search(b, e, x); }

struct VoronoiResult {
  std::vector<double> vertices;
  std::vector<std::int64_t> simplex_vertex;
  std::vector<std::int64_t> ridge_points;
  Csr ridge_vertices, regions;
  std::size_t nv = 0;
};

VoronoiResult voronoi_core(const PointSet& ps, const std::int64_t* S, std::size_t m, int threads,
                           const std::int64_t* given_nbr = nullptr) {
  const int d = ps.dim;
  const std::size_t k = static_cast<std::size_t>(d + 1), n = ps.size();
  VoronoiResult out;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  auto pt = [&](std::int64_t i) { return ps.point(static_cast<std::size_t>(i)); };
  auto wt = [&](std::int64_t i) { return ps.weights[static_cast<std::size_t>(i)]; };
  const bool weighted = ps.weighted;
  // FLIPFLOP_VORONOI_TIMES set: each phase's time on stderr
  const bool timing = std::getenv("FLIPFLOP_VORONOI_TIMES") != nullptr;
  auto clock0 = std::chrono::steady_clock::now();
  auto lap = [&](const char* what) {
    if (!timing) return;
    const auto now = std::chrono::steady_clock::now();
    std::fprintf(stderr, "voronoi %s: %.3f s\n", what, std::chrono::duration<double>(now - clock0).count());
    clock0 = now;
  };

  std::atomic<std::size_t> exact_count{0}, gmp_count{0};
  // 1. every simplex's centre, rounded (parallel); flat[s] when zero volume
  std::vector<double> C(m * static_cast<std::size_t>(d));
  std::vector<std::uint8_t> flat(m, 0);
  // every coordinate an integer below 2^20: the predicates' own lattice test
  // (StaticFilter::small_integers; their integer stage decides such calls)
  // — or such a lattice times one exact double g (lattice_quotient: a grid
  // of step 0.1 with three values a row, 0.25, ...): its centres are g times
  // the quotient's, rounded once, and its exact zero-volume tests the
  // quotient's (the same signs); lps holds the lattice's points
  const bool given_lattice = pred::StaticFilter::for_points(ps.coords.data(), n, d).small_integers();
  const std::optional<LatticeQuotient> quotient = given_lattice ? std::nullopt : lattice_quotient(ps);
  const PointSet& lps = quotient ? quotient->points : ps;
  const double* factor = quotient ? &quotient->factor : nullptr;
  const bool lattice = given_lattice || quotient.has_value();
  const bool int_centres = lattice && d <= 6 && (!weighted || std::all_of(lps.weights.begin(), lps.weights.end(), [](double x) {
                             return x == std::trunc(x) && std::fabs(x) < 0x1p40;
                           }));
  // every value n + a 2^-60 + b 2^-1074 with small integers (near_lattice.hpp
  // nl_split): a lattice moved by some ulp, whose centres nl_centre computes;
  // elsewhere it is not asked (on random input the scan stops at its first
  // value)
  const bool near_lattice = [&] {
    long long n0, a0, b0;
    const double* x = ps.coords.data();
    for (std::size_t i = 0; i < n * static_cast<std::size_t>(d); ++i)
      if (!pred::xp::nl_split(x[i], n0, a0, b0)) return false;
    if (weighted)
      for (std::size_t i = 0; i < n; ++i)
        if (!pred::xp::nl_split(ps.weights[i], n0, a0, b0)) return false;
    return true;
  }();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 256), [&](const tbb::blocked_range<std::size_t>& rg) {
      CentreSolver cs;
      cs.d = d;
#ifdef FLIPFLOP_VORONOI_FILTER
      NlCentreScratch nls;
#endif
      const double* p[kMaxD + 1];
      double w[kMaxD + 1];
      const double* lp[kMaxD + 1];  // the lattice's points (lps)
      double lw[kMaxD + 1];
      for (std::size_t s = rg.begin(); s != rg.end(); ++s) {
        for (std::size_t j = 0; j < k; ++j) {
          const auto i = static_cast<std::size_t>(S[s * k + j]);
          p[j] = pt(S[s * k + j]);
          lp[j] = lps.point(i);
          if (weighted) {
            w[j] = wt(S[s * k + j]);
            lw[j] = lps.weights[i];
          }
        }
        // on an integer lattice (integer weights) the centre, or zero
        // volume, in 64-bit integers where the bounds hold
        if (int_centres) {
          const int r = lattice_centre_d(d, lp, weighted ? lw : nullptr, &C[s * d], factor);
          if (r == 0) flat[s] = 1;
          if (r >= 0) continue;
        }
        // on an integer lattice the exact orientation first: the
        // predicates' integer stage decides it in about the time the
        // long double filter takes to fail on a zero-volume simplex, and
        // most of a lattice's canonical simplices have zero volume (the 6^4
        // grid: 20,352 of 35,352); the same test as below, only earlier
        if (lattice && pred::orient_d_exact(d, lp) == 0) {
          flat[s] = 1;
          continue;
        }
#ifdef FLIPFLOP_VORONOI_FILTER
        // a lattice moved by some ulp: the centre, or zero volume, from the
        // minors as polynomials (nl_centre), before the filter, which fails
        // on such a lattice's slivers
        if (const int r = near_lattice ? nl_centre_d(d, p, weighted ? w : nullptr, &C[s * d], nls) : -1; r >= 0) {
          if (r == 0) flat[s] = 1;
          continue;
        }
        if (d <= 3 ? centre_filtered(d, p, weighted ? w : nullptr, &C[s * d])
                   : centre_filtered_gauss(d, p, weighted ? w : nullptr, &C[s * d]))
          continue;
        if (timing) exact_count.fetch_add(1, std::memory_order_relaxed);
#endif
        // zero volume decided by the exact (unperturbed) orientation first:
        // on lattices most simplices the filter leaves are flat, and the
        // predicate's integer stages decide that for a fraction of the GMP
        // solve's cost (which finds the same zero determinant)
        if (!lattice && pred::orient_d_exact(d, p) == 0) {  // (a lattice's: asked above)
          flat[s] = 1;
          continue;
        }
        if (timing) gmp_count.fetch_add(1, std::memory_order_relaxed);
        if (cs.solve(p, weighted ? w : nullptr))
          cs.rounded(&C[s * d]);
        else
          flat[s] = 1;
      }
    });
  });

  if (timing)
    std::fprintf(stderr, "voronoi: %zu of %zu centres by the exact path, %zu of them not flat (GMP)\n", exact_count.load(), m,
                 gmp_count.load());
  lap("centres");
  // 2. groups: runs of equal rounded centres, split by exact comparison
  std::vector<std::uint32_t> order;
  order.reserve(m);
  for (std::size_t s = 0; s < m; ++s)
    if (!flat[s]) order.push_back(static_cast<std::uint32_t>(s));
  auto key_less = [&](std::uint32_t a, std::uint32_t b) {
    for (int l = 0; l < d; ++l) {
      std::uint64_t x, y;
      std::memcpy(&x, &C[a * static_cast<std::size_t>(d) + l], 8);
      std::memcpy(&y, &C[b * static_cast<std::size_t>(d) + l], 8);
      if (x != y) return x < y;
    }
    return a < b;
  };
  auto key_eq = [&](std::uint32_t a, std::uint32_t b) {
    return std::memcmp(&C[a * static_cast<std::size_t>(d)], &C[b * static_cast<std::size_t>(d)], 8 * d) == 0;
  };
  arena.execute([&] { tbb::parallel_sort(order.begin(), order.end(), key_less); });
  // Whether the non-flat simplices a and b have the same exact centre (1),
  // not (0), or this cannot tell (-1). With c_a and rho_a a's orthosphere
  // (|c_a - x|^2 - w_x = rho_a on a's vertices), power_d of a's vertices
  // and a point v is 0 exactly when |c_a - v|^2 - w_v = rho_a (the lifted
  // points on one hyperplane). All of b's vertices so: c_a solves b's
  // equations, whose solution is unique (b not flat): c_b = c_a. One of
  // them not so while a and b share a vertex u: were c_b = c_a, then rho_b
  // = |c_a - u|^2 - w_u = rho_a and every vertex of b would be so — the
  // centres differ. No shared vertex: -1, and the exact centres decide. (For
  // the cells of a regular or furthest-site triangulation they then always
  // differ: one centre with two radii would put one cell's vertices strictly
  // inside the other's sphere, or outside it. The comparison keeps the answer
  // exact for any simplices given.) Unweighted: w = 0, the circumsphere. On
  // lattices the exact power tests are the predicates' integer stages, far
  // cheaper than GMP centres.
  // `on`: the points already asked against a's sphere, sorted, each with its
  // answer (a run's members share few points: the 3^5 grid's 32 runs of
  // about 120 simplices each have the 32 corners of one unit cube, where
  // asking each member's vertices made 5 power tests a member)
  using OnSphere = std::vector<std::pair<std::int64_t, bool>>;
  auto same_centre = [&](std::uint32_t a, std::uint32_t b, OnSphere& on) {
    const std::int64_t* A = S + static_cast<std::size_t>(a) * k;
    const std::int64_t* B = S + static_cast<std::size_t>(b) * k;
    const double* q[kMaxD + 2];
    double qw[kMaxD + 2];
    for (std::size_t j = 0; j < k; ++j) q[j] = pt(A[j]), qw[j] = weighted ? wt(A[j]) : 0.0;
    bool shared = false, all_on = true;
    for (std::size_t j = 0; j < k; ++j) {
      if (std::find(A, A + k, B[j]) != A + k) {
        shared = true;
        continue;
      }
      if (!all_on) continue;
      auto it = std::lower_bound(on.begin(), on.end(), std::pair<std::int64_t, bool>{B[j], false});
      if (it != on.end() && it->first == B[j]) {
        all_on = it->second;
        continue;
      }
      q[k] = pt(B[j]), qw[k] = weighted ? wt(B[j]) : 0.0;
      all_on = pred::power_d_exact(d, q, qw) == 0;
      on.insert(it, {B[j], all_on});
    }
    return all_on ? 1 : shared ? 0 : -1;
  };
  std::atomic<std::size_t> group_members{0}, group_gmp{0};
  std::vector<std::int64_t> group(m, -1);  // provisional ids: the first simplex (smallest index) of the group
  // the runs (each [runs[r], runs[r + 1]) of `order`), grouped in parallel:
  // a run's members are written by the run's task alone
  std::vector<std::size_t> runs;
  for (std::size_t a = 0; a < order.size(); ++a)
    if (a == 0 || !key_eq(order[a - 1], order[a])) runs.push_back(a);
  runs.push_back(order.size());
  arena.execute([&] {
    // (grain 1: a lattice has a few long runs — the 3^5 grid 32 of about 120
    // simplices — which a grain of 64 left to one thread)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size() - 1, 1), [&](const tbb::blocked_range<std::size_t>& rg) {
      std::unique_ptr<CentreSolver> cs;  // made on the first exact centre of this piece
      const double* p[kMaxD + 1];
      double w[kMaxD + 1];
      auto exact_of = [&](std::uint32_t s) {
        if (!cs) cs = std::make_unique<CentreSolver>(), cs->d = d;
        for (std::size_t j = 0; j < k; ++j) {
          p[j] = pt(S[s * k + j]);
          if (weighted) w[j] = wt(S[s * k + j]);
        }
        cs->solve(p, weighted ? w : nullptr);
        auto e = std::make_unique<ExactCentre>();
        e->take(*cs);
        return e;
      };
      std::vector<std::unique_ptr<ExactCentre>> reps;  // null until needed
      std::vector<std::uint32_t> rep_id;
      std::vector<OnSphere> rep_on;  // each representative's points asked
      for (std::size_t run = rg.begin(); run != rg.end(); ++run) {
        const std::size_t a = runs[run], b = runs[run + 1];
        if (b - a == 1) {
          group[order[a]] = order[a];
          continue;
        }
        // a run's members grouped by exact centre: against each
        // representative first by same_centre (exact power tests), then,
        // where that cannot tell, by the exact centres (GMP, made on demand)
        reps.clear();
        rep_id.clear();
        rep_on.clear();
        if (timing) group_members += b - a;
        for (std::size_t x = a; x < b; ++x) {  // in simplex order (the sort's tie-break)
          const std::uint32_t s = order[x];
          std::unique_ptr<ExactCentre> mine;
          std::size_t r = 0;
          for (; r < reps.size(); ++r) {
            const int same = same_centre(rep_id[r], s, rep_on[r]);
            if (same == 1) break;
            if (same == 0) continue;
            if (!reps[r]) reps[r] = exact_of(rep_id[r]);
            if (!mine) mine = exact_of(s);
            if (timing) ++group_gmp;
            if (reps[r]->equals(*mine)) break;
          }
          if (r == reps.size()) {
            reps.push_back(std::move(mine));
            rep_id.push_back(s);
            rep_on.emplace_back();
          }
          group[s] = rep_id[r];
        }
      }
    });
  });
  // final vertex ids in order of each group's first simplex (canonical order)
  {
    std::vector<std::int64_t> id(m, -1);
    std::size_t nv = 0;
    for (std::size_t s = 0; s < m; ++s)
      if (!flat[s] && group[s] == static_cast<std::int64_t>(s)) id[s] = static_cast<std::int64_t>(nv++);
    out.vertices.resize(nv * d);
    for (std::size_t s = 0; s < m; ++s)
      if (!flat[s]) {
        group[s] = id[group[s]];
        std::memcpy(&out.vertices[group[s] * d], &C[s * d], 8 * d);
      }
    out.nv = nv;
  }
  C = {};
  const std::size_t nv = out.nv;
  if (timing)
    std::fprintf(stderr, "voronoi: %zu simplices in runs of equal rounded centres, %zu GMP comparisons, %zu vertices\n",
                 group_members.load(), group_gmp.load(), nv);
  lap("groups");

  // 3. each group's vertex set, sorted (CSR over groups)
  std::vector<std::int64_t> gv_off(nv + 1, 0), gv;
  {
    std::vector<std::int64_t> cnt(nv + 1, 0);
    for (std::size_t s = 0; s < m; ++s)
      if (group[s] >= 0) cnt[group[s] + 1] += static_cast<std::int64_t>(k);
    for (std::size_t g = 0; g < nv; ++g) cnt[g + 1] += cnt[g];
    std::vector<std::int64_t> cur(cnt.begin(), cnt.end() - 1), raw(cnt[nv]);
    for (std::size_t s = 0; s < m; ++s)
      if (group[s] >= 0)
        for (std::size_t j = 0; j < k; ++j) raw[cur[group[s]]++] = S[s * k + j];
    for (std::size_t g = 0; g < nv; ++g) {
      auto b = raw.begin() + cnt[g], e = raw.begin() + cnt[g + 1];
      std::sort(b, e);
      e = std::unique(b, e);
      gv.insert(gv.end(), b, e);
      gv_off[g + 1] = static_cast<std::int64_t>(gv.size());
    }
  }

  lap("group vertex sets");
  // 4. neighbours; the hull's exact facets ("infinite groups")
  // (the caller's, where the triangulation's certificate gave them: the same
  // array, simplex across the facet opposite each vertex or -1)
  std::vector<std::int64_t> matched;
  if (!given_nbr) matched = facet_neighbors(m, k, n, [&](std::size_t i, std::size_t l) { return S[i * k + l]; });
  const std::int64_t* const nbr = given_nbr ? given_nbr : matched.data();
  std::vector<std::uint8_t> layer(m, 0);  // zero-volume simplices lying in a hull facet
  std::vector<std::vector<std::int64_t>> hull_facets;  // each: the points on it, sorted
  {
    // boundary facets (s, j): the facet of s opposite its vertex j
    std::vector<std::int64_t> bf;
    for (std::size_t x = 0; x < m * k; ++x)
      if (nbr[x] < 0) bf.push_back(static_cast<std::int64_t>(x));
    const std::size_t nb_ = bf.size();
    auto fvert = [&](std::size_t b, std::array<std::int64_t, kMaxD>& f) {
      const std::size_t s = static_cast<std::size_t>(bf[b]) / k, j = static_cast<std::size_t>(bf[b]) % k;
      std::size_t c = 0;
      for (std::size_t l = 0; l < k; ++l)
        if (l != j) f[c++] = S[s * k + l];
      std::sort(f.begin(), f.begin() + d);
    };
    // ridges of boundary facets: (sorted d-1 vertices, boundary facet); the
    // vertices as 32-bit ids (n < 2^31: voronoi() checks it), a record of
    // 36 bytes where 64-bit ids made 72
    struct RidgeRec {
      std::array<std::int32_t, kMaxD - 1> v;  // d - 1 vertices, -1 after them
      std::uint32_t b;
    };
    std::vector<RidgeRec> rr(nb_ * static_cast<std::size_t>(d));
    std::array<std::int64_t, kMaxD> f;
    for (std::size_t b = 0; b < nb_; ++b) {
      fvert(b, f);
      for (int drop = 0; drop < d; ++drop) {
        RidgeRec& x = rr[b * static_cast<std::size_t>(d) + static_cast<std::size_t>(drop)];
        x.v.fill(-1);
        int c = 0;
        for (int l = 0; l < d; ++l)
          if (l != drop) x.v[c++] = static_cast<std::int32_t>(f[l]);
        x.b = static_cast<std::uint32_t>(b);
      }
    }
    // sorted by (vertices, facet); where the d - 1 vertices fit 64 bits
    // together (bits each: n's width), as one integer key beside the facet
    // (the records' lexicographic sort took 4 ms of the 3^5 grid's 24,480)
    int bits = 1;
    while (bits < 31 && (std::size_t(1) << bits) < n) ++bits;
    const bool packed = (d - 1) * bits <= 64;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    if (packed) {
      keyed.resize(rr.size());
      for (std::size_t x = 0; x < rr.size(); ++x) {
        std::uint64_t key = 0;
        for (int l = 0; l + 1 < d; ++l) key = (key << bits) | static_cast<std::uint64_t>(rr[x].v[l]);
        keyed[x] = {key, rr[x].b};
      }
      rr = {};
      std::sort(keyed.begin(), keyed.end());
    } else {
      std::sort(rr.begin(), rr.end(), [](const RidgeRec& a, const RidgeRec& b) {
        return a.v != b.v ? a.v < b.v : a.b < b.b;
      });
    }
    // adjacency of boundary facets across their ridges (CSR: adj_off, adj)
    std::vector<std::size_t> adj_off(nb_ + 1, 0);
    std::vector<std::uint32_t> adj;
    auto ridge_runs = [&](auto&& same, auto&& facet, std::size_t total, auto&& visit) {
      for (std::size_t a = 0; a < total;) {
        std::size_t b = a + 1;
        while (b < total && same(a, b)) ++b;
        for (std::size_t x = a; x < b; ++x)
          for (std::size_t y = a; y < b; ++y)
            if (x != y) visit(facet(x), facet(y));
        a = b;
      }
    };
    auto both_passes = [&](auto&& same, auto&& facet, std::size_t total) {
      ridge_runs(same, facet, total, [&](std::uint32_t from, std::uint32_t) { ++adj_off[from + 1]; });
      for (std::size_t b = 0; b < nb_; ++b) adj_off[b + 1] += adj_off[b];
      adj.resize(adj_off[nb_]);
      std::vector<std::size_t> cur(adj_off.begin(), adj_off.end() - 1);
      ridge_runs(same, facet, total, [&](std::uint32_t from, std::uint32_t to) { adj[cur[from]++] = to; });
    };
    if (packed)
      both_passes([&](std::size_t a, std::size_t b) { return keyed[a].first == keyed[b].first; },
                  [&](std::size_t x) { return keyed[x].second; }, keyed.size());
    else
      both_passes([&](std::size_t a, std::size_t b) { return rr[a].v == rr[b].v; }, [&](std::size_t x) { return rr[x].b; },
                  rr.size());
    rr = {};
    keyed = {};
    // non-degenerate: spans a (d-1)-flat (the facet of a positive simplex, or
    // a projection along some axis has non-zero (d-1)-volume); a degenerate
    // one costs d exactly zero orientations, so only the seeds' loop below
    // asks, for facets no earlier hull facet's search has reached
    auto nondegenerate = [&](std::size_t b) {
      const std::size_t s = static_cast<std::size_t>(bf[b]) / k;
      if (!flat[s]) return true;
      fvert(b, f);
      double proj[kMaxD][kMaxD];
      const double* rows[kMaxD + 1];
      for (int axis = 0; axis < d; ++axis) {
        for (int r = 0; r < d; ++r) {
          const double* x = pt(f[r]);
          int c = 0;
          for (int l = 0; l < d; ++l)
            if (l != axis) proj[r][c++] = x[l];
          rows[r] = proj[r];
        }
        if (pred::orient_d_exact(d - 1, rows) != 0) return true;
      }
      return false;
    };
    // bstamp: the last hull facet whose search reached the boundary facet
    // (all its points on that facet's plane). A non-degenerate one so
    // reached spans that plane and would seed the same hull facet again; a
    // degenerate one seeds none: the seeds' loop skips both, unasked (on the
    // 3^5 grid 4,816 facets of zero-volume simplices were asked, 20,160
    // exact orientations, most of them exactly zero)
    std::vector<std::int64_t> bstamp(nb_, -1), sstamp(m, -1);
    // each point's answer for the plane of hull facet h, kept while h is
    // built: a point on the plane lies in many of its boundary facets and
    // zero-volume simplices, each of which asked again (one exact
    // orientation per incidence; most are exactly 0, decided by the
    // predicates' exact stages)
    std::vector<std::int64_t> on_stamp(n, -1), off_stamp(n, -1);
    // what h's search has settled: zero-volume simplices and boundary facets
    // found not in its plane (the layers of a lattice's hull facet meet each
    // such neighbour from several sides), points already in its list
    std::vector<std::int64_t> s_off(m, -1), b_off(nb_, -1), listed(n, -1);
    for (std::size_t b0 = 0; b0 < nb_; ++b0) {
      if (bstamp[b0] >= 0 || !nondegenerate(b0)) continue;
      const std::int64_t h = static_cast<std::int64_t>(hull_facets.size());
      std::array<std::int64_t, kMaxD> base;
      fvert(b0, base);
      const double* rows[kMaxD + 1];
      for (int r = 0; r < d; ++r) rows[r] = pt(base[r]);
      // a vertex of the base facet is on its plane: no determinant with a
      // repeated row (exactly 0, which only the exact stage can tell: the
      // neighbouring facets share d - 1 vertices with it)
      for (int r = 0; r < d; ++r) on_stamp[static_cast<std::size_t>(base[r])] = h;
      auto on_plane = [&](std::int64_t v) {
        const std::size_t u = static_cast<std::size_t>(v);
        if (on_stamp[u] == h) return true;
        if (off_stamp[u] == h) return false;
        rows[d] = pt(v);
        const bool on = pred::orient_d_exact(d, rows) == 0;
        (on ? on_stamp : off_stamp)[u] = h;
        return on;
      };
      std::vector<std::int64_t> pts_on;
      auto list = [&](std::int64_t v) {
        if (listed[static_cast<std::size_t>(v)] == h) return;
        listed[static_cast<std::size_t>(v)] = h;
        pts_on.push_back(v);
      };
      std::vector<std::size_t> queue{b0}, flats;
      bstamp[b0] = h;
      while (!queue.empty() || !flats.empty()) {
        if (!flats.empty()) {  // a zero-volume simplex in the plane: its vertices, its flat neighbours in the plane
          const std::size_t s = flats.back();
          flats.pop_back();
          layer[s] = 1;
          for (std::size_t j = 0; j < k; ++j) list(S[s * k + j]);
          for (std::size_t j = 0; j < k; ++j) {
            const std::int64_t t2 = nbr[s * k + j];
            if (t2 < 0 || !flat[t2] || sstamp[t2] == h || s_off[t2] == h) continue;
            bool all = true;
            for (std::size_t l = 0; l < k && all; ++l) all = on_plane(S[t2 * k + l]);
            if (all) {
              sstamp[t2] = h;
              flats.push_back(static_cast<std::size_t>(t2));
            } else {
              s_off[t2] = h;
            }
          }
          continue;
        }
        const std::size_t b = queue.back();
        queue.pop_back();
        std::array<std::int64_t, kMaxD> fb;
        fvert(b, fb);
        for (int l = 0; l < d; ++l) list(fb[l]);
        const std::size_t s = static_cast<std::size_t>(bf[b]) / k;
        if (flat[s] && sstamp[s] != h && s_off[s] != h) {
          bool all = true;
          for (std::size_t l = 0; l < k && all; ++l) all = on_plane(S[s * k + l]);
          if (all) {
            sstamp[s] = h;
            flats.push_back(s);
          } else {
            s_off[s] = h;
          }
        }
        for (std::size_t x = adj_off[b]; x != adj_off[b + 1]; ++x) {
          const std::uint32_t b2 = adj[x];
          if (bstamp[b2] == h || b_off[b2] == h) continue;
          std::array<std::int64_t, kMaxD> f2;
          fvert(b2, f2);
          bool all = true;
          for (int l = 0; l < d && all; ++l) all = on_plane(f2[l]);
          if (all) {
            bstamp[b2] = h;
            queue.push_back(b2);
          } else {
            b_off[b2] = h;
          }
        }
      }
      std::sort(pts_on.begin(), pts_on.end());  // (each listed once)
      hull_facets.push_back(std::move(pts_on));
    }
  }
  // point -> hull facets holding it (sorted CSR)
  std::vector<std::int64_t> ph_off(n + 1, 0), ph;
  {
    for (const auto& h : hull_facets)
      for (std::int64_t v : h) ++ph_off[v + 1];
    for (std::size_t i = 0; i < n; ++i) ph_off[i + 1] += ph_off[i];
    ph.resize(ph_off[n]);
    std::vector<std::int64_t> cur(ph_off.begin(), ph_off.end() - 1);
    for (std::size_t h = 0; h < hull_facets.size(); ++h)
      for (std::int64_t v : hull_facets[h]) ph[cur[v]++] = static_cast<std::int64_t>(h);
  }
  auto on_hull = [&](std::int64_t i) { return ph_off[i + 1] > ph_off[i]; };
  lap("neighbours, hull facets");

  // the cyclic sequence of groups around a (d-2)-face `face` (2D: a point; 3D: an edge):
  // walk the simplices holding it across their facets holding it; a
  // zero-volume simplex of a hull facet stands for the vertex at infinity, as
  // does the gap of an open walk (the triangulation's boundary)
  auto cyclic = [&](const std::int64_t* star, std::size_t cnt, const std::int64_t* face, int fsize,
                    bool infinite, std::vector<std::int64_t>& seq) {
    seq.clear();
    auto others = [&](std::int64_t s, int o[2]) {  // the two positions not in face
      int c = 0;
      for (std::size_t j = 0; j < k; ++j) {
        bool in = false;
        for (int x = 0; x < fsize; ++x) in |= S[s * k + j] == face[x];
        if (!in && c < 2) o[c++] = static_cast<int>(j);
      }
    };
    std::int64_t start = star[0];
    int o[2];
    int exit_side = -1;
    for (std::size_t x = 0; x < cnt && exit_side < 0; ++x) {
      others(star[x], o);
      if (nbr[star[x] * k + o[0]] < 0) {
        start = star[x];
        exit_side = o[1];
      } else if (nbr[star[x] * k + o[1]] < 0) {
        start = star[x];
        exit_side = o[0];
      }
    }
    const bool open = exit_side >= 0;
    if (!open) {
      others(start, o);
      exit_side = o[0];
    }
    if (open) seq.push_back(-1);
    std::int64_t cur = start;
    for (std::size_t steps = 0; steps <= cnt; ++steps) {
      seq.push_back(group[cur] >= 0 ? group[cur] : (layer[cur] ? -1 : -2));
      const std::int64_t next = nbr[cur * k + exit_side];
      if (next < 0 || next == start) break;
      others(next, o);
      // leave `next` through the side that is not shared with cur
      exit_side = nbr[next * k + o[0]] == cur ? o[1] : o[0];
      cur = next;
    }
    // compress in place: drop -2 (zero-volume simplices inside), repeats
    // (a cell's simplices are consecutive around the face), -1 unless infinite
    std::size_t kept = 0;
    for (std::size_t x = 0; x < seq.size(); ++x) {
      const std::int64_t g = seq[x];
      if (g == -2 || (g == -1 && !infinite)) continue;
      if (std::find(seq.begin(), seq.begin() + static_cast<std::ptrdiff_t>(kept), g) !=
          seq.begin() + static_cast<std::ptrdiff_t>(kept))
        continue;
      seq[kept++] = g;
    }
    seq.resize(kept);
    if (infinite && std::find(seq.begin(), seq.end(), -1) == seq.end()) seq.insert(seq.begin(), -1);
  };

  // 5. regions, point by point in parallel (in chunks of points whose
  // results are joined in order). Point i has a cell with interior iff its
  // lifted point P_i is a vertex of the lower hull Q (with its vertical
  // rays); then every cell of the exact subdivision whose lifted face holds
  // P_i uses i in a positive simplex (the cell's positive simplices cover
  // it, and a vertex of the face is only covered by a simplex having it as
  // a vertex), so the cells around i are all the cells at P_i, and no third
  // point lies in all of them and the hull facets holding i (their
  // intersection is P_i). When P_i is no vertex, the smallest face of Q
  // holding it has two vertices or more, which every cell and hull facet
  // holding P_i uses: the third-point test finds one.
  std::vector<std::int64_t> ps_off(n + 1, 0), pss;
  for (std::size_t x = 0; x < m * k; ++x) ++ps_off[S[x] + 1];
  for (std::size_t i = 0; i < n; ++i) ps_off[i + 1] += ps_off[i];
  pss.resize(ps_off[n]);
  {
    std::vector<std::int64_t> cur(ps_off.begin(), ps_off.end() - 1);
    for (std::size_t x = 0; x < m * k; ++x) pss[cur[S[x]]++] = static_cast<std::int64_t>(x / k);
  }
  // the cells around point i (the groups of its positive simplices), sorted
  auto cells_around = [&](std::int64_t i, std::vector<std::int64_t>& out) {
    out.clear();
    for (std::int64_t x = ps_off[i]; x < ps_off[i + 1]; ++x)
      if (group[pss[x]] >= 0) out.push_back(group[pss[x]]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  };
  using Set = std::pair<const std::int64_t*, const std::int64_t*>;
  auto gset = [&](std::int64_t g) { return Set{gv.data() + gv_off[g], gv.data() + gv_off[g + 1]}; };
  auto hset = [&](std::int64_t h) {
    const auto& f = hull_facets[h];
    return Set{f.data(), f.data() + f.size()};
  };
  // calls visit(l) for each l of the intersection of `sets` (non-empty)
  // until it returns false
  auto intersect = [&](const std::vector<Set>& sets, auto&& visit) {
    std::size_t small = 0;
    for (std::size_t x = 1; x < sets.size(); ++x)
      if (sets[x].second - sets[x].first < sets[small].second - sets[small].first) small = x;
    for (const std::int64_t* l = sets[small].first; l != sets[small].second; ++l) {
      bool everywhere = true;
      for (std::size_t x = 0; x < sets.size() && everywhere; ++x)
        if (x != small) everywhere = holds(sets[x].first, sets[x].second, *l);
      if (everywhere && !visit(*l)) return;
    }
  };
  struct Chunk {
    std::vector<std::int64_t> rp;
    std::vector<std::pair<std::int64_t, std::int64_t>> extra;
    Csr rv, rg;
  };
  // about four pieces per worker (a fixed 2048 left inputs of a few thousand
  // points, the 4D and 5D lattices, on one thread)
  const std::size_t workers = static_cast<std::size_t>(std::max(1, arena.max_concurrency()));
  const std::size_t chunk = std::clamp<std::size_t>((n + 4 * workers - 1) / (4 * workers), 16, 2048),
                    nchunks = (n + chunk - 1) / chunk;
  std::vector<Chunk> chunks(nchunks);
  std::vector<std::uint8_t> vertex(n, 0);  // P_i is a vertex of Q: i has a cell with interior
  std::atomic<bool> ties{false};           // some point of a positive simplex is no vertex
  // the ridges (i, j), j > i, of point i (see 6 below); tie: whether ties
  // were found (vertex[] and the extra candidates are then known)
  struct Scratch {
    // (j, simplex or -1) as j 2^32 + simplex + 1: the pairs' order, sorted
    // as one integer (j < n < 2^31, simplex + 1 < m + 1 <= 2^32: voronoi()
    // checks both)
    std::vector<std::uint64_t> e;
    std::vector<std::int64_t> around, cs, gs, star, seq, order;
    std::vector<Set> sets;
    std::vector<std::uint8_t> adj;
  };
  std::vector<std::int64_t> ex_off(n + 1, 0), ex;  // the extra candidates by their first point (CSR)
  std::vector<std::int64_t> gq_off, gq;  // with ties: each cell's points that are vertices of Q
  auto qset = [&](std::int64_t g) { return Set{gq.data() + gq_off[g], gq.data() + gq_off[g + 1]}; };
  auto ridges_of = [&](std::int64_t i, bool tie, Scratch& sc, Chunk& out_c) {
    auto& e = sc.e;
    auto &around = sc.around, &cs = sc.cs, &gs = sc.gs, &star = sc.star, &seq = sc.seq, &order = sc.order;
    auto& sets = sc.sets;
    auto& adj = sc.adj;
    const std::int64_t* st = pss.data() + ps_off[i];
    const std::size_t cnt = static_cast<std::size_t>(ps_off[i + 1] - ps_off[i]);
    if (tie) cells_around(i, around);
    e.clear();
    for (std::size_t x = 0; x < cnt; ++x)
      for (std::size_t l = 0; l < k; ++l)
        if (S[st[x] * k + l] > i)
          e.push_back(static_cast<std::uint64_t>(S[st[x] * k + l]) << 32 | static_cast<std::uint64_t>(st[x] + 1));
    for (std::int64_t x = ex_off[i]; x < ex_off[i + 1]; ++x) e.push_back(static_cast<std::uint64_t>(ex[x]) << 32);
    std::sort(e.begin(), e.end());
    auto e_point = [&](std::size_t x) { return static_cast<std::int64_t>(e[x] >> 32); };
    auto e_simplex = [&](std::size_t x) { return static_cast<std::int64_t>(e[x] & 0xffffffffu) - 1; };
    for (std::size_t a = 0; a < e.size();) {
      std::size_t b = a + 1;
      const std::int64_t j = e_point(a);
      while (b < e.size() && e_point(b) == j) ++b;
      const std::size_t a0 = a;
      a = b;
      if (tie && !vertex[j]) continue;
      // the cells holding i and j. Without ties they are the cells of
      // the simplices holding edge ij when it is an edge of Q (each cell
      // holding it covers it by edges of its positive simplices between
      // vertices of Q on it: i and j alone); when it is not, a subset
      // of the cells holding i and j still has the third vertex of the
      // smallest face holding both in all of their point sets.
      cs.clear();
      if (tie) {
        for (std::int64_t g : around)
          if (holds(gq.data() + gq_off[g], gq.data() + gq_off[g + 1], j)) cs.push_back(g);
      } else {
        for (std::size_t x = a0; x < b; ++x)
          if (group[e_simplex(x)] >= 0) cs.push_back(group[e_simplex(x)]);
        std::sort(cs.begin(), cs.end());
        cs.erase(std::unique(cs.begin(), cs.end()), cs.end());
      }
      if (cs.empty()) continue;
      sets.clear();
      for (std::int64_t g : cs) sets.push_back(tie ? qset(g) : gset(g));
      bool infinite = false;
      {  // hull facets holding both i and j
        const std::int64_t *x = ph.data() + ph_off[i], *xe = ph.data() + ph_off[i + 1];
        const std::int64_t *y = ph.data() + ph_off[j], *ye = ph.data() + ph_off[j + 1];
        while (x < xe && y < ye) {
          if (*x < *y) {
            ++x;
          } else if (*y < *x) {
            ++y;
          } else {
            infinite = true;
            sets.push_back(hset(*x));
            ++x, ++y;
          }
        }
      }
      bool ridge = true;
      intersect(sets, [&](std::int64_t l) { return l == i || l == j || (tie && !vertex[l]) || (ridge = false); });
      if (!ridge) continue;
      out_c.rp.push_back(i);
      out_c.rp.push_back(j);
      if (d != 3) {
        seq = cs;
        if (infinite) seq.insert(seq.begin(), -1);
      } else {
        // the simplices holding edge ij; when their cells are all the
        // cells holding i and j, the walk around the edge orders them
        gs.clear();
        star.clear();
        for (std::size_t x = a0; x < b; ++x)
          if (e_simplex(x) >= 0) {
            star.push_back(e_simplex(x));
            const std::int64_t g = group[e_simplex(x)];
            if (tie && g >= 0) gs.push_back(g);
          }
        if (tie) {
          std::sort(gs.begin(), gs.end());
          gs.erase(std::unique(gs.begin(), gs.end()), gs.end());
        }
        if (!tie || gs.size() == cs.size()) {
          const std::int64_t face[2] = {i, j};
          cyclic(star.data(), star.size(), face, 2, infinite, seq);
        } else {
          // otherwise (ties): two cells around the edge P_iP_j are
          // consecutive iff they share a 2-face, i.e. a vertex of Q
          // other than i and j; the cells form a cycle, or a path from
          // infinity to infinity when the ridge is unbounded
          const std::size_t nc = cs.size();
          adj.assign(nc * nc, 0);
          std::vector<int> deg(nc, 0);
          for (std::size_t x = 0; x < nc; ++x)
            for (std::size_t y = x + 1; y < nc; ++y) {
              const std::int64_t *p = gq.data() + gq_off[cs[x]], *pe = gq.data() + gq_off[cs[x] + 1];
              const std::int64_t *q = gq.data() + gq_off[cs[y]], *qe = gq.data() + gq_off[cs[y] + 1];
              bool share = false;
              while (p < pe && q < qe && !share) {
                if (*p < *q) {
                  ++p;
                } else if (*q < *p) {
                  ++q;
                } else {
                  share = *p != i && *p != j && vertex[*p];
                  ++p, ++q;
                }
              }
              if (share) {
                adj[x * nc + y] = adj[y * nc + x] = 1;
                ++deg[x], ++deg[y];
              }
            }
          std::size_t start = 0;
          if (infinite)
            for (std::size_t x = 0; x < nc; ++x)
              if (deg[x] <= 1) {
                start = x;
                break;
              }
          std::vector<std::uint8_t> seen(nc, 0);
          order.clear();
          for (std::size_t cur = start;;) {
            seen[cur] = 1;
            order.push_back(cs[cur]);
            std::size_t next = nc;
            for (std::size_t y = 0; y < nc && next == nc; ++y)
              if (adj[cur * nc + y] && !seen[y]) next = y;
            if (next == nc) break;
            cur = next;
          }
          for (std::size_t x = 0; x < nc; ++x)  // not reached by the walk (cannot happen)
            if (!seen[x]) order.push_back(cs[x]);
          seq.clear();
          if (infinite) seq.push_back(-1);
          seq.insert(seq.end(), order.begin(), order.end());
        }
      }
      out_c.rv.val.insert(out_c.rv.val.end(), seq.begin(), seq.end());
      out_c.rv.close();
    }
  };
  arena.execute([&] {
    tbb::parallel_for(std::size_t(0), nchunks, [&](std::size_t c) {
      Chunk& out_c = chunks[c];
      Scratch sc;
      std::vector<std::int64_t> seq;
      std::vector<Set> sets;
      for (std::size_t ii = c * chunk; ii < std::min(n, (c + 1) * chunk); ++ii) {
        const std::int64_t i = static_cast<std::int64_t>(ii);
        const std::int64_t* st = pss.data() + ps_off[i];
        const std::size_t cnt = static_cast<std::size_t>(ps_off[i + 1] - ps_off[i]);
        if (cnt > 0) {
          const bool infinite = on_hull(i);
          if (d == 2) {
            const std::int64_t face[1] = {i};
            cyclic(st, cnt, face, 1, infinite, seq);
          } else {
            cells_around(i, seq);
            if (infinite) seq.insert(seq.begin(), -1);
          }
          sets.clear();
          for (std::int64_t g : seq)
            if (g >= 0) sets.push_back(gset(g));
          bool cell = !sets.empty();
          if (cell) {
            for (std::int64_t x = ph_off[i]; x < ph_off[i + 1]; ++x) sets.push_back(hset(ph[x]));
            intersect(sets, [&](std::int64_t l) { return l == i || (cell = false); });
            if (!cell) ties.store(true, std::memory_order_relaxed);
          }
          if (cell) {
            vertex[i] = 1;
            out_c.rg.val.insert(out_c.rg.val.end(), seq.begin(), seq.end());
          }
        }
        out_c.rg.close();
        // the ridges as if without ties (the answer when none are found)
        ridges_of(i, false, sc, out_c);
      }
    });
  });
  lap("regions, ridges");
  if (ties.load()) {
    gq_off.assign(nv + 1, 0);
    for (std::size_t g = 0; g < nv; ++g) {
      for (std::int64_t x = gv_off[g]; x < gv_off[g + 1]; ++x)
        if (vertex[gv[x]]) gq.push_back(gv[x]);
      gq_off[g + 1] = static_cast<std::int64_t>(gq.size());
    }
  }

  // 6. ridges. V_i ∩ V_j is the set of x whose supporting hyperplane (slope
  // 2x) touches Q in a face holding P_i and P_j; it is (d-1)-dimensional iff
  // some edge (1-face) of Q holds both, i.e. iff P_i and P_j are vertices of
  // Q (regions with interior; a point inside an edge has a cell of no
  // interior) and the smallest face G of Q holding both is the edge P_iP_j.
  // G is bounded iff a cell (lower facet) holds both; then G is the
  // intersection of the cells and hull facets (vertical facets) holding
  // both, and the vertices of G are exactly the vertices of Q among the
  // points in all of their point sets (each lies in G; each vertex of G is
  // used by every cell holding it, see 5). So (i, j) is a ridge iff i and j
  // are vertices of Q, some cell holds both, and no third vertex of Q lies
  // in every cell and hull facet holding both. Points in the set that are no
  // vertices of Q (ties: a lifted point inside an edge or face) are ignored.
  // The cells holding both are the cells around i whose point sets hold j.
  //
  // Candidates: every edge ij of the triangulation, and the pairs found
  // through the tie points: when no simplex has the edge ij, a cell F holding
  // the edge P_iP_j covers it by edges of its positive simplices with both
  // ends on it, so the one at P_i is ia with P_a inside the edge, in a
  // positive simplex of F. The cells around a and the hull facets holding a
  // all hold P_iP_j, so their intersection is a face G' of Q with P_iP_j as
  // an edge, and i, j are among the vertices of Q in its point set. On a
  // line through P_a in G' at most two vertices of G' lie, one on either
  // side of P_a; for each point a that is no vertex, every pair of vertices
  // of Q in that set lying on one line with p_a, on either side of it, is a
  // candidate (the projection is one-to-one on G', a bounded face). Lines
  // are compared exactly: by the first axis f where the point differs from
  // p_a, then the ratios (x_l - a_l) / (x_f - a_f), l > f, by exact orient2d
  // of the projections onto axes (f, l).
  arena.execute([&] {
    tbb::parallel_for(std::size_t(0), nchunks, [&](std::size_t c) {
      if (!ties.load(std::memory_order_relaxed)) return;
      Chunk& out_c = chunks[c];
      std::vector<std::int64_t> cs, vs;
      std::vector<Set> sets;
      struct Dir {
        std::int64_t id;
        int f, side;
      };
      std::vector<Dir> dirs;
      for (std::size_t ii = c * chunk; ii < std::min(n, (c + 1) * chunk); ++ii) {
        const std::int64_t a = static_cast<std::int64_t>(ii);
        if (vertex[a]) continue;
        cells_around(a, cs);
        if (cs.empty()) continue;
        sets.clear();
        for (std::int64_t g : cs) sets.push_back(qset(g));
        for (std::int64_t x = ph_off[a]; x < ph_off[a + 1]; ++x) sets.push_back(hset(ph[x]));
        vs.clear();
        intersect(sets, [&](std::int64_t l) {
          if (vertex[l]) vs.push_back(l);
          return true;
        });
        if (vs.size() < 2) continue;
        const double* pa = pt(a);
        dirs.clear();
        for (std::int64_t b : vs) {
          const double* pb = pt(b);
          int f = 0;
          while (f < d && pb[f] == pa[f]) ++f;
          if (f < d) dirs.push_back({b, f, pb[f] > pa[f] ? 1 : -1});
        }
        // -1, 0, 1: the line through p_a and p_x before, equal to, after the one through p_a and p_y
        auto line_cmp = [&](const Dir& x, const Dir& y) {
          if (x.f != y.f) return x.f < y.f ? -1 : 1;
          const double *px = pt(x.id), *py = pt(y.id);
          for (int l = x.f + 1; l < d; ++l) {
            const double A[2] = {pa[x.f], pa[l]}, X[2] = {px[x.f], px[l]}, Y[2] = {py[x.f], py[l]};
            // sign of (x_l - a_l)(y_f - a_f) - (y_l - a_l)(x_f - a_f)
            const int o = pred::orient2d_exact(A, Y, X) * x.side * y.side;
            if (o != 0) return o;
          }
          return 0;
        };
        std::sort(dirs.begin(), dirs.end(), [&](const Dir& x, const Dir& y) {
          const int o = line_cmp(x, y);
          if (o != 0) return o < 0;
          return x.side != y.side ? x.side < y.side : x.id < y.id;
        });
        for (std::size_t s = 0; s < dirs.size();) {
          std::size_t e = s + 1;
          while (e < dirs.size() && line_cmp(dirs[s], dirs[e]) == 0) ++e;
          for (std::size_t x = s; x < e; ++x)
            for (std::size_t y = s; y < e; ++y)
              if (dirs[x].side < 0 && dirs[y].side > 0)
                out_c.extra.push_back({std::min(dirs[x].id, dirs[y].id), std::max(dirs[x].id, dirs[y].id)});
          s = e;
        }
      }
    });
  });
  if (ties.load()) {
    std::vector<std::pair<std::int64_t, std::int64_t>> all;
    for (Chunk& c : chunks) {
      all.insert(all.end(), c.extra.begin(), c.extra.end());
      c.extra = {};
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    for (const auto& pr : all) ++ex_off[pr.first + 1];
    for (std::size_t i = 0; i < n; ++i) ex_off[i + 1] += ex_off[i];
    for (const auto& pr : all) ex.push_back(pr.second);  // sorted by first, then second
  }
  lap("tie candidates");
  if (ties.load()) {
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), nchunks, [&](std::size_t c) {
        Chunk& out_c = chunks[c];
        out_c.rp.clear();
        out_c.rv = Csr();
        Scratch sc;
        for (std::size_t ii = c * chunk; ii < std::min(n, (c + 1) * chunk); ++ii)
          if (vertex[ii]) ridges_of(static_cast<std::int64_t>(ii), true, sc, out_c);
      });
    });
    lap("ridges with ties");
  }

  for (Chunk& c : chunks) {
    out.ridge_points.insert(out.ridge_points.end(), c.rp.begin(), c.rp.end());
    const std::int64_t base_rv = static_cast<std::int64_t>(out.ridge_vertices.val.size());
    for (std::size_t x = 1; x < c.rv.off.size(); ++x) out.ridge_vertices.off.push_back(base_rv + c.rv.off[x]);
    out.ridge_vertices.val.insert(out.ridge_vertices.val.end(), c.rv.val.begin(), c.rv.val.end());
    const std::int64_t base_rg = static_cast<std::int64_t>(out.regions.val.size());
    for (std::size_t x = 1; x < c.rg.off.size(); ++x) out.regions.off.push_back(base_rg + c.rg.off[x]);
    out.regions.val.insert(out.regions.val.end(), c.rg.val.begin(), c.rg.val.end());
    c = Chunk();
  }
  lap("join");
  out.simplex_vertex = std::move(group);
  return out;
}

// (vertices, simplex_vertex, ridge_points, ridge_offsets, ridge_values,
// region_offsets, region_values); see voronoi_core.
nb::tuple voronoi(const Points& p, const std::optional<Vector>& w, const Cells& c, int threads,
                  const std::optional<Cells>& neighbors) {
  const PointSet ps = point_set(p, w);
  const int d = ps.dim;
  if (d < 2 || d > ref::rtd::kMaxDim) throw std::invalid_argument("Voronoi expects points of shape (n, d) with d = 2..9");
  if (c.shape(1) != static_cast<std::size_t>(d + 1)) throw std::invalid_argument("simplices must have d + 1 columns");
  const std::size_t m = c.shape(0), n = ps.size();
  if (n >= (std::size_t(1) << 31) || m >= (std::size_t(1) << 32)) throw std::invalid_argument("too many points");
  for (std::size_t x = 0; x < m * c.shape(1); ++x)
    if (c.data()[x] < 0 || static_cast<std::size_t>(c.data()[x]) >= n)
      throw std::invalid_argument("simplices name a point that does not exist");
  if (neighbors) {
    if (neighbors->shape(0) != m || neighbors->shape(1) != c.shape(1))
      throw std::invalid_argument("neighbors must have the simplices' shape");
    for (std::size_t x = 0; x < m * c.shape(1); ++x)
      if (neighbors->data()[x] < -1 || neighbors->data()[x] >= static_cast<std::int64_t>(m))
        throw std::invalid_argument("neighbors name a simplex that does not exist");
  }
  VoronoiResult r;
  {
    nb::gil_scoped_release nogil;
    r = voronoi_core(ps, c.data(), m, threads, neighbors ? neighbors->data() : nullptr);
  }
  const std::size_t nr = r.ridge_points.size() / 2;
  return nb::make_tuple(double_array(std::move(r.vertices), r.nv, static_cast<std::size_t>(d)),
                        index_array(std::move(r.simplex_vertex), m, 0, true),
                        index_array(std::move(r.ridge_points), nr, 2),
                        index_array(r.ridge_vertices.off, r.ridge_vertices.off.size(), 0, true),
                        index_array(r.ridge_vertices.val, r.ridge_vertices.val.size(), 0, true),
                        index_array(r.regions.off, r.regions.off.size(), 0, true),
                        index_array(r.regions.val, r.regions.val.size(), 0, true));
}

// For the tests: the correctly rounded value of M / D * 2^E (decimal strings).
double _round_ratio(const std::string& M, const std::string& D, long E) {
  Mpz a, b, q, r, tmp;
  mpz_set_str(a.v, M.c_str(), 10);
  mpz_set_str(b.v, D.c_str(), 10);
  if (mpz_sgn(b.v) <= 0) throw std::invalid_argument("D must be positive");
  return round_ratio(a.v, b.v, E, q.v, r.v, tmp.v);
}

// The exact solver alone, for the tests: the centre of the simplex `points`
// ((d + 1) x d, optional weights) as decimal strings (M_0..M_(d-1), D) and E
// with c_l = M_l / D * 2^E exactly and whether SplitCentre solved it, or
// None for a simplex of zero volume.
nb::object _exact_centre(const std::vector<std::vector<double>>& points, std::optional<std::vector<double>> weights) {
  const int d = static_cast<int>(points.size()) - 1;
  if (d < 1 || d > kMaxD) throw std::invalid_argument("need d + 1 points, 1 <= d <= 9");
  for (const auto& q : points)
    if (static_cast<int>(q.size()) != d) throw std::invalid_argument("each point needs d coordinates");
  if (weights && static_cast<int>(weights->size()) != d + 1) throw std::invalid_argument("need d + 1 weights");
  auto cs = std::make_unique<CentreSolver>();
  cs->d = d;
  const double* p[kMaxD + 1];
  for (int k = 0; k <= d; ++k) p[k] = points[static_cast<std::size_t>(k)].data();
  if (!cs->solve(p, weights ? weights->data() : nullptr)) return nb::none();
  auto str = [](const mpz_t v) {
    std::string out(mpz_sizeinbase(v, 10) + 2, '\0');
    mpz_get_str(out.data(), 10, v);
    out.resize(std::strlen(out.c_str()));
    return out;
  };
  nb::list M;
  for (int l = 0; l < d; ++l) M.append(str(cs->M[l].v));
  return nb::make_tuple(M, str(cs->Dn.v), cs->E, cs->used_split);
}


// nl_centre alone, for the tests: the correctly rounded centre of the
// simplex `points` ((d + 1) x d, optional weights) as a list, False for zero
// volume, None where it does not decide (the exact solver's case).
nb::object _near_lattice_centre(const std::vector<std::vector<double>>& points,
                                std::optional<std::vector<double>> weights) {
  const int d = static_cast<int>(points.size()) - 1;
  if (d < 1 || d > kMaxD) throw std::invalid_argument("need d + 1 points, 1 <= d <= 9");
  for (const auto& q : points)
    if (static_cast<int>(q.size()) != d) throw std::invalid_argument("each point needs d coordinates");
  if (weights && static_cast<int>(weights->size()) != d + 1) throw std::invalid_argument("need d + 1 weights");
  const double* p[kMaxD + 1];
  for (int k = 0; k <= d; ++k) p[k] = points[static_cast<std::size_t>(k)].data();
  double c[kMaxD];
#ifdef FLIPFLOP_VORONOI_FILTER
  NlCentreScratch sc;
  const int r = nl_centre_d(d, p, weights ? weights->data() : nullptr, c, sc);
#else
  const int r = -1;
#endif
  if (r < 0) return nb::none();
  if (r == 0) return nb::bool_(false);
  nb::list out;
  for (int l = 0; l < d; ++l) out.append(c[l]);
  return out;
}

}  // namespace

NB_MODULE(_flipflop, m) {
  m.doc() = "flipflop's compiled core (use the flipflop package, not this module)";
  m.attr("__version__") = FLIPFLOP_VERSION;
  m.def("gpu_backends", &gpu_backends);
  m.def("hull2", &hull2, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3", &hull3, nb::arg("points"), nb::arg("backend"), nb::arg("threads"));
  m.def("hull3_strict", &hull3_strict, nb::arg("points"), nb::arg("threads"));
  m.def("hull_d", &hull_d, nb::arg("points"), nb::arg("threads") = 0);
  m.def("hull_d_attributes", &hull_d_attributes, nb::arg("points"), nb::arg("facets"));
  m.def("triangulate", &triangulate, nb::arg("points"), nb::arg("weights").none(), nb::arg("backend"),
        nb::arg("strict"), nb::arg("threads"), nb::arg("furthest") = false);
  m.def("triangulate_with_neighbors", &triangulate_with_neighbors, nb::arg("points"), nb::arg("weights").none(),
        nb::arg("backend"), nb::arg("strict"), nb::arg("threads"), nb::arg("furthest") = false);
  nb::class_<IncrementalTriangulation>(m, "IncrementalTriangulation")
      .def(nb::init<const Points&, const std::optional<Vector>&, bool, int, bool>(), nb::arg("points"),
           nb::arg("weights").none(), nb::arg("strict"), nb::arg("threads"), nb::arg("furthest"))
      .def(nb::init<const Points&, const std::optional<Vector>&, int, const Cells&, const Cells&>(), nb::arg("points"),
           nb::arg("weights").none(), nb::arg("threads"), nb::arg("simplices"), nb::arg("neighbors"))
      .def("add", &IncrementalTriangulation::add, nb::arg("points"), nb::arg("weights").none())
      .def("result", &IncrementalTriangulation::result)
      .def("neighbors", &IncrementalTriangulation::neighbors)
      .def("__len__", &IncrementalTriangulation::size);
  nb::class_<IncrementalHull>(m, "IncrementalHull")
      .def(nb::init<const Points&, int>(), nb::arg("points"), nb::arg("threads"))
      .def(nb::init<const Points&, int, const Cells&, const Cells&>(), nb::arg("points"), nb::arg("threads"),
           nb::arg("facets"), nb::arg("neighbors"))
      .def("add", &IncrementalHull::add, nb::arg("points"))
      .def("attributes", &IncrementalHull::attributes)
      .def("facets", &IncrementalHull::facets)
      .def("__len__", &IncrementalHull::size);
  m.def("neighbors", &neighbors, nb::arg("simplices"));
  m.def("find_simplex", &find_simplex, nb::arg("points"), nb::arg("simplices"), nb::arg("neighbors"),
        nb::arg("queries"), nb::arg("signs").none() = nb::none(), nb::arg("threads") = 0);
  m.def("simplex_signs", &simplex_signs, nb::arg("points"), nb::arg("simplices"));
  m.def("barycentric_transforms", &barycentric_transforms, nb::arg("points"), nb::arg("simplices"), nb::arg("signs"));
  m.def("power_signs", &power_signs, nb::arg("points"), nb::arg("weights").none(), nb::arg("cells"));
  m.def("vertex_neighbours", &vertex_neighbours, nb::arg("simplices"), nb::arg("n"));
  m.def("lifted_equations", &lifted_equations, nb::arg("points"), nb::arg("weights").none(), nb::arg("simplices"),
        nb::arg("lift_exponent"), nb::arg("furthest"));
  m.def("certify", &certify_cells, nb::arg("kind"), nb::arg("points"), nb::arg("cells"), nb::arg("weights").none(),
        nb::arg("canonical"));
  m.def("orient", &orient_cells, nb::arg("kind"), nb::arg("points"), nb::arg("cells"));
  m.def("generate", &generate, nb::arg("dist"), nb::arg("n"), nb::arg("seed"), nb::arg("thickness"),
        nb::arg("weights").none());
  m.def("distributions", &gen::distributions);
  m.def("dimension_of", &gen::dimension_of);
  m.def("_reads_in_place", &reads_in_place, nb::arg("points"), nb::arg("weights").none());
  m.def("instant_flip", &instant_flip, nb::arg("points"), nb::arg("w"), nb::arg("u"));
  m.def("voronoi", &voronoi, nb::arg("points"), nb::arg("weights").none(), nb::arg("simplices"), nb::arg("threads"),
        nb::arg("neighbors").none() = nb::none());
  m.def("_round_ratio", &_round_ratio, nb::arg("M"), nb::arg("D"), nb::arg("E"));
  m.def("_exact_centre", &_exact_centre, nb::arg("points"), nb::arg("weights").none());
  m.def("_near_lattice_centre", &_near_lattice_centre, nb::arg("points"), nb::arg("weights").none());
}

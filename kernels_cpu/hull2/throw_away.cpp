// throw_away.cpp — the Akl–Toussaint-style first pass (throw_away.hpp).
#include "kernels_cpu/hull2/throw_away.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "kernels_cpu/hull2/graham_sorting.hpp"
#include "kernels_cpu/parallel.hpp"
#include "predicates/static_filter.hpp"
#include "reference/pseudo_angle.hpp"

namespace flipflop::cpu::hull2 {

namespace {

constexpr std::size_t kMinSample = 1024;
constexpr std::size_t kMaxSample = std::size_t{1} << 17;
constexpr std::size_t kScanChunk = 4096;
constexpr int kBuckets = 4096;                     // pseudo-angle buckets of the wedge table

// The polygon, the centre and the filter bound of the pass.
struct Polygon {
  std::vector<Pt2> v;          // V, counter-clockwise, by increasing pseudo-angle around c
  std::vector<double> ang;     // pseudo-angle of V_j around c
  std::vector<int> first;      // per bucket: the last j with ang[j] <= the bucket's start, or -1
  Pt2 c{};
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // the bounding box of c and V
  double bound = 0;                        // C_2 W_x W_y
};

// det [[a - p], [b - p]] > bound, evaluated as static_filter.hpp's det_plain<2>
// on the differences to p (the last row): orient2d(a, b, p) > 0 proved.
inline bool positive(const Pt2& a, const Pt2& b, double px, double py, double bound) {
  const double* p[3] = {&a.x, &b.x, nullptr};
  const double pp[2] = {px, py};
  p[2] = pp;
  double t[4];
  pred::filter_detail::differences<3, false>(p, nullptr, t, nullptr);
  return pred::filter_detail::det_plain<2>(t) > bound;
}

// false: no usable polygon (then nothing is discarded).
bool make_polygon(const PointSet& ps, std::size_t s, Polygon& P) {
  const std::size_t n = ps.size();
  if (s == 0) s = std::min(kMaxSample, std::max<std::size_t>(n / 64, kMinSample));
  s = std::min(s, n);
  if (s < 3) return false;
  std::vector<Pt2> sample(s);
  par_for(s, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      const auto i = static_cast<Index>(k * n / s);
      sample[k] = {ps.point(i)[0], ps.point(i)[1], i};
    }
  });
  ScanCounts unused;
  std::vector<Pt2> by_index = sample;  // graham_sorting reorders its copy
  const std::vector<Index> hull = graham_sorting(std::move(sample), static_filter_of(by_index), kScanChunk, unused);
  if (hull.size() < 3) return false;
  // V in hull order; the sample holds index k * n / s at position k
  double cx = 0, cy = 0;
  for (Index i : hull) {
    P.v.push_back({ps.point(i)[0], ps.point(i)[1], i});
    cx += P.v.back().x / static_cast<double>(hull.size());
    cy += P.v.back().y / static_cast<double>(hull.size());
  }
  const Pt2* near = &by_index[0];
  double best = HUGE_VAL;
  for (const Pt2& q : by_index) {
    const double d = std::fabs(q.x - cx) + std::fabs(q.y - cy);
    if (d < best) best = d, near = &q;
  }
  P.c = *near;
  // pseudo-angles, V rotated to start at the smallest; they must increase
  for (const Pt2& q : P.v) P.ang.push_back(pseudo_angle(q.x - P.c.x, q.y - P.c.y));
  for (double a : P.ang)
    if (!(a >= 0 && a < 4)) return false;
  const auto r = std::min_element(P.ang.begin(), P.ang.end()) - P.ang.begin();
  std::rotate(P.v.begin(), P.v.begin() + r, P.v.end());
  std::rotate(P.ang.begin(), P.ang.begin() + r, P.ang.end());
  for (std::size_t j = 1; j < P.ang.size(); ++j)
    if (!(P.ang[j - 1] < P.ang[j])) return false;
  // the bounding box and the bound
  P.x0 = P.x1 = P.c.x, P.y0 = P.y1 = P.c.y;
  for (const Pt2& q : P.v) {
    P.x0 = std::min(P.x0, q.x), P.x1 = std::max(P.x1, q.x);
    P.y0 = std::min(P.y0, q.y), P.y1 = std::max(P.y1, q.y);
  }
  const double wx = P.x1 - P.x0, wy = P.y1 - P.y0;
  constexpr int B = pred::filter_detail::window_exponent(2);
  constexpr double lo = pred::filter_detail::pow2i(-B), hi = pred::filter_detail::pow2i(B);
  if (!(wx >= lo && wx <= hi && wy >= lo && wy <= hi)) return false;
  P.bound = pred::filter_detail::bound_constant(2, false) * wx * wy;
  // the wedge table
  P.first.resize(kBuckets);
  for (int b = 0; b < kBuckets; ++b) {
    const double start = 4.0 * b / kBuckets;
    P.first[b] = static_cast<int>(std::upper_bound(P.ang.begin(), P.ang.end(), start) - P.ang.begin()) - 1;
  }
  return true;
}

// p strictly inside the triangle c V_j V_j+1 of its wedge, proved.
inline bool inside(const Polygon& P, double px, double py) {
  if (!(px >= P.x0 && px <= P.x1 && py >= P.y0 && py <= P.y1)) return false;
  const double a = pseudo_angle(px - P.c.x, py - P.c.y);
  if (!(a >= 0 && a < 4)) return false;
  const int m = static_cast<int>(P.v.size());
  int j = P.first[std::min(kBuckets - 1, static_cast<int>(a * (kBuckets / 4)))];
  while (j + 1 < m && P.ang[j + 1] <= a) ++j;
  if (j < 0) j = m - 1;
  const Pt2& u = P.v[j];
  const Pt2& w = P.v[j + 1 == m ? 0 : j + 1];
  return positive(u, w, px, py, P.bound) && positive(P.c, u, px, py, P.bound) &&
         positive(w, P.c, px, py, P.bound);
}

}  // namespace

ThrowAwayResult throw_away(const PointSet& ps, std::size_t from, std::size_t sample) {
  ThrowAwayResult out;
  const std::size_t n = ps.size();
  Polygon P;
  if (n < from || n < 3 || !make_polygon(ps, sample, P)) {
    out.survivors.resize(n);
    std::iota(out.survivors.begin(), out.survivors.end(), Index{0});
    return out;
  }
  out.polygon_vertices = P.v.size();
  const double* xy = ps.coords.data();
  out.survivors = par_select(n, [&](Index i) { return !inside(P, xy[2 * std::size_t{i}], xy[2 * std::size_t{i} + 1]); });
  return out;
}

}  // namespace flipflop::cpu::hull2

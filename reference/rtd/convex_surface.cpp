// convex_surface.cpp — the linear-time convexity certificate of a closed
// surface (convex_surface.hpp: the conditions and why they suffice).
#include "reference/rtd/convex_surface.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify_detail.hpp"

namespace flipflop::certify {

namespace {
constexpr int kMaxD = 9;  // orientations of up to 10 points (lambda_sign)

struct Orient {
  const PointSet& ps;
  int d;
  pred::StaticFilter filter;
  // orient_d of the first k of t (k = d + 1: facet and point; k = d: the
  // projections of d points to the first d - 1 coordinates)
  int operator()(const Index* t, int k) const {
    pred::PointId id[kMaxD + 1];
    const double* p[kMaxD + 1];
    for (int j = 0; j < k; ++j) id[j] = t[j], p[j] = ps.point(t[j]);
    return k == d + 1 ? pred::lambda_sign(&filter, k, id, p, nullptr) : pred::lambda_sign(k, id, p, nullptr, pred::Mode::filtered);
  }
  int facet_and(const std::vector<Index>& f, Index x) const {
    Index t[kMaxD + 1];
    for (int j = 0; j < d; ++j) t[j] = f[static_cast<std::size_t>(j)];
    t[d] = x;
    return (*this)(t, d + 1);
  }
};
}  // namespace

SurfaceCheck convex_surface(const PointSet& ps, const std::vector<std::vector<Index>>& facets, Index centre,
                            std::vector<std::uint32_t>* across, const ForRange& for_range) {
  const int d = ps.dim;
  SurfaceCheck out;
  // (a) ridges: sorted d-1 vertices, the facet and its vertex off the ridge
  struct Ridge {
    std::array<Index, kMaxD - 1> key;
    std::uint32_t f;
    int j;
  };
  std::vector<Ridge> ridges(facets.size() * static_cast<std::size_t>(d));
  const std::size_t nr = ridges.size();
  if (nr > 0xFFFFFFFFu) throw std::length_error("convex_surface: more ridges than 32-bit positions hold");
  // grouped by a stable radix sort of (32-bit hash of the key, position)
  // words (certify_detail.hpp: the same order at any split), then each run
  // of one hash sorted by (key, position) where its keys differ: equal keys
  // end up adjacent, in (facet, j) order. The ridges and their hashes are
  // built in parallel pieces. (A std::sort of (64-bit hash, position) pairs,
  // the keys breaking ties, took 4.9 of a 5D hull certificate's 17.7 ms on
  // 2x10^4 normal points, and building the ridges in one loop 1.9.)
  std::vector<std::uint64_t> keys(nr);
  detail::for_pieces(facets.size(), for_range, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k)
      for (int j = 0; j < d; ++j) {
        const std::size_t i = k * static_cast<std::size_t>(d) + static_cast<std::size_t>(j);
        Ridge& r = ridges[i];
        r.f = static_cast<std::uint32_t>(k);
        r.j = j;
        r.key.fill(~Index{0});
        int c = 0;
        for (int q = 0; q < d; ++q)
          if (q != j) r.key[static_cast<std::size_t>(c++)] = facets[k][static_cast<std::size_t>(q)];
        std::sort(r.key.begin(), r.key.begin() + c);
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (Index x : r.key) h = (h ^ x) * 0x100000001B3ull;
        keys[i] = ((h ^ (h >> 29)) & 0xFFFFFFFF00000000ull) | i;
      }
  });
  detail::radix_sort_high(keys, 32, for_range);
  std::vector<std::uint32_t> order(nr);
  for (std::size_t i = 0; i < nr; ++i) order[i] = static_cast<std::uint32_t>(keys[i] & 0xFFFFFFFFu);
  auto at = [&](std::size_t i) -> const Ridge& { return ridges[order[i]]; };
  auto hash_of = [&](std::size_t i) { return keys[i] >> 32; };
  const Orient plain{ps, d, pred::StaticFilter::for_points(ps.coords.data(), ps.size(), d)};
  if (across) across->assign(facets.size() * static_cast<std::size_t>(d), 0);
  // the groups of equal keys (starts), then each group checked — through
  // for_range, the first failing group in sorted order reported
  std::vector<std::size_t> group;
  for (std::size_t a = 0; a < nr;) {
    std::size_t e = a + 1;  // [a, e): one hash
    while (e < nr && hash_of(e) == hash_of(a)) ++e;
    if (e - a > 2 || (e - a == 2 && at(a).key != at(a + 1).key))
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(a), order.begin() + static_cast<std::ptrdiff_t>(e),
                [&](std::uint32_t x, std::uint32_t y) {
                  const auto &kx = ridges[x].key, &ky = ridges[y].key;
                  return kx != ky ? kx < ky : x < y;
                });
    for (std::size_t g = a; g < e;) {
      std::size_t b = g + 1;
      while (b < e && at(b).key == at(g).key) ++b;
      group.push_back(g);
      g = b;
    }
    a = e;
  }
  group.push_back(nr);
  const std::size_t ng = group.size() - 1;
  // the failing side of a two-facet group (0, 1), or -1
  auto concave_side = [&](std::size_t a) {
    for (int side = 0; side < 2; ++side) {
      const Ridge &f = at(a + static_cast<std::size_t>(side)), &g = at(a + 1 - static_cast<std::size_t>(side));
      if (plain.facet_and(facets[f.f], facets[g.f][static_cast<std::size_t>(g.j)]) >= 0) return side;
    }
    return -1;
  };
  if (const std::size_t bad = detail::smallest_failing(ng, for_range, [&](std::size_t k) {
        const std::size_t a = group[k];
        if (group[k + 1] - a != 2) return true;
        if (concave_side(a) >= 0) return true;
        if (across)
          for (int side = 0; side < 2; ++side) {
            const Ridge &f = at(a + static_cast<std::size_t>(side)), &g = at(a + 1 - static_cast<std::size_t>(side));
            (*across)[f.f * static_cast<std::size_t>(d) + static_cast<std::size_t>(f.j)] = g.f;
          }
        return false;
      });
      bad < ng) {
    const std::size_t a = group[bad], b = group[bad + 1];
    if (b - a != 2) {
      out.kind = SurfaceCheck::Kind::not_closed;
      out.count = b - a;
      out.facet = at(a).f;
      out.ridge.assign(at(a).key.begin(), at(a).key.begin() + (d - 1));
      return out;
    }
    const int side = concave_side(a);
    const Ridge &f = at(a + static_cast<std::size_t>(side)), &g = at(a + 1 - static_cast<std::size_t>(side));
    out.kind = SurfaceCheck::Kind::not_convex;
    out.facet = f.f, out.other = g.f, out.point = facets[g.f][static_cast<std::size_t>(g.j)];
    return out;
  }
  // (b) the centre: the given point, or the auxiliary one in a copy of the input
  PointSet ext;
  const PointSet* cps = &ps;
  Index c = centre;
  if (centre == kAuxiliaryCentre) {
    std::vector<char> on(ps.size(), 0);
    std::size_t m = 0;
    for (const auto& f : facets)
      for (Index x : f)
        if (!on[x]) on[x] = 1, ++m;
    std::vector<double> coords(ps.coords.begin(), ps.coords.end()), avg(static_cast<std::size_t>(d), 0.0);
    for (Index x = 0; x < ps.size(); ++x)
      if (on[x])
        for (int j = 0; j < d; ++j) avg[static_cast<std::size_t>(j)] += ps.point(x)[j] / static_cast<double>(m);
    coords.insert(coords.end(), avg.begin(), avg.end());
    ext.dim = d;
    ext.coords = Values(std::move(coords));
    cps = &ext;
    c = static_cast<Index>(ps.size());
    out.auxiliary = true;
  }
  const Orient o{*cps, d, out.auxiliary ? pred::StaticFilter::for_points(cps->coords.data(), cps->size(), d)
                                        : plain.filter};
  out.point = c;
  // (b) through for_range, the first facet not strictly beyond c reported
  if (const std::size_t bad =
          detail::smallest_failing(facets.size(), for_range, [&](std::size_t k) { return o.facet_and(facets[k], c) >= 0; });
      bad < facets.size()) {
    out.kind = out.auxiliary ? SurfaceCheck::Kind::no_centre : SurfaceCheck::Kind::outside;
    out.facet = bad;
    return out;
  }
  // (c) the vertical ray up from c, the crossings counted per piece
  auto crosses = [&](std::size_t k) {
    // a facet whose projection's bounding box (first d-1 coordinates)
    // misses c's projection by a positive gap is not crossed, under any
    // infinitesimal perturbation: only comparisons of input doubles, no
    // rounding
    bool apart = false;
    for (int i = 0; i + 1 < d && !apart; ++i) {
      const double x = cps->point(c)[i];
      bool below = true, above = true;
      for (int j = 0; j < d; ++j) {
        const double y = cps->point(facets[k][static_cast<std::size_t>(j)])[i];
        below &= x < y;
        above &= x > y;
      }
      apart = below || above;
    }
    if (apart) return false;
    Index t[kMaxD + 1];
    for (int j = 0; j < d; ++j) t[j] = facets[k][static_cast<std::size_t>(j)];
    const int s = o(t, d);
    bool inside = true;
    for (int j = 0; j < d && inside; ++j) {
      const Index keep = t[j];
      t[j] = c;
      inside = o(t, d) == s;
      t[j] = keep;
    }
    t[d] = c;
    return inside && o(t, d + 1) == s;
  };
  std::atomic<std::size_t> crossed{0};
  detail::for_pieces(facets.size(), for_range, [&](std::size_t lo, std::size_t hi) {
    std::size_t here = 0;
    for (std::size_t k = lo; k < hi; ++k) here += crosses(k) ? 1 : 0;
    crossed += here;
  });
  if (crossed != 1) {
    out.kind = SurfaceCheck::Kind::winds;
    out.count = crossed;
  }
  return out;
}

}  // namespace flipflop::certify

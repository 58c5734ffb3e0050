// strict_hull3.cpp — the strict view of a 3D hull (strict_hull3.hpp explains
// the three steps and why they find exactly the facets of the exact hull).
#include "reference/hull3/strict_hull3.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "predicates/exact.hpp"
#include "predicates/predicates.hpp"
#include "reference/locations.hpp"

namespace flipflop::ref {

namespace {

struct UnionFind {
  std::vector<std::uint32_t> up;
  explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) up[std::max(a, b)] = std::min(a, b);
  }
};


// The plane of a non-degenerate triangle as an exact key: normal
// n = (b - a) x (c - a) and offset n·a, dyadic rationals scaled to integers
// and divided by their gcd. Triangles of one facet, all counter-clockwise
// seen from outside, get the same key; different planes different keys.
using PlaneKey = std::array<mpz_class, 4>;

PlaneKey plane_key(const double* a, const double* b, const double* c) {
  namespace ex = pred::exact;
  ex::Dyadic A[3], U[3], W[3];
  for (int i = 0; i < 3; ++i) {
    A[i] = ex::to_dyadic(a[i]);
    U[i] = ex::sub(ex::to_dyadic(b[i]), A[i]);
    W[i] = ex::sub(ex::to_dyadic(c[i]), A[i]);
  }
  ex::Dyadic v[4];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    v[i] = ex::sub(ex::mul(U[j], W[k]), ex::mul(U[k], W[j]));
  }
  v[3] = ex::add(ex::add(ex::mul(v[0], A[0]), ex::mul(v[1], A[1])), ex::mul(v[2], A[2]));
  long emin = 0;
  bool first = true;
  for (const auto& d : v)
    if (ex::sign(d) != 0 && (first || d.e < emin)) emin = d.e, first = false;
  PlaneKey key;
  mpz_class g = 0;
  for (int i = 0; i < 4; ++i) {
    key[i] = v[i].m;
    if (ex::sign(v[i]) != 0) mpz_mul_2exp(key[i].get_mpz_t(), key[i].get_mpz_t(), static_cast<unsigned long>(v[i].e - emin));
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), key[i].get_mpz_t());
  }
  for (auto& x : key) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return key;
}

bool key_less(const PlaneKey& x, const PlaneKey& y) {
  for (int i = 0; i < 4; ++i) {
    const int c = cmp(x[i], y[i]);
    if (c != 0) return c < 0;
  }
  return false;
}

std::uint64_t edge_key(Index a, Index b) { return (std::uint64_t{a} << 32) | b; }

}  // namespace

StrictHull3 strict_hull3(const PointSet& ps, const std::vector<Triangle>& hull) {
  if (ps.dim != 3) throw std::invalid_argument("strict_hull3: expected 3D points, got " + std::to_string(ps.dim) + "D");
  const std::size_t n = ps.size(), m = hull.size();
  if (m < 4) throw std::invalid_argument("strict_hull3: a closed hull has at least 4 triangles, got " + std::to_string(m));
  std::unordered_map<std::uint64_t, std::uint32_t> at;  // directed edge -> triangle
  at.reserve(3 * m);
  for (std::uint32_t t = 0; t < m; ++t)
    for (int e = 0; e < 3; ++e) {
      const Index a = hull[t][e], b = hull[t][(e + 1) % 3];
      if (a >= n || b >= n) throw std::invalid_argument("strict_hull3: triangle index out of range");
      if (a == b) throw std::invalid_argument("strict_hull3: a triangle repeats a vertex");
      if (!at.emplace(edge_key(a, b), t).second)
        throw std::invalid_argument("strict_hull3: edge " + std::to_string(a) + "-" + std::to_string(b) +
                                    " is used twice in one direction (not an oriented surface)");
    }
  std::vector<std::array<std::uint32_t, 3>> nbr(m);
  for (std::uint32_t t = 0; t < m; ++t)
    for (int e = 0; e < 3; ++e) {
      auto it = at.find(edge_key(hull[t][(e + 1) % 3], hull[t][e]));
      if (it == at.end()) throw std::invalid_argument("strict_hull3: the triangles do not form a closed surface");
      nbr[t][e] = it->second;
    }

  // Every vertex to the smallest index at its location.
  const SmallestAtLocation smallest(ps);
  std::vector<Index> rep(n);
  for (const Triangle& T : hull)
    for (Index v : T) rep[v] = smallest(v);
  auto P = [&](Index v) { return ps.point(rep[v]); };

  std::vector<std::uint8_t> degenerate(m);
  for (std::uint32_t t = 0; t < m; ++t) degenerate[t] = pred::collinear3_exact(P(hull[t][0]), P(hull[t][1]), P(hull[t][2]));

  // Step 1: union across edges of exactly coplanar non-degenerate triangles.
  UnionFind uf(m);
  std::vector<std::uint8_t> suspect(m, 0);
  for (std::uint32_t t = 0; t < m; ++t) {
    if (degenerate[t]) continue;
    const Triangle& T = hull[t];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = nbr[t][e];
      if (degenerate[u]) {
        suspect[t] = 1;
        continue;
      }
      if (u < t) continue;
      const Triangle& U = hull[u];
      for (Index d : U)
        if (d != T[e] && d != T[(e + 1) % 3]) {
          if (pred::orient3d_exact(P(T[0]), P(T[1]), P(T[2]), P(d)) == 0) uf.unite(t, u);
          break;
        }
    }
  }
  // Step 2: classes touching a degenerate triangle, merged by plane key.
  {
    std::vector<std::uint32_t> roots;
    for (std::uint32_t t = 0; t < m; ++t)
      if (suspect[t]) roots.push_back(uf.find(t));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    std::vector<std::pair<PlaneKey, std::uint32_t>> keyed;
    keyed.reserve(roots.size());
    for (std::uint32_t r : roots) keyed.push_back({plane_key(P(hull[r][0]), P(hull[r][1]), P(hull[r][2])), r});
    std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return key_less(x.first, y.first); });
    for (std::size_t i = 1; i < keyed.size(); ++i)
      if (!key_less(keyed[i - 1].first, keyed[i].first)) uf.unite(keyed[i - 1].second, keyed[i].second);
  }

  // The facets: locations of each class.
  std::vector<std::int64_t> facet_of(m, -1);
  std::vector<std::uint32_t> facet_tri;  // a representative triangle per facet
  std::vector<std::vector<Index>> locs;
  for (std::uint32_t t = 0; t < m; ++t) {
    if (degenerate[t]) continue;
    const std::uint32_t r = uf.find(t);
    if (facet_of[r] < 0) {
      facet_of[r] = static_cast<std::int64_t>(locs.size());
      facet_tri.push_back(r);
      locs.emplace_back();
    }
    auto& L = locs[static_cast<std::size_t>(facet_of[r])];
    for (Index v : hull[t]) L.push_back(rep[v]);
  }
  // Step 3: strictly extreme = in at least three facets.
  std::vector<std::uint32_t> count(n, 0);
  for (auto& L : locs) {
    std::sort(L.begin(), L.end());
    L.erase(std::unique(L.begin(), L.end()), L.end());
    for (Index v : L) ++count[v];
  }
  StrictHull3 out;
  for (Index v = 0; v < n; ++v)
    if (count[v] >= 3) out.extreme_points.push_back(v);
  if (out.extreme_points.size() < 4) throw std::invalid_argument("strict_hull3: the triangles do not bound a 3D hull");

  for (std::size_t f = 0; f < locs.size(); ++f) {
    std::vector<Index> poly;
    for (Index v : locs[f])
      if (count[v] >= 3) poly.push_back(v);  // sorted: poly[0] is the smallest
    if (poly.size() < 3) throw std::invalid_argument("strict_hull3: a facet has fewer than 3 extreme vertices");
    const Triangle& T = hull[facet_tri[f]];
    const double *a = P(T[0]), *b = P(T[1]), *c = P(T[2]);
    Index q = n;  // an extreme point off the facet's plane (on its inner side)
    for (Index v : out.extreme_points)
      if (pred::orient3d_exact(a, b, c, ps.point(v)) != 0) {
        q = v;
        break;
      }
    if (q == n) throw std::invalid_argument("strict_hull3: the hull is flat");
    // Counter-clockwise from poly[0] seen from outside: x before y iff
    // (poly[0], x, y) is counter-clockwise, i.e. q on its inner side. A total
    // order: the other vertices of a convex polygon lie within an angle < π
    // at poly[0], no two collinear with it.
    const double* p0 = ps.point(poly[0]);
    const double* qx = ps.point(q);
    std::sort(poly.begin() + 1, poly.end(), [&](Index x, Index y) {
      return pred::orient3d_exact(p0, ps.point(x), ps.point(y), qx) > 0;
    });
    out.facets.push_back(std::move(poly));
  }
  std::sort(out.facets.begin(), out.facets.end());
  return out;
}

StrictHull3 fan_triangulated(const StrictHull3& h) {
  StrictHull3 t;
  t.extreme_points = h.extreme_points;
  for (const auto& f : h.facets)
    for (std::size_t j = 1; j + 1 < f.size(); ++j) t.facets.push_back({f[0], f[j], f[j + 1]});
  std::sort(t.facets.begin(), t.facets.end());
  return t;
}

std::string format_strict_hull3(const StrictHull3& h) {
  std::string s = std::to_string(h.extreme_points.size()) + " " + std::to_string(h.facets.size()) + "\n";
  for (Index v : h.extreme_points) s += std::to_string(v) + "\n";
  for (const auto& f : h.facets) {
    for (std::size_t i = 0; i < f.size(); ++i) s += (i ? " " : "") + std::to_string(f[i]);
    s += "\n";
  }
  return s;
}

}  // namespace flipflop::ref

// initial_stars.cpp — stars from the hull of a recursive sample, and the
// pipeline hull3_splay (thesis ch. 7, gHull Stages 2-5, exact and
// sequential; initial_stars.hpp describes the steps).
#include "reference/hull3/initial_stars.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "predicates/predicates.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"

namespace flipflop::ref {

namespace {

constexpr std::size_t kTetrahedronSample = 32;  // at most this many points: S is a tetrahedron
constexpr std::size_t kSampleRatio = 8;         // |S| = |idx| / 8

int orient(const PointSet& ps, Index a, Index b, Index c, Index d) {
  return pred::orient3d({a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)}, {d, ps.point(d)});
}

Index least_of(const PointSet& ps, const std::vector<Index>& idx) {
  Index least = idx.front();
  for (Index v : idx)
    if (lex_precedes(ps, v, least)) least = v;
  return least;
}

// Position of x in [lo, hi] as a 21-bit cell (a heuristic for the visiting
// order only; halves avoid overflow of hi - lo).
std::uint64_t cell(double x, double lo, double hi) {
  const double t = (x * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5);
  if (!(t > 0)) return 0;
  if (!(t < 1)) return (1u << 21) - 1;
  return static_cast<std::uint64_t>(t * double(1u << 21));
}

std::uint64_t morton(const std::uint64_t c[3]) {
  std::uint64_t code = 0;
  for (int b = 20; b >= 0; --b)
    for (int a = 0; a < 3; ++a) code = (code << 1) | ((c[a] >> b) & 1u);
  return code;
}

// The visiting order of `pts`: by Morton code of their coordinates.
void spatial_sort(const PointSet& ps, std::vector<Index>& pts) {
  if (pts.size() < 2) return;
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = ps.point(pts[0])[a];
  for (Index v : pts)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], ps.point(v)[a]), hi[a] = std::max(hi[a], ps.point(v)[a]);
  std::vector<std::pair<std::uint64_t, Index>> keyed;
  keyed.reserve(pts.size());
  for (Index v : pts) {
    std::uint64_t c[3];
    for (int a = 0; a < 3; ++a) c[a] = cell(ps.point(v)[a], lo[a], hi[a]);
    keyed.push_back({morton(c), v});
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = keyed[i].second;
}

// The hull H of the sample, with adjacency: nbr[t][e] is the triangle across
// edge (T[e], T[e+1]) of triangle t.
struct Polytope {
  std::vector<Triangle> tri;
  std::vector<std::array<std::uint32_t, 3>> nbr;

  explicit Polytope(std::vector<Triangle> tris) : tri(std::move(tris)), nbr(tri.size()) {
    std::unordered_map<std::uint64_t, std::uint32_t> at;  // directed edge -> triangle
    at.reserve(3 * tri.size());
    auto key = [](Index a, Index b) { return (std::uint64_t{a} << 32) | b; };
    for (std::uint32_t t = 0; t < tri.size(); ++t)
      for (int e = 0; e < 3; ++e) at.emplace(key(tri[t][e], tri[t][(e + 1) % 3]), t);
    for (std::uint32_t t = 0; t < tri.size(); ++t)
      for (int e = 0; e < 3; ++e) {
        auto it = at.find(key(tri[t][(e + 1) % 3], tri[t][e]));
        if (it == at.end()) throw std::logic_error("stars_from_hull: the hull is not a closed surface");
        nbr[t][e] = it->second;
      }
  }
  bool has(std::uint32_t t, Index v) const { return tri[t][0] == v || tri[t][1] == v || tri[t][2] == v; }
  int corner(std::uint32_t t, Index v) const { return tri[t][0] == v ? 0 : tri[t][1] == v ? 1 : 2; }
};

// Where a point is relative to H: outside with a triangle of H it is beyond,
// or strictly inside the tetrahedron (r, triangle).
struct Location {
  bool outside;
  std::uint32_t t;
};

class Locator {
 public:
  Locator(const PointSet& ps, const Polytope& H, Index r) : ps_(ps), H_(H), r_(r) {
    for (std::uint32_t t = 0; t < H.tri.size(); ++t) (H.has(t, r) ? at_r_ : far_).push_back(t);
    start_ = far_.front();
  }

  Location locate(Index p) {
    // p beyond a triangle of r's star: outside (p - r leaves r's cone).
    for (std::uint32_t t : at_r_)
      if (beyond(t, p)) return {true, t};
    // p - r is inside r's cone: walk over the far triangles to the one whose
    // cone from r holds p. A triangle (a, b, c) holds it iff
    // orient3d(r, x, y, p) < 0 for its three edges (x, y); otherwise cross an
    // edge with orient3d(r, x, y, p) > 0. Crossing into a triangle incident
    // to r is impossible here (the cross-section is convex and holds p).
    std::uint32_t t = start_;
    const std::size_t bound = 2 * H_.tri.size() + 64;
    int from = -1;
    for (std::size_t steps = 0;; ++steps) {
      if (steps > bound) {
        t = scan(p);
        break;
      }
      const Triangle& T = H_.tri[t];
      const int off = static_cast<int>(next_random() % 3);
      int cross = -1;
      for (int q = 0; q < 3 && cross < 0; ++q) {
        const int e = (off + q) % 3;
        if (e != from && orient(ps_, r_, T[e], T[(e + 1) % 3], p) > 0) cross = e;
      }
      if (cross < 0) break;
      const std::uint32_t u = H_.nbr[t][cross];
      if (H_.has(u, r_)) throw std::logic_error("stars_from_hull: the walk left the cone of r");
      const Triangle& U = H_.tri[u];
      from = -1;  // the edge we came through is not crossed back (its sign is < 0 from u)
      for (int e = 0; e < 3; ++e)
        if (U[e] == T[(cross + 1) % 3] && U[(e + 1) % 3] == T[cross]) from = e;
      t = u;
    }
    start_ = t;
    return {beyond(t, p), t};
  }

 private:
  bool beyond(std::uint32_t t, Index p) const {
    const Triangle& T = H_.tri[t];
    return orient(ps_, T[0], T[1], T[2], p) < 0;
  }
  std::uint32_t scan(Index p) const {
    for (std::uint32_t t : far_) {
      const Triangle& T = H_.tri[t];
      if (orient(ps_, r_, T[0], T[1], p) < 0 && orient(ps_, r_, T[1], T[2], p) < 0 &&
          orient(ps_, r_, T[2], T[0], p) < 0)
        return t;
    }
    throw std::logic_error("stars_from_hull: no triangle's cone holds a point inside r's cone");
  }
  std::uint64_t next_random() {
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 7;
    rng_ ^= rng_ << 17;
    return rng_;
  }

  const PointSet& ps_;
  const Polytope& H_;
  Index r_;
  std::vector<std::uint32_t> at_r_, far_;
  std::uint32_t start_ = 0;
  std::uint64_t rng_ = 0x9e3779b97f4a7c15ULL;
};

// The SoS hull of the points idx (|idx| >= 4), by the pipeline.
std::vector<Triangle> hull_of(const PointSet& ps, const std::vector<Index>& idx, Hull3Stats* stats,
                              splay::State* last);

std::vector<Star> stars_of(const PointSet& ps, const std::vector<Index>& idx, Hull3Stats* stats) {
  const Index least = least_of(ps, idx);
  std::vector<Index> sample = {least};
  for (Index v : idx)
    if (v != least) sample.push_back(v);
  if (idx.size() <= kTetrahedronSample) {
    // S = a tetrahedron (any four distinct points are affinely independent
    // under SoS), oriented so that its triangles face outwards.
    Index a = sample[0], b = sample[1], c = sample[2], d = sample[3];
    if (orient(ps, a, b, c, d) < 0) std::swap(b, c);
    return splay::stars_from_hull(ps, idx, {{a, b, c}, {a, d, b}, {a, c, d}, {b, d, c}});
  }
  // S = least + a pseudo-random eighth of the others (partial Fisher-Yates).
  const std::size_t m = std::max<std::size_t>(4, idx.size() / kSampleRatio);
  std::mt19937_64 rng(0x5eed5eedULL ^ idx.size());
  for (std::size_t i = 1; i < m; ++i) std::swap(sample[i], sample[i + rng() % (sample.size() - i)]);
  sample.resize(m);
  return splay::stars_from_hull(ps, idx, hull_of(ps, sample, stats, nullptr));
}

std::vector<Triangle> hull_of(const PointSet& ps, const std::vector<Index>& idx, Hull3Stats* stats,
                              splay::State* last) {
  splay::State st = splay::make_state(ps, stars_of(ps, idx, stats), /*validate=*/FF_CHECKED);
  splay::run(st, stats);
  std::vector<Triangle> out = splay::triangles(st);
  if (last) *last = std::move(st);
  return out;
}

void require_3d(const PointSet& ps, const char* who) {
  if (ps.dim != 3) throw std::invalid_argument(std::string(who) + ": expected 3D points, got " + std::to_string(ps.dim) + "D");
  const std::string flat = dimension_problem(ps);
  if (!flat.empty()) throw std::invalid_argument(flat);
}

std::vector<Index> all_points(const PointSet& ps) {
  std::vector<Index> idx(ps.size());
  for (Index i = 0; i < idx.size(); ++i) idx[i] = i;
  return idx;
}

}  // namespace

namespace splay {

std::vector<Star> stars_from_hull(const PointSet& ps, const std::vector<Index>& idx, const std::vector<Triangle>& hull) {
  const Polytope H(hull);
  const std::size_t n = ps.size();
  std::vector<std::uint32_t> incident(n, UINT32_MAX);  // a triangle at each vertex of H
  for (std::uint32_t t = 0; t < H.tri.size(); ++t)
    for (Index v : H.tri[t]) incident[v] = t;

  std::vector<Star> out;
  out.reserve(idx.size());
  std::vector<Index> rest;
  for (Index v : idx) {
    if (incident[v] == UINT32_MAX) {
      rest.push_back(v);
      continue;
    }
    // v's star in H: around v, triangle t = (v, x, y) is followed by the one
    // across edge (y, v).
    Star s;
    s.apex = v;
    std::uint32_t t = incident[v];
    do {
      const int e = H.corner(t, v);
      s.link.push_back(H.tri[t][(e + 1) % 3]);
      t = H.nbr[t][(e + 2) % 3];
    } while (t != incident[v]);
    out.push_back(std::move(s));
  }

  const Index r = least_of(ps, idx);
  if (incident[r] == UINT32_MAX) throw std::logic_error("stars_from_hull: the least point is not a hull vertex");
  Locator locator(ps, H, r);
  spatial_sort(ps, rest);
  std::vector<std::uint32_t> seen(H.tri.size(), 0);  // stamp: visibility evaluated for this point
  std::vector<std::uint8_t> visible(H.tri.size(), 0);
  std::vector<Index> succ(n);  // horizon: succ[a] = b for horizon edge (a, b)
  std::vector<std::uint32_t> stack;
  std::uint32_t stamp = 0;
  for (Index p : rest) {
    const Location loc = locator.locate(p);
    Star s;
    s.apex = p;
    if (!loc.outside) {
      const Triangle& T = H.tri[loc.t];
      s.dead = true;
      s.certificate = {r, T[0], T[1], T[2]};
      FF_CHECK(is_death_certificate(ps, p, s.certificate), "stars_from_hull: invalid certificate");
      out.push_back(std::move(s));
      continue;
    }
    // The region of H visible from p (connected, a disk) and its horizon:
    // edges (a, b) of visible triangles whose neighbour is not visible; the
    // star of p in conv(H ∪ {p}) has the triangles (p, a, b).
    ++stamp;
    stack.assign(1, loc.t);
    seen[loc.t] = stamp;
    visible[loc.t] = 1;
    Index first = 0;
    bool any = false;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t u = H.nbr[t][e];
        if (seen[u] != stamp) {
          seen[u] = stamp;
          const Triangle& U = H.tri[u];
          visible[u] = orient(ps, U[0], U[1], U[2], p) < 0;
          if (visible[u]) stack.push_back(u);
        }
        if (!visible[u]) {
          succ[H.tri[t][e]] = H.tri[t][(e + 1) % 3];
          first = H.tri[t][e];
          any = true;
        }
      }
    }
    if (!any) throw std::logic_error("stars_from_hull: a point sees every triangle of the hull");
    Index a = first;
    do {
      s.link.push_back(a);
      a = succ[a];
      if (s.link.size() > hull.size()) throw std::logic_error("stars_from_hull: the horizon is not one cycle");
    } while (a != first);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace splay

std::vector<Triangle> hull3_splay(const PointSet& ps, Hull3Stats* stats) {
  require_3d(ps, "hull3_splay");
  if (stats) *stats = Hull3Stats{};
  splay::State last;
  std::vector<Triangle> out = hull_of(ps, all_points(ps), stats, &last);
  if (stats)
    stats->dead_stars = static_cast<std::uint64_t>(std::count(last.status.begin(), last.status.end(), splay::Status::dead));
  return out;
}

std::vector<Star> initial_stars(const PointSet& ps) {
  require_3d(ps, "initial_stars");
  return stars_of(ps, all_points(ps), nullptr);
}

}  // namespace flipflop::ref

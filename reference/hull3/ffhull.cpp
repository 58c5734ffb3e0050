// ffhull.cpp — ffHull, thesis §6.4 Algorithm 7 (sequential): construct a
// polyhedron star-shaped w.r.t. the exact centroid of an initial tetrahedron
// by furthest-point insertion (lines 1-14), then flip-flop (line 15,
// Algorithm 6). The rules fixed here are documented in ffhull.hpp.
#include "reference/hull3/ffhull.hpp"

#include <deque>
#include <random>
#include <stdexcept>
#include <string>

#include "predicates/err_double.hpp"
#include "predicates/exact.hpp"
#include "predicates/predicates.hpp"
#include "predicates/fast.hpp"
#include "reference/canonical.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/polyhedron3.hpp"

namespace flipflop::ref {

namespace {

namespace ex = pred::exact;
using pred::ErrDouble;

constexpr Index kNoPoint = ~Index{0};

// A linear functional f·p with rational coefficients, held exactly (dyadic)
// and as filtered doubles with an error bound.
struct Functional {
  ex::Dyadic f[3];
  ErrDouble fa[3];
};

ErrDouble approx_value(const ErrDouble* fa, const double* p) {
  return fa[0] * ErrDouble(p[0]) + fa[1] * ErrDouble(p[1]) + fa[2] * ErrDouble(p[2]);
}

// sign(f·p - f·q) when the filter (coefficients fa with their error bounds) is
// certain, else 0.
int filtered_compare(const ErrDouble* fa, const double* p, const double* q) {
  return pred::sign_if_certain(approx_value(fa, p) - approx_value(fa, q));
}

// sign(f·p - f·q) in exact arithmetic (GMP).
int exact_compare(const ex::Dyadic* f, const double* p, const double* q) {
  ex::Dyadic sum;
  for (int j = 0; j < 3; ++j) sum = ex::add(sum, ex::mul(f[j], ex::sub(ex::to_dyadic(p[j]), ex::to_dyadic(q[j]))));
  return ex::sign(sum);
}

// sign(f·p - f·q), exactly: the filter first, GMP when it cannot decide.
int compare(const Functional& f, const double* p, const double* q) {
  if (int s = filtered_compare(f.fa, p, q)) return s;
  return exact_compare(f.f, p, q);
}

// Exact ties of f·p are broken by the perturbation: for indices i < j the
// difference f·(δ_i - δ_j) has the sign of the first non-zero of
// (f_z, f_y, f_x) (the z term of the smaller index dominates, predicates.hpp).
// True when the smaller index wins.
bool smaller_index_wins(const Functional& f) {
  for (int j = 2; j >= 0; --j)
    if (int s = ex::sign(f.f[j])) return s > 0;
  throw std::logic_error("ffHull: a zero functional");
}

// The unique maximiser of f over the perturbed points: a vertex of the SoS hull.
Index argmax(const PointSet& ps, const Functional& f) {
  const bool small_wins = smaller_index_wins(f);
  Index best = 0;
  for (Index p = 1; p < ps.size(); ++p) {
    const int c = compare(f, ps.point(p), ps.point(best));
    if (c > 0 || (c == 0 && !small_wins)) best = p;  // p > best: the larger index wins a tie iff !small_wins
  }
  return best;
}

Functional axis(int j, int sign) {
  Functional f;
  for (int k = 0; k < 3; ++k) {
    f.f[k] = ex::to_dyadic(k == j ? sign : 0.0);
    f.fa[k] = ErrDouble(k == j ? sign : 0.0);
  }
  return f;
}

Functional negate(Functional f) {
  for (int k = 0; k < 3; ++k) {
    f.f[k].m = -f.f[k].m;
    f.fa[k] = -f.fa[k];
  }
  return f;
}

// u × v on filtered doubles
void cross_approx(const ErrDouble* ua, const ErrDouble* va, ErrDouble* out) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    out[k] = ua[i] * va[j] - ua[j] * va[i];
  }
}

// u × v of exact vectors given as dyadics (with their filtered doubles).
Functional cross(const ex::Dyadic* u, const ErrDouble* ua, const ex::Dyadic* v, const ErrDouble* va) {
  Functional f;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    f.f[k] = ex::sub(ex::mul(u[i], v[j]), ex::mul(u[j], v[i]));
  }
  cross_approx(ua, va, f.fa);
  return f;
}

void difference_approx(const PointSet& ps, Index b, Index a, ErrDouble* da) {
  for (int k = 0; k < 3; ++k) da[k] = ErrDouble(ps.point(b)[k]) - ErrDouble(ps.point(a)[k]);
}

void difference(const PointSet& ps, Index b, Index a, ex::Dyadic* d, ErrDouble* da) {
  for (int k = 0; k < 3; ++k) d[k] = ex::sub(ex::to_dyadic(ps.point(b)[k]), ex::to_dyadic(ps.point(a)[k]));
  difference_approx(ps, b, a, da);
}

// The outward normal (b - a) × (c - a) of a triangle counter-clockwise seen from
// outside: f·p - f·a > 0 exactly when p is beyond its plane, and f·p is the
// distance to the plane times |f| (line 8's "furthest").
Functional outward_normal(const PointSet& ps, const Triangle& t) {
  ex::Dyadic u[3], v[3];
  ErrDouble ua[3], va[3];
  difference(ps, t[1], t[0], u, ua);
  difference(ps, t[2], t[0], v, va);
  return cross(u, ua, v, va);
}

// The same normal for line 8's comparisons, with its exact (GMP) coefficients
// made only when the filter cannot decide a comparison: the filter decides
// nearly all of them, and making the dyadic normal of every new triangle
// eagerly was about a tenth of the reference's time on thin spherical shells
// (perf, 2026-11-27). The comparisons' results are the same.
struct LazyNormal {
  Triangle t{};
  ErrDouble fa[3];
};

LazyNormal lazy_outward_normal(const PointSet& ps, const Triangle& t) {
  LazyNormal n;
  n.t = t;
  ErrDouble ua[3], va[3];
  difference_approx(ps, t[1], t[0], ua);
  difference_approx(ps, t[2], t[0], va);
  cross_approx(ua, va, n.fa);
  return n;
}

// sign(N·p - N·q) for the outward normal N of n.t, exactly.
int compare(const PointSet& ps, const LazyNormal& n, const double* p, const double* q) {
  if (int s = filtered_compare(n.fa, p, q)) return s;
  return exact_compare(outward_normal(ps, n.t).f, p, q);
}

// orient3d under SoS, the per-input static filter (thesis §6.4.2) first.
int orient(const PointSet& ps, const pred::StaticFilter& f, Index a, Index b, Index c, Index p) {
  return pred::fast::orient3d(f, {a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)}, {p, ps.point(p)});
}

// The constructing stage's per-triangle data: the points associated to each
// triangle slot (line 5 / 13), its furthest point (line 8) and its normal.
struct Cones {
  std::vector<std::vector<Index>> pts;
  std::vector<Index> far;
  std::vector<LazyNormal> normal;
  void grow(std::size_t slots) {
    if (pts.size() < slots) {
      pts.resize(slots);
      far.resize(slots, kNoPoint);
      normal.resize(slots);
    }
  }
};

poly::Polyhedron3 construct_polyhedron(const PointSet& ps, const KernelPoint& s, const std::array<Index, 4>& tet,
                                       const ffhull::BuildOptions& opt, Hull3Stats* stats) {
  const std::size_t n = ps.size();
  const auto [a, b, c, d] = tet;
  // line 3: P = CH({a, b, c, d}), (a, b, c) counter-clockwise from outside
  poly::Polyhedron3 P = poly::build(n, {{a, b, c}, {a, c, d}, {a, d, b}, {b, d, c}});
  // s strictly inside the tetrahedron (a, b, c) + d, (a, b, c) counter-clockwise
  // seen from outside: 16 predicates, checked always (construct() is public)
  if (std::string why = poly::star_problem(P, s); !why.empty())
    throw std::invalid_argument("ffHull: the kernel point is not inside the initial tetrahedron: " + why);
  Cones K;
  K.grow(P.tri.size());
  const pred::StaticFilter filter = pred::StaticFilter::for_points(ps.coords.data(), n, 3);
  std::mt19937_64 rng(opt.seed);
  auto start_triangle = [&](std::uint32_t t) {
    K.pts[t].clear();
    K.far[t] = kNoPoint;
    if (opt.furthest) K.normal[t] = lazy_outward_normal(ps, P.tri[t]);
  };
  // Associates p with triangle t (p ∈ C_s(t)); lines 13-14: discards p when it
  // lies on the same side of t as s (inside the tetrahedron s + t).
  auto associate = [&](std::uint32_t t, Index p) {
    const Triangle& T = P.tri[t];
    FF_CHECK(poly::in_cone(s, T[0], T[1], T[2], p), "ffHull: a point associated with a triangle outside its cone");
    if (opt.discard_inside && orient(ps, filter, T[0], T[1], T[2], p) > 0) {
      if (stats) ++stats->discarded_early;
      return;
    }
    K.pts[t].push_back(p);
    if (!opt.furthest) return;
    const Index f = K.far[t];
    if (f == kNoPoint) {
      K.far[t] = p;
      return;
    }
    const int cmp = compare(ps, K.normal[t], ps.point(p), ps.point(f));
    if (cmp > 0 || (cmp == 0 && p < f)) K.far[t] = p;  // line 8; exact ties: the smaller index
  };
  for (std::uint32_t t = 0; t < 4; ++t) start_triangle(t);
  // line 5: each remaining point to the triangle of the tetrahedron whose cone
  // contains it (the cones of a star-shaped polyhedron cover R^3, §6.1)
  for (Index p = 0; p < n; ++p) {
    if (p == a || p == b || p == c || p == d) continue;  // line 2
    std::uint32_t t = 0;
    while (t < 3 && !poly::in_cone(s, P.tri[t][0], P.tri[t][1], P.tri[t][2], p)) ++t;
    associate(t, p);
  }
  std::deque<std::uint32_t> work;
  for (std::uint32_t t = 0; t < 4; ++t)
    if (!K.pts[t].empty()) work.push_back(t);
  while (!work.empty()) {  // line 6: while S ≠ ∅ (rounds of line 7 in FIFO order)
    const std::uint32_t t = work.front();
    work.pop_front();
    std::vector<Index> S = std::move(K.pts[t]);
    if (S.empty()) continue;
    // line 8: the furthest point (or a random one when building other
    // star-shaped polyhedra for tests)
    const Index v = opt.furthest ? K.far[t] : S[std::uniform_int_distribution<std::size_t>(0, S.size() - 1)(rng)];
    const Index ta = P.tri[t][0], tb = P.tri[t][1], tc = P.tri[t][2];
    const std::array<std::uint32_t, 3> nt = poly::split13(P, t, v);  // line 9: (a,b,v), (b,c,v), (c,a,v)
    if (stats) ++stats->insertions, ++stats->flips_1_3;
    K.grow(P.tri.size());
    for (std::uint32_t u : nt) start_triangle(u);
    for (Index p : S) {  // lines 11-14
      if (p == v) continue;  // line 10
      // line 13: the cone of abc is split by the planes (s, v, a), (s, v, b),
      // (s, v, c); p ∈ C_s(abv) iff side(v,a,p) > 0 and side(v,b,p) < 0,
      // ∈ C_s(bcv) iff side(v,b,p) > 0 and side(v,c,p) < 0, ∈ C_s(cav) iff
      // side(v,c,p) > 0 and side(v,a,p) < 0 (side(x,y,p) = orient3d(x,y,p,s)).
      std::uint32_t u;
      if (s.side(v, ta, p) > 0)
        u = s.side(v, tb, p) < 0 ? nt[0] : nt[1];
      else
        u = s.side(v, tc, p) > 0 ? nt[2] : nt[1];
      associate(u, p);
    }
    for (std::uint32_t u : nt)
      if (!K.pts[u].empty()) work.push_back(u);
  }
  if constexpr (FF_CHECKED) {
    FF_CHECK(poly::structure_problem(P).empty(), "ffHull: inconsistent polyhedron after construction");
    FF_CHECK(poly::star_problem(P, s).empty(), "ffHull: constructed polyhedron is not star-shaped");
  }
  return P;
}

void check_input(const PointSet& ps) {
  if (ps.dim != 3) throw std::invalid_argument("ffHull needs 3D points, got dimension " + std::to_string(ps.dim));
  if (std::string why = dimension_problem(ps); !why.empty()) throw std::invalid_argument(why);
}

}  // namespace

namespace ffhull {

std::array<Index, 4> initial_tetrahedron(const PointSet& ps) {
  check_input(ps);
  const Index a = argmax(ps, axis(0, -1)), b = argmax(ps, axis(0, +1));
  // x(a) < x(b) exactly: a 3D input does not lie in a plane x = const
  ex::Dyadic u[3];
  ErrDouble ua[3];
  difference(ps, b, a, u, ua);
  Index c = kNoPoint;
  for (int j = 0; j < 3 && c == kNoPoint; ++j) {
    // (b - a) × e_j, perpendicular to the line ab, so constant on it
    ex::Dyadic e[3];
    ErrDouble ea[3];
    for (int k = 0; k < 3; ++k) e[k] = ex::to_dyadic(k == j ? 1.0 : 0.0), ea[k] = ErrDouble(k == j ? 1.0 : 0.0);
    const Functional f = cross(u, ua, e, ea);
    bool zero = true;
    for (int k = 0; k < 3; ++k) zero &= ex::sign(f.f[k]) == 0;
    if (zero) continue;  // b - a parallel to e_j
    for (const Functional& g : {f, negate(f)}) {
      const Index m = argmax(ps, g);
      if (compare(g, ps.point(m), ps.point(a)) > 0) {
        c = m;
        break;
      }
    }
  }
  if (c == kNoPoint) throw std::logic_error("ffHull: no point off the line of the x-extreme points of a 3D input");
  ex::Dyadic w[3];
  ErrDouble wa[3];
  difference(ps, c, a, w, wa);
  const Functional N = cross(u, ua, w, wa);
  Index d = kNoPoint;
  for (const Functional& g : {N, negate(N)}) {
    const Index m = argmax(ps, g);
    if (compare(g, ps.point(m), ps.point(a)) > 0) {
      d = m;
      break;
    }
  }
  if (d == kNoPoint) throw std::logic_error("ffHull: no point off the plane of three points of a 3D input");
  // (a, b, c) counter-clockwise seen from outside: d on its inner side
  if (pred::orient3d_exact(ps.point(a), ps.point(b), ps.point(c), ps.point(d)) < 0) return {a, c, b, d};
  return {a, b, c, d};
}

std::vector<Triangle> construct(const PointSet& ps, const KernelPoint& s, const std::array<Index, 4>& tet,
                                const BuildOptions& opt, Hull3Stats* stats) {
  check_input(ps);
  return poly::triangles(construct_polyhedron(ps, s, tet, opt, stats));
}

}  // namespace ffhull

std::vector<Triangle> hull3_ffhull(const PointSet& ps, Hull3Stats* stats) {
  if (stats) *stats = Hull3Stats{};
  const std::array<Index, 4> tet = ffhull::initial_tetrahedron(ps);  // line 1 (validates the input)
  const RationalKernel s = centroid_kernel(ps, tet[0], tet[1], tet[2], tet[3]);  // line 4
  poly::Polyhedron3 P = construct_polyhedron(ps, s, tet, ffhull::BuildOptions{}, stats);  // lines 2-14
  ff3::State st = ff3::make_state(ps, s, std::move(P));
  ff3::run(st, stats);  // line 15: flip-flop (Algorithm 6)
  return canonical_triangles(poly::triangles(st.P));
}

}  // namespace flipflop::ref

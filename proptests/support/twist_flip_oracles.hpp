// twist_flip_oracles.hpp — independent oracles for twist-flip (thesis §8.4.1):
// CGAL's exact kernel (Epeck: exact rationals) instead of flipflop's
// predicates. They decide the real configuration, without the Simulation of
// Simplicity, so they are used on inputs in general position — which each
// oracle checks itself (`general` comes back false on an exact tie, and the
// property then discards the case) — and on those they must agree with
// flipflop exactly.
//
//   shewchuk_orient     orient3d with flipflop's sign convention (> 0: d on the
//                       inner side of (a, b, c) counter-clockwise from outside);
//   secondary_point     the secondary kernel s in exact rationals;
//   positive_all        Theorem 8.9's end state: triangles without v have v on
//                       their inner side, triangles (v, p, q) have s there;
//   ray_crossings       Theorem 8.2 (2): triangles without v crossed by the
//                       ray from v through s (the ray from κ = v + η(s - v));
//   projected_link      the link of v projected from v onto the horizontal
//                       plane H through s (§8.4.1, Figure 8.8), exactly;
//   link_star_shaped    Lemma 8.3: that polygon is simple, and every edge turns
//                       counter-clockwise around s (CGAL Polygon_2);
//   angular_inversions  Theorem 8.1: the number of pairs of the link sequence
//                       (from its first slot) out of the angular order around
//                       s in H — the number of twists of a bubble sort.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <array>
#include <cstddef>
#include <vector>

#include "predicates/exact.hpp"
#include "predicates/rational_point.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test::tf {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using P3 = K::Point_3;
using P2 = K::Point_2;

inline P3 point3(const PointSet& ps, Index i) { return P3(ps.point(i)[0], ps.point(i)[1], ps.point(i)[2]); }

// flipflop's orient3d sign (predicates.hpp): CGAL::orientation(a, b, c, d) is
// the sign of det[b - a, c - a, d - a], Shewchuk's orient3d that of
// det[a - d, b - d, c - d] = -det[b - a, c - a, d - a]. (Checked against
// pred::orient3d_exact by a test.)
inline int shewchuk_orient(const P3& a, const P3& b, const P3& c, const P3& d) {
  return -static_cast<int>(CGAL::orientation(a, b, c, d));
}

// An exact dyadic m 2^e (predicates/exact.hpp) as a CGAL number.
inline FT to_ft(const pred::exact::Dyadic& d) {
  mpz_class m = abs(d.m);
  std::vector<long> chunks;  // base 2^30, least significant first
  while (m != 0) {
    const mpz_class low = m % (1L << 30);
    chunks.push_back(low.get_si());
    m /= (1L << 30);
  }
  FT r = 0;
  for (std::size_t i = chunks.size(); i-- > 0;) r = r * FT(1L << 30) + FT(chunks[i]);
  if (d.m < 0) r = -r;
  FT scale = 1;
  const FT step = d.e >= 0 ? FT(2) : FT(0.5);
  for (long i = 0; i < (d.e >= 0 ? d.e : -d.e); ++i) scale = scale * step;
  return r * scale;
}

// The secondary kernel of TwistFlipKernel, exactly.
inline P3 secondary_point(const pred::RationalPoint& s) {
  return P3(to_ft(s.exact[0]), to_ft(s.exact[1]), to_ft(s.exact[2]));
}

// Every triangle positive (v on the inner side, or s for those through v).
// `general` false: some orientation is exactly 0 (then nothing is claimed).
inline bool positive_all(const PointSet& ps, const std::vector<Triangle>& tris, Index v, const P3& s,
                         bool& general) {
  general = true;
  bool ok = true;
  const P3 pv = point3(ps, v);
  for (const Triangle& t : tris) {
    const bool through_v = t[0] == v || t[1] == v || t[2] == v;
    const int o = shewchuk_orient(point3(ps, t[0]), point3(ps, t[1]), point3(ps, t[2]), through_v ? s : pv);
    if (o == 0) general = false;
    if (o <= 0) ok = false;
  }
  return ok;
}

// Triangles not through v crossed by the open ray from v through s; `general`
// false when the ray meets a triangle's boundary or plane degenerately.
inline std::size_t ray_crossings(const PointSet& ps, const std::vector<Triangle>& tris, Index v, const P3& s,
                                 bool& general) {
  general = true;
  const P3 pv = point3(ps, v);
  std::size_t hits = 0;
  for (const Triangle& t : tris) {
    if (t[0] == v || t[1] == v || t[2] == v) continue;
    const P3 a = point3(ps, t[0]), b = point3(ps, t[1]), c = point3(ps, t[2]);
    // the line v + λ(s - v) passes through the open triangle iff v, s see its
    // three edges with one sign; then the hit is at λ > 0 iff v and the far
    // point v + M(s - v) (M large) are on opposite sides of the plane, i.e.
    // orient(a, b, c, v) != orient(a, b, c, v + (s - v) * M) for M -> ∞: the
    // sign of orient(a, b, c, ·) along the direction s - v.
    const int e1 = CGAL::orientation(pv, s, a, b), e2 = CGAL::orientation(pv, s, b, c),
              e3 = CGAL::orientation(pv, s, c, a);
    if (e1 == 0 || e2 == 0 || e3 == 0) {
      general = false;
      continue;
    }
    if (!(e1 == e2 && e2 == e3)) continue;
    const int at_v = CGAL::orientation(a, b, c, pv);
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
    const int along = CGAL::sign(n * (s - pv));  // d/dλ of det[b-a, c-a, x-a]
    if (at_v == 0 || along == 0) {
      general = false;
      continue;
    }
    if (at_v != along) ++hits;  // the plane is crossed at some λ > 0
  }
  return hits;
}

// The link order projected from v onto H: p* = v + (v.z - s.z)/(v.z - p.z) (p - v).
// `general` false when some p is not strictly below v, or s not (exactly).
inline std::vector<P2> projected_link(const PointSet& ps, const std::vector<Index>& link, Index v, const P3& s,
                                      bool& general) {
  general = true;
  const P3 pv = point3(ps, v);
  std::vector<P2> out;
  if (!(s.z() < pv.z())) general = false;
  for (Index p : link) {
    const P3 q = point3(ps, p);
    if (!(q.z() < pv.z())) {
      general = false;
      out.push_back(P2(0, 0));
      continue;
    }
    const FT lambda = (pv.z() - s.z()) / (pv.z() - q.z());
    out.push_back(P2(pv.x() + lambda * (q.x() - pv.x()), pv.y() + lambda * (q.y() - pv.y())));
  }
  return out;
}

// Lemma 8.3 on the projection: a simple polygon, every edge a left turn
// around s (then it winds once around s, counter-clockwise: star-shaped).
inline bool link_star_shaped(const std::vector<P2>& poly, const P3& s) {
  const P2 s2(s.x(), s.y());
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (CGAL::orientation(s2, poly[i], poly[(i + 1) % poly.size()]) != CGAL::LEFT_TURN) return false;
  CGAL::Polygon_2<K> P(poly.begin(), poly.end());
  return P.is_simple() && P.is_counterclockwise_oriented();
}

// g(p) < g(q) around s in H (§8.3): upper half-plane first, then left turn.
// `general` false on a tie (a point on the horizontal line through s, or two
// on one ray from s).
inline std::size_t angular_inversions(const std::vector<P2>& poly, const P3& s, bool& general) {
  general = true;
  const P2 s2(s.x(), s.y());
  auto less = [&](const P2& p, const P2& q) {
    const int hp = CGAL::compare(p.y(), s2.y()), hq = CGAL::compare(q.y(), s2.y());
    if (hp == 0 || hq == 0) general = false;
    if (hp != hq) return hp > 0;
    const auto o = CGAL::orientation(s2, p, q);
    if (o == CGAL::COLLINEAR) general = false;
    return o == CGAL::LEFT_TURN;
  };
  std::size_t inv = 0;
  for (std::size_t i = 0; i < poly.size(); ++i)
    for (std::size_t j = i + 1; j < poly.size(); ++j)
      if (less(poly[j], poly[i])) ++inv;
  return inv;
}

}  // namespace flipflop::test::tf

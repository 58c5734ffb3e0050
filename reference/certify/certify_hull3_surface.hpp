// certify_hull3_surface.hpp — the per-facet and per-edge half of certify::hull3
// (certify_hull3.cpp), shared with the witness-checked certifier of the
// multithreaded kernel (kernels_cpu/hull3/certify_witnessed.hpp): everything
// up to and including `convex-edge`, i.e. the output is a closed oriented
// surface, star-shaped w.r.t. an exact interior point s and with every edge
// convex, hence (Lemma 6.1 / Thm 6.2) the boundary of a convex polytope whose
// vertices are input points. What is left is to show that every input point
// lies inside it: certify::hull3 locates each point by a walk over the cones
// from s; the witnessed certifier checks the facet a witness names.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify::detail {

// What the surface checks established, for the point checks.
struct Hull3Surface {
  const PointSet* ps = nullptr;
  bool canonical = false;
  pred::RationalPoint s;  // the exact interior point (SoS index n)
  pred::PointId s_id = 0;
  bool s_is_double = false;  // s = sd (a double point), else the rational s
  double sd[3] = {0, 0, 0};
  pred::StaticFilter f;  // over the input (and sd)
  std::vector<std::array<std::uint32_t, 3>> across;  // across[t][k]: the facet across edge k of t
  std::vector<char> is_vertex;                       // per input point
  std::size_t vertices = 0;

  const double* P(Index i) const { return ps->point(i); }
  pred::MixedRow row(Index i) const { return {i, P(i), nullptr}; }
  pred::MixedRow srow() const { return {s_id, nullptr, &s}; }
  pred::Pt pt(Index i) const { return {i, P(i)}; }

  // orient3d(a, b, c, s) under the perturbation
  int facet_vs_s(const Triangle& t) const {
    if (s_is_double) return pred::fast::orient3d(f, pt(t[0]), pt(t[1]), pt(t[2]), {s_id, sd});
    pred::MixedRow r[4] = {row(t[0]), row(t[1]), row(t[2]), srow()};
    return pred::mixed_sign(4, r, true);
  }
  // orient3d(s, a, b, p) under the perturbation: > 0 when p is across the
  // plane (s, a, b) from the third vertex of a facet (a, b, c) facing away
  // from s, i.e. outside the facet's cone across its edge (a, b)
  int side(Index a, Index b, Index p) const {
    if (s_is_double) return pred::fast::orient3d(f, {s_id, sd}, pt(a), pt(b), pt(p));
    pred::MixedRow r[4] = {srow(), row(a), row(b), row(p)};
    return pred::mixed_sign(4, r, true);
  }
  // geometric orientation of p against facet (a, b, c): > 0 inner side
  // (perturbed at the canonical level, exact at the exact level)
  int facet_vs_point(const Triangle& t, Index p) const {
    if (canonical) return pred::fast::orient3d(f, pt(t[0]), pt(t[1]), pt(t[2]), pt(p));
    return pred::orient3d_exact(P(t[0]), P(t[1]), P(t[2]), P(p));
  }
  // p on the wrong side of facet t for the level (canonical: not strictly
  // inside under the perturbation; exact: strictly outside)
  bool outside(const Triangle& t, Index p) const {
    const int sgn = facet_vs_point(t, p);
    return canonical ? sgn <= 0 : sgn < 0;
  }
};

// The conditions of certify::hull3 from input-dimension to convex-edge
// (certify_hull3.cpp's header), with the same messages. s is the centroid of
// `tet` when given (four input indices, which the caller has checked to be
// distinct and affinely independent: then s is strictly inside conv(S)),
// else of four far-apart hull vertices the certifier picks; in either case
// the centroid rounded to doubles when that point is strictly inside the
// tetrahedron exactly (the rounding in the order tet[0..3], as
// kernels_cpu/hull3/rounded_centroid.hpp), else the exact one. On success
// `out` holds s, the filter and the tables for the point checks.
Report hull3_surface(const PointSet& ps, const std::vector<Triangle>& tris, Level level, const Speedups& speedups,
                     const std::array<Index, 4>* tet, Hull3Surface& out);

// Where a walk over the cones from s starts: the directions from s are cut
// into the cells of a cube map (6 faces of side x side; certify::hull3: 64);
// each cell holds a
// facet whose centroid direction falls into it (empty cells: the previous
// filled cell's). Floating point throughout — the table is a hint, never a
// decision: the exact walk from any facet reaches the right cone, a good
// start only makes it short (10^7 ball points: about one step). Used by
// certify::hull3 and by the witness walks of kernels_cpu/hull3/ffhull.cpp.
class DirectionTable {
 public:
  // s: the interior point, approximately (a hint only)
  DirectionTable(const PointSet& ps, const std::vector<Triangle>& tris, const double* s, int side = 64)
      : side_(side) {
    for (int j = 0; j < 3; ++j) s_[j] = s[j];
    cell_ = start_cells(6 * static_cast<std::size_t>(side) * static_cast<std::size_t>(side), ps, tris, 1, [&](const double* c) { return cell(c); });
  }
  std::size_t hint(const double* p) const { return cell_[cell(p)]; }

 private:
  std::size_t cell(const double* p) const {
    const double v[3] = {p[0] - s_[0], p[1] - s_[1], p[2] - s_[2]};
    // a centroid of points near ±1.8e308 overflows; inf - inf is NaN: any
    // non-finite difference takes cell 0 (a hint only)
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return 0;
    int a = 0;
    for (int j = 1; j < 3; ++j)
      if (std::abs(v[j]) > std::abs(v[a])) a = j;
    const double m = std::abs(v[a]);
    if (!(m > 0)) return 0;
    const int face = 2 * a + (v[a] < 0 ? 1 : 0);
    auto coord = [&](double x) {
      const int c = static_cast<int>((x / m + 1) * 0.5 * side_);
      return std::clamp(c, 0, side_ - 1);
    };
    const int u = coord(v[(a + 1) % 3]), w = coord(v[(a + 2) % 3]);
    return (static_cast<std::size_t>(face) * side_ + static_cast<std::size_t>(u)) * side_ + static_cast<std::size_t>(w);
  }
  int side_;
  double s_[3];
  std::vector<std::uint32_t> cell_;
};

}  // namespace flipflop::certify::detail

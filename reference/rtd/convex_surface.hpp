// convex_surface.hpp — the linear-time certificate that a closed surface of
// (d-1)-simplices in R^d bounds a convex polytope, shared by the
// d-dimensional triangulation certifier (certify_rtd.cpp: the boundary of the
// simplices) and the d-dimensional hull certifier (kernels_cpu/rtd/hull_d).
//
// The facets are d-tuples of point indices oriented so that
// orient_d(facet, x) < 0 (predicates.hpp, with the index as SoS index) for x
// on their inner side. The conditions, in order:
//   (a) every ridge (d-1 vertices) lies in exactly two facets, and each of
//       the two has its vertex off the ridge strictly on the inner side of
//       the other (a closed surface, convex at every ridge);
//   (b) a centre c lies strictly on the inner side of every facet: a given
//       point, or — none given — an auxiliary point, the surface vertices'
//       average rounded to doubles, with the SoS index n after every input
//       (predicates.hpp, "Points that are not inputs");
//   (c) the vertical ray up from c (the last coordinate growing) crosses
//       exactly one facet: f is crossed iff c's projection to the first d-1
//       coordinates lies strictly in f's projection and f passes strictly
//       above c; det Λ(f, c) is affine in c's last coordinate with slope
//       -orient_{d-1}(f projected), so "above" is sign orient_d(f, c) =
//       sign orient_{d-1}(f projected). Projections are predicates on a
//       prefix of the columns: signs of the same perturbed configuration.
// Why they suffice (certify_rtd.hpp, "The boundary in linear time"): by (b)
// the central projection from c maps every facet onto the sphere around c
// preserving orientation, so its degree is the number of facets over any
// regular value — by (c), 1 — and the surface is embedded and star-shaped
// from c; embedded and convex at every ridge, it bounds a convex polytope
// (locally convex everywhere by induction on the links, then
// Tietze–Nakajima), and every surface vertex lies strictly inside every
// facet it is not on (general position under SoS).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::certify {

struct SurfaceCheck {
  enum class Kind {
    ok,          // (a), (b), (c) hold
    not_closed,  // a ridge in `count` facets (not two): `ridge`, `facet` one of them
    not_convex,  // vertex `point` of facet `other` is not strictly inside facet `facet`
    outside,     // the centre `point` is not strictly inside facet `facet`
    winds,       // the ray from the centre `point` crosses `count` facets
    no_centre    // no centre given, and the auxiliary one is not inside every facet
  } kind = Kind::ok;
  std::size_t facet = 0, other = 0, count = 0;
  Index point = 0;
  bool auxiliary = false;  // the centre is the auxiliary point (index n)
  std::vector<Index> ridge;
};

// centre: a point index, or kAuxiliaryCentre for the auxiliary point. Every
// facet must hold d distinct in-range indices (the callers check). across
// (optional): receives, where (a) holds, the facet across the ridge opposite
// vertex j of facet k at k * d + j. for_range (Speedups, certify.hpp;
// optional): the per-ridge and per-facet predicates run through it, the
// result the same (the first failing ridge group or facet in the sequential
// order is reported).
inline constexpr Index kAuxiliaryCentre = ~Index{0};
using ForRange = decltype(Speedups::for_range);
SurfaceCheck convex_surface(const PointSet& ps, const std::vector<std::vector<Index>>& facets, Index centre,
                            std::vector<std::uint32_t>* across = nullptr, const ForRange& for_range = {});

}  // namespace flipflop::certify

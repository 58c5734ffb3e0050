// fast.hpp — the default path with a per-input static filter, its first two
// stages inlined into the caller: the static filter (static_filter.hpp: a few
// subtractions, a 2x2..4x4 determinant and one comparison with a bound
// computed once per input) decides almost every call on non-degenerate input
// without a function call; when it cannot — typically for points much closer
// to each other than the input's extent, e.g. the power tests of a Delaunay
// triangulation of 10^7 points, whose determinants are far below the
// per-input bound — the per-call semi-static filter (the same determinant,
// its bound from this call's own magnitudes; for orient2d/3d the permanent
// bound of plain_filters, with the static filter's determinant) is tried,
// still inline; what
// neither decides goes to the out-of-line rest of the staged predicate
// (predicates.hpp, after_filters: double-double or dynamic filter, exact
// expansion stage, Simulation of Simplicity; the filters are not rerun). Same
// answers as pred::orient2d(f, ...) etc. — the filters only decide sooner, and
// never on an exactly degenerate determinant (|det| > bound implies the sign).
//
// Include it in the hot loops of the kernels (kernels_cpu/, and the reference
// where it pays); code that is not time-critical can keep predicates.hpp alone.
#pragma once

#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::pred::fast {

inline int orient2d(const StaticFilter& f, Pt a, Pt b, Pt c) {
  const double* p[3] = {a.x, b.x, c.x};
  if (const int s = plain_filters<3>(f, p)) return s;
  return pred::after_filters::orient2d(a, b, c, f.dd_window(), f.lattice(3, false));
}

inline int orient3d(const StaticFilter& f, Pt a, Pt b, Pt c, Pt d) {
  const double* p[4] = {a.x, b.x, c.x, d.x};
  if (const int s = plain_filters<4>(f, p)) return s;
  return pred::after_filters::orient3d(a, b, c, d, f.dd_window(), f.lattice(4, false));
}

inline int power2d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d) {
  const double* p[4] = {a.x, b.x, c.x, d.x};
  const double w[4] = {a.w, b.w, c.w, d.w};
  if (const int s = static_sign<4>(f, p, w)) return s;
  if (const int s = semi_static_sign<4>(p, w)) return s;
  return pred::after_filters::power2d(a, b, c, d, f.dd_window(), f.lattice(4, true));
}

// power3d's stages after the static filter: for a caller that inlines
// static_sign<5> alone and keeps the rest out of its hot loop (kernels_cpu/rt3)
inline int power3d_after_static(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d, WPt e) {
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  if (const int s = semi_static_sign<5>(p, w)) return s;
  return pred::after_filters::power3d(a, b, c, d, e, f.dd_window(), f.lattice(5, true));
}

inline int power3d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d, WPt e) {
  const double* p[5] = {a.x, b.x, c.x, d.x, e.x};
  const double w[5] = {a.w, b.w, c.w, d.w, e.w};
  if (const int s = static_sign<5>(f, p, w)) return s;
  return power3d_after_static(f, a, b, c, d, e);
}

}  // namespace flipflop::pred::fast

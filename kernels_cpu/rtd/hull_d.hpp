// hull_d.hpp — the convex hull in R^d (d = 2..9) by beneath–beyond insertion
// with outside sets (Quickhull's order), exact under flipflop's Simulation of
// Simplicity, and its certifier in time linear in the output plus a walk per
// point. The backend of Python's `ConvexHull` in 4D..7D (one thread).
//
// The answer. Under SoS the points are in general position, their hull is
// simplicial and unique: its facets are the d-subsets whose hyperplane has
// every other point strictly on one side (orient_d, predicates.hpp, with the
// input index as SoS index). They are the boundary facets of the canonical
// Delaunay triangulation (python/flipflop's _hull_from_triangulation gives
// the argument), which the tests compare them with.
//
// The algorithm (beneath–beyond [Seidel; Clarkson–Shor], in Quickhull's
// order [Barber, Dobkin, Huhdanpaa 1996]): an initial simplex of d+1 points
// far apart in floating point (any d+1 points do under SoS; far apart ones
// leave few points outside); every other point assigned to one facet it sees
// strictly (orient_d(facet, q) > 0, facets oriented with the inside
// negative) or discarded as inside. While some facet has points: its point
// furthest from the facet's hyperplane in floating point (a heuristic only)
// is the apex p; the facets p sees form a connected set (breadth-first
// search over ridge links), each replaced by the cone from p over the
// horizon — facet f with its vertex off a horizon ridge replaced by p keeps
// the orientation, since that vertex lies strictly inside the new facet
// (orient(f[i:=p], f_i) = -orient(f, p) < 0) —, and the points of the
// removed facets are assigned to new facets they see, or discarded. A point
// outside the new hull that saw a removed facet sees a new one: its visible
// facets form a connected set that meets the removed ones, so it sees both
// facets f, g of some horizon ridge, and the new facet u over that ridge has
// its outer normal in the cone of those of f and g (the normal cone of the
// grown hull at the ridge is a subcone), so it sees u too. Points of kept
// facets keep their facet. Every decision is an exact SoS predicate.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::cpu {

struct HullDStats {
  std::uint64_t apexes = 0;      // points made vertices after the initial simplex
  std::uint64_t removed = 0;     // facets removed (visible from an apex)
  std::uint64_t created = 0;     // facets created (cones)
  std::uint64_t tests = 0;       // point-facet visibility tests
  std::uint64_t parallel_batches = 0;  // insertions whose orphans were walked in parallel pieces
};

// Determinant of an n x n double matrix (row-major, 1 <= n <= 9) by Gaussian
// elimination with partial pivoting: floating point, for heuristics and
// floating-point attributes only (hull_d's furthest-point choice, Python's
// hull equations), never for a sign that decides anything.
inline double det_gauss_double(const double* m, int n) {
  double a[81];
  for (int k = 0; k < n * n; ++k) a[k] = m[k];
  double det = 1.0;
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(a[r * n + c]) > std::fabs(a[piv * n + c])) piv = r;
    if (a[piv * n + c] == 0.0) return 0.0;
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(a[c * n + k], a[piv * n + k]);
      det = -det;
    }
    det *= a[c * n + c];
    for (int r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      for (int k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
    }
  }
  return det;
}

// The facets of the hull of ps (dim 2..9; weights ignored), each a d-tuple
// of input indices oriented so that orient_d(facet, x) < 0 for every point x
// inside (predicates.hpp's convention), in no particular order. Input that
// is not finite or does not span R^d is rejected with std::invalid_argument
// (d <= 5: ref::validate_rtd_input's, the same messages as RT+1).
std::vector<std::vector<Index>> hull_d(const PointSet& ps, HullDStats* stats = nullptr);

// The same kernel kept between calls, for in-place insertion (Python's
// ConvexHull(..., incremental=True).add_points): the facets, their links and
// the hull's vertices stay; add() assigns each new point to a facet it sees
// (a scan of the live facets) or discards it as inside, then inserts as
// hull_d does. facets() is the canonical hull of all the points given so far
// (the same set as hull_d's: the hull under SoS is unique; SoS indices are
// the input indices, so appending keeps every earlier point's). The caller
// certifies each result.
class HullDIncremental {
 public:
  explicit HullDIncremental(const PointSet& ps);  // as hull_d(ps), kept
  // Seeded with the hull of ps, given as facets in hull_d's convention and
  // their neighbours (neighbors[k][j]: the facet across the ridge opposite
  // vertex j of facet k) — the caller's certified hull: checked only to be
  // d distinct in-range indices per facet glued along their ridges
  // (std::invalid_argument otherwise), so that each result after add() must
  // be certified as it is anyway. O(facets d^2) and one plane form per
  // facet, no predicate. For a kernel over the hull's vertices only, whose
  // points are all on it.
  HullDIncremental(const PointSet& ps, const std::vector<std::vector<Index>>& facets,
                   const std::vector<std::vector<Index>>& neighbors);
  ~HullDIncremental();
  HullDIncremental(HullDIncremental&&) noexcept;
  HullDIncremental& operator=(HullDIncremental&&) noexcept;

  // `all`: the size() points given so far, unchanged and in the same order,
  // followed by the new ones; validated as hull_d's input before anything
  // changes (std::invalid_argument, nothing changed). An exception during
  // the insertion itself leaves the object unusable (std::logic_error after).
  void add(const PointSet& all);
  std::vector<std::vector<Index>> facets() const;  // hull_d's convention, in no particular order
  std::size_t size() const;                        // points given so far
  HullDStats stats() const;                        // summed over the construction and every add

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Certifies `facets` (the convention above) as the canonical hull of ps:
// returns "" or the first violated condition and what is wrong:
//   facet-indices   d distinct in-range indices per facet, at least d+1 facets
//   closed-surface  every ridge (d-1 vertices) in exactly two facets
//   convex          at every ridge, the vertex of each facet off it strictly
//                   inside the other
//   star-shaped     a point v that is not a vertex (the smallest) strictly
//                   inside every facet, and the vertical ray up from v crosses
//                   exactly one facet (reference/rtd/convex_surface.hpp, shared
//                   with certify::rtd; certify_rtd.hpp, "The boundary in
//                   linear time": then the facets are those of a convex
//                   polytope P star-shaped from v, and of conv(their vertices))
//   points-inside   every other point that is not a vertex strictly inside P:
//                   strictly inside an axis-aligned box or a ball verified
//                   strictly inside every facet (reference/certify/
//                   inner_box.hpp, hull_d.cpp propose_ball; both tried where
//                   the points outnumber the facets), or by a
//                   visibility walk in the cone triangulation {(v, f)} (a
//                   scan of every facet where the walk does not settle)
// When every point is a vertex (no such v), v is an auxiliary point: the
// vertices' average rounded to doubles, with the SoS index n (after every
// input, predicates.hpp), used when it is strictly inside every facet; only
// where it is not (a hull too thin for the rounding) is every vertex tested
// against every facet (quadratic).
struct HullDCertifyStats {
  bool box = false;          // an inner box was verified
  bool ball = false;         // an inner ball was verified
  std::size_t walked = 0;    // points that took the walk (not vertices, not in the box or the ball)
};
std::string hull_d_problem(const PointSet& ps, const std::vector<std::vector<Index>>& facets,
                           HullDCertifyStats* stats = nullptr);

}  // namespace flipflop::cpu

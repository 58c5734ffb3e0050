// predicates.hpp — the exact geometric predicates of flipflop, with Simulation
// of Simplicity. Every geometric decision of every backend goes through here.
//
// ============================================================================
// The perturbation (Simulation of Simplicity, Edelsbrunner–Mücke 1990 [EM90])
// ============================================================================
//
// Inputs are IEEE binary64 values taken as exact rationals. A computation uses
// one perturbation for all its predicates: point i (i = 0-based input index + 1)
// has δ coordinates c(i,1..δ) — δ counts every coordinate the computation uses,
// a lifted height included — and is replaced by the symbolic point
//
//        c(i,j) + ε^(2^(i·δ - j)),     ε > 0 infinitesimal.          [EM90 §4]
//
// Every predicate is the sign of det Λ (lambda_filter.hpp) of perturbed points:
// rows = points, columns = coordinates 1..m then a constant 1. Expanding the
// multilinear determinant, the perturbed value is a sum over *matchings* T
// (sets of entries (row, column), at most one per row and per column, never
// in the 1-column):
//
//     det Λ(ε) = Σ_T  cof_T · Π_{(r,c) ∈ T} ε^(2^(i_r·δ - c)),
//
// where cof_T is the signed complementary minor: det Λ with the rows and
// columns of T deleted, times (-1)^(position of row + position of column) for
// each deletion (a mixed partial derivative of det, so the order of deletions
// does not matter). The empty matching gives det Λ itself.
//
// Which term dominates? The exponents 2^(iδ-j) are distinct powers of two, so
// the ε-exponent of a matching is a sum of distinct powers of two, and two such
// sums compare like binary numbers: the larger sum (the smaller term) is the
// one holding the largest exponent in which the two matchings differ. Because
// all exponents of point i lie in [(i-1)δ, iδ-1], every exponent of a point
// exceeds the sum of all exponents of points with smaller indices. Hence:
//
//   Dominance order. Compare two matchings on the row of the *largest* index
//   first, then the next largest, and so on; on a row, "not perturbed" beats
//   any perturbed entry, and among entries the larger coordinate number j
//   beats the smaller (its exponent iδ - j is smaller).
//
// The sign of det Λ(ε) is the sign of the first non-zero cof_T in this order.
// It always exists: the matching that deletes rows 1..m (all but the largest
// index) against all m coordinate columns leaves the 1x1 minor "1". So for
// points with distinct indices a predicate never returns 0; with a repeated
// index two rows are equal and the answer is 0 (the same point twice).
//
// The dominance order depends only on (a) the order of indices and (b) the
// order of the coordinate columns within a row — not on δ itself. Therefore
// orient2d of (x, y) projections, orient3d of (x, y, h) lifted points and
// orient3d of (x, y, z) hull points are all signs of the *same* perturbed
// configuration whenever they share their columns in this order, and all answers
// of a computation are consistent with one real configuration in general
// position (DESIGN.md, "The perturbation, precisely"). The lifted height
// h = |x|^2 - w is perturbed as an independent coordinate (column m), which is
// perturbing the weight (thesis §9.2.2, last paragraph): it is *not* recomputed
// from perturbed x.
//
// Points that are not inputs. A point that is not an input (a kernel point, an
// auxiliary point of an algorithm) takes an index after all n inputs: the first
// such point created by a computation is n, the next n+1, ... (documented by the
// algorithm that creates it); a larger index means a smaller perturbation, so
// inputs never depend on the perturbation of auxiliary points. The virtual
// vertex of an extended triangulation (thesis §2.2) has no coordinates and never
// enters a determinant: predicates involving it are decided combinatorially by
// the rules of §2.2 from predicates on real points.
//
// ============================================================================
// Stages (staged.hpp), two implementations
// ============================================================================
//
// Mode::filtered (default): no GMP, no heap, header-usable on the device —
//   1. static filter (static_filter.hpp): an error bound computed once per
//      input from its largest magnitudes (overloads taking a StaticFilter);
//   2. semi-static filter: a bound from this call's column magnitudes;
//   3. dynamic filter: ErrDouble running error bound (err_double.hpp);
//   4. exact: Shewchuk's expansion arithmetic (expansion.hpp,
//      exact_expansion.hpp), double components inside a proven exponent
//      window, unbounded-exponent components outside it (1e±300, subnormals);
//   5. Simulation of Simplicity on the same expansions.
// Mode::gmp: GMP only — the independent oracle of the property tests. Both
// return the same sign on every input (proptests/predicates_stages_test.cpp).
//
// Conventions (determinant with the 1-column last, i.e. Shewchuk's signs):
//   orient2d(a,b,c) > 0  iff a, b, c are counter-clockwise.
//   orient3d(a,b,c,d) > 0 iff d lies below the plane of a, b, c when a, b, c
//                         appear counter-clockwise seen from above, i.e. on the
//                         side from which (a, b, c) appears clockwise.
//                         For a hull facet (a,b,c) counter-clockwise seen from
//                         outside, interior points p give orient3d(a,b,c,p) > 0.
//   power2d(a,b,c,d) = orient3d of the lifted points (x, y, x²+y²-w): for a, b,
//                         c counter-clockwise, > 0 iff d is strictly closer than
//                         orthogonal to the orthocircle of a, b, c (the edge
//                         opposite d is locally non-regular); with zero weights,
//                         > 0 iff d is inside the circumcircle (Shewchuk's
//                         incircle).
//   power3d(a,b,c,d,e) = 4D analogue: orient4d of lifted points.
//   orient_d(d, p[0..d]) = sign det Λ of d+1 points in R^d (d <= 10).
//   power_d(d, p[0..d+1], w) = orient_{d+1} of the lifted points (d <= 9).
//
// Sizes: k = 2..8 rows take every stage below; k = 9..11 (orientations in
// 8D..10D, power tests in 7D..9D: the d-dimensional hulls and triangulations
// beyond 7D / 6D) are host-only and take the dynamic filter (ErrDouble over
// column subsets, evaluated at run time) and then GMP (lambda_sign_high).
#pragma once

#include <cstdint>

namespace flipflop::pred {

using PointId = std::uint64_t;

// The largest Λ-matrix any predicate takes: 11 rows (power_d in 9D).
inline constexpr int kMaxLambdaK = 11;
// The largest Λ-matrix of the staged (device-usable) path; larger ones go to
// lambda_sign_high.
inline constexpr int kMaxStagedK = 8;

enum class Mode { filtered, gmp };

// A point as a predicate sees it: its index in the perturbation order and a
// pointer to its coordinates (2, 3 or d doubles).
struct Pt {
  PointId id;
  const double* x;
};

// A weighted point: index, coordinates and weight.
struct WPt {
  PointId id;
  const double* x;
  double w;
};

// ---- Per-input static filter (static_filter.hpp) ------------------------------
// StaticFilter::for_points(coords, n, dim, weights) computes, once per input,
// error bounds valid for every predicate call on points of that input; the
// overloads below taking a StaticFilter try it first (then the per-call
// stages). A default-constructed StaticFilter decides nothing.
class StaticFilter;

// ---- Exact signs of the unperturbed determinants (may be 0) -----------------
int orient2d_exact(const double* a, const double* b, const double* c, Mode m = Mode::filtered);
int orient3d_exact(const double* a, const double* b, const double* c, const double* d,
                   Mode m = Mode::filtered);
int power2d_exact(WPt a, WPt b, WPt c, WPt d, Mode m = Mode::filtered);
int power3d_exact(WPt a, WPt b, WPt c, WPt d, WPt e, Mode m = Mode::filtered);
// d+1 points in R^d, 1 <= d <= 10
int orient_d_exact(int d, const double* const* p, Mode m = Mode::filtered);
// d+2 weighted points in R^d, 1 <= d <= 9 (lifted to R^(d+1))
int power_d_exact(int d, const double* const* p, const double* w, Mode m = Mode::filtered);

// ---- Signs under Simulation of Simplicity (never 0 for distinct ids) --------
int orient2d(Pt a, Pt b, Pt c, Mode m = Mode::filtered);
int orient3d(Pt a, Pt b, Pt c, Pt d, Mode m = Mode::filtered);
int power2d(WPt a, WPt b, WPt c, WPt d, Mode m = Mode::filtered);
int power3d(WPt a, WPt b, WPt c, WPt d, WPt e, Mode m = Mode::filtered);
int orient_d(int d, const Pt* p, Mode m = Mode::filtered);
int power_d(int d, const WPt* p, Mode m = Mode::filtered);

// power_d under a second perturbation, used only by the strict views of
// d-dimensional regular triangulations (reference/rtd/strict_rtd.hpp): every
// lifted height h_i = |x_i|^2 - w_i becomes h_i + ε1 |x_i|^2 - ε2^(r_i)
// (r_i the rank of the index: the smallest index PULLED down most), the
// coordinates are perturbed as above (the height not with them), and
// ε1 >> ε2 >> every coordinate perturbation. Since det Λ is linear in the
// height column, the sign is: the exact one when that is not 0; else that of
// the unweighted determinant (the ε1 term; it is the exact one again for
// Delaunay input); else, when the d+2 points span R^d, that of the first
// non-zero -cofactor of the height column, smallest index first (the pulls).
// The ε1 term refines every cell of the exact regular subdivision by the
// Delaunay subdivision of its points (a strictly convex function added to an
// affine one: every point lifted onto the lower hull becomes a vertex), the
// pulls then split cospherical ties — no simplex of zero volume in the
// interior; only tuples inside a hyperplane of R^d (flat simplices on the
// hull boundary) reach the coordinate perturbation. orient_d is unchanged (no
// height), so orient_d and power_d_pulled are the predicates of one real
// configuration in general position. Never 0 for distinct ids. Rows may come
// in any order (sorted by id here, with the permutation's sign).
int power_d_pulled(int d, const WPt* p, Mode m = Mode::filtered);

// Sign of a.x[coord] - b.x[coord] under the perturbation (the 1-dimensional
// Λ-determinant of the coordinate column): equal coordinates are separated by
// the perturbation, which is larger for the smaller index. Never 0 for
// distinct ids. Sorting by this comparison (e.g. by x for Graham's scan) is
// consistent with every other predicate of the computation.
int compare_sos(Pt a, Pt b, int coord, Mode m = Mode::filtered);

// ---- Small exact helpers used by certifiers --------------------------------
// Sign of (b - a) · (c - b) in 2D, exactly.
int dot2d_exact(const double* a, const double* b, const double* c);
// Are three points of R^3 on one line (or not all distinct), exactly, i.e.
// (b - a) x (c - a) = 0? True iff all three coordinate-plane projections
// (xy, yz, zx) have orient2d_exact 0: a cross product vanishes iff each of its
// components, which are these projected signed areas (times 2), does.
bool collinear3_exact(const double* a, const double* b, const double* c);

// The general entry point: sign of det Λ for k = dim+1 points (k <= 11).
// `coords[i]` points to the coordinates of point i; if `weights` is non-null
// the last column is the lifted height of the first dim-1 coordinates
// (|x|^2 - w). `ids` may be null (no perturbation: exact sign, may be 0).
int lambda_sign(int k, const PointId* ids, const double* const* coords, const double* weights,
                Mode m);
// The same, first trying the per-input static filter `f` (may be null).
int lambda_sign(const StaticFilter* f, int k, const PointId* ids, const double* const* coords,
                const double* weights, Mode m = Mode::filtered);

// ---- The default path with a per-input static filter -------------------------
// Same answers as the overloads above (the filter only decides sooner).
int orient2d(const StaticFilter& f, Pt a, Pt b, Pt c);
int orient3d(const StaticFilter& f, Pt a, Pt b, Pt c, Pt d);
int power2d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d);
int power3d(const StaticFilter& f, WPt a, WPt b, WPt c, WPt d, WPt e);

// The same after the static and semi-static (or permanent) filters
// (staged.hpp, lambda_sign_after_filters): fast.hpp runs those inline and
// calls these only when they have failed. `dd_window`: the input's
// StaticFilter::dd_window(); `lattice`: its StaticFilter::lattice(k, lifted)
// (0: nothing known). On an x86-64 host with FMA (checked once per
// call by __builtin_cpu_supports) the double-double filter runs in its FMA
// instantiation (dd_filter.hpp): the same signs, fewer instructions.
namespace after_filters {
int orient2d(Pt a, Pt b, Pt c, bool dd_window, int lattice = 0);
int orient3d(Pt a, Pt b, Pt c, Pt d, bool dd_window, int lattice = 0);
int power2d(WPt a, WPt b, WPt c, WPt d, bool dd_window, int lattice = 0);
int power3d(WPt a, WPt b, WPt c, WPt d, WPt e, bool dd_window, int lattice = 0);
}  // namespace after_filters

// Host-only path for k = 9..11 rows (kMaxStagedK < k <= kMaxLambdaK): a
// repeated id gives 0; then the dynamic filter (ErrDouble minors over column
// subsets), then the exact sign and, when it is 0 and ids are given, the
// Simulation of Simplicity, both on GMP integers (exact.hpp). The static
// filter `f` is accepted for a uniform call and not used (its bounds are
// derived for k <= 8). lambda_sign_staged<K> calls it for K > 8.
int lambda_sign_high(const StaticFilter* f, int k, const PointId* ids, const double* const* coords,
                     const double* weights);

// Whether after_filters uses the FMA instantiation on this host.
bool host_fma();

// ---- Each stage alone (benchmarks and tests) --------------------------------
// On the Λ-matrix of k points (2 <= k <= 8), p[i] the coordinates of point i,
// `w` the weights (lifted matrix, k >= 3) or null, as for lambda_sign. Rows
// are taken in the given order (no sorting by id).
//   filters: +1 / -1 when they decide, 0 when they cannot;
//   exact stages: the exact sign of the unperturbed determinant (may be 0);
//   *_sos: the Simulation-of-Simplicity sign (ids distinct: never 0).
namespace stage {
int static_filter(const StaticFilter& f, int k, const double* const* p, const double* w);
int semi_static(int k, const double* const* p, const double* w);   // bound from this call's magnitudes
int dynamic(int k, const double* const* p, const double* w);       // ErrDouble running bound
int dd_filter(int k, const double* const* p, const double* w, bool fma);  // k = 3..7; 2: outside its window
int expansion(int k, const double* const* p, const double* w);     // exact, expansion arithmetic
int expansion_sos(int k, const PointId* ids, const double* const* p, const double* w);
int gmp(int k, const double* const* p, const double* w);           // exact, GMP (the oracle)
int gmp_sos(int k, const PointId* ids, const double* const* p, const double* w);
}  // namespace stage

}  // namespace flipflop::pred

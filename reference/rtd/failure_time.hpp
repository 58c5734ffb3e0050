// failure_time.hpp — the moving model of thesis §9.2 and exact comparison of
// failure times (§9.2.2, Equations 9.1–9.4), without ever computing a time.
//
// ============================================================================
// The moving model (§9.2, §9.3)
// ============================================================================
// Every point p of S keeps its coordinates; its weight moves linearly,
// v_p(t) = (1-t) w_p + t u_p, so its lifted height h_p(t) = |p|^2 - v_p(t) is
// affine in t: h_p(t) = h_p(0) + t (h_p(1) - h_p(0)). For a ridge F of a
// triangulation with incident simplices C1 = F + a and C2 = F + b (a, b: the
// link of F), S_F = (f_1, ..., f_d, a, b) and the (d+2) x (d+2) determinant
//
//        | f_1  h_f1(t)  1 |
//        | ...    ...   ...|                                      (Eq. 9.1)
//   det  | f_d  h_fd(t)  1 |   = Σ_r (-1)^(r+d) h_r(t) M_r        (r = 0..d+1)
//        | a    h_a(t)   1 |
//        | b    h_b(t)   1 |
//
// (expansion along the height column, 0-based rows; M_r = Orient^d(S_F, a_r),
// the (d+1)-minor without row r and the height column, Eq. 9.2: it does not
// depend on t) is affine in t. This file normalises its sign:
//
//   Orient^{d+1}(S_F, t) := -sign(M_{d+1}) · det,    M_{d+1} = Orient^d(C1),
//
// so that Orient^{d+1} > 0 iff F is *convex* (b lies above the hyperplane of
// the lifted C1: locally regular), < 0 iff reflex, 0 iff flat — whatever the
// order of the vertices of F. A = Orient^{d+1}(S_F, 0), B = Orient^{d+1}(S_F, 1),
// D = B - A. F deforms from convex to reflex (negative changing direction,
// §9.3) iff D < 0, and then its failure time (§9.2) / changing time (§9.3) is
//
//        t_F = A / (A - B) = -A / D.                              (Eq. 9.3)
//
// Comparing two failure times (both D < 0): sign(t_F - t_G) =
// sign(B_F·A_G - A_F·B_G) (§9.2.2). For changing times of any directions
// (§9.3) the sign is multiplied by sign(D_F)·sign(D_G).
//
// ============================================================================
// The weight perturbation (§9.2.2, Eq. 9.4) and its sign convention
// ============================================================================
// A perturbation order (perturbation_order.hpp, Algorithm 15) ranks the points;
// point p gets a symbolic perturbing value ε_p > 0, ε_p dominating every ε_q
// of a point q behind p. The perturbation is constant in t. It is added to
// the lifted *height* (h_p + ε_p, i.e. subtracted from the weight): this is
// the convention of the Simulation of Simplicity of predicates.hpp, where the
// height is perturbed like an independent coordinate by a positive amount and
// the point of smallest index dominates. Hence with the index order
// (PerturbationOrder::identity) and points whose d-dimensional orientation
// minors do not vanish, the perturbed signs at t = 0 and t = 1 are exactly
// those of pred::power_d on S ⊕ W and S ⊕ U: RT(S⊕W) built by the reference
// is strongly regular under it and the instant flip ends at the reference's
// RT(S⊕U). (The thesis adds ε to the weight; that mirror image only swaps the
// roles of S_p and S_n in Algorithm 15.)
//
// Perturbed, Orient^{d+1}(S*_F, t) = Orient^{d+1}(S_F, t) + Σ_p c_F(p) ε_p with
// c_F(p) = -sign(M_{d+1}) (-1)^(r_p+d) M_{r_p}, the same at every t. The sign
// at t = 0 or 1 is that of A (B) or, when it is 0, of the first non-zero c_F(p)
// in perturbation order; c_F(b) = |M_{d+1}| != 0, so it is never 0.
// Comparing t_F and t_G, the quadratic ε terms cancel and
//
//   A*_G B*_F - A*_F B*_G = (A_G B_F - A_F B_G) + Σ_p ε_p (c_G(p) D_F - c_F(p) D_G):
//
// the main term decides; when it is 0, the coefficient of the most dominant
// ε_p that is non-zero does. All coefficients vanish only when S_F and S_G
// describe the same flip (§9.2.2) — or, with degenerate coordinates, for two
// independent events: compare_times() then returns 0.
//
// ============================================================================
// Exactness and cost
// ============================================================================
// Coordinates and heights are exact dyadic rationals (predicates/exact.hpp).
// Per ridge, each coordinate column is scaled to integers by 2^-(its smallest
// exponent among the d+2 points), which multiplies all M_r by the same 2^E;
// the 2(d+2) heights are scaled together by 2^-H. Stored: the integers
// c_F(p)·2^-E and A·2^-(E+H), B·2^-(E+H), and H. Positive common factors do
// not change a sign; where quantities of two ridges are added (the ε
// coefficients above), the 2^H factors are restored. The M_r are computed
// all at once by Laplace expansion over row subsets. Before any of this, the
// same expansion in floating point with a running error bound (ErrDouble,
// the project's filter) gives A, B, D and t_F with proven error bounds; signs
// and time comparisons that the bounds decide never reach GMP.
//
// Precondition (the thesis' general position in R^d, §9.2): both simplices of
// a ridge have non-zero volume (M_{d+1} != 0 and M_d != 0); ridge_motion()
// throws std::invalid_argument otherwise. Weights may be degenerate.
//
// ============================================================================
// Insertion events: a redundant point below its simplex (beyond the thesis)
// ============================================================================
// A point p that is not a vertex lies in a real simplex C = (c_0, ..., c_d)
// (positive). Its lifted point passes below the lifted hyperplane of C when
// the same determinant (Eq. 9.1) with S = (c_0, ..., c_{d-1}, a = c_d, b = p)
// turns from positive (p above C: "convex") to negative: it is a RidgeMotion
// whose "second simplex" (c_0, ..., c_{d-1}, p) is not a simplex of T, so
// its volume M_d may vanish (point_motion() accepts that; only C must have
// non-zero volume). Everything above — the failure time, the perturbation
// (c_F(p) = |M_{d+1}| != 0 for b = p), compare_times() — applies unchanged,
// so insertion events and ridge failures are ordered exactly in one queue.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "predicates/err_double.hpp"
#include "predicates/exact.hpp"
#include "reference/point_set.hpp"

namespace flipflop::ref {

// The rank of every point in a perturbation order: rank[p] = position of p in
// `order`; position 0 is the most dominant perturbing value.
struct PerturbationOrder {
  std::vector<Index> order;
  std::vector<Index> rank;

  // The index order 0, 1, ..., n-1 (the Simulation of Simplicity's).
  static PerturbationOrder identity(std::size_t n);
  // Throws std::invalid_argument unless `order` is a permutation of 0..n-1.
  static PerturbationOrder from_order(std::vector<Index> order);
  std::size_t size() const { return order.size(); }
};

// The points with their heights at t = 0 (weights W) and t = 1 (weights U),
// as exact dyadics. A point's dyadics are made the first time the exact stage
// asks for them (most runs need few: the filtered stage reads the doubles),
// so building a model costs O(n) double checks, not O(n) GMP numbers; the
// references returned stay valid for the model's lifetime.
class MovingModel {
 public:
  // ps.dim = d in 1..5 (lifted determinants need d+2 <= 7 rows); w and u hold
  // ps.size() finite weights each. Throws std::invalid_argument otherwise.
  MovingModel(const PointSet& ps, const std::vector<double>& w, const std::vector<double>& u);

  int dim() const { return d_; }
  std::size_t size() const { return n_; }
  const PointSet& points() const { return *ps_; }
  const std::vector<double>& w() const { return w_; }
  const std::vector<double>& u() const { return u_; }

  const pred::exact::Dyadic& coord(std::size_t p, int j) const { return exact(p).x[static_cast<std::size_t>(j)]; }
  const pred::exact::Dyadic& height(std::size_t p, int t) const { return t == 0 ? exact(p).h0 : exact(p).h1; }

 private:
  struct Exact {  // one point: coordinates, heights |p|^2 - w_p and |p|^2 - u_p
    std::array<pred::exact::Dyadic, 5> x;
    pred::exact::Dyadic h0, h1;
  };
  const Exact& exact(std::size_t p) const;

  const PointSet* ps_;
  int d_;
  std::size_t n_;
  std::vector<double> w_, u_;
  mutable std::vector<std::uint32_t> made_;  // per point: 1 + its index in exact_, 0 when not made
  mutable std::deque<Exact> exact_;          // deque: references stay valid as it grows
};

constexpr int kMaxRidgeRows = 7;  // d + 2 for d <= 5

// What the moving model knows about one ridge F with its link (a, b):
// Orient^{d+1}(S_F, 0), Orient^{d+1}(S_F, 1) and the coefficients of the
// perturbing values (see the header comment), in two stages. The filtered
// stage (always computed) holds A, B and D in floating point with proven error
// bounds (pred::ErrDouble, coordinates translated to the last point of S_F
// first: the minors and the lifted determinant do not change); the exact
// stage (GMP, computed on demand by ensure_exact) decides whatever the filter
// cannot. Every function below returns the exact answer either way.
struct RidgeMotion {
  int d = 0;
  std::array<Index, kMaxRidgeRows> pts{};  // S_F = (f_1, ..., f_d, a, b)
  const MovingModel* model = nullptr;

  // filtered stage: A, B, D = B - A (true scale, sign-normalised)
  bool filtered = false;  // false: the exact stage was needed at once
  pred::ErrDouble fa0, fa1, fd;
  double t_approx = 0.0;  // ≈ -A/D (when D != 0)
  double t_rel = 0.0;     // proven relative error bound of t_approx (inf: none)

  // exact stage (scaled integers, see the header comment)
  mutable bool exact = false;
  mutable mpz_class a0, a1;                        // A·2^-(E+H), B·2^-(E+H)
  mutable std::array<mpz_class, kMaxRidgeRows> c;  // c_F(pts[r])·2^-E
  mutable long hexp = 0;                           // H
  mutable int dir = 2;                             // direction(), 2: not yet known
  bool point_event = false;  // S = (C, p) of a tracked point p: M_d may be 0

  int rows() const { return d + 2; }
  Index link_a() const { return pts[static_cast<std::size_t>(d)]; }
  Index link_b() const { return pts[static_cast<std::size_t>(d) + 1]; }
  // sign of D = B - A: -1 convex -> reflex, +1 reflex -> convex, 0 parallel
  int direction() const;
  // Computes the exact stage (idempotent). Throws std::invalid_argument for a
  // zero-volume simplex.
  void ensure_exact() const;
};

// S_F for the ridge `ridge` (d indices) with link vertices a (C1 = F + a) and b.
RidgeMotion ridge_motion(const MovingModel& mm, const Index* ridge, Index a, Index b);

// S = (simplex[0..d-1], a = simplex[d], b = p) for a point p that is not a
// vertex, in the real simplex `simplex` (d+1 indices, positively oriented):
// its lifted point lies above C's lifted hyperplane iff the sign is positive
// ("convex"); it enters when that fails (header comment, insertion events).
RidgeMotion point_motion(const MovingModel& mm, const Index* simplex, Index p);

// Sign of Orient^{d+1}(S*_F, t) for t = 0 or 1 under the perturbation: +1
// convex, -1 reflex; never 0.
int perturbed_sign(const RidgeMotion& m, int t, const PerturbationOrder& order);
// The same at any time t (a finite double, exactly): Orient^{d+1}(S*_F, t).
int perturbed_sign_at(const RidgeMotion& m, double t, const PerturbationOrder& order);
// Sign of the unperturbed Orient^{d+1}(S_F, t), t = 0 or 1 (0: flat).
int exact_sign(const RidgeMotion& m, int t);
// Sign of c_F(pts[r]), the coefficient of point pts[r]'s perturbing value.
int coefficient_sign(const RidgeMotion& m, int r);

// F has a failure time in (0, 1) (Algorithm 14, lines 4 and 11): convex at
// t = 0, reflex at t = 1 (perturbed), hence D < 0.
bool fails_in_unit_interval(const RidgeMotion& m, const PerturbationOrder& order);

// Sign of τ_F - τ_G for two ridges with direction() != 0 (changing times,
// §9.3; for failure times both directions are -1). 0 only when no perturbing
// value separates them (the same flip).
int compare_times(const RidgeMotion& f, const RidgeMotion& g, const PerturbationOrder& order);

// An interior ridge of a triangulation given as a simplex list: its d
// vertices (sorted) and its link: C1 = ridge + a, C2 = ridge + b, a < b.
struct RidgeLink {
  std::array<Index, 5> v{};
  Index a = 0, b = 0;
};

// The interior ridges of `simplices` (d+1 indices each, any order; e.g. the
// canonical list of canonical_d.hpp), sorted by vertices; `boundary` (if not
// null) receives the number of ridges with one simplex. Throws
// std::invalid_argument when a simplex has not d+1 distinct indices below n
// or a ridge has more than two simplices (not a triangulation).
std::vector<RidgeLink> interior_ridges(int d, std::size_t n,
                                       const std::vector<std::vector<Index>>& simplices,
                                       std::size_t* boundary = nullptr);

// The changing time -A/D as a (rounded) double, for display only; requires
// direction() != 0.
double approximate_time(const RidgeMotion& m);
// The unperturbed changing time -A/D as an exact rational; requires
// direction() != 0.
mpq_class exact_time(const RidgeMotion& m);

}  // namespace flipflop::ref

// predicates_test.cpp — properties of the exact and SoS predicates
// (predicates/predicates.hpp) on the input families of
// support/predicate_inputs.hpp, hand-checked conventions, and CGAL's exact
// kernels as an independent oracle for the unperturbed signs.
//
// Properties (each runs RC_PARAMS' max_success cases, 2000 by default):
//   (a) Mode::filtered == Mode::gmp, *_exact and SoS variants,
//       one property per predicate and family (13 x 4);
//   (b) a permutation of the arguments multiplies the sign by the sign of the
//       permutation (ids travel with their points), exact and SoS (13);
//   (c) SoS is never 0 for distinct ids and is 0 when an id repeats (13),
//       and never 0 when all points coincide (13, a tenth of the cases);
//   (d) SoS equals the exact sign whenever that is non-zero (13);
//   the specialised predicates equal the general-dimension ones (4);
//   CGAL (Epick and Simple_cartesian<Exact_rational>) agrees with the exact
//   signs (4 properties).
// The SoS oracle (e) and the hand-worked SoS cases are in sos_test.cpp.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <rapidcheck/catch.h>

#include "predicates/predicates.hpp"
#include "proptests/support/predicate_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"

using flipflop::pred::Mode;
using flipflop::pred::Pt;
using flipflop::pred::WPt;
using namespace flipflop::test;

namespace {

bool is_sign(int s) { return s == -1 || s == 0 || s == 1; }

// (a) on one instance: the filtered path's exact and SoS signs are GMP's;
// returns GMP's SoS sign
int check_filtered_equals_gmp(const Spec& s, const Instance& in) {
  int gmp = 0;
  for (bool sos : {false, true}) {
    const int filtered = eval(s, in, sos, Mode::filtered);
    gmp = eval(s, in, sos, Mode::gmp);
    RC_ASSERT(is_sign(gmp));
    RC_ASSERT(filtered == gmp);
  }
  return gmp;
}

}  // namespace

// ---- (a) filtered == GMP ---------------------------------------------------------
TEST_CASE("predicates: filtered equals GMP on every family (exact and SoS)") {
  for (const Spec& s : all_specs()) {
    for (Family f : kFamilies) {
      rc::prop(s.name() + ", " + family_name(f), [s, f] {
        const Instance in = gen_instance(s, f);
        RC_LOG() << describe(s, in);
        check_filtered_equals_gmp(s, in);
      });
    }
  }
}

// The same, and (b)-(d) below, for 8..11 rows (orient_d in 7D..10D, power_d
// in 6D..9D: the d-dimensional hulls and triangulations up to 9D): the run-
// time filters (Gaussian elimination in ErrDouble) against GMP. A tenth of
// the configured cases: a GMP 11 x 11 determinant and its SoS search are the
// slow part.
TEST_CASE("predicates: 8..11 rows: filtered equals GMP, permutations, SoS refines the exact sign") {
  for (const Spec& s : high_specs()) {
    for (Family f : kFamilies) {
      prop_scaled(s.name() + ", " + family_name(f), 10, [s, f] {
        const Instance in = gen_instance(s, f);
        RC_LOG() << describe(s, in);
        const int sos = check_filtered_equals_gmp(s, in);
        RC_ASSERT(sos != 0);
        const int exact = eval(s, in, false, Mode::gmp);
        if (exact != 0) RC_ASSERT(sos == exact);
        const std::vector<int> perm = gen_permutation(in.k);
        const Instance out = permuted(in, perm);
        for (bool sos : {false, true})
          RC_ASSERT(eval(s, out, sos, Mode::filtered) == permutation_sign(perm) * eval(s, in, sos, Mode::filtered));
      });
    }
  }
}

// ---- (b) permutations ----------------------------------------------------------------
// Every predicate is sign det Λ with one row per point; permuting rows
// multiplies the determinant by the sign of the permutation. Under SoS the
// perturbation of a row is keyed by its id, so permuting points together with
// their ids permutes the rows of the perturbed matrix too.
TEST_CASE("predicates: odd permutations flip the sign, even ones keep it") {
  for (const Spec& s : all_specs()) {
    rc::prop(s.name(), [s] {
      const Instance in = gen_any(s);
      const std::vector<int> perm = gen_permutation(in.k);
      const Instance out = permuted(in, perm);
      const Mode m = *rc::gen::element(Mode::filtered, Mode::gmp);
      RC_LOG() << describe(s, in);
      for (bool sos : {false, true})
        RC_ASSERT(eval(s, out, sos, m) == permutation_sign(perm) * eval(s, in, sos, m));
    });
  }
}

// ---- (c) SoS never 0 for distinct ids, 0 for a repeated id ---------------------
TEST_CASE("predicates: SoS is non-zero for distinct ids and zero for a repeated id") {
  for (const Spec& s : all_specs()) {
    rc::prop(s.name(), [s] {
      Instance in = gen_any(s);
      RC_LOG() << describe(s, in);
      for (Mode m : {Mode::filtered, Mode::gmp}) RC_ASSERT(eval(s, in, true, m) != 0);
      // The same point twice (same id, coordinates and weight): rows of the
      // perturbed matrix coincide, the determinant is identically 0.
      const int a = *rc::gen::inRange(0, in.k);
      const int b = (a + *rc::gen::inRange(1, in.k)) % in.k;
      for (int j = 0; j < in.d; ++j) in.p(b)[j] = in.p(a)[j];
      in.w[static_cast<size_t>(b)] = in.w[static_cast<size_t>(a)];
      in.id[static_cast<size_t>(b)] = in.id[static_cast<size_t>(a)];
      for (Mode m : {Mode::filtered, Mode::gmp}) RC_ASSERT(eval(s, in, true, m) == 0);
    });
  }
}

// Degenerate extremes of (c): all points identical, ids distinct. Only the
// ids' order and the common point vary, and such a case is the slowest one of
// the SoS search (every minor of two or more rows vanishes), so this property
// runs a tenth of the configured cases.
TEST_CASE("predicates: SoS is non-zero when all points coincide") {
  for (const Spec& s : all_specs()) {
    prop_scaled(s.name(), 10, [s] {
      Instance in = gen_any(s);
      for (int i = 1; i < in.k; ++i) {
        for (int j = 0; j < in.d; ++j) in.p(i)[j] = in.p(0)[j];
        in.w[static_cast<size_t>(i)] = in.w[0];
      }
      RC_LOG() << describe(s, in);
      for (Mode m : {Mode::filtered, Mode::gmp}) {
        RC_ASSERT(eval(s, in, false, m) == 0);
        RC_ASSERT(eval(s, in, true, m) != 0);
      }
    });
  }
}

// ---- (d) SoS refines the exact sign ------------------------------------------------------
// det Λ(ε) = det Λ + O(ε): a non-zero unperturbed determinant decides.
TEST_CASE("predicates: SoS equals the exact sign when that is non-zero") {
  for (const Spec& s : all_specs()) {
    rc::prop(s.name(), [s] {
      const Instance in = gen_any(s);
      const Mode m = *rc::gen::element(Mode::filtered, Mode::gmp);
      RC_LOG() << describe(s, in);
      const int exact = eval(s, in, false, m);
      if (exact != 0) RC_ASSERT(eval(s, in, true, m) == exact);
    });
  }
}

// ---- the fixed-dimension predicates are the general ones ------------------------
TEST_CASE("predicates: orient2d/3d and power2d/3d equal orient_d/power_d") {
  const std::pair<Spec, Spec> pairs[] = {{{Kind::orient2d, 2}, {Kind::orient_d, 2}},
                                         {{Kind::orient3d, 3}, {Kind::orient_d, 3}},
                                         {{Kind::power2d, 2}, {Kind::power_d, 2}},
                                         {{Kind::power3d, 3}, {Kind::power_d, 3}}};
  for (const auto& [fixed, general] : pairs) {
    rc::prop(fixed.name() + " vs " + general.name(), [fixed = fixed, general = general] {
      const Instance in = gen_any(fixed);
      const Mode m = *rc::gen::element(Mode::filtered, Mode::gmp);
      RC_LOG() << describe(fixed, in);
      for (bool sos : {false, true}) RC_ASSERT(eval(fixed, in, sos, m) == eval(general, in, sos, m));
    });
  }
}

// ---- (f) hand-checked conventions -----------------------------------------------------
// Each expected value is derived in the comment next to it, from the
// conventions documented in predicates.hpp; none was obtained by running the
// code under test.
TEST_CASE("predicates: hand-checked orientation conventions") {
  for (Mode m : {Mode::filtered, Mode::gmp}) {
    // (b - a) x (c - a) = (1,0) x (0,1) = 1 > 0: counter-clockwise.
    const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
    CHECK(flipflop::pred::orient2d_exact(a, b, c, m) == 1);
    CHECK(flipflop::pred::orient2d_exact(a, c, b, m) == -1);
    // On the line y = x.
    const double l0[2] = {0, 0}, l1[2] = {1, 1}, l2[2] = {2, 2};
    CHECK(flipflop::pred::orient2d_exact(l0, l1, l2, m) == 0);
    // c = (3, 3 + 2^-51) is one ulp above the line y = x through (1,1), (2,2):
    // (1,1) x (2, 2 + 2^-51) = 2 + 2^-51 - 2 = 2^-51 > 0.
    const double n0[2] = {1, 1}, n1[2] = {2, 2}, n2[2] = {3, std::nextafter(3.0, 4.0)};
    CHECK(flipflop::pred::orient2d_exact(n0, n1, n2, m) == 1);
    // Subnormal triangle: det = 2^-1074 * 2^-1074 = 2^-2148 > 0 (underflows to
    // 0 in doubles, so the filter must defer).
    const double t = 4.9e-324;
    const double s0[2] = {0, 0}, s1[2] = {t, 0}, s2[2] = {0, t};
    CHECK(flipflop::pred::orient2d_exact(s0, s1, s2, m) == 1);
    // Huge triangle: det = DBL_MAX^2 > 0 (overflows in doubles).
    const double h1[2] = {DBL_MAX, 0}, h2[2] = {0, DBL_MAX};
    CHECK(flipflop::pred::orient2d_exact(s0, h1, h2, m) == 1);
    // (-M,-M), (M,M), (0,0) are collinear; the differences 2M overflow.
    const double g0[2] = {-DBL_MAX, -DBL_MAX}, g1[2] = {DBL_MAX, DBL_MAX};
    CHECK(flipflop::pred::orient2d_exact(g0, g1, s0, m) == 0);
    // Mixed magnitudes: (0,0), (1e300, 0), (-1e300, 2^-1074):
    // det = 1e300 * 2^-1074 - 0 * (-1e300) > 0.
    const double x0[2] = {0, 0}, x1[2] = {1e300, 0}, x2[2] = {-1e300, t};
    CHECK(flipflop::pred::orient2d_exact(x0, x1, x2, m) == 1);

    // orient3d: a, b, c counter-clockwise seen from above (+z). det Λ = det of
    // the rows a-d, b-d, c-d = [[0,0,1],[1,0,1],[0,1,1]] = 1 for d = (0,0,-1)
    // (below the plane: positive), and -1 for d = (0,0,1) (above).
    const double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0};
    const double below[3] = {0, 0, -1}, above[3] = {0, 0, 1}, on[3] = {5, 7, 0};
    CHECK(flipflop::pred::orient3d_exact(A, B, C, below, m) == 1);
    CHECK(flipflop::pred::orient3d_exact(A, B, C, above, m) == -1);
    CHECK(flipflop::pred::orient3d_exact(A, B, C, on, m) == 0);

    // orient_d(e_1, ..., e_d, 0): rows (e_i, 1) and (0, 1). Expanding along the
    // last row (only its 1-column entry is non-zero, sign (-1)^((d+1)+(d+1)) = +1)
    // leaves det(I_d) = 1, so the sign is +1 in every dimension.
    for (int d = 1; d <= 6; ++d) {
      std::vector<std::vector<double>> pts(static_cast<size_t>(d + 1),
                                           std::vector<double>(static_cast<size_t>(d), 0.0));
      for (int i = 0; i < d; ++i) pts[static_cast<size_t>(i)][static_cast<size_t>(i)] = 1.0;
      std::vector<const double*> p;
      for (auto& q : pts) p.push_back(q.data());
      CHECK(flipflop::pred::orient_d_exact(d, p.data(), m) == 1);
      // Swapping the first two points: odd permutation.
      if (d >= 2) {
        std::swap(p[0], p[1]);
        CHECK(flipflop::pred::orient_d_exact(d, p.data(), m) == -1);
      }
    }
  }
}

TEST_CASE("predicates: hand-checked power (incircle / insphere) conventions") {
  for (Mode m : {Mode::filtered, Mode::gmp}) {
    auto w2 = [](const double* x, double w) { return WPt{0, x, w}; };
    // a, b, c counter-clockwise; circumcircle centre (1/2, 1/2), r^2 = 1/2.
    // Lifting (x, y) -> (x, y, x^2 + y^2): the lifted a', b', c' span the plane
    // z = x + y. power2d = orient3d of lifted points, > 0 iff d' lies below that
    // plane, i.e. iff d is inside the circle (Shewchuk's incircle).
    const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
    const double inside[2] = {0.5, 0.5};  // h = 0.5 < 1 = plane
    const double outside[2] = {2, 2};     // h = 8 > 4
    const double cocirc[2] = {1, 1};      // h = 2 = 2
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(inside, 0), m) == 1);
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(outside, 0), m) == -1);
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(cocirc, 0), m) == 0);
    // Swapping a and b reverses the orientation and the sign.
    CHECK(flipflop::pred::power2d_exact(w2(b, 0), w2(a, 0), w2(c, 0), w2(inside, 0), m) == -1);
    // Weights: the power of d = (2,2) to the orthocircle (centre z = (1/2,1/2),
    // r^2 = 1/2) is |d - z|^2 - r^2 - w_d = 4.5 - 0.5 - w_d = 4 - w_d; the answer
    // is positive iff that is negative (closer than orthogonal).
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(outside, 5), m) == 1);
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(outside, 4), m) == 0);
    CHECK(flipflop::pred::power2d_exact(w2(a, 0), w2(b, 0), w2(c, 0), w2(outside, 3), m) == -1);
    // A weight on a lowers a' to height -w_a: the plane through (0,0,-w_a),
    // (1,0,1), (0,1,1) is z = -w_a + (1+w_a)(x+y), at (1,1) it is 2 + w_a, while
    // d' = (1,1,2). w_a = 1: d' below, +1; w_a = -1: d' above, -1.
    CHECK(flipflop::pred::power2d_exact(w2(a, 1), w2(b, 0), w2(c, 0), w2(cocirc, 0), m) == 1);
    CHECK(flipflop::pred::power2d_exact(w2(a, -1), w2(b, 0), w2(c, 0), w2(cocirc, 0), m) == -1);
    // Equal weights shift every height by the same constant: no change.
    CHECK(flipflop::pred::power2d_exact(w2(a, 7), w2(b, 7), w2(c, 7), w2(cocirc, 7), m) == 0);
    CHECK(flipflop::pred::power2d_exact(w2(a, 7), w2(b, 7), w2(c, 7), w2(inside, 7), m) == 1);

    // power3d. With A = 0, B = e1, C = e2, D = e3, the tetrahedron (A, C, B, D)
    // is positively oriented for orient3d (A, C, B clockwise from above, D
    // above). Circumsphere: centre (1/2,1/2,1/2), r^2 = 3/4.
    const double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0}, D[3] = {0, 0, 1};
    const double e_in[3] = {0.25, 0.25, 0.25}, e_on[3] = {1, 1, 1}, e_out[3] = {2, 2, 2};
    CHECK(flipflop::pred::orient3d_exact(A, C, B, D, m) == 1);
    // e_in: the 4x4 determinant of rows (p - e, |p - e|^2) scaled by 4 (and
    // the lifts by 16) is [[-1,-1,-1,3],[-1,3,-1,11],[3,-1,-1,11],[-1,-1,3,11]];
    // subtracting row 1 from the others and then adding 1/4 of rows 2..4 to
    // row 1 gives row 1 = (0,0,0,9) and rows (0,4,0,8), (4,0,0,8), (0,0,4,8):
    // det = 9 * (-1)^(1+4) * det[[0,4,0],[4,0,0],[0,0,4]] = -9 * -64 = 576 > 0.
    CHECK(flipflop::pred::power3d_exact(w2(A, 0), w2(C, 0), w2(B, 0), w2(D, 0), w2(e_in, 0), m) ==
          1);
    // e_on: |e_on - centre|^2 = 3/4 = r^2: cospherical.
    CHECK(flipflop::pred::power3d_exact(w2(A, 0), w2(C, 0), w2(B, 0), w2(D, 0), w2(e_on, 0), m) ==
          0);
    CHECK(flipflop::pred::power3d_exact(w2(A, 0), w2(C, 0), w2(B, 0), w2(D, 0), w2(e_out, 0), m) ==
          -1);
    // Weight 1 on e_on: power = 0 - 1 < 0, closer than orthogonal: +1.
    CHECK(flipflop::pred::power3d_exact(w2(A, 0), w2(C, 0), w2(B, 0), w2(D, 0), w2(e_on, 1), m) ==
          1);

    // power_d(e_1, ..., e_d, 0, q): rows (e_i, 1, 1), (0, 0, 1), (q, |q|^2 - w, 1).
    // Expanding along the row of 0 (one entry, 1 in the last column, sign
    // (-1)^((d+1)+(d+2)) = -1) leaves det [[I, 1],[q^T, s]] = s - Σ q_i with
    // s = |q|^2 - w. So power_d = sign(Σ q_i - |q|^2 + w):
    //   q = (1/2, ..., 1/2), w = 0: d/2 - d/4 > 0  -> +1 (inside);
    //   q = (1, ..., 1),     w = 0: d - d = 0      ->  0 (on the sphere);
    //   q = (2, ..., 2),     w = 0: 2d - 4d < 0    -> -1 (outside);
    //   q = (1, ..., 1),     w = 1: 1 > 0          -> +1.
    // (e_1..e_d, 0) is positively oriented (see orient_d above), so these are
    // the incircle conventions again.
    for (int d = 1; d <= 5; ++d) {
      std::vector<std::vector<double>> pts(static_cast<size_t>(d + 2),
                                           std::vector<double>(static_cast<size_t>(d), 0.0));
      for (int i = 0; i < d; ++i) pts[static_cast<size_t>(i)][static_cast<size_t>(i)] = 1.0;
      std::vector<const double*> p;
      for (auto& q : pts) p.push_back(q.data());
      std::vector<double> w(static_cast<size_t>(d + 2), 0.0);
      auto& q = pts[static_cast<size_t>(d + 1)];
      const std::pair<double, int> cases[] = {{0.5, 1}, {1.0, 0}, {2.0, -1}};
      for (const auto& [v, expected] : cases) {
        std::fill(q.begin(), q.end(), v);
        CHECK(flipflop::pred::power_d_exact(d, p.data(), w.data(), m) == expected);
      }
      std::fill(q.begin(), q.end(), 1.0);
      w[static_cast<size_t>(d + 1)] = 1.0;
      CHECK(flipflop::pred::power_d_exact(d, p.data(), w.data(), m) == 1);
    }
  }
}

// ---- CGAL as an independent oracle for the exact signs --------------------------------
// Sign conventions, from CGAL's predicates/kernel_ftC2.h and kernel_ftC3.h:
//   orientation_2 = sign det(q-p, r-p) = det Λ(p,q,r) (1-column first or last:
//     a cyclic shift of 3 columns, even)                      -> same sign;
//   side_of_oriented_circle, power_side_of_oriented_power_circle = sign of
//     det [p-t, |p-t|^2 - w_p + w_t] (rows p, q, r), our lifted det      -> same;
//   orientation_3 = sign det(q-p, r-p, s-p) = det Λ with the 1-column first;
//     moving it last is a cyclic shift of 4 columns (odd)     -> opposite sign;
//   side_of_oriented_sphere = sign det(P,R,Q,S) (rows swapped, source comment),
//   power_side_of_oriented_power_sphere = -sign det(P,Q,R,S)  -> opposite sign.
namespace {

template <class K>
struct CgalSigns {
  using P2 = typename K::Point_2;
  using P3 = typename K::Point_3;
  using W2 = typename K::Weighted_point_2;
  using W3 = typename K::Weighted_point_3;

  static P2 p2(const Instance& in, int i) { return P2(in.p(i)[0], in.p(i)[1]); }
  static P3 p3(const Instance& in, int i) { return P3(in.p(i)[0], in.p(i)[1], in.p(i)[2]); }
  static W2 w2(const Instance& in, int i) { return W2(p2(in, i), in.w[static_cast<size_t>(i)]); }
  static W3 w3(const Instance& in, int i) { return W3(p3(in, i), in.w[static_cast<size_t>(i)]); }

  static int orient2d(const Instance& in) {
    return static_cast<int>(CGAL::orientation(p2(in, 0), p2(in, 1), p2(in, 2)));
  }
  static int orient3d(const Instance& in) {
    return -static_cast<int>(CGAL::orientation(p3(in, 0), p3(in, 1), p3(in, 2), p3(in, 3)));
  }
  static int incircle(const Instance& in) {
    return static_cast<int>(CGAL::side_of_oriented_circle(p2(in, 0), p2(in, 1), p2(in, 2), p2(in, 3)));
  }
  static int power2d(const Instance& in) {
    return static_cast<int>(
        CGAL::power_side_of_oriented_power_circle(w2(in, 0), w2(in, 1), w2(in, 2), w2(in, 3)));
  }
  static int insphere(const Instance& in) {
    return -static_cast<int>(
        CGAL::side_of_oriented_sphere(p3(in, 0), p3(in, 1), p3(in, 2), p3(in, 3), p3(in, 4)));
  }
  static int power3d(const Instance& in) {
    return -static_cast<int>(CGAL::power_side_of_oriented_power_sphere(w3(in, 0), w3(in, 1), w3(in, 2),
                                                                       w3(in, 3), w3(in, 4)));
  }
};

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Rational = CGAL::Simple_cartesian<CGAL::Exact_rational>;

template <class K>
void check_against_cgal(const Spec& s, const Instance& in, int ours) {
  using C = CgalSigns<K>;
  switch (s.kind) {
    case Kind::orient2d: RC_ASSERT(C::orient2d(in) == ours); break;
    case Kind::orient3d: RC_ASSERT(C::orient3d(in) == ours); break;
    case Kind::power2d: {
      RC_ASSERT(C::power2d(in) == ours);
      Instance zero = in;
      std::fill(zero.w.begin(), zero.w.end(), 0.0);
      RC_ASSERT(C::incircle(zero) == eval(s, zero, false, Mode::gmp));
      break;
    }
    case Kind::power3d: {
      RC_ASSERT(C::power3d(in) == ours);
      Instance zero = in;
      std::fill(zero.w.begin(), zero.w.end(), 0.0);
      RC_ASSERT(C::insphere(zero) == eval(s, zero, false, Mode::gmp));
      break;
    }
    default: break;
  }
}

}  // namespace

TEST_CASE("predicates: CGAL exact kernels agree with the exact signs") {
  const Spec specs[] = {{Kind::orient2d, 2}, {Kind::orient3d, 3}, {Kind::power2d, 2},
                        {Kind::power3d, 3}};
  for (const Spec& s : specs) {
    rc::prop(s.name() + " vs CGAL", [s] {
      const Instance in = gen_any(s);
      RC_LOG() << describe(s, in);
      const int ours = eval(s, in, false, Mode::filtered);
      check_against_cgal<Epick>(s, in, ours);
      check_against_cgal<Rational>(s, in, ours);
    });
  }
}

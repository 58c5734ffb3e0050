// sos_test.cpp — Simulation of Simplicity (predicates.hpp) checked against an
// independent oracle, plus hand-worked cases.
//
// The oracle (property (e)) does not use the dominance order or the search of
// predicates/exact.cpp at all: it substitutes a concrete, provably small
// enough ε into the perturbation of DESIGN.md,
//
//     c(i,j) + ε^(2^(i·δ - j)),   i = id + 1, j = 1..δ,
//
// (δ = number of non-constant columns of the Λ-matrix, a lifted height being
// column δ), and computes the determinant of the perturbed Λ-matrix exactly.
//
// Why a concrete ε decides the sign. Expanding the determinant multilinearly,
//     det Λ(ε) = Σ_T c_T ε^(E_T),
// a sum over partial matchings T of perturbed entries (at most one per row
// and per column), c_T = ± the complementary minor of the integer matrix and
// E_T = Σ_{(i,j)∈T} 2^(iδ-j). Distinct entries carry distinct powers of two,
// so distinct matchings have distinct exponents E_T. Let T* be the non-zero
// term of least exponent E*. Then |c_T*| >= 1 (an integer), every other
// non-zero term has E_T >= E* + 1, and with B >= |c_T| for all T and N the
// number of matchings,
//     |Σ_{T≠T*} c_T ε^(E_T)| <= N·B·ε^(E*+1) < ε^(E*) <= |c_T*| ε^(E*)
// as soon as N·B·ε < 1 (and ε <= 1/2). So sign det Λ(ε) = sign c_T*, which is
// the sign of the perturbed determinant for every small enough ε > 0, i.e.
// the SoS sign. B is bounded by Hadamard's inequality with 1-norms: every
// minor is at most Π_columns max(1, Σ_rows |entry|); N = Σ_r C(k,r) C(δ,r) r!.
// The test computes both per case and takes ε = 2^-e with 2^e > N·B.
//
// Cost. With ε = 2^-e the perturbed entries are integers after scaling every
// entry by 2^(e·Emax), Emax = 2^(iδ-1) for the largest i: numbers of e·Emax
// bits. Inputs are small integers (|x| <= 5, |h| <= 60), so e is about 22, and
// with ids <= 5 and δ = 3 the numbers would have 22·2^17 ≈ 2.9M bits, far
// too slow for thousands of cases. The properties therefore use ids 0..5 for
// orient2d (δ = 2: ~45k bits) with the full case count, ids 0..3 for orient3d
// and power2d (δ = 3: ~45k bits, a few ms per case) with a quarter of the
// cases, and ids 0..4 (~360k bits, 40-60 ms per case) with a hundredth. Only the
// order of the ids matters to SoS (checked below), so ids 0..3 already cover
// every ordering of four distinct points.
#include <gmpxx.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <vector>

#include "predicates/exact_expansion.hpp"
#include "predicates/predicates.hpp"
#include "predicates/staged.hpp"
#include "proptests/support/predicate_inputs.hpp"
#include "proptests/support/rc_scaled.hpp"

using flipflop::pred::Mode;
using flipflop::pred::PointId;
using flipflop::pred::Pt;
using flipflop::pred::WPt;
using namespace flipflop::test;

namespace {

// ---- the oracle ----------------------------------------------------------------------

using IntMatrix = std::vector<std::vector<long>>;

// The integer Λ-matrix of an instance with small-integer coordinates and
// weights: rows (x_1..x_d, [|x|^2 - w], 1).
IntMatrix int_lambda(const Spec& s, const Instance& in) {
  IntMatrix a(static_cast<size_t>(in.k));
  for (int r = 0; r < in.k; ++r) {
    auto& row = a[static_cast<size_t>(r)];
    long h = 0;
    for (int j = 0; j < in.d; ++j) {
      const long v = static_cast<long>(in.p(r)[j]);
      row.push_back(v);
      h += v * v;
    }
    if (s.weighted()) row.push_back(h - static_cast<long>(in.w[static_cast<size_t>(r)]));
    row.push_back(1);
  }
  return a;
}

// Determinant by Laplace expansion along the first remaining row (k <= 4).
mpz_class det_laplace(const std::vector<std::vector<mpz_class>>& m, size_t row, unsigned cols) {
  if (cols == 0) return 1;
  mpz_class sum = 0;
  int pos = 0;
  for (size_t c = 0; c < m.size(); ++c) {
    if (!(cols & (1u << c))) continue;
    const mpz_class& entry = m[row][c];
    if (entry != 0) {
      mpz_class term = entry * det_laplace(m, row + 1, cols & ~(1u << c));
      if (pos & 1) sum -= term; else sum += term;
    }
    ++pos;
  }
  return sum;
}

long binomial(int n, int r) {
  long b = 1;
  for (int i = 1; i <= r; ++i) b = b * (n - r + i) / i;
  return b;
}

// Sign of det Λ(ε) for the concrete ε of the header comment.
int oracle_sos_sign(const IntMatrix& a, const std::vector<PointId>& ids) {
  const int k = static_cast<int>(a.size());
  const int delta = k - 1;
  // B: product of the columns' 1-norms (at least 1 each); N: matchings.
  mpz_class bound = 1;
  for (int c = 0; c < k; ++c) {
    long norm = 0;
    for (int r = 0; r < k; ++r) norm += std::labs(a[static_cast<size_t>(r)][static_cast<size_t>(c)]);
    bound *= std::max(1L, norm);
  }
  long matchings = 0, factorial = 1;
  for (int r = 0; r <= std::min(k, delta); ++r) {
    if (r > 0) factorial *= r;
    matchings += binomial(k, r) * binomial(delta, r) * factorial;
  }
  bound *= matchings;
  const unsigned long e = mpz_sizeinbase(bound.get_mpz_t(), 2) + 1;  // 2^e > N·B, e >= 2
  // Exponent of ε on entry (row r, column j = 1..δ): 2^(iδ - j), i = id + 1.
  auto exponent = [&](int r, int j) {
    return std::uint64_t(1) << ((ids[static_cast<size_t>(r)] + 1) * delta - static_cast<unsigned>(j));
  };
  std::uint64_t emax = 0;
  for (int r = 0; r < k; ++r) emax = std::max(emax, exponent(r, 1));
  // Scale every entry by 2^L, L = e·Emax: entry·2^L + 2^(L - e·exponent).
  const std::uint64_t scale = e * emax;
  std::vector<std::vector<mpz_class>> m(static_cast<size_t>(k),
                                        std::vector<mpz_class>(static_cast<size_t>(k)));
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < k; ++c) {
      mpz_class& v = m[static_cast<size_t>(r)][static_cast<size_t>(c)];
      v = a[static_cast<size_t>(r)][static_cast<size_t>(c)];
      mpz_mul_2exp(v.get_mpz_t(), v.get_mpz_t(), scale);
      if (c < delta) {
        mpz_class eps;
        mpz_setbit(eps.get_mpz_t(), scale - e * exponent(r, c + 1));
        v += eps;
      }
    }
  }
  return sgn(det_laplace(m, 0, (1u << k) - 1u));
}

// ---- small-integer inputs (|x| <= 5), mostly degenerate ---------------------------------

Instance gen_small_int(const Spec& s, int max_id) {
  Instance in;
  in.d = s.d;
  in.k = s.points();
  in.x.assign(static_cast<size_t>(in.k * in.d), 0.0);
  in.w.assign(static_cast<size_t>(in.k), 0.0);
  auto ints = [](int lo, int hi) { return static_cast<double>(*rc::gen::inRange(lo, hi + 1)); };
  const int mode = *rc::gen::inRange(0, 5);
  switch (mode) {
    case 0:  // tiny grid
      for (double& v : in.x) v = ints(-2, 2);
      for (double& v : in.w) v = s.weighted() ? ints(-3, 3) : 0.0;
      break;
    case 1: {  // on a line (collinear; for 3D also coplanar): p + t·v
      std::vector<double> p(static_cast<size_t>(s.d)), v(static_cast<size_t>(s.d));
      for (double& c : p) c = ints(-2, 2);
      for (double& c : v) c = ints(-1, 1);
      for (int i = 0; i < in.k; ++i) {
        const double t = ints(-3, 3);
        for (int j = 0; j < s.d; ++j) in.p(i)[j] = p[static_cast<size_t>(j)] + t * v[static_cast<size_t>(j)];
      }
      for (double& w : in.w) w = s.weighted() ? ints(-4, 4) : 0.0;
      break;
    }
    case 2: {  // 2D: lattice points of x^2 + y^2 = 25 with equal weights;
               // 3D: a plane p + s·u + t·v
      if (s.d == 2) {
        const auto& circle = lattice_sphere(2, 25);
        const double wall = ints(-3, 3);
        for (int i = 0; i < in.k; ++i) {
          const auto& q = circle[static_cast<size_t>(*rc::gen::inRange<size_t>(0, circle.size()))];
          in.p(i)[0] = q[0];
          in.p(i)[1] = q[1];
          in.w[static_cast<size_t>(i)] = s.weighted() ? wall : 0.0;
        }
      } else {
        std::vector<double> p(3), u(3), v(3);
        for (double& c : p) c = ints(-2, 2);
        for (double& c : u) c = ints(-1, 1);
        for (double& c : v) c = ints(-1, 1);
        for (int i = 0; i < in.k; ++i) {
          const double a = ints(-1, 1), b = ints(-1, 1);
          for (int j = 0; j < 3; ++j)
            in.p(i)[j] = p[static_cast<size_t>(j)] + a * u[static_cast<size_t>(j)] + b * v[static_cast<size_t>(j)];
        }
      }
      break;
    }
    case 3: {  // power2d: lifted points on a plane, w = |x|^2 - αx - βy - γ
      for (double& v : in.x) v = ints(-3, 3);
      const double al = ints(-2, 2), be = ints(-2, 2), ga = ints(-3, 3);
      for (int i = 0; i < in.k; ++i) {
        const double x = in.p(i)[0], y = in.p(i)[1];
        in.w[static_cast<size_t>(i)] = s.weighted() ? x * x + y * y - al * x - be * y - ga : 0.0;
      }
      if (s.d == 3)
        for (int i = 0; i < in.k; ++i) in.p(i)[2] = ints(-1, 1);
      break;
    }
    default: {  // all points equal
      for (int j = 0; j < s.d; ++j) in.p(0)[j] = ints(-5, 5);
      in.w[0] = s.weighted() ? ints(-5, 5) : 0.0;
      for (int i = 1; i < in.k; ++i) {
        for (int j = 0; j < s.d; ++j) in.p(i)[j] = in.p(0)[j];
        in.w[static_cast<size_t>(i)] = in.w[0];
      }
      break;
    }
  }
  // Ids: k distinct values of 0..max_id (a random arrangement), or with one
  // repeat (the same point twice, copied with its weight).
  std::vector<int> perm = gen_permutation(max_id + 1);
  in.id.resize(static_cast<size_t>(in.k));
  for (int i = 0; i < in.k; ++i) in.id[static_cast<size_t>(i)] = static_cast<PointId>(perm[static_cast<size_t>(i)]);
  if (*rc::gen::inRange(0, 5) == 0) {
    const int a = *rc::gen::inRange(0, in.k);
    const int b = (a + *rc::gen::inRange(1, in.k)) % in.k;
    for (int j = 0; j < in.d; ++j) in.p(b)[j] = in.p(a)[j];
    in.w[static_cast<size_t>(b)] = in.w[static_cast<size_t>(a)];
    in.id[static_cast<size_t>(b)] = in.id[static_cast<size_t>(a)];
  }
  return in;
}

// The SoS search on double minors alone (xp::sos_sign_doubles, the first SoS
// step of the default path when det Λ = 0): rows sorted by id as lambda_exact
// sorts them; 2 when it leaves the call to the expansions, or when it does not
// apply (a repeated id, det Λ != 0).
template <int K>
int sos_doubles(const Instance& in, bool lifted) {
  const double* p[K];
  for (int i = 0; i < K; ++i) p[i] = in.p(i);
  const double* w = lifted ? in.w.data() : nullptr;
  if (flipflop::pred::stage::gmp(K, p, w) != 0) return 2;
  int order[K];
  const int parity = flipflop::pred::sort_rows_by_id(K, in.id.data(), order);
  if (parity == 0) return 2;
  const double* sp[K];
  double sw[K];
  for (int i = 0; i < K; ++i) {
    sp[i] = p[order[i]];
    sw[i] = lifted ? w[order[i]] : 0.0;
  }
  const int s = flipflop::pred::xp::sos_sign_doubles<K>(sp, lifted ? sw : nullptr);
  return s == 2 ? 2 : parity * s;
}

void check_oracle(const Spec& s, int max_id) {
  const Instance in = gen_small_int(s, max_id);
  RC_LOG() << describe(s, in);
  const int expected = oracle_sos_sign(int_lambda(s, in), in.id);
  RC_ASSERT(eval(s, in, true, Mode::gmp) == expected);
  RC_ASSERT(eval(s, in, true, Mode::filtered) == expected);
  const int d = in.k == 3 ? sos_doubles<3>(in, s.weighted()) : sos_doubles<4>(in, s.weighted());
  RC_LOG() << "sos_sign_doubles " << d << "\n";
  RC_ASSERT((d == 2 || d == expected));
}

}  // namespace

// ---- (e) the concrete-ε oracle ------------------------------------------------------------
TEST_CASE("sos: agrees with the determinant at a concrete tiny epsilon") {
  const Spec o2{Kind::orient2d, 2}, o3{Kind::orient3d, 3}, p2{Kind::power2d, 2};
  rc::prop("orient2d, ids 0..5", [o2] { check_oracle(o2, 5); });
  // δ = 3: ~2-3 ms per case with ids 0..3, 40-60 ms with ids 0..4.
  prop_scaled("orient3d, ids 0..3", 4, [o3] { check_oracle(o3, 3); });
  prop_scaled("power2d, ids 0..3", 4, [p2] { check_oracle(p2, 3); });
  prop_scaled("orient3d, ids 0..4", 100, [o3] { check_oracle(o3, 4); });
  prop_scaled("power2d, ids 0..4", 100, [p2] { check_oracle(p2, 4); });
}

// ---- only the order of the ids matters -------------------------------------------------
// The dominance order (predicates.hpp) compares rows by index only, so any
// strictly increasing relabelling of the ids leaves every SoS sign unchanged.
TEST_CASE("sos: invariant under order-preserving relabelling of the ids") {
  for (const Spec& s : all_specs()) {
    rc::prop(s.name(), [s] {
      const Instance in = gen_any(s);
      RC_LOG() << describe(s, in);
      std::vector<int> order(static_cast<size_t>(in.k));
      for (int i = 0; i < in.k; ++i) order[static_cast<size_t>(i)] = i;
      std::sort(order.begin(), order.end(), [&](int a, int b) {
        return in.id[static_cast<size_t>(a)] < in.id[static_cast<size_t>(b)];
      });
      Instance re = in;
      PointId next = *rc::gen::inRange<PointId>(0, 1000);
      for (int r : order) {
        re.id[static_cast<size_t>(r)] = next;
        next += *rc::gen::inRange<PointId>(1, PointId(1) << 32);
      }
      const Mode m = *rc::gen::element(Mode::filtered, Mode::gmp);
      RC_ASSERT(eval(s, re, true, m) == eval(s, in, true, m));
    });
  }
}

// ---- (f) hand-worked SoS cases --------------------------------------------------------------
// Rows are sorted by id (index i = id + 1); the dominance order of
// predicates.hpp visits matchings from the row of the largest index down,
// "not perturbed" first, then larger column numbers j first. The first
// non-zero cofactor decides. Every expected value below is worked out by hand
// in its comment and cross-checked geometrically.
TEST_CASE("sos: hand-worked cases") {
  for (Mode m : {Mode::filtered, Mode::gmp}) {
    const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {2, 0};
    // Collinear on the x-axis, ids a:0, b:1, c:2. det Λ = 0, rows b and c
    // unperturbed; on row a (id 0) the y-entry (j = 2) comes first: cofactor
    // (-1)^(1+2) det [[b_x, 1], [c_x, 1]] = -(1 - 2) = +1. Geometrically a
    // moves up by ε^(2^0) = ε, above the line b -> c: counter-clockwise.
    CHECK(flipflop::pred::orient2d(Pt{0, a}, Pt{1, b}, Pt{2, c}, m) == 1);
    // Ids a:1, b:0, c:2: sorted rows (b, a, c), an odd permutation of (a, b, c).
    // Cofactor of b's y-entry: -det [[a_x, 1], [c_x, 1]] = -(0 - 2) = 2 > 0,
    // times the parity -1: -1. Geometrically b moves up: a -> b -> c turns right.
    CHECK(flipflop::pred::orient2d(Pt{1, a}, Pt{0, b}, Pt{2, c}, m) == -1);
    // Large ids with gaps, same order as the first case: same answer.
    CHECK(flipflop::pred::orient2d(Pt{10, a}, Pt{1000, b}, Pt{~PointId(0), c}, m) == 1);

    // Three copies of p = (3, -7), ids 0, 1, 2. Every minor with two rows of
    // the same point vanishes; the first non-zero term deletes (row 2, y) and
    // (row 1, x), leaving the 1x1 minor "1" of row 3's 1-column, Laplace signs
    // (+1)(+1): +1. Check: with q_t = p + (ε^(2^(2t-1)), ε^(2^(2t-2))),
    // (q1 - q3) x (q2 - q3) = ε^2·ε^4 - ε·ε^8 + o(...) = ε^6 - ε^9 > 0.
    const double p[2] = {3, -7};
    CHECK(flipflop::pred::orient2d(Pt{0, p}, Pt{1, p}, Pt{2, p}, m) == 1);
    // Same points, arguments in an odd arrangement of the ids: -1.
    CHECK(flipflop::pred::orient2d(Pt{1, p}, Pt{0, p}, Pt{2, p}, m) == -1);
    // A repeated id: the same point twice, 0.
    CHECK(flipflop::pred::orient2d(Pt{4, a}, Pt{4, a}, Pt{2, c}, m) == 0);

    // power2d, zero weights, the cocircular square a=(0,0):0, b=(1,0):1,
    // c=(0,1):2, d=(1,1):3 (det Λ = 0, rows (x, y, h, 1)). Rows d, c, b
    // unperturbed; row a's height (j = 3) first: cofactor (-1)^(1+3) det of
    // rows b, c, d on columns (x, y, 1) = orient2d(b, c, d) = (-1,1) x (0,1) = -1.
    // Geometrically: raising a' by ε tilts the plane down at d, d' is above: -1.
    const double sq_a[2] = {0, 0}, sq_b[2] = {1, 0}, sq_c[2] = {0, 1}, sq_d[2] = {1, 1};
    CHECK(flipflop::pred::power2d(WPt{0, sq_a, 0}, WPt{1, sq_b, 0}, WPt{2, sq_c, 0},
                                  WPt{3, sq_d, 0}, m) == -1);
    // Same square, ids a:3, b:1, c:2, d:0: now d (smallest index) has the
    // dominant perturbation, its height. In argument order d's row is row 4:
    // cofactor (-1)^(4+3) det of rows a, b, c on (x, y, 1) = -orient2d(a, b, c)
    // = -1. Geometrically d' moves up, above the plane of a', b', c': -1.
    CHECK(flipflop::pred::power2d(WPt{3, sq_a, 0}, WPt{1, sq_b, 0}, WPt{2, sq_c, 0},
                                  WPt{0, sq_d, 0}, m) == -1);

    // orient3d, coplanar in z = 0: a=(0,0,0):0, b=(1,0,0):1, c=(0,1,0):2,
    // d=(1,1,0):3. First term: a's z (j = 3), cofactor (-1)^(1+3) det of rows
    // b, c, d on (x, y, 1) = orient2d(b, c, d) = -1. Geometrically a rises to
    // z = ε; the plane through a', b, c is z = ε(1 - x - y), at (1,1) it is -ε,
    // so d lies above it, and a, b, c are counter-clockwise from above: -1.
    const double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0}, D[3] = {1, 1, 0};
    CHECK(flipflop::pred::orient3d(Pt{0, A}, Pt{1, B}, Pt{2, C}, Pt{3, D}, m) == -1);
    CHECK(flipflop::pred::orient3d_exact(A, B, C, D, m) == 0);
  }
}

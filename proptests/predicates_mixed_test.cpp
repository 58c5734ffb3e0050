// predicates_mixed_test.cpp — the mixed predicates (rows of input points and
// one exact rational point, the kernel point of the hulls: a centroid of 1, 2,
// 4 or 8 input points, rational_point.hpp) on the default path equal the GMP
// oracle, exact and under Simulation of Simplicity; the semi-static filter for
// one approximate row (static_filter.hpp, (5)) returns 0 or the GMP sign.
//
// Families: uniform values on the 2^-53 grid; exactly degenerate (every point,
// the centroid's sources included, on one integer line / plane, so the
// centroid is on it too and SoS decides); near-degenerate (the same, every
// value moved by 0..3 ulps); extreme magnitudes (predicate_inputs.hpp).
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <array>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "predicates/rational_point.hpp"
#include "predicates/static_filter.hpp"
#include "proptests/support/predicate_inputs.hpp"

namespace {

using namespace flipflop;
using pred::Mode;

enum class Fam { uniform, degenerate, near, extreme };

const char* fam_name(Fam f) {
  switch (f) {
    case Fam::uniform: return "uniform";
    case Fam::degenerate: return "exactly degenerate";
    case Fam::near: return "near-degenerate";
    default: return "extreme";
  }
}

// One point of dimension dim in the family. For the degenerate families all
// points lie on the flat x_{dim-1} = Σ_j a_j x_j + b (small integers).
std::vector<double> gen_point(Fam f, int dim, const std::array<int, 3>& flat) {
  std::vector<double> x(static_cast<size_t>(dim));
  switch (f) {
    case Fam::uniform:
      for (auto& v : x) v = test::gen_unit();
      break;
    case Fam::extreme:
      for (auto& v : x) v = test::gen_extreme_value();
      break;
    default: {
      double last = flat[2];
      for (int j = 0; j + 1 < dim; ++j) {
        x[static_cast<size_t>(j)] = *rc::gen::inRange(-20, 21);
        last += flat[static_cast<size_t>(j)] * x[static_cast<size_t>(j)];
      }
      x[static_cast<size_t>(dim - 1)] = last;
      if (f == Fam::near)
        for (auto& v : x) v = test::gen_nudged(v);
      break;
    }
  }
  return x;
}

void check_mixed(int k, Fam fam) {
  const int dim = k - 1;
  const std::array<int, 3> flat = {*rc::gen::inRange(-3, 4), *rc::gen::inRange(-3, 4),
                                   *rc::gen::inRange(-5, 6)};
  const int count = *rc::gen::element(1, 2, 4, 8);
  std::vector<std::vector<double>> src;
  std::vector<const double*> sp;
  for (int i = 0; i < count; ++i) src.push_back(gen_point(fam, dim, flat));
  for (auto& s : src) sp.push_back(s.data());
  const pred::RationalPoint rp = pred::RationalPoint::centroid(sp.data(), count, dim);
  std::vector<std::vector<double>> pts;
  for (int i = 0; i + 1 < k; ++i) {
    // sometimes a source of the centroid itself, or a repeated point
    const int pick = *rc::gen::inRange(0, 4);
    if (pick == 0) pts.push_back(src[static_cast<size_t>(*rc::gen::inRange(0, count))]);
    else if (pick == 1 && !pts.empty()) pts.push_back(pts.back());
    else pts.push_back(gen_point(fam, dim, flat));
  }
  const int r = *rc::gen::inRange(0, k);
  const std::vector<pred::PointId> ids = test::gen_distinct_ids(k);
  std::vector<pred::MixedRow> rows(static_cast<size_t>(k));
  std::vector<const double*> approx_rows(static_cast<size_t>(k));
  double q[3], err[3];
  for (int j = 0; j < dim; ++j) {
    q[j] = rp.approx[j].v;
    err[j] = rp.approx[j].e;
  }
  for (int i = 0, t = 0; i < k; ++i) {
    rows[static_cast<size_t>(i)].id = ids[static_cast<size_t>(i)];
    if (i == r) {
      rows[static_cast<size_t>(i)].r = &rp;
      approx_rows[static_cast<size_t>(i)] = q;
    } else {
      rows[static_cast<size_t>(i)].x = pts[static_cast<size_t>(t)].data();
      approx_rows[static_cast<size_t>(i)] = pts[static_cast<size_t>(t++)].data();
    }
  }
  const int g = pred::mixed_sign(k, rows.data(), false, Mode::gmp);
  const int gs = pred::mixed_sign(k, rows.data(), true, Mode::gmp);
  RC_ASSERT(pred::mixed_sign(k, rows.data(), false, Mode::filtered) == g);
  RC_ASSERT(pred::mixed_sign(k, rows.data(), true, Mode::filtered) == gs);
  RC_ASSERT(gs != 0);
  int s = 0;
  switch (k) {
    case 2: s = pred::mixed_semi_static_sign<2>(approx_rows.data(), r, err); break;
    case 3: s = pred::mixed_semi_static_sign<3>(approx_rows.data(), r, err); break;
    default: s = pred::mixed_semi_static_sign<4>(approx_rows.data(), r, err); break;
  }
  RC_ASSERT(s == 0 || s == g);
  if (fam == Fam::uniform) RC_TAG(s != 0 ? "filter decided" : "filter undecided");
}

}  // namespace

TEST_CASE("mixed predicates: default path and semi-static filter equal GMP") {
  for (int k = 2; k <= 4; ++k)
    for (Fam f : {Fam::uniform, Fam::degenerate, Fam::near, Fam::extreme})
      rc::prop("k = " + std::to_string(k) + ", " + fam_name(f), [k, f] { check_mixed(k, f); });
}

TEST_CASE("mixed predicates: the filter decides ordinary kernel-point calls") {
  // A kernel point inside a tetrahedron, query planes through three far points:
  // the semi-static filter must decide (it is what makes the hull fast).
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  const double* src[4] = {a, b, c, d};
  const pred::RationalPoint rp = pred::RationalPoint::centroid(src, 4, 3);
  const double q[3] = {rp.approx[0].v, rp.approx[1].v, rp.approx[2].v};
  const double err[3] = {rp.approx[0].e, rp.approx[1].e, rp.approx[2].e};
  const double* rows[4] = {b, c, d, q};
  const int s = pred::mixed_semi_static_sign<4>(rows, 3, err);
  const pred::MixedRow mr[4] = {{1, b, nullptr}, {2, c, nullptr}, {3, d, nullptr}, {9, nullptr, &rp}};
  CHECK(s != 0);
  CHECK(s == pred::mixed_sign(4, mr, false, Mode::gmp));
}

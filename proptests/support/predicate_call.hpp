// predicate_call.hpp — one predicate instance (points, weights, ids) and a
// uniform way to call any of the 13 predicates under test on it. Used by the
// property tests (proptests/) and by the fuzz target (fuzz/); no RapidCheck here.
//
// A predicate instance is k points of R^d (point-major doubles), their weights
// (power predicates only) and their ids (the SoS perturbation order,
// predicates.hpp). `Spec` names one of the predicates: orient2d, orient3d,
// power2d, power3d, orient_d (d = 2..6), power_d (d = 2..5).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "predicates/predicates.hpp"

namespace flipflop::test {

using pred::Mode;
using pred::PointId;

enum class Kind { orient2d, orient3d, power2d, power3d, orient_d, power_d };

struct Spec {
  Kind kind;
  int d;  // dimension of the points

  bool weighted() const {
    return kind == Kind::power2d || kind == Kind::power3d || kind == Kind::power_d;
  }
  // orient: d+1 points in R^d; power: d+2 weighted points in R^d.
  int points() const { return weighted() ? d + 2 : d + 1; }
  std::string name() const {
    switch (kind) {
      case Kind::orient2d: return "orient2d";
      case Kind::orient3d: return "orient3d";
      case Kind::power2d: return "power2d";
      case Kind::power3d: return "power3d";
      case Kind::orient_d: return "orient_d(" + std::to_string(d) + ")";
      case Kind::power_d: return "power_d(" + std::to_string(d) + ")";
    }
    return "?";
  }
};

inline std::vector<Spec> all_specs() {
  std::vector<Spec> s = {{Kind::orient2d, 2}, {Kind::orient3d, 3}, {Kind::power2d, 2},
                         {Kind::power3d, 3}};
  for (int d = 2; d <= 6; ++d) s.push_back({Kind::orient_d, d});
  for (int d = 2; d <= 5; ++d) s.push_back({Kind::power_d, d});
  return s;
}

// The host-only sizes, 9..11 rows (predicates.hpp, lambda_sign_high):
// orient_d in 8D..10D, power_d in 7D..9D (7D orient_d and 6D power_d, 8 rows,
// take the staged path like all_specs()).
inline std::vector<Spec> high_specs() {
  std::vector<Spec> s;
  for (int d = 7; d <= 10; ++d) s.push_back({Kind::orient_d, d});
  for (int d = 6; d <= 9; ++d) s.push_back({Kind::power_d, d});
  return s;
}

struct Instance {
  int d = 0;                // coordinates per point
  int k = 0;                // number of points
  std::vector<double> x;    // k*d, point-major
  std::vector<double> w;    // k weights (all zero for orientation predicates)
  std::vector<PointId> id;  // k ids
  const double* p(int i) const { return x.data() + static_cast<size_t>(i) * d; }
  double* p(int i) { return x.data() + static_cast<size_t>(i) * d; }
};

// Exact hexadecimal rendering, so that a counterexample can be replayed.
inline std::string describe(const Spec& s, const Instance& in) {
  std::string out = s.name() + " points:\n";
  char buf[64];
  for (int i = 0; i < in.k; ++i) {
    out += "  id " + std::to_string(in.id[static_cast<size_t>(i)]) + " (";
    for (int j = 0; j < in.d; ++j) {
      std::snprintf(buf, sizeof buf, "%a%s", in.p(i)[j], j + 1 < in.d ? ", " : "");
      out += buf;
    }
    std::snprintf(buf, sizeof buf, ") w %a\n", in.w[static_cast<size_t>(i)]);
    out += buf;
  }
  return out;
}

// ---- calling the predicates --------------------------------------------------

// The predicate `s` on `in`: the exact sign of the unperturbed determinant
// (sos = false) or the SoS sign keyed by in.id (sos = true).
inline int eval(const Spec& s, const Instance& in, bool sos, Mode m) {
  using namespace pred;
  auto pt = [&](int i) { return Pt{in.id[static_cast<size_t>(i)], in.p(i)}; };
  auto wpt = [&](int i) {
    return WPt{in.id[static_cast<size_t>(i)], in.p(i), in.w[static_cast<size_t>(i)]};
  };
  switch (s.kind) {
    case Kind::orient2d:
      return sos ? orient2d(pt(0), pt(1), pt(2), m) : orient2d_exact(in.p(0), in.p(1), in.p(2), m);
    case Kind::orient3d:
      return sos ? orient3d(pt(0), pt(1), pt(2), pt(3), m)
                 : orient3d_exact(in.p(0), in.p(1), in.p(2), in.p(3), m);
    case Kind::power2d:
      return sos ? power2d(wpt(0), wpt(1), wpt(2), wpt(3), m)
                 : power2d_exact(wpt(0), wpt(1), wpt(2), wpt(3), m);
    case Kind::power3d:
      return sos ? power3d(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4), m)
                 : power3d_exact(wpt(0), wpt(1), wpt(2), wpt(3), wpt(4), m);
    case Kind::orient_d: {
      std::vector<Pt> pts;
      std::vector<const double*> ps;
      for (int i = 0; i < in.k; ++i) {
        pts.push_back(pt(i));
        ps.push_back(in.p(i));
      }
      return sos ? orient_d(s.d, pts.data(), m) : orient_d_exact(s.d, ps.data(), m);
    }
    case Kind::power_d: {
      std::vector<WPt> pts;
      std::vector<const double*> ps;
      for (int i = 0; i < in.k; ++i) {
        pts.push_back(wpt(i));
        ps.push_back(in.p(i));
      }
      return sos ? power_d(s.d, pts.data(), m) : power_d_exact(s.d, ps.data(), in.w.data(), m);
    }
  }
  return 2;  // unreachable: every Kind is handled above
}

// ---- permutations --------------------------------------------------------------

// Rows permuted: row i of the result is row perm[i] of `in` (ids travel along).
inline Instance permuted(const Instance& in, const std::vector<int>& perm) {
  Instance out = in;
  for (int i = 0; i < in.k; ++i) {
    const int src = perm[static_cast<size_t>(i)];
    for (int j = 0; j < in.d; ++j) out.p(i)[j] = in.p(src)[j];
    out.w[static_cast<size_t>(i)] = in.w[static_cast<size_t>(src)];
    out.id[static_cast<size_t>(i)] = in.id[static_cast<size_t>(src)];
  }
  return out;
}

// +1 for an even permutation, -1 for an odd one (parity of the inversions).
inline int permutation_sign(const std::vector<int>& perm) {
  int s = 1;
  for (size_t i = 0; i < perm.size(); ++i)
    for (size_t j = i + 1; j < perm.size(); ++j)
      if (perm[i] > perm[j]) s = -s;
  return s;
}

}  // namespace flipflop::test

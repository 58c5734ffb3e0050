// rational_point.hpp — predicates on rows that mix input points (doubles) with
// a point whose coordinates are exact dyadic rationals but not doubles: the
// kernel point of the 3D certifier (the centroid of four input points, thesis
// §6.4.2 warns against rounding it), and later the kernel points of ffHull.
//
// Such a point takes part in the same Simulation of Simplicity as the inputs
// (predicates.hpp): it carries an index after all inputs (the first auxiliary
// point of a computation gets index n).
#pragma once

#include <vector>

#include "predicates/err_double.hpp"
#include "predicates/exact.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::pred {

struct RationalPoint {
  int dim = 0;
  ErrDouble approx[3];               // filter view: value and error bound
  std::vector<exact::Dyadic> exact;  // exact coordinates (the GMP oracle, Mode::gmp)
  // The same point for the expansion stage (exact_expansion.hpp): the centroid
  // of `count` input points src[i * dim + j] (row-major), never rounded.
  int count = 0;
  double src[8 * 3] = {};

  // The centroid of `count` points (count a power of two <= 8, so the
  // centroid is dyadic and exact) with `dim` <= 3 coordinates each.
  static RationalPoint centroid(const double* const* pts, int count, int dim);

  // The point seen through some of its coordinates (cols[0..m-1]), e.g. its
  // y coordinate alone for a 1D comparison.
  RationalPoint project(const int* cols, int m) const;
};

// One row of a mixed Λ-matrix: an input point (x != nullptr) or a rational point.
struct MixedRow {
  PointId id;
  const double* x = nullptr;
  const RationalPoint* r = nullptr;
};

// Sign of det Λ of k = dim+1 mixed rows (2 <= k <= 4), filtered then exact.
// With `sos` the answer is the Simulation-of-Simplicity sign (never 0 for
// distinct ids), otherwise the exact sign (may be 0).
// Mode::filtered: ErrDouble filter, then expansion arithmetic (no GMP);
// Mode::gmp: the GMP oracle.
int mixed_sign(int k, const MixedRow* rows, bool sos, Mode m = Mode::filtered);

}  // namespace flipflop::pred

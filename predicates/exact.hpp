// exact.hpp — exact (GMP) evaluation of Λ-determinants.
//
// Every binary64 value is a dyadic rational m·2^e with an integer m of at most
// 53 bits. A lifted height |x|^2 - w is dyadic too (a sum of products of
// dyadics), computed here exactly. Scaling a column of a matrix by a positive
// constant does not change the sign of its determinant or of any of its minors,
// so each column is multiplied by 2^(-min exponent of the column) and the whole
// Λ-matrix becomes an integer matrix (mpz). Signs of the determinant and of its
// minors are then computed by fraction-free Gaussian elimination (Bareiss).
#pragma once

#include <gmpxx.h>

#include "predicates/predicates.hpp"

#include <cstdint>
#include <vector>

namespace flipflop::pred::exact {

// An exact dyadic rational: value = m · 2^e.
struct Dyadic {
  mpz_class m;
  long e = 0;
};

Dyadic to_dyadic(double x);
Dyadic add(const Dyadic& a, const Dyadic& b);
Dyadic sub(const Dyadic& a, const Dyadic& b);
Dyadic mul(const Dyadic& a, const Dyadic& b);
int sign(const Dyadic& a);

// A k x k integer matrix, row-major, whose last column is all ones: the exact
// Λ-matrix of k points (see lambda_filter.hpp), each column scaled to integers.
// Either `a` holds the entries, or — build_lambda's fast path, where every
// entry is an integer below 2^61 in magnitude (lattices: the degenerate calls
// that reach this stage) — `s` does and `a` is empty; exact.cpp reads both.
struct IntLambda {
  int k = 0;
  std::vector<mpz_class> a;  // k*k entries (empty when s holds them)
  std::vector<long> s;       // k*k small entries, or empty
  const mpz_class& at(int r, int c) const { return a[static_cast<size_t>(r * k + c)]; }
};

// Builds the integer Λ-matrix of k points (rows in the given order). If
// `weights` is non-null, column k-2 is the lifted height |x|^2 - w of the
// first k-2 coordinates.
IntLambda build_lambda(int k, const double* const* coords, const double* weights);

// Same from exact dyadic entries: `entries` holds k rows of k-1 values
// (row-major); the 1-column is appended. Used for points that are not doubles,
// e.g. an exact rational kernel point (a centroid of input points).
IntLambda build_lambda_dyadic(int k, const std::vector<Dyadic>& entries);

// Sign of the minor of `m` on the kept rows and columns (bit masks of equal
// popcount); the full determinant for all-ones masks.
int minor_sign(const IntLambda& m, std::uint32_t rows, std::uint32_t cols);

// Sign of det Λ under Simulation of Simplicity; rows of `m` must be sorted by
// strictly increasing point index (see predicates.hpp for the derivation).
// With `unweighted` (the same points' Λ with zero weights): the perturbation
// of power_d_pulled (predicates.hpp) instead, for a lifted Λ (column k-2).
int sos_sign(const IntLambda& m, const IntLambda* unweighted = nullptr);

}  // namespace flipflop::pred::exact

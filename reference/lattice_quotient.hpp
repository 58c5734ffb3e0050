// lattice_quotient.hpp — an input that is a small-integer lattice up to one
// exact common factor, as that lattice.
//
// Grids are often written with a step that is not 1: np.linspace(0, 1, 5)
// (step 0.25), np.mgrid[0:0.25:0.1] (0, 0.1 and 0.2 = 2 x 0.1 exactly),
// coordinates in millimetres on a 0.5 mm voxel grid, integers in steps of
// 1000. Every value is then q g for one double g > 0 and small integers q,
// but not itself a small integer, so the predicates' lattice path
// (StaticFilter::small_integers: the integer SoS walk before the float
// filters, which cannot decide the exact zeros a lattice is full of) does not
// apply, and their exactly degenerate calls run to the exact stages (the
// 3^5 grid of step 0.1: 6.5x the integer grid's time in Delaunay).
//
// Why the quotient has the same answer, sign for sign: every predicate
// (orientation, lifted power test) is det Λ over rows (1, x, |x|^2 - w) or
// (1, x); dividing every coordinate by g and every weight by g^2 divides
// each column c of Λ by a power g^k_c > 0. The SoS sign is the sign of the
// first non-zero term of the perturbed determinant's expansion, each term a
// minor of Λ (kept columns, DESIGN.md "The perturbation, precisely") times a
// fixed sign; a minor over columns C is divided by Π_{c in C} g^k_c > 0, so
// every term keeps its sign and its being zero or not. Every predicate —
// SoS or plain, strict views included — hence answers the same on the
// quotient, and every index-valued answer (simplices, redundant points,
// neighbours, hull facets) is the same, byte for byte. The invariance
// suite's x -> 2^k x (proptests/invariance_test.cpp) is the case g = 2^-k.
//
// The quotient is computed in integers from the IEEE 754 bits, exactly: g is
// gcd of the values' odd mantissas times 2^(least exponent), each q the
// exact integer ratio. Only coordinates and weights change; the caller keeps
// the original point set for anything that reads coordinates (output
// meshes, Voronoi centres, equations). The tests check the quotient against
// fma(q, g, -x) == 0 and the kernels' answers on both point sets.
#pragma once

#include <optional>

#include "reference/point_set.hpp"

namespace flipflop {

struct LatticeQuotient {
  PointSet points;    // every coordinate x / g, every weight w / g^2: integers below 2^20 in magnitude
  double factor = 0;  // g > 0
};

// The quotient of `ps` by its values' exact common factor g where every
// coordinate / g and every weight / g^2 is an integer below 2^20 in magnitude
// (the predicates' small-integer lattice, StaticFilter::small_integers) and
// the values are not such integers already; std::nullopt otherwise (a value
// not finite, every value 0, a quotient too large, a weight not an integer
// multiple of g^2). Two passes over the values, the first (g) with an exit at
// the first value whose quotient must be large (random input: the second).
std::optional<LatticeQuotient> lattice_quotient(const PointSet& ps);

}  // namespace flipflop

// dimension.hpp — exact affine dimension of a point set.
#pragma once

#include <cstddef>
#include <string>

#include "reference/point_set.hpp"

namespace flipflop {

// The dimension of the affine hull of the points, decided exactly (0 when all
// points are equal, 1 when collinear, 2 when coplanar, ...; at most ps.dim).
// O(n) exact predicates (d <= 3); exact rational elimination for d >= 4.
int affine_dimension(const PointSet& ps);

// Empty when the set spans its space; otherwise one line saying why it does
// not ("all 12 points are collinear (affine dimension 1)").
std::string dimension_problem(const PointSet& ps);

// The same line for n points in R^dim whose affine hull has dimension
// affine_dim (known otherwise, e.g. from a subset with the same hull: the
// distributed hulls of distributed/); empty when n > dim and affine_dim == dim.
std::string dimension_problem(std::size_t n, int dim, int affine_dim);

}  // namespace flipflop

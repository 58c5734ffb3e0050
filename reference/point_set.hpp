// point_set.hpp — the plain-data point set every part of flipflop passes around.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/values.hpp"

namespace flipflop {

// n points with `dim` coordinates each, stored contiguously (structure of
// arrays would split coordinates; predicates take a pointer to one point's
// coordinates, so points are stored point-major). Weights, when present, are a
// separate array of n values. Point i has SoS index i (predicates.hpp).
struct PointSet {
  int dim = 0;
  bool weighted = false;
  Values coords;   // size() * dim values (owned, or borrowed: values.hpp)
  Values weights;  // size() values when weighted

  std::size_t size() const { return dim > 0 ? coords.size() / static_cast<std::size_t>(dim) : 0; }
  const double* point(std::size_t i) const { return coords.data() + i * static_cast<std::size_t>(dim); }
  double weight(std::size_t i) const { return weighted ? weights[i] : 0.0; }
};

using Index = std::uint32_t;
using Triangle = std::array<Index, 3>;

}  // namespace flipflop

// generated.hpp — gen/'s families as test inputs (shared by the property
// tests of every problem).
#pragma once

#include <cstdint>
#include <string>

#include "gen/generate.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test {

// gen/'s family `name`: n points, seed, weights uniform in [0, whi] when
// weighted.
inline PointSet generated(const std::string& name, std::size_t n, std::uint64_t seed, bool weighted, double whi) {
  gen::Options o;
  o.seed = seed;
  o.weighted = weighted;
  o.wlo = 0;
  o.whi = whi;
  return gen::generate(name, n, o);
}

}  // namespace flipflop::test

// family_sweep.hpp — the deterministic sweep of the kernel tests: every
// generator family of a dimension (families.hpp), every size, seeds 1..S,
// each input's reference answer as text (outcome.hpp; a rejection must be
// lower-dimensional input) handed to the test's comparisons. Catch2 context
// (INFO, REQUIRE) of the including test.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <initializer_list>
#include <string>

#include "gen/generate.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/outcome.hpp"
#include "reference/dimension.hpp"

namespace flipflop::test {

struct SweepCounts {
  std::size_t inputs = 0, rejected = 0;
};

// body(ps, expect) for every input; ref_text(ps) gives expect.
template <class RefText, class Body>
SweepCounts family_sweep(int dim, std::initializer_list<std::size_t> sizes, std::uint64_t seeds,
                         RefText&& ref_text, Body&& body) {
  SweepCounts c;
  for (const std::string& fam : families(dim))
    for (std::size_t n : sizes)
      for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        gen::Options g;
        g.seed = seed;
        const PointSet ps = gen::generate(fam, n, g);
        INFO(fam << " n=" << n << " seed=" << seed);
        const std::string expect = ref_text(ps);
        if (is_error(expect)) {
          ++c.rejected;
          REQUIRE(!dimension_problem(ps).empty());
        }
        body(ps, expect);
        ++c.inputs;
      }
  return c;
}

}  // namespace flipflop::test

// twist_flip_inputs.hpp — RapidCheck generators for the twist-flip tests
// (reference/hull3/twist_flip.hpp, thesis §8.4.1): point sets and the options
// of the special polyhedra built over them (reference/hull3/twist_flip_input.hpp).
#pragma once

#include <rapidcheck.h>

#include <string>
#include <vector>

#include "proptests/support/families.hpp"
#include "reference/hull3/twist_flip_input.hpp"

namespace flipflop::test {

// Random doubles of the thesis' distributions, or wide integers: almost
// surely in general position (the CGAL oracles check it and discard ties).
inline rc::Gen<PointSet> twist_flip_general_points(int nmin, int nmax) {
  return one_of({
      {3, family_points({"ball", "cube", "sphere", "box", "cball"}, nmin, nmax, false)},
      {2, wide_integers(3, nmin, nmax, false)},
  });
}

// Every way special_polyhedron builds a start: random or angular link,
// fan / zigzag / random disk, 0 .. 3n random twists, either orientation.
inline rc::Gen<ref::SpecialInputOptions> special_options() {
  return rc::gen::exec([] {
    ref::SpecialInputOptions o;
    o.seed = *any_seed();
    o.link = *rc::gen::element(ref::LinkOrder::random, ref::LinkOrder::angular);
    o.disk = *rc::gen::element(ref::DiskTriangulation::fan, ref::DiskTriangulation::zigzag,
                               ref::DiskTriangulation::random);
    o.twists = static_cast<std::size_t>(*rc::gen::element(0, 0, 1, 3, 20, 100));
    o.reversed = *rc::gen::arbitrary<bool>();
    return o;
  });
}

}  // namespace flipflop::test

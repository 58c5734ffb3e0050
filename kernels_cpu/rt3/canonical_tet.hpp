// canonical_tet.hpp — the canonical tuple (reference/rtd/canonical_d.hpp) of a
// tetrahedron given as an orient_d-positive tuple of input indices: to the
// volume convention by swapping the last two entries (d = 3 is odd), then
// sorted, the last two swapped back when the sorting permutation is odd.
// __host__ __device__: kernels_cpu/rt3's output stage and the GPU kernel's
// (kernels_cuda/rt3/rt3.cuh) call this one function.
#pragma once

#include <array>

#include "predicates/err_double.hpp"  // FF_HD
#include "reference/point_set.hpp"    // Index

namespace flipflop {

// Branch-free (the comparisons of a tetrahedron's indices are unpredictable:
// a branching network cost kernels_cpu/rt3's output stage about five
// mispredictions per tetrahedron, twice; and g++ turns std::min/std::max
// pairs back into branches): the parity of the sorting permutation is that of
// the number of inversions, the sort a compare-exchange network by masks.
// out receives the four indices.
FF_HD inline void canonical_tet(Index a, Index b, Index c, Index d, Index* out) {
  Index t0 = a, t1 = b, t2 = d, t3 = c;
  const Index inv = Index{t0 > t1} + Index{t0 > t2} + Index{t0 > t3} + Index{t1 > t2} + Index{t1 > t3} +
                    Index{t2 > t3};
  auto cs = [](Index& x, Index& y) {
    const Index e = (x ^ y) & (Index{0} - Index{y < x});
    x ^= e, y ^= e;
  };
  cs(t0, t1), cs(t2, t3), cs(t0, t2), cs(t1, t3), cs(t1, t2);
  const Index e = (t2 ^ t3) & (Index{0} - (inv & 1u));  // odd: the last two swapped back
  out[0] = t0, out[1] = t1, out[2] = t2 ^ e, out[3] = t3 ^ e;
}

inline std::array<Index, 4> canonical_tet(Index a, Index b, Index c, Index d) {
  std::array<Index, 4> r;
  canonical_tet(a, b, c, d, r.data());
  return r;
}

}  // namespace flipflop

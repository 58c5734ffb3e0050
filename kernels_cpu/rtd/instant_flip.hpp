// kernels_cpu/rtd/instant_flip.hpp — the weight update of a regular
// triangulation (reference/rtd/dynamic_rt.hpp, the instant flip of thesis
// §9.2.1 with insertions) with its data-parallel part on oneTBB.
//
// What runs in parallel: the filter part of Algorithm 14's lines 3-5, the
// static filter's proof that a ridge is strictly convex at U, one slot at a
// time (InstantFlipOptions::for_range). Each slot's result depends only on
// the triangulation and U, so the ridges that go on to the exact scan, their
// order and every later step are those of the sequential run: the answer is
// the reference's, byte for byte, for every thread count (tested:
// proptests/instant_flip_dynamic_test.cpp). The event queue stays sequential
// (its order is the algorithm).
#pragma once

#include <vector>

#include "kernels_cpu/parallel.hpp"
#include "reference/rtd/dynamic_rt.hpp"

namespace flipflop::cpu {

// rt.set_weights(u, options) on `threads` workers (0: the runtime's default).
inline ref::WeightUpdateStats set_weights(ref::DynamicRegularTriangulation& rt, const std::vector<double>& u,
                                          int threads, ref::WeightUpdateOptions options = {}) {
  ref::WeightUpdateStats st;
  with_threads(threads, [&] {
    options.for_range = [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) {
      par_for(n, kChunk, body);
    };
    st = rt.set_weights(u, options);
  });
  return st;
}

}  // namespace flipflop::cpu

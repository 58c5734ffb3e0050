// two_pass.cuh — thesis §6.4.2's split of a kernel that may need exact
// arithmetic into two passes, for the kernels of kernels_cuda/ (hull2, hull3,
// rt2).
//
// The thesis splits every GPU kernel that may need exact arithmetic in two:
// the exact stage's code takes many registers and much local memory (here
// the staged predicates' expansion buffers: 25-34 KB of stack per thread
// along the deepest chain of calls of a kernel, 42-198 KB before each
// expansion stage became a call of its own; predicates/exact_expansion.hpp,
// "Stack per call"), which limits how many threads run
// at once, so a first kernel does the fast arithmetic only and tests it with
// precomputed error bounds, and a second, with only the threads that failed
// active, does the exact work.
//
// A decision F of item i, in two passes over [0, n):
//   F::decide(i, signs) -> R   the item's result, its predicates asked of
//                              `signs`;
//   F::fast(), F::exact()      the two kinds of signs: fast() a filter that
//                              returns a sign only when it is certain and
//                              otherwise 0 and sets its `undecided`; exact()
//                              the whole staged path (undecided is false);
//   F::write(i, r)             stores the result;
//   F::mark(i), F::marked(i)   the first pass's mark on an item it could
//                              not decide, and the second pass's test. The
//                              mark lives in the result's own array, as a
//                              value no result has, or where the result
//                              array is also an input (rt2's relocation) in
//                              an array of its own; the first pass writes
//                              nothing else for a marked item, so the second
//                              reads the item's inputs as they were.
// Both passes run the one decide(): every sign the fast pass uses is the
// exact one, so a decided item's result is the one-pass result, and a marked
// item gets exactly that result in the second pass.
#pragma once

#include <cstddef>

#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::dev {

// The fast signs' common part: a filter's result, 0 recorded as undecided.
struct Undecided {
  bool undecided = false;
  FF_HD int certain(int r) {
    undecided |= r == 0;
    return r;
  }
};

// The first pass's orient3d for a geometry G with the per-input static
// filter G::filter and the coordinates G::P(i) (hull3.cuh, ghull.cuh): that
// filter alone, inlined, no call into the staged path; 0 where it cannot
// decide.
template <class G>
struct StaticOrient : Undecided {
  const G& g;
  FF_HD explicit StaticOrient(const G& geo) : g(geo) {}
  template <class I>
  FF_HD int orient(I a, I b, I c, I d) {
    const double* p[4] = {g.P(a), g.P(b), g.P(c), g.P(d)};
    return certain(pred::static_sign<4>(g.filter, p, nullptr));
  }
};

// The second pass's work on a marked item, a call of its own on the device,
// taking the decision by value. The exact stage takes the address of the
// decision's data (its filter, its coordinates' pointer), and a kernel
// parameter has none: inlined into the kernel, that made every thread of the
// pass copy the whole functor (376 bytes for hull3's Decide) from the
// parameter space to its local memory on entry, before its test of the mark
// — measured on an H200 (Nsight Compute, 10^7 ball points): 16-27 us (17.8 on
// average) for each of hull3's 72 second decision passes over 2.2e5 edge
// slots, which mark almost nothing; 3.8 us on average once called. Called,
// only the marked items make the copy.
template <class F>
FF_HD FF_DEVICE_NOINLINE void decide_exactly(F f, std::size_t i) {
  auto signs = f.exact();
  f.write(i, f.decide(i, signs));
}

template <class F, bool kExact>
struct Pass {
  F f;
  FF_HD void operator()(std::size_t i) const {
    if constexpr (kExact) {
      if (f.marked(i)) decide_exactly(f, i);
    } else {
      auto signs = f.fast();
      const auto r = f.decide(i, signs);
      if (signs.undecided) f.mark(i);
      else f.write(i, r);
    }
  }
};

}  // namespace flipflop::dev

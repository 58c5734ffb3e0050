// static_filter.cuh — the per-input static filter (predicates/static_filter.hpp)
// of an array of coordinates (and weights) as one thrust reduction where the
// data lives, for the kernels of kernels_cuda/ (include after backend.cuh, in
// the same FF_KERNELS_NS).
//
// StaticFilter::for_points depends on three things only: the largest
// magnitude M of the coordinates (W of the weights), the lowest set bit over
// every value, and whether some value is not finite. The reduction keeps, per
// array, one representative value of each — the value of largest magnitude,
// the value of lowest set bit, a non-finite value if any — and for_points on
// those few values gives the bounds it would give on the whole array
// (kernels_cpu/parallel.hpp's filter_representatives does the same with TBB).
// The combination is associative and commutative up to ties between values of
// equal magnitude or equal lowest bit, which give the same bounds: the filter
// does not depend on the order of the reduction.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including static_filter.cuh"
#endif

#include <thrust/transform_reduce.h>

#include <cstdint>
#include <cstring>

#include "kernels_cuda/backend.cuh"
#include "predicates/static_filter.hpp"

namespace flipflop::FF_KERNELS_NS::filter {

// x finite and non-zero is a multiple of 2^result.
FF_HD inline int low_bit_exponent(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  const int e = static_cast<int>((b >> 52) & 0x7ff);
  std::uint64_t m = b & ((std::uint64_t{1} << 52) - 1);
  if (e != 0) m |= std::uint64_t{1} << 52;
#ifdef __CUDA_ARCH__
  const int tz = __ffsll(static_cast<long long>(m)) - 1;
#else
  const int tz = __builtin_ctzll(m);
#endif
  return (e == 0 ? -1074 : e - 1075) + tz;
}

struct Reps {
  double big;  // a value of largest magnitude (0: none)
  double low;  // a non-zero value of lowest set bit (0: none)
  int low_e;   // its exponent (INT_MAX: none)
  double bad;  // a non-finite value (0: none)
};

struct ToReps {
  FF_HD Reps operator()(double x) const {
    if (!(x - x == 0.0)) return {0.0, 0.0, 0x7fffffff, x};  // inf or NaN
    if (x == 0.0) return {0.0, 0.0, 0x7fffffff, 0.0};
    return {x, x, low_bit_exponent(x), 0.0};
  }
};

struct CombineReps {
  FF_HD Reps operator()(const Reps& a, const Reps& b) const {
    Reps r;
    r.big = (b.big < 0 ? -b.big : b.big) > (a.big < 0 ? -a.big : a.big) ? b.big : a.big;
    if (b.low_e < a.low_e) r.low = b.low, r.low_e = b.low_e;
    else r.low = a.low, r.low_e = a.low_e;
    r.bad = a.bad != 0.0 ? a.bad : b.bad;
    return r;
  }
};

// The representatives of values[0, m) (device pointer in the CUDA build).
template <std::size_t ParallelFrom>
Reps representatives(const double* values, std::size_t m) {
  Reps r{0.0, 0.0, 0x7fffffff, 0.0};
  if (m == 0) return r;
  backend::run_step<ParallelFrom>(m, [&](auto policy) {
    r = thrust::transform_reduce(policy, values, values + m, ToReps(), r, CombineReps());
  });
  return r;
}

// The static filter of m coordinate values (device memory in the CUDA build),
// nw weights (weights may be null) and extra_count further coordinate values
// on the host (e.g. a kernel point's): the filter StaticFilter::for_points
// gives on the whole arrays.
template <std::size_t ParallelFrom>
pred::StaticFilter static_filter(const double* coords, std::size_t m, const double* weights = nullptr,
                                 std::size_t nw = 0, const double* extra = nullptr, std::size_t extra_count = 0) {
  const Reps c = representatives<ParallelFrom>(coords, m);
  const double cv[3] = {c.big, c.low, c.bad};
  if (!weights) return pred::StaticFilter::for_points(cv, 3, 1, nullptr, extra, extra_count);
  const Reps w = representatives<ParallelFrom>(weights, nw);
  const double wv[3] = {w.big, w.low, w.bad};
  return pred::StaticFilter::for_points(cv, 3, 1, wv, extra, extra_count);
}

}  // namespace flipflop::FF_KERNELS_NS::filter

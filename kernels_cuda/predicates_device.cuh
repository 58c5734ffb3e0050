// predicates_device.cuh — the one source of the batched device predicate path
// (predicates_device.hpp explains the task). Included by predicates_omp.cpp
// (thrust's OpenMP backend, host compiler) and predicates_cuda.cu (nvcc), each
// defining FF_KERNELS_NS to the namespace it implements, so that the two builds
// never share a symbol (classify.cuh does the same; its helpers live in
// FF_KERNELS_NS::detail, these in FF_KERNELS_NS::predicates_detail).
//
// One thread per call runs pred::lambda_sign_staged<K> (predicates/staged.hpp):
// every stage, the exact one and SoS included, on the device. Stack: the exact
// stage's buffers (exact_expansion.hpp, "Stack per call": calls of their
// own on the device, the deepest chain is the thread's stack); on the device the XDbl minors are sums over permutations
// (xp::MinorX), on the host (OpenMP build) Laplace levels (xp::MinorLaplace):
// the two builds run the same code otherwise.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including predicates_device.cuh"
#endif

#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/predicates_device.hpp"
#include "predicates/staged.hpp"
#include "predicates/static_filter.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace predicates_detail {

// The rows of call c: point pointers, weights, ids.
template <int K>
struct CallRows {
  const double* p[K];
  double w[K];
  pred::PointId id[K];
};

// Everything a thread reads (device pointers) and the per-input filter, by value.
template <int K>
struct BatchView {
  const double* coords;
  const double* weights;       // null: not lifted
  const pred::PointId* ids;    // null: exact signs
  const std::uint32_t* calls;  // K indices per call
  int dim;
  bool use_filter;
  pred::StaticFilter filter;

  FF_HD void rows(std::size_t c, CallRows<K>& r) const {
    const std::uint32_t* call = calls + static_cast<std::size_t>(K) * c;
    for (int i = 0; i < K; ++i) {
      const std::size_t q = call[i];
      r.p[i] = coords + q * static_cast<std::size_t>(dim);
      r.w[i] = weights ? weights[q] : 0.0;
      r.id[i] = ids ? ids[q] : pred::PointId{0};
    }
  }
};

// The whole staged path for call c.
template <int K>
struct LambdaSignOp {
  BatchView<K> v;
  FF_HD int operator()(std::size_t c) const {
    CallRows<K> r;
    v.rows(c, r);
    return pred::lambda_sign_staged<K>(v.use_filter ? &v.filter : nullptr,
                                       v.ids ? r.id : static_cast<const pred::PointId*>(nullptr),
                                       r.p, v.weights ? r.w : static_cast<const double*>(nullptr));
  }
};

// 1 when no filter decides call c (it goes to the exact stage), else 0.
template <int K>
struct ReachesExactOp {
  BatchView<K> v;
  FF_HD std::size_t operator()(std::size_t c) const {
    CallRows<K> r;
    v.rows(c, r);
    if (v.ids && pred::repeated_id(K, r.id)) return 0;
    const double* w = v.weights ? r.w : static_cast<const double*>(nullptr);
    if (v.use_filter && pred::static_sign<K>(v.filter, r.p, w) != 0) return 0;
    if (pred::semi_static_sign<K>(r.p, w) != 0) return 0;
    if (pred::lambda_sign_filter<K>(r.p, w) != 0) return 0;
    return 1;
  }
};

// ---- Where the data lives and how steps run (as classify.cuh) --------------------
// Buffers and steps: backend.cuh; the OpenMP grain size for this kernel.
constexpr std::size_t kParallelFrom = std::size_t{1} << 10;

inline void validate(const kernels::PredicateBatch& b, const char* who) {
  auto fail = [who](const std::string& what) { throw std::invalid_argument(std::string(who) + ": " + what); };
  if (b.k < 3 || b.k > 5) fail("k must be 3, 4 or 5, got " + std::to_string(b.k));
  const int want = b.weights ? b.k - 2 : b.k - 1;
  if (b.dim != want)
    fail("k = " + std::to_string(b.k) + (b.weights ? " weighted" : " unweighted") +
         " points need dim " + std::to_string(want) + ", got " + std::to_string(b.dim));
  if (b.n_points > 0 && !b.coords) fail("null coordinates");
  if (b.n_calls > 0 && !b.calls) fail("null calls");
  if (b.n_points > std::size_t{0xffffffffu} + 1) fail("more points than 32-bit indices reach");
  const std::size_t n = b.n_calls * static_cast<std::size_t>(b.k);
  for (std::size_t i = 0; i < n; ++i)
    if (b.calls[i] >= b.n_points) fail("point index out of range");
}

template <int K>
std::vector<int> lambda_signs(const kernels::PredicateBatch& b, kernels::PredicateStats* stats) {
  const std::size_t n = b.n_calls;
  backend::Buffer<double> b_coords, b_weights;
  backend::Buffer<pred::PointId> b_ids;
  backend::Buffer<std::uint32_t> b_calls;
  BatchView<K> view{};
  view.coords = backend::to_device(b.coords, b.n_points * static_cast<std::size_t>(b.dim), b_coords);
  view.weights = b.weights ? backend::to_device(b.weights, b.n_points, b_weights) : nullptr;
  view.ids = b.ids ? backend::to_device(b.ids, b.n_points, b_ids) : nullptr;
  view.calls = backend::to_device(b.calls, n * static_cast<std::size_t>(K), b_calls);
  view.dim = b.dim;
  view.use_filter = b.static_filter && b.n_points > 0;
  if (view.use_filter)
    view.filter = pred::StaticFilter::for_points(b.coords, b.n_points, b.dim, b.weights);
  thrust::counting_iterator<std::size_t> first(0), last(n);

  backend::Buffer<int> b_sign(n);
  const LambdaSignOp<K> op{view};
  backend::run_step<kParallelFrom>(n, [&](auto policy) { thrust::transform(policy, first, last, b_sign.begin(), op); });
  if (stats) {
    std::size_t exact = 0;
    const ReachesExactOp<K> count{view};
    backend::run_step<kParallelFrom>(n, [&](auto policy) {
      exact = thrust::transform_reduce(policy, first, last, count, std::size_t{0},
                                       thrust::plus<std::size_t>());
    });
    *stats = {n, exact};
  }
  return backend::to_host(b_sign, n);
}

}  // namespace predicates_detail

std::vector<int> lambda_signs(const kernels::PredicateBatch& batch,
                              kernels::PredicateStats* stats) {
  predicates_detail::validate(batch, "lambda_signs");
  switch (batch.k) {
    case 3: return predicates_detail::lambda_signs<3>(batch, stats);
    case 4: return predicates_detail::lambda_signs<4>(batch, stats);
    default: return predicates_detail::lambda_signs<5>(batch, stats);
  }
}

}  // namespace flipflop::FF_KERNELS_NS

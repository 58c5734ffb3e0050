// predicates_device_test.cpp — the device predicate path
// (kernels_cuda/predicates_device.cuh: pred::lambda_sign_staged<K> in a thrust
// functor, one thread per call) built against thrust's OpenMP backend
// (flipflop_kernels_omp) equals the sequential GMP oracle (stage::gmp,
// stage::gmp_sos) entry for entry, on batches built from every instance family
// of support/predicate_inputs.hpp (support/predicate_batch.hpp), for the shapes
// orient2d, orient3d, power2d, power3d, orient_d(4) and power_d(1); exact and
// SoS signs, with and without the per-input static filter; small batches
// (sequential below the OpenMP grain) and large ones (parallel). The CUDA build
// of the same source is checked by kernels_cuda/predicates_cuda_test.cpp.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cuda/predicates_device.hpp"
#include "proptests/support/predicate_batch.hpp"
#include "proptests/support/rc_scaled.hpp"

using namespace flipflop;
using namespace flipflop::test;

namespace {

std::vector<int> omp_backend(const kernels::PredicateBatch& b, kernels::PredicateStats* stats) {
  return kernels_omp::lambda_signs(b, stats);
}

void batch_property(BatchShape shape, Family fam) {
  BatchTally t;
  rc::prop(batch_name(shape) + ", " + family_name(fam), [&] {
    check_batch(gen_batch(shape, fam, 4, 0, 12), omp_backend, &t);
  });
  if (t.calls == 0) return;  // Catch ran another section this time
  std::printf("device predicates (OpenMP) %-28s %-20s calls %7zu, exact stage %7zu, exact zeros %6zu\n",
              batch_name(shape).c_str(), family_name(fam), t.calls, t.exact_stage, t.zeros);
  // The families do what they claim on this path too: degenerate inputs reach
  // the exact stage, and every exact zero does (a filter never certifies 0).
  if (fam == Family::near_degenerate || fam == Family::exact_degenerate) CHECK(t.exact_stage > 0);
  CHECK(t.exact_stage >= t.zeros);
}

}  // namespace

TEST_CASE("device predicates (OpenMP): equal GMP on every family", "[kernels][predicates]") {
  for (BatchShape shape : device_shapes())
    for (Family fam : kFamilies) batch_property(shape, fam);
}

// Batches above the OpenMP grain size (1024 calls, predicates_device.cuh): the
// parallel path. Each case costs thousands of GMP and exact-stage calls: a
// hundredth of the configured cases, one family drawn per case.
TEST_CASE("device predicates (OpenMP): large batches (parallel)", "[kernels][predicates][long]") {
  for (BatchShape shape : device_shapes()) {
    BatchTally t;
    prop_scaled(batch_name(shape) + ", large", 100, [&] {
      const Family fam = *rc::gen::elementOf(std::vector<Family>(std::begin(kFamilies), std::end(kFamilies)));
      check_batch(gen_batch(shape, fam, 16, 1500, 5000), omp_backend, &t);
    });
    if (t.calls == 0) continue;
    std::printf("device predicates (OpenMP) %-28s large calls %7zu, exact stage %7zu, exact zeros %6zu\n",
                batch_name(shape).c_str(), t.calls, t.exact_stage, t.zeros);
    CHECK(t.exact_stage >= t.zeros);
  }
}

TEST_CASE("device predicates (OpenMP): empty batches and preconditions", "[kernels][predicates]") {
  const double coords[6] = {0, 0, 1, 0, 0, 1};
  const double weights[3] = {0, 0, 0};
  const pred::PointId ids[3] = {0, 1, 2};
  const std::uint32_t calls[3] = {0, 1, 2};
  kernels::PredicateBatch b;
  b.k = 3;
  b.dim = 2;
  b.coords = coords;
  b.ids = ids;
  b.n_points = 3;
  b.calls = calls;
  b.n_calls = 1;
  // (0,0), (1,0), (0,1): counter-clockwise (predicates.hpp conventions)
  CHECK(kernels_omp::lambda_signs(b) == std::vector<int>{1});
  kernels::PredicateBatch empty = b;
  empty.n_calls = 0;
  kernels::PredicateStats stats{7, 7};
  CHECK(kernels_omp::lambda_signs(empty, &stats).empty());
  CHECK(stats.calls == 0);
  CHECK(stats.exact_stage == 0);
  empty.n_points = 0;
  empty.coords = nullptr;
  CHECK(kernels_omp::lambda_signs(empty).empty());

  kernels::PredicateBatch bad = b;
  bad.k = 6;
  CHECK_THROWS_AS(kernels_omp::lambda_signs(bad), std::invalid_argument);
  bad = b;
  bad.dim = 3;  // orient2d needs 2 coordinates
  CHECK_THROWS_AS(kernels_omp::lambda_signs(bad), std::invalid_argument);
  bad = b;
  bad.weights = weights;  // k = 3 weighted needs dim 1
  CHECK_THROWS_AS(kernels_omp::lambda_signs(bad), std::invalid_argument);
  bad = b;
  const std::uint32_t out_of_range[3] = {0, 1, 3};
  bad.calls = out_of_range;
  CHECK_THROWS_AS(kernels_omp::lambda_signs(bad), std::invalid_argument);
  bad = b;
  bad.calls = nullptr;
  CHECK_THROWS_AS(kernels_omp::lambda_signs(bad), std::invalid_argument);
}


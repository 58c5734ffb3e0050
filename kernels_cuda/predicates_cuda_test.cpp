// predicates_cuda_test.cpp — the CUDA build of the device predicate path
// (predicates_device.cuh) equals the sequential GMP oracle on batches from every
// input family (proptests/support/predicate_batch.hpp), exact and SoS signs,
// with and without the static filter, small batches per family and large ones
// (tens of thousands of calls, many blocks) per shape. RapidCheck runs without
// Catch here (RC_PARAMS applies; large batches run a tenth of the cases).
// Without a usable CUDA device it prints "no CUDA device: skipped" and exits
// with 77, which ctest reports as skipped (SKIP_RETURN_CODE), never as passed.
#include <rapidcheck.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "kernels_cuda/device_test.hpp"
#include "kernels_cuda/predicates_device.hpp"
#include "proptests/support/predicate_batch.hpp"
#include "proptests/support/rc_check.hpp"

using namespace flipflop;
using namespace flipflop::test;

namespace {

std::vector<int> cuda_backend(const kernels::PredicateBatch& b, kernels::PredicateStats* stats) {
  return kernels_cuda::lambda_signs(b, stats);
}

// check_scaled (rc_check.hpp) with the report printed on failure.
template <class Testable>
bool check_and_report(const std::string& name, int divisor, Testable&& testable) {
  const test::ScaledResult r = test::check_scaled(name, divisor, std::forward<Testable>(testable));
  if (!r.ok) std::printf("%s:\n%s\n", name.c_str(), r.message.c_str());
  return r.ok;
}

}  // namespace

int main() {
  kernels_cuda::require_device();
  bool ok = true;
  for (BatchShape shape : device_shapes()) {
    for (Family fam : kFamilies) {
      BatchTally t;
      const std::string name = batch_name(shape) + ", " + family_name(fam);
      const bool passed = check_and_report(name, 1, [&] {
        check_batch(gen_batch(shape, fam, 8, 0, 24), cuda_backend, &t);
      });
      std::printf("%s %-48s calls %8zu, exact stage %8zu\n", passed ? "ok  " : "FAIL", name.c_str(),
                  t.calls, t.exact_stage);
      ok = passed && ok;
    }
    BatchTally t;
    const std::string name = batch_name(shape) + ", large";
    const bool passed = check_and_report(name, 10, [&] {
      const Family fam =
          *rc::gen::elementOf(std::vector<Family>(std::begin(kFamilies), std::end(kFamilies)));
      check_batch(gen_batch(shape, fam, 16, 20000, 60000), cuda_backend, &t);
    });
    std::printf("%s %-48s calls %8zu, exact stage %8zu\n", passed ? "ok  " : "FAIL", name.c_str(),
                t.calls, t.exact_stage);
    ok = passed && ok;
  }
  return ok ? 0 : 1;
}

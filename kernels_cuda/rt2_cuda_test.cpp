// rt2_cuda_test.cpp — the CUDA build of the GPU ffRT (kernels_cuda/rt2/rt2.cuh)
// equals the exact sequential reference ref::rt2_ffrt byte for byte: degenerate
// sets of 3..60 points and every generator family up to 3000 points, weighted
// and unweighted (RapidCheck without Catch, RC_PARAMS applies; shrinking on
// failure), then uniform inputs of 10^4 and 10^5 points in the weight ranges of
// §5.4 and unweighted, and the reference's rejection of collinear input.
// Without a usable CUDA device it prints "no CUDA device: skipped" and exits
// with 77, which ctest reports as skipped (SKIP_RETURN_CODE), never as passed.
#include <rapidcheck.h>

#include <cstdio>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cuda/device_property.hpp"
#include "kernels_cuda/device_test.hpp"
#include "kernels_cuda/rt2/rt2.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rt2_outcome.hpp"

using namespace flipflop;
using kernels_cuda::property;
using kernels_cuda::report;

namespace {

std::string cuda_text(const PointSet& ps) {
  return test::problem_of(test::outcome([&] { return kernels_cuda::rt2_ffrt(ps); }));
}

}  // namespace

int main() {
  kernels_cuda::require_device();
  bool ok = true;
  for (bool weighted : {false, true}) {
    const std::string w = weighted ? "weighted" : "unweighted";
    ok = property("degenerate sets of 3..60 points, " + w, 2, test::degenerate_points(2, 3, 60, weighted), cuda_text,
                  test::ref_text) &&
         ok;
    ok = property("family sets of 3..3000 points, " + w, 10, test::thinned(test::family_points(2, 3, 3000, weighted)),
                  cuda_text, test::ref_text) &&
         ok;
  }
  for (std::size_t n : {std::size_t{10000}, std::size_t{100000}})
    for (double whi : {0.0, 2e-7, 1e-5, 1e-2}) {
      gen::Options o;
      o.seed = 3;
      o.weighted = whi > 0;
      o.whi = whi;
      const PointSet ps = gen::generate("square", n, o);
      ref::Rt2Stats st;
      const bool same = kernels_cuda::rt2_ffrt(ps, &st) == ref::rt2_ffrt(ps);
      ok = report("square n=" + std::to_string(n) + " weights [0, " + std::to_string(whi) + "] (" +
                      std::to_string(st.rounds) + " insertion rounds, " + std::to_string(st.flips_2_2) +
                      " 2-2 flips, " + std::to_string(st.flips_3_1) + " 3-1 flips)",
                  same) &&
           ok;
    }
  PointSet line;
  line.dim = 2;
  line.coords = {0, 0, 1, 1, 2, 2, 3, 3, -1, -1};
  const std::string rejected = cuda_text(line);
  ok = report("collinear input rejected like the reference", test::is_error(rejected) && rejected == test::ref_text(line)) && ok;
  kernels_cuda::report_stack_limit("after the kernels");
  return ok ? 0 : 1;
}

// classify_cuda_test.cpp — the CUDA build of the point classification equals
// the sequential GMP oracle on every input family (classify_inputs.hpp).
// Without a usable CUDA device it prints "no CUDA device: skipped" and exits
// with 77, which ctest reports as skipped (SKIP_RETURN_CODE), never as passed.
#include <cstdio>

#include "kernels_cuda/device_test.hpp"
#include "kernels_cuda/classify.hpp"
#include "kernels_cuda/classify_inputs.hpp"

using namespace flipflop;
namespace kt = flipflop::kernels::testing;

namespace {

template <std::size_t D>
bool check(kt::Family fam, std::size_t n, std::uint64_t seed) {
  auto in = kt::make_input<D>(fam, n, seed);
  kernels::ClassifyStats stats;
  std::vector<int> got;
  if constexpr (D == 3)
    got = kernels_cuda::classify_points_3d(in.pts, in.facets, in.facet_of_point, &stats);
  else
    got = kernels_cuda::classify_points_2d(in.pts, in.facets, in.facet_of_point, &stats);
  const bool ok = got == kt::reference_signs(in);
  std::printf("%s %zuD %-16s n=%zu exact stage: %zu  %s\n", ok ? "ok  " : "FAIL", D,
              kt::name(fam), n, stats.exact_stage, ok ? "" : "(differs from the GMP oracle)");
  return ok;
}

}  // namespace

int main() {
  kernels_cuda::require_device();
  bool ok = true;
  for (kt::Family fam : {kt::Family::random, kt::Family::lattice, kt::Family::near_degenerate})
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{200000}}) {
      ok = check<3>(fam, n, 17 + n) && ok;
      ok = check<2>(fam, n, 29 + n) && ok;
    }
  return ok ? 0 : 1;
}

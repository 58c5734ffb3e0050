// hull2_cuda_test.cpp — the CUDA build of the GPU 2D hull
// (kernels_cuda::hull2_graham_sort and hull2_graham_insert) equals the
// reference (ref::hull2_graham_sort, ref::hull2_graham_insert)
// byte for byte over every 2D generator family (degenerate ones included:
// grids, circle lattices, collinear subsets, duplicates, huge and tiny
// magnitudes), sizes 3..10^6, with the default options and with no throw-away
// and chunks of 3 (the most flip-pop passes); 10^7 disk points against the
// multithreaded cpu kernel; the rejection of collinear input with the
// reference's message. Without a usable CUDA device it prints "no CUDA device:
// skipped" and exits with 77, which ctest reports as skipped, never as passed.
#include <cstdio>
#include <string>

#include "gen/generate.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cuda/device_test.hpp"
#include "kernels_cuda/hull2/hull2.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

template <class F>
std::string outcome(F&& f) {
  try {
    std::string s;
    for (Index v : f()) s += std::to_string(v) + "\n";
    return s;
  } catch (const std::exception& e) {
    return std::string("error: ") + e.what();
  }
}

}  // namespace

// hull2_cuda_test [FAMILY N]: every case, or only those of one family and
// size (to rerun the case a failure names, e.g. under compute-sanitizer). Each
// case is announced before it runs ("case ..."), so the last line of a
// program the device kills names the case that failed.
int main(int argc, char** argv) {
  kernels_cuda::require_device();
  const std::string only_family = argc > 2 ? argv[1] : "";
  const std::size_t only_n = argc > 2 ? std::stoul(argv[2]) : 0;
  bool ok = true;
  kernels::Hull2GpuOptions tiny;
  tiny.throw_away = false;
  tiny.chunk = 3;
  std::size_t cases = 0;
  for (const std::string& fam : gen::distributions()) {
    if (gen::dimension_of(fam) != 2) continue;
    if (!only_family.empty() && fam != only_family) continue;
    for (std::size_t n : {3, 7, 30, 200, 2000, 50000, 1000000}) {
      if (only_n && n != only_n) continue;
      gen::Options g;
      g.seed = 11 + n;
      const PointSet ps = gen::generate(fam, n, g);
      const std::string expect = outcome([&] { return ref::hull2_graham_sort(ps); });
      for (const kernels::Hull2GpuOptions& o : {kernels::Hull2GpuOptions{}, tiny}) {
        if (n > 50000 && !o.throw_away) continue;
        for (bool insert : {false, true}) {
          const std::string want = insert ? outcome([&] { return ref::hull2_graham_insert(ps); }) : expect;
          std::printf("case %s %zu throw_away=%d chunk=%zu %s\n", fam.c_str(), n, o.throw_away, o.chunk,
                      insert ? "graham-insert" : "graham-sort");
          const bool same = outcome([&] {
                              return insert ? kernels_cuda::hull2_graham_insert(ps, o)
                                            : kernels_cuda::hull2_graham_sort(ps, o);
                            }) == want;
          ++cases;
          if (!same)
            std::printf("FAIL %s n=%zu throw_away=%d chunk=%zu %s\n", fam.c_str(), n, o.throw_away, o.chunk,
                        insert ? "graham-insert" : "graham-sort");
          ok = same && ok;
        }
      }
    }
  }
  if (!only_family.empty()) return ok ? 0 : 1;
  std::printf("case disk 10000000 against the cpu kernel\n");
  const PointSet big = gen::generate("disk", 10000000, {});
  const bool same = outcome([&] { return kernels_cuda::hull2_graham_sort(big); }) ==
                    outcome([&] { return cpu::hull2_graham_sort(big); });
  std::printf("%s disk n=10^7 against the cpu kernel\n", same ? "ok  " : "FAIL");
  ok = same && ok;
  std::printf("%s %zu cases against the reference\n", ok ? "ok  " : "FAIL", cases);
  kernels_cuda::report_stack_limit("after the kernels");
  return ok ? 0 : 1;
}

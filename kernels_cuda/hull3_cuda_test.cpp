// hull3_cuda_test.cpp — the CUDA build of ffHull (kernels_cuda/hull3) and of
// gHull (kernels_cuda/hull3/ghull.hpp) equals
// the exact sequential reference ref::hull3_ffhull byte for byte on every 3D
// generator family (degenerate ones included: grids, lattices on a sphere,
// coplanar subsets, duplicates, huge / tiny coordinates, 1-ulp jitter) at
// several sizes, on large ball and sphere inputs, and rejects input that does
// not span R^3 with the reference's message. Without a usable CUDA device it
// prints "no CUDA device: skipped" and exits with 77 (ctest: skipped).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cuda/device_test.hpp"
#include "kernels_cuda/hull3/ghull.hpp"
#include "kernels_cuda/hull3/hull3.hpp"
#include "reference/hull3/ffhull.hpp"

using namespace flipflop;

namespace {

// "ok: <triangles>" or "error: <message>" (std::invalid_argument)
template <class F>
std::string outcome(F&& f) {
  try {
    const std::vector<Triangle> t = f();
    std::string s = "ok:";
    for (const Triangle& x : t) s += " " + std::to_string(x[0]) + "," + std::to_string(x[1]) + "," + std::to_string(x[2]);
    return s;
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

// stats: where given, the kernel's counters of the run
bool check(const std::string& what, const PointSet& ps, ref::Hull3Stats* stats = nullptr) {
  ref::Hull3Stats st;
  cpu::StageTimes times;
  const std::string got = outcome([&] { return kernels_cuda::hull3_ffhull(ps, &st, &times); });
  const std::string expect = outcome([&] { return ref::hull3_ffhull(ps); });
  const bool ok = got == expect;
  const bool counts = expect.rfind("error: ", 0) == 0 ||
                      (st.insertions == st.flips_1_3 && 4 + st.insertions + st.discarded_early == ps.size());
  std::printf("%s %-28s n=%-8zu insertions %llu, 2-2 %llu, 3-1 %llu, rounds %llu%s\n", ok && counts ? "ok  " : "FAIL",
              what.c_str(), ps.size(), static_cast<unsigned long long>(st.insertions),
              static_cast<unsigned long long>(st.flips_2_2), static_cast<unsigned long long>(st.flips_3_1),
              static_cast<unsigned long long>(st.rounds),
              ok ? (counts ? "" : "  (counters inconsistent)") : "  (differs from the reference)");
  if (stats) *stats = st;
  return ok && counts;
}

// gHull (kernels_cuda/hull3/ghull.hpp) against the same reference
// (known: the reference's outcome where the caller has it already)
bool check_ghull(const std::string& what, const PointSet& ps, const kernels::GhullOptions& opt = {},
                 const std::string* known = nullptr) {
  kernels::GhullStats st;
  const std::string got = outcome([&] { return kernels_cuda::hull3_ghull(ps, opt, &st); });
  const std::string expect = known ? *known : outcome([&] { return ref::hull3_ffhull(ps); });
  const bool ok = got == expect && st.handed_back == 0;
  std::printf("%s ghull %-22s n=%-8zu |S'| %llu, candidates %llu, added %llu, misses %llu, splay rounds %llu%s\n",
              ok ? "ok  " : "FAIL", what.c_str(), ps.size(), static_cast<unsigned long long>(st.captured),
              static_cast<unsigned long long>(st.depth_candidates), static_cast<unsigned long long>(st.added),
              static_cast<unsigned long long>(st.depth_misses), static_cast<unsigned long long>(st.splay_rounds),
              ok ? "" : "  (differs from the reference)");
  return ok;
}

}  // namespace

int main() {
  kernels_cuda::require_device();
  bool ok = true;
  for (const std::string& fam : gen::distributions()) {
    if (gen::dimension_of(fam) != 3) continue;
    for (std::size_t n : {4, 7, 30, 200, 2000, 20000})
      for (std::uint64_t seed : {1, 2}) {
        gen::Options o;
        o.seed = seed;
        const PointSet ps = gen::generate(fam, n, o);
        ok = check(fam + " seed " + std::to_string(seed), ps) && ok;
        ok = check_ghull(fam + " seed " + std::to_string(seed), ps) && ok;
      }
  }
  for (const char* fam : {"ball", "sphere"}) {
    gen::Options o;
    o.seed = 11;
    const PointSet ps = gen::generate(fam, 1000000, o);
    ok = check(std::string(fam) + " (large)", ps) && ok;
    ok = check_ghull(std::string(fam) + " (large)", ps) && ok;
    // Stage 1's PBA at other band counts (one band: one thread per line),
    // against the reference's answer computed once
    const std::string expect = outcome([&] { return ref::hull3_ffhull(ps); });
    for (std::uint32_t bands : {1u, 7u, 256u}) {
      kernels::GhullOptions g;
      g.bands = bands;
      ok = check_ghull(std::string(fam) + " (large, " + std::to_string(bands) + " bands)", ps, g, &expect) && ok;
    }
  }
  // almost flat slabs (heights one ulp apart): the exact kernel point's side
  // tests on the device (dev::orient3d_centroid); the run must take that path
  for (std::uint64_t seed : {1, 2, 3}) {
    PointSet slab;
    slab.dim = 3;
    std::uint64_t x = seed * 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < 5000; ++i) {
      double c[3];
      for (int j = 0; j < 2; ++j) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;  // xorshift64
        c[j] = static_cast<double>(x % 65) / 64;
      }
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      c[2] = (x & 1) ? std::nextafter(1.0, 2.0) : 1.0;
      slab.coords.insert(slab.coords.end(), c, c + 3);
    }
    ref::Hull3Stats st;
    const bool same = check("almost flat slab seed " + std::to_string(seed), slab, &st);
    const bool exact = st.exact_kernel_point == 1;
    if (!exact) std::printf("FAIL almost flat slab seed %llu: not on the exact kernel point\n",
                            static_cast<unsigned long long>(seed));
    ok = same && exact && ok;
  }
  PointSet flat;
  flat.dim = 3;
  flat.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0};
  ok = check("coplanar (rejected)", flat) && ok;
  ok = check_ghull("coplanar (rejected)", flat) && ok;
  kernels_cuda::report_stack_limit("after the kernels");
  return ok ? 0 : 1;
}

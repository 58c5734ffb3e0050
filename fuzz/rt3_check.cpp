// rt3_check.cpp — fuzz_rt3: the multithreaded 3D regular / Delaunay
// triangulation (kernels_cpu/rt3) against the exact sequential reference
// (RT+1, ref::rtd_incremental with d = 3) and the certifiers.
//
// Byte layout: byte 0: bit 0 weighted. Then a 3D point set of 1..24 points
// (fuzz_input.hpp: small integers, duplicates, ulp jitter, points on lines
// and planes, raw and extreme magnitudes, cospherical lattice points, quarter
// weights, power-of-two scalings).
// Checked:
//   * input that does not span R^3: cpu::rt3 throws std::invalid_argument,
//     as the reference does (nothing else);
//   * otherwise cpu::rt3 returns, at 1 and 3 threads and BRIO rounds down to
//     one point, the reference's canonical tetrahedra and redundant points
//     byte for byte, with consistent counts (inserted + discarded = n;
//     discarded + removed = redundant), certified by the witness-free
//     certify::rtd at Level::canonical and by its own witness
//     (cpu::certify_rt3).
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "kernels_cpu/rt3/certify_rt3.hpp"
#include "kernels_cpu/rt3/rt3.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
#include "kernels_cuda/rt3/rt3.hpp"
#endif
#include "reference/dimension.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_rt3";
constexpr std::size_t kMaxPoints = 24;

std::vector<std::vector<Index>> as_simplices(const std::vector<cpu::Tet>& tets) {
  std::vector<std::vector<Index>> out;
  for (const cpu::Tet& t : tets) out.emplace_back(t.begin(), t.end());
  return out;
}

}  // namespace

bool check_rt3_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  const bool weighted = (r.byte() & 1) != 0;
  PointSet ps;
  if (!decode_points(r, 3, weighted, 1, kMaxPoints, ps)) return false;

  if (affine_dimension(ps) < 3) {
    for (int threads : {1, 3}) {
      cpu::Rt3Options o;
      o.threads = threads;
      try {
        (void)cpu::rt3(ps, o);
        fail(kTarget, "cpu::rt3 returned on input that does not span R^3", describe(ps));
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail(kTarget, std::string("cpu::rt3 threw the wrong exception: ") + e.what(), describe(ps));
      }
    }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
    try {
      (void)kernels_omp::rt3(ps);
      fail(kTarget, "kernels_omp::rt3 returned on input that does not span R^3", describe(ps));
    } catch (const std::invalid_argument&) {
    } catch (const std::exception& e) {
      fail(kTarget, std::string("kernels_omp::rt3 threw the wrong exception: ") + e.what(), describe(ps));
    }
#endif
    return true;
  }

  ref::Rtd answer;
  try {
    answer = ref::rtd_incremental(ps);
  } catch (const std::exception& e) {
    fail(kTarget, std::string("rtd_incremental threw: ") + e.what(), describe(ps));
  }
  // a kernel's run: it returns, the reference's bytes, counts that add up
  // (counts_ok), its witness certified
  auto check_run = [&](const std::string& what, auto&& run, auto&& counts_ok) {
    cpu::Rt3Witness w;
    cpu::Rt3Result got;
    try {
      got = run(w);
    } catch (const std::exception& e) {
      fail(kTarget, what + " threw: " + e.what(), describe(ps));
    }
    const auto simplices = as_simplices(got.tets);
    if (simplices != answer.simplices || got.redundant != answer.redundant)
      fail(kTarget, what + " differs from rtd_incremental",
           describe(ps) + what + "\n" + simplices_text(simplices) + "rtd_incremental\n" +
               simplices_text(answer.simplices));
    if (!counts_ok(got)) fail(kTarget, what + ": inconsistent counts", describe(ps));
    const certify::Report rep = cpu::certify_rt3(ps, w, got.tets, certify::Level::canonical);
    if (!rep.ok) fail(kTarget, what + ": certify_rt3 rejected its witness: " + rep.message(), describe(ps));
  };
  for (int threads : {1, 3})
    for (std::size_t brio : {std::size_t{1}, std::size_t{256}}) {
      cpu::Rt3Options o;
      o.threads = threads;
      o.brio_min = brio;
      cpu::Rt3Stats st;
      check_run("cpu::rt3 (" + std::to_string(threads) + " threads, brio_min " + std::to_string(brio) + ")",
                [&](cpu::Rt3Witness& w) { return cpu::rt3(ps, o, &st, &w); },
                [&](const cpu::Rt3Result& got) {
                  return st.inserted + st.discarded == ps.size() &&
                         st.discarded + st.removed == got.redundant.size();
                });
    }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  kernels::Rt3GpuStats gst;
  check_run("kernels_omp::rt3", [&](cpu::Rt3Witness& w) { return kernels_omp::rt3(ps, &gst, nullptr, &w); },
            [&](const cpu::Rt3Result&) { return gst.inserted + gst.discarded == ps.size(); });
#endif
  const certify::Report rep = certify::rtd(ps, answer.simplices, certify::Level::canonical);
  if (!rep.ok) fail(kTarget, "certify::rtd rejected the answer: " + rep.message(), describe(ps));
  return true;
}

}  // namespace flipflop::fuzz

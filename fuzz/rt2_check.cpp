// rt2_check.cpp — fuzz_rt2: the 2D regular / Delaunay triangulation
// algorithms (reference/rt2/rt2.hpp) against each other, the definition and the
// certifier.
//
// Byte 0: bit 0 weighted. Then a 2D point set of 1..32 points (fuzz_input.hpp:
// cocircular lattice points, duplicates, collinear runs, quarter weights,
// power-of-two scalings). Checked:
//   * input that does not span the plane: rt2_ffrt (both flip-flop variants),
//     dt2_lawson and the cpu backend (kernels_cpu/rt2, one and three
//     threads, one BRIO round and rounds down to one point, sequential and
//     parallel insertion from the 4th point) throw
//     std::invalid_argument;
//   * otherwise rt2_ffrt with FlipFlopVariant::combined and ::v_first return
//     the same canonical triangles, equal to brute::rt2 (the definition, for
//     n <= 20), accepted by certify::rt2 at Level::canonical and Level::exact;
//   * the cpu backend (same settings) returns the same triangles, and so does
//     the GPU ffRT built against thrust's OpenMP backend (kernels_omp, when
//     built: FLIPFLOP_HAVE_KERNELS_OMP), which also rejects what does not span
//     the plane;
//   * unweighted input (or all weights 0): dt2_lawson returns the same;
//   * flip_flop (both variants) started from the answer returns it, and
//     started from the Delaunay triangulation of the same points without
//     weights (a triangulation of conv(S), any vertex subset allowed) returns
//     the regular one;
//   * lawson started from that Delaunay triangulation: throws
//     std::invalid_argument when a point is not one of its vertices; else
//     returns the answer when every point is a vertex of it, and throws
//     std::runtime_error (stuck, Lemma 5.1) when some point is redundant.
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
#include "kernels_cuda/rt2/rt2.hpp"
#endif
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/rt2/rt2.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_rt2";
constexpr std::size_t kMaxPoints = 32;
constexpr std::size_t kMaxBrute = 20;

using ref::FlipFlopVariant;
using Tris = std::vector<Triangle>;

template <class F>
Tris must_return(const char* what, const PointSet& ps, F f) {
  try {
    return f();
  } catch (const std::exception& e) {
    fail(kTarget, std::string(what) + " threw: " + e.what(), describe(ps));
  }
}

template <class E, class F>
void must_throw(const std::string& what, const PointSet& ps, F f) {
  try {
    const Tris t = f();
    fail(kTarget, what + " returned instead of throwing", describe(ps) + "returned " + describe(t));
  } catch (const E&) {
  } catch (const std::exception& e) {
    fail(kTarget, what + " threw the wrong exception: " + e.what(), describe(ps));
  }
}

void expect_same(const std::string& what, const PointSet& ps, const Tris& got, const Tris& answer) {
  if (got != answer)
    fail(kTarget, what + " differs from rt2_ffrt", describe(ps) + what + " " + describe(got) + "\nrt2_ffrt " + describe(answer));
}

// the cpu backend's settings tried: 1 and 3 threads, one BRIO round and
// rounds down to a single point, the sequential insertion and both parallel
// ones (stage 2b) from the 4th point on (the result must not depend on them)
std::vector<cpu::Rt2Options> cpu_settings() {
  using Insertion = cpu::Rt2Options::Insertion;
  std::vector<cpu::Rt2Options> out;
  for (Insertion insertion : {Insertion::sequential, Insertion::territories, Insertion::batches})
    for (int threads : {1, 3})
      for (std::size_t brio : {std::size_t{1}, std::size_t{256}}) {
        cpu::Rt2Options o;
        o.threads = threads;
        o.brio_min = brio;
        o.insertion = insertion;
        o.parallel_from = 4;
        out.push_back(o);
      }
  return out;
}

std::size_t vertex_count(const Tris& tris, std::size_t n) {
  std::vector<char> seen(n, 0);
  for (const Triangle& t : tris)
    for (Index v : t) seen[v] = 1;
  return static_cast<std::size_t>(std::count(seen.begin(), seen.end(), 1));
}

}  // namespace

bool check_rt2_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  const bool weighted = (r.byte() & 1) != 0;
  PointSet ps;
  if (!decode_points(r, 2, weighted, 1, kMaxPoints, ps)) return false;
  const std::size_t n = ps.size();
  const bool zero_weights = std::all_of(ps.weights.begin(), ps.weights.end(), [](double w) { return w == 0; });

  if (affine_dimension(ps) < 2) {
    must_throw<std::invalid_argument>("rt2_ffrt", ps, [&] { return ref::rt2_ffrt(ps); });
    must_throw<std::invalid_argument>("rt2_ffrt v_first", ps,
                                      [&] { return ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first); });
    if (zero_weights) must_throw<std::invalid_argument>("dt2_lawson", ps, [&] { return ref::dt2_lawson(ps); });
    for (const cpu::Rt2Options& o : cpu_settings())
      must_throw<std::invalid_argument>("cpu::rt2", ps, [&] { return cpu::rt2(ps, o); });
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
    must_throw<std::invalid_argument>("kernels_omp::rt2_ffrt", ps, [&] { return kernels_omp::rt2_ffrt(ps); });
#endif
    return true;
  }

  ref::Rt2Stats stats;
  const Tris answer = must_return("rt2_ffrt", ps, [&] { return ref::rt2_ffrt(ps, &stats); });
  expect_same("rt2_ffrt v_first", ps,
              must_return("rt2_ffrt v_first", ps, [&] { return ref::rt2_ffrt(ps, nullptr, FlipFlopVariant::v_first); }),
              answer);
  if (n <= kMaxBrute) expect_same("brute::rt2", ps, brute::rt2(ps), answer);
  for (const cpu::Rt2Options& o : cpu_settings())
    expect_same("cpu::rt2 (" + std::to_string(o.threads) + " threads, brio_min " + std::to_string(o.brio_min) +
                    ", insertion " + std::to_string(static_cast<int>(o.insertion)) + ")",
                ps,
                must_return("cpu::rt2", ps, [&] { return cpu::rt2(ps, o); }), answer);
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  expect_same("kernels_omp::rt2_ffrt", ps, must_return("kernels_omp::rt2_ffrt", ps, [&] { return kernels_omp::rt2_ffrt(ps); }),
              answer);
#endif
  for (auto level : {certify::Level::canonical, certify::Level::exact}) {
    const certify::Report rep = certify::rt2(ps, answer, level);
    if (!rep.ok)
      fail(kTarget, std::string("certify::rt2 rejected rt2_ffrt's answer at Level::") +
                        (level == certify::Level::canonical ? "canonical: " : "exact: ") + rep.message(),
           describe(ps) + describe(answer));
  }
  if (zero_weights) expect_same("dt2_lawson", ps, must_return("dt2_lawson", ps, [&] { return ref::dt2_lawson(ps); }), answer);

  for (auto variant : {FlipFlopVariant::combined, FlipFlopVariant::v_first}) {
    const char* vname = variant == FlipFlopVariant::combined ? " (combined)" : " (v_first)";
    expect_same(std::string("flip_flop from the answer") + vname, ps,
                must_return("flip_flop from the answer", ps, [&] { return ref::flip_flop(ps, answer, variant); }), answer);
  }
  if (!weighted) return true;

  PointSet plain = ps;
  plain.weighted = false;
  plain.weights.clear();
  const Tris dt = must_return("rt2_ffrt of the unweighted points", plain, [&] { return ref::rt2_ffrt(plain); });
  for (auto variant : {FlipFlopVariant::combined, FlipFlopVariant::v_first}) {
    const char* vname = variant == FlipFlopVariant::combined ? " (combined)" : " (v_first)";
    expect_same(std::string("flip_flop from the Delaunay triangulation") + vname, ps,
                must_return("flip_flop from the Delaunay triangulation", ps,
                            [&] { return ref::flip_flop(ps, dt, variant); }),
                answer);
  }
  if (vertex_count(dt, n) < n) {
    must_throw<std::invalid_argument>("lawson from a triangulation missing a point", ps,
                                      [&] { return ref::lawson(ps, dt); });
  } else if (vertex_count(answer, n) < n) {
    must_throw<std::runtime_error>("lawson with a redundant point", ps, [&] { return ref::lawson(ps, dt); });
  } else {
    expect_same("lawson from the Delaunay triangulation", ps,
                must_return("lawson", ps, [&] { return ref::lawson(ps, dt); }), answer);
  }
  return true;
}

}  // namespace flipflop::fuzz

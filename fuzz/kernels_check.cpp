// kernels_check.cpp — fuzz_kernels: the parallel point classification
// (kernels_cpu: TBB; kernels_omp: the thrust functors on the OpenMP backend,
// when built) against a sequential loop of GMP predicates.
//
// Byte 0: bit 0 the dimension (3, else 2); bit 1 ids may be out of range
// (byte mod n + 2 for facet vertices, mod m + 1 for facet ids); bit 2 one
// facet id too few. Then the point set (fuzz_input.hpp, 1..64 points: filter
// boundaries — huge, tiny, subnormal, ulp-jittered and exactly degenerate
// values — are what matters here), m = 1 + byte mod 8 facets of dim vertex
// ids each (repeated vertices allowed: every sign is then 0), and one facet
// id per point. Checked:
//   * valid input: every backend returns, for every point i with facet
//     (a, b[, c]), exactly orient2d_exact / orient3d_exact(a, b[, c], p_i)
//     decided in Mode::gmp (no filter), and kernels_omp counts n points;
//   * invalid input (an id out of range, a missing facet id): every backend
//     throws std::invalid_argument.
#include <exception>
#include <stdexcept>
#include <string>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "kernels_cpu/classify_tbb.hpp"
#include "predicates/predicates.hpp"
#if FLIPFLOP_HAVE_KERNELS_OMP
#include "kernels_cuda/classify.hpp"
#endif

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_kernels";

template <std::size_t D>
std::vector<int> oracle(const PointSet& ps, const std::vector<std::array<Index, D>>& facets,
                        const std::vector<Index>& facet_of_point) {
  std::vector<int> s(ps.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& f = facets[facet_of_point[i]];
    if constexpr (D == 3)
      s[i] = pred::orient3d_exact(ps.point(f[0]), ps.point(f[1]), ps.point(f[2]), ps.point(i), pred::Mode::gmp);
    else
      s[i] = pred::orient2d_exact(ps.point(f[0]), ps.point(f[1]), ps.point(i), pred::Mode::gmp);
  }
  return s;
}

std::string describe_signs(const std::vector<int>& s) {
  std::string out;
  for (int v : s) out += v > 0 ? '+' : v < 0 ? '-' : '0';
  return out;
}

template <std::size_t D, class Run>
void check_backend(const char* backend, Run run, bool valid, const std::vector<int>& expected,
                   const std::string& details) {
  std::vector<int> got;
  try {
    got = run();
  } catch (const std::invalid_argument& e) {
    if (valid) fail(kTarget, std::string(backend) + " rejected valid input: " + e.what(), details);
    return;
  } catch (const std::exception& e) {
    fail(kTarget, std::string(backend) + " threw " + e.what(), details);
  }
  if (!valid) fail(kTarget, std::string(backend) + " accepted invalid input", details);
  if (got != expected)
    fail(kTarget, std::string(backend) + " differs from the sequential GMP loop",
         details + "expected " + describe_signs(expected) + "\ngot      " + describe_signs(got));
}

template <std::size_t D>
void check(ByteReader& r, const PointSet& ps, bool out_of_range, bool short_ids) {
  const std::size_t n = ps.size();
  const std::size_t m = 1 + r.byte() % 8;
  std::vector<std::array<Index, D>> facets(m);
  bool valid = !short_ids;
  for (auto& f : facets)
    for (Index& v : f) {
      v = static_cast<Index>(r.byte() % (out_of_range ? n + 2 : n));
      if (v >= n) valid = false;
    }
  std::vector<Index> facet_of_point(short_ids ? n - 1 : n);
  for (Index& f : facet_of_point) {
    f = static_cast<Index>(r.byte() % (out_of_range ? m + 1 : m));
    if (f >= m) valid = false;
  }
  const std::vector<int> expected = valid ? oracle<D>(ps, facets, facet_of_point) : std::vector<int>{};
  std::string details = describe(ps) + "facets";
  for (const auto& f : facets) {
    details += " (";
    for (std::size_t k = 0; k < D; ++k) details += (k ? "," : "") + std::to_string(f[k]);
    details += ")";
  }
  details += "\nfacet_of_point " + describe(facet_of_point) + "\n";

  check_backend<D>("kernels_cpu", [&] {
    if constexpr (D == 3) return kernels_cpu::classify_points_3d(ps, facets, facet_of_point);
    else return kernels_cpu::classify_points_2d(ps, facets, facet_of_point);
  }, valid, expected, details);
#if FLIPFLOP_HAVE_KERNELS_OMP
  check_backend<D>("kernels_omp", [&] {
    kernels::ClassifyStats stats;
    std::vector<int> s;
    if constexpr (D == 3) s = kernels_omp::classify_points_3d(ps, facets, facet_of_point, &stats);
    else s = kernels_omp::classify_points_2d(ps, facets, facet_of_point, &stats);
    if (stats.points != n || stats.exact_stage > n)
      fail(kTarget, "kernels_omp: stats count " + std::to_string(stats.points) + " points, " +
                        std::to_string(stats.exact_stage) + " exact, for " + std::to_string(n), details);
    return s;
  }, valid, expected, details);
#endif
}

}  // namespace

bool check_kernels_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  const std::uint8_t flags = r.byte();
  const int dim = (flags & 1) ? 3 : 2;
  PointSet ps;
  if (!decode_points(r, dim, false, 1, 64, ps)) return false;
  if (dim == 3)
    check<3>(r, ps, (flags & 2) != 0, (flags & 4) != 0);
  else
    check<2>(r, ps, (flags & 2) != 0, (flags & 4) != 0);
  return true;
}

}  // namespace flipflop::fuzz

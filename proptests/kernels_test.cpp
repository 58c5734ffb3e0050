// kernels_test.cpp — the parallel point classifications (kernels_cpu: TBB over
// predicates.hpp; kernels_omp: the thrust functor of kernels_cuda/classify.cuh
// on thrust's OpenMP backend, two stages) equal a sequential loop over
// predicates.hpp in Mode::gmp, entry for entry, on random, lattice (many exact
// zeros) and near-degenerate (nearly all beyond the filter) inputs.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cstdio>

#include "kernels_cpu/classify_tbb.hpp"
#include "kernels_cuda/classify.hpp"
#include "kernels_cuda/classify_inputs.hpp"

using namespace flipflop;
namespace kt = flipflop::kernels::testing;

namespace {

const kt::Family kFamilies[] = {kt::Family::random, kt::Family::lattice,
                                kt::Family::near_degenerate};

// Totals per family, reported after each test case.
struct Tally {
  std::size_t points = 0, zeros = 0, exact_stage = 0;
};

template <std::size_t D>
std::vector<int> tbb_signs(const kt::Input<D>& in) {
  if constexpr (D == 3)
    return kernels_cpu::classify_points_3d(in.pts, in.facets, in.facet_of_point);
  else
    return kernels_cpu::classify_points_2d(in.pts, in.facets, in.facet_of_point);
}

#ifdef FLIPFLOP_HAVE_KERNELS_OMP
template <std::size_t D>
std::vector<int> omp_signs(const kt::Input<D>& in, kernels::ClassifyStats* stats) {
  if constexpr (D == 3)
    return kernels_omp::classify_points_3d(in.pts, in.facets, in.facet_of_point, stats);
  else
    return kernels_omp::classify_points_2d(in.pts, in.facets, in.facet_of_point, stats);
}
#endif

// One input: both backends equal the oracle; counts go into `t`.
template <std::size_t D>
void check_one(const kt::Input<D>& in, Tally& t) {
  const std::vector<int> expected = kt::reference_signs(in);
  RC_ASSERT(tbb_signs(in) == expected);
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  kernels::ClassifyStats stats;
  RC_ASSERT(omp_signs(in, &stats) == expected);
  RC_ASSERT(stats.points == in.pts.size());
  t.exact_stage += stats.exact_stage;
#endif
  t.points += expected.size();
  for (int s : expected) t.zeros += (s == 0);
}

template <std::size_t D>
void property(kt::Family fam) {
  Tally t;
  rc::prop(std::string("classify ") + std::to_string(D) + "D " + kt::name(fam), [&] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(0, 400));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    check_one(kt::make_input<D>(fam, n, seed), t);
  });
  if (t.points == 0) return;  // Catch ran another section (property) this time
  std::printf("classify %zuD %-16s points %zu, exact zeros %zu, exact stage (omp) %zu\n", D,
              kt::name(fam), t.points, t.zeros, t.exact_stage);
  // The families do what they claim: lattice inputs hold exact zeros, and
  // near-degenerate ones send many points to the exact stage.
  if (fam == kt::Family::lattice) CHECK(t.zeros > 0);
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  if (fam == kt::Family::near_degenerate) CHECK(4 * t.exact_stage > t.points);
  // Exact zeros always need the exact stage (a filter certifies only +1/-1);
  // on random input the filter decides nearly every non-zero sign.
  CHECK(t.exact_stage >= t.zeros);
  if (fam == kt::Family::random) CHECK(100 * (t.exact_stage - t.zeros) < t.points);
#endif
}

}  // namespace

TEST_CASE("kernels: 3D classification equals the sequential GMP loop", "[kernels]") {
#ifndef FLIPFLOP_HAVE_KERNELS_OMP
  WARN("flipflop_kernels_omp not built (no CUDA toolkit headers or OpenMP): TBB only");
#endif
  for (kt::Family fam : kFamilies) property<3>(fam);
}

TEST_CASE("kernels: 2D classification equals the sequential GMP loop", "[kernels]") {
  for (kt::Family fam : kFamilies) property<2>(fam);
}

TEST_CASE("kernels: large inputs (many threads, many blocks)", "[kernels][long]") {
  // Sizes on both sides of the OpenMP grain size 2^14 of classify.cuh (below
  // it thrust runs sequentially), and one well above.
  for (std::size_t n : {std::size_t{16383}, std::size_t{16384}, std::size_t{100000}})
  for (kt::Family fam : kFamilies) {
    auto in3 = kt::make_input<3>(fam, n, 7 + n);
    auto in2 = kt::make_input<2>(fam, n, 8 + n);
    const auto ref3 = kt::reference_signs(in3), ref2 = kt::reference_signs(in2);
    CHECK(kernels_cpu::classify_points_3d(in3.pts, in3.facets, in3.facet_of_point) == ref3);
    CHECK(kernels_cpu::classify_points_2d(in2.pts, in2.facets, in2.facet_of_point) == ref2);
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
    kernels::ClassifyStats s3, s2;
    CHECK(kernels_omp::classify_points_3d(in3.pts, in3.facets, in3.facet_of_point, &s3) == ref3);
    CHECK(kernels_omp::classify_points_2d(in2.pts, in2.facets, in2.facet_of_point, &s2) == ref2);
    std::printf("classify %-16s exact stage: 3D %zu / %zu, 2D %zu / %zu\n", kt::name(fam),
                s3.exact_stage, s3.points, s2.exact_stage, s2.points);
#endif
  }
}

TEST_CASE("kernels: preconditions are checked", "[kernels]") {
  auto in = kt::make_input<3>(kt::Family::random, 100, 3);
  auto bad_facet = in.facet_of_point;
  bad_facet[5] = static_cast<Index>(in.facets.size());
  CHECK_THROWS_AS(kernels_cpu::classify_points_3d(in.pts, in.facets, bad_facet),
                  std::invalid_argument);
  auto bad_vertex = in.facets;
  bad_vertex[0][1] = 100;
  CHECK_THROWS_AS(kernels_cpu::classify_points_3d(in.pts, bad_vertex, in.facet_of_point),
                  std::invalid_argument);
  CHECK_THROWS_AS(kernels_cpu::classify_points_2d(in.pts, {}, in.facet_of_point),
                  std::invalid_argument);  // 3D points
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  CHECK_THROWS_AS(kernels_omp::classify_points_3d(in.pts, in.facets, bad_facet),
                  std::invalid_argument);
  CHECK_THROWS_AS(kernels_omp::classify_points_3d(in.pts, bad_vertex, in.facet_of_point),
                  std::invalid_argument);
  CHECK_THROWS_AS(kernels_omp::classify_points_3d(in.pts, in.facets, {}),
                  std::invalid_argument);
#endif
}

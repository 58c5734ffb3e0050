// predicates_device.hpp — batches of predicate calls evaluated by the default
// staged path of predicates/staged.hpp (static filter, semi-static filter,
// ErrDouble filter, exact expansion arithmetic, Simulation of Simplicity) with
// one thrust thread per call: the device predicate path, entirely __host__
// __device__, no GMP, no heap.
//
// A batch holds one point array and calls of one shape: k = 3, 4 or 5 points
// per call, given by indices into the array —
//   unweighted (dim = k - 1): k = 3 orient2d, k = 4 orient3d, k = 5 orient_d(4);
//   weighted, lifted (dim = k - 2): k = 4 power2d, k = 5 power3d (k = 3: power_d(1)).
// Entry c of the result is sign det Λ of the rows calls[c k .. c k + k - 1] in
// that order (predicates.hpp conventions): with `ids` the Simulation-of-
// Simplicity sign (never 0 unless a call repeats a point id), without them the
// exact sign of the unperturbed determinant (0 when degenerate). It equals
// pred::lambda_sign(k, ids, rows, weights, Mode::gmp) — stage::gmp_sos /
// stage::gmp — on every finite input.
//
// With `static_filter` set, StaticFilter::for_points over the whole point
// array is computed once on the host and handed to every call (stage 1).
//
// Backends built from the same source (predicates_device.cuh), as classify.hpp:
//   flipflop::kernels_omp  — thrust's OpenMP backend, host compiler
//                            (library flipflop_kernels_omp);
//   flipflop::kernels_cuda — thrust's CUDA backend, nvcc for sm_90 (library
//                            flipflop_kernels_cuda, only where nvcc exists).
//
// Preconditions (checked, std::invalid_argument otherwise): k in 3..5, dim =
// k - 1 (no weights) or k - 2 (weights), every index < n_points, non-null
// arrays where their counts are non-zero. Coordinates and weights must be
// finite (not checked: the device path has no way to report it; the GMP
// oracle throws on them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "predicates/predicates.hpp"

namespace flipflop::kernels {

// A view of one batch (nothing is copied or owned).
struct PredicateBatch {
  int k = 0;                            // points per call: 3, 4 or 5
  int dim = 0;                          // coordinates per point: k - 1, or k - 2 with weights
  const double* coords = nullptr;       // n_points * dim, point-major
  const double* weights = nullptr;      // n_points weights (lifted calls) or null
  const pred::PointId* ids = nullptr;   // n_points ids (SoS) or null (exact signs)
  std::size_t n_points = 0;
  const std::uint32_t* calls = nullptr;  // n_calls * k point indices
  std::size_t n_calls = 0;
  bool static_filter = true;            // stage 1 with the per-input filter of the points
};

// What the stages did.
struct PredicateStats {
  std::size_t calls = 0;        // entries evaluated
  std::size_t exact_stage = 0;  // entries no filter decided (exact expansion stage, SoS)
};

}  // namespace flipflop::kernels

namespace flipflop::kernels_omp {
std::vector<int> lambda_signs(const kernels::PredicateBatch& batch,
                              kernels::PredicateStats* stats = nullptr);
}  // namespace flipflop::kernels_omp

namespace flipflop::kernels_cuda {
// Number of usable CUDA devices (classify_cuda.cu); 0 without a device or driver.
int device_count();
std::vector<int> lambda_signs(const kernels::PredicateBatch& batch,
                              kernels::PredicateStats* stats = nullptr);
}  // namespace flipflop::kernels_cuda

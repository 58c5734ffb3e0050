// hull3.cuh — the one source of the data-parallel ffHull (hull3.hpp explains
// the task). Included by hull3_omp.cpp (thrust's OpenMP backend, host
// compiler) and hull3_cuda.cu (nvcc), each defining FF_KERNELS_NS to the
// namespace it implements; helpers live in FF_KERNELS_NS::hull3_detail.
//
// Every step is a thrust primitive (for_each over an index range,
// transform_reduce, copy_if, remove_if, sort; the flip-flop rounds'
// operations listed by atomic appends) over a __host__ __device__
// functor reading flat arrays (structure of arrays): the surface is tv[3t + k] (vertex k of triangle slot t,
// counter-clockwise seen from outside) and tn[3t + k] (the slot across its
// edge tv[3t + k] -> tv[3t + (k + 1) % 3]), as in §6.4.1 ("an array of
// triangles, each containing the indices of its three vertices and the
// indices of the triangles sharing its three edges"). Atomics are
// cuda::atomic_ref. Every buffer is allocated once, sized from n (at most
// 2n - 4 triangle slots: every insertion adds two), before the first step;
// thrust's temporary storage (scans, sorts, reductions) comes from a caching
// allocator (TempStorage), so later rounds reuse the first rounds' blocks.
// Every decision is an exact SoS predicate run on the device
// (device_predicates.cuh: orient3d with the per-input static filter, the
// exact expansion stage and SoS; no heap, no recursion).
//
// Stages:
//  * Algorithm 7 line 1: four approximately extreme points by arg-max
//    reductions (double keys, ties: the smaller index), accepted when exactly
//    affinely independent (host: four points); else the reference's rule,
//    which also rejects input that does not span R^3.
//  * line 4: the kernel point s, the centroid rounded to doubles, SoS index n
//    (after all inputs), used when it is strictly inside the tetrahedron
//    exactly (four exact orient3d on the host). Otherwise — an almost flat
//    tetrahedron, §6.4.2's trap — the exact dyadic centroid, as the
//    reference's (ref::centroid_kernel): its side tests are filtered by the
//    reference's per-input bound (which covers the rounding of s) and decided
//    on the device by the exact expansion stage on the row (Σ q_i, 4)
//    (dev::orient3d_centroid), so the kernel keeps the run.
//  * lines 5-14 in rounds (§6.4.1, "four major GPU kernels"): round 0
//    associates every point with a face of the tetrahedron; every round takes
//    per triangle the furthest point — the largest rounded orient(p, t),
//    §6.4.1's "second technique", ties to the smaller index; any point beyond
//    t in its cone is correct, kernels_cpu/hull3/ffhull.hpp — by an atomic
//    maximum over the points in place (no sort of the points by triangle),
//    lists the triangles with points in slot order, splits each 1-3 (its own
//    slot and slots T + 2k, T + 2k + 1 for its rank k among the round's
//    triangles: disjoint writes), repairs the adjacency in a separate pass
//    (§6.4.1: "a separate kernel is necessary here"), re-associates every
//    point with one of the three new cones (line 13) and drops it when it is
//    beneath the new triangle (line 14, "first technique": s is beneath every
//    triangle), then compacts the points (remove_if).
//  * line 15, flip-flop (Algorithm 6) in rounds (see "flip-flop" below).
//  * output: the live triangles rotated and sorted on the device (the
//    canonical order of reference/canonical.hpp), then downloaded.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including hull3.cuh"
#endif

#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/fill.h>
#include <thrust/for_each.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/iterator/zip_iterator.h>
#include <thrust/reduce.h>
#include <thrust/remove.h>
#include <thrust/sort.h>
#include <thrust/system/system_error.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#include <thrust/tuple.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#endif

#include <cuda/atomic>
#include <cuda/std/bit>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_CUDA
#include <thrust/system/cuda/error.h>
#include <cuda_runtime_api.h>
#endif

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernels_cpu/hull3/in_plane_tie.hpp"
#include "kernels_cpu/hull3/rounded_centroid.hpp"
#include "kernels_cpu/stage_times.hpp"
#include "kernels_cuda/backend.cuh"
#include "kernels_cuda/spread.cuh"
#include "kernels_cuda/static_filter.cuh"
#include "kernels_cuda/device_predicates.cuh"
#include "kernels_cuda/two_pass.cuh"
#include "kernels_cuda/hull3/hull3.hpp"
#include "kernels_cuda/kernel_errors.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/rational_kernel.hpp"

namespace flipflop::FF_KERNELS_NS {

namespace hull3_detail {

using std::uint32_t;
using std::uint8_t;
constexpr uint32_t kNone = ~uint32_t{0};
// OpenMP build: below this many items a step runs on one thread (backend.cuh).
constexpr std::size_t kParallelFrom = std::size_t{1} << 12;
// The flip-flop rounds issued between two waits of the host (Hull3::flip_flop).
constexpr uint32_t kRoundsPerWait = 8;

// The raw pointer to a buffer's elements (std::vector or device_vector).
template <class V>
auto raw(V& b) {
  return thrust::raw_pointer_cast(b.data());
}

// f(i) for i in [0, n), one thread per item.
template <class F>
void for_n(std::size_t n, const F& f) {
  if (n == 0) return;
  backend::run_step_async<kParallelFrom>(
      n, [&](auto policy) { thrust::for_each_n(policy, thrust::counting_iterator<std::size_t>(0), n, f); });
}

template <class T>
void fill_n(T* p, std::size_t n, T value) {
  if (n == 0) return;
  backend::run_step_async<kParallelFrom>(n, [&](auto policy) { thrust::fill_n(policy, p, n, value); });
}

// The temporary storage of the steps that need some (scans, sorts,
// reductions), allocated by thrust through this allocator: a freed block is
// kept and handed out again, so the rounds reuse the first rounds' storage
// instead of allocating (cudaMalloc / cudaFree on the device) every round.
// Locked: thrust's OpenMP sort allocates its merges' temporary arrays from
// inside its parallel region, one call per thread (ThreadSanitizer reported
// the unlocked maps racing in the output's sort at 4 threads, make tsan).
class TempStorage {
 public:
  using value_type = char;
  TempStorage() = default;
  TempStorage(const TempStorage&) = delete;
  TempStorage& operator=(const TempStorage&) = delete;
  ~TempStorage() {
    for (auto& [bytes, p] : free_) release(p);
    for (auto& [p, bytes] : used_) release(p);
  }
  char* allocate(std::ptrdiff_t bytes) {
    const std::lock_guard<std::mutex> lock(mutex_);
    char* p;
    const auto it = free_.lower_bound(bytes);
    if (it != free_.end()) {
      bytes = it->first;
      p = it->second;
      free_.erase(it);
    } else {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_CUDA
      void* q = nullptr;
      if (cudaMalloc(&q, static_cast<std::size_t>(bytes)) != cudaSuccess) {
        cudaGetLastError();  // clear the error: the caller reports it
        throw std::bad_alloc();
      }
      p = static_cast<char*>(q);
#else
      p = new char[static_cast<std::size_t>(bytes)];
#endif
    }
    used_.emplace(p, bytes);
    return p;
  }
  void deallocate(char* p, std::size_t) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = used_.find(p);
    free_.emplace(it->second, p);
    used_.erase(it);
  }

 private:
  static void release(char* p) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_CUDA
    cudaFree(p);
#else
    delete[] p;
#endif
  }
  std::mutex mutex_;
  std::multimap<std::ptrdiff_t, char*> free_;
  std::map<char*, std::ptrdiff_t> used_;
};

// backend::run_step for the steps that allocate: their temporary storage
// from `temp`.
template <class Step>
void run_with(TempStorage& temp, std::size_t n, Step&& step) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  if (n < kParallelFrom)
    step(thrust::seq);
  else
    step(thrust::omp::par(temp));
#else
  (void)n;
  step(thrust::cuda::par(temp));
#endif
}

// The indices i in [0, n) with pred(i), in order, written to out; their count.
template <class Pred>
std::size_t select(TempStorage& temp, std::size_t n, uint32_t* out, const Pred& pred) {
  if (n == 0) return 0;
  std::size_t m = 0;
  run_with(temp, n, [&](auto policy) {
    m = static_cast<std::size_t>(thrust::copy_if(policy, thrust::counting_iterator<uint32_t>(0),
                                                 thrust::counting_iterator<uint32_t>(static_cast<uint32_t>(n)),
                                                 out, pred) -
                                 out);
  });
  return m;
}

// ---- counts that stay on the device (the flip-flop rounds) ----------------------
// A flip-flop round's operation count is needed by its own steps, and by the
// host only to see whether the rounds have ended: on the device it stays in
// device memory, written by the decision's appends and read by the steps'
// threads, and the rounds' state that depends on it (RoundState) is kept
// there too, so that the host waits only once every few rounds
// (kRoundsPerWait). In the OpenMP build the steps have finished when the next
// one starts, and the count is read directly.

// f(i) for i in [0, *count): *count was written by an earlier step and is at
// most bound. On the device one thread per i < bound, each testing
// i < *count; in the OpenMP build one per i < *count.
template <class F>
struct UpTo {
  F f;
  const uint32_t* count;
  FF_HD void operator()(std::size_t i) const {
    if (i < *count) f(i);
  }
};
template <class F>
void for_upto(std::size_t bound, const uint32_t* count, const F& f) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  (void)bound;
  for_n(*count, f);
#else
  for_n(bound, UpTo<F>{f, count});
#endif
}

// a(i) then b(i) in one pass over i: the same as a pass of a then a pass of b
// where no b(j) reads or writes what an a(i) writes or reads, for j != i.
template <class A, class B>
struct Then {
  A a;
  B b;
  FF_HD void operator()(std::size_t i) const {
    a(i);
    b(i);
  }
};

// f(i) for i in [0, K * *count) (K threads per counted item), and then
// g(0) once, in the same pass: on the device thread 0 runs g(0) too (after
// its f(0), if any), so g may read nothing that any f(i) writes, nor write
// anything an f(i) reads — *count included; in the OpenMP build g(0) runs
// after the pass. One launch less than a pass of f and a one-thread pass of g.
template <uint32_t K, class F, class G>
struct UpToThen {
  F f;
  G g;
  const uint32_t* count;
  FF_HD void operator()(std::size_t i) const {
    if (i < std::size_t{K} * *count) f(i);
    if (i == 0) g(0);
  }
};
template <uint32_t K, class F, class G>
void for_upto_then(std::size_t bound, const uint32_t* count, const F& f, const G& g) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  (void)bound;
  for_n(std::size_t{K} * *count, f);
  g(0);
#else
  for_n(bound > 0 ? K * bound : 1, UpToThen<K, F, G>{f, g, count});
#endif
}

// A value written by the device steps, on the host (a wait for them there).
template <class T>
T read_back(const T* value) {
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
  return *value;
#else
  T h{};
  const cudaError_t err = cudaMemcpy(&h, value, sizeof h, cudaMemcpyDeviceToHost);
  if (err != cudaSuccess) throw thrust::system_error(err, thrust::cuda_category(), "hull3: reading a count");
  return h;
#endif
}

template <class T>
using Atomic = cuda::atomic_ref<T, cuda::thread_scope_device>;

FF_HD inline uint32_t next3(uint32_t k) { return k == 2 ? 0 : k + 1; }
FF_HD inline uint32_t prev3(uint32_t k) { return k == 0 ? 2 : k - 1; }

// ---- geometry: input points and the kernel point ---------------------------------
struct Geo {
  const double* xyz;        // 3 per point
  pred::StaticFilter filter;  // per input, the kernel point's coordinates included
  double s[3];              // the kernel point (double; exact_s: the rounded exact centroid)
  uint32_t n;               // its SoS index: after every input
  // exact_s: s stands for the exact centroid of the tetrahedron's four points
  // src[0..11] (§6.4.2); side() is then filtered by s_bound
  // (ref::RationalKernel's per-input bound, which covers s's rounding) and
  // decided by dev::orient3d_centroid
  bool exact_s;
  double s_bound;
  double src[12];

  FF_HD const double* P(Index i) const { return xyz + 3 * static_cast<std::size_t>(i); }
  // orient3d(a, b, c, d) under SoS: > 0 when d is on the inner side of
  // (a, b, c) counter-clockwise seen from outside (predicates.hpp). The
  // per-input static filter inline first (the first stage of the staged
  // predicate, which decides nearly every call), then the whole staged path.
  FF_HD int orient(Index a, Index b, Index c, Index d) const {
    const double* p[4] = {P(a), P(b), P(c), P(d)};
    if (const int r = pred::static_sign<4>(filter, p, nullptr)) return r;
    return dev::orient3d(&filter, a, p[0], b, p[1], c, p[2], d, p[3]);
  }
  // KernelPoint::side(a, b, c) = orient3d(a, b, c, s) (kernel_point.hpp)
  FF_HD int side(Index a, Index b, Index c) const {
    const double* p[4] = {P(a), P(b), P(c), s};
    if (exact_s) {  // RationalKernel::side: its bound, then the exact stage
      if (const int r = pred::sign_beyond_bound<4>(p, nullptr, s_bound)) return r;
      return dev::orient3d_centroid(a, p[0], b, p[1], c, p[2], n, src);
    }
    if (const int r = pred::static_sign<4>(filter, p, nullptr)) return r;
    return dev::orient3d(&filter, a, p[0], b, p[1], c, p[2], n, s);
  }
};

// ---- §6.4.2's two passes (kernels_cuda/two_pass.cuh) ------------------------------
// The first pass's signs: the per-input static filter alone (static_filter.hpp,
// its bound precomputed once per input: Geo::filter), inlined, no call into
// the staged path; 0 where it cannot decide.
struct FastSigns : dev::StaticOrient<Geo> {
  FF_HD explicit FastSigns(const Geo& geo) : dev::StaticOrient<Geo>(geo) {}
  FF_HD int side(Index a, Index b, Index c) {
    const double* p[4] = {g.P(a), g.P(b), g.P(c), g.s};
    return certain(g.exact_s ? pred::sign_beyond_bound<4>(p, nullptr, g.s_bound)
                             : pred::static_sign<4>(g.filter, p, nullptr));
  }
};
// The second pass's: Geo's (every one certain).
struct ExactSigns {
  const Geo& g;
  static constexpr bool undecided = false;
  FF_HD int orient(Index a, Index b, Index c, Index d) const { return g.orient(a, b, c, d); }
  FF_HD int side(Index a, Index b, Index c) const { return g.side(a, b, c); }
};
// The signs of a decision on Geo, for dev::Pass.
struct OnGeo {
  Geo g;
  FF_HD FastSigns fast() const { return FastSigns(g); }
  FF_HD ExactSigns exact() const { return ExactSigns{g}; }
};

// p beyond the triangle t (orient3d(t0, t1, t2, p) < 0, never 0 under SoS);
// key: the rounded (p - t0) · ((t1 - t0) × (t2 - t0)), > 0 beyond, the
// volume |orient(p, t)| of §6.4.1's furthest point (NaN: -inf)
template <class S>
FF_HD bool beyond(S& sg, const Index* t, Index p, double& key) {
  const Geo& g = sg.g;
  const double *o = g.P(t[0]), *b = g.P(t[1]), *c = g.P(t[2]), *q = g.P(p);
  const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
  const double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
  const double k = (q[0] - o[0]) * (by * cz - bz * cy) + (q[1] - o[1]) * (bz * cx - bx * cz) +
                   (q[2] - o[2]) * (bx * cy - by * cx);
  key = k == k ? k : -HUGE_VAL;
  return sg.orient(t[0], t[1], t[2], p) < 0;
}

template <class F>
void two_passes(std::size_t n, const F& f) {
  for_n(n, dev::Pass<F, false>{f});
  for_n(n, dev::Pass<F, true>{f});
}

// ---- arg-max reductions (spread.cuh) -----------------------------------------------
using dev::Best;
using dev::BestOf;
using dev::TetKey;

template <class Key>  // TetKey or OffKey (spread.cuh)
Index argmax(TempStorage& temp, std::size_t n, const Key& key) {
  Best b{-HUGE_VAL, kNone};
  run_with(temp, n, [&](auto policy) {
    b = thrust::transform_reduce(policy, thrust::counting_iterator<std::size_t>(0),
                                 thrust::counting_iterator<std::size_t>(n), key, b, BestOf());
  });
  return b.id;
}

// ---- construction (Algorithm 7 lines 2-14) ---------------------------------------

// Where a point of the construction goes: point i (index p) associated with
// triangle t, dropped when beneath it (line 14), with its distance key.
// In two passes (two_pass.cuh): the first pass marks a point it cannot place
// with drop = kUndecidedDrop and leaves its triangle as it was; the second
// pass places exactly the marked points. Compaction follows both.
struct Assoc {
  uint32_t t;
  double key;
  uint8_t drop;
};
constexpr uint8_t kUndecidedDrop = 2;
struct PointSlots {
  uint32_t* ptri;
  double* pkey;
  uint8_t* drop;
  template <class S>
  FF_HD Assoc associate(S& sg, const Index* tv, Index p, uint32_t t) const {
    Assoc r{t, 0.0, 0};
    r.drop = !beyond(sg, tv + 3 * t, p, r.key);
    return r;
  }
  FF_HD void write(std::size_t i, const Assoc& r) const {
    drop[i] = r.drop;
    ptri[i] = r.t;
    pkey[i] = r.key;
  }
  FF_HD void mark(std::size_t i) const { drop[i] = kUndecidedDrop; }
  FF_HD bool marked(std::size_t i) const { return drop[i] == kUndecidedDrop; }
};

struct NotTetrahedron {
  Index a, b, c, d;
  FF_HD bool operator()(uint32_t p) const { return p != a && p != b && p != c && p != d; }
};

// Line 5 (round 0): point i to the cone of a face of the tetrahedron, faces
// 0 (a,b,c), 1 (a,c,d), 2 (a,d,b), 3 (b,d,c). The faces around d are the 1-3
// split of (a, c, b) by d seen from s, so line 13's rule picks the wedge
// around the line sd; within the wedge of face (x, y, d) the point is in that
// face's cone when it is on d's side of the plane (s, x, y), else in the cone
// of (a, b, c). Line 14: dropped when beneath its face.
struct AssociateRound0 : OnGeo {
  const Index* tv;
  Index a, b, c, d;
  const Index* pid;
  PointSlots out;
  template <class S>
  FF_HD Assoc decide(std::size_t i, S& sg) const {
    const Index p = pid[i];
    uint32_t t;
    if (sg.side(d, a, p) > 0) {
      if (sg.side(d, c, p) < 0) t = sg.side(a, c, p) > 0 ? 1 : 0;  // wedge (a, c, d)
      else t = sg.side(c, b, p) > 0 ? 3 : 0;                        // wedge (c, b, d)
    } else {
      if (sg.side(d, b, p) > 0) t = sg.side(b, a, p) > 0 ? 2 : 0;  // wedge (b, a, d)
      else t = sg.side(c, b, p) > 0 ? 3 : 0;                        // wedge (c, b, d)
    }
    return out.associate(sg, tv, p, t);
  }
  FF_HD void write(std::size_t i, const Assoc& r) const { out.write(i, r); }
  FF_HD void mark(std::size_t i) const { out.mark(i); }
  FF_HD bool marked(std::size_t i) const { return out.marked(i); }
};

// Line 8: per triangle t with points, its furthest point — the larger key,
// ties: the smaller index; among points of key 0 (exactly in t's plane) the
// larger in_plane_tie first (kernels_cpu/hull3/in_plane_tie.hpp: the order of
// the perturbed distance; here rounded to the top 32 bits of its order, the
// CPU kernel compares the doubles) — in passes over the points in place: the
// largest key's bits by atomic maximum; when that key is 0, the largest
// (tie's top 32 bits, complement of the index) by atomic maximum, one
// computation of the tie per point; else the smallest index among the points
// of that key by atomic minimum. The triangles with points are then listed
// in slot order (select), each given its rank k, its point far[k], and its
// entries emptied for later rounds.

// The order of doubles as unsigned integers: x < y exactly when
// ordered_key(x) < ordered_key(y), for keys (never NaN; -0 taken as +0, which
// it equals); 0 is below every key's (a triangle without points).
FF_HD inline unsigned long long ordered_key(double x) {
  const unsigned long long u = cuda::std::bit_cast<unsigned long long>(x == 0 ? 0.0 : x);
  return u >> 63 ? ~u : u | (1ull << 63);
}
struct FurthestKey {
  const uint32_t* ptri;
  const double* pkey;
  unsigned long long* best_key;
  FF_HD void operator()(std::size_t i) const {
    const unsigned long long k = ordered_key(pkey[i]);
    Atomic<unsigned long long> b(best_key[ptri[i]]);
    // a key not above the current maximum leaves it (most, after the first few)
    if (k > b.load(cuda::memory_order_relaxed)) b.fetch_max(k, cuda::memory_order_relaxed);
  }
};
// the ordered key of key 0 (a point exactly in its triangle's plane)
FF_HD inline unsigned long long zero_key() { return ordered_key(0.0); }
struct FurthestTie {
  const double* xyz;
  const Index* tv;
  const uint32_t* ptri;
  const double* pkey;
  const Index* pid;
  const unsigned long long* best_key;
  unsigned long long* best_tie;
  FF_HD void operator()(std::size_t i) const {
    const uint32_t t = ptri[i];
    if (best_key[t] != zero_key() || pkey[i] != 0) return;
    const Index* v = tv + 3 * static_cast<std::size_t>(t);
    const double* c[3] = {xyz + 3 * std::size_t{v[0]}, xyz + 3 * std::size_t{v[1]}, xyz + 3 * std::size_t{v[2]}};
    const double tie = cpu::in_plane_tie(v, c, pid[i], xyz + 3 * std::size_t{pid[i]});
    const unsigned long long order = ordered_key(tie == tie ? tie : -HUGE_VAL) & 0xffffffff00000000ull;
    Atomic<unsigned long long>(best_tie[t]).fetch_max(order | (~pid[i] & 0xffffffffull), cuda::memory_order_relaxed);
  }
};
struct FurthestId {
  const uint32_t* ptri;
  const double* pkey;
  const Index* pid;
  const unsigned long long* best_key;
  Index* best_id;
  FF_HD void operator()(std::size_t i) const {
    const uint32_t t = ptri[i];
    if (best_key[t] == zero_key() || ordered_key(pkey[i]) != best_key[t]) return;
    Atomic<Index>(best_id[t]).fetch_min(pid[i], cuda::memory_order_relaxed);
  }
};
struct HasPoints {
  const unsigned long long* best_key;
  FF_HD bool operator()(uint32_t t) const { return best_key[t] != 0; }
};
struct TakeFurthest {
  const uint32_t* seg_tri;
  unsigned long long* best_key;
  unsigned long long* best_tie;
  Index* best_id;
  Index* far;
  FF_HD void operator()(std::size_t k) const {
    const uint32_t t = seg_tri[k];
    far[k] = best_key[t] == zero_key() ? static_cast<Index>(~best_tie[t] & 0xffffffffull) : best_id[t];
    best_key[t] = 0, best_tie[t] = 0, best_id[t] = kNone;
  }
};

// Line 9, first pass: the round's triangles read their old state (vertices,
// neighbours, and the position of the shared edge in each neighbour) and
// publish their rank k.
struct SplitRead {
  const Index* tv;
  const uint32_t* tn;
  const uint32_t* seg_tri;
  uint32_t* rank;
  Index* old_v;
  uint32_t* old_nb;
  uint8_t* old_pos;
  FF_HD void operator()(std::size_t k) const {
    const uint32_t t = seg_tri[k];
    rank[t] = static_cast<uint32_t>(k);
    for (int e = 0; e < 3; ++e) {
      const uint32_t m = tn[3 * t + e];
      old_v[3 * k + e] = tv[3 * t + e];
      old_nb[3 * k + e] = m;
      uint8_t j = 0;
      while (j < 2 && tn[3 * m + j] != t) ++j;
      old_pos[3 * k + e] = j;
    }
  }
};

// Line 9, second pass: triangle t = (ta, tb, tc) of rank k split by its
// furthest point v into t = (ta, tb, v), T + 2k = (tb, tc, v),
// T + 2k + 1 = (tc, ta, v); old edge e lives on in child e at position 0.
// Writes only the three children's slots: their vertices and inner adjacency.
struct SplitWrite {
  Index* tv;
  uint32_t* tn;
  const uint32_t* seg_tri;
  const Index* far;
  const Index* old_v;
  uint32_t T;
  FF_HD void operator()(std::size_t k) const {
    const uint32_t t = seg_tri[k], n1 = T + 2 * static_cast<uint32_t>(k), n2 = n1 + 1;
    const Index ta = old_v[3 * k], tb = old_v[3 * k + 1], tc = old_v[3 * k + 2], v = far[k];
    tv[3 * t + 2] = v;
    tv[3 * n1] = tb, tv[3 * n1 + 1] = tc, tv[3 * n1 + 2] = v;
    tv[3 * n2] = tc, tv[3 * n2 + 1] = ta, tv[3 * n2 + 2] = v;
    tn[3 * t + 1] = n1, tn[3 * t + 2] = n2;    // b->v | v->b, v->a | a->v
    tn[3 * n1 + 1] = n2, tn[3 * n1 + 2] = t;   // c->v | v->c, v->b | b->v
    tn[3 * n2 + 1] = t, tn[3 * n2 + 2] = n1;   // a->v | v->a, v->c | c->v
  }
};

// Line 9, third pass (§6.4.1's adjacency kernel): the outer edges. A
// neighbour m split in the same round has the shared edge in its child j at
// position 0; an unsplit neighbour's entry for the edge is written by this
// thread only.
struct SplitOuter {
  uint32_t* tn;
  const uint32_t* seg_tri;
  const uint32_t* rank;
  const uint32_t* old_nb;
  const uint8_t* old_pos;
  uint32_t T;
  FF_HD void operator()(std::size_t k) const {
    const uint32_t t = seg_tri[k], n1 = T + 2 * static_cast<uint32_t>(k);
    const uint32_t child[3] = {t, n1, n1 + 1};
    for (int e = 0; e < 3; ++e) {
      const uint32_t m = old_nb[3 * k + e];
      const uint32_t j = old_pos[3 * k + e];
      if (rank[m] != kNone) {
        tn[3 * child[e]] = j == 0 ? m : T + 2 * rank[m] + (j - 1);
      } else {
        tn[3 * child[e]] = m;
        tn[3 * m + j] = child[e];
      }
    }
  }
};

// Lines 10-14: point i of a split triangle to one of the three new cones
// (line 13: the cone of abc is split by the planes (s, v, a), (s, v, b),
// (s, v, c), as in reference/hull3/ffhull.cpp), dropped when it is the
// inserted point (line 10) or beneath its new triangle (line 14).
struct Reassociate : OnGeo {
  const Index* tv;
  const uint32_t* rank;
  const Index* far;
  const Index* old_v;
  uint32_t T;
  const Index* pid;
  PointSlots out;
  template <class S>
  FF_HD Assoc decide(std::size_t i, S& sg) const {
    const Index p = pid[i];
    const uint32_t t = out.ptri[i], k = rank[t];
    const Index v = far[k];
    if (p == v) return Assoc{t, 0.0, 1};
    const Index ta = old_v[3 * k], tb = old_v[3 * k + 1], tc = old_v[3 * k + 2];
    uint32_t ch;
    if (sg.side(v, ta, p) > 0) ch = sg.side(v, tb, p) < 0 ? 0 : 1;
    else ch = sg.side(v, tc, p) > 0 ? 2 : 1;
    const uint32_t u = ch == 0 ? t : T + 2 * k + (ch - 1);
    return out.associate(sg, tv, p, u);
  }
  FF_HD void write(std::size_t i, const Assoc& r) const { out.write(i, r); }
  FF_HD void mark(std::size_t i) const { out.mark(i); }
  FF_HD bool marked(std::size_t i) const { return out.marked(i); }
};

struct ResetRank {
  const uint32_t* seg_tri;
  uint32_t* rank;
  FF_HD void operator()(std::size_t k) const { rank[seg_tri[k]] = kNone; }
};

struct IsSet {
  FF_HD bool operator()(uint8_t f) const { return f != 0; }
};

// ---- flip-flop (Algorithm 6) in parallel rounds -----------------------------------
// A round (§6.4.1, "a checking kernel and a flipping kernel"):
//  1. candidates (IsCandidate): the edges (one directed half each, the one
//     with the smaller tail) whose decision may differ from the previous
//     round's, a superset of the Q of lines 9, 13, 15, 19: the decision of
//     edge ab with triangles abc and bad reads those two triangles, the labels
//     of a, b, c, d and the degrees of a and b, so the candidates are the
//     edges with a triangle changed in the previous round, or with a, b, c or
//     d labelled or of changed degree in it (Apply stamps those vertices), and
//     the edges whose action of the previous round lost its claims. Any other
//     edge decided "no action" last round and would again. The first round,
//     and a last round that confirms the end, take all edges. (With the
//     triangles' changes and the edges' own labels alone, the losers and the
//     changes seen through c, d and the degrees waited for a round over all
//     edges: 116 rounds with operations on 10^6 ball points instead of 68.)
//  2. check (lines 5-19): decide() below, ff3::decide of
//     reference/hull3/flip_flop_3d.cpp on the state at the start of the round;
//  3. claim: a flip labels the triangles of its induced subcomplex T_e (2-2:
//     the two triangles of e; 3-1: the three around the removed vertex) with
//     its edge's id by atomic minimum (§3.3.1, §6.4.1) — done by the thread
//     that decided it, in the decision's pass (Claim);
//  4. flip where every label is still the flip's own (the smallest id always
//     wins: at least one flip per round); labels of non-extreme vertices
//     (line 18) are set by every deciding thread;
//  5. repair the adjacency across the flips' outer edges in a separate pass.
// Why the result is the reference's: the flips of a round touch disjoint
// triangles, so they are applied in some order, each on a state where its
// edge has the same link and its decision (lines 5-15) is unchanged — the
// decision reads the two triangles, the labels of a, b, c, d (set only after
// the round's flips, in step 4) and the degrees of a and b, which matter only
// for a 3-1 flip (lines 6-7), whose whole star is claimed. A label is a fact
// (Lemma 6.5: the vertex lies inside the tetrahedron of s and three vertices
// of the star-shaped polyhedron, hence is non-extreme) and stays true after
// any flip. So every round extends a valid sequential run of the free
// execution order (§3.2); Theorem 6.12 gives termination and the SoS hull.
// The end is confirmed by a round over all edges that decides nothing, and
// then checked as the reference does (no reflex edge, no labelled vertex).

// kUndecided: the first pass of Decide could not decide the edge (two_pass.cuh); the
// second pass replaces it before anything reads the actions.
enum : uint8_t { kNoAction = 0, kFlip31V, kFlip31D, kFlip22V, kFlip22D, kLabel, kUndecided };

// What the host's loop over the rounds kept on the host when it waited for
// every round's count; now in device memory, updated at the end of each round
// (EndRound) from the round's operation count. The rounds count their
// operations in two counters, a round in counts[round % 2]: EndRound, in the
// round's last pass, reads the round's and zeroes the next round's, which no
// thread of that pass reads (for_upto_then).
struct RoundState {
  uint32_t all;     // this round's candidates are all edges (line 2; after a round without operations)
  uint32_t done;    // a round over all edges decided nothing: the end; the rounds after it do nothing
  uint32_t rounds;  // the rounds with operations (Hull3Stats::rounds)
};
struct EndRound {
  const uint32_t* n_ops;
  uint32_t* next_ops;
  RoundState* state;
  FF_HD void operator()(std::size_t) const {
    *next_ops = 0;  // the next round's Decide appends there
    RoundState& s = *state;
    if (s.done) return;
    if (*n_ops == 0) {
      if (s.all) s.done = 1;  // line 2's round found nothing: the end (Theorem 6.12)
      s.all = 1;              // else: a round over all edges confirms it
      return;
    }
    s.all = 0;
    ++s.rounds;
  }
};

// The edge e = 3t + k, a = tv[e] -> b: triangles t = (a, b, c) and
// t2 = (b, a, d), the edge at position j of t2.
struct Quad {
  uint32_t t, k, t2, j;
  Index a, b, c, d;
};

FF_HD inline Quad quad_of(const Index* tv, const uint32_t* tn, uint32_t e) {
  Quad q;
  q.t = e / 3, q.k = e % 3;
  q.a = tv[e], q.b = tv[3 * q.t + next3(q.k)], q.c = tv[3 * q.t + prev3(q.k)];
  q.t2 = tn[e];
  q.j = 0;
  while (q.j < 2 && tv[3 * q.t2 + q.j] != q.b) ++q.j;
  q.d = tv[3 * q.t2 + prev3(q.j)];
  return q;
}

struct IsCandidate {
  const Index* tv;
  const uint32_t* tn;
  const uint8_t* alive;
  const uint32_t* stamp_t;
  const uint32_t* stamp_v;
  const uint8_t* action;  // the previous round's decisions (read by slot e's own thread only)
  uint32_t prev;  // the previous round
  const RoundState* state;  // written only by EndRound, between rounds
  // The loads are grouped by what they depend on, three levels, each
  // issued together: a test after each load (as the conditions read) made a
  // chain of about eleven dependent loads for every edge that is not a
  // candidate, most of them. Every index read is a slot or vertex in range
  // (a dead slot keeps its last vertices and neighbours).
  FF_HD bool operator()(uint32_t e) const {
    if (state->done) return false;  // a round issued after the end: no operations
    const uint32_t t = e / 3, k = e % 3;
    // level 1: the slot's own entries
    const uint8_t live = alive[t];
    const Index u = tv[e], w = tv[3 * t + next3(k)], c = tv[3 * t + prev3(k)];
    const uint8_t act = action[e];
    const uint32_t t2 = tn[e];
    const uint32_t st = stamp_t[t];
    if (!live || !(u < w)) return false;
    if (state->all) return true;
    // level 2: the stamps of t2 and of u, w, c; t2's vertices, for d (quad_of)
    const uint32_t st2 = stamp_t[t2], su = stamp_v[u], sw = stamp_v[w], sc = stamp_v[c];
    const Index x0 = tv[3 * t2], x1 = tv[3 * t2 + 1], x2 = tv[3 * t2 + 2];
    const Index d = x0 == w ? x2 : x1 == w ? x0 : x1;  // the vertex before w in t2 = (w, u, d)
    // level 3
    const uint32_t sd = stamp_v[d];
    // an action last round that lost its claims, or won (then its slot
    // changed); a changed triangle; a, b changed label or degree; the
    // opposite vertices c, d changed label (line 5 reads their labels)
    return act != kNoAction || st == prev || st2 == prev || su == prev || sw == prev || sc == prev || sd == prev;
  }
};

// The triangles of T_e for the decision of edge i (kNone-padded).
struct ClaimTriangles {
  const Index* tv;
  const uint32_t* tn;
  const uint8_t* action;
  const Index* inner;
  FF_HD void operator()(uint32_t i, uint32_t out[3]) const {
    out[0] = out[1] = out[2] = kNone;
    const uint8_t act = action[i];
    if (act == kLabel) return;
    const Quad q = quad_of(tv, tn, i);
    out[0] = q.t, out[1] = q.t2;
    if (act == kFlip31V || act == kFlip31D)  // the third triangle around the removed vertex
      out[2] = tn[3 * q.t + (inner[i] == q.a ? prev3(q.k) : next3(q.k))];
  }
};

// Steps 2-3 for an edge i with an action, by the thread that decided it:
// appended to the round's operations (ops, *n_ops) by atomic increment as
// op r, whose triangles are kept in op_tri[3r..3r+2] (the edge id names other
// triangles once flipped), and claimed by atomic minimum. The operations come
// in whatever order the threads do: nothing depends on it — a claim is won
// by the smallest edge id, and slot r only keeps op r's triangles and outcome
// (won) for the round.
struct Claim {
  ClaimTriangles tris;
  uint32_t* ops;
  uint32_t* n_ops;
  uint32_t* claim;
  uint32_t* op_tri;
  FF_HD void operator()(uint32_t i) const {
    const uint32_t r = Atomic<uint32_t>(*n_ops).fetch_add(1u, cuda::memory_order_relaxed);
    ops[r] = i;
    uint32_t* t = op_tri + 3 * r;
    tris(i, t);
    for (int j = 0; j < 3; ++j)
      if (t[j] != kNone) Atomic<uint32_t>(claim[t[j]]).fetch_min(i, cuda::memory_order_relaxed);
  }
};

// Lines 5-19 for the edge e: the action and the vertex it concerns
// (ff3::decide, line by line), in action[e] and inner[e]; kNoAction for an
// edge that is not a candidate (step 1, tested here: one thread per edge slot,
// no list of candidates). In two passes (two_pass.cuh). An edge with an action
// is listed and claims its triangles in the same pass (Claim).
struct Decision {
  uint8_t action;
  Index inner;
};
struct Decide : OnGeo {
  const Index* tv;
  const uint32_t* tn;
  const uint32_t* deg;
  const uint32_t* labelled;
  IsCandidate candidate;
  uint8_t* action;
  Index* inner;
  Claim claim;  // reads action[i] and inner[i]
  template <class S>
  FF_HD Decision decide(std::size_t i, S& sg) const {  // i: the edge slot e
    if (!candidate(static_cast<uint32_t>(i))) return {kNoAction, kNone};
    const Quad q = quad_of(tv, tn, static_cast<uint32_t>(i));
    Index x = kNone;  // line 5: the labelled vertex of smallest index
    const Index vs[4] = {q.a, q.b, q.c, q.d};
    for (int r = 0; r < 4; ++r)
      if (labelled[vs[r]] && vs[r] < x) x = vs[r];
    const int o = sg.orient(q.a, q.b, q.c, q.d);
    const bool reflex = o < 0;  // §6.1: d beyond abc (s is beneath every triangle)
    if (!reflex && x == kNone) return {kNoAction, kNone};
    // The cone tests of lines 6-7 and 11 and the tetrahedron test of line 14
    // from two orientations with s (kernels_cpu/hull3/ffhull.cpp,
    // FlipFlop::decide, has the derivation): s is beneath every triangle, so
    // in_cone(b, c, d, a) holds exactly when X = Y = +1, in_cone(a, c, d, b)
    // exactly when X = Y = -1, and s lies in abcd exactly when o = Y = +1 = -X,
    // for X = side(b, c, d) and Y = side(a, c, d). (The first pass also no
    // longer defers a decision for a sign that was known all along.)
    const int X = sg.side(q.b, q.c, q.d), Y = sg.side(q.a, q.c, q.d);
    const bool a_in = X > 0 && Y > 0, b_in = X < 0 && Y < 0;
    // lines 6-7: an endpoint of degree 3 inside the cone of its link's triangle
    Index in31 = kNone;
    if (deg[q.a] == 3 && a_in) in31 = q.a;
    else if (deg[q.b] == 3 && b_in) in31 = q.b;
    if (in31 != kNone) {  // line 8
      if (labelled[in31]) return {kFlip31D, in31};
      return {reflex ? kFlip31V : kNoAction, in31};
    }
    // line 11: C_s(T_e) convex
    if (!a_in && !b_in) {
      if (x == kNone) return {reflex ? kFlip22V : kNoAction, kNone};  // lines 12-13
      const bool s_in = o > 0 && Y > 0 && X < 0;
      if ((x == q.a || x == q.b) && !s_in) return {kFlip22D, kNone};  // lines 14-15
      return {kNoAction, kNone};
    }
    // lines 16-18: label the inner endpoint (Lemma 6.5)
    const Index in = a_in ? q.a : q.b;
    if (!labelled[in] && reflex) return {kLabel, in};
    return {kNoAction, kNone};
  }
  FF_HD void write(std::size_t i, const Decision& r) const {
    action[i] = r.action;
    if (r.action == kNoAction) return;
    inner[i] = r.inner;  // read for the actions only
    claim(static_cast<uint32_t>(i));
  }
  FF_HD void mark(std::size_t i) const { action[i] = kUndecided; }
  FF_HD bool marked(std::size_t i) const { return action[i] == kUndecided; }
};

// Step 4's test: won[r] = 1 when every claim of op r holds (labels: always).
struct Won {
  const uint32_t* ops;
  const uint32_t* op_tri;
  const uint32_t* claim;
  uint8_t* won;
  FF_HD void operator()(std::size_t r) const {
    const uint32_t* t = op_tri + 3 * r;
    uint8_t ok = 1;
    for (int j = 0; j < 3; ++j)
      if (t[j] != kNone && claim[t[j]] != ops[r]) ok = 0;
    won[r] = ok;
  }
};

// The codes of applied operations (for the counters).
enum : uint8_t { kLost = 0, kDid22 = 1, kDid31 = 2, kNewLabel = 3, kOldLabel = 4 };
// The applied operations by kind, added up over the rounds on the device
// (counts[0] 2-2 flips, [1] 3-1 flips, [2] new labels) and read once at the end.
struct CountOp {
  const uint8_t* won;
  unsigned long long* counts;
  FF_HD void operator()(std::size_t r) const {
    const uint8_t code = won[r];
    const int k = code == kDid22 ? 0 : code == kDid31 ? 1 : code == kNewLabel ? 2 : -1;
    if (k >= 0) Atomic<unsigned long long>(counts[k]).fetch_add(1ull, cuda::memory_order_relaxed);
  }
};

// Step 4: the winning flips rewrite their own triangle slots (vertices, inner
// adjacency; the outer entries keep the *old* neighbour ids for step 5) and
// publish, per slot, that it changed this round (stamp_t) and which live slot
// of the same flip may hold an edge it had (partner); degrees by atomics.
// Labels (line 18) by atomic exchange; the vertex's edges are stamped (line 19).
struct Apply {
  ClaimTriangles tris;
  const uint32_t* ops;
  const uint32_t* op_tri;
  Index* tv;
  uint32_t* tn;
  uint8_t* alive;
  uint32_t* partner;
  uint32_t* stamp_t;
  uint32_t* stamp_v;
  uint32_t* deg;
  uint32_t* labelled;
  uint8_t* won;
  uint32_t round;
  // a vertex whose label or degree changed this round (other flips may stamp it too)
  FF_HD void stamp(Index v) const { Atomic<uint32_t>(stamp_v[v]).store(round, cuda::memory_order_relaxed); }
  FF_HD void operator()(std::size_t r) const {
    if (!won[r]) return;
    const uint32_t i = ops[r];
    const uint8_t act = tris.action[i];
    if (act == kLabel) {
      const Index x = tris.inner[i];
      won[r] = Atomic<uint32_t>(labelled[x]).exchange(1u, cuda::memory_order_relaxed) ? kOldLabel : kNewLabel;
      stamp(x);
      return;
    }
    const Quad q = quad_of(tv, tn, i);
    if (act == kFlip22V || act == kFlip22D) {
      // lines 13 / 15: (a, b, c), (b, a, d) -> (a, d, c), (d, b, c)
      const uint32_t n_bc = tn[3 * q.t + next3(q.k)], n_ca = tn[3 * q.t + prev3(q.k)];
      const uint32_t n_ad = tn[3 * q.t2 + next3(q.j)], n_db = tn[3 * q.t2 + prev3(q.j)];
      Index* A = tv + 3 * q.t;
      Index* B = tv + 3 * q.t2;
      A[0] = q.a, A[1] = q.d, A[2] = q.c;
      B[0] = q.d, B[1] = q.b, B[2] = q.c;
      uint32_t* nA = tn + 3 * q.t;
      uint32_t* nB = tn + 3 * q.t2;
      nA[0] = n_ad, nA[1] = q.t2, nA[2] = n_ca;
      nB[0] = n_db, nB[1] = n_bc, nB[2] = q.t;
      partner[q.t] = q.t2, partner[q.t2] = q.t;
      stamp_t[q.t] = round, stamp_t[q.t2] = round;
      Atomic<uint32_t>(deg[q.a]).fetch_sub(1u, cuda::memory_order_relaxed);
      Atomic<uint32_t>(deg[q.b]).fetch_sub(1u, cuda::memory_order_relaxed);
      Atomic<uint32_t>(deg[q.c]).fetch_add(1u, cuda::memory_order_relaxed);
      Atomic<uint32_t>(deg[q.d]).fetch_add(1u, cuda::memory_order_relaxed);
      for (const Index v : {q.a, q.b, q.c, q.d}) stamp(v);
      won[r] = kDid22;
      return;
    }
    // line 9: the 3-1 flip of x; each triangle (x, u, w) of its star gives the
    // link edge u -> w with its outer neighbour; the link triangle replaces
    // the star in slot t, the other two slots die
    const Index x = tris.inner[i];
    const uint32_t* star = op_tri + 3 * r;
    Index u[3], w[3];
    uint32_t o[3];
    for (int s = 0; s < 3; ++s) {
      const uint32_t t = star[s];
      uint32_t px = 0;
      while (px < 2 && tv[3 * t + px] != x) ++px;
      u[s] = tv[3 * t + next3(px)], w[s] = tv[3 * t + prev3(px)];
      o[s] = tn[3 * t + next3(px)];
    }
    const int s1 = u[1] == w[0] ? 1 : 2, s2 = 3 - s1;  // the link cycle u0 -> w0 = u[s1] -> w[s1] = u[s2]
    const uint32_t t = star[0];
    tv[3 * t] = u[0], tv[3 * t + 1] = w[0], tv[3 * t + 2] = w[s1];
    tn[3 * t] = o[0], tn[3 * t + 1] = o[s1], tn[3 * t + 2] = o[s2];
    for (int s = 0; s < 3; ++s) {
      partner[star[s]] = t;
      stamp_t[star[s]] = round;
      if (s > 0) alive[star[s]] = 0;
    }
    deg[x] = 0;  // x is in no live triangle: no other thread touches its degree
    Atomic<uint32_t>(deg[u[0]]).fetch_sub(1u, cuda::memory_order_relaxed);
    Atomic<uint32_t>(deg[w[0]]).fetch_sub(1u, cuda::memory_order_relaxed);
    Atomic<uint32_t>(deg[w[s1]]).fetch_sub(1u, cuda::memory_order_relaxed);
    for (const Index v : {u[0], w[0], w[s1]}) stamp(v);
    won[r] = kDid31;
  }
};

// Step 5: for each new triangle of a winning flip, each outer edge x -> y
// (its entry still holds the old neighbour m): an unchanged m gets its entry
// for y -> x set to the new triangle (only this thread writes it); a changed
// m (stamp_t == round) holds y -> x in m itself, when m is still alive and
// has it, else in partner[m] — the flips of a round keep their outer edges
// in their own live slots. Reads only vertices, alive and partner, which
// step 5 does not write.
// One thread per outer edge (x = kLinks r + j: link j of op r): each link is
// a chain of dependent loads, and one thread doing an op's four one after
// another took 28 us a round on an H200 (Nsight Compute, 10^7 ball points).
// Links run in parallel safely: a link writes its own entry, or the entry of
// an unchanged neighbour for its edge, which no other link reads or writes.
struct Repair {
  static constexpr uint32_t kLinks = 4;  // a 2-2 flip's outer edges; a 3-1 flip has 3
  const uint32_t* ops;
  const uint8_t* won;
  const Index* tv;
  uint32_t* tn;
  const uint8_t* alive;
  const uint32_t* partner;
  const uint32_t* stamp_t;
  uint32_t round;
  FF_HD int find(uint32_t m, Index y, Index x) const {  // the position of y -> x in m, or -1
    for (uint32_t j = 0; j < 3; ++j)
      if (tv[3 * m + j] == y && tv[3 * m + next3(j)] == x) return static_cast<int>(j);
    return -1;
  }
  FF_HD void link(uint32_t s, uint32_t q) const {
    const Index x = tv[3 * s + q], y = tv[3 * s + next3(q)];
    const uint32_t m = tn[3 * s + q];
    if (stamp_t[m] != round) {
      const int j = find(m, y, x);
      if (j >= 0) tn[3 * m + j] = s;
      return;
    }
    if (alive[m] && find(m, y, x) >= 0) return;  // tn[3s + q] = m already
    tn[3 * s + q] = partner[m];
  }
  FF_HD void operator()(std::size_t x) const {
    const std::size_t r = x / kLinks;
    const uint32_t j = static_cast<uint32_t>(x % kLinks);
    if (won[r] != kDid22 && won[r] != kDid31) return;
    const uint32_t t = ops[r] / 3;
    if (won[r] == kDid31) {
      if (j < 3) link(t, j);
      return;
    }
    // (a, d, c): a -> d, c -> a; partner (d, b, c): d -> b, b -> c
    if (j < 2) link(t, j == 0 ? 0 : 2);
    else link(partner[t], j == 2 ? 0 : 1);
  }
};

// f(x / K) for the first of each K consecutive x (a per-op step in a pass
// of K threads per op).
template <class F, uint32_t K>
struct OnFirst {
  F f;
  FF_HD void operator()(std::size_t x) const {
    if (x % K == 0) f(x / K);
  }
};

struct ResetClaims {
  const uint32_t* op_tri;
  uint32_t* claim;
  FF_HD void operator()(std::size_t r) const {
    const uint32_t* t = op_tri + 3 * r;
    for (int j = 0; j < 3; ++j)
      if (t[j] != kNone) Atomic<uint32_t>(claim[t[j]]).store(kNone, cuda::memory_order_relaxed);
  }
};

struct CountDegree {
  const Index* tv;
  uint32_t* deg;
  FF_HD void operator()(std::size_t i) const { Atomic<uint32_t>(deg[tv[i]]).fetch_add(1u, cuda::memory_order_relaxed); }
};

// The end state (ff3::final_problem): 1 per reflex edge / per labelled vertex left.
struct ReflexEdge {
  Geo g;
  const Index* tv;
  const uint32_t* tn;
  const uint8_t* alive;
  FF_HD std::size_t operator()(std::size_t e) const {
    const uint32_t t = static_cast<uint32_t>(e / 3), k = static_cast<uint32_t>(e % 3);
    if (!alive[t] || !(tv[e] < tv[3 * t + next3(k)])) return 0;
    const Quad q = quad_of(tv, tn, static_cast<uint32_t>(e));
    return g.orient(q.a, q.b, q.c, q.d) < 0 ? 1 : 0;
  }
};
struct LabelledVertex {
  const uint32_t* deg;
  const uint32_t* labelled;
  FF_HD std::size_t operator()(std::size_t v) const { return deg[v] != 0 && labelled[v] != 0 ? 1 : 0; }
};

// ---- output ---------------------------------------------------------------------
struct Tri {
  Index v[3];
};
struct IsAlive {
  const uint8_t* alive;
  FF_HD bool operator()(uint32_t t) const { return alive[t] != 0; }
};
// canonical_rotation: an even permutation bringing the smallest index first
struct CanonicalTri {
  const Index* tv;
  FF_HD Tri operator()(uint32_t t) const {
    const Index* p = tv + 3 * t;
    const uint32_t m = p[0] < p[1] ? (p[0] < p[2] ? 0 : 2) : (p[1] < p[2] ? 1 : 2);
    return {{p[m], p[next3(m)], p[prev3(m)]}};
  }
};
struct TriLess {
  FF_HD bool operator()(const Tri& x, const Tri& y) const {
    if (x.v[0] != y.v[0]) return x.v[0] < y.v[0];
    if (x.v[1] != y.v[1]) return x.v[1] < y.v[1];
    return x.v[2] < y.v[2];
  }
};
static_assert(sizeof(Tri) == sizeof(Triangle), "Tri and Triangle must be three packed ids");

// ---- the whole computation ------------------------------------------------------

// The buffers of the steps: allocated once and not initialised (every step
// writes before it reads; the few with initial values are filled in
// parallel), so that in the OpenMP build the unused tail of a buffer sized
// for the worst case is never touched (backend::Scratch).
using backend::Scratch;

// Every buffer of the computation, sized from n once (§6.4.1 grows its arrays;
// here the bounds are allocated up front): at most max_tri = 2n - 4 triangle
// slots (every insertion adds two), at most n - 4 triangles split in a round
// (each has a point), at most 3 max_tri / 2 edges.
struct Buffers {
  TempStorage temp;  // the steps' temporary storage, reused
  backend::Buffer<double> coords;
  // points under construction
  Scratch<Index> pid;
  Scratch<uint32_t> ptri;
  Scratch<double> pkey;
  Scratch<uint8_t> drop;
  // the surface: 3 entries per slot
  Scratch<Index> tv;
  Scratch<uint32_t> tn;
  Scratch<uint8_t> alive;
  // construction rounds: per slot its rank in the round; per split triangle
  Scratch<uint32_t> rank, seg_tri;
  Scratch<Index> far;
  // per slot: the largest key's bits, the largest tie among its points of
  // key 0, and the smallest index of that key (and tie) among its points
  Scratch<unsigned long long> best_key, best_tie;
  Scratch<Index> best_id;
  Scratch<Index> old_v;
  Scratch<uint32_t> old_nb;
  Scratch<uint8_t> old_pos;
  // flip-flop: per slot, per vertex, per candidate edge
  Scratch<uint32_t> claim, partner, stamp_t;
  Scratch<uint32_t> deg, labelled, stamp_v;
  Scratch<uint32_t> ops, op_tri;
  Scratch<uint8_t> action, won;
  Scratch<Index> inner;
  // a round's operation count; the rounds' state; the operations by kind
  Scratch<uint32_t> counts;
  Scratch<RoundState> state;
  Scratch<unsigned long long> op_counts;

  Buffers(std::size_t n, std::size_t max_tri) {
    pid.resize(n), ptri.resize(n), pkey.resize(n), drop.resize(n);
    tv.resize(3 * max_tri), tn.resize(3 * max_tri), alive.resize(max_tri);
    rank.resize(max_tri), seg_tri.resize(n), far.resize(n);
    best_key.resize(max_tri), best_tie.resize(max_tri), best_id.resize(max_tri);
    old_v.resize(3 * n), old_nb.resize(3 * n), old_pos.resize(3 * n);
    claim.resize(max_tri), partner.resize(max_tri), stamp_t.resize(max_tri);
    deg.resize(n), labelled.resize(n), stamp_v.resize(n);
    // operations: at most one per edge (its directed half with the smaller
    // tail); ops also lists the live slots at the output
    const std::size_t max_edges = 3 * max_tri / 2;
    ops.resize(max_edges), op_tri.resize(3 * max_edges), won.resize(max_edges);
    action.resize(3 * max_tri), inner.resize(3 * max_tri);  // per edge slot
    counts.resize(2), state.resize(1), op_counts.resize(3);
    fill_n(raw(rank), max_tri, kNone);
    fill_n(raw(best_key), max_tri, 0ull);
    fill_n(raw(best_tie), max_tri, 0ull);
    fill_n(raw(best_id), max_tri, kNone);
    fill_n(raw(deg), n, uint32_t{0});
    fill_n(raw(labelled), n, uint32_t{0});
    fill_n(raw(stamp_v), n, uint32_t{0});
  }
};

class Hull3 {
 public:
  // xyz: the coordinates where the steps read them (backend::to_device)
  // steps: null, or the clock that times every step (see step())
  // exact: the exact kernel point (s is then its rounded coordinates), or null
  Hull3(const PointSet& ps, const double* xyz, const std::array<Index, 4>& tet, const std::array<double, 3>& s,
        const ref::RationalKernel* exact, Buffers& B, ref::Hull3Stats& st, cpu::StageClock* steps)
      : n_(ps.size()), tet_(tet), B_(B), st_(st), steps_(steps) {
    g_.xyz = xyz;
    // the per-input filter over the coordinates where they are (one reduction)
    // and the kernel point's
    g_.filter = filter::static_filter<kParallelFrom>(xyz, 3 * n_, nullptr, 0, s.data(), 3);
    for (int j = 0; j < 3; ++j) g_.s[j] = s[j];
    g_.n = static_cast<uint32_t>(n_);
    g_.exact_s = exact != nullptr;
    g_.s_bound = exact ? exact->static_bound() : 0.0;
    for (int j = 0; j < 12; ++j) g_.src[j] = exact ? exact->point().src[j] : 0.0;
  }

  void construct() {
    const Index a = tet_[0], b = tet_[1], c = tet_[2], d = tet_[3];
    // line 3: the tetrahedron, faces 0 (a,b,c), 1 (a,c,d), 2 (a,d,b), 3 (b,d,c)
    const Index faces[12] = {a, b, c, a, c, d, a, d, b, b, d, c};
    uint32_t adj[12];
    for (uint32_t t = 0; t < 4; ++t)
      for (uint32_t k = 0; k < 3; ++k)
        for (uint32_t r = 0; r < 4; ++r)
          for (uint32_t j = 0; j < 3; ++j)
            if (faces[3 * r + j] == faces[3 * t + next3(k)] && faces[3 * r + next3(j)] == faces[3 * t + k])
              adj[3 * t + k] = r;
    thrust::copy(faces, faces + 12, B_.tv.begin());
    thrust::copy(adj, adj + 12, B_.tn.begin());
    T_ = 4;
    Index* pid = raw(B_.pid);
    uint32_t* ptri = raw(B_.ptri);
    double* pkey = raw(B_.pkey);
    uint8_t* drop = raw(B_.drop);
    // lines 2, 5, 14 (round 0)
    std::size_t m = select(B_.temp, n_, pid, NotTetrahedron{a, b, c, d});
    two_passes(m, AssociateRound0{{g_}, raw(B_.tv), a, b, c, d, pid, {ptri, pkey, drop}});
    std::size_t kept = compact(m);
    st_.discarded_early += m - kept;
    m = kept;
    step("construction: round 0");
    // lines 6-14 in rounds: every triangle with points is split at once
    while (m > 0) {
      ++st_.rounds;
      // line 8 (see FurthestKey)
      for_n(m, FurthestKey{ptri, pkey, raw(B_.best_key)});
      for_n(m, FurthestTie{g_.xyz, raw(B_.tv), ptri, pkey, pid, raw(B_.best_key), raw(B_.best_tie)});
      for_n(m, FurthestId{ptri, pkey, pid, raw(B_.best_key), raw(B_.best_id)});
      const std::size_t K = select(B_.temp, T_, raw(B_.seg_tri), HasPoints{raw(B_.best_key)});
      for_n(K, TakeFurthest{raw(B_.seg_tri), raw(B_.best_key), raw(B_.best_tie), raw(B_.best_id), raw(B_.far)});
      step("construction: furthest points");
      const uint32_t T = T_;
      for_n(K, SplitRead{raw(B_.tv), raw(B_.tn), raw(B_.seg_tri), raw(B_.rank), raw(B_.old_v), raw(B_.old_nb),
                         raw(B_.old_pos)});
      for_n(K, SplitWrite{raw(B_.tv), raw(B_.tn), raw(B_.seg_tri), raw(B_.far), raw(B_.old_v), T});
      for_n(K, SplitOuter{raw(B_.tn), raw(B_.seg_tri), raw(B_.rank), raw(B_.old_nb), raw(B_.old_pos), T});
      step("construction: split");
      two_passes(m, Reassociate{{g_}, raw(B_.tv), raw(B_.rank), raw(B_.far), raw(B_.old_v), T, pid,
                                {ptri, pkey, drop}});
      for_n(K, ResetRank{raw(B_.seg_tri), raw(B_.rank)});
      step("construction: re-association");
      T_ += 2 * static_cast<uint32_t>(K);
      kept = compact(m);
      step("construction: compaction");
      st_.insertions += K;
      st_.discarded_early += m - kept - K;  // the K inserted points are not discarded
      m = kept;
    }
    st_.flips_1_3 = st_.insertions;
  }

  void flip_flop() {
    const std::size_t T = T_;
    fill_n(raw(B_.alive), T, uint8_t{1});
    fill_n(raw(B_.claim), T, kNone);
    fill_n(raw(B_.stamp_t), T, uint32_t{0});
    for_n(3 * T, CountDegree{raw(B_.tv), raw(B_.deg)});  // line 1: labels are all 0 ("unknown")
    Index* tv = raw(B_.tv);
    uint32_t* tn = raw(B_.tn);
    uint32_t* ops = raw(B_.ops);
    // the rounds' operation counts, in device memory (see for_upto and RoundState)
    uint32_t* counts = raw(B_.counts);
    fill_n(counts, 2, uint32_t{0});
    unsigned long long* op_counts = raw(B_.op_counts);
    fill_n(op_counts, 3, 0ull);
    RoundState* state = raw(B_.state);
    fill_n(state, 1, RoundState{1, 0, 0});  // line 2: every edge
    // a round's operations: at most one per edge (one directed half each),
    // 3T / 2 on the closed surface of T (or fewer live) slots
    const std::size_t E = 3 * T / 2;
    step("flip-flop: set-up");
    // The host issues the rounds without waiting for them, and reads their
    // state once every kRoundsPerWait rounds: a wait leaves the device idle
    // for a round trip and the next launch (68 rounds on 10^7 ball points),
    // while a round issued after the end costs its launches and one pass over
    // the edge slots that writes "no action" (IsCandidate). The stamps still
    // name every issued round, so a round's candidates are the ones it had
    // when the host waited for every round.
    for (uint32_t round = 1;; ++round) {
      uint32_t* n_ops = counts + round % 2;
      // steps 1-3 in one pass over the edge slots (two, with the exact one):
      // each edge with an action is listed and claims its triangles (Claim)
      const ClaimTriangles tris{tv, tn, raw(B_.action), raw(B_.inner)};
      two_passes(3 * T, Decide{{g_}, tv, tn, raw(B_.deg), raw(B_.labelled),
                               IsCandidate{tv, tn, raw(B_.alive), raw(B_.stamp_t), raw(B_.stamp_v),
                                           raw(B_.action), round - 1, state},
                               raw(B_.action), raw(B_.inner),
                               Claim{tris, ops, n_ops, raw(B_.claim), raw(B_.op_tri)}});
      step("flip-flop: decision and claims");
      // steps 4-5 (a round without operations runs them over none); step 4's
      // test (Won) reads only claims, which Apply does not write, and Repair
      // reads no claims: each pair is one pass (Then)
      for_upto(E, n_ops,
               Then<Won, Apply>{Won{ops, raw(B_.op_tri), raw(B_.claim), raw(B_.won)},
                                Apply{tris, ops, raw(B_.op_tri), tv, tn, raw(B_.alive), raw(B_.partner),
                                      raw(B_.stamp_t), raw(B_.stamp_v), raw(B_.deg), raw(B_.labelled), raw(B_.won),
                                      round}});
      step("flip-flop: apply");
      // and the round's end (EndRound) in the same pass, Repair::kLinks
      // threads per operation
      constexpr uint32_t L = Repair::kLinks;
      for_upto_then<L>(E, n_ops,
                       Then<Repair, OnFirst<Then<ResetClaims, CountOp>, L>>{
                           Repair{ops, raw(B_.won), tv, tn, raw(B_.alive), raw(B_.partner), raw(B_.stamp_t),
                                  round},
                           {{ResetClaims{raw(B_.op_tri), raw(B_.claim)}, CountOp{raw(B_.won), op_counts}}}},
                       EndRound{n_ops, counts + (round + 1) % 2, state});
      step("flip-flop: repair");
      if (round % kRoundsPerWait != 0) continue;
      const RoundState now = read_back(state);  // the host's one wait in kRoundsPerWait rounds
      step("flip-flop: round state");
      if (now.done) {
        st_.rounds += now.rounds;
        break;
      }
    }
    unsigned long long c[3];
    thrust::copy(B_.op_counts.begin(), B_.op_counts.begin() + 3, c);
    st_.flips_2_2 += c[0];
    st_.flips_3_1 += c[1];
    st_.labelled_non_extreme += c[2];
    // Theorems 6.2 and 6.12: all edges convex and no non-extreme vertex left
    std::size_t reflex = 0, labelled = 0;
    run_with(B_.temp, 3 * T, [&](auto policy) {
      reflex = thrust::transform_reduce(policy, thrust::counting_iterator<std::size_t>(0),
                                        thrust::counting_iterator<std::size_t>(3 * T),
                                        ReflexEdge{g_, tv, tn, raw(B_.alive)}, std::size_t{0},
                                        thrust::plus<std::size_t>());
      labelled = thrust::transform_reduce(policy, thrust::counting_iterator<std::size_t>(0),
                                          thrust::counting_iterator<std::size_t>(n_),
                                          LabelledVertex{raw(B_.deg), raw(B_.labelled)}, std::size_t{0},
                                          thrust::plus<std::size_t>());
    });
    step("flip-flop: final check");
    if (reflex || labelled)
      throw std::logic_error("hull3 (kernels): flip-flop ended with " + std::to_string(reflex) + " reflex edges and " +
                             std::to_string(labelled) + " non-extreme vertices");
  }

  // The live triangles in canonical order (reference/canonical.hpp), on the
  // device; returns their number (in B_.ops as slots, then as Tri in `out`).
  std::size_t output(backend::Buffer<Tri>& out) {
    uint32_t* slots = raw(B_.ops);
    const std::size_t F = select(B_.temp, T_, slots, IsAlive{raw(B_.alive)});
    out.resize(F);
    run_with(B_.temp, F, [&](auto policy) {
      thrust::transform(policy, slots, slots + F, raw(out), CanonicalTri{raw(B_.tv)});
      thrust::sort(policy, raw(out), raw(out) + F, TriLess());
    });
    return F;
  }

 private:
  // Drops the points with drop[i] set (stable); returns how many are kept.
  std::size_t compact(std::size_t m) {
    if (m == 0) return 0;
    std::size_t kept = 0;
    run_with(B_.temp, m, [&](auto policy) {
      const auto first = thrust::make_zip_iterator(thrust::make_tuple(raw(B_.pid), raw(B_.ptri), raw(B_.pkey)));
      kept = static_cast<std::size_t>(thrust::remove_if(policy, first, first + m, raw(B_.drop), IsSet()) - first);
    });
    return kept;
  }
  // With FLIPFLOP_GPU_STEPS set (and --stats), every step of the
  // construction and flip-flop rounds is a stage of its own, summed over the
  // rounds, timed after a wait for the device (for attribution only: the
  // waits themselves cost time), in a second run (hull3_ffhull); otherwise
  // nothing.
  void step(const char* name) {
    if (!steps_) return;
    backend::sync();
    steps_->mark(name);
  }

  std::size_t n_;
  std::array<Index, 4> tet_;
  Buffers& B_;
  ref::Hull3Stats& st_;
  cpu::StageClock* steps_;
  Geo g_{};
  uint32_t T_ = 0;
};

// Line 1 by reductions (spread.cuh: floating keys, repaired by exact ones).
// by_reference: the reference's sequential rule ran (a hand-back, counted in
// the stats; it only rejects input that does not span R^3).
std::array<Index, 4> initial_tetrahedron(TempStorage& temp, const PointSet& ps, const double* xyz, bool* by_reference) {
  return dev::spanning_tetrahedron(
      ps, xyz, [&](const auto& key) { return argmax(temp, ps.size(), key); }, by_reference);
}

// Runs f, turning a failed allocation of device memory (std::bad_alloc, from
// which thrust's bad_alloc derives: the buffers, or the temporary storage of
// a sort or reduction) into the kernels' DeviceMemoryError.
template <class F>
auto on_device(std::size_t n, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw kernels::DeviceMemoryError("hull3: " + std::to_string(n) + " points do not fit in device memory");
  }
}

// by_step: the construction and flip-flop by step (Hull3::step), else as two stages
std::vector<Triangle> compute(const PointSet& ps, ref::Hull3Stats& st, cpu::StageClock& clock, bool by_step) {
  const std::size_t n = ps.size();
  if (ps.dim != 3 || n < 4) {
    ref::ffhull::initial_tetrahedron(ps);  // throws the reference's message
    throw std::logic_error("hull3 (kernels): the reference accepted input of fewer than 4 points");
  }
  if (n >= (std::size_t{1} << 29))
    throw std::invalid_argument("hull3 (kernels): too many points for 32-bit triangle and edge ids");
  std::unique_ptr<Buffers> B;
  const double* xyz = on_device(n, [&] {
    B = std::make_unique<Buffers>(n, 2 * n);
    return backend::to_device(ps.coords.data(), ps.coords.size(), B->coords);
  });
  clock.mark("upload");
  bool by_reference = false;
  const std::array<Index, 4> tet =
      on_device(n, [&] { return initial_tetrahedron(B->temp, ps, xyz, &by_reference); });  // line 1
  st.handed_back += by_reference;
  // line 4: the rounded centroid, when strictly inside the tetrahedron exactly;
  // else (§6.4.2) the exact centroid, as the reference's (its four points are
  // exactly independent: initial_tetrahedron)
  std::array<double, 3> s{};
  std::unique_ptr<ref::RationalKernel> exact;
  if (!cpu::rounded_centroid(ps, tet, s)) {
    exact = std::make_unique<ref::RationalKernel>(ref::centroid_kernel(ps, tet[0], tet[1], tet[2], tet[3]));
    for (int j = 0; j < 3; ++j) s[j] = exact->point().approx[j].v;
    ++st.exact_kernel_point;
  }
  return on_device(n, [&] {
    Hull3 h(ps, xyz, tet, s, exact.get(), *B, st, by_step ? &clock : nullptr);
    clock.mark("tetrahedron");
    h.construct();  // lines 2-14
    if (!by_step) clock.mark("construction");
    h.flip_flop();  // line 15
    if (!by_step) clock.mark("flip-flop");
    backend::Buffer<Tri> tris;
    const std::size_t F = h.output(tris);
    clock.mark("output");
    const std::vector<Tri> host = backend::to_host(tris, F);
    std::vector<Triangle> out(F);
    if (F) std::memcpy(out.data(), host.data(), F * sizeof(Tri));
    clock.mark("download");
    return out;
  });
}

}  // namespace hull3_detail

std::vector<Triangle> hull3_ffhull(const PointSet& ps, ref::Hull3Stats* stats, cpu::StageTimes* times) {
  backend::require_device("hull3 ffhull");
  const bool by_step = times != nullptr && std::getenv("FLIPFLOP_GPU_STEPS") != nullptr;
  if (by_step) {
    // one untimed run first: a kernel's first launch in a process (module
    // loading; on the device, local memory for the exact stage's frames) costs
    // far more than its work — seen on an H200: a process's first 10^7-point
    // hull 0.4 s, the next ones 0.06 s — and would be counted in its step
    ref::Hull3Stats warm;
    cpu::StageClock untimed(nullptr);
    hull3_detail::compute(ps, warm, untimed, false);
  }
  ref::Hull3Stats st;
  cpu::StageClock clock(times);
  std::vector<Triangle> out = hull3_detail::compute(ps, st, clock, by_step);
  if (stats) *stats = st;
  return out;
}

}  // namespace flipflop::FF_KERNELS_NS

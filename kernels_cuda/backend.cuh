// backend.cuh — where a kernel's data lives and how its steps run, for every
// thrust kernel of kernels_cuda/ (classify.cuh, predicates_device.cuh), in the
// namespace FF_KERNELS_NS::backend of the including build:
//   OpenMP backend (host compiler): the "device" is the host. Buffers are
//     std::vector, the functors read the caller's arrays in place, and below a
//     grain size (a template argument: it depends on the cost of one item) one
//     thread does the work — opening a parallel region costs more than it saves
//     there, and on a loaded machine OpenMP's spinning barriers cost most.
//   CUDA: copies to and from device memory; every step runs on the device.
#pragma once

#ifndef FF_KERNELS_NS
#error "define FF_KERNELS_NS (kernels_omp or kernels_cuda) before including backend.cuh"
#endif

#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/for_each.h>
#include <thrust/iterator/counting_iterator.h>
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
#include <thrust/system/omp/execution_policy.h>
#else
#include <cuda_runtime_api.h>
#endif

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernels_cuda/kernel_errors.hpp"
#include "reference/default_init.hpp"

namespace flipflop::FF_KERNELS_NS::backend {

#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_OMP
template <class T>
using Buffer = std::vector<T>;
// Scratch<T>: a buffer every step writes before it reads — in the OpenMP build
// its elements are left uninitialised (std::vector would zero n elements, a
// pass over memory that costs as much as a kernel step); on the device an
// ordinary Buffer.
template <class T>
using Scratch = UninitVector<T>;  // reference/default_init.hpp
template <class T>
const T* to_device(const T* first, std::size_t, Buffer<T>&) {
  return first;
}
template <class T>
std::vector<T> to_host(Buffer<T>& b, std::size_t count) {
  b.resize(count);
  return std::move(b);
}
template <std::size_t ParallelFrom, class Step>
void run_step(std::size_t n, Step&& step) {
  if (n < ParallelFrom)
    step(thrust::seq);
  else
    step(thrust::omp::par);
}
// run_step for a step whose caller does not read its result on the host
// before the next step (for_each, fill): the same as run_step here.
template <std::size_t ParallelFrom, class Step>
void run_step_async(std::size_t n, Step&& step) {
  run_step<ParallelFrom>(n, std::forward<Step>(step));
}
// every step issued so far has finished (a stage clock's mark follows it)
inline void sync() {}
// the host is the device: always there
inline void require_device(const char*) {}
#else
template <class T>
using Buffer = thrust::device_vector<T>;
template <class T>
using Scratch = thrust::device_vector<T>;
template <class T>
const T* to_device(const T* first, std::size_t count, Buffer<T>& b) {
  if (count == 0) return nullptr;
  b.assign(first, first + count);
  return thrust::raw_pointer_cast(b.data());
}
template <class T>
std::vector<T> to_host(Buffer<T>& b, std::size_t count) {
  std::vector<T> h(count);
  thrust::copy(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(count), h.begin());
  return h;
}
template <std::size_t ParallelFrom, class Step>
void run_step(std::size_t, Step&& step) {
  step(thrust::device);
}
// thrust's default device policy blocks the host until each algorithm has
// finished; par_nosync returns after the launch. Every step runs on the
// default stream, so the next step (or copy to the host) still starts after
// this one: only the host's wait, and the idle device while the host issues
// the next launch, are saved. For steps whose result the host does not read
// (an algorithm that returns a value, e.g. copy_if's end, still waits).
template <std::size_t ParallelFrom, class Step>
void run_step_async(std::size_t, Step&& step) {
  step(thrust::cuda::par_nosync);
}
inline void sync() { cudaDeviceSynchronize(); }
// kernels::NoDeviceError ("<who>: no CUDA device") unless one is usable
inline void require_device(const char* who) {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error of a missing driver
    count = 0;
  }
  if (count <= 0) throw kernels::NoDeviceError(std::string(who) + " (--backend cuda): no CUDA device; use --backend cuda-omp or cpu");
}
#endif

// ---- helpers of the kernels' host code (rt2.cuh, rt3.cuh) -------------------------
// The buffer's data as a pointer the functors take.
template <class T>
T* raw(Buffer<T>& b) {
  return thrust::raw_pointer_cast(b.data());
}
// One element read on the host (a copy from the device in the CUDA build).
template <class T>
T read_one(Buffer<T>& b, std::size_t i) {
  return static_cast<T>(b[i]);
}
// f(i) for i in [0, count), as one step (run_step).
template <std::size_t ParallelFrom, class F>
void for_range(std::size_t count, const F& f) {
  if (count == 0) return;
  thrust::counting_iterator<std::uint32_t> first(0);
  run_step<ParallelFrom>(count, [&](auto policy) { thrust::for_each(policy, first, first + count, f); });
}

}  // namespace flipflop::FF_KERNELS_NS::backend

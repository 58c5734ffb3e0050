// elections.cuh — what the insertion rounds of the GPU triangulations (rt2.cuh,
// rt3.cuh) share: atomics on plain arrays through cuda::atomic_ref (libcu++,
// also for the host compiler), and the election of one point per cell
// (triangle, tetrahedron): each point votes for its cell with an atomic
// minimum of vote_key, and the point whose key is the minimum wins.
#pragma once

#include <cuda/atomic>

#include <cstdint>

#include "predicates/err_double.hpp"  // FF_HD

namespace flipflop::dev {

template <class T>
FF_HD inline T atomic_fetch_min(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_min(v, cuda::memory_order_relaxed);
}
template <class T>
FF_HD inline T atomic_fetch_add(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_add(v, cuda::memory_order_relaxed);
}
template <class T>
FF_HD inline T atomic_exchange(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.exchange(v, cuda::memory_order_relaxed);
}
// (several threads may store one value to one entry: atomic, so that the
// stores do not race)
template <class T>
FF_HD inline void atomic_store(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  r.store(v, cuda::memory_order_relaxed);
}

// A point's vote for its cell: a hash of the point first (any point may be
// chosen; a pseudo-random one splits a cell's points evenly in expectation),
// the point index breaking ties.
FF_HD inline std::uint64_t vote_key(std::uint32_t p) {
  std::uint32_t h = p * 0x9E3779B1u;
  h ^= h >> 15;
  h *= 0x85EBCA77u;
  h ^= h >> 13;
  return (static_cast<std::uint64_t>(h) << 32) | p;
}

// Point p's vote for its cell loc[p] (best: the cells' minima, ~0 before).
struct Vote {
  const std::uint32_t* loc;
  std::uint64_t* best;
  FF_HD void operator()(std::uint32_t p) const { atomic_fetch_min(best + loc[p], vote_key(p)); }
};

// Did point p win the election of its cell loc[p]?
struct IsWinner {
  const std::uint32_t* loc;
  const std::uint64_t* best;
  FF_HD bool operator()(std::uint32_t p) const { return best[loc[p]] == vote_key(p); }
};

}  // namespace flipflop::dev

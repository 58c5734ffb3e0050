// witnessed_output.hpp — the last check of the witness certifiers
// (kernels_cpu/rt2/certify_rt2.cpp, kernels_cpu/rt3/certify_rt3.cpp), written
// once: every real simplex of the witness is in the output.
//
// The output T is sorted, strictly increasing and of as many simplices as the
// witness has real slots (checked by the caller), each simplex in canonical
// form (smallest index first), so holding every witnessed simplex makes it
// the set of the witnessed ones. The witnessed simplices come as the caller's
// pass over fixed chunks of slots gathered them: part[ch] the canonical
// simplices of chunk ch's real slots, pos[ch * B + b] how many of them have
// bucket(smallest index) = b.
//
// Looked up in slot order, each witnessed simplex would be a cache miss in
// `first` and in the output; bucketed by smallest index (each chunk writing
// its own ranges), each bucket is looked up in its own small range of both.
// Only when one is absent are the slots walked again, in order, to name the
// smallest such slot.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels_cpu/parallel.hpp"
#include "reference/certify/certify_detail.hpp"

namespace flipflop::cpu {

// The smallest slot t < slots with real(t) whose canonical simplex
// simplex_of(t) is not in T, or `slots` when every witnessed simplex is in T.
// n: the number of points (every index of T below n); B, bucket: the buckets
// of part and pos (header); part is emptied and pos overwritten.
template <class Simplex, class Bucket, class ForRange, class Real, class SimplexOf>
std::size_t first_unwitnessed_slot(std::size_t n, const std::vector<Simplex>& T,
                                   std::vector<std::vector<Simplex>>& part, std::vector<std::size_t>& pos,
                                   std::size_t B, const Bucket& bucket, std::size_t slots, const ForRange& for_range,
                                   const Real& real, const SimplexOf& simplex_of) {
  const std::size_t chunks = part.size();
  // first[m]: the first output simplex whose smallest index is >= m (each m
  // written by one i: race-free)
  std::vector<std::uint32_t> first(n + 1);
  par_for(T.size() + 1, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t from = i == 0 ? 0 : std::size_t{T[i - 1][0]} + 1, to = i == T.size() ? n : T[i][0];
      for (std::size_t m = from; m <= to; ++m) first[m] = static_cast<std::uint32_t>(i);
    }
  });
  auto in_output = [&](const Simplex& x) {
    for (std::uint32_t i = first[x[0]]; i < first[x[0] + 1]; ++i)
      if (T[i] == x) return true;
    return false;
  };
  // bucket-major write positions: bucket b of chunk ch after all of bucket
  // b's earlier chunks and all smaller buckets
  std::size_t total = 0;
  for (std::size_t b = 0; b < B; ++b)
    for (std::size_t ch = 0; ch < chunks; ++ch) {
      const std::size_t k = pos[ch * B + b];
      pos[ch * B + b] = total;
      total += k;
    }
  std::vector<Simplex> by_bucket(total);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t ch = lo; ch < hi; ++ch) {
      for (const Simplex& x : part[ch]) by_bucket[pos[ch * B + bucket(x[0])]++] = x;
      std::vector<Simplex>().swap(part[ch]);
    }
  });
  std::atomic<bool> absent{false};
  par_for(total, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i)
      if (!in_output(by_bucket[i])) absent.store(true, std::memory_order_relaxed);
  });
  if (!absent.load()) return slots;
  // name the smallest such slot
  return certify::detail::smallest_failing(slots, for_range,
                                           [&](std::size_t t) { return real(t) && !in_output(simplex_of(t)); });
}

}  // namespace flipflop::cpu

// witnessed_output.hpp — what the witness certifiers of the triangulation
// kernels (kernels_cpu/rt2/certify_rt2.cpp, kernels_cpu/rt3/certify_rt3.cpp)
// check alike, written once: the witness' shape, its points (a permutation of
// the input, bit for bit) and its slots' corner indices, first; and last,
// that every real simplex of the witness is in the output.
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

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "kernels_cpu/parallel.hpp"
#include "reference/certify/certify_detail.hpp"

namespace flipflop::cpu {

// The witness-size, witness-points and <indices> conditions of a witness of
// K corners per slot (3: triangles, 4: tetrahedra) over the n points of ps:
// pts a permutation of the input with every coordinate and weight equal bit
// for bit (coords(q): q's coordinates, ps.dim of them); tv and tn of equal
// size, K per slot, fewer than kNo / K slots; each slot unused (all K corners
// kNo) or K distinct positions <= n (n: the virtual vertex). The first
// failing condition's Report, or nothing when all hold. `what`: "triangle"
// or "tetrahedra" in the messages, indices: the slots' condition's name.
template <std::size_t K, class Pt, class Coords, class ForRange>
std::optional<certify::Report> witness_problem(const PointSet& ps, const std::vector<Pt>& pts,
                                               const std::vector<std::uint32_t>& at,
                                               const std::vector<std::uint32_t>& tv,
                                               const std::vector<std::uint32_t>& tn, std::uint32_t kNo,
                                               const char* what, const char* indices, const Coords& coords,
                                               const ForRange& for_range) {
  using certify::Report;
  using certify::detail::smallest_failing;
  const std::size_t n = ps.size();
  if (pts.size() != n || at.size() != n || tv.size() != tn.size() || tv.size() % K != 0 || tv.size() / K >= kNo / K)
    return Report::fail("witness-size", "the witness has " + std::to_string(pts.size()) + " points, " +
                                            std::to_string(at.size()) + " witness " + what + ", " +
                                            std::to_string(tv.size()) + " corners and " + std::to_string(tn.size()) +
                                            " links for " + std::to_string(n) + " input points");
  {
    std::vector<std::atomic<std::uint8_t>> seen(n);  // zero-initialised
    const std::size_t d = ps.dim;
    auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    if (const std::size_t k = smallest_failing(n, for_range,
                                               [&](std::size_t k) {
                                                 const Pt& q = pts[k];
                                                 if (q.id >= n) return true;
                                                 seen[q.id].store(1, std::memory_order_relaxed);
                                                 const double *x = ps.point(q.id), *y = coords(q);
                                                 for (std::size_t i = 0; i < d; ++i)
                                                   if (!same(y[i], x[i])) return true;
                                                 return !same(q.w, ps.weight(q.id));
                                               });
        k < n)
      return Report::fail("witness-points", "position " + std::to_string(k) + " names input point " +
                                                std::to_string(pts[k].id) +
                                                " with other coordinates or weight, or one that does not exist");
    // n positions with values in [0, n): a permutation iff every value is met
    if (const std::size_t i = smallest_failing(
            n, for_range, [&](std::size_t i) { return seen[i].load(std::memory_order_relaxed) == 0; });
        i < n)
      return Report::fail("witness-points", "input point " + std::to_string(i) + " is at no position of the witness");
  }
  const std::size_t slots = tv.size() / K;
  if (const std::size_t t = smallest_failing(slots, for_range,
                                             [&](std::size_t t) {
                                               const std::uint32_t* c = &tv[K * t];
                                               std::size_t unused = 0;
                                               for (std::size_t i = 0; i < K; ++i) unused += c[i] == kNo;
                                               if (unused != 0) return unused != K;
                                               for (std::size_t i = 0; i < K; ++i) {
                                                 if (c[i] > n) return true;
                                                 for (std::size_t j = 0; j < i; ++j)
                                                   if (c[i] == c[j]) return true;
                                               }
                                               return false;
                                             });
      t < slots) {
    std::string c;
    for (std::size_t i = 0; i < K; ++i) c += (i ? ", " : "") + std::to_string(tv[K * t + i]);
    return Report::fail(indices, "slot " + std::to_string(t) + " holds positions " + c + " of " + std::to_string(n) +
                                     " points and the virtual vertex " + std::to_string(n));
  }
  return std::nullopt;
}

// Positions in a canonical output T (simplices strictly increasing, every
// index below n, the smallest first in each): find(x) is x's index in T, or
// T.size() when x is not there. first[m]: the first simplex whose smallest
// index is >= m (built in parallel, each m written by one i: race-free); a
// lookup is a binary search among the simplices with x's smallest index, so
// a vertex that is the smallest index of very many simplices (a fan of flat
// ones over coplanar points) costs O(log), not O(run).
template <class Simplex>
struct OutputIndex {
  const std::vector<Simplex>& T;
  std::vector<std::uint32_t> first;
  OutputIndex(std::size_t n, const std::vector<Simplex>& t) : T(t), first(n + 1) {
    par_for(T.size() + 1, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) {
        const std::size_t from = i == 0 ? 0 : std::size_t{T[i - 1][0]} + 1, to = i == T.size() ? n : T[i][0];
        for (std::size_t m = from; m <= to; ++m) first[m] = static_cast<std::uint32_t>(i);
      }
    });
  }
  std::size_t find(const Simplex& x) const {
    if (std::size_t{x[0]} + 1 >= first.size()) return T.size();
    const auto b = T.begin() + first[x[0]], e = T.begin() + first[x[0] + 1];
    const auto it = std::lower_bound(b, e, x);
    return it != e && *it == x ? static_cast<std::size_t>(it - T.begin()) : T.size();
  }
};

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
  const OutputIndex<Simplex> index(n, T);
  auto in_output = [&](const Simplex& x) { return index.find(x) < T.size(); };
  const std::size_t total = bucket_major_positions(pos, chunks, B)[B];
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

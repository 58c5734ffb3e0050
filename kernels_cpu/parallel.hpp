// parallel.hpp — the data-parallel steps the multithreaded kernels share
// (kernels_cpu/hull2, kernels_cpu/hull3), written once on oneTBB:
//
//   with_threads            run f() on exactly `threads` threads (0: the
//                           runtime's default);
//   par_for                 tbb::parallel_for over [0, n) in blocks, fork/join
//                           declared to ThreadSanitizer (tsan.hpp);
//   par_argmax              deterministic arg-max (a strict total order on
//                           (key, index), so the answer does not depend on how
//                           the range is split or on the thread count);
//   par_sort                sort by a strict total order (chunks sorted in
//                           parallel, then merged pairwise in parallel
//                           rounds): the result is unique, so it does not
//                           depend on the thread count;
//   make_units              pieces of at most kChunk points of segmented lists;
//   par_select              the indices i of [0, n) with keep(i), in increasing
//                           order (fixed chunks, each filtered by one task,
//                           then concatenated in chunk order);
//   parallel_static_filter  the per-input static filter of
//                           predicates/static_filter.hpp from a parallel scan
//                           (of values, or of a point set with its weights);
//   certify_in_parallel     a reference certifier with certify::Speedups
//                           (parallel per-point checks, parallel filter scan).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "kernels_cpu/tsan.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cpu {

constexpr std::uint32_t kNone = ~std::uint32_t{0};
constexpr std::size_t kChunk = std::size_t{1} << 13;  // points per work unit

// The thread count for a call on n items: `threads`, but 1 where it is 0
// (the runtime's default) and n is below `sequential_below` — small inputs,
// whose parallel rounds cost more in wake-ups and joins than they save (the
// caller measures its threshold).
inline int threads_for_size(int threads, std::size_t n, std::size_t sequential_below) {
  return threads == 0 && n < sequential_below ? 1 : threads;
}

// f() inside a task arena of exactly `threads` threads, also more than the
// machine's cores (TBB caps its worker pool at the core count unless told
// otherwise: the cap is raised for the call then, and only then — a
// global_control is process-wide, and lowering it would also throttle other
// threads' TBB work while f runs, e.g. a small hull that threads_for_size
// sends to one thread); threads == 0: the runtime's default.
template <class F>
void with_threads(int threads, const F& f) {
  if (threads <= 0) {
    f();
    return;
  }
  std::optional<tbb::global_control> allow;
  if (threads > tbb::info::default_concurrency())
    allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  arena.execute([&] { f(); });
}

// tbb::parallel_for over [0, n) in blocks, body(lo, hi); the fork/join edges
// are declared to ThreadSanitizer (kernels_cpu/tsan.hpp).
template <class Body>
void par_for(std::size_t n, std::size_t grain, const Body& body) {
  if (n == 0) return;
  tsan::ForkJoin fj;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
    fj.task_begin();
    body(r.begin(), r.end());
    fj.task_end();
  });
  fj.joined();
}

// Bucket-major write positions for a parallel scatter into buckets: at[c *
// B + b] holds piece c's number of items in bucket b and becomes the
// position of its first one — bucket b's pieces in piece order, after every
// smaller bucket — so that pieces writing their items in order keep each
// bucket in piece order. Returns the buckets' starts (B + 1 entries, the
// last the total).
template <class Count>
std::vector<std::size_t> bucket_major_positions(std::vector<Count>& at, std::size_t pieces, std::size_t B) {
  std::vector<std::size_t> start(B + 1, 0);
  std::size_t total = 0;
  for (std::size_t b = 0; b < B; ++b) {
    start[b] = total;
    for (std::size_t c = 0; c < pieces; ++c) {
      const std::size_t k = at[c * B + b];
      at[c * B + b] = static_cast<Count>(total);
      total += k;
    }
  }
  start[B] = total;
  return start;
}

// ---- deterministic parallel arg-max ------------------------------------------
// A candidate (key, index); the larger key wins, equal keys the smaller index,
// NaN keys count as -inf. A strict total order, so the result does not depend
// on how the range is split: fixed chunks, each reduced by one task, then the
// chunk results combined in order.
struct Best {
  double key = -HUGE_VAL;
  Index i = kNone;
};
inline bool better(double key, Index i, const Best& b) {
  if (std::isnan(key)) key = -HUGE_VAL;
  if (b.i == kNone) return true;
  return key > b.key || (key == b.key && i < b.i);
}
// K arg-maxima in one pass: keys(p, k, state) fills k[0 .. K) for point p;
// entry j of the result is the arg-max of key j (each by the order above).
// state: the chunk's own State (states[c] for chunk c when states is given,
// sized here), for a scan of its own that rides on the same pass.
struct NoChunkState {};
template <int K, class State = NoChunkState, class Keys>
std::array<Index, K> par_argmax_multi(std::size_t n, const Keys& keys, std::vector<State>* states = nullptr) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::array<Best, K>> part(chunks);
  if (states) states->assign(chunks, State{});
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c) {
      // `better` within a chunk, whose indices increase: after the first
      // element only a strictly larger key wins (a NaN key compares false,
      // like -inf against any best), one comparison per key and element
      State own{};
      State& state = states ? (*states)[c] : own;
      // (in blocks of kB points: the block's maximum per key without a
      // branch, and only a block that beats the best is searched for the
      // first point with that key — the same point as one comparison each)
      constexpr std::size_t kB = 8;
      const std::size_t first = c * kChunk, end = std::min(n, (c + 1) * kChunk);
      double k0[K], best[K];
      Index at[K];
      keys(static_cast<Index>(first), k0, state);
      for (int j = 0; j < K; ++j) best[j] = std::isnan(k0[j]) ? -HUGE_VAL : k0[j], at[j] = static_cast<Index>(first);
      for (std::size_t b = first + 1; b < end; b += kB) {
        const std::size_t m = std::min(kB, end - b);
        double kb[kB][K], top[K];
        for (std::size_t i = 0; i < m; ++i) keys(static_cast<Index>(b + i), kb[i], state);
        // (from -inf, so that a NaN key, which compares false, never hides the block's others)
        for (int j = 0; j < K; ++j) top[j] = -HUGE_VAL;
        for (std::size_t i = 0; i < m; ++i)
          for (int j = 0; j < K; ++j) top[j] = kb[i][j] > top[j] ? kb[i][j] : top[j];
        for (int j = 0; j < K; ++j) {
          if (!(top[j] > best[j])) continue;
          std::size_t i = 0;
          while (!(kb[i][j] > best[j])) ++i;
          best[j] = kb[i][j], at[j] = static_cast<Index>(b + i);
          for (++i; i < m; ++i)
            if (kb[i][j] > best[j]) best[j] = kb[i][j], at[j] = static_cast<Index>(b + i);
        }
      }
      for (int j = 0; j < K; ++j) part[c][j] = Best{best[j], at[j]};
    }
  });
  std::array<Index, K> out;
  for (int j = 0; j < K; ++j) {
    Best b;
    for (const auto& c : part)
      if (c[j].i != kNone && better(c[j].key, c[j].i, b)) b = c[j];
    out[j] = b.i;
  }
  return out;
}
template <class Key>
Index par_argmax(std::size_t n, const Key& key) {
  return par_argmax_multi<1>(n, [&](Index p, double* k, NoChunkState&) { k[0] = key(p); })[0];
}

// ---- work units of segmented point lists ----------------------------------------
// Points grouped in K segments, segment k = [lo[k], lo[k + 1]); a unit is a
// piece of at most kChunk points of one segment (load balance for the few
// huge segments of the first rounds and the many small ones later).
struct Units {
  std::vector<std::uint32_t> seg;
  std::vector<std::size_t> lo, hi;
  std::vector<std::size_t> first;  // per segment: its first unit; size K + 1
};
inline Units make_units(const std::vector<std::size_t>& lo) {
  Units U;
  const std::size_t K = lo.empty() ? 0 : lo.size() - 1;
  U.first.reserve(K + 1);
  for (std::size_t k = 0; k < K; ++k) {
    U.first.push_back(U.seg.size());
    for (std::size_t i = lo[k]; i < lo[k + 1]; i += kChunk) {
      U.seg.push_back(static_cast<std::uint32_t>(k));
      U.lo.push_back(i);
      U.hi.push_back(std::min(lo[k + 1], i + kChunk));
    }
  }
  U.first.push_back(U.seg.size());
  return U;
}

// ---- parallel sort -------------------------------------------------------------
// Chunks of kChunk elements sorted by one task each (std::sort), then rounds
// of pairwise merges of neighbouring runs (std::merge, one task per pair).
// Written with par_for rather than tbb::parallel_sort so that every hand-off
// is a fork/join declared to ThreadSanitizer. `less` must be a strict total
// order on the elements (no two equivalent), which makes the result unique.
template <class T, class Less>
void par_sort(std::vector<T>& v, const Less& less) {
  const std::size_t n = v.size();
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c)
      std::sort(v.begin() + static_cast<std::ptrdiff_t>(c * kChunk),
                v.begin() + static_cast<std::ptrdiff_t>(std::min(n, (c + 1) * kChunk)), less);
  });
  if (chunks <= 1) return;
  std::vector<T> out(n);
  for (std::size_t width = kChunk; width < n; width *= 2) {
    const std::size_t pairs = (n + 2 * width - 1) / (2 * width);
    par_for(pairs, 1, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t p = lo; p < hi; ++p) {
        const std::size_t a = p * 2 * width, m = std::min(n, a + width), e = std::min(n, a + 2 * width);
        std::merge(v.begin() + static_cast<std::ptrdiff_t>(a), v.begin() + static_cast<std::ptrdiff_t>(m),
                   v.begin() + static_cast<std::ptrdiff_t>(m), v.begin() + static_cast<std::ptrdiff_t>(e),
                   out.begin() + static_cast<std::ptrdiff_t>(a), less);
      }
    });
    v.swap(out);
  }
}

// ---- deterministic parallel selection ----------------------------------------
// The i in [0, n) with keep(i), increasing. Chunks of kChunk are filtered by
// one task each into their own buffer, the buffers concatenated in order: the
// result is the sequential filter's, whatever the thread count.
template <class Keep>
std::vector<Index> par_select(std::size_t n, const Keep& keep) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<Index>> part(chunks);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c)
      for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
        if (keep(static_cast<Index>(i))) part[c].push_back(static_cast<Index>(i));
  });
  std::size_t total = 0;
  for (const auto& p : part) total += p.size();
  std::vector<Index> out;
  out.reserve(total);
  for (const auto& p : part) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// ---- the per-input static filter, scanned in parallel -------------------------
// StaticFilter::for_points over the m values value(0..m) and `extra`, as if
// they were one input: it depends only on the largest magnitude, the lowest
// set bit over all values and whether all are finite, so it is computed on a
// few representatives (per chunk: the largest magnitude, a value of the lowest
// set bit, a non-finite value if any) plus the extra values given. The lowest
// set bit of a finite non-zero x is the L with x a multiple of 2^L: with
// exponent field e and fraction f, L = e - 1075 + ctz(f + 2^52) for e > 0,
// -1074 + ctz(f) for subnormals.

// One chunk's representatives: add(x) for each of its values, then put(out)
// writes the largest magnitude, a value of the lowest set bit and a
// non-finite value if any (0 where none) to out[0..3).
struct FilterScan {
  // on the bits, without a branch but the rare non-finite one: a finite
  // value's magnitude orders as its bits without the sign; its lowest set bit
  // is L (above), written with the subnormal case folded in (exponent field
  // 0: no implicit bit, the scale of field 1), zeros mapped to no bit at all
  double bad = 0.0;
  std::uint64_t big_bits = 0;
  int low_e = std::numeric_limits<int>::max();
  void add(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    const std::uint64_t mag = b & ~(std::uint64_t{1} << 63);
    if (mag >= (std::uint64_t{0x7ff} << 52)) {  // inf or NaN
      bad = x;
      return;
    }
    big_bits = std::max(big_bits, mag);
    const int e = static_cast<int>(mag >> 52);
    const std::uint64_t mant = (mag & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{e != 0} << 52);
    const int lb = std::max(e, 1) - 1075 + __builtin_ctzll(mant | (std::uint64_t{1} << 63));
    low_e = std::min(low_e, mag != 0 ? lb : std::numeric_limits<int>::max());
  }
  // representatives: the largest magnitude and a value of the lowest set bit,
  // 2^low_e itself (no larger than the value it came from); the filter
  // depends on magnitudes and that bit only
  void put(double* out) const {
    double big;
    std::memcpy(&big, &big_bits, sizeof big);
    out[0] = big;
    out[1] = low_e == std::numeric_limits<int>::max() ? 0.0 : std::ldexp(1.0, low_e);
    out[2] = bad;
  }
};

// Per chunk of the m values value(0..m): FilterScan's three representatives.
template <class Value>
std::vector<double> filter_representatives(std::size_t m, const Value& value) {
  const std::size_t chunks = (m + kChunk - 1) / kChunk;
  std::vector<double> reps(chunks * 3, 0.0);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c) {
      FilterScan scan;
      for (std::size_t i = c * kChunk; i < std::min(m, (c + 1) * kChunk); ++i) scan.add(value(i));
      scan.put(&reps[3 * c]);
    }
  });
  return reps;
}

// The filter of representatives (filter_representatives, FilterScan) and the
// extra values; largest, when given: the largest magnitude among them.
inline pred::StaticFilter static_filter_of(std::vector<double> reps, const std::vector<double>& extra,
                                           double* largest = nullptr) {
  reps.insert(reps.end(), extra.begin(), extra.end());
  if (largest) {
    *largest = 0.0;
    for (std::size_t i = 0; i < reps.size(); ++i) *largest = std::fmax(*largest, std::fabs(reps[i]));
  }
  while (reps.size() % 3) reps.push_back(0.0);
  return pred::StaticFilter::for_points(reps.data(), reps.size() / 3, 3);
}

// largest, when given: the largest magnitude among the values and `extra`
// (from the representatives; no pass of its own)
template <class Value>
pred::StaticFilter parallel_static_filter(std::size_t m, const Value& value, const std::vector<double>& extra,
                                          double* largest = nullptr) {
  return static_filter_of(filter_representatives(m, value), extra, largest);
}

// The same over the coordinates of ps and `extra`, and ps' weights when it
// has them (StaticFilter::for_points(coords, n, dim, weights)): the weights'
// representatives are the weights of as many points (zeros added on either
// side change neither the magnitudes nor the lowest bit).
inline pred::StaticFilter parallel_static_filter(const PointSet& ps, const std::vector<double>& extra) {
  // (raw pointers: Values::operator[] asks whether the values are borrowed at every access)
  const double* coords = ps.coords.data();
  std::vector<double> reps = filter_representatives(ps.coords.size(), [coords](std::size_t i) { return coords[i]; });
  reps.insert(reps.end(), extra.begin(), extra.end());
  std::vector<double> w;
  const double* weights = ps.weights.data();
  if (ps.weighted) w = filter_representatives(ps.weights.size(), [weights](std::size_t i) { return weights[i]; });
  const std::size_t points = std::max((reps.size() + 2) / 3, w.size());
  reps.resize(3 * points, 0.0);
  w.resize(points, 0.0);
  return pred::StaticFilter::for_points(reps.data(), points, 3, ps.weighted ? w.data() : nullptr);
}

// par_for over pieces of `grain` items as certify::Speedups::for_range (the
// certifiers' shared helpers in certify_detail.hpp take it)
inline decltype(certify::Speedups::for_range) par_for_range(std::size_t grain = kChunk) {
  return [grain](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) { par_for(n, grain, body); };
}

// Runs certify(speedups) (a certifier of reference/certify taking
// certify::Speedups) inside an arena of `threads` workers (0: the runtime's
// default), the per-point checks split into pieces of `grain` (kChunk by
// default), the static filter of the input (its coordinates, its weights if
// any, and the certifier's extra values) from a parallel scan.
template <class Certify>
certify::Report certify_in_parallel(const PointSet& ps, int threads, const Certify& certify,
                                    std::size_t grain = kChunk) {
  certify::Report r;
  with_threads(threads, [&] {
    certify::Speedups s;
    s.make_filter = [&](const std::vector<double>& extra) { return parallel_static_filter(ps, extra); };
    s.for_range = par_for_range(grain);
    r = certify(s);
  });
  return r;
}

}  // namespace flipflop::cpu

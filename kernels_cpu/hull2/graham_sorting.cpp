// graham_sorting.cpp — parallel Graham-sorting with chunked flip-pop (thesis
// §4.2 Algorithm 3; see graham_sorting.hpp).
#include "kernels_cpu/hull2/graham_sorting.hpp"

#include <algorithm>

#include "kernels_cpu/parallel.hpp"
#include "predicates/fast.hpp"

namespace flipflop::cpu::hull2 {

// orient2d(a, b, c) under SoS: the static filter, then the staged predicate.
int orient(const pred::StaticFilter& f, const Pt2& a, const Pt2& b, const Pt2& c) {
  return pred::fast::orient2d(f, {a.i, &a.x}, {b.i, &b.x}, {c.i, &c.x});
}

// a before b in x under the perturbation (a strict total order on distinct
// indices: the sort's result is unique).
bool x_less(const Pt2& a, const Pt2& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.i == b.i) return false;
  return pred::compare_sos({a.i, &a.x}, {b.i, &b.x}, 0) < 0;
}

namespace {

// Flip-pop on c[lo, hi) as a stack scan, the two ends held; the kept vertices
// are moved to c[lo, lo + k), k returned. A pop removes the stack's top p_i
// between p_j (below it) and p_k (the next vertex): its neighbours in the
// current polygon, so it is the 2-1 flip of Alg 1 line 6 when p_i ∈ △ s p_j
// p_k, i.e. orient2d(p_j, p_k, p_i) > 0 for both chains (flip_pop.hpp).
std::size_t scan(const pred::StaticFilter& f, Pt2* c, std::size_t lo, std::size_t hi, std::size_t& flips) {
  std::size_t top = lo;  // c[lo, top) is the stack
  for (std::size_t k = lo; k < hi; ++k) {
    while (top - lo >= 2 && orient(f, c[top - 2], c[k], c[top - 1]) > 0) {
      --top;
      ++flips;
    }
    c[top++] = c[k];
  }
  return top - lo;
}

}  // namespace

std::vector<Pt2> flip_pop_chain(std::vector<Pt2> chain, const pred::StaticFilter& f, std::size_t chunk,
                                ScanCounts& counts) {
  const std::size_t n = chain.size();
  const std::size_t chunks = (n + chunk - 1) / chunk;
  std::vector<std::size_t> kept(chunks), flips(chunks, 0);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c)
      kept[c] = scan(f, chain.data(), c * chunk, std::min(n, (c + 1) * chunk), flips[c]);
  });
  std::size_t m = 0;
  for (std::size_t c = 0; c < chunks; ++c) {
    std::copy_n(chain.begin() + static_cast<std::ptrdiff_t>(c * chunk), kept[c],
                chain.begin() + static_cast<std::ptrdiff_t>(m));
    m += kept[c];
    counts.flips_2_1 += flips[c];
  }
  std::size_t last = 0;
  m = scan(f, chain.data(), 0, m, last);
  counts.flips_2_1 += last;
  counts.passes += 2;
  chain.resize(m);
  return chain;
}

pred::StaticFilter static_filter_of(const std::vector<Pt2>& pts) {
  return parallel_static_filter(
      2 * pts.size(), [&](std::size_t v) { return v & 1 ? pts[v >> 1].y : pts[v >> 1].x; }, {});
}

std::vector<Index> graham_sorting(std::vector<Pt2> pts, const pred::StaticFilter& f, std::size_t chunk,
                                  ScanCounts& counts, StageClock* clock) {
  chunk = std::max<std::size_t>(chunk, 1);
  // lines 4-5, once for both sets: the x order under the perturbation
  par_sort(pts, x_less);
  if (clock) clock->mark("sort by x");
  // line 1
  const Pt2 vl = pts.front(), vr = pts.back();
  const std::size_t n = pts.size();
  // lines 2-3: label, then select stably (both sets stay sorted by x)
  std::vector<char> above(n, 0);
  par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = std::max<std::size_t>(lo, 1); k < std::min(hi, n - 1); ++k)
      above[k] = orient(f, vl, vr, pts[k]) > 0;
  });
  const std::vector<Index> a = par_select(n, [&](Index k) { return k > 0 && k + 1 < n && above[k]; });
  const std::vector<Index> b = par_select(n, [&](Index k) { return k > 0 && k + 1 < n && !above[k]; });
  // line 6: the upper chain v_r, S_a (x descending), v_l; the lower chain v_l,
  // S_b (x ascending), v_r
  std::vector<Pt2> upper(a.size() + 2), lower(b.size() + 2);
  upper.front() = vr, upper.back() = vl;
  lower.front() = vl, lower.back() = vr;
  par_for(std::max(a.size(), b.size()), kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      if (k < a.size()) upper[a.size() - k] = pts[a[k]];
      if (k < b.size()) lower[k + 1] = pts[b[k]];
    }
  });
  // line 7: flip-pop
  upper = flip_pop_chain(std::move(upper), f, chunk, counts);
  lower = flip_pop_chain(std::move(lower), f, chunk, counts);
  std::vector<Index> cycle;
  cycle.reserve(upper.size() + lower.size() - 2);
  for (std::size_t k = 0; k + 1 < upper.size(); ++k) cycle.push_back(upper[k].i);
  for (std::size_t k = 0; k + 1 < lower.size(); ++k) cycle.push_back(lower[k].i);
  if (clock) clock->mark("split and flip-pop");
  return cycle;
}

}  // namespace flipflop::cpu::hull2

// graham_insertion.cpp — parallel Graham-insertion (thesis §4.3 Algorithm 4;
// see graham_insertion.hpp).
#include "kernels_cpu/hull2/graham_insertion.hpp"

#include <algorithm>
#include <cstdint>

#include "kernels_cpu/parallel.hpp"

namespace flipflop::cpu::hull2 {

namespace {

// The points associated with the edges, grouped: the points of segment k are
// pts[lo[k], lo[k + 1]), associated with polygon edge edge[k] (poly[e] ->
// poly[e + 1], cyclically); only edges with points have a segment.
struct Segments {
  std::vector<Pt2> pts;
  std::vector<std::size_t> lo;
  std::vector<std::uint32_t> edge;
  std::size_t count() const { return edge.size(); }
};

// Distance key of u beyond p -> q: the rounded cross product (q - p) x (p - u),
// positive for u beyond (clockwise of) the edge, growing with the distance.
inline double beyond_key(const Pt2& p, const Pt2& q, const Pt2& u) {
  return (q.x - p.x) * (p.y - u.y) - (q.y - p.y) * (p.x - u.x);
}

}  // namespace

std::vector<Index> graham_insertion(std::vector<Pt2> pts, const pred::StaticFilter& f, std::size_t chunk,
                                    ScanCounts& scan, InsertionCounts& counts, StageClock* clock) {
  const std::size_t n = pts.size();
  // line 1: the extremes in x under the perturbation (x_less is a strict total
  // order, so the reduction's answer does not depend on the split)
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::pair<std::size_t, std::size_t>> ext(chunks);
  par_for(chunks, 1, [&](std::size_t clo, std::size_t chi) {
    for (std::size_t c = clo; c < chi; ++c) {
      std::size_t lo = c * kChunk, hi = lo;
      for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
        if (x_less(pts[i], pts[lo])) lo = i;
        if (x_less(pts[hi], pts[i])) hi = i;
      }
      ext[c] = {lo, hi};
    }
  });
  std::size_t il = ext[0].first, ir = ext[0].second;
  for (const auto& [lo, hi] : ext) {
    if (x_less(pts[lo], pts[il])) il = lo;
    if (x_less(pts[ir], pts[hi])) ir = hi;
  }
  const Pt2 vl = pts[il], vr = pts[ir];
  // lines 2-6: P = <v_r, v_l>; edge 0 = v_r -> v_l (points above), 1 = v_l -> v_r
  std::vector<Pt2> poly = {vr, vl};
  Segments S;
  {
    std::vector<std::uint8_t> above(n);
    par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) above[i] = orient(f, vr, vl, pts[i]) < 0;
    });
    const auto keep = [&](bool up) {
      return par_select(n, [&](Index i) { return i != il && i != ir && (above[i] != 0) == up; });
    };
    const std::vector<Index> a = keep(true), b = keep(false);
    S.pts.resize(a.size() + b.size());
    par_for(S.pts.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) S.pts[k] = pts[k < a.size() ? a[k] : b[k - a.size()]];
    });
    S.lo.push_back(0);
    if (!a.empty()) S.edge.push_back(0), S.lo.push_back(a.size());
    if (!b.empty()) S.edge.push_back(1), S.lo.push_back(a.size() + b.size());
  }
  std::vector<Pt2>().swap(pts);
  if (clock) clock->mark("extremes and split");

  Segments next;
  std::vector<std::uint8_t> code;
  while (S.count() > 0) {
    ++counts.rounds;
    const std::size_t K = S.count(), m = poly.size();
    const Units U = make_units(S.lo);
    const std::size_t nu = U.seg.size();
    // lines 8-9: the approximately furthest point of every segment
    std::vector<Best> part(nu);
    par_for(nu, 1, [&](std::size_t ulo, std::size_t uhi) {
      for (std::size_t u = ulo; u < uhi; ++u) {
        const std::uint32_t e = S.edge[U.seg[u]];
        const Pt2 &p = poly[e], &q = poly[(e + 1) % m];
        Best b;  // b.i: a position in S.pts (ties: the first, so the choice is the layout's, not the schedule's)
        for (std::size_t i = U.lo[u]; i < U.hi[u]; ++i) {
          const double key = beyond_key(p, q, S.pts[i]);
          if (better(key, static_cast<Index>(i), b)) b = {std::isnan(key) ? -HUGE_VAL : key, static_cast<Index>(i)};
        }
        part[u] = b;
      }
    });
    std::vector<Pt2> r(K);
    for (std::size_t k = 0; k < K; ++k) {
      Best b;
      for (std::size_t u = U.first[k]; u < U.first[k + 1]; ++u)
        if (part[u].i != kNone && better(part[u].key, part[u].i, b)) b = part[u];
      r[k] = S.pts[b.i];
    }
    // line 9: the new polygon; newpos[e]: where vertex e goes (its edge's
    // first half keeps that number, the second half is newpos[e] + 1)
    std::vector<std::size_t> newpos(m);
    std::vector<std::int64_t> seg_of(m, -1);
    for (std::size_t k = 0; k < K; ++k) seg_of[S.edge[k]] = static_cast<std::int64_t>(k);
    std::size_t pos = 0;
    for (std::size_t e = 0; e < m; ++e) newpos[e] = pos, pos += seg_of[e] >= 0 ? 2 : 1;
    std::vector<Pt2> grown(pos);
    for (std::size_t e = 0; e < m; ++e) {
      grown[newpos[e]] = poly[e];
      if (seg_of[e] >= 0) grown[newpos[e] + 1] = r[static_cast<std::size_t>(seg_of[e])];
    }
    counts.insertions += K;
    // lines 12-17: each point to p -> r (code 0) or r -> q (1), or dropped
    if (code.size() < S.pts.size()) code.resize(S.pts.size());
    std::vector<std::size_t> cnt(2 * nu, 0);
    constexpr std::uint8_t kDrop = 2;
    par_for(nu, 1, [&](std::size_t ulo, std::size_t uhi) {
      for (std::size_t u = ulo; u < uhi; ++u) {
        const std::size_t k = U.seg[u];
        const std::uint32_t e = S.edge[k];
        const Pt2 &p = poly[e], &q = poly[(e + 1) % m], &rk = r[k];
        for (std::size_t i = U.lo[u]; i < U.hi[u]; ++i) {
          const Pt2& x = S.pts[i];
          std::uint8_t c = kDrop;
          if (x.i != rk.i) {
            const bool first = x_less(p, x) != x_less(rk, x);  // x between p's and r's
            c = first ? (orient(f, p, rk, x) < 0 ? 0 : kDrop) : (orient(f, rk, q, x) < 0 ? 1 : kDrop);
          }
          code[i] = c;
          if (c != kDrop) ++cnt[2 * u + c];
        }
      }
    });
    // regroup, stable: offsets in (segment, child, unit) order, then scatter
    std::vector<std::size_t> off(2 * nu);
    next.lo.clear();
    next.edge.clear();
    std::size_t total = 0;
    for (std::size_t k = 0; k < K; ++k)
      for (std::size_t c = 0; c < 2; ++c) {
        const std::size_t start = total;
        for (std::size_t u = U.first[k]; u < U.first[k + 1]; ++u) off[2 * u + c] = total, total += cnt[2 * u + c];
        if (total > start) {
          next.lo.push_back(start);
          next.edge.push_back(static_cast<std::uint32_t>(newpos[S.edge[k]] + c));
        }
      }
    next.lo.push_back(total);
    next.pts.resize(total);
    par_for(nu, 1, [&](std::size_t ulo, std::size_t uhi) {
      for (std::size_t u = ulo; u < uhi; ++u) {
        std::size_t o[2] = {off[2 * u], off[2 * u + 1]};
        for (std::size_t i = U.lo[u]; i < U.hi[u]; ++i)
          if (code[i] != kDrop) next.pts[o[code[i]]++] = S.pts[i];
      }
    });
    counts.dropped += S.pts.size() - K - total;
    std::swap(S, next);
    poly.swap(grown);
  }
  if (clock) clock->mark("insertion rounds");

  // line 19: flip-pop on the two chains, v_r ... v_l and v_l ... v_r
  const auto at_vl = std::find_if(poly.begin(), poly.end(), [&](const Pt2& v) { return v.i == vl.i; });
  std::vector<Pt2> upper(poly.begin(), at_vl + 1), lower(at_vl, poly.end());
  lower.push_back(vr);
  upper = flip_pop_chain(std::move(upper), f, chunk, scan);
  lower = flip_pop_chain(std::move(lower), f, chunk, scan);
  std::vector<Index> cycle;
  cycle.reserve(upper.size() + lower.size() - 2);
  for (std::size_t k = 0; k + 1 < upper.size(); ++k) cycle.push_back(upper[k].i);
  for (std::size_t k = 0; k + 1 < lower.size(); ++k) cycle.push_back(lower[k].i);
  if (clock) clock->mark("flip-pop");
  return cycle;
}

}  // namespace flipflop::cpu::hull2

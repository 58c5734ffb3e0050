// certify_rt3.cpp — the witness-checked certifier of cpu::rt3's output. The
// conditions and why they suffice are in certify_rt3.hpp.
#include "kernels_cpu/rt3/certify_rt3.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <functional>
#include <string>

#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/witnessed_output.hpp"
#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/certify/certify_detail.hpp"
#include "reference/certify/certify_hull3_surface.hpp"
#include "reference/dimension.hpp"

namespace flipflop::cpu {

namespace {

using certify::Report;
using certify::detail::smallest_failing;
constexpr std::uint32_t kNo = Rt3Witness::kNoSlot;

std::string tet_str(const Tet& t) {
  return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + "," +
         std::to_string(t[3]) + ")";
}

// The facet opposite corner i of a tuple (c0, c1, c2, c3) as a triangle
// (x, y, z) with (x, y, z, c_i) an even permutation of the tuple: for a
// positive tuple (orient3d > 0), counter-clockwise seen from outside (c_i on
// its inner side, predicates.hpp). Moving c_i to the end is 3 - i adjacent
// transpositions; when odd, the first two of the others are swapped.
constexpr int kFacet[4][3] = {{2, 1, 3}, {0, 2, 3}, {1, 0, 3}, {0, 1, 2}};

// canonical_d.hpp's canonical_simplex for d = 3 on a fixed-size tuple: a
// positive tuple in the predicates' convention (orient_d) is first made
// volume-positive (the last two swapped), then sorted; when the sort is an
// odd permutation the last two are swapped back.
Tet canonical_tet(Tet t, bool from_orient_d) {
  if (from_orient_d) std::swap(t[2], t[3]);
  bool odd = false;
  for (int i = 1; i < 4; ++i)  // insertion sort, counting transpositions
    for (int j = i; j > 0 && t[j] < t[j - 1]; --j) {
      std::swap(t[j], t[j - 1]);
      odd = !odd;
    }
  if (odd) std::swap(t[2], t[3]);
  return t;
}

// canonical_d.hpp's is_canonical_shape for d = 3 (distinct entries)
bool canonical_shape(const Tet& t) {
  return t[0] < t[1] && t[1] < t[2] && t[1] < t[3] && t[2] != t[3];
}

struct Witnessed {
  const Rt3Witness& w;
  const pred::StaticFilter& f;  // over the input's coordinates and weights
  bool canonical;
  std::uint32_t n;  // the number of points, also the virtual vertex
  std::size_t slots;

  pred::Pt pt(std::uint32_t k) const { return {w.pts[k].id, w.pts[k].xyz}; }
  pred::WPt wpt(std::uint32_t k) const { return {w.pts[k].id, w.pts[k].xyz, w.pts[k].w}; }
  const std::uint32_t* corners(std::size_t t) const { return &w.tv[4 * t]; }
  // orient3d under SoS at both levels (predicates.hpp's convention)
  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
    return pred::fast::orient3d(f, pt(a), pt(b), pt(c), pt(d));
  }
  // > 0 when e's lifted point is strictly below the lifted hyperplane of the
  // positive (a, b, c, d); perturbed at the canonical level, exact at the
  // exact level
  int power(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint32_t e) const {
    if (canonical) return pred::fast::power3d(f, wpt(a), wpt(b), wpt(c), wpt(d), wpt(e));
    return pred::power3d_exact(wpt(a), wpt(b), wpt(c), wpt(d), wpt(e));
  }
  bool irregular(int s) const { return canonical ? s >= 0 : s > 0; }
  bool used(std::size_t t) const { return w.tv[4 * t] != kNo; }
  bool real(std::size_t t) const {
    const std::uint32_t* c = corners(t);
    return c[0] != kNo && c[0] != n && c[1] != n && c[2] != n && c[3] != n;
  }
  // position k is a vertex: its `at` is a real slot with k as a corner
  bool vertex(std::uint32_t k) const {
    const std::uint32_t t = w.at[k];
    if (t >= slots || !real(t)) return false;
    const std::uint32_t* c = corners(t);
    return c[0] == k || c[1] == k || c[2] == k || c[3] == k;
  }
  Tet ids(std::size_t t) const {
    const std::uint32_t* c = corners(t);
    return {w.pts[c[0]].id, w.pts[c[1]].id, w.pts[c[2]].id, w.pts[c[3]].id};
  }
  std::string name(std::uint32_t k) const { return k == n ? std::string("v") : std::to_string(w.pts[k].id); }
  // a slot in input indices, v for the virtual vertex
  std::string tet(std::size_t t) const {
    const std::uint32_t* c = corners(t);
    return "(" + name(c[0]) + "," + name(c[1]) + "," + name(c[2]) + "," + name(c[3]) + ")";
  }
  std::string facet(std::size_t t, int i) const {
    const std::uint32_t* c = corners(t);
    return "(" + name(c[kFacet[i][0]]) + "," + name(c[kFacet[i][1]]) + "," + name(c[kFacet[i][2]]) + ")";
  }
  std::string point(std::uint32_t k) const { return "point " + std::to_string(w.pts[k].id); }

  // facet-manifold at the facet of used slot t opposite corner i (header)
  bool bad_link(std::size_t t, int i) const {
    const std::uint32_t e = static_cast<std::uint32_t>(4 * t) + static_cast<std::uint32_t>(i), f = w.tn[e];
    if (f >= 4 * slots || !used(f / 4) || w.tn[f] != e) return true;
    const std::uint32_t j = f % 4;
    const std::uint32_t *c = corners(t), *d = corners(f / 4);
    // pos[k]: the corner of t at which u's corner k (its corner j replaced by
    // t's corner i) stands; a permutation of 0..3 when the facets agree
    int pos[4];
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t x = k == j ? c[i] : d[k];
      int p = 0;
      while (p < 4 && c[p] != x) ++p;
      if (p == 4 || (k != j && p == i)) return true;
      pos[k] = p;
    }
    int inversions = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) inversions += pos[a] > pos[b];
    return inversions % 2 == 0;  // same orientation induced on the facet
  }
  // locally-regular at the facet of real slot t opposite corner i, tested
  // from the smaller half-facet of an interior facet
  bool irregular_facet(std::size_t t, int i) const {
    const std::uint32_t e = static_cast<std::uint32_t>(4 * t) + static_cast<std::uint32_t>(i), f = w.tn[e];
    if (f < e || !real(f / 4)) return false;
    const std::uint32_t* c = corners(t);
    return irregular(power(c[0], c[1], c[2], c[3], w.tv[f]));
  }
  // missing-point-witness: k is not strictly inside a real slot w.at[k]
  bool outside_witness(std::uint32_t k) const {
    const std::uint32_t t = w.at[k];
    if (t >= slots || !real(t)) return true;
    const std::uint32_t* c = corners(t);
    return orient(k, c[1], c[2], c[3]) <= 0 || orient(c[0], k, c[2], c[3]) <= 0 || orient(c[0], c[1], k, c[3]) <= 0 ||
           orient(c[0], c[1], c[2], k) <= 0;
  }
  bool not_redundant(std::uint32_t k) const {
    const std::uint32_t* c = corners(w.at[k]);
    return irregular(power(c[0], c[1], c[2], c[3], k));
  }
};

constexpr std::size_t kAhead = 8;  // slots of look-ahead for the main pass's prefetches

void record_min(std::atomic<std::size_t>& first, std::size_t x) {
  std::size_t cur = first.load(std::memory_order_relaxed);
  while (x < cur && !first.compare_exchange_weak(cur, x)) {
  }
}

Report certify_witnessed(const PointSet& ps, const Rt3Witness& w, const std::vector<Tet>& tets,
                         certify::Level level) {
  if (ps.dim != 3) return Report::fail("input-dimension", "rt3 needs 3D points");
  if (std::string why = dimension_problem(ps); !why.empty()) return Report::fail("input-dimension", why);
  const std::size_t n = ps.size();
  const auto for_range = par_for_range();
  const pred::StaticFilter filter = parallel_static_filter(ps, {});
  const bool canonical = level == certify::Level::canonical;
  const Witnessed W{w, filter, canonical, static_cast<std::uint32_t>(n), w.tv.size() / 4};
  const std::size_t slots = W.slots;

  // witness-size, witness-points, simplex-indices (witnessed_output.hpp)
  if (auto bad = witness_problem<4>(ps, w.pts, w.at, w.tv, w.tn, kNo, "tetrahedra", "simplex-indices",
                                     [](const Rt3Point& q) { return q.xyz; }, for_range))
    return *bad;

  // The per-slot conditions in one pass over fixed chunks of slots, each
  // recording its smallest failing slot; a slot failing one condition is not
  // tested for the later ones, so the first condition reported and its slot
  // are the sequential scan's whatever the thread count (as certify_rt2.cpp).
  // The same pass counts the real slots, collects the boundary triangles and
  // gathers the real slots' canonical tuples, bucketed by smallest index for
  // the output check.
  enum { kOrient, kLinks, kCorners, kRegular, kSlotConditions };
  std::atomic<std::size_t> first_bad[kSlotConditions];
  for (auto& x : first_bad) x.store(slots);
  int shift = 0;  // buckets of the output check: at most 4097 ranges of 2^shift indices
  while ((n >> shift) > 4096) ++shift;
  const std::size_t B = (n >> shift) + 1;
  auto bucket = [&](Index m) { return static_cast<std::size_t>(m >> shift); };
  const std::size_t per = std::max<std::size_t>(kChunk, (slots + 63) / 64), chunks = (slots + per - 1) / per;
  std::vector<std::size_t> pos(chunks * B, 0);  // pos[c * B + b]: counts, then write positions
  std::vector<std::vector<Tet>> part(chunks);
  std::vector<std::vector<Triangle>> hull_part(chunks);
  std::vector<std::size_t> real_in(chunks, 0);
  // Which positions are vertices (W.vertex), once per point: the main pass
  // asks it of every corner of every real slot (about 27 times per point at
  // 10^6 uniform points), and each answer is two dependent scattered loads
  // (the point's witness slot, then that slot's corners) — perf: the loads'
  // waits were a sixth of the pass's samples. One byte per point here, read
  // in the pass as one load from an array of n bytes; the same answers.
  std::vector<std::uint8_t> is_vertex(n);
  par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) is_vertex[k] = W.vertex(static_cast<std::uint32_t>(k));
  });
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t ch = lo; ch < hi; ++ch)
      for (std::size_t t = ch * per; t < std::min(slots, (ch + 1) * per); ++t) {
        // the slot kAhead further on: its neighbours' corners and links and
        // its corners' points and witness slots, requested now (each a
        // scattered load that the tests below wait for)
        if (t + kAhead < slots) {
          const std::size_t u = t + kAhead;
          for (int i = 0; i < 4; ++i) {
            const std::uint32_t f = w.tn[4 * u + static_cast<std::size_t>(i)];
            if (f < 4 * slots) __builtin_prefetch(&w.tv[f & ~3u]), __builtin_prefetch(&w.tn[f & ~3u]);
            const std::uint32_t k = w.tv[4 * u + static_cast<std::size_t>(i)];
            if (k < n) __builtin_prefetch(&w.pts[k]), __builtin_prefetch(&is_vertex[k]);
          }
        }
        if (!W.used(t)) continue;
        const bool real = W.real(t);
        const std::uint32_t* c = W.corners(t);
        if (real) {
          ++real_in[ch];
          if (W.orient(c[0], c[1], c[2], c[3]) <= 0) {
            record_min(first_bad[kOrient], t);
            continue;
          }
        }
        if (W.bad_link(t, 0) || W.bad_link(t, 1) || W.bad_link(t, 2) || W.bad_link(t, 3)) {
          record_min(first_bad[kLinks], t);
          continue;
        }
        if (!real) continue;
        if (!(is_vertex[c[0]] & is_vertex[c[1]] & is_vertex[c[2]] & is_vertex[c[3]])) {
          record_min(first_bad[kCorners], t);
          continue;
        }
        if (W.irregular_facet(t, 0) || W.irregular_facet(t, 1) || W.irregular_facet(t, 2) ||
            W.irregular_facet(t, 3))
          record_min(first_bad[kRegular], t);
        for (int i = 0; i < 4; ++i)
          if (!W.real(w.tn[4 * t + static_cast<std::size_t>(i)] / 4)) {
            Triangle x = {w.pts[c[kFacet[i][0]]].id, w.pts[c[kFacet[i][1]]].id, w.pts[c[kFacet[i][2]]].id};
            std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
            hull_part[ch].push_back(x);
          }
        const Tet x = canonical_tet(W.ids(t), true);
        part[ch].push_back(x);
        ++pos[ch * B + bucket(x[0])];
      }
  });
  std::size_t real_slots = 0;
  for (std::size_t r : real_in) real_slots += r;
  if (real_slots == 0) return Report::fail("simplex-indices", "the witness has no real tetrahedron");
  if (const std::size_t t = first_bad[kOrient].load(); t < slots)
    return Report::fail("simplex-orientation",
                        "tetrahedron " + W.tet(t) + " is not positively oriented (orient3d <= 0 under SoS)");
  if (const std::size_t t = first_bad[kLinks].load(); t < slots) {
    int i = 0;
    while (!W.bad_link(t, i)) ++i;
    return Report::fail("facet-manifold", "facet " + W.facet(t, i) + " of tetrahedron " + W.tet(t) +
                                              " is not linked to the same facet, oppositely oriented, of a "
                                              "tetrahedron linked back");
  }
  if (const std::size_t t = first_bad[kCorners].load(); t < slots) {
    const std::uint32_t* c = W.corners(t);
    int i = 0;
    while (W.vertex(c[i])) ++i;
    return Report::fail("witness-vertex", W.point(c[i]) + " is a corner of tetrahedron " + W.tet(t) +
                                              " but its witness tetrahedron does not have it as a corner");
  }

  // The per-point conditions: every position that is not a vertex lies in its
  // witness tetrahedron and is redundant there (reported after the hull and
  // local regularity).
  const std::size_t first_missing = smallest_failing(n, for_range, [&](std::size_t k) {
    const std::uint32_t v = static_cast<std::uint32_t>(k);
    return !is_vertex[v] && (W.outside_witness(v) || W.not_redundant(v));
  });

  // boundary-is-hull: the boundary triangles, canonical (rotated, sorted),
  // are the hull by certify::hull3's surface conditions
  {
    std::vector<Triangle> hull;
    for (auto& h : hull_part) {
      hull.insert(hull.end(), h.begin(), h.end());
      std::vector<Triangle>().swap(h);
    }
    par_sort(hull, [](const Triangle& a, const Triangle& b) { return a < b; });
    certify::Speedups s;
    s.filter = &filter;
    s.for_range = for_range;
    s.make_filter = [&](const std::vector<double>& extra) { return parallel_static_filter(ps, extra); };
    certify::detail::Hull3Surface ck;
    if (Report r = certify::detail::hull3_surface(ps, hull, level, s, nullptr, ck); !r.ok)
      return Report::fail("boundary-is-hull", "the boundary of the tetrahedra is not the convex hull: " + r.message());
  }

  if (const std::size_t t = first_bad[kRegular].load(); t < slots) {
    int i = 0;
    while (!W.irregular_facet(t, i)) ++i;
    return Report::fail("locally-regular",
                        "facet " + W.facet(t, i) + " is not locally regular: the lifted point of " +
                            W.point(w.tv[w.tn[4 * t + static_cast<std::size_t>(i)]]) + " is " +
                            (canonical ? "not strictly above" : "strictly below") + " the lifted tetrahedron " +
                            W.tet(t));
  }

  if (first_missing < n) {
    const std::uint32_t v = static_cast<std::uint32_t>(first_missing);
    if (W.outside_witness(v))
      return Report::fail("missing-point-witness",
                          W.point(v) + " is not a vertex and " +
                              (w.at[v] < slots && W.real(w.at[v])
                                   ? "does not lie strictly inside its witness tetrahedron " + W.tet(w.at[v]) +
                                         " (SoS)"
                                   : std::string("has no real witness tetrahedron")));
    return Report::fail("missing-point-redundant",
                        W.point(v) + " is not a vertex but is not redundant: its lifted point is " +
                            (canonical ? "not strictly above" : "strictly below") + " the lifted tetrahedron " +
                            W.tet(w.at[v]));
  }

  // canonical-form, canonical-output: tets is the set of the witnessed
  // tetrahedra (volume-positive tuples of input indices)
  if (const std::size_t i = smallest_failing(tets.size(), for_range,
                                             [&](std::size_t i) {
                                               const Tet& x = tets[i];
                                               return x[0] >= n || x[1] >= n || x[2] >= n || x[3] >= n ||
                                                      x[0] == x[1] || x[0] == x[2] || x[0] == x[3] ||
                                                      x[1] == x[2] || x[1] == x[3] || x[2] == x[3];
                                             });
      i < tets.size())
    return Report::fail("canonical-output", "tetrahedron " + std::to_string(i) + " " + tet_str(tets[i]) +
                                                " of the output names a point twice or one of at least " +
                                                std::to_string(n));
  std::vector<Tet> sorted;
  const std::vector<Tet>* out_tets = &tets;
  if (canonical) {
    if (const std::size_t i = smallest_failing(
            tets.size(), for_range,
            [&](std::size_t i) { return !canonical_shape(tets[i]) || (i > 0 && !(tets[i - 1] < tets[i])); });
        i < tets.size()) {
      if (!canonical_shape(tets[i]))
        return Report::fail("canonical-form", "tetrahedron " + std::to_string(i) + " " + tet_str(tets[i]) +
                                                  " is not in canonical order");
      return Report::fail("canonical-form", "tetrahedra " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                                " are not in strictly increasing order");
    }
  } else {
    // any order, any even permutation of a volume-positive tuple: compared
    // in canonical form (an odd permutation's canonical tuple is the other
    // one of its set, which the witness does not hold)
    sorted = tets;
    par_for(sorted.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) sorted[i] = canonical_tet(sorted[i], false);
    });
    par_sort(sorted, [](const Tet& a, const Tet& b) { return a < b; });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i] == sorted[i - 1])
        return Report::fail("canonical-output", "tetrahedron " + tet_str(sorted[i]) + " is repeated");
    out_tets = &sorted;
  }
  const std::vector<Tet>& T = *out_tets;
  if (T.size() != real_slots)
    return Report::fail("canonical-output", "the output has " + std::to_string(T.size()) +
                                                " tetrahedra, the witness " + std::to_string(real_slots));
  // every witnessed tetrahedron is in the output, bucketed by smallest index
  // (witnessed_output.hpp)
  if (const std::size_t t = first_unwitnessed_slot(
          n, T, part, pos, B, bucket, slots, for_range, [&](std::size_t t) { return W.real(t); },
          [&](std::size_t t) { return canonical_tet(W.ids(t), true); });
      t < slots)
    return Report::fail("canonical-output", "tetrahedron " + tet_str(canonical_tet(W.ids(t), true)) +
                                                " of the witness is not in the output");
  return Report::pass();
}

}  // namespace

certify::Report certify_rt3(const PointSet& ps, const Rt3Witness& w, const std::vector<Tet>& tets,
                            certify::Level level, int threads) {
  certify::Report r;
  with_threads(threads, [&] { r = certify_witnessed(ps, w, tets, level); });
  return r;
}

}  // namespace flipflop::cpu

// rt_incremental.cpp — RT+1: incremental insertion and monotonic flips
// (Edelsbrunner–Shah [ES92]; thesis §3.1 Table 3.1 "Edelsbrunner-Shah's
// flip: any dimension, 'RT+1' triangulation, flip, free execution order";
// §9.1 "Arbitrarily Monotonic Flip Algorithm Works for 'RT+1'
// Triangulation").
//
// For each point p (spatially coherent order):
//   1. locate p (visibility walk, exact orient_d under SoS);
//   2a. p inside the hull, in simplex C: if p's lifted point lies strictly
//       above the lifted C (power_d(C, p) < 0) p is redundant — for good: the
//       lower hull only descends as points are added — and is not inserted;
//       otherwise the 1-(d+1) flip inserts it ("RT+1", §9.1);
//   2b. p outside: placing — the cone from p over the hull facets p sees
//       (beneath-beyond). This is the regular triangulation with p's height
//       raised until p's lifted point sees exactly those facets from above:
//       again "RT+1" (§9.1: "the arbitrarily monotonic flip algorithm also
//       works for a 'RT+1' extended triangulation"); the hull-convexity flips
//       of the virtual ridges (§2.2) are all done at once;
//   3. monotonic flips [ES92]: the link ridges of p (the facets opposite p of
//       its star) enter a queue; a popped ridge still in T with the same
//       link, locally non-regular (power_d > 0: the link vertex b below the
//       lifted simplex of p) and flippable (bistellar_flip.hpp) is flipped,
//       and the new link ridges of p are pushed. Every flip replaces upper
//       by lower facets of the lifted S_F, so the lifted surface descends
//       (monotonic) and terminates; a (d+1)-1 flip removes a vertex whose
//       lifted point ends above the surface: redundant. ES92 prove that
//       while some ridge is locally non-regular one of the link ridges of p
//       is locally non-regular and flippable (the facet of star(p) whose
//       hyperplane meets the vertical line through p highest). When the
//       queue is empty the star of p is re-examined (a "sweep"); a
//       non-regular link ridge found there is queued again. A sweep that
//       finds non-regular ridges but no flippable one would contradict ES92
//       and throws std::logic_error.
// Finally every ridge is checked locally regular (Thm 2.2; §2.2 for the
// virtual ones) — the result is never returned unverified.
#include "reference/rtd/rt_incremental.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "predicates/predicates.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/bistellar_flip.hpp"

namespace flipflop::ref {

// ---- input validation -----------------------------------------------------------

void validate_rtd_input(const PointSet& ps) {
  if (ps.dim < 2 || ps.dim > rtd::kMaxDim)
    throw std::invalid_argument("rtd needs points of dimension 2.." + std::to_string(rtd::kMaxDim) + ", got " +
                                std::to_string(ps.dim));
  if (ps.weighted && ps.weights.size() != ps.size())
    throw std::invalid_argument("rtd: " + std::to_string(ps.weights.size()) + " weights for " +
                                std::to_string(ps.size()) + " points");
  for (double c : ps.coords)
    if (!std::isfinite(c)) throw std::invalid_argument("rtd: a coordinate is not finite");
  for (double w : ps.weights)
    if (!std::isfinite(w)) throw std::invalid_argument("rtd: a weight is not finite");
  if (ps.size() > 0xfffffff0u) throw std::invalid_argument("rtd: too many points");
  if (std::string why = dimension_problem(ps); !why.empty()) throw std::invalid_argument(why);
}

namespace {
using namespace rtd;

// ---- insertion order ----------------------------------------------------------------
// Morton (Z-order) of the points in their bounding box: spatial coherence for
// the walk only; the result does not depend on the order (it is unique).
std::vector<Index> insertion_order(const PointSet& ps) {
  const int d = ps.dim;
  const std::size_t n = ps.size();
  std::vector<double> lo(static_cast<std::size_t>(d)), hi(static_cast<std::size_t>(d));
  for (int j = 0; j < d; ++j) lo[static_cast<std::size_t>(j)] = hi[static_cast<std::size_t>(j)] = ps.point(0)[j];
  for (std::size_t p = 0; p < n; ++p)
    for (int j = 0; j < d; ++j) {
      lo[static_cast<std::size_t>(j)] = std::min(lo[static_cast<std::size_t>(j)], ps.point(p)[j]);
      hi[static_cast<std::size_t>(j)] = std::max(hi[static_cast<std::size_t>(j)], ps.point(p)[j]);
    }
  const int bits = 60 / d;
  std::vector<std::pair<std::uint64_t, Index>> keyed(n);
  for (std::size_t p = 0; p < n; ++p) {
    std::uint32_t cell[kMaxDim] = {};
    for (int j = 0; j < d; ++j) {
      const double span = hi[static_cast<std::size_t>(j)] - lo[static_cast<std::size_t>(j)];
      double t = (std::isfinite(span) && span > 0) ? (ps.point(p)[j] - lo[static_cast<std::size_t>(j)]) / span : 0.0;
      if (!(t >= 0)) t = 0;
      cell[j] = static_cast<std::uint32_t>(std::min(t, 1.0) * static_cast<double>((1u << bits) - 1));
    }
    std::uint64_t k = 0;
    for (int b = bits - 1; b >= 0; --b)
      for (int j = 0; j < d; ++j) k = (k << 1) | ((cell[j] >> b) & 1u);
    keyed[p] = {k, static_cast<Index>(p)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

// ---- placing a point outside the hull (step 2b) ------------------------------------
// vs: a virtual simplex whose facet p sees. The visible virtual simplices
// (v, f) — p strictly beyond f: orient(tuple with v := p) > 0 — form a
// connected set (the facets of a convex polytope visible from a point); each
// becomes the real simplex (p, f) in place (v replaced by p: positive). Each
// horizon ridge g (between a visible f and an invisible f') gets the new
// virtual simplex (v, p, g). Returns the new real simplices.
std::vector<std::int32_t> place(TriangulationD& T, std::int32_t vs, Index p) {
  const int d = T.d;
  const Index v = T.n;
  auto sees = [&](std::int32_t s) {
    Index t[kMaxDim + 1];
    for (int j = 0; j <= d; ++j) t[j] = T.vertex(s, j) == v ? p : T.vertex(s, j);
    return orient(T, t) > 0;
  };
  std::vector<std::int32_t> vis{vs};
  std::unordered_set<std::int32_t> in_vis{vs}, rejected;
  for (std::size_t q = 0; q < vis.size(); ++q) {
    const std::int32_t s = vis[q];
    for (int i = 0; i <= d; ++i) {
      const std::int32_t t = T.neighbor(s, i);
      if (T.vertex(s, i) == v) continue;  // across f: the real simplex
      if (in_vis.count(t) || rejected.count(t)) continue;
      if (sees(t)) {
        in_vis.insert(t);
        vis.push_back(t);
      } else {
        rejected.insert(t);
      }
    }
  }
  // horizon: (visible slot, position) whose neighbour is an invisible virtual simplex
  struct Horizon {
    std::int32_t s;
    int i;
    std::int32_t out;
    int back;
  };
  std::vector<Horizon> hz;
  for (std::int32_t s : vis)
    for (int i = 0; i <= d; ++i) {
      if (T.vertex(s, i) == v) continue;
      const std::int32_t t = T.neighbor(s, i);
      if (!in_vis.count(t)) hz.push_back({s, i, t, mirror_index(T, s, i)});
    }
  for (std::int32_t s : vis) set_vertex(T, s, index_of(T, s, v), p);
  std::vector<std::int32_t> created;
  std::map<std::vector<Index>, std::pair<std::int32_t, int>> open;
  for (const Horizon& h : hz) {
    // tuple: the real (p, f) with the vertex opposite the horizon facet
    // replaced by v, two other entries swapped (virtual orientation rule)
    Index u[kMaxDim + 1];
    for (int j = 0; j <= d; ++j) u[j] = T.vertex(h.s, j);
    u[h.i] = v;
    const int j1 = h.i == 0 ? 1 : 0, j2 = (h.i == 0 || h.i == 1) ? 2 : 1;
    std::swap(u[j1], u[j2]);
    const std::int32_t n = new_slot(T);
    for (int j = 0; j <= d; ++j) set_vertex(T, n, j, u[j]);
    created.push_back(n);
    const int pv = index_of(T, n, v), pp = index_of(T, n, p);
    set_neighbor(T, n, pv, h.s);
    set_neighbor(T, h.s, h.i, n);
    set_neighbor(T, n, pp, h.out);
    set_neighbor(T, h.out, h.back, n);
    // the remaining facets (v, p, g \ y) pair up among the new virtual simplices
    for (int j = 0; j <= d; ++j) {
      if (j == pv || j == pp) continue;
      std::vector<Index> key;
      for (int q = 0; q <= d; ++q)
        if (q != j && q != pv && q != pp) key.push_back(u[q]);
      std::sort(key.begin(), key.end());
      auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(std::move(key), std::make_pair(n, j));
      } else {
        set_neighbor(T, n, j, it->second.first);
        set_neighbor(T, it->second.first, it->second.second, n);
        open.erase(it);
      }
    }
  }
  if (!open.empty()) throw std::logic_error("rtd placing: the horizon is not a closed ridge cycle");
  for (std::int32_t s : vis)
    for (int j = 0; j <= d; ++j) T.vsimplex[T.vertex(s, j)] = s;
  for (std::int32_t s : created) T.vsimplex[v] = s;
  return vis;
}

// ---- step 3: monotonic flips -------------------------------------------------------
struct Inserter {
  TriangulationD& T;
  RtdStats& st;
  std::vector<Index>& redundant;
  std::deque<RidgeRef> queue;

  void push_link(std::int32_t s, Index p) {
    const int i = index_of(T, s, p);
    if (i < 0) return;
    queue.push_back(remember(T, {s, i}));
    ++st.queue_pushes;
  }

  // Returns true when at least one flip was done.
  bool drain(Index p) {
    bool flipped = false;
    while (!queue.empty()) {
      const RidgeRef ref = queue.front();
      queue.pop_front();
      ++st.queue_pops;
      const RidgeD r = recall(T, ref);
      if (!r.valid()) continue;                    // no longer in T with the same link
      if (T.is_virtual(link_b(T, r))) continue;     // a hull facet: locally regular (§2.2)
      if (locally_regular(T, r)) continue;
      const FlipShape sh = flip_shape(T, r);
      if (!sh.flippable) {
        ++st.unflippable;
        continue;
      }
      const FlipResult res = flip(T, sh);
      ++st.flips[res.k];
      flipped = true;
      if (res.removed != kNoVertex) {
        redundant.push_back(res.removed);
        ++st.removed;
      }
      for (std::int32_t c : res.created) push_link(c, p);
    }
    return flipped;
  }

  void flip_link(Index p) {
    for (;;) {
      const bool flipped = drain(p);
      // sweep: re-examine every link ridge of p
      ++st.sweeps;
      std::size_t bad = 0;
      for (std::int32_t s : star(T, p)) {
        if (is_virtual_simplex(T, s)) continue;
        const RidgeD r{s, index_of(T, s, p)};
        if (!T.is_virtual(link_b(T, r)) && !locally_regular(T, r)) {
          ++bad;
          push_link(s, p);
        }
      }
      if (bad == 0) return;
      if (!flipped && !drain(p))
        throw std::logic_error("RT+1 is stuck: " + std::to_string(bad) + " locally non-regular link ridges of point " +
                               std::to_string(p) + " and none flippable (contradicts [ES92])");
    }
  }
};

}  // namespace

rtd::TriangulationD build_rtd(const PointSet& ps, RtdStats* stats, bool pulled, bool furthest) {
  validate_rtd_input(ps);
  RtdStats local;
  RtdStats& st = stats ? *stats : local;
  st = RtdStats{};
  const int d = ps.dim;
  const std::vector<Index> order = insertion_order(ps);
  TriangulationD T = make_simplex(ps, order.data());
  T.pulled = pulled;  // make_simplex decides orientations only (orient_d: no height)
  T.furthest = furthest;
  st.insertions = static_cast<std::uint64_t>(d + 1);
  std::vector<Index> redundant;
  Inserter ins{T, st, redundant, {}};
  std::int32_t last = 0;
  for (std::size_t k = static_cast<std::size_t>(d + 1); k < order.size(); ++k) {
    const Index p = order[k];
    std::size_t steps = 0;
    const std::int32_t s = locate(T, p, last, &steps);
    st.walk_steps += steps;
    std::vector<std::int32_t> created;
    if (is_virtual_simplex(T, s)) {
      created = place(T, s, p);
      ++st.placed;
    } else {
      Index t[kMaxDim + 2];
      for (int j = 0; j <= d; ++j) t[j] = T.vertex(s, j);
      t[d + 1] = p;
      if (power(T, t) < 0) {  // p's lifted point strictly above the lifted simplex
        redundant.push_back(p);
        last = s;
        continue;
      }
      created = insert_in_simplex(T, s, p).created;
      ++st.flips[1];
    }
    ++st.insertions;
    for (std::int32_t c : created) ins.push_link(c, p);
    ins.flip_link(p);
    last = T.vsimplex[p];
    FF_CHECK(validity_problem(T).empty(), "RT+1 after inserting " + std::to_string(p) + ": " + validity_problem(T));
  }
  // Theorem 2.2: every ridge locally regular (real: power_d; virtual: §2.2)
  for (const RidgeD& r : ridges(T))
    if (!locally_regular(T, r))
      throw std::logic_error("RT+1 ended with a locally non-regular ridge (opposite " +
                             std::to_string(link_a(T, r)) + " in a simplex of " + std::to_string(link_b(T, r)) + ")");
  st.redundant = ps.size() - vertices(T).size();
  if (st.redundant != redundant.size()) throw std::logic_error("RT+1: redundant-point bookkeeping is inconsistent");
  return T;
}

Rtd rtd_incremental(const PointSet& ps, RtdStats* stats, bool furthest) {
  const TriangulationD T = build_rtd(ps, stats, false, furthest);
  Rtd out;
  out.simplices = real_simplices(T);
  for (Index x = 0; x < T.n; ++x)
    if (!T.is_vertex(x)) out.redundant.push_back(x);
  return out;
}

}  // namespace flipflop::ref

// rtd_cavity.cpp — the d-dimensional regular triangulation by cavity
// insertion (rtd_cavity.hpp: stages, and why the answer is the reference's).
//
// ============================================================================
// Insertion: the cavity step is Edelsbrunner–Shah's flips, composed
// ============================================================================
// The argument of kernels_cpu/rt3/rt3.cpp, in R^d. Lift every point x to
// x̂ = (x, |x|² - w) in R^(d+1) (thesis §2.1, §9.2.2; the height perturbed as
// an independent coordinate under SoS). With the virtual vertex v read as the
// point at infinity straight up, the extended triangulation is the boundary
// complex of Q = conv(lifted points) + upward ray: a real simplex is a lower
// facet of Q, a virtual simplex (v, f) the vertical facet over the hull facet
// f. Inserting p adds p̂ to Q (beneath–beyond). A facet is VISIBLE from p̂
// when p̂ lies strictly on its outer side:
//   * a real simplex (positive under orient_d): p̂ strictly below its lifted
//     hyperplane — power_d(simplex, p) > 0 (predicates.hpp);
//   * a virtual simplex (v, f): p strictly beyond the hull facet f — orient_d
//     of its tuple with v replaced by p > 0 (the orientation rule of
//     reference/rtd/triangulation_d.hpp, make_simplex).
// Under SoS no facet is flat to p̂. The visible facets of a convex polytope
// form a non-empty connected set whose boundary (the horizon) is a closed
// (d-1)-manifold of ridges; conv(Q ∪ p̂) keeps the invisible facets and adds
// the cone from p̂ over the horizon. No visible facet (the real simplex
// containing p passes below p̂): p is redundant, for good (Q only grows).
// Edelsbrunner–Shah's RT+1 ([ES92]; thesis §3.1 Table 3.1, §9.1;
// reference/rtd/rt_incremental.cpp) — the 1-(d+1) flip into the simplex
// containing p (or, outside the hull, the placing step), then monotonic flips
// of p's non-regular link ridges — ends in the regular triangulation of the
// points so far, unique under SoS; each of its flips replaces facets visible
// from p̂ by facets through p̂ (the lifted surface only descends), and the
// cavity step performs the whole sequence at once: it removes every visible
// facet (a vertex all of whose simplices are visible is the (d+1)-1 flip's
// removed vertex, redundant from then on) and creates the cone.
//
// The visible set is found by a breadth-first search from the simplex the
// walk ends in (every visible facet is reached through visible facets), so
// only the visible simplices and their neighbours are tested. The new simplex
// over a horizon ridge is the visible simplex with its corner opposite that
// ridge replaced by p (same position): p lies on that corner's side of the
// ridge, so a real new simplex stays positive and a virtual one keeps the
// orientation rule; across every facet the two tuples still induce opposite
// orientations.
//
// With more than one thread the search runs a wave at a time
// (visible_region_waves): the cells a wave names are tested by the filters
// first, and those the filters leave go through the exact stages together,
// in parallel where their measured cost pays for it (visible_all) — the
// two passes of thesis §6.4.2 that the GPU hull runs. On exactly degenerate
// input (decimal and moved lattices) nearly every test is left to the exact
// stages and those are most of the run; the insertions themselves stay in
// order. The search visits the same cells in the same order and makes the
// same horizon calls as the one-by-one search (rtd_cavity_test, "the
// two-pass search by waves"), so the triangulation, its slots and the
// counters are those of one thread.

#include "kernels_cpu/rtd/rtd_cavity.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cpu/brio.hpp"
#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/rtd/ridge_table.hpp"
#include "kernels_cpu/rtd/visible_region.hpp"
#include "predicates/staged.hpp"
#include "reference/rtd/canonical_d.hpp"

namespace flipflop::cpu {

namespace {

constexpr std::uint32_t kDead = 0xffffffffu;

template <int D>
class Builder {
  static constexpr int W = D + 1;  // corners per simplex
  static constexpr int kKey = D - 1;  // vertices of a cone facet's key (its ridge minus one corner)

 public:
  Builder(const PointSet& ps, const std::vector<Index>& order, bool furthest, int threads, double parallel_min_ns)
      : furthest_(furthest), threads_(threads), parallel_min_ns_(parallel_min_ns) {
    // Room for the slots the run will use, so that the arrays do not move:
    // each move copies them into fresh pages, and a fresh page costs about
    // 2.4 us on the 2-core VM (a page fault; 3^5 grid: 24,000 slots at the
    // end against 9,800 reserved before, two moves, 27 % of the run's
    // faults). Reserved memory is not touched until used, so the guess may
    // be high: about twice the slots at the end on random points (random
    // 4D: 30 a point, 5D: 151) and on grids (3^5: 97), capped at 2^22.
    constexpr std::size_t kPerPoint = D <= 2 ? 6 : D == 3 ? 16 : D == 4 ? 64 : 256;
    const std::size_t guess = std::min<std::size_t>(kPerPoint * order.size(), std::size_t{1} << 22) + 64;
    tv_.reserve(guess * W);
    tn_.reserve(guess * W);
    mark_.reserve(guess);
    take(ps, order);
  }

  void run(RtdCavityStats& st) {
    start(st);
    insert_range(W, st);
  }

  // Seeded (RtdCavityIncremental's second constructor) instead of run():
  // the positions are the input indices (the Builder was made with the
  // identity order), `simplices` the caller's real simplices, positively
  // oriented in the output's convention (canonical_d.hpp: volume), slot k
  // for simplex k, and nb[k][j] the simplex across the
  // facet opposite corner j (-1: a hull facet), checked to glue the
  // simplices along their facets (false where they do not). Each hull
  // facet, opposite corner i of simplex t, gets the virtual simplex of
  // start()'s rule (t's tuple with corner i := v and two other corners
  // swapped), linked to t across it and to the other virtual simplices
  // across its other facets by link_cone, as an insertion's cone.
  bool seed(const Index* simplices, const std::int64_t* nb, std::size_t m, RtdCavityStats& st) {
    if ((m + 1) * W >= kDead) throw std::length_error("rtd (cpu): more simplices than 32-bit neighbour links hold");
    tv_.resize(m * W);
    tn_.assign(m * W, kDead);
    mark_.assign(m, 0);
    for (std::size_t k = 0; k < m; ++k) {
      for (int j = 0; j < W; ++j) tv_[k * W + static_cast<std::size_t>(j)] = simplices[k * W + static_cast<std::size_t>(j)];
      // the output's (volume) convention to the predicates' (orient_d):
      // the last two swapped in odd d (canonical_d.hpp), nb's columns alike
      if (D % 2 == 1) std::swap(tv_[k * W + D - 1], tv_[k * W + D]);
    }
    auto neighbour = [&](std::size_t t, int j) {
      return nb[t * W + static_cast<std::size_t>(D % 2 == 1 && j >= D - 1 ? 2 * D - 1 - j : j)];
    };
    cavity_.clear();
    horizon_.clear();
    for (std::uint32_t t = 0; t < m; ++t)
      for (int j = 0; j < W; ++j) {
        const std::int64_t u = neighbour(t, j);
        if (u < 0) {  // a hull facet: its virtual simplex
          horizon_.push_back(virtual_over(simplex(t), j, t));
          continue;
        }
        if (static_cast<std::uint64_t>(u) >= m || static_cast<std::uint32_t>(u) == t) return false;
        // u holds every corner of t but the j-th, and one more at corner i,
        // across which it names t back
        const int i = across(simplex(t), simplex(static_cast<std::uint32_t>(u)), W, j);
        if (i < 0 || neighbour(static_cast<std::size_t>(u), i) != t) return false;
        tn_[static_cast<std::size_t>(t) * W + static_cast<std::size_t>(j)] = static_cast<std::uint32_t>(u) * W + static_cast<std::uint32_t>(i);
      }
    if (horizon_.size() < static_cast<std::size_t>(W)) return false;  // a closed hull has at least D+1 facets
    try {
      link_cone(st);
    } catch (const std::logic_error&) {  // a hull ridge not in exactly two hull facets
      return false;
    }
    last_ = 0;
    return true;
  }

  // In-place insertion of more points (RtdCavityIncremental::add): ps holds
  // the points given so far followed by the new ones, `order` the new ones'
  // input indices in insertion order. The static filter is recomputed over
  // all points (its bound may grow); the simplices, links and redundant
  // points stay (a redundant point stays redundant: Q only grows).
  void append(const PointSet& ps, const std::vector<Index>& order, RtdCavityStats& st) {
    const std::size_t first = n_;
    take(ps, order);
    insert_range(first, st);
  }

  // Positions first.. in order, except that exact copies wait for the copy
  // of larger index that follows them (brio.hpp, waits_for_next) until the
  // rest are in. The answer does not depend on the order.
  void insert_range(std::size_t first, RtdCavityStats& st) {
    std::vector<std::uint32_t> waited;
    for (std::size_t k = first; k < n_; ++k) {
      if (k + 1 < n_ && brio::waits_for_next(&xs_[k * D], ws_[k], static_cast<Index>(ids_[k]), &xs_[(k + 1) * D],
                                             ws_[k + 1], static_cast<Index>(ids_[k + 1]), D)) {
        waited.push_back(static_cast<std::uint32_t>(k));
        continue;
      }
      insert(static_cast<std::uint32_t>(k), st);
    }
    for (std::uint32_t k : waited) insert(k, st);
  }

  // The real simplices in canonical form (canonical_d.hpp), sorted; the
  // redundant points.
  ref::Rtd output() const {
    ref::Rtd r;
    std::vector<char> vertex(n_, 0);
    std::vector<Index> flat;
    const std::size_t slots = mark_.size();
    flat.reserve(slots * W);
    for (std::size_t s = 0; s < slots; ++s) {
      const std::uint32_t* v = tv_.data() + s * W;
      if (v[0] == kDead || is_virtual(static_cast<std::uint32_t>(s))) continue;
      Index t[W];
      for (int j = 0; j < W; ++j) {
        t[j] = static_cast<Index>(ids_[v[j]]);
        vertex[v[j]] = 1;
      }
      canonicalize(t, W, Orientation::orient_d);
      flat.insert(flat.end(), t, t + W);
    }
    const std::size_t m = flat.size() / W;
    std::vector<std::uint32_t> order(m);
    for (std::size_t k = 0; k < m; ++k) order[k] = static_cast<std::uint32_t>(k);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Index* x = flat.data() + static_cast<std::size_t>(a) * W;
      const Index* y = flat.data() + static_cast<std::size_t>(b) * W;
      for (int j = 0; j < W; ++j)
        if (x[j] != y[j]) return x[j] < y[j];
      return false;
    });
    r.simplices.reserve(m);
    for (std::uint32_t k : order)
      r.simplices.emplace_back(flat.begin() + static_cast<std::ptrdiff_t>(k) * W,
                               flat.begin() + static_cast<std::ptrdiff_t>(k + 1) * W);
    for (std::size_t k = 0; k < n_; ++k)
      if (!vertex[k]) r.redundant.push_back(static_cast<Index>(ids_[k]));
    std::sort(r.redundant.begin(), r.redundant.end());
    return r;
  }

 private:
  std::size_t n_ = 0;  // positions taken (points given so far)
  // the virtual vertex: a fixed value no position reaches (positions < 2^29),
  // so that in-place insertion can append positions
  static constexpr std::uint32_t V_ = kDead - 1;
  bool furthest_;
  int threads_;  // RtdCavityOptions::threads: 1 tests a cavity's cells one by one (visible_region)
  double parallel_min_ns_;  // RtdCavityOptions::parallel_min_ns
  std::vector<double> xs_, ws_;
  std::vector<pred::PointId> ids_;
  pred::StaticFilter f_;
  std::vector<std::uint32_t> tv_, tn_, mark_, free_;
  std::uint32_t stamp_ = 0;
  std::uint32_t last_ = kDead;
  std::uint64_t rng_ = 0x2545F4914F6CDD1Dull;

  struct Horizon {
    std::uint32_t v[W];  // the visible simplex's tuple with corner i := p
    int i;               // corner of p (the facet opposite it is the horizon ridge)
    std::uint32_t out;   // link W u + j of the invisible neighbour across it
  };
  std::vector<std::uint32_t> cavity_;
  std::vector<std::uint32_t> pending_;  // visible_region_waves' undecided cells
  std::vector<char> result_;
  std::uint32_t batches_ = 0;  // visible_all's batches, and its latest cost per cell (ns)
  double cell_ns_ = 0.0;
  std::vector<Horizon> horizon_;
  RidgeTable<kKey> ridges_;  // link_cone's

  // Appends the points `order` (input indices of ps) as positions n_..; the
  // static filter over all of ps.
  void take(const PointSet& ps, const std::vector<Index>& order) {
    const std::size_t n = n_ + order.size();
    xs_.resize(n * D);
    ws_.resize(n);
    ids_.resize(n);
    for (std::size_t k = n_; k < n; ++k) {
      const Index i = order[k - n_];
      const double* x = ps.point(i);
      for (int j = 0; j < D; ++j) xs_[k * D + static_cast<std::size_t>(j)] = x[j];
      ws_[k] = ps.weight(i);
      ids_[k] = i;
    }
    n_ = n;
    f_ = pred::StaticFilter::for_points(ps.coords.data(), ps.size(), D, ps.weighted ? ps.weights.data() : nullptr);
  }

  const std::uint32_t* simplex(std::uint32_t t) const { return tv_.data() + static_cast<std::size_t>(t) * W; }
  bool is_virtual(std::uint32_t t) const {
    const std::uint32_t* v = simplex(t);
    bool any = false;
    for (int j = 0; j < W; ++j) any |= v[j] == V_;
    return any;
  }

  // The sign of K rows: lambda_sign_staged, or with FiltersOnly its first
  // stage alone — the static and semi-static filters, 0 where they do not
  // decide. On an input of small integers (StaticFilter::lattice)
  // lambda_sign_staged runs the integer walk before any filter from
  // kLatticeFirstK rows on (most of those calls are exactly degenerate), and
  // beyond kMaxStagedK rows (8D, 9D) it has no such stage: 0 there.
  template <int K, bool FiltersOnly>
  int sign_of(const pred::PointId* id, const double* const* x, const double* w) const {
    if constexpr (!FiltersOnly) {
      return pred::lambda_sign_staged<K>(&f_, id, x, w);
    } else if constexpr (K > pred::kMaxStagedK) {
      return 0;
    } else {
      if (K >= pred::kLatticeFirstK && f_.lattice(K, w != nullptr) >= 1) return 0;
      return pred::static_semi_static_sign<K>(&f_, x, w);
    }
  }
  // orient_d of D+1 positions (none virtual)
  template <bool FiltersOnly = false>
  int orient(const std::uint32_t* u) const {
    pred::PointId id[W];
    const double* p[W];
    for (int j = 0; j < W; ++j) {
      id[j] = ids_[u[j]];
      p[j] = xs_.data() + static_cast<std::size_t>(u[j]) * D;
    }
    return sign_of<W, FiltersOnly>(id, p, static_cast<const double*>(nullptr));
  }
  // power_d of a real simplex and p: > 0 iff p̂ strictly below its lifted hyperplane
  template <bool FiltersOnly = false>
  int power(const std::uint32_t* u, std::uint32_t q) const {
    pred::PointId id[W + 1];
    const double* p[W + 1];
    double w[W + 1];
    for (int j = 0; j <= W; ++j) {
      const std::uint32_t x = j < W ? u[j] : q;
      id[j] = ids_[x];
      p[j] = xs_.data() + static_cast<std::size_t>(x) * D;
      w[j] = ws_[x];
    }
    const int s = sign_of<W + 1, FiltersOnly>(id, p, w);
    return furthest_ ? -s : s;
  }
  // Is p̂ strictly beyond cell t (1) or not (0)? With FiltersOnly, 2 where
  // the filters do not decide (visible_region_waves' first pass).
  template <bool FiltersOnly = false>
  int visibility(std::uint32_t t, std::uint32_t p) const {
    const std::uint32_t* v = simplex(t);
    int s = 0;
    bool virt = false;
    for (int j = 0; j < W && !virt; ++j)
      if (v[j] == V_) {
        std::uint32_t u[W];
        for (int q = 0; q < W; ++q) u[q] = v[q];
        u[j] = p;
        s = orient<FiltersOnly>(u);
        virt = true;
      }
    if (!virt) s = power<FiltersOnly>(v, p);
    return FiltersOnly && s == 0 ? 2 : s > 0;
  }
  bool visible(std::uint32_t t, std::uint32_t p) const { return visibility(t, p) == 1; }
  // visible(cells[k], p) into result[k] (the exact stages of a wave's
  // undecided cells): in parallel where the wave's work pays for the fork
  // and join. That work differs by three orders of magnitude between inputs
  // — a call of the integer walk on a small-integer grid costs about a
  // microsecond, a perturbation's search on a moved or decimal lattice tens
  // — so it is measured: every kProbe-th batch runs on this thread, timed,
  // and sets the cost per cell that the next batches are judged by (two
  // cells at least, and RtdCavityOptions::parallel_min_ns of work
  // estimated). Only the time taken depends on the clock; every result is
  // visible()'s. The predicates keep no shared state.
  static constexpr std::uint32_t kProbe = 16;
  void visible_all(const std::uint32_t* cells, std::size_t n, std::uint32_t p, char* result) {
    const bool probe = batches_++ % kProbe == 0;
    if (probe || n < 2 || cell_ns_ * static_cast<double>(n) < parallel_min_ns_) {
      const auto t0 = probe ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
      for (std::size_t k = 0; k < n; ++k) result[k] = visible(cells[k], p);
      if (probe)
        cell_ns_ = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
                   static_cast<double>(n);
      return;
    }
    par_for(n, 1, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) result[k] = visible(cells[k], p);
    });
  }

  std::uint32_t take_slot() {
    if (!free_.empty()) {
      const std::uint32_t s = free_.back();
      free_.pop_back();
      return s;
    }
    const std::size_t s = mark_.size();
    if ((s + 1) * W >= kDead) throw std::length_error("rtd (cpu): more simplices than 32-bit neighbour links hold");
    tv_.resize((s + 1) * W, kDead);
    tn_.resize((s + 1) * W, kDead);
    mark_.push_back(0);
    return static_cast<std::uint32_t>(s);
  }

  // The cone entry of the virtual simplex over facet i of the positive real
  // simplex t (tuple r): r with corner i := v and two other corners swapped,
  // so that replacing v by a point beyond facet i gives a positive tuple
  // (make_simplex's rule), linked to t across facet i.
  Horizon virtual_over(const std::uint32_t* r, int i, std::uint32_t t) const {
    Horizon h;
    for (int j = 0; j < W; ++j) h.v[j] = r[j];
    h.v[i] = V_;
    const int j1 = i == 0 ? 1 : 0, j2 = (i == 0 || i == 1) ? 2 : 1;
    std::swap(h.v[j1], h.v[j2]);
    h.i = i;
    h.out = t * W + static_cast<std::uint32_t>(i);
    return h;
  }

  // The first simplex (positions 0..D: distinct indices, never flat under
  // SoS), made positive, and its D+1 virtual simplices (v, facet i):
  // virtual_over's.
  void start(RtdCavityStats& st) {
    std::uint32_t r[W];
    for (int j = 0; j < W; ++j) r[j] = static_cast<std::uint32_t>(j);
    if (orient(r) < 0) std::swap(r[0], r[1]);
    const std::uint32_t t0 = take_slot();
    for (int j = 0; j < W; ++j) tv_[static_cast<std::size_t>(t0) * W + static_cast<std::size_t>(j)] = r[j];
    cavity_.clear();
    horizon_.clear();
    for (int i = 0; i < W; ++i) horizon_.push_back(virtual_over(r, i, t0));
    link_cone(st);
    last_ = t0;
    st.inserted = W;
  }

  // One simplex per horizon entry (the cavity's slots first), linked to the
  // invisible neighbour across its horizon ridge and, across its other D
  // facets — each the apex and a (D-2)-face of the horizon, shared by exactly
  // two horizon ridges (the horizon is a closed (D-1)-manifold) — to the new
  // simplex across, matched by that face's sorted vertices in a hash table.
  void link_cone(RtdCavityStats& st) {
    const std::size_t m = horizon_.size();
    ridges_.begin(m * D);
    for (std::size_t k = 0; k < m; ++k) {
      const Horizon& h = horizon_[k];
      const std::uint32_t s = k < cavity_.size() ? cavity_[k] : take_slot();
      std::uint32_t* v = tv_.data() + static_cast<std::size_t>(s) * W;
      bool real = true;
      for (int j = 0; j < W; ++j) {
        v[j] = h.v[j];
        real &= h.v[j] != V_;
      }
      tn_[static_cast<std::size_t>(s) * W + static_cast<std::size_t>(h.i)] = h.out;
      tn_[h.out] = s * W + static_cast<std::uint32_t>(h.i);
      // the horizon ridge's D vertices sorted once; the key of the cone
      // facet opposite corner j is that list without h.v[j] (sorted still),
      // instead of a sort per facet (3^5 grid, callgrind: link_cone 70.7 M ->
      // 64.3 M instructions; docs/performance/python_scipy.md, stop 87)
      typename RidgeTable<D>::Key ridge;
      {
        int c = 0;
        for (int q = 0; q < W; ++q)
          if (q != h.i) ridge[static_cast<std::size_t>(c++)] = h.v[q];
        RidgeTable<D>::sort(ridge);
      }
      for (int j = 0; j < W; ++j) {
        if (j == h.i) continue;
        typename RidgeTable<kKey>::Key key;
        const std::uint32_t x = h.v[j];
        for (int c = 0; c < kKey; ++c)
          key[static_cast<std::size_t>(c)] = ridge[static_cast<std::size_t>(c + (ridge[static_cast<std::size_t>(c)] >= x))];
        const std::uint32_t half = s * W + static_cast<std::uint32_t>(j);
        const std::uint32_t other = ridges_.offer(key, half);
        if (other != RidgeTable<kKey>::kOpen) tn_[half] = other, tn_[other] = half;
      }
      if (real) last_ = s;
    }
    if (!ridges_.end()) throw std::logic_error("rtd (cpu): the horizon of an insertion is not a closed manifold");
    for (std::size_t q = m; q < cavity_.size(); ++q) {  // cavity slots not reused
      const std::uint32_t s = cavity_[q];
      for (int j = 0; j < W; ++j) tv_[static_cast<std::size_t>(s) * W + static_cast<std::size_t>(j)] = kDead;
      free_.push_back(s);
    }
    st.created += m;
  }

  // Visibility walk from real simplex t toward p: across a facet that
  // separates t from p (orient_d with that corner replaced by p negative),
  // never back across the facet just crossed, the facets tried from a random
  // one (the stochastic walk of Devillers–Pion–Teillaud; it terminates on a
  // regular triangulation: Edelsbrunner's acyclicity theorem, as
  // reference/rtd's locate). Returns the real simplex containing p (SoS:
  // strictly) or the first virtual simplex reached (one whose hull facet p
  // sees).
  std::uint32_t walk(std::uint32_t p, std::uint32_t t, RtdCavityStats& st) {
    int from = W;
    for (;;) {
      ++st.walk_steps;
      rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
      const int r = static_cast<int>((rng_ >> 32) % static_cast<std::uint64_t>(W));
      const std::uint32_t* v = simplex(t);
      std::uint32_t next = kDead;
      for (int q = 0; q < W; ++q) {
        const int i = (r + q) % W;
        if (i == from) continue;
        std::uint32_t u[W];
        for (int j = 0; j < W; ++j) u[j] = v[j];
        u[i] = p;
        if (orient(u) < 0) {
          next = tn_[static_cast<std::size_t>(t) * W + static_cast<std::size_t>(i)];
          break;
        }
      }
      if (next == kDead) return t;
      t = next / W;
      from = static_cast<int>(next % W);
      if (is_virtual(t)) return t;
    }
  }

  void insert(std::uint32_t p, RtdCavityStats& st) {
    const std::uint32_t root = walk(p, last_, st);
    if (!visible(root, p)) {  // real (a virtual end is visible): p̂ inside Q
      ++st.discarded;
      last_ = root;
      return;
    }
    stamp_ += 4;  // (visible_region_waves' four stamps; visible_region uses two of them)
    if (stamp_ < 4) {  // wrapped: clear the stamps
      std::fill(mark_.begin(), mark_.end(), 0u);
      stamp_ = 4;
    }
    horizon_.clear();
    auto on_horizon = [&](std::uint32_t t, int i, std::uint32_t l) {
      Horizon h;
      const std::uint32_t* v = simplex(t);
      for (int j = 0; j < W; ++j) h.v[j] = v[j];
      h.v[i] = p;
      h.i = i;
      h.out = l;
      horizon_.push_back(h);
    };
    if (threads_ == 1)
      visible_region<W>(root, tn_, mark_, stamp_, cavity_, [&](std::uint32_t u) { return visible(u, p); }, on_horizon);
    else
      visible_region_waves<W>(
          root, tn_, mark_, stamp_, cavity_, pending_, result_, [&](std::uint32_t u) { return visibility<true>(u, p); },
          [&](const std::uint32_t* cells, std::size_t n, char* r) { visible_all(cells, n, p, r); }, on_horizon);
    if (is_virtual(root)) ++st.placed;
    link_cone(st);
    ++st.inserted;
    st.cavity += cavity_.size();
  }
};

// The insertion order of ps's points first.. (BRIO rounds, a Morton curve of
// the bounding box of all of ps: keys below 2^30, as brio::order needs).
template <int D>
std::vector<Index> insertion_order(const PointSet& ps, std::size_t first, const RtdCavityOptions& o) {
  std::vector<Index> order;
  with_threads(o.threads, [&] {
    const std::array<double, 2 * D> box = brio::bounding_box<D>(ps);
    order = brio::order(ps.size() - first, o.brio_min,
                        [&](std::size_t i) {
                          return static_cast<std::uint32_t>(
                              brio::morton(ps.point(first + i), box.data(), box.data() + D, D, 30));
                        },
                        [&](std::size_t i) { return brio::point_hash(ps.point(first + i), D); }, nullptr);
  });
  if (first != 0)
    for (Index& i : order) i += static_cast<Index>(first);
  return order;
}

// A Builder<D> behind the dimension-free interface of RtdCavityIncremental.
struct AnyBuilder {
  virtual ~AnyBuilder() = default;
  virtual void append(const PointSet& ps, std::size_t first, const RtdCavityOptions& o, RtdCavityStats& st) = 0;
  virtual ref::Rtd output() const = 0;
};

std::vector<Index> identity_order(std::size_t n) {
  std::vector<Index> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<Index>(i);
  return order;
}

template <int D>
struct BuilderOf final : AnyBuilder {
  Builder<D> b;
  BuilderOf(const PointSet& ps, const RtdCavityOptions& o, RtdCavityStats& st)
      : b(ps, insertion_order<D>(ps, 0, o), o.furthest, o.threads, o.parallel_min_ns) {
    with_threads(o.threads, [&] { b.run(st); });
  }
  // seeded (RtdCavityIncremental's second constructor)
  BuilderOf(const PointSet& ps, const RtdCavityOptions& o, RtdCavityStats& st, const Index* simplices,
            const std::int64_t* nb, std::size_t m)
      : b(ps, identity_order(ps.size()), o.furthest, o.threads, o.parallel_min_ns) {
    if (!b.seed(simplices, nb, m, st))
      throw std::invalid_argument("rtd (cpu): the seed simplices and neighbours are not a closed triangulation");
  }
  void append(const PointSet& ps, std::size_t first, const RtdCavityOptions& o, RtdCavityStats& st) override {
    const std::vector<Index> order = insertion_order<D>(ps, first, o);
    with_threads(o.threads, [&] { b.append(ps, order, st); });
  }
  ref::Rtd output() const override { return b.output(); }
};

std::unique_ptr<AnyBuilder> build(const PointSet& ps, const RtdCavityOptions& o, RtdCavityStats& st) {
  switch (ps.dim) {
    case 2: return std::make_unique<BuilderOf<2>>(ps, o, st);
    case 3: return std::make_unique<BuilderOf<3>>(ps, o, st);
    case 4: return std::make_unique<BuilderOf<4>>(ps, o, st);
    case 5: return std::make_unique<BuilderOf<5>>(ps, o, st);
    case 6: return std::make_unique<BuilderOf<6>>(ps, o, st);
    case 7: return std::make_unique<BuilderOf<7>>(ps, o, st);
    case 8: return std::make_unique<BuilderOf<8>>(ps, o, st);
    default: return std::make_unique<BuilderOf<9>>(ps, o, st);
  }
}

template <int D>
std::unique_ptr<AnyBuilder> seeded(const PointSet& ps, const RtdCavityOptions& o, RtdCavityStats& st,
                                   const Index* simplices, const std::int64_t* nb, std::size_t m) {
  return std::make_unique<BuilderOf<D>>(ps, o, st, simplices, nb, m);
}

void check_size(const PointSet& ps) {
  if (ps.size() >= (std::size_t{1} << brio::kIndexBits))
    throw std::length_error("rtd (cpu): more than 2^29 points");
}

}  // namespace

ref::Rtd rtd_cavity(const PointSet& ps, RtdCavityStats* stats, const RtdCavityOptions& options) {
  ref::validate_rtd_input(ps);
  check_size(ps);
  RtdCavityStats local;
  RtdCavityStats& st = stats ? *stats : local;
  st = RtdCavityStats{};
  ref::Rtd r = build(ps, options, st)->output();
  st.removed = r.redundant.size() - st.discarded;
  return r;
}

// ---- in-place insertion ------------------------------------------------------------

struct RtdCavityIncremental::Impl {
  RtdCavityOptions options;
  RtdCavityStats stats;
  std::unique_ptr<AnyBuilder> builder;
  std::size_t size = 0;
  int dim = 0;
  bool weighted = false;
  bool broken = false;  // an insertion threw: the state is not a triangulation any more
};

RtdCavityIncremental::RtdCavityIncremental(const PointSet& ps, const RtdCavityOptions& options)
    : impl_(std::make_unique<Impl>()) {
  ref::validate_rtd_input(ps);
  check_size(ps);
  impl_->options = options;
  impl_->builder = build(ps, options, impl_->stats);
  impl_->size = ps.size();
  impl_->dim = ps.dim;
  impl_->weighted = ps.weighted;
}

RtdCavityIncremental::RtdCavityIncremental(const PointSet& ps, const std::vector<Index>& simplices,
                                           const std::vector<std::int64_t>& neighbors, const RtdCavityOptions& options)
    : impl_(std::make_unique<Impl>()) {
  ref::validate_rtd_input(ps);
  check_size(ps);
  if (options.furthest) throw std::invalid_argument("rtd (cpu): a seeded triangulation is not furthest-site");
  const std::size_t w = static_cast<std::size_t>(ps.dim) + 1, m = simplices.size() / w;
  if (m == 0 || simplices.size() != m * w || neighbors.size() != simplices.size())
    throw std::invalid_argument("rtd (cpu): a seed needs its simplices, d + 1 corners and d + 1 neighbours each");
  for (std::size_t k = 0; k < m; ++k) {
    const Index* t = simplices.data() + k * w;
    for (std::size_t c = 0; c < w; ++c)
      if (t[c] >= ps.size() || std::find(t, t + c, t[c]) != t + c)
        throw std::invalid_argument("rtd (cpu): a seed simplex needs d + 1 distinct indices of the points");
  }
  impl_->options = options;
  const Index* s = simplices.data();
  const std::int64_t* nb = neighbors.data();
  switch (ps.dim) {
    case 2: impl_->builder = seeded<2>(ps, options, impl_->stats, s, nb, m); break;
    case 3: impl_->builder = seeded<3>(ps, options, impl_->stats, s, nb, m); break;
    case 4: impl_->builder = seeded<4>(ps, options, impl_->stats, s, nb, m); break;
    case 5: impl_->builder = seeded<5>(ps, options, impl_->stats, s, nb, m); break;
    case 6: impl_->builder = seeded<6>(ps, options, impl_->stats, s, nb, m); break;
    case 7: impl_->builder = seeded<7>(ps, options, impl_->stats, s, nb, m); break;
    case 8: impl_->builder = seeded<8>(ps, options, impl_->stats, s, nb, m); break;
    default: impl_->builder = seeded<9>(ps, options, impl_->stats, s, nb, m); break;
  }
  impl_->size = ps.size();
  impl_->dim = ps.dim;
  impl_->weighted = ps.weighted;
}

RtdCavityIncremental::~RtdCavityIncremental() = default;
RtdCavityIncremental::RtdCavityIncremental(RtdCavityIncremental&&) noexcept = default;
RtdCavityIncremental& RtdCavityIncremental::operator=(RtdCavityIncremental&&) noexcept = default;

void RtdCavityIncremental::add(const PointSet& all) {
  Impl& m = *impl_;
  if (m.broken) throw std::logic_error("rtd (cpu): an earlier insertion failed; the triangulation must be rebuilt");
  if (all.dim != m.dim || all.weighted != m.weighted)
    throw std::invalid_argument("rtd (cpu): the added points' dimension or weights differ from the triangulation's");
  if (all.size() < m.size)
    throw std::invalid_argument("rtd (cpu): add() needs the points given so far followed by the new ones");
  if (all.size() == m.size) return;
  ref::validate_rtd_input(all);
  check_size(all);
  try {
    m.builder->append(all, m.size, m.options, m.stats);
  } catch (...) {
    m.broken = true;
    throw;
  }
  m.size = all.size();
}

ref::Rtd RtdCavityIncremental::result() const {
  if (impl_->broken) throw std::logic_error("rtd (cpu): an earlier insertion failed; the triangulation must be rebuilt");
  return impl_->builder->output();
}

std::size_t RtdCavityIncremental::size() const { return impl_->size; }

RtdCavityStats RtdCavityIncremental::stats() const { return impl_->stats; }

}  // namespace flipflop::cpu

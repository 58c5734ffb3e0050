// rt3.cpp — the multithreaded 3D regular / Delaunay triangulation (see
// rt3.hpp for the stages and why the answer is the reference's).
//
// ============================================================================
// Insertion: the cavity step is Edelsbrunner–Shah's flips, composed
// ============================================================================
// Lift every point x to x̂ = (x, |x|² - w) in R^4 (thesis §2.1, §9.2.2; the
// height perturbed as an independent coordinate under SoS). The regular
// triangulation of the points inserted so far is the projection of the lower
// hull of their lifted points; with the virtual vertex v read as the point at
// infinity straight up, the extended triangulation (rt3.hpp, thesis §2.1) is
// the boundary complex of the polytope Q = conv(lifted points) + upward ray:
// a real tetrahedron is a lower facet, a virtual tetrahedron (v, f) the
// vertical facet over the hull facet f.
//
// Inserting p is adding p̂ to Q (beneath–beyond). A facet of Q is VISIBLE
// from p̂ when p̂ lies strictly on its outer side:
//   * a real tetrahedron (a, b, c, d), positive: p̂ strictly below the
//     hyperplane of â, b̂, ĉ, d̂ — power3d(a, b, c, d, p) > 0 (predicates.hpp);
//   * a virtual tetrahedron (v, f): p strictly beyond the hull facet f —
//     orient3d of its tuple with v replaced by p > 0 (rt3.hpp's rule).
// Under SoS no facet is ever "flat" to p̂. The facets visible from a point
// outside a convex polytope form a non-empty connected set whose boundary
// (the horizon) is a closed 2-manifold of ridges; conv(Q ∪ p̂) keeps the
// invisible facets and adds the cone from p̂ over every horizon ridge. When
// p̂ lies inside Q (no facet visible: the real tetrahedron containing p
// passes below p̂) p is redundant — for good, since Q only grows.
//
// This is exactly what Edelsbrunner–Shah's RT+1 returns ([ES92], thesis §3.1
// Table 3.1, §9.1; reference/rtd/rt_incremental.cpp): the 1-4 flip into the
// tetrahedron containing p followed by 2-3 / 3-2 / 4-1 flips of the
// non-regular link facets of p ends, by their Theorem (the flips terminate in
// THE regular triangulation of the points so far, which is unique under SoS),
// in the same triangulation; each of their flips replaces visible facets of Q
// by facets through p̂ (the lifted surface only descends, §9.1), and the
// cavity step performs the whole sequence at once: it removes every facet
// visible from p̂ — the tetrahedra the flips destroy, a vertex all of whose
// tetrahedra are visible being the (3+1)-1 flip's removed vertex — and
// creates the cone over the horizon, the tetrahedra the flips create and
// keep. Outside the hull the visible virtual facets are the reference's
// placing step (rt_incremental.cpp, step 2b) and the visible real ones its
// following flips.
//
// The visible set is found by a breadth-first search from the tetrahedron
// the walk ends in (the real one containing p, or the first virtual one whose
// hull facet p sees): every visible facet is reached through visible facets
// (connectedness), so the search tests only the visible facets and their
// neighbours. New tetrahedron across a horizon ridge = the visible
// tetrahedron with its corner opposite that ridge replaced by p (same slot
// position): p lies on the same side of the ridge as that corner (the cone is
// a triangulation of the new lower hull), so a real new tetrahedron stays
// positive and a virtual one keeps rt3.hpp's rule, and across every facet
// the two tuples still induce opposite orientations.
#include "kernels_cpu/rt3/rt3.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "kernels_cpu/brio.hpp"
#include "kernels_cpu/rt3/canonical_tet.hpp"
#include "kernels_cpu/parallel.hpp"
#include "kernels_cpu/witnessed_output.hpp"
#include "predicates/fast.hpp"
#include "reference/dimension.hpp"

namespace flipflop::cpu {

namespace {

constexpr std::uint32_t kDead = Rt3Witness::kNoSlot;

// ---- stage 1: BRIO order ---------------------------------------------------------

// Hilbert index of (x, y, z) on the 2^10 grid per axis (30 bits): Skilling's
// transform (J. Skilling, "Programming the Hilbert curve", AIP Conf. Proc.
// 707, 2004) — undo the excess work of the Gray code axis by axis from the
// top bit, Gray-encode, then interleave the transposed bits.
std::uint32_t hilbert10(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  std::uint32_t X[3] = {x, y, z};
  constexpr std::uint32_t M = 1u << 9;
  for (std::uint32_t Q = M; Q > 1; Q >>= 1) {
    const std::uint32_t P = Q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & Q) {
        X[0] ^= P;  // invert the low bits of axis 0
      } else {      // exchange the low bits of axis 0 and axis i
        const std::uint32_t t = (X[0] ^ X[i]) & P;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  X[1] ^= X[0];
  X[2] ^= X[1];
  std::uint32_t t = 0;
  for (std::uint32_t Q = M; Q > 1; Q >>= 1)
    if (X[2] & Q) t ^= Q - 1;
  for (auto& c : X) c ^= t;
  std::uint32_t key = 0;
  for (int b = 9; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

// The BRIO order (kernels_cpu/brio.hpp) along the 3D Hilbert curve of the
// bounding box; rounds_at receives the first position of each round, and n.
// keys (when asked for): each input point's Hilbert index.
std::vector<Index> brio_order(const PointSet& ps, std::size_t brio_min, std::vector<std::size_t>* rounds_at,
                              std::vector<std::uint32_t>* keys) {
  const std::array<double, 6> box = brio::bounding_box<3>(ps);
  if (keys) keys->resize(ps.size());
  return brio::order(
      ps.size(), brio_min,
      [&](std::size_t i) {
        const double* p = ps.point(i);
        const std::uint32_t h = hilbert10(brio::grid<10>(p[0], box[0], box[3]), brio::grid<10>(p[1], box[1], box[4]),
                                          brio::grid<10>(p[2], box[2], box[5]));
        if (keys) (*keys)[i] = h;
        return h;
      },
      [&](std::size_t i) { return brio::point_hash(ps.point(i), 3); }, rounds_at);
}

// ---- stage 2: insertion -------------------------------------------------------------

// The lock cells of the parallel rounds (Builder's claims): runs of about
// n / 256 points, between 16 and 512 (fewer, larger cells: fewer cells per
// insertion; more: fewer conflicts on small inputs), consecutive on the
// Hilbert curve of brio_order, cut at
// quantiles of a sample of the points' Hilbert indices (key, per input
// point; a cell is a stretch of the curve: compact in space, and adapted to
// the points' density). Returns each position's cell (order: position ->
// input point); ncells: their number.
std::vector<std::uint32_t> lock_cells(const std::vector<std::uint32_t>& key, const std::vector<Index>& order,
                                      std::size_t& ncells) {
  const std::size_t n = order.size();
  const std::size_t cell_points = std::clamp<std::size_t>(n / 256, 16, 512);
  constexpr std::size_t kSample = 16;  // every 16th position (the BRIO order is a spatially random one)
  std::vector<std::uint32_t> sample;
  for (std::size_t k = 0; k < n; k += kSample) sample.push_back(key[order[k]]);
  std::sort(sample.begin(), sample.end());
  std::vector<std::uint32_t> cut;
  for (std::size_t i = cell_points / kSample; i < sample.size(); i += cell_points / kSample) cut.push_back(sample[i]);
  cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
  ncells = cut.size() + 1;
  std::vector<std::uint32_t> cell(n);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t k = a; k < b; ++k)
      cell[k] = static_cast<std::uint32_t>(std::upper_bound(cut.begin(), cut.end(), key[order[k]]) - cut.begin());
  });
  return cell;
}

// Tetrahedron slots above this make a link 4t + i overflow 32 bits.
constexpr std::size_t kMaxSlots = (std::size_t{1} << 30) - 1;

// kFacet[i][k] (i: the apex's corner of a cone tetrahedron, k = 0..2): the
// corner j of the k-th other facet, opposite j, and the two corners other than
// i and j — the facet is the apex and the horizon edge between those two.
struct ConeFacet {
  std::uint8_t j, a, b;
};
constexpr ConeFacet kFacet[4][3] = {{{1, 2, 3}, {2, 1, 3}, {3, 1, 2}},
                                    {{0, 2, 3}, {2, 0, 3}, {3, 0, 2}},
                                    {{0, 1, 3}, {1, 0, 3}, {3, 0, 1}},
                                    {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}}};

// A horizon ridge of an insertion: the new tetrahedron over it.
struct Horizon {
  std::uint32_t v[4];  // the visible tetrahedron's tuple with its corner i := p
  std::uint32_t i;     // corner of p (the facet opposite it is the horizon ridge)
  std::uint32_t out;   // link 4u + j of the invisible neighbour across it
  std::uint32_t loc[4];  // link_cone (sequential): the corners' numbers on the horizon
};

// The state of one inserting thread: the sequential insertion's, or one
// piece's in a parallel round (stage 2, parallel rounds: Builder::run).
struct alignas(64) Worker {  // on lines of its own: its counters and vector ends are written all the time
  std::uint32_t me = 0;  // claim tag in a parallel round (piece + 1); 0: sequential, no claims
  std::vector<std::uint32_t> cavity, held, fresh, free;  // held: lock cells (parallel rounds)
  std::vector<Horizon> horizon;
  std::vector<std::uint64_t> hkey;
  std::vector<std::uint32_t> hval;
  std::uint64_t rng = 0x2545F4914F6CDD1Dull;
  std::uint32_t last = kDead;  // a real tetrahedron near the last point inserted
  std::uint32_t recent[8] = {kDead, kDead, kDead, kDead, kDead, kDead, kDead, kDead};
  unsigned nrecent = 0;
  std::size_t bump = 0, bump_end = 0;  // private range of never-used slots (parallel rounds)
  std::uint32_t stamp = 0, stamp_end = 0;  // private range of BFS stamps (insert)
  std::vector<std::uint32_t> deferred;
  std::size_t fail_every = 0, claims = 0;  // test hook (Rt3Options::fail_claims_every)
  Rt3Stats st;
  void remember(std::uint32_t t) { recent[nrecent++ & 7u] = last = t; }
};

enum class Outcome { done, deferred, lost };

class Builder {
 public:
  Builder(std::vector<Rt3Point> pts, const pred::StaticFilter& f)
      : P_(std::move(pts)), f_(f), V_(static_cast<std::uint32_t>(P_.size())), hint_(P_.size(), kDead) {
    // the first points' slots; run reserves each BRIO round's before it
    grow(7 * std::min<std::size_t>(P_.size(), 4096) + 64);
    tables_.resize(static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency())));
  }

  // Inserts every point: sequentially up to position `parallel_from` (all
  // of them when !parallel), then each BRIO round (rounds_at: the first
  // position of each round, and n) in parallel pieces.
  void run(bool parallel, std::size_t parallel_from, std::size_t min_piece, std::size_t fail_every,
           const std::vector<std::size_t>& rounds_at, Rt3Stats& st);

  // The lock cell of each position (parallel rounds; see the claims below).
  void set_cells(const std::vector<std::uint32_t>& cell, std::size_t ncells) {
    lock_count_ = ncells;
    for (std::size_t k = 0; k < cell.size(); ++k) P_[k].cell = cell[k];
    lock_.reset(new std::atomic<std::uint32_t>[ncells]);
    for (std::size_t c = 0; c < ncells; ++c) lock_[c].store(0, std::memory_order_relaxed);
  }

  // Live real tetrahedra as canonical tuples of input indices, sorted.
  std::vector<Tet> output() const;
  // Input indices that are vertices of no real tetrahedron, ascending.
  std::vector<Index> redundant(std::vector<std::uint32_t>* at_vertex) const;
  void witness(Rt3Witness& w, std::vector<std::uint32_t> at);

 private:
  std::vector<Rt3Point> P_;
  const pred::StaticFilter& f_;
  const std::uint32_t V_;  // the virtual vertex (position n)
  // per slot: corners, links, BFS stamps; all of capacity cap_, grown
  // between rounds only
  std::vector<std::uint32_t> tv_, tn_, mark_;
  // parallel rounds: per lock cell the tag of the worker holding it (0:
  // free); each position's cell is P_[k].cell
  std::unique_ptr<std::atomic<std::uint32_t>[]> lock_;
  std::size_t lock_count_ = 0;
  std::size_t cap_ = 0;
  std::atomic<std::size_t> slots_{0};  // slots ever used (a prefix of the capacity)
  // per position: a tetrahedron near it — for a point found redundant, the
  // one it was found in (the witness's walk starts there); for an inserted
  // one, one of its new tetrahedra (a parallel round's pieces start there)
  std::vector<std::uint32_t> hint_;
  // link_cone's edge table, one per thread (a worker runs on one thread from
  // its first insertion to its last, and the sequential one alone): the
  // horizon's vertices numbered 0..L-1 through per-position tags
  // (stamp << 8 | number; 24-bit stamps, the tags cleared when they wrap),
  // then an L x L table of half-matched edges, for horizons of up to
  // kMaxLocal vertices. Allocated on a thread's first use.
  static constexpr std::uint32_t kMaxLocal = 64;
  // One cache line each: the stamp is written on every insertion, and two
  // threads' tables on one line were falsely shared (perf: the stamp's
  // increment and the table's first load were a tenth of link_cone's samples)
  struct alignas(64) EdgeTable {
    std::vector<std::uint32_t> tag, pending;
    std::uint32_t stamp = 0;
  };
  std::vector<EdgeTable> tables_;
  std::atomic<std::uint32_t> stamps_{2};  // BFS stamps: 2 per insertion attempt (mark_ starts at 0), in blocks
  Worker seq_;  // the sequential insertion (also of the points parallel rounds defer)

  pred::Pt pt(std::uint32_t k) const { return {P_[k].id, P_[k].xyz}; }
  pred::WPt wpt(std::uint32_t k) const { return {P_[k].id, P_[k].xyz, P_[k].w}; }
  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
    return pred::fast::orient3d(f_, pt(a), pt(b), pt(c), pt(d));
  }
  const std::uint32_t* tet(std::uint32_t t) const { return tv_.data() + 4 * static_cast<std::size_t>(t); }
  bool is_virtual(std::uint32_t t) const {
    const std::uint32_t* v = tet(t);
    return (v[0] == V_) | (v[1] == V_) | (v[2] == V_) | (v[3] == V_);
  }
  bool live(std::uint32_t t) const { return t < cap_ && tv_[4 * static_cast<std::size_t>(t)] != kDead; }

  // Is tetrahedron t visible from p̂ (header)? Inline only the static
  // filter of a real tetrahedron's power test, which decides almost every
  // call (perf: with the whole staged path inline, the ids and pointers its
  // later stages need were spilled to the stack on every call).
  bool visible(std::uint32_t t, std::uint32_t p) const {
    const std::uint32_t* v = tet(t);
    const std::uint32_t a = v[0], b = v[1], c = v[2], d = v[3];
    if ((a == V_) | (b == V_) | (c == V_) | (d == V_)) return visible_rest(t, p);
    const Rt3Point &A = P_[a], &B = P_[b], &C = P_[c], &D = P_[d], &E = P_[p];
    const double* x[5] = {A.xyz, B.xyz, C.xyz, D.xyz, E.xyz};
    const double w[5] = {A.w, B.w, C.w, D.w, E.w};
    if (const int s = pred::static_sign<5>(f_, x, w)) return s > 0;
    return visible_rest(t, p);
  }
  // The rest of visible: a virtual tetrahedron's orientation test, or the
  // power test's stages after the static filter.
  __attribute__((noinline)) bool visible_rest(std::uint32_t t, std::uint32_t p) const {
    const std::uint32_t* v = tet(t);
    for (int i = 0; i < 4; ++i)
      if (v[i] == V_) {
        std::uint32_t u[4] = {v[0], v[1], v[2], v[3]};
        u[i] = p;
        return orient(u[0], u[1], u[2], u[3]) > 0;
      }
    return pred::fast::power3d_after_static(f_, wpt(v[0]), wpt(v[1]), wpt(v[2]), wpt(v[3]), wpt(p)) > 0;
  }

  void grow(std::size_t cap) {
    tv_.resize(4 * cap, kDead);
    tn_.resize(4 * cap, kDead);
    mark_.resize(cap, 0);
    cap_ = cap;
  }

  // ---- claims (parallel rounds) -------------------------------------------------
  // The points are cut into lock cells: runs of up to 512 points
  // consecutive on the Hilbert curve of stage 1 (lock_cells), each with a
  // lock word. The rule: a worker of a parallel round reads or writes a
  // tetrahedron only while it holds the cells of all its real corners
  // (the virtual vertex has none). Two workers can then never both have a
  // tetrahedron (every tetrahedron has a real corner, a cell has one
  // holder); an insertion holds what it took until it ends, and a cell held
  // by another worker makes it give up (nothing written yet) and defer the
  // point. The sequential worker (me = 0) holds nothing.
  //   Moving to a neighbour: a worker that has tetrahedron t reads the link
  // 4u + j across t's facet i and then u's corners — safe before it holds
  // u's cells, since every facet has at least two real corners, those of the
  // shared facet are held, and anyone writing u (or freeing it, which
  // rewrites t's link) must hold them; then it takes the cell of u's corner
  // j, the one new corner (hold_across). Only walk_start reads a slot it
  // does not have (a remembered one, possibly freed or reused since): its
  // corners by atomic loads (corners are written by atomic stores,
  // put_corners, for that reader), then the cells of the real ones taken,
  // then the corners read again; the slot is kept when both reads agree. A
  // worker W writing the slot meanwhile holds the cells of the real corners
  // it writes, and the slot held before either kDead (freed) or a
  // tetrahedron of W's cavity (real corners in W's cells): so a read whose
  // real entries all lie in cells the reader holds has no entry of W's and
  // no old entry of W's — it is the slot's settled content, and the reader
  // has that tetrahedron. Compared with one claim per tetrahedron, an
  // insertion takes about four cells (10^6 uniform points) instead of ~50
  // compare-exchanges.
  //   "Do I hold it already?" is the lock word itself: it holds w.me only
  // while w holds the cell (w alone writes its tag, by its compare-exchange,
  // and w alone clears it, in release_all; a thread never reads an older
  // value of a location than its own last write to it), so a relaxed load
  // answers it. perf (10^6 ball points, parallel rounds on one thread): a
  // scan of w.held instead — about 57 calls per insertion, leaving the loop
  // at an unpredictable entry — made the claims cost 22-27 % of the
  // insertion; with the load, 6-8 %.
  bool hold_cell(Worker& w, std::uint32_t c) {
    if (lock_[c].load(std::memory_order_relaxed) == w.me) return true;
    if (w.fail_every != 0 && ++w.claims % w.fail_every == 0) return false;  // as if another task held it
    std::uint32_t cur = 0;
    if (!lock_[c].compare_exchange_strong(cur, w.me, std::memory_order_acquire, std::memory_order_relaxed))
      return false;
    tsan::acquired(&lock_[c]);
    w.held.push_back(c);
    return true;
  }
  // Link l = 4u + j read from a tetrahedron w has: take u (its corner j's cell).
  bool hold_across(Worker& w, std::uint32_t l) {
    if (w.me == 0) return true;
    const std::uint32_t x = tv_[l];  // corner j of u (l = 4u + j)
    return x == V_ || hold_cell(w, P_[x].cell);
  }
  void release_all(Worker& w) {
    for (std::uint32_t c : w.held) {
      tsan::released(&lock_[c]);
      lock_[c].store(0, std::memory_order_release);
    }
    w.held.clear();
  }
  // Corners of slot s written for walk_start's atomic reads (relaxed
  // atomic stores and loads on the plain array: C++17 has no atomic_ref; the
  // builtins are what it compiles to, and ThreadSanitizer sees them).
  void put_corners(std::uint32_t s, const std::uint32_t* v) {
    for (std::size_t j = 0; j < 4; ++j) __atomic_store_n(&tv_[4 * static_cast<std::size_t>(s) + j], v[j], __ATOMIC_RELAXED);
  }
  std::uint32_t corner_atomic(std::uint32_t s, std::size_t j) const {
    return __atomic_load_n(&tv_[4 * static_cast<std::size_t>(s) + j], __ATOMIC_RELAXED);
  }
  // BFS stamps (insert), read before the tetrahedron is held: atomic too
  std::uint32_t mark(std::uint32_t t) const { return __atomic_load_n(&mark_[t], __ATOMIC_RELAXED); }
  void set_mark(std::uint32_t t, std::uint32_t v) { __atomic_store_n(&mark_[t], v, __ATOMIC_RELAXED); }

  // A slot for a new tetrahedron: the worker's free list, else a never-used
  // one (sequential: growing the arrays; parallel: from the worker's range,
  // refilled from slots_ in blocks). kDead when none (parallel, capacity
  // reached). A free or never-used slot is no tetrahedron: no cell guards it
  // (only stale walk starts read it, atomically; the worker's writes to it are
  // put_corners' and the links of a tetrahedron it has until it releases).
  std::uint32_t take_slot(Worker& w) {
    if (!w.free.empty()) {
      const std::uint32_t s = w.free.back();
      w.free.pop_back();
      return s;
    }
    if (w.me == 0) {
      const std::size_t s = slots_.load(std::memory_order_relaxed);
      if (s >= kMaxSlots) throw std::length_error("rt3 (cpu): more than 2^30 tetrahedra (32-bit neighbour links)");
      if (s >= cap_) grow(std::min(kMaxSlots, s + s / 4 + 64));  // beyond run's reservation
      slots_.store(s + 1, std::memory_order_relaxed);
      return static_cast<std::uint32_t>(s);
    }
    if (w.bump == w.bump_end) {
      constexpr std::size_t kBlock = 256;
      const std::size_t s = slots_.fetch_add(kBlock, std::memory_order_relaxed);
      if (s + kBlock > cap_) return kDead;  // the round stops taking points (run: capacity)
      w.bump = s, w.bump_end = s + kBlock;
    }
    return static_cast<std::uint32_t>(w.bump++);
  }

  void start();
  Outcome insert(Worker& w, std::uint32_t p);
  bool link_cone(Worker& w);
  std::uint32_t walk_start(Worker& w);
  std::uint32_t walk(Worker* w, std::uint32_t p, std::uint32_t t, std::uint64_t& rng, std::uint64_t* steps);
  std::uint32_t any_real() const;
};

// The first tetrahedron: positions 0..3 (distinct indices: SoS never makes
// them coplanar), made positive, and its four virtual tetrahedra (v, face i):
// the real tuple with corner i := v and two other corners swapped (odd), so
// that replacing v by a point beyond face i gives a positive tuple — the
// rule of rt3.hpp, as reference/rtd's make_simplex.
void Builder::start() {
  Worker& w = seq_;
  std::uint32_t r[4] = {0, 1, 2, 3};
  if (orient(r[0], r[1], r[2], r[3]) < 0) std::swap(r[0], r[1]);
  const std::uint32_t t0 = take_slot(w);
  for (int i = 0; i < 4; ++i) tv_[4 * t0 + static_cast<std::uint32_t>(i)] = r[i];
  w.horizon.clear();
  w.cavity.clear();
  // the four virtual tetrahedra are the cone from v over the boundary of t0:
  // the same linking as an insertion's cone (link_cone), with v as the apex
  for (std::uint32_t i = 0; i < 4; ++i) {
    Horizon h;
    for (int j = 0; j < 4; ++j) h.v[j] = r[j];
    h.v[i] = V_;
    const std::uint32_t j1 = i == 0 ? 1 : 0, j2 = (i == 0 || i == 1) ? 2 : 1;
    std::swap(h.v[j1], h.v[j2]);
    h.i = i;
    h.out = 4 * t0 + i;
    w.horizon.push_back(h);
  }
  link_cone(w);
  w.remember(t0);
  w.st.inserted = 4;
}

// Creates one tetrahedron per horizon entry (in the cavity's slots first),
// links it to its invisible neighbour across the horizon ridge and to the
// new tetrahedra across its other three facets — those contain the apex and
// one edge of the horizon, shared by exactly two horizon ridges (the horizon
// is a closed 2-manifold). The two are matched by that edge: for the
// horizon's vertices numbered 0..L-1 (the thread's EdgeTable), in an L x L
// table whose entry is set by the first half and cleared by the second, so
// that it is empty again afterwards; above kMaxLocal vertices in a hash
// table. Returns false,
// having written nothing, when a parallel worker gets no slot.
bool Builder::link_cone(Worker& w) {
  const std::size_t m = w.horizon.size();
  w.fresh.clear();
  for (std::size_t q = w.cavity.size(); q < m; ++q) {
    const std::uint32_t s = take_slot(w);
    if (s == kDead) {
      w.free.insert(w.free.end(), w.fresh.begin(), w.fresh.end());
      return false;
    }
    w.fresh.push_back(s);
  }
  // (no 64-bit division on the way: the index is below the size but for an
  // arena larger than at construction)
  const std::size_t ti = static_cast<std::size_t>(std::max(0, tbb::this_task_arena::current_thread_index()));
  EdgeTable& et = tables_[ti < tables_.size() ? ti : ti % tables_.size()];
  if (et.tag.empty()) {
    et.tag.assign(V_ + 1, 0);
    et.pending.assign(kMaxLocal * kMaxLocal, kDead);
  }
  if (++et.stamp == (1u << 24)) {
    std::fill(et.tag.begin(), et.tag.end(), 0);
    et.stamp = 1;
  }
  const std::uint32_t st = et.stamp << 8;
  // Branch-free (callgrind/perf: as branches, "vertex seen before?" and
  // "which of the four corners is the apex's?" were mispredicted about once
  // per horizon entry): a vertex's first sight numbers it, the others read
  // the number; numbers up to kMaxLocal + 2 fit the tag's 8 bits, and a
  // horizon numbered beyond kMaxLocal - 1 goes to the hash table instead.
  std::uint32_t L = 0;
  for (Horizon& h : w.horizon) {
    for (const ConeFacet& f : kFacet[h.i]) {
      std::uint32_t& tag = et.tag[h.v[f.j]];
      // selects as masks: gcc turned the ?: back into branches
      const std::uint32_t old = tag;
      const std::uint32_t first = static_cast<std::uint32_t>((old & ~0xFFu) != st);
      const std::uint32_t all = 0u - first;  // all ones on a first sight
      const std::uint32_t now = (old & ~all) | ((st | L) & all);
      tag = now;
      L += first;
      h.loc[f.j] = now & 0xFFu;
    }
    if (L > kMaxLocal) break;
  }
  const bool small = L <= kMaxLocal;
  std::uint64_t mask = 0;
  if (!small) {
    std::size_t cap = 16;
    while (cap < 4 * m) cap <<= 1;
    if (w.hkey.size() < cap) {
      w.hkey.resize(cap);
      w.hval.resize(cap);
    }
    std::fill(w.hkey.begin(), w.hkey.begin() + static_cast<std::ptrdiff_t>(cap), ~std::uint64_t{0});
    mask = cap - 1;
  }
  // half-matched edges: +1 for a first half, -1 for a second; 0 at the end
  // on a closed horizon
  std::ptrdiff_t open = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Horizon& h = w.horizon[k];
    const std::uint32_t s = k < w.cavity.size() ? w.cavity[k] : w.fresh[k - w.cavity.size()];
    put_corners(s, h.v);
    tn_[4 * static_cast<std::size_t>(s) + h.i] = h.out;
    tn_[h.out] = 4 * s + h.i;
    for (const ConeFacet& f : kFacet[h.i]) {
      const std::uint32_t half = 4 * s + f.j;
      // the other half of the edge's facet when it came before (then the
      // entry is cleared), else kDead (then this half is entered)
      std::uint32_t other = kDead;
      if (small) {
        const std::uint32_t la = h.loc[f.a], lb = h.loc[f.b];
        const std::uint32_t lo = la < lb ? la : lb, hi = la < lb ? lb : la;
        std::uint32_t& e = et.pending[lo * kMaxLocal + hi];
        other = e;
        e = half | (0u - static_cast<std::uint32_t>(other != kDead));  // kDead on the second half
      } else {
        const std::uint32_t a = h.v[f.a], b = h.v[f.b];
        const std::uint64_t key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
        std::uint64_t slot = (key * 0x9E3779B97F4A7C15ull) >> 40 & mask;
        for (;; slot = (slot + 1) & mask) {
          if (w.hkey[slot] == key) {
            other = w.hval[slot];
            w.hkey[slot] = ~std::uint64_t{1};  // tombstone: an edge is met exactly twice
            break;
          }
          if (w.hkey[slot] == ~std::uint64_t{0}) {
            w.hkey[slot] = key;
            w.hval[slot] = half;
            break;
          }
        }
      }
      // Linking as masks (gcc made a branch of the ?: forms): on the second
      // half tn_[half] := other and tn_[other] := half; on the first
      // tn_[half] := kDead twice (the second half's store links it later)
      const std::uint32_t second = static_cast<std::uint32_t>(other != kDead);
      const std::uint32_t all = 0u - second;  // all ones on the second half
      tn_[half] = other;
      tn_[(other & all) | (half & ~all)] = half | ~all;
      open += 1 - 2 * static_cast<std::ptrdiff_t>(second);
    }
    if (h.v[0] != V_ && h.v[1] != V_ && h.v[2] != V_ && h.v[3] != V_) w.remember(s);
  }
  if (open != 0) throw std::logic_error("rt3 (cpu): the horizon of an insertion is not a closed surface");
  // cavity slots not reused (more visible tetrahedra than horizon ridges)
  for (std::size_t q = m; q < w.cavity.size(); ++q) {
    const std::uint32_t s = w.cavity[q];
    const std::uint32_t dead[4] = {kDead, kDead, kDead, kDead};
    put_corners(s, dead);
    w.free.push_back(s);
  }
  w.st.created_tets += m;
  return true;
}

// Remembering visibility walk from real tetrahedron t toward p: across a
// facet that separates t from p (orient3d with that corner replaced by p
// negative), never back across the facet just crossed, the facets tried from
// a random one (the stochastic walk of Devillers–Pion–Teillaud; on a regular
// triangulation the visibility walk terminates: Edelsbrunner's acyclicity
// theorem, as reference/rtd's locate). Returns the real tetrahedron
// containing p (SoS: strictly) or the first virtual tetrahedron reached —
// one whose hull facet p sees. With a parallel worker w: w has t, and takes
// each next tetrahedron (hold_across) before it reads it; kDead when a cell
// is held by another worker. (w null: read-only, after stage 2.)
std::uint32_t Builder::walk(Worker* w, std::uint32_t p, std::uint32_t t, std::uint64_t& rng,
                            std::uint64_t* steps) {
  std::uint32_t from = 4;  // the corner of t opposite the facet crossed into t
  for (;;) {
    if (steps) ++*steps;
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    const std::uint32_t r = static_cast<std::uint32_t>(rng >> 32) & 3u;
    const std::uint32_t* v = tet(t);
    std::uint32_t next = kDead;
    for (std::uint32_t q = 0; q < 4; ++q) {
      const std::uint32_t i = (r + q) & 3u;
      if (i == from) continue;
      std::uint32_t u[4] = {v[0], v[1], v[2], v[3]};
      u[i] = p;
      if (orient(u[0], u[1], u[2], u[3]) < 0) {
        next = tn_[4 * static_cast<std::size_t>(t) + i];
        break;
      }
    }
    if (next == kDead) return t;
    const std::uint32_t u = next >> 2;
    if (w && !hold_across(*w, next)) return kDead;
    t = u;
    from = next & 3u;
    if (is_virtual(t)) return t;
  }
}

// A live real tetrahedron for a parallel worker to start a walk from, which
// it then has: the worker's last one, else a recent one, whatever the slot
// holds now (another tetrahedron when it was freed and reused since; a
// walk from anywhere ends): its corners are read atomically, their cells
// taken, and the slot is the worker's when a second read gives the same
// corners — a writer holds the cells of the corners it writes, so a torn
// first read cannot be confirmed (claims, above); a virtual tetrahedron
// leads across its hull facet to its real neighbour. kDead when none is
// (the worker is lost: run defers the rest of its piece).
std::uint32_t Builder::walk_start(Worker& w) {
  for (unsigned q = 0; q < 8; ++q) {
    const std::uint32_t t = w.recent[(w.nrecent + 7 - q) & 7u];  // the last remembered first
    if (t == kDead) continue;
    std::uint32_t c[4];
    bool ok = true;
    for (std::size_t j = 0; j < 4; ++j) ok = ok && (c[j] = corner_atomic(t, j)) <= V_;  // kDead: free
    for (std::size_t j = 0; j < 4 && ok; ++j) {
      if (c[j] == V_) continue;
      // worth waiting for briefly (a neighbouring insertion ending)
      ok = false;
      for (int spin = 0; spin < 64 && !(ok = hold_cell(w, P_[c[j]].cell)); ++spin) std::this_thread::yield();
    }
    for (std::size_t j = 0; j < 4 && ok; ++j) ok = corner_atomic(t, j) == c[j];
    ok = ok && (c[0] == V_) + (c[1] == V_) + (c[2] == V_) + (c[3] == V_) <= 1;  // (always, by the above)
    if (!ok) {
      release_all(w);
      continue;
    }
    int iv = 0;
    while (iv < 4 && c[iv] != V_) ++iv;
    if (iv == 4) return t;
    const std::uint32_t l = tn_[4 * static_cast<std::size_t>(t) + static_cast<std::size_t>(iv)];
    if (hold_across(w, l)) return l >> 2;  // real: across the hull facet
    release_all(w);
  }
  return kDead;
}

std::uint32_t Builder::any_real() const {
  const std::size_t n = slots_.load(std::memory_order_relaxed);
  for (std::size_t t = 0; t < n; ++t)
    if (live(static_cast<std::uint32_t>(t)) && !is_virtual(static_cast<std::uint32_t>(t)))
      return static_cast<std::uint32_t>(t);
  throw std::logic_error("rt3 (cpu): no real tetrahedron");
}

Outcome Builder::insert(Worker& w, std::uint32_t p) {
  const bool par = w.me != 0;
  std::uint32_t from = w.last;
  if (par) {
    from = walk_start(w);
    if (from == kDead) return Outcome::lost;
  }
  const std::uint32_t root = walk(&w, p, from, w.rng, &w.st.walk_steps);
  auto give_up = [&] {
    release_all(w);
    return Outcome::deferred;
  };
  if (root == kDead) return give_up();
  if (!visible(root, p)) {  // real (a virtual end is visible): p̂ inside Q
    ++w.st.discarded;
    hint_[p] = root;
    w.remember(root);
    release_all(w);
    return Outcome::done;
  }
  // breadth-first search of the visible tetrahedra (stamps of this attempt,
  // unique over all attempts and workers: in visible, out not)
  // (taken by the worker in blocks of 2^16 from the shared counter). A
  // mark is read before the worker has the tetrahedron (atomically: its
  // holder may be writing it): this attempt's stamps are written by this
  // worker only, so a tetrahedron carrying one was had — and is still held —
  // by it, and only an unmarked neighbour needs taking and testing.
  if (w.stamp == w.stamp_end) {
    w.stamp = stamps_.fetch_add(std::uint32_t{1} << 16, std::memory_order_relaxed);
    w.stamp_end = w.stamp + (std::uint32_t{1} << 16);
  }
  const std::uint32_t in = w.stamp, out = in + 1;
  w.stamp += 2;
  w.cavity.clear();
  w.horizon.clear();
  w.cavity.push_back(root);
  set_mark(root, in);
  for (std::size_t q = 0; q < w.cavity.size(); ++q) {
    const std::uint32_t t = w.cavity[q];
    // t's four neighbours: their marks and corners requested together, so
    // that the misses overlap instead of coming one after the other (perf:
    // the loads of a neighbour's mark and corner were the loop's hottest)
    std::uint32_t links[4];
    for (std::uint32_t i = 0; i < 4; ++i) {
      links[i] = tn_[4 * static_cast<std::size_t>(t) + i];
      __builtin_prefetch(&mark_[links[i] >> 2]);
      __builtin_prefetch(&tv_[links[i] & ~3u]);
    }
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t l = links[i];
      const std::uint32_t u = l >> 2;
      const std::uint32_t mu = mark(u);
      if (mu == in) continue;
      if (mu != out) {
        if (par && !hold_across(w, l)) return give_up();
        if (visible(u, p)) {
          set_mark(u, in);
          w.cavity.push_back(u);
          __builtin_prefetch(&tn_[4 * static_cast<std::size_t>(u)]);
          continue;
        }
        set_mark(u, out);
      }
      // built in place: a Horizon assembled on the stack and copied was
      // read back as 16 bytes over a 4-byte store (h.v[i] = p) — a
      // store-forwarding stall that took 9 % of the insertion's time
      Horizon& h = w.horizon.emplace_back();
      const std::uint32_t* v = tet(t);
      for (std::uint32_t j = 0; j < 4; ++j) h.v[j] = j == i ? p : v[j];
      h.i = i;
      h.out = l;
    }
  }
  if (!link_cone(w)) return give_up();
  hint_[p] = w.last;  // a real new tetrahedron (every cone has one: over the hull facet or real ones)
  if (is_virtual(root)) ++w.st.placed;
  ++w.st.inserted;
  w.st.cavity_tets += w.cavity.size();
  release_all(w);
  return Outcome::done;
}

void Builder::run(bool parallel, std::size_t parallel_from, std::size_t min_piece, std::size_t fail_every,
                  const std::vector<std::size_t>& rounds_at, Rt3Stats& st) {
  start();
  const std::size_t n = V_;
  std::size_t k = 4;
  // Exact copies wait for the copy of larger index that follows them
  // (brio.hpp, waits_for_next) until every other point is in; then they are
  // inserted in a parallel round of their own (sequential run: one by one).
  std::vector<std::uint8_t> wait(n, 0);
  par_for(n > 5 ? n - 5 : 0, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t j = lo + 4; j < hi + 4; ++j) {
      const Rt3Point &a = P_[j], &b = P_[j + 1];
      wait[j] = brio::waits_for_next(a.xyz, a.w, a.id, b.xyz, b.w, b.id, 3);
    }
  });
  auto sequential_to = [&](std::size_t end) {
    for (; k < end; ++k)
      if (!wait[k]) insert(seq_, static_cast<std::uint32_t>(k));
  };
  auto merge = [&](const Rt3Stats& a) {
    st.inserted += a.inserted, st.placed += a.placed, st.discarded += a.discarded;
    st.cavity_tets += a.cavity_tets, st.created_tets += a.created_tets, st.walk_steps += a.walk_steps;
  };
  // Room for the points up to position `end` before they are inserted: the
  // slots used per point so far (7 for the first points; about 6.7 on
  // uniform input, fewer where points are redundant), 10 % more, and the
  // blocks of 256 the pieces of a parallel round take. Growing at round
  // boundaries only (BRIO rounds grow geometrically) keeps the peak near the
  // final size — one reservation for all the points cost uniform input 8
  // slots per point and a weighted input with 72 % redundant points four
  // times what it used — and a parallel worker that finds no room defers
  // its points (the sequential insertion grows the arrays by a quarter).
  auto reserve_for = [&](std::size_t end, std::size_t pieces) {
    const std::size_t used = slots_.load();
    const double rate = k >= 4096 ? static_cast<double>(used) / static_cast<double>(k) : 7.0;
    const std::size_t need = used + static_cast<std::size_t>(1.1 * rate * static_cast<double>(end - k)) +
                             512 * pieces + 1024;
    if (need > cap_) {
      if (need > kMaxSlots) throw std::length_error("rt3 (cpu): more than 2^30 tetrahedra (32-bit neighbour links)");
      grow(need);
    }
  };
  if (!parallel) {
    for (std::size_t r = 0; r + 1 < rounds_at.size(); ++r)
      if (rounds_at[r + 1] > k) {
        reserve_for(rounds_at[r + 1], 0);
        sequential_to(rounds_at[r + 1]);
      }
    sequential_to(n);
  } else {
    reserve_for(std::min(n, std::max<std::size_t>(parallel_from, 4)), 0);
    sequential_to(std::min(n, std::max<std::size_t>(parallel_from, 4)));
    const std::size_t threads = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    if (rounds_at.empty()) throw std::logic_error("rt3 (cpu): no BRIO rounds");
    // A parallel round over the `count` positions pos(0..count-1) (in curve
    // order), `pieces` of them; known: the positions below which hold the
    // hints of the points handled so far.
    auto parallel_round = [&](std::size_t count, std::size_t pieces, std::size_t known, const auto& pos) {
      const std::uint32_t anchor = live(seq_.last) && !is_virtual(seq_.last) ? seq_.last : any_real();
      // each piece starts near its first point: at the tetrahedron noted for
      // the last point inserted so far in the nearest lock cell along the
      // curve (hint_) — one shared start would make the pieces wait for the
      // first one there
      std::vector<std::uint32_t> cellpos(lock_count_, kDead);
      for (std::size_t j = 0; j < known; ++j)
        if (hint_[j] != kDead) cellpos[P_[j].cell] = static_cast<std::uint32_t>(j);
      std::vector<Worker> ws(pieces);
      for (std::size_t q = 0; q < pieces; ++q) {
        ws[q].me = static_cast<std::uint32_t>(q + 1);
        ws[q].rng = brio::splitmix64(pos(0) + q) | 1;
        ws[q].fail_every = fail_every;
        ws[q].remember(anchor);
        const std::size_t c = P_[pos(count * q / pieces)].cell;
        for (std::size_t d = 0; d < lock_count_; ++d) {
          const std::uint32_t j = c >= d && cellpos[c - d] != kDead ? cellpos[c - d]
                                  : c + d < lock_count_         ? cellpos[c + d]
                                                                : kDead;
          if (j == kDead) continue;
          if (live(hint_[j])) ws[q].remember(hint_[j]);
          break;
        }
        // the free slots so far, shared out
        const std::size_t f = seq_.free.size();
        ws[q].free.assign(seq_.free.begin() + static_cast<std::ptrdiff_t>(f * q / pieces),
                          seq_.free.begin() + static_cast<std::ptrdiff_t>(f * (q + 1) / pieces));
      }
      seq_.free.clear();
      par_for(pieces, 1, [&](std::size_t a, std::size_t b) {
        for (std::size_t q = a; q < b; ++q) {
          Worker& w = ws[q];
          const std::size_t from = count * q / pieces, to = count * (q + 1) / pieces;
          int lost = 0;  // consecutive insertions that found no start
          for (std::size_t i = from; i < to; ++i) {
            const std::uint32_t p = static_cast<std::uint32_t>(pos(i));
            if (wait[p]) continue;
            const Outcome o = insert(w, p);
            if (o != Outcome::done) w.deferred.push_back(p);
            lost = o == Outcome::lost ? lost + 1 : 0;
            if (lost == 8) {  // no start for a while: the rest of the piece after the round
              for (++i; i < to; ++i)
                if (!wait[pos(i)]) w.deferred.push_back(static_cast<std::uint32_t>(pos(i)));
              break;
            }
          }
        }
      });
      // the deferred points, in position order of the pieces, one by one
      if (slots_.load() > cap_) slots_.store(cap_);  // a failed block grab overshoots
      for (Worker& w : ws) {
        merge(w.st);
        st.deferred += w.deferred.size();
        seq_.free.insert(seq_.free.end(), w.free.begin(), w.free.end());
        // a worker's unused block of never-used slots stays unused (dead)
      }
      seq_.last = kDead;
      for (Worker& w : ws)
        if (live(w.last) && !is_virtual(w.last)) seq_.last = w.last;
      if (seq_.last == kDead) seq_.last = any_real();
      for (Worker& w : ws)
        for (std::uint32_t p : w.deferred) insert(seq_, p);
      ++st.parallel_rounds;
    };
    for (std::size_t r = 0; r + 1 < rounds_at.size(); ++r) {
      const std::size_t lo = std::max(k, rounds_at[r]), hi = rounds_at[r + 1];
      if (hi <= lo) continue;
      const std::size_t pieces = std::min(8 * threads, (hi - lo) / std::max<std::size_t>(min_piece, 1));
      if (pieces < 2) {
        reserve_for(hi, 0);
        sequential_to(hi);
        continue;
      }
      reserve_for(hi, pieces);
      parallel_round(hi - lo, pieces, lo, [lo](std::size_t i) { return lo + i; });
      k = hi;
    }
    sequential_to(n);
    // the copies that waited: located (nearly all found redundant) in a
    // parallel round of their own
    std::vector<std::uint32_t> waited;
    for (std::size_t p = 4; p < n; ++p)
      if (wait[p]) waited.push_back(static_cast<std::uint32_t>(p)), wait[p] = 0;
    const std::size_t pieces = std::min(8 * threads, waited.size() / std::max<std::size_t>(min_piece, 1));
    if (pieces >= 2) {
      reserve_for(n, pieces);
      parallel_round(waited.size(), pieces, n, [&waited](std::size_t i) { return std::size_t{waited[i]}; });
      waited.clear();
    }
    for (std::uint32_t p : waited) insert(seq_, p);
  }
  for (std::size_t p = 4; p < n; ++p)  // the copies that waited (sequential run), along the curve
    if (wait[p]) insert(seq_, static_cast<std::uint32_t>(p));
  merge(seq_.st);
  st.slots = slots_.load();
}

// ---- stage 3: output ----------------------------------------------------------------

// The sort is a two-pass MSD radix sort on the smallest index, then a sort
// of the few tetrahedra sharing it: (1) every piece of slots counts its live
// real tetrahedra per coarse bucket (the top bits of the smallest index, at
// most 1024 buckets); (2) each piece writes its tetrahedra to its own
// stretch of each bucket (offsets from the counts, bucket-major, so nothing
// is shared and the writes go to at most 1024 sequential streams per piece);
// (3) each bucket, which fits in cache, is counting-sorted on the rest of
// the smallest index and each run sorted. The result is the unique sorted
// list whatever the thread count.
std::vector<Tet> Builder::output() const {
  const std::size_t slots = slots_.load();
  const std::size_t n = V_;
  int shift = 0;
  while ((n >> shift) > 1024) ++shift;
  const std::size_t B = ((n - 1) >> shift) + 1;
  const std::size_t pieces = (slots + kChunk - 1) / kChunk;
  std::vector<std::uint32_t> at(pieces * B, 0);  // counts, then write cursors
  // the canonical tuple of slot t, or none (computed twice rather than
  // stored: 16 bytes per slot less at the peak)
  auto canonical = [&](std::size_t t, Tet& out) {
    if (t + 8 < slots) {  // the corners' points of the slot 8 ahead, requested now (scattered loads)
      const std::uint32_t* a = tet(static_cast<std::uint32_t>(t + 8));
      for (int j = 0; j < 4; ++j)
        if (a[j] < V_) __builtin_prefetch(&P_[a[j]]);
    }
    const std::uint32_t* v = tet(static_cast<std::uint32_t>(t));
    if (v[0] == kDead || v[0] == V_ || v[1] == V_ || v[2] == V_ || v[3] == V_) return false;
    out = canonical_tet(P_[v[0]].id, P_[v[1]].id, P_[v[2]].id, P_[v[3]].id);
    return true;
  };
  par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
    Tet c4;
    for (std::size_t c = lo; c < hi; ++c)
      for (std::size_t t = c * kChunk; t < std::min(slots, (c + 1) * kChunk); ++t)
        if (canonical(t, c4)) ++at[c * B + (c4[0] >> shift)];
  });
  // (positions below the slot count, < 2^30: 32 bits hold them)
  const std::vector<std::size_t> bucket = bucket_major_positions(at, pieces, B);
  std::vector<Tet> out(bucket[B]);
  par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
    Tet c4;
    for (std::size_t c = lo; c < hi; ++c)
      for (std::size_t t = c * kChunk; t < std::min(slots, (c + 1) * kChunk); ++t)
        if (canonical(t, c4)) {
          const std::size_t b = c4[0] >> shift;
          out[at[c * B + b]++] = c4;
        }
  });
  par_for(B, 1, [&](std::size_t lo, std::size_t hi) {
    std::vector<std::size_t> cnt;
    std::vector<Tet> tmp;
    for (std::size_t b = lo; b < hi; ++b) {
      const std::size_t first = bucket[b], m = bucket[b + 1] - first;
      cnt.assign((std::size_t{1} << shift) + 1, 0);
      const Index base = static_cast<Index>(b << shift);
      for (std::size_t q = 0; q < m; ++q) ++cnt[out[first + q][0] - base + 1];
      for (std::size_t i = 1; i < cnt.size(); ++i) cnt[i] += cnt[i - 1];
      tmp.resize(m);
      for (std::size_t q = 0; q < m; ++q) tmp[cnt[out[first + q][0] - base]++] = out[first + q];
      // runs of one smallest index (about six tetrahedra): insertion sort,
      // the rest of the tuple compared as one 64-bit and one 32-bit key; a
      // long run (a vertex that is the smallest index of a fan of flat
      // tetrahedra over coplanar points: 128885 of them in planes3 at 10^6)
      // by std::sort, not in quadratic time
      auto before = [](const Tet& a, const Tet& b) {  // a < b when a[0] == b[0]
        const std::uint64_t ka = std::uint64_t{a[1]} << 32 | a[2], kb = std::uint64_t{b[1]} << 32 | b[2];
        return ka < kb || (ka == kb && a[3] < b[3]);
      };
      for (std::size_t run = 0; run < m;) {
        std::size_t end = run + 1;
        while (end < m && tmp[end][0] == tmp[run][0]) ++end;
        if (end - run > 32) {
          std::sort(tmp.begin() + static_cast<std::ptrdiff_t>(run), tmp.begin() + static_cast<std::ptrdiff_t>(end),
                    before);
        } else {
          for (std::size_t q = run + 1; q < end; ++q) {
            const Tet x = tmp[q];
            std::size_t r = q;
            while (r > run && before(x, tmp[r - 1])) tmp[r] = tmp[r - 1], --r;
            tmp[r] = x;
          }
        }
        run = end;
      }
      std::copy(tmp.begin(), tmp.end(), out.begin() + static_cast<std::ptrdiff_t>(first));
    }
  });
  return out;
}

// at_vertex (out): per position, a real slot with it as a corner (kDead for
// a point that is not a vertex).
std::vector<Index> Builder::redundant(std::vector<std::uint32_t>* at_vertex) const {
  const std::size_t n = V_, slots = slots_.load();
  std::unique_ptr<std::atomic<std::uint32_t>[]> at(new std::atomic<std::uint32_t>[n]);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) at[i].store(kDead, std::memory_order_relaxed);
  });
  par_for(slots, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t t = a; t < b; ++t) {
      const std::uint32_t* v = tet(static_cast<std::uint32_t>(t));
      if (v[0] == kDead || v[0] == V_ || v[1] == V_ || v[2] == V_ || v[3] == V_) continue;
      // any real slot will do (the witness's slots already depend on the
      // parallel insertion's timing): one relaxed store, no read
      for (int j = 0; j < 4; ++j) at[v[j]].store(static_cast<std::uint32_t>(t), std::memory_order_relaxed);
    }
  });
  std::vector<Index> red = par_select(n, [&](Index k) { return at[k].load(std::memory_order_relaxed) == kDead; });
  for (Index& k : red) k = P_[k].id;
  std::sort(red.begin(), red.end());
  if (at_vertex) {
    at_vertex->assign(n, kDead);
    par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
      for (std::size_t i = a; i < b; ++i) (*at_vertex)[i] = at[i].load(std::memory_order_relaxed);
    });
  }
  return red;
}

// ---- stage 4: witness -----------------------------------------------------------------
// For each position that is not a vertex, the real tetrahedron containing it:
// a walk from the tetrahedron it was found redundant in when that slot still
// holds a real tetrahedron, else from the previous position's answer in its
// piece (the BRIO order is spatially coherent), else from a vertex's
// tetrahedron. Each piece of kChunk positions is one task; the walk is
// read-only, its random choices seeded by the piece, so the witness does not
// depend on the thread count.
void Builder::witness(Rt3Witness& w, std::vector<std::uint32_t> at) {
  const std::size_t n = V_;
  const std::uint32_t anchor = any_real();
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    std::uint64_t rng = brio::splitmix64(a) | 1;
    std::uint32_t prev = kDead;
    for (std::size_t k = a; k < b; ++k) {
      if (at[k] != kDead) {
        prev = at[k];
        continue;
      }
      std::uint32_t s = hint_[k];
      if (s == kDead || tv_[4 * static_cast<std::size_t>(s)] == kDead || is_virtual(s)) s = prev;
      if (s == kDead) s = anchor;
      const std::uint32_t t = walk(nullptr, static_cast<std::uint32_t>(k), s, rng, nullptr);
      // a point that is not a vertex lies inside the hull, so the walk ends
      // in a real tetrahedron; the certifier checks it either way
      at[k] = t;
      prev = is_virtual(t) ? prev : t;
    }
  });
  w.pts = std::move(P_);
  tv_.resize(4 * slots_.load());
  tn_.resize(4 * slots_.load());
  w.tv = std::move(tv_);
  w.tn = std::move(tn_);
  w.at = std::move(at);
}

}  // namespace

std::vector<std::int64_t> rt3_neighbors(const Rt3Witness& w, const std::vector<Tet>& tets, int threads) {
  const std::size_t n = w.pts.size(), slots = w.tv.size() / 4, m = tets.size();
  constexpr std::uint32_t kNo = Rt3Witness::kNoSlot;
  std::vector<std::int64_t> nb(4 * m, -1);
  std::atomic<bool> inconsistent{false};
  with_threads(threads, [&] {
    const OutputIndex<Tet> index(n, tets);
    auto real = [&](std::size_t t) {
      const std::uint32_t* c = &w.tv[4 * t];
      return c[0] != kNo && c[0] != n && c[1] != n && c[2] != n && c[3] != n;
    };
    // per real slot, its tetrahedron's index in tets (each index taken once:
    // two slots with one tetrahedron are refused)
    std::vector<std::uint32_t> at(slots, kNo);
    std::unique_ptr<std::atomic<std::uint8_t>[]> taken(new std::atomic<std::uint8_t>[m]);
    par_for(m, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) taken[k].store(0, std::memory_order_relaxed);
    });
    std::atomic<std::size_t> found{0};
    par_for(slots, kChunk, [&](std::size_t lo, std::size_t hi) {
      std::size_t here = 0;
      for (std::size_t t = lo; t < hi; ++t) {
        if (!real(t)) continue;
        const std::uint32_t* c = &w.tv[4 * t];
        const std::size_t k = index.find(canonical_tet(w.pts[c[0]].id, w.pts[c[1]].id, w.pts[c[2]].id, w.pts[c[3]].id));
        if (k == m || taken[k].exchange(1, std::memory_order_relaxed) != 0) {
          inconsistent.store(true, std::memory_order_relaxed);
          continue;
        }
        at[t] = static_cast<std::uint32_t>(k);
        ++here;
      }
      found += here;
    });
    if (found.load() != m) inconsistent.store(true);
    if (inconsistent.load()) return;
    // the link across corner i of slot t is the neighbour opposite the
    // vertex of tets[at[t]] that is corner i's point
    par_for(slots, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t t = lo; t < hi; ++t) {
        if (at[t] == kNo) continue;
        const std::size_t k = at[t];
        const Tet& x = tets[k];
        for (std::size_t i = 0; i < 4; ++i) {
          const Index id = w.pts[w.tv[4 * t + i]].id;
          std::size_t j = 0;
          while (j < 4 && x[j] != id) ++j;
          const std::uint32_t l = w.tn[4 * t + i];
          if (j == 4 || l / 4 >= slots) {
            inconsistent.store(true, std::memory_order_relaxed);
            continue;
          }
          const std::uint32_t u = at[l / 4];
          nb[4 * k + j] = u == kNo ? -1 : static_cast<std::int64_t>(u);
        }
      }
    });
  });
  if (inconsistent.load()) throw std::logic_error("rt3_neighbors: the witness and the output disagree");
  return nb;
}

Rt3Result rt3(const PointSet& ps, const Rt3Options& opt, Rt3Stats* stats, Rt3Witness* witness) {
  if (ps.dim != 3) throw std::invalid_argument("rt3 (cpu): the points must be 3D, got dimension " + std::to_string(ps.dim));
  if (ps.weighted && ps.weights.size() != ps.size())
    throw std::invalid_argument("rt3 (cpu): " + std::to_string(ps.weights.size()) + " weights for " +
                                std::to_string(ps.size()) + " points");
  constexpr std::size_t kMaxPoints = std::size_t{1} << brio::kIndexBits;
  if (ps.size() > kMaxPoints)
    throw std::invalid_argument("rt3 (cpu): " + std::to_string(ps.size()) + " points exceed the limit of " +
                                std::to_string(kMaxPoints));
  Rt3Stats st;
  Rt3Result res;
  with_threads(opt.threads, [&] {
    StageClock clock(opt.times);
    // non-finite values, fewer than 4 points, input in a plane: rejected
    // with the reference's exact test (reference/dimension.hpp)
    std::atomic<int> bad{0};  // 1: a coordinate, 2: a weight is not finite
    par_for(ps.size(), kChunk, [&](std::size_t a, std::size_t b) {
      for (std::size_t i = a; i < b; ++i) {
        const double* x = ps.point(i);
        if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))) bad.fetch_or(1);
        if (!std::isfinite(ps.weight(i))) bad.fetch_or(2);
      }
    });
    if (bad.load() & 1) throw std::invalid_argument("rt3 (cpu): a coordinate is not finite");
    if (bad.load() & 2) throw std::invalid_argument("rt3 (cpu): a weight is not finite");
    if (std::string why = dimension_problem(ps); !why.empty()) throw std::invalid_argument("rt3 (cpu): " + why);
    const pred::StaticFilter f = parallel_static_filter(ps, {});
    const bool parallel = opt.insertion == Rt3Options::Insertion::parallel ||
                          (opt.insertion == Rt3Options::Insertion::automatic &&
                           tbb::this_task_arena::max_concurrency() > 1);
    std::vector<std::size_t> rounds_at;
    std::vector<std::uint32_t> keys;
    const std::vector<Index> order = brio_order(ps, opt.brio_min, &rounds_at, parallel ? &keys : nullptr);
    std::vector<Rt3Point> pts(order.size());
    par_for(order.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const Index i = order[k];
        const double* x = ps.point(i);
        pts[k] = {{x[0], x[1], x[2]}, ps.weight(i), i};
      }
    });
    std::size_t ncells = 0;
    std::vector<std::uint32_t> cells;
    if (parallel) cells = lock_cells(keys, order, ncells);
    clock.mark("sort");
    Builder B(std::move(pts), f);
    if (parallel) B.set_cells(cells, ncells);
    B.run(parallel, opt.parallel_from, opt.min_piece, opt.fail_claims_every, rounds_at, st);
    clock.mark("insert");
    res.tets = B.output();
    std::vector<std::uint32_t> at;
    res.redundant = B.redundant(witness ? &at : nullptr);
    clock.mark("output");
    if (witness) {
      B.witness(*witness, std::move(at));
      clock.mark("witness");
    }
  });
  st.removed = st.inserted - (ps.size() - res.redundant.size());
  if (stats) *stats = st;
  return res;
}

}  // namespace flipflop::cpu

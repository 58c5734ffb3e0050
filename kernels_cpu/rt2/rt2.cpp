// rt2.cpp — the multithreaded 2D regular triangulation (see rt2.hpp).
#include "kernels_cpu/rt2/rt2.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "kernels_cpu/brio.hpp"
#include "kernels_cpu/parallel.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/rt2/rt2.hpp"  // require_plane

namespace flipflop::cpu {
namespace {

// A point in insertion order: coordinates (the predicates' coordinate
// pointer), weight, input index (= SoS index).
using Vtx = Rt2Point;

constexpr std::uint32_t kDead = Rt2Witness::kNoSlot;

// half-edge e = 3t + i: the edge of triangle t opposite its corner i, directed
// from corner i+1 to corner i+2 (counter-clockwise)
inline std::uint32_t nx(std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::uint32_t pv(std::uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

// ---- stage 1: BRIO order ---------------------------------------------------------

// Hilbert index of (x, y) on the 2^15 x 2^15 grid (30 bits): one step per
// bit level from the top, a state machine over the curve's four orientations
// (state 0: the base "U" opening down, 1: transposed, 2: reflected, 3:
// transposed and reflected) — the classic rotation rule as two tables.
std::uint32_t hilbert15(std::uint32_t x, std::uint32_t y) {
  // kDigit[state][quadrant] (quadrant = 2·xbit + ybit): the position of that
  // quadrant along the curve; kNext: the orientation of the sub-curve there
  static constexpr std::uint8_t kDigit[4][4] = {{0, 1, 3, 2}, {0, 3, 1, 2}, {2, 3, 1, 0}, {2, 1, 3, 0}};
  static constexpr std::uint8_t kNext[4][4] = {{1, 0, 3, 0}, {0, 2, 1, 1}, {2, 1, 2, 3}, {3, 3, 0, 2}};
  std::uint32_t d = 0, state = 0;
  for (int b = 14; b >= 0; --b) {
    const std::uint32_t q = (((x >> b) & 1u) << 1) | ((y >> b) & 1u);
    d = (d << 2) | kDigit[state][q];
    state = kNext[state][q];
  }
  return d;
}

using brio::grid15;

// The BRIO order (kernels_cpu/brio.hpp) along the Hilbert curve of the
// bounding box. rounds (optional) receives the first position of each round
// and n; box (optional) the bounding box: min x, min y, max x, max y.
std::vector<Index> brio_order(const PointSet& ps, std::size_t brio_min, std::vector<std::size_t>* rounds_at = nullptr,
                              std::array<double, 4>* box = nullptr) {
  const std::array<double, 4> b = brio::bounding_box<2>(ps);
  if (box) *box = b;
  return brio::order(
      ps.size(), brio_min,
      [&](std::size_t i) {
        const double* p = ps.point(i);
        return hilbert15(grid15(p[0], b[0], b[2]), grid15(p[1], b[1], b[3]));
      },
      [&](std::size_t i) { return brio::point_hash(ps.point(i), 2); }, rounds_at);
}

// ---- stage 2: incremental flipping ----------------------------------------------

class Builder {
 public:
  Builder(std::vector<Vtx> pts, const pred::StaticFilter& f, ref::Rt2Stats& st, const std::array<double, 4>& box)
      : P_(std::move(pts)), f_(f), st_(st), V_(static_cast<std::uint32_t>(P_.size())),
        at_(P_.size(), kDead), missing_(P_.size(), 0) {
    box_ = box;
    tv_.reserve(6 * P_.size() + 12);
    tn_.reserve(6 * P_.size() + 12);
  }

  // positions [0, parallel_from) inserted one by one, the rest of each BRIO
  // round (rounds_at: brio_order's round starts) in parallel batches
  void run(std::size_t parallel_from, bool territories, const std::vector<std::size_t>& rounds_at);
  void defer_copies();
  // the real triangles, as input indices in canonical form, sorted
  std::vector<Triangle> output() const;
  // stage 4: completes at_ and hands the triangulation over (the builder is
  // spent afterwards)
  void witness(Rt2Witness& w);

 private:
  std::vector<Vtx> P_;
  const pred::StaticFilter& f_;
  ref::Rt2Stats& st_;
  const std::uint32_t V_;  // the virtual vertex (thesis §2.1): vertex n
  std::vector<std::uint32_t> tv_, tn_;  // per half-edge: the corner's vertex, the twin half-edge
  std::vector<std::uint32_t> free_;     // dead triangle slots
  std::vector<std::uint32_t> stack_, pending_;
  std::uint32_t home_ = 0;  // a live real triangle at the last inserted point: where the walk starts
  std::uint32_t rng_ = 0x2545F491u;
  // per position: while inserting, for a point found redundant or removed by
  // a 3-1 flip (missing_ set) the slot it was in then — a hint where to look
  // for it at the end; after witness(), Rt2Witness::at
  std::vector<std::uint32_t> at_;
  std::vector<std::uint8_t> missing_;

  pred::Pt pt(std::uint32_t v) const { return {P_[v].id, P_[v].xy}; }
  pred::WPt wpt(std::uint32_t v) const { return {P_[v].id, P_[v].xy, P_[v].w}; }
  // The predicates: the per-call semi-static filter inline (the points of a
  // walk step or a flip are neighbours, much closer to each other than the
  // input's extent, so the per-input static bound rarely decides here — at
  // 10^7 uniform points it decided almost no power test), then the staged
  // exact path with SoS (predicates.hpp).
  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const double* p[3] = {P_[a].xy, P_[b].xy, P_[c].xy};
    if (const int s = pred::semi_static_sign<3>(p, nullptr)) return s;
    return pred::orient2d(f_, pt(a), pt(b), pt(c));
  }
  // > 0 iff d^+ lies strictly below the lifted plane of the counter-clockwise
  // (a, b, c) under SoS: d is inside the power circle (never 0)
  int power(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
    const double* p[4] = {P_[a].xy, P_[b].xy, P_[c].xy, P_[d].xy};
    const double w[4] = {P_[a].w, P_[b].w, P_[c].w, P_[d].w};
    if (const int s = pred::semi_static_sign<4>(p, w)) return s;
    return pred::power2d(f_, wpt(a), wpt(b), wpt(c), wpt(d));
  }
  bool is_virtual(std::uint32_t t) const { return tv_[3 * t] == V_ || tv_[3 * t + 1] == V_ || tv_[3 * t + 2] == V_; }
  bool is_real(std::uint32_t t) const { return tv_[3 * t] != kDead && !is_virtual(t); }

  std::uint32_t alloc() {
    if (!free_.empty()) {
      const std::uint32_t t = free_.back();
      free_.pop_back();
      return t;
    }
    if (tv_.size() == tv_.capacity()) {  // grow by half (one call per growth, not per triangle)
      tv_.reserve(tv_.size() + tv_.size() / 2 + 12);
      tn_.reserve(tv_.capacity());
    }
    tv_.insert(tv_.end(), 3, 0u);
    tn_.insert(tn_.end(), 3, 0u);
    return static_cast<std::uint32_t>(tv_.size() / 3 - 1);
  }
  void release(std::uint32_t t) {
    tv_[3 * t] = tv_[3 * t + 1] = tv_[3 * t + 2] = kDead;
    free_.push_back(t);
  }
  void set(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    tv_[3 * t] = a, tv_[3 * t + 1] = b, tv_[3 * t + 2] = c;
  }
  void link(std::uint32_t e, std::uint32_t f) { tn_[e] = f, tn_[f] = e; }
  // the half-edge of triangle w opposite its vertex x (x is a corner of w)
  std::uint32_t corner(std::uint32_t w, std::uint32_t x) const {
    return tv_[3 * w] == x ? 3 * w : tv_[3 * w + 1] == x ? 3 * w + 1 : 3 * w + 2;
  }

  void initial(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  std::array<std::uint32_t, 3> flip13(std::uint32_t t, std::uint32_t p);
  void flip22(std::uint32_t e);
  void flip31(std::uint32_t e, bool remove_a);
  template <class Leaves>
  std::uint32_t walk_to(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside, Leaves leaves) const;
  std::uint32_t locate(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside) const;
  std::uint32_t walk(std::uint32_t p, bool& inside) { return locate(p, home_, rng_, inside); }
  void insert_outside(std::uint32_t p, std::uint32_t e0);
  void regularize(std::uint32_t p);
  void insert_one(std::uint32_t p);

  // ---- stage 2b: parallel batches (see run_parallel) ----
  struct Cand {                // a batch point that lies in a real triangle and is not redundant there
    std::uint32_t p, key;      // position, priority
    std::uint32_t cav, bnd;    // offsets of its cavity / boundary in its piece's lists
    std::uint32_t k, m;        // cavity triangles, boundary edges
    std::uint32_t xo, ro;      // winner: offsets of its extra / released slots; kDead: lost
  };
  struct Piece {  // a run of consecutive batch points, handled by one task
    std::vector<Cand> cand;
    std::vector<std::uint32_t> cav;                 // cavity slots
    std::vector<std::array<std::uint32_t, 3>> bnd;  // boundary edges (a, b, twin half-edge outside)
    std::vector<std::uint32_t> outside;             // positions outside the hull (territories: deferred)
    std::vector<std::uint32_t> scratch, freed;
    std::unordered_set<std::uint32_t> big;          // find_cavity: a large cavity's slots
    std::vector<std::pair<std::uint32_t, std::uint32_t>> located;  // batch: (point, its triangle)
    std::size_t discarded = 0, removed = 0, absorbed = 0, inserted = 0;
  };
  // per slot: the smallest key with it in its cavity ([2t]) and in its ring
  // ([2t + 1]), side by side (one cache line for both labels)
  std::vector<std::uint32_t> resv_;
  std::size_t parallel_from_ = 1;
  bool territories_ = false;  // Rt2Options::Insertion::territories, else batches
  std::vector<Piece> pieces_;
  void run_parallel(std::size_t from, const std::vector<std::size_t>& rounds_at);
  void batch(const std::vector<std::uint32_t>& pts, std::vector<std::uint32_t>& losers);
  bool find_cavity(std::uint32_t q, std::uint32_t t0, Piece& pc, std::uint32_t terr = kDead);
  // territories (stage 2b, first pass): per slot the piece of the round
  // that owns it (kDead: none)
  std::array<double, 4> box_{};
  std::vector<std::uint32_t> terr_;
  std::uint32_t curve_key(double x, double y) const {
    return hilbert15(grid15(x, box_[0], box_[2]), grid15(y, box_[1], box_[3]));
  }
  std::uint32_t locate_in(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, std::uint32_t terr,
                          bool& inside) const;
  void territories(std::vector<std::uint32_t>& pending);
  bool wins(const Piece& pc, const Cand& c) const;
  void commit(Piece& pc, const Cand& c, const std::uint32_t* extra, std::uint32_t* released);
};

// The extended triangulation of the counter-clockwise (a, b, c) (§2.1): the
// real triangle and, for each edge x -> y, the virtual triangle (y, x, v).
void Builder::initial(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  for (int k = 0; k < 4; ++k) alloc();
  set(0, a, b, c);   // half-edges 0: b->c, 1: c->a, 2: a->b
  set(1, b, a, V_);  // 3: a->v, 4: v->b, 5: b->a
  set(2, c, b, V_);  // 6: b->v, 7: v->c, 8: c->b
  set(3, a, c, V_);  // 9: c->v, 10: v->a, 11: a->c
  link(2, 5), link(0, 8), link(1, 11);
  link(3, 10), link(4, 6), link(7, 9);
  home_ = 0;
}

// 1-3 flip (§2.3): t = (A, B, C) becomes (p, A, B), (p, B, C), (p, C, A); the
// half-edges opposite p are returned.
std::array<std::uint32_t, 3> Builder::flip13(std::uint32_t t, std::uint32_t p) {
  const std::uint32_t A = tv_[3 * t], B = tv_[3 * t + 1], C = tv_[3 * t + 2];
  const std::uint32_t tAB = tn_[3 * t + 2], tBC = tn_[3 * t], tCA = tn_[3 * t + 1];
  const std::uint32_t s1 = alloc(), s2 = alloc();
  set(t, p, A, B);
  set(s1, p, B, C);
  set(s2, p, C, A);
  link(3 * t, tAB), link(3 * s1, tBC), link(3 * s2, tCA);
  link(3 * t + 1, 3 * s1 + 2);   // B -> p | p -> B
  link(3 * t + 2, 3 * s2 + 1);   // p -> A | A -> p
  link(3 * s1 + 1, 3 * s2 + 2);  // C -> p | p -> C
  ++st_.flips_1_3;
  return {3 * t, 3 * s1, 3 * s2};
}

// 2-2 flip (§2.3) of the edge a -> b opposite p in t = (p, a, b), whose twin
// triangle is u = (b, a, d): t becomes (p, a, d), u becomes (p, d, b).
void Builder::flip22(std::uint32_t e) {
  const std::uint32_t t = e / 3, f = tn_[e], u = f / 3;
  const std::uint32_t p = tv_[e], a = tv_[nx(e)], b = tv_[pv(e)], d = tv_[f];
  const std::uint32_t tw_bp = tn_[nx(e)], tw_pa = tn_[pv(e)], tw_ad = tn_[nx(f)], tw_db = tn_[pv(f)];
  set(t, p, a, d);
  set(u, p, d, b);
  link(3 * t, tw_ad), link(3 * t + 2, tw_pa);
  link(3 * u, tw_db), link(3 * u + 1, tw_bp);
  link(3 * t + 1, 3 * u + 2);  // d -> p | p -> d
  ++st_.flips_2_2;
}

// 3-1 flip (§2.3) removing the degree-3 vertex a (remove_a) or b of the edge
// a -> b opposite p in t = (p, a, b), twin u = (b, a, d): the three triangles
// around it become (p, d, b), resp. (p, a, d), in slot t.
void Builder::flip31(std::uint32_t e, bool remove_a) {
  const std::uint32_t t = e / 3, f = tn_[e], u = f / 3;
  const std::uint32_t p = tv_[e], a = tv_[nx(e)], b = tv_[pv(e)], d = tv_[f];
  if (remove_a) {
    // w = (a, p, d): across p -> a from t
    const std::uint32_t w = tn_[pv(e)] / 3;
    const std::uint32_t tw_pd = tn_[corner(w, a)], tw_db = tn_[pv(f)], tw_bp = tn_[nx(e)];
    set(t, p, d, b);
    link(3 * t, tw_db), link(3 * t + 1, tw_bp), link(3 * t + 2, tw_pd);
    release(u), release(w);
    at_[a] = t, missing_[a] = 1;  // a lies in (p, d, b)
  } else {
    // w = (b, d, p): across b -> p from t
    const std::uint32_t w = tn_[nx(e)] / 3;
    const std::uint32_t tw_dp = tn_[corner(w, b)], tw_ad = tn_[nx(f)], tw_pa = tn_[pv(e)];
    set(t, p, a, d);
    link(3 * t, tw_ad), link(3 * t + 1, tw_dp), link(3 * t + 2, tw_pa);
    release(u), release(w);
    at_[b] = t, missing_[b] = 1;  // b lies in (p, a, d)
  }
  ++st_.flips_3_1;
}

// Remembering visibility walk from the real triangle `start` to the point p
// (never a vertex), rng its random state:
// returns 3t with inside = true when p lies in the real triangle t, or, with
// inside = false, the first half-edge e it would cross into a triangle that
// `leaves` (locate: a virtual one, so e is a hull edge p sees). Under SoS no
// point is on a line, so every step is decided; the walk is acyclic in a
// regular triangulation (Edelsbrunner 1990: the in-front relation of its
// cells is acyclic) and the random first edge keeps it short on adversarial
// layouts. The step bound only guards against a corrupted structure.
template <class Leaves>
std::uint32_t Builder::walk_to(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside,
                               Leaves leaves) const {
  std::uint32_t t = start, came = kDead;
  const std::size_t cap = tv_.size() + 16;
  for (std::size_t steps = 0; steps < cap; ++steps) {
    rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
    const std::uint32_t r = rng % 3;
    bool moved = false;
    for (std::uint32_t j = 0; j < 3; ++j) {
      const std::uint32_t e = 3 * t + (r + j) % 3;
      if (e == came) continue;  // p is on t's side of the edge it came through
      if (orient(tv_[nx(e)], tv_[pv(e)], p) < 0) {
        const std::uint32_t f = tn_[e];
        if (leaves(f / 3)) {
          inside = false;
          return e;
        }
        t = f / 3, came = f, moved = true;
        break;
      }
    }
    if (!moved) {
      inside = true;
      return 3 * t;
    }
  }
  throw std::logic_error("rt2 (cpu): the point location walk did not end (corrupted triangulation)");
}

std::uint32_t Builder::locate(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside) const {
  return walk_to(p, start, rng, inside, [this](std::uint32_t t) { return is_virtual(t); });
}

// p lies beyond the hull edge a -> b of e's real triangle (orient(a, b, p) <
// 0). The 1-3 flip of the virtual triangle (b, a, v) gives the real (p, b, a)
// and the virtual (p, a, v), (p, v, b); then the virtual edges at p are
// flipped while the hull polygon is reflex there (§2.2: an edge x v between
// two virtual triangles is locally non-regular iff the polygon is reflex at
// x; here iff p sees the next hull edge, i.e. iff the new real triangle is
// counter-clockwise). Every new real triangle's edge opposite p is queued.
void Builder::insert_outside(std::uint32_t p, std::uint32_t e0) {
  const std::array<std::uint32_t, 3> h = flip13(tn_[e0] / 3, p);
  std::uint32_t side1 = kDead, side2 = kDead;
  for (std::uint32_t e : h) {
    const std::uint32_t t = e / 3;
    if (tv_[3 * t + 2] == V_) side1 = e;       // (p, a, v)
    else if (tv_[3 * t + 1] == V_) side2 = e;  // (p, v, b)
    else {
      stack_.push_back(e);  // (p, b, a)
      home_ = t;
    }
  }
  // (p, a, v) with twin (v, a, r) across a -> v: becomes (p, a, r), (p, r, v)
  for (std::uint32_t e = side1;;) {
    const std::uint32_t r = tv_[tn_[e]], a = tv_[nx(e)];
    if (orient(p, a, r) < 0) break;
    const std::uint32_t u = tn_[e] / 3;
    flip22(e);
    stack_.push_back(e - e % 3);  // (p, a, r): the edge a -> r
    e = 3 * u;                    // (p, r, v): the edge r -> v
  }
  // (p, v, b) with twin (b, v, s) across v -> b: becomes (p, v, s), (p, s, b)
  for (std::uint32_t e = side2;;) {
    const std::uint32_t s = tv_[tn_[e]], b = tv_[pv(e)];
    if (orient(p, s, b) < 0) break;
    const std::uint32_t u = tn_[e] / 3;
    flip22(e);
    stack_.push_back(3 * u);  // (p, s, b): the edge s -> b
    e = e - e % 3;            // (p, v, s): the edge v -> s
  }
}

// Make every edge of p's link locally regular (Edelsbrunner–Shah): an edge a
// -> b opposite p in (p, a, b) with twin (b, a, d), d real, is locally
// non-regular iff power(p, a, b, d) > 0 (§2.2; an edge with a virtual
// triangle is regular). It is flipped by a 2-2 flip when (p, a, d) and (p, d,
// b) are counter-clockwise (the quadrilateral is convex; Algorithm 5 line
// 11), else the reflex vertex — a or b, inside the triangle of the other
// three — is removed by a 3-1 flip when it has degree 3 (lines 6-9; its link
// triangle is then the counter-clockwise one of the other two corners and p).
// Otherwise the edge waits: Lemma 4.2 of Edelsbrunner–Shah guarantees another
// flippable non-regular link edge, whose flips eventually make it flippable or
// regular; the waiting edges are retried when the queue is empty, and a pass
// without any flip while some wait would contradict the lemma (logic_error).
void Builder::regularize(std::uint32_t p) {
  bool progress = false;
  for (;;) {
    while (!stack_.empty()) {
      const std::uint32_t e = stack_.back();
      stack_.pop_back();
      if (tv_[e] != p) continue;  // stale: the triangle changed since
      const std::uint32_t f = tn_[e], d = tv_[f];
      if (d == V_) continue;  // a hull edge
      const std::uint32_t a = tv_[nx(e)], b = tv_[pv(e)];
      if (power(p, a, b, d) < 0) continue;  // locally regular
      const int at_a = orient(p, a, d), at_b = orient(p, d, b);
      const std::uint32_t t = e / 3, u = f / 3;
      if (at_a > 0 && at_b > 0) {
        flip22(e);
        stack_.push_back(3 * t), stack_.push_back(3 * u);
        home_ = t, progress = true;
        continue;
      }
      // degree 3: the triangle across p -> a (resp. b -> p) from t is the one
      // across a -> d (resp. d -> b) from u
      const bool remove_a = at_a < 0;
      const bool degree3 = remove_a ? tn_[pv(e)] / 3 == tn_[nx(f)] / 3 : tn_[nx(e)] / 3 == tn_[pv(f)] / 3;
      if (degree3) {
        flip31(e, remove_a);
        stack_.push_back(3 * t);
        home_ = t, progress = true;
      } else {
        pending_.push_back(e);
      }
    }
    if (pending_.empty()) return;
    if (!progress)
      throw std::logic_error("rt2 (cpu): no flip applies around point " + std::to_string(P_[p].id) +
                             " while a link edge is not locally regular (Edelsbrunner-Shah Lemma 4.2 violated)");
    progress = false;
    stack_.swap(pending_);
  }
}

// Exact copies wait for the copy of larger index that follows them
// (brio.hpp, waits_for_next): missing_ 3 until everything else is in, then
// insert_one. Not the initial three (missing_ 2).
void Builder::defer_copies() {
  const std::uint32_t n = V_;
  for (std::uint32_t k = 0; k + 1 < n; ++k)
    if (missing_[k] == 0 &&
        brio::waits_for_next(P_[k].xy, P_[k].w, P_[k].id, P_[k + 1].xy, P_[k + 1].w, P_[k + 1].id, 2))
      missing_[k] = 3;
}

void Builder::insert_one(std::uint32_t p) {
  bool inside = false;
  const std::uint32_t e = walk(p, inside);
  if (inside) {
    const std::uint32_t t = e / 3;
    // §5.3: "proved to be redundant by the three vertices of the triangle
    // it is associated with": p^+ above their lifted plane, hence above the
    // lower hull now and after any insertion (it only moves down).
    if (power(tv_[3 * t], tv_[3 * t + 1], tv_[3 * t + 2], p) < 0) {
      ++st_.discarded_early;
      at_[p] = t, missing_[p] = 1;
      home_ = t;  // the next point along the curve is near
      return;
    }
    for (std::uint32_t h : flip13(t, p)) stack_.push_back(h);
    home_ = t;
  } else {
    insert_outside(p, e);
  }
  regularize(p);
}

void Builder::run(std::size_t parallel_from, bool territories, const std::vector<std::size_t>& rounds_at) {
  parallel_from_ = std::max<std::size_t>(1, parallel_from);
  territories_ = territories;
  const std::uint32_t n = V_;
  // the initial triangle: the first point, the first at another location, the
  // first off their line (exactly non-degenerate, like ffrt::initial_triangle)
  std::uint32_t a = 0, b = kDead, c = kDead;
  int o = 0;
  for (std::uint32_t k = 1; k < n && b == kDead; ++k)
    if (P_[k].xy[0] != P_[a].xy[0] || P_[k].xy[1] != P_[a].xy[1]) b = k;
  for (std::uint32_t k = b + 1; b != kDead && k < n && c == kDead; ++k)
    if ((o = pred::orient2d_exact(P_[a].xy, P_[b].xy, P_[k].xy)) != 0) c = k;
  if (c == kDead) throw std::logic_error("rt2 (cpu): no initial triangle in input that spans the plane");
  if (o < 0) std::swap(b, c);
  initial(a, b, c);
  // the initial three are vertices from the start: missing_ 2 while
  // inserting (nothing inserts them again), 0 again at the end if still
  // vertices
  missing_[a] = missing_[b] = missing_[c] = 2;
  defer_copies();
  const std::uint32_t seq_end = static_cast<std::uint32_t>(std::min<std::size_t>(n, parallel_from));
  for (std::uint32_t p = 0; p < seq_end; ++p)
    if (missing_[p] == 0) insert_one(p);
  if (seq_end < n) run_parallel(seq_end, rounds_at);
  for (std::uint32_t p = 0; p < n; ++p)  // the copies that waited, along the curve
    if (missing_[p] == 3) {
      missing_[p] = 0;
      insert_one(p);
    }
  for (std::uint32_t x : {a, b, c})
    if (missing_[x] == 2) missing_[x] = 0;  // still a vertex (else removed: 1)
}

// ---- stage 2b: parallel insertion ------------------------------------------------
//
// Every point of a batch is a Bowyer–Watson insertion into the regular
// triangulation T of the points inserted so far, done by many threads at
// once. Its cavity C(q) — the triangles of T whose lifted plane lies above
// q^+ (power > 0) — is the part of T that the flipping insertion of
// insert_one would replace (Edelsbrunner–Shah: every flip there destroys one
// triangle of T in conflict with q, and the triangles it creates are q's);
// C(q) is edge-connected (the triangles it is replaced by, the star of q in
// the new regular triangulation, form a disk), so a search from the triangle
// containing q finds it. Its ring R(q): the triangles outside C(q) across
// its boundary edges. Inserting q replaces C(q) by the fan from q to the
// boundary of C(q) (a vertex of T all of whose triangles are in C(q) is
// removed: it becomes redundant, the 3-1 flips of insert_one) and changes
// R(q) only in the twin links of the boundary edges.
//
// Which points go together: Insertion::territories, see territories();
// Insertion::batches (thesis §3.3.1's conflict resolution by
// atomic-minimum labelling of the induced subcomplex, [NHS11, QCT12]): each
// point writes its priority (a bijective hash of its position) as an atomic
// minimum into the cavity label of its cavity triangles and into the ring
// label of its ring triangles (resv_); after the join, q is a winner iff it
// holds the cavity label of all of its cavity, no smaller key has one of
// them in its ring and no smaller key has one of its ring triangles in its
// cavity. Two winners p, q then have disjoint cavities and C(p) ∩
// R(q) = C(q) ∩ R(p) = ∅ (they may share ring triangles: each writes other
// half-edges of them). That makes the winners independent: a triangle (p, a,
// b) of p's fan conflicts with q only if the triangle across a b outside C(p)
// — a ring triangle of p — or the one inside does (the lifted planes of the
// three triangles through a^+ b^+ form a pencil: on the side of p the new
// plane lies below the inner one, on the other side below the outer one,
// because p conflicts with the inner triangle and not with the outer one);
// neither is in C(q), so C(q) in T + p is C(q) in T, and inserting all the
// winners at once gives the regular triangulation of T's points and theirs,
// as inserting them one after the other would. The smallest key always
// wins, so every batch makes progress; the winners, their slots and their
// fans depend only on T and the batch, not on the threads, and so does the
// triangulation (slots included: the witness is thread-independent).
//
// A batch point found in a real triangle under whose lifted plane it is not
// is redundant and dropped for good (as in insert_one: p^+ is above the
// plane of three lifted points around it, so above the lower hull of every
// superset — under SoS the same for the perturbed points). A point outside
// the current hull (the walk leaves through a hull edge) is inserted after
// the batch's winners, one by one in position order, by insert_one (virtual
// triangles and their 2-2 flips, §2.2): rare after the first rounds, and
// sequential keeps the extended triangulation's virtual part simple.

namespace {
// a bijection of 32-bit words (products by odd constants and xor-shifts):
// distinct priorities, spread over the batch so that neighbouring points of
// the Hilbert order do not all lose to their predecessor
std::uint32_t priority(std::uint32_t p) {
  p *= 0x9E3779B1u;
  p ^= p >> 15;
  p *= 0x85EBCA77u;
  p ^= p >> 13;
  return p;
}
void atomic_min(std::uint32_t* a, std::uint32_t v) {
  std::uint32_t cur = __atomic_load_n(a, __ATOMIC_RELAXED);
  while (v < cur && !__atomic_compare_exchange_n(a, &cur, v, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
  }
}
std::uint32_t load(const std::uint32_t* a) { return __atomic_load_n(a, __ATOMIC_RELAXED); }
constexpr std::uint32_t kFree = ~std::uint32_t{0};  // resv_*: no point
}  // namespace

// Breadth-first search of C(q) from t0 (which contains q, in conflict);
// the cavity and its boundary edges are appended to pc's lists. With a
// territory terr: false (and nothing appended) as soon as a triangle of the
// cavity or of its ring is not terr's — read nothing of it (another task may
// be writing it).
bool Builder::find_cavity(std::uint32_t q, std::uint32_t t0, Piece& pc, std::uint32_t terr) {
  Cand c{q, priority(q), static_cast<std::uint32_t>(pc.cav.size()), static_cast<std::uint32_t>(pc.bnd.size()), 0, 0,
         kDead, kDead};
  pc.cav.push_back(t0);
  // the cavity so far: a scan while small (the usual 4 triangles), a hash
  // set from kScan on (a point on a circle through many others has a
  // cavity of all their triangles)
  constexpr std::size_t kScan = 32;
  pc.big.clear();
  auto seen = [&](std::uint32_t u) {
    const std::size_t k = pc.cav.size() - c.cav;
    if (k <= kScan) return std::find(pc.cav.begin() + c.cav, pc.cav.end(), u) != pc.cav.end();
    if (pc.big.empty()) pc.big.insert(pc.cav.begin() + c.cav, pc.cav.end());
    return pc.big.count(u) != 0;
  };
  auto add = [&](std::uint32_t u) {
    pc.cav.push_back(u);
    if (!pc.big.empty()) pc.big.insert(u);
  };
  for (std::size_t i = c.cav; i < pc.cav.size(); ++i) {
    const std::uint32_t t = pc.cav[i];
    for (std::uint32_t j = 0; j < 3; ++j) {
      const std::uint32_t e = 3 * t + j, f = tn_[e], u = f / 3;
      if (terr != kDead && terr_[u] != terr) {
        pc.cav.resize(c.cav), pc.bnd.resize(c.bnd);
        return false;
      }
      if (seen(u)) continue;
      if (!is_virtual(u) && power(tv_[3 * u], tv_[3 * u + 1], tv_[3 * u + 2], q) > 0) {
        add(u);
        continue;
      }
      pc.bnd.push_back({tv_[nx(e)], tv_[pv(e)], f});
    }
  }
  c.k = static_cast<std::uint32_t>(pc.cav.size()) - c.cav;
  c.m = static_cast<std::uint32_t>(pc.bnd.size()) - c.bnd;
  if (terr == kDead) {  // a batch: label the cavity and the ring
    for (std::uint32_t i = 0; i < c.k; ++i) atomic_min(&resv_[2 * pc.cav[c.cav + i]], c.key);
    for (std::uint32_t i = 0; i < c.m; ++i) atomic_min(&resv_[2 * (pc.bnd[c.bnd + i][2] / 3) + 1], c.key);
  }
  pc.cand.push_back(c);
  return true;
}

bool Builder::wins(const Piece& pc, const Cand& c) const {
  for (std::uint32_t i = 0; i < c.k; ++i) {
    const std::uint32_t t = pc.cav[c.cav + i];
    if (load(&resv_[2 * t]) != c.key || load(&resv_[2 * t + 1]) < c.key) return false;
  }
  for (std::uint32_t i = 0; i < c.m; ++i)
    if (load(&resv_[2 * (pc.bnd[c.bnd + i][2] / 3)]) < c.key) return false;
  return true;
}

// The Bowyer–Watson step of the winner c: its cavity slots, then extra (m -
// k of them when the fan is larger), hold the fan (q, a, b) over the
// boundary edges a -> b in counter-clockwise order; cavity slots left over
// are released (their numbers written to released). The vertices of the
// cavity that are not on its boundary are removed (3-1 flips).
void Builder::commit(Piece& pc, const Cand& c, const std::uint32_t* extra, std::uint32_t* released) {
  const std::uint32_t q = c.p, k = c.k, m = c.m;
  const std::uint32_t* C = &pc.cav[c.cav];
  const std::array<std::uint32_t, 3>* E = &pc.bnd[c.bnd];
  // boundary edges sorted by their first vertex, then chained into the cycle
  std::vector<std::uint32_t>& ord = pc.scratch;
  ord.resize(2 * static_cast<std::size_t>(m));
  std::uint32_t* by_a = ord.data();
  std::uint32_t* cyc = ord.data() + m;
  for (std::uint32_t i = 0; i < m; ++i) by_a[i] = i;
  std::sort(by_a, by_a + m, [&](std::uint32_t x, std::uint32_t y) { return E[x][0] < E[y][0]; });
  auto starting_at = [&](std::uint32_t v) {
    const std::uint32_t* it =
        std::lower_bound(by_a, by_a + m, v, [&](std::uint32_t x, std::uint32_t val) { return E[x][0] < val; });
    return it != by_a + m && E[*it][0] == v ? *it : kDead;
  };
  cyc[0] = 0;
  for (std::uint32_t j = 1; j < m; ++j) {
    cyc[j] = starting_at(E[cyc[j - 1]][1]);
    if (cyc[j] == kDead || cyc[j] == 0)
      throw std::logic_error("rt2 (cpu): the cavity of point " + std::to_string(P_[q].id) +
                             " is not a disk (corrupted triangulation)");
  }
  if (E[cyc[m - 1]][1] != E[0][0])
    throw std::logic_error("rt2 (cpu): the cavity boundary of point " + std::to_string(P_[q].id) + " is not closed");
  auto slot = [&](std::uint32_t j) { return j < k ? C[j] : extra[j - k]; };
  const std::uint32_t s0 = slot(0);
  // the removed vertices: corners of the cavity that start no boundary edge
  std::uint32_t removed = 0;
  for (std::uint32_t i = 0; i < k; ++i)
    for (std::uint32_t j = 0; j < 3; ++j) {
      const std::uint32_t x = tv_[3 * C[i] + j];
      if (starting_at(x) != kDead || missing_[x] == 1) continue;
      missing_[x] = 1, at_[x] = s0;  // x lies in the fan; a hint for the witness walk
      ++removed;
    }
  if (k + 2 != m + 2 * removed)
    throw std::logic_error("rt2 (cpu): the cavity of point " + std::to_string(P_[q].id) +
                           " does not match its boundary (Euler)");
  for (std::uint32_t j = 0; j < m; ++j) {
    const std::uint32_t s = slot(j), s1 = slot(j + 1 == m ? 0 : j + 1);
    const std::array<std::uint32_t, 3>& ab = E[cyc[j]];
    set(s, q, ab[0], ab[1]);
    link(3 * s, ab[2]);
    link(3 * s + 1, 3 * s1 + 2);  // b -> q | q -> b of the next fan triangle
  }
  for (std::uint32_t j = m; j < k; ++j) {
    tv_[3 * C[j]] = tv_[3 * C[j] + 1] = tv_[3 * C[j] + 2] = kDead;
    released[j - m] = C[j];
  }
  at_[q] = s0;  // a triangle at q: where the walks of the points after it start
  ++pc.inserted;
  pc.removed += removed;
  pc.absorbed += k - 1 - removed;  // insert_one's 2-2 flips: one per cavity triangle not split or removed
}

// One batch: locate (walks from the last location), drop the redundant,
// find cavities and label them (parallel); pick the winners (parallel);
// hand out slots (prefix sums in batch order); insert the winners
// (parallel); then the points outside the hull one by one. losers: the
// points to try again, in order.
void Builder::batch(const std::vector<std::uint32_t>& pts, std::vector<std::uint32_t>& losers) {
  // points per task: small enough that the batches of the tests (tens of
  // points) span several tasks too
  constexpr std::size_t kPiece = 32;
  const std::size_t pieces = (pts.size() + kPiece - 1) / kPiece;
  if (pieces_.size() < pieces) pieces_.resize(pieces);
  const std::uint32_t slots = static_cast<std::uint32_t>(tv_.size() / 3);
  resv_.resize(2 * static_cast<std::size_t>(slots), kFree);  // insert_one may have added slots since
  par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t g = lo; g < hi; ++g) {
      Piece& pc = pieces_[g];
      pc.cand.clear(), pc.cav.clear(), pc.bnd.clear(), pc.outside.clear(), pc.located.clear();
      pc.discarded = pc.removed = pc.absorbed = pc.inserted = 0;
      std::uint32_t prev = kDead;
      for (std::size_t i = g * kPiece; i < std::min(pts.size(), (g + 1) * kPiece); ++i) {
        const std::uint32_t q = pts[i];
        std::uint32_t rng = priority(q) | 1u;
        // where to start: q's last location, else that of the nearest point
        // before q on the curve that was handled already (it is near q)
        std::uint32_t hint = at_[q];
        for (std::uint32_t x = q; hint == kDead && x-- > 0 && q - x < 64;) hint = at_[x];
        const std::uint32_t start = hint < slots && is_real(hint) ? hint : prev != kDead ? prev : home_;
        bool inside = false;
        const std::uint32_t e = locate(q, start, rng, inside);
        if (!inside) {
          pc.outside.push_back(q);
          continue;
        }
        const std::uint32_t t = e / 3;
        prev = t;
        pc.located.push_back({q, t});  // into at_ after the join (other tasks read at_ here)
        if (power(tv_[3 * t], tv_[3 * t + 1], tv_[3 * t + 2], q) < 0) {
          missing_[q] = 1;
          ++pc.discarded;
          continue;
        }
        find_cavity(q, t, pc);
      }
    }
  });
  par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t g = lo; g < hi; ++g) {
      for (Cand& c : pieces_[g].cand) c.xo = wins(pieces_[g], c) ? 0 : kDead;
      for (const auto& [q, t] : pieces_[g].located) at_[q] = t;
    }
  });
  std::uint32_t need = 0, rel = 0;
  losers.clear();
  for (std::size_t g = 0; g < pieces; ++g)
    for (Cand& c : pieces_[g].cand) {
      if (c.xo == kDead) {
        losers.push_back(c.p);
        continue;
      }
      c.xo = need, c.ro = rel;
      need += c.m > c.k ? c.m - c.k : 0;
      rel += c.k > c.m ? c.k - c.m : 0;
    }
  // the extra slots: the free ones from the back of free_, then new ones
  std::vector<std::uint32_t> extra(need), released(rel);
  const std::size_t reuse = std::min<std::size_t>(need, free_.size());
  for (std::size_t j = 0; j < reuse; ++j) extra[j] = free_[free_.size() - 1 - j];
  free_.resize(free_.size() - reuse);
  for (std::size_t j = reuse; j < need; ++j) extra[j] = static_cast<std::uint32_t>(slots + (j - reuse));
  const std::size_t grown = 3 * (static_cast<std::size_t>(slots) + (need - reuse));
  tv_.resize(grown, kDead), tn_.resize(grown, kDead);
  resv_.resize(2 * (grown / 3), kFree);
  par_for(pieces, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t g = lo; g < hi; ++g) {
      Piece& pc = pieces_[g];
      for (const Cand& c : pc.cand)
        if (c.xo != kDead) commit(pc, c, extra.data() + c.xo, released.data() + c.ro);
      // unlabel (every label of this batch is read: the winners are known)
      for (std::uint32_t t : pc.cav) __atomic_store_n(&resv_[2 * t], kFree, __ATOMIC_RELAXED);
      for (const auto& ab : pc.bnd) __atomic_store_n(&resv_[2 * (ab[2] / 3) + 1], kFree, __ATOMIC_RELAXED);
    }
  });
  free_.insert(free_.end(), released.begin(), released.end());
  for (std::size_t g = 0; g < pieces; ++g) {
    const Piece& pc = pieces_[g];
    st_.discarded_early += pc.discarded;
    st_.flips_1_3 += pc.inserted;
    st_.flips_3_1 += pc.removed;
    st_.flips_2_2 += pc.absorbed;
  }
  // home_ (where insert_one's walk starts) must be a real triangle: the
  // first winner's first fan triangle when the old one was released
  if (!is_real(home_))
    for (std::size_t g = 0; g < pieces && !is_real(home_); ++g)
      for (const Cand& c : pieces_[g].cand)
        if (c.xo != kDead) {
          home_ = pieces_[g].cav[c.cav];
          break;
        }
  for (std::size_t g = 0; g < pieces; ++g)
    for (std::uint32_t q : pieces_[g].outside) insert_one(q);
}

// The same walk as locate() for a point inside the territory terr, reading
// only terr's triangles: kDead as soon as it would step into another
// (another territory's, or a virtual one: the point may be outside the hull).
std::uint32_t Builder::locate_in(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, std::uint32_t terr,
                                 bool& inside) const {
  const std::uint32_t e = walk_to(p, start, rng, inside, [&](std::uint32_t t) { return terr_[t] != terr; });
  return inside ? e : kDead;
}

// Stage 2b, first pass over a round: territories. The pending points (in
// position order, i.e. along the round's Hilbert curve) are cut into S
// consecutive pieces; a real triangle belongs to the piece whose stretch
// of the curve holds the curve key of its centroid (the cut keys are the
// pieces' first points' keys). Each piece is one task, inserting its points
// one after the other as a batch winner would (walk, discard, cavity, fan)
// as long as the walk, the cavity and its ring stay in the piece's own
// triangles and the slots it creates (2 reserved per point, its released
// ones reused first) — the cache locality of stage 2 — and deferring the
// others. Territories are disjoint and each task reads and writes only its
// own (a triangle of another territory is never read: its territory label
// is enough to stop), so two insertions of different tasks meet the
// independence condition of the batches (disjoint cavities, neither
// cavity in the other's ring) and the result does not depend on the order
// in which the tasks run: the triangulation, slots included, is the same
// for every thread count. pending receives the deferred points, in order.
void Builder::territories(std::vector<std::uint32_t>& pending) {
  const std::size_t vertices = 3 + st_.flips_1_3 - st_.flips_3_1;
  const std::size_t S = std::min<std::size_t>(64, vertices / std::min<std::size_t>(1024, parallel_from_));
  const std::size_t np = pending.size();
  if (S < 2 || np < S) return;
  auto key_of = [&](std::uint32_t q) { return curve_key(P_[q].xy[0], P_[q].xy[1]); };
  std::vector<std::uint32_t> cut(S - 1);
  for (std::size_t j = 1; j < S; ++j) cut[j - 1] = key_of(pending[np * j / S]);
  // piece j: the pending points with curve keys in [cut[j - 1], cut[j])
  // (keys do not decrease along a round)
  std::vector<std::size_t> start(S + 1, np);
  start[0] = 0;
  for (std::size_t j = 1; j < S; ++j)
    start[j] = static_cast<std::size_t>(
        std::partition_point(pending.begin(), pending.end(), [&](std::uint32_t q) { return key_of(q) < cut[j - 1]; }) -
        pending.begin());
  auto piece_at = [&](std::size_t j) { return start[j]; };
  // piece j's reserved slots: slots + 2 piece_at(j) ... slots + 2 piece_at(j + 1)
  const std::size_t slots = tv_.size() / 3, total = slots + 2 * np;
  tv_.resize(3 * total, kDead), tn_.resize(3 * total, kDead);
  terr_.resize(total);
  // per territory (curve key of the centroid << 32 | slot), the smallest:
  // the triangle at the start of its stretch of the curve, near its piece's
  // first point — where its walks start
  std::vector<std::uint64_t> first(S, ~std::uint64_t{0});
  par_for(slots, kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t t = lo; t < hi; ++t) {
      std::uint32_t j = kDead;
      if (is_real(static_cast<std::uint32_t>(t))) {
        const Vtx &a = P_[tv_[3 * t]], &b = P_[tv_[3 * t + 1]], &c = P_[tv_[3 * t + 2]];
        const std::uint32_t key = curve_key((a.xy[0] + b.xy[0] + c.xy[0]) / 3, (a.xy[1] + b.xy[1] + c.xy[1]) / 3);
        j = static_cast<std::uint32_t>(std::upper_bound(cut.begin(), cut.end(), key) - cut.begin());
        const std::uint64_t mark = (std::uint64_t{key} << 32) | t;
        std::uint64_t old = __atomic_load_n(&first[j], __ATOMIC_RELAXED);
        while (mark < old && !__atomic_compare_exchange_n(&first[j], &old, mark, true, __ATOMIC_RELAXED,
                                                          __ATOMIC_RELAXED)) {
        }
      }
      terr_[t] = j;
    }
  });
  if (pieces_.size() < S) pieces_.resize(S);
  par_for(S, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t j = lo; j < hi; ++j)
      for (std::size_t t = slots + 2 * piece_at(j); t < slots + 2 * piece_at(j + 1); ++t)
        terr_[t] = static_cast<std::uint32_t>(j);
  });
  // phase 1: the pieces in parallel; pc.outside collects the deferred
  // points, pc.scratch2 the slots left free
  par_for(S, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t j = lo; j < hi; ++j) {
      Piece& pc = pieces_[j];
      pc.cand.clear(), pc.cav.clear(), pc.bnd.clear(), pc.outside.clear(), pc.freed.clear();
      pc.discarded = pc.removed = pc.absorbed = pc.inserted = 0;
      const std::uint32_t terr = static_cast<std::uint32_t>(j);
      std::uint32_t fresh = static_cast<std::uint32_t>(slots + 2 * piece_at(j));
      const std::uint64_t f = __atomic_load_n(&first[j], __ATOMIC_RELAXED);
      std::uint32_t cur = f == ~std::uint64_t{0} ? kFree : static_cast<std::uint32_t>(f);
      std::uint32_t extra[2], released_buf[64];
      std::vector<std::uint32_t> released_big;
      for (std::size_t i = piece_at(j); i < piece_at(j + 1); ++i) {
        const std::uint32_t q = pending[i];
        bool inside = false;
        std::uint32_t rng = priority(q) | 1u;
        const std::uint32_t e = cur == kFree ? kDead : locate_in(q, cur, rng, terr, inside);
        if (e == kDead) {
          pc.outside.push_back(q);
          continue;
        }
        const std::uint32_t t = e / 3;
        at_[q] = cur = t;
        if (power(tv_[3 * t], tv_[3 * t + 1], tv_[3 * t + 2], q) < 0) {
          missing_[q] = 1;
          ++pc.discarded;
          continue;
        }
        if (!find_cavity(q, t, pc, terr)) {
          pc.outside.push_back(q);
          continue;
        }
        const Cand c = pc.cand.back();
        const std::uint32_t need = c.m > c.k ? c.m - c.k : 0, rel = c.k > c.m ? c.k - c.m : 0;
        for (std::uint32_t x = 0; x < need; ++x) {
          if (!pc.freed.empty()) {
            extra[x] = pc.freed.back();
            pc.freed.pop_back();
          } else {
            extra[x] = fresh++;  // at most 2 per point: never beyond the piece's reserve
          }
        }
        std::uint32_t* released = released_buf;
        if (rel > 64) released_big.resize(rel), released = released_big.data();
        commit(pc, c, extra, released);
        pc.freed.insert(pc.freed.end(), released, released + rel);
        cur = at_[q];
        pc.cand.clear(), pc.cav.clear(), pc.bnd.clear();
      }
      for (; fresh < slots + 2 * piece_at(j + 1); ++fresh) pc.freed.push_back(fresh);
    }
  });
  pending.clear();
  for (std::size_t j = 0; j < S; ++j) {
    const Piece& pc = pieces_[j];
    pending.insert(pending.end(), pc.outside.begin(), pc.outside.end());
    free_.insert(free_.end(), pc.freed.begin(), pc.freed.end());
    st_.discarded_early += pc.discarded;
    st_.flips_1_3 += pc.inserted;
    st_.flips_3_1 += pc.removed;
    st_.flips_2_2 += pc.absorbed;
  }
  // home_ (where insert_one's walks start) must be a real triangle
  for (std::size_t t = 0; t < total && !is_real(home_); ++t) home_ = static_cast<std::uint32_t>(t);
  ++st_.rounds;
}

// The positions [from, n) round by round (BRIO order). Insertion::
// territories: the territories (most points, each piece with the locality
// of stage 2), then the points they deferred — near the territories'
// borders and the hull — one by one (insert_one, in position order: about
// 17 % of the last round of 300 000 uniform points, in a tenth of the
// round's time). Insertion::batches: every point in batches, taken in the
// bit-reversed order of their rank in the round (van der Corput): every
// slice of that order is spread evenly along the curve, hence over the
// plane, so few cavities of one batch meet.
// A batch: the losers of the previous one and the next slice, about
// 1/kShare of the current vertex count, in position order (the walks go
// from one point to the next along the curve). The last few pending points
// (fewer than kTail) go one by one. Batches and territories depend only on
// counts, not on the threads.
void Builder::run_parallel(std::size_t from, const std::vector<std::size_t>& rounds_at) {
  // batch ~ vertices / kShare: about 95 % of a batch wins at 1/128
  constexpr std::size_t kShare = 128;
  const std::size_t kTail = std::min<std::size_t>(64, parallel_from_);
  std::vector<std::uint32_t> pending, order, carry, slice, pts;
  for (std::size_t r = 0; r + 1 < rounds_at.size(); ++r) {
    const std::size_t lo = std::max(from, rounds_at[r]), hi = rounds_at[r + 1];
    if (lo >= hi) continue;
    pending.clear();
    for (std::size_t p = lo; p < hi; ++p)
      if (missing_[p] == 0) pending.push_back(static_cast<std::uint32_t>(p));
    if (territories_) {  // the territories, then the points they deferred one by one
      territories(pending);
      st_.retried += pending.size();
      for (std::uint32_t p : pending) insert_one(p);
      continue;
    }
    const std::size_t N = pending.size();
    unsigned bits = 0;
    while ((std::size_t{1} << bits) < N) ++bits;
    order.clear();
    for (std::size_t i = 0; i < (std::size_t{1} << bits); ++i) {
      std::size_t j = 0;  // i bit-reversed over `bits` bits
      for (unsigned b = 0; b < bits; ++b) j |= ((i >> b) & 1u) << (bits - 1 - b);
      if (j < N) order.push_back(pending[j]);
    }
    carry.clear();
    std::size_t cursor = 0;
    while (order.size() - cursor + carry.size() >= kTail) {
      const std::size_t vertices = 3 + st_.flips_1_3 - st_.flips_3_1;
      const std::size_t take = std::min(order.size() - cursor, std::max<std::size_t>(1, vertices / kShare));
      slice.assign(order.begin() + static_cast<std::ptrdiff_t>(cursor),
                   order.begin() + static_cast<std::ptrdiff_t>(cursor + take));
      cursor += take;
      std::sort(slice.begin(), slice.end());
      pts.clear();
      std::merge(carry.begin(), carry.end(), slice.begin(), slice.end(), std::back_inserter(pts));
      batch(pts, carry);
      st_.retried += carry.size();
      ++st_.rounds;
    }
    pts.clear();
    std::sort(order.begin() + static_cast<std::ptrdiff_t>(cursor), order.end());
    std::merge(carry.begin(), carry.end(), order.begin() + static_cast<std::ptrdiff_t>(cursor), order.end(),
               std::back_inserter(pts));
    for (std::uint32_t p : pts) insert_one(p);
  }
}

// Canonical order without a comparison sort: the real triangles, each
// rotated to its smallest input index m, are gathered per chunk of slots
// (with a histogram of B coarse buckets of consecutive m), scattered into
// their buckets (each chunk writes its own ranges: no atomics), then each
// bucket — a range of about n / B indices, small enough for the cache — is
// counting-sorted by m and every group of one m (about two triangles) sorted
// by its other two indices. The result does not depend on the thread count.
std::vector<Triangle> Builder::output() const {
  const std::size_t slots = tv_.size() / 3, n = V_;
  const std::size_t per = std::max<std::size_t>(kChunk, (slots + 15) / 16);  // slots per chunk: <= 16 chunks
  const std::size_t chunks = (slots + per - 1) / per;
  const std::size_t B = std::max<std::size_t>(1, std::min<std::size_t>(1024, n / 64));
  auto bucket = [&](Index m) { return static_cast<std::size_t>(static_cast<std::uint64_t>(m) * B / n); };
  std::vector<std::vector<Triangle>> part(chunks);
  std::vector<std::size_t> at(chunks * B, 0);  // at[c * B + b]: counts, then write positions
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c) {
      std::vector<Triangle>& L = part[c];
      L.reserve(std::min(slots, (c + 1) * per) - c * per);
      for (std::size_t t = c * per; t < std::min(slots, (c + 1) * per); ++t) {
        if (!is_real(static_cast<std::uint32_t>(t))) continue;
        const Index a = P_[tv_[3 * t]].id, b = P_[tv_[3 * t + 1]].id, d = P_[tv_[3 * t + 2]].id;
        L.push_back(a < b ? (a < d ? Triangle{a, b, d} : Triangle{d, a, b})
                          : (b < d ? Triangle{b, d, a} : Triangle{d, a, b}));
        ++at[c * B + bucket(L.back()[0])];
      }
    }
  });
  const std::vector<std::size_t> first = bucket_major_positions(at, chunks, B);
  std::vector<Triangle> out(first[B]);
  par_for(chunks, 1, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t c = lo; c < hi; ++c) {
      for (const Triangle& x : part[c]) out[at[c * B + bucket(x[0])]++] = x;
      std::vector<Triangle>().swap(part[c]);
    }
  });
  par_for(B, 1, [&](std::size_t lo, std::size_t hi) {
    std::vector<std::uint32_t> count;
    std::vector<Triangle> tmp;
    for (std::size_t b = lo; b < hi; ++b) {
      if (first[b] == first[b + 1]) continue;
      // the indices m of bucket b: [mlo, mhi)
      const Index mlo = static_cast<Index>((static_cast<std::uint64_t>(b) * n + B - 1) / B);
      const Index mhi = static_cast<Index>(std::min<std::uint64_t>(n, (static_cast<std::uint64_t>(b + 1) * n + B - 1) / B));
      count.assign(static_cast<std::size_t>(mhi - mlo) + 1, 0);
      const auto begin = out.begin() + static_cast<std::ptrdiff_t>(first[b]);
      const auto end = out.begin() + static_cast<std::ptrdiff_t>(first[b + 1]);
      for (auto it = begin; it != end; ++it) ++count[(*it)[0] - mlo + 1];
      for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
      tmp.assign(begin, end);
      for (const Triangle& x : tmp) *(begin + count[x[0] - mlo]++) = x;
      // count[m - mlo] is now the end of group m
      std::uint32_t g = 0;
      for (std::size_t m = 0; m + 1 < count.size(); ++m) {
        std::sort(begin + g, begin + count[m]);
        g = count[m];
      }
    }
  });
  return out;
}

// Stage 4. A vertex's triangle: the smallest real slot with it as a corner
// (an atomic maximum of ~slot, so the witness does not depend on the thread
// count). A missing point's: the real triangle containing it under SoS, by
// the visibility walk of stage 2 — the points taken in insertion order in
// pieces of kChunk, each walk starting from the previous missing point's
// triangle (the BRIO order is spatially coherent: most points are in its last
// round, along a Hilbert curve), a piece's first from its hint (the slot it
// was found redundant in, or removed from, if that slot still holds a real
// triangle: usually nearby), else from home_. The triangle containing a point
// is unique under SoS, so the walks' starts and random choices do not change
// the answer. Every missing point lies in a real triangle: it was in one when
// it was discarded or removed, and the region of the real triangles (the hull
// of the inserted points) only grows; leaving it is a broken structure.
// Whether p is redundant under the triangle found is for the certifier to
// decide (it is: the final triangulation is regular, p is not a vertex).
void Builder::witness(Rt2Witness& w) {
  const std::size_t slots = tv_.size() / 3, n = V_;
  {
    std::vector<std::atomic<std::uint32_t>> first(n);  // ~slot; 0: none yet (zero-initialised)
    par_for(slots, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t t = lo; t < hi; ++t) {
        if (!is_real(static_cast<std::uint32_t>(t))) continue;
        const std::uint32_t mark = ~static_cast<std::uint32_t>(t);
        for (int i = 0; i < 3; ++i) {
          std::atomic<std::uint32_t>& a = first[tv_[3 * t + static_cast<std::size_t>(i)]];
          std::uint32_t cur = a.load(std::memory_order_relaxed);
          while (cur < mark && !a.compare_exchange_weak(cur, mark, std::memory_order_relaxed)) {
          }
        }
      }
    });
    par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const std::uint32_t m = first[k].load(std::memory_order_relaxed);
        if (!missing_[k]) at_[k] = m == 0 ? kDead : ~m;
      }
    });
  }
  par_for(n, kChunk, [&](std::size_t lo, std::size_t hi) {
    std::uint32_t rng = 0x2545F491u ^ static_cast<std::uint32_t>(lo * 0x9E3779B9u), prev = kDead;
    for (std::size_t k = lo; k < hi; ++k) {
      if (!missing_[k]) continue;
      const std::uint32_t hint = at_[k];
      // (hint: kDead when the point was never located)
      const std::uint32_t start = prev != kDead ? prev : hint < slots && is_real(hint) ? hint : home_;
      bool inside = false;
      const std::uint32_t e = locate(static_cast<std::uint32_t>(k), start, rng, inside);
      if (!inside)
        throw std::logic_error("rt2 (cpu): point " + std::to_string(P_[k].id) +
                               " is not a vertex and lies outside the triangulation (corrupted triangulation)");
      at_[k] = prev = e / 3;
    }
  });
  w.pts = std::move(P_);
  w.tv = std::move(tv_);
  w.tn = std::move(tn_);
  w.at = std::move(at_);
}

}  // namespace

std::vector<Triangle> rt2(const PointSet& ps, const Rt2Options& opt, ref::Rt2Stats* stats, Rt2Witness* witness) {
  ref::require_plane(ps, "rt2 (cpu)");
  // half-edges 3t + i of about 2n triangles must fit 32 bits, indices the
  // 29 bits of the BRIO key
  constexpr std::size_t kMaxPoints = std::size_t{1} << brio::kIndexBits;
  if (ps.size() > kMaxPoints)
    throw std::invalid_argument("rt2 (cpu): " + std::to_string(ps.size()) + " points exceed the limit of " +
                                std::to_string(kMaxPoints) + " (32-bit half-edge indices)");
  ref::Rt2Stats st;
  std::vector<Triangle> out;
  with_threads(opt.threads, [&] {
    StageClock clock(opt.times);
    const pred::StaticFilter f = parallel_static_filter(ps, {});
    std::vector<std::size_t> rounds_at;
    std::array<double, 4> box{};
    const std::vector<Index> order = brio_order(ps, opt.brio_min, &rounds_at, &box);
    std::vector<Vtx> pts(order.size());
    par_for(order.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const Index i = order[k];
        pts[k] = {{ps.point(i)[0], ps.point(i)[1]}, ps.weight(i), i};
      }
    });
    clock.mark("sort");
    const std::size_t pts_size = pts.size();
    Builder B(std::move(pts), f, st, box);
    B.run(opt.insertion == Rt2Options::Insertion::sequential ? pts_size : std::max<std::size_t>(1, opt.parallel_from),
          opt.insertion == Rt2Options::Insertion::territories, rounds_at);
    clock.mark("insert");
    out = B.output();
    clock.mark("output");
    if (witness) {
      B.witness(*witness);
      clock.mark("witness");
    }
  });
  st.rounds += 1;
  if (stats) *stats = st;
  return out;
}

}  // namespace flipflop::cpu

// rt2.cpp — the multithreaded 2D regular triangulation (see rt2.hpp).
#include "kernels_cpu/rt2/rt2.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels_cpu/parallel.hpp"
#include "reference/certify/certify_detail.hpp"  // radix_sort_high
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

std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Grid coordinate in [0, 2^15) of x in [lo, hi]; halves first so that no
// difference overflows near ±DBL_MAX (the order is a heuristic: any value is
// correct, only locality depends on it).
std::uint32_t grid(double x, double lo, double hi) {
  const double span = hi * 0.5 - lo * 0.5;
  double u = span > 0 ? (x * 0.5 - lo * 0.5) / span : 0.0;
  if (!(u >= 0)) u = 0;
  if (u > 1) u = 1;
  return static_cast<std::uint32_t>(std::min(32767.0, u * 32768.0));
}

// The sort key of a point: its round (5 bits, sparsest first), its Hilbert
// index (30 bits), its input index (29 bits, rt2() admits at most 2^29
// points) — distinct keys, so the order is unique.
constexpr int kIndexBits = 29;

// certify::detail::radix_sort_high with the pieces run by par_for
void radix_sort_par(std::vector<std::uint64_t>& keys, int lo_bit) {
  const std::function<void(std::size_t, const std::function<void(std::size_t, std::size_t)>&)> for_range =
      [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) { par_for(n, kChunk, body); };
  certify::detail::radix_sort_high(keys, lo_bit, for_range);
}

// Biased randomized insertion order: point i belongs to round r = min(R - 1,
// (leading zero bits of hash(i)) / 3), i.e. to round r with probability about
// 8^-r (7/8 of the points in the last round), the rounds inserted from the
// sparsest one, each along the Hilbert curve of the bounding box. R is the
// number of rounds of expected size >= brio_min.
std::vector<Index> brio_order(const PointSet& ps, std::size_t brio_min) {
  const std::size_t n = ps.size();
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  {
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<std::array<double, 4>> part(chunks);
    par_for(chunks, 1, [&](std::size_t clo, std::size_t chi) {
      for (std::size_t c = clo; c < chi; ++c) {
        std::array<double, 4> b = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
          for (int k = 0; k < 2; ++k) {
            b[static_cast<std::size_t>(k)] = std::min(b[static_cast<std::size_t>(k)], ps.point(i)[k]);
            b[static_cast<std::size_t>(k) + 2] = std::max(b[static_cast<std::size_t>(k) + 2], ps.point(i)[k]);
          }
        part[c] = b;
      }
    });
    for (const auto& b : part)
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], b[static_cast<std::size_t>(k)]);
        hi[k] = std::max(hi[k], b[static_cast<std::size_t>(k) + 2]);
      }
  }
  unsigned rounds = 1;
  while (rounds < 20 && (n >> (3 * rounds)) >= std::max<std::size_t>(brio_min, 1)) ++rounds;  // < 2^5
  std::vector<std::uint64_t> keys(n);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) {
      const double* p = ps.point(i);
      const std::uint64_t h = splitmix64(i);
      const unsigned zeros = h == 0 ? 64u : static_cast<unsigned>(__builtin_clzll(h));
      const unsigned r = std::min(rounds - 1, zeros / 3);
      const std::uint64_t curve = hilbert15(grid(p[0], lo[0], hi[0]), grid(p[1], lo[1], hi[1]));
      keys[i] = (static_cast<std::uint64_t>(rounds - 1 - r) << (30 + kIndexBits)) | (curve << kIndexBits) | i;
    }
  });
  // keys[i] holds i in its low bits, so the stable radix sort on the high
  // bits (the certifiers' one, here over par_for) is the sort of the whole
  // (distinct) keys
  radix_sort_par(keys, kIndexBits);
  std::vector<Index> order(n);
  par_for(n, kChunk, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) order[i] = static_cast<Index>(keys[i] & ((std::uint64_t{1} << kIndexBits) - 1));
  });
  return order;
}

// ---- stage 2: incremental flipping ----------------------------------------------

class Builder {
 public:
  Builder(std::vector<Vtx> pts, const pred::StaticFilter& f, ref::Rt2Stats& st)
      : P_(std::move(pts)), f_(f), st_(st), V_(static_cast<std::uint32_t>(P_.size())),
        at_(P_.size(), kDead), missing_(P_.size(), 0) {
    tv_.reserve(6 * P_.size() + 12);
    tn_.reserve(6 * P_.size() + 12);
  }

  void run();
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
  std::uint32_t locate(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside) const;
  std::uint32_t walk(std::uint32_t p, bool& inside) { return locate(p, home_, rng_, inside); }
  void insert_outside(std::uint32_t p, std::uint32_t e0);
  void regularize(std::uint32_t p);
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
// returns 3t with inside = true when p lies in the real triangle t, or a
// half-edge e of a real triangle whose edge (a hull edge) p sees, with inside
// = false. Under SoS no point is on a line, so every step is decided; the
// walk is acyclic in a regular triangulation (Edelsbrunner 1990: the in-front
// relation of its cells is acyclic) and the random first edge keeps it short
// on adversarial layouts. The step bound only guards against a corrupted
// structure.
std::uint32_t Builder::locate(std::uint32_t p, std::uint32_t start, std::uint32_t& rng, bool& inside) const {
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
        if (is_virtual(f / 3)) {
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

void Builder::run() {
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
  for (std::uint32_t p = 0; p < n; ++p) {
    if (p == a || p == b || p == c) continue;
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
        continue;
      }
      for (std::uint32_t h : flip13(t, p)) stack_.push_back(h);
      home_ = t;
    } else {
      insert_outside(p, e);
    }
    regularize(p);
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
  std::vector<std::size_t> first(B + 1, 0);
  std::size_t total = 0;
  for (std::size_t b = 0; b < B; ++b) {
    first[b] = total;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t k = at[c * B + b];
      at[c * B + b] = total;
      total += k;
    }
  }
  first[B] = total;
  std::vector<Triangle> out(total);
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
      const std::uint32_t start = prev != kDead ? prev : is_real(hint) ? hint : home_;
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
  constexpr std::size_t kMaxPoints = std::size_t{1} << kIndexBits;
  if (ps.size() > kMaxPoints)
    throw std::invalid_argument("rt2 (cpu): " + std::to_string(ps.size()) + " points exceed the limit of " +
                                std::to_string(kMaxPoints) + " (32-bit half-edge indices)");
  ref::Rt2Stats st;
  std::vector<Triangle> out;
  with_threads(opt.threads, [&] {
    StageClock clock(opt.times);
    const pred::StaticFilter f = parallel_static_filter(ps, {});
    const std::vector<Index> order = brio_order(ps, opt.brio_min);
    std::vector<Vtx> pts(order.size());
    par_for(order.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const Index i = order[k];
        pts[k] = {{ps.point(i)[0], ps.point(i)[1]}, ps.weight(i), i};
      }
    });
    clock.mark("sort");
    Builder B(std::move(pts), f, st);
    B.run();
    clock.mark("insert");
    out = B.output();
    clock.mark("output");
    if (witness) {
      B.witness(*witness);
      clock.mark("witness");
    }
  });
  st.rounds = 1;
  if (stats) *stats = st;
  return out;
}

}  // namespace flipflop::cpu

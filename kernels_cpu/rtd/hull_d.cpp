// hull_d.cpp — the d-dimensional convex hull by beneath–beyond insertion in
// Quickhull's order, and its certifier (hull_d.hpp: the algorithm, why the
// answer is the canonical hull, the certificate's conditions).
#include "kernels_cpu/rtd/hull_d.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "kernels_cpu/brio.hpp"
#include "kernels_cpu/parallel.hpp"
#include "predicates/plane_form.hpp"
#include "predicates/predicates.hpp"
#include "predicates/staged.hpp"
#include "kernels_cpu/rtd/ridge_table.hpp"
#include "kernels_cpu/rtd/visible_region.hpp"
#include "reference/certify/ball_test.hpp"
#include "reference/certify/inner_box.hpp"
#include "reference/dimension.hpp"
#include "reference/rtd/convex_surface.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::cpu {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr int kMaxHullDim = 9;  // orientations of up to 10 points (predicates.hpp: lambda_sign; k > 8 host-only)

// The plane forms the builder and the certifier's walks use (plane_form.hpp:
// an orientation against a fixed tuple as a dot product and a bound): where
// the static filter has bounds, D <= 7, StaticPlaneForm (one determinant's
// top levels in plain doubles to build, decided against the per-input static
// bound `sbound`); beyond, PlaneForm (D minors in ErrDouble to build, its own
// running bound). form_decides: the form's sign of orient_d(tuple, x), 0
// where it cannot tell.
template <int D>
inline constexpr bool kStaticForm = D <= 7;
template <int D>
using FormOf = std::conditional_t<kStaticForm<D>, pred::StaticPlaneForm<(kStaticForm<D> ? D : 2)>, pred::PlaneForm<D>>;
template <int D>
int form_decides(const FormOf<D>& form, const double* x, double sbound) {
  if constexpr (kStaticForm<D>) {
    return form.sign(x, sbound);
  } else {
    (void)sbound;
    return form.sign(x);
  }
}

// An axis-aligned box strictly inside the convex region the facets bound
// (hull_d's convention: orient_d(facet, x) < 0 inside), or an empty box: the
// bounding box half-extents `half` about `centre`, scaled by the largest
// factor (at most 1, times 0.99) that the facets' plane forms, read in
// floating point, leave inside every facet; then verified exactly
// (certify::detail::box_inside: per facet, the corners that can maximise its
// orientation, by its form and, where undecided, the exact unperturbed
// predicate; a facet with more than 2^6 corners to test, none). Where the
// verification fails: no box. forms: the facets' plane
// forms (built here, in parallel). That the facets bound a convex region is
// the caller's to know (a certified surface).
template <int D>
certify::BoxTest<D> propose_box(const PointSet& ps, const std::vector<std::vector<Index>>& facets,
                                const double* centre, const double* half, std::vector<pred::PlaneForm<D>>& forms) {
  const std::size_t h = facets.size();
  forms.resize(h);
  par_for(h, 512, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      const double* t[D];
      for (int c = 0; c < D; ++c) t[c] = ps.point(facets[k][static_cast<std::size_t>(c)]);
      forms[k] = pred::PlaneForm<D>(t);
    }
  });
  // inside a facet: N . (centre - t_0) + scale Σ |N_j| half_j < 0
  double scale = 1.0;
  for (std::size_t k = 0; k < h && scale > 0; ++k) {
    const pred::PlaneForm<D>& f = forms[k];
    double at = 0.0, reach = 0.0;
    for (int c = 0; c < D; ++c) at += f.n[c] * (centre[c] - f.base[c]), reach += std::fabs(f.n[c]) * half[c];
    if (reach == 0.0) continue;  // a flat facet (or underflow): box_inside decides
    scale = at < 0.0 ? std::min(scale, -at / reach) : 0.0;
  }
  scale *= 0.99;
  certify::BoxTest<D> box;
  if (!(scale > 0.0) || !std::isfinite(scale)) return box;
  for (int c = 0; c < D; ++c) box.lo[c] = centre[c] - scale * half[c], box.hi[c] = centre[c] + scale * half[c];
  const bool inside = certify::detail::box_inside<D>(h, box, par_for_range(512), [&](std::size_t k) {
    const double* t[D];
    for (int c = 0; c < D; ++c) t[c] = ps.point(facets[k][static_cast<std::size_t>(c)]);
    return certify::detail::NegativeInsideFormTest<D>(forms[k], t);
  }, std::min(D, 6));
  return inside ? box : certify::BoxTest<D>{};
}

// A ball strictly inside the convex region the facets bound (hull_d's
// convention), or an empty one: centred at `centre`, radius 0.999999 times
// the smallest floating-point distance from it to a facet's hyperplane
// (forms: the facets' plane forms, propose_box's), then verified per facet
// by PlaneForm::ball_below (the whole closed ball strictly on the facet's
// inner side, certainly; no exact stage: a facet it cannot decide, one of
// zero volume included, leaves no ball). A point that BallTest says is
// strictly inside (ball_test.hpp: |p - c|^2 + 2^-990 < r^2 (1 - 2^-40) in
// floating point, the rounding of a sum of D <= 9 squares far inside that
// margin, so |p - c| < r exactly) is strictly inside every facet, exactly
// and under the perturbation, as for the box. Radii outside [2^-400, 2^400]:
// no ball (the squares stay normal and finite). Normal input fills a ball,
// not a box: 2x10^4 normal 5D points, 10,863 walks with the box alone.
// That the facets bound a convex region is the caller's to know.
template <int D>
certify::BallTest<D> propose_ball(const std::vector<pred::PlaneForm<D>>& forms, const double* centre) {
  certify::BallTest<D> ball;  // limit 0: empty
  double dmin = HUGE_VAL;
  for (const pred::PlaneForm<D>& f : forms) {
    double nn = 0.0;
    for (int c = 0; c < D; ++c) nn += f.n[c] * f.n[c];
    const double d = -f.value(centre) / std::sqrt(nn);
    if (!(d >= 0.0)) return ball;  // NaN, a flat facet, or the centre outside
    dmin = std::min(dmin, d);
  }
  const double r = 0.999999 * dmin;
  if (!(r >= 0x1p-400 && r <= 0x1p400)) return ball;
  const bool inside = certify::detail::smallest_failing(forms.size(), par_for_range(512), [&](std::size_t k) {
    return !forms[k].ball_below(centre, r);
  }) == forms.size();
  if (!inside) return ball;
  for (int c = 0; c < D; ++c) ball.s[c] = centre[c];
  ball.limit = r * r * (1.0 - 0x1p-40);
  return ball;
}

template <int D>
class HullBuilder {
 public:
  HullBuilder(const PointSet& ps, HullDStats& st) : ps_(&ps), st_(&st), n_(ps.size()) {
    f_ = pred::StaticFilter::for_points(ps.coords.data(), n_, D);
    sbound_ = f_.bound(D + 1, false);
  }

  void run() {
    start();
    grow();
  }

  // In-place insertion (HullDIncremental::add): ps holds the points given
  // so far followed by new ones (the builder keeps only indices, so it reads
  // coordinates from ps during this call only). Each new point q is assigned
  // to a live facet it sees, or discarded as inside (a point inside stays
  // inside: the hull only grows); then the outside sets are emptied as in
  // run() (a point outside a convex polytope sees one of its facets).
  //
  // Finding the facet: with a point v discarded earlier (strictly inside the
  // hull under SoS), the cones (v, f) over the live facets fill the space
  // once (the hull is star-shaped from v); a visibility walk through them —
  // side j of cone (v, f) is f with f_j replaced by v, f_j's side positive
  // (orient(f[j:=v], f_j) = -orient(f, v) > 0) — from the last point's cone
  // ends in the cone that holds q, and q is outside the hull iff it sees
  // that cone's facet: assigned to it, or discarded. A walk past its cap, or
  // no such v yet: every live facet is tested (the first seen).
  void add(const PointSet& ps, HullDStats& st) {
    ps_ = &ps;
    st_ = &st;
    const std::size_t first = n_;
    n_ = ps.size();
    f_ = pred::StaticFilter::for_points(ps.coords.data(), n_, D);
    // the union's bound: no smaller, so still valid for the forms built
    // before (their entries are differences of its coordinates)
    sbound_ = f_.bound(D + 1, false);
    std::vector<std::uint32_t> live;
    for (std::uint32_t f = 0; f < fv_.size() / D; ++f)
      if (alive(f)) live.push_back(f);
    // the facets' forms point into the previous call's coordinates: to the
    // same values in ps (the points given so far come first in it)
    if constexpr (kStatic)
      for (std::uint32_t f : live) ff_[f].base = ps.point(fv_[static_cast<std::size_t>(f) * D]);
    std::uint32_t cur = live.front();
    const std::size_t cap = 4 * live.size() + 100;
    for (Index q = static_cast<Index>(first); q < n_; ++q) {
      long found = -1;
      int from = -1;  // the side just crossed: q behind it (walk_orphan says why), not tested
      for (std::size_t steps = 0; inner_ != kNone && steps < cap && found < 0; ++steps) {
        int cand[D], nc = 0;
        for (int j = 0; j < D; ++j) {
          if (j == from) continue;
          Index t[D];
          for (int c = 0; c < D; ++c) t[c] = c == j ? inner_ : fv_[cur * D + static_cast<std::uint32_t>(c)];
          if (orient_of(t, q) < 0) cand[nc++] = j;
        }
        if (nc == 0) {
          found = static_cast<long>(cur);
          break;
        }
        rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
        const std::uint32_t l = fn_[cur * D + static_cast<std::uint32_t>(cand[(rng_ >> 32) % static_cast<std::uint64_t>(nc)])];
        cur = l / D;
        from = static_cast<int>(l % D);
      }
      if (found < 0) {
        if (!assign(q, live)) discard(q);
      } else if (sees(cur, q)) {
        if (out_[cur].empty()) work_.push_back(cur);
        out_[cur].push_back(q);
      } else {
        discard(q);
      }
    }
    grow();
  }

  // Seeded (HullDIncremental's second constructor) instead of run(): the
  // hull of ps given as its facets in this builder's convention
  // (orient_d(facet, x) < 0 inside), each with its static form, and their
  // neighbours (nb[k][j]: the facet across the ridge opposite vertex j of
  // facet k), checked to be a closed surface of d-simplices glued along
  // their ridges; false where they are not. Facet k takes slot k. No
  // outside sets (every point of ps is on the hull or inside it) and no
  // inner point yet: add() tests every live facet for its new points until
  // it discards one.
  bool seed(const std::vector<std::vector<Index>>& facets, const std::vector<std::vector<Index>>& nb) {
    const std::size_t m = facets.size();
    if ((m + 1) * D >= kNone) throw std::length_error("hull (cpu): more facets than 32-bit links hold");
    // the slots take_slot() would make, at once
    fv_.resize(m * D);
    fn_.assign(m * D, kNone);
    out_.resize(m);
    nrm_.resize(m);
    if constexpr (kStatic) ff_.resize(m);
    mark_.assign(m, 0);
    for (std::size_t k = 0; k < m; ++k)
      for (int c = 0; c < D; ++c) fv_[k * D + static_cast<std::size_t>(c)] = facets[k][static_cast<std::size_t>(c)];
    // the link across ridge j of facet k: g = nb[k][j] holds every vertex of
    // k but the j-th, and one more at position i; g's link i names k back
    for (std::uint32_t k = 0; k < m; ++k)
      for (int j = 0; j < D; ++j) {
        const Index g = nb[k][static_cast<std::size_t>(j)];
        if (g >= m || g == k) return false;
        const int i = across(&fv_[static_cast<std::size_t>(k) * D], &fv_[static_cast<std::size_t>(g) * D], D, j);
        if (i < 0 || nb[g][static_cast<std::size_t>(i)] != k) return false;
        fn_[k * D + static_cast<std::uint32_t>(j)] = g * D + static_cast<std::uint32_t>(i);
      }
    if constexpr (kStatic)
      par_for(m, 512, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t k = lo; k < hi; ++k) ff_[k] = facet_form(static_cast<std::uint32_t>(k), kNone, 0);
      });
    return true;
  }

  std::vector<std::vector<Index>> facets() const {
    std::vector<std::vector<Index>> out;
    for (std::uint32_t f = 0; f < fv_.size() / D; ++f)
      if (alive(f)) out.emplace_back(fv_.begin() + static_cast<std::ptrdiff_t>(f) * D,
                                     fv_.begin() + static_cast<std::ptrdiff_t>(f + 1) * D);
    return out;
  }

 private:
  const PointSet* ps_;  // the points of the current call (run or add)
  HullDStats* st_;
  std::size_t n_;
  pred::StaticFilter f_;
  std::vector<Index> fv_;                      // D vertices per facet slot (kNone: dead)
  std::vector<std::uint32_t> fn_;              // D links per slot: D t + k across the ridge opposite vertex j
  std::vector<std::vector<Index>> out_;        // outside set per slot
  std::vector<std::array<double, D + 1>> nrm_; // floating-point hyperplane per slot (heuristic)
  // Plane forms (FormOf above). Static ones (D <= 7) are cheap to build:
  // every facet gets its own (ff_, built with the facet) and every visible
  // facet with a few orphans its cone sides. PlaneForms (beyond): only for
  // visible facets with many orphans. An undecided form asks the predicate.
  static constexpr bool kStatic = kStaticForm<D>;
  using Form = FormOf<D>;
  double sbound_ = HUGE_VAL;  // f_.bound(D + 1, false): the static forms' bound
  std::vector<Form> ff_;      // kStatic: per slot, the facet's form
  std::vector<std::uint32_t> mark_, free_, work_;
  std::uint32_t stamp_ = 0;
  Index inner_ = kNone;  // a point found inside the hull (discard())
  RidgeTable<D - 1> ridges_;  // match()'s
  static constexpr std::size_t kAhead = 8;  // prefetch distance in the point loops (points)
  // orphans of one insertion walked in parallel pieces from this many on
  // (measured on 2 cores, 8 seeds: 10^5 normal 4D points about 8 % less
  // build time than walking every orphan in turn; 2x10^4 5D points, within
  // the noise)
  static constexpr std::size_t kParallelOrphans = 4096, kOrphanPiece = 1024;
  // during one insertion: per visible facet slot, the first of its D+1 plane
  // forms in vis_forms_ (kNone: none); insert() says when it has them.
  // Measured (callgrind, the build's instructions, one thread): PlaneForm
  // from 32 D orphans, among 2..64 D (4D 10^5, 5D 2x10^4 normal points);
  // static forms from 2 orphans, among 1, 2, 4, 8, 16 and static forms only
  // from 32 D on with PlaneForm beyond (5D normal 276 M, 4D normal 301 M):
  // 5D normal 2x10^4 270 M, 4D normal 10^5 268 M, 5D cube 10^5 1982 M.
  static constexpr std::size_t kFormMin = kStatic ? 2 : 32 * D;
  std::vector<std::uint32_t> vis_form_at_;
  std::vector<Form> vis_forms_;
  std::uint64_t rng_ = 0x2545F4914F6CDD1Dull;

  bool alive(std::uint32_t f) const { return fv_[static_cast<std::size_t>(f) * D] != kNone; }

  // q is inside the hull (for good: the hull only grows); the first such
  // point is add()'s centre of cones
  void discard(Index q) {
    if (inner_ == kNone) inner_ = q;
  }

  // Quickhull's loop: while some facet has an outside set, insert its
  // furthest point. The facets are taken first in, first out, as Qhull
  // walks its facet list (new facets appended): the older facets' furthest
  // points, the more extreme ones, go in before the new facets' outside sets
  // are split further, so fewer points are made apexes only to be buried.
  // Measured against last in, first out (one build each, AMD EPYC 2-core VM,
  // medians of 6-300 runs): 2x10^4 normal 5D points 964 -> 731 apexes,
  // 72,747 -> 53,707 facets created, build 54.7 -> 38 ms; 1296 normal 4D
  // points 1.85 -> 1.22 ms; 10^5 in the 5D cube 418 -> 312 ms; 10^5 normal
  // 4D points, four seeds, 27-37 -> 20-30 ms (one seed even); 2000 normal 6D
  // points 110 -> 95 ms, 800 normal 7D points 580 -> 551 ms. A slot may be
  // queued again after reuse: then its entries are visited in turn, and those
  // that find it dead or without outside points skip it.
  void grow() {
    for (std::size_t head = 0; head < work_.size(); ++head) {
      const std::uint32_t f = work_[head];
      if (!alive(f) || out_[f].empty()) continue;
      insert(f);
    }
    work_.clear();
  }

  // orient_d(t, q) of a d-tuple and a point (SoS, never 0 for distinct ids)
  int orient_of(const Index* t, Index q) {
    ++st_->tests;
    return orient_tuple(t, q);
  }
  // the same, uncounted (no state written: safe from parallel pieces)
  int orient_tuple(const Index* t, Index q) const {
    pred::PointId id[D + 1];
    const double* p[D + 1];
    for (int j = 0; j < D; ++j) {
      id[j] = t[j];
      p[j] = ps_->point(t[j]);
    }
    id[D] = q;
    p[D] = ps_->point(q);
    return pred::lambda_sign_staged<D + 1>(&f_, id, p, static_cast<const double*>(nullptr));
  }
  // q strictly beyond facet f (by its form first, kStatic)
  bool sees(std::uint32_t f, Index q) {
    if constexpr (kStatic) {
      ++st_->tests;
      return form_sign(&ff_[f], &fv_[static_cast<std::size_t>(f) * D], q) > 0;
    }
    return orient_of(&fv_[static_cast<std::size_t>(f) * D], q) > 0;
  }

  // The plane form of facet f's tuple with vertex j replaced by p (j =
  // kNone: the facet itself).
  Form facet_form(std::uint32_t f, std::uint32_t j, Index p) const {
    const double* t[D];
    for (int c = 0; c < D; ++c)
      t[c] = ps_->point(static_cast<std::uint32_t>(c) == j ? p : fv_[static_cast<std::size_t>(f) * D + static_cast<std::size_t>(c)]);
    return Form(t);
  }
  // the static form of the same points with the opposite orientation:
  // every term of its value negated, exactly (so the same bound holds)
  static Form negated(Form f) {
    if constexpr (kStatic)
      for (double& m : f.minor) m = -m;
    return f;
  }
  // orient_d(t, q) by the form of the tuple t (null: none), the predicate
  // where it is undecided; uncounted, safe from parallel pieces
  int form_sign(const Form* form, const Index* t, Index q) const {
    if (form)
      if (const int s = form_decides<D>(*form, ps_->point(q), sbound_)) return s;
    return orient_tuple(t, q);
  }

  // the floating-point hyperplane n . x + c of facet f (heuristic only)
  void plane(std::uint32_t f) {
    const double* a = ps_->point(fv_[static_cast<std::size_t>(f) * D]);
    double m[(D - 1) * D];
    for (int r = 1; r < D; ++r) {
      const double* b = ps_->point(fv_[static_cast<std::size_t>(f) * D + static_cast<std::size_t>(r)]);
      for (int c = 0; c < D; ++c) m[(r - 1) * D + c] = b[c] - a[c];
    }
    auto& h = nrm_[f];
    double c0 = 0.0;
    for (int k = 0; k < D; ++k) {
      double sub[(D - 1) * (D - 1) + 1];
      int q = 0;
      for (int r = 0; r < D - 1; ++r)
        for (int c = 0; c < D; ++c)
          if (c != k) sub[q++] = m[r * D + c];
      h[static_cast<std::size_t>(k)] = (k % 2 ? -1.0 : 1.0) * (D > 1 ? det_gauss_double(sub, D - 1) : 1.0);
      c0 -= h[static_cast<std::size_t>(k)] * a[k];
    }
    h[D] = c0;
  }
  double height(std::uint32_t f, Index q) const {
    const auto& h = nrm_[f];
    const double* x = ps_->point(q);
    double s = h[D];
    for (int k = 0; k < D; ++k) s += h[static_cast<std::size_t>(k)] * x[k];
    return std::fabs(s);
  }

  std::uint32_t take_slot() {
    if (!free_.empty()) {
      const std::uint32_t s = free_.back();
      free_.pop_back();
      return s;
    }
    const std::size_t s = fv_.size() / D;
    if ((s + 1) * D >= kNone) throw std::length_error("hull (cpu): more facets than 32-bit links hold");
    fv_.resize((s + 1) * D, kNone);
    fn_.resize((s + 1) * D, kNone);
    out_.emplace_back();
    nrm_.emplace_back();
    if constexpr (kStatic) ff_.emplace_back();
    mark_.push_back(0);
    return static_cast<std::uint32_t>(s);
  }

  // Links the ridges of the facets `fs` (all but position skip[k] of fs[k],
  // -1: none) among themselves: each such ridge is met exactly twice, and
  // two halves are the same ridge when they hold the same vertices (sorted;
  // a ridge has D-1 vertices, or D-2 besides the apex of a cone). Matched in
  // a hash table (ridge_table.hpp; a sort of the halves took a sixth of a 5D
  // hull's time).
  void match(const std::vector<std::uint32_t>& fs, const std::vector<int>& skip) {
    ridges_.begin(fs.size() * D);
    for (std::size_t k = 0; k < fs.size(); ++k)
      for (int j = 0; j < D; ++j) {
        if (j == skip[k]) continue;
        typename RidgeTable<D - 1>::Key key;
        key.fill(kNone);
        int c = 0;
        for (int q = 0; q < D; ++q)
          if (q != j && q != skip[k]) key[static_cast<std::size_t>(c++)] = fv_[fs[k] * D + static_cast<std::uint32_t>(q)];
        RidgeTable<D - 1>::sort(key);  // the kNone entries last
        const std::uint32_t link = fs[k] * D + static_cast<std::uint32_t>(j);
        const std::uint32_t other = ridges_.offer(key, link);
        if (other != RidgeTable<D - 1>::kOpen) fn_[link] = other, fn_[other] = link;
      }
    if (!ridges_.end()) throw std::logic_error("hull (cpu): the horizon is not a closed ridge cycle");
  }

  // Adds q to facet f's outside set when f is the first of `fs` q sees;
  // false when q sees none of them.
  bool assign(Index q, const std::vector<std::uint32_t>& fs) {
    for (std::uint32_t f : fs)
      if (sees(f, q)) {
        if (out_[f].empty()) work_.push_back(f);
        out_[f].push_back(q);
        return true;
      }
    return false;
  }

  void start() {
    // d+1 points far apart in floating point (Gram–Schmidt); any d+1 do
    // under SoS, the choice only steers the work
    std::vector<Index> s;
    // (the arg-max scans in parallel pieces; par_argmax: the first of the
    // best, as a sequential scan)
    s.push_back(par_argmax(n_, [&](Index i) { return -ps_->point(i)[0]; }));
    std::vector<std::array<double, D>> basis;
    for (int k = 1; k <= D; ++k) {
      const double* o = ps_->point(s[0]);
      // the squared length of i - o off the basis (-inf: not finite); about 0
      // for the points chosen already, which are taken again only where
      // every other point is as degenerate (below: then the first unchosen)
      auto residual = [&](Index i) {
        std::array<double, D> v;
        for (int c = 0; c < D; ++c) v[static_cast<std::size_t>(c)] = ps_->point(i)[c] - o[c];
        for (const auto& b : basis) {
          double dot = 0.0;
          for (int c = 0; c < D; ++c) dot += v[static_cast<std::size_t>(c)] * b[static_cast<std::size_t>(c)];
          for (int c = 0; c < D; ++c) v[static_cast<std::size_t>(c)] -= dot * b[static_cast<std::size_t>(c)];
        }
        double len = 0.0;
        for (int c = 0; c < D; ++c) len += v[static_cast<std::size_t>(c)] * v[static_cast<std::size_t>(c)];
        return std::isfinite(len) ? len : -HUGE_VAL;
      };
      Index arg = par_argmax(n_, residual);
      // every length overflowed (magnitudes near DBL_MAX), or no point off the
      // span in floating point: any unchosen point (SoS decides the rest)
      if (!(residual(arg) > -HUGE_VAL) || std::find(s.begin(), s.end(), arg) != s.end())
        for (arg = 0; std::find(s.begin(), s.end(), arg) != s.end(); ++arg) {
        }
      s.push_back(arg);
      std::array<double, D> v;
      double len = 0.0;
      for (int c = 0; c < D; ++c) {
        v[static_cast<std::size_t>(c)] = ps_->point(arg)[c] - o[c];
      }
      for (const auto& b : basis) {
        double dot = 0.0;
        for (int c = 0; c < D; ++c) dot += v[static_cast<std::size_t>(c)] * b[static_cast<std::size_t>(c)];
        for (int c = 0; c < D; ++c) v[static_cast<std::size_t>(c)] -= dot * b[static_cast<std::size_t>(c)];
      }
      for (int c = 0; c < D; ++c) len += v[static_cast<std::size_t>(c)] * v[static_cast<std::size_t>(c)];
      len = std::sqrt(len);
      for (int c = 0; c < D; ++c) v[static_cast<std::size_t>(c)] = len > 0 && std::isfinite(len) ? v[static_cast<std::size_t>(c)] / len : 0.0;
      basis.push_back(v);
    }
    // positive: orient_d(s) > 0
    {
      pred::PointId id[D + 1];
      const double* p[D + 1];
      for (int j = 0; j <= D; ++j) id[j] = s[static_cast<std::size_t>(j)], p[j] = ps_->point(s[static_cast<std::size_t>(j)]);
      if (pred::lambda_sign_staged<D + 1>(&f_, id, p, static_cast<const double*>(nullptr)) < 0) std::swap(s[0], s[1]);
    }
    std::vector<std::uint32_t> fs;
    std::vector<int> skip;
    for (int i = 0; i <= D; ++i) {
      const std::uint32_t f = take_slot();
      int c = 0;
      for (int j = 0; j <= D; ++j)
        if (j != i) fv_[f * D + static_cast<std::uint32_t>(c++)] = s[static_cast<std::size_t>(j)];
      // orient(facet, s_i) = (-1)^(D-i) orient(s): negative wanted
      if ((D - i) % 2 == 0) std::swap(fv_[f * D], fv_[f * D + 1]);
      fs.push_back(f);
      skip.push_back(-1);
    }
    match(fs, skip);
    std::vector<char> used(n_, 0);
    for (Index x : s) used[x] = 1;
    // every point is tested against these D+1 facets: by their plane forms
    std::vector<Form> form;
    for (std::uint32_t f : fs) form.push_back(facet_form(f, kNone, 0));
    if constexpr (kStatic)
      for (std::size_t k = 0; k < fs.size(); ++k) ff_[fs[k]] = form[k];
    // in parallel pieces (a point's facet depends on that point alone: the
    // first of fs it sees), then the outside sets filled in index order, as
    // the sequential loop would
    std::vector<std::uint8_t> at(n_, 0);  // k + 1: beyond fs[k] first; 0: inside (or a corner)
    const std::size_t pieces = (n_ + kChunk - 1) / kChunk;
    std::vector<std::uint64_t> tests(pieces, 0);
    par_for(pieces, 1, [&](std::size_t plo, std::size_t phi) {
      for (std::size_t c = plo; c < phi; ++c)
        for (Index q = static_cast<Index>(c * kChunk); q < std::min<std::size_t>(n_, (c + 1) * kChunk); ++q) {
          if (used[q]) continue;
          for (std::size_t k = 0; k < fs.size(); ++k) {
            ++tests[c];
            if (form_sign(&form[k], &fv_[static_cast<std::size_t>(fs[k]) * D], q) > 0) {
              at[q] = static_cast<std::uint8_t>(k + 1);
              break;
            }
          }
        }
    });
    for (std::uint64_t t : tests) st_->tests += t;
    {
      std::array<std::size_t, D + 2> count{};
      for (Index q = 0; q < n_; ++q) ++count[at[q]];
      for (std::size_t k = 0; k < fs.size(); ++k) out_[fs[k]].reserve(count[k + 1]);
    }
    for (Index q = 0; q < n_; ++q) {
      if (used[q]) continue;
      if (at[q] == 0) {
        discard(q);
        continue;
      }
      const std::uint32_t f = fs[at[q] - 1u];
      if (out_[f].empty()) work_.push_back(f);
      out_[f].push_back(q);
    }
  }

  void insert(std::uint32_t f0) {
    // the apex: the furthest point of f0's outside set in floating point
    // (the plane only for the facets that pick an apex: a few percent of
    // those created)
    plane(f0);
    std::vector<Index>& pts = out_[f0];
    std::size_t best = 0;
    double hb = -1.0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      if (k + kAhead < pts.size()) __builtin_prefetch(ps_->point(pts[k + kAhead]));
      const double h = height(f0, pts[k]);
      if (h > hb || !(hb >= 0)) hb = h, best = k;
    }
    const Index p = pts[best];
    ++st_->apexes;
    // the facets p sees: breadth-first from f0 (marks: in = stamp, out = stamp + 1)
    stamp_ += 2;
    if (stamp_ < 2) {  // wrapped: clear the stamps
      std::fill(mark_.begin(), mark_.end(), 0u);
      stamp_ = 2;
    }
    struct Horizon {
      std::uint32_t f;
      int i;
      std::uint32_t link;
    };
    std::vector<Horizon> hz;
    std::vector<std::uint32_t> vis;
    visible_region<D>(f0, fn_, mark_, stamp_, vis, [&](std::uint32_t g) { return sees(g, p); },
                      [&](std::uint32_t f, int i, std::uint32_t l) { hz.push_back({f, i, l}); });
    // the cone: facet f with vertex i replaced by p, one per horizon ridge,
    // in slots other than the visible facets' (read below, freed after)
    std::vector<std::uint32_t> fresh;
    std::vector<int> skip;
    for (const Horizon& h : hz) {
      const std::uint32_t u = take_slot();
      for (int j = 0; j < D; ++j)
        fv_[u * D + static_cast<std::uint32_t>(j)] = j == h.i ? p : fv_[h.f * D + static_cast<std::uint32_t>(j)];
      fn_[u * D + static_cast<std::uint32_t>(h.i)] = h.link;
      fn_[h.link] = u * D + static_cast<std::uint32_t>(h.i);
      mark_[u] = 0;
      if constexpr (kStatic) ff_[u] = facet_form(u, kNone, 0);
      fresh.push_back(u);
      skip.push_back(h.i);
    }
    st_->created += fresh.size();
    match(fresh, skip);
    // the points of the visible facets (p aside): each inside the grown hull
    // or beyond one of the new facets (header). A visible facet with at
    // least kFormMin orphans gets the plane forms of its D cone sides f[j:=p]
    // and of itself, which its orphans' walks test again and again (a test
    // with a form is a dot product; to build one costs a determinant's top
    // levels, or D determinants of D-1 rows in ErrDouble for a PlaneForm).
    // A side over a horizon ridge is the tuple of the new facet over it (the
    // same vertices in the same order): a copy of that facet's form. A side
    // over a ridge between two visible facets is the other's side over it
    // with the opposite orientation (walk_orphan: adjacent facets orient
    // their common ridge oppositely): its form negated, where built before.
    // Static forms only: PlaneForm's sides (8D, 9D, visible facets of 32 D
    // orphans or more, which no test input reaches) are each built, as before.
    // (callgrind, the build's instructions: 5D normal 2x10^4 272 -> 268 M,
    // 5D cube 10^5 1994 -> 1968 M; most forms built are the facets' own)
    if (vis_form_at_.size() < mark_.size()) vis_form_at_.resize(mark_.size(), kNone);
    vis_forms_.clear();
    for (std::uint32_t f : vis) vis_form_at_[f] = kNone;
    for (std::uint32_t f : vis) {
      if (out_[f].size() < kFormMin) continue;
      const auto at = static_cast<std::uint32_t>(vis_forms_.size());
      for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(D); ++j) {
        const std::uint32_t l = fn_[f * D + j], g = l / D;
        if (mark_[g] != stamp_) {
          if constexpr (kStatic) {
            vis_forms_.push_back(ff_[fn_[l] / D]);
          } else {
            vis_forms_.push_back(facet_form(f, j, p));
          }
        } else if (kStatic && vis_form_at_[g] != kNone) {
          vis_forms_.push_back(negated(vis_forms_[vis_form_at_[g] + l % D]));
        } else {
          vis_forms_.push_back(facet_form(f, j, p));
        }
      }
      vis_form_at_[f] = at;
      if constexpr (kStatic) {
        vis_forms_.push_back(ff_[f]);
      } else {
        vis_forms_.push_back(facet_form(f, kNone, 0));
      }
    }
    std::size_t orphans = 0;
    for (std::uint32_t f : vis) orphans += out_[f].size();
    if (orphans >= kParallelOrphans) {
      place_orphans_in_parallel(vis, orphans, p, fresh);
    } else {
      for (std::uint32_t f : vis) {
        const std::vector<Index>& o = out_[f];
        // the orphans' coordinates lie scattered in memory: fetched ahead
        for (std::size_t k = 0; k < o.size(); ++k) {
          if (k + kAhead < o.size()) __builtin_prefetch(ps_->point(o[k + kAhead]));
          if (o[k] != p) {
            std::uint64_t tests = 0;
            settle(o[k], walk_orphan(o[k], f, p, rng_, tests), fresh);
            st_->tests += tests;
          }
        }
      }
    }
    for (std::uint32_t f : vis) {
      for (int j = 0; j < D; ++j) fv_[f * D + static_cast<std::uint32_t>(j)] = kNone;
      out_[f].clear();
      out_[f].shrink_to_fit();
      free_.push_back(f);
    }
    st_->removed += vis.size();
  }

  // q lay beyond the visible facet f. The grown hull adds to the old one the
  // simplices conv(f' ∪ p) over the visible facets f'; a visibility walk
  // through them from conv(f ∪ p) ends either inside one — every side
  // (p, ridge) on q's side and q beyond f' itself: q is inside, discarded —
  // or by crossing a side over a horizon ridge, which is the new facet u over
  // it (the same tuple f'[j := p]), so q sees u and is assigned to it. Both
  // conclusions are sound on any path; a walk that does not conclude (q
  // behind f', or the step cap) falls back to testing every new facet
  // (settle()). Whether q is inside does not depend on the path, only which
  // new facet it is assigned to. Reads the structure only (its tests counted
  // in `tests`, its random choices from `rng`): the parallel pieces call it.
  static constexpr std::uint32_t kInside = kNone, kUndecided = kNone - 1;
  std::uint32_t walk_orphan(Index q, std::uint32_t f, Index p, std::uint64_t& rng, std::uint64_t& tests) const {
    const std::uint32_t in = stamp_;
    // cur's cone side j (j = D: cur itself) by a form where there is one
    auto test = [&](std::uint32_t cur, int j, const Index* t) {
      ++tests;
      const std::uint32_t at = vis_form_at_[cur];
      if (at != kNone) return form_sign(&vis_forms_[at + static_cast<std::uint32_t>(j)], t, q);
      if constexpr (kStatic)
        if (j == D) return form_sign(&ff_[cur], t, q);
      return orient_tuple(t, q);
    };
    std::uint32_t cur = f;
    // whether q is beyond cur (known for f): asked only where the walk
    // stops, the one place it decides something (it was tested at every
    // step before: 16-19 % of a 5D build's tests, 8-11 % in 4D)
    bool beyond_known = true;
    // the side just crossed (-1: none yet): cur's side `from` is the same
    // hyperplane (its ridge and p) as the side of the facet left behind that
    // q was beyond, with the opposite orientation (adjacent facets orient
    // their common ridge oppositely), so q is behind it: not tested, as the
    // cavity kernel's walk does
    int from = -1;
    for (std::size_t steps = 0; steps < 64; ++steps) {
      rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
      const int r = static_cast<int>((rng >> 32) % static_cast<std::uint64_t>(D));
      int exit = -1;
      for (int k = 0; k < D && exit < 0; ++k) {
        const int j = (r + k) % D;
        if (j == from) continue;
        Index t[D];
        for (int c = 0; c < D; ++c) t[c] = c == j ? p : fv_[cur * D + static_cast<std::uint32_t>(c)];
        if (test(cur, j, t) > 0) exit = j;
      }
      if (exit < 0) {
        if (!beyond_known && test(cur, D, &fv_[cur * D]) <= 0) break;
        return kInside;  // inside conv(cur ∪ p): inside the grown hull
      }
      const std::uint32_t l = fn_[cur * D + static_cast<std::uint32_t>(exit)];
      const std::uint32_t g = l / D;
      if (mark_[g] != in) return fn_[l] / D;  // a horizon ridge: the new facet over it
      cur = g;
      from = static_cast<int>(l % D);
      beyond_known = false;
    }
    return kUndecided;
  }
  // q's place after its walk: the new facet u's outside set, or discarded,
  // or (undecided) the first new facet it sees, or discarded when none
  void settle(Index q, std::uint32_t u, const std::vector<std::uint32_t>& fresh) {
    if (u == kInside) {
      discard(q);
    } else if (u == kUndecided) {
      if (!assign(q, fresh)) discard(q);
    } else {
      if (out_[u].empty()) work_.push_back(u);
      out_[u].push_back(q);
    }
  }
  // The orphans of the visible facets `vis` (p aside) walked in parallel
  // pieces of kOrphanPiece (each its own random sequence: the walks only read
  // the structure), then settled in their sequential order: the same outside
  // sets as one walk after the other, up to which new facet an outside point
  // joins (header: the answer does not depend on it).
  void place_orphans_in_parallel(const std::vector<std::uint32_t>& vis, std::size_t orphans, Index p,
                                 const std::vector<std::uint32_t>& fresh) {
    std::vector<Index> qs;
    std::vector<std::uint32_t> from;
    qs.reserve(orphans), from.reserve(orphans);
    for (std::uint32_t f : vis)
      for (Index q : out_[f])
        if (q != p) qs.push_back(q), from.push_back(f);
    std::vector<std::uint32_t> to(qs.size());
    const std::size_t pieces = (qs.size() + kOrphanPiece - 1) / kOrphanPiece;
    std::vector<std::uint64_t> tests(pieces, 0);
    par_for(pieces, 1, [&](std::size_t plo, std::size_t phi) {
      for (std::size_t c = plo; c < phi; ++c) {
        std::uint64_t rng = brio::splitmix64(c ^ rng_) | 1;
        const std::size_t end = std::min(qs.size(), (c + 1) * kOrphanPiece);
        for (std::size_t k = c * kOrphanPiece; k < end; ++k) {
          if (k + kAhead < end) __builtin_prefetch(ps_->point(qs[k + kAhead]));
          to[k] = walk_orphan(qs[k], from[k], p, rng, tests[c]);
        }
      }
    });
    for (std::uint64_t t : tests) st_->tests += t;
    ++st_->parallel_batches;
    for (std::size_t k = 0; k < qs.size(); ++k) settle(qs[k], to[k], fresh);
  }
};

// ---- the certifier ---------------------------------------------------------------

struct Certifier {
  const PointSet& ps;
  int d;
  pred::StaticFilter filter;
  int orient(const Index* t, Index x) const {
    pred::PointId id[kMaxHullDim + 1];
    const double* p[kMaxHullDim + 1];
    for (int j = 0; j < d; ++j) id[j] = t[j], p[j] = ps.point(t[j]);
    id[d] = x, p[d] = ps.point(x);
    return pred::lambda_sign(&filter, d + 1, id, p, nullptr);
  }
};

std::string tuple_str(const Index* t, int k) {
  std::string o = "(";
  for (int i = 0; i < k; ++i) o += (i ? "," : "") + std::to_string(t[i]);
  return o + ")";
}

// The walk of hull_d_problem's "points-inside" condition, for the points
// `order` (Morton order): each q walks through the cones (v, f) of the
// certified star-shaped surface — side j of cone (v, f) is the hyperplane of
// f with f_j replaced by v, and f_j's side is positive there
// (orient(f[j:=v], f_j) = -orient(f, v) > 0) — to the cone that holds it (a
// scan of every cone where the walk does not settle), then q must lie
// strictly inside that cone's facet. The cones hold the space once (the
// surface is star-shaped from v), so the cone reached, and the verdict, do
// not depend on the walk's path.
//
// Speed: every side and facet orientation is a PlaneForm (plane_form.hpp:
// the orientation as a linear form with a proven bound), built on first use
// by the thread that claims it (an atomic state per form; a thread that
// finds one being built asks the predicate itself) and shared by the walks
// of every point; an undecided form falls back to the exact SoS predicate.
// The points are walked in pieces (at most kChunk) in parallel (par_for: the
// caller's thread count), each piece from cone 0 with its own random
// sequence; the first failing point in `order` is reported, so the message
// does not depend on the thread count. Without forms (more than 2^21 of
// them), the predicate alone.
// facet_forms (may be empty): the facets' own plane forms, built already
// (certify_points: the inner box's), used for the slots j = D.
template <int D>
std::string points_inside(const Certifier& ck, const std::vector<std::vector<Index>>& facets,
                          const std::vector<std::uint32_t>& nb, Index v,
                          const std::vector<Index>& order, const std::vector<pred::PlaneForm<D>>& facet_forms) {
  const std::size_t h = facets.size();
  const std::size_t slots = h * (D + 1);  // slot k (D+1) + j: side j of cone k; j = D: facet k itself
  const bool cache = slots <= (std::size_t{1} << 21);
  // the forms (FormOf above; static ones are sound here: v and the facets'
  // vertices are input points)
  using Form = FormOf<D>;
  const double sbound = ck.filter.bound(D + 1, false);
  std::vector<Form> form(cache ? slots : 0);
  std::unique_ptr<std::atomic<std::uint8_t>[]> state(cache ? new std::atomic<std::uint8_t>[slots] : nullptr);
  for (std::size_t i = 0; cache && i < slots; ++i) state[i].store(0, std::memory_order_relaxed);
  // A slot's state: below `lazy` - 1 the number of its uses so far (each
  // asks the predicate); the next use builds its form. A static form costs
  // about one predicate call to build: at once. A PlaneForm: at once where
  // the points are many per cone (10^5 normal 4D points: 82), from the 16th
  // use on where they are few (2x10^4 normal 5D points: 2.8 per cone, 37,000
  // forms had been built for 20,000 walks). Measured on 2 cores, certifier
  // CPU time: 5D 17 % less with the threshold 16 (8: 14 %, never: 19 %); 4D
  // within the noise with 16, 25 % more without forms. Static forms at once
  // instead (callgrind, hull_d_problem's instructions, one thread): 2x10^4
  // normal 5D points 213 -> 139 M, 10^5 in the 5D cube 1705 -> 1036 M,
  // 10^5 normal 4D points 92 -> 79 M.
  constexpr std::uint8_t kBuilding = 254, kReady = 255;
  const int lazy = kStaticForm<D> || order.size() >= 16 * h ? 1 : 16;
  // orient_d of cone k's side j (j < D) or facet k (j = D) and point q
  auto orient = [&](std::size_t k, int j, Index q) {
    Index t[D];
    for (int c = 0; c < D; ++c) t[c] = c == j ? v : facets[k][static_cast<std::size_t>(c)];
    if (j == D && !facet_forms.empty()) {
      if (const int s = facet_forms[k].sign(ck.ps.point(q))) return s;
    } else if (cache) {
      const std::size_t slot = k * (D + 1) + static_cast<std::size_t>(j);
      std::uint8_t st = state[slot].load(std::memory_order_acquire);
      if (st + 1 < lazy) {
        state[slot].compare_exchange_strong(st, static_cast<std::uint8_t>(st + 1), std::memory_order_relaxed);
      } else if (st + 1 == lazy && state[slot].compare_exchange_strong(st, kBuilding, std::memory_order_acq_rel)) {
        const double* p[D];
        for (int c = 0; c < D; ++c) p[c] = ck.ps.point(t[c]);
        form[slot] = Form(p);
        tsan::released(&state[slot]);  // std::atomic is not instrumented here (.ci/tsan.ignorelist)
        state[slot].store(kReady, std::memory_order_release);
        st = kReady;
      }
      if (st == kReady) {
        tsan::acquired(&state[slot]);
        if (const int s = form_decides<D>(form[slot], ck.ps.point(q), sbound)) return s;
      }
    }
    return ck.orient(t, q);
  };
  // pieces of at most kChunk points, at least 16 of them down to 256 points
  // each: 2x10^4 points in kChunk pieces made three, two of them on one
  // of two threads
  const std::size_t chunk = std::clamp<std::size_t>(order.size() / 16, 256, kChunk);
  const std::size_t pieces = (order.size() + chunk - 1) / chunk;
  std::vector<std::size_t> failed_at(pieces, order.size());
  std::vector<std::string> why(pieces);
  const std::size_t cap = 4 * h + 100;
  par_for(pieces, 1, [&](std::size_t plo, std::size_t phi) {
    for (std::size_t piece = plo; piece < phi; ++piece) {
      std::uint64_t rng = brio::splitmix64(piece) | 1;
      std::size_t cur = 0;
      for (std::size_t at = piece * chunk; at < std::min(order.size(), (piece + 1) * chunk); ++at) {
        const Index q = order[at];
        long found = -1;
        for (std::size_t steps = 0; steps < cap && found < 0; ++steps) {
          // the first side q is beyond, from a random one on: crossed
          rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
          const int r = static_cast<int>((rng >> 11) % static_cast<std::uint64_t>(D));
          int exit = -1;
          for (int k = 0; k < D && exit < 0; ++k) {
            const int j = (r + k) % D;
            if (orient(cur, j, q) < 0) exit = j;
          }
          if (exit < 0) {
            found = static_cast<long>(cur);
            break;
          }
          cur = nb[cur * D + static_cast<std::size_t>(exit)];
        }
        if (found < 0) {  // the walk did not settle: the cone that holds q by a scan
          for (std::size_t k = 0; k < h && found < 0; ++k) {
            bool in = true;
            for (int j = 0; j < D && in; ++j) in = orient(k, j, q) > 0;
            if (in) found = static_cast<long>(k);
          }
          if (found < 0) {
            failed_at[piece] = at;
            why[piece] = "points-inside: point " + std::to_string(q) + " lies in no cone from point " + std::to_string(v);
            break;
          }
          cur = static_cast<std::size_t>(found);
        }
        if (orient(cur, D, q) >= 0) {
          failed_at[piece] = at;
          why[piece] = "points-inside: point " + std::to_string(q) +
                       " is not a vertex and not strictly inside the facet " + tuple_str(facets[cur].data(), D);
          break;
        }
      }
    }
  });
  for (std::size_t piece = 0; piece < pieces; ++piece)
    if (failed_at[piece] < order.size()) return why[piece];
  return {};
}

// hull_d_problem's "points-inside" condition for every point that is not a
// vertex (nor v): after the surface is certified closed, convex and
// star-shaped from v. An inner box first (reference/certify/inner_box.hpp):
// a point strictly inside a box that lies strictly inside every facet is
// strictly inside the hull, exactly and under the perturbation, and needs no
// walk. The box: propose_box's, from the points' bounding box about the
// vertices' mean. Only where the points outnumber the facets: the facets'
// forms are built for it (and passed on to the walks, which would build most
// of them anyway).
template <int D>
std::string certify_points(const Certifier& ck, const std::vector<std::vector<Index>>& facets,
                           const std::vector<std::uint32_t>& nb, Index v, const std::vector<char>& vertex,
                           HullDCertifyStats* stats) {
  const PointSet& ps = ck.ps;
  const std::size_t n = ps.size(), h = facets.size();
  std::size_t vertices = 0;
  for (char x : vertex) vertices += x != 0;
  std::vector<pred::PlaneForm<D>> forms;
  certify::BoxTest<D> box;
  certify::BallTest<D> ball;
  if (n - vertices >= h) {
    const std::array<double, 2 * D> bb = brio::bounding_box<D>(ps);  // lo, then hi
    double mean[D] = {}, half[D];
    for (Index q = 0; q < n; ++q)
      if (vertex[q])
        for (int c = 0; c < D; ++c) mean[c] += ps.point(q)[c];
    for (int c = 0; c < D; ++c)
      mean[c] /= static_cast<double>(vertices), half[c] = 0.5 * (bb[static_cast<std::size_t>(D + c)] - bb[static_cast<std::size_t>(c)]);
    box = propose_box<D>(ps, facets, mean, half, forms);
    ball = propose_ball<D>(forms, mean);
  }
  // the other points: a visibility walk in the cones (v, f) (points_inside),
  // in Morton order of their bounding box so that consecutive walks start
  // near their target
  std::vector<Index> order =
      par_select(n, [&](std::size_t q) {
        return !vertex[q] && q != v && !box.strictly_inside(ps.point(q)) && !ball.strictly_inside(ps.point(q));
      });
  if (stats) {
    stats->box = !box.empty();
    stats->ball = ball.limit > 0.0;
    stats->walked = order.size();
  }
  certify::detail::morton_sort(ps, order, par_for_range());
  return points_inside<D>(ck, facets, nb, v, order, forms);
}

}  // namespace

namespace {

// ps without its weights (the hull has none), validated: d <= 5 by
// ref::validate_rtd_input (RT+1's checks and messages: its boundary is the
// same hull), beyond by the same checks here.
PointSet hull_input(const PointSet& ps) {
  PointSet plain = ps;
  plain.weighted = false;
  plain.weights = Values();
  if (ps.dim <= 5) {
    ref::validate_rtd_input(plain);
  } else {
    if (ps.dim > kMaxHullDim)
      throw std::invalid_argument("hull: points of dimension 2.." + std::to_string(kMaxHullDim) + ", got " +
                                  std::to_string(ps.dim));
    for (double c : ps.coords)
      if (!std::isfinite(c)) throw std::invalid_argument("hull: a coordinate is not finite");
    if (std::string why = dimension_problem(plain); !why.empty()) throw std::invalid_argument(why);
  }
  return plain;
}

// A HullBuilder<D> behind HullDIncremental's dimension-free interface.
struct AnyHull {
  virtual ~AnyHull() = default;
  virtual void add(const PointSet& ps, HullDStats& st) = 0;
  virtual std::vector<std::vector<Index>> facets() const = 0;
};

template <int D>
struct HullOf final : AnyHull {
  HullBuilder<D> b;
  using Facets = std::vector<std::vector<Index>>;
  HullOf(const PointSet& ps, HullDStats& st, const Facets* seed, const Facets* nb) : b(ps, st) {
    if (!seed)
      b.run();
    else if (!b.seed(*seed, *nb))
      throw std::invalid_argument("hull (cpu): the seed facets and neighbours are not a closed surface of simplices");
  }
  void add(const PointSet& ps, HullDStats& st) override { b.add(ps, st); }
  std::vector<std::vector<Index>> facets() const override { return b.facets(); }
};

// seed, nb: the hull's facets and their neighbours (HullDIncremental's
// second constructor), or null to build it
std::unique_ptr<AnyHull> build_hull(const PointSet& plain, HullDStats& st,
                                    const std::vector<std::vector<Index>>* seed = nullptr,
                                    const std::vector<std::vector<Index>>* nb = nullptr) {
  switch (plain.dim) {
    case 2: return std::make_unique<HullOf<2>>(plain, st, seed, nb);
    case 3: return std::make_unique<HullOf<3>>(plain, st, seed, nb);
    case 4: return std::make_unique<HullOf<4>>(plain, st, seed, nb);
    case 5: return std::make_unique<HullOf<5>>(plain, st, seed, nb);
    case 6: return std::make_unique<HullOf<6>>(plain, st, seed, nb);
    case 7: return std::make_unique<HullOf<7>>(plain, st, seed, nb);
    case 8: return std::make_unique<HullOf<8>>(plain, st, seed, nb);
    default: return std::make_unique<HullOf<9>>(plain, st, seed, nb);
  }
}

}  // namespace

std::vector<std::vector<Index>> hull_d(const PointSet& ps, HullDStats* stats) {
  const PointSet plain = hull_input(ps);
  HullDStats local;
  HullDStats& st = stats ? *stats : local;
  st = HullDStats{};
  return build_hull(plain, st)->facets();
}

struct HullDIncremental::Impl {
  std::unique_ptr<AnyHull> hull;
  HullDStats stats;
  std::size_t size = 0;
  int dim = 0;
  bool broken = false;  // an insertion threw: the state is not a hull any more
};

HullDIncremental::HullDIncremental(const PointSet& ps) : impl_(std::make_unique<Impl>()) {
  const PointSet plain = hull_input(ps);
  impl_->hull = build_hull(plain, impl_->stats);
  impl_->size = ps.size();
  impl_->dim = ps.dim;
}

HullDIncremental::HullDIncremental(const PointSet& ps, const std::vector<std::vector<Index>>& facets,
                                   const std::vector<std::vector<Index>>& neighbors)
    : impl_(std::make_unique<Impl>()) {
  const PointSet plain = hull_input(ps);
  const std::size_t d = static_cast<std::size_t>(ps.dim);
  if (facets.size() < d + 1 || neighbors.size() != facets.size())
    throw std::invalid_argument("hull (cpu): a seed hull needs at least d + 1 facets, each with its neighbours");
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const std::vector<Index>& t = facets[k];
    if (t.size() != d || neighbors[k].size() != d)
      throw std::invalid_argument("hull (cpu): a seed facet needs d vertices and d neighbours");
    for (std::size_t c = 0; c < d; ++c)
      if (t[c] >= ps.size() || std::find(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(c), t[c]) != t.begin() + static_cast<std::ptrdiff_t>(c))
        throw std::invalid_argument("hull (cpu): a seed facet needs d distinct indices of the points");
  }
  impl_->hull = build_hull(plain, impl_->stats, &facets, &neighbors);
  impl_->size = ps.size();
  impl_->dim = ps.dim;
}

HullDIncremental::~HullDIncremental() = default;
HullDIncremental::HullDIncremental(HullDIncremental&&) noexcept = default;
HullDIncremental& HullDIncremental::operator=(HullDIncremental&&) noexcept = default;

void HullDIncremental::add(const PointSet& all) {
  Impl& m = *impl_;
  if (m.broken) throw std::logic_error("hull (cpu): an earlier insertion failed; the hull must be rebuilt");
  if (all.dim != m.dim) throw std::invalid_argument("hull (cpu): the added points' dimension differs from the hull's");
  if (all.size() < m.size)
    throw std::invalid_argument("hull (cpu): add() needs the points given so far followed by the new ones");
  if (all.size() == m.size) return;
  // the points given before were validated (and span R^d): only the new
  // ones are read here, so that an add costs O(new points + hull)
  for (std::size_t i = m.size * static_cast<std::size_t>(m.dim); i < all.coords.size(); ++i)
    if (!std::isfinite(all.coords[i])) throw std::invalid_argument("hull: a coordinate is not finite");
  PointSet plain = all;
  plain.weighted = false;
  plain.weights = Values();
  try {
    m.hull->add(plain, m.stats);
  } catch (...) {
    m.broken = true;
    throw;
  }
  m.size = all.size();
}

std::vector<std::vector<Index>> HullDIncremental::facets() const {
  if (impl_->broken) throw std::logic_error("hull (cpu): an earlier insertion failed; the hull must be rebuilt");
  return impl_->hull->facets();
}

std::size_t HullDIncremental::size() const { return impl_->size; }

HullDStats HullDIncremental::stats() const { return impl_->stats; }

std::string hull_d_problem(const PointSet& ps, const std::vector<std::vector<Index>>& facets, HullDCertifyStats* stats) {
  const int d = ps.dim;
  const std::size_t n = ps.size();
  if (d < 2 || d > kMaxHullDim) return "input-dimension: d must be 2.." + std::to_string(kMaxHullDim);
  if (facets.size() < static_cast<std::size_t>(d + 1))
    return "facet-indices: " + std::to_string(facets.size()) + " facets, a hull in R^" + std::to_string(d) +
           " has at least " + std::to_string(d + 1);
  std::vector<char> vertex(n, 0);
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const auto& f = facets[k];
    if (f.size() != static_cast<std::size_t>(d)) return "facet-indices: facet " + std::to_string(k) + " has " +
                                                            std::to_string(f.size()) + " vertices, not " + std::to_string(d);
    for (std::size_t a = 0; a < f.size(); ++a) {
      if (f[a] >= n) return "facet-indices: facet " + std::to_string(k) + " names point " + std::to_string(f[a]);
      for (std::size_t b = 0; b < a; ++b)
        if (f[a] == f[b]) return "facet-indices: facet " + tuple_str(f.data(), d) + " repeats a vertex";
      vertex[f[a]] = 1;
    }
  }
  // closed, convex at every ridge, star-shaped from the smallest point that
  // is not a vertex (or the auxiliary centre): convex_surface.hpp
  Index v = 0;
  while (v < n && vertex[v]) ++v;
  std::vector<std::uint32_t> nb;  // nb[k * d + j]: the facet across the ridge opposite vertex j of facet k
  // (its per-ridge and per-facet predicates in parallel pieces of 512)
  const certify::SurfaceCheck r =
      certify::convex_surface(ps, facets, v < n ? v : certify::kAuxiliaryCentre, &nb, par_for_range(512));
  const std::string who = r.auxiliary ? "the vertices' average (auxiliary point " + std::to_string(n) + ")"
                                      : "point " + std::to_string(v) + " (not a vertex)";
  const Certifier ck{ps, d, pred::StaticFilter::for_points(ps.coords.data(), n, d)};
  switch (r.kind) {
    case certify::SurfaceCheck::Kind::ok: break;
    case certify::SurfaceCheck::Kind::not_closed:
      return "closed-surface: the ridge " + tuple_str(r.ridge.data(), d - 1) + " lies in " + std::to_string(r.count) +
             " facet" + (r.count == 1 ? "" : "s");
    case certify::SurfaceCheck::Kind::not_convex:
      return "convex: vertex " + std::to_string(r.point) + " of facet " + tuple_str(facets[r.other].data(), d) +
             " is not strictly inside its neighbour " + tuple_str(facets[r.facet].data(), d);
    case certify::SurfaceCheck::Kind::outside:
      return "star-shaped: " + who + " is not strictly inside the facet " + tuple_str(facets[r.facet].data(), d);
    case certify::SurfaceCheck::Kind::winds:
      return "star-shaped: the facets wind " + std::to_string(r.count) + " times around " + who +
             " (the vertical ray up from it crosses " + std::to_string(r.count) + " of them)";
    case certify::SurfaceCheck::Kind::no_centre:
      // every point a vertex and a hull too thin for the rounded average:
      // every vertex against every facet
      for (const auto& f : facets)
        for (Index x = 0; x < n; ++x)
          if (std::find(f.begin(), f.end(), x) == f.end() && ck.orient(f.data(), x) >= 0)
            return "points-inside: vertex " + std::to_string(x) + " is not strictly inside the facet " +
                   tuple_str(f.data(), d);
      return {};
  }
  if (v == n) return {};  // every point a vertex
  // every other non-vertex point: strictly inside the hull (certify_points)
  switch (d) {
    case 2: return certify_points<2>(ck, facets, nb, v, vertex, stats);
    case 3: return certify_points<3>(ck, facets, nb, v, vertex, stats);
    case 4: return certify_points<4>(ck, facets, nb, v, vertex, stats);
    case 5: return certify_points<5>(ck, facets, nb, v, vertex, stats);
    case 6: return certify_points<6>(ck, facets, nb, v, vertex, stats);
    case 7: return certify_points<7>(ck, facets, nb, v, vertex, stats);
    case 8: return certify_points<8>(ck, facets, nb, v, vertex, stats);
    default: return certify_points<9>(ck, facets, nb, v, vertex, stats);
  }
}

}  // namespace flipflop::cpu

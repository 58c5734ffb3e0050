// instant_flip.cpp — thesis §9.2.1, Algorithm 14, with insertion events for
// the redundant points (see the header).
#include "reference/rtd/instant_flip.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "predicates/predicates.hpp"
#include "predicates/fast.hpp"
#include "predicates/static_filter.hpp"
#include "reference/checked.hpp"
#include "reference/rtd/bistellar_flip.hpp"

namespace flipflop::ref {

namespace {

// A queue entry: a ridge as remembered in T, or a tracked point with the
// simplex containing it (ref.s, ref.gen), and its moving-model data.
struct Entry {
  RidgeMotion motion;
  rtd::RidgeRef ref;
  Index point = rtd::kNoVertex;  // insertion event: the point (= motion.link_b())
  std::uint64_t seq = 0;         // the last tie-break (push order or drawn from tie_seed)
};

// Binary min-heap of entry ids, ordered by failure time (compare_times).
class FailureQueue {
 public:
  explicit FailureQueue(const PerturbationOrder& order) : order_(&order) {}

  void push(Entry e) {
    std::size_t id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      pool_[id] = std::move(e);
    } else {
      id = pool_.size();
      pool_.push_back(std::move(e));
    }
    heap_.push_back(id);
    std::push_heap(heap_.begin(), heap_.end(), Later{this});
  }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  const Entry& top() const { return pool_[heap_.front()]; }
  Entry pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{this});
    const std::size_t id = heap_.back();
    heap_.pop_back();
    free_.push_back(id);
    return std::move(pool_[id]);
  }
  // sign of t(x) - t(y), never 0 (push order breaks exact ties)
  int compare(const Entry& x, const Entry& y) const {
    if (int c = compare_times(x.motion, y.motion, *order_)) return c;
    return x.seq < y.seq ? -1 : (x.seq > y.seq ? 1 : 0);
  }

 private:
  struct Later {  // the heap's "less": x fails later than y
    const FailureQueue* q;
    bool operator()(std::size_t x, std::size_t y) const { return q->compare(q->pool_[x], q->pool_[y]) > 0; }
  };
  const PerturbationOrder* order_;
  std::vector<Entry> pool_;
  std::vector<std::size_t> free_, heap_;
};

RidgeMotion motion_of(const MovingModel& mm, const rtd::TriangulationD& T, rtd::RidgeD r) {
  const rtd::PointTuple s = rtd::points(T, r);
  return ridge_motion(mm, s.data(), s[static_cast<std::size_t>(T.d)],
                      s[static_cast<std::size_t>(T.d) + 1]);
}

std::string ridge_text(const RidgeMotion& m) {
  std::string s = "{";
  for (int i = 0; i < m.d; ++i) s += (i ? " " : "") + std::to_string(m.pts[static_cast<std::size_t>(i)]);
  return s + "} with link {" + std::to_string(m.link_a()) + " " + std::to_string(m.link_b()) + "}";
}

RidgeMotion point_motion_in(const MovingModel& mm, const rtd::TriangulationD& T, std::int32_t s, Index p) {
  return point_motion(mm, T.tuple(s), p);
}

// Exact unperturbed sign at t = 1 of the event determinant of S (d+2 real
// points, C1 = the first d+1, positive): -1 when S is strictly convex there
// (b strictly above the lifted C1), so that no perturbation can make it fail
// in (0, 1). The per-input static filter of U (predicates/static_filter.hpp)
// decides almost every call; the staged filters and exact arithmetic the rest.
template <int K>
int filtered_sign(const pred::StaticFilter& f, const double* const* x, const double* w) {
  if (const int s = pred::static_sign<K>(f, x, w)) return s;
  return pred::semi_static_sign<K>(x, w);
}

int sign_at_u(const pred::StaticFilter& f, const rtd::TriangulationD& T, const std::vector<double>& u,
              const Index* S) {
  const double* x[rtd::kMaxDim + 2];
  double w[rtd::kMaxDim + 2];
  for (int i = 0; i < T.d + 2; ++i) {
    x[i] = T.ps->point(S[i]);
    w[i] = u[S[i]];
  }
  // > 0: b strictly below (reflex); the static and semi-static filters
  // inline (predicates/fast.hpp), the out-of-line stages for the rest
  int s = 0;
  switch (T.d) {
    case 2: s = filtered_sign<4>(f, x, w); break;
    case 3: s = filtered_sign<5>(f, x, w); break;
    case 4: s = filtered_sign<6>(f, x, w); break;
    default: s = filtered_sign<7>(f, x, w); break;
  }
  return s != 0 ? s : pred::lambda_sign(&f, T.d + 2, nullptr, x, w);
}

// Lines 3-5, the filter part, one simplex at a time. For the interior ridges
// of real slot s seen from s (neighbour t > s, real), the static filter of U
// on the determinant of S' = (s_1..s_d, b, s_0), b the vertex of t not in s:
// rows 0..d-1 (s_r - s_0, lifted) are the simplex's, only the last row is
// b's, so the minors of rows 0..d-1 are computed once per simplex and each
// ridge costs one row (top_minors / with_last_row: det_plain's operations in
// det_plain's order, so StaticFilter's bound for d+2 lifted points holds).
// S' is S_F = (f_1..f_d, a, b) up to an even permutation of C1's tuple and
// the cyclic shift of s_0 to the end, d+1 transpositions: det S_F =
// (-1)^(d+1) det S'. Returns the facets i whose ridge is NOT proven strictly
// convex at t = 1 (sign < 0): only those can fail in (0, 1) and go to
// scan_ridge, which decides them exactly — the same ridges, in the same order,
// as scanning every ridge.
void lifted_row(const double* x, double w, const double* x0, double w0, int d, double* row) {
  double lift = 0.0;
  for (int j = 0; j < d; ++j) {
    const double e = x[j] - x0[j];
    row[j] = e;
    lift = (j == 0) ? e * e : lift + e * e;
  }
  row[d] = lift - (w - w0);
}

// The scan is bound by memory: per ridge the neighbour's vertex tuple and the
// opposite vertex's point, per simplex its d+1 points, at random places.
// `xu` holds each point's coordinates and weight u together (one load where
// there were two), and the loop prefetches kAhead slots ahead: their
// neighbours' tuples and their own points.
template <int D>
unsigned uncertain_facets(double bound, const rtd::TriangulationD& T, const double* xu, std::int32_t s) {
  constexpr int N = D + 1;
  const Index* v = T.verts.data() + static_cast<std::size_t>(s) * N;
  const double* x0 = xu + static_cast<std::size_t>(v[0]) * N;
  double t[N * N];
  for (int r = 0; r < D; ++r) {
    const double* x = xu + static_cast<std::size_t>(v[r + 1]) * N;
    lifted_row(x, x[D], x0, x0[D], D, t + r * N);
  }
  double minor[N];
  pred::filter_detail::top_minors<N>(t, minor);
  unsigned uncertain = 0;
  for (int i = 0; i <= D; ++i) {
    const std::int32_t n = T.nbrs[static_cast<std::size_t>(s) * N + static_cast<std::size_t>(i)];
    if (n < s) continue;
    const Index* vn = T.verts.data() + static_cast<std::size_t>(n) * N;
    Index b = rtd::kNoVertex;
    bool virtual_side = false;
    for (int k = 0; k < N; ++k) {
      const Index x = vn[k];
      virtual_side |= x == T.n;
      bool shared = false;
      for (int m = 0; m < N; ++m) shared |= x == v[m];
      if (!shared) b = x;
    }
    if (virtual_side) continue;  // a boundary ridge: convex by default
    double last[N];
    const double* xb = xu + static_cast<std::size_t>(b) * N;
    lifted_row(xb, xb[D], x0, x0[D], D, last);
    const double det = pred::filter_detail::with_last_row<N>(minor, last);
    const double det_sf = (D % 2 == 1) ? det : -det;
    if (!(-det_sf > bound)) uncertain |= 1u << i;
  }
  return uncertain;
}

constexpr std::int32_t kAhead = 8;

template <int D>
void prefetch_slot(const rtd::TriangulationD& T, const double* xu, std::int32_t s) {
  constexpr int N = D + 1;
  if (s >= static_cast<std::int32_t>(T.slots())) return;
  const Index* v = T.verts.data() + static_cast<std::size_t>(s) * N;
  for (int i = 0; i < N; ++i) {
    const std::int32_t n = T.nbrs[static_cast<std::size_t>(s) * N + static_cast<std::size_t>(i)];
    if (n > s) __builtin_prefetch(T.verts.data() + static_cast<std::size_t>(n) * N);
    if (v[i] < T.n) __builtin_prefetch(xu + static_cast<std::size_t>(v[i]) * N);
  }
}

using ForRange = decltype(InstantFlipOptions::for_range);

// The uncertain facets of every real slot (0 for dead and virtual slots);
// every slot's entry depends on nothing else, so the pieces of for_range may
// run in any order and concurrently.
template <int D>
void uncertain_all(double bound, const rtd::TriangulationD& T, const std::vector<double>& u,
                   const ForRange& for_range, std::vector<std::uint8_t>& out) {
  constexpr int N = D + 1;
  const PointSet& ps = *T.ps;
  std::vector<double> xu(static_cast<std::size_t>(T.n) * N);
  const auto slots = static_cast<std::int32_t>(T.slots());
  out.assign(static_cast<std::size_t>(slots), 0);
  auto pack = [&](std::size_t lo, std::size_t hi) {
    for (std::size_t p = lo; p < hi; ++p) {
      double* x = xu.data() + p * N;
      for (int j = 0; j < D; ++j) x[j] = ps.point(p)[j];
      x[D] = u[p];
    }
  };
  auto scan = [&](std::size_t lo, std::size_t hi) {
    for (auto s = static_cast<std::int32_t>(lo); s < static_cast<std::int32_t>(hi); ++s) {
      prefetch_slot<D>(T, xu.data(), std::min(s + kAhead, static_cast<std::int32_t>(hi)));
      if (!T.alive[static_cast<std::size_t>(s)] || rtd::is_virtual_simplex(T, s)) continue;
      out[static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(uncertain_facets<D>(bound, T, xu.data(), s));
    }
  };
  if (for_range) {
    for_range(T.n, pack);
    for_range(static_cast<std::size_t>(slots), scan);
  } else {
    pack(0, T.n);
    scan(0, static_cast<std::size_t>(slots));
  }
}

void uncertain_all(double bound, const rtd::TriangulationD& T, const std::vector<double>& u,
                   const ForRange& for_range, std::vector<std::uint8_t>& out) {
  switch (T.d) {
    case 2: return uncertain_all<2>(bound, T, u, for_range, out);
    case 3: return uncertain_all<3>(bound, T, u, for_range, out);
    case 4: return uncertain_all<4>(bound, T, u, for_range, out);
    default: return uncertain_all<5>(bound, T, u, for_range, out);
  }
}

std::uint64_t mix(std::uint64_t x) {  // splitmix64
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

InstantFlipStats instant_flip(rtd::TriangulationD& T, const std::vector<double>& w,
                              const std::vector<double>& u, const InstantFlipOptions& options) {
  if (T.ps == nullptr) throw std::invalid_argument("instant flip: triangulation without points");
  const MovingModel mm(*T.ps, w, u);
  const PerturbationOrder order =
      options.order.size() == 0 ? PerturbationOrder::identity(mm.size()) : options.order;
  if (order.size() != mm.size())
    throw std::invalid_argument("instant flip: the perturbation order has " +
                                std::to_string(order.size()) + " points, the input " +
                                std::to_string(mm.size()));
  rtd::PointBuckets own;
  if (options.points == nullptr) own = rtd::track_all(T);
  rtd::PointBuckets& B = options.points ? *options.points : own;
  InstantFlipTrace* trace = options.trace;
  auto note = [&](std::int32_t s) {
    if (!trace) return;
    trace->slots.push_back(s);
    trace->gens.push_back(T.gen[static_cast<std::size_t>(s)]);
  };
  InstantFlipStats st;
  FailureQueue q(order);
  std::uint64_t seq = 0;
  auto next_seq = [&] { return options.tie_seed ? mix(options.tie_seed ^ mix(seq++)) : seq++; };
  auto push = [&](RidgeMotion m, rtd::RidgeRef ref, Index point) {
    q.push(Entry{std::move(m), ref, point, next_seq()});
    ++st.pushes;
    st.max_queue = std::max<std::uint64_t>(st.max_queue, q.size());
  };
  auto push_ridge = [&](RidgeMotion m, rtd::RidgeD r) { push(std::move(m), rtd::remember(T, r), rtd::kNoVertex); };
  auto push_point = [&](RidgeMotion m, std::int32_t s, Index p) {
    rtd::RidgeRef ref;
    ref.s = s;
    ref.gen = T.gen[static_cast<std::size_t>(s)];
    push(std::move(m), ref, p);
  };

  // Lines 1-5 (and the precondition: every interior ridge convex and every
  // tracked point above its simplex at t = 0). Without check_start, what is
  // strictly convex at t = 1 cannot fail in (0, 1) and is skipped.
  const auto d2 = static_cast<std::size_t>(T.d) + 2;
  const bool need_u = !options.check_start || trace != nullptr;
  const pred::StaticFilter filter_u =
      need_u ? pred::StaticFilter::for_points(T.ps->coords.data(), T.n, T.d, u.data()) : pred::StaticFilter();
  auto scan_ridge = [&](rtd::RidgeD r) {
    if (need_u) {
      const rtd::PointTuple S = rtd::points(T, r);
      if (sign_at_u(filter_u, T, u, S.data()) < 0) {
        if (!options.check_start) return;
      } else {
        note(r.s);  // may be flat at t = 1: the caller's verification looks at it
      }
    }
    RidgeMotion m = motion_of(mm, T, r);
    ++st.initial_ridges;
    if (options.check_start && perturbed_sign(m, 0, order) < 0)
      throw std::invalid_argument(
          "instant flip: the start triangulation is not strongly regular for W under the "
          "perturbation order (ridge " +
          ridge_text(m) + (exact_sign(m, 0) == 0 ? " is flat" : " is reflex") +
          "; see find_perturbation_order, thesis Algorithm 15)");
    if (fails_in_unit_interval(m, order)) push_ridge(std::move(m), r);
  };
  // with check_start every ridge is examined; without, the static filter of U
  // proves most ridges strictly convex at t = 1 a simplex at a time
  const bool skip_convex = need_u && !options.check_start;
  std::vector<std::uint8_t> uncertain_of;
  if (skip_convex) uncertain_all(filter_u.bound(T.d + 2, true), T, u, options.for_range, uncertain_of);
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    const unsigned uncertain = skip_convex ? uncertain_of[static_cast<std::size_t>(s)] : ~0u;
    if (uncertain == 0) continue;
    if (!T.alive[static_cast<std::size_t>(s)] || rtd::is_virtual_simplex(T, s)) continue;
    for (int i = 0; i <= T.d; ++i) {
      if (!((uncertain >> i) & 1u)) continue;
      const std::int32_t t = T.neighbor(s, i);
      // each interior ridge once, from its smaller slot; boundary ridges
      // (a virtual side) are convex by default
      if (t < s || rtd::is_virtual_simplex(T, t)) continue;
      scan_ridge(rtd::RidgeD{s, i});
    }
  }
  for (Index p = 0; p < T.n; ++p) {
    if (!B.is_tracked(p)) continue;
    const std::int32_t s = B.slot_of(p);
    if (need_u) {
      Index S[rtd::kMaxDim + 2];
      for (int i = 0; i <= T.d; ++i) S[i] = T.vertex(s, i);
      S[d2 - 1] = p;
      if (sign_at_u(filter_u, T, u, S) < 0) {
        if (!options.check_start) continue;
      } else {
        note(s);
      }
    }
    RidgeMotion m = point_motion_in(mm, T, s, p);
    ++st.initial_points;
    if (options.check_start && perturbed_sign(m, 0, order) < 0)
      throw std::invalid_argument("instant flip: point " + std::to_string(p) +
                                  " is not a vertex but lies below the lifted simplex containing it "
                                  "at t = 0 under the perturbation order (T is not RT(S+W))");
    if (fails_in_unit_interval(m, order)) push_point(std::move(m), s, p);
  }

  // After a flip: the points of the destroyed simplices (`moved`, plus a
  // removed vertex) go to the created ones; their events and those of the
  // boundary ridges (lines 10-12) enter the queue.
  std::vector<Index> moved;
  auto after_flip = [&](const Entry& e, const rtd::FlipResult& fr) {
    (void)e;  // the current time, for the checked build's Lemma 9.10 checks
    if (fr.removed != rtd::kNoVertex) moved.push_back(fr.removed);
    rtd::redistribute(T, B, moved, fr.created);
    st.moved_points += moved.size();
    for (Index p : moved) {
      const std::int32_t s = B.slot_of(p);
      RidgeMotion m = point_motion_in(mm, T, s, p);
      if (fails_in_unit_interval(m, order)) {
        FF_CHECK(compare_times(e.motion, m, order) <= 0,
                 "instant flip: a tracked point enters before the current time (Lemma 9.4)");
        push_point(std::move(m), s, p);
      }
    }
    moved.clear();
    for (std::int32_t c : fr.created) note(c);
    for (rtd::RidgeD g : fr.boundary) {  // lines 10-12
      if (!rtd::interior(T, g)) continue;
      // Strictly convex at t = 1 (exact sign): it cannot fail in (now, 1).
      // Its determinant is affine in t plus a constant perturbation, negative
      // just after the current time (T is regular then, Lemma 9.10) and at
      // t = 1, hence on the whole interval — fails_in_unit_interval would say
      // no; the static filter of U decides this for most new ridges at a
      // fraction of the moving model's cost.
      if (need_u) {
        const rtd::PointTuple S = rtd::points(T, g);
        if (sign_at_u(filter_u, T, u, S.data()) < 0) continue;
      }
      RidgeMotion m = motion_of(mm, T, g);
      if (fails_in_unit_interval(m, order)) {
        FF_CHECK(compare_times(e.motion, m, order) <= 0,
                 "instant flip: a new ridge fails before the current time (Lemma 9.10)");
        push_ridge(std::move(m), g);
      }
    }
  };

  // Lines 6-12.
  std::vector<Entry> deferred;  // unflippable minima waiting for simultaneous events
  while (!q.empty()) {
    Entry e = q.pop();
    ++st.pops;
    if (e.point != rtd::kNoVertex) {
      // An insertion event: valid while p is tracked in the same simplex.
      const std::int32_t s = e.ref.s;
      if (!T.alive[static_cast<std::size_t>(s)] || T.gen[static_cast<std::size_t>(s)] != e.ref.gen ||
          B.slot_of(e.point) != s) {
        ++st.stale;
        continue;
      }
      rtd::remove_point(B, e.point);
      rtd::take_points(B, s, moved);
      const rtd::FlipResult fr = rtd::insert_in_simplex(T, s, e.point);  // the 1-(d+1) flip
      ++st.flips[1];
      ++st.inserted_vertices;
      if (options.on_flip) options.on_flip(T, InstantFlipEvent{&e.motion, 1, rtd::kNoVertex, e.point});
      after_flip(e, fr);
    } else {
      const rtd::RidgeD r = rtd::recall(T, e.ref);
      if (!r.valid()) {  // line 8: no longer in T with the same link
        ++st.stale;
        continue;
      }
      if (!deferred.empty() && compare_times(deferred.front().motion, e.motion, order) != 0)
        throw std::logic_error("instant flip: ridge " + ridge_text(deferred.front().motion) +
                               " fails first but is unflippable (degenerate coordinates, "
                               "thesis §9.2.2)");
      const rtd::FlipShape shape = rtd::flip_shape(T, r);
      if (!shape.flippable) {
        ++st.deferred;
        deferred.push_back(std::move(e));
        continue;
      }
      for (int j = 0; j < shape.nu; ++j) rtd::take_points(B, shape.cur[static_cast<std::size_t>(j)], moved);
      const rtd::FlipResult fr = rtd::flip(T, shape);  // line 9
      ++st.flips[fr.k];
      if (fr.removed != rtd::kNoVertex) ++st.removed_vertices;
      if (options.on_flip) options.on_flip(T, InstantFlipEvent{&e.motion, fr.k, fr.removed, rtd::kNoVertex});
      after_flip(e, fr);
    }
    for (Entry& x : deferred) q.push(std::move(x));  // retry after this event
    deferred.clear();
  }
  if (!deferred.empty())
    throw std::logic_error("instant flip: ridge " + ridge_text(deferred.front().motion) +
                           " fails but is unflippable (degenerate coordinates, thesis §9.2.2)");
  FF_CHECK(rtd::validity_problem(T).empty(), "instant flip: " + rtd::validity_problem(T));
  return st;
}

std::vector<Index> reappearing_points(const rtd::TriangulationD& T, const std::vector<double>& u) {
  const PointSet& ps = *T.ps;
  if (u.size() != ps.size())
    throw std::invalid_argument("reappearing_points: " + std::to_string(ps.size()) +
                                " points but " + std::to_string(u.size()) + " weights");
  std::vector<Index> out;
  std::int32_t hint = rtd::kNone;
  for (Index p = 0; p < T.n; ++p) {
    if (T.is_vertex(p)) continue;
    if (hint == rtd::kNone || !T.alive[static_cast<std::size_t>(hint)]) {
      hint = rtd::kNone;
      for (std::size_t s = 0; s < T.slots(); ++s)
        if (T.alive[s] && !rtd::is_virtual_simplex(T, static_cast<std::int32_t>(s))) {
          hint = static_cast<std::int32_t>(s);
          break;
        }
    }
    const std::int32_t s = rtd::locate(T, p, hint);
    if (rtd::is_virtual_simplex(T, s)) {  // outside conv(T): a vertex of RT(S ⊕ u)
      out.push_back(p);
      continue;
    }
    hint = s;
    // power_d(simplex (positive), p) > 0 iff p's lifted point lies strictly below
    pred::WPt q[rtd::kMaxDim + 2];
    for (int i = 0; i <= T.d; ++i) {
      const Index x = T.vertex(s, i);
      q[i] = pred::WPt{x, ps.point(x), u[x]};
    }
    q[T.d + 1] = pred::WPt{p, ps.point(p), u[p]};
    if (pred::power_d(T.d, q) > 0) out.push_back(p);
  }
  return out;
}

}  // namespace flipflop::ref

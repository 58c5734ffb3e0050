// instant_flip.cpp — thesis §9.2.1, Algorithm 14 (see the header).
#include "reference/rtd/instant_flip.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "predicates/predicates.hpp"
#include "reference/checked.hpp"
#include "reference/rtd/bistellar_flip.hpp"

namespace flipflop::ref {

namespace {

// A queue entry: the ridge as remembered in T and its moving-model data.
struct Entry {
  RidgeMotion motion;
  rtd::RidgeRef ref;
  std::uint64_t seq = 0;  // push order: the last tie-break (same flip)
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
  InstantFlipStats st;
  FailureQueue q(order);
  std::uint64_t seq = 0;
  auto push = [&](RidgeMotion m, rtd::RidgeD r) {
    q.push(Entry{std::move(m), rtd::remember(T, r), seq++});
    ++st.pushes;
    st.max_queue = std::max<std::uint64_t>(st.max_queue, q.size());
  };

  // Lines 1-5 (and the precondition: every interior ridge convex at t = 0).
  for (rtd::RidgeD r : rtd::ridges(T)) {
    if (!rtd::interior(T, r)) continue;  // boundary ridges: convex by default
    RidgeMotion m = motion_of(mm, T, r);
    ++st.initial_ridges;
    if (perturbed_sign(m, 0, order) < 0)
      throw std::invalid_argument(
          "instant flip: the start triangulation is not strongly regular for W under the "
          "perturbation order (ridge " +
          ridge_text(m) + (exact_sign(m, 0) == 0 ? " is flat" : " is reflex") +
          "; see find_perturbation_order, thesis Algorithm 15)");
    if (fails_in_unit_interval(m, order)) push(std::move(m), r);
  }

  // Lines 6-12.
  std::vector<Entry> deferred;  // unflippable minima waiting for simultaneous events
  while (!q.empty()) {
    Entry e = q.pop();
    ++st.pops;
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
    const rtd::FlipResult fr = rtd::flip(T, shape);  // line 9
    ++st.flips[fr.k];
    if (fr.removed != rtd::kNoVertex) ++st.removed_vertices;
    if (options.on_flip) options.on_flip(T, InstantFlipEvent{&e.motion, fr.k, fr.removed});
    for (rtd::RidgeD g : fr.boundary) {  // lines 10-12
      if (!rtd::interior(T, g)) continue;
      RidgeMotion m = motion_of(mm, T, g);
      if (fails_in_unit_interval(m, order)) {
        FF_CHECK(compare_times(e.motion, m, order) <= 0,
                 "instant flip: a new ridge fails before the current time (Lemma 9.10)");
        push(std::move(m), g);
      }
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

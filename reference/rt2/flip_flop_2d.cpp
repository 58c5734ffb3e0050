// flip_flop_2d.cpp — Algorithm 5 (thesis §5.1) on the extended triangulation;
// see flip_flop_2d.hpp.
#include "reference/rt2/flip_flop_2d.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/checked.hpp"

namespace flipflop::ref::ff {

using tri::Edge;
using tri::Quad;
using tri::Shape;
using tri::Triangulation2;

namespace {

constexpr Index kNoVertex = ~Index{0};

// Line 5: x, the labelled vertex of smallest index among {a, b, c, d}. The
// virtual vertex is never labelled.
Index smallest_labelled(const State& s, const Quad& q) {
  Index x = kNoVertex;
  for (Index v : {q.a, q.b, q.c, q.d})
    if (s.labelled[v] && v < x) x = v;
  return x;
}

[[maybe_unused]] std::string qstr(const Triangulation2& T, const Quad& q) {
  auto V = [&](Index x) { return T.is_virtual(x) ? std::string("v") : std::to_string(x); };
  return "edge " + V(q.a) + " " + V(q.b) + " (link " + V(q.c) + " " + V(q.d) + ")";
}

// Checked build, Lemma 5.1: the vertex `a` about to be labelled lies inside the
// triangle of the other three and its lifted point lies above their lifted
// plane, so it is above the lower hull of the four: redundant.
void check_label(const State& s, const Quad& q, Index a) {
  if constexpr (FF_CHECKED) {
    [[maybe_unused]] const Triangulation2& T = s.T;
    FF_CHECK(!T.is_virtual(q.a) && !T.is_virtual(q.b) && !T.is_virtual(q.c) && !T.is_virtual(q.d),
             "a virtual edge is unflippable and locally non-regular: " + qstr(T, q));
    // the other three counter-clockwise: the quadrilateral a d b c without the
    // inner vertex, i.e. (b, c, d) when a is inner and (a, d, c) when b is
    [[maybe_unused]] const Index u = a == q.a ? q.b : q.a, w1 = a == q.a ? q.c : q.d, w2 = a == q.a ? q.d : q.c;
    FF_CHECK(tri::orient(T, u, w1, w2) > 0 && tri::orient(T, u, w1, a) > 0 && tri::orient(T, w1, w2, a) > 0 &&
                 tri::orient(T, w2, u, a) > 0,
             "Lemma 5.1: the labelled vertex is not inside the triangle of the other three, " + qstr(T, q));
    FF_CHECK(tri::power(T, u, w1, w2, a) < 0,
             "Lemma 5.1: the labelled vertex is not above the lifted triangle of the other three, " + qstr(T, q));
  } else {
    (void)s, (void)q, (void)a;
  }
}

}  // namespace

State make_state(Triangulation2 T) {
  State s;
  s.labelled.assign(static_cast<std::size_t>(T.n) + 1, 0);  // line 1: all "unknown"
  s.T = std::move(T);
  return s;
}

Decision decide(const State& s, Edge e, Criteria crit) {
  const Triangulation2& T = s.T;
  const Quad q = tri::quad(T, e);                   // line 5: e = ab, link {c, d}
  const Index x = smallest_labelled(s, q);          // line 5: x
  const tri::EdgeShape shape = tri::classify(T, e);
  const bool use_v = crit != Criteria::d_only, use_d = crit != Criteria::v_only;
  if (shape.shape == Shape::three_one) {            // line 6: a 3-1 edge, a in triangle bcd
    const Index a = shape.inner;                    // line 7
    if (use_d && s.labelled[a]) return {Action::flip31_d, a};                         // line 8
    if (use_v && !tri::locally_regular(T, e)) return {Action::flip31_v, a};           // line 8
    return {};
  }
  if (shape.shape == Shape::two_two) {              // line 11: a ∉ △bcd and b ∉ △acd
    if (x == kNoVertex) {
      if (use_v && !tri::locally_regular(T, e)) return {Action::flip22_v, 0};          // lines 12-13
      return {};
    }
    if (use_d && (x == q.a || x == q.b)) return {Action::flip22_d, 0};                 // lines 14-15
    return {};                                      // x in the link: the D-criterion forbids
  }
  // lines 16-19: unflippable 2-2 edge; a in triangle bcd (Lemma 5.1: a is redundant)
  if (crit != Criteria::combined) return {};  // v_first labels in a pass of its own
  if (!s.labelled[shape.inner] && !tri::locally_regular(T, e)) return {Action::label, shape.inner};
  return {};
}

void apply(State& s, Edge e, const Decision& d, std::vector<std::pair<Index, Index>>* pushed, Rt2Stats* stats) {
  Triangulation2& T = s.T;
  if (d.action == Action::none) return;
  const Quad q = tri::quad(T, e);
  auto push = [&](Index u, Index w) {
    if (pushed) pushed->emplace_back(u, w);
  };
  // checked build: the D-criterion's measure before the flip (Theorem 5.5)
  const bool d_flip = d.action == Action::flip22_d || d.action == Action::flip31_d;
  Index x = kNoVertex;
  [[maybe_unused]] std::uint32_t deg_x_before = 0;
  if constexpr (FF_CHECKED) {
    x = smallest_labelled(s, q);
    if (x != kNoVertex) deg_x_before = T.deg[x];
    FF_CHECK(!d_flip || x != kNoVertex, "a D-flip without a labelled vertex: " + qstr(T, q));
  }
  switch (d.action) {
    case Action::none: break;
    case Action::label: {
      check_label(s, q, d.inner);
      s.labelled[d.inner] = 1;  // line 18
      if (stats) ++stats->labelled_redundant;
      for (Index w : tri::link(T, d.inner)) push(d.inner, w);  // line 19: the edges incident to a
      break;
    }
    case Action::flip31_v:
    case Action::flip31_d: {
      const Index a = d.inner;
      const std::vector<Index> L = tri::link(T, a);  // b, c, d counter-clockwise
      FF_CHECK(L.size() == 3, "3-1 flip of a vertex whose degree is not 3");
      if constexpr (FF_CHECKED) {
        if (d.action == Action::flip31_v) {
          // V-criterion lowers the surface: a^+ lies above the plane of the
          // other three (only real configurations are locally non-regular 3-1)
          FF_CHECK(!T.is_virtual(L[0]) && !T.is_virtual(L[1]) && !T.is_virtual(L[2]),
                   "a locally non-regular 3-1 edge with the virtual vertex: " + qstr(T, q));
          FF_CHECK(tri::power(T, L[0], L[1], L[2], a) < 0,
                   "V-criterion 3-1 flip does not lower the lifted surface: " + qstr(T, q));
        }
      }
      tri::flip31(T, a);  // line 9
      if (stats) {
        ++stats->flips_3_1;
        if (d.action == Action::flip31_d) ++stats->flops;
      }
      push(L[0], L[1]);  // line 9: Q <- {bc, cd, db}
      push(L[1], L[2]);
      push(L[2], L[0]);
      break;
    }
    case Action::flip22_v:
    case Action::flip22_d: {
      [[maybe_unused]] const Edge ne = tri::flip22(T, e);  // lines 13 / 15
      if (stats) {
        ++stats->flips_2_2;
        if (d.action == Action::flip22_d) ++stats->flops;
      }
      if constexpr (FF_CHECKED) {
        if (d.action == Action::flip22_v) {
          // V-criterion lowers the lifted surface: of the two triangulations of
          // the four points the new one is the lower, i.e. the new edge is
          // locally regular (for an edge of v: a real triangle was added).
          FF_CHECK(tri::locally_regular(T, ne), "V-criterion 2-2 flip does not lower the lifted surface: " +
                                                    qstr(T, q));
          FF_CHECK(!T.is_virtual(q.c) && !T.is_virtual(q.d),
                   "V-criterion flipped an edge with one virtual triangle: " + qstr(T, q));
        }
      }
      push(q.a, q.c);  // line 13 / 15: Q <- {ac, bc, ad, bd}
      push(q.b, q.c);
      push(q.a, q.d);
      push(q.b, q.d);
      break;
    }
  }
  if constexpr (FF_CHECKED) {
    const std::string problem = tri::validity_problem(T);
    FF_CHECK(problem.empty(), "after a flip-flop operation on " + qstr(T, q) + ": " + problem);
    if (d_flip) {
      // Theorem 5.5: the D-criterion lowers the degree of the smallest-index
      // labelled vertex of the induced subcomplex (removing it when it is the
      // inner vertex of a 3-1 flip) and no labelled vertex of smaller index
      // is touched (none is in the induced subcomplex by the choice of x).
      FF_CHECK(!T.is_vertex(x) || T.deg[x] < deg_x_before,
               "D-flip did not lower the degree of the smallest-index redundant vertex " + std::to_string(x));
      for ([[maybe_unused]] Index v : {q.a, q.b, q.c, q.d})
        FF_CHECK(!s.labelled[v] || v >= x, "D-flip touched a labelled vertex of smaller index");
    }
    for ([[maybe_unused]] Index v : {q.a, q.b, q.c, q.d})
      FF_CHECK(!T.removed[v] || !T.is_vertex(v), "a removed vertex reappeared");
  }
}

namespace {

// The sequential workflow of Figure 3.1 with a FIFO queue (lines 2-4): pop an
// edge, skip it when it is gone, run the local check, apply.
void drain(State& s, std::deque<std::pair<Index, Index>>& Q, Criteria crit, Rt2Stats* stats) {
  std::vector<std::pair<Index, Index>> pushed;
  while (!Q.empty()) {                  // line 3
    const auto [u, w] = Q.front();      // line 4
    Q.pop_front();
    const Edge e = tri::find_edge(s.T, u, w);
    if (!e.valid()) continue;  // flipped away or its vertex removed since it was pushed
    if (stats) ++stats->candidates;
    const Decision d = decide(s, e, crit);
    if (d.action == Action::none) continue;
    pushed.clear();
    apply(s, e, d, &pushed, stats);
    Q.insert(Q.end(), pushed.begin(), pushed.end());
  }
}

std::deque<std::pair<Index, Index>> all_edges(const State& s) {  // line 2
  const auto E = tri::edges(s.T);
  return {E.begin(), E.end()};
}

// Theorem 5.5's final state, verified: every edge locally regular, nothing
// labelled left (then Theorem 2.2 / §2.2 make the real part RT and the link of
// v the convex hull).
void verify_final(const State& s) {
  for (const auto& [u, w] : tri::edges(s.T)) {
    const Edge e = tri::find_edge(s.T, u, w);
    if (!tri::locally_regular(s.T, e))
      throw std::logic_error("flip-flop ended with a locally non-regular edge " + std::to_string(u) + " " +
                             std::to_string(w));
  }
  for (Index v = 0; v < s.T.n; ++v)
    if (s.labelled[v] && s.T.is_vertex(v))
      throw std::logic_error("flip-flop ended with the labelled vertex " + std::to_string(v));
  FF_CHECK(tri::validity_problem(s.T).empty(), "final triangulation invalid");
}

}  // namespace

void run(State& s, FlipFlopVariant variant, Rt2Stats* stats) {
  if constexpr (FF_CHECKED) {
    const std::string problem = tri::validity_problem(s.T);
    FF_CHECK(problem.empty(), "flip-flop input: " + problem);
  }
  if (variant == FlipFlopVariant::combined) {
    auto Q = all_edges(s);  // line 2
    drain(s, Q, Criteria::combined, stats);
  } else {
    // §5.1, after Algorithm 5: "keep flipping according to the V-criterion
    // first, until no more flips can be done. After that, we can start
    // labeling redundant vertices and use flips due to the D-criterion to
    // remove them. The process is then repeated until all the redundant
    // vertices are identified and removed."
    for (;;) {
      if (stats) ++stats->phases;
      auto Q = all_edges(s);
      drain(s, Q, Criteria::v_only, stats);  // V: 2-2 and 3-1 flips of locally non-regular edges
      std::vector<std::pair<Index, Index>> pushed;
      bool labelled_any = false;
      for (const auto& [u, w] : tri::edges(s.T)) {  // lines 16-18 on every edge
        const Edge e = tri::find_edge(s.T, u, w);
        const Decision d = decide(s, e, Criteria::combined);
        if (d.action == Action::label) {
          apply(s, e, d, &pushed, stats);
          labelled_any = true;
        }
      }
      if (!labelled_any) break;
      std::deque<std::pair<Index, Index>> D(pushed.begin(), pushed.end());
      drain(s, D, Criteria::d_only, stats);  // D: flips that lower the degree of labelled vertices
      for (Index v = 0; v < s.T.n; ++v)
        if (s.labelled[v] && s.T.is_vertex(v))
          throw std::logic_error("flip-flop (V first): the D pass left the labelled vertex " + std::to_string(v));
    }
  }
  verify_final(s);
}

}  // namespace flipflop::ref::ff

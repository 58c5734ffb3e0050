// flip_flop_3d.cpp — Algorithm 6 (thesis §6.2), flip-flop for 3D convex hull,
// on a polyhedron star-shaped w.r.t. a kernel point s; see flip_flop_3d.hpp.
#include "reference/hull3/flip_flop_3d.hpp"

#include <deque>
#include <stdexcept>
#include <string>

#include "predicates/fast.hpp"
#include "predicates/predicates.hpp"
#include "reference/canonical.hpp"
#include "reference/checked.hpp"

namespace flipflop::ref {

namespace ff3 {

using poly::DEdge;
using poly::in_cone;

namespace {

constexpr Index kNoVertex = ~Index{0};

// orient3d(a, b, c, p) of input points under SoS: > 0 when p lies on the inner
// side of (a, b, c) counter-clockwise seen from outside.
int orient(const State& st, Index a, Index b, Index c, Index p) {
  const PointSet& ps = *st.ps;
  return pred::fast::orient3d(st.filter, {a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)}, {p, ps.point(p)});
}

// The induced subcomplex of e = ab (line 5): triangles (a, b, c) and (b, a, d).
struct Quad {
  Index a, b, c, d;
};

Quad quad(const State& st, Index u, Index w) {
  const DEdge e = poly::find_edge(st.P, u, w);
  if (!e.valid())
    throw std::logic_error("flip-flop: " + std::to_string(u) + " " + std::to_string(w) + " is not an edge");
  return {u, w, st.P.apex(e), st.P.apex(st.P.twin(e))};
}

[[maybe_unused]] std::string qstr(const Quad& q) {
  return "edge " + std::to_string(q.a) + " " + std::to_string(q.b) + " (link " + std::to_string(q.c) + " " +
         std::to_string(q.d) + ")";
}

// Line 5: x, the labelled (non-extreme) vertex of smallest index in {a, b, c, d}.
Index smallest_labelled(const State& st, const Quad& q) {
  Index x = kNoVertex;
  for (Index v : {q.a, q.b, q.c, q.d})
    if (st.labelled[v] && v < x) x = v;
  return x;
}

// §6.1: e is reflex w.r.t. s when d and s lie on different sides of △abc.
// Every triangle faces away from s (s is beneath it, §6.4.1's first
// technique), so this is orient3d(a, b, c, d) < 0 — without referring to s.
bool reflex(const State& st, const Quad& q) { return orient(st, q.a, q.b, q.c, q.d) < 0; }

// s inside the tetrahedron abcd: s on the same side of each face as the
// opposite vertex. With o = orient3d(a, b, c, d) (never 0 under SoS):
// orient3d(a,b,c,s) = side(a,b,c), orient3d(a,b,s,d) = -side(a,b,d),
// orient3d(a,s,c,d) = side(a,c,d), orient3d(s,b,c,d) = -side(b,c,d), all o.
bool s_in_tetrahedron(const State& st, const Quad& q) {
  const KernelPoint& s = *st.s;
  const int o = orient(st, q.a, q.b, q.c, q.d);
  return s.side(q.a, q.b, q.c) == o && -s.side(q.a, q.b, q.d) == o && s.side(q.a, q.c, q.d) == o &&
         -s.side(q.b, q.c, q.d) == o;
}

// Lines 6-7: e is a 3-1 edge when an endpoint of degree 3 lies inside the
// cone of the triangle of the other three (its link): returns it, or
// kNoVertex. (For a of degree 3 the three planes through s and the link edges
// are the sides of star(a)'s cones, so the test reduces to the orientation of
// △bcd w.r.t. s; in_cone states it as the thesis does.)
Index three_one_inner(const State& st, const Quad& q) {
  if (st.P.deg[q.a] == 3 && in_cone(*st.s, q.b, q.c, q.d, q.a)) return q.a;
  if (st.P.deg[q.b] == 3 && in_cone(*st.s, q.a, q.c, q.d, q.b)) return q.b;
  return kNoVertex;
}

[[maybe_unused]] std::string problem_after(const State& st) {
  if (std::string p = poly::structure_problem(st.P); !p.empty()) return p;
  return poly::star_problem(st.P, *st.s);
}

}  // namespace

State make_state(const PointSet& ps, const KernelPoint& s, poly::Polyhedron3 P, const pred::StaticFilter& filter) {
  State st;
  st.ps = &ps;
  st.s = &s;
  st.labelled.assign(P.n, 0);  // line 1: all vertices "unknown"
  st.removed.assign(P.n, 0);
  st.filter = filter;
  st.P = std::move(P);
  return st;
}

State make_state(const PointSet& ps, const KernelPoint& s, poly::Polyhedron3 P) {
  return make_state(ps, s, std::move(P), pred::StaticFilter::for_points(ps.coords.data(), ps.size(), 3));
}

Decision decide(const State& st, Index u, Index w) {
  const Quad q = quad(st, u, w);                 // line 5: e = ab, link {c, d}
  const Index x = smallest_labelled(st, q);       // line 5: x
  const bool is_reflex = reflex(st, q);
  // Every action of lines 8, 12, 14 and 16 needs a reflex edge or a labelled
  // vertex among a, b, c, d: a convex edge without labels is decided without
  // the cone tests (the common case once the polyhedron is nearly convex).
  if (!is_reflex && x == kNoVertex) return {};
  if (const Index a = three_one_inner(st, q); a != kNoVertex) {  // lines 6-7
    // line 8: a labelled (D-criterion) or e reflex (V-criterion; Lemma 6.4:
    // a reflex 3-1 edge is flippable)
    if (st.labelled[a]) return {Action::flip31_d, a};
    if (is_reflex) return {Action::flip31_v, a};
    return {};
  }
  // line 11: C_s(T_e) convex — the union of the cones of abc and abd is the
  // convex hull of the rays sa, sb, sc, sd
  const bool a_in = in_cone(*st.s, q.b, q.c, q.d, q.a);
  const bool b_in = !a_in && in_cone(*st.s, q.a, q.c, q.d, q.b);
  if (!a_in && !b_in) {
    if (x == kNoVertex) {
      // lines 12-13: V-criterion; reflex implies s outside abcd (it is on the
      // other side of △abc than d), so e is flippable
      if (is_reflex) return {Action::flip22_v, 0};
      return {};
    }
    // lines 14-15: D-criterion, flippable when s stays inside (s ∉ CH(abcd));
    // x in the link forbids the flip
    if ((x == q.a || x == q.b) && !s_in_tetrahedron(st, q)) return {Action::flip22_d, 0};
    return {};
  }
  // lines 16-18: an unflippable reflex 2-2 edge; w.l.o.g. a ∈ C_s(△bcd): then a
  // lies inside the tetrahedron sbcd and is non-extreme (Lemma 6.5)
  const Index inner = a_in ? q.a : q.b;
  if (!st.labelled[inner] && is_reflex) return {Action::label, inner};
  return {};
}

void apply(State& st, Index u, Index w, const Decision& d, std::vector<std::pair<Index, Index>>* pushed,
           Hull3Stats* stats) {
  if (d.action == Action::none) return;
  poly::Polyhedron3& P = st.P;
  const Quad q = quad(st, u, w);
  auto push = [&](Index x, Index y) {
    if (pushed) pushed->emplace_back(x, y);
  };
  const bool d_flip = d.action == Action::flip22_d || d.action == Action::flip31_d;
  [[maybe_unused]] Index x = kNoVertex;
  [[maybe_unused]] std::uint32_t deg_x_before = 0;
  if constexpr (FF_CHECKED) {
    x = smallest_labelled(st, q);
    if (x != kNoVertex) deg_x_before = P.deg[x];
    FF_CHECK(!d_flip || x != kNoVertex, "a D-flip without a labelled vertex: " + qstr(q));
  }
  switch (d.action) {
    case Action::none: break;
    case Action::label: {
      const Index a = d.inner;
      if constexpr (FF_CHECKED) {
        // Lemma 6.5: a lies inside the tetrahedron s + (the other three): in
        // the cone of their triangle and on the same side of it as s.
        [[maybe_unused]] const Index o1 = a == q.a ? q.b : q.a;
        FF_CHECK(reflex(st, q), "Lemma 6.5: labelling from a convex edge, " + qstr(q));
        FF_CHECK(in_cone(*st.s, o1, q.c, q.d, a), "Lemma 6.5: the labelled vertex is not in the cone, " + qstr(q));
        FF_CHECK(orient(st, o1, q.c, q.d, a) == st.s->side(o1, q.c, q.d),
                 "Lemma 6.5: the labelled vertex is not on the kernel's side of the other three, " + qstr(q));
      }
      st.labelled[a] = 1;  // line 18
      if (stats) ++stats->labelled_non_extreme;
      for (Index v : poly::link(P, a)) push(a, v);  // line 19: the edges incident to a
      break;
    }
    case Action::flip31_v:
    case Action::flip31_d: {
      const Index a = d.inner;
      const std::vector<Index> L = poly::link(P, a);  // b, c, d counter-clockwise
      FF_CHECK(L.size() == 3, "3-1 flip of a vertex whose degree is not 3");
      if constexpr (FF_CHECKED) {
        // a 3-1 flip removes only a vertex inside the cone of its link's
        // triangle (lines 6-7) that is labelled non-extreme (D) or, for a
        // reflex edge, lies inside the tetrahedron s + link (Lemma 6.4) — then
        // the volume grows by the tetrahedron a + link (V-criterion).
        FF_CHECK(in_cone(*st.s, L[0], L[1], L[2], a), "3-1 flip of a vertex outside the cone of its link, " + qstr(q));
        FF_CHECK(d.action == Action::flip31_v || st.labelled[a], "D 3-1 flip of an unlabelled vertex, " + qstr(q));
        if (d.action == Action::flip31_v)
          FF_CHECK(orient(st, L[0], L[1], L[2], a) > 0,
                   "V-criterion 3-1 flip does not make the volume grow (the vertex is not beneath its link), " + qstr(q));
      }
      poly::flip31(P, a);  // line 9
      st.removed[a] = 1;
      if (stats) ++stats->flips_3_1;
      push(L[0], L[1]);  // line 9: Q <- {bc, cd, db}
      push(L[1], L[2]);
      push(L[2], L[0]);
      break;
    }
    case Action::flip22_v:
    case Action::flip22_d: {
      if constexpr (FF_CHECKED) {
        FF_CHECK(!poly::find_edge(P, q.c, q.d).valid(), "2-2 flip would duplicate the edge of its link, " + qstr(q));
        FF_CHECK(!s_in_tetrahedron(st, q), "2-2 flip with the kernel point inside abcd, " + qstr(q));
        if (d.action == Action::flip22_v)
          FF_CHECK(reflex(st, q), "V-criterion 2-2 flip of a convex edge, " + qstr(q));
      }
      const DEdge e = poly::find_edge(P, q.a, q.b);
      [[maybe_unused]] const DEdge ne = poly::flip22(P, e);  // lines 13 / 15: triangles (a,d,c), (d,b,c)
      if (stats) ++stats->flips_2_2;
      if constexpr (FF_CHECKED) {
        if (d.action == Action::flip22_v) {
          // the volume grows by the tetrahedron abcd: d was beyond △abc (checked
          // above) and the new edge dc is convex (b beneath △adc)
          FF_CHECK(orient(st, q.a, q.d, q.c, q.b) > 0,
                   "V-criterion 2-2 flip does not make the volume grow, " + qstr(q));
        }
      }
      push(q.a, q.c);  // lines 13 / 15: Q <- {ac, bc, ad, bd}
      push(q.b, q.c);
      push(q.a, q.d);
      push(q.b, q.d);
      break;
    }
  }
  if constexpr (FF_CHECKED) {
    const std::string problem = problem_after(st);
    FF_CHECK(problem.empty(), "after a flip-flop operation on " + qstr(q) + ": " + problem);  // Lemma 6.3
    if (d_flip) {
      // the D-criterion lowers the degree of the smallest-index labelled vertex
      // of the induced subcomplex (removing it in a 3-1 flip), touching no
      // labelled vertex of smaller index
      FF_CHECK(!P.is_vertex(x) || P.deg[x] < deg_x_before,
               "D-flip did not lower the degree of the smallest-index non-extreme vertex " + std::to_string(x));
    }
    for ([[maybe_unused]] Index v : {q.a, q.b, q.c, q.d})
      FF_CHECK(!st.removed[v] || !P.is_vertex(v), "a removed vertex reappeared");
  }
}

std::vector<Candidate> applicable(const State& st) {
  std::vector<Candidate> out;
  for (const auto& [u, w] : poly::edges(st.P)) {
    const Decision d = decide(st, u, w);
    if (d.action != Action::none) out.push_back({u, w, d});
  }
  return out;
}

std::string final_problem(const State& st) {
  for (const auto& [u, w] : poly::edges(st.P))
    if (reflex(st, quad(st, u, w)))
      return "flip-flop ended with the reflex edge " + std::to_string(u) + " " + std::to_string(w);
  for (Index v = 0; v < st.P.n; ++v)
    if (st.labelled[v] && st.P.is_vertex(v))
      return "flip-flop ended with the non-extreme vertex " + std::to_string(v);
  return {};
}

void run(State& st, Hull3Stats* stats, const Chooser& choose) {
  if constexpr (FF_CHECKED) {
    const std::string problem = problem_after(st);
    FF_CHECK(problem.empty(), "flip-flop input: " + problem);
  }
  if (!choose) {
    // The sequential workflow (Figure 3.1) with a FIFO queue Q.
    const auto E = poly::edges(st.P);
    std::deque<std::pair<Index, Index>> Q(E.begin(), E.end());  // line 2
    std::vector<std::pair<Index, Index>> pushed;
    while (!Q.empty()) {                                        // line 3
      const auto [u, w] = Q.front();                            // line 4
      Q.pop_front();
      if (!poly::find_edge(st.P, u, w).valid()) continue;  // flipped away since it was pushed
      const Decision d = decide(st, u, w);
      if (d.action == Action::none) continue;
      pushed.clear();
      apply(st, u, w, d, &pushed, stats);
      Q.insert(Q.end(), pushed.begin(), pushed.end());
    }
  } else {
    for (;;) {
      const std::vector<Candidate> C = applicable(st);
      if (C.empty()) break;
      const std::size_t i = choose(C);
      if (i >= C.size()) throw std::out_of_range("flip-flop chooser returned an index out of range");
      apply(st, C[i].u, C[i].w, C[i].d, nullptr, stats);
    }
  }
  // Theorems 6.2 and 6.12: all edges convex and no non-extreme vertex left.
  if (std::string p = final_problem(st); !p.empty()) throw std::logic_error(p);
}

}  // namespace ff3

std::vector<Triangle> flip_flop_3d(const PointSet& ps, const std::vector<Triangle>& surface, const KernelPoint& s,
                                   Hull3Stats* stats, bool check_star) {
  if (ps.dim != 3) throw std::invalid_argument("flip-flop 3D needs 3D points, got dimension " + std::to_string(ps.dim));
  poly::Polyhedron3 P = poly::build(ps.size(), surface);
  if (check_star)
    if (std::string why = poly::star_problem(P, s); !why.empty())
      throw std::invalid_argument("surface is not star-shaped w.r.t. the kernel point: " + why);
  if (stats) *stats = Hull3Stats{};
  ff3::State st = ff3::make_state(ps, s, std::move(P));
  ff3::run(st, stats);
  return canonical_triangles(poly::triangles(st.P));
}

bool is_star_shaped(const PointSet& ps, const std::vector<Triangle>& surface, const KernelPoint& s) {
  if (ps.dim != 3 || !poly::surface_problem(ps.size(), surface).empty()) return false;
  return poly::star_problem(poly::build(ps.size(), surface), s).empty();
}

}  // namespace flipflop::ref

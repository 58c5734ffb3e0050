// lawson_flip.cpp — Lawson's flip algorithm (thesis §3.3.1); see lawson_flip.hpp.
#include "reference/rt2/lawson_flip.hpp"

#include <deque>
#include <string>

#include "reference/checked.hpp"

namespace flipflop::ref::lawson_flip {

using tri::Edge;

Move decide(const tri::Triangulation2& T, Edge e) {
  if (tri::locally_regular(T, e)) return Move::none;  // local check
  return tri::classify(T, e).shape == tri::Shape::two_two ? Move::flip22 : Move::stuck;
}

void apply(tri::Triangulation2& T, Edge e, std::vector<std::pair<Index, Index>>* pushed, Rt2Stats* stats) {
  const tri::Quad q = tri::quad(T, e);
  const Edge ne = tri::flip22(T, e);  // local operation: 2-2 flip
  if (stats) ++stats->flips_2_2;
  if constexpr (FF_CHECKED) {
    const std::string problem = tri::validity_problem(T);
    FF_CHECK(problem.empty(), "after a Lawson flip: " + problem);
    FF_CHECK(tri::locally_regular(T, ne), "a Lawson flip did not lower the lifted surface");
    for ([[maybe_unused]] Index v : {q.a, q.b, q.c, q.d}) FF_CHECK(!T.removed[v], "a removed vertex reappeared");
  } else {
    (void)ne;
  }
  if (pushed) {  // the candidates whose induced subcomplex changed
    pushed->emplace_back(q.a, q.c);
    pushed->emplace_back(q.b, q.c);
    pushed->emplace_back(q.a, q.d);
    pushed->emplace_back(q.b, q.d);
  }
}

void flip(tri::Triangulation2& T, Rt2Stats* stats, const std::vector<std::pair<Index, Index>>* candidates) {
  if constexpr (FF_CHECKED) {
    const std::string problem = tri::validity_problem(T);
    FF_CHECK(problem.empty(), "Lawson input: " + problem);
  }
  std::deque<std::pair<Index, Index>> Q;
  if (candidates) Q.assign(candidates->begin(), candidates->end());
  else {
    const auto E = tri::edges(T);
    Q.assign(E.begin(), E.end());
  }
  std::vector<std::pair<Index, Index>> pushed;
  while (!Q.empty()) {
    const auto [u, w] = Q.front();
    Q.pop_front();
    const Edge e = tri::find_edge(T, u, w);
    if (!e.valid()) continue;  // flipped away since it was pushed
    if (stats) ++stats->candidates;
    if (decide(T, e) != Move::flip22) continue;
    pushed.clear();
    apply(T, e, &pushed, stats);
    Q.insert(Q.end(), pushed.begin(), pushed.end());
  }
}

bool all_locally_regular(const tri::Triangulation2& T) {
  for (const auto& [u, w] : tri::edges(T))
    if (!tri::locally_regular(T, tri::find_edge(T, u, w))) return false;
  return true;
}

bool run(tri::Triangulation2& T, Rt2Stats* stats) {
  flip(T, stats);
  return all_locally_regular(T);  // false: stuck (Figure 3.3)
}

}  // namespace flipflop::ref::lawson_flip

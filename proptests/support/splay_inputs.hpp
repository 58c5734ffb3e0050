// splay_inputs.hpp — inputs for the star splaying and strict view tests:
// the 3D families star splaying accepts, and random initial stars.
//
//   splay_families()   every 3D distribution of gen/ except the flat ones
//                      (collinear3, coplanar3: rejected as lower-dimensional,
//                      tested separately);
//   random_stars(ps)   one star per point, drawn at random but valid: the
//                      star of w is the convex cone (or the dead star) of a
//                      random subset of the other points that holds a point
//                      ≺ w (the lexicographic precondition), built by
//                      splaying them into a first simplicial cone one by one.
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "predicates/predicates.hpp"
#include "reference/hull3/star_splaying.hpp"
#include "reference/point_set.hpp"

namespace flipflop::test {

inline std::vector<std::string> splay_families() {
  std::vector<std::string> out;
  for (const std::string& d : gen::distributions())
    if (gen::dimension_of(d) == 3 && d != "collinear3" && d != "coplanar3") out.push_back(d);
  return out;
}

inline PointSet family3(const std::string& name, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  return gen::generate(name, n, o);
}

inline std::vector<ref::Star> random_stars(const PointSet& ps, std::uint64_t seed) {
  const Index n = static_cast<Index>(ps.size());
  std::mt19937_64 rng(seed);
  Index least = 0;
  for (Index v = 1; v < n; ++v)
    if (ref::lex_precedes(ps, v, least)) least = v;
  std::vector<ref::Star> out;
  for (Index w = 0; w < n; ++w) {
    std::vector<Index> others;
    for (Index u = 0; u < n; ++u)
      if (u != w) others.push_back(u);
    std::shuffle(others.begin(), others.end(), rng);
    if (w != least) {  // a point ≺ w first
      auto it = std::find_if(others.begin(), others.end(), [&](Index u) { return ref::lex_precedes(ps, u, w); });
      std::iter_swap(others.begin(), it);
    }
    Index a = others[0], b = others[1], c = others[2];
    const int s = pred::orient3d({w, ps.point(w)}, {a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)});
    if (s < 0) std::swap(b, c);  // c on the inner side of (w, a, b)
    ref::splay::State st;
    st.ps = &ps;
    st.status.assign(n, ref::splay::Status::none);
    st.link.assign(n, {});
    st.cert.assign(n, {});
    st.status[w] = ref::splay::Status::alive;
    st.link[w] = {a, b, c};
    const std::size_t extra = std::uniform_int_distribution<std::size_t>(0, others.size() - 3)(rng);
    for (std::size_t i = 3; i < 3 + extra; ++i) ref::splay::insert(st, w, others[i]);
    ref::Star star;
    star.apex = w;
    star.dead = st.status[w] == ref::splay::Status::dead;
    if (star.dead)
      star.certificate = st.cert[w];
    else
      star.link = st.link[w];
    out.push_back(std::move(star));
  }
  std::shuffle(out.begin(), out.end(), rng);  // any order of stars
  return out;
}

}  // namespace flipflop::test

// certify_rt2_cpu_test.cpp — the parallel certifier of 2D regular / Delaunay
// triangulations (cpu::certify_rt2, kernels_cpu/rt2) against the sequential
// one (certify::rt2): the same verdict and the same message, at 1, 2 and 8
// threads and at both levels, on the right answer and on answers made wrong
// in many ways, for random weighted and unweighted inputs and degenerate ones
// (grid, duplicates, cocircular lattice points, ulp jitter, the edges of the
// double range).
//
// Oracle: ref::rt2_ffrt (the exact reference, tested against brute force in
// rt2_reference_test.cpp), whose answer must be certified at both levels and
// whose corruptions must be rejected at Level::canonical. The inputs hold more
// than one piece of work (kernels_cpu/parallel.hpp kChunk = 8192 triangles,
// vertices or missing points), so the pieces really run apart.
#include <catch2/catch.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "kernels_cpu/rt2/certify_rt2.hpp"
#include "reference/certify/certify.hpp"
#include "reference/rt2/rt2.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};

struct Case {
  std::string name;
  std::vector<Triangle> tris;
};

// The answer of ps without the points `drop` (re-triangulated by the
// reference, indices mapped back to ps): those points are then missing and,
// when they were vertices, not redundant.
std::vector<Triangle> without(const PointSet& ps, const std::vector<bool>& drop) {
  PointSet rest;
  rest.dim = 2;
  rest.weighted = ps.weighted;
  std::vector<Index> back;
  for (Index i = 0; i < ps.size(); ++i)
    if (!drop[i]) {
      back.push_back(i);
      rest.coords.insert(rest.coords.end(), ps.point(i), ps.point(i) + 2);
      if (ps.weighted) rest.weights.push_back(ps.weights[i]);
    }
  std::vector<Triangle> tris = ref::rt2_ffrt(rest);
  for (Triangle& t : tris)
    for (Index& v : t) v = back[v];
  return tris;
}

// The right answer and wrong ones: a triangle removed, an interior edge
// flipped, vertices dropped (the triangulation of the other points), a
// triangle reversed, a triangle repeated, an index out of range, a vertex of
// a triangle replaced by another point, two triangles' orders swapped.
std::vector<Case> outputs(const PointSet& ps) {
  const std::vector<Triangle> right = ref::rt2_ffrt(ps);
  std::vector<Case> out = {{"right", right}};
  const std::size_t F = right.size(), mid = F / 2;
  auto removed = right;
  removed.erase(removed.begin() + static_cast<long>(mid));
  out.push_back({"triangle removed", removed});
  // flip the first interior edge of the middle triangle: (a, b, c) and its
  // neighbour (b, a, d) become (a, d, c) and (d, b, c)
  for (int k = 0; k < 3; ++k) {
    const Index a = right[mid][k], b = right[mid][(k + 1) % 3], c = right[mid][(k + 2) % 3];
    const auto o = std::find_if(right.begin(), right.end(), [&](const Triangle& t) {
      for (int j = 0; j < 3; ++j)
        if (t[j] == b && t[(j + 1) % 3] == a) return true;
      return false;
    });
    if (o == right.end()) continue;
    Index d = 0;
    for (Index v : *o)
      if (v != a && v != b) d = v;
    auto flipped = right;
    flipped[mid] = {a, d, c};
    flipped[static_cast<std::size_t>(o - right.begin())] = {d, b, c};
    out.push_back({"edge flipped", flipped});
    break;
  }
  // drop every 97th vertex of the answer (many missing points that are not
  // redundant: the first in the sequential order must be named)
  std::vector<bool> drop(ps.size(), false);
  std::vector<Index> verts;
  for (const Triangle& t : right) verts.insert(verts.end(), t.begin(), t.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (std::size_t i = 3; i < verts.size(); i += 97) drop[verts[i]] = true;
  out.push_back({"vertices dropped", without(ps, drop)});
  auto reversed = right;
  std::swap(reversed[mid][1], reversed[mid][2]);
  out.push_back({"triangle reversed", reversed});
  auto repeated = right;
  repeated.push_back(right[F / 3]);
  out.push_back({"triangle repeated", repeated});
  auto range = right;
  range[mid][1] = static_cast<Index>(ps.size());
  out.push_back({"index out of range", range});
  auto moved = right;
  moved[mid][0] = moved[F / 3][1] == moved[mid][1] || moved[F / 3][1] == moved[mid][2] ? moved[F / 4][2]
                                                                                          : moved[F / 3][1];
  out.push_back({"vertex replaced", moved});
  auto swapped = right;
  std::swap(swapped[1], swapped[F - 2]);
  out.push_back({"order swapped", swapped});
  return out;
}

}  // namespace

TEST_CASE("rt2 cpu certify: the parallel certifier gives the sequential verdict and message", "[certify][rt2][long]") {
  struct Input {
    const char* dist;
    std::size_t n;
    double whi;  // weights in [0, whi]; 0: unweighted
  };
  // random (Delaunay, few / many redundant points) and degenerate families
  const Input inputs[] = {{"square", 6000, 0},      {"square", 20000, 1e-3}, {"disk", 6000, 1e-5},
                          {"grid2", 6000, 0},       {"grid2", 6000, 1e-2},   {"duplicates2", 6000, 0},
                          {"circle-lattice", 6000, 0}, {"jitter2", 6000, 1e-4},   {"huge2", 6000, 0},
                          {"tiny2", 6000, 0}};
  std::size_t runs = 0, rejected = 0, accepted_wrong = 0;
  for (const Input& in : inputs)
    for (std::uint64_t seed : {1, 2}) {
      gen::Options o;
      o.seed = seed;
      o.weighted = in.whi > 0;
      o.wlo = 0;
      o.whi = in.whi;
      const PointSet ps = gen::generate(in.dist, in.n, o);
      for (const Case& c : outputs(ps))
        for (certify::Level level : {certify::Level::exact, certify::Level::canonical}) {
          const certify::Report seq = certify::rt2(ps, c.tris, level);
          INFO(in.dist << " n " << in.n << " w " << in.whi << " seed " << seed << ", " << c.name << ", "
                       << (level == certify::Level::exact ? "exact" : "canonical") << ": " << seq.message());
          // the right answer passes at both levels, every wrong one fails at
          // the canonical level (at the exact level a wrong one can pass on
          // degenerate input: a flip between cocircular points, a dropped
          // point that is a vertex only under the perturbation)
          if (c.name == "right" || level == certify::Level::canonical) REQUIRE(seq.ok == (c.name == "right"));
          rejected += !seq.ok;
          accepted_wrong += seq.ok && c.name != "right";
          for (int t : kThreads) {
            REQUIRE(cpu::certify_rt2(ps, c.tris, level, t).message() == seq.message());
            ++runs;
          }
        }
    }
  std::cout << "rt2 parallel certifier: " << runs << " runs, sequential verdicts reproduced (" << rejected
            << " rejections, " << accepted_wrong << " wrong answers accepted at the exact level)\n";
}

// Many missing points, most of them redundant and some not, spread over many
// pieces of the Morton order: the named point is the first failing one in
// that order whatever the split, and each piece's own walk finds the same
// triangles.
TEST_CASE("rt2 cpu certify: many missing points, the first failing one in Morton order is named", "[certify][rt2]") {
  gen::Options o;
  o.seed = 5;
  o.weighted = true;
  o.wlo = 0;
  o.whi = 0.05;  // most of the 40000 points redundant
  const PointSet ps = gen::generate("square", 40000, o);
  const std::vector<Triangle> right = ref::rt2_ffrt(ps);
  REQUIRE(3 * right.size() < ps.size());  // more than 8192 missing points
  std::vector<bool> drop(ps.size(), false);
  for (std::size_t i = 10; i < right.size(); i += 211) drop[right[i][1]] = true;
  const std::vector<Triangle> wrong = without(ps, drop);
  for (certify::Level level : {certify::Level::exact, certify::Level::canonical}) {
    REQUIRE(certify::rt2(ps, right, level).ok);
    const certify::Report seq = certify::rt2(ps, wrong, level);
    INFO(seq.message());
    REQUIRE(seq.condition == "missing-point-redundant");
    for (int t : kThreads) {
      REQUIRE(cpu::certify_rt2(ps, right, level, t).ok);
      REQUIRE(cpu::certify_rt2(ps, wrong, level, t).message() == seq.message());
    }
  }
}

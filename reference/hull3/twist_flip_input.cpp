// twist_flip_input.cpp — valid special inputs of twist-flip, thesis §8.4.1
// (see twist_flip_input.hpp).
#include "reference/hull3/twist_flip_input.hpp"

#include <algorithm>
#include <array>
#include <random>
#include <stdexcept>
#include <utility>

#include "predicates/predicates.hpp"

namespace flipflop::ref {

namespace {

pred::Pt pt(const PointSet& ps, Index i) { return {i, ps.point(i)}; }

// uniform in [0, m) from the engine (the modulo bias is irrelevant here; the
// mapping is ours, so the sequence is the same on every platform)
std::size_t below(std::mt19937_64& rng, std::size_t m) { return static_cast<std::size_t>(rng() % m); }

// g_v(p) < g_v(q): the angle of p - v in the xy-plane, counter-clockwise from
// +x. The upper half-plane (p.y > v.y under SoS) comes first; within a half-
// plane orient2d(v, p, q) > 0 (on the x, y columns: the same perturbation as
// the 3D predicates, predicates.hpp) puts p first. In the perturbed
// configuration no p - v is horizontal and no two are parallel, so this is a
// strict total order.
struct AngleAroundVertical {
  const PointSet* ps;
  Index v;
  bool operator()(Index p, Index q) const {
    if (p == q) return false;
    const bool up_p = pred::compare_sos(pt(*ps, p), pt(*ps, v), 1) > 0;
    const bool up_q = pred::compare_sos(pt(*ps, q), pt(*ps, v), 1) > 0;
    if (up_p != up_q) return up_p;
    return pred::orient2d(pt(*ps, v), pt(*ps, p), pt(*ps, q)) > 0;
  }
};

// triangulations of the k-gon of slots 0..k-1, as slot triples x < y < z
std::vector<std::array<std::uint32_t, 3>> disk(std::uint32_t k, DiskTriangulation kind, std::mt19937_64& rng) {
  std::vector<std::array<std::uint32_t, 3>> out;
  switch (kind) {
    case DiskTriangulation::fan:
      for (std::uint32_t i = 1; i + 1 < k; ++i) out.push_back({0, i, i + 1});
      break;
    case DiskTriangulation::zigzag: {
      std::vector<std::uint32_t> chain = {0};
      for (std::uint32_t lo = 1, hi = k - 1; lo <= hi;) {
        chain.push_back(lo++);
        if (lo <= hi) chain.push_back(hi--);
      }
      for (std::size_t i = 0; i + 2 < chain.size(); ++i) {
        std::array<std::uint32_t, 3> t = {chain[i], chain[i + 1], chain[i + 2]};
        std::sort(t.begin(), t.end());
        out.push_back(t);
      }
      break;
    }
    case DiskTriangulation::random: {
      // the sub-polygon of slots i..j closed by the chord (i, j): a random apex
      std::vector<std::pair<std::uint32_t, std::uint32_t>> stack = {{0, k - 1}};
      while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2) continue;
        const auto m = static_cast<std::uint32_t>(i + 1 + below(rng, j - i - 1));
        out.push_back({i, m, j});
        stack.push_back({i, m});
        stack.push_back({m, j});
      }
      break;
    }
  }
  return out;
}

}  // namespace

Index topmost_point(const PointSet& ps) {
  if (ps.dim != 3 || ps.size() == 0) throw std::invalid_argument("topmost_point: a non-empty 3D point set is needed");
  Index v = 0;
  for (Index p = 1; p < ps.size(); ++p)
    if (pred::compare_sos(pt(ps, p), pt(ps, v), 2) > 0) v = p;
  return v;
}

std::vector<Triangle> special_polyhedron(const PointSet& ps, const SpecialInputOptions& o) {
  if (ps.dim != 3) throw std::invalid_argument("special_polyhedron: the points must be 3D");
  if (ps.size() < 4) throw std::invalid_argument("special_polyhedron: at least 4 points are needed");
  std::mt19937_64 rng(o.seed);
  const Index v = topmost_point(ps);
  std::vector<Index> link;  // L_0 .. L_{k-1}
  for (Index p = 0; p < ps.size(); ++p)
    if (p != v) link.push_back(p);
  const auto k = static_cast<std::uint32_t>(link.size());
  if (o.link == LinkOrder::angular) {
    std::sort(link.begin(), link.end(), AngleAroundVertical{&ps, v});
  } else {
    for (std::size_t i = k - 1; i > 0; --i) std::swap(link[i], link[below(rng, i + 1)]);
  }
  const auto slots = disk(k, o.disk, rng);
  // random twists on edges not incident to v: every such edge is an edge of a
  // triangle of the disk; twisting it swaps the points of its two slots
  for (std::size_t t = 0; t < o.twists && !slots.empty(); ++t) {
    const auto& tri = slots[below(rng, slots.size())];
    const std::size_t e = below(rng, 3);
    std::swap(link[tri[e]], link[tri[(e + 1) % 3]]);
  }
  std::vector<Triangle> out;
  out.reserve(k + slots.size());
  for (std::uint32_t i = 0; i < k; ++i) out.push_back({v, link[i], link[(i + 1) % k]});
  for (const auto& t : slots) out.push_back({link[t[2]], link[t[1]], link[t[0]]});
  if (o.reversed)
    for (Triangle& t : out) std::swap(t[1], t[2]);
  return out;
}

}  // namespace flipflop::ref

// rt3_witness_from_ref.hpp — an Rt3Witness (kernels_cpu/rt3/rt3.hpp) built
// from the reference's extended triangulation (ref::build_rtd, d = 3:
// reference/rtd/rt_incremental.hpp), for the tests of cpu::certify_rt3: a
// second producer of witnesses that shares no code with the kernel, so that
// the certifier is tested on witnesses the kernel did not make, in another
// slot order and another order of positions.
//
// The translation: positions are the input indices in an order shuffled by
// `seed` (0: the input order); slot s of the reference becomes slot s (dead
// slots: four kNoSlot corners and links), its corners the positions of its
// vertices (the virtual vertex n stays n); the reference's neighbour links
// name slots, so the link of corner i is 4u + j with j the mirror corner
// (rtd::mirror_index). For a vertex, `at` is a real slot of its star; for a
// point that is not a vertex, the real slot containing it, located by the
// reference's visibility walk (rtd::locate). The real slots are positive in
// orient_d = orient3d (triangulation_d.hpp), the virtual ones follow the same
// rule as the kernel's (rt3.hpp), so the witness is valid as it is.
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "kernels_cpu/rt3/rt3.hpp"
#include "reference/point_set.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::test {

struct RefRt3 {
  cpu::Rt3Witness w;
  std::vector<cpu::Tet> tets;  // the reference's canonical output
};

inline RefRt3 rt3_witness_from_ref(const PointSet& ps, std::uint64_t seed = 0) {
  namespace rtd = ref::rtd;
  constexpr std::uint32_t kNo = cpu::Rt3Witness::kNoSlot;
  const rtd::TriangulationD T = ref::build_rtd(ps);
  const Index n = T.n;
  std::vector<Index> order(n);  // position -> input index
  for (Index i = 0; i < n; ++i) order[i] = i;
  if (seed != 0) {
    std::mt19937_64 rng(seed);
    for (Index i = n; i > 1; --i) std::swap(order[i - 1], order[static_cast<Index>(rng() % i)]);
  }
  std::vector<std::uint32_t> position(n + 1);
  for (Index k = 0; k < n; ++k) position[order[k]] = k;
  position[n] = n;  // the virtual vertex

  RefRt3 r;
  cpu::Rt3Witness& w = r.w;
  w.pts.resize(n);
  for (Index k = 0; k < n; ++k) {
    const double* x = ps.point(order[k]);
    w.pts[k] = {{x[0], x[1], x[2]}, ps.weight(order[k]), order[k]};
  }
  const std::size_t slots = T.slots();
  w.tv.assign(4 * slots, kNo);
  w.tn.assign(4 * slots, kNo);
  std::int32_t some_real = rtd::kNone;
  for (std::size_t s = 0; s < slots; ++s) {
    if (!T.alive[s]) continue;
    const std::int32_t si = static_cast<std::int32_t>(s);
    if (!rtd::is_virtual_simplex(T, si) && some_real == rtd::kNone) some_real = si;
    for (int i = 0; i < 4; ++i) {
      w.tv[4 * s + static_cast<std::size_t>(i)] = position[T.vertex(si, i)];
      w.tn[4 * s + static_cast<std::size_t>(i)] =
          4 * static_cast<std::uint32_t>(T.neighbor(si, i)) + static_cast<std::uint32_t>(rtd::mirror_index(T, si, i));
    }
  }
  w.at.assign(n, kNo);
  for (Index x = 0; x < n; ++x) {
    std::int32_t s = rtd::kNone;
    if (T.is_vertex(x)) {
      for (std::int32_t t : rtd::star(T, x))
        if (!rtd::is_virtual_simplex(T, t)) {
          s = t;
          break;
        }
    } else {
      s = rtd::locate(T, x, some_real);
      if (rtd::is_virtual_simplex(T, s))
        throw std::logic_error("rt3_witness_from_ref: a missing point outside the hull");
    }
    w.at[position[x]] = static_cast<std::uint32_t>(s);
  }
  for (const auto& t : rtd::real_simplices(T)) r.tets.push_back({t[0], t[1], t[2], t[3]});
  return r;
}

}  // namespace flipflop::test

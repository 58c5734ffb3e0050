// rt2.cpp — public entry points of the 2D regular triangulation reference;
// see rt2.hpp.
#include "reference/rt2/rt2.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "reference/dimension.hpp"
#include "reference/rt2/ffrt.hpp"
#include "reference/rt2/flip_flop_2d.hpp"
#include "reference/rt2/lawson_flip.hpp"

namespace flipflop::ref {

void require_plane(const PointSet& ps, const char* who) {
  if (ps.dim != 2)
    throw std::invalid_argument(std::string(who) + ": needs 2D points, got dimension " + std::to_string(ps.dim));
  if (ps.size() < 3)
    throw std::invalid_argument(std::string(who) + ": needs at least 3 points, got " + std::to_string(ps.size()));
  const std::string problem = dimension_problem(ps);
  if (!problem.empty()) throw std::invalid_argument(std::string(who) + ": " + problem);
}

namespace {

std::vector<Index> missing_points(const tri::Triangulation2& T) {
  std::vector<Index> out;
  for (Index i = 0; i < T.n; ++i)
    if (!T.is_vertex(i)) out.push_back(i);
  return out;
}

}  // namespace

std::vector<Triangle> rt2_ffrt(const PointSet& ps, Rt2Stats* stats, FlipFlopVariant variant) {
  require_plane(ps, "rt2 (ffRT)");
  return ffrt::ffrt(ps, variant, stats);
}

std::vector<Triangle> dt2_lawson(const PointSet& ps, Rt2Stats* stats) {
  require_plane(ps, "dt2 (Lawson)");
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (ps.weight(i) != 0)
      throw std::invalid_argument("dt2 (Lawson): point " + std::to_string(i) +
                                  " has a non-zero weight; Lawson's flip algorithm computes Delaunay "
                                  "triangulations (use rt2 / ffRT for weighted points)");
  // Lawson's algorithm cannot remove a vertex, so it must start from points
  // that are all non-redundant. With zero weights only copies of a repeated
  // location can be redundant. Groups of identical points, in index order.
  std::vector<Index> order(ps.size());
  std::iota(order.begin(), order.end(), Index{0});
  auto same = [&](Index i, Index j) { return ps.point(i)[0] == ps.point(j)[0] && ps.point(i)[1] == ps.point(j)[1]; };
  std::sort(order.begin(), order.end(), [&](Index i, Index j) {
    const double* p = ps.point(i);
    const double* q = ps.point(j);
    if (p[0] != q[0]) return p[0] < q[0];
    if (p[1] != q[1]) return p[1] < q[1];
    return i < j;
  });
  std::vector<Index> kept;                         // one per location: the largest index
  std::vector<std::pair<Index, Index>> copies;     // (other copy, kept copy of its location)
  for (std::size_t k = 0, g = 0; k < order.size(); k = g) {
    for (g = k + 1; g < order.size() && same(order[k], order[g]);) ++g;
    kept.push_back(order[g - 1]);
    for (std::size_t j = k; j + 1 < g; ++j) copies.emplace_back(order[j], order[g - 1]);
  }
  std::sort(kept.begin(), kept.end());
  tri::Triangulation2 T = ffrt::construct(ps, kept, false, stats);  // all kept points inserted
  if (!lawson_flip::run(T, stats))
    throw std::logic_error("dt2 (Lawson): stuck with a locally non-Delaunay edge on distinct points");
  // The other copies, in increasing index order (decreasing perturbation):
  // each is inserted only when the triangle of the current Delaunay
  // triangulation containing it does not prove it redundant (§5.3, cf. Lemma
  // 5.1), and Lawson's flips continue from the three edges of that triangle
  // (incremental insertion: the other edges are locally Delaunay already).
  // Why no inserted vertex later becomes redundant: a copy j inserted after a
  // copy i < j is perturbed infinitely less than i (predicates.hpp, dominance
  // order), so at i's scale it sits where the kept copy m already is and
  // cannot change whether i is on the lower hull. The final check below
  // verifies it: a stuck state throws.
  std::sort(copies.begin(), copies.end());
  std::vector<std::pair<Index, Index>> seed;
  for (const auto& [d, m] : copies) {
    const std::int32_t t = ffrt::locate_near(T, d, m);
    const Triangle x = T.tv[static_cast<std::size_t>(t)];
    const bool real = !T.is_virtual(x[0]) && !T.is_virtual(x[1]) && !T.is_virtual(x[2]);
    if (real && tri::power(T, x[0], x[1], x[2], d) < 0) {  // proved redundant
      if (stats) ++stats->discarded_early;
      continue;
    }
    tri::flip13(T, t, d);
    if (stats) ++stats->flips_1_3;
    seed = {{x[0], x[1]}, {x[1], x[2]}, {x[2], x[0]}, {d, x[0]}, {d, x[1]}, {d, x[2]}};
    lawson_flip::flip(T, stats, &seed);
  }
  if (!lawson_flip::all_locally_regular(T))
    throw std::runtime_error("dt2 (Lawson): a copy of a repeated point became redundant after its insertion; "
                             "Lawson's flip algorithm cannot remove it (use ffRT)");
  return tri::real_triangles(T);
}

std::vector<Triangle> flip_flop(const PointSet& ps, std::vector<Triangle> triangulation, FlipFlopVariant variant,
                                Rt2Stats* stats) {
  require_plane(ps, "flip-flop");
  tri::Triangulation2 T = tri::from_triangles(ps, triangulation);
  ffrt::insert_points(T, missing_points(T), true, stats);  // §5.3 constructing stage for the others
  ff::State s = ff::make_state(std::move(T));
  ff::run(s, variant, stats);
  return tri::real_triangles(s.T);
}

std::vector<Triangle> lawson(const PointSet& ps, std::vector<Triangle> triangulation, Rt2Stats* stats) {
  require_plane(ps, "Lawson");
  tri::Triangulation2 T = tri::from_triangles(ps, triangulation);
  const auto missing = missing_points(T);
  if (!missing.empty())
    throw std::invalid_argument("Lawson: point " + std::to_string(missing.front()) +
                                " is not a vertex of the triangulation (Lawson's flip algorithm needs every "
                                "point as a vertex; flip_flop inserts missing points)");
  if (!lawson_flip::run(T, stats))
    throw std::runtime_error("Lawson: stuck with a locally non-regular edge that cannot be flipped (a redundant "
                             "vertex, Lemma 5.1 / Figure 3.3); use flip_flop");
  return tri::real_triangles(T);
}

}  // namespace flipflop::ref

// classify_tbb.cpp — see classify_tbb.hpp.
#include "kernels_cpu/classify_tbb.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <stdexcept>
#include <string>

#include "kernels_cpu/tsan.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::kernels_cpu {

namespace {

template <std::size_t D>
void validate(const PointSet& pts, const std::vector<std::array<Index, D>>& facets,
              const std::vector<Index>& facet_of_point, const char* who) {
  if (pts.dim != static_cast<int>(D))
    throw std::invalid_argument(std::string(who) + ": expected " + std::to_string(D) +
                                "D points, got " + std::to_string(pts.dim) + "D");
  if (facet_of_point.size() != pts.size())
    throw std::invalid_argument(std::string(who) + ": need one facet id per point");
  for (const auto& f : facets)
    for (Index v : f)
      if (v >= pts.size())
        throw std::invalid_argument(std::string(who) + ": facet vertex id out of range");
  for (Index f : facet_of_point)
    if (f >= facets.size()) throw std::invalid_argument(std::string(who) + ": facet id out of range");
}

// Points are independent: split the index range, one sign per point.
template <class SignOf>
std::vector<int> for_all_points(std::size_t n, SignOf sign_of) {
  std::vector<int> sign(n);
  tsan::ForkJoin fj;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      fj.task_begin();
                      for (std::size_t i = r.begin(); i != r.end(); ++i) sign[i] = sign_of(i);
                      fj.task_end();
                    });
  fj.joined();
  return sign;
}

}  // namespace

std::vector<int> classify_points_3d(const PointSet& pts, const std::vector<Triangle>& facets,
                                    const std::vector<Index>& facet_of_point) {
  validate(pts, facets, facet_of_point, "classify_points_3d");
  return for_all_points(pts.size(), [&](std::size_t i) {
    const Triangle& f = facets[facet_of_point[i]];
    return pred::orient3d_exact(pts.point(f[0]), pts.point(f[1]), pts.point(f[2]), pts.point(i),
                                pred::Mode::filtered);
  });
}

std::vector<int> classify_points_2d(const PointSet& pts, const std::vector<Edge>& edges,
                                    const std::vector<Index>& edge_of_point) {
  validate(pts, edges, edge_of_point, "classify_points_2d");
  return for_all_points(pts.size(), [&](std::size_t i) {
    const Edge& e = edges[edge_of_point[i]];
    return pred::orient2d_exact(pts.point(e[0]), pts.point(e[1]), pts.point(i),
                                pred::Mode::filtered);
  });
}

}  // namespace flipflop::kernels_cpu

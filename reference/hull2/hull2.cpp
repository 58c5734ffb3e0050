// hull2.cpp — public entry points of the reference 2D hull (see hull2.hpp).
#include "reference/hull2/hull2.hpp"

#include <numeric>
#include <stdexcept>

namespace flipflop::ref {

namespace {
// Resets *stats and records the input size.
void begin(const PointSet& ps, Hull2Stats* stats, const char* who) {
  require_planar_input(ps, who);
  if (stats) {
    *stats = Hull2Stats{};
    stats->input_vertices = ps.size();
  }
}
}  // namespace

std::vector<Index> hull2_graham_sort(const PointSet& ps, Hull2Stats* stats) {
  begin(ps, stats, "hull2 graham-sort");
  return graham_sorting(ps, stats);
}

std::vector<Index> hull2_graham_insert(const PointSet& ps, Hull2Stats* stats) {
  begin(ps, stats, "hull2 graham-insert");
  return graham_insertion(ps, stats);
}

std::vector<Index> hull2_twist(const PointSet& ps, Hull2Stats* stats) {
  begin(ps, stats, "hull2 twist");
  const pred::RationalPoint s = interior_kernel(ps);
  std::vector<Index> polygon(ps.size());
  std::iota(polygon.begin(), polygon.end(), Index{0});  // the input order <p_0, ..., p_{n-1}>
  polygon = twist_to_star(ps, std::move(polygon), s, stats);
  return flip_pop(ps, std::move(polygon), s, stats);
}

std::vector<Index> hull2(const PointSet& ps, const std::string& algo, Hull2Stats* stats) {
  if (algo == "graham-sort") return hull2_graham_sort(ps, stats);
  if (algo == "graham-insert") return hull2_graham_insert(ps, stats);
  if (algo == "twist") return hull2_twist(ps, stats);
  throw std::invalid_argument("unknown hull2 algorithm '" + algo + "'; valid: graham-sort, graham-insert, twist");
}

std::vector<std::string> hull2_algorithms() { return {"graham-sort", "graham-insert", "twist"}; }

}  // namespace flipflop::ref

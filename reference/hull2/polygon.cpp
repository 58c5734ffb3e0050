// polygon.cpp — predicates, kernel point and star-shapedness (polygon.hpp).
#include "reference/hull2/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/dimension.hpp"

namespace flipflop::ref {

int orient(const PointSet& ps, Index a, Index b, Index c) {
  return pred::orient2d({a, ps.point(a)}, {b, ps.point(b)}, {c, ps.point(c)});
}

int compare_coord(const PointSet& ps, Index a, Index b, int coord) {
  return pred::compare_sos({a, ps.point(a)}, {b, ps.point(b)}, coord);
}

std::pair<Index, Index> leftmost_rightmost(const PointSet& ps) {
  Index l = 0, r = 0;
  for (Index i = 1; i < static_cast<Index>(ps.size()); ++i) {
    if (compare_coord(ps, i, l, 0) < 0) l = i;
    if (compare_coord(ps, i, r, 0) > 0) r = i;
  }
  return {l, r};
}

// ---- StarKernel ----------------------------------------------------------------
StarKernel::StarKernel(const PointSet& ps, const pred::RationalPoint& s)
    : ps_(&ps), s_(s), id_(static_cast<pred::PointId>(ps.size())) {
  if (ps.dim != 2 || s.dim != 2 || s.exact.size() != 2)
    throw std::invalid_argument("StarKernel: a 2D point set and a 2D kernel point are needed");
  // The 1D Λ-matrix of a y comparison has the single coordinate column; which
  // coordinate it holds does not change the dominance order of the perturbation
  // (predicates.hpp: rows are compared by index, the column is the only one), so
  // a copy of s holding only its y is compared with pointers to input y's.
  const int y = 1;
  s_y_ = s.project(&y, 1);
}

int StarKernel::orient(Index p, Index q) const {
  const pred::MixedRow rows[3] = {{id_, nullptr, &s_}, {p, ps_->point(p), nullptr}, {q, ps_->point(q), nullptr}};
  return pred::mixed_sign(3, rows, true);
}

int StarKernel::compare_y(Index p) const {
  // det [[p.y, 1], [s.y, 1]] = p.y - s.y
  const pred::MixedRow rows[2] = {{p, ps_->point(p) + 1, nullptr}, {id_, nullptr, &s_y_}};
  return pred::mixed_sign(2, rows, true);
}

bool StarKernel::angle_less(Index p, Index q) const {
  if (p == q) return false;
  const bool upper_p = compare_y(p) > 0, upper_q = compare_y(q) > 0;
  if (upper_p != upper_q) return upper_p;  // g in (0, π) before g in (π, 2π)
  return orient(p, q) > 0;                 // within a half-plane: counter-clockwise = larger g
}

pred::RationalPoint interior_kernel(const PointSet& ps) {
  require_planar_input(ps, "interior_kernel");
  const auto [a, b] = leftmost_rightmost(ps);
  const double* A = ps.point(a);
  const double* B = ps.point(b);
  long best = -1;
  double best_area = -1;
  for (Index c = 0; c < static_cast<Index>(ps.size()); ++c) {
    const double* C = ps.point(c);
    if (pred::orient2d_exact(A, B, C) == 0) continue;
    double area = std::fabs((B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]));
    if (!std::isfinite(area)) area = 0;  // huge coordinates: any c exactly off the line will do
    if (area > best_area) best_area = area, best = c;
  }
  // a and b are at distinct locations and some point is exactly off their line:
  // otherwise all points would lie on one line (all x equal when a, b coincide).
  if (best < 0) throw std::logic_error("interior_kernel: no point off the line of the x-extremes");
  const double* C = ps.point(static_cast<Index>(best));
  const double* pts[4] = {A, B, C, C};
  return pred::RationalPoint::centroid(pts, 4, 2);
}

// ---- star-shapedness ---------------------------------------------------------
bool is_star_shaped(const StarKernel& s, const std::vector<Index>& polygon) {
  const PointSet& ps = s.points();
  const std::size_t m = polygon.size();
  if (m < 3) return false;
  std::vector<char> seen(ps.size(), 0);
  for (Index v : polygon) {
    if (v >= ps.size() || seen[v]) return false;
    seen[v] = 1;
  }
  std::size_t crossings = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Index p = polygon[k], q = polygon[(k + 1) % m];
    if (s.orient(p, q) <= 0) return false;                      // condition (1)
    if (s.compare_y(p) < 0 && s.compare_y(q) > 0) ++crossings;  // crosses γ
  }
  return crossings == 1;  // condition (2)
}

bool is_star_shaped(const PointSet& ps, const std::vector<Index>& polygon, const pred::RationalPoint& kernel) {
  return is_star_shaped(StarKernel(ps, kernel), polygon);
}

// ---- plumbing ------------------------------------------------------------------
void require_polygon(const PointSet& ps, const std::vector<Index>& polygon, const char* who) {
  if (ps.dim != 2) throw std::invalid_argument(std::string(who) + ": 2D points are needed");
  if (polygon.size() < 3)
    throw std::invalid_argument(std::string(who) + ": a polygon has at least 3 vertices, got " +
                                std::to_string(polygon.size()));
  std::vector<char> seen(ps.size(), 0);
  for (Index v : polygon) {
    if (v >= ps.size())
      throw std::invalid_argument(std::string(who) + ": vertex " + std::to_string(v) + " is not a point index (" +
                                  std::to_string(ps.size()) + " points)");
    if (seen[v]) throw std::invalid_argument(std::string(who) + ": vertex " + std::to_string(v) + " is repeated");
    seen[v] = 1;
  }
}

void require_planar_input(const PointSet& ps, const char* who) {
  if (ps.dim != 2) throw std::invalid_argument(std::string(who) + ": 2D points are needed");
  if (std::string why = dimension_problem(ps); !why.empty())
    throw std::invalid_argument(std::string(who) + ": " + why);
}

bool cycle_spans_plane(const PointSet& ps, const std::vector<Index>& cycle) {
  if (cycle.empty()) return false;
  const double* a = ps.point(cycle[0]);
  const double* b = nullptr;
  for (Index v : cycle) {
    const double* q = ps.point(v);
    if (!b) {
      if (q[0] != a[0] || q[1] != a[1]) b = q;
    } else if (pred::orient2d_exact(a, b, q) != 0) {
      return true;
    }
  }
  return false;
}

std::vector<Index> rotate_to_smallest(std::vector<Index> cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}

}  // namespace flipflop::ref

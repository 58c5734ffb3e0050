// dimension.cpp — exact affine dimension by incremental independence tests.
#include "reference/dimension.hpp"

#include "predicates/predicates.hpp"

namespace flipflop {

namespace {
bool same_location(const PointSet& ps, std::size_t a, std::size_t b) {
  for (int j = 0; j < ps.dim; ++j)
    if (ps.point(a)[j] != ps.point(b)[j]) return false;
  return true;
}

// Three points of R^3 are collinear iff all three coordinate projections of the
// triangle have zero signed area.
bool collinear3(const double* a, const double* b, const double* c) {
  const int axes[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (const auto& ax : axes) {
    double pa[2] = {a[ax[0]], a[ax[1]]}, pb[2] = {b[ax[0]], b[ax[1]]}, pc[2] = {c[ax[0]], c[ax[1]]};
    if (pred::orient2d_exact(pa, pb, pc) != 0) return false;
  }
  return true;
}
}  // namespace

int affine_dimension(const PointSet& ps) {
  const std::size_t n = ps.size();
  if (n == 0) return -1;
  std::size_t b = 1;
  while (b < n && same_location(ps, 0, b)) ++b;
  if (b == n) return 0;
  if (ps.dim == 1) return 1;
  std::size_t c = b + 1;
  if (ps.dim == 2) {
    while (c < n && pred::orient2d_exact(ps.point(0), ps.point(b), ps.point(c)) == 0) ++c;
    return c == n ? 1 : 2;
  }
  // dim == 3
  while (c < n && collinear3(ps.point(0), ps.point(b), ps.point(c))) ++c;
  if (c == n) return 1;
  std::size_t d = c + 1;
  while (d < n && pred::orient3d_exact(ps.point(0), ps.point(b), ps.point(c), ps.point(d)) == 0) ++d;
  return d == n ? 2 : 3;
}

std::string dimension_problem(const PointSet& ps) {
  const std::size_t n = ps.size();
  if (n < static_cast<std::size_t>(ps.dim) + 1)
    return std::to_string(n) + " point" + (n == 1 ? "" : "s") + ", at least " +
           std::to_string(ps.dim + 1) + " needed in " + std::to_string(ps.dim) + "D";
  int d = affine_dimension(ps);
  if (d == ps.dim) return {};
  static const char* what[] = {"equal", "collinear", "coplanar"};
  return "input is lower-dimensional: all " + std::to_string(n) + " points are " + what[d] +
         " (affine dimension " + std::to_string(d) + ")";
}

}  // namespace flipflop

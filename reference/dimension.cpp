// dimension.cpp — exact affine dimension by incremental independence tests.
#include "reference/dimension.hpp"

#include <gmpxx.h>

#include <vector>

#include "predicates/predicates.hpp"

namespace flipflop {

namespace {
bool same_location(const PointSet& ps, std::size_t a, std::size_t b) {
  for (int j = 0; j < ps.dim; ++j)
    if (ps.point(a)[j] != ps.point(b)[j]) return false;
  return true;
}

// d >= 4: the rank of the difference vectors p_i - p_0, by exact rational
// Gaussian elimination (doubles convert to mpq exactly). The basis is kept in
// echelon form: basis[k] has its leading entry in column lead[k]. Stops as
// soon as the rank is d (general input: after about d+1 points).
int affine_dimension_rational(const PointSet& ps) {
  const std::size_t n = ps.size();
  const int d = ps.dim;
  std::vector<std::vector<mpq_class>> basis;
  std::vector<int> lead;
  std::vector<mpq_class> v(static_cast<std::size_t>(d));
  for (std::size_t i = 1; i < n && static_cast<int>(basis.size()) < d; ++i) {
    for (int j = 0; j < d; ++j) v[j] = mpq_class(ps.point(i)[j]) - mpq_class(ps.point(0)[j]);
    for (std::size_t k = 0; k < basis.size(); ++k) {
      const int c = lead[k];
      if (v[c] == 0) continue;
      const mpq_class f = v[c] / basis[k][c];
      for (int j = 0; j < d; ++j) v[j] -= f * basis[k][j];
    }
    int c = 0;
    while (c < d && v[c] == 0) ++c;
    if (c < d) {
      basis.push_back(v);
      lead.push_back(c);
    }
  }
  return static_cast<int>(basis.size());
}
}  // namespace

int affine_dimension(const PointSet& ps) {
  const std::size_t n = ps.size();
  if (n == 0) return -1;
  std::size_t b = 1;
  while (b < n && same_location(ps, 0, b)) ++b;
  if (b == n) return 0;
  if (ps.dim == 1) return 1;
  if (ps.dim >= 4) return affine_dimension_rational(ps);
  std::size_t c = b + 1;
  if (ps.dim == 2) {
    while (c < n && pred::orient2d_exact(ps.point(0), ps.point(b), ps.point(c)) == 0) ++c;
    return c == n ? 1 : 2;
  }
  // dim == 3
  while (c < n && pred::collinear3_exact(ps.point(0), ps.point(b), ps.point(c))) ++c;
  if (c == n) return 1;
  std::size_t d = c + 1;
  while (d < n && pred::orient3d_exact(ps.point(0), ps.point(b), ps.point(c), ps.point(d)) == 0) ++d;
  return d == n ? 2 : 3;
}

std::string dimension_problem(std::size_t n, int dim, int affine_dim) {
  if (n < static_cast<std::size_t>(dim) + 1)
    return std::to_string(n) + " point" + (n == 1 ? "" : "s") + ", at least " + std::to_string(dim + 1) +
           " needed in " + std::to_string(dim) + "D";
  const int d = affine_dim;
  if (d == dim) return {};
  static const char* what[] = {"are equal", "are collinear", "are coplanar"};
  return "input is lower-dimensional: all " + std::to_string(n) + " points " +
         (d <= 2 ? std::string(what[d]) : "lie in an affine subspace of dimension " + std::to_string(d)) +
         " (affine dimension " + std::to_string(d) + ")";
}

std::string dimension_problem(const PointSet& ps) {
  const std::size_t n = ps.size();
  if (n < static_cast<std::size_t>(ps.dim) + 1) return dimension_problem(n, ps.dim, 0);
  return dimension_problem(n, ps.dim, affine_dimension(ps));
}

}  // namespace flipflop

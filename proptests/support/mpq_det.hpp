// mpq_det.hpp — exact determinant signs over GMP rationals for the tests:
// an oracle independent of pred:: and of CGAL (doubles are dyadic
// rationals, Gaussian elimination over mpq_class).
#pragma once

#include <gmpxx.h>

#include <utility>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop::test {

// Sign of det m (k x k).
inline int mpq_det_sign(std::vector<std::vector<mpq_class>> m) {
  const std::size_t k = m.size();
  int sign = 1;
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t r = c;
    while (r < k && m[r][c] == 0) ++r;
    if (r == k) return 0;
    if (r != c) {
      std::swap(m[r], m[c]);
      sign = -sign;
    }
    if (m[c][c] < 0) sign = -sign;
    for (std::size_t i = c + 1; i < k; ++i) {
      const mpq_class f = m[i][c] / m[c][c];
      for (std::size_t j = c; j < k; ++j) m[i][j] -= f * m[c][j];
    }
  }
  return sign;
}

// The sign of det[p_1 - p_0, ..., p_d - p_0] of the points `t` in that order
// (the volume convention of the output).
inline int exact_volume_sign(const PointSet& ps, const std::vector<Index>& t) {
  const auto d = static_cast<std::size_t>(ps.dim);
  std::vector<std::vector<mpq_class>> m(d, std::vector<mpq_class>(d));
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = 0; j < d; ++j) m[i][j] = mpq_class(ps.point(t[i + 1])[j]) - mpq_class(ps.point(t[0])[j]);
  return mpq_det_sign(std::move(m));
}

}  // namespace flipflop::test

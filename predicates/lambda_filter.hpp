// lambda_filter.hpp — floating-point filters for the sign of Λ-determinants.
//
// Every predicate of flipflop is the sign of a "Λ-matrix" determinant
// (Edelsbrunner–Mücke [EM90] §4): k = m+1 rows, one per point, holding the
// point's m coordinates followed by a constant 1,
//
//        | a_1,1  ...  a_1,m   1 |
//   Λ =  |  ...         ...   ... |        sign(det Λ) = orientation of the
//        | a_k,1  ...  a_k,m   1 |        k points in R^m.
//
// For the lifting map (regular triangulations, thesis §2.2) the last
// coordinate is the height h = |x|^2 - w of a weighted point.
//
// Evaluation. Subtracting the last row from the others and expanding along the
// 1-column gives det Λ = det T with T_ij = a_ij - a_kj (i, j < k), an
// (m x m) determinant of differences. For a lifted height the column of
// differences h_i - h_k = |a_i - a_k|^2 - (w_i - w_k) + 2 a_k·(a_i - a_k); the
// last term is the same linear combination of the other columns in every row,
// so it is dropped without changing the determinant: lifted column entries are
// |a_i - a_k|^2 - (w_i - w_k), which is also the numerically better form
// (Shewchuk's incircle, [She97] §4.4).
//
// The determinant of T is expanded by minors (Laplace, row by row over column
// subsets), every operation in ErrDouble, so the filter's error bound is proven
// by construction (err_double.hpp). The result is +1/-1 when certain and 0 when
// the exact stage must decide.
//
// Header-only and __host__ __device__ (used by the CUDA kernels and their OpenMP
// build).
#pragma once

#include <utility>

#include "err_double.hpp"

namespace flipflop::pred {

FF_HD constexpr int popcount_small(unsigned s) {
  int c = 0;
  for (; s != 0; s &= s - 1) ++c;
  return c;
}

// The Laplace expansion below for N <= 4, written out (the same operations in
// the same order, so the same values: for the double-double types of err_dd.hpp
// and dd_filter.hpp the loop's subset bookkeeping cost more than the
// arithmetic), and always inlined (FF_FORCEINLINE: dd_filter.hpp's FMA
// instantiation must be compiled inside its caller). det_minor2(a, b): the
// level-2 minor on columns a < b (rows 0, 1); d012 etc.: level 3 (row 2).
template <int N, class V>
FF_HD FF_FORCEINLINE V det_minor2(const V* t, int a, int b) {
  return -(t[N + a] * t[b]) + t[N + b] * t[a];
}
template <int N, class V>
FF_HD FF_FORCEINLINE V det_small(const V* t) {
  static_assert(N >= 1 && N <= 4, "det_small supports N in 1..4");
  if constexpr (N == 1) {
    return t[0];
  } else if constexpr (N == 2) {
    return t[0] * t[3] - t[1] * t[2];
  } else if constexpr (N == 3) {
    const V m01 = det_minor2<N>(t, 0, 1), m02 = det_minor2<N>(t, 0, 2), m12 = det_minor2<N>(t, 1, 2);
    return (t[6] * m12 - t[7] * m02) + t[8] * m01;
  } else {
    const V m01 = det_minor2<N>(t, 0, 1), m02 = det_minor2<N>(t, 0, 2), m03 = det_minor2<N>(t, 0, 3);
    const V m12 = det_minor2<N>(t, 1, 2), m13 = det_minor2<N>(t, 1, 3), m23 = det_minor2<N>(t, 2, 3);
    const V d012 = (t[8] * m12 - t[9] * m02) + t[10] * m01;
    const V d013 = (t[8] * m13 - t[9] * m03) + t[11] * m01;
    const V d023 = (t[8] * m23 - t[10] * m03) + t[11] * m02;
    const V d123 = (t[9] * m23 - t[10] * m13) + t[11] * m12;
    return ((-(t[12] * d123) + t[13] * d023) - t[14] * d013) + t[15] * d012;
  }
}

// Levels 1..R of the Laplace expansion over column subsets of an N x N
// matrix t (row-major): d[S] = det(rows 0..|S|-1, columns S) for every column
// subset S with |S| <= R, each expanded along its last row in ascending column
// order, signs (-1)^((|S|-1) + position) — det_by_minors (R = N) and
// top_minors (static_filter.hpp, R = N - 1) share this operation order, on
// which the bounds derived for them rest. d holds 2^N entries.
//
// The subsets are visited in increasing numeric order (every subset needed by
// d[S], S less one column, is smaller than S), one instantiation per subset
// (minor_of_subset<..., S>: its size, the row and the columns are constants,
// so the loop over the columns unrolls and no subset bookkeeping is left at
// run time — the loop over all 2^N subsets per level with a popcount test
// cost more than the arithmetic for N = 5, 6). Each d[S] is the same
// expression in the same order as before, so the same value bit for bit.
// (Lo: the levels up to Lo are already in d; dd_filter_sign_wide computes
// them in binary64 where that is exact.)
template <int N, int R, class V, int S, int Lo = 1>
FF_HD FF_FORCEINLINE void minor_of_subset(const V* t, V* d) {
  constexpr int r = popcount_small(static_cast<unsigned>(S));
  if constexpr (r >= 2 && r > Lo && r <= R) {
    V acc{};  // assigned by the first term (value-initialised: no maybe-uninitialized)
    bool first = true;
    int pos = 0;  // position of column j inside subset S
    for (int j = 0; j < N; ++j) {
      if (!(S & (1 << j))) continue;
      // Laplace along row r-1: sign (-1)^((r-1) + pos)
      const V term = t[(r - 1) * N + j] * d[S & ~(1 << j)];
      const bool negative = ((r - 1 + pos) & 1) != 0;
      if (first) {
        acc = negative ? -term : term;
        first = false;
      } else {
        acc = negative ? acc - term : acc + term;
      }
      ++pos;
    }
    d[S] = acc;
  }
}

template <int N, int R, class V, int... S>
FF_HD FF_FORCEINLINE void minors_of_subsets(const V* t, V* d, std::integer_sequence<int, S...>) {
  (minor_of_subset<N, R, V, S>(t, d), ...);
}
template <int N, int Lo, class V, int... S>
FF_HD FF_FORCEINLINE void minors_above(const V* t, V* d, std::integer_sequence<int, S...>) {
  (minor_of_subset<N, N, V, S, Lo>(t, d), ...);
}

template <int N, int R, class V>
FF_HD inline void minor_levels(const V* t, V* d) {
  for (int j = 0; j < N; ++j) d[1 << j] = t[j];  // row 0, single columns
  minors_of_subsets<N, R, V>(t, d, std::make_integer_sequence<int, (1 << N)>{});
}

// Determinant of an N x N matrix of ErrDouble (row-major) by expansion over
// column subsets: D[S] = det(rows 0..|S|-1, columns S). N <= 7. V may be any
// value type with a proven running error bound and +, -, * (ErrDD,
// err_dd.hpp: the same expansion one precision further). N <= 4: det_small.
template <int N, class V = ErrDouble>
FF_HD inline V det_by_minors(const V* t) {
  static_assert(N >= 1 && N <= 7, "det_by_minors supports N in 1..7");
  if constexpr (N <= 4) {
    return det_small<N, V>(t);
  } else {
    V d[1 << N];
    minor_levels<N, N, V>(t, d);
    return d[(1 << N) - 1];
  }
}

// det of an n x n ErrDouble matrix (row-major, n <= MaxN) by Gaussian
// elimination with partial pivoting on the computed values: exact arithmetic
// on the exact entries with the same pivot order gives det T exactly (every
// pivot used is certainly non-zero, tested below), so the running bound
// covers det T. Row i's factor is a_ip (1 / a_pp), one ErrDouble reciprocal
// per pivot and a product (covered as the quotient would be). n^3/3
// operations against det_by_minors' n 2^(n-1). det_gauss_rt (n <= 10): the
// dynamic filter of 9..11-row predicates and the d-dimensional certifier's
// facet forms beyond 5D; det_gauss<N> (a compile-time order, the loops
// unrolled): sos_lazy's search (exact_expansion.hpp errdouble_minor_lazy),
// N = 5..7. Tested on its own against exact determinants
// (predicates_stages_test, "the ErrDouble Gaussian eliminations").
template <int MaxN>
FF_HD inline ErrDouble det_gauss_n(const ErrDouble* t, int n) {
  ErrDouble a[MaxN * MaxN];
  for (int i = 0; i < n * n; ++i) a[i] = t[i];
  bool negate = false;
  ErrDouble det(1.0);
  for (int p = 0; p < n; ++p) {
    int best = p;
    for (int i = p + 1; i < n; ++i)
      if (std::fabs(a[i * n + p].v) > std::fabs(a[best * n + p].v)) best = i;
    if (best != p) {
      for (int j = p; j < n; ++j) {
        const ErrDouble x = a[p * n + j];
        a[p * n + j] = a[best * n + j];
        a[best * n + j] = x;
      }
      negate = !negate;
    }
    const ErrDouble piv = a[p * n + p];
    if (!(std::fabs(piv.v) > piv.e)) return ErrDouble(0.0, HUGE_VAL);  // the pivot may be 0
    det = p == 0 ? piv : det * piv;
    if (p + 1 == n) break;
    const ErrDouble inv = ErrDouble(1.0) / piv;
    for (int i = p + 1; i < n; ++i) {
      const ErrDouble f = a[i * n + p] * inv;
      for (int j = p + 1; j < n; ++j) a[i * n + j] = a[i * n + j] - f * a[p * n + j];
    }
  }
  return negate ? -det : det;
}
template <int N>
FF_HD inline ErrDouble det_gauss(const ErrDouble* t) {
  return det_gauss_n<N>(t, N);
}
inline ErrDouble det_gauss_rt(const ErrDouble* t, int n) {
  if (n < 1 || n > 10) return ErrDouble(0.0, HUGE_VAL);
  return det_gauss_n<10>(t, n);
}

// The (k-1) x (k-1) matrix T of det Λ translated by the last row, in
// ErrDouble (row-major into t): plain, row i is p_i - p_{k-1}; lifted (w
// given, k-2 coordinates), row i is (p_i - p_{k-1}, |p_i - p_{k-1}|^2 -
// (w_i - w_{k-1})). The dynamic filters of every k share it
// (lambda_sign_filter<K> here, predicates.cpp's 9..11-row filter).
FF_HD inline void translated_lambda(int k, const double* const* p, const double* w, ErrDouble* t) {
  const int n = k - 1;
  const double* base = p[k - 1];
  if (w == nullptr) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) t[i * n + j] = ErrDouble(p[i][j]) - ErrDouble(base[j]);
  } else {
    const int m = n - 1;  // real coordinates per point
    for (int i = 0; i < n; ++i) {
      ErrDouble lift = ErrDouble(0.0);
      for (int j = 0; j < m; ++j) {
        const ErrDouble diff = ErrDouble(p[i][j]) - ErrDouble(base[j]);
        t[i * n + j] = diff;
        lift = (j == 0) ? diff * diff : lift + diff * diff;
      }
      t[i * n + m] = lift - (ErrDouble(w[i]) - ErrDouble(w[k - 1]));
    }
  }
}

// Filtered sign of det Λ for K points in R^(K-1) given by coordinate pointers.
// If `w` is non-null the last coordinate is the lifted height |x|^2 - w of the
// first K-2 coordinates (the points then have K-2 real coordinates each).
template <int K>
FF_HD inline int lambda_sign_filter(const double* const* p, const double* w) {
  constexpr int N = K - 1;  // size of the translated determinant
  ErrDouble t[N * N];
  translated_lambda(K, p, w, t);
  return sign_if_certain(det_by_minors<N>(t));
}

// Filtered sign of det Λ for K rows of K-1 coordinates that are themselves
// uncertain (ErrDouble values with error bounds), e.g. a rounded rational
// kernel point: rows[i * (K-1) + j] is coordinate j of row i.
template <int K>
FF_HD inline int lambda_sign_filter_err(const ErrDouble* rows) {
  constexpr int N = K - 1;
  ErrDouble t[N * N];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) t[i * N + j] = rows[i * N + j] - rows[(K - 1) * N + j];
  return sign_if_certain(det_by_minors<N>(t));
}

}  // namespace flipflop::pred

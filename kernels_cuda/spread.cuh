// spread.cuh — reductions the 3D kernels of kernels_cuda/ share (hull3.cuh's
// ffHull, ghull.cuh's gHull, rt3.cuh's triangulation): the bounding box of the
// points, and thesis Algorithm 7 line 1's four spread-out points by arg-max
// reductions of floating keys (a heuristic: the points are accepted only when
// exactly affinely independent; where they are not, further reductions on
// exact signs repair them, and only input that does not span R^3 reaches the
// reference's rule, which rejects it).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "kernels_cuda/device_predicates.cuh"
#include "predicates/predicates.hpp"
#include "reference/hull3/ffhull.hpp"
#include "reference/point_set.hpp"

namespace flipflop::dev {

// ---- the bounding box -------------------------------------------------------------
struct Box {
  double lo[3], hi[3];
};
struct PointBox {
  const double* xyz;
  FF_HD Box operator()(std::uint32_t i) const {
    const double* x = xyz + 3 * static_cast<std::size_t>(i);
    return {{x[0], x[1], x[2]}, {x[0], x[1], x[2]}};
  }
};
struct BoxUnion {
  FF_HD Box operator()(const Box& a, const Box& b) const {
    Box r;
    for (int k = 0; k < 3; ++k) {
      r.lo[k] = a.lo[k] < b.lo[k] ? a.lo[k] : b.lo[k];
      r.hi[k] = a.hi[k] > b.hi[k] ? a.hi[k] : b.hi[k];
    }
    return r;
  }
};

// ---- arg-max reductions -----------------------------------------------------------
struct Best {
  double key;
  Index id;
};
// the larger key; ties: the smaller index (a total order: keys are never NaN)
struct BestOf {
  FF_HD Best operator()(const Best& x, const Best& y) const {
    if (x.key > y.key) return x;
    if (y.key > x.key) return y;
    return x.id < y.id ? x : y;
  }
};

// Line 1's keys (kernels_cpu/hull3/ffhull.cpp's approximations): mode 0: -x,
// 1: x, 2: squared distance to the line A + R u, 3: |N · (p - A)|, 4: the
// largest |coordinate|. Modes 2 and 3 work on the coordinates times `scale`,
// a power of two that brings the largest magnitude near 1 (exact: only the
// order of the keys matters, and products of 1e±300 would overflow or
// underflow); A, u and N are in those units.
struct TetKey {
  const double* xyz;
  int mode;
  double A[3], u[3], N[3];
  double scale = 1;
  FF_HD Best operator()(std::size_t i) const {
    const double* q = xyz + 3 * i;
    double k;
    if (mode == 4) {
      k = q[0] < 0 ? -q[0] : q[0];
      for (int j = 1; j < 3; ++j) k = (q[j] < 0 ? -q[j] : q[j]) > k ? (q[j] < 0 ? -q[j] : q[j]) : k;
      return {k == k ? k : -HUGE_VAL, static_cast<Index>(i)};
    }
    const double p[3] = {q[0] * scale, q[1] * scale, q[2] * scale};
    if (mode == 0) {
      k = -p[0];
    } else if (mode == 1) {
      k = p[0];
    } else if (mode == 2) {
      const double w0 = p[0] - A[0], w1 = p[1] - A[1], w2 = p[2] - A[2];
      const double x = u[1] * w2 - u[2] * w1, y = u[2] * w0 - u[0] * w2, z = u[0] * w1 - u[1] * w0;
      k = x * x + y * y + z * z;
    } else {
      k = N[0] * (p[0] - A[0]) + N[1] * (p[1] - A[1]) + N[2] * (p[2] - A[2]);
      k = k < 0 ? -k : k;
    }
    return {k == k ? k : -HUGE_VAL, static_cast<Index>(i)};
  }
};

// Line 1's exact repair: key 1 for the points that qualify, -inf for the
// others, so that the arg-max (ties: the least index) is the least qualifying
// point, or a point that does not qualify when none does (the caller checks).
// mode 0: differs from A; 1: off the line AB (some coordinate-plane projection
// of A, B, p has a nonzero exact area: the cross product's components);
// 2: off the plane ABC (exact orient3d). Exact signs: device_predicates.cuh's
// staged path without ids (no perturbation; exact for every finite double,
// subnormals and 1e±300 included), so the same answer on the device and in
// the OpenMP build.
struct OffKey {
  const double* xyz;
  int mode;
  double A[3], B[3], C[3];
  FF_HD static bool off_line(const double* a, const double* b, const double* p) {
    for (int j = 0; j < 3; ++j) {
      const int u = j, v = j == 2 ? 0 : j + 1;
      const double pa[2] = {a[u], a[v]}, pb[2] = {b[u], b[v]}, pp[2] = {p[u], p[v]};
      const double* rows[3] = {pa, pb, pp};
      if (lambda<3>(nullptr, static_cast<const PointId*>(nullptr), rows, nullptr) != 0) return true;
    }
    return false;
  }
  FF_HD bool qualifies(const double* p) const {
    if (mode == 0) return p[0] != A[0] || p[1] != A[1] || p[2] != A[2];
    if (mode == 1) return off_line(A, B, p);
    const double* rows[4] = {A, B, C, p};
    return lambda<4>(nullptr, static_cast<const PointId*>(nullptr), rows, nullptr) != 0;
  }
  FF_HD Best operator()(std::size_t i) const {
    return {qualifies(xyz + 3 * i) ? 1.0 : -HUGE_VAL, static_cast<Index>(i)};
  }
};

// Line 1 by reductions (argmax(key): the arg-max of the key, a TetKey or an
// OffKey, over every point, a reduction where the points live). The floating
// keys' four points are kept where exactly independent; where a step's point
// is not (equal to a, on the line ab, on the plane abc: floating keys that
// tie, underflow or round, e.g. subnormal coordinates beside ones near 1),
// that step is repeated with an OffKey, whose answer is exact. Only input
// that does not span R^3 leaves a step without a point: then the reference's
// rule (ref::ffhull::initial_tetrahedron, a sequential pass on the host)
// throws its std::invalid_argument. (a, b, c) is counter-clockwise seen from
// outside: d on its inner side. by_reference (optional): set when the
// reference's rule ran (the kernels count it as work handed back; it can
// only return for a bug, which is then reported as one).
template <class Argmax>
std::array<Index, 4> spanning_tetrahedron(const PointSet& ps, const double* xyz, const Argmax& argmax,
                                          bool* by_reference = nullptr) {
  if (by_reference) *by_reference = false;
  TetKey key{xyz, 4, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  {
    double big = 0;
    for (int j = 0; j < 3; ++j) big = std::max(big, std::fabs(ps.point(argmax(key))[j]));
    int e = 0;
    if (big > 0 && std::isfinite(big)) std::frexp(big, &e);
    key.scale = std::ldexp(1.0, -e);
  }
  OffKey off{xyz, 0, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  // the exact repair of one step: the least qualifying point, or the
  // reference's rejection of input that does not span R^3
  const auto repair = [&](int mode) {
    off.mode = mode;
    const Index m = argmax(off);
    if (off.qualifies(ps.point(m))) return m;
    if (by_reference) *by_reference = true;
    ref::ffhull::initial_tetrahedron(ps);  // throws for input not spanning R^3
    throw std::logic_error("hull3 line 1: no point off the span of the others, yet the input spans R^3");
  };
  key.mode = 0;
  const Index a = argmax(key);
  const double* A = ps.point(a);
  for (int j = 0; j < 3; ++j) off.A[j] = A[j];
  key.mode = 1;
  Index b = argmax(key);
  if (!off.qualifies(ps.point(b))) b = repair(0);
  const double* Bp = ps.point(b);
  for (int j = 0; j < 3; ++j) off.B[j] = Bp[j];
  const double sc = key.scale;
  for (int j = 0; j < 3; ++j) key.A[j] = A[j] * sc, key.u[j] = Bp[j] * sc - A[j] * sc;
  key.mode = 2;
  Index c = argmax(key);
  off.mode = 1;
  if (!off.qualifies(ps.point(c))) c = repair(1);
  const double* Cp = ps.point(c);
  for (int j = 0; j < 3; ++j) off.C[j] = Cp[j];
  const double v[3] = {Cp[0] * sc - A[0] * sc, Cp[1] * sc - A[1] * sc, Cp[2] * sc - A[2] * sc};
  key.N[0] = key.u[1] * v[2] - key.u[2] * v[1];
  key.N[1] = key.u[2] * v[0] - key.u[0] * v[2];
  key.N[2] = key.u[0] * v[1] - key.u[1] * v[0];
  key.mode = 3;
  Index d = argmax(key);
  int o = pred::orient3d_exact(A, Bp, Cp, ps.point(d));
  if (o == 0) {
    d = repair(2);
    o = pred::orient3d_exact(A, Bp, Cp, ps.point(d));
  }
  if (o < 0) return {a, c, b, d};
  return {a, b, c, d};
}

}  // namespace flipflop::dev

// twist_flip.cpp — twist-flip, thesis §8.4.1, Algorithms 12 and 13, and the
// hull pipeline twist-flip + flip-flop (see twist_flip.hpp).
//
// Sign identities used by the predicates (v above s, H the horizontal plane
// through s, p* = v + λ_p (p - v) with λ_p > 0 the central projection of p
// onto H; every identity holds in the perturbed configuration, where all the
// signs are non-zero):
//
//  (1) orient3d(v, p, q, x) for x in H. orient3d(v, p, q, x) = ±det[p - v,
//      q - v, x - v]; scaling a row by λ > 0 keeps the sign, so p, q may be
//      replaced by p*, q*. For three points of H and v above H, orient3d(p*, q*,
//      x, v) > 0 iff v is below the plane when p*, q*, x are counter-clockwise
//      seen from above (predicates.hpp), i.e. iff they are clockwise; and
//      orient3d(v, p, q, x) = -orient3d(p, q, x, v) (a 4-cycle is odd). Hence
//          orient3d(v, p, q, x) = orient2d_H(x, p*, q*),
//      the orientation inside H seen from above. With x = s this is "△spq
//      counter-clockwise" of Algorithm 11, which Algorithm 12 simulates.
//  (2) The plane △vss' (s' = s + t e_x, any t > 0) is the plane through v and
//      the line of H through s parallel to x. orient3d(v, s, s', p) =
//      det Λ with the row s' - s = t e_x: its sign is that of the (y, z)
//      orientation orient2d_yz(v, s, p) = (s.y - v.y)(p.z - v.z) -
//      (s.z - v.z)(p.y - v.y). Replacing p by p* (a positive multiple of
//      p - v, p*.z = s.z) gives (s.z - v.z)(s.y - p*.y), and s.z < v.z, so
//          orient2d_yz(v, s, p) = sign(p*.y - s.y):
//      p* above the horizontal line of H through s. The (y, z) determinant is
//      evaluated with the SoS of the same perturbation: the dominance order of
//      predicates.hpp depends only on the order of the indices and of the
//      columns within a row, and (y, z) keep theirs.
//  (3) s' = (+∞, s.y, s.z): orient3d(v, p, q, s') has the sign of the
//      coefficient of s'.x in the 4x4 determinant, the cofactor
//      -orient2d_yz(v, p, q); by the computation of (2) with p*, q*,
//      orient2d_yz(v, p, q) = (s.z - v.z)(p*.y - q*.y), so
//          orient3d(v, p, q, s') = sign(p*.y - q*.y) = orient2d_H(s', p*, q*),
//      exactly as Algorithm 11 computes orient2d(s', p, q) (twist.cpp).
//  (4) The flipping stage compares sides of lines inside H through (1) with v
//      in the last place: orient3d(a, b, x, v) = -orient2d_H(a*, b*, x*), so
//      "x is on the same side of a*b* as d*" is sign orient3d(a, b, x, v) =
//      sign orient3d(a, b, d, v).
#include "reference/hull3/twist_flip.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "predicates/predicates.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"
#include "reference/hull3/flip_flop_3d.hpp"
#include "reference/hull3/twist_flip_input.hpp"

namespace flipflop::ref {

namespace {

pred::Pt pt(const PointSet& ps, Index i) { return {i, ps.point(i)}; }
// the (y, z) projection of an input point, with its own SoS index (identity (2))
pred::Pt pt_yz(const PointSet& ps, Index i) { return {i, ps.point(i) + 1}; }

std::uint64_t key(Index a, Index b) { return (std::uint64_t(a) << 32) | b; }

[[noreturn]] void reject(const std::string& why) { throw std::invalid_argument("twist_flip: " + why); }

std::string tri_str(const Triangle& t) {
  return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + ")";
}


}  // namespace

// ============================================================================
// TwistFlipKernel: κ = v + η (s - v) (twist_flip.hpp, "The kernel point")
// ============================================================================

TwistFlipKernel::TwistFlipKernel(const PointSet& ps, Index v, const pred::RationalPoint& s)
    : ps_(&ps), v_(v), s_(s) {
  if (ps.dim != 3 || s.dim != 3 || s.exact.size() != 3)
    throw std::invalid_argument("TwistFlipKernel: 3D points and a 3D secondary kernel are needed");
  if (v >= ps.size()) throw std::invalid_argument("TwistFlipKernel: index out of range");
}

int TwistFlipKernel::side(Index a, Index b, Index c) const {
  const PointSet& ps = *ps_;
  if (a != v_ && b != v_ && c != v_) return pred::orient3d(pt(ps, a), pt(ps, b), pt(ps, c), pt(ps, v_));
  // v in {a, b, c}: the η term, orient3d(a, b, c, s), s with SoS index n
  const pred::MixedRow rows[4] = {{a, ps.point(a), nullptr},
                                  {b, ps.point(b), nullptr},
                                  {c, ps.point(c), nullptr},
                                  {static_cast<pred::PointId>(ps.size()), nullptr, &s_}};
  return pred::mixed_sign(4, rows, true);
}

// ============================================================================
// The precondition and the initial state
// ============================================================================

struct TwistFlip::Prepared {
  std::vector<Index> order;
  std::vector<std::array<std::uint32_t, 3>> disk;
  pred::RationalPoint s;
};

TwistFlip::Prepared TwistFlip::prepare(const PointSet& ps, const std::vector<Triangle>& poly, Index v) {
  if (ps.dim != 3) reject("the points must be 3D");
  if (poly.size() < 4) reject("a closed polyhedron has at least 4 triangles, got " + std::to_string(poly.size()));
  const std::size_t n = ps.size();
  // --- a closed, coherently oriented 2-manifold (§8.1): every directed edge
  // once, and its reverse present (each edge in exactly two triangles, which
  // induce opposite orientations on it)
  std::unordered_map<std::uint64_t, std::uint32_t> tri_of;
  tri_of.reserve(poly.size() * 6);
  std::vector<std::uint8_t> is_vertex(n, 0);
  for (std::uint32_t t = 0; t < poly.size(); ++t) {
    const Triangle& T = poly[t];
    for (Index i : T)
      if (i >= n) reject("triangle " + tri_str(T) + " has an index out of range (" + std::to_string(n) + " points)");
    if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2]) reject("triangle " + tri_str(T) + " repeats a vertex");
    for (int k = 0; k < 3; ++k) {
      is_vertex[T[k]] = 1;
      if (!tri_of.emplace(key(T[k], T[(k + 1) % 3]), t).second)
        reject("the directed edge (" + std::to_string(T[k]) + "," + std::to_string(T[(k + 1) % 3]) +
               ") is in two triangles: not a coherently oriented 2-manifold");
    }
  }
  for (const Triangle& T : poly)
    for (int k = 0; k < 3; ++k)
      if (!tri_of.count(key(T[(k + 1) % 3], T[k])))
        reject("the edge (" + std::to_string(T[k]) + "," + std::to_string(T[(k + 1) % 3]) +
               ") has no triangle on its other side: the surface is not closed");
  // --- a sphere: connected (across edges) and Euler characteristic 2. An
  // edge-connected closed surface with a pinched vertex, or of genus > 0, has
  // V - E + F < 2.
  std::vector<std::uint8_t> seen(poly.size(), 0);
  std::vector<std::uint32_t> stack = {0};
  seen[0] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = tri_of.at(key(poly[t][(k + 1) % 3], poly[t][k]));
      if (!seen[u]) seen[u] = 1, ++reached, stack.push_back(u);
    }
  }
  if (reached != poly.size()) reject("the surface is not connected");
  std::size_t V = 0;
  for (std::uint8_t b : is_vertex) V += b;
  const std::size_t E = poly.size() * 3 / 2, F = poly.size();
  const long chi = static_cast<long>(V) - static_cast<long>(E) + static_cast<long>(F);
  if (chi != 2)
    reject("the surface is not a sphere (Euler characteristic " + std::to_string(chi) +
           ", a pinched vertex or a handle)");
  // --- v: a vertex joined to all others, and topmost
  if (v >= n || !is_vertex[v]) reject("v = " + std::to_string(v) + " is not a vertex of the polyhedron");
  std::vector<Index> next(n, static_cast<Index>(n));  // link(v): (v, p, q) gives p -> q
  Index first = static_cast<Index>(n);
  std::size_t k = 0;
  for (const Triangle& T : poly)
    for (int j = 0; j < 3; ++j)
      if (T[j] == v) {
        const Index p = T[(j + 1) % 3], q = T[(j + 2) % 3];
        next[p] = q;
        if (first == n) first = p;
        ++k;
      }
  if (k != V - 1)
    reject("v = " + std::to_string(v) + " is adjacent to " + std::to_string(k) + " of the other " +
           std::to_string(V - 1) + " vertices, not to all");
  for (Index p = 0; p < n; ++p)
    if (is_vertex[p] && p != v && pred::compare_sos(pt(ps, p), pt(ps, v), 2) > 0)
      reject("v = " + std::to_string(v) + " is not the topmost vertex: " + std::to_string(p) + " is above it");
  Prepared out;
  std::vector<std::uint32_t> slot(n, 0);
  for (Index p = first; out.order.size() < k; p = next[p]) {
    if (p >= n || (p == first && !out.order.empty())) reject("link(v) is not one cycle");
    slot[p] = static_cast<std::uint32_t>(out.order.size());
    out.order.push_back(p);
  }
  if (next[out.order.back()] != first) reject("link(v) is not one cycle");
  // --- T over slots: the triangles without v (identity of §8.2: slots fixed)
  for (const Triangle& T : poly)
    if (T[0] != v && T[1] != v && T[2] != v) out.disk.push_back({slot[T[0]], slot[T[1]], slot[T[2]]});
  // --- the secondary kernel s (twist_flip.hpp)
  out.s = secondary_kernel(ps, out.order, v);
  return out;
}

pred::RationalPoint TwistFlip::secondary_kernel(const PointSet& ps, const std::vector<Index>& L, Index v) {
  const std::size_t k = L.size();
  const double* P = ps.point(v);
  auto independent = [&](Index a, Index b, Index c) {
    return pred::orient3d_exact(P, ps.point(a), ps.point(b), ps.point(c)) != 0;
  };
  // (1) s straight below v. Proposal (floating point, IEEE +, -, *, /, sqrt
  // only, so the same on every machine): the link vertices whose directions
  // from v's vertical line are closest to three directions 120 degrees apart,
  // and s halfway between v and the plane of those three.
  {
    const double h = std::sqrt(3.0) / 2;
    const double u[3][2] = {{1, 0}, {-0.5, h}, {-0.5, -h}};
    std::array<Index, 3> abc = {L[0], L[0], L[0]};
    double best[3] = {-2, -2, -2};
    for (Index p : L) {
      const double dx = ps.point(p)[0] - P[0], dy = ps.point(p)[1] - P[1];
      const double len = std::sqrt(dx * dx + dy * dy);
      if (!(len > 0) || !std::isfinite(len)) continue;
      for (int i = 0; i < 3; ++i) {
        const double cosine = (dx * u[i][0] + dy * u[i][1]) / len;
        if (cosine > best[i]) best[i] = cosine, abc[i] = p;
      }
    }
    if (independent(abc[0], abc[1], abc[2])) {
      const double* A = ps.point(abc[0]);
      const double* B = ps.point(abc[1]);
      const double* C = ps.point(abc[2]);
      const double nrm[3] = {(B[1] - A[1]) * (C[2] - A[2]) - (B[2] - A[2]) * (C[1] - A[1]),
                             (B[2] - A[2]) * (C[0] - A[0]) - (B[0] - A[0]) * (C[2] - A[2]),
                             (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0])};
      const double z_plane = A[2] - (nrm[0] * (P[0] - A[0]) + nrm[1] * (P[1] - A[1])) / nrm[2];
      const double below[3] = {P[0], P[1], 0.5 * P[2] + 0.5 * z_plane};
      const double* S = below;
      // Exact: s is in the open cone from v over abc iff it is on the side of
      // each of the planes vab, vbc, vca where the third vertex is.
      const int o = pred::orient3d_exact(P, A, B, C);
      if (std::isfinite(below[2]) && pred::orient3d_exact(P, A, B, S) == o &&
          pred::orient3d_exact(P, B, C, S) == o && pred::orient3d_exact(P, C, A, S) == o)
        return pred::RationalPoint::centroid(&S, 1, 3);  // the point itself, exactly
    }
  }
  // (2) s = (a + b + c + c) / 4: the link vertices at positions 0, k/3, 2k/3,
  // else the first triple in link order with a not at v's location, b off the
  // line va, c off the plane vab.
  std::array<Index, 3> abc = {L[0], L[k / 3], L[2 * k / 3]};
  if (!independent(abc[0], abc[1], abc[2])) {
    auto same_location = [&](Index p) { return std::equal(ps.point(p), ps.point(p) + 3, P); };
    std::size_t ja = 0;
    while (ja < k && same_location(L[ja])) ++ja;
    std::size_t jb = ja;
    while (jb < k && pred::collinear3_exact(ps.point(v), ps.point(L[ja]), ps.point(L[jb]))) ++jb;
    if (jb == k) reject("the vertices of the polyhedron are collinear");
    std::size_t jc = 0;
    while (jc < k && !independent(L[ja], L[jb], L[jc])) ++jc;
    if (jc == k) reject("the vertices of the polyhedron are coplanar");
    abc = {L[ja], L[jb], L[jc]};
  }
  const double* abcc[4] = {ps.point(abc[0]), ps.point(abc[1]), ps.point(abc[2]), ps.point(abc[2])};
  return pred::RationalPoint::centroid(abcc, 4, 3);
}

TwistFlip::TwistFlip(const PointSet& ps, const std::vector<Triangle>& polyhedron, Index v)
    : TwistFlip(ps, v, prepare(ps, polyhedron, v)) {}

TwistFlip::TwistFlip(const PointSet& ps, Index v, Prepared prep)
    : ps_(&ps), v_(v), order_(std::move(prep.order)), disk_(std::move(prep.disk)), kernel_(ps, v, prep.s) {
  pos_.assign(ps.size(), 0);
  for (std::uint32_t i = 0; i < order_.size(); ++i) pos_[order_[i]] = i;
  const pred::RationalPoint& s = kernel_.secondary();
  const int yz[2] = {1, 2};
  s_yz_ = s.project(yz, 2);
}

// ============================================================================
// Predicates (identities (1)-(4) of the file comment)
// ============================================================================

int TwistFlip::side_of_gamma_plane(Index p) const {
  // identity (2): orient2d_yz(v, s, p) = sign(p*.y - s.y)
  const PointSet& ps = *ps_;
  const pred::MixedRow rows[3] = {{v_, ps.point(v_) + 1, nullptr},
                                  {static_cast<pred::PointId>(ps.size()), nullptr, &s_yz_},
                                  {p, ps.point(p) + 1, nullptr}};
  return pred::mixed_sign(3, rows, true);
}

int TwistFlip::orient_vpq_s(Index p, Index q) const {
  // identity (1): = orient2d_H(s, p*, q*)
  const PointSet& ps = *ps_;
  const pred::MixedRow rows[4] = {{v_, ps.point(v_), nullptr},
                                  {p, ps.point(p), nullptr},
                                  {q, ps.point(q), nullptr},
                                  {static_cast<pred::PointId>(ps.size()), nullptr, &kernel_.secondary()}};
  return pred::mixed_sign(4, rows, true);
}

int TwistFlip::orient_vpq_s_far(Index p, Index q) const {
  // identity (3): orient3d(v, p, q, s') = -orient2d_yz(v, p, q)
  const PointSet& ps = *ps_;
  return -pred::orient2d(pt_yz(ps, v_), pt_yz(ps, p), pt_yz(ps, q));
}

bool TwistFlip::positive(Index a, Index b, Index c) const {
  const PointSet& ps = *ps_;
  return pred::orient3d(pt(ps, a), pt(ps, b), pt(ps, c), pt(ps, v_)) > 0;
}

// ============================================================================
// The twisting stage, Algorithm 12
// ============================================================================

bool TwistFlip::needs_twist(Index p, Index q) const {
  // line 5: if q is the first vertex of link(v) then continue
  if (pos_[q] == 0) return false;
  const int o = orient_vpq_s(p, q);  // orientation of △vpq w.r.t. s
  // line 6: the orientations of △vss' w.r.t. p and q differ, and those of
  // △vpq w.r.t. s and s' differ: the projected edge p*q* crosses γ
  const int sp = side_of_gamma_plane(p);
  if (sp != side_of_gamma_plane(q)) {
    const int o_far = orient_vpq_s_far(p, q);
    // p* and q* on opposite sides of the line y = s.y: sign(p*.y - q*.y) = sp
    FF_CHECK(o_far == sp, "identity (3): orient3d(v, p, q, s') disagrees with the sides of p and q");
    if (o != o_far) return o > 0;  // lines 7-9: twist if △vpq is counter-clockwise w.r.t. s
  }
  return o < 0;  // lines 10-13: twist if △vpq is clockwise w.r.t. s
}

// Checked build, Lemma 8.3: every link edge p -> q has orient3d(v, p, q, s) > 0
// (all of star(v) positive) and the projected link winds once around s: with
// all edges counter-clockwise around s, an edge crosses γ iff it goes from
// below the line y = s.y to above it, and there is exactly one such edge.
bool TwistFlip::link_is_star_shaped() const {
  const std::size_t k = order_.size();
  std::size_t crossings = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Index p = order_[i], q = order_[(i + 1) % k];
    if (orient_vpq_s(p, q) <= 0) return false;
    if (side_of_gamma_plane(p) < 0 && side_of_gamma_plane(q) > 0) ++crossings;
  }
  return crossings == 1;
}

void TwistFlip::twisting_stage(Hull3Stats* stats) {
  if (twisted_) throw std::logic_error("TwistFlip: the twisting stage has already run");
  twisted_ = true;
  const std::size_t k = order_.size();
  std::uint64_t twists = 0;
  // line 1 (s') is folded into needs_twist (identity (3)).
  // line 2: Q <- all triangles of star(v), as their link edges p -> q
  std::deque<std::pair<Index, Index>> queue;
  for (std::size_t i = 0; i < k; ++i) queue.emplace_back(order_[i], order_[(i + 1) % k]);
  while (!queue.empty()) {  // line 3
    const auto [p, q] = queue.front();  // line 4: △vpq
    queue.pop_front();
    // a triangle pushed earlier may have been destroyed by a later twist
    if ((pos_[p] + 1) % k != pos_[q]) continue;
    if (!needs_twist(p, q)) continue;  // lines 5-7, 10-11
    const std::uint32_t i = pos_[p];
    // Theorem 8.1 (bubble sort): the twist swaps an adjacent pair out of the
    // angular order g around s in H — an independent comparator: the upper
    // half-plane first (identity (2)), then orient2d_H(s, q*, p*) (identity (1)).
    FF_CHECK(side_of_gamma_plane(q) != side_of_gamma_plane(p) ? side_of_gamma_plane(q) > 0
                                                              : orient_vpq_s(q, p) > 0,
             "twist on a link edge p -> q with g(p) < g(q)");
    // lines 8, 12: twist pq — swap p and q in every triangle, i.e. their slots
    std::swap(order_[i], order_[i + 1]);
    pos_[p] = i + 1;
    pos_[q] = i;
    ++twists;
    // lines 9, 13: Q <- {△vrq, △vpt}, the triangles of star(v) next to △vqp
    const Index r = order_[(i + k - 1) % k], t = order_[(i + 2) % k];
    queue.emplace_back(r, q);
    queue.emplace_back(p, t);
  }
  FF_CHECK(link_is_star_shaped(), "Lemma 8.3: after the twisting stage star(v) is not star-shaped w.r.t. s");
  if (stats) stats->twists += twists;
}

// ============================================================================
// The flipping stage, Algorithm 13
// ============================================================================

void TwistFlip::flipping_stage(Hull3Stats* stats, std::vector<FoldFlip>* log) {
  if (!twisted_) throw std::logic_error("TwistFlip: the flipping stage needs the twisting stage first (Lemma 8.3)");
  if (flipped_) throw std::logic_error("TwistFlip: the flipping stage has already run");
  flipped_ = true;
  // T over points: the labels are final (no twist after this point)
  tris_.clear();
  for (const auto& t : disk_) tris_.push_back({order_[t[0]], order_[t[1]], order_[t[2]]});
  disk_.clear();
  std::unordered_map<std::uint64_t, std::uint32_t> tri_of;  // directed edge of T -> triangle
  tri_of.reserve(tris_.size() * 6);
  for (std::uint32_t t = 0; t < tris_.size(); ++t)
    for (int j = 0; j < 3; ++j) tri_of[key(tris_[t][j], tris_[t][(j + 1) % 3])] = t;
  auto third = [&](std::uint32_t t, Index a, Index b) {
    for (Index x : tris_[t])
      if (x != a && x != b) return x;
    return tris_[t][0];
  };
  // line 1: Q <- the edges of P \ (star(v) ∪ link(v)): the edges of T whose
  // both directions are in T (a link edge has star(v) on its other side)
  std::deque<std::pair<Index, Index>> queue;
  for (const Triangle& t : tris_)
    for (int j = 0; j < 3; ++j) {
      const Index a = t[j], b = t[(j + 1) % 3];
      if (a < b && tri_of.count(key(b, a))) queue.emplace_back(a, b);
    }
  std::uint64_t flips = 0;
  while (!queue.empty()) {  // line 2
    auto [a, b] = queue.front();  // line 3
    queue.pop_front();
    // line 4: △abc and △bad, the triangles of ab. An edge pushed earlier may
    // have been flipped away since; a missing side means the other triangle
    // is in star(v) (ab is a link edge, line 5).
    const auto i1 = tri_of.find(key(a, b)), i2 = tri_of.find(key(b, a));
    if (i1 == tri_of.end() || i2 == tri_of.end()) continue;  // line 5: v in {a, b, c, d}
    std::uint32_t t1 = i1->second, t2 = i2->second;
    Index c = third(t1, a, b), d = third(t2, a, b);
    const bool pos1 = positive(a, b, c);
    if (pos1 == positive(b, a, d)) continue;  // line 6: not a fold
    if (!pos1) {  // line 7: w.l.o.g. △abc is the positive one
      std::swap(a, b);
      std::swap(c, d);
      std::swap(t1, t2);
    }
    // line 8: △bas clockwise w.r.t. v, i.e. s on the side of ab where d is
    // (identity (4)): the primary vertex of △bad is d, neither a nor b
    const PointSet& ps = *ps_;
    const pred::MixedRow rows[4] = {{b, ps.point(b), nullptr},
                                    {a, ps.point(a), nullptr},
                                    {static_cast<pred::PointId>(ps.size()), nullptr, &kernel_.secondary()},
                                    {v_, ps.point(v_), nullptr}};
    if (pred::mixed_sign(4, rows, true) >= 0) continue;
    // Lemma 8.7: every inner edge of T is flippable — cd is not yet an edge
    // (T holds every edge of P but those of star(v), and a link edge has its
    // reverse in T)
    FF_CHECK(!tri_of.count(key(c, d)) && !tri_of.count(key(d, c)), "Lemma 8.7: the new edge cd is already in P");
    // line 9: flip ab — {△abc, △bad} -> {△adc, △bcd} (§8.2, Figure 8.5)
    tri_of.erase(key(a, b));
    tri_of.erase(key(b, a));
    tris_[t1] = {a, d, c};
    tris_[t2] = {b, c, d};
    tri_of[key(a, d)] = t1;
    tri_of[key(d, c)] = t1;
    tri_of[key(c, a)] = t1;
    tri_of[key(b, c)] = t2;
    tri_of[key(c, d)] = t2;
    tri_of[key(d, b)] = t2;
    ++flips;
    // Figure 8.9: case (b), two negative triangles, is never flipped
    FF_CHECK(positive(a, d, c) || positive(b, c, d), "Theorem 8.9: a fold flip created two negative triangles");
    if (log) log->push_back({a, b, c, d});
    // line 10: Q <- {ac, bc, ad, bd}
    queue.emplace_back(a, c);
    queue.emplace_back(b, c);
    queue.emplace_back(a, d);
    queue.emplace_back(b, d);
  }
  if constexpr (FF_CHECKED) {
    for (const Triangle& t : tris_) {
      FF_CHECK(positive(t[0], t[1], t[2]), "Theorem 8.9: a negative triangle is left");
      (void)t;
    }
  }
  if (stats) stats->fold_flips += flips;
}

std::vector<Triangle> TwistFlip::triangles() const {
  const std::size_t k = order_.size();
  std::vector<Triangle> out;
  out.reserve(k + std::max(disk_.size(), tris_.size()));
  for (std::size_t i = 0; i < k; ++i) out.push_back({v_, order_[i], order_[(i + 1) % k]});
  if (flipped_) {
    out.insert(out.end(), tris_.begin(), tris_.end());
  } else {
    for (const auto& t : disk_) out.push_back({order_[t[0]], order_[t[1]], order_[t[2]]});
  }
  return out;
}

// ============================================================================
// Entry points
// ============================================================================

std::vector<Triangle> twist_flip(const PointSet& ps, const std::vector<Triangle>& polyhedron, Index v,
                                 Hull3Stats* stats) {
  TwistFlip tf(ps, polyhedron, v);
  if (stats) *stats = Hull3Stats{};
  tf.twisting_stage(stats);
  tf.flipping_stage(stats);
  return tf.triangles();
}

std::vector<Triangle> hull3_twist_flip(const PointSet& ps, Hull3Stats* stats) {
  if (ps.dim != 3) throw std::invalid_argument("hull3_twist_flip: the points must be 3D");
  if (const std::string problem = dimension_problem(ps); !problem.empty()) throw std::invalid_argument(problem);
  if (stats) *stats = Hull3Stats{};
  SpecialInputOptions o;
  o.link = LinkOrder::angular;
  o.disk = DiskTriangulation::zigzag;
  const std::vector<Triangle> start = special_polyhedron(ps, o);
  TwistFlip tf(ps, start, topmost_point(ps));
  tf.twisting_stage(stats);
  tf.flipping_stage(stats);
  Hull3Stats ff;
  std::vector<Triangle> hull = flip_flop_3d(ps, tf.triangles(), tf.kernel(), &ff, true);
  if (stats) {
    ff.twists = stats->twists;
    ff.fold_flips = stats->fold_flips;
    *stats = ff;
  }
  return hull;
}

}  // namespace flipflop::ref

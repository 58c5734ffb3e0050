// certify_rtd.cpp — exact certification of a d-dimensional regular
// triangulation at the canonical level (SoS). The conditions and the
// local-to-global argument (thesis Thm 2.2 [ES92]) are in certify_rtd.hpp.
#include "reference/rtd/certify_rtd.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include <gmpxx.h>

#include "predicates/lambda_filter.hpp"
#include "reference/certify/certify_detail.hpp"
#include "predicates/predicates.hpp"
#include "predicates/static_filter.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/convex_surface.hpp"
#include "reference/rtd/rt_incremental.hpp"

namespace flipflop::certify {

namespace {

constexpr int kMaxD = ref::rtd::kMaxDim;
using FacetKey = std::array<Index, kMaxD>;  // sorted facet vertices, unused = ~0
using ErrDoubleRow = std::array<pred::ErrDouble, kMaxD + 1>;

std::string simplex_str(const std::vector<Index>& t) {
  std::string o = "(";
  for (std::size_t i = 0; i < t.size(); ++i) o += (i ? "," : "") + std::to_string(t[i]);
  return o + ")";
}

// The facet structure of a list of positive simplices: for each simplex and
// position i, the simplex across the facet opposite t[i] (-1: boundary).
struct Facets {
  int d = 0;
  std::vector<std::int64_t> across;  // simplices * (d+1)
  std::int64_t nb(std::size_t s, int i) const { return across[s * static_cast<std::size_t>(d + 1) + static_cast<std::size_t>(i)]; }
};

// The simplices' orientation convention (canonical_d.hpp): the certified
// output is in the volume convention; rtd_detail::tiling_problem's callers
// hand over the algorithms' orient_d-positive tuples. In odd d the two
// differ by one transposition, undone here on the last two points of every
// tuple before a predicate sees it, so that orient > 0 means "positive in
// the given convention" and power keeps its meaning below.
struct Checker {
  const PointSet& ps;
  int d;
  Orientation given;
  bool exact = false;  // Level::exact: unperturbed signs (may be 0), weak conditions
  bool furthest = false;  // the furthest-site triangulation: every power sign negated
  // the static filter of the input's values (every call below is on input
  // points), set by with_filter(); the default one decides nothing. On an
  // integer lattice it also sends the calls to the integer walk first
  // (staged.hpp, kLatticeFirstK).
  pred::StaticFilter filter;
  Checker& with_filter(const Speedups& speedups) {
    filter = speedups.make_filter ? speedups.make_filter({})
                                  : pred::StaticFilter::for_points(ps.coords.data(), ps.size(), ps.dim,
                                                                   ps.weighted ? ps.weights.data() : nullptr);
    return *this;
  }
  bool swap_last_two() const { return given == Orientation::volume && d % 2 == 1; }
  pred::Pt P(Index i) const { return {i, ps.point(i)}; }
  pred::WPt W(Index i) const { return {i, ps.point(i), ps.weight(i)}; }
  int orient(const Index* t) const {
    pred::Pt p[kMaxD + 1];
    for (int i = 0; i <= d; ++i) p[i] = P(t[i]);
    if (swap_last_two()) std::swap(p[d - 1], p[d]);
    if (exact) {
      const double* rows[kMaxD + 1];
      for (int i = 0; i <= d; ++i) rows[i] = p[i].x;
      return pred::orient_d_exact(d, rows);
    }
    pred::PointId id[kMaxD + 1];
    const double* rows[kMaxD + 1];
    for (int i = 0; i <= d; ++i) id[i] = p[i].id, rows[i] = p[i].x;
    return pred::lambda_sign(&filter, d + 1, id, rows, nullptr);
  }
  // orient of t with entry i replaced by x
  int orient_with(const std::vector<Index>& t, int i, Index x) const {
    Index u[kMaxD + 1];
    for (int j = 0; j <= d; ++j) u[j] = t[static_cast<std::size_t>(j)];
    u[i] = x;
    return orient(u);
  }
  // power_d(t, x) > 0 iff x's lifted point is strictly below the lifted t
  int power(const std::vector<Index>& t, Index x) const {
    pred::WPt p[kMaxD + 2];
    for (int i = 0; i <= d; ++i) p[i] = W(t[static_cast<std::size_t>(i)]);
    if (swap_last_two()) std::swap(p[d - 1], p[d]);
    p[d + 1] = W(x);
    if (exact) {
      const double* rows[kMaxD + 2];
      double w[kMaxD + 2];
      for (int i = 0; i <= d + 1; ++i) {
        rows[i] = p[i].x;
        w[i] = p[i].w;
      }
      return furthest ? -pred::power_d_exact(d, rows, w) : pred::power_d_exact(d, rows, w);
    }
    pred::PointId id[kMaxD + 2];
    const double* rows[kMaxD + 2];
    double w[kMaxD + 2];
    for (int i = 0; i <= d + 1; ++i) id[i] = p[i].id, rows[i] = p[i].x, w[i] = p[i].w;
    const int s = pred::lambda_sign(&filter, d + 2, id, rows, w);
    return furthest ? -s : s;
  }
};

std::string index_problem(const std::vector<std::vector<Index>>& simplices, std::size_t n, int d) {
  if (simplices.empty()) return "simplex-indices: the output has no simplices";
  for (std::size_t k = 0; k < simplices.size(); ++k) {
    const auto& t = simplices[k];
    if (t.size() != static_cast<std::size_t>(d + 1))
      return "simplex-indices: simplex " + std::to_string(k) + " has " + std::to_string(t.size()) +
             " vertices, a " + std::to_string(d) + "-simplex has " + std::to_string(d + 1);
    for (Index x : t)
      if (x >= n)
        return "simplex-indices: simplex " + std::to_string(k) + " " + simplex_str(t) + " names point " +
               std::to_string(x) + " but the input has " + std::to_string(n) + " points";
    std::vector<Index> s = t;
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end())
      return "simplex-indices: simplex " + std::to_string(k) + " " + simplex_str(t) + " repeats a vertex";
  }
  return {};
}

// The orient_d sign of a boundary facet's simplex with its apex replaced by
// x, as an affine function of x: det Λ is linear in the replaced row, so it
// is Σ_j c_j (x_j - b_j) + c_d, b a vertex of the facet (translation changes
// no determinant) and c the cofactors of that row — (d x d) minors of the
// other rows, computed once per facet in ErrDouble (err_double.hpp: a proven
// running error bound, the rounded differences included). Evaluating it for a
// vertex in ErrDouble and taking sign_if_certain decides the sign exactly
// whenever the bound allows; an undecided vertex (on or near the facet's
// hyperplane: every exactly degenerate one) goes to the exact SoS predicate.
// The rows are those of Checker::orient (the convention's swap included), so
// a decided sign is the one it would return.
struct FacetForm {
  int d = 0;
  ErrDoubleRow c;  // c[0..d-1] coordinate cofactors, c[d] the 1-column's
  const double* base = nullptr;
  FacetForm(const Checker& ck, const std::vector<Index>& t, int apex) : d(ck.d) {
    int pos[kMaxD + 1];
    for (int k = 0; k <= d; ++k) pos[k] = k;
    if (ck.swap_last_two()) std::swap(pos[d - 1], pos[d]);
    int xrow = 0;  // the row the apex's replacement lands in
    for (int k = 0; k <= d; ++k)
      if (pos[k] == apex) xrow = k;
    base = ck.ps.point(t[static_cast<std::size_t>(apex == 0 ? 1 : 0)]);
    // rows of Λ (translated by base) other than xrow, with the 1-column
    pred::ErrDouble rows[kMaxD][kMaxD + 1];
    int r = 0;
    for (int k = 0; k <= d; ++k) {
      if (k == xrow) continue;
      const double* p = ck.ps.point(t[static_cast<std::size_t>(pos[k])]);
      for (int j = 0; j < d; ++j) rows[r][j] = pred::ErrDouble(p[j]) - pred::ErrDouble(base[j]);
      rows[r][d] = pred::ErrDouble(1.0);
      ++r;
    }
    for (int j = 0; j <= d; ++j) {
      pred::ErrDouble m[kMaxD * kMaxD];
      for (int a = 0; a < d; ++a) {
        int b = 0;
        for (int col = 0; col <= d; ++col)
          if (col != j) m[a * d + b++] = rows[a][col];
      }
      pred::ErrDouble minor = det_err(m, d);
      if ((xrow + j) % 2 != 0) minor = -minor;
      c[static_cast<std::size_t>(j)] = minor;
    }
  }
  static pred::ErrDouble det_err(const pred::ErrDouble* m, int n) {
    switch (n) {
      case 2: return pred::det_by_minors<2>(m);
      case 3: return pred::det_by_minors<3>(m);
      case 4: return pred::det_by_minors<4>(m);
      case 5: return pred::det_by_minors<5>(m);
      default: return pred::det_gauss_rt(m, n);
    }
  }
  // +1 / -1 when certain, 0 when undecided
  int sign(const double* x) const {
    pred::ErrDouble v = c[static_cast<std::size_t>(d)];
    for (int j = 0; j < d; ++j) v = v + c[static_cast<std::size_t>(j)] * (pred::ErrDouble(x[j]) - pred::ErrDouble(base[j]));
    return pred::sign_if_certain(v);
  }
};

// boundary-is-hull at the canonical level in time linear in the boundary
// (certify_rtd.hpp, "The boundary in linear time"; convex_surface.hpp): the
// boundary facets as d-tuples with the inside negative, from an interior
// vertex (the smallest vertex not on the boundary) or, with none, the
// auxiliary centre. Returns "" when the conditions hold, the violation when
// one fails, nothing when the auxiliary centre is not inside (the caller
// then tests every boundary vertex against every boundary facet).
std::optional<std::string> convex_boundary(const Checker& ck, const std::vector<std::vector<Index>>& S,
                                           const std::vector<std::pair<std::uint32_t, int>>& boundary,
                                           const std::vector<Index>& bverts, const ForRange& for_range) {
  const int d = ck.d;
  // facet k: the simplex in the predicates' convention without vertex i,
  // orient_d(facet, t_i) = (-1)^(d - i) orient_d(t) > 0: an even d - i swaps
  // two of its vertices to make the inside negative
  std::vector<std::vector<Index>> facets;
  facets.reserve(boundary.size());
  for (const auto& [s, i] : boundary) {
    std::vector<Index> u = S[s];
    int pos = i;
    if (ck.swap_last_two()) {
      std::swap(u[static_cast<std::size_t>(d - 1)], u[static_cast<std::size_t>(d)]);
      if (pos >= d - 1) pos = 2 * d - 1 - pos;
    }
    u.erase(u.begin() + pos);
    if ((d - pos) % 2 == 0) std::swap(u[0], u[1]);
    facets.push_back(std::move(u));
  }
  std::vector<char> is_vertex(ck.ps.size(), 0);
  for (const auto& t : S)
    for (Index x : t) is_vertex[x] = 1;
  for (Index x : bverts) is_vertex[x] = 0;
  Index v = 0;
  while (v < is_vertex.size() && !is_vertex[v]) ++v;
  const SurfaceCheck r = convex_surface(ck.ps, facets, v < is_vertex.size() ? v : kAuxiliaryCentre, nullptr, for_range);
  const std::string who =
      r.auxiliary ? "auxiliary point (the boundary vertices' average)" : "interior vertex";
  auto outside = [&](std::size_t k, Index x, const std::string& what) {
    const auto& [s, i] = boundary[k];
    std::vector<Index> f;
    for (int j = 0; j <= d; ++j)
      if (j != i) f.push_back(S[s][static_cast<std::size_t>(j)]);
    return "boundary-is-hull: " + what + " " + std::to_string(x) + " is not strictly inside the boundary facet " +
           simplex_str(f) + " of simplex " + simplex_str(S[s]);
  };
  switch (r.kind) {
    case SurfaceCheck::Kind::ok: return std::string();
    case SurfaceCheck::Kind::no_centre: return std::nullopt;
    case SurfaceCheck::Kind::not_closed:
      return "boundary-is-hull: the boundary facets do not form a closed surface: the ridge " + simplex_str(r.ridge) +
             " lies in " + std::to_string(r.count) + " boundary facet" + (r.count == 1 ? "" : "s");
    case SurfaceCheck::Kind::not_convex: return outside(r.facet, r.point, "boundary vertex");
    case SurfaceCheck::Kind::outside: return outside(r.facet, r.point, who);
    case SurfaceCheck::Kind::winds: break;
  }
  return "boundary-is-hull: the boundary facets wind " + std::to_string(r.count) + " times around the " + who + " " +
         std::to_string(r.point) + " (the vertical ray up from it crosses " + std::to_string(r.count) +
         " of them; a convex boundary: exactly one)";
}

// Conditions simplex-orientation, facet-manifold, boundary-is-hull (header).
// Fills `F` for the later conditions. Facets are matched by sorting their
// keys (sorted vertices, unused entries ~0), not by a hash map of vectors.
// The per-simplex and per-facet checks run through for_range (Speedups;
// empty: sequentially); the first failure in the sequential order is the one
// reported.
std::string tiling(const Checker& ck, const std::vector<std::vector<Index>>& S, Facets& F, const ForRange& for_range) {
  const int d = ck.d;
  const std::size_t w = static_cast<std::size_t>(d + 1);
  if (const std::size_t bad =
          detail::smallest_failing(S.size(), for_range, [&](std::size_t k) { return ck.orient(S[k].data()) <= 0; });
      bad < S.size()) {
    const auto& t = S[bad];
    if (ck.orient(t.data()) == 0)  // only at Level::exact (SoS signs are never 0)
      return "simplex-orientation: simplex " + simplex_str(t) +
             " has zero volume (the exact level accepts none; a canonical answer with zero-volume simplices is "
             "certified at the canonical level)";
    return "simplex-orientation: simplex " + simplex_str(t) + " is negatively oriented";
  }
  // every (simplex, position): its facet's key and induced orientation
  struct Half {
    FacetKey key;
    std::uint32_t s;
    int i;
    bool odd;
  };
  const auto make_half = [&](std::size_t code, Half& h) {
    h.s = static_cast<std::uint32_t>(code / w);
    h.i = static_cast<int>(code % w);
    const std::vector<Index>& t = S[h.s];
    h.key.fill(~Index{0});
    int c = 0;
    for (int j = 0; j <= d; ++j)
      if (j != h.i) h.key[static_cast<std::size_t>(c++)] = t[static_cast<std::size_t>(j)];
    // induced orientation of the facet: (-1)^i (t without t_i); compare
    // with its sorted order
    bool odd = h.i % 2 != 0;
    for (int a = 0; a < d; ++a)
      for (int b = a + 1; b < d; ++b)
        if (h.key[static_cast<std::size_t>(b)] < h.key[static_cast<std::size_t>(a)]) odd = !odd;
    std::sort(h.key.begin(), h.key.begin() + d);
    h.odd = odd;
  };
  // The halves in the order of a global sort by (key, simplex, position),
  // without one: bucketed by the facet's smallest vertex (a counting sort of
  // the codes s (d+1) + i, a stable pass in (simplex, position) order), then
  // each bucket — the facets whose smallest vertex is that point: 150 on
  // average on 20,000 random 4D points, 460 on the 3^5 grid — made into keys
  // and sorted stably by its other vertices. Equal keys share their smallest
  // vertex, so each bucket is matched on its own,
  // in one pass over the buckets (in parallel pieces; the first failure in
  // bucket order is the first in the global order). Only the codes and one
  // bucket's keys at a time are held: 8 bytes a half instead of a key array
  // (48 bytes) twice over, whose fresh pages cost more than the matching on
  // a 2-core VM (3^5 grid, 112,566 halves: 10.8 MB, 2,600 page faults of
  // about 2.4 us each).
  const std::size_t n = ck.ps.size(), halves = S.size() * w;
  std::vector<std::size_t> start(n + 2, 0);
  const auto smallest_of_facet = [&](std::size_t s, Index& m1, std::size_t& at, Index& m2) {
    const std::vector<Index>& t = S[s];
    m1 = t[0], m2 = t[1], at = 0;
    if (m2 < m1) std::swap(m1, m2), at = 1;
    for (std::size_t j = 2; j < w; ++j)
      if (t[j] < m1) m2 = m1, m1 = t[j], at = j;
      else if (t[j] < m2) m2 = t[j];
  };
  for (std::size_t s = 0; s < S.size(); ++s) {
    Index m1, m2;
    std::size_t at;
    smallest_of_facet(s, m1, at, m2);
    start[static_cast<std::size_t>(m1) + 2] += d;  // the d facets that keep m1
    start[static_cast<std::size_t>(m2) + 2] += 1;  // the one opposite m1
  }
  for (std::size_t v = 0; v <= n; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> code(halves);
  for (std::size_t s = 0; s < S.size(); ++s) {  // start[v + 1]: bucket v's cursor
    Index m1, m2;
    std::size_t at;
    smallest_of_facet(s, m1, at, m2);
    for (std::size_t i = 0; i < w; ++i) code[start[static_cast<std::size_t>(i == at ? m2 : m1) + 1]++] = s * w + i;
  }
  const auto rest_less = [d](const Half& x, const Half& y) {
    for (int j = 1; j < d; ++j)
      if (x.key[static_cast<std::size_t>(j)] != y.key[static_cast<std::size_t>(j)])
        return x.key[static_cast<std::size_t>(j)] < y.key[static_cast<std::size_t>(j)];
    return false;
  };
  const auto same_key = [d](const Half& x, const Half& y) {
    for (int j = 0; j < d; ++j)
      if (x.key[static_cast<std::size_t>(j)] != y.key[static_cast<std::size_t>(j)]) return false;
    return true;
  };
  F.d = d;
  F.across.assign(halves, -1);
  // Where a key's other d - 1 vertices fit 64 bits together (b bits each,
  // every index below 2^b: 5D up to 65,536 points), a large bucket is sorted
  // as (packed vertices, position) pairs: their order is the keys' in
  // lexicographic order, ties by position (stable), at a fraction of the
  // moves of a stable sort of the halves (3^5 grid: buckets of 460 halves on
  // average).
  int bits = 1;
  while (bits < 32 && (std::size_t{1} << bits) < n) ++bits;
  const bool packable = (d - 1) * bits <= 64;
  struct Buffers {
    std::vector<Half> buf, tmp;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> packed;
  };
  // bucket v's halves, sorted, into `b.buf`; its pairs linked in F; the
  // first failure's message (empty: none)
  const auto match_bucket = [&](std::size_t v, Buffers& bufs) -> std::string {
    std::vector<Half>& buf = bufs.buf;
    buf.resize(start[v + 1] - start[v]);
    for (std::size_t k = 0; k < buf.size(); ++k) make_half(code[start[v] + k], buf[k]);
    if (buf.size() <= 32) {
      for (std::size_t x = 1; x < buf.size(); ++x)
        for (std::size_t y = x; y > 0 && rest_less(buf[y], buf[y - 1]); --y) std::swap(buf[y], buf[y - 1]);
    } else if (packable) {
      bufs.packed.resize(buf.size());
      for (std::size_t k = 0; k < buf.size(); ++k) {
        std::uint64_t x = 0;
        for (int j = 1; j < d; ++j) x = (x << bits) | buf[k].key[static_cast<std::size_t>(j)];
        bufs.packed[k] = {x, static_cast<std::uint32_t>(k)};
      }
      std::sort(bufs.packed.begin(), bufs.packed.end());
      bufs.tmp.resize(buf.size());
      for (std::size_t k = 0; k < buf.size(); ++k) bufs.tmp[k] = buf[bufs.packed[k].second];
      buf.swap(bufs.tmp);
    } else {
      std::stable_sort(buf.begin(), buf.end(), rest_less);
    }
    auto facet_vec = [&](const FacetKey& k) { return std::vector<Index>(k.begin(), k.begin() + d); };
    for (std::size_t a = 0; a < buf.size();) {
      std::size_t b = a + 1;
      while (b < buf.size() && same_key(buf[b], buf[a])) ++b;
      if (b - a >= 3)
        return "facet-manifold: facet " + simplex_str(facet_vec(buf[a].key)) + " lies in three or more simplices";
      if (b - a == 2) {
        const Half &x = buf[a], &y = buf[a + 1];
        if (x.odd == y.odd)
          return "facet-manifold: simplices " + simplex_str(S[x.s]) + " and " + simplex_str(S[y.s]) +
                 " lie on the same side of their common facet " + simplex_str(facet_vec(x.key));
        F.across[x.s * w + static_cast<std::size_t>(x.i)] = y.s;
        F.across[y.s * w + static_cast<std::size_t>(y.i)] = x.s;
      }
      a = b;
    }
    return {};
  };
  struct Piece {
    Buffers bufs;
    const decltype(match_bucket)* match;
    bool operator()(std::size_t v) { return !(*match)(v, bufs).empty(); }
  };
  if (const std::size_t bad =
          detail::smallest_failing_by_piece(n, for_range, [&](std::size_t) { return Piece{{}, &match_bucket}; });
      bad < n) {
    Buffers bufs;
    return match_bucket(bad, bufs);
  }
  // the boundary: the halves left unmatched, in (simplex, position) order
  std::vector<std::pair<std::uint32_t, int>> boundary;
  for (std::size_t k = 0; k < halves; ++k)
    if (F.across[k] < 0) boundary.emplace_back(static_cast<std::uint32_t>(k / w), static_cast<int>(k % w));
  if (boundary.empty()) return "boundary-is-hull: the simplices have no boundary";
  std::vector<Index> bverts;
  for (const auto& [s, i] : boundary)
    for (int j = 0; j <= d; ++j)
      if (j != i) bverts.push_back(S[s][static_cast<std::size_t>(j)]);
  std::sort(bverts.begin(), bverts.end());
  bverts.erase(std::unique(bverts.begin(), bverts.end()), bverts.end());
  if (!ck.exact)
    if (const std::optional<std::string> why = convex_boundary(ck, S, boundary, bverts, for_range)) return *why;
  // the quadratic test: per boundary facet, the first boundary vertex not
  // (strictly) on its inner side
  auto first_outside = [&](std::size_t k) -> long {
    const auto& [s, i] = boundary[k];
    const auto& t = S[s];
    const FacetForm form(ck, t, i);
    for (Index x : bverts) {
      if (std::find(t.begin(), t.end(), x) != t.end()) continue;  // on f, or the simplex's own apex
      int o = form.sign(ck.ps.point(x));
      if (o == 0) o = ck.orient_with(t, i, x);
      if (o < 0 || (o == 0 && !ck.exact)) return static_cast<long>(x);
    }
    return -1;
  };
  if (const std::size_t bad = detail::smallest_failing(boundary.size(), for_range,
                                                       [&](std::size_t k) { return first_outside(k) >= 0; });
      bad < boundary.size()) {
    const auto& [s, i] = boundary[bad];
    const auto& t = S[s];
    std::vector<Index> f;
    for (int j = 0; j <= d; ++j)
      if (j != i) f.push_back(t[static_cast<std::size_t>(j)]);
    return "boundary-is-hull: boundary vertex " + std::to_string(first_outside(bad)) + " is not " +
           (ck.exact ? "on the inner side of" : "strictly inside") + " the boundary facet " + simplex_str(f) +
           " of simplex " + simplex_str(t);
  }
  return {};
}

// d! times the total volume of the simplices, exactly: each det[p_1 - p_0,
// ..., p_d - p_0] by Gaussian elimination over the rationals (doubles are
// dyadic rationals), absolute values summed.
mpq_class total_volume(const PointSet& ps, const std::vector<std::vector<Index>>& S) {
  const int d = ps.dim;
  mpq_class sum = 0;
  std::vector<mpq_class> m(static_cast<std::size_t>(d * d));
  for (const auto& t : S) {
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        m[static_cast<std::size_t>(i * d + j)] =
            mpq_class(ps.point(t[static_cast<std::size_t>(i + 1)])[j]) - mpq_class(ps.point(t[0])[j]);
    mpq_class det = 1;
    for (int c = 0; c < d && det != 0; ++c) {
      int r = c;
      while (r < d && m[static_cast<std::size_t>(r * d + c)] == 0) ++r;
      if (r == d) {
        det = 0;
        break;
      }
      if (r != c) {
        for (int j = 0; j < d; ++j) std::swap(m[static_cast<std::size_t>(r * d + j)], m[static_cast<std::size_t>(c * d + j)]);
        det = -det;
      }
      det *= m[static_cast<std::size_t>(c * d + c)];
      for (int k = c + 1; k < d; ++k) {
        const mpq_class f = m[static_cast<std::size_t>(k * d + c)] / m[static_cast<std::size_t>(c * d + c)];
        for (int j = c; j < d; ++j) m[static_cast<std::size_t>(k * d + j)] -= f * m[static_cast<std::size_t>(c * d + j)];
      }
    }
    sum += abs(det);
  }
  return sum;
}

Report fail_from(const std::string& why) {
  const auto colon = why.find(':');
  return Report::fail(why.substr(0, colon), colon == std::string::npos ? why : why.substr(colon + 2));
}

}  // namespace

namespace rtd_detail {
std::string tiling_problem(const PointSet& ps, const std::vector<std::vector<Index>>& positive_simplices) {
  if (ps.dim < 2 || ps.dim > kMaxD) return "input-dimension: d must be 2.." + std::to_string(kMaxD);
  if (std::string why = index_problem(positive_simplices, ps.size(), ps.dim); !why.empty()) return why;
  Checker ck{ps, ps.dim, Orientation::orient_d, false, false, {}};
  ck.with_filter(Speedups{});
  Facets F;
  return tiling(ck, positive_simplices, F, ForRange{});
}
}  // namespace rtd_detail

Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& S, Level level, bool furthest) {
  return rtd(ps, S, level, furthest, Speedups{});
}

Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& S, Level level, bool furthest,
           const Speedups& speedups) {
  return rtd(ps, S, level, furthest, speedups, nullptr);
}

Report rtd(const PointSet& ps, const std::vector<std::vector<Index>>& S, Level level, bool furthest,
           const Speedups& speedups, std::vector<std::int64_t>* neighbors) {
  const ForRange& for_range = speedups.for_range;
  const int d = ps.dim;
  const bool exact = level == Level::exact;
  if (d < 2 || d > kMaxD) return Report::fail("input-dimension", "rtd needs points of dimension 2.." + std::to_string(kMaxD));
  const std::size_t n = ps.size();
  if (n < static_cast<std::size_t>(d) + 1)
    return Report::fail("input-dimension", std::to_string(n) + " points, at least " + std::to_string(d + 1) +
                                               " needed in " + std::to_string(d) + "D");
  if (std::string why = index_problem(S, n, d); !why.empty()) return fail_from(why);
  for (std::size_t k = 0; k < S.size() && !exact; ++k) {
    if (!is_canonical_shape(S[k]))
      return Report::fail("canonical-form", "simplex " + simplex_str(S[k]) + " is not in canonical order");
    if (k > 0 && !(S[k - 1] < S[k]))
      return Report::fail("canonical-form", "simplices " + simplex_str(S[k - 1]) + " and " + simplex_str(S[k]) +
                                                " are not sorted or repeat");
  }
  Checker ck{ps, d, Orientation::volume, exact, false, {}};
  ck.with_filter(speedups);
  ck.furthest = furthest;
  Facets F;
  if (std::string why = tiling(ck, S, F, for_range); !why.empty()) return fail_from(why);
  // (the tiling covers a full-dimensional convex region, so the input spans R^d)

  // Theorem 2.2: every interior facet locally regular
  // (per simplex s, its facets toward later simplices, in position order:
  // the first failing (s, i) of the sequential order)
  auto irregular = [&](std::size_t s) -> int {  // the first failing position, or -1
    for (int i = 0; i <= d; ++i) {
      const std::int64_t o = F.nb(s, i);
      if (o < static_cast<std::int64_t>(s)) continue;  // boundary, or checked from the other side
      const auto& u = S[static_cast<std::size_t>(o)];
      Index b = 0;
      for (Index x : u)
        if (std::find(S[s].begin(), S[s].end(), x) == S[s].end()) b = x;
      const int pw = ck.power(S[s], b);
      if (pw > 0 || (pw == 0 && !exact)) return i;
    }
    return -1;
  };
  if (const std::size_t s = detail::smallest_failing(S.size(), for_range, [&](std::size_t k) { return irregular(k) >= 0; });
      s < S.size()) {
    const auto& u = S[static_cast<std::size_t>(F.nb(s, irregular(s)))];
    Index b = 0;
    for (Index x : u)
      if (std::find(S[s].begin(), S[s].end(), x) == S[s].end()) b = x;
    return Report::fail("locally-regular", "the facet between " + simplex_str(S[s]) + " and " + simplex_str(u) +
                                               " is not locally regular: the lifted point of " + std::to_string(b) +
                                               " is not " + (exact ? "on or above" : "strictly above") +
                                               " the lifted " + simplex_str(S[s]) +
                                               (furthest ? " (furthest site: the heights negated)" : ""));
  }

  // every missing point redundant: locate it (visibility walk, perturbed),
  // compare with the lifted simplex containing it. Through for_range each
  // piece of points walks from its own start; a failure anywhere is then
  // reported by the sequential pass (one walk carried from point to point),
  // so the message names the simplex that pass finds.
  std::vector<char> is_vertex(n, 0);
  for (const auto& t : S)
    for (Index x : t) is_vertex[x] = 1;
  const std::size_t cap = 4 * S.size() + 100;
  // the simplex containing p (walk from cur, then a scan), -1 when none
  auto locate = [&](Index p, std::size_t cur, std::uint64_t& rng) -> long {
    std::size_t steps = 0;
    while (steps++ < cap) {
      int cand[kMaxD + 1], nc = 0;
      for (int i = 0; i <= d; ++i)
        if (ck.orient_with(S[cur], i, p) < 0) cand[nc++] = i;
      if (nc == 0) return static_cast<long>(cur);
      rng ^= rng << 13;
      rng ^= rng >> 7;
      rng ^= rng << 17;
      const int i = cand[nc == 1 ? 0 : static_cast<int>((rng >> 11) % static_cast<std::uint64_t>(nc))];
      const std::int64_t next = F.nb(cur, i);
      if (next < 0) return -1;  // strictly beyond a boundary facet: outside the tiled hull
      cur = static_cast<std::size_t>(next);
    }
    // the walk did not settle (cannot happen after regularity): scan
    for (std::size_t s = 0; s < S.size(); ++s) {
      bool in = true;
      for (int i = 0; i <= d && in; ++i) in = exact ? ck.orient_with(S[s], i, p) >= 0 : ck.orient_with(S[s], i, p) > 0;
      if (in) return static_cast<long>(s);
    }
    return -1;
  };
  auto not_redundant = [&](Index p, long found) {
    const int pw = ck.power(S[static_cast<std::size_t>(found)], p);
    return pw > 0 || (pw == 0 && !exact);
  };
  struct Walker {
    std::uint64_t rng = 0x9E3779B97F4A7C15ull;
    std::size_t cur = 0;
  };
  bool any_fails = false;
  if (for_range) {
    any_fails = detail::smallest_failing_by_piece(n, for_range, [&](std::size_t) {
                  return [&, wk = Walker{}](std::size_t p) mutable {
                    if (is_vertex[p]) return false;
                    const long found = locate(static_cast<Index>(p), wk.cur, wk.rng);
                    if (found < 0 || not_redundant(static_cast<Index>(p), found)) return true;
                    wk.cur = static_cast<std::size_t>(found);
                    return false;
                  };
                }) < n;
  }
  if (!for_range || any_fails) {
    Walker wk;
    for (Index p = 0; p < n; ++p) {
      if (is_vertex[p]) continue;
      const long found = locate(p, wk.cur, wk.rng);
      if (found < 0)
        return Report::fail("missing-point-redundant", "point " + std::to_string(p) +
                                                           " is not a vertex and lies outside every simplex (under the perturbation)");
      if (not_redundant(p, found))
        return Report::fail("missing-point-redundant",
                            "point " + std::to_string(p) + " is not a vertex but is not redundant: its lifted point is " +
                                (exact ? "strictly below" : "not strictly above") + " the lifted simplex " +
                                simplex_str(S[static_cast<std::size_t>(found)]) +
                                (furthest ? " (furthest site: the heights negated)" : ""));
      wk.cur = static_cast<std::size_t>(found);
    }
  }
  if (exact) {
    // covers-hull-once (header): the simplices tile conv(P) k times, k >= 1;
    // their exact total volume equals that of conv(P) — taken from the
    // canonical answer, certified here first — iff k = 1.
    const std::vector<std::vector<Index>> canonical = ref::rtd_incremental(ps).simplices;
    if (const Report rc = rtd(ps, canonical, Level::canonical); !rc.ok)
      return Report::fail("covers-hull-once", "the reference triangulation used for the hull's volume failed: " +
                                                  rc.message());
    if (total_volume(ps, S) != total_volume(ps, canonical))
      return Report::fail("covers-hull-once", "the simplices' total volume differs from the convex hull's: they "
                                              "cover it more than once");
  }
  if (neighbors) *neighbors = std::move(F.across);
  return Report::pass();
}

}  // namespace flipflop::certify

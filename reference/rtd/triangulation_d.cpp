// triangulation_d.cpp — the d-dimensional extended triangulation (thesis
// §2.1, §2.2): combinatorics, predicates with the virtual vertex, point
// location, construction and validation. See triangulation_d.hpp.
#include "reference/rtd/triangulation_d.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_set>

#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"

namespace flipflop::ref::rtd {

// ---- slot management ----------------------------------------------------------
std::int32_t new_slot(TriangulationD& T) {
  const std::size_t w = static_cast<std::size_t>(T.d + 1);
  std::int32_t s;
  if (!T.free_slots.empty()) {
    s = T.free_slots.back();
    T.free_slots.pop_back();
    for (std::size_t j = 0; j < w; ++j) {
      T.verts[static_cast<std::size_t>(s) * w + j] = kNoVertex;
      T.nbrs[static_cast<std::size_t>(s) * w + j] = kNone;
    }
  } else {
    s = static_cast<std::int32_t>(T.alive.size());
    T.verts.resize(T.verts.size() + w, kNoVertex);
    T.nbrs.resize(T.nbrs.size() + w, kNone);
    T.gen.push_back(0);
    T.alive.push_back(0);
  }
  T.alive[static_cast<std::size_t>(s)] = 1;
  ++T.live;
  return s;
}

void free_slot(TriangulationD& T, std::int32_t s) {
  T.alive[static_cast<std::size_t>(s)] = 0;
  ++T.gen[static_cast<std::size_t>(s)];
  T.free_slots.push_back(s);
  --T.live;
}

void set_vertex(TriangulationD& T, std::int32_t s, int i, Index x) {
  T.verts[static_cast<std::size_t>(s) * static_cast<std::size_t>(T.d + 1) + static_cast<std::size_t>(i)] = x;
}

void set_neighbor(TriangulationD& T, std::int32_t s, int i, std::int32_t t) {
  T.nbrs[static_cast<std::size_t>(s) * static_cast<std::size_t>(T.d + 1) + static_cast<std::size_t>(i)] = t;
}

// ---- combinatorics ----------------------------------------------------------
int index_of(const TriangulationD& T, std::int32_t s, Index x) {
  for (int i = 0; i <= T.d; ++i)
    if (T.vertex(s, i) == x) return i;
  return -1;
}

bool is_virtual_simplex(const TriangulationD& T, std::int32_t s) { return index_of(T, s, T.n) >= 0; }

int mirror_index(const TriangulationD& T, std::int32_t s, int i) {
  // Two distinct simplices of a triangulated sphere share at most one facet
  // (two facets of a simplex span all its vertices), so the back pointer is
  // unique.
  const std::int32_t t = T.neighbor(s, i);
  for (int j = 0; j <= T.d; ++j)
    if (T.neighbor(t, j) == s) return j;
  throw std::logic_error("rtd: neighbour links are not symmetric");
}

RidgeD twin(const TriangulationD& T, RidgeD r) { return {T.neighbor(r.s, r.i), mirror_index(T, r.s, r.i)}; }

Index link_a(const TriangulationD& T, RidgeD r) { return T.vertex(r.s, r.i); }

Index link_b(const TriangulationD& T, RidgeD r) {
  const RidgeD o = twin(T, r);
  return T.vertex(o.s, o.i);
}

PointTuple points(const TriangulationD& T, RidgeD r) {
  // Moving entry i of (c_0..c_d) to the end is d - i adjacent transpositions;
  // when that is odd, swapping the first two ridge vertices restores an even
  // permutation of C1.
  PointTuple S{};
  int k = 0;
  for (int j = 0; j <= T.d; ++j)
    if (j != r.i) S[static_cast<std::size_t>(k++)] = T.vertex(r.s, j);
  if ((T.d - r.i) % 2 != 0) std::swap(S[0], S[1]);
  S[static_cast<std::size_t>(T.d)] = link_a(T, r);
  S[static_cast<std::size_t>(T.d + 1)] = link_b(T, r);
  return S;
}

bool interior(const TriangulationD& T, RidgeD r) {
  return !is_virtual_simplex(T, r.s) && !is_virtual_simplex(T, T.neighbor(r.s, r.i));
}

std::vector<RidgeD> ridges(const TriangulationD& T) {
  std::vector<RidgeD> out;
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    for (int i = 0; i <= T.d; ++i)
      if (s < T.neighbor(s, i)) out.push_back({s, i});
  }
  return out;
}

std::vector<std::int32_t> star(const TriangulationD& T, Index x) {
  std::vector<std::int32_t> out;
  if (x > T.n || T.vsimplex[x] == kNone) return out;
  std::unordered_set<std::int32_t> seen;
  out.push_back(T.vsimplex[x]);
  seen.insert(T.vsimplex[x]);
  for (std::size_t q = 0; q < out.size(); ++q) {
    const std::int32_t s = out[q];
    for (int i = 0; i <= T.d; ++i) {
      if (T.vertex(s, i) == x) continue;  // facets containing x lead to simplices containing x
      const std::int32_t t = T.neighbor(s, i);
      if (seen.insert(t).second) out.push_back(t);
    }
  }
  return out;
}

std::int32_t find_simplex(const TriangulationD& T, const Index* vs) {
  for (int i = 0; i <= T.d; ++i)
    if (vs[i] > T.n) return kNone;
  for (std::int32_t s : star(T, vs[0])) {
    bool all = true;
    for (int i = 1; i <= T.d && all; ++i) all = index_of(T, s, vs[i]) >= 0;
    if (all) return s;
  }
  return kNone;
}

RidgeD find_ridge(const TriangulationD& T, const Index* ridge, Index a, Index b) {
  Index vs[kMaxDim + 1];
  for (int i = 0; i < T.d; ++i) vs[i] = ridge[i];
  vs[T.d] = a;
  const std::int32_t s = find_simplex(T, vs);
  if (s == kNone) return {};
  const RidgeD r{s, index_of(T, s, a)};
  if (link_b(T, r) != b) return {};
  return r;
}

RidgeRef remember(const TriangulationD& T, RidgeD r) {
  return {r.s, r.i, T.gen[static_cast<std::size_t>(r.s)], link_a(T, r), link_b(T, r)};
}

RidgeD recall(const TriangulationD& T, const RidgeRef& ref) {
  if (ref.s == kNone || ref.s >= static_cast<std::int32_t>(T.slots())) return {};
  if (!T.alive[static_cast<std::size_t>(ref.s)] || T.gen[static_cast<std::size_t>(ref.s)] != ref.gen) return {};
  const RidgeD r{ref.s, ref.i};
  if (link_a(T, r) != ref.a || link_b(T, r) != ref.b) return {};
  return r;
}

std::vector<std::vector<Index>> real_simplices(const TriangulationD& T) {
  std::vector<std::vector<Index>> out;
  out.reserve(T.live);
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)] || is_virtual_simplex(T, s)) continue;
    out.emplace_back(T.tuple(s), T.tuple(s) + T.d + 1);
  }
  return canonical_simplices(std::move(out), Orientation::orient_d);  // tuples kept orient_d-positive
}

std::vector<Index> vertices(const TriangulationD& T) {
  std::vector<Index> out;
  for (Index x = 0; x < T.n; ++x)
    if (T.vsimplex[x] != kNone) out.push_back(x);
  return out;
}

// ---- predicates -----------------------------------------------------------------
pred::Pt pt(const TriangulationD& T, Index x) { return {x, T.ps->point(x)}; }
pred::WPt wpt(const TriangulationD& T, Index x) { return {x, T.ps->point(x), T.ps->weight(x)}; }

int orient(const TriangulationD& T, const Index* tuple) {
  pred::Pt p[kMaxDim + 1];
  for (int i = 0; i <= T.d; ++i) p[i] = pt(T, tuple[i]);
  return pred::orient_d(T.d, p);
}

int power(const TriangulationD& T, const Index* tuple) {
  pred::WPt p[kMaxDim + 2];
  for (int i = 0; i <= T.d + 1; ++i) p[i] = wpt(T, tuple[i]);
  const int s = T.pulled ? pred::power_d_pulled(T.d, p) : pred::power_d(T.d, p);
  return T.furthest ? -s : s;
}

bool locally_regular(const TriangulationD& T, RidgeD r) {
  const Index a = link_a(T, r), b = link_b(T, r);
  if (T.is_virtual(a) || T.is_virtual(b)) return true;  // a facet of the hull (§2.2)
  const int vpos = index_of(T, r.s, T.n);
  if (vpos >= 0) {
    // F = (v, G): convex at G iff b is on the inner side of the hull facet
    // (G, a), i.e. replacing v in C1 by b gives a negative tuple (header).
    Index t[kMaxDim + 1];
    for (int j = 0; j <= T.d; ++j) t[j] = T.vertex(r.s, j);
    t[vpos] = b;
    return orient(T, t) < 0;
  }
  const PointTuple S = points(T, r);
  return power(T, S.data()) < 0;
}

bool contains(const TriangulationD& T, std::int32_t s, Index p) {
  Index t[kMaxDim + 1];
  for (int i = 0; i <= T.d; ++i) {
    for (int j = 0; j <= T.d; ++j) t[j] = T.vertex(s, j);
    t[i] = p;
    if (orient(T, t) <= 0) return false;
  }
  return true;
}

// ---- construction ------------------------------------------------------------------
namespace {

void check_dim(const PointSet& ps) {
  if (ps.dim < 2 || ps.dim > kMaxDim)
    throw std::invalid_argument("d-dimensional triangulation needs points of dimension 2.." +
                                std::to_string(kMaxDim) + ", got " + std::to_string(ps.dim));
}

// The virtual tuple across the facet of real tuple t opposite position i:
// t with t[i] := v, then two other entries swapped (an odd permutation of
// "v in place of an interior point": the orientation rule of the header).
void virtual_tuple(int d, const Index* t, int i, Index v, Index* out) {
  for (int j = 0; j <= d; ++j) out[j] = t[j];
  out[i] = v;
  const int j1 = i == 0 ? 1 : 0;
  const int j2 = (i == 0 || i == 1) ? 2 : 1;
  std::swap(out[j1], out[j2]);
}

// Facets waiting for their partner, by sorted vertex set: (slot, position).
using OpenFacets = std::map<std::vector<Index>, std::pair<std::int32_t, int>>;

// The facet of slot s opposite position i: linked to the open facet with the
// same vertex set if there is one (both leave `open`), else left open.
void glue_facet(TriangulationD& T, OpenFacets& open, std::int32_t s, int i) {
  std::vector<Index> key;
  for (int j = 0; j <= T.d; ++j)
    if (j != i) key.push_back(T.vertex(s, j));
  std::sort(key.begin(), key.end());
  auto it = open.find(key);
  if (it == open.end()) {
    open.emplace(std::move(key), std::make_pair(s, i));
  } else {
    set_neighbor(T, s, i, it->second.first);
    set_neighbor(T, it->second.first, it->second.second, s);
    open.erase(it);
  }
}

// Links every facet of the given slots to the other slot (among them or
// already linked) holding the same facet vertex set; facets are matched by
// their sorted vertex sets.
void link_facets(TriangulationD& T, const std::vector<std::int32_t>& slots) {
  OpenFacets open;
  for (std::int32_t s : slots)
    for (int i = 0; i <= T.d; ++i) {
      if (T.neighbor(s, i) != kNone) continue;
      glue_facet(T, open, s, i);
    }
  if (!open.empty()) throw std::logic_error("rtd: a facet is not shared by two simplices");
}

TriangulationD empty_structure(const PointSet& ps) {
  TriangulationD T;
  T.ps = &ps;
  T.d = ps.dim;
  T.n = static_cast<Index>(ps.size());
  T.vsimplex.assign(static_cast<std::size_t>(T.n) + 1, kNone);
  return T;
}

void set_vertex_simplices(TriangulationD& T, std::int32_t s) {
  for (int j = 0; j <= T.d; ++j) T.vsimplex[T.vertex(s, j)] = s;
}

}  // namespace

TriangulationD make_simplex(const PointSet& ps, const Index* pts) {
  check_dim(ps);
  TriangulationD T = empty_structure(ps);
  const int d = T.d;
  Index t[kMaxDim + 1];
  for (int i = 0; i <= d; ++i) {
    if (pts[i] >= T.n) throw std::invalid_argument("make_simplex: point index out of range");
    t[i] = pts[i];
  }
  for (int i = 0; i <= d; ++i)
    for (int j = i + 1; j <= d; ++j)
      if (t[i] == t[j]) throw std::invalid_argument("make_simplex: repeated point " + std::to_string(t[i]));
  if (orient(T, t) < 0) std::swap(t[0], t[1]);  // SoS: never 0 for distinct indices
  std::vector<std::int32_t> slots;
  const std::int32_t r = new_slot(T);
  for (int j = 0; j <= d; ++j) set_vertex(T, r, j, t[j]);
  slots.push_back(r);
  for (int i = 0; i <= d; ++i) {
    Index u[kMaxDim + 1];
    virtual_tuple(d, t, i, T.n, u);
    const std::int32_t s = new_slot(T);
    for (int j = 0; j <= d; ++j) set_vertex(T, s, j, u[j]);
    slots.push_back(s);
  }
  link_facets(T, slots);
  for (std::int32_t s : slots) set_vertex_simplices(T, s);
  set_vertex_simplices(T, r);
  return T;
}

TriangulationD from_simplices(const PointSet& ps, const std::vector<std::vector<Index>>& simplices) {
  check_dim(ps);
  TriangulationD T = empty_structure(ps);
  const int d = T.d;
  std::vector<std::vector<Index>> positive = simplices;
  for (std::size_t k = 0; k < positive.size(); ++k) {
    auto& t = positive[k];
    if (t.size() != static_cast<std::size_t>(d + 1))
      throw std::invalid_argument("simplex " + std::to_string(k) + " has " + std::to_string(t.size()) +
                                  " vertices, a " + std::to_string(d) + "-simplex has " + std::to_string(d + 1));
    for (Index x : t)
      if (x >= T.n)
        throw std::invalid_argument("simplex " + std::to_string(k) + " names point " + std::to_string(x) +
                                    " but the input has " + std::to_string(T.n) + " points");
    std::vector<Index> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw std::invalid_argument("simplex " + std::to_string(k) + " repeats a vertex");
    if (orient(T, t.data()) < 0) std::swap(t[0], t[1]);
  }
  if (std::string why = certify::rtd_detail::tiling_problem(ps, positive); !why.empty())
    throw std::invalid_argument("not a triangulation of a convex region: " + why);
  std::vector<std::int32_t> slots;
  for (const auto& t : positive) {
    const std::int32_t s = new_slot(T);
    for (int j = 0; j <= d; ++j) set_vertex(T, s, j, t[static_cast<std::size_t>(j)]);
    slots.push_back(s);
  }
  // real facets first (a facet without a real partner is a hull facet) ...
  OpenFacets open;
  for (std::int32_t s : slots)
    for (int i = 0; i <= d; ++i) {
      glue_facet(T, open, s, i);
    }
  // ... then one virtual simplex per hull facet, linked among themselves
  std::vector<std::int32_t> virt;
  for (const auto& [key, si] : open) {
    (void)key;
    Index u[kMaxDim + 1];
    virtual_tuple(d, T.tuple(si.first), si.second, T.n, u);
    const std::int32_t s = new_slot(T);
    for (int j = 0; j <= d; ++j) set_vertex(T, s, j, u[j]);
    const int vpos = index_of(T, s, T.n);
    set_neighbor(T, s, vpos, si.first);
    set_neighbor(T, si.first, si.second, s);
    virt.push_back(s);
  }
  link_facets(T, virt);
  for (std::int32_t s : slots) set_vertex_simplices(T, s);
  for (std::int32_t s : virt) T.vsimplex[T.n] = s;
  if (std::string why = validity_problem(T); !why.empty())
    throw std::logic_error("from_simplices built an invalid structure: " + why);
  return T;
}

std::int32_t locate(const TriangulationD& T, Index p, std::int32_t start, std::size_t* steps) {
  std::int32_t s = start;
  if (s == kNone || s >= static_cast<std::int32_t>(T.slots()) || !T.alive[static_cast<std::size_t>(s)]) {
    s = kNone;
    for (std::int32_t q = 0; q < static_cast<std::int32_t>(T.slots()); ++q)
      if (T.alive[static_cast<std::size_t>(q)]) {
        s = q;
        break;
      }
    if (s == kNone) throw std::logic_error("rtd::locate: empty triangulation");
  }
  if (const int vpos = index_of(T, s, T.n); vpos >= 0) s = T.neighbor(s, vpos);
  std::int32_t came_from = kNone;
  std::size_t count = 0;
  const int d = T.d;
  Index t[kMaxDim + 1];
  // Edelsbrunner's acyclicity theorem: in a regular triangulation the
  // "in front of" relation seen from p has no cycle, so the walk ends; in
  // any other triangulation it may cycle, and after `cap` steps an
  // exhaustive scan decides.
  const std::size_t cap = 2 * T.live + 64;
  for (;;) {
    if (++count > cap) {
      // Not a regular triangulation (the walk can cycle there): scan. A real
      // simplex strictly containing p, else a virtual one whose facet sees p.
      std::int32_t outside = kNone;
      for (std::int32_t q = 0; q < static_cast<std::int32_t>(T.slots()); ++q) {
        if (!T.alive[static_cast<std::size_t>(q)]) continue;
        if (const int vpos = index_of(T, q, T.n); vpos >= 0) {
          if (outside != kNone) continue;
          for (int j = 0; j <= d; ++j) t[j] = T.vertex(q, j);
          t[vpos] = p;
          if (orient(T, t) > 0) outside = q;
        } else if (contains(T, q, p)) {
          if (steps) *steps += count;
          return q;
        }
      }
      if (outside == kNone) throw std::logic_error("rtd::locate: point in no simplex (invalid triangulation)");
      if (steps) *steps += count;
      return outside;
    }
    bool moved = false;
    const int start_i = static_cast<int>(count % static_cast<std::size_t>(d + 1));
    for (int k = 0; k <= d; ++k) {
      const int i = (start_i + k) % (d + 1);
      const std::int32_t nb = T.neighbor(s, i);
      if (nb == came_from) continue;  // p is on the inner side of the facet we came through
      for (int j = 0; j <= d; ++j) t[j] = T.vertex(s, j);
      t[i] = p;
      if (orient(T, t) < 0) {
        came_from = s;
        s = nb;
        moved = true;
        break;
      }
    }
    if (!moved) break;
    if (is_virtual_simplex(T, s)) break;  // p beyond the hull facet we crossed
  }
  if (steps) *steps += count;
  return s;
}

// ---- validity -----------------------------------------------------------------------
std::string validity_problem(const TriangulationD& T) {
  const int d = T.d;
  auto sstr = [&](std::int32_t s) {
    std::string o = "#" + std::to_string(s) + "(";
    for (int j = 0; j <= d; ++j) o += (j ? "," : "") + (T.vertex(s, j) == T.n ? std::string("v") : std::to_string(T.vertex(s, j)));
    return o + ")";
  };
  std::size_t live = 0;
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    ++live;
    int nv = 0;
    for (int j = 0; j <= d; ++j) {
      if (T.vertex(s, j) > T.n) return "simplex " + sstr(s) + " has an invalid vertex";
      if (T.vertex(s, j) == T.n) ++nv;
      for (int k = j + 1; k <= d; ++k)
        if (T.vertex(s, j) == T.vertex(s, k)) return "simplex " + sstr(s) + " repeats a vertex";
    }
    if (nv == 0 && orient(T, T.tuple(s)) <= 0) return "real simplex " + sstr(s) + " is not positive";
    for (int i = 0; i <= d; ++i) {
      const std::int32_t t = T.neighbor(s, i);
      if (t == kNone || t >= static_cast<std::int32_t>(T.slots()) || !T.alive[static_cast<std::size_t>(t)])
        return "simplex " + sstr(s) + " has a dead neighbour";
      int back = -1, cnt = 0;
      for (int j = 0; j <= d; ++j)
        if (T.neighbor(t, j) == s) {
          back = j;
          ++cnt;
        }
      if (cnt != 1) return "neighbour links of " + sstr(s) + " and " + sstr(t) + " are not symmetric";
      // shared facet: all vertices but i of s are in t, and t's back vertex is not in s
      for (int j = 0; j <= d; ++j)
        if (j != i && index_of(T, t, T.vertex(s, j)) < 0)
          return "simplices " + sstr(s) + " and " + sstr(t) + " are linked but do not share a facet";
      if (index_of(T, s, T.vertex(t, back)) >= 0)
        return "simplices " + sstr(s) + " and " + sstr(t) + " share all vertices";
      // opposite induced orientations: the tuple of s with entry i replaced by
      // t's opposite vertex is an odd permutation of t's tuple
      std::vector<Index> a(T.tuple(s), T.tuple(s) + d + 1), b(T.tuple(t), T.tuple(t) + d + 1);
      a[static_cast<std::size_t>(i)] = T.vertex(t, back);
      // parity of the permutation taking b to a
      if (odd_sorting_parity(a) == odd_sorting_parity(b))
        return "simplices " + sstr(s) + " and " + sstr(t) + " induce the same orientation on their facet";
    }
  }
  if (live != T.live) return "live simplex count is " + std::to_string(T.live) + ", found " + std::to_string(live);
  for (Index x = 0; x <= T.n; ++x) {
    const std::int32_t s = T.vsimplex[x];
    if (s == kNone) continue;
    if (s >= static_cast<std::int32_t>(T.slots()) || !T.alive[static_cast<std::size_t>(s)] || index_of(T, s, x) < 0)
      return "vertex " + std::to_string(x) + " points to a simplex that does not contain it";
  }
  // every vertex of a live simplex is registered
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    for (int j = 0; j <= d; ++j)
      if (T.vsimplex[T.vertex(s, j)] == kNone)
        return "vertex " + std::to_string(T.vertex(s, j)) + " of " + sstr(s) + " is not registered";
  }
  // hull convex at every ridge containing v; virtual simplices have one real
  // neighbour (opposite v)
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    const int vpos = index_of(T, s, T.n);
    if (vpos < 0) continue;
    if (is_virtual_simplex(T, T.neighbor(s, vpos))) return "virtual simplex " + sstr(s) + " has a virtual base";
    for (int i = 0; i <= d; ++i)
      if (i != vpos && !locally_regular(T, {s, i}))
        return "the hull is not convex at the ridge of " + sstr(s) + " opposite " + std::to_string(T.vertex(s, i));
  }
  return {};
}

}  // namespace flipflop::ref::rtd

// star_splaying.cpp — Shewchuk's star splaying (thesis §3.3.2, Figure 3.4;
// [She05]) in the sequential workflow of §3.2. The header states the
// structure, the operation, the check, the criterion and the correctness
// argument; the comments here point at the step each piece implements.
#include "reference/hull3/star_splaying.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "predicates/predicates.hpp"
#include "reference/canonical.hpp"
#include "reference/checked.hpp"
#include "reference/dimension.hpp"

namespace flipflop::ref {

namespace {

pred::Pt pt(const PointSet& ps, Index i) { return {i, ps.point(i)}; }

// orient3d under SoS: > 0 iff d is on the inner side of triangle (a, b, c)
// counter-clockwise seen from outside (predicates.hpp). Never 0 for distinct
// indices.
int orient(const PointSet& ps, Index a, Index b, Index c, Index d) {
  return pred::orient3d(pt(ps, a), pt(ps, b), pt(ps, c), pt(ps, d));
}

// Is q strictly inside the simplicial cone apex + R+{A-apex, B-apex, C-apex}?
// q must be on C's side of plane (apex, A, B), on A's side of (apex, B, C)
// and on B's side of (apex, C, A); the three reference signs are one
// determinant up to a cyclic (even) permutation of its last three rows.
bool in_cone(const PointSet& ps, Index apex, Index A, Index B, Index C, Index q) {
  const int s = orient(ps, apex, A, B, C);
  return orient(ps, apex, A, B, q) == s && orient(ps, apex, B, C, q) == s && orient(ps, apex, C, A, q) == s;
}

// Is q strictly inside the reflected cone apex - R+{A-apex, B-apex, C-apex},
// i.e. is apex - q inside the cone? Then apex = (q + Σ β_i p_i) / (1 + Σ β_i)
// with β_i > 0: apex lies strictly inside the tetrahedron (q, A, B, C).
bool in_reflected_cone(const PointSet& ps, Index apex, Index A, Index B, Index C, Index q) {
  const int s = orient(ps, apex, A, B, C);
  return orient(ps, apex, A, B, q) == -s && orient(ps, apex, B, C, q) == -s && orient(ps, apex, C, A, q) == -s;
}

std::size_t find(const std::vector<Index>& v, Index x) {
  return static_cast<std::size_t>(std::find(v.begin(), v.end(), x) - v.begin());
}

std::string tri_str(Index a, Index b, Index c) {
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ")";
}

// The convexity condition of the header: every link vertex strictly on the
// inner side of every star triangle it is not a vertex of. Empty when it
// holds, else what fails.
std::string convexity_problem(const PointSet& ps, Index v, const std::vector<Index>& L) {
  const std::size_t k = L.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Index a = L[i], b = L[(i + 1) % k];
    for (std::size_t j = 0; j < k; ++j) {
      if (j == i || j == (i + 1) % k) continue;
      if (orient(ps, v, a, b, L[j]) < 0)
        return "link is not convex: link vertex " + std::to_string(L[j]) + " is beyond triangle " + tri_str(v, a, b) +
               " (the link must be convex and counter-clockwise seen from outside)";
    }
  }
  return {};
}

std::uint64_t key(splay::Edge e) { return (std::uint64_t{e.first} << 32) | e.second; }

}  // namespace

bool lex_precedes(const PointSet& ps, Index a, Index b) {
  return pred::compare_sos(pt(ps, a), pt(ps, b), 0) < 0;
}

bool is_death_certificate(const PointSet& ps, Index v, const std::array<Index, 4>& c) {
  const std::size_t n = ps.size();
  if (v >= n) return false;
  for (int i = 0; i < 4; ++i) {
    if (c[i] >= n || c[i] == v) return false;
    for (int j = 0; j < i; ++j)
      if (c[i] == c[j]) return false;
  }
  // v strictly inside: replacing any vertex of the tetrahedron by v keeps the
  // orientation.
  const int s = orient(ps, c[0], c[1], c[2], c[3]);
  return orient(ps, v, c[1], c[2], c[3]) == s && orient(ps, c[0], v, c[2], c[3]) == s &&
         orient(ps, c[0], c[1], v, c[3]) == s && orient(ps, c[0], c[1], c[2], v) == s;
}

namespace splay {

State make_state(const PointSet& ps, const std::vector<Star>& stars, bool validate) {
  const std::size_t n = ps.size();
  State st;
  st.ps = &ps;
  st.status.assign(n, Status::none);
  st.link.assign(n, {});
  st.cert.assign(n, {});
  auto fail = [](const std::string& what) { throw std::invalid_argument("star_splaying: " + what); };
  for (const Star& s : stars) {
    if (s.apex >= n) fail("star of point " + std::to_string(s.apex) + ": no such point (" + std::to_string(n) + " points)");
    if (st.status[s.apex] != Status::none) fail("point " + std::to_string(s.apex) + " has two stars");
    if (s.dead) {
      st.status[s.apex] = Status::dead;
      st.cert[s.apex] = s.certificate;
    } else {
      st.status[s.apex] = Status::alive;
      st.link[s.apex] = s.link;
    }
  }
  if (!validate) return st;

  Index least = static_cast<Index>(n);  // the ≺-least participating point
  for (Index v = 0; v < n; ++v)
    if (st.status[v] != Status::none && (least == n || lex_precedes(ps, v, least))) least = v;
  auto takes_part = [&](Index u) { return u < n && st.status[u] != Status::none; };

  for (Index v = 0; v < n; ++v) {
    const std::string who = "star of point " + std::to_string(v) + ": ";
    if (st.status[v] == Status::dead) {
      for (Index c : st.cert[v])
        if (!takes_part(c)) fail(who + "certificate point " + std::to_string(c) + " has no star");
      if (!is_death_certificate(ps, v, st.cert[v]))
        fail(who + "the certificate is not four distinct other points whose tetrahedron holds the point strictly inside");
      continue;
    }
    if (st.status[v] != Status::alive) continue;
    const std::vector<Index>& L = st.link[v];
    if (L.size() < 3) fail(who + "a link needs at least 3 vertices, got " + std::to_string(L.size()));
    std::vector<Index> sorted = L;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      if (!takes_part(sorted[i])) fail(who + "link vertex " + std::to_string(sorted[i]) + " has no star");
      if (sorted[i] == v) fail(who + "the apex is in its own link");
      if (i > 0 && sorted[i] == sorted[i - 1]) fail(who + "link vertex " + std::to_string(sorted[i]) + " repeated");
    }
    const std::string convex = convexity_problem(ps, v, L);
    if (!convex.empty()) fail(who + convex);
    // Shewchuk's precondition (header): the star encloses a point ≺ v.
    if (v == least) continue;
    bool encloses = std::any_of(L.begin(), L.end(), [&](Index u) { return lex_precedes(ps, u, v); });
    for (Index u = 0; u < n && !encloses; ++u) {
      if (u == v || !takes_part(u) || !lex_precedes(ps, u, v)) continue;
      bool inside = true;  // strictly beneath every triangle: inside the cone
      for (std::size_t i = 0; i < L.size() && inside; ++i) inside = orient(ps, v, L[i], L[(i + 1) % L.size()], u) > 0;
      encloses = inside;
    }
    if (!encloses)
      fail(who + "violates the lexicographic precondition: its cone encloses no point preceding it (thesis §3.3.2)");
  }
  return st;
}

// Splaying: Figure 3.4, Cases 1-3.
Outcome insert(State& st, Index s, Index p, Hull3Stats* stats, std::vector<Edge>* touched) {
  if (st.status[s] != Status::alive || p == s) return Outcome::unchanged;
  const PointSet& ps = *st.ps;
  std::vector<Index>& L = st.link[s];
  const std::size_t k = L.size();
  if (find(L, p) < k) return Outcome::unchanged;
  std::vector<std::uint8_t> beyond(k);
  std::size_t count = 0;
  for (std::size_t i = 0; i < k; ++i) {
    beyond[i] = orient(ps, s, L[i], L[(i + 1) % k], p) < 0;
    count += beyond[i];
  }
  if (count == 0) return Outcome::unchanged;  // Case 1: p inside the cone

  if (count == k) {
    // Case 3: p beyond every triangle, s - p is inside the cone; the fan from
    // L[0] splits the cone into simplicial cones and exactly one holds s - p
    // (SoS: never on a boundary): s is strictly inside (p, L[0], L[i], L[i+1]).
    for (std::size_t i = 1; i + 1 < k; ++i) {
      if (!in_reflected_cone(ps, s, L[0], L[i], L[i + 1], p)) continue;
      st.cert[s] = {p, L[0], L[i], L[i + 1]};
      FF_CHECK(is_death_certificate(ps, s, st.cert[s]), "death certificate does not hold the dead point");
      if (touched)
        for (Index u : L) touched->push_back({u, s});
      st.status[s] = Status::dead;
      std::vector<Index>().swap(L);
      return Outcome::died;
    }
    throw std::logic_error("star_splaying: no fan cone holds the direction of a dead star (not a convex star)");
  }

  // Case 2: the beyond triangles form one run i0 .. i0+m-1 (the region of a
  // convex cone visible from p is connected); its inner link vertices
  // L[i0+1 .. i0+m-1] leave the star, p joins between L[i0] and L[i0+m].
  std::size_t i0 = 0;
  while (!(beyond[i0] && !beyond[(i0 + k - 1) % k])) ++i0;
  std::size_t m = 0;
  while (m < k && beyond[(i0 + m) % k]) ++m;
  FF_CHECK(m == count, "the triangles beyond an inserted point are not one run");
  std::vector<Index> next;
  next.reserve(k - m + 2);
  for (std::size_t t = 0; t <= k - m; ++t) next.push_back(L[(i0 + m + t) % k]);  // L[i0+m] .. L[i0]
  next.push_back(p);
  if (touched) {
    for (std::size_t t = 1; t < m; ++t) touched->push_back({L[(i0 + t) % k], s});
    const Index h0 = L[i0], h1 = L[(i0 + m) % k];
    touched->insert(touched->end(), {{s, h0}, {h0, s}, {s, h1}, {h1, s}, {s, p}, {p, s}});
  }
  if (stats) {
    ++stats->splay_insertions;
    stats->splay_removals += m - 1;
  }
  L = std::move(next);
  FF_CHECK(convexity_problem(ps, s, L).empty(), "a splayed star is not convex");
  return Outcome::splayed;
}

// Inconsistency enforcement on candidate edge (v, u) (§3.3.2). Progress: at
// least one demanded insertion succeeds whenever the list is non-empty:
//   * u dead: u is strictly inside its certificate's tetrahedron; were every
//     certificate point (other than v) already in v's cone, u would be
//     strictly inside that cone and not a link vertex;
//   * v strictly inside cone(u; a, b, c): v - u = Σ α(p - u), α > 0; with
//     s = Σ α, either s < 1 and v is inside the tetrahedron (u, a, b, c)
//     (inserting a, b, c makes v's cone contain a line: v dies), or s > 1 and
//     u - v = Σ α/(s-1) (p - v): u becomes strictly interior to v's cone;
//   * v's star has (v, u, b) and u's has (u, c, v) with b != c: if both
//     insertions <u, b> and <v, c> failed, orient3d(u, c, v, b) > 0 and
//     orient3d(v, u, b, c) > 0, but these are one determinant with opposite
//     signs (an odd permutation). Likewise for the other side.
std::vector<Insertion> demanded(const State& st, Index v, Index u) {
  if (st.status[v] != Status::alive) return {};
  const PointSet& ps = *st.ps;
  const std::vector<Index>& Lv = st.link[v];
  const std::size_t kv = Lv.size(), i = find(Lv, u);
  if (i == kv) return {};
  std::vector<Insertion> out;
  if (st.status[u] == Status::dead) {  // insert u's death certificate into v's star
    for (Index c : st.cert[u])
      if (c != v) out.push_back({v, c});
    return out;
  }
  if (st.status[u] != Status::alive) throw std::logic_error("star_splaying: a link vertex takes no part");
  const std::vector<Index>& Lu = st.link[u];
  const std::size_t ku = Lu.size(), j = find(Lu, v);
  if (j == ku) {
    // v is not in u's star: insert it, unless it would fail (Case 1) ...
    for (std::size_t t = 0; t < ku; ++t)
      if (orient(ps, u, Lu[t], Lu[(t + 1) % ku], v) < 0) return {{u, v}};
    // ... then the three link vertices of u that prohibit it go into v's star.
    for (std::size_t t = 1; t + 1 < ku; ++t)
      if (in_cone(ps, u, Lu[0], Lu[t], Lu[t + 1], v)) return {{v, Lu[0]}, {v, Lu[t]}, {v, Lu[t + 1]}};
    throw std::logic_error("star_splaying: no fan cone of a convex star holds a point inside it");
  }
  // Both stars hold edge vu: v's triangles (v, a, u), (v, u, b); u's
  // triangles (u, c, v), (u, v, d). They agree iff b == c and a == d.
  const Index a = Lv[(i + kv - 1) % kv], b = Lv[(i + 1) % kv];
  const Index c = Lu[(j + ku - 1) % ku], d = Lu[(j + 1) % ku];
  if (b != c) out.insert(out.end(), {{u, b}, {v, c}});
  if (a != d) out.insert(out.end(), {{u, a}, {v, d}});
  return out;
}

std::vector<Edge> candidates(const State& st) {
  std::vector<Edge> out;
  for (Index v = 0; v < st.status.size(); ++v)
    if (st.status[v] == Status::alive)
      for (Index u : st.link[v]) out.push_back({v, u});
  return out;
}

void run(State& st, Hull3Stats* stats, const Chooser& choose) {
  std::deque<Edge> flagged;
  std::unordered_set<std::uint64_t> is_flagged;
  auto flag = [&](Edge e) {
    if (is_flagged.insert(key(e)).second) flagged.push_back(e);
  };
  for (Edge e : candidates(st)) flag(e);
  std::vector<Edge> touched;
  std::vector<Edge> list;
  while (!flagged.empty()) {
    Edge e;
    if (choose) {
      list.assign(flagged.begin(), flagged.end());
      const std::size_t at = choose(list);
      if (at >= list.size()) throw std::out_of_range("star_splaying: chooser returned an invalid position");
      e = flagged[at];
      flagged.erase(flagged.begin() + static_cast<std::ptrdiff_t>(at));
    } else {
      e = flagged.front();
      flagged.pop_front();
    }
    is_flagged.erase(key(e));
    // Enforce consistency on e until its check passes (each round makes
    // progress: see `demanded`).
    for (;;) {
      const std::vector<Insertion> todo = demanded(st, e.first, e.second);
      if (todo.empty()) break;
      bool changed = false;
      for (const Insertion& x : todo) {
        touched.clear();
        if (insert(st, x.star, x.point, stats, &touched) != Outcome::unchanged) changed = true;
        for (Edge t : touched) flag(t);
      }
      if (!changed) throw std::logic_error("star_splaying: inconsistency enforcement made no progress");
    }
  }
  FF_CHECK(consistent(st), "star splaying ended with inconsistent stars");
}

bool consistent(const State& st) {
  for (Edge e : candidates(st))
    if (!demanded(st, e.first, e.second).empty()) return false;
  return true;
}

std::vector<Triangle> triangles(const State& st) {
  std::vector<Triangle> out;
  for (Index v = 0; v < st.status.size(); ++v) {
    if (st.status[v] != Status::alive) continue;
    const std::vector<Index>& L = st.link[v];
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Index a = L[i], b = L[(i + 1) % L.size()];
      if (v < a && v < b) out.push_back({v, a, b});  // each triangle from its smallest vertex
    }
  }
  return canonical_triangles(std::move(out));
}

std::vector<Star> stars(const State& st) {
  std::vector<Star> out;
  for (Index v = 0; v < st.status.size(); ++v) {
    if (st.status[v] == Status::none) continue;
    Star s;
    s.apex = v;
    s.dead = st.status[v] == Status::dead;
    if (s.dead)
      s.certificate = st.cert[v];
    else
      s.link = st.link[v];
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace splay

std::vector<Triangle> star_splaying(const PointSet& ps, std::vector<Star> initial, Hull3Stats* stats) {
  if (ps.dim != 3) throw std::invalid_argument("star_splaying: expected 3D points, got " + std::to_string(ps.dim) + "D");
  const std::string flat = dimension_problem(ps);
  if (!flat.empty()) throw std::invalid_argument(flat);
  if (initial.size() != ps.size())
    throw std::invalid_argument("star_splaying: every point needs exactly one star (" + std::to_string(ps.size()) +
                                " points, " + std::to_string(initial.size()) + " stars)");
  if (stats) *stats = Hull3Stats{};
  splay::State st = splay::make_state(ps, initial, /*validate=*/true);
  splay::run(st, stats);
  if (stats)
    stats->dead_stars = static_cast<std::uint64_t>(std::count(st.status.begin(), st.status.end(), splay::Status::dead));
  return splay::triangles(st);
}

}  // namespace flipflop::ref

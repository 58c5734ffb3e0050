// certify_check.cpp — fuzz_certify: the certifier against the brute-force
// definition of the answer, on arbitrary and on near-miss outputs.
//
// Byte 0: bits 0-1 the kind (0 hull2, 1 hull3, 2 rt2, 3 hull2), bit 2 weighted
// (rt2 only), bit 3 how the output is made: clear → an arbitrary list
// (indices byte mod n + 2, so out-of-range ones occur), set → the brute-force
// answer with 0..3 random edits (remove / duplicate / replace an index / swap
// two entries / flip an orientation or reverse / rotate / insert). Then the
// point set (fuzz_input.hpp; at most 40 points for hull2, 16 for hull3, 14 for
// rt2 so that the O(n^3) / O(n^4) definitions stay fast), then the output
// bytes. certify::hull2/hull3/rt2 run at both levels and must not crash or
// hang, and:
//   * input that does not span its space is rejected at both levels;
//   * Level::canonical accepts exactly the brute-force answer (brute::hull2 /
//     hull3 / rt2: under Simulation of Simplicity the answer is unique);
//   * Level::exact accepts the brute-force answer (the SoS answer is a
//     correct answer of the exact input), and its verdict does not depend on
//     the order of the list or on the rotation of a cycle / triangle (it
//     judges a set of oriented simplices);
//   * what Level::exact accepts passes necessary conditions of correctness
//     checked here by brute force with exact predicates, independently of the
//     certifier's local-to-global arguments: hull2 — every point is on the
//     inner side of (or on) every edge of the cycle; hull3 — of every facet;
//     rt2 — no lifted point lies strictly below the plane of any lifted
//     triangle (power2d_exact <= 0), and every point lies in some closed
//     triangle of non-zero area.
#include <algorithm>
#include <string>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/canonical.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_certify";
using certify::Level;
using certify::Report;

enum class Kind { hull2, hull3, rt2 };

const char* name(Kind k) { return k == Kind::hull2 ? "hull2" : k == Kind::hull3 ? "hull3" : "rt2"; }

Report run(Kind k, const PointSet& ps, const std::vector<Index>& cycle, Level level) {
  (void)k;
  return certify::hull2(ps, cycle, level);
}
Report run(Kind k, const PointSet& ps, const std::vector<Triangle>& tris, Level level) {
  return k == Kind::hull3 ? certify::hull3(ps, tris, level) : certify::rt2(ps, tris, level);
}

std::vector<Index> answer_of(Kind, const PointSet& ps, std::vector<Index>*) { return brute::hull2(ps); }
std::vector<Triangle> answer_of(Kind k, const PointSet& ps, std::vector<Triangle>*) {
  return k == Kind::hull3 ? brute::hull3(ps) : brute::rt2(ps);
}

// Reading one element (an index or a triangle) from the bytes.
void read_element(ByteReader& r, std::size_t n, Index& v) { v = static_cast<Index>(r.byte() % (n + 2)); }
void read_element(ByteReader& r, std::size_t n, Triangle& t) {
  for (Index& v : t) read_element(r, n, v);
}

// Orientation-reversing and orientation-keeping changes of one element.
void flip(std::vector<Index>& c, std::size_t) { std::reverse(c.begin(), c.end()); }
void flip(std::vector<Triangle>& t, std::size_t pos) { std::swap(t[pos][1], t[pos][2]); }
void rotate(std::vector<Index>& c, std::size_t) { std::rotate(c.begin(), c.begin() + 1, c.end()); }
void rotate(std::vector<Triangle>& t, std::size_t pos) { std::rotate(t[pos].begin(), t[pos].begin() + 1, t[pos].end()); }
void replace(ByteReader& r, std::size_t n, Index& v) { v = static_cast<Index>(r.byte() % (n + 1)); }
void replace(ByteReader& r, std::size_t n, Triangle& t) { t[r.byte() % 3] = static_cast<Index>(r.byte() % (n + 1)); }

// The same set of oriented simplices in canonical order (rotations and list
// order removed).
std::vector<Index> normalized(const std::vector<Index>& c) {
  return c.empty() ? c : canonical_hull2(c);
}
std::vector<Triangle> normalized(const std::vector<Triangle>& t) { return canonical_triangles(t); }

// Necessary conditions for an exactly correct answer (see the top): empty
// when they hold, else what is violated.
std::string exact_violation(Kind, const PointSet& ps, const std::vector<Index>& cycle) {
  const std::size_t m = cycle.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Index a = cycle[k], b = cycle[(k + 1) % m];
    if (a >= ps.size() || b >= ps.size()) return "index out of range";
    for (Index p = 0; p < ps.size(); ++p)
      if (pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(p)) < 0)
        return "point " + std::to_string(p) + " is strictly outside edge (" + std::to_string(a) + "," +
               std::to_string(b) + ")";
  }
  return {};
}
std::string exact_violation(Kind kind, const PointSet& ps, const std::vector<Triangle>& tris) {
  for (const Triangle& t : tris)
    for (Index v : t)
      if (v >= ps.size()) return "index out of range";
  auto tri = [](const Triangle& t) { return describe(std::vector<Triangle>{t}); };
  if (kind == Kind::hull3) {
    for (const Triangle& t : tris)
      for (Index p = 0; p < ps.size(); ++p)
        if (pred::orient3d_exact(ps.point(t[0]), ps.point(t[1]), ps.point(t[2]), ps.point(p)) < 0)
          return "point " + std::to_string(p) + " is strictly outside facet " + tri(t);
    return {};
  }
  auto W = [&](Index i) { return pred::WPt{i, ps.point(i), ps.weight(i)}; };
  for (const Triangle& t : tris)
    for (Index p = 0; p < ps.size(); ++p)
      if (pred::power2d_exact(W(t[0]), W(t[1]), W(t[2]), W(p)) > 0)
        return "lifted point " + std::to_string(p) + " is strictly below the lifted triangle " + tri(t);
  for (Index p = 0; p < ps.size(); ++p) {
    bool covered = false;
    for (const Triangle& t : tris) {
      const double *a = ps.point(t[0]), *b = ps.point(t[1]), *c = ps.point(t[2]), *x = ps.point(p);
      if (pred::orient2d_exact(a, b, c) > 0 && pred::orient2d_exact(a, b, x) >= 0 &&
          pred::orient2d_exact(b, c, x) >= 0 && pred::orient2d_exact(c, a, x) >= 0) {
        covered = true;
        break;
      }
    }
    if (!covered) return "point " + std::to_string(p) + " is in no triangle of non-zero area";
  }
  return {};
}

template <class List>
void check(Kind kind, ByteReader& r, const PointSet& ps, bool edit) {
  const std::size_t n = ps.size();
  const bool spans = affine_dimension(ps) == ps.dim;
  List out;
  List answer;
  if (spans) answer = answer_of(kind, ps, static_cast<List*>(nullptr));
  if (edit && spans) {
    out = answer;
    const int edits = r.byte() % 4;
    for (int e = 0; e < edits; ++e) {
      const int op = r.byte() % 7;
      if (op == 6 || out.empty()) {  // insert a new element
        typename List::value_type x;
        read_element(r, n, x);
        out.insert(out.begin() + static_cast<long>(r.byte() % (out.size() + 1)), x);
        continue;
      }
      const std::size_t pos = r.byte() % out.size();
      switch (op) {
        case 0: out.erase(out.begin() + static_cast<long>(pos)); break;
        case 1: out.insert(out.begin() + static_cast<long>(r.byte() % (out.size() + 1)), out[pos]); break;
        case 2: replace(r, n, out[pos]); break;
        case 3: std::swap(out[pos], out[r.byte() % out.size()]); break;
        case 4: flip(out, pos); break;
        default: rotate(out, pos); break;
      }
    }
  } else {
    const std::size_t count = r.byte() % 48;
    out.resize(count);
    for (auto& x : out) read_element(r, n, x);
  }

  const Report canonical = run(kind, ps, out, Level::canonical);
  const Report exact = run(kind, ps, out, Level::exact);
  const std::string details = describe(ps) + "output " + describe(out) + "\n" +
                              (spans ? "brute   " + describe(answer) + "\n" : "") +
                              "canonical: " + canonical.message() + "\nexact: " + exact.message();
  const std::string what = std::string("certify::") + name(kind);
  if (!spans) {
    if (canonical.ok || exact.ok) fail(kTarget, what + " accepted output of input that does not span", details);
    return;
  }
  if (canonical.ok != (out == answer))
    fail(kTarget, what + (canonical.ok ? " at Level::canonical accepted an output that is not the brute-force answer"
                                       : " at Level::canonical rejected the brute-force answer"),
         details);
  const Report exact_answer = run(kind, ps, answer, Level::exact);
  if (!exact_answer.ok)
    fail(kTarget, what + " at Level::exact rejected the brute-force answer: " + exact_answer.message(), details);
  if (exact.ok) {
    const std::string why = exact_violation(kind, ps, out);
    if (!why.empty()) fail(kTarget, what + " at Level::exact accepted a wrong output: " + why, details);
  }
  const List norm = normalized(out);
  const Report exact_norm = run(kind, ps, norm, Level::exact);
  if (exact_norm.ok != exact.ok)
    fail(kTarget, what + " at Level::exact judged a reordering of the output differently: " + exact_norm.message(),
         details + "\nreordered " + describe(norm));
}

}  // namespace

bool check_certify_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  const std::uint8_t flags = r.byte();
  const int k = flags & 3;
  const Kind kind = k == 1 ? Kind::hull3 : k == 2 ? Kind::rt2 : Kind::hull2;
  const bool weighted = kind == Kind::rt2 && (flags & 4);
  const bool edit = (flags & 8) != 0;
  const std::size_t max_n = kind == Kind::hull2 ? 40 : kind == Kind::hull3 ? 16 : 14;
  PointSet ps;
  if (!decode_points(r, kind == Kind::hull3 ? 3 : 2, weighted, 1, max_n, ps)) return false;
  if (kind == Kind::hull2)
    check<std::vector<Index>>(kind, r, ps, edit);
  else
    check<std::vector<Triangle>>(kind, r, ps, edit);
  return true;
}

}  // namespace flipflop::fuzz

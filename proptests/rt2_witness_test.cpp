// rt2_witness_test.cpp — the witness-checked certifier of the multithreaded
// 2D regular / Delaunay triangulation (cpu::certify_rt2 with cpu::Rt2Witness,
// kernels_cpu/rt2/certify_rt2.hpp).
//
// Properties: on every 2D generator family with weights, degenerate sets
// included, at 1, 2 and 8 threads, with the sequential insertion and with
// stage 2b's territories and batches, the kernel's output with its witness is
// certified at both levels, and the witness-free certifier (certify::rt2,
// an independent oracle: it locates every point itself and derives the
// structure from the triangles alone) agrees; the witness does not depend on
// the thread count.
// Rejections: witnesses and outputs made wrong in one way each — a missing
// point given a triangle that does not contain it, a vertex declared missing,
// a link made asymmetric, two links swapped (symmetric but wrong), one
// interior edge flipped to a non-regular one (witness and output), a triangle
// dropped (from both, or from the output only), an output triangle changed,
// the output out of order, a vertex that is not redundant declared missing
// (the triangulation of the set with it redundant), a triangle turned
// clockwise, the points' permutation broken — each must be rejected with its
// named condition, at every thread count, and certify::rt2 must agree
// wherever the output itself is wrong. The inputs hold more than one piece of
// work (kernels_cpu/parallel.hpp kChunk = 8192 slots or points).
//
// Case counts (RC_PARAMS max_success = 2000 under ctest, divided per property
// by prop_scaled): degenerate sets of 3..60 points 2000 / 8 = 250 each
// weighted and unweighted; generator families at 3..2000 points 2000 / 40 =
// 50 each; every family at 20000 points ([long]: 130 s on the loaded 2-core
// VM at 30000); the rejections on 30000 square points.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "kernels_cpu/rt2/certify_rt2.hpp"
#include "kernels_cpu/rt2/rt2.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/families.hpp"
#include "proptests/support/rc_scaled.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"

using namespace flipflop;

namespace {

constexpr int kThreads[] = {1, 2, 8};
constexpr std::uint32_t kNo = cpu::Rt2Witness::kNoSlot;

struct Run {
  std::vector<Triangle> tris;
  cpu::Rt2Witness w;
};

using Insertion = cpu::Rt2Options::Insertion;

// parallel_from: where stage 2b (territories, batches) starts; small, so
// that small inputs reach it
Run run(const PointSet& ps, int threads = 0, Insertion how = Insertion::sequential, std::size_t parallel_from = 4096) {
  Run r;
  cpu::Rt2Options o;
  o.threads = threads;
  o.insertion = how;
  o.parallel_from = parallel_from;
  r.tris = cpu::rt2(ps, o, nullptr, &r.w);
  return r;
}

bool same_witness(const cpu::Rt2Witness& a, const cpu::Rt2Witness& b) {
  if (a.pts.size() != b.pts.size()) return false;
  for (std::size_t k = 0; k < a.pts.size(); ++k)
    if (a.pts[k].id != b.pts[k].id) return false;
  return a.tv == b.tv && a.tn == b.tn && a.at == b.at;
}

// kernel output certified from its witness at both levels and every thread
// count, the witness-free certifier agreeing, the witness thread-independent;
// for each way of inserting (sequential, and stage 2b's territories and
// batches from the fourth point on; parallel false: sequential only)
template <class Require>
void check_accepts(const PointSet& ps, const Require& require, bool parallel = true) {
  if (!dimension_problem(ps).empty()) return;  // rejected before any triangle (rt2_cpu_test)
  const Run base = run(ps, 1);
  require(certify::rt2(ps, base.tris, certify::Level::canonical).ok, "certify::rt2 rejects the kernel's output");
  for (Insertion how : {Insertion::sequential, Insertion::territories, Insertion::batches}) {
    if (!parallel && how != Insertion::sequential) continue;
    const Run first = how == Insertion::sequential ? base : run(ps, 1, how, 3);
    for (int t : kThreads) {
      const Run r = how == Insertion::sequential ? run(ps, t) : run(ps, t, how, 3);
      require(r.tris == base.tris, "the insertion modes disagree");
      require(same_witness(r.w, first.w), "the witness depends on the thread count");
      for (certify::Level level : {certify::Level::canonical, certify::Level::exact}) {
        require(cpu::certify_rt2(ps, r.tris, level, r.w, t).ok, "the witnessed certifier rejects the kernel's output");
      }
    }
  }
}

// ---- deliberate corruptions -------------------------------------------------

bool real(const cpu::Rt2Witness& w, std::size_t t) {
  const std::uint32_t n = static_cast<std::uint32_t>(w.pts.size());
  return w.tv[3 * t] != kNo && w.tv[3 * t] != n && w.tv[3 * t + 1] != n && w.tv[3 * t + 2] != n;
}
Triangle canonical_ids(const cpu::Rt2Witness& w, std::size_t t) {
  Triangle x = {w.pts[w.tv[3 * t]].id, w.pts[w.tv[3 * t + 1]].id, w.pts[w.tv[3 * t + 2]].id};
  std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
  return x;
}
// the canonical output of the witness' real triangles
std::vector<Triangle> output_of(const cpu::Rt2Witness& w) {
  std::vector<Triangle> out;
  for (std::size_t t = 0; t < w.tv.size() / 3; ++t)
    if (real(w, t)) out.push_back(canonical_ids(w, t));
  std::sort(out.begin(), out.end());
  return out;
}
pred::Pt pt(const cpu::Rt2Witness& w, std::uint32_t k) { return {w.pts[k].id, w.pts[k].xy}; }
inline std::uint32_t nx(std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::uint32_t pv(std::uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

// interior half-edges e (twin in a real triangle, e < twin) in slot order
std::vector<std::uint32_t> interior_edges(const cpu::Rt2Witness& w) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t e = 0; e < w.tn.size(); ++e)
    if (real(w, e / 3) && real(w, w.tn[e] / 3) && e < w.tn[e]) out.push_back(e);
  return out;
}

// 2-2 flip of the interior edge of half-edge e in the witness: t = (p, a, b)
// and u = (d, b, a) become (p, a, d) and (p, d, b), links and `at` updated
// (the kernel's flip, written independently here). Only for a convex
// quadrilateral (both new triangles counter-clockwise).
bool flip_edge(cpu::Rt2Witness& w, std::uint32_t e) {
  const std::uint32_t f = w.tn[e], t = e / 3, u = f / 3;
  const std::uint32_t p = w.tv[e], a = w.tv[nx(e)], b = w.tv[pv(e)], d = w.tv[f];
  if (pred::orient2d(pt(w, p), pt(w, a), pt(w, d)) <= 0 || pred::orient2d(pt(w, p), pt(w, d), pt(w, b)) <= 0)
    return false;
  auto half = [&](std::uint32_t s, std::uint32_t x, std::uint32_t y) {  // the half-edge x -> y of slot s
    for (std::uint32_t i = 0; i < 3; ++i)
      if (w.tv[3 * s + (i + 1) % 3] == x && w.tv[3 * s + (i + 2) % 3] == y) return 3 * s + i;
    FAIL("no half-edge");
    return kNo;
  };
  const std::uint32_t tw_pa = w.tn[half(t, p, a)], tw_bp = w.tn[half(t, b, p)], tw_ad = w.tn[half(u, a, d)],
                      tw_db = w.tn[half(u, d, b)];
  auto link = [&](std::uint32_t x, std::uint32_t y) { w.tn[x] = y, w.tn[y] = x; };
  w.tv[3 * t] = p, w.tv[3 * t + 1] = a, w.tv[3 * t + 2] = d;  // 0: a->d, 1: d->p, 2: p->a
  w.tv[3 * u] = p, w.tv[3 * u + 1] = d, w.tv[3 * u + 2] = b;  // 0: d->b, 1: b->p, 2: p->d
  link(3 * t, tw_ad), link(3 * t + 2, tw_pa), link(3 * u, tw_db), link(3 * u + 1, tw_bp);
  link(3 * t + 1, 3 * u + 2);
  if (w.at[a] == u) w.at[a] = t;
  if (w.at[b] == t) w.at[b] = u;
  return true;
}

struct Corruption {
  std::string name;
  std::string condition;  // expected at Level::canonical
  bool output_wrong;      // the output itself is wrong: certify::rt2 must reject it too
  std::function<bool(const PointSet&, Run&)> apply;  // false: not applicable to this input
};

std::vector<Corruption> corruptions() {
  std::vector<Corruption> c;
  c.push_back({"a missing point given a triangle that does not contain it", "missing-point-witness", false,
               [](const PointSet&, Run& r) {
                 const std::uint32_t n = static_cast<std::uint32_t>(r.w.pts.size());
                 for (std::uint32_t k = n / 2; k < n; ++k) {
                   const std::uint32_t t = r.w.at[k];
                   const std::uint32_t* v = &r.w.tv[3 * t];
                   if (v[0] == k || v[1] == k || v[2] == k) continue;  // a vertex
                   // a real triangle that is not t and does not have k as a corner
                   for (std::uint32_t s = 0; s < r.w.tv.size() / 3; ++s)
                     if (s != t && real(r.w, s) && r.w.tv[3 * s] != k && r.w.tv[3 * s + 1] != k &&
                         r.w.tv[3 * s + 2] != k) {
                       r.w.at[k] = s;
                       return true;
                     }
                 }
                 return false;
               }});
  c.push_back({"a vertex declared missing (its witness triangle without it)", "vertex-fan", false,
               [](const PointSet&, Run& r) {
                 const std::uint32_t n = static_cast<std::uint32_t>(r.w.pts.size());
                 for (std::uint32_t k = n / 2; k < n; ++k) {
                   const std::uint32_t t = r.w.at[k];
                   const std::uint32_t* v = &r.w.tv[3 * t];
                   if (v[0] != k && v[1] != k && v[2] != k) continue;
                   for (std::uint32_t s = 0; s < r.w.tv.size() / 3; ++s)
                     if (real(r.w, s) && r.w.tv[3 * s] != k && r.w.tv[3 * s + 1] != k && r.w.tv[3 * s + 2] != k) {
                       r.w.at[k] = s;
                       return true;
                     }
                 }
                 return false;
               }});
  c.push_back({"an asymmetric neighbour link", "neighbour-links", false, [](const PointSet&, Run& r) {
                 const std::vector<std::uint32_t> in = interior_edges(r.w);
                 if (in.size() < 2) return false;
                 r.w.tn[in[in.size() / 2]] = in[in.size() / 2 + 1];
                 return true;
               }});
  c.push_back({"two neighbour links swapped (symmetric, wrong edges)", "neighbour-links", false,
               [](const PointSet&, Run& r) {
                 const std::vector<std::uint32_t> in = interior_edges(r.w);
                 if (in.size() < 2) return false;
                 const std::uint32_t e1 = in[in.size() / 3], e2 = in[2 * in.size() / 3];
                 const std::uint32_t f1 = r.w.tn[e1], f2 = r.w.tn[e2];
                 r.w.tn[e1] = f2, r.w.tn[f2] = e1, r.w.tn[e2] = f1, r.w.tn[f1] = e2;
                 return true;
               }});
  c.push_back({"one interior edge flipped to a non-regular one (witness and output)", "locally-regular", true,
               [](const PointSet&, Run& r) {
                 const std::vector<std::uint32_t> in = interior_edges(r.w);
                 for (std::size_t i = in.size() / 2; i < in.size(); ++i)
                   if (flip_edge(r.w, in[i])) {
                     r.tris = output_of(r.w);
                     return true;
                   }
                 return false;
               }});
  c.push_back({"a triangle dropped (witness and output)", "neighbour-links", true, [](const PointSet&, Run& r) {
                 for (std::size_t t = r.w.tv.size() / 6; t < r.w.tv.size() / 3; ++t)
                   if (real(r.w, t)) {
                     r.w.tv[3 * t] = r.w.tv[3 * t + 1] = r.w.tv[3 * t + 2] = kNo;
                     r.tris = output_of(r.w);
                     return true;
                   }
                 return false;
               }});
  c.push_back({"a triangle dropped from the output only", "canonical-output", true, [](const PointSet&, Run& r) {
                 r.tris.erase(r.tris.begin() + static_cast<long>(r.tris.size() / 2));
                 return true;
               }});
  c.push_back({"an output triangle that is not the witness'", "canonical-output", true, [](const PointSet& ps, Run& r) {
                 // the middle triangle's last vertex replaced by the smallest
                 // other index above its first (so it stays rotated), the
                 // output kept sorted and without repeats
                 Triangle x = r.tris[r.tris.size() / 2];
                 Index c = x[0] + 1;
                 while (c == x[1] || c == x[2]) ++c;
                 if (c >= ps.size()) return false;
                 x[2] = c;
                 if (std::binary_search(r.tris.begin(), r.tris.end(), x)) return false;
                 r.tris[r.tris.size() / 2] = x;
                 std::sort(r.tris.begin(), r.tris.end());
                 return true;
               }});
  c.push_back({"the output out of canonical order", "canonical-output", true, [](const PointSet&, Run& r) {
                 if (r.tris.size() < 2) return false;
                 std::swap(r.tris[0], r.tris[r.tris.size() - 1]);
                 return true;
               }});
  c.push_back({"a vertex that is not redundant declared missing", "missing-point-redundant", true,
               [](const PointSet& ps, Run& r) {
                 // the kernel's answer for ps with one interior vertex v made
                 // redundant (its weight lowered far), its witness then given
                 // back v's own weight: v is missing, inside its witness
                 // triangle, and not redundant in ps
                 if (!ps.weighted) return false;
                 const std::uint32_t n = static_cast<std::uint32_t>(r.w.pts.size());
                 Index v = kNo;
                 for (std::uint32_t k = n / 2; k < n && v == kNo; ++k) {
                   const std::uint32_t* c = &r.w.tv[3 * r.w.at[k]];
                   if (c[0] != k && c[1] != k && c[2] != k) continue;  // not a vertex
                   const double* x = r.w.pts[k].xy;
                   if (x[0] > 0.25 && x[0] < 0.75 && x[1] > 0.25 && x[1] < 0.75) v = r.w.pts[k].id;
                 }
                 if (v == kNo) return false;
                 PointSet lowered = ps;
                 lowered.weights[v] = -1.0;
                 r = run(lowered);
                 for (cpu::Rt2Point& q : r.w.pts)
                   if (q.id == v) q.w = ps.weights[v];
                 return true;
               }});
  c.push_back({"a triangle turned clockwise", "triangle-orientation", false, [](const PointSet&, Run& r) {
                 for (std::size_t t = r.w.tv.size() / 6; t < r.w.tv.size() / 3; ++t)
                   if (real(r.w, t)) {
                     std::swap(r.w.tv[3 * t + 1], r.w.tv[3 * t + 2]);
                     return true;
                   }
                 return false;
               }});
  c.push_back({"two positions naming the same input point", "witness-points", false, [](const PointSet&, Run& r) {
                 r.w.pts[1] = r.w.pts[0];
                 return true;
               }});
  return c;
}

PointSet square(std::size_t n, double whi, std::uint64_t seed) {
  gen::Options o;
  o.seed = seed;
  o.weighted = whi > 0;
  o.whi = whi;
  return gen::generate("square", n, o);
}

}  // namespace

TEST_CASE("rt2 witness: degenerate sets are certified from the kernel's witness (shrinking)", "[rt2_witness]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("degenerate sets of 3..60 points, ") + (weighted ? "weighted" : "unweighted") +
                          ": witnessed certifier accepts at 1, 2, 8 threads, both levels; certify::rt2 agrees",
                      8, [weighted] {
                        const PointSet ps = *test::degenerate_points(2, 3, 60, weighted);
                        check_accepts(ps, [](bool ok, const char*) { RC_ASSERT(ok); });
                      });
}

TEST_CASE("rt2 witness: every generator family is certified from the kernel's witness (shrinking)", "[rt2_witness]") {
  for (bool weighted : {false, true})
    test::prop_scaled(std::string("family sets of 3..2000 points, ") +
                          (weighted ? "weights from none to 99% redundant" : "unweighted") +
                          ": witnessed certifier accepts at 1, 2, 8 threads, both levels; certify::rt2 agrees "
                          "(sequential insertion; stage 2b: the degenerate sets and the 5000-point inputs)",
                      40, [weighted] {
                        const PointSet ps = *test::thinned(test::family_points(2, 3, 2000, weighted));
                        check_accepts(ps, [](bool ok, const char*) { RC_ASSERT(ok); }, false);
                      });
}

TEST_CASE("rt2 witness: stage 2b's witness is thread-independent and certified on 5000-point inputs", "[rt2_witness]") {
  // parallel insertion from the 65th point on: dozens of territories and
  // batches; uniform (weights in three ranges) and lattice input
  for (const double whi : {0.0, 1e-5, 1e-3, 1e-1}) {
    const PointSet ps = square(5000, whi, 7);
    INFO("square, weights [0, " << whi << "]");
    const Run base = run(ps, 1);
    for (Insertion how : {Insertion::territories, Insertion::batches}) {
      const Run first = run(ps, 1, how, 64);
      REQUIRE(first.tris == base.tris);
      for (int t : kThreads) {
        const Run r = run(ps, t, how, 64);
        INFO(t << " threads, " << (how == Insertion::territories ? "territories" : "batches"));
        REQUIRE(r.tris == base.tris);
        REQUIRE(same_witness(r.w, first.w));
        REQUIRE(cpu::certify_rt2(ps, r.tris, certify::Level::exact, r.w, t).ok);
      }
    }
  }
  const PointSet grid = test::family_input("grid2", 5000, 2, false, 0);
  for (Insertion how : {Insertion::territories, Insertion::batches}) {
    const Run first = run(grid, 1, how, 64);
    REQUIRE(cpu::certify_rt2(grid, first.tris, certify::Level::exact, first.w, 1).ok);
    for (int t : kThreads) REQUIRE(same_witness(run(grid, t, how, 64).w, first.w));
  }
}

TEST_CASE("rt2 witness: large inputs in several pieces are certified, every family", "[rt2_witness][long]") {
  // 20000 points: several kChunk pieces of points and slots; the sequential
  // insertion (stage 2b's witnesses: the 5000-point case above, CI time)
  for (const std::string& fam : test::families(2))
    for (bool weighted : {false, true}) {
      const PointSet ps = test::family_input(fam, 20000, 3, weighted, 1e-5);
      INFO(fam << (weighted ? " weighted" : ""));
      check_accepts(
          ps,
          [](bool ok, const char* what) {
            INFO(what);
            REQUIRE(ok);
          },
          false);
    }
}

TEST_CASE("rt2 witness: wrong witnesses and outputs are rejected with their condition", "[rt2_witness]") {
  // 30000 points, weights in [0, 1e-5]: about a third are vertices, so there
  // are missing points in every piece; and unweighted (every point a vertex)
  for (const double whi : {1e-5, 0.0}) {
    const PointSet ps = square(30000, whi, 11);
    const Run right = run(ps);
    std::size_t applied = 0;
    for (const Corruption& c : corruptions()) {
      Run r = right;
      if (!c.apply(ps, r)) continue;
      ++applied;
      for (int t : kThreads) {
        const certify::Report rep = cpu::certify_rt2(ps, r.tris, certify::Level::canonical, r.w, t);
        INFO(c.name << (whi > 0 ? ", weighted" : ", unweighted") << ", " << t << " threads: " << rep.message());
        REQUIRE(!rep.ok);
        REQUIRE(rep.condition == c.condition);
        // the exact level rejects it too, except an output merely out of
        // order (any order is a right answer there)
        const certify::Report ex = cpu::certify_rt2(ps, r.tris, certify::Level::exact, r.w, t);
        INFO("exact level: " << ex.message());
        REQUIRE(ex.ok == (c.condition == "canonical-output" && c.name.find("order") != std::string::npos));
      }
      // the witness-free certifier agrees where the output itself is wrong,
      // and accepts the (right) output of a wrong witness
      const certify::Report plain = certify::rt2(ps, r.tris, certify::Level::canonical);
      INFO(c.name << ": certify::rt2 says " << plain.message());
      REQUIRE(plain.ok == !c.output_wrong);
    }
    REQUIRE(applied == corruptions().size() - (whi > 0 ? 0 : 2));  // unweighted: no missing point, no weight
  }
}

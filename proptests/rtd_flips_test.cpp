// rtd_flips_test.cpp — the d-dimensional triangulation structure and its
// bistellar flips (reference/rtd/triangulation_d.hpp, bistellar_flip.hpp;
// thesis §2.1-§2.3).
//
// Properties, for d = 2..5:
//   * every flip k-(d+2-k), k = 1..d+1, is exercised on random walks through
//     the flip graph (starting from RT+1 outputs) and is followed by its
//     inverse, which gives back the same triangulation (all simplices, real
//     and virtual, as vertex sets);
//   * after every flip the structure is valid (validity_problem: symmetric
//     links, positive real simplices, opposite induced orientations, convex
//     hull);
//   * flip_shape's Radon partition and flippability agree with an independent
//     computation: the affine dependence of S_F from the signs of
//     (-1)^i orient_d(S_F \ s_i), and the induced subcomplex found by scanning
//     all simplices (flippable iff it is the triangulation T_U, §2.3);
//   * the canonical simplex form (canonical_d.hpp) coincides with
//     canonical_triangles for d = 2 and its writer/reader round-trip.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <random>
#include <set>
#include <sstream>

#include "predicates/predicates.hpp"
#include "proptests/support/rtd_inputs.hpp"
#include "reference/canonical.hpp"
#include "reference/rtd/bistellar_flip.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/rt_incremental.hpp"

using namespace flipflop;
using namespace flipflop::ref::rtd;

namespace {

// Every live simplex as a sorted vertex set (v = n included): the whole state.
std::set<std::vector<Index>> state(const TriangulationD& T) {
  std::set<std::vector<Index>> out;
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    std::vector<Index> t(T.tuple(s), T.tuple(s) + T.d + 1);
    std::sort(t.begin(), t.end());
    out.insert(t);
  }
  return out;
}

// Independent Radon partition of S_F: sign of (-1)^i orient_d(S without s_i).
std::vector<int> radon_signs(const TriangulationD& T, const PointTuple& S) {
  const int d = T.d;
  std::vector<int> sg;
  for (int i = 0; i < d + 2; ++i) {
    pred::Pt p[8];
    int k = 0;
    for (int j = 0; j < d + 2; ++j)
      if (j != i) p[k++] = {S[static_cast<std::size_t>(j)], T.ps->point(S[static_cast<std::size_t>(j)])};
    const int o = pred::orient_d(d, p);
    sg.push_back((i % 2 == 0) ? o : -o);
  }
  return sg;
}

// The induced subcomplex of S_F by scanning every live simplex.
std::set<std::vector<Index>> induced(const TriangulationD& T, const PointTuple& S) {
  std::set<Index> in(S.begin(), S.begin() + T.d + 2);
  std::set<std::vector<Index>> out;
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(T.slots()); ++s) {
    if (!T.alive[static_cast<std::size_t>(s)]) continue;
    std::vector<Index> t(T.tuple(s), T.tuple(s) + T.d + 1);
    bool all = true;
    for (Index x : t) all = all && in.count(x);
    if (!all) continue;
    std::sort(t.begin(), t.end());
    out.insert(t);
  }
  return out;
}

void check_shape(const TriangulationD& T, RidgeD r, const FlipShape& sh) {
  const int d = T.d;
  REQUIRE(sh.interior);
  const std::vector<int> sg = radon_signs(T, sh.S);
  const int sb = sg[static_cast<std::size_t>(d + 1)];  // b = S[d+1] is in U
  std::set<Index> U, V;
  for (int i = 0; i < d + 2; ++i) (sg[static_cast<std::size_t>(i)] == sb ? U : V).insert(sh.S[static_cast<std::size_t>(i)]);
  REQUIRE(U == std::set<Index>(sh.U.begin(), sh.U.begin() + sh.nu));
  REQUIRE(V == std::set<Index>(sh.V.begin(), sh.V.begin() + sh.nv));
  REQUIRE(U.count(link_a(T, r)) == 1);
  std::set<std::vector<Index>> TU;
  for (Index x : U) {
    std::vector<Index> t;
    for (int i = 0; i < d + 2; ++i)
      if (sh.S[static_cast<std::size_t>(i)] != x) t.push_back(sh.S[static_cast<std::size_t>(i)]);
    std::sort(t.begin(), t.end());
    TU.insert(t);
  }
  REQUIRE(sh.flippable == (induced(T, sh.S) == TU));
}

// All interior ridges whose flip exists.
std::vector<RidgeD> flippable_ridges(const TriangulationD& T) {
  std::vector<RidgeD> out;
  for (const RidgeD& r : ridges(T))
    if (interior(T, r) && flip_shape(T, r).flippable) out.push_back(r);
  return out;
}

// The inverse of a flip: for |V| >= 2 a ridge between two created simplices
// (its flip is the (d+2-k)-k flip on the same S_F); for a (d+1)-1 flip the
// 1-(d+1) insertion of the removed vertex into the created simplex.
void undo(TriangulationD& T, const FlipResult& res, int k) {
  const int d = T.d;
  if (res.removed != kNoVertex) {
    REQUIRE(res.created.size() == 1u);
    const FlipResult back = insert_in_simplex(T, res.created[0], res.removed);
    REQUIRE(back.k == 1);
    return;
  }
  REQUIRE(res.created.size() >= 2u);
  const std::int32_t s = res.created[0];
  for (int i = 0; i <= d; ++i) {
    const std::int32_t t = T.neighbor(s, i);
    if (std::find(res.created.begin(), res.created.end(), t) == res.created.end()) continue;
    const FlipShape sh = flip_shape(T, {s, i});
    check_shape(T, {s, i}, sh);
    REQUIRE(sh.flippable);
    REQUIRE(sh.k == d + 2 - k);
    flip(T, sh);
    return;
  }
  FAIL("no ridge between the created simplices");
}

}  // namespace

TEST_CASE("rtd flips: every k-(d+2-k) flip and its inverse on random walks for d 2 to 5") {
  for (int d = 2; d <= 5; ++d) {
    INFO("d=" << d);
    std::vector<std::uint64_t> done(static_cast<std::size_t>(d + 2), 0);
    for (std::uint64_t seed = 1; seed <= (d == 5 ? 3u : 5u); ++seed) {
      // heavy weights: redundant points to insert by 1-(d+1) flips
      const PointSet ps = test::rtd_uniform(d, d == 5 ? 40 : 40, 100 * seed + static_cast<std::uint64_t>(d), d == 5 ? 1.0 : 0.2);
      TriangulationD T = ref::build_rtd(ps);
      std::mt19937_64 g(seed);
      const int steps = d == 5 ? 60 : 120;
      for (int step = 0; step < steps; ++step) {
        const auto before = state(T);
        // a 1-(d+1) flip of a non-vertex point, then its inverse
        if (step % 10 == 0) {
          for (Index p = 0; p < T.n; ++p) {
            if (T.is_vertex(p)) continue;
            const std::int32_t s = locate(T, p, kNone);
            if (is_virtual_simplex(T, s)) continue;
            REQUIRE(contains(T, s, p));
            const FlipResult in = insert_in_simplex(T, s, p);
            REQUIRE(in.created.size() == static_cast<std::size_t>(d + 1));
            REQUIRE(validity_problem(T).empty());
            ++done[1];
            const FlipResult out = remove_vertex(T, p);  // the (d+1)-1 flip
            REQUIRE(out.k == d + 1);
            REQUIRE(out.removed == p);
            ++done[static_cast<std::size_t>(d + 1)];
            REQUIRE(state(T) == before);
            break;
          }
        }
        const std::vector<RidgeD> fr = flippable_ridges(T);
        REQUIRE(!fr.empty());
        // prefer rare flip types so every k shows up
        std::vector<RidgeD> pick;
        for (const RidgeD& r : fr) {
          const int k = flip_shape(T, r).k;
          if (done[static_cast<std::size_t>(k)] < 3) pick.push_back(r);
        }
        if (pick.empty()) pick = fr;
        const RidgeD r = pick[g() % pick.size()];
        const FlipShape sh = flip_shape(T, r);
        check_shape(T, r, sh);
        const FlipResult res = flip(T, sh);
        REQUIRE(res.k == sh.k);
        REQUIRE(res.created.size() == static_cast<std::size_t>(d + 2 - sh.k));
        REQUIRE(res.boundary.size() == static_cast<std::size_t>(sh.k * (d + 2 - sh.k)));
        {
          const std::string why = validity_problem(T);
          INFO(why);
          REQUIRE(why.empty());
        }
        ++done[static_cast<std::size_t>(sh.k)];
        const auto after = state(T);
        undo(T, res, sh.k);
        ++done[static_cast<std::size_t>(d + 2 - sh.k)];
        REQUIRE(validity_problem(T).empty());
        REQUIRE(state(T) == before);
        // walk on: redo the forward flip (a fresh ridge of the same S_F)
        const RidgeD again = find_ridge(T, sh.S.data(), sh.S[static_cast<std::size_t>(d)], sh.S[static_cast<std::size_t>(d + 1)]);
        REQUIRE(again.valid());
        flip(T, again);
        REQUIRE(state(T) == after);
      }
    }
    for (int k = 1; k <= d + 1; ++k) {
      INFO("k=" << k << " flips done " << done[static_cast<std::size_t>(k)]);
      CHECK(done[static_cast<std::size_t>(k)] > 0);
    }
  }
}

TEST_CASE("rtd flips: flip_shape agrees with the independent Radon partition and induced subcomplex") {
  // a loop over seeds (each case checks every ridge of a triangulation
  // against an O(#simplices) scan: too expensive for 2000 RapidCheck cases)
  for (std::uint64_t seed = 1; seed <= 90 / test::kRtdSanitizerDivisor; ++seed) {
    const int d = 2 + static_cast<int>(seed % 3);
    const PointSet ps = (seed >> 2) % 2 ? test::rtd_uniform(d, 12 + (seed >> 3) % 20, seed, 0.05)
                                        : test::rtd_lattice(d, 12 + (seed >> 3) % 20, seed, 2, 1);
    TriangulationD T;
    try {
      T = ref::build_rtd(ps);
    } catch (const std::invalid_argument&) {
      continue;  // lower-dimensional lattice sample
    }
    std::mt19937_64 g(seed);
    for (int round = 0; round < 3; ++round) {
      std::vector<RidgeD> fr;
      for (const RidgeD& r : ridges(T)) {
        if (!interior(T, r)) {
          REQUIRE(!flip_shape(T, r).flippable);  // §2.3: boundary ridges are unflippable
          continue;
        }
        const FlipShape sh = flip_shape(T, r);
        check_shape(T, r, sh);
        if (sh.flippable) fr.push_back(r);
      }
      if (fr.empty()) break;
      flip(T, fr[g() % fr.size()]);
      REQUIRE(validity_problem(T).empty());
    }
  }
}

TEST_CASE("rtd structure: ridges and S_F and recall and find and from_simplices") {
  for (int d = 2; d <= 5; ++d) {
    INFO("d=" << d);
    const PointSet ps = test::rtd_uniform(d, 30, 7 + static_cast<std::uint64_t>(d), 0.01);
    TriangulationD T = ref::build_rtd(ps);
    REQUIRE(validity_problem(T).empty());
    for (const RidgeD& r : ridges(T)) {
      const PointTuple S = points(T, r);
      // (S_0..S_{d-1}, a) is an even permutation of C1's tuple
      std::vector<Index> c1(T.tuple(r.s), T.tuple(r.s) + d + 1), f(S.begin(), S.begin() + d + 1);
      REQUIRE(odd_sorting_parity(c1) == odd_sorting_parity(f));
      REQUIRE(S[static_cast<std::size_t>(d + 1)] == link_b(T, r));
      const RidgeD o = twin(T, r);
      REQUIRE(twin(T, o).s == r.s);
      REQUIRE(twin(T, o).i == r.i);
      if (interior(T, r)) {
        // local regularity of an interior ridge is the power test on S_F
        REQUIRE(locally_regular(T, r));
        REQUIRE(power(T, S.data()) < 0);
        REQUIRE(find_ridge(T, S.data(), S[static_cast<std::size_t>(d)], S[static_cast<std::size_t>(d + 1)]).s == r.s);
        REQUIRE(recall(T, remember(T, r)).s == r.s);
      }
    }
    // remembered ridges die with their simplices
    const std::vector<RidgeD> all = ridges(T);
    std::vector<RidgeRef> refs;
    for (const RidgeD& r : all) refs.push_back(remember(T, r));
    RidgeD target;
    for (const RidgeD& r : all)
      if (interior(T, r) && flip_shape(T, r).flippable) {
        target = r;
        break;
      }
    REQUIRE(target.valid());
    const FlipShape sh = flip_shape(T, target);
    flip(T, sh);
    for (std::size_t k = 0; k < all.size(); ++k) {
      const RidgeD back = recall(T, refs[k]);
      if (back.valid()) REQUIRE(find_ridge(T, points(T, back).data(), refs[k].a, refs[k].b).valid());
    }
    // from_simplices rebuilds the same structure from the output simplices
    const auto out = real_simplices(T);
    const TriangulationD U = from_simplices(ps, out);
    REQUIRE(validity_problem(U).empty());
    REQUIRE(state(U) == state(T));
    // and rejects a non-tiling
    auto bad = out;
    bad.pop_back();
    REQUIRE_THROWS_AS(from_simplices(ps, bad), std::invalid_argument);
  }
}

TEST_CASE("rtd canonical form: d = 2 coincides with canonical_triangles and the writer and reader round-trip") {
  rc::prop("random triangles and d-tuples", [](std::uint64_t seed) {
    std::mt19937_64 g(seed);
    std::vector<Triangle> tris;
    std::vector<std::vector<Index>> as_tuples;
    for (int k = 0; k < 20; ++k) {
      Triangle t{static_cast<Index>(g() % 50), static_cast<Index>(50 + g() % 50), static_cast<Index>(100 + g() % 50)};
      std::shuffle(t.begin(), t.end(), g);
      tris.push_back(t);  // taken as counter-clockwise (positive) as given
      as_tuples.push_back({t[0], t[1], t[2]});
    }
    const auto ct = canonical_triangles(tris);
    const auto cs = canonical_simplices(as_tuples, Orientation::orient_d);  // d = 2: the conventions agree
    RC_ASSERT(canonical_simplices(as_tuples, Orientation::volume) == cs);
    RC_ASSERT(ct.size() == cs.size());
    for (std::size_t i = 0; i < ct.size(); ++i)
      RC_ASSERT((std::vector<Index>{ct[i][0], ct[i][1], ct[i][2]}) == cs[i]);
    // d-tuples: the canonical tuple is an even permutation of the given one
    // when given in the volume convention; when given in the orient_d
    // convention, an even permutation in even d and an odd one in odd d
    // (det[[p_i 1]] = (-1)^d det[p_1 - p_0, ...], canonical_d.hpp);
    // smallest first, rest ascending up to the last two
    const int d = 2 + static_cast<int>(seed % 4);
    std::vector<std::vector<Index>> ts;
    for (int k = 0; k < 10; ++k) {
      std::vector<Index> t;
      for (int i = 0; i <= d; ++i) t.push_back(static_cast<Index>(i * 1000 + g() % 1000));
      std::shuffle(t.begin(), t.end(), g);
      const auto c = canonical_simplex(t, Orientation::volume);
      RC_ASSERT(odd_sorting_parity(c) == odd_sorting_parity(t));
      RC_ASSERT(is_canonical_shape(c));
      const auto co = canonical_simplex(t, Orientation::orient_d);
      RC_ASSERT((odd_sorting_parity(co) != odd_sorting_parity(t)) == (d % 2 == 1));
      RC_ASSERT(is_canonical_shape(co));
      RC_ASSERT(c[0] == *std::min_element(t.begin(), t.end()));
      ts.push_back(t);
    }
    const auto cts = canonical_simplices(ts, Orientation::volume);
    RC_ASSERT(std::is_sorted(cts.begin(), cts.end()));
    const std::string text = simplices_text(cts);
    RC_ASSERT(parse_simplices(text, d) == cts);
  });
  REQUIRE_THROWS_AS(parse_simplices("0 1 2\n3 4\n", 2), std::invalid_argument);
  REQUIRE_THROWS_AS(parse_simplices("0 1 -2\n", 2), std::invalid_argument);
  REQUIRE_THROWS_AS(parse_simplices("0 1 x\n", 2), std::invalid_argument);
  REQUIRE(parse_simplices("\n0 1 2 3\n\n", 3) == std::vector<std::vector<Index>>{{0, 1, 2, 3}});
}

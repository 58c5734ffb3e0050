// instant_flip_rt_plus_2_test.cpp — thesis §9.1, Table 9.1 and Figure 9.2:
// from the "RT+2" triangulation an arbitrarily monotonic flip algorithm can get
// stuck (exhaustive enumeration of all monotonic flip sequences), while the
// monotonic instant flip (Algorithm 14) reaches the regular triangulation
// (Theorem 9.3: a monotonic flip algorithm gets stuck only at non-regular
// triangulations; the instant flip visits regular ones only).
//
// The virtual vertex of the thesis' extended triangulation is replaced by four
// real vertices far from the kernel point s (a regular tetrahedron of
// circumradius 100 around s, slightly irregular), as §9.1 suggests. a and g
// are inserted by 1-4 flips into the Delaunay triangulation of the others,
// each lifted just below its tetrahedron (so the start is RT(S ⊕ W) for a W
// that differs from 0 at a and g only); the target is U = 0 (Delaunay).
#include <catch2/catch.hpp>

#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/instant_flip.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "reference/rtd/timeline.hpp"
#include "support/instant_flip_rt_plus_2.hpp"

using namespace flipflop;
using namespace flipflop::test_if;

namespace {

std::vector<std::vector<Index>> as_list(const SimplexSet& T) { return {T.begin(), T.end()}; }

}  // namespace

TEST_CASE("RT+2 (Table 9.1): monotonic flipping can get stuck, the instant flip cannot",
          "[instant_flip][rt_plus_2]") {
  for (std::size_t first : {std::size_t{0}, std::size_t{6}}) {  // insert a then g, or g then a
    const std::size_t second = first == 0 ? 6 : 0;
    RtPlus2 r = make_rt_plus_2(first, second, 4, 100.0);
    const std::size_t n = r.ps.size();
    const PointSet pw = with_weights(r.ps, r.w);
    const std::vector<double> u(n, 0.0);
    const PointSet pu = with_weights(r.ps, u);
    const auto h_u = heights_q(r.ps, to_q(u));

    // The start is RT(S ⊕ W): strictly convex everywhere (oracle) and certified.
    REQUIRE(all_convex_q(r.ps, heights_q(r.ps, to_q(r.w)), r.start));
    ref::rtd::TriangulationD T = ref::rtd::from_simplices(pw, as_list(r.start));
    const auto start_list = ref::rtd::real_simplices(T);
    REQUIRE(ref::certify_rtd(pw, start_list).ok);

    // An RT+2 triangulation is not regular for U = 0: it has locally
    // non-Delaunay ridges. (With the far vertices in place of the virtual
    // vertex they are other ridges than the thesis' {bce, cde, vbc, vce} of
    // Figure 9.2(a); the phenomenon below is the same.)
    CHECK_FALSE(non_regular(r.ps, h_u, r.start).empty());

    // Every monotonic flip sequence (Figure 9.2(b)): two terminals, the
    // regular triangulation and one where all non-regular ridges are stuck.
    const FlipGraph g = monotonic_flip_graph(r.ps, h_u, r.start);
    const ref::Rtd delaunay = ref::rtd_incremental(pu);
    REQUIRE(g.regular.size() == 1);
    CHECK(to_set(delaunay.simplices) == g.regular.front());
    REQUIRE(g.stuck.size() >= 1);
    for (const SimplexSet& stuck : g.stuck) {
      const std::vector<Ridge> left = non_regular(r.ps, h_u, stuck);
      CHECK_FALSE(left.empty());
      for (const Ridge& x : left) CHECK_FALSE(radon_flip(r.ps, stuck, x, nullptr));
    }

    // The instant flip: each flip is monotonic (a failing ridge stays reflex
    // until t = 1), so its run is a path of that graph; it ends regular, and
    // every intermediate time line is well-separated (Lemma 9.10).
    std::size_t off_graph = 0, not_separated = 0, flips = 0;
    ref::InstantFlipOptions opt;
    const ref::MovingModel mm(r.ps, r.w, u);
    const auto order = ref::PerturbationOrder::identity(n);
    opt.on_flip = [&](const ref::rtd::TriangulationD& cur, const ref::InstantFlipEvent&) {
      ++flips;
      const auto list = ref::rtd::real_simplices(cur);
      off_graph += g.seen.count(to_set(list)) ? 0 : 1;
      not_separated += ref::build_timeline(mm, list, order).well_separated ? 0 : 1;
    };
    ref::instant_flip(T, r.w, u, opt);
    CHECK(flips > 0);
    CHECK(off_graph == 0);
    CHECK(not_separated == 0);
    CHECK(ref::rtd::real_simplices(T) == delaunay.simplices);
    CHECK(ref::certify_rtd(pu, ref::rtd::real_simplices(T)).ok);
  }
}

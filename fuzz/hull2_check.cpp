// hull2_check.cpp — fuzz_hull2: every reference 2D hull algorithm against the
// definition, and the certifier against small edits of the answer.
//
// Bytes: a 2D point set of 1..64 points (fuzz_input.hpp: small integers,
// duplicates, collinear runs, ulp jitter, huge / tiny magnitudes), then bytes
// choosing the edits below. Checked:
//   * input that does not span the plane (affine_dimension < 2): every
//     algorithm throws std::invalid_argument and the certifier rejects any
//     cycle at both levels;
//   * otherwise every algorithm of ref::hull2_algorithms() (graham-sort,
//     graham-insert, twist — all fast at this size) returns the same canonical
//     cycle, equal to brute::hull2 (the definition, for n <= 40), and
//     certify::hull2 accepts it at Level::canonical and Level::exact;
//   * the certifier at Level::canonical accepts only THE answer (the SoS hull
//     is unique): removing a vertex, swapping two neighbours, reversing the
//     cycle, inserting a non-vertex and rotating the start are all rejected;
//   * at Level::exact a rotation is still accepted (it is a correct hull), a
//     reversal is rejected, and so is removing a vertex that is a strict
//     corner in exact arithmetic (orient2d_exact(prev, v, next) > 0 and no
//     other vertex at its location): v then lies strictly outside the polygon.
// The multithreaded hull of kernels_cpu/hull2 (the cpu backend) is run at 1
// and 2 threads with its throw-away forced on these small inputs (sample size
// and flip-pop chunk chosen by the last bytes): it must return the answer
// byte for byte, with its counters' lemmas (every point discarded or in the
// chains' polygon, every flip removes one vertex), and reject the same inputs
// with std::invalid_argument. The GPU kernel (kernels_cuda/hull2, Graham-
// sorting and Graham-insertion) in its OpenMP build likewise, with and without
// its throw-away, chunks of 3..8.
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
#include "kernels_cuda/hull2/hull2.hpp"
#endif
#include "predicates/predicates.hpp"
#include "reference/brute_force.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"
#include "reference/hull2/hull2.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_hull2";
constexpr std::size_t kMaxPoints = 64;
constexpr std::size_t kMaxBrute = 40;

using certify::Level;

void expect(bool accept, const PointSet& ps, const std::vector<Index>& cycle, Level level, const std::string& what) {
  const certify::Report r = certify::hull2(ps, cycle, level);
  if (r.ok != accept)
    fail(kTarget,
         std::string("certify::hull2 at Level::") + (level == Level::canonical ? "canonical" : "exact") +
             (accept ? " rejected " : " accepted ") + what + ": " + r.message(),
         describe(ps) + "cycle " + describe(cycle));
}

// The cpu backend at `threads` threads, throw-away forced, tuning from bytes;
// Graham-sorting or (insert) Graham-insertion.
std::vector<Index> cpu_hull(const PointSet& ps, int threads, std::uint8_t sample, std::uint8_t chunk,
                            ref::Hull2Stats* st, bool insert) {
  cpu::Hull2Options o;
  o.threads = threads;
  o.throw_away_from = 0;
  o.sample = sample % 70;  // 0: automatic (the whole input here)
  o.scan_chunk = 1 + chunk % 9;
  return insert ? cpu::hull2_graham_insert(ps, o, st) : cpu::hull2_graham_sort(ps, o, st);
}

bool same_location(const PointSet& ps, Index a, Index b) {
  return ps.point(a)[0] == ps.point(b)[0] && ps.point(a)[1] == ps.point(b)[1];
}

}  // namespace

bool check_hull2_input(const std::uint8_t* data, std::size_t size) {
  ByteReader r{data, size};
  PointSet ps;
  if (!decode_points(r, 2, false, 1, kMaxPoints, ps)) return false;
  const std::size_t n = ps.size();

  if (affine_dimension(ps) < 2) {
    for (const std::string& algo : ref::hull2_algorithms()) {
      try {
        (void)ref::hull2(ps, algo);
        fail(kTarget, algo + " returned a hull of input that does not span the plane", describe(ps));
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail(kTarget, algo + " threw " + e.what() + " instead of std::invalid_argument", describe(ps));
      }
    }
    const std::uint8_t sample = r.byte(), chunk = r.byte();
    for (int threads : {1, 2}) {
      try {
        (void)cpu_hull(ps, threads, sample, chunk, nullptr, threads == 2);
        fail(kTarget, "cpu returned a hull of input that does not span the plane", describe(ps));
      } catch (const std::invalid_argument&) {
      } catch (const std::exception& e) {
        fail(kTarget, std::string("cpu threw ") + e.what() + " instead of std::invalid_argument", describe(ps));
      }
    }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
    try {
      (void)kernels_omp::hull2_graham_sort(ps);
      fail(kTarget, "cuda-omp returned a hull of input that does not span the plane", describe(ps));
    } catch (const std::invalid_argument&) {
    } catch (const std::exception& e) {
      fail(kTarget, std::string("cuda-omp threw ") + e.what() + " instead of std::invalid_argument", describe(ps));
    }
#endif
    if (n >= 3) {
      expect(false, ps, {0, 1, 2}, Level::exact, "a cycle of input that does not span the plane");
      expect(false, ps, {0, 1, 2}, Level::canonical, "a cycle of input that does not span the plane");
    }
    return true;
  }

  std::vector<Index> answer;
  std::string answer_from;
  if (n <= kMaxBrute) {
    answer = brute::hull2(ps);
    answer_from = "brute::hull2";
  }
  for (const std::string& algo : ref::hull2_algorithms()) {
    std::vector<Index> out;
    ref::Hull2Stats stats;
    try {
      out = ref::hull2(ps, algo, &stats);
    } catch (const std::exception& e) {
      fail(kTarget, algo + " threw: " + e.what(), describe(ps));
    }
    if (answer_from.empty()) {
      answer = out;
      answer_from = algo;
    } else if (out != answer) {
      fail(kTarget, algo + " differs from " + answer_from,
           describe(ps) + algo + " " + describe(out) + "\n" + answer_from + " " + describe(answer));
    }
    if (stats.hull_vertices != out.size())
      fail(kTarget, algo + ": stats.hull_vertices != size of the result", describe(ps));
  }
  expect(true, ps, answer, Level::canonical, "the answer");
  expect(true, ps, answer, Level::exact, "the answer");

  const std::size_t m = answer.size();
  const std::size_t k = r.byte() % m;
  {  // remove vertex k
    std::vector<Index> c = answer;
    c.erase(c.begin() + static_cast<long>(k));
    expect(false, ps, c, Level::canonical, "the answer without vertex " + std::to_string(answer[k]));
    const Index prev = answer[(k + m - 1) % m], v = answer[k], next = answer[(k + 1) % m];
    bool alone = true;
    for (std::size_t j = 0; j < m; ++j)
      if (j != k && same_location(ps, answer[j], v)) alone = false;
    if (alone && pred::orient2d_exact(ps.point(prev), ps.point(v), ps.point(next)) > 0)
      expect(false, ps, c, Level::exact, "the answer without its strict corner " + std::to_string(v));
  }
  {  // swap vertices k and k + 1
    std::vector<Index> c = answer;
    std::swap(c[k], c[(k + 1) % m]);
    expect(false, ps, c, Level::canonical, "the answer with two neighbours swapped");
  }
  {  // reverse
    std::vector<Index> c(answer.rbegin(), answer.rend());
    expect(false, ps, c, Level::canonical, "the reversed answer");
    expect(false, ps, c, Level::exact, "the reversed (clockwise) answer");
  }
  {  // rotate the start
    std::vector<Index> c = answer;
    std::rotate(c.begin(), c.begin() + 1, c.end());
    expect(false, ps, c, Level::canonical, "a rotation of the answer");
    expect(true, ps, c, Level::exact, "a rotation of the answer");
  }
  {  // insert a point that is not a vertex after position k
    std::vector<char> is_vertex(n, 0);
    for (Index v : answer) is_vertex[v] = 1;
    const std::size_t start = r.byte() % n;
    for (std::size_t j = 0; j < n; ++j) {
      const auto p = static_cast<Index>((start + j) % n);
      if (is_vertex[p]) continue;
      std::vector<Index> c = answer;
      c.insert(c.begin() + static_cast<long>(k) + 1, p);
      expect(false, ps, c, Level::canonical, "the answer with non-vertex " + std::to_string(p) + " inserted");
      break;
    }
  }
  const std::uint8_t sample = r.byte(), chunk = r.byte();
  for (int run = 0; run < 4; ++run) {
    const int threads = 1 + run % 2;
    const bool insert = run >= 2;
    std::vector<Index> got;
    ref::Hull2Stats st;
    try {
      got = cpu_hull(ps, threads, sample, chunk, &st, insert);
    } catch (const std::exception& e) {
      fail(kTarget, std::string("cpu threw: ") + e.what(), describe(ps));
    }
    if (got != answer)
      fail(kTarget, std::string("cpu ") + (insert ? "graham-insert" : "graham-sort") + " (" + std::to_string(threads) +
                        " threads) differs from " + answer_from,
           describe(ps) + "cpu " + describe(got) + "\n" + answer_from + " " + describe(answer));
    if (st.discarded_early + st.polygon_vertices != n || st.polygon_vertices - st.flips_2_1 != got.size())
      fail(kTarget, "cpu: counters break their lemmas", describe(ps));
  }
#ifdef FLIPFLOP_HAVE_KERNELS_OMP
  // the GPU kernel's OpenMP build, with and without the throw-away
  for (int run = 0; run < 4; ++run) {
    const bool throw_away = run % 2 == 0, insert = run >= 2;
    kernels::Hull2GpuOptions o;
    o.throw_away = throw_away;
    o.chunk = 3 + r.byte() % 6;
    ref::Hull2Stats st;
    std::vector<Index> got;
    try {
      got = insert ? kernels_omp::hull2_graham_insert(ps, o, &st) : kernels_omp::hull2_graham_sort(ps, o, &st);
    } catch (const std::exception& e) {
      fail(kTarget, std::string("cuda-omp threw: ") + e.what(), describe(ps));
    }
    if (got != answer)
      fail(kTarget, "cuda-omp (chunk " + std::to_string(o.chunk) + ") differs from " + answer_from,
           describe(ps) + "cuda-omp " + describe(got) + "\n" + answer_from + " " + describe(answer));
    if (st.discarded_early + st.polygon_vertices != n || st.polygon_vertices - st.flips_2_1 != got.size())
      fail(kTarget, "cuda-omp: counters break their lemmas", describe(ps));
  }
#endif
  return true;
}

}  // namespace flipflop::fuzz

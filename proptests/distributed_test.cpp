// distributed_test.cpp — the steps of a distributed hull (distributed/
// partial_hull.hpp) run in one process: rows cut into parts and blocks, the
// blocks' hull vertices, the merges, the final hull and every part's check.
// The answer must be the single-machine kernel's, cell for cell, on every
// family of gen/ (random and degenerate: grids, lattice spheres, collinear
// and coplanar sets, duplicates), for any number of parts and any block size,
// including blocks too small or too flat for a hull (passed on whole). The
// check must reject a final hull that misses a point, on the part that holds
// it. (The MPI runs of the same steps: mpi_hull_test.cpp.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "distributed/partial_hull.hpp"
#include "gen/generate.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "reference/dimension.hpp"

namespace {

using namespace flipflop;

struct Part {
  dist::Candidates mine;  // every block's hull vertices
  std::uint64_t begin = 0, end = 0;
  dist::BlockStats stats;
};

// rows [begin, end) of ps in blocks of `block` rows
Part run_part(const PointSet& ps, std::uint64_t begin, std::uint64_t end, std::uint64_t block) {
  Part p;
  p.begin = begin;
  p.end = end;
  p.mine.dim = ps.dim;
  for (std::uint64_t b = begin; b < end; b += block) {
    const std::uint64_t n = std::min(block, end - b);
    dist::append(p.mine, dist::block_candidates(ps.dim, ps.point(static_cast<std::size_t>(b)), n, b, 2, &p.stats));
  }
  return p;
}

// The binary tree of mpi_main.cpp over the parts' reduced candidates.
dist::Candidates tree(std::vector<dist::Candidates> parts) {
  for (auto& c : parts) c = dist::reduce(c, 2);
  for (std::size_t step = 1; step < parts.size(); step *= 2)
    for (std::size_t r = 0; r + step < parts.size(); r += 2 * step)
      parts[r] = dist::reduce(dist::merge(parts[r], parts[r + step]), 2);
  return parts.front();
}

std::vector<std::uint64_t> single_machine(const PointSet& ps) {
  std::vector<std::uint64_t> cells;
  if (ps.dim == 2) {
    for (Index i : cpu::hull2_graham_sort(ps)) cells.push_back(i);
  } else {
    for (const Triangle& t : cpu::hull3_ffhull(ps))
      for (Index i : t) cells.push_back(i);
  }
  return cells;
}

struct Distributed {
  dist::FinalHull hull;
  std::vector<Part> parts;
};

Distributed distributed(const PointSet& ps, int P, std::uint64_t block) {
  Distributed d;
  const std::uint64_t n = ps.size();
  std::vector<dist::Candidates> cands;
  for (int r = 0; r < P; ++r) {
    d.parts.push_back(run_part(ps, n * static_cast<std::uint64_t>(r) / static_cast<std::uint64_t>(P),
                               n * static_cast<std::uint64_t>(r + 1) / static_cast<std::uint64_t>(P), block));
    cands.push_back(d.parts.back().mine);
  }
  d.hull = dist::final_hull(tree(cands), n, 2);
  return d;
}

std::vector<std::string> families(int dim) {
  std::vector<std::string> out;
  for (const std::string& f : gen::distributions())
    if (gen::dimension_of(f) == dim) out.push_back(f);
  return out;
}

}  // namespace

TEST_CASE("distributed: every family, parts and blocks give the single-machine hull, each part certifies it",
          "[distributed][long]") {
  std::mt19937_64 rng(20261129);
  std::printf("distributed: seed 20261129\n");
  for (int dim : {2, 3})
    for (const std::string& fam : families(dim))
      for (std::size_t n : {std::size_t{40}, std::size_t{2000}}) {
        gen::Options o;
        o.seed = 7;
        const PointSet ps = gen::generate(fam, n, o);
        if (!dimension_problem(ps).empty()) continue;  // the lower-dimensional refusal: its own case below
        const std::vector<std::uint64_t> expect = single_machine(ps);
        for (int P : {1, 2, 3, 7}) {
          const std::uint64_t block = std::uniform_int_distribution<std::uint64_t>(1, n / 3 + 1)(rng);
          INFO(fam << " n " << n << " parts " << P << " block " << block);
          const Distributed d = distributed(ps, P, block);
          CHECK(d.hull.cells == expect);
          for (const Part& p : d.parts) {
            const certify::Report r = dist::check(d.hull, p.mine, 2);
            INFO("part rows " << p.begin << ".." << p.end << ": " << r.message());
            CHECK(r.ok);
          }
        }
      }
}

TEST_CASE("distributed: blocks too small or flat for a hull are passed on whole", "[distributed]") {
  // 60 collinear points, then 60 coplanar ones, then a ball: blocks of 60
  gen::Options o;
  o.seed = 3;
  PointSet ps = gen::generate("ball", 500, o);
  std::vector<double> c;
  for (int i = 0; i < 60; ++i) c.insert(c.end(), {0.01 * i - 0.3, 0.02 * i - 0.6, 0.005 * i});
  for (int i = 0; i < 60; ++i) c.insert(c.end(), {0.1 * (i % 8) - 0.4, 0.1 * (i / 8) - 0.4, 0.0});
  c.insert(c.end(), ps.coords.begin(), ps.coords.end());
  ps.coords = Values(c);
  const std::vector<std::uint64_t> expect = single_machine(ps);
  for (std::uint64_t block : {std::uint64_t{1}, std::uint64_t{3}, std::uint64_t{60}}) {
    INFO("block " << block);
    const Distributed d = distributed(ps, 2, block);
    CHECK(d.hull.cells == expect);
    std::uint64_t whole = 0;
    for (const Part& p : d.parts) whole += p.stats.passed_whole;
    CHECK(whole >= (block == 60 ? 2u : ps.size() / block / 2));
    for (const Part& p : d.parts) CHECK(dist::check(d.hull, p.mine, 2).ok);
  }
}

TEST_CASE("distributed: a final hull that misses a point fails the check of the part that holds it",
          "[distributed]") {
  for (int dim : {2, 3}) {
    gen::Options o;
    o.seed = 11;
    const PointSet ps = gen::generate(dim == 2 ? "disk" : "ball", 3000, o);
    const int P = 4;
    const Distributed d = distributed(ps, P, 500);
    REQUIRE(d.hull.cells == single_machine(ps));
    // every third vertex, left out of the candidates in turn
    for (std::size_t k = 0; k < d.hull.vertices.size(); k += 3) {
      const std::uint64_t gone = d.hull.vertices.ids[k];
      dist::Candidates keep;
      keep.dim = dim;
      for (std::size_t i = 0; i < d.hull.vertices.size(); ++i)
        if (i != k) {
          keep.ids.push_back(d.hull.vertices.ids[i]);
          keep.coords.insert(keep.coords.end(), d.hull.vertices.point(i), d.hull.vertices.point(i) + dim);
        }
      const dist::FinalHull wrong = dist::final_hull(keep, ps.size(), 2);
      for (const Part& p : d.parts)
        if (gone >= p.begin && gone < p.end) {
          const certify::Report r = dist::check(wrong, p.mine, 2);
          INFO(dim << "D, row " << gone << " left out: " << r.message());
          CHECK_FALSE(r.ok);
        }
    }
  }
}

TEST_CASE("distributed: lower-dimensional input is refused with the single-machine line", "[distributed]") {
  int refused = 0;
  for (const char* fam : {"collinear2", "coplanar3", "collinear3"}) {
    gen::Options o;
    const PointSet ps = gen::generate(fam, 500, o);
    const std::string why = dimension_problem(ps);
    if (why.empty()) continue;  // (a family with points off the line or plane)
    INFO(fam << ": " << why);
    std::vector<dist::Candidates> parts;
    for (int r = 0; r < 3; ++r) parts.push_back(run_part(ps, 500u * r / 3, 500u * (r + 1) / 3, 50).mine);
    try {
      dist::final_hull(tree(parts), ps.size(), 2);
      FAIL("no refusal");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()) == why);
      ++refused;
    }
  }
  CHECK(refused >= 2);
}

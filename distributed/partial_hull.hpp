// partial_hull.hpp — the convex hull of a point set held in parts, without
// MPI (the MPI driver, mpi_main.cpp, moves these values between ranks; the
// tests run the same steps in one process).
//
// Why the parts' answer is the single-machine answer byte for byte
// (DESIGN.md "Beyond one machine"). Point g (its global row) is perturbed by
// ε^(2^(g·δ − j)) (Simulation of Simplicity). Every predicate is the sign of
// the lowest-order term of a determinant's expansion, each term a product of
// distinct perturbations, its order a sum of distinct powers 2^(g·δ − j);
// two such sums compare as their largest differing exponents, so a map of
// the indices that keeps their order (g → its rank among a subset's global
// rows) keeps every sign. A part's points, numbered 0.. in ascending global
// row, therefore have the SoS hull of those perturbed points, and the
// canonical output (DESIGN.md: rotated to the smallest index, sorted) maps
// back to global rows unchanged. The hull of a set is the hull of its parts'
// hull vertices (perturbed or not), so the merges keep only vertices and the
// final hull, computed on the last candidates, is the hull of all points.
//
// The certificate (thesis Thm 6.2, Lemma 6.1, as in certify_hull3.hpp) is
// split where the points lie:
//   1. every block of rows is certified with the kernel's own certifier at
//      the canonical level (cpu::certify_hull3_witnessed, cpu::certify_hull2):
//      its non-vertices lie strictly inside its perturbed hull, i.e. inside
//      the hull of its candidates (the block's hull vertices);
//   2. the final hull is certified, at the canonical level, as the hull of
//      its own vertices together with every block's candidates (check(): on
//      the rank that holds the block): the candidates lie inside it, or are
//      its vertices, and its surface is a convex SoS hull;
//   3. the final hull's vertices are input points: the rank that holds a
//      vertex's row compares its coordinates bit for bit (mpi_main.cpp).
// So every input point lies in the final hull, every vertex is an input
// point, and no non-vertex is extreme under the perturbation: the final hull
// is the canonical SoS hull of the whole input. A block with fewer than
// dim + 1 points or that does not span R^dim (its hull is not defined: the
// kernels refuse it) passes all its points on as candidates, which step 2
// then checks one by one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/certify/certify.hpp"

namespace flipflop::dist {

// A computed hull failed its certification (exit code 3, never written).
struct CertificationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Points with global rows, in ascending row order, rows distinct.
struct Candidates {
  int dim = 0;
  std::vector<std::uint64_t> ids;
  std::vector<double> coords;  // ids.size() * dim

  std::size_t size() const { return ids.size(); }
  const double* point(std::size_t i) const { return coords.data() + i * static_cast<std::size_t>(dim); }
};

// The union of two candidate sets (a row in both: kept once).
Candidates merge(const Candidates& a, const Candidates& b);
// Appends b to a; every row of b must be larger than a's last (blocks in order).
void append(Candidates& a, const Candidates& b);

struct BlockStats {
  std::uint64_t blocks = 0, points = 0;
  std::uint64_t passed_whole = 0;  // blocks too small or lower-dimensional: all points passed on
  double compute_s = 0, certify_s = 0;
};

// Step 1: the hull vertices of `count` rows of `dim` doubles at `rows`
// (C order; read in place, not copied), global rows first_row.., computed
// with kernels_cpu (dim 2: parallel Graham-sorting; 3: parallel ffHull, with
// its witness) on `threads` threads and certified at the canonical level.
// Throws CertificationError when the certifier rejects the kernel's hull.
Candidates block_candidates(int dim, const double* rows, std::uint64_t count, std::uint64_t first_row, int threads,
                            BlockStats* stats = nullptr);

// The vertices of the hull of c (a merge step), or c itself when its hull is
// not defined (fewer than dim + 1 points, lower-dimensional).
Candidates reduce(const Candidates& c, int threads);

// The final hull: its vertices and its cells in global rows — dim 2: the
// cycle, counter-clockwise from the smallest row; dim 3: the triangles, 3
// rows each, in the canonical order of `flipflop hull3`.
struct FinalHull {
  Candidates vertices;
  std::vector<std::uint64_t> cells;
};

// The final hull of the last candidates of an input of `total_rows` points;
// throws std::invalid_argument with dimension_problem's line (for
// total_rows points) when the input does not span R^dim.
FinalHull final_hull(const Candidates& c, std::uint64_t total_rows, int threads);

// Step 2 for one holder of candidates: the final hull certified (canonical
// level, kernels_cpu's parallel certifier) as the SoS hull of its vertices
// and `mine`. The report's detail names points by global row.
certify::Report check(const FinalHull& h, const Candidates& mine, int threads);

}  // namespace flipflop::dist

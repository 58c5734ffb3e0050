// partial_hull.cpp — see partial_hull.hpp.
#include "distributed/partial_hull.hpp"

#include <algorithm>
#include <chrono>
#include <regex>

#include "kernels_cpu/hull2/certify_hull2.hpp"
#include "kernels_cpu/hull2/hull2.hpp"
#include "kernels_cpu/hull3/certify_hull3.hpp"
#include "kernels_cpu/hull3/ffhull.hpp"
#include "reference/dimension.hpp"
#include "reference/point_set.hpp"

namespace flipflop::dist {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The points of c read in place, numbered 0.. in ascending row (the monotone
// map of partial_hull.hpp).
PointSet view(int dim, const double* rows, std::size_t count) {
  PointSet ps;
  ps.dim = dim;
  ps.coords = Values::borrow(rows, count * static_cast<std::size_t>(dim));
  return ps;
}

// The hull's vertices in ascending local index: dim 2 a cycle, dim 3
// triangles.
std::vector<Index> vertices_of(int dim, const std::vector<Index>& cycle, const std::vector<Triangle>& tris) {
  std::vector<Index> v = cycle;
  if (dim == 3)
    for (const Triangle& t : tris) v.insert(v.end(), t.begin(), t.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

Candidates pick(int dim, const double* rows, const std::vector<Index>& local, const std::uint64_t* ids,
                std::uint64_t first_row) {
  Candidates out;
  out.dim = dim;
  out.ids.reserve(local.size());
  out.coords.reserve(local.size() * static_cast<std::size_t>(dim));
  for (Index i : local) {
    out.ids.push_back(ids ? ids[i] : first_row + i);
    const double* x = rows + static_cast<std::size_t>(i) * static_cast<std::size_t>(dim);
    out.coords.insert(out.coords.end(), x, x + dim);
  }
  return out;
}

Candidates all_of(int dim, const double* rows, std::uint64_t count, std::uint64_t first_row) {
  Candidates out;
  out.dim = dim;
  out.ids.resize(static_cast<std::size_t>(count));
  for (std::uint64_t i = 0; i < count; ++i) out.ids[static_cast<std::size_t>(i)] = first_row + i;
  out.coords.assign(rows, rows + count * static_cast<std::uint64_t>(dim));
  return out;
}

// The hull of ps (the kernels of kernels_cpu) — false when it is not
// defined (too few points, lower-dimensional: the kernels' invalid_argument).
// witness: filled for dim 3 (the block's certifier uses it).
bool kernel_hull(const PointSet& ps, int threads, std::vector<Index>& cycle, std::vector<Triangle>& tris,
                 cpu::Hull3Witness* witness) {
  if (ps.size() < static_cast<std::size_t>(ps.dim) + 1) return false;
  try {
    if (ps.dim == 2) {
      cpu::Hull2Options o;
      o.threads = threads;
      cycle = cpu::hull2_graham_sort(ps, o);
    } else {
      cpu::Hull3Options o;
      o.threads = threads;
      o.witness = witness;
      tris = cpu::hull3_ffhull(ps, o);
    }
  } catch (const std::invalid_argument&) {
    if (dimension_problem(ps).empty()) throw;  // not the lower-dimensional refusal
    return false;
  }
  return true;
}

// "point 7", "vertex 7", "(3,7,9)", "(3,7)" of a certifier's detail in the
// check's local numbering -> global rows.
std::string global_detail(const std::string& detail, const std::vector<std::uint64_t>& ids) {
  auto row = [&](const std::string& s) {
    const unsigned long long i = std::stoull(s);
    return i < ids.size() ? std::to_string(ids[static_cast<std::size_t>(i)]) : s + "(?)";
  };
  std::string out;
  static const std::regex token(R"((point |vertex )(\d+)|\((\d+),(\d+)(,(\d+))?\))");
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(detail.begin(), detail.end(), token); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += detail.substr(last, static_cast<std::size_t>(m.position(0)) - last);
    if (m[1].matched) out += m[1].str() + row(m[2].str());
    else
      out += "(" + row(m[3].str()) + "," + row(m[4].str()) + (m[6].matched ? "," + row(m[6].str()) : "") + ")";
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  return out + detail.substr(last);
}

}  // namespace

Candidates merge(const Candidates& a, const Candidates& b) {
  Candidates out;
  out.dim = a.dim ? a.dim : b.dim;
  const auto d = static_cast<std::size_t>(out.dim);
  out.ids.reserve(a.size() + b.size());
  out.coords.reserve((a.size() + b.size()) * d);
  std::size_t i = 0, j = 0;
  auto take = [&](const Candidates& c, std::size_t k) {
    out.ids.push_back(c.ids[k]);
    out.coords.insert(out.coords.end(), c.point(k), c.point(k) + d);
  };
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a.ids[i] < b.ids[j])) take(a, i++);
    else if (i == a.size() || b.ids[j] < a.ids[i]) take(b, j++);
    else {
      take(a, i++);
      ++j;
    }
  }
  return out;
}

void append(Candidates& a, const Candidates& b) {
  if (a.dim == 0) a.dim = b.dim;
  if (!a.ids.empty() && !b.ids.empty() && b.ids.front() <= a.ids.back())
    throw std::logic_error("dist::append: blocks out of order");
  a.ids.insert(a.ids.end(), b.ids.begin(), b.ids.end());
  a.coords.insert(a.coords.end(), b.coords.begin(), b.coords.end());
}

Candidates block_candidates(int dim, const double* rows, std::uint64_t count, std::uint64_t first_row, int threads,
                            BlockStats* stats) {
  const PointSet ps = view(dim, rows, static_cast<std::size_t>(count));
  std::vector<Index> cycle;
  std::vector<Triangle> tris;
  cpu::Hull3Witness witness;
  const auto t0 = std::chrono::steady_clock::now();
  const bool hull = kernel_hull(ps, threads, cycle, tris, &witness);
  const double t_compute = seconds_since(t0);
  if (stats) {
    ++stats->blocks;
    stats->points += count;
    stats->compute_s += t_compute;
  }
  if (!hull) {
    if (stats) ++stats->passed_whole;
    return all_of(dim, rows, count, first_row);
  }
  const auto t1 = std::chrono::steady_clock::now();
  const certify::Report r =
      dim == 2 ? cpu::certify_hull2(ps, cycle, certify::Level::canonical, threads)
               : cpu::certify_hull3_witnessed(ps, tris, certify::Level::canonical, witness, threads);
  if (stats) stats->certify_s += seconds_since(t1);
  if (!r.ok) {
    std::vector<std::uint64_t> ids(static_cast<std::size_t>(count));
    for (std::uint64_t i = 0; i < count; ++i) ids[static_cast<std::size_t>(i)] = first_row + i;
    throw CertificationError("the hull of rows " + std::to_string(first_row) + ".." +
                             std::to_string(first_row + count - 1) + " failed certification: " + r.condition + ": " +
                             global_detail(r.detail, ids));
  }
  return pick(dim, rows, vertices_of(dim, cycle, tris), nullptr, first_row);
}

Candidates reduce(const Candidates& c, int threads) {
  const PointSet ps = view(c.dim, c.coords.data(), c.size());
  std::vector<Index> cycle;
  std::vector<Triangle> tris;
  if (!kernel_hull(ps, threads, cycle, tris, nullptr)) return c;
  return pick(c.dim, c.coords.data(), vertices_of(c.dim, cycle, tris), c.ids.data(), 0);
}

FinalHull final_hull(const Candidates& c, std::uint64_t total_rows, int threads) {
  const PointSet ps = view(c.dim, c.coords.data(), c.size());
  std::vector<Index> cycle;
  std::vector<Triangle> tris;
  if (!kernel_hull(ps, threads, cycle, tris, nullptr)) {
    // the candidates' hull is the input's (partial_hull.hpp), so is its
    // affine dimension
    const int d = c.size() == 0 ? 0 : affine_dimension(ps);
    throw std::invalid_argument(dimension_problem(static_cast<std::size_t>(total_rows), c.dim,
                                                  total_rows < static_cast<std::uint64_t>(c.dim) + 1 ? 0 : d));
  }
  FinalHull h;
  const std::vector<Index> v = vertices_of(c.dim, cycle, tris);
  h.vertices = pick(c.dim, c.coords.data(), v, c.ids.data(), 0);
  if (c.dim == 2)
    for (Index i : cycle) h.cells.push_back(c.ids[i]);
  else
    for (const Triangle& t : tris)
      for (Index i : t) h.cells.push_back(c.ids[i]);
  return h;
}

certify::Report check(const FinalHull& h, const Candidates& mine, int threads) {
  const Candidates all = merge(h.vertices, mine);
  const PointSet ps = view(all.dim, all.coords.data(), all.size());
  auto local = [&](std::uint64_t g) {
    return static_cast<Index>(std::lower_bound(all.ids.begin(), all.ids.end(), g) - all.ids.begin());
  };
  certify::Report r;
  if (all.dim == 2) {
    std::vector<Index> cycle;
    for (std::uint64_t g : h.cells) cycle.push_back(local(g));
    r = cpu::certify_hull2(ps, cycle, certify::Level::canonical, threads);
  } else {
    std::vector<Triangle> tris;
    for (std::size_t k = 0; k + 2 < h.cells.size(); k += 3)
      tris.push_back({local(h.cells[k]), local(h.cells[k + 1]), local(h.cells[k + 2])});
    r = cpu::certify_hull3(ps, tris, certify::Level::canonical, threads);
  }
  if (!r.ok) r.detail = global_detail(r.detail, all.ids);
  return r;
}

}  // namespace flipflop::dist

// optimal_transport_2d.cpp — semi-discrete optimal transport in the plane with
// the regular triangulation updated by flipflop's instant flip (issue 16).
//
// The problem (Aurenhammer, Hoffmann & Aronov 1998; Mérigot 2011; Kitagawa,
// Mérigot & Thibert 2019, "KMT" below): transport the uniform density μ on
// the unit square Ω = [0,1]² to the discrete measure ν = Σ_i ν_i δ_{y_i},
// ν_i = 1/n, at quadratic cost. The optimal map sends the Laguerre (power)
// cell
//
//   Lag_i(ψ) = { x ∈ Ω : |x - y_i|² - ψ_i <= |x - y_j|² - ψ_j  for all j }
//
// to y_i, for the weights ψ that solve G(ψ) = 0 with G_i(ψ) = μ(Lag_i(ψ)) - ν_i.
// The Laguerre cells are the power diagram of the weighted points (y_i, ψ_i)
// clipped to Ω, the dual of the regular triangulation RT(Y ⊕ ψ) (flipflop's
// power distance |x - p|² - w, predicates.hpp): the cell of a vertex i is Ω
// cut by the half-planes of its neighbours in RT(Y ⊕ ψ), and a redundant
// point has an empty cell.
//
// The solver is KMT's damped Newton method. DG(ψ) is the weighted graph
// Laplacian of the cells' adjacency: ∂G_i/∂ψ_j = -|Lag_i ∩ Lag_j| / (2 |y_i - y_j|)
// for i != j (the length of the common edge; raising ψ_j moves that edge
// towards y_i by dψ_j / (2 |y_i - y_j|)), and ∂G_i/∂ψ_i = -Σ_{j≠i} ∂G_i/∂ψ_j. A
// step solves DG δ = -G (ψ_0 pinned: DG's kernel is the constants; sparse
// LDLᵀ, Eigen) and takes ψ + τδ with the largest τ in {1, 1/2, 1/4, ...} that
// keeps every cell at least ε = ½ min(min_i μ(Lag_i(ψ⁰)), min_i ν_i) and
// reduces |G| by the factor (1 - τ/2) (KMT, Algorithm 1: linear, then
// quadratic convergence).
//
// Every trial weight vector updates ONE regular triangulation in place by
// DynamicRegularTriangulation::set_weights (the monotonic instant flip with
// insertion events, reference/rtd/dynamic_rt.hpp) — the steps move ψ in any
// direction and points enter and leave the triangulation. After every update
// the triangulation is certified (certify::rtd, the exact certifier) and
// compared with a fresh CGAL Regular_triangulation_2 of the same weighted
// points, whose build time is the reference the update is measured against.
// The run fails (exit 1) if a certificate or the comparison fails, and exits 3
// if it does not converge within --max-steps.
//
// Floating point is used only for the transport quantities (cell areas, edge
// lengths, the Newton system); every combinatorial decision — which triangles,
// which points are redundant — is the exact, certified regular triangulation.
//
// Usage: optimal_transport_2d [--n N] [--seed S] [--tol T] [--max-steps K] [--svg FILE]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/SparseCholesky>

#include "peers/peers.hpp"
#include "reference/point_set.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/dynamic_rt.hpp"

namespace {

using flipflop::Index;
using flipflop::PointSet;
using Vec2 = std::array<double, 2>;
using Triangles = std::vector<std::array<Index, 3>>;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ---- Laguerre cells clipped to the unit square ---------------------------------

// A convex polygon with, for each edge (v[k], v[k+1]), the index of the point
// whose half-plane made it (-1: a side of the square).
struct Cell {
  std::vector<Vec2> v;
  std::vector<int> label;
};

// Cuts `c` by the half-plane a·x <= b made by point j (Sutherland–Hodgman,
// keeping the labels: the edge along the cutting line gets label j).
Cell clip(const Cell& c, Vec2 a, double b, int j) {
  Cell out;
  const std::size_t m = c.v.size();
  auto side = [&](const Vec2& p) { return a[0] * p[0] + a[1] * p[1] - b; };
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2& p = c.v[k];
    const Vec2& q = c.v[(k + 1) % m];
    const double sp = side(p), sq = side(q);
    auto cut = [&] {
      const double t = sp / (sp - sq);
      return Vec2{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
    };
    if (sp <= 0) {
      out.v.push_back(p);
      if (sq <= 0) {
        out.label.push_back(c.label[k]);
      } else {  // leaves the half-plane: p..cut on the old edge, then along the line
        out.label.push_back(c.label[k]);
        out.v.push_back(cut());
        out.label.push_back(j);
      }
    } else if (sq <= 0) {  // enters: cut..q on the old edge
      out.v.push_back(cut());
      out.label.push_back(c.label[k]);
    }
  }
  return out;
}

struct Cells {
  std::vector<Cell> cell;                                    // per point (empty: redundant)
  std::vector<double> area;                                  // μ(Lag_i)
  std::vector<std::vector<std::pair<Index, double>>> edge;   // (j, |Lag_i ∩ Lag_j|)
};

Cells laguerre_cells(const PointSet& y, const std::vector<double>& psi, const Triangles& tris) {
  const std::size_t n = y.size();
  std::vector<std::vector<Index>> nb(n);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      nb[t[k]].push_back(t[(k + 1) % 3]);
      nb[t[k]].push_back(t[(k + 2) % 3]);
    }
  Cells C;
  C.cell.resize(n);
  C.area.assign(n, 0.0);
  C.edge.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (nb[i].empty()) continue;  // not a vertex: redundant, empty cell
    std::sort(nb[i].begin(), nb[i].end());
    nb[i].erase(std::unique(nb[i].begin(), nb[i].end()), nb[i].end());
    Cell c{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {-1, -1, -1, -1}};
    const double* yi = y.point(i);
    for (Index j : nb[i]) {
      const double* yj = y.point(j);
      // |x - y_i|² - ψ_i <= |x - y_j|² - ψ_j  <=>  2 x·(y_j - y_i) <= |y_j|² - |y_i|² - ψ_j + ψ_i
      const Vec2 a{2 * (yj[0] - yi[0]), 2 * (yj[1] - yi[1])};
      const double b = yj[0] * yj[0] + yj[1] * yj[1] - yi[0] * yi[0] - yi[1] * yi[1] - psi[j] + psi[i];
      c = clip(c, a, b, static_cast<int>(j));
      if (c.v.empty()) break;
    }
    double area = 0;
    std::map<Index, double> len;
    for (std::size_t k = 0; k < c.v.size(); ++k) {
      const Vec2& p = c.v[k];
      const Vec2& q = c.v[(k + 1) % c.v.size()];
      area += p[0] * q[1] - p[1] * q[0];
      if (c.label[k] >= 0) len[static_cast<Index>(c.label[k])] += std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    C.area[i] = 0.5 * area;
    for (const auto& [j, l] : len)
      if (l > 0) C.edge[i].push_back({j, l});
    C.cell[i] = std::move(c);
  }
  return C;
}

double norm2(const std::vector<double>& g) {
  double s = 0;
  for (double x : g) s += x * x;
  return std::sqrt(s);
}

// ---- one triangulation update, certified and compared with CGAL ----------------

struct UpdateLog {
  double update_s = 0, certify_s = 0, cgal_s = 0;
  std::uint64_t flips = 0, inserted = 0, removed = 0, rebuilt = 0;
};

Triangles triangles_of(const std::vector<std::vector<Index>>& s) {
  Triangles t;
  t.reserve(s.size());
  for (const auto& x : s) t.push_back({x[0], x[1], x[2]});
  return t;
}

// Moves `rt` to the weights psi; certifies it and compares it with CGAL. An
// empty string on success, the failure otherwise.
std::string update(flipflop::ref::DynamicRegularTriangulation& rt, const std::vector<double>& psi, UpdateLog& log,
                   Triangles& out) {
  auto t0 = std::chrono::steady_clock::now();
  const flipflop::ref::WeightUpdateStats st = rt.set_weights(psi);
  log.update_s += seconds_since(t0);
  log.flips += st.total_flips();
  log.inserted += st.flips(1);
  log.removed += st.instant.removed_vertices + st.repair_removed;
  log.rebuilt += st.rebuilt ? 1 : 0;
  const std::vector<std::vector<Index>> simplices = rt.simplices();
  t0 = std::chrono::steady_clock::now();
  const flipflop::certify::Report rep = flipflop::certify::rtd(rt.points(), simplices);
  log.certify_s += seconds_since(t0);
  if (!rep.ok) return "the updated triangulation is not certified: " + rep.message();
  double cgal_build = 0;
  std::vector<flipflop::Triangle> cgal = flipflop::peers::cgal_regular2(rt.points(), &cgal_build);
  log.cgal_s += cgal_build;
  out = triangles_of(simplices);
  // compare as sets of vertex triples (CGAL's triangles in flipflop's canonical form)
  auto key = [](Triangles t) {
    for (auto& x : t) std::sort(x.begin(), x.end());
    std::sort(t.begin(), t.end());
    return t;
  };
  Triangles theirs(cgal.begin(), cgal.end());
  if (key(out) != key(theirs))
    return "the updated triangulation (" + std::to_string(out.size()) + " triangles) differs from CGAL's fresh " +
           "Regular_triangulation_2 (" + std::to_string(theirs.size()) + " triangles)";
  return {};
}

void write_svg(const std::string& path, const PointSet& y, const Cells& C) {
  std::ofstream f(path);
  const double s = 800;
  f << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << s << "\" height=\"" << s << "\" viewBox=\"0 0 " << s
    << ' ' << s << "\">\n<rect width=\"" << s << "\" height=\"" << s << "\" fill=\"white\"/>\n";
  for (const Cell& c : C.cell) {
    if (c.v.empty()) continue;
    f << "<polygon fill=\"#dde8f6\" stroke=\"#335\" stroke-width=\"0.6\" points=\"";
    for (const Vec2& p : c.v) f << p[0] * s << ',' << (1 - p[1]) * s << ' ';
    f << "\"/>\n";
  }
  for (std::size_t i = 0; i < y.size(); ++i)
    f << "<circle cx=\"" << y.point(i)[0] * s << "\" cy=\"" << (1 - y.point(i)[1]) * s << "\" r=\"1.5\" fill=\""
      << (C.cell[i].v.empty() ? "#c00" : "#000") << "\"/>\n";
  f << "</svg>\n";
  if (!f) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000;
  unsigned seed = 1;
  double tol = 1e-6;
  int max_steps = 50;
  std::string svg;
  CLI::App app{"Semi-discrete optimal transport from the uniform density on the unit square to n random points: "
               "damped Newton on the weights, the regular triangulation updated by flipflop's instant flip"};
  app.add_option("--n", n, "number of target points (uniform in the unit square)")->check(CLI::Range(3, 1000000));
  app.add_option("--seed", seed, "random seed of the points");
  app.add_option("--tol", tol, "stop when every cell's mass is within tol/n of 1/n")->check(CLI::PositiveNumber);
  app.add_option("--max-steps", max_steps, "Newton steps at most")->check(CLI::Range(1, 10000));
  app.add_option("--svg", svg, "write the final power diagram (Laguerre cells) to this SVG file");
  CLI11_PARSE(app, argc, argv);

  try {
    PointSet y;
    y.dim = 2;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (std::size_t i = 0; i < 2 * n; ++i) y.coords.push_back(U(rng));
    const double nu = 1.0 / static_cast<double>(n);

    std::vector<double> psi(n, 0.0);  // ψ = 0: the Voronoi diagram
    auto t0 = std::chrono::steady_clock::now();
    flipflop::ref::DynamicRegularTriangulation rt(y, psi);
    const double build_s = seconds_since(t0);
    Triangles tris = triangles_of(rt.simplices());
    Cells C = laguerre_cells(y, psi, tris);
    auto residual = [&](const Cells& c) {
      std::vector<double> g(n);
      for (std::size_t i = 0; i < n; ++i) g[i] = c.area[i] - nu;
      return g;
    };
    std::vector<double> G = residual(C);
    const double eps = 0.5 * std::min(*std::min_element(C.area.begin(), C.area.end()), nu);
    if (!(eps > 0)) throw std::runtime_error("a Voronoi cell of the start has no area (points not in general position)");
    std::printf("optimal_transport_2d: n = %zu, seed %u; RT(Y + 0) built in %.3f s (RT+1); KMT eps = %.3g\n", n, seed,
                build_s, eps);
    std::printf("%4s %12s %8s %6s %8s %6s %6s %11s %11s %11s %8s\n", "step", "max|G|/nu", "tau", "tries", "flips",
                "ins", "rem", "update_ms", "certify_ms", "cgal_ms", "cgal/upd");

    UpdateLog total;
    int step = 0;
    auto maxabs = [](const std::vector<double>& g) {
      double m = 0;
      for (double x : g) m = std::max(m, std::fabs(x));
      return m;
    };
    while (maxabs(G) > tol * nu) {
      if (step == max_steps) {
        std::printf("optimal_transport_2d: not converged after %d steps (max |G|/nu = %.3g > %.3g)\n", step,
                    maxabs(G) / nu, tol);
        return 3;
      }
      ++step;
      // DG δ = -G with δ_0 = 0 (rows and columns 1..n-1)
      std::vector<Eigen::Triplet<double>> trip;
      for (std::size_t i = 1; i < n; ++i) {
        double diag = 0;
        for (const auto& [j, len] : C.edge[i]) {
          const double* yi = y.point(i);
          const double* yj = y.point(j);
          const double c = len / (2 * std::hypot(yi[0] - yj[0], yi[1] - yj[1]));
          diag += c;
          if (j != 0) trip.emplace_back(static_cast<int>(i - 1), static_cast<int>(j - 1), -c);
        }
        trip.emplace_back(static_cast<int>(i - 1), static_cast<int>(i - 1), diag);
      }
      Eigen::SparseMatrix<double> H(static_cast<int>(n - 1), static_cast<int>(n - 1));
      H.setFromTriplets(trip.begin(), trip.end());
      Eigen::VectorXd rhs(static_cast<int>(n - 1));
      for (std::size_t i = 1; i < n; ++i) rhs[static_cast<int>(i - 1)] = -G[i];
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(H);
      if (solver.info() != Eigen::Success) throw std::runtime_error("the Newton system could not be factored");
      const Eigen::VectorXd delta = solver.solve(rhs);

      UpdateLog log;
      const double g0 = norm2(G);
      double tau = 1;
      int tries = 0;
      for (;; tau /= 2) {
        ++tries;
        if (tau < 1e-12) throw std::runtime_error("the damped Newton step found no admissible step length");
        std::vector<double> trial = psi;
        for (std::size_t i = 1; i < n; ++i) trial[i] += tau * delta[static_cast<int>(i - 1)];
        Triangles trial_tris;
        const std::string problem = update(rt, trial, log, trial_tris);
        if (!problem.empty()) {
          std::printf("optimal_transport_2d: step %d: %s\n", step, problem.c_str());
          return 1;
        }
        Cells trial_cells = laguerre_cells(y, trial, trial_tris);
        const std::vector<double> trial_g = residual(trial_cells);
        if (*std::min_element(trial_cells.area.begin(), trial_cells.area.end()) >= eps &&
            norm2(trial_g) <= (1 - tau / 2) * g0) {
          psi = std::move(trial);
          C = std::move(trial_cells);
          G = trial_g;
          break;
        }
      }
      std::printf("%4d %12.3e %8.4f %6d %8llu %6llu %6llu %11.3f %11.3f %11.3f %8.2f%s\n", step, maxabs(G) / nu, tau,
                  tries, static_cast<unsigned long long>(log.flips), static_cast<unsigned long long>(log.inserted),
                  static_cast<unsigned long long>(log.removed), 1e3 * log.update_s, 1e3 * log.certify_s,
                  1e3 * log.cgal_s, log.cgal_s / log.update_s, log.rebuilt ? "  (rebuilt by RT+1)" : "");
      total.update_s += log.update_s;
      total.certify_s += log.certify_s;
      total.cgal_s += log.cgal_s;
      total.flips += log.flips;
      total.rebuilt += log.rebuilt;
    }
    std::size_t empty = 0;
    for (const Cell& c : C.cell) empty += c.v.empty() ? 1 : 0;
    std::printf(
        "optimal_transport_2d: converged in %d steps (max |G|/nu = %.3g <= %.3g); every update certified and equal to "
        "CGAL's fresh Regular_triangulation_2; %llu flips in all, %zu empty cells at the end\n",
        step, maxabs(G) / nu, tol, static_cast<unsigned long long>(total.flips), empty);
    std::printf("optimal_transport_2d: updates %.3f s (instant flip), fresh CGAL builds %.3f s: %.2fx; certification %.3f s%s\n",
                total.update_s, total.cgal_s, total.update_s > 0 ? total.cgal_s / total.update_s : 0.0,
                total.certify_s, total.rebuilt ? " (some updates were rebuilt by RT+1, see the steps)" : "");
    if (!svg.empty()) {
      write_svg(svg, y, C);
      std::printf("optimal_transport_2d: wrote %s\n", svg.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "optimal_transport_2d: %s\n", e.what());
    return 1;
  }
  return 0;
}

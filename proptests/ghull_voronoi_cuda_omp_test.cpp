// ghull_voronoi_cuda_omp_test.cpp — gHull's Stage 1 and the dual of Stage 2
// (kernels_cuda/hull3/digital_voronoi.cuh) in the thrust/OpenMP build,
// through ghull.hpp's test entries (kernels_omp::ghull_stages), against brute
// forces written here from ghull.hpp's definitions:
//   projection      every pixel's site is the point of least height over the
//                   face among those in the pixel, ties to the smaller index;
//   digital Voronoi every pixel's label is a site of its face at the least
//                   exact integer distance (site_distance) over all the
//                   face's sites; site_distance is the documented formula;
//   working sets    pixels grouped by their corners' 3D integer coordinates
//                   (so the box's edges and corners are found by geometry,
//                   not by the kernel's vertex-to-pixel rule), the pairs of
//                   each vertex with 3 or 4 distinct labels, as CSR;
// the same answers at 1 and 16 OpenMP threads; a planted wrong label caught.
// Inputs: grids 1..64, 1..200 points, coordinates drawn to collide — points
// repeated, sharing pixels, columns, rows and heights, on pixel boundaries,
// clustered — and random labellings (many labels meeting on the box's edges
// and corners) for the working sets. Fixed seeds; a few seconds in all.
#include <catch2/catch.hpp>

#ifdef FLIPFLOP_HAVE_KERNELS_OMP

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "kernels_cuda/hull3/ghull.hpp"
#include "proptests/support/omp_threads.hpp"

using namespace flipflop;
namespace st = flipflop::kernels_omp::ghull_stages;

namespace {

constexpr std::uint32_t kNone = ~std::uint32_t{0};

// "" when a == b, else where they first differ (Catch2 would print whole
// vectors of up to 10^5 entries, slowly).
template <class T>
std::string diff(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return "at " + std::to_string(i) + ": " + std::to_string(a[i]) + " and " + std::to_string(b[i]);
  return "";
}

// ---- ghull.hpp's definitions, written out again ----------------------------------------
struct Seen {
  std::uint32_t u, v;  // pixel on the face
  double h;            // height over it
};
Seen seen_from(const std::vector<double>& s, std::uint32_t G, std::uint32_t face, std::uint32_t p) {
  static const int other[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  const int axis = static_cast<int>(face / 2);
  const double* P = &s[3 * std::size_t{p}];
  auto px = [&](double c) {
    const double f = std::floor(c);
    return static_cast<std::uint32_t>(std::min<double>(std::max<double>(f, 0), G - 1));
  };
  const double h = face % 2 ? G - P[axis] : P[axis];
  return {px(P[other[axis][0]]), px(P[other[axis][1]]), h};
}

std::vector<std::uint32_t> brute_sites(const std::vector<double>& s, std::uint32_t G) {
  const std::uint32_t n = static_cast<std::uint32_t>(s.size() / 3);
  std::vector<std::uint32_t> sites(6 * std::size_t{G} * G, kNone);
  std::vector<double> best(sites.size(), std::numeric_limits<double>::infinity());
  for (std::uint32_t p = 0; p < n; ++p)
    for (std::uint32_t f = 0; f < 6; ++f) {
      const Seen q = seen_from(s, G, f, p);
      const std::size_t i = f * std::size_t{G} * G + q.v * std::size_t{G} + q.u;
      if (q.h < best[i]) best[i] = q.h, sites[i] = p;  // p ascending: an equal h keeps the smaller index
    }
  return sites;
}

// D = ((i - u)^2 + (j - v)^2) 2^16 + round(h^2 2^16) (digital_voronoi.cuh, Q = 16)
std::int64_t brute_distance(const std::vector<double>& s, std::uint32_t G, std::uint32_t f, std::uint32_t i,
                            std::uint32_t j, std::uint32_t p) {
  const Seen q = seen_from(s, G, f, p);
  const std::int64_t du = std::int64_t{i} - q.u, dv = std::int64_t{j} - q.v;
  return (du * du + dv * dv) * 65536 + std::llround(q.h * q.h * 65536.0);
}

// "" when labels is a nearest-site labelling of `sites` (site_distance's
// units), else what is wrong.
std::string voronoi_error(const std::vector<double>& s, std::uint32_t G, const std::vector<std::uint32_t>& sites,
                          const std::vector<std::uint32_t>& labels) {
  const std::size_t GG = std::size_t{G} * G;
  for (std::uint32_t f = 0; f < 6; ++f) {
    std::set<std::uint32_t> on_face;
    for (std::size_t q = 0; q < GG; ++q)
      if (sites[f * GG + q] != kNone) on_face.insert(sites[f * GG + q]);
    for (std::uint32_t q = 0; q < GG; ++q) {
      const std::uint32_t l = labels[f * GG + q];
      const std::string where = "face " + std::to_string(f) + " pixel " + std::to_string(q);
      if (on_face.empty()) {
        if (l != kNone) return where + ": a label on a face without sites";
        continue;
      }
      if (!on_face.count(l)) return where + ": label " + std::to_string(l) + " is not a site of the face";
      std::int64_t best = std::numeric_limits<std::int64_t>::max();
      for (std::uint32_t p : on_face) best = std::min(best, st::site_distance(s, G, f, q, p));
      const std::int64_t got = st::site_distance(s, G, f, q, l);
      if (got != best)
        return where + ": label " + std::to_string(l) + " at " + std::to_string(got) + ", nearest at " +
               std::to_string(best);
    }
  }
  return "";
}

// The labels by the definition (ghull.hpp): per pixel the site of least
// site_distance over all the face's sites; of several, the one whose pixel
// (u, v) is least, u first.
std::vector<std::uint32_t> brute_labels(const std::vector<double>& s, std::uint32_t G,
                                        const std::vector<std::uint32_t>& sites) {
  const std::size_t GG = std::size_t{G} * G;
  std::vector<std::uint32_t> labels(6 * GG, kNone);
  for (std::uint32_t f = 0; f < 6; ++f) {
    struct Site {
      std::int64_t u, v, hq;  // its pixel, its squared height in D's units
      std::uint32_t p;
    };
    std::vector<Site> on_face;
    for (std::size_t q = 0; q < GG; ++q)
      if (const std::uint32_t p = sites[f * GG + q]; p != kNone) {
        const Seen at = seen_from(s, G, f, p);
        on_face.push_back({at.u, at.v, std::llround(at.h * at.h * 65536.0), p});
      }
    for (std::uint32_t q = 0; q < GG; ++q) {
      const std::int64_t i = q % G, j = q / G;
      std::int64_t best = std::numeric_limits<std::int64_t>::max(), bu = 0, bv = 0;
      std::uint32_t l = kNone;
      for (const Site& t : on_face) {
        const std::int64_t d = ((i - t.u) * (i - t.u) + (j - t.v) * (j - t.v)) * 65536 + t.hq;  // brute_distance
        if (d < best || (d == best && (t.u < bu || (t.u == bu && t.v < bv)))) best = d, bu = t.u, bv = t.v, l = t.p;
      }
      labels[f * GG + q] = l;
    }
  }
  return labels;
}

// The working sets by geometry: each pixel's four corners in 3D (integer
// points of B's surface); the pixels sharing a corner are that vertex's.
void brute_working_sets(const std::vector<std::uint32_t>& labels, std::uint32_t G, std::uint32_t n,
                        std::vector<std::uint32_t>& off, std::vector<std::uint32_t>& nbr,
                        std::map<std::size_t, std::size_t>* pixels_per_vertex = nullptr) {
  static const int other[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  std::map<std::array<std::uint32_t, 3>, std::vector<std::uint32_t>> at;  // vertex -> labels of its pixels
  for (std::uint32_t f = 0; f < 6; ++f)
    for (std::uint32_t v = 0; v < G; ++v)
      for (std::uint32_t u = 0; u < G; ++u)
        for (std::uint32_t du = 0; du < 2; ++du)
          for (std::uint32_t dv = 0; dv < 2; ++dv) {
            std::array<std::uint32_t, 3> x;
            x[f / 2] = f % 2 ? G : 0;
            x[other[f / 2][0]] = u + du;
            x[other[f / 2][1]] = v + dv;
            at[x].push_back(labels[(f * std::size_t{G} + v) * G + u]);
          }
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [x, ls] : at) {
    if (pixels_per_vertex) ++(*pixels_per_vertex)[ls.size()];
    std::set<std::uint32_t> d(ls.begin(), ls.end());
    d.erase(kNone);
    if (d.size() < 3) continue;
    for (std::uint32_t a : d)
      for (std::uint32_t b : d)
        if (a != b) pairs.insert({a, b});
  }
  off.assign(n + 1, 0);
  nbr.clear();
  for (const auto& [a, b] : pairs) ++off[a + 1], nbr.push_back(b);
  for (std::uint32_t p = 0; p < n; ++p) off[p + 1] += off[p];
}

// ---- inputs ----------------------------------------------------------------------------------
struct Case {
  std::uint32_t G;
  std::vector<double> s;
};

// n points in (0, G)^3 drawn to collide: each coordinate from one of a few
// modes (uniform; a handful of shared values; integers, i.e. pixel
// boundaries; a cluster), some points copies of earlier ones, some sharing a
// column (two coordinates) with an earlier one.
Case make_case(std::mt19937_64& rng, std::uint32_t gmin, std::uint32_t gmax, std::uint32_t nmax) {
  Case c;
  c.G = std::uniform_int_distribution<std::uint32_t>(gmin, gmax)(rng);
  const double G = c.G;
  const std::uint32_t n = std::uniform_int_distribution<std::uint32_t>(1, nmax)(rng);
  std::uniform_real_distribution<double> unit(0, 1);
  auto inside = [&](double x) { return std::min(std::max(x, G * 1e-9), G * (1 - 1e-9)); };
  std::vector<double> shared;  // a few values many points take
  for (int k = 0; k < 4; ++k) shared.push_back(inside(G * unit(rng)));
  const double cx = G * unit(rng), cy = G * unit(rng), cz = G * unit(rng), r = 0.5 + 2 * unit(rng);
  const int mode = static_cast<int>(rng() % 4);  // the case's leaning
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::size_t have = c.s.size() / 3;
    const std::uint64_t roll = rng() % 100;
    if (have > 0 && roll < 10) {  // a copy
      const std::size_t q = rng() % have;
      for (int k = 0; k < 3; ++k) c.s.push_back(c.s[3 * q + k]);
      continue;
    }
    if (have > 0 && roll < 25) {  // the same column along a random axis
      const std::size_t q = rng() % have;
      const int axis = static_cast<int>(rng() % 3);
      for (int k = 0; k < 3; ++k) c.s.push_back(k == axis ? inside(G * unit(rng)) : c.s[3 * q + k]);
      continue;
    }
    const double centre[3] = {cx, cy, cz};
    for (int k = 0; k < 3; ++k) {
      const int m = mode == 0 ? static_cast<int>(rng() % 4) : (rng() % 3 == 0 ? static_cast<int>(rng() % 4) : mode);
      double x;
      switch (m) {
        case 1: x = shared[rng() % shared.size()]; break;
        case 2: x = c.G > 1 ? static_cast<double>(1 + rng() % (c.G - 1)) : 0.5; break;  // a pixel boundary
        case 3: x = inside(centre[k] + r * (2 * unit(rng) - 1)); break;
        default: x = inside(G * unit(rng)); break;
      }
      c.s.push_back(x);
    }
  }
  return c;
}

std::string describe(const Case& c) {
  std::string t = "G = " + std::to_string(c.G) + ", " + std::to_string(c.s.size() / 3) + " points:";
  for (std::size_t i = 0; i < c.s.size() && i < 3 * 40; ++i) t += (i % 3 ? " " : "\n  ") + std::to_string(c.s[i]);
  return t;
}

}  // namespace

TEST_CASE("ghull stage 1: projection keeps the point nearest each face, ties to the smaller index",
          "[ghull][cuda-omp]") {
  std::mt19937_64 rng(71);
  for (int k = 0; k < 400; ++k) {
    const Case c = make_case(rng, 1, 32, 200);
    INFO("case " << k << ": " << describe(c));
    std::vector<std::uint32_t> sites;
    st::digital_voronoi(c.s, c.G, &sites);
    REQUIRE(diff(sites, brute_sites(c.s, c.G)) == "");
  }
}

TEST_CASE("ghull stage 1: site_distance is the documented integer distance", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(72);
  for (int k = 0; k < 200; ++k) {
    const Case c = make_case(rng, 1, 2048, 20);
    const std::uint32_t n = static_cast<std::uint32_t>(c.s.size() / 3);
    INFO("case " << k << ": " << describe(c));
    for (int t = 0; t < 50; ++t) {
      const std::uint32_t f = static_cast<std::uint32_t>(rng() % 6), p = static_cast<std::uint32_t>(rng() % n);
      const std::uint32_t i = static_cast<std::uint32_t>(rng() % c.G), j = static_cast<std::uint32_t>(rng() % c.G);
      const std::uint32_t q = j * c.G + i;
      const std::int64_t d = brute_distance(c.s, c.G, f, i, j, p);
      REQUIRE(st::site_distance(c.s, c.G, f, q, p) == d);
      REQUIRE(st::site_distance(c.s, c.G, f, f * c.G * c.G + q, p) == d);  // a whole index, modulo G^2
    }
  }
  // the extreme of the bound (digital_voronoi.cuh): G = 2048, a pixel at the
  // far corner of face x = 0 from the site, h near G
  const std::vector<double> far = {2047.999, 0.001, 2047.999};  // on face 0: pixel (0, 2047)
  const std::int64_t most = 2 * 2047ll * 2047 * 65536 + std::llround(2047.999 * 2047.999 * 65536.0);
  REQUIRE(st::site_distance(far, 2048, 0, 2047, 0) == most);  // pixel (2047, 0)
  REQUIRE(brute_distance(far, 2048, 0, 2047, 0, 0) == most);
}

TEST_CASE("ghull stage 1: digital Voronoi labels are nearest sites (exact, brute force)", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(73);
  for (int k = 0; k < 600; ++k) {
    const Case c = k < 300   ? make_case(rng, 1, 16, 60)
                   : k < 560 ? make_case(rng, 8, 40, 200)
                             : make_case(rng, 40, 64, 200);
    INFO("case " << k << ": " << describe(c));
    std::vector<std::uint32_t> sites;
    const std::vector<std::uint32_t> labels = st::digital_voronoi(c.s, c.G, &sites);
    REQUIRE(labels.size() == 6 * std::size_t{c.G} * c.G);
    REQUIRE(voronoi_error(c.s, c.G, sites, labels) == "");
    REQUIRE(diff(labels, brute_labels(c.s, c.G, sites)) == "");  // the tie rule too
  }
}

// PBA's bands (digital_voronoi.cuh): every band count, dividing G or not,
// one band, one pixel a band and more bands than pixels, gives the labels of
// the definition, ties included. The ramps put the sites of a row or column
// at heights rising (falling) with the position, so that the parabola least
// at a band's first pixel lies bands before (after) it: the colouring's walk
// back (forward) over other bands' survivors, and merges that empty whole
// bands.
TEST_CASE("ghull stage 1: PBA's bands give the definition's labels at any band count", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(76);
  for (int k = 0; k < 160; ++k) {
    Case c;
    if (k % 2 == 0) {
      c = make_case(rng, 1, 48, 150);
    } else {  // ramps on face z = 0 (rows) or on face x = 0 (columns: the same pattern along y)
      c.G = std::uniform_int_distribution<std::uint32_t>(2, 64)(rng);
      const double G = c.G;
      const double slope = std::vector<double>{0.25, 0.5, 1, 2, 3}[rng() % 5];
      const bool rising = rng() % 2, columns = rng() % 2;
      const std::uint32_t lines = 1 + static_cast<std::uint32_t>(rng() % 4);
      for (std::uint32_t l = 0; l < lines; ++l) {
        const double w = static_cast<double>(rng() % c.G) + 0.5;
        for (std::uint32_t a = 0; a < c.G; ++a) {
          if (rng() % 8 == 0) continue;  // a few positions without a site
          const double t = rising ? a : c.G - 1 - a;
          const double h = std::min(G - 0.25, 0.25 + slope * t + 0.01 * static_cast<double>(rng() % 3));
          if (columns)
            c.s.insert(c.s.end(), {h, w, a + 0.5});  // face 0 (x = 0): u along y, v along z
          else
            c.s.insert(c.s.end(), {a + 0.5, w, h});  // face 4 (z = 0): u along x, v along y
        }
      }
      if (c.s.empty()) c.s = {0.5, 0.5, 0.5};
    }
    INFO("case " << k << ": " << describe(c));
    std::vector<std::uint32_t> sites;
    const std::vector<std::uint32_t> first = st::digital_voronoi(c.s, c.G, &sites, 1);
    const std::vector<std::uint32_t> want = brute_labels(c.s, c.G, sites);
    REQUIRE(diff(first, want) == "");
    for (std::uint32_t m : {2u, 3u, 4u, 5u, 7u, 8u, 13u, 32u, c.G / 2 + 1, c.G, 2 * c.G + 1, 0u}) {
      INFO("bands " << m);
      REQUIRE(diff(st::digital_voronoi(c.s, c.G, nullptr, m), want) == "");
    }
  }
}

TEST_CASE("ghull stage 1: many sites in one column or row, equal heights", "[ghull][cuda-omp]") {
  // every pixel of a column / row / the whole face holding a site of one
  // height or of heights that make many parabolas tie
  for (std::uint32_t G : {1u, 2u, 3u, 7u, 16u, 33u}) {
    for (int layout = 0; layout < 4; ++layout) {
      Case c{G, {}};
      std::mt19937_64 rng(G * 10 + static_cast<std::uint32_t>(layout));
      for (std::uint32_t a = 0; a < G; ++a)
        for (std::uint32_t b = 0; b < G; ++b) {
          if (layout == 0 && a != G / 2) continue;  // one column of face z = 0
          if (layout == 1 && b != 0) continue;      // one row
          const double z = layout == 3 ? 0.5 + static_cast<double>(rng() % 3) : 0.25 + 0.5 * G * ((a + b) % 2);
          c.s.insert(c.s.end(), {a + 0.5, b + 0.5, std::min(z, G - 0.25)});
        }
      INFO("G = " << G << ", layout " << layout);
      std::vector<std::uint32_t> sites;
      const std::vector<std::uint32_t> labels = st::digital_voronoi(c.s, c.G, &sites);
      REQUIRE(diff(sites, brute_sites(c.s, c.G)) == "");
      REQUIRE(voronoi_error(c.s, c.G, sites, labels) == "");
    }
  }
}

TEST_CASE("ghull stage 1: the same labels at 1 and 16 OpenMP threads", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(74);
  for (int k = 0; k < 6; ++k) {
    Case c = make_case(rng, 64, 128, 200);
    // enough points for the projection to run in parallel (4096 items)
    while (c.s.size() < 3 * 1200) {  // points near earlier ones
      const std::size_t q = rng() % (c.s.size() / 3);
      for (int a = 0; a < 3; ++a)
        c.s.push_back(std::min(std::max(c.s[3 * q + a] + 0.01 * (rng() % 64), 1e-3), c.G - 1e-3));
    }
    INFO("case " << k << ": " << describe(c));
    std::vector<std::uint32_t> s1, s16;
    const auto l1 = test::with_omp_threads(1, [&] { return st::digital_voronoi(c.s, c.G, &s1); });
    const auto l16 = test::with_omp_threads(16, [&] { return st::digital_voronoi(c.s, c.G, &s16); });
    REQUIRE(diff(s1, s16) == "");
    REQUIRE(diff(l1, l16) == "");
    REQUIRE(diff(s1, brute_sites(c.s, c.G)) == "");
    REQUIRE(voronoi_error(c.s, c.G, s1, l1) == "");
    const std::uint32_t n = static_cast<std::uint32_t>(c.s.size() / 3);
    std::vector<std::uint32_t> o1, n1, o16, n16;
    test::with_omp_threads(1, [&] { st::working_sets(l1, c.G, n, o1, n1); return 0; });
    test::with_omp_threads(16, [&] { st::working_sets(l1, c.G, n, o16, n16); return 0; });
    REQUIRE(diff(o1, o16) == "");
    REQUIRE(diff(n1, n16) == "");
  }
}

TEST_CASE("ghull stage 1: a planted wrong label is caught by the brute force", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(75);
  int planted = 0;
  for (int k = 0; k < 100 && planted < 20; ++k) {
    const Case c = make_case(rng, 4, 16, 40);
    std::vector<std::uint32_t> sites;
    std::vector<std::uint32_t> labels = st::digital_voronoi(c.s, c.G, &sites);
    // a pixel whose label changes to a strictly farther site of its face
    const std::size_t GG = std::size_t{c.G} * c.G;
    const std::size_t q = rng() % labels.size();
    const std::uint32_t f = static_cast<std::uint32_t>(q / GG);
    for (std::size_t r = 0; r < GG; ++r) {
      const std::uint32_t other = sites[f * GG + r];
      if (other == kNone) continue;
      const std::uint32_t pix = static_cast<std::uint32_t>(q % GG);
      if (st::site_distance(c.s, c.G, f, pix, other) > st::site_distance(c.s, c.G, f, pix, labels[q])) {
        labels[q] = other;
        REQUIRE(voronoi_error(c.s, c.G, sites, labels) != "");
        ++planted;
        break;
      }
    }
  }
  REQUIRE(planted == 20);
}

TEST_CASE("ghull stage 2: working sets of random labellings against pixels grouped by 3D corners",
          "[ghull][cuda-omp]") {
  std::mt19937_64 rng(81);
  std::size_t pairs = 0;
  for (int k = 0; k < 600; ++k) {
    const std::uint32_t G = 1 + static_cast<std::uint32_t>(rng() % (k < 300 ? 4 : 12));
    const std::uint32_t n = 2 + static_cast<std::uint32_t>(rng() % 6);
    const int holes = static_cast<int>(rng() % 3);  // 0: none, else kNone for about 1 in 4 or 1 in 2 pixels
    std::vector<std::uint32_t> labels(6 * std::size_t{G} * G);
    for (auto& l : labels)
      l = holes && rng() % (holes == 1 ? 4 : 2) == 0 ? kNone : static_cast<std::uint32_t>(rng() % n);
    INFO("case " << k << ": G = " << G << ", n = " << n);
    std::vector<std::uint32_t> off, nbr, boff, bnbr;
    std::map<std::size_t, std::size_t> per_vertex;
    st::working_sets(labels, G, n, off, nbr);
    brute_working_sets(labels, G, n, boff, bnbr, &per_vertex);
    REQUIRE(diff(off, boff) == "");
    REQUIRE(diff(nbr, bnbr) == "");
    pairs += nbr.size();
    // the surface's vertices: 8 corners of 3 pixels, the rest 4 (edges: 2 + 2)
    REQUIRE(per_vertex[3] == 8);
    const std::size_t surface = std::size_t{G + 1} * (G + 1) * (G + 1) - std::size_t{G - 1} * (G - 1) * (G - 1);
    REQUIRE(per_vertex[4] == surface - 8);
    REQUIRE(per_vertex.size() == 2);
  }
  REQUIRE(pairs > 600 * 10);  // the cases are not empty
}

TEST_CASE("ghull stage 2: working sets of digital Voronoi diagrams against the brute force", "[ghull][cuda-omp]") {
  std::mt19937_64 rng(82);
  int with_pairs = 0;
  for (int k = 0; k < 200; ++k) {
    const Case c = make_case(rng, 1, 40, 200);
    const std::uint32_t n = static_cast<std::uint32_t>(c.s.size() / 3);
    INFO("case " << k << ": " << describe(c));
    const std::vector<std::uint32_t> labels = st::digital_voronoi(c.s, c.G);
    std::vector<std::uint32_t> off, nbr, boff, bnbr;
    st::working_sets(labels, c.G, n, off, nbr);
    brute_working_sets(labels, c.G, n, boff, bnbr);
    REQUIRE(diff(off, boff) == "");
    REQUIRE(diff(nbr, bnbr) == "");
    with_pairs += !nbr.empty();
  }
  REQUIRE(with_pairs > 150);
  // nothing labelled: no pairs
  std::vector<std::uint32_t> off, nbr;
  st::working_sets(std::vector<std::uint32_t>(6 * 5 * 5, kNone), 5, 3, off, nbr);
  REQUIRE(off == std::vector<std::uint32_t>(4, 0));
  REQUIRE(nbr.empty());
}

#endif  // FLIPFLOP_HAVE_KERNELS_OMP

// generate.cpp — the table of distributions, option checks and weights.
#include "gen/generate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gen/families.hpp"

namespace flipflop::gen {

namespace {

using detail::Coords;
using detail::Rng;

struct Family {
  const char* name;
  int dim;
  void (*make)(Rng&, std::size_t, const Options&, Coords&);
};

// The cball default h = max(4, n/100), at most n.
std::size_t hull_points(std::size_t n, const Options& o) {
  if (o.hull_points > n)
    throw std::invalid_argument("cball: hull_points (" + std::to_string(o.hull_points) +
                                ") exceeds n (" + std::to_string(n) + ")");
  return o.hull_points > 0 ? o.hull_points : std::min(n, std::max<std::size_t>(4, n / 100));
}

const Family kFamilies[] = {
    {"square", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::square(r, n, c); }},
    {"disk", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::disk(r, n, c); }},
    {"frame", 2, [](Rng& r, std::size_t n, const Options& o, Coords& c) { detail::frame(r, n, o.thickness, c); }},
    {"circle", 2, [](Rng& r, std::size_t n, const Options& o, Coords& c) { detail::circle(r, n, o.thickness, c); }},
    {"cube", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::cube(r, n, c); }},
    {"ball", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::ball(r, n, c); }},
    {"box", 3, [](Rng& r, std::size_t n, const Options& o, Coords& c) { detail::box(r, n, o.thickness, c); }},
    {"sphere", 3, [](Rng& r, std::size_t n, const Options& o, Coords& c) { detail::sphere(r, n, o.thickness, c); }},
    {"cball", 3, [](Rng& r, std::size_t n, const Options& o, Coords& c) { detail::cball(r, n, hull_points(n, o), c); }},
    {"grid2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::grid(r, 2, n, c); }},
    {"grid3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::grid(r, 3, n, c); }},
    {"circle-lattice", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::circle_lattice(r, n, c); }},
    {"sphere-lattice", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::sphere_lattice(r, n, c); }},
    {"collinear2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::collinear(r, 2, n, c); }},
    {"collinear3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::collinear(r, 3, n, c); }},
    {"coplanar3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::coplanar3(r, n, c); }},
    {"duplicates2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::duplicates(r, 2, n, c); }},
    {"duplicates3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::duplicates(r, 3, n, c); }},
    {"jitter2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::jitter(r, 2, n, c); }},
    {"jitter3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::jitter(r, 3, n, c); }},
    {"huge2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::huge(r, 2, n, c); }},
    {"huge3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::huge(r, 3, n, c); }},
    {"tiny2", 2, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::tiny(r, 2, n, c); }},
    {"tiny3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::tiny(r, 3, n, c); }},
    {"planes3", 3, [](Rng& r, std::size_t n, const Options&, Coords& c) { detail::planes3(r, n, c); }},
};

const Family& find(const std::string& dist) {
  for (const Family& f : kFamilies)
    if (dist == f.name) return f;
  std::string names;
  for (const Family& f : kFamilies) names += (names.empty() ? "" : ", ") + std::string(f.name);
  throw std::invalid_argument("unknown distribution '" + dist + "'; valid: " + names);
}

bool uses_thickness(const std::string& dist) {
  return dist == "frame" || dist == "circle" || dist == "box" || dist == "sphere";
}

}  // namespace

std::vector<std::string> distributions() {
  std::vector<std::string> names;
  for (const Family& f : kFamilies) names.emplace_back(f.name);
  return names;
}

int dimension_of(const std::string& dist) { return find(dist).dim; }

PointSet generate(const std::string& dist, std::size_t n, const Options& o) {
  const Family& f = find(dist);
  if (n > std::numeric_limits<Index>::max())
    throw std::invalid_argument("n = " + std::to_string(n) + " exceeds the largest point count " +
                                std::to_string(std::numeric_limits<Index>::max()));
  if (uses_thickness(dist) && !(o.thickness > 0.0 && o.thickness <= 0.5))
    throw std::invalid_argument(dist + ": thickness must be in (0, 0.5], got " +
                                std::to_string(o.thickness));
  if (o.weighted && !(std::isfinite(o.wlo) && std::isfinite(o.whi) && o.wlo <= o.whi))
    throw std::invalid_argument("weights: need finite wlo <= whi, got [" + std::to_string(o.wlo) +
                                ", " + std::to_string(o.whi) + "]");
  PointSet ps;
  ps.dim = f.dim;
  ps.weighted = o.weighted;
  ps.coords.reserve(n * static_cast<std::size_t>(f.dim));
  Rng r(o.seed);
  f.make(r, n, o, ps.coords.vec());
  if (o.weighted) {
    // wlo·(1-u) + whi·u cannot overflow where whi - wlo would; clamped
    // against rounding past the ends.
    Rng wr(detail::derive_seed(o.seed, 1));
    ps.weights.resize(n);
    for (double& w : ps.weights) {
      const double u = wr.unit();
      w = std::clamp(o.wlo * (1.0 - u) + o.whi * u, o.wlo, o.whi);
    }
  }
  return ps;
}

}  // namespace flipflop::gen

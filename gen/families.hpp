// families.hpp — the generators behind generate() (internal). Each appends
// exactly n points of its dimension to `out` (coords only; weights are added
// by generate()).
#pragma once

#include <cstddef>
#include <vector>

#include "gen/generate.hpp"
#include "gen/rng.hpp"

namespace flipflop::gen::detail {

using Coords = std::vector<double>;

// Shuffles the points from index `first` on (Fisher–Yates on the points).
void shuffle_points(Rng& r, int dim, Coords& c, std::size_t first);

// uniform.cpp — thesis distributions, coordinates in [0, 1].
void square(Rng& r, std::size_t n, Coords& out);
void disk(Rng& r, std::size_t n, Coords& out);
void frame(Rng& r, std::size_t n, double t, Coords& out);
void circle(Rng& r, std::size_t n, double t, Coords& out);
void cube(Rng& r, std::size_t n, Coords& out);
void ball(Rng& r, std::size_t n, Coords& out);
void box(Rng& r, std::size_t n, double t, Coords& out);
void sphere(Rng& r, std::size_t n, double t, Coords& out);
void cball(Rng& r, std::size_t n, std::size_t h, Coords& out);

// degenerate.cpp
void grid(Rng& r, int dim, std::size_t n, Coords& out);
void collinear(Rng& r, int dim, std::size_t n, Coords& out);
void coplanar3(Rng& r, std::size_t n, Coords& out);
void duplicates(Rng& r, int dim, std::size_t n, Coords& out);
void jitter(Rng& r, int dim, std::size_t n, Coords& out);
void huge(Rng& r, int dim, std::size_t n, Coords& out);
void tiny(Rng& r, int dim, std::size_t n, Coords& out);

// lattice.cpp
void circle_lattice(Rng& r, std::size_t n, Coords& out);
void sphere_lattice(Rng& r, std::size_t n, Coords& out);

// planes.cpp — a scanned building: planes, millimetres, duplicates
void planes3(Rng& r, std::size_t n, Coords& out);

}  // namespace flipflop::gen::detail

// uniform.cpp — the distributions of the thesis' experiments (§4.4 Fig. 4.4,
// §5.4, §6.5 Fig. 6.12, §7.4 "controlled ball"), coordinates in [0, 1].
//
// Disk, ball and the controlled ball's interior are sampled exactly: the
// candidate lies on the grid k·2^-53 (or k·2^-52 - 1), and the test
// "inside the closed ball" is decided in 128-bit integers, so every accepted
// point is inside, exactly. Frame and box pick one of their rectangular
// strips by area and sample it; the band coordinate is t·u or 1 - t·u, so
// every point has a coordinate <= t or >= fl(1 - t), exactly (rounding is
// monotone). Annulus and spherical shell combine a uniform direction (a point
// of the unit ball, by rejection, divided by its length) with a radius drawn
// by rejection with density ∝ r^(d-1) on [r_in, r_out] (uniform by area or
// volume, no cube roots needed); their points lie in the shell up to a few
// rounding errors, and a point that rounds outside [0,1]^d is drawn again.
#include <cmath>

#include "gen/families.hpp"

namespace flipflop::gen::detail {

namespace {

constexpr std::int64_t kHalf = std::int64_t{1} << 52;  // 0.5 on the 2^-53 grid

// A point of the closed ball of radius 1/2 around (1/2, ..., 1/2), uniform on
// the grid k·2^-53 of [0,1)^dim: (Σ (k_i - 2^52)^2 <= 2^104) in integers.
void grid_ball(Rng& r, int dim, double* p) {
  for (;;) {
    std::int64_t k[3];
    i128 s = 0;
    for (int c = 0; c < dim; ++c) {
      k[c] = static_cast<std::int64_t>(r.bits53());
      const i128 d = k[c] - kHalf;
      s += d * d;
    }
    if (s <= static_cast<i128>(kHalf) * kHalf) {
      for (int c = 0; c < dim; ++c) p[c] = static_cast<double>(k[c]) * 0x1p-53;
      return;
    }
  }
}

// A uniform direction: a point v of the unit ball with |v| >= 1/4 (a
// rotation-invariant region), divided by |v|.
void direction(Rng& r, int dim, double* u) {
  for (;;) {
    double s = 0;
    for (int c = 0; c < dim; ++c) {
      u[c] = r.symmetric();
      s += u[c] * u[c];
    }
    if (s <= 1.0 && s >= 0.0625) {
      const double len = std::sqrt(s);
      for (int c = 0; c < dim; ++c) u[c] /= len;
      return;
    }
  }
}

// Uniform (by area or volume) in the shell r_in <= |p - c| <= r_out around
// c = (1/2, ..., 1/2).
void shell(Rng& r, int dim, double r_in, double r_out, double* p) {
  for (;;) {
    double u[3];
    direction(r, dim, u);
    double rad = 0;
    for (;;) {  // density ∝ rad^(dim-1): accept with probability (rad/r_out)^(dim-1)
      rad = r_in + (r_out - r_in) * r.unit();
      const double a = r.unit();
      if (dim == 2 ? a * r_out <= rad : a * r_out * r_out <= rad * rad) break;
    }
    bool inside = true;
    for (int c = 0; c < dim; ++c) {
      p[c] = 0.5 + rad * u[c];
      inside = inside && p[c] >= 0.0 && p[c] <= 1.0;
    }
    if (inside) return;
  }
}

// A coordinate in the band of width t at the low (0) or high (1) side.
double band(Rng& r, double t, bool high) { return high ? 1.0 - t * r.unit() : t * r.unit(); }

void append(Coords& out, const double* p, int dim) { out.insert(out.end(), p, p + dim); }

}  // namespace

void square(Rng& r, std::size_t n, Coords& out) {
  for (std::size_t i = 0; i < 2 * n; ++i) out.push_back(r.unit());
}

void cube(Rng& r, std::size_t n, Coords& out) {
  for (std::size_t i = 0; i < 3 * n; ++i) out.push_back(r.unit());
}

void disk(Rng& r, std::size_t n, Coords& out) {
  double p[2];
  for (std::size_t i = 0; i < n; ++i) {
    grid_ball(r, 2, p);
    append(out, p, 2);
  }
}

void ball(Rng& r, std::size_t n, Coords& out) {
  double p[3];
  for (std::size_t i = 0; i < n; ++i) {
    grid_ball(r, 3, p);
    append(out, p, 3);
  }
}

// The frame: strips bottom, top (t × 1) and left, right (t × (1 - 2t)).
void frame(Rng& r, std::size_t n, double t, Coords& out) {
  const double side = t * (1.0 - 2.0 * t);
  const double total = 2.0 * t + 2.0 * side;
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = r.unit() * total;
    double p[2];
    if (pick < 2.0 * t) {  // bottom or top: the band is y
      p[0] = r.unit();
      p[1] = band(r, t, pick >= t);
    } else {  // left or right: the band is x
      p[0] = band(r, t, pick >= 2.0 * t + side);
      p[1] = t + (1.0 - 2.0 * t) * r.unit();
    }
    append(out, p, 2);
  }
}

// The box: slabs z (t × 1 × 1), y (t × 1 × (1-2t)), x (t × (1-2t)^2), two each.
void box(Rng& r, std::size_t n, double t, Coords& out) {
  const double inner = 1.0 - 2.0 * t;
  const double area[3] = {t * inner * inner, t * inner, t};  // band axis x, y, z
  const double total = 2.0 * (area[0] + area[1] + area[2]);
  for (std::size_t i = 0; i < n; ++i) {
    double pick = r.unit() * total;
    int axis = 2;
    for (int a = 0; a < 3; ++a) {
      if (pick < 2.0 * area[a]) {
        axis = a;
        break;
      }
      pick -= 2.0 * area[a];
    }
    const bool high = pick >= area[axis];
    double p[3];
    for (int c = 0; c < 3; ++c) {
      if (c == axis) continue;
      // Axes before the band axis span [0,1); axes after it only the inner
      // range [t, 1-t] (the slabs of those axes own the rest).
      p[c] = c < axis ? r.unit() : t + inner * r.unit();
    }
    p[axis] = band(r, t, high);
    append(out, p, 3);
  }
}

void circle(Rng& r, std::size_t n, double t, Coords& out) {
  double p[2];
  for (std::size_t i = 0; i < n; ++i) {
    shell(r, 2, 0.5 - t, 0.5, p);
    append(out, p, 2);
  }
}

void sphere(Rng& r, std::size_t n, double t, Coords& out) {
  double p[3];
  for (std::size_t i = 0; i < n; ++i) {
    shell(r, 3, 0.5 - t, 0.5, p);
    append(out, p, 3);
  }
}

// Controlled ball (thesis §7.4): h points on the sphere of radius 0.5, n - h
// uniform in the ball of radius 0.45, both around (0.5, 0.5, 0.5); then the
// order is shuffled so that the hull points are not the first indices.
void cball(Rng& r, std::size_t n, std::size_t h, Coords& out) {
  const std::size_t first = out.size() / 3;
  double p[3];
  for (std::size_t i = 0; i < h; ++i) {
    shell(r, 3, 0.5, 0.5, p);
    append(out, p, 3);
  }
  for (std::size_t i = h; i < n; ++i) {
    // grid_ball gives the ball of radius 1/2 around 1/2; scale it by 0.9.
    grid_ball(r, 3, p);
    for (double& c : p) c = 0.5 + 0.9 * (c - 0.5);
    append(out, p, 3);
  }
  shuffle_points(r, 3, out, first);
}

}  // namespace flipflop::gen::detail

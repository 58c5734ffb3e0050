// fuzz_input.cpp — the point-set decoder and failure report of fuzz_input.hpp.
#include "fuzz/fuzz_input.hpp"

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace flipflop::fuzz {

namespace {

double special_value(std::uint8_t b) {
  static const double table[16] = {0.0,  0x1p-1074, 1e-310, DBL_MIN, 1e-300, 0.1,   1.0, 3.0,
                                   1e15, 0x1p53,    1e300,  DBL_MAX / 8, 0.5, 1e-15, 7.0, 1e-3};
  const double v = table[b & 15] * static_cast<double>(1 + (b >> 5));
  return (b & 16) ? -v : v;
}

double raw_double(ByteReader& r) {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(r.byte()) << (8 * i);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return std::isfinite(v) ? v : 0.0;
}

// Integer points on x² + y² = 25 and on x² + y² + z² = 9.
const std::array<std::array<double, 2>, 12> kCircle = {{{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4},
                                                        {3, -4}, {-3, -4}, {4, 3}, {-4, 3}, {4, -3}, {-4, -3}}};

std::array<double, 3> sphere_point(std::uint8_t b) {
  const int k = b % 30;
  if (k < 6) {  // (±3, 0, 0) and its permutations
    std::array<double, 3> p{0, 0, 0};
    p[static_cast<std::size_t>(k / 2)] = (k % 2) ? -3 : 3;
    return p;
  }
  // (±1, ±2, ±2): the 1 in one of 3 places, 8 sign patterns
  const int j = k - 6, place = j / 8, signs = j % 8;
  std::array<double, 3> p{2, 2, 2};
  p[static_cast<std::size_t>(place)] = 1;
  for (int c = 0; c < 3; ++c)
    if (signs & (1 << c)) p[static_cast<std::size_t>(c)] = -p[static_cast<std::size_t>(c)];
  return p;
}

}  // namespace

bool decode_points(ByteReader& r, int dim, bool weighted, std::size_t min_n, std::size_t max_n,
                   PointSet& out) {
  const std::size_t n = min_n + r.byte() % (max_n - min_n + 1);
  const std::uint8_t scale_byte = r.byte();
  const int e = (scale_byte & 1) ? 16 * (static_cast<std::int8_t>(scale_byte) >> 1) : 0;
  const auto d = static_cast<std::size_t>(dim);
  out = PointSet{};
  out.dim = dim;
  out.weighted = weighted;
  out.coords.reserve(n * d);
  if (weighted) out.weights.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Fewer points when the bytes run out: short inputs are small inputs.
    if (i >= min_n && r.at_end()) break;
    out.coords.resize((i + 1) * d, 0.0);
    if (weighted) out.weights.resize(i + 1, 0.0);
    double* p = out.coords.data() + i * d;
    int mode = r.byte() & 7;
    if ((mode == 2 || mode == 3) && i == 0) mode = 0;
    if (mode == 4 && i < 2) mode = 0;
    switch (mode) {
      case 0:
        for (std::size_t c = 0; c < d; ++c) p[c] = static_cast<double>(r.byte() & 15) - 8;
        break;
      case 1:
        for (std::size_t c = 0; c < d; ++c) p[c] = static_cast<std::int8_t>(r.byte());
        break;
      case 2: {
        const double* q = out.point(r.byte() % i);
        for (std::size_t c = 0; c < d; ++c) p[c] = q[c];
        break;
      }
      case 3: {
        const double* q = out.point(r.byte() % i);
        for (std::size_t c = 0; c < d; ++c) {
          double v = q[c];
          const int steps = r.byte() % 5 - 2;
          for (int s = 0; s < std::abs(steps); ++s) v = std::nextafter(v, steps > 0 ? HUGE_VAL : -HUGE_VAL);
          p[c] = v;
        }
        break;
      }
      case 4: {
        const double* a = out.point(r.byte() % i);
        const double* b = out.point(r.byte() % i);
        const double t = static_cast<std::int8_t>(r.byte()) / 4.0;
        for (std::size_t c = 0; c < d; ++c) p[c] = a[c] + t * (b[c] - a[c]);
        break;
      }
      case 5:
        for (std::size_t c = 0; c < d; ++c) p[c] = raw_double(r);
        break;
      case 6:
        for (std::size_t c = 0; c < d; ++c) p[c] = special_value(r.byte());
        break;
      default:
        if (dim == 2) {
          const auto& q = kCircle[r.byte() % kCircle.size()];
          p[0] = q[0];
          p[1] = q[1];
        } else {
          // |p|^2 = 9; in d > 3 the three coordinates of the sphere point
          // go to three consecutive places (cyclically) chosen by a byte
          const std::uint8_t b = r.byte();
          const auto q = sphere_point(b);
          const std::size_t shift = d > 3 ? static_cast<std::size_t>(b / 30) % d : 0;
          for (std::size_t c = 0; c < d; ++c) p[c] = 0;
          for (std::size_t c = 0; c < 3 && c < d; ++c) p[(c + shift) % d] = q[c];
        }
        break;
    }
    if (weighted) out.weights[i] = static_cast<std::int8_t>(r.byte()) / 4.0;
  }
  if (e != 0) {
    // modes 2-4 read earlier points, so scaling comes last
    for (double& v : out.coords) v = std::ldexp(v, e);
    for (double& w : out.weights) w = std::ldexp(w, 2 * e);
  }
  for (double v : out.coords)
    if (!std::isfinite(v)) return false;
  for (double w : out.weights)
    if (!std::isfinite(w)) return false;
  return true;
}

std::string describe(const PointSet& ps) {
  std::string s = "# " + std::to_string(ps.size()) + " points, dim " + std::to_string(ps.dim) +
                  (ps.weighted ? ", weighted" : "") + " (hexadecimal floats)\n";
  char buf[64];
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (int c = 0; c < ps.dim; ++c) {
      std::snprintf(buf, sizeof buf, "%s%a", c ? " " : "", ps.point(i)[c]);
      s += buf;
    }
    if (ps.weighted) {
      std::snprintf(buf, sizeof buf, " %a", ps.weight(i));
      s += buf;
    }
    s += "   # " + std::to_string(i) + "\n";
  }
  return s;
}

std::string describe(const std::vector<Index>& cycle) {
  std::string s = "[";
  for (std::size_t k = 0; k < cycle.size(); ++k) s += (k ? " " : "") + std::to_string(cycle[k]);
  return s + "]";
}

std::string describe(const std::vector<Triangle>& tris) {
  std::string s = "[";
  for (std::size_t k = 0; k < tris.size(); ++k)
    s += (k ? " (" : "(") + std::to_string(tris[k][0]) + "," + std::to_string(tris[k][1]) + "," +
         std::to_string(tris[k][2]) + ")";
  return s + "]";
}

void fail(const char* target, const std::string& what, const std::string& details) {
  std::fprintf(stderr, "%s: %s\n%s%s", target, what.c_str(), details.c_str(),
               details.empty() || details.back() == '\n' ? "" : "\n");
  std::fflush(stderr);
  std::abort();
}

}  // namespace flipflop::fuzz

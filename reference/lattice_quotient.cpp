// lattice_quotient.cpp — see lattice_quotient.hpp.
#include "reference/lattice_quotient.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

namespace flipflop {
namespace {

constexpr std::uint64_t kLimit = std::uint64_t{1} << 20;  // StaticFilter::small_integers' bound

// |x| = m 2^e with m odd (x finite, not 0), from the IEEE 754 bits.
struct Odd {
  std::uint64_t m = 0;
  int e = 0;
  bool negative = false;
};

enum class Kind { zero, finite, other };

Kind decompose(double x, Odd& o) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int be = static_cast<int>((bits >> 52) & 0x7ff);
  if (be == 0x7ff) return Kind::other;
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if (be != 0) mant |= std::uint64_t{1} << 52;
  if (mant == 0) return Kind::zero;
  const int tz = __builtin_ctzll(mant);
  o.m = mant >> tz;
  o.e = (be == 0 ? -1074 : be - 1075) + tz;
  o.negative = (bits >> 63) != 0;
  return Kind::finite;
}

// The signed integer m / G 2^(e - E) into `out` where it is an integer below
// 2^20 in magnitude; false otherwise (G does not divide m, or too large).
bool quotient(const Odd& o, std::uint64_t G, int E, double& out) {
  if (o.m % G != 0) return false;
  const std::uint64_t q = o.m / G;
  const int shift = o.e - E;
  if (shift < 0 || shift >= 20 || (q << shift) >= kLimit) return false;
  const double v = static_cast<double>(q << shift);
  out = o.negative ? -v : v;
  return true;
}

}  // namespace

std::optional<LatticeQuotient> lattice_quotient(const PointSet& ps) {
  const std::size_t count = ps.coords.size();
  const double* x = ps.coords.data();
  // pass 1: G = gcd of the odd mantissas, E = the least exponent; whether
  // every value is a small integer already
  std::uint64_t G = 0;
  int E = 0;
  bool small = true;
  Odd o;
  for (std::size_t i = 0; i < count; ++i) {
    const Kind k = decompose(x[i], o);
    if (k == Kind::other) return std::nullopt;
    if (k == Kind::zero) continue;
    if (G == 0) {
      G = o.m;
      E = o.e;
    } else {
      if (o.m % G != 0) G = std::gcd(G, o.m);
      if (o.e < E) E = o.e;
    }
    // G only shrinks (to a divisor) from here: m / G >= 2^20 stays so
    if (o.m / G >= kLimit) return std::nullopt;
    small = small && o.e >= 0 && std::fabs(x[i]) < 0x1p20;
  }
  if (G == 0) return std::nullopt;  // every coordinate 0
  bool weights_small = true;
  if (ps.weighted)
    for (std::size_t i = 0; i < ps.weights.size(); ++i) {
      const double w = ps.weights[i];
      if (!std::isfinite(w)) return std::nullopt;
      weights_small = weights_small && w == std::trunc(w) && std::fabs(w) < 0x1p20;
    }
  if (small && weights_small) return std::nullopt;  // the lattice path applies as it is
  LatticeQuotient out;
  out.factor = std::ldexp(static_cast<double>(G), E);  // exact: G < 2^53 divides a mantissa, E >= -1074
  out.points.dim = ps.dim;
  out.points.weighted = ps.weighted;
  std::vector<double> q(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (decompose(x[i], o) == Kind::zero) {
      q[i] = 0.0;
      continue;
    }
    if (!quotient(o, G, E, q[i])) return std::nullopt;
  }
  out.points.coords = std::move(q);
  if (ps.weighted) {
    // w / g^2 = (m_w / G^2) 2^(e_w - 2E): G^2 must divide m_w < 2^53, so a
    // non-zero weight needs G < 2^26.5 (taken as G < 2^26: G^2 < 2^52)
    const std::uint64_t G2 = G < (std::uint64_t{1} << 26) ? G * G : 0;
    std::vector<double> qw(ps.weights.size());
    for (std::size_t i = 0; i < qw.size(); ++i) {
      if (decompose(ps.weights[i], o) == Kind::zero) {
        qw[i] = 0.0;
        continue;
      }
      if (G2 == 0 || !quotient(o, G2, 2 * E, qw[i])) return std::nullopt;
    }
    out.points.weights = std::move(qw);
  }
  return out;
}

}  // namespace flipflop

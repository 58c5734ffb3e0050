// predicates_check.cpp — fuzz_predicates: raw bytes decoded into one
// predicate instance and checked:
//   1. Mode::filtered == Mode::gmp for the exact and the SoS variant;
//   2. SoS is non-zero when the ids are distinct, zero when an id repeats;
//   3. SoS equals the exact sign whenever that is non-zero;
//   4. swapping the first two arguments negates both signs.
// Non-finite decoded values are skipped (the API requires finite inputs).
// A violation prints the decoded instance (hexadecimal floats) and aborts.
//
// Byte layout (missing bytes read as 0, extra bytes are ignored):
//   byte 0   predicate: index mod 13 into all_specs() — orient2d, orient3d,
//            power2d, power3d, orient_d d=2..6, power_d d=2..5.
//   byte 1   flags: bits 0-1 value encoding (below); bit 2 set: ids are the
//            raw id bytes (repeats possible; a repeated id is the same point,
//            so it takes the values of its first occurrence), clear:
//            id_i = 8·byte_i + i (always distinct, any order).
//   byte 2   scale s for encoding 2 (signed).
//   k bytes  ids, one per point.
//   values   k·d coordinates, then k weights for power predicates, in the
//            chosen encoding:
//     0: raw little-endian binary64, 8 bytes each (non-finite → skipped);
//     1: signed 8-bit integers (exact degeneracies are easy to reach);
//     2: signed 8-bit integers times 2^e for coordinates and 2^(2e) for
//        weights (keeps integer degeneracies exact), e = 8·s (orientation) or
//        4·s (power), i.e. from subnormal to ~1e300 magnitudes;
//     3: one byte per value from a table of special magnitudes: bits 0-3
//        pick 0, 2^-1074, 1e-310, DBL_MIN, 1e-300, 0.1, 1, 3, 1e15, 2^53,
//        1e300, DBL_MAX, ... ; bit 4 the sign; bits 5-7 a factor 1..8.
#include "fuzz/checks.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "proptests/support/predicate_call.hpp"

namespace flipflop::fuzz {

namespace {

using pred::Mode;
using pred::PointId;
using test::Instance;
using test::Spec;

struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos = 0;
  std::uint8_t byte() { return pos < size ? data[pos++] : 0; }
};

double special_value(std::uint8_t b) {
  static const double table[16] = {0.0,    4.9e-324, 1e-310, DBL_MIN, 1e-300, 0.1,  1.0,     3.0,
                                   1e15,   9007199254740992.0, 1e300, DBL_MAX, 0.5, 1e-15, 7.0, 1e-3};
  const double v = table[b & 15] * static_cast<double>(1 + (b >> 5));
  return (b & 16) ? -v : v;
}

double decode_value(Reader& r, int encoding, int scale_exp) {
  switch (encoding) {
    case 0: {
      std::uint64_t bits = 0;
      for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(r.byte()) << (8 * i);
      double v;
      std::memcpy(&v, &bits, sizeof v);
      return v;
    }
    case 1: return static_cast<double>(static_cast<std::int8_t>(r.byte()));
    case 2: return std::ldexp(static_cast<double>(static_cast<std::int8_t>(r.byte())), scale_exp);
    default: return special_value(r.byte());
  }
}

[[noreturn]] void fail(const char* what, const Spec& s, const Instance& in) {
  std::fprintf(stderr, "fuzz_predicates: %s\n%s", what, test::describe(s, in).c_str());
  std::abort();
}

}  // namespace

bool check_predicates_input(const std::uint8_t* data, std::size_t size) {
  Reader r{data, size};
  const std::vector<Spec> specs = test::all_specs();
  const Spec s = specs[r.byte() % specs.size()];
  const std::uint8_t flags = r.byte();
  const int encoding = flags & 3;
  const bool raw_ids = (flags & 4) != 0;
  const int scale = static_cast<std::int8_t>(r.byte());
  const int coord_exp = s.weighted() ? 4 * scale : 8 * scale;

  Instance in;
  in.d = s.d;
  in.k = s.points();
  in.id.resize(static_cast<size_t>(in.k));
  for (int i = 0; i < in.k; ++i) {
    const PointId b = r.byte();
    in.id[static_cast<size_t>(i)] = raw_ids ? b : 8 * b + static_cast<PointId>(i);
  }
  in.x.resize(static_cast<size_t>(in.k * in.d));
  for (double& v : in.x) v = decode_value(r, encoding, coord_exp);
  in.w.assign(static_cast<size_t>(in.k), 0.0);
  if (s.weighted())
    for (double& v : in.w) v = decode_value(r, encoding, 2 * coord_exp);
  for (double v : in.x)
    if (!std::isfinite(v)) return false;
  for (double v : in.w)
    if (!std::isfinite(v)) return false;

  // An id names one point (predicates.hpp): a repeated id takes the
  // coordinates and weight of its first occurrence.
  bool distinct = true;
  for (int j = 1; j < in.k; ++j) {
    for (int i = 0; i < j; ++i) {
      if (in.id[static_cast<size_t>(i)] != in.id[static_cast<size_t>(j)]) continue;
      distinct = false;
      for (int c = 0; c < in.d; ++c) in.p(j)[c] = in.p(i)[c];
      in.w[static_cast<size_t>(j)] = in.w[static_cast<size_t>(i)];
      break;
    }
  }

  const int exact = test::eval(s, in, false, Mode::gmp);
  const int sos = test::eval(s, in, true, Mode::gmp);
  if (test::eval(s, in, false, Mode::filtered) != exact) fail("exact: filtered != gmp", s, in);
  if (test::eval(s, in, true, Mode::filtered) != sos) fail("SoS: filtered != gmp", s, in);
  if (distinct && sos == 0) fail("SoS returned 0 for distinct ids", s, in);
  if (!distinct && sos != 0) fail("SoS non-zero for a repeated id", s, in);
  if (exact != 0 && sos != exact) fail("SoS disagrees with a non-zero exact sign", s, in);

  std::vector<int> swap01(static_cast<size_t>(in.k));
  for (int i = 0; i < in.k; ++i) swap01[static_cast<size_t>(i)] = i;
  std::swap(swap01[0], swap01[1]);
  const Instance swapped = test::permuted(in, swap01);
  if (test::eval(s, swapped, false, Mode::filtered) != -exact)
    fail("exact: swapping two arguments did not negate the sign", s, in);
  if (test::eval(s, swapped, true, Mode::filtered) != -sos)
    fail("SoS: swapping two arguments did not negate the sign", s, in);
  return true;
}

}  // namespace flipflop::fuzz

// read_npy.cpp — the .npy reader (numpy's format 1.0, 2.0 and 3.0): a
// little-endian float64 array of shape (n, d), or (n, d + 1) with the weight
// as the last column, C order. Coordinates are read with one copy, straight
// from the file into the point set (weighted: into a buffer, then split).
//
// Header: magic "\x93NUMPY", major and minor version, header length (2 bytes
// for 1.0, 4 for 2.0 and 3.0), then a Python dict literal with the keys
// 'descr', 'fortran_order' and 'shape'. Anything else — another dtype
// ('<f4', '<i8', '>f8'), Fortran order, a shape of other rank or width, a
// truncated file, NaN or Inf — is refused with one line naming it.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/npy.hpp"
#include "io/text.hpp"

namespace flipflop::io::detail {

namespace {

// The value text of key `k` in the header dict ('descr': '<f8' -> '<f8').
std::string dict_value(const std::string& h, const std::string& k, const std::string& path) {
  const std::size_t at = h.find("'" + k + "'");
  if (at == std::string::npos) throw InputError(path, "npy header has no '" + k + "'");
  std::size_t v = h.find(':', at);
  if (v == std::string::npos) throw InputError(path, "npy header: no value for '" + k + "'");
  ++v;
  while (v < h.size() && h[v] == ' ') ++v;
  std::size_t e = v;
  if (v < h.size() && h[v] == '(') e = h.find(')', v) + 1;
  else if (v < h.size() && h[v] == '\'') e = h.find('\'', v + 1) + 1;
  else
    while (e < h.size() && h[e] != ',' && h[e] != '}') ++e;
  if (e == 0 || e > h.size()) throw InputError(path, "npy header: malformed value of '" + k + "'");
  return h.substr(v, e - v);
}

}  // namespace

}  // namespace flipflop::io::detail

namespace flipflop::io {

std::string nonfinite_problem(double value, std::uint64_t row, int column, int dim) {
  return std::string(std::isnan(value) ? "NaN" : "Inf") + " in row " + std::to_string(row) + ", column " +
         std::to_string(column + 1) + " (" + detail::column_name(column, dim) + ")";
}

NpyLayout npy_layout(const std::string& path, int dim, bool weighted) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path, "cannot open");
  char magic[8] = {};
  f.read(magic, 8);
  if (f.gcount() == 0) throw InputError(path, "empty file, no points");
  if (f.gcount() < 8 || std::memcmp(magic, "\x93NUMPY", 6) != 0) throw InputError(path, "not a .npy file (no NUMPY magic)");
  const int major = static_cast<unsigned char>(magic[6]);
  if (major < 1 || major > 3) throw InputError(path, "npy format version " + std::to_string(major) + " is not supported");
  unsigned char len_bytes[4] = {};
  const int len_size = major == 1 ? 2 : 4;
  f.read(reinterpret_cast<char*>(len_bytes), len_size);
  std::uint32_t hlen = 0;
  for (int i = len_size - 1; i >= 0; --i) hlen = (hlen << 8) | len_bytes[i];
  if (!f || hlen > (1u << 20)) throw InputError(path, "npy header is truncated or too long");
  std::string h(hlen, '\0');
  f.read(h.data(), static_cast<std::streamsize>(hlen));
  if (!f) throw InputError(path, "npy header is truncated");

  const std::string descr = detail::dict_value(h, "descr", path);
  if (descr != "'<f8'" && descr != "'f8'")
    throw InputError(path, "npy dtype " + detail::show(descr.size() >= 2 && descr.front() == '\'' ? descr.substr(1, descr.size() - 2) : descr) +
                               ": expected little-endian float64 ('<f8')");
  if (detail::dict_value(h, "fortran_order", path) != "False")
    throw InputError(path, "npy array in Fortran order: expected C order (numpy.ascontiguousarray)");
  const std::string shape = detail::dict_value(h, "shape", path);  // "(n, c)"
  long long n = -1, c = -1;
  {
    std::string s = shape.substr(1, shape.size() - 2);
    const std::size_t comma = s.find(',');
    std::string a = s.substr(0, comma), b = comma == std::string::npos ? "" : s.substr(comma + 1);
    auto trim = [](std::string t) {
      while (!t.empty() && (t.front() == ' ')) t.erase(t.begin());
      while (!t.empty() && (t.back() == ' ' || t.back() == ',')) t.pop_back();
      return t;
    };
    a = trim(a);
    b = trim(b);
    if (b.find(',') != std::string::npos || !detail::parse_integer(a, 0, 1LL << 40, n) || !detail::parse_integer(b, 0, 64, c))
      throw InputError(path, "npy shape " + detail::show(shape) + ": expected (n, " + std::to_string(dim) +
                                 (weighted ? " + 1" : "") + ")");
  }
  const long long cols = dim + (weighted ? 1 : 0);
  if (c != cols)
    throw InputError(path, "npy shape " + detail::show(shape) + ": expected " + std::to_string(cols) + " columns (" +
                               std::to_string(dim) + " coordinates" + (weighted ? " and a weight" : "") + ")");
  NpyLayout out;
  out.rows = static_cast<std::uint64_t>(n);
  out.cols = static_cast<int>(c);
  out.data_offset = static_cast<std::uint64_t>(f.tellg());
  f.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(f.tellg());
  const std::uint64_t need = out.rows * static_cast<std::uint64_t>(c) * sizeof(double);
  if (size < out.data_offset + need)
    throw InputError(path, "npy data is truncated: " + std::to_string((size - out.data_offset) / 8) + " of " +
                               std::to_string(need / 8) + " values");
  return out;
}

}  // namespace flipflop::io

namespace flipflop::io::detail {

PointSet read_npy(const std::string& path, int dim, bool weighted) {
  const NpyLayout lay = npy_layout(path, dim, weighted);
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path, "cannot open");
  f.seekg(static_cast<std::streamoff>(lay.data_offset));
  const long long n = static_cast<long long>(lay.rows), c = lay.cols;
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;
  const std::size_t values = static_cast<std::size_t>(n) * static_cast<std::size_t>(c);
  std::vector<double> buf;
  std::vector<double>& target = weighted ? buf : ps.coords.vec();
  target.resize(values);
  f.read(reinterpret_cast<char*>(target.data()), static_cast<std::streamsize>(values * sizeof(double)));
  if (static_cast<std::size_t>(f.gcount()) != values * sizeof(double))
    throw InputError(path, "npy data is truncated: " + std::to_string(f.gcount() / 8) + " of " +
                               std::to_string(values) + " values");
  for (std::size_t i = 0; i < values; ++i)
    if (!std::isfinite(target[i]))
      throw InputError(path, nonfinite_problem(target[i], i / static_cast<std::size_t>(c),
                                               static_cast<int>(i % static_cast<std::size_t>(c)), dim));
  if (weighted) {
    ps.coords.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(dim));
    ps.weights.resize(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      std::memcpy(&ps.coords[i * static_cast<std::size_t>(dim)], &buf[i * static_cast<std::size_t>(c)],
                  sizeof(double) * static_cast<std::size_t>(dim));
      ps.weights[i] = buf[i * static_cast<std::size_t>(c) + static_cast<std::size_t>(dim)];
    }
  }
  if (ps.size() >= 0xffffffffULL) throw InputError(path, "more than 4294967295 points");
  check_count(ps, path, 0);
  return ps;
}

}  // namespace flipflop::io::detail

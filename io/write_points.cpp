// write_points.cpp — the .xyz writer and checked file output.
#include "io/write_points.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/decimal.hpp"

namespace flipflop::io {

void write_points(std::ostream& os, const PointSet& ps) {
  std::string out;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* p = ps.point(i);
    for (int c = 0; c < ps.dim; ++c) {
      if (c > 0) out += ' ';
      detail::put_decimal(out, p[c]);
    }
    if (ps.weighted) {
      out += ' ';
      detail::put_decimal(out, ps.weights[i]);
    }
    out += '\n';
    detail::drain(os, out, false);
  }
  detail::drain(os, out, true);
}

void write_npy_header(std::ostream& os, const char* descr, const std::string& shape) {
  std::string header = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  // magic (6) + version (2) + header length (2) + header, padded with
  // spaces to a multiple of 64 and ended by '\n' (format 1.0)
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  os.write("\x93NUMPY\x01\x00", 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  const char lb[2] = {static_cast<char>(len & 0xff), static_cast<char>(len >> 8)};
  os.write(lb, 2);
  os << header;
}

void write_points_npy(std::ostream& os, const PointSet& ps) {
  const int cols = ps.dim + (ps.weighted ? 1 : 0);
  write_npy_header(os, "<f8", "(" + std::to_string(ps.size()) + ", " + std::to_string(cols) + ")");
  std::vector<char> buf;
  buf.reserve(std::size_t{1} << 20);
  auto put = [&](double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    for (int i = 0; i < 8; ++i) buf.push_back(static_cast<char>((u >> (8 * i)) & 0xff));
  };
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (int c = 0; c < ps.dim; ++c) put(ps.point(i)[c]);
    if (ps.weighted) put(ps.weights[i]);
    if (buf.size() >= (std::size_t{1} << 20) - 64) {
      os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

void write_file(const std::string& path, const std::function<void(std::ostream&)>& body) {
  auto fail = [&path](const char* what) {
    const int e = errno;
    throw std::runtime_error(path + ": cannot write: " + (e != 0 ? std::strerror(e) : what));
  };
  errno = 0;
  std::ofstream os(path, std::ios::binary | std::ios::trunc);
  if (!os) fail("cannot open");
  body(os);
  os.flush();
  if (!os) fail("write failed");
  os.close();
  if (os.fail()) fail("close failed");
}

}  // namespace flipflop::io

// write_points.cpp — the .xyz writer and checked file output.
#include "io/write_points.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

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

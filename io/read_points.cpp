// read_points.cpp — format dispatch and the checks shared by all formats.
#include "io/read_points.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>

#include "io/formats.hpp"
#include "io/text.hpp"

namespace flipflop::io {

namespace detail {
const char* column_name(int c, int dim) {
  static const char* xyz[] = {"x", "y", "z"};
  static const char* xd[] = {"x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9"};
  if (c >= dim) return "w";
  return dim <= 3 ? xyz[c] : xd[c];
}

void check_count(const PointSet& ps, const std::string& path, std::size_t line) {
  const std::size_t n = ps.size();
  const auto need = static_cast<std::size_t>(ps.dim) + 1;
  if (n == 0) throw InputError(path, line, "no points");
  if (n < need)
    throw InputError(path, line,
                     std::to_string(n) + (n == 1 ? " point" : " points") + ", at least " +
                         std::to_string(need) + " needed");
}

void append_point(PointSet& ps, const double* x, double w, const std::string& path,
                  std::size_t line) {
  if (ps.size() >= std::numeric_limits<Index>::max())
    throw InputError(path, line,
                     "more than " + std::to_string(std::numeric_limits<Index>::max()) +
                         " points");
  ps.coords.insert(ps.coords.end(), x, x + ps.dim);
  if (ps.weighted) ps.weights.push_back(w);
}
}  // namespace detail

PointSet read_points(const std::string& path, int dim, bool weighted) {
  if (dim < 2 || dim > detail::kMaxXyzColumns - 1)
    throw InputError(path, "dimension " + std::to_string(dim) + " is not supported (2 to " +
                               std::to_string(detail::kMaxXyzColumns - 1) + ")");
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  PointSet ps;
  if (dim > 3 && ext != ".xyz" && ext != ".npy")
    throw InputError(path, "unknown file extension " + detail::show(ext) + " (expected .xyz or .npy for dimension " +
                               std::to_string(dim) + ")");
  if (ext == ".xyz")
    ps = detail::read_xyz(path, dim, weighted);
  else if (ext == ".npy")
    ps = detail::read_npy(path, dim, weighted);
  else if (ext == ".off")
    ps = detail::read_off(path, dim, weighted);
  else if (ext == ".ply")
    ps = detail::read_ply(path, dim, weighted);
  else
    throw InputError(path, "unknown file extension " + detail::show(ext) +
                               " (expected .xyz, .npy, .off or .ply)");
  return ps;
}

}  // namespace flipflop::io

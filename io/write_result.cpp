// write_result.cpp — see write_result.hpp.
#include "io/write_result.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <stdexcept>

#include "io/write_points.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::io {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;

struct Ext {
  const char* ext;
  Format f;
};
constexpr Ext kExtensions[] = {{"", Format::index},    {".txt", Format::index}, {".idx", Format::index},
                               {".off", Format::off},  {".obj", Format::obj},   {".ply", Format::ply},
                               {".stl", Format::stl},  {".vtu", Format::vtu},   {".npy", Format::npy},
                               {".svg", Format::svg}};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The extension of the file name (after the last '/'): "" when none.
std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0) return "";
  return lower(name.substr(dot));
}

// The used vertices, increasing, and each input index's rank among them.
struct Vertices {
  std::vector<Index> used;
  std::vector<Index> rank;  // per input index; meaningful for used ones
};
Vertices used_vertices(std::size_t n, const std::vector<std::vector<Index>>& cells) {
  Vertices v;
  std::vector<char> is(n, 0);
  for (const auto& c : cells)
    for (Index x : c) is.at(x) = 1;
  v.rank.assign(n, 0);
  for (Index i = 0; i < n; ++i)
    if (is[i]) {
      v.rank[i] = static_cast<Index>(v.used.size());
      v.used.push_back(i);
    }
  return v;
}

P3 point3(const PointSet& ps, Index i) {
  const double* x = ps.point(i);
  return P3(x[0], x[1], ps.dim >= 3 ? x[2] : 0.0);
}

std::string formats_holding(CellKind kind, int dim) {
  if (kind == CellKind::simplices && dim >= 4) return ".txt, .idx or .npy";
  if (kind == CellKind::simplices && dim == 3) return ".vtu, .txt, .idx or .npy";
  if (dim == 3) return ".txt, .idx, .off, .obj, .ply, .stl, .vtu or .npy";
  return "all";
}

void refuse(const std::string& path, Format f, const std::string& why, CellKind kind, int dim) {
  throw std::invalid_argument(path + ": " + format_name(f) + " " + why + " (formats that hold this result: " +
                              formats_holding(kind, dim) + ")");
}

// Exactly collinear (2D or 3D points): every coordinate-plane projection has
// orient2d 0.
bool collinear(const PointSet& ps, Index a, Index b, Index c) {
  if (ps.dim == 2) return pred::orient2d_exact(ps.point(a), ps.point(b), ps.point(c)) == 0;
  return pred::collinear3_exact(ps.point(a), ps.point(b), ps.point(c));
}

std::string num(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round-trip decimal
  return std::string(buf, r.ptr);
}

// ---- CGAL writers ----------------------------------------------------------
using Soup = std::vector<std::vector<std::size_t>>;
Soup soup_of(const Vertices& v, const std::vector<std::vector<Index>>& cells) {
  Soup s;
  s.reserve(cells.size());
  for (const auto& c : cells) {
    std::vector<std::size_t> f;
    for (Index x : c) f.push_back(v.rank[x]);
    s.push_back(std::move(f));
  }
  return s;
}
std::vector<P3> points_of(const PointSet& ps, const Vertices& v) {
  std::vector<P3> pts;
  pts.reserve(v.used.size());
  for (Index i : v.used) pts.push_back(point3(ps, i));
  return pts;
}

void write_ply(std::ostream& os, const PointSet& ps, const Vertices& v, const std::vector<std::vector<Index>>& cells,
               bool ascii, const std::string& path) {
  using Mesh = CGAL::Surface_mesh<P3>;
  Mesh m;
  std::vector<Mesh::Vertex_index> vi;
  vi.reserve(v.used.size());
  auto [index_map, created] = m.add_property_map<Mesh::Vertex_index, std::uint32_t>("v:input_index", 0);
  (void)created;
  for (Index i : v.used) {
    vi.push_back(m.add_vertex(point3(ps, i)));
    index_map[vi.back()] = i;
  }
  for (const auto& c : cells) {
    std::vector<Mesh::Vertex_index> f;
    for (Index x : c) f.push_back(vi[v.rank[x]]);
    if (m.add_face(f) == Mesh::null_face())
      throw std::runtime_error(path + ": cannot write: the cells are not an oriented 2-manifold (PLY face " +
                               std::to_string(m.number_of_faces()) + ")");
  }
  if (!CGAL::IO::write_PLY(os, m, CGAL::parameters::use_binary_mode(!ascii).stream_precision(17)))
    throw std::runtime_error(path + ": cannot write: CGAL's PLY writer failed");
}

// ---- own writers (no maintained writer among the dependencies) -------------
void write_vtu(std::ostream& os, const PointSet& ps, const Vertices& v, const std::vector<std::vector<Index>>& cells,
               CellKind kind) {
  // VTK cell types: 5 triangle, 7 polygon, 10 tetra
  os << "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << v.used.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n"
     << "      <PointData>\n        <DataArray type=\"Int64\" Name=\"input_index\" format=\"ascii\">\n";
  for (Index i : v.used) os << "          " << i << "\n";
  os << "        </DataArray>\n      </PointData>\n"
        "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (Index i : v.used) {
    const double* x = ps.point(i);
    os << "          " << num(x[0]) << ' ' << num(x[1]) << ' ' << num(ps.dim >= 3 ? x[2] : 0.0) << "\n";
  }
  os << "        </DataArray>\n      </Points>\n      <Cells>\n"
        "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : cells) {
    os << "         ";
    for (Index x : c) os << ' ' << v.rank[x];
    os << "\n";
  }
  os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t off = 0;
  for (const auto& c : cells) os << "          " << (off += c.size()) << "\n";
  os << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const auto& c : cells) {
    const int type = kind == CellKind::simplices && c.size() == 4 ? 10 : (c.size() == 3 ? 5 : 7);
    os << "          " << type << "\n";
  }
  os << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

namespace {
// Writes `count` rows of k indices as little-endian int64, at(i, j) the
// index of row i, column j, through a 1 MiB buffer (one stream write per
// buffer, not per number: rt3's answer at 10^7 points has 2.7e8 of them).
template <class At>
void write_i8_rows(std::ostream& os, std::size_t count, std::size_t k, const At& at) {
  constexpr std::size_t kBuf = std::size_t{1} << 20;
  std::vector<char> buf(kBuf);
  std::size_t used = 0;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      if (used == kBuf) os.write(buf.data(), static_cast<std::streamsize>(used)), used = 0;
      const std::uint64_t u = static_cast<std::uint64_t>(static_cast<std::int64_t>(at(i, j)));
      for (int b = 0; b < 8; ++b) buf[used++] = static_cast<char>((u >> (8 * b)) & 0xff);
    }
  os.write(buf.data(), static_cast<std::streamsize>(used));
}
}  // namespace

void write_npy_indices(std::ostream& os, const std::vector<std::vector<Index>>& cells, bool one_cycle) {
  std::string shape;
  std::size_t k = cells.empty() ? 0 : cells[0].size();
  if (one_cycle) shape = "(" + std::to_string(k) + ",)";
  else shape = "(" + std::to_string(cells.size()) + ", " + std::to_string(k) + ")";
  write_npy_header(os, "<i8", shape);
  write_i8_rows(os, cells.size(), k, [&](std::size_t i, std::size_t j) { return cells[i][j]; });
}

void write_npy_indices(std::ostream& os, const Index* flat, std::size_t count, std::size_t k) {
  write_npy_header(os, "<i8", "(" + std::to_string(count) + ", " + std::to_string(k) + ")");
  write_i8_rows(os, count, k, [&](std::size_t i, std::size_t j) { return flat[i * k + j]; });
}

namespace {

void write_svg(std::ostream& os, const PointSet& ps, const std::vector<std::vector<Index>>& cells,
               const std::vector<Index>& marked) {
  // viewBox over the input's bounding box (y up: every y is negated), with a
  // margin; strokes scaled to the box
  double lo[2] = {ps.point(0)[0], ps.point(0)[1]}, hi[2] = {lo[0], lo[1]};
  for (Index i = 0; i < ps.size(); ++i)
    for (int j = 0; j < 2; ++j) {
      lo[j] = std::min(lo[j], ps.point(i)[j]);
      hi[j] = std::max(hi[j], ps.point(i)[j]);
    }
  double span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(span > 0) || !std::isfinite(span)) span = 1;
  const double m = span * 0.03, r = span * 0.004, sw = span * 0.0015;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << num(lo[0] - m) << ' ' << num(-hi[1] - m) << ' '
     << num(hi[0] - lo[0] + 2 * m) << ' ' << num(hi[1] - lo[1] + 2 * m) << "\" width=\"800\" height=\"800\">\n";
  os << "<g fill=\"#cfe3f7\" fill-opacity=\"0.5\" stroke=\"#1f4e79\" stroke-width=\"" << num(sw)
     << "\" stroke-linejoin=\"round\">\n";
  for (const auto& c : cells) {
    os << "<polygon points=\"";
    for (std::size_t j = 0; j < c.size(); ++j)
      os << (j ? " " : "") << num(ps.point(c[j])[0]) << ',' << num(-ps.point(c[j])[1]);
    os << "\"/>\n";
  }
  os << "</g>\n<g fill=\"#000\">\n";
  for (Index i = 0; i < ps.size(); ++i)
    os << "<circle cx=\"" << num(ps.point(i)[0]) << "\" cy=\"" << num(-ps.point(i)[1]) << "\" r=\"" << num(r)
       << "\"><title>" << i << "</title></circle>\n";
  os << "</g>\n<g stroke=\"#d62728\" stroke-width=\"" << num(sw * 1.5) << "\">\n";
  for (Index i : marked) {
    const double x = ps.point(i)[0], y = -ps.point(i)[1], a = 2.5 * r;
    os << "<path d=\"M" << num(x - a) << ',' << num(y - a) << "L" << num(x + a) << ',' << num(y + a) << "M"
       << num(x - a) << ',' << num(y + a) << "L" << num(x + a) << ',' << num(y - a) << "\"><title>" << i
       << " (redundant)</title></path>\n";
  }
  os << "</g>\n</svg>\n";
}

}  // namespace

Format output_format(const std::string& path) {
  if (path.empty() || path == "-") return Format::index;
  const std::string e = extension_of(path);
  for (const Ext& x : kExtensions)
    if (e == x.ext) return x.f;
  throw std::invalid_argument(path + ": unknown output extension '" + e +
                              "' (known: .txt .idx or none for index text, .off .obj .ply .stl .vtu meshes, .npy, .svg)");
}

const char* format_name(Format f) {
  switch (f) {
    case Format::index: return "index text";
    case Format::off: return "OFF";
    case Format::obj: return "OBJ";
    case Format::ply: return "PLY";
    case Format::stl: return "STL";
    case Format::vtu: return "VTU";
    case Format::npy: return "NPY";
    case Format::svg: return "SVG";
  }
  return "?";
}

std::vector<std::vector<Index>> fan_triangulate(const PointSet& ps, const std::vector<std::vector<Index>>& polygons) {
  std::vector<std::vector<Index>> out;
  for (const auto& p : polygons)
    for (std::size_t j = 1; j + 1 < p.size(); ++j)
      if (!collinear(ps, p[0], p[j], p[j + 1])) out.push_back({p[0], p[j], p[j + 1]});
  return out;
}

void write_cells(const std::string& path, Format f, const PointSet& ps, const std::vector<std::vector<Index>>& cells,
                 CellKind kind, const std::vector<Index>& marked, bool ascii) {
  if (f == Format::index) throw std::invalid_argument(path + ": index text is written by the caller");
  const int d = ps.dim;
  const bool surface = kind != CellKind::simplices || d == 2;  // d = 2 simplices are triangles
  if ((f == Format::off || f == Format::obj || f == Format::ply || f == Format::stl) && !surface)
    refuse(path, f, "holds polygons, not " + std::to_string(d) + "-simplices", kind, d);
  if (f == Format::vtu && !surface && d > 3) refuse(path, f, "has no " + std::to_string(d) + "-simplex cells", kind, d);
  if (f == Format::svg && d != 2) refuse(path, f, "draws 2D results only, this one is " + std::to_string(d) + "D", kind, d);
  if (f == Format::npy)
    for (const auto& c : cells)
      if (c.size() != cells[0].size())
        throw std::invalid_argument(path + ": NPY holds an array: the polygons have different numbers of vertices "
                                           "(triangulate them, e.g. hull3 --strict --triangulate)");
  const std::vector<std::vector<Index>> tris = f == Format::stl ? fan_triangulate(ps, cells) : std::vector<std::vector<Index>>{};
  const std::vector<std::vector<Index>>& written = f == Format::stl ? tris : cells;
  const Vertices v = used_vertices(ps.size(), written);
  write_file(path, [&](std::ostream& os) {
    // CGAL's stream writers take the mode from the stream, not from
    // use_binary_mode (that one is read by the file-name overloads)
    if ((f == Format::ply || f == Format::stl) && !ascii) CGAL::IO::set_binary_mode(os);
    else CGAL::IO::set_ascii_mode(os);
    switch (f) {
      case Format::off:
        if (!CGAL::IO::write_OFF(os, points_of(ps, v), soup_of(v, written), CGAL::parameters::stream_precision(17)))
          throw std::runtime_error(path + ": cannot write: CGAL's OFF writer failed");
        break;
      case Format::obj:
        if (!CGAL::IO::write_OBJ(os, points_of(ps, v), soup_of(v, written), CGAL::parameters::stream_precision(17)))
          throw std::runtime_error(path + ": cannot write: CGAL's OBJ writer failed");
        break;
      case Format::stl: {
        std::vector<std::array<std::size_t, 3>> t;
        for (const auto& c : soup_of(v, written)) t.push_back({c[0], c[1], c[2]});
        if (!CGAL::IO::write_STL(os, points_of(ps, v), t,
                                 CGAL::parameters::use_binary_mode(!ascii).stream_precision(17)))
          throw std::runtime_error(path + ": cannot write: CGAL's STL writer failed");
        break;
      }
      case Format::ply: write_ply(os, ps, v, written, ascii, path); break;
      case Format::vtu: write_vtu(os, ps, v, written, kind); break;
      case Format::npy: write_npy_indices(os, written, kind == CellKind::cycle); break;
      case Format::svg: write_svg(os, ps, written, marked); break;
      case Format::index: break;
    }
  });
}

}  // namespace flipflop::io

// read_ply.cpp — the .ply reader: CGAL's PLY reader behind a checked header.
//
// CGAL::IO::read_PLY_with_properties (Point_set_processing_3) reads the vertex
// properties x, y, z (and the weight `w` or `weight`). Its header parser adds
// no property of an unknown type (so the following values shift), fills a
// missing property with 0, and assumes coordinates are float or double. A
// streaming scan therefore checks the header first, and refuses, naming the
// line: unknown types, a property outside an element, a missing x/y (z for
// 3D), integer-typed coordinates, list properties in or before the vertex
// element (faces must follow the vertices — they are never read). Then:
//   ASCII   every vertex line is checked (one vertex per line, one value per
//           property, each a number of the property's type, coordinates
//           finite, z = 0 for dim 2), and problems name the line;
//   binary  the file size is checked against the header, and after CGAL has
//           decoded the vertices every coordinate is checked; problems name
//           the vertex number (0-based).
// CGAL is stopped after the last vertex (cgal_sink.hpp).
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "io/cgal_sink.hpp"
#include "io/decimal.hpp"
#include "io/formats.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace flipflop::io::detail {

namespace {

using Point_3 = CGAL::Simple_cartesian<double>::Point_3;
using Rec = std::pair<Point_3, double>;  // a vertex and its weight

// The scalar types of PLY (both spellings, as CGAL accepts them).
struct PlyType {
  const char* name;
  const char* alias;
  int bytes;
  bool real;
  long long lo, hi;  // range of an integer type
};
constexpr PlyType kTypes[] = {
    {"char", "int8", 1, false, -128, 127},
    {"uchar", "uint8", 1, false, 0, 255},
    {"short", "int16", 2, false, -32768, 32767},
    {"ushort", "uint16", 2, false, 0, 65535},
    {"int", "int32", 4, false, -2147483648LL, 2147483647LL},
    {"uint", "uint32", 4, false, 0, 4294967295LL},
    {"float", "float32", 4, true, 0, 0},
    {"double", "float64", 8, true, 0, 0},
};

const PlyType* find_type(std::string_view s) {
  for (const PlyType& t : kTypes)
    if (s == t.name || s == t.alias) return &t;
  return nullptr;
}

struct Property {
  std::string name;
  const PlyType* type = nullptr;
  bool list = false;
  std::size_t line = 0;
};

struct Element {
  std::string name;
  unsigned long long count = 0;
  std::vector<Property> props;
  std::size_t line = 0;
  int record_bytes() const {
    int b = 0;
    for (const Property& p : props) b += p.type->bytes;
    return b;
  }
};

enum class Format { ascii, little, big };

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::uint64_t data_offset = 0;  // first byte after "end_header\n"
};

Header scan_header(LineReader& in) {
  const std::string& path = in.path();
  Header h;
  std::string_view line;
  std::string_view tok[6];
  if (!in.next(line)) throw InputError(path, "empty file, no points");
  if (split(line, tok, 6) == 0 || tok[0] != "ply")
    throw InputError(path, 1, "not a PLY file: the first line must be 'ply'");
  if (!in.next(line)) throw InputError(path, 1, "end of file inside the PLY header");
  {
    const std::size_t k = split(line, tok, 6);
    if (k < 3 || tok[0] != "format")
      throw InputError(path, in.line_number(), "expected 'format FORMAT VERSION'");
    if (tok[1] == "ascii")
      h.format = Format::ascii;
    else if (tok[1] == "binary_little_endian")
      h.format = Format::little;
    else if (tok[1] == "binary_big_endian")
      h.format = Format::big;
    else
      throw InputError(path, in.line_number(), "unknown PLY format " + show(tok[1]));
  }
  for (;;) {
    if (!in.next(line))
      throw InputError(path, in.line_number(), "end of file inside the PLY header (no end_header)");
    const std::size_t ln = in.line_number();
    const std::size_t k = split(line, tok, 6);
    if (k == 0) throw InputError(path, ln, "blank line in the PLY header");
    if (tok[0] == "end_header") break;
    if (tok[0] == "element") {
      long long count = 0;
      if (k < 3 || !parse_integer(tok[2], 0, std::numeric_limits<long long>::max(), count))
        throw InputError(path, ln, "expected 'element NAME COUNT'");
      h.elements.push_back({std::string(tok[1]), static_cast<unsigned long long>(count), {}, ln});
    } else if (tok[0] == "property") {
      if (h.elements.empty()) throw InputError(path, ln, "property before any element");
      Property p;
      p.line = ln;
      if (k >= 2 && tok[1] == "list") {
        if (k < 5) throw InputError(path, ln, "expected 'property list SIZE_TYPE INDEX_TYPE NAME'");
        const PlyType* size_type = find_type(tok[2]);
        p.type = find_type(tok[3]);
        if (size_type == nullptr || size_type->real || p.type == nullptr)
          throw InputError(path, ln, "unsupported list types " + show(tok[2]) + " " + show(tok[3]));
        p.list = true;
        p.name = std::string(tok[4]);
      } else {
        if (k < 3) throw InputError(path, ln, "expected 'property TYPE NAME'");
        p.type = find_type(tok[1]);
        if (p.type == nullptr) throw InputError(path, ln, "unknown property type " + show(tok[1]));
        p.name = std::string(tok[2]);
      }
      h.elements.back().props.push_back(p);
    }
    // "comment", "obj_info" and other keywords are ignored, as CGAL does.
  }
  h.data_offset = in.offset();
  return h;
}

const Property* find_prop(const Element& e, const char* name) {
  for (const Property& p : e.props)
    if (p.name == name) return &p;  // CGAL takes the first of a name
  return nullptr;
}

std::string shortest(double v) {
  std::string s;
  put_decimal(s, v);
  return s;
}

// Checks the ASCII data of the elements up to and including the vertices:
// one item per non-blank line, one token per property, each a finite number
// of its property's type; z == 0 for dim 2.
void scan_ascii(LineReader& in, const Header& h, std::size_t vi, int dim) {
  const std::string& path = in.path();
  std::string_view line;
  std::vector<std::string_view> tok;
  for (std::size_t e = 0; e <= vi; ++e) {
    const Element& el = h.elements[e];
    const bool vertices = e == vi;
    std::string names;
    for (const Property& p : el.props) names += (names.empty() ? "" : " ") + p.name;
    tok.resize(el.props.size() + 1);
    for (unsigned long long item = 0; item < el.count; ++item) {
      std::size_t k = 0;
      do {
        if (!in.next(line))
          throw InputError(path, in.line_number(),
                           "end of file after " + std::to_string(item) + " of the " +
                               std::to_string(el.count) + " items of element '" + el.name +
                               "' declared on line " + std::to_string(el.line));
        k = split(line, tok.data(), tok.size());
      } while (k == 0);
      const std::size_t ln = in.line_number();
      if (k != el.props.size())
        throw InputError(path, ln,
                         "expected " + std::to_string(el.props.size()) + " values (" + names +
                             "), found " + std::to_string(k));
      for (std::size_t c = 0; c < k; ++c) {
        const Property& p = el.props[c];
        Num s = Num::ok;
        double v = 0;
        if (!p.type->real) {
          long long iv = 0;
          if (!parse_integer(tok[c], p.type->lo, p.type->hi, iv))
            throw InputError(path, ln,
                             show(tok[c]) + " is not a " + p.type->name + " (property " + p.name +
                                 ")");
          continue;
        }
        if (p.type->bytes == 4) {
          float f = 0;
          s = parse_real(tok[c], f);
          v = f;
        } else {
          s = parse_real(tok[c], v);
        }
        if (s != Num::ok)
          throw InputError(path, ln,
                           describe(s, tok[c], p.type->name) + " in property " + p.name);
        if (vertices && dim == 2 && p.name == "z" && v != 0.0)
          throw InputError(path, ln,
                           "z = " + shortest(v) + " is not 0 (vertex " + std::to_string(item) +
                               "); a 2D input needs z = 0 for every vertex");
      }
    }
  }
}

}  // namespace

PointSet read_ply(const std::string& path, int dim, bool weighted) {
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;

  LineReader in(path);
  const Header h = scan_header(in);

  // ---- The vertex element and its properties -------------------------------
  std::size_t vi = h.elements.size();
  for (std::size_t e = 0; e < h.elements.size(); ++e) {
    const Element& el = h.elements[e];
    if (el.name != "vertex" && el.name != "vertices") continue;
    if (vi != h.elements.size())
      throw InputError(path, el.line, "a second vertex element (CGAL would read both)");
    vi = e;
  }
  if (vi == h.elements.size()) throw InputError(path, in.line_number(), "no vertex element in the header");
  for (std::size_t e = 0; e <= vi; ++e) {
    // CGAL loops over every item of an element, reading its properties: an
    // element with items but no properties reads no bytes, so its count is
    // bounded by nothing in the file (a count of 10^12 kept CGAL busy for
    // hours, found by fuzz_read_points). No PLY writer emits one.
    if (e < vi && h.elements[e].props.empty() && h.elements[e].count > 0)
      throw InputError(path, h.elements[e].line,
                       "element '" + h.elements[e].name + "' declares " +
                           std::to_string(h.elements[e].count) + " items but no properties");
    for (const Property& p : h.elements[e].props)
      if (p.list)
        throw InputError(path, p.line,
                         "list property '" + p.name + "' in element '" + h.elements[e].name +
                             "'; flipflop reads PLY files whose lists (faces) follow the vertices");
  }
  const Element& ve = h.elements[vi];
  const char* needed[] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    const Property* p = find_prop(ve, needed[c]);
    if (p == nullptr) {
      if (c < dim) throw InputError(path, ve.line, std::string("no vertex property ") + needed[c]);
      continue;
    }
    if (!p->type->real)
      throw InputError(path, p->line,
                       std::string("property ") + needed[c] + " has type " + p->type->name +
                           "; coordinates must be float or double");
  }
  const char* weight_name = nullptr;
  if (weighted) {
    weight_name = find_prop(ve, "w") != nullptr ? "w" : find_prop(ve, "weight") != nullptr ? "weight" : nullptr;
    if (weight_name == nullptr)
      throw InputError(path, ve.line,
                       "no vertex property 'w' or 'weight'; give weighted points as a PLY vertex "
                       "property w, or as .xyz with the weight as the last column");
    if (!find_prop(ve, weight_name)->type->real)
      throw InputError(path, find_prop(ve, weight_name)->line,
                       std::string("weight property ") + weight_name + " must be float or double");
  }
  if (ve.count == 0) throw InputError(path, ve.line, "no points (the header declares 0 vertices)");
  if (ve.count > std::numeric_limits<Index>::max())
    throw InputError(path, ve.line,
                     "more than " + std::to_string(std::numeric_limits<Index>::max()) + " points");
  const auto n = static_cast<std::size_t>(ve.count);

  // ---- The data: lines (ASCII) or size (binary) -----------------------------
  if (h.format == Format::ascii) {
    scan_ascii(in, h, vi, dim);
  } else {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path, "cannot read: " + ec.message());
    // Bytes before the vertices; each count is checked against the size
    // first, so that no product overflows.
    std::uintmax_t start = h.data_offset;
    for (std::size_t e = 0; e < vi; ++e) {
      const auto rec = static_cast<std::uintmax_t>(h.elements[e].record_bytes());
      if (rec > 0 && h.elements[e].count > (size - std::min(size, start)) / rec)
        throw InputError(path, "the file ends inside element '" + h.elements[e].name +
                                   "' (binary PLY is truncated)");
      start += h.elements[e].count * rec;
    }
    const auto rec = static_cast<std::uintmax_t>(ve.record_bytes());
    const std::uintmax_t room = size - std::min(size, start);
    if (room / rec < n) {
      const std::uintmax_t k = room / rec;
      throw InputError(path, "vertex " + std::to_string(k) + ": the file ends inside vertex " +
                                 std::to_string(k) + " of " + std::to_string(n) +
                                 " (binary PLY is truncated)");
    }
  }

  // ---- CGAL reads the vertices ----------------------------------------------
  ps.coords.reserve(n * static_cast<std::size_t>(dim));
  if (weighted) ps.weights.reserve(n);
  std::size_t count = 0;
  auto put = [&](const Rec& r) {
    const Point_3& p = r.first;
    const double x[4] = {p.x(), p.y(), p.z(), r.second};
    auto finite = [&](double v, const char* name) {
      if (!std::isfinite(v))
        throw InputError(path, "vertex " + std::to_string(count) + ": " +
                                   (std::isnan(v) ? "NaN" : "Inf") + " in property " + name);
    };
    for (int c = 0; c < dim; ++c) finite(x[c], needed[c]);
    if (weighted) finite(x[3], weight_name);
    if (dim == 2 && x[2] != 0.0)
      throw InputError(path, "vertex " + std::to_string(count) + ": z = " + shortest(x[2]) +
                                 " is not 0; a 2D input needs z = 0 for every vertex");
    ps.coords.insert(ps.coords.end(), x, x + dim);
    if (weighted) ps.weights.push_back(x[3]);
  };
  using Sink = CgalSink<Rec, decltype(put)>;
  const auto point_map = CGAL::First_of_pair_property_map<Rec>();
  const auto weight_map = CGAL::Second_of_pair_property_map<Rec>();
  std::ifstream is(path, std::ios::binary);
  try {
    if (weighted)
      CGAL::IO::read_PLY_with_properties(
          is, Sink(n, &count, put), CGAL::IO::make_ply_point_reader(point_map),
          std::make_pair(weight_map, CGAL::IO::PLY_property<double>(weight_name)));
    else
      CGAL::IO::read_PLY_with_properties(is, Sink(n, &count, put),
                                         CGAL::IO::make_ply_point_reader(point_map));
  } catch (const Enough&) {
  }
  if (count != n)
    throw InputError(path, "vertex " + std::to_string(count) + ": CGAL's PLY reader stopped after " +
                               std::to_string(count) + " of " + std::to_string(n) + " vertices");
  check_count(ps, path, ve.line);
  return ps;
}

}  // namespace flipflop::io::detail

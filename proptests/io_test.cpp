// io_test.cpp — properties and error reports of io/ (point files, canonical
// index output, index readers).
//
// Oracles: bit patterns of the doubles written (round trips), CGAL's own
// writers for .off/.ply, the qhull program for Qhull's output format, and
// hand-built files whose faulty line is known by construction.
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <CGAL/IO/write_off_points.h>
#include <CGAL/IO/write_ply_points.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "gen/generate.hpp"
#include "reference/certify/certify.hpp"
#include "io/formats.hpp"
#include "io/io.hpp"
#include "io/write_result.hpp"

namespace fs = std::filesystem;
using namespace flipflop;
using io::InputError;

namespace {

// A fresh directory under the system temp dir, removed at the end of a test.
struct TempDir {
  fs::path dir;
  TempDir() {
    static int counter = 0;
    dir = fs::temp_directory_path() /
          ("flipflop_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string file(const std::string& name, const std::string& content) const {
    const std::string p = (dir / name).string();
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

double from_bits(std::uint64_t b) {
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// Runs f, which must throw InputError; returns it.
InputError error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no InputError thrown");
  throw std::logic_error("unreachable");
}

// The error names the file and the line ("FILE:LINE: ...", or "FILE: ..." for
// line 0), is one line, and mentions `what`.
void check_error(const InputError& e, const std::string& file, std::size_t line,
                 const std::string& what) {
  const std::string msg = e.what();
  INFO(msg);
  CHECK(e.file() == file);
  CHECK(e.line() == line);
  const std::string prefix = line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
  CHECK(msg.compare(0, prefix.size(), prefix) == 0);
  CHECK(msg.find('\n') == std::string::npos);
  CHECK(msg.find(what) != std::string::npos);
}

void expect_error(const std::string& file, int dim, bool weighted, std::size_t line,
                  const std::string& what) {
  check_error(error_of([&] { io::read_points(file, dim, weighted); }), file, line, what);
}

// Finite doubles of every kind: any bit pattern, subnormals, ±1e±300,
// boundary values.
rc::Gen<double> finite_double() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::suchThat(rc::gen::arbitrary<std::uint64_t>(),
                                     [](std::uint64_t b) { return std::isfinite(from_bits(b)); }),
                   from_bits),
      rc::gen::map(rc::gen::pair(rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 52),
                                 rc::gen::arbitrary<bool>()),
                   [](std::pair<std::uint64_t, bool> p) {
                     return from_bits(p.first | (p.second ? std::uint64_t{1} << 63 : 0));
                   }),
      rc::gen::map(rc::gen::inRange(-1000000, 1000000), [](int k) { return k * 1.2345678901e294; }),
      rc::gen::map(rc::gen::inRange(-1000000, 1000000), [](int k) { return k * 1.2345678901e-306; }),
      rc::gen::element(0.0, -0.0, DBL_MAX, -DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 0.1, 1.0 / 3.0,
                       1e300, 1e-300));
}

rc::Gen<PointSet> point_set() {
  return rc::gen::mapcat(
      rc::gen::pair(rc::gen::inRange(2, 4), rc::gen::arbitrary<bool>()), [](std::pair<int, bool> p) {
        return rc::gen::mapcat(rc::gen::inRange(p.first + 1, 40), [p](int n) {
          const auto nc = static_cast<std::size_t>(n * p.first);
          return rc::gen::map(
              rc::gen::pair(rc::gen::container<std::vector<double>>(nc, finite_double()),
                            rc::gen::container<std::vector<double>>(p.second ? n : 0,
                                                                    finite_double())),
              [p](std::pair<std::vector<double>, std::vector<double>> v) {
                PointSet ps;
                ps.dim = p.first;
                ps.weighted = p.second;
                ps.coords = std::move(v.first);
                ps.weights = std::move(v.second);
                return ps;
              });
        });
      });
}

using K = CGAL::Simple_cartesian<double>;
using Point_3 = K::Point_3;

std::vector<Point_3> as_points3(const PointSet& ps) {
  std::vector<Point_3> v;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double* p = ps.point(i);
    v.emplace_back(p[0], p[1], ps.dim == 3 ? p[2] : 0.0);
  }
  return v;
}

// Writes ps (z = 0 in 2D) with CGAL's PLY writer, ASCII (17 digits) or
// binary, with the weights as property "w" when weighted.
std::string write_ply_cgal(const TempDir& t, const std::string& name, const PointSet& ps,
                           bool binary) {
  const std::string path = t.path(name);
  std::ofstream os(path, std::ios::binary);
  CGAL::IO::set_mode(os, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  os.precision(17);
  using Rec = std::pair<Point_3, double>;
  std::vector<Rec> recs;
  const std::vector<Point_3> pts = as_points3(ps);
  for (std::size_t i = 0; i < pts.size(); ++i) recs.emplace_back(pts[i], ps.weight(i));
  bool ok;
  if (ps.weighted)
    ok = CGAL::IO::write_PLY_with_properties(
        os, recs, CGAL::IO::make_ply_point_writer(CGAL::First_of_pair_property_map<Rec>()),
        std::make_pair(CGAL::Second_of_pair_property_map<Rec>(), CGAL::IO::PLY_property<double>("w")));
  else
    ok = CGAL::IO::write_PLY_with_properties(
        os, recs, CGAL::IO::make_ply_point_writer(CGAL::First_of_pair_property_map<Rec>()));
  REQUIRE(ok);
  return path;
}

PointSet random_points(std::uint64_t seed, int dim, std::size_t n, bool weighted) {
  std::mt19937_64 g(seed);
  PointSet ps;
  ps.dim = dim;
  ps.weighted = weighted;
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i) {
    const int kind = static_cast<int>(g() % 4);
    const double u = static_cast<double>(g() >> 11) * 0x1p-53 - 0.5;
    ps.coords.push_back(kind == 0 ? u : kind == 1 ? u * 1e300 : kind == 2 ? u * 1e-300 : u * 0x1p-1060);
  }
  for (std::size_t i = 0; weighted && i < n; ++i)
    ps.weights.push_back(static_cast<double>(g() >> 11) * 0x1p-60);
  return ps;
}

}  // namespace

// ---------------------------------------------------------------------------
// .xyz
// ---------------------------------------------------------------------------

TEST_CASE("xyz: write_points then read_points is the identity, bit for bit") {
  TempDir t;
  const std::string path = t.path("p.xyz");
  rc::prop("round trip", [&] {
    const PointSet ps = *point_set();
    fs::remove(path);  // a new file: rewriting in place (truncation) can force a flush to disk
    io::write_file(path, [&](std::ostream& os) { io::write_points(os, ps); });
    const PointSet q = io::read_points(path, ps.dim, ps.weighted);
    RC_ASSERT(q.dim == ps.dim);
    RC_ASSERT(q.weighted == ps.weighted);
    RC_ASSERT(same_bits(q.coords, ps.coords));
    RC_ASSERT(same_bits(q.weights, ps.weights));
  });
}

TEST_CASE("xyz: every generated distribution round-trips bit for bit") {
  TempDir t;
  const std::string path = t.path("g.xyz");
  for (const std::string& d : gen::distributions()) {
    gen::Options o;
    o.seed = 7;
    o.weighted = true;
    o.wlo = -1e-300;
    o.whi = 1e300;
    const PointSet ps = gen::generate(d, 200, o);
    io::write_file(path, [&](std::ostream& os) { io::write_points(os, ps); });
    const PointSet q = io::read_points(path, ps.dim, true);
    INFO(d);
    CHECK(same_bits(q.coords, ps.coords));
    CHECK(same_bits(q.weights, ps.weights));
  }
}

TEST_CASE("xyz: comments, blank lines, CRLF, signs, upper-case extension") {
  TempDir t;
  const std::string p = t.file("c.XYZ",
                               "# header comment\r\n"
                               "\r\n"
                               "  1.5\t-2   # trailing comment\r\n"
                               "+3 4e-1\n"
                               "\n"
                               "   # indented comment\n"
                               "-0 1e-400\n"
                               "5 6");  // no final newline
  const PointSet ps = io::read_points(p, 2, false);
  REQUIRE(ps.size() == 4);
  const std::vector<double> want = {1.5, -2, 3, 0.4, -0.0, 0.0, 5, 6};
  CHECK(same_bits(ps.coords, want));  // 1e-400 rounds to +0, "-0" stays -0
}

TEST_CASE("xyz: each error names the file and the line") {
  TempDir t;
  SECTION("missing file") {
    const std::string p = t.path("missing.xyz");
    expect_error(p, 2, false, 0, "cannot open");
  }
  SECTION("a directory") {
    const std::string p = t.path("dir.xyz");
    fs::create_directories(p);
    expect_error(p, 2, false, 0, "cannot read");
  }
  SECTION("empty file") { expect_error(t.file("e.xyz", ""), 2, false, 0, "no points"); }
  SECTION("only comments") {
    expect_error(t.file("c.xyz", "# a\n\n  # b\n"), 2, false, 3, "no points");
  }
  SECTION("malformed number") {
    expect_error(t.file("m.xyz", "0 0\n1 0\n1 abc\n0 1\n"), 2, false, 3, "'abc'");
    expect_error(t.file("m2.xyz", "0 0 0\n1 0 0\n0 1 0.5.5\n0 0 1\n"), 3, false, 3, "'0.5.5'");
    expect_error(t.file("m3.xyz", "0 0\n1e 0\n"), 2, false, 2, "malformed number '1e'");
    expect_error(t.file("m4.xyz", "0 0\n0x1p3 0\n"), 2, false, 2, "'0x1p3'");
    expect_error(t.file("m5.xyz", "0 0\n0,5 1\n"), 2, false, 2, "'0,5'");
  }
  SECTION("wrong column count") {
    expect_error(t.file("w.xyz", "0 0\n1 0 7\n"), 2, false, 2, "expected 2 columns (x y), found 3");
    expect_error(t.file("w2.xyz", "0 0 1\n1 0\n"), 2, true, 2, "expected 3 columns (x y w), found 2");
    expect_error(t.file("w3.xyz", "\n\n0 0\n"), 3, false, 3, "expected 3 columns (x y z), found 2");
  }
  SECTION("NaN and Inf") {
    expect_error(t.file("n.xyz", "0 0\n1 nan\n"), 2, false, 2, "NaN");
    expect_error(t.file("i.xyz", "0 0\n1 0\n-inf 1\n"), 2, false, 3, "Inf");
    expect_error(t.file("i2.xyz", "0 0 0\n1 1 Infinity\n"), 2, true, 2, "Inf");
    expect_error(t.file("o.xyz", "0 0\n1e999 1\n"), 2, false, 2, "overflows to Inf");
    expect_error(t.file("nw.xyz", "0 0 1\n1 0 nan\n"), 2, true, 2, "column 3 (w)");
  }
  SECTION("too few points") {
    expect_error(t.file("f.xyz", "0 0\n1 1\n# end\n"), 2, false, 3, "2 points, at least 3 needed");
    expect_error(t.file("f3.xyz", "0 0 0\n1 1 1\n2 0 0\n"), 3, false, 3,
                 "3 points, at least 4 needed");
  }
  SECTION("unknown extension") {
    expect_error(t.file("p.txt", "0 0\n1 0\n0 1\n"), 2, false, 0, "unknown file extension");
    expect_error(t.file("noext", "0 0\n1 0\n0 1\n"), 2, false, 0, "unknown file extension");
  }
  SECTION("a line longer than the limit") {
    expect_error(t.file("l.xyz", "0 0\n" + std::string(200000, '1') + "\n"), 2, false, 2,
                 "line longer than");
  }
  SECTION("a long comment is fine") {
    const std::string p =
        t.file("lc.xyz", "0 0 #" + std::string(3000000, 'c') + "\n1 0\n0 1 #" +
                             std::string(100000, 'd'));
    CHECK(io::read_points(p, 2, false).size() == 3);
  }
}

TEST_CASE("a huge file of garbage gives one error line, about its beginning") {
  TempDir t;
  // 2 GiB of zero bytes (a sparse file: no disk used): no line end in sight.
  for (const char* ext : {".xyz", ".off", ".ply"}) {
    const std::string p = t.path(std::string("zeros") + ext);
    { std::ofstream(p, std::ios::binary).put('\0'); }
    fs::resize_file(p, std::uintmax_t{2} << 30);
    const InputError e = error_of([&] { io::read_points(p, 3, false); });
    INFO(e.what());
    CHECK(e.line() == 1);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
    CHECK(std::string(e.what()).rfind(p + ":1: ", 0) == 0);
  }
  // A valid first line, then 2 GiB of zeros.
  {
    const std::string p = t.path("tail.xyz");
    { std::ofstream(p, std::ios::binary) << "0 0 0\n"; }
    fs::resize_file(p, std::uintmax_t{2} << 30);
    const InputError e = error_of([&] { io::read_points(p, 3, false); });
    CHECK(e.line() == 2);
  }
  // 8 MiB of random bytes.
  {
    std::mt19937_64 g(42);
    std::string junk(8u << 20, '\0');
    for (char& c : junk) c = static_cast<char>(g());
    for (const char* ext : {".xyz", ".off", ".ply"}) {
      const std::string p = t.file(std::string("junk") + ext, junk);
      const InputError e = error_of([&] { io::read_points(p, 2, false); });
      INFO(e.what());
      CHECK(e.line() >= 1);
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
  }
}

// ---------------------------------------------------------------------------
// .off (CGAL's point reader behind a checking scan)
// ---------------------------------------------------------------------------

TEST_CASE("off: points written by CGAL's OFF writer read back exactly") {
  TempDir t;
  for (int dim : {2, 3}) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const PointSet ps = random_points(seed, dim, 4 + seed * 7, false);
      const std::string p = t.path("c.off");
      {
        std::ofstream os(p);
        REQUIRE(CGAL::IO::write_OFF(os, as_points3(ps), CGAL::parameters::stream_precision(17)));
      }
      const PointSet q = io::read_points(p, dim, false);
      CHECK(same_bits(q.coords, ps.coords));
    }
  }
}

TEST_CASE("off: comments, NOFF normals, faces after the vertices are not read") {
  TempDir t;
  const std::string p = t.file("a.off",
                               "# made by hand\n"
                               "OFF\n"
                               "\n"
                               "4 2 0  # counts\n"
                               "0 0 0\n"
                               "# between vertices\n"
                               "1 0 0   # a comment\n"
                               "   \n"
                               "0 1 0\n"
                               "0 0 1 0.1 0.2 0.3\n"
                               "3 0 1 2\n"
                               "this line is garbage and never read\n");
  const PointSet ps = io::read_points(p, 3, false);
  CHECK(ps.coords == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  const std::string n = t.file("n.off", "NOFF\n3 0 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n");
  CHECK(io::read_points(n, 2, false).coords == std::vector<double>{0, 0, 1, 0, 0, 1});
}

TEST_CASE("off: each error names the file and the line") {
  TempDir t;
  const std::string tri = "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_error(t.file("w.off", tri), 2, true, 0, ".xyz");
  expect_error(t.file("c.off", "# c\nCOFF\n3 0 0\n"), 2, false, 2, "unsupported OFF variant 'COFF'");
  expect_error(t.file("x.off", "PLY\n"), 2, false, 1, "not an OFF file");
  expect_error(t.file("k.off", "OFF 3 0 0\n0 0 0\n"), 2, false, 1, "own line");
  expect_error(t.file("b.off", "OFF BINARY\n"), 2, false, 1, "binary OFF");
  expect_error(t.file("h.off", "OFF\n3 0\n"), 2, false, 2, "3 counts");
  expect_error(t.file("h2.off", "OFF\n-3 0 0\n"), 2, false, 2, "'-3'");
  expect_error(t.file("e.off", "OFF\n"), 2, false, 1, "end of file inside the OFF header");
  expect_error(t.file("t.off", "OFF\n5 0 0\n0 0 0\n1 0 0\n\n0 1 0\n"), 2, false, 6,
               "end of file after 3 of the 5 vertices declared on line 2");
  expect_error(t.file("m.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1x 0\n"), 2, false, 5, "'1x'");
  expect_error(t.file("n.off", "OFF\n3 0 0\n0 0 0\n1 nan 0\n0 1 0\n"), 3, false, 4, "NaN");
  expect_error(t.file("i.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 inf\n"), 3, false, 5, "Inf");
  expect_error(t.file("4.off", "OFF\n3 0 0\n0 0 0 1\n"), 3, false, 3, "found 4");
  expect_error(t.file("nn.off", "NOFF\n3 0 0\n0 0 0\n"), 3, false, 3, "expected 6 numbers");
  expect_error(t.file("z.off", "OFF\n3 0 0\n0 0 0\n1 0 0.5\n0 1 0\n"), 2, false, 4,
               "z = '0.5' is not 0 (vertex 1)");
  expect_error(t.file("0.off", "OFF\n0 0 0\n"), 3, false, 2, "no points");
  expect_error(t.file("few.off", tri), 3, false, 2, "3 points, at least 4 needed");
  expect_error(t.file("blank.off", " \nOFF\n"), 3, false, 1, "blank line");
}

// ---------------------------------------------------------------------------
// .ply (CGAL's PLY reader behind a checked header)
// ---------------------------------------------------------------------------

TEST_CASE("ply: ASCII and binary files written by CGAL read back exactly, weights too") {
  TempDir t;
  for (int dim : {2, 3})
    for (bool weighted : {false, true})
      for (bool binary : {false, true})
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
          const PointSet ps = random_points(seed * 31 + static_cast<std::uint64_t>(dim), dim,
                                            5 + seed * 13, weighted);
          const std::string p = write_ply_cgal(t, "c.ply", ps, binary);
          const PointSet q = io::read_points(p, dim, weighted);
          INFO("dim " << dim << " weighted " << weighted << " binary " << binary);
          CHECK(same_bits(q.coords, ps.coords));
          CHECK(same_bits(q.weights, ps.weights));
        }
}

namespace {

// A binary PLY by hand: a header, then records of `double` values in the
// given byte order.
std::string binary_ply(bool big_endian, const std::string& props, std::size_t count,
                       const std::vector<double>& values, const std::string& tail = "") {
  std::string s = std::string("ply\nformat ") +
                  (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment hand made\nelement vertex " + std::to_string(count) + "\n" +
                  props + tail + "end_header\n";
  for (double v : values) {
    char b[8];
    std::memcpy(b, &v, 8);
    if (big_endian) std::reverse(b, b + 8);
    s.append(b, 8);
  }
  return s;
}

const std::string kXYZ = "property double x\nproperty double y\nproperty double z\n";

}  // namespace

TEST_CASE("ply: big-endian binary and extra properties and faces") {
  TempDir t;
  const std::vector<double> v = {0.1, 0.2, 0.3, -1e300, 5e-324, 2, 3, 4, 5, 6, 7, 8};
  const std::string p = t.file("big.ply", binary_ply(true, kXYZ, 4, v,
                                                     "element face 1\nproperty list uchar int vertex_indices\n") +
                                              "\x03\x00\x00\x00\x00");
  CHECK(same_bits(io::read_points(p, 3, false).coords, v));
  const std::string a = t.file("a.ply",
                               "ply\r\nformat ascii 1.0\r\nobj_info x\r\nelement vertex 3\r\n"
                               "property float x\r\nproperty uchar red\r\nproperty float y\r\n"
                               "property double w\r\n"
                               "element face 1\r\nproperty list uchar int vertex_indices\r\n"
                               "end_header\r\n"
                               "0.5 255 1 0.25\r\n\r\n-1 0 2 1e-3\r\n3 7 +4 2\r\n3 0 1 2\r\n");
  const PointSet q = io::read_points(a, 2, true);
  CHECK(q.coords == std::vector<double>{0.5, 1, -1, 2, 3, 4});
  CHECK(q.weights == std::vector<double>{0.25, 1e-3, 2});
  // Binary float properties, the weight named "weight", a uchar in between.
  std::string f = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                  "property uchar tag\nproperty float y\nproperty float weight\nend_header\n";
  const float fv[3][3] = {{0.1f, 0.2f, 0.3f}, {-1e30f, 1e-45f, 0.5f}, {3, 4, 5}};
  for (const auto& row : fv) {
    f.append(reinterpret_cast<const char*>(&row[0]), 4);
    f.push_back('\x7f');
    f.append(reinterpret_cast<const char*>(&row[1]), 8);
  }
  const PointSet w = io::read_points(t.file("f.ply", f), 2, true);
  CHECK(w.coords == std::vector<double>{0.1f, 0.2f, -1e30f, 1e-45f, 3, 4});
  CHECK(w.weights == std::vector<double>{0.3f, 0.5f, 5});
}

TEST_CASE("ply: each error names the file and the line, or the vertex") {
  TempDir t;
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\n" + kXYZ + "end_header\n";
  // ASCII data: lines.
  expect_error(t.file("m.ply", head + "0 0 0\n1 0 zz\n0 1 0\n"), 3, false, 9, "'zz'");
  expect_error(t.file("n.ply", head + "0 0 0\n1 0 0\nnan 1 0\n"), 3, false, 10, "NaN");
  expect_error(t.file("c.ply", head + "0 0 0\n1 0\n0 1 0\n"), 3, false, 9,
               "expected 3 values (x y z), found 2");
  expect_error(t.file("e.ply", head + "0 0 0\n1 0 0\n"), 2, false, 9, "end of file after 2 of the 3");
  expect_error(t.file("z.ply", head + "0 0 0\n1 0 0\n0 1 1e-3\n"), 2, false, 10,
               "z = 0.001 is not 0 (vertex 2)");
  expect_error(t.file("i.ply",
                      "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\nend_header\n"),
               2, false, 4, "coordinates must be float or double");
  expect_error(t.file("r.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property uchar q\nend_header\n0 0 1\n1 0 300\n0 1 2\n"),
               2, false, 9, "'300' is not a uchar");
  expect_error(t.file("of.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "end_header\n0 0\n1e39 0\n0 1\n"),
               2, false, 8, "overflows to Inf as a float");
  // Header.
  expect_error(t.file("h1.ply", "plx\n"), 3, false, 1, "not a PLY file");
  expect_error(t.file("h2.ply", "ply\nformat ebcdic 1.0\n"), 3, false, 2, "unknown PLY format");
  expect_error(t.file("h3.ply", "ply\nformat ascii 1.0\nproperty float x\n"), 3, false, 3,
               "property before any element");
  expect_error(t.file("h4.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\n"), 3,
               false, 4, "unknown property type 'quad'");
  expect_error(t.file("h5.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"), 3, false, 3,
               "no end_header");
  expect_error(t.file("h6.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "end_header\n"),
               3, false, 3, "no vertex property z");
  expect_error(t.file("h7.ply",
                      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                      "element vertex 3\n" + kXYZ + "end_header\n"),
               3, false, 4, "list property 'vertex_indices'");
  expect_error(t.file("h8.ply", "ply\nformat ascii 1.0\nelement face 3\nend_header\n"), 3, false, 4,
               "no vertex element");
  expect_error(t.file("w.ply", head + "0 0 0\n1 0 0\n0 1 0\n"), 2, true, 3, "'w' or 'weight'");
  expect_error(t.file("0.ply", "ply\nformat ascii 1.0\nelement vertex 0\n" + kXYZ + "end_header\n"),
               3, false, 3, "no points");
  expect_error(t.file("few.ply", head + "0 0 0\n1 0 0\n0 1 0\n"), 3, false, 3,
               "3 points, at least 4 needed");
  // Binary data: vertex numbers.
  const std::vector<double> good = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::string trunc = binary_ply(false, kXYZ, 4, good);
  trunc.resize(trunc.size() - 3);
  expect_error(t.file("t.ply", trunc), 3, false, 0, "vertex 3: the file ends inside vertex 3 of 4");
  std::vector<double> bad = good;
  bad[7] = std::nan("");
  expect_error(t.file("bn.ply", binary_ply(false, kXYZ, 4, bad)), 3, false, 0, "vertex 2: NaN in property y");
  bad = good;
  bad[11] = -INFINITY;
  expect_error(t.file("bi.ply", binary_ply(true, kXYZ, 4, bad)), 3, false, 0, "vertex 3: Inf in property z");
  expect_error(t.file("bz.ply", binary_ply(false, kXYZ, 4, good)), 2, false, 0,
               "vertex 3: z = 1 is not 0");
  // An element with items but no properties before the vertices: CGAL would
  // loop over its 10^12 items, reading nothing (a hang fuzz_read_points found).
  std::string empty_element = binary_ply(false, kXYZ, 4, good);
  const std::string format_line = "format binary_little_endian 1.0\n";
  REQUIRE(empty_element.find(format_line) != std::string::npos);
  empty_element.insert(empty_element.find(format_line) + format_line.size(),
                       "element foo 1000000000000\n");
  expect_error(t.file("be.ply", empty_element), 3, false, 3,
               "element 'foo' declares 1000000000000 items but no properties");
  expect_error(t.file("ae.ply", "ply\nformat ascii 1.0\nelement foo 2\nelement vertex 4\n" + kXYZ +
                                    "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"),
               3, false, 3, "element 'foo' declares 2 items but no properties");
}

// ---------------------------------------------------------------------------
// Canonical output and index files
// ---------------------------------------------------------------------------

namespace {

// Triangles with distinct vertices, and no two on the same vertex set.
rc::Gen<std::vector<Triangle>> triangle_list() {
  return rc::gen::map(rc::gen::container<std::vector<std::array<Index, 3>>>(
                          rc::gen::container<std::array<Index, 3>>(rc::gen::inRange<Index>(0, 30))),
                      [](std::vector<std::array<Index, 3>> v) {
                        std::vector<Triangle> out;
                        std::set<std::set<Index>> seen;
                        for (const auto& t : v) {
                          const std::set<Index> s(t.begin(), t.end());
                          if (s.size() == 3 && seen.insert(s).second) out.push_back(t);
                        }
                        return out;
                      });
}

bool is_rotation(const Triangle& a, const Triangle& b) {
  return a == b || a == Triangle{b[1], b[2], b[0]} || a == Triangle{b[2], b[0], b[1]};
}

}  // namespace

TEST_CASE("canonical_triangles: invariant under rotations and permutations, keeps orientation") {
  rc::prop("canonical form", [] {
    const std::vector<Triangle> tris = *triangle_list();
    std::vector<Triangle> moved = tris;
    for (Triangle& t : moved) {
      const int k = *rc::gen::inRange(0, 3);
      std::rotate(t.begin(), t.begin() + k, t.end());
    }
    // A random permutation: order by random keys.
    const auto keys = *rc::gen::container<std::vector<int>>(moved.size(), rc::gen::arbitrary<int>());
    std::vector<std::size_t> order(moved.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return keys[x] < keys[y]; });
    std::vector<Triangle> permuted;
    for (std::size_t i : order) permuted.push_back(moved[i]);
    moved = permuted;
    const std::vector<Triangle> a = io::canonical_triangles(tris);
    RC_ASSERT(a == io::canonical_triangles(moved));
    RC_ASSERT(std::is_sorted(a.begin(), a.end()));
    RC_ASSERT(a.size() == tris.size());
    for (const Triangle& t : a) {
      RC_ASSERT(t[0] < t[1]);
      RC_ASSERT(t[0] < t[2]);
      // The input triangle on the same vertices is a rotation of t: the
      // orientation is kept (a reflection would be (t0 t2 t1)).
      const auto same = std::find_if(tris.begin(), tris.end(), [&](const Triangle& u) {
        return std::set<Index>(u.begin(), u.end()) == std::set<Index>(t.begin(), t.end());
      });
      RC_ASSERT(same != tris.end());
      RC_ASSERT(is_rotation(*same, t));
    }
  });
}

TEST_CASE("canonical_hull2: starts at the smallest index, a rotation of the input") {
  rc::prop("canonical cycle", [] {
    std::vector<Index> cyc = *rc::gen::unique<std::vector<Index>>(rc::gen::inRange<Index>(0, 1000));
    RC_PRE(!cyc.empty());
    std::vector<Index> moved = cyc;
    std::rotate(moved.begin(), moved.begin() + *rc::gen::inRange<std::size_t>(0, cyc.size()),
                moved.end());
    const std::vector<Index> a = io::canonical_hull2(cyc);
    RC_ASSERT(a == io::canonical_hull2(moved));
    RC_ASSERT(a.front() == *std::min_element(cyc.begin(), cyc.end()));
    // a is cyc read from some start: a[i] = cyc[(s + i) mod n].
    const std::size_t s = static_cast<std::size_t>(std::find(cyc.begin(), cyc.end(), a[0]) - cyc.begin());
    for (std::size_t i = 0; i < a.size(); ++i) RC_ASSERT(a[i] == cyc[(s + i) % cyc.size()]);
  });
}

TEST_CASE("index files: write then read is the identity, and the format is plain") {
  TempDir t;
  const std::string tp = t.path("t.txt"), hp = t.path("h.txt");
  rc::prop("triangles and cycles round trip", [&] {
    const auto tris = *rc::gen::container<std::vector<Triangle>>(
        rc::gen::container<Triangle>(rc::gen::arbitrary<Index>()));
    const auto cyc = *rc::gen::container<std::vector<Index>>(rc::gen::arbitrary<Index>());
    fs::remove(tp);
    fs::remove(hp);
    io::write_file(tp, [&](std::ostream& os) { io::write_triangles(os, tris); });
    io::write_file(hp, [&](std::ostream& os) { io::write_hull2(os, cyc); });
    RC_ASSERT(io::read_triangles(tp) == tris);
    RC_ASSERT(io::read_index_cycle(hp) == cyc);
  });
  std::ostringstream a, b;
  io::write_triangles(a, {{0, 1, 2}, {4294967295u, 7, 10}});
  io::write_hull2(b, {3, 1, 2});
  CHECK(a.str() == "0 1 2\n4294967295 7 10\n");
  CHECK(b.str() == "3\n1\n2\n");
}

TEST_CASE("index files: comments, blank lines and Qhull's 'i' format") {
  TempDir t;
  CHECK(io::read_triangles(t.file("a.txt", "# ours\n0 1 2\n\n  3 4 5 # c\n")) ==
        std::vector<Triangle>{{0, 1, 2}, {3, 4, 5}});
  // Qhull's facets are clockwise seen from outside: reversed on reading
  CHECK(io::read_triangles(t.file("q.txt", "2\n0 1 2 \n3 4 5 \n")) ==
        std::vector<Triangle>{{0, 2, 1}, {3, 5, 4}});
  CHECK(io::read_triangles(t.file("e.txt", "")).empty());
  CHECK(io::read_triangles(t.file("q0.txt", "0\n")).empty());
  CHECK(io::read_index_cycle(t.file("h.txt", "#\n5\n\n3 # c\n0\n")) == std::vector<Index>{5, 3, 0});
}

TEST_CASE("index files: output of the qhull program parses") {
  // qhull-bin is a dependency installed by `make deps`: its absence is a failure
  REQUIRE(std::system("qhull -V > /dev/null 2>&1") == 0);
  TempDir t;
  for (const char* dist : {"ball", "cube", "sphere"}) {
    const PointSet ps = gen::generate(dist, 500, {});
    std::string in = "3\n" + std::to_string(ps.size()) + "\n";
    {
      std::ostringstream os;
      io::write_points(os, ps);
      in += os.str();
    }
    const std::string ip = t.file("in.txt", in), op = t.path("out.txt");
    REQUIRE(std::system(("qhull i Qt < " + ip + " > " + op).c_str()) == 0);
    std::ifstream f(op);
    std::size_t announced = 0;
    f >> announced;
    const std::vector<Triangle> tris = io::read_triangles(op);
    CHECK(tris.size() == announced);
    std::set<Index> vertices;
    for (const Triangle& tr : tris) {
      CHECK(tr[0] != tr[1]);
      CHECK(tr[1] != tr[2]);
      CHECK(tr[0] != tr[2]);
      for (Index i : tr) {
        CHECK(i < ps.size());
        vertices.insert(i);
      }
    }
    // A triangulated sphere: F = 2V - 4 (Euler).
    CHECK(tris.size() == 2 * vertices.size() - 4);
    // and, read with flipflop's orientation, it is the convex hull
    CHECK(certify::hull3(ps, tris).message() == "certified");
  }
}

TEST_CASE("index files: each error names the file and the line") {
  TempDir t;
  auto tri = [&](const std::string& name, const std::string& text, std::size_t line,
                 const std::string& what) {
    const std::string p = t.file(name, text);
    check_error(error_of([&] { io::read_triangles(p); }), p, line, what);
  };
  auto cyc = [&](const std::string& name, const std::string& text, std::size_t line,
                 const std::string& what) {
    const std::string p = t.file(name, text);
    check_error(error_of([&] { io::read_index_cycle(p); }), p, line, what);
  };
  tri("a", "0 1 2\n3 x 5\n", 2, "'x' is not an index");
  tri("b", "0 1 2\n\n3 -4 5\n", 3, "negative index '-4'");
  tri("c", "0 1 2\n3 4\n", 2, "expected 3 indices");
  tri("d", "0 1 2 3\n", 1, "found 4 tokens");
  tri("e", "0 1 4294967296\n", 1, "exceeds the largest index");
  tri("f", "0 1 99999999999999999999999\n", 1, "exceeds the largest index");
  tri("g", "0 1 2.0\n", 1, "'2.0' is not an index");
  tri("q1", "3\n0 1 2\n1 2 3\n", 3, "facet count on line 1 is 3, but 2 facets follow");
  tri("q2", "2\n0 1 2 3\n", 2, "Qt");
  tri("q3", "-2\n", 1, "negative index");
  cyc("h", "0\n1\n2 3\n", 3, "expected 1 index per line, found 2 tokens");
  cyc("i", "0\n-1\n", 2, "negative index");
  cyc("j", "0\n1.5\n", 2, "'1.5' is not an index");
  check_error(error_of([&] { io::read_index_cycle(t.path("none")); }), t.path("none"), 0, "cannot open");
}

TEST_CASE("write_file: a failure to open or to write is one error line naming the file") {
  TempDir t;
  const std::string p = t.path("no/such/dir/out.txt");
  try {
    io::write_file(p, [](std::ostream& os) { os << "x\n"; });
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    CHECK(msg.rfind(p + ": cannot write: ", 0) == 0);
    CHECK(msg.find('\n') == std::string::npos);
  }
  if (fs::exists("/dev/full")) {
    try {
      io::write_file("/dev/full", [](std::ostream& os) { os << std::string(1 << 20, 'x'); });
      FAIL("no error writing to /dev/full");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()).rfind("/dev/full: cannot write: ", 0) == 0);
    }
  }
  const std::string ok = t.path("ok.txt");
  io::write_file(ok, [](std::ostream& os) { io::write_hull2(os, {2, 0, 1}); });
  std::ifstream f(ok);
  std::stringstream s;
  s << f.rdbuf();
  CHECK(s.str() == "2\n0\n1\n");
}

// ---------------------------------------------------------------------------
// .xyz in parallel blocks: errors in file order, far into the file
// ---------------------------------------------------------------------------

TEST_CASE("xyz: the first bad line of a large file is reported, whatever batch it is in") {
  TempDir t;
  const std::string p = t.path("big.xyz");
  const std::size_t lines = 3'500'000;  // about 45 MiB: several 8 MiB blocks (read_xyz.cpp)
  {
    std::ofstream f(p, std::ios::binary);
    for (std::size_t i = 1; i <= lines; ++i) {
      if (i == 2'900'001) f << "0.5 zz 0.125\n";
      else if (i == 3'000'000) f << "1 2\n";
      else f << "0.5 0.25 " << (i % 1000) << "\n";
    }
  }
  const InputError e = error_of([&] { io::read_points(p, 3, false); });
  INFO(e.what());
  CHECK(e.line() == 2'900'001);
  CHECK(std::string(e.what()).find("malformed number 'zz' in column 2 (y)") != std::string::npos);
  // the same file without the bad lines: every point, in order
  {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    for (std::size_t i = 1; i <= lines; ++i) f << "0.5 0.25 " << (i % 1000) << (i % 7 == 0 ? " # c\n\n" : "\n");
  }
  const PointSet ps = io::read_points(p, 3, false);
  REQUIRE(ps.size() == lines);
  for (std::size_t i = 0; i < lines; i += 9973) CHECK(ps.point(i)[2] == static_cast<double>((i + 1) % 1000));
}

// ---------------------------------------------------------------------------
// .xyz with small blocks and pieces, against a reader written here
// ---------------------------------------------------------------------------

namespace {

// The .xyz rules of read_points.hpp and text.hpp, line by line, with strtod
// for the values: a line longer than max_line is bad unless a '#' starts
// within max_line bytes; the text from '#' on is dropped; a line without
// tokens is skipped; otherwise exactly cols tokens of the grammar
// [+-](digits[.digits]|.digits)[(e|E)[+-]digits], none overflowing to Inf.
struct OracleXyz {
  std::size_t bad_line = 0;  // 0: none
  std::size_t lines = 0;
  std::vector<double> coords, weights;
};
bool decimal_token(const std::string& t) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const auto digits = [&] {
    const std::size_t b = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - b;
  };
  std::size_t m = digits();
  if (i < t.size() && t[i] == '.') ++i, m += digits();
  if (m == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == t.size();
}
OracleXyz oracle_xyz(const std::string& text, int dim, bool weighted, std::size_t max_line) {
  OracleXyz o;
  const std::size_t cols = static_cast<std::size_t>(dim) + (weighted ? 1 : 0);
  std::size_t b = 0;
  while (b < text.size()) {
    std::size_t e = text.find('\n', b);
    if (e == std::string::npos) e = text.size();
    std::string line = text.substr(b, e - b);
    b = e + 1;
    ++o.lines;
    const std::size_t hash = line.find('#');
    if (line.size() > max_line && (hash == std::string::npos || hash >= max_line)) {
      o.bad_line = o.lines;
      return o;
    }
    if (hash != std::string::npos) line.resize(hash);
    std::vector<std::string> tok;
    for (std::size_t i = 0; i < line.size();) {
      if (std::strchr(" \t\r\v\f", line[i]) != nullptr) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < line.size() && std::strchr(" \t\r\v\f", line[j]) == nullptr) ++j;
      tok.push_back(line.substr(i, j - i));
      i = j;
    }
    if (tok.empty()) continue;
    bool ok = tok.size() == cols;
    std::vector<double> v;
    for (std::size_t c = 0; ok && c < cols; ++c) {
      ok = decimal_token(tok[c]);
      if (ok) v.push_back(std::strtod(tok[c].c_str(), nullptr));
      ok = ok && std::isfinite(v.back());
    }
    if (!ok) {
      o.bad_line = o.lines;
      return o;
    }
    o.coords.insert(o.coords.end(), v.begin(), v.begin() + dim);
    if (weighted) o.weights.push_back(v[static_cast<std::size_t>(dim)]);
  }
  return o;
}

// A number as text, in one of many spellings (some of them refused).
std::string number_text(std::mt19937_64& g, bool allow_bad) {
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  char buf[64];
  const double x = u(g) * std::pow(10.0, static_cast<int>(g() % 40) - 20);
  switch (g() % (allow_bad ? 16 : 11)) {
    case 0: std::snprintf(buf, sizeof buf, "%.17g", x); break;
    case 1: std::snprintf(buf, sizeof buf, "%.3e", x); break;
    case 2: std::snprintf(buf, sizeof buf, "+%.6f", std::fabs(x)); break;
    case 3: std::snprintf(buf, sizeof buf, "%d.", static_cast<int>(g() % 1000)); break;
    case 4: std::snprintf(buf, sizeof buf, "-.%03d", static_cast<int>(g() % 1000)); break;
    case 5: std::snprintf(buf, sizeof buf, "%s", g() % 2 ? "-0" : "0007.50E+01"); break;
    case 6: std::snprintf(buf, sizeof buf, "%de-%d", static_cast<int>(g() % 9 + 1), static_cast<int>(300 + g() % 60)); break;
    case 7: std::snprintf(buf, sizeof buf, "%.20g", 4.9406564584124654e-324 * static_cast<double>(g() % 5000)); break;
    case 8: std::snprintf(buf, sizeof buf, "1.7976931348623157e%d", static_cast<int>(300 + g() % 8)); break;
    case 9: std::snprintf(buf, sizeof buf, "%.25f", x * 1e-12); break;
    case 10: std::snprintf(buf, sizeof buf, "%d", static_cast<int>(g() % 200000) - 100000); break;
    default: {
      static const char* bad[] = {"nan", "-inf", "Infinity", "1e", "0x1p3", "1..2", "+-1", "1,5", "abc",
                                  "1e999", "-2e308", ".", "+", "1.5x", "e5"};
      return bad[g() % (sizeof bad / sizeof *bad)];
    }
  }
  return buf;
}

// A random .xyz text: points with varied spacing, blank and comment lines,
// CRLF, trailing comments, now and then a long line or a bad one.
std::string xyz_text(std::mt19937_64& g, std::size_t cols, std::size_t max_line, bool allow_bad) {
  static const char* space[] = {" ", "  ", "\t", " \t ", "\v", "\f"};
  std::string text;
  const std::size_t n = g() % 40;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned kind = static_cast<unsigned>(g() % 20);
    std::string line;
    if (kind == 0) {
      line = "";
    } else if (kind == 1) {
      line = std::string(g() % 3, ' ') + "# comment " + std::to_string(i);
    } else if (kind == 2) {  // longer than max_line: fine only with an early '#'
      const bool hash = g() % 2 == 0 || !allow_bad;
      for (std::size_t k = 0; k < cols; ++k) line += std::to_string(k + i) + " ";
      line += std::string(hash ? "#" : "") + std::string(max_line + g() % 40, hash ? 'c' : ' ') + "3";
    } else {
      std::size_t c = cols;
      if (allow_bad && kind == 3) c = g() % 2 ? cols + 1 : cols - 1;
      if (g() % 3 == 0) line += space[g() % 6];
      for (std::size_t k = 0; k < c; ++k) {
        if (k) line += space[g() % 6];
        line += number_text(g, allow_bad && g() % 8 == 0);
      }
      if (g() % 4 == 0) line += space[g() % 6];
      if (g() % 5 == 0) line += "#x";
      if (line.size() > max_line && line.find('#') >= max_line) line = "# (too long) ";
    }
    text += line;
    if (i + 1 < n || g() % 2) text += g() % 4 == 0 ? "\r\n" : "\n";
  }
  return text;
}

// read_xyz with `layout` on `text` is the oracle's answer: the same doubles,
// bit for bit, or one InputError line at the oracle's first bad line (or, for
// too few points, at the last line). Returns what differs, or "".
std::string against_oracle(const TempDir& t, const std::string& text, int dim, bool weighted,
                           const io::detail::XyzLayout& layout) {
  const std::string p = t.file("o.xyz", text);
  const OracleXyz o = oracle_xyz(text, dim, weighted, layout.max_line);
  const std::size_t pts = o.coords.size() / static_cast<std::size_t>(dim);
  const bool error = o.bad_line != 0 || pts < static_cast<std::size_t>(dim) + 1;
  const std::size_t line = o.bad_line != 0 ? o.bad_line : o.lines;
  try {
    const PointSet ps = io::detail::read_xyz(p, dim, weighted, layout);
    if (error) return "read " + std::to_string(ps.size()) + " points, expected an error at line " + std::to_string(line);
    if (!same_bits(ps.coords, o.coords) || !same_bits(ps.weights, o.weights))
      return "other values (" + std::to_string(ps.size()) + " points, expected " + std::to_string(pts) + ")";
  } catch (const InputError& e) {
    if (!error) return std::string("unexpected error: ") + e.what();
    if (e.line() != line) return std::string(e.what()) + " (expected line " + std::to_string(line) + ")";
    if (std::string(e.what()).find('\n') != std::string::npos) return "a message of several lines";
  }
  return "";
}

}  // namespace

TEST_CASE("xyz: blocks and pieces of any size read what a line-by-line strtod reader reads") {
  TempDir t;
  rc::prop("random text, small blocks and pieces", [&] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const int dim = *rc::gen::inRange(2, 4);
    const bool weighted = *rc::gen::arbitrary<bool>();
    io::detail::XyzLayout layout;
    layout.max_line = *rc::gen::inRange<std::size_t>(60, 200);
    layout.block = *rc::gen::inRange<std::size_t>(2 * layout.max_line, 3 * layout.max_line);
    layout.piece = *rc::gen::inRange<std::size_t>(1, 90);
    std::mt19937_64 g(seed);
    const std::string text = xyz_text(g, static_cast<std::size_t>(dim) + weighted, layout.max_line, seed % 3 == 0);
    const std::string diff = against_oracle(t, text, dim, weighted, layout);
    RC_TAG(oracle_xyz(text, dim, weighted, layout.max_line).bad_line != 0 ? "bad line" : "no bad line");
    RC_ASSERT(diff == "");
  });
}

TEST_CASE("xyz: every block and piece boundary inside the numbers of one file") {
  TempDir t;
  std::mt19937_64 g(11);
  std::string text;
  do text = xyz_text(g, 3, 64, false);
  while (text.size() < 600);
  const OracleXyz o = oracle_xyz(text, 3, false, 64);
  REQUIRE(o.bad_line == 0);
  REQUIRE(o.coords.size() >= 3 * 10);
  for (std::size_t block = 128; block < 128 + 64; ++block)
    for (std::size_t piece = 1; piece < 48; piece += 3) {
      INFO("block " << block << " piece " << piece);
      CHECK(against_oracle(t, text, 3, false, {block, piece, 64}) == "");
    }
}

// ---------------------------------------------------------------------------
// .npy (numpy's binary format)
// ---------------------------------------------------------------------------

namespace {

// A float64 .npy file written here from the format's definition (version 1
// or 2 header), independent of the reader.
std::string npy_bytes(const std::vector<double>& v, const std::string& shape, int version = 1,
                      const std::string& descr = "<f8", const std::string& order = "False") {
  std::string header = "{'descr': '" + descr + "', 'fortran_order': " + order + ", 'shape': " + shape + ", }";
  const std::size_t pre = version == 1 ? 10 : 12;
  header.append((64 - (pre + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY";
  out += static_cast<char>(version);
  out += '\0';
  const std::size_t len = header.size();
  for (std::size_t i = 0; i < (version == 1 ? 2u : 4u); ++i) out += static_cast<char>((len >> (8 * i)) & 0xff);
  out += header;
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));  // x86-64: little-endian
  return out;
}

// The points as the rows of an (n, d) or (n, d + 1) array, and its shape.
std::vector<double> npy_rows(const PointSet& ps) {
  std::vector<double> rows;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    rows.insert(rows.end(), ps.point(i), ps.point(i) + ps.dim);
    if (ps.weighted) rows.push_back(ps.weights[i]);
  }
  return rows;
}
std::string npy_shape(const PointSet& ps) {
  return "(" + std::to_string(ps.size()) + ", " + std::to_string(ps.dim + (ps.weighted ? 1 : 0)) + ")";
}

}  // namespace

TEST_CASE("npy: float64 (n, d) and (n, d+1) arrays read back bit for bit") {
  TempDir t;
  rc::prop("round trip", [&] {
    const PointSet ps = *point_set();
    const std::vector<double> rows = npy_rows(ps);
    const int version = *rc::gen::inRange(1, 3);
    const std::string p = t.file("p.npy", npy_bytes(rows, npy_shape(ps), version));
    const PointSet q = io::read_points(p, ps.dim, ps.weighted);
    RC_ASSERT(same_bits(q.coords, ps.coords));
    RC_ASSERT(same_bits(q.weights, ps.weights));
  });
}

TEST_CASE("npy: write_points_npy writes the bytes of the format's definition, read back bit for bit") {
  TempDir t;
  rc::prop("writer = independent bytes, reader inverts it", [&] {
    const PointSet ps = *point_set();
    const std::vector<double> rows = npy_rows(ps);
    std::ostringstream os;
    io::write_points_npy(os, ps);
    RC_ASSERT(os.str() == npy_bytes(rows, npy_shape(ps)));
    const std::string p = t.file("w.npy", os.str());
    const PointSet q = io::read_points(p, ps.dim, ps.weighted);
    RC_ASSERT(same_bits(q.coords, ps.coords));
    RC_ASSERT(same_bits(q.weights, ps.weights));
  });
}

TEST_CASE("npy: write_npy_indices, from cells or flat, writes the format's int64 bytes across its buffer") {
  // up to 3e5 indices: the writer's 1 MiB buffer (131072 numbers) fills
  // and is flushed at any point of a row. One case in 16 that large (the
  // buffer's edges: its first flush, a row across it, two flushes): at
  // 2000 cases the test took 27 s with one in 2, most of it building the
  // expected bytes and the cells.
  rc::prop("cells and flat = independent bytes", [] {
    const std::size_t k = *rc::gen::inRange<std::size_t>(1, 7);
    const std::size_t count =
        *rc::gen::weightedOneOf<std::size_t>({{15, rc::gen::inRange<std::size_t>(0, 40)},
                                              {1, rc::gen::inRange<std::size_t>(131072 / k - 3, 300000 / k)}});
    const std::uint64_t seed = *rc::gen::arbitrary<std::uint64_t>();
    std::mt19937_64 rng(seed);
    std::vector<Index> flat(count * k);
    for (Index& x : flat) x = static_cast<Index>(rng());
    std::vector<std::vector<Index>> cells;
    for (std::size_t i = 0; i < count; ++i) cells.emplace_back(flat.begin() + i * k, flat.begin() + (i + 1) * k);
    std::string want = npy_bytes({}, "(" + std::to_string(count) + ", " + std::to_string(k) + ")", 1, "<i8");
    want.reserve(want.size() + 8 * flat.size());
    for (Index x : flat)
      for (int b = 0; b < 8; ++b) want += static_cast<char>((static_cast<std::uint64_t>(x) >> (8 * b)) & 0xff);
    std::ostringstream a, f;
    io::write_npy_indices(a, cells, false);
    io::write_npy_indices(f, flat.data(), count, k);
    RC_ASSERT(f.str() == want);
    if (count > 0) RC_ASSERT(a.str() == want);  // (no cells: the cells overload cannot know k)
  });
}

TEST_CASE("npy: each error is one line naming the file") {
  TempDir t;
  const std::vector<double> ok = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::pair<std::string, std::string> cases[] = {
      {npy_bytes(ok, "(4, 3)", 1, "<f4"), "dtype '<f4'"},
      {npy_bytes(ok, "(4, 3)", 1, ">f8"), "dtype '>f8'"},
      {npy_bytes(ok, "(4, 3)", 1, "<f8", "True"), "Fortran order"},
      {npy_bytes(ok, "(3, 4)"), "expected 3 columns"},
      {npy_bytes(ok, "(12,)"), "npy shape"},
      {npy_bytes(ok, "(5, 3)"), "truncated"},
      {npy_bytes({0, 0, 0, 1, 0, 0, 0, std::nan(""), 0, 0, 0, 1}, "(4, 3)"), "NaN in row 2, column 2 (y)"},
      {npy_bytes({0, 0, 0, 1, 0, 0}, "(2, 3)"), "2 points, at least 4 needed"},
      {"", "empty file"},
      {"not numpy at all", "not a .npy file"},
  };
  for (const auto& [bytes, what] : cases) {
    const std::string p = t.file("bad.npy", bytes);
    const InputError e = error_of([&] { io::read_points(p, 3, false); });
    INFO(e.what());
    CHECK(std::string(e.what()).find(what) != std::string::npos);
    CHECK(std::string(e.what()).rfind(p + ": ", 0) == 0);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
}

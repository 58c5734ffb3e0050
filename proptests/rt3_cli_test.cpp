// rt3_cli_test.cpp — the command-line contract of `flipflop rt3|dt3`,
// `flipflop rtd --dim 3 [--backend cpu|reference]` and `flipflop certify
// rt3|dt3` (cli/rt3_commands.hpp), run on the built binary:
//   * the cpu backend (kernels_cpu/rt3, the default) writes the reference's
//     bytes (RT+1) at 1, 2 and 8 threads, as rt3, dt3 and rtd --dim 3, on
//     random, weighted, grid, duplicated and coplanar-layered input, and
//     reports the same redundant points; --strict likewise;
//   * bad input and bad usage: exit 2 and one line naming the problem;
//   * extreme magnitudes (2^+-1000, subnormals, 1e+-300) are taken exactly:
//     points scaled by a power of two get the unscaled answer;
//   * .vtu and .npy outputs hold the index text's tetrahedra;
//   * certify rt3|dt3 accepts the output and rejects corrupted ones.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "proptests/support/cli_run.hpp"

namespace fs = std::filesystem;
using namespace flipflop::test::cli;

namespace {

std::string replace_prefix(std::string s, const std::string& from, const std::string& to) {
  // every line of s that starts with `from` starts with `to` instead
  std::string out;
  std::istringstream in(s);
  for (std::string line; std::getline(in, line);)
    out += (line.rfind(from, 0) == 0 ? to + line.substr(from.size()) : line) + "\n";
  return out;
}

// a file of `rows`, each a line of doubles (shortest round trip)
std::string xyz(const std::vector<std::vector<double>>& rows) {
  std::string s;
  char buf[64];
  for (const auto& r : rows) {
    for (std::size_t j = 0; j < r.size(); ++j) {
      std::snprintf(buf, sizeof buf, "%.17g", r[j]);
      s += (j ? " " : "") + std::string(buf);
    }
    s += "\n";
  }
  return s;
}

// the same points with a weight column of zeros (dt3 input as rt3/rtd input)
std::string with_zero_weights(const std::string& text) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') out += line + " 0\n";
  return out;
}

std::vector<std::vector<long>> parse_rows(const std::string& text) {
  std::vector<std::vector<long>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::vector<long> r;
    for (long v; ls >> v;) r.push_back(v);
    if (!r.empty()) rows.push_back(r);
  }
  return rows;
}

// One line on stderr, exit code 2, nothing on stdout, `what` in the line.

// KIND IN with the cpu backend — by default and named, at 1, 2 and 8 threads
// — and, for weighted input, rtd --dim 3 (cpu by default, and the reference):
// the bytes of `KIND IN --backend reference`, and the same redundant points on
// standard error. Returns the reference's output. light: only the cpu
// backend at 2 threads against the reference.
std::string check_backends_agree(const TempDir& t, const std::string& kind, const fs::path& in, bool light = false) {
  const fs::path ref_out = t.dir / "ref.txt";
  const Run ref = run(t, kind + " " + in.string() + " --backend reference -o " + ref_out.string());
  INFO(kind << " " << in.filename() << ": " << ref.err);
  REQUIRE(ref.code == 0);
  const std::string expect = slurp(ref_out);
  REQUIRE(!expect.empty());
  const std::vector<std::string> cpu_opts =
      light ? std::vector<std::string>{"--threads 2"}
            : std::vector<std::string>{"", "--backend cpu", "--threads 1", "--backend cpu --threads 2", "--threads 8"};
  for (const std::string& opts : cpu_opts) {
    const fs::path out = t.dir / "cpu.txt";
    fs::remove(out);
    const Run r = run(t, kind + " " + in.string() + " " + opts + " -o " + out.string());
    INFO(opts << ": " << r.err);
    REQUIRE(r.code == 0);
    CHECK(slurp(out) == expect);
    CHECK(r.err == ref.err);  // the redundant points, as rtd reports them
  }
  if (light) return expect;
  // to standard output: the same bytes
  const Run piped = run(t, kind + " " + in.string() + " --threads 2");
  CHECK(piped.code == 0);
  CHECK(piped.out == expect);
  // rtd --dim 3 reads x y z w: dt3's points get a zero weight column
  fs::path win = in;
  if (kind == "dt3") win = t.file("zero_w.xyz", with_zero_weights(slurp(in)));
  for (const char* opts : {"", "--backend cpu --threads 2", "--threads 8", "--backend reference"}) {
    const fs::path out = t.dir / "rtd.txt";
    fs::remove(out);
    const Run r = run(t, "rtd " + win.string() + " --dim 3 " + opts + " -o " + out.string());
    INFO("rtd --dim 3 " << opts << ": " << r.err);
    REQUIRE(r.code == 0);
    CHECK(slurp(out) == expect);
    CHECK(replace_prefix(r.err, "rtd: ", kind + ": ") == ref.err);
  }
  return expect;
}

void add_grid(std::vector<std::vector<double>>& rows, int k, double w_step = -1) {
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) {
        std::vector<double> r = {double(x), double(y), double(z)};
        if (w_step >= 0) r.push_back(((x + 2 * y + 3 * z) % 3) * w_step);
        rows.push_back(r);
      }
}

}  // namespace

TEST_CASE("rt3 cli: rt3, dt3 and rtd --dim 3 write the reference's bytes with the cpu backend at 1, 2, 8 threads",
          "[cli][long]") {
  TempDir t("flipflop_rt3_cli_");
  struct Gen {
    const char* kind;
    const char* args;  // flipflop gen ...
  };
  // random (uniform cube, ball), weighted (three weight ranges: few, some and
  // many redundant points), degenerate (grid: cospherical; duplicates;
  // planes with duplicates; a lattice on a sphere)
  const Gen gens[] = {{"dt3", "cube 3000 --seed 1"},
                      {"dt3", "ball 2000 --seed 2"},
                      {"rt3", "ball 2000 --seed 3 --weights 0,0.0001"},
                      {"rt3", "cube 2000 --seed 4 --weights 0,0.01"},
                      {"rt3", "cube 1000 --seed 5 --weights 0,0.1"},
                      {"dt3", "grid3 1000 --seed 6"},
                      {"dt3", "duplicates3 1000 --seed 7"},
                      {"dt3", "planes3 1000 --seed 8"},
                      {"dt3", "sphere-lattice 500 --seed 9"},
                      {"rt3", "grid3 512 --seed 10 --weights 0,0.3"}};
  for (const Gen& g : gens) {
    SECTION(std::string(g.kind) + " on gen " + g.args) {
      const fs::path in = t.dir / "in.xyz";
      REQUIRE(run(t, std::string("gen ") + g.args + " -o " + in.string()).code == 0);
      check_backends_agree(t, g.kind, in);
    }
  }
  SECTION("a weighted grid with repeated points and integer weights") {
    std::vector<std::vector<double>> rows;
    add_grid(rows, 5, 0.25);
    for (std::size_t i = 0; i < 125; i += 7) rows.push_back({rows[i][0], rows[i][1], rows[i][2], 0.5});
    for (std::size_t i = 3; i < 125; i += 11) rows.push_back(rows[i]);  // exact duplicates, weight too
    const std::string out = check_backends_agree(t, "rt3", t.file("wgrid.xyz", xyz(rows)));
    CHECK(lines(out) > 0);
  }
  SECTION("the smallest input: 4 points, and 5 with one redundant") {
    check_backends_agree(t, "dt3", t.file("four.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"));
    const Run r = run(t, "rt3 " + t.file("five.xyz", "0 0 0 1\n4 0 0 1\n0 4 0 1\n0 0 4 1\n1 1 1 -20\n").string());
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.out == "0 1 2 3\n");
    CHECK(r.err == "rt3: 1 redundant point (not vertices): 4\n");
  }
}

TEST_CASE("rt3 cli: --strict from the cpu backend's answer is the reference's, certified as strict", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  std::vector<std::vector<double>> rows;
  add_grid(rows, 4);
  const fs::path in = t.file("grid.xyz", xyz(rows));
  const fs::path win = t.file("grid_w.xyz", with_zero_weights(xyz(rows)));
  const fs::path ref_out = t.dir / "ref.txt";
  REQUIRE(run(t, "dt3 " + in.string() + " --strict --backend reference -o " + ref_out.string()).code == 0);
  const std::string expect = slurp(ref_out);
  CHECK(lines(expect) == 27 * 6);  // the pulling triangulation of each cube (rtd --strict's count)
  for (const std::string& cmd :
       {"dt3 " + in.string() + " --strict", "dt3 " + in.string() + " --strict --threads 2",
        "rt3 " + win.string() + " --strict --threads 8", "rtd " + win.string() + " --dim 3 --strict",
        "rtd " + win.string() + " --dim 3 --strict --backend reference"}) {
    const fs::path out = t.dir / "s.txt";
    const Run r = run(t, cmd + " -o " + out.string());
    INFO(cmd << ": " << r.err);
    REQUIRE(r.code == 0);
    CHECK(slurp(out) == expect);
  }
  const Run ok = run(t, "certify dt3 " + in.string() + " " + ref_out.string() + " --strict");
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  CHECK(ok.out == "certified (dt3, strict): 64 points in R^3, 162 tetrahedra\n");
  // the canonical answer has zero-volume tetrahedra: not a strict view
  const fs::path canon = t.dir / "c.txt";
  REQUIRE(run(t, "dt3 " + in.string() + " -o " + canon.string()).code == 0);
  CHECK(lines(slurp(canon)) > 27 * 6);
  const Run flat = run(t, "certify dt3 " + in.string() + " " + canon.string() + " --strict");
  CHECK(flat.code == 1);
  CHECK(flat.out.find("NOT certified (dt3, strict): simplex-orientation") == 0);
  // --stats says where each stage ran
  const Run s = run(t, "dt3 " + in.string() + " --strict --stats --threads 2 -o " + (t.dir / "x.txt").string());
  CHECK(s.code == 0);
  CHECK(s.err.find("dt3: backend cpu (2 threads)") != std::string::npos);
  CHECK(s.err.find("dt3 --strict: 162 tetrahedra") != std::string::npos);
  CHECK(s.err.find("sequential, from the cpu backend's certified canonical answer") != std::string::npos);
}

TEST_CASE("rt3 cli: --stats prints counts and stage timings", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  const fs::path in = t.dir / "w.xyz";
  REQUIRE(run(t, "gen cube 2000 --seed 11 --weights 0,0.01 -o " + in.string()).code == 0);
  const Run cpu = run(t, "rt3 " + in.string() + " --stats --threads 2 -o " + (t.dir / "a.txt").string());
  INFO(cpu.err);
  REQUIRE(cpu.code == 0);
  CHECK(cpu.err.find("rt3: backend cpu (2 threads), 2000 points, ") != std::string::npos);
  CHECK(cpu.err.find("certify") != std::string::npos);
  CHECK(cpu.err.find("certify_rt3 from the kernel's witness") != std::string::npos);
  CHECK(cpu.err.find("rt3: inserted ") != std::string::npos);
  for (const char* stage : {": stages sort ", ", insert ", ", output ", ", witness "})
    CHECK(cpu.err.find(stage) != std::string::npos);
  const Run ref = run(t, "rt3 " + in.string() + " --stats --backend reference -o " + (t.dir / "b.txt").string());
  INFO(ref.err);
  REQUIRE(ref.code == 0);
  CHECK(ref.err.find("rt3: backend reference, 2000 points, ") != std::string::npos);
  CHECK(ref.err.find("rt3: flips 1-4:") != std::string::npos);
  // the counts agree: tetrahedra and redundant points of the first line
  const auto sizes = [](const std::string& err) {
    const std::size_t a = err.find("points, "), b = err.find(" redundant;");
    return err.substr(a, b - a);
  };
  CHECK(sizes(cpu.err) == sizes(ref.err));
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
  const Run omp = run(t, "rt3 " + in.string() + " --stats --backend cuda-omp -o " + (t.dir / "d.txt").string());
  INFO(omp.err);
  REQUIRE(omp.code == 0);
  CHECK(omp.err.find("rt3: backend cuda-omp, 2000 points, ") != std::string::npos);
  CHECK(omp.err.find("certify_rt3 from the kernel's witness") != std::string::npos);
  CHECK(omp.err.find("rt3: BRIO levels ") != std::string::npos);
  CHECK(omp.err.find(", insertion rounds ") != std::string::npos);
  CHECK(omp.err.find("(kernels_cuda/rt3, backend cuda-omp)") != std::string::npos);
  CHECK(sizes(omp.err) == sizes(ref.err));
  CHECK(slurp(t.dir / "d.txt") == slurp(t.dir / "b.txt"));
#endif
  const Run rtd = run(t, "rtd " + in.string() + " --dim 3 --stats -o " + (t.dir / "c.txt").string());
  CHECK(rtd.code == 0);
  CHECK(rtd.err.find("rtd: backend cpu, 2000 points, ") != std::string::npos);
}

TEST_CASE("rt3 cli: bad input and bad usage give one line and exit code 2", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  struct Case {
    const char* kind;
    const char* file;
    const char* content;
    const char* what;  // a word the message must contain
  };
  const Case cases[] = {
      {"rt3", "empty.xyz", "", "no points"},
      {"dt3", "comments.xyz", "# only a comment\n\n", "no points"},
      {"dt3", "three.xyz", "0 0 0\n1 0 0\n0 1 0\n", "at least 4"},
      {"rt3", "three_w.xyz", "0 0 0 0\n1 0 0 0\n0 1 0 0\n", "at least 4"},
      {"dt3", "equal.xyz", "1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n", "are equal"},
      {"dt3", "collinear.xyz", "0 0 0\n1 1 1\n2 2 2\n3 3 3\n", "collinear"},
      {"dt3", "coplanar.xyz", "0 0 1\n1 0 1\n0 1 1\n1 1 1\n2 3 1\n", "coplanar"},
      {"rt3", "coplanar_w.xyz", "0 0 1 5\n1 0 1 0\n0 1 1 1\n1 1 1 0\n2 3 1 9\n", "coplanar"},
      {"dt3", "nan.xyz", "0 0 0\n1 0 0\n0 1 0\nnan 0 1\n", "NaN"},
      {"dt3", "inf.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 inf\n", "Inf"},
      {"rt3", "nan_w.xyz", "0 0 0 0\n1 0 0 0\n0 1 0 nan\n0 0 1 0\n", "NaN"},
      {"rt3", "inf_w.xyz", "0 0 0 0\n1 0 0 0\n0 1 0 -inf\n0 0 1 0\n", "Inf"},
      {"dt3", "overflow.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1e400\n", "1e400"},
      {"dt3", "malformed.xyz", "0 0 0\n1 0 0\n0 1x 0\n0 0 1\n", "1x"},
      {"dt3", "columns.xyz", "0 0 0\n1 0 0 5\n0 1 0\n0 0 1\n", "column"},
      {"rt3", "noweight.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "column"},
      {"dt3", "weighted.xyz", "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n", "column"},
      {"rt3", "short_line.xyz", "0 0 0 0\n1 0 0 0\n0 1\n0 0 1 0\n", "column"},
  };
  for (const Case& c : cases) {
    SECTION(std::string(c.kind) + " " + c.file) {
      const fs::path p = t.file(c.file, c.content);
      for (const char* backend : {"cpu", "reference"}) {
        const Run r = run(t, std::string(c.kind) + " " + p.string() + " --backend " + backend);
        expect_one_line_error(r, c.what);
        CHECK(r.err.find(c.file) != std::string::npos);
      }
      if (std::string(c.kind) == "rt3") {  // rtd --dim 3 reads the same columns
        expect_one_line_error(run(t, "rtd " + p.string() + " --dim 3"), c.what);
        expect_one_line_error(run(t, "certify rt3 " + p.string() + " " + p.string()), c.what);
      }
    }
  }
  SECTION("unreadable file and unknown input extension") {
    expect_one_line_error(run(t, "dt3 " + (t.dir / "missing.xyz").string()), "missing.xyz");
    expect_one_line_error(run(t, "rt3 " + t.file("points.csv", "0 0 0 0\n").string()), "points.csv");
  }
  SECTION("usage") {
    std::string text;
    for (int i = 0; i < 40; ++i)
      text += std::to_string(i % 4) + " " + std::to_string(i * 7 % 5) + " " + std::to_string(i * i % 6) + " 0\n";
    const fs::path p = t.file("ok.xyz", text);
    const std::string in = p.string();
    struct Usage {
      std::string args, what;
    };
    const Usage usages[] = {
        {"rt3 " + in + " --threads 0", "--threads"},
        {"rt3 " + in + " --threads -2", "--threads"},
        {"rt3 " + in + " --threads x", "--threads"},
        {"rt3 " + in + " --backend reference --threads 2", "--threads applies"},
        {"rt3 " + in + " --backend gpu", "--backend"},
        {"rt3 " + in + " --backend cuda-omp --threads 2", "--threads applies"},
        {"rt3 " + in + " --algo brute", "--algo"},
        {"rt3 " + in + " -o " + (t.dir / "x.foo").string(), "x.foo"},
        {"rt3 " + in + " -o " + (t.dir / "x.off").string(), "x.off"},
        {"rt3 " + in + " -o " + (t.dir / "x.stl").string(), "x.stl"},
        {"rt3 " + in + " -o " + (t.dir / "x.svg").string(), "x.svg"},
        {"rt3 " + in + " -o " + (t.dir / "no" / "such" / "dir.txt").string(), "dir.txt"},
        {"rt3", "IN"},
        {"rtd " + in + " --dim 5 --backend gpu", "--backend"},
        {"rtd " + in + " --dim 2 --threads 2", "--threads applies"},
        {"rtd " + in + " --dim 3 --backend reference --threads 2", "--threads applies"},
        {"rtd " + in + " --dim 3 --backend gpu", "--backend"},
        {"certify dt3 " + in + " " + in + " --dim 4", "3D"},
        {"certify rt3 " + in + " " + in + " --strict --canonical", "--canonical"},
    };
    for (const Usage& u : usages) {
      const Run r = run(t, u.args);
      INFO(u.args);
      expect_one_line_error(r, u.what);
    }
    // nothing was written for a refused format
    CHECK(!fs::exists(t.dir / "x.off"));
    CHECK(!fs::exists(t.dir / "x.svg"));
  }
}

TEST_CASE("rt3 cli: extreme magnitudes are taken exactly (2^+-1000, subnormals, 1e+-300)", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  // integer points in general position (random), and a grid; scaled by a
  // power of two s the Delaunay triangulation is the same (every predicate is
  // a positive multiple of the unscaled one: orient3d by s^3, the in-sphere
  // test by s^5; the perturbation is symbolic), and so is the regular one
  // with weights scaled by s^2
  std::mt19937_64 g(17);
  std::uniform_int_distribution<int> coord(-500, 500), weight(0, 2000);
  std::vector<std::vector<double>> ints, grid;
  for (int i = 0; i < 300; ++i)
    ints.push_back({double(coord(g)), double(coord(g)), double(coord(g)), double(weight(g))});
  add_grid(grid, 4, 0.0);
  const auto scaled = [](std::vector<std::vector<double>> rows, double s, bool weights) {
    for (auto& r : rows) {
      for (int j = 0; j < 3; ++j) r[static_cast<std::size_t>(j)] *= s;
      if (weights) r[3] *= s * s;
      else r.resize(3);
    }
    return rows;
  };
  for (const auto* base : {&ints, &grid}) {
    const std::string name = base == &ints ? "random" : "grid";
    const fs::path plain = t.file(name + ".xyz", xyz(scaled(*base, 1.0, false)));
    const fs::path plain_w = t.file(name + "_w.xyz", xyz(scaled(*base, 1.0, true)));
    const std::string dt = check_backends_agree(t, "dt3", plain);
    const std::string rt = check_backends_agree(t, "rt3", plain_w);
    for (const int e : {-1074 + 12, -1000, -500, 500, 1000 - 12}) {
      // 2^-1062: subnormal coordinates (|x| <= 500 * 2^-1062 < 2^-1022)
      const double s = std::ldexp(1.0, e);
      INFO(name << " scaled by 2^" << e);
      const fs::path f = t.file(name + "_s.xyz", xyz(scaled(*base, s, false)));
      CHECK(check_backends_agree(t, "dt3", f, true) == dt);
      if (e >= -500 && e <= 500) {  // s^2 a normal double
        const fs::path fw = t.file(name + "_sw.xyz", xyz(scaled(*base, s, true)));
        CHECK(check_backends_agree(t, "rt3", fw, true) == rt);
      }
      const Run c = run(t, "dt3 " + f.string() + " -o " + (t.dir / "e.txt").string());
      REQUIRE(c.code == 0);
      const Run ok = run(t, "certify dt3 " + f.string() + " " + (t.dir / "e.txt").string() + " --canonical");
      CHECK(ok.code == 0);
    }
  }
  // decimal magnitudes (not a scaling of another input): certified, and the
  // backends agree
  std::uniform_real_distribution<double> u(-1, 1);
  for (const double scale : {1e300, 1e-300, 4.9e-324 * 1e6}) {
    std::vector<std::vector<double>> rows;
    for (int i = 0; i < 200; ++i) rows.push_back({u(g) * scale, u(g) * scale, u(g) * scale});
    const fs::path f = t.file("dec.xyz", xyz(rows));
    INFO("scale " << scale);
    check_backends_agree(t, "dt3", f, true);
    REQUIRE(run(t, "dt3 " + f.string() + " -o " + (t.dir / "d.txt").string()).code == 0);
    CHECK(run(t, "certify dt3 " + f.string() + " " + (t.dir / "d.txt").string() + " --canonical").code == 0);
  }
}

namespace {
// .npy (format 1.0, '<i8', C order): the header's shape and the values
std::pair<std::string, std::vector<std::int64_t>> read_npy_int64(const std::string& bytes) {
  REQUIRE(bytes.size() >= 10);
  REQUIRE(bytes.substr(0, 6) == "\x93NUMPY");
  const std::size_t hlen = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  const std::string header = bytes.substr(10, hlen);
  CHECK(header.find("'descr': '<i8'") != std::string::npos);
  CHECK(header.find("'fortran_order': False") != std::string::npos);
  const std::size_t a = header.find("'shape': (") + 10, b = header.find(')', a);
  std::vector<std::int64_t> v;
  for (std::size_t i = 10 + hlen; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t x = 0;
    for (int k = 7; k >= 0; --k) x = (x << 8) | static_cast<unsigned char>(bytes[i + static_cast<std::size_t>(k)]);
    v.push_back(static_cast<std::int64_t>(x));
  }
  CHECK((bytes.size() - 10 - hlen) % 8 == 0);
  return {header.substr(a, b - a), v};
}

// The values of the DataArray named `name` of a VTU file (ASCII).
std::vector<double> vtu_array(const std::string& xml, const std::string& name) {
  const std::size_t at = xml.find("Name=\"" + name + "\"");
  REQUIRE(at != std::string::npos);
  const std::size_t a = xml.find('>', at) + 1, b = xml.find("</DataArray>", a);
  std::istringstream in(xml.substr(a, b - a));
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}
std::vector<double> vtu_points(const std::string& xml) {
  const std::size_t at = xml.find("<Points>");
  REQUIRE(at != std::string::npos);
  const std::size_t a = xml.find('>', xml.find("<DataArray", at)) + 1, b = xml.find("</DataArray>", a);
  std::istringstream in(xml.substr(a, b - a));
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}
}  // namespace

TEST_CASE("rt3 cli: .vtu and .npy hold the index text's tetrahedra, the same bytes from either backend", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  const fs::path in = t.dir / "w.xyz";
  REQUIRE(run(t, "gen ball 400 --seed 12 --weights 0,0.02 -o " + in.string()).code == 0);
  const fs::path txt = t.dir / "r.txt";
  REQUIRE(run(t, "rt3 " + in.string() + " -o " + txt.string()).code == 0);
  const auto tets = parse_rows(slurp(txt));
  REQUIRE(!tets.empty());
  for (const char* ext : {".npy", ".vtu"}) {
    const fs::path a = t.dir / (std::string("cpu") + ext), b = t.dir / (std::string("ref") + ext),
                   c = t.dir / (std::string("rtd") + ext);
    REQUIRE(run(t, "rt3 " + in.string() + " --threads 2 -o " + a.string()).code == 0);
    REQUIRE(run(t, "rt3 " + in.string() + " --backend reference -o " + b.string()).code == 0);
    REQUIRE(run(t, "rtd " + in.string() + " --dim 3 --backend reference -o " + c.string()).code == 0);
    CHECK(slurp(a) == slurp(b));
    CHECK(slurp(a) == slurp(c));
  }
  // .npy: int64 (m, 4), the index text's rows
  const auto [shape, values] = read_npy_int64(slurp(t.dir / "cpu.npy"));
  CHECK(shape == std::to_string(tets.size()) + ", 4");
  REQUIRE(values.size() == 4 * tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j) CHECK(values[4 * i + j] == tets[i][j]);
  // .vtu: VTK_TETRA cells over the used points (increasing input index,
  // carried as input_index), the coordinates the input's
  const std::string xml = slurp(t.dir / "cpu.vtu");
  const std::vector<double> index = vtu_array(xml, "input_index"), conn = vtu_array(xml, "connectivity"),
                            types = vtu_array(xml, "types"), offsets = vtu_array(xml, "offsets");
  REQUIRE(conn.size() == 4 * tets.size());
  REQUIRE(types.size() == tets.size());
  REQUIRE(offsets.size() == tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) {
    CHECK(types[i] == 10);
    CHECK(offsets[i] == double(4 * (i + 1)));
    for (std::size_t j = 0; j < 4; ++j) CHECK(index.at(static_cast<std::size_t>(conn[4 * i + j])) == tets[i][j]);
  }
  const std::vector<double> pts = vtu_points(xml);
  REQUIRE(pts.size() == 3 * index.size());
  std::vector<std::vector<double>> input;
  {
    std::istringstream f(slurp(in));
    for (std::string line; std::getline(f, line);) {
      std::istringstream ls(line);
      std::vector<double> r;
      for (double x; ls >> x;) r.push_back(x);
      if (!r.empty()) input.push_back(r);
    }
  }
  for (std::size_t k = 0; k < index.size(); ++k)
    for (std::size_t j = 0; j < 3; ++j) CHECK(pts[3 * k + j] == input.at(static_cast<std::size_t>(index[k]))[j]);
  // the tetrahedra have positive volume in the output's convention
  // (det[p1-p0, p2-p0, p3-p0] > 0 in floating point: a random ball is far
  // from degenerate)
  for (const auto& tet : tets) {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        m[r][c] = input[static_cast<std::size_t>(tet[static_cast<std::size_t>(r + 1)])][static_cast<std::size_t>(c)] -
                  input[static_cast<std::size_t>(tet[0])][static_cast<std::size_t>(c)];
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    CHECK(det > 0);
  }
}

TEST_CASE("rt3 cli: certify rt3|dt3 accepts the output and rejects corrupted ones", "[cli]") {
  TempDir t("flipflop_rt3_cli_");
  for (const char* kind : {"rt3", "dt3"}) {
    INFO(kind);
    const bool w = std::string(kind) == "rt3";
    const fs::path in = t.dir / (std::string(kind) + ".xyz"), out = t.dir / (std::string(kind) + ".txt");
    REQUIRE(run(t, std::string("gen cube 1500 --seed 13") + (w ? " --weights 0,0.005" : "") + " -o " + in.string())
                .code == 0);
    REQUIRE(run(t, std::string(kind) + " " + in.string() + " -o " + out.string()).code == 0);
    const std::string body = slurp(out);
    const int m = lines(body);
    const std::string k = std::string(kind);
    const Run canon = run(t, "certify " + k + " " + in.string() + " " + out.string() + " --canonical");
    INFO(canon.out << canon.err);
    CHECK(canon.code == 0);
    CHECK(canon.out == "certified (" + k + ", canonical): 1500 points in R^3, " + std::to_string(m) + " tetrahedra\n");
    const Run exact = run(t, "certify " + k + " " + in.string() + " " + out.string());
    CHECK(exact.code == 0);
    CHECK(exact.out.find("certified (" + k + ", exact)") == 0);
    if (w) {  // the alias: certify rtd --dim 3 gives the same verdict
      const Run rtd = run(t, "certify rtd " + in.string() + " " + out.string() + " --dim 3 --canonical");
      CHECK(rtd.code == 0);
      CHECK(rtd.out == "certified (rtd, canonical): 1500 points in R^3, " + std::to_string(m) + " simplices\n");
    }
    // corruptions: a reversed tetrahedron, a missing one, a repeated one, an
    // index out of range, a non-regular pair (2-3 flip of an interior facet
    // is not attempted here: the reversed and missing ones cover the
    // orientation and the tiling)
    std::vector<std::string> rows;
    {
      std::istringstream s(body);
      for (std::string line; std::getline(s, line);) rows.push_back(line);
    }
    const auto join = [](const std::vector<std::string>& v) {
      std::string s;
      for (const std::string& x : v) s += x + "\n";
      return s;
    };
    std::vector<std::string> reversed = rows, missing = rows, repeated = rows, out_of_range = rows;
    {
      std::istringstream ls(rows[rows.size() / 2]);
      long a, b, c, d;
      ls >> a >> b >> c >> d;
      reversed[rows.size() / 2] =
          std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + " " + std::to_string(c);
    }
    missing.erase(missing.begin() + static_cast<long>(rows.size() / 3));
    repeated.push_back(rows.back());
    out_of_range[0] = "0 1 2 999999";
    for (const auto& [name, text] : {std::pair<std::string, std::string>{"reversed", join(reversed)},
                                     {"missing", join(missing)},
                                     {"repeated", join(repeated)},
                                     {"out of range", join(out_of_range)}}) {
      INFO(name);
      const fs::path bad = t.file("bad.txt", text);
      for (const char* level : {"", " --canonical"}) {
        const Run r = run(t, "certify " + k + " " + in.string() + " " + bad.string() + level);
        INFO(r.out << r.err);
        CHECK(r.code == 1);
        CHECK(r.out.find("NOT certified (" + k + ", ") == 0);
      }
    }
    // a line that is not a tetrahedron: one line naming the file, exit 2
    const fs::path three = t.file("three.txt", "0 1 2\n");
    const Run malformed = run(t, "certify " + k + " " + in.string() + " " + three.string());
    expect_one_line_error(malformed, "three.txt");
  }
  // the unweighted points under certify rt3: no weight column, one line
  const Run cols = run(t, "certify rt3 " + (t.dir / "dt3.xyz").string() + " " + (t.dir / "dt3.txt").string());
  expect_one_line_error(cols, "column");
  // rt3's output is not dt3's (the weights matter)
  const Run weights = run(t, "certify dt3 " + t.file("dt3_of_rt3.xyz", [&] {
                               std::string out;
                               std::istringstream in(slurp(t.dir / "rt3.xyz"));
                               for (std::string line; std::getline(in, line);)
                                 if (!line.empty()) out += line.substr(0, line.rfind(' ')) + "\n";
                               return out;
                             }()).string() + " " + (t.dir / "rt3.txt").string() + " --canonical");
  CHECK(weights.code == 1);
}

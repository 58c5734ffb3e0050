// cli_test.cpp — the command-line contract: bad input gets one clear line and
// exit code 2; valid extreme input gets a certified answer; certify accepts
// right answers (ours and Qhull's) and rejects wrong ones with exit code 1.
#include <catch2/catch.hpp>

#include <algorithm>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "io/read_points.hpp"
#include "io/write_points.hpp"
#include "peers/cgal_regular_d.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "peers/peers.hpp"
#include "proptests/support/cli_run.hpp"

namespace fs = std::filesystem;
using namespace flipflop::test::cli;

TEST_CASE("cli: bad input matrix gives one line and exit code 2", "[cli]") {
  TempDir t;
  struct Case {
    const char* kind;
    const char* file;
    const char* content;
    const char* what;  // a word the message must contain
  };
  const Case cases[] = {
      {"hull2", "empty.xyz", "", "no points"},
      {"hull2", "comments.xyz", "# only a comment\n\n", "no points"},
      {"hull2", "one.xyz", "1 2\n", "at least 3"},
      {"hull3", "three.xyz", "0 0 0\n1 0 0\n0 1 0\n", "at least 4"},
      {"hull2", "equal.xyz", "1 1\n1 1\n1 1\n1 1\n", "lower-dimensional"},
      {"hull2", "collinear.xyz", "0 0\n1 1\n2 2\n3 3\n", "collinear"},
      {"hull3", "coplanar.xyz", "0 0 1\n1 0 1\n0 1 1\n1 1 1\n2 3 1\n", "coplanar"},
      {"hull3", "collinear3.xyz", "0 0 0\n1 1 1\n2 2 2\n3 3 3\n", "collinear"},
      {"hull2", "nan.xyz", "0 0\n1 0\nnan 1\n", "NaN"},
      {"hull2", "inf.xyz", "0 0\n1 0\n0 inf\n", "Inf"},
      {"hull2", "overflow.xyz", "0 0\n1 0\n0 1e400\n", "1e400"},
      {"hull2", "malformed.xyz", "0 0\n1 0\n0 1x\n", "1x"},
      {"hull2", "columns.xyz", "0 0\n1 0 5\n0 1\n", "column"},
      {"rt2", "noweight.xyz", "0 0\n1 0\n0 1\n", "column"},
  };
  for (const Case& c : cases) {
    SECTION(std::string(c.kind) + " " + c.file) {
      fs::path p = t.file(c.file, c.content);
      expect_input_error(run(t, std::string(c.kind) + " " + p.string()), c.file, c.what);
    }
  }
  SECTION("the error names the line") {
    fs::path p = t.file("line3.xyz", "0 0\n# comment\n1 zero\n0 1\n");
    Run r = run(t, "hull2 " + p.string());
    expect_input_error(r, "line3.xyz:3", "zero");
  }
  SECTION("unreadable file") {
    expect_input_error(run(t, "hull2 " + (t.dir / "missing.xyz").string()), "missing.xyz", "");
    expect_input_error(run(t, "hull2 " + t.dir.string() + "/"), t.dir.string(), "");
  }
  SECTION("a 2 GB file of garbage gives one line at once") {
    // sparse: no disk space used; every byte reads as NUL
    fs::path big = t.dir / "garbage.xyz";
    { std::ofstream(big) << ""; }
    fs::resize_file(big, std::uintmax_t{2} << 30);
    expect_input_error(run(t, "hull2 " + big.string()), "garbage.xyz:1", "");
    // random bytes in each format
    std::string bytes;
    std::srand(7);
    for (int i = 0; i < 1 << 20; ++i) bytes.push_back(static_cast<char>(std::rand() & 0xff));
    for (const char* name : {"random.xyz", "random.off", "random.ply"}) {
      fs::path p = t.file(name, bytes);
      expect_input_error(run(t, "hull3 " + p.string()), name, "");
    }
  }
  SECTION("unknown extension") {
    fs::path p = t.file("points.txt", "0 0\n1 0\n0 1\n");
    expect_input_error(run(t, "hull2 " + p.string()), "points.txt", "");
  }
  SECTION("output path that cannot be written") {
    fs::path p = t.file("ok.xyz", "0 0\n1 0\n0 1\n");
    Run r = run(t, "hull2 " + p.string() + " -o " + (t.dir / "no" / "such" / "dir.txt").string());
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find("dir.txt") != std::string::npos);
  }
  SECTION("usage errors") {
    Run r = run(t, "hull2");
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
    r = run(t, "nosuchcommand");
    CHECK(r.code == 2);
    fs::path p = t.file("ok.xyz", "0 0\n1 0\n0 1\n");
    r = run(t, "hull2 " + p.string() + " --backend nosuch");
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
  }
}

TEST_CASE("cli: extreme magnitudes give certified answers equal to CGAL's", "[cli]") {
  TempDir t;
  // general position, so the answer is the strictly convex hull CGAL reports
  const char* sets[] = {
      "1e308 1e308\n-1e308 1.5e308\n-1.7e308 -1e308\n1.2e308 -1.6e308\n1e307 2e306\n",
      "4.9e-324 0\n1e-310 4.9e-324\n0 2e-310\n-3e-310 -1e-315\n1e-320 1e-320\n",
      "1e-300 1e300\n-1e300 1e-300\n1e300 -1e300\n0.5 0.25\n-1e-300 -1e300\n",
  };
  int k = 0;
  for (const char* content : sets) {
    fs::path p = t.file("extreme" + std::to_string(k++) + ".xyz", content);
    fs::path out = t.dir / "hull.txt";
    Run r = run(t, "hull2 " + p.string() + " -o " + out.string());
    INFO(p << ": " << r.err);
    REQUIRE(r.code == 0);
    Run c = run(t, "certify hull2 " + p.string() + " " + out.string() + " --canonical");
    CHECK(c.code == 0);
    flipflop::PointSet ps = flipflop::io::read_points(p.string(), 2, false);
    std::string expect;
    for (auto v : flipflop::peers::cgal_hull2(ps, flipflop::peers::Hull2Algo::akl_toussaint))
      expect += std::to_string(v) + "\n";
    CHECK(slurp(out) == expect);
  }
}

TEST_CASE("cli: certify accepts Qhull's output and rejects a broken one", "[cli]") {
  TempDir t;
  fs::path pts = t.dir / "ball.xyz";
  REQUIRE(run(t, "gen ball 2000 --seed 7 -o " + pts.string()).code == 0);
  // qhull's input format: dimension, count, then the coordinates
  fs::path qin = t.dir / "ball.qh", qout = t.dir / "ball.qhull";
  {
    std::ifstream in(pts);
    std::stringstream body;
    body << in.rdbuf();
    std::ofstream q(qin);
    q << "3\n" << lines(body.str()) << "\n" << body.str();
  }
  REQUIRE(std::system(("qhull i Qt < " + qin.string() + " > " + qout.string()).c_str()) == 0);
  Run ok = run(t, "certify hull3 " + pts.string() + " " + qout.string());
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  CHECK(ok.out.find("certified") == 0);
  // break it: reverse the orientation of the last facet
  std::string text = slurp(qout);
  const std::size_t last = text.rfind('\n', text.size() - 2) + 1;
  std::istringstream facet(text.substr(last));
  long a = 0, b = 0, c = 0;
  REQUIRE(static_cast<bool>(facet >> a >> b >> c));
  text = text.substr(0, last) + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\n";
  fs::path broken = t.file("broken.qhull", text);
  Run bad = run(t, "certify hull3 " + pts.string() + " " + broken.string());
  CHECK(bad.code == 1);
  CHECK(bad.out.find("NOT certified") != std::string::npos);
  // the parallel checks name the same first violation at any thread count
  for (const char* threads : {"1", "2", "8"}) {
    Run par = run(t, "certify hull3 " + pts.string() + " " + broken.string() + " --threads " + threads);
    CHECK(par.code == 1);
    CHECK(par.out == bad.out);
  }
}

TEST_CASE("cli: certify rt2|dt2 --threads N gives the verdict and message of the sequential checks", "[cli]") {
  TempDir t;
  for (const char* kind : {"rt2", "dt2"}) {
    const fs::path pts = t.dir / (std::string(kind) + ".xyz"), out = t.dir / (std::string(kind) + ".txt");
    const std::string w = std::string(kind) == "rt2" ? " --weights 0,0.001" : "";
    REQUIRE(run(t, "gen square 12000 --seed 3" + w + " -o " + pts.string()).code == 0);
    REQUIRE(run(t, std::string(kind) + " " + pts.string() + " -o " + out.string()).code == 0);
    // broken: the middle triangle dropped (a hole: condition boundary)
    std::istringstream lines_in(slurp(out));
    std::vector<std::string> tri_lines;
    for (std::string line; std::getline(lines_in, line);) tri_lines.push_back(line);
    std::string text;
    for (std::size_t i = 0; i < tri_lines.size(); ++i)
      if (i != tri_lines.size() / 2) text += tri_lines[i] + "\n";
    const fs::path broken = t.file(std::string(kind) + "_broken.txt", text);
    for (const char* level : {"", " --canonical"}) {
      const Run good = run(t, "certify " + std::string(kind) + " " + pts.string() + " " + out.string() + level);
      const Run bad = run(t, "certify " + std::string(kind) + " " + pts.string() + " " + broken.string() + level);
      INFO(kind << level << ": " << good.out << good.err << bad.out << bad.err);
      CHECK(good.code == 0);
      CHECK(bad.code == 1);
      CHECK(bad.out.find("NOT certified") != std::string::npos);
      for (const char* threads : {"1", "2", "8"}) {
        const std::string opt = std::string(level) + " --threads " + threads;
        const Run par_good = run(t, "certify " + std::string(kind) + " " + pts.string() + " " + out.string() + opt);
        const Run par_bad = run(t, "certify " + std::string(kind) + " " + pts.string() + " " + broken.string() + opt);
        CHECK(par_good.code == 0);
        CHECK(par_good.out == good.out);
        CHECK(par_bad.code == 1);
        CHECK(par_bad.out == bad.out);
      }
    }
  }
}

TEST_CASE("cli: gen -o FILE.npy writes the points .xyz holds and every command reads it", "[cli]") {
  TempDir t;
  for (const char* job : {"hull3 ball", "hull2 disk", "rt2 square"}) {
    const std::string kind = std::string(job).substr(0, 4) == "hull" ? std::string(job, 5) : "rt2";
    const std::string dist = std::string(job).substr(kind.size() + 1);
    const std::string w = kind == "rt2" ? " --weights 0,0.001" : "";
    const fs::path npy = t.dir / "p.npy", xyz = t.dir / "p.xyz", a = t.dir / "a.txt", b = t.dir / "b.txt";
    REQUIRE(run(t, "gen " + dist + " 3000 --seed 4" + w + " -o " + npy.string()).code == 0);
    REQUIRE(run(t, "gen " + dist + " 3000 --seed 4" + w + " -o " + xyz.string()).code == 0);
    REQUIRE(slurp(npy).substr(0, 6) == "\x93NUMPY");
    Run from_npy = run(t, kind + " " + npy.string() + " -o " + a.string());
    Run from_xyz = run(t, kind + " " + xyz.string() + " -o " + b.string());
    INFO(job << ": " << from_npy.err << from_xyz.err);
    REQUIRE(from_npy.code == 0);
    REQUIRE(from_xyz.code == 0);
    CHECK(slurp(a) == slurp(b));
    CHECK(!slurp(a).empty());
  }
}

TEST_CASE("cli: computed answers round-trip through certify --canonical", "[cli]") {
  TempDir t;
  const char* jobs[][3] = {{"grid2", "hull2", "60"}, {"grid3", "hull3", "40"}, {"sphere-lattice", "hull3", "60"},
                           {"grid2", "dt2", "40"},   {"square", "rt2", "50"},  {"duplicates2", "dt2", "30"}};
  for (auto& j : jobs) {
    SECTION(std::string(j[1]) + " on " + j[0]) {
      fs::path pts = t.dir / "in.xyz", out = t.dir / "out.txt";
      std::string w = std::string(j[1]) == "rt2" ? " --weights 0,0.01" : "";
      REQUIRE(run(t, std::string("gen ") + j[0] + " " + j[2] + w + " -o " + pts.string()).code == 0);
      Run r = run(t, std::string(j[1]) + " " + pts.string() + " -o " + out.string() + " --stats");
      INFO(r.err);
      REQUIRE(r.code == 0);
      CHECK(r.err.find("certify") != std::string::npos);
      CHECK(run(t, std::string("certify ") + j[1] + " " + pts.string() + " " + out.string() + " --canonical").code == 0);
      CHECK(run(t, std::string("certify ") + j[1] + " " + pts.string() + " " + out.string()).code == 0);
    }
  }
}

namespace {
// `kind IN` with the cpu backend (by default and named, at 1, 2, 8 threads)
// writes the bytes of --backend reference; each of `bad` exits 2 with one line.
void check_cpu_backend(TempDir& t, const std::string& kind, const fs::path& in, const std::vector<std::string>& bad) {
  const fs::path ref_out = t.dir / "ref.txt";
  REQUIRE(run(t, kind + " " + in.string() + " --backend reference -o " + ref_out.string()).code == 0);
  const std::string expect = slurp(ref_out);
  REQUIRE(!expect.empty());
  for (const char* opts : {"", "--backend cpu", "--backend cpu --threads 1", "--threads 2", "--threads 8"}) {
    const fs::path out = t.dir / "cpu.txt";
    const Run r = run(t, kind + " " + in.string() + " " + opts + " -o " + out.string());
    INFO(opts << ": " << r.err);
    REQUIRE(r.code == 0);
    CHECK(slurp(out) == expect);
  }
  const Run s = run(t, kind + " " + in.string() + " --threads 2 --stats -o " + (t.dir / "x.txt").string());
  CHECK(s.err.find("backend cpu (2 threads)") != std::string::npos);
  for (const std::string& b : bad) {
    const Run r = run(t, kind + " " + in.string() + " " + b);
    INFO(b << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
  }
}
}  // namespace

TEST_CASE("cli: hull3 --backend cpu --threads N writes the reference's bytes, bad options get one line",
          "[cli]") {
  TempDir t;
  std::string grid;  // a 6x6x6 lattice: heavily degenerate (coplanar faces with many points)
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 6; ++z) grid += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  check_cpu_backend(t, "hull3", t.file("grid.xyz", grid),
                    {"--threads 0", "--threads -3", "--threads x", "--backend cpu --algo splay",
                     "--backend reference --threads 2", "--algo twist-flip --threads 2"});
}

TEST_CASE("cli: rt2 and dt2 --backend cpu (the default) write the reference's bytes, bad options get one line",
          "[cli]") {
  TempDir t;
  // an 8x8 grid with repeated points (cocircular quadruples, collinear
  // boundary points, duplicates); weighted: quarter weights
  std::string dt, rt;
  for (int k = 0; k < 80; ++k) {
    const int x = k % 8, y = (k / 8) % 8;
    dt += std::to_string(x) + " " + std::to_string(y) + "\n";
    rt += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string((k % 5) * 0.25) + "\n";
  }
  const std::vector<std::string> bad = {"--threads 0", "--threads -1", "--backend cpu --algo lawson",
                                        "--backend reference --algo incremental", "--backend reference --threads 2",
                                        "--algo ffrt --threads 2"};
  check_cpu_backend(t, "dt2", t.file("grid.xyz", dt), bad);
  check_cpu_backend(t, "rt2", t.file("grid_w.xyz", rt), {bad[0], bad[1], bad[3], bad[4], bad[5]});
  // the strict view from the cpu backend's answer is the reference's
  const fs::path grid = t.dir / "grid.xyz";
  REQUIRE(run(t, "dt2 " + grid.string() + " --strict -o " + (t.dir / "s_cpu.txt").string()).code == 0);
  REQUIRE(run(t, "dt2 " + grid.string() + " --strict --backend reference -o " + (t.dir / "s_ref.txt").string()).code == 0);
  CHECK(slurp(t.dir / "s_cpu.txt") == slurp(t.dir / "s_ref.txt"));
  // the parallel insertions (stage 2b) are the cpu backend's: the same bytes
  REQUIRE(run(t, "dt2 " + grid.string() + " --backend reference -o " + (t.dir / "ref.txt").string()).code == 0);
  for (const char* algo : {"territories", "batches"}) {
    INFO(algo);
    const fs::path out = t.dir / (std::string(algo) + ".txt");
    REQUIRE(run(t, "dt2 " + grid.string() + " --algo " + algo + " --threads 2 -o " + out.string()).code == 0);
    CHECK(slurp(out) == slurp(t.dir / "ref.txt"));
    CHECK(run(t, "dt2 " + grid.string() + " --backend reference --algo " + algo).code != 0);
  }
}

TEST_CASE("cli: certify rtd (exact and --canonical) accepts rtd's output and CGAL's, rejects a reversed simplex", "[cli]") {
  TempDir t;
  for (int d = 2; d <= 5; ++d) {
    INFO("d=" << d);
    std::mt19937_64 g(40 + static_cast<unsigned>(d));
    std::uniform_real_distribution<double> u(0, 1), w(0, 0.01);
    const std::size_t n = d == 5 ? 30 : 80;
    flipflop::PointSet ps;
    ps.dim = d;
    ps.weighted = true;
    for (std::size_t i = 0; i < n; ++i) {
      for (int j = 0; j < d; ++j) ps.coords.push_back(u(g));
      ps.weights.push_back(w(g));
    }
    std::ostringstream os;
    flipflop::io::write_points(os, ps);  // shortest round-trip decimals
    const std::string text = os.str();
    const fs::path in = t.file("p.xyz", text), out = t.dir / "rt.txt", cg = t.dir / "cgal.txt";
    const std::string dim = " --dim " + std::to_string(d);
    REQUIRE(run(t, "rtd " + in.string() + dim + " -o " + out.string()).code == 0);
    Run ok = run(t, "certify rtd " + in.string() + " " + out.string() + dim + " --canonical");
    INFO(ok.out << ok.err);
    CHECK(ok.code == 0);
    CHECK(ok.out.find("certified (rtd, canonical)") == 0);
    // CGAL's regular triangulation (general position: the same answer),
    // written independently in the volume convention
    std::ofstream(cg) << flipflop::simplices_text(flipflop::peers::cgal_regular_d(ps));
    CHECK(run(t, "certify rtd " + in.string() + " " + cg.string() + dim + " --canonical").code == 0);
    // a reversed simplex: swap the last two indices of the first line
    std::string body = slurp(out);
    const std::size_t eol = body.find('\n'), sp = body.rfind(' ', eol), sp2 = body.rfind(' ', sp - 1);
    body = body.substr(0, sp2 + 1) + body.substr(sp + 1, eol - sp - 1) + " " + body.substr(sp2 + 1, sp - sp2 - 1) +
           body.substr(eol);
    const fs::path bad = t.file("bad.txt", body);
    Run no = run(t, "certify rtd " + in.string() + " " + bad.string() + dim + " --canonical");
    CHECK(no.code == 1);
    CHECK(no.out.find("NOT certified (rtd, canonical)") == 0);
    // the exact level (any tie-breaking): rtd's and CGAL's pass, the reversed simplex fails
    Run exact = run(t, "certify rtd " + in.string() + " " + out.string() + dim);
    CHECK(exact.code == 0);
    CHECK(exact.out.find("certified (rtd, exact)") == 0);
    CHECK(run(t, "certify rtd " + in.string() + " " + cg.string() + dim).code == 0);
    CHECK(run(t, "certify rtd " + in.string() + " " + bad.string() + dim).code == 1);
  }
}

TEST_CASE("cli: rtd --strict on a 4x4x4 grid: 6 tetrahedra per cube, certified as strict, and the canonical answer is not", "[cli]") {
  TempDir t;
  std::string grid;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int z = 0; z < 4; ++z) grid += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " 0\n";
  const fs::path in = t.file("grid.xyz", grid), canon = t.dir / "c.txt", strict = t.dir / "s.txt";
  REQUIRE(run(t, "rtd " + in.string() + " --dim 3 -o " + canon.string()).code == 0);
  Run s = run(t, "rtd " + in.string() + " --dim 3 --strict -o " + strict.string());
  INFO(s.out << s.err);
  REQUIRE(s.code == 0);
  const std::string body = slurp(strict);
  CHECK(std::count(body.begin(), body.end(), '\n') == 27 * 6);  // the pulling triangulation of each cube
  Run ok = run(t, "certify rtd " + in.string() + " " + strict.string() + " --dim 3 --strict");
  CHECK(ok.code == 0);
  CHECK(ok.out.find("certified (rtd, strict)") == 0);
  Run no = run(t, "certify rtd " + in.string() + " " + canon.string() + " --dim 3 --strict");  // zero-volume tetrahedra
  CHECK(no.code == 1);
  CHECK(no.out.find("NOT certified (rtd, strict): simplex-orientation") == 0);
  Run both = run(t, "certify rtd " + in.string() + " " + strict.string() + " --dim 3 --strict --canonical");
  CHECK(both.code == 2);
}

TEST_CASE("cli: dt2/rt2 --strict on a 12x12 grid: CGAL's 242 triangles, no zero-area one, certified", "[cli]") {
  TempDir t;
  std::string grid;
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y) grid += std::to_string(x) + " " + std::to_string(y) + "\n";
  const fs::path in = t.file("g.xyz", grid), out = t.dir / "s.txt", canon = t.dir / "c.txt";
  REQUIRE(run(t, "dt2 " + in.string() + " -o " + canon.string()).code == 0);
  REQUIRE(run(t, "dt2 " + in.string() + " --strict -o " + out.string()).code == 0);
  CHECK(lines(slurp(canon)) > 242);  // the canonical answer holds zero-area triangles along the boundary
  CHECK(lines(slurp(out)) == 242);   // CGAL's count: 2 n - h - 2 = 288 - 44 - 2
  Run ok = run(t, "certify dt2 " + in.string() + " " + out.string());
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  // every triangle has non-zero area (the grid's coordinates are small integers: exact in doubles)
  flipflop::PointSet ps = flipflop::io::read_points(in.string(), 2, false);
  std::istringstream tri(slurp(out));
  for (unsigned a, b, c; tri >> a >> b >> c;) {
    const double* p = ps.point(a);
    const double *q = ps.point(b), *r = ps.point(c);
    CHECK((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0);
  }
  Run refused = run(t, "hull2 " + in.string() + " --strict");
  CHECK(refused.code == 2);
  CHECK(lines(refused.err) == 1);
  // certify --strict: the strict view passes, the canonical answer (zero-area
  // triangles) does not
  Run strict = run(t, "certify dt2 " + in.string() + " " + out.string() + " --strict");
  CHECK(strict.code == 0);
  CHECK(strict.out == "certified (dt2, strict): 144 points, 242 triangles\n");
  Run flat = run(t, "certify dt2 " + in.string() + " " + canon.string() + " --strict");
  CHECK(flat.code == 1);
  CHECK(flat.out.find("NOT certified (dt2, strict): zero-area") == 0);
}

TEST_CASE("cli: certify hull3 --strict [--triangulate] checks hull3's strict views", "[cli]") {
  TempDir t;
  const fs::path in = t.dir / "g.xyz", poly = t.dir / "p.txt", tri = t.dir / "t.txt";
  REQUIRE(run(t, "gen sphere-lattice 2000 -o " + in.string()).code == 0);
  REQUIRE(run(t, "hull3 " + in.string() + " --strict -o " + poly.string()).code == 0);
  REQUIRE(run(t, "hull3 " + in.string() + " --strict --triangulate -o " + tri.string()).code == 0);
  Run p = run(t, "certify hull3 " + in.string() + " " + poly.string() + " --strict");
  INFO(p.out << p.err);
  CHECK(p.code == 0);
  CHECK(p.out.find("certified (hull3, strict): 2000 points, ") == 0);
  Run q = run(t, "certify hull3 " + in.string() + " " + tri.string() + " --strict --triangulate");
  CHECK(q.code == 0);
  // the triangulated view is not the polygon view (coplanar neighbours), when
  // some facet has more than three vertices
  bool polygons = false;
  {
    std::istringstream ls(slurp(poly));
    std::string line;
    while (std::getline(ls, line)) polygons = polygons || std::count(line.begin(), line.end(), ' ') >= 3;
  }
  REQUIRE(polygons);
  Run mixed = run(t, "certify hull3 " + in.string() + " " + tri.string() + " --strict");
  CHECK(mixed.code == 1);
  CHECK(mixed.out.find("NOT certified (hull3, strict): maximal-facets") == 0);
  // a facet reversed: the last line's vertices in the opposite order
  std::string text = slurp(poly);
  const std::size_t last = text.rfind('\n', text.size() - 2) + 1;
  std::istringstream facet(text.substr(last));
  std::vector<std::string> vs;
  for (std::string v; facet >> v;) vs.push_back(v);
  std::string reversed;
  for (auto it = vs.rbegin(); it != vs.rend(); ++it) reversed += (reversed.empty() ? "" : " ") + *it;
  const fs::path bad = t.file("bad.txt", text.substr(0, last) + reversed + "\n");
  Run wrong = run(t, "certify hull3 " + in.string() + " " + bad.string() + " --strict");
  CHECK(wrong.code == 1);
  CHECK(wrong.out.find("NOT certified (hull3, strict): facet-polygon") == 0);
  // a count that does not match the lines: one line naming the file, exit 2
  const fs::path short_file = t.file("short.txt", text.substr(0, last));
  Run malformed = run(t, "certify hull3 " + in.string() + " " + short_file.string() + " --strict");
  CHECK(malformed.code == 2);
  CHECK(lines(malformed.err) == 1);
  CHECK(malformed.err.find(short_file.string()) != std::string::npos);
  Run misuse = run(t, "certify hull3 " + in.string() + " " + poly.string() + " --strict --canonical");
  CHECK(misuse.code == 2);
  Run misuse2 = run(t, "certify hull2 " + in.string() + " " + poly.string() + " --strict");
  CHECK(misuse2.code == 2);
}

TEST_CASE("cli: hull2 --backend cpu --threads N writes the reference's bytes, bad options and collinear input "
          "get one line",
          "[cli]") {
  TempDir t;
  std::string grid;  // a 40x40 lattice (enough points for the throw-away): many collinear hull points
  for (int x = 0; x < 40; ++x)
    for (int y = 0; y < 40; ++y) grid += std::to_string(x) + " " + std::to_string(y) + "\n";
  check_cpu_backend(t, "hull2", t.file("grid2.xyz", grid),
                    {"--threads 0", "--threads -3", "--threads x", "--backend cpu --algo twist",
                     "--backend reference --threads 2", "--algo twist --threads 2"});
  // the cpu backend's Graham-insertion writes the same bytes
  const fs::path a = t.dir / "insert.txt", b = t.dir / "sort.txt";
  REQUIRE(run(t, "hull2 " + (t.dir / "grid2.xyz").string() + " --algo graham-insert --backend cpu --threads 2 -o " +
                     a.string()).code == 0);
  REQUIRE(run(t, "hull2 " + (t.dir / "grid2.xyz").string() + " --backend reference -o " + b.string()).code == 0);
  CHECK(slurp(a) == slurp(b));
  std::string line;  // 2000 collinear points
  for (int i = 0; i < 2000; ++i) line += std::to_string(i) + " " + std::to_string(2 * i + 1) + "\n";
  const fs::path flat = t.file("line.xyz", line);
  for (const char* backend : {"cpu", "reference"}) {
    const Run r = run(t, "hull2 " + flat.string() + " --backend " + backend);
    INFO(backend << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(lines(r.err) == 1);
  }
}

#ifdef FLIPFLOP_HAVE_KERNELS_GPU
// A --backend cuda run: the expected bytes where a device and the CUDA
// kernels are, else one line saying which is missing, exit 2, no output.
void check_cuda_run(const Run& cuda, const fs::path& got, const fs::path& expect) {
  if (cuda.code == 0) {
    CHECK(slurp(got) == slurp(expect));
    return;
  }
  INFO(cuda.err);
  CHECK(cuda.code == 2);
  CHECK(lines(cuda.err) == 1);
  CHECK((cuda.err.find("no CUDA device") != std::string::npos ||
         cuda.err.find("without the CUDA algorithm kernels") != std::string::npos));
  CHECK(!fs::exists(got));
}
#endif

TEST_CASE("cli: --backend cuda-omp writes the reference's bytes, and --backend cuda writes them or says in one line "
          "that there is no device",
          "[cli]") {
  TempDir t;
  std::string grid, random;  // a lattice (collinear hull points) and scattered points
  for (int x = 0; x < 60; ++x)
    for (int y = 0; y < 60; ++y) grid += std::to_string(x) + " " + std::to_string(y) + "\n";
  std::string cube;  // a 12^3 lattice: coplanar hull facets
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y)
      for (int z = 0; z < 12; ++z) cube += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  std::string weighted3;  // a 7^3 lattice with weights of three sizes (equal and lattice weights: SoS decides)
  for (int x = 0; x < 7; ++x)
    for (int y = 0; y < 7; ++y)
      for (int z = 0; z < 7; ++z)
        weighted3 += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " " +
                     std::to_string((x + 2 * y + 3 * z) % 3 * 0.25) + "\n";
  std::string weighted;  // integer points with weights of three sizes (some points redundant)
  std::srand(7);
  for (int i = 0; i < 5000; ++i)
    random += std::to_string(std::rand() % 100000) + " " + std::to_string(std::rand() % 100000) + "\n";
  for (int i = 0; i < 3000; ++i)
    weighted += std::to_string(std::rand() % 1000) + " " + std::to_string(std::rand() % 1000) + " " +
                std::to_string(std::rand() % 3 * 50) + "\n";
  struct Job {
    const char* kind;
    fs::path in;
    std::vector<std::string> bad;  // option sets the GPU backends refuse
  };
  const std::vector<Job> jobs = {
      {"hull2", t.file("grid.xyz", grid), {"--backend cuda-omp --algo twist", "--backend cuda-omp --threads 2"}},
      {"hull2", t.file("random.xyz", random), {}},
      {"dt2", t.file("grid.xyz", grid), {"--backend cuda-omp --algo lawson", "--backend cuda --algo incremental"}},
      {"rt2", t.file("weighted.xyz", weighted), {"--backend cuda-omp --threads 2"}},
      {"hull3", t.file("cube.xyz", cube), {"--backend cuda-omp --algo splay"}},
      {"dt3", t.file("cube.xyz", cube), {"--backend cuda-omp --threads 2"}},
      {"rt3", t.file("weighted3.xyz", weighted3), {"--backend cuda --threads 2"}}};
  for (const Job& j : jobs) {
    const fs::path expect = t.dir / "expect.txt", got = t.dir / "got.txt";
    REQUIRE(run(t, std::string(j.kind) + " " + j.in.string() + " --backend reference -o " + expect.string()).code == 0);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    const Run omp = run(t, std::string(j.kind) + " " + j.in.string() + " --backend cuda-omp -o " + got.string());
    INFO(j.kind << " " << j.in << ": " << omp.err);
    REQUIRE(omp.code == 0);
    CHECK(slurp(got) == slurp(expect));
    fs::remove(got);
    if (std::string(j.kind) == "hull3") {
      // --stats says whether the run needed the exact kernel point (issue 38:
      // the kernel decides it on the device; these inputs do not need it)
      const Run st = run(t, "hull3 " + j.in.string() + " --backend cuda-omp --stats -o " + got.string());
      INFO(st.err);
      CHECK(st.err.find("hull3: exact kernel point: 0 ") != std::string::npos);
      CHECK(st.err.find("hull3: handed back: 0 ") != std::string::npos);  // issue 36's counter
      fs::remove(got);
    }
    check_cuda_run(run(t, std::string(j.kind) + " " + j.in.string() + " --backend cuda -o " + got.string()), got,
                   expect);
    for (const std::string& opts : j.bad) {
      const Run r = run(t, std::string(j.kind) + " " + j.in.string() + " " + opts);
      INFO(opts << ": " << r.err);
      CHECK(r.code == 2);
      CHECK(lines(r.err) == 1);
    }
#else
    // without the thrust/OpenMP build the GPU backends are not offered
    const Run r = run(t, std::string(j.kind) + " " + j.in.string() + " --backend cuda-omp");
    CHECK(r.code == 2);
#endif
  }
}

// gHull (kernels_cuda/hull3/ghull.hpp) from the command line: the GPU
// backends' own algorithm, cuda-omp by default; the reference's bytes on a
// lattice (coplanar hull facets, interior points) and scattered points;
// --stats reports its stages and no hand-back; the other backends refuse it in
// one line.
TEST_CASE("cli: hull3 --algo ghull writes the reference's bytes on the GPU backends, others refuse it", "[cli]") {
  TempDir t;
  std::string cube, scattered;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y)
      for (int z = 0; z < 10; ++z) cube += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  std::srand(11);
  for (int i = 0; i < 4000; ++i)
    scattered += std::to_string(std::rand() % 1000) + " " + std::to_string(std::rand() % 1000) + " " +
                 std::to_string(std::rand() % 1000) + "\n";
  for (const fs::path& in : {t.file("cube.xyz", cube), t.file("scattered.xyz", scattered)}) {
    const fs::path expect = t.dir / "expect.txt", got = t.dir / "got.txt";
    REQUIRE(run(t, "hull3 " + in.string() + " --backend reference -o " + expect.string()).code == 0);
#ifdef FLIPFLOP_HAVE_KERNELS_GPU
    const Run r = run(t, "hull3 " + in.string() + " --algo ghull --stats -o " + got.string());
    INFO(in << ": " << r.err);
    REQUIRE(r.code == 0);
    CHECK(slurp(got) == slurp(expect));
    CHECK(r.err.find("hull3: backend cuda-omp, algo ghull") != std::string::npos);
    CHECK(r.err.find("hull3: handed back: 0 ") != std::string::npos);
    CHECK(r.err.find("depth misses 0") != std::string::npos);
    CHECK(r.err.find("stage 6: verification") != std::string::npos);
    fs::remove(got);
    check_cuda_run(run(t, "hull3 " + in.string() + " --backend cuda --algo ghull -o " + got.string()), got, expect);
    for (const char* backend : {"reference", "cpu"}) {
      const Run bad = run(t, "hull3 " + in.string() + " --backend " + backend + " --algo ghull");
      INFO(backend << ": " << bad.err);
      CHECK(bad.code == 2);
      CHECK(lines(bad.err) == 1);
    }
#else
    const Run r = run(t, "hull3 " + in.string() + " --algo ghull");
    CHECK(r.code == 2);
#endif
  }
}

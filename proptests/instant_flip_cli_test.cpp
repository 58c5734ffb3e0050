// instant_flip_cli_test.cpp — `flipflop rtd` and `flipflop instant-flip`
// (cli/rtd_commands.hpp), called as functions on small files: good input gives
// the canonical simplex list that the certifier accepts and a fresh
// construction reproduces; bad input gives one UsageError line.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

// The command functions are compiled into this test directly (the tool's
// executable is the only other place they are built).
#include "cli/commands.hpp"
#include "cli/rtd_commands.hpp"
#include "io/read_points.hpp"
#include "reference/rtd/canonical_d.hpp"
#include "reference/rtd/certify_rtd.hpp"
#include "reference/rtd/rt_incremental.hpp"
#include "support/instant_flip_oracles.hpp"

namespace fs = std::filesystem;
using namespace flipflop;
using namespace flipflop::test_if;

namespace {

struct TempDir {
  fs::path dir;
  TempDir() {
    dir = fs::temp_directory_path() / ("flipflop_rtdcli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

void write_xyz(const std::string& path, const PointSet& ps, const std::vector<double>* w) {
  std::ofstream f(path);
  f.precision(17);
  f << "# test points\n";
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (int j = 0; j < ps.dim; ++j) f << (j ? " " : "") << ps.point(i)[j];
    if (w) f << " " << (*w)[i];
    f << "\n";
  }
}

std::string slurp(const std::string& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// POINTS, W and U files of an instant-flip run in tmp: p.xyz, w.xyz, u.xyz.
struct FlipFiles {
  std::string p, fw, fu;
};
template <class Tmp>
FlipFiles write_flip_files(const Tmp& tmp, const PointSet& pts, const std::vector<double>& w,
                           const std::vector<double>& u) {
  FlipFiles f{tmp.path("p.xyz"), tmp.path("w.xyz"), tmp.path("u.xyz")};
  write_xyz(f.p, pts, nullptr);
  write_xyz(f.fw, pts, &w);
  write_xyz(f.fu, pts, &u);
  return f;
}

// Reads back what the writer wrote (the files hold %.17g: exact round trip).
PointSet read_back(const std::string& path, int d) { return io::read_points(path, d, true); }

}  // namespace

TEST_CASE("cli rtd: certified canonical output in d = 2..9", "[instant_flip][cli]") {
  TempDir tmp;
  for (int d = 2; d <= 9; ++d) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(d));
    const std::size_t n = d == 2 ? 60 : (d == 3 ? 40 : d <= 5 ? 20 : d <= 7 ? 16 : 13);
    const PointSet pts = random_points(d, n, rng);
    const std::vector<double> w = random_weights(n, 0.02, rng);
    const std::string in = tmp.path("in" + std::to_string(d) + ".xyz"), out = tmp.path("out.txt");
    write_xyz(in, pts, &w);
    cli::RtdArgs a;
    a.in = in;
    a.out = out;
    a.dim = d;
    a.stats = true;
    REQUIRE(cli::run_rtd(a) == 0);
    const std::vector<std::vector<Index>> got = parse_simplices(slurp(out), d);
    const PointSet pw = read_back(in, d);
    CHECK(certify::rtd(pw, got).ok);
    CHECK(got == ref::rtd_incremental(pw).simplices);
  }
}

TEST_CASE("cli instant-flip: RT(S+U) from RT(S+W), and --timeline", "[instant_flip][cli]") {
  TempDir tmp;
  for (int d = 2; d <= 4; ++d) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(10 + d));
    const std::size_t n = d == 2 ? 60 : (d == 3 ? 35 : 18);
    const PointSet pts = random_points(d, n, rng);
    const std::vector<double> w(n, 0.0), u = random_weights(n, 0.02, rng);
    const auto [p, fw, fu] = write_flip_files(tmp, pts, w, u);
    const std::string out = tmp.path("out.txt");
    cli::InstantFlipArgs a;
    a.points = p;
    a.from = fw;
    a.to = fu;
    a.out = out;
    a.dim = d;
    a.stats = true;
    a.timeline = d == 2;
    REQUIRE(cli::run_instant_flip(a) == 0);
    const std::vector<std::vector<Index>> got = parse_simplices(slurp(out), d);
    const PointSet pu = read_back(fu, d);
    CHECK(certify::rtd(pu, got).ok);
    CHECK(got == ref::rtd_incremental(pu).simplices);
  }
}

TEST_CASE("cli rtd / instant-flip: bad input is one UsageError", "[instant_flip][cli]") {
  TempDir tmp;
  std::mt19937_64 rng(3);
  const PointSet pts = random_points(3, 20, rng);
  const std::vector<double> w = random_weights(20, 0.01, rng), u = random_weights(20, 0.01, rng);
  const std::string p = tmp.path("p.xyz"), fw = tmp.path("w.xyz"), fu = tmp.path("u.xyz"),
                    out = tmp.path("out.txt");
  write_xyz(p, pts, nullptr);
  write_xyz(fw, pts, &w);
  write_xyz(fu, pts, &u);
  auto expect_usage = [&](auto run, const auto& args, const std::string& needle) {
    fs::remove(out);
    try {
      run(args);
      FAIL("no error for: " << needle);
    } catch (const cli::UsageError& e) {
      const std::string msg = e.what();
      CHECK(msg.find('\n') == std::string::npos);
      CHECK(msg.find(needle) != std::string::npos);
      INFO(msg);
    }
    CHECK_FALSE(fs::exists(out));  // nothing written
  };
  const auto rtd = [](const cli::RtdArgs& a) { return cli::run_rtd(a); };
  const auto iflip = [](const cli::InstantFlipArgs& a) { return cli::run_instant_flip(a); };

  cli::RtdArgs r{fw, out, 3, false};
  expect_usage(rtd, cli::RtdArgs{fw, out, 10, false}, "--dim 10");
  expect_usage(rtd, cli::RtdArgs{tmp.path("missing.xyz"), out, 3, false}, "missing.xyz");
  expect_usage(rtd, cli::RtdArgs{p, out, 3, false}, "columns");  // no weight column
  expect_usage(rtd, cli::RtdArgs{fw, out, 4, false}, "columns");  // 4 columns read as 4D + weight
  {
    std::ofstream f(tmp.path("nan.xyz"));
    f << "0 0 0 0\n1 0 0 0\n0 1 0 nan\n0 0 1 0\n";
  }
  expect_usage(rtd, cli::RtdArgs{tmp.path("nan.xyz"), out, 3, false}, "NaN");
  {
    std::ofstream f(tmp.path("flat.xyz"));
    f << "0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n2 3 0 1\n";
  }
  expect_usage(rtd, cli::RtdArgs{tmp.path("flat.xyz"), out, 3, false}, "flat.xyz");
  {
    // d = 4 and 5: points in a hyperplane (x4 = x1 + x2) and in a plane
    std::ofstream f4(tmp.path("flat4.xyz")), f5(tmp.path("flat5.xyz"));
    f4 << "0 0 0 0 0\n1 0 0 1 0\n0 1 0 1 0\n0 0 1 0 0\n1 1 1 2 0\n3 1 2 4 1\n";
    f5 << "0 0 0 0 0 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n1 1 0 0 0 0\n2 5 0 0 0 1\n3 1 0 0 0 1\n7 2 0 0 0 0\n";
  }
  expect_usage(rtd, cli::RtdArgs{tmp.path("flat4.xyz"), out, 4, false}, "affine subspace of dimension 3");
  expect_usage(rtd, cli::RtdArgs{tmp.path("flat5.xyz"), out, 5, false}, "are coplanar (affine dimension 2)");
  REQUIRE(cli::run_rtd(r) == 0);  // and the good one works

  // instant-flip: points of W differ from POINTS
  PointSet moved = pts;
  moved.coords[7] += 1e-9;
  write_xyz(tmp.path("moved.xyz"), moved, &w);
  expect_usage(iflip, cli::InstantFlipArgs{p, tmp.path("moved.xyz"), fu, out, 3, false, false}, "differs");
  // a point fewer
  PointSet fewer = pts;
  fewer.coords.resize(fewer.coords.size() - 3);
  std::vector<double> u_fewer(u.begin(), u.end() - 1);
  write_xyz(tmp.path("fewer.xyz"), fewer, &u_fewer);
  expect_usage(iflip, cli::InstantFlipArgs{p, fw, tmp.path("fewer.xyz"), out, 3, false, false}, "19 points");
  expect_usage(iflip, cli::InstantFlipArgs{p, "", fu, out, 3, false, false}, "--from");
  expect_usage(iflip, cli::InstantFlipArgs{p, fw, fu, out, 6, false, false}, "--dim 6");  // the moving model: 2..5
  REQUIRE(cli::run_instant_flip(cli::InstantFlipArgs{p, fw, fu, out, 3, false, false}) == 0);
}

TEST_CASE("cli instant-flip: a point redundant under W comes back under U", "[instant_flip][cli]") {
  // The extended Algorithm 14 inserts it: the output equals `flipflop rtd` on
  // U byte for byte, in d = 2..4, and with W and U drawn independently.
  TempDir tmp;
  for (int d = 2; d <= 4; ++d) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(70 + d));
    const std::size_t n = d == 2 ? 80 : (d == 3 ? 40 : 20);
    const PointSet pts = random_points(d, n, rng);
    std::size_t mid = 0;  // the point nearest the centre: not a hull vertex
    double best = 1e300;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double s = 0;
      for (int j = 0; j < d; ++j) s += (pts.point(i)[j] - 0.5) * (pts.point(i)[j] - 0.5);
      if (s < best) best = s, mid = i;
    }
    for (int independent = 0; independent < 2; ++independent) {
      std::vector<double> w = random_weights(n, 0.02, rng), u = random_weights(n, 0.02, rng);
      if (!independent) {
        w[mid] = -1.0;  // redundant under W (lifted far up) ...
        u[mid] = 1.0;   // ... and a vertex under U (lifted far down)
      }
      const auto [p, fw, fu] = write_flip_files(tmp, pts, w, u);
      const std::string out = tmp.path("out.txt"), direct = tmp.path("direct.txt");
      if (!independent) {
        const ref::Rtd before = ref::rtd_incremental(read_back(fw, d));
        REQUIRE(std::binary_search(before.redundant.begin(), before.redundant.end(), static_cast<Index>(mid)));
      }
      REQUIRE(cli::run_instant_flip(cli::InstantFlipArgs{p, fw, fu, out, d, true, false}) == 0);
      cli::RtdArgs r;
      r.in = fu;
      r.out = direct;
      r.dim = d;
      REQUIRE(cli::run_rtd(r) == 0);
      CHECK(slurp(out) == slurp(direct));
      const PointSet pu = read_back(fu, d);
      const std::vector<std::vector<Index>> got = parse_simplices(slurp(out), d);
      CHECK(certify::rtd(pu, got).ok);
      if (!independent) {
        bool mid_is_vertex = false;
        for (const auto& t : got) mid_is_vertex |= std::find(t.begin(), t.end(), static_cast<Index>(mid)) != t.end();
        CHECK(mid_is_vertex);
      }
    }
  }
}

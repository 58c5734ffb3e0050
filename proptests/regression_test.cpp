// regression_test.cpp — replays the saved regression inputs of the property
// suite through every check.
//
// The mechanism (support/regressions.hpp):
//   * Every property of invariance_test.cpp is a named check (hull2_canonical,
//     hull2_scale, ..., rt2_counts, hull3_*, rtd_*, instant_flip_*,
//     classify2/3) run on generated input with parameters (scale exponent k,
//     integer shift, seed).
//   * When a case fails, check_or_save writes its input, before failing it, to
//       proptests/regressions/<check>/<hash>.xyz
//     in the source tree ($FLIPFLOP_REGRESSIONS_DIR overrides the folder):
//     one header line
//       # flipflop-regression property=<check> dim=2 weighted=0 scale=k shift=a,b,c seed=s
//     then the points as io::write_points writes them (shortest round-trip
//     decimals: read back bit for bit); <hash> is FNV-1a of the whole text.
//     While RapidCheck shrinks, each failing candidate replaces the file
//     written before it, so the file left is the minimal counterexample.
//   * Commit that file with the fix. This test then replays every file under
//     proptests/regressions/: the check it was saved for must pass (and must
//     apply: a saved input that the check skips would test nothing), and every
//     other check that applies to its dimension (NamedCheck::applies; the
//     rtd_* and instant_flip_* checks apply to d = 2..5) — every algorithm and
//     backend — must pass or skip, with the saved parameters. Files of d > 3
//     are read by read_points_d (io::read_points reads 2D and 3D).
//   * A file can also be made by hand: write the points with the header line
//     above (any property name of all_checks()); the round-trip test below
//     asks for the exact text save_regression writes, so run the points
//     through save_regression (or copy the name it reports) to get it right.
// The committed files are hand-made degenerate cases that exercised real
// subtleties (see proptests/regressions/README.md).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/regressions.hpp"

using namespace flipflop;
using namespace flipflop::test;

namespace {

const char* kind_name(Outcome::Kind k) {
  return k == Outcome::Kind::pass ? "pass" : k == Outcome::Kind::fail ? "FAIL" : "skip";
}

std::string file_text(const std::string& path) {
  std::ifstream is(path, std::ios::binary);
  std::ostringstream os;
  os << is.rdbuf();
  return os.str();
}

}  // namespace

TEST_CASE("regressions: saved files are exact round trips named by their hash", "[regressions]") {
  const auto files = regression_files();
  REQUIRE(!files.empty());
  for (const std::string& path : files) {
    INFO(path);
    const Regression r = load_regression(path);
    REQUIRE(std::filesystem::path(path).parent_path().filename().string() == r.property);
    const std::string body = regression_text(r.property, r.points, r.params);
    CHECK(body == file_text(path));
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(body)));
    CHECK(std::filesystem::path(path).stem().string() == hash);
  }
}

TEST_CASE("regressions: every saved input passes every check", "[regressions]") {
  saving_enabled() = false;
  std::size_t replayed = 0, runs = 0;
  for (const std::string& path : regression_files()) {
    const Regression r = load_regression(path);
    INFO(path << " (" << r.points.size() << " points)");
    const NamedCheck* own = find_check(r.property);
    if (own == nullptr) {  // e.g. an rtd check in a build without reference/rtd linked
      WARN(path << ": no check named " << r.property << " in this build; not replayed");
      continue;
    }
    const Outcome o = run_check(*own, r.points, r.params);
    INFO(r.property << ": " << kind_name(o.kind) << " " << o.message);
    CHECK(o.kind == Outcome::Kind::pass);
    for (const NamedCheck& c : all_checks()) {
      if (!c.applies(r.points.dim)) continue;
      const Outcome x = run_check(c, r.points, r.params);
      INFO(c.name << ": " << kind_name(x.kind) << " " << x.message);
      CHECK(x.kind != Outcome::Kind::fail);
      ++runs;
    }
    ++replayed;
  }
  REQUIRE(replayed > 0);
  std::printf("regressions: %zu saved inputs replayed, %zu check runs\n", replayed, runs);
}

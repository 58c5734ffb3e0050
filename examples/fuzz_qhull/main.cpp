// fuzz_qhull — fuzz a third-party convex hull (Qhull) on degenerate inputs and
// certify every output with flipflop, as a consumer's CI would.
//
//   fuzz_qhull [--seeds K] [--first-seed S] [--options "Qt"] [--save DIR]
//
// For each seed and each case below, the points come from flipflop::gen
// (deterministic: the same seed gives the same points on every machine), Qhull
// computes the hull, and flipflop::certify::hull3 decides, with exact
// arithmetic, whether the triangles are a correct convex hull of the exact
// input (Level::exact: degeneracies may be resolved either way — points on a
// facet may or may not be vertices, coplanar facets may be triangulated in any
// way, duplicates may appear once). One line per run, then a summary.
//
// Outcomes: "certified"; "WRONG" (Qhull returned triangles that are not the
// hull: the certifier names the first violated condition); "QHULL FAILED"
// (Qhull refused input that spans R^3); "refused flat input" (Qhull refused
// input that does not span R^3 — correct). With --save DIR every wrong case is
// written as DIR/<case>-seed<S>.xyz plus Qhull's triangles in .tri, for
// `flipflop certify hull3 X.xyz X.tri`.
//
// Exit status: 0 when every run was decided (whatever Qhull did: its errors are
// what this program reports); 2 when the program itself failed (bad
// arguments, an exception from the generator or the certifier, a file that
// cannot be written).
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "io/io.hpp"
#include "qhull_hull3.hpp"
#include "reference/certify/certify.hpp"
#include "reference/dimension.hpp"

using flipflop::PointSet;

namespace {

struct Case {
  std::string name;
  std::function<PointSet(std::uint64_t seed)> make;
};

PointSet generate(const std::string& dist, std::size_t n, std::uint64_t seed, double thickness = 0.01) {
  flipflop::gen::Options o;
  o.seed = seed;
  o.thickness = thickness;
  return flipflop::gen::generate(dist, n, o);
}

PointSet concat(PointSet a, const PointSet& b) {
  a.coords.insert(a.coords.end(), b.coords.begin(), b.coords.end());
  return a;
}

// The inputs: flipflop's degenerate families, and combinations of them that
// are degenerate in more than one way.
std::vector<Case> cases() {
  std::vector<Case> c;
  for (std::size_t n : {8, 27, 64, 300})
    c.push_back({"grid3 n=" + std::to_string(n), [n](std::uint64_t s) { return generate("grid3", n, s); }});
  for (std::size_t n : {30, 200})
    c.push_back({"sphere-lattice n=" + std::to_string(n), [n](std::uint64_t s) { return generate("sphere-lattice", n, s); }});
  for (std::size_t n : {10, 200})
    c.push_back({"coplanar3+1 n=" + std::to_string(n), [n](std::uint64_t s) {
                   // points on one plane z = a x + b y + c, then one point above it
                   PointSet p = generate("coplanar3", n - 1, s);
                   const double* q = p.point(0);
                   p.coords.insert(p.coords.end(), {q[0], q[1], q[2] + 1});
                   return p;
                 }});
  c.push_back({"coplanar3 n=50 (flat)", [](std::uint64_t s) { return generate("coplanar3", 50, s); }});
  c.push_back({"collinear3+2 n=40", [](std::uint64_t s) {
                 // a line and two points off it: a thin tetrahedron with 38 points on an edge
                 PointSet p = generate("collinear3", 38, s);
                 const double* q = p.point(0);
                 p.coords.insert(p.coords.end(), {q[0] + 1, q[1], q[2], q[0], q[1] + 1, q[2] + 1});
                 return p;
               }});
  for (std::size_t n : {20, 300})
    c.push_back({"duplicates3 n=" + std::to_string(n), [n](std::uint64_t s) { return generate("duplicates3", n, s); }});
  for (std::size_t n : {27, 200})
    c.push_back({"jitter3 n=" + std::to_string(n), [n](std::uint64_t s) { return generate("jitter3", n, s); }});
  c.push_back({"huge3 n=100", [](std::uint64_t s) { return generate("huge3", 100, s); }});
  c.push_back({"tiny3 n=100", [](std::uint64_t s) { return generate("tiny3", 100, s); }});
  for (std::size_t n : {4, 5, 6})
    c.push_back({"cube n=" + std::to_string(n), [n](std::uint64_t s) { return generate("cube", n, s); }});
  c.push_back({"grid3+duplicates3 n=64+64", [](std::uint64_t s) {
                 return concat(generate("grid3", 64, s), generate("duplicates3", 64, s));
               }});
  c.push_back({"box thickness 1e-9 n=500", [](std::uint64_t s) { return generate("box", 500, s, 1e-9); }});
  c.push_back({"sphere thickness 1e-12 n=500", [](std::uint64_t s) { return generate("sphere", 500, s, 1e-12); }});
  return c;
}

std::string file_stem(const std::string& name, std::uint64_t seed) {
  std::string s;
  for (char ch : name) s += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '.') ? ch : '_';
  return s + "-seed" + std::to_string(seed);
}

int usage(const char* why) {
  std::fprintf(stderr, "fuzz_qhull: %s\nusage: fuzz_qhull [--seeds K] [--first-seed S] [--options \"Qt\"] [--save DIR]\n",
               why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seeds = 3, first = 1;
  std::string options = "Qt", save_dir;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (a + 1 >= argc) return usage(("missing value after " + arg).c_str());
    const std::string value = argv[++a];
    try {
      if (arg == "--seeds") seeds = std::stoull(value);
      else if (arg == "--first-seed") first = std::stoull(value);
      else if (arg == "--options") options = value;
      else if (arg == "--save") save_dir = value;
      else return usage(("unknown option " + arg).c_str());
    } catch (const std::exception&) {
      return usage(("bad value for " + arg + ": " + value).c_str());
    }
  }

  std::size_t runs = 0, certified = 0, refused_flat = 0;
  std::map<std::string, std::size_t> wrong;  // case → count (WRONG or QHULL FAILED)
  try {
    const std::vector<Case> all = cases();
    for (std::uint64_t seed = first; seed < first + seeds; ++seed) {
      for (const Case& c : all) {
        const PointSet ps = c.make(seed);
        const bool spans = flipflop::affine_dimension(ps) == 3;
        const QhullHull q = qhull_hull3(ps, options);
        ++runs;
        std::string line = "seed " + std::to_string(seed) + "  " + c.name + ": ";
        bool is_wrong = false;
        if (!q.ok) {
          if (spans) {
            line += "QHULL FAILED on input that spans R^3: " + q.error;
            is_wrong = true;
          } else {
            line += "refused flat input (correct): " + q.error;
            ++refused_flat;
          }
        } else {
          const auto report = flipflop::certify::hull3(ps, q.triangles, flipflop::certify::Level::exact);
          if (report.ok) {
            line += std::to_string(q.triangles.size()) + " triangles, certified";
            ++certified;
          } else {
            line += "WRONG: " + std::to_string(q.triangles.size()) + " triangles, " + report.message();
            is_wrong = true;
          }
        }
        std::printf("%s\n", line.c_str());
        if (!is_wrong) continue;
        ++wrong[c.name];
        if (!save_dir.empty()) {
          const std::string stem = save_dir + "/" + file_stem(c.name, seed);
          flipflop::io::write_file(stem + ".xyz", [&](std::ostream& os) { flipflop::io::write_points(os, ps); });
          flipflop::io::write_file(stem + ".tri", [&](std::ostream& os) {
            flipflop::io::write_triangles(os, flipflop::io::canonical_triangles(q.triangles));
          });
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_qhull: error: %s\n", e.what());
    return 2;
  }

  std::size_t total_wrong = 0;
  for (const auto& [name, k] : wrong) total_wrong += k;
  std::printf("\nfuzz_qhull: %zu runs (Qhull options \"%s\"): %zu certified, %zu flat inputs refused (correct), "
              "%zu wrong\n",
              runs, options.c_str(), certified, refused_flat, total_wrong);
  for (const auto& [name, k] : wrong) std::printf("  Qhull wrong on %-32s %zu of %llu seeds\n", name.c_str(), k,
                                                  static_cast<unsigned long long>(seeds));
  return 0;
}

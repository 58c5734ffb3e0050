// commands.hpp — the subcommands of the flipflop tool, callable from tests.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <functional>
#include <iosfwd>
#include <optional>
#include <vector>

#include "io/write_result.hpp"
#include "reference/lattice_quotient.hpp"
#include "reference/point_set.hpp"

namespace flipflop::cli {

// Bad usage or input: one line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A computed result failed its own certification: never printed, exit code 3.
struct InternalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct GenArgs {
  std::string dist, out, weights;
  std::size_t n = 0, hull_points = 0;
  std::uint64_t seed = 1;
  double thickness = 0.01;
  bool list = false;
};

struct ComputeArgs {
  std::string kind;  // hull2, hull3, rt2, dt2
  std::string in, out;
  std::string backend;  // empty: the kind's default (default_backend)
  int threads = 0;      // --threads (cpu backend); 0: the runtime's default
  std::string algo;  // empty: the kind's default (default_algorithm)
  bool stats = false;
  bool strict = false;  // hull3: strictly extreme points and merged coplanar facets
  bool triangulate = false;  // with strict: the polygons fan-triangulated
  bool ascii = false;        // .ply/.stl output in ASCII instead of binary
};

struct CertifyArgs {
  std::string kind, points, output;
  bool canonical = false;
  int dim = 0;      // rtd: the dimension d (2..9); rt3|dt3 (certify rtd --dim 3): 0 or 3
  int threads = 0;  // hull2, hull3: worker threads of the parallel checks (0: all cores)
  bool strict = false;       // the strict views (hull3 --strict polygons, rt2/dt2 --strict triangles)
  bool triangulate = false;  // hull3 --strict --triangulate (fan triangles)
};

// Per kind, the backends and the algorithms that exist in this build (the
// command line accepts exactly these; the first algorithm is the default).
// hull3: "cpu" (kernels_cpu/hull3, multithreaded ffHull, byte-identical to the
// reference) and "reference"; the other kinds: "reference".
std::vector<std::string> available_backends(const std::string& kind);
// The default backend of a kind for an algorithm: the fastest one that is
// byte-identical to the reference and implements it (hull3 ffhull: cpu).
std::string default_backend(const std::string& kind, const std::string& algo);
std::vector<std::string> available_algorithms(const std::string& kind);
std::string default_algorithm(const std::string& kind);

// The output format of -o PATH by its extension (io/write_result.hpp); an
// unknown extension is a UsageError.
io::Format output_format_of(const std::string& path);
// Writes a result to PATH (empty or "-": standard output) in format f: the
// canonical index text by `index_text`, any other format from the cells
// (io::write_cells). Refusals and write failures are UsageErrors (one line).
void write_result_file(const std::string& path, io::Format f, const std::function<void(std::ostream&)>& index_text,
                       const PointSet& ps, const std::vector<std::vector<Index>>& cells, io::CellKind kind,
                       const std::vector<Index>& marked, bool ascii);
// The same for cells of k vertices stored flat (cell i is flat[i*k ..
// i*k+k-1]): .npy is written from them directly; other formats build the
// cells for io::write_cells.
void write_result_file(const std::string& path, io::Format f, const std::function<void(std::ostream&)>& index_text,
                       const PointSet& ps, const Index* flat, std::size_t count, std::size_t k, io::CellKind kind,
                       const std::vector<Index>& marked, bool ascii);

// --stats' note where a command ran on lattice_quotient's small-integer
// lattice ("; computed and certified on ... x / g ..."), empty otherwise.
std::string quotient_note(const std::optional<LatticeQuotient>& quotient);

int run_gen(const GenArgs& a);
int run_compute(const ComputeArgs& a);
int run_certify(const CertifyArgs& a);
int run_demo();

}  // namespace flipflop::cli

// mpi_main.cpp — `flipflop-mpi`: the 2D and 3D convex hull of points held in
// .npy shards, computed by MPI ranks (Open MPI), byte for byte the output of
// the single-process `flipflop hull2|hull3` on the concatenated shards
// (DESIGN.md "Beyond one machine"; the argument: partial_hull.hpp).
//
//   mpirun -n P flipflop-mpi hull2|hull3 INPUT [-o OUT] [--threads T] [--block ROWS] [--stats]
//
// INPUT is one .npy file or a directory of .npy shards (shards.hpp). The
// global rows are split into P contiguous ranges, one per rank. A rank maps
// only its own rows and walks them in blocks of --block rows: each block is
// checked for NaN/Inf, its hull computed by kernels_cpu on T threads (TBB) and
// certified by the kernel's certifier, its hull vertices kept (coordinates and
// global rows), its pages given back. The ranks' vertices are reduced to the
// vertices of their hull and merged up a binary tree of ranks (rank r + 2^k
// sends to rank r at level k; only candidate rows and coordinates travel); the
// root computes the final hull and broadcasts it; every rank certifies it
// against every block's vertices it holds and checks the coordinates of the
// final vertices in its rows against its file; the verdicts are reduced, and
// the root writes the output only when every rank certified it.
//
// Errors (DESIGN.md: one line, no hang): every phase ends with a collective
// agreement on the first problem (the smallest global row for bad input, then
// the smallest rank); rank 0 prints that one line, every rank exits with its
// code: 2 bad input or usage, 3 a hull that failed certification (never
// written). A failure outside the phases (out of memory in a transfer) ends
// the job through MPI_Abort.
//
// Output (-o, by extension): index text (none, .txt, .idx, "-"), .npy, and
// the meshes that carry no input index (.off, .obj, .stl) — the bytes of
// `flipflop hull2|hull3 -o` for the same extension. .ply, .vtu and .svg need
// every input point or its index in the file and are refused.
#include <mpi.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include "distributed/partial_hull.hpp"
#include "distributed/shards.hpp"
#include "io/index_io.hpp"
#include "io/input_error.hpp"
#include "io/npy.hpp"
#include "io/write_points.hpp"
#include "io/write_result.hpp"

namespace {

using namespace flipflop;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Args {
  std::string kind, in, out;
  int threads = 0;
  std::uint64_t block = std::uint64_t{1} << 22;
  bool stats = false;
  long long drop = -1;  // testing: the root leaves this row out of the final hull
};

// One problem, agreed on by all ranks: code 0 none, 2 input/usage, 3
// certification; key orders problems (global row; 0 for those every rank
// sees alike).
struct Status {
  int code = 0;
  std::uint64_t key = 0;
  std::string msg;
  void set(int c, std::uint64_t k, std::string m) {
    if (code == 0 || k < key) {
      code = c;
      key = k;
      msg = std::move(m);
    }
  }
};

int rank_of() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// The first problem of any rank (smallest key, then smallest rank), the same
// on every rank.
Status agree(const Status& mine) {
  struct {
    long value;
    int rank;
  } in{mine.code ? static_cast<long>(std::min<std::uint64_t>(mine.key, LONG_MAX - 1)) : LONG_MAX, rank_of()}, out{};
  MPI_Allreduce(&in, &out, 1, MPI_LONG_INT, MPI_MINLOC, MPI_COMM_WORLD);
  Status s;
  if (out.value == LONG_MAX) return s;
  int code = mine.code;
  MPI_Bcast(&code, 1, MPI_INT, out.rank, MPI_COMM_WORLD);
  unsigned long len = mine.msg.size();
  MPI_Bcast(&len, 1, MPI_UNSIGNED_LONG, out.rank, MPI_COMM_WORLD);
  std::string msg = rank_of() == out.rank ? mine.msg : std::string(len, '\0');
  MPI_Bcast(msg.data(), static_cast<int>(len), MPI_CHAR, out.rank, MPI_COMM_WORLD);
  s.code = code;
  s.msg = std::move(msg);
  // a certificate that failed on more than one rank: say on which
  int P = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &P);
  std::vector<int> failed(static_cast<std::size_t>(P));
  const int mine_failed = mine.code == 3;
  MPI_Allgather(&mine_failed, 1, MPI_INT, failed.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::string ranks;
  int count = 0;
  for (int r = 0; r < P; ++r)
    if (failed[static_cast<std::size_t>(r)]) ranks += (count++ ? ", " : "") + std::to_string(r);
  if (s.code == 3 && count > 1) s.msg += " (the certificate failed on ranks " + ranks + ")";
  return s;
}

// Ends the run on every rank with the agreed problem's code; rank 0 prints it.
int finish(const Status& s) {
  if (rank_of() == 0 && s.code == 2) std::cerr << "flipflop-mpi: error: " << s.msg << "\n";
  if (rank_of() == 0 && s.code == 3) std::cerr << "flipflop-mpi: internal error: " << s.msg << "\n";
  MPI_Finalize();
  return s.code;
}

// ---- moving candidates -------------------------------------------------------

constexpr int kTag = 17;
constexpr std::uint64_t kChunk = std::uint64_t{1} << 27;  // elements per message (below INT_MAX)

template <class T>
void send_all(const std::vector<T>& v, MPI_Datatype t, int to) {
  for (std::uint64_t at = 0; at < v.size(); at += kChunk)
    MPI_Send(v.data() + at, static_cast<int>(std::min<std::uint64_t>(kChunk, v.size() - at)), t, to, kTag,
             MPI_COMM_WORLD);
}
template <class T>
void recv_all(std::vector<T>& v, MPI_Datatype t, int from) {
  for (std::uint64_t at = 0; at < v.size(); at += kChunk)
    MPI_Recv(v.data() + at, static_cast<int>(std::min<std::uint64_t>(kChunk, v.size() - at)), t, from, kTag,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

std::uint64_t send_candidates(const dist::Candidates& c, int to) {
  std::uint64_t n = c.size();
  MPI_Send(&n, 1, MPI_UINT64_T, to, kTag, MPI_COMM_WORLD);
  send_all(c.ids, MPI_UINT64_T, to);
  send_all(c.coords, MPI_DOUBLE, to);
  return sizeof n + n * sizeof(std::uint64_t) + c.coords.size() * sizeof(double);
}
dist::Candidates recv_candidates(int dim, int from) {
  std::uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  dist::Candidates c;
  c.dim = dim;
  c.ids.resize(static_cast<std::size_t>(n));
  c.coords.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(dim));
  recv_all(c.ids, MPI_UINT64_T, from);
  recv_all(c.coords, MPI_DOUBLE, from);
  return c;
}
template <class T>
void bcast_vector(std::vector<T>& v, MPI_Datatype t) {
  std::uint64_t n = v.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  v.resize(static_cast<std::size_t>(n));
  for (std::uint64_t at = 0; at < n; at += kChunk)
    MPI_Bcast(v.data() + at, static_cast<int>(std::min<std::uint64_t>(kChunk, n - at)), t, 0, MPI_COMM_WORLD);
}

// ---- the rank's rows -------------------------------------------------------------

// The first non-finite value of rows [0, count) (row * dim + column), or
// count * dim when all are finite; in parallel on the arena's threads.
std::uint64_t first_nonfinite(const double* x, std::uint64_t values) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::uint64_t>(0, values, 1 << 16), values,
      [&](const tbb::blocked_range<std::uint64_t>& r, std::uint64_t best) {
        for (std::uint64_t i = r.begin(); i < r.end() && i < best; ++i)
          if (!std::isfinite(x[i])) return i;
        return best;
      },
      [](std::uint64_t a, std::uint64_t b) { return std::min(a, b); });
}

struct Local {
  dist::Candidates mine;  // every block's hull vertices (step 2 checks them)
  dist::BlockStats stats;
};

// Step 1 on this rank's rows [begin, end).
Local local_blocks(const dist::ShardSet& s, std::uint64_t begin, std::uint64_t end, const Args& a,
                   tbb::task_arena& arena, Status& st) {
  Local out;
  out.mine.dim = s.dim;
  const auto d = static_cast<std::uint64_t>(s.dim);
  for (const dist::Piece& p : dist::pieces(s, begin, end)) {
    const dist::Shard& sh = s.shards[p.shard];
    const dist::MappedRows rows(sh, s.dim, p.row, p.count);
    for (std::uint64_t b = 0; b < p.count; b += a.block) {
      const std::uint64_t n = std::min(a.block, p.count - b);
      const double* x = rows.data() + b * d;
      const std::uint64_t bad = arena.execute([&] { return first_nonfinite(x, n * d); });
      if (bad < n * d) {
        const std::uint64_t row = p.row + b + bad / d;
        st.set(2, sh.first_row + row,
               sh.path + ": " + io::nonfinite_problem(x[bad], row, static_cast<int>(bad % d), s.dim));
        return out;
      }
      try {
        dist::append(out.mine, dist::block_candidates(s.dim, x, n, sh.first_row + p.row + b, a.threads, &out.stats));
      } catch (const dist::CertificationError& e) {
        st.set(3, sh.first_row + p.row + b, "rank " + std::to_string(rank_of()) + ": " + e.what());
        return out;
      }
      rows.release(b, n);
    }
  }
  return out;
}

// Step 3: the final vertices in rows [begin, end) are this rank's points, bit
// for bit (each row read alone: mapping them would map the pages around each).
void check_vertex_rows(const dist::ShardSet& s, std::uint64_t begin, std::uint64_t end, const dist::FinalHull& h,
                       Status& st) {
  const auto d = static_cast<std::size_t>(s.dim);
  std::vector<double> x(d);
  for (const dist::Piece& p : dist::pieces(s, begin, end)) {
    const dist::Shard& sh = s.shards[p.shard];
    const std::uint64_t lo = sh.first_row + p.row, hi = lo + p.count;
    auto it = std::lower_bound(h.vertices.ids.begin(), h.vertices.ids.end(), lo);
    if (it == h.vertices.ids.end() || *it >= hi) continue;
    const dist::ShardRows file(sh, s.dim);
    for (; it != h.vertices.ids.end() && *it < hi; ++it) {
      const auto k = static_cast<std::size_t>(it - h.vertices.ids.begin());
      file.read(*it - sh.first_row, x.data());
      if (!std::equal(h.vertices.point(k), h.vertices.point(k) + d, x.begin()))
        st.set(3, *it,
               "rank " + std::to_string(rank_of()) + ": vertex " + std::to_string(*it) +
                   " of the final hull does not have the coordinates of row " + std::to_string(*it - sh.first_row) +
                   " of " + sh.path);
    }
  }
}

void write_output(const Args& a, io::Format f, const dist::FinalHull& h) {
  const bool two = a.kind == "hull2";
  std::vector<Index> cycle;
  std::vector<Triangle> tris;
  for (std::size_t k = 0; two && k < h.cells.size(); ++k) cycle.push_back(static_cast<Index>(h.cells[k]));
  for (std::size_t k = 0; !two && k + 2 < h.cells.size(); k += 3)
    tris.push_back({static_cast<Index>(h.cells[k]), static_cast<Index>(h.cells[k + 1]),
                    static_cast<Index>(h.cells[k + 2])});
  auto body = [&](std::ostream& os) {
    if (f == io::Format::npy) {
      std::vector<std::vector<Index>> cells;
      if (two) cells = {cycle};
      else
        for (const Triangle& t : tris) cells.push_back({t[0], t[1], t[2]});
      io::write_npy_indices(os, cells, two);
    } else if (two) {
      io::write_hull2(os, cycle);
    } else {
      io::write_triangles(os, tris);
    }
  };
  if (f == io::Format::index || f == io::Format::npy) {
    if (a.out.empty() || a.out == "-") {
      body(std::cout);
      std::cout.flush();
      if (!std::cout) throw std::runtime_error("cannot write to standard output");
    } else {
      io::write_file(a.out, body);
    }
    return;
  }
  // a mesh holds the vertices only, in increasing input index: the final
  // vertices numbered 0.. in that order write the same bytes
  PointSet ps;
  ps.dim = h.vertices.dim;
  ps.coords = Values::borrow(h.vertices.coords.data(), h.vertices.coords.size());
  auto local = [&](std::uint64_t g) {
    return static_cast<Index>(std::lower_bound(h.vertices.ids.begin(), h.vertices.ids.end(), g) -
                              h.vertices.ids.begin());
  };
  std::vector<std::vector<Index>> cells;
  if (two) {
    cells.emplace_back();
    for (std::uint64_t g : h.cells) cells.back().push_back(local(g));
  } else {
    for (std::size_t k = 0; k + 2 < h.cells.size(); k += 3)
      cells.push_back({local(h.cells[k]), local(h.cells[k + 1]), local(h.cells[k + 2])});
  }
  io::write_cells(a.out, f, ps, cells, two ? io::CellKind::cycle : io::CellKind::polygons);
}

int run(const Args& a) {
  const int rank = rank_of();
  int P = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &P);
  const int dim = a.kind == "hull2" ? 2 : 3;
  const auto t_start = Clock::now();

  // ---- open: every rank reads every shard's header (the same verdict everywhere)
  Status st;
  dist::ShardSet shards;
  io::Format fmt = io::Format::index;
  try {
    if (a.threads < 0) throw std::invalid_argument("--threads must be at least 0");
    if (a.block == 0) throw std::invalid_argument("--block must be at least 1");
    fmt = io::output_format(a.out.empty() || a.out == "-" ? "" : a.out);
    if (fmt == io::Format::ply || fmt == io::Format::vtu || fmt == io::Format::svg)
      throw std::invalid_argument(a.out + ": flipflop-mpi writes index text (.txt, .idx or none), .npy, .off, .obj "
                                  "or .stl; " + io::format_name(fmt) +
                                  " carries every input point or its index (use flipflop on one machine)");
    shards = dist::open_shards(a.in, dim);
    const std::uint64_t n = shards.rows;
    if (n == 0) throw io::InputError(a.in, "no points");
    if (n < static_cast<std::uint64_t>(dim) + 1)
      throw io::InputError(a.in, std::to_string(n) + (n == 1 ? " point" : " points") + ", at least " +
                                     std::to_string(dim + 1) + " needed");
    if (n >= 0xffffffffULL) throw io::InputError(a.in, "more than 4294967295 points (the output's indices are 32-bit)");
  } catch (const std::exception& e) {
    st.set(2, 0, e.what());
  }
  if (Status s = agree(st); s.code) return finish(s);

  // ---- step 1: this rank's rows, block by block
  const std::uint64_t n = shards.rows;
  const std::uint64_t begin = n * static_cast<std::uint64_t>(rank) / static_cast<std::uint64_t>(P),
                      end = n * static_cast<std::uint64_t>(rank + 1) / static_cast<std::uint64_t>(P);
  tbb::task_arena arena(a.threads > 0 ? a.threads : tbb::task_arena::automatic);
  const auto t1 = Clock::now();
  Local local;
  try {
    local = local_blocks(shards, begin, end, a, arena, st);
  } catch (const std::exception& e) {
    st.set(2, begin, e.what());
  }
  const double t_local = seconds_since(t1);
  if (Status s = agree(st); s.code) return finish(s);

  // ---- the tree: reduce to the hull's vertices, merge with the partner
  const auto t2 = Clock::now();
  std::uint64_t sent = 0;
  int levels = 0;
  dist::Candidates part;
  try {
    part = dist::reduce(local.mine, a.threads);
  } catch (const std::exception&) {
    part = local.mine;  // (a merge only saves work: the unreduced set is as good)
  }
  for (int step = 1; step < P; step *= 2, ++levels) {
    if (rank % (2 * step) == step) {
      sent += send_candidates(part, rank - step);
      part = dist::Candidates{};
      break;
    }
    if (rank % (2 * step) == 0 && rank + step < P) {
      part = dist::merge(part, recv_candidates(dim, rank + step));
      try {
        part = dist::reduce(part, a.threads);
      } catch (const std::exception&) {
      }
    }
  }
  const double t_tree = seconds_since(t2);

  // ---- the root's final hull, broadcast
  const auto t3 = Clock::now();
  dist::FinalHull h;
  if (rank == 0) {
    try {
      if (a.drop >= 0) {  // testing: a hull that misses one point
        dist::Candidates keep;
        keep.dim = dim;
        for (std::size_t k = 0; k < part.size(); ++k)
          if (part.ids[k] != static_cast<std::uint64_t>(a.drop)) {
            keep.ids.push_back(part.ids[k]);
            keep.coords.insert(keep.coords.end(), part.point(k), part.point(k) + dim);
          }
        part = std::move(keep);
      }
      h = dist::final_hull(part, n, a.threads);
    } catch (const std::invalid_argument& e) {
      st.set(2, 0, a.in + ": " + e.what());
    } catch (const std::exception& e) {
      st.set(2, 0, e.what());
    }
  }
  if (Status s = agree(st); s.code) return finish(s);
  h.vertices.dim = dim;
  bcast_vector(h.vertices.ids, MPI_UINT64_T);
  bcast_vector(h.vertices.coords, MPI_DOUBLE);
  bcast_vector(h.cells, MPI_UINT64_T);
  const double t_final = seconds_since(t3);

  // ---- steps 2 and 3 on every rank, the verdicts reduced
  const auto t4 = Clock::now();
  try {
    check_vertex_rows(shards, begin, end, h, st);
    const certify::Report r = dist::check(h, local.mine, a.threads);
    if (!r.ok)
      st.set(3, begin,
             "rank " + std::to_string(rank) + " (rows " + std::to_string(begin) + ".." + std::to_string(end - 1) +
                 "): the final hull failed certification against this rank's points: " + r.message());
  } catch (const std::exception& e) {
    st.set(3, begin, "rank " + std::to_string(rank) + ": " + e.what());
  }
  const double t_check = seconds_since(t4);
  if (Status s = agree(st); s.code) return finish(s);

  // ---- output, by the root
  const auto t5 = Clock::now();
  if (rank == 0) {
    try {
      write_output(a, fmt, h);
    } catch (const std::exception& e) {
      st.set(2, 0, e.what());
    }
  }
  const double t_write = seconds_since(t5);
  if (Status s = agree(st); s.code) return finish(s);

  if (a.stats) {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);  // ru_maxrss: peak resident set in KiB
    double mine[5] = {t_local, t_tree, t_check, local.stats.compute_s + local.stats.certify_s,
                      static_cast<double>(ru.ru_maxrss) / 1024.0},
           most[5] = {};
    MPI_Reduce(mine, most, 5, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    std::uint64_t counts[5] = {local.stats.blocks, local.stats.passed_whole, local.mine.size(), sent,
                               local.stats.points},
                  sums[5] = {};
    MPI_Reduce(counts, sums, 5, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    if (rank == 0)
      std::cerr << a.kind << ": " << P << " ranks x " << (a.threads ? std::to_string(a.threads) : "all")
                << " threads, " << n << " points in " << shards.shards.size() << " shards, "
                << (dim == 2 ? h.cells.size() : h.cells.size() / 3) << (dim == 2 ? " vertices" : " triangles")
                << "; total " << seconds_since(t_start) << " s: local " << most[0] << " s (slowest rank), tree "
                << most[1] << " s, final " << t_final << " s, check " << most[2] << " s, write " << t_write << " s\n"
                << a.kind << ": blocks " << sums[0] << " (" << sums[1] << " passed on whole), block vertices "
                << sums[2] << ", tree levels " << levels << ", bytes sent up the tree " << sums[3]
                << ", final hull broadcast " << (h.vertices.ids.size() * (8 + 8 * dim) + h.cells.size() * 8)
                << " bytes, peak resident memory of a rank " << most[4] << " MiB (largest)\n";
  }
  MPI_Finalize();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const bool root = rank_of() == 0;
  CLI::App app{"flipflop-mpi: the 2D and 3D convex hull of .npy shards on MPI ranks, exact and certified, "
               "byte-identical to `flipflop hull2|hull3` on the concatenated shards"};
  app.require_subcommand(1);
  Args a;
  const char* kinds[] = {"hull2", "hull3"};
  std::vector<CLI::App*> cmds;
  for (const char* k : kinds) {
    auto* cmd = app.add_subcommand(k, std::string(k == kinds[0] ? "2D" : "3D") + " convex hull (columns x y" +
                                          (k == kinds[0] ? "" : " z") + ")");
    cmd->add_option("INPUT", a.in, "a .npy file or a directory of .npy shards (rows in shard-name order)")
        ->required();
    cmd->add_option("-o,--output", a.out, "output file: index text (.txt, .idx, none), .npy, .off, .obj, .stl");
    cmd->add_option("--threads", a.threads, "worker threads per rank (default: all cores)");
    cmd->add_option("--block", a.block, "rows per block of a rank's work (default 4194304)");
    cmd->add_flag("--stats", a.stats, "print timings and transfer volumes on standard error");
    cmd->add_option("--test-drop-row", a.drop,
                    "testing the distributed certifier: the root leaves this global row out of the final hull");
    cmds.push_back(cmd);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    if (root) app.exit(e);
    MPI_Finalize();
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    while (!msg.empty() && msg.back() == '\n') msg.pop_back();
    if (root) std::cerr << "flipflop-mpi: error: " << msg << " (see flipflop-mpi --help)\n";
    MPI_Finalize();
    return 2;
  }
  for (std::size_t k = 0; k < cmds.size(); ++k)
    if (cmds[k]->parsed()) a.kind = kinds[k];
  return run(a);
}

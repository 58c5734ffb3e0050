// qhull.cpp — Qhull (libqhull_r, the reentrant C library) as a peer.
//
// Qhull computes in floating point and merges facets that it cannot separate
// reliably ("C-0" is its default in 2-d and 3-d); option "Qt" triangulates the
// merged facets. The index of an input point is qh_pointid(vertex->point).
//
// Orientation (mirrors Qhull's own printers, io_r.c):
//   2-d, qh_printextremes_2d: a facet is an edge with vertices {A, B}; when
//     facet->toporient (xor qh_ORIENTclock, 0 by default) the hull runs from the
//     first vertex to the second, otherwise from the second to the first; that
//     walk is counter-clockwise.
//   3-d, qh_printfacetNvertex_simplicial (output "i"): a simplicial facet lists
//     its vertices in set order when facet->toporient, otherwise with the first
//     two swapped. That order has an inward right-hand normal ("qh_ORIENTclock
//     0 for inward pointing normals by Geomview convention", user_r.h), i.e. it
//     is clockwise seen from outside; we reverse it.
// proptests/peers_test.cpp checks both against CGAL and flipflop's predicates.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "reference/canonical.hpp"
#include "peers/peers.hpp"
#include "peers/triangulation3.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace flipflop::peers {

namespace {

// One Qhull run: builds the hull on construction, frees Qhull's memory on
// destruction. Qhull's messages go to an in-memory stream so that an error can
// be reported as one line.
class QhullRun {
 public:
  QhullRun(const PointSet& pts, int dim, const char* options, const char* who = nullptr) : coords_(pts.coords.to_vector()) {
    if (pts.dim != dim)
      throw std::invalid_argument((who ? std::string(who) : "qhull_hull" + std::to_string(dim)) + ": expected " +
                                  std::to_string(dim) + "D points, got " +
                                  std::to_string(pts.dim) + "D");
    err_ = open_memstream(&err_buf_, &err_len_);
    if (!err_) throw std::runtime_error("qhull: cannot open a memory stream for messages");
    std::string cmd = std::string("qhull ") + options;
    // qh_new_qhull catches Qhull's internal errors (setjmp/longjmp inside C
    // frames only) and returns a non-zero exit code.
    exitcode_ = qh_new_qhull(&qh_, dim, static_cast<int>(pts.size()), coords_.data(),
                             /*ismalloc=*/False, cmd.data(), /*outfile=*/nullptr, err_);
    std::fflush(err_);
    if (exitcode_ != 0) {
      std::string msg = first_line();
      release();
      throw std::runtime_error(msg.empty() ? "qhull failed with exit code " +
                                                 std::to_string(exitcode_)
                                           : msg);
    }
  }
  ~QhullRun() { release(); }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  qhT* qh() { return &qh_; }

 private:
  std::string first_line() const {
    std::string all(err_buf_ ? err_buf_ : "", err_len_);
    std::size_t start = all.find_first_not_of(" \n\r\t");
    if (start == std::string::npos) return {};
    std::size_t end = all.find('\n', start);
    return all.substr(start, end == std::string::npos ? std::string::npos : end - start);
  }
  void release() {
    if (released_) return;
    released_ = true;
    int curlong = 0, totlong = 0;
    qh_freeqhull(&qh_, !qh_ALL);
    qh_memfreeshort(&qh_, &curlong, &totlong);
    if (err_) std::fclose(err_);
    std::free(err_buf_);
    err_ = nullptr;
    err_buf_ = nullptr;
  }

  std::vector<coordT> coords_;  // Qhull wants a mutable array
  qhT qh_{};
  FILE* err_ = nullptr;
  char* err_buf_ = nullptr;
  std::size_t err_len_ = 0;
  int exitcode_ = 0;
  bool released_ = false;
};

// The input indices of a simplicial facet's three vertices, in Qhull's set
// order (a merged facet is not simplicial: option Qt must be given).
Triangle facet_triangle(qhT* qh, facetT* facet, const char* who) {
  if (qh_setsize(qh, facet->vertices) != 3)
    throw std::runtime_error(std::string(who) + ": Qhull returned a non-triangular facet under Qt");
  Triangle t;
  for (int k = 0; k < 3; ++k) {
    auto* v = static_cast<vertexT*>(facet->vertices->e[k].p);
    t[static_cast<std::size_t>(k)] = static_cast<Index>(qh_pointid(qh, v->point));
  }
  return t;
}

}  // namespace

std::vector<Index> qhull_hull2(const PointSet& pts) {
  QhullRun run(pts, 2, "");
  qhT* qh = run.qh();
  // Directed hull edges A -> B (counter-clockwise), then one walk around.
  std::map<Index, Index> next;
  facetT* facet;
  FORALLfacets {
    auto* v0 = SETfirstt_(facet->vertices, vertexT);
    auto* v1 = SETsecondt_(facet->vertices, vertexT);
    auto a = static_cast<Index>(qh_pointid(qh, v0->point));
    auto b = static_cast<Index>(qh_pointid(qh, v1->point));
    if (facet->toporient ^ qh_ORIENTclock) next[a] = b;
    else next[b] = a;
  }
  std::vector<Index> cycle;
  if (next.empty()) return cycle;
  Index start = next.begin()->first, v = start;
  do {
    cycle.push_back(v);
    auto it = next.find(v);
    if (it == next.end() || cycle.size() > next.size())
      throw std::runtime_error("qhull_hull2: Qhull's facets do not form one cycle");
    v = it->second;
  } while (v != start);
  if (cycle.size() != next.size())
    throw std::runtime_error("qhull_hull2: Qhull's facets do not form one cycle");
  return canonical_hull2(std::move(cycle));
}

std::vector<Triangle> qhull_hull3(const PointSet& pts) {
  QhullRun run(pts, 3, "Qt");
  qhT* qh = run.qh();
  std::vector<Triangle> tris;
  facetT* facet;
  FORALLfacets {
    Triangle t = facet_triangle(qh, facet, "qhull_hull3");
    // Qhull's printed order, then reversed to counter-clockwise from outside.
    if (facet->toporient ^ qh_ORIENTclock) std::swap(t[0], t[1]);
    tris.push_back(t);
  }
  return canonical_triangles(std::move(tris));
}

std::vector<Triangle> qhull_delaunay2(const PointSet& pts) {
  // "d": the Delaunay triangulation as the lower hull of the points lifted to
  // the paraboloid; "Qbb": the lifted coordinate scaled to the others' range
  // (qdelaunay's recommended option); "Qt": merged facets triangulated.
  QhullRun run(pts, 2, "d Qbb Qt", "qhull_delaunay2");
  qhT* qh = run.qh();
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Triangle> tris;
  facetT* facet;
  FORALLfacets {
    if (facet->upperdelaunay) continue;  // the upper hull is not part of the triangulation
    Triangle t = facet_triangle(qh, facet, "qhull_delaunay2");
    // counter-clockwise in the plane (exact orientation of the input points;
    // a triangle Qhull made flat keeps its order)
    auto P = [&](Index i) { return K::Point_2(pts.point(i)[0], pts.point(i)[1]); };
    if (CGAL::orientation(P(t[0]), P(t[1]), P(t[2])) == CGAL::CLOCKWISE) std::swap(t[1], t[2]);
    tris.push_back(t);
  }
  return canonical_triangles(std::move(tris));
}

std::vector<Tet> qhull_delaunay3(const PointSet& pts, double* build_seconds) {
  // "d Qt Qbb" (qhull_delaunay2's options, scipy's engine): the lower facets
  // of the lifted hull in R^4 are the Delaunay tetrahedra; under Qt each is
  // simplicial (4 vertices).
  const auto t0 = std::chrono::steady_clock::now();
  QhullRun run(pts, 3, "d Qt Qbb", "qhull_delaunay3");
  if (build_seconds)
    *build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  qhT* qh = run.qh();
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto P = [&](Index i) { return K::Point_3(pts.point(i)[0], pts.point(i)[1], pts.point(i)[2]); };
  // the volume sign of CGAL's POSITIVE (cgal_triangulation3.cpp)
  const int positive = static_cast<int>(
      CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1)));
  std::vector<Tet> tets;
  facetT* facet;
  FORALLfacets {
    if (facet->upperdelaunay) continue;  // the upper hull is not part of the triangulation
    if (qh_setsize(qh, facet->vertices) != 4)
      throw std::runtime_error("qhull_delaunay3: Qhull returned a non-simplicial facet under Qt");
    Tet t;
    for (int k = 0; k < 4; ++k)
      t[static_cast<std::size_t>(k)] =
          static_cast<Index>(qh_pointid(qh, static_cast<vertexT*>(facet->vertices->e[k].p)->point));
    // volume-positive by the exact orientation of the input points; a flat
    // tetrahedron (Qt on a merged facet) keeps Qhull's order
    if (static_cast<int>(CGAL::orientation(P(t[0]), P(t[1]), P(t[2]), P(t[3]))) * positive < 0) std::swap(t[0], t[1]);
    tets.push_back(t);
  }
  return canonical_tets(std::move(tets));
}

}  // namespace flipflop::peers

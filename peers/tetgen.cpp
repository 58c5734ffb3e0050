// tetgen.cpp — TetGen 1.5 (Hang Si; Debian's libtet1.5-dev) as a peer of
// `flipflop dt3` (triangulation3.hpp). Built where peers/CMakeLists.txt found
// tetgen.h and libtet (FLIPFLOP_HAVE_TETGEN); elsewhere the wrapper throws.
//
// tetrahedralize("Q", in, out) on a point set (no -p: no boundary to recover)
// is TetGen's Delaunay tetrahedralization: incremental insertion (Bowyer–
// Watson with flips) in a BRIO order, Shewchuk's adaptive exact predicates,
// ties broken by TetGen's own symbolic perturbation. Indices: in.firstnumber
// = 0, and without -j TetGen keeps every input point in its output point list
// at its input position (a duplicated location is a vertex once; the other
// copies are vertices of no tetrahedron), so tetrahedronlist holds input
// indices. TetGen reports a failure (e.g. all points coplanar) by calling
// terminatetetgen, which in the library build throws the error code (an int).
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "peers/triangulation3.hpp"

#ifdef FLIPFLOP_HAVE_TETGEN
#define TETLIBRARY
#include <tetgen.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace flipflop::peers {

#ifdef FLIPFLOP_HAVE_TETGEN

bool tetgen_available() { return true; }

std::vector<Tet> tetgen_delaunay3(const PointSet& ps, double* build_seconds) {
  if (ps.dim != 3)
    throw std::invalid_argument("tetgen_delaunay3: expected 3D points, got " + std::to_string(ps.dim) + "D");
  if (ps.size() < 4) throw std::runtime_error("tetgen_delaunay3: fewer than 4 points");
  tetgenio in, out;  // their destructors free the lists with delete[]
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(ps.size());
  in.pointlist = new REAL[3 * ps.size()];
  for (std::size_t i = 0; i < 3 * ps.size(); ++i) in.pointlist[i] = ps.coords[i];
  const auto t0 = std::chrono::steady_clock::now();
  char switches[] = "Q";
  try {
    tetrahedralize(switches, &in, &out);
  } catch (int code) {
    throw std::runtime_error("tetgen_delaunay3: TetGen failed with error code " + std::to_string(code) +
                             (code == 4 || code == 3 ? " (the points are coplanar or too few)" : ""));
  }
  if (build_seconds)
    *build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (out.numberofcorners != 4) throw std::runtime_error("tetgen_delaunay3: TetGen returned non-linear tetrahedra");
  const auto m = static_cast<std::size_t>(out.numberoftetrahedra);
  if (m == 0) throw std::runtime_error("tetgen_delaunay3: TetGen returned no tetrahedron (lower-dimensional input)");
  std::vector<Tet> tets(m);
  for (std::size_t t = 0; t < m; ++t)
    for (std::size_t k = 0; k < 4; ++k) {
      const int v = out.tetrahedronlist[4 * t + k];
      if (v < 0 || static_cast<std::size_t>(v) >= ps.size())
        throw std::runtime_error("tetgen_delaunay3: a vertex that is not an input point (" + std::to_string(v) + ")");
      tets[t][k] = static_cast<Index>(v);
    }
  // TetGen orients every tetrahedron alike: the first one that is not flat
  // gives the sign for all, in the volume convention (CGAL's, as in
  // cgal_triangulation3.cpp).
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto P = [&](Index i) { return K::Point_3(ps.point(i)[0], ps.point(i)[1], ps.point(i)[2]); };
  const int positive = static_cast<int>(
      CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, 0, 1)));
  int sign = 0;
  for (std::size_t t = 0; t < m && sign == 0; ++t)
    sign = static_cast<int>(CGAL::orientation(P(tets[t][0]), P(tets[t][1]), P(tets[t][2]), P(tets[t][3]))) * positive;
  if (sign < 0)
    for (Tet& t : tets) std::swap(t[0], t[1]);
  return canonical_tets(std::move(tets));
}

#else

bool tetgen_available() { return false; }

std::vector<Tet> tetgen_delaunay3(const PointSet&, double*) {
  throw std::runtime_error("tetgen_delaunay3: this build has no TetGen (Debian: libtet1.5-dev)");
}

#endif

}  // namespace flipflop::peers

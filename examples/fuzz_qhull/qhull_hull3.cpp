// qhull_hull3.cpp — see qhull_hull3.hpp.
//
// The triangles are reported in Qhull's own orientation, not re-oriented
// here: a flipped facet is exactly the kind of error the certifier must see.
// Qhull's "i" output (qh_printfacetNvertex_simplicial in io_r.c) lists a
// simplicial facet's vertex set in order when facet->toporient xor
// qh_ORIENTclock, else with the first two swapped, and that order is
// clockwise seen from outside (user_r.h: "qh_ORIENTclock 0 for inward
// pointing normals by Geomview convention"). flipflop wants counter-clockwise,
// so the opposite choice is made below.
#include "qhull_hull3.hpp"

#include <cstdio>
#include <cstdlib>
#include <utility>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

QhullHull qhull_hull3(const flipflop::PointSet& ps, const std::string& options) {
  QhullHull out;
  std::vector<coordT> coords(ps.coords.begin(), ps.coords.end());  // Qhull wants it mutable
  char* messages = nullptr;
  std::size_t length = 0;
  FILE* err = open_memstream(&messages, &length);
  if (!err) {
    out.error = "cannot open a memory stream for Qhull's messages";
    return out;
  }
  qhT qh_storage;
  qhT* qh = &qh_storage;
  QHULL_LIB_CHECK
  qh_zero(qh, err);
  std::string command = "qhull " + options;
  // qh_new_qhull catches Qhull's errors (longjmp inside Qhull) and returns non-zero.
  const int exitcode = qh_new_qhull(qh, 3, static_cast<int>(ps.size()), coords.data(), False,
                                    command.data(), nullptr, err);
  if (exitcode == 0) {
    out.ok = true;
    facetT* facet;
    FORALLfacets {
      if (qh_setsize(qh, facet->vertices) != 3) {
        out.ok = false;
        out.error = "a facet with " + std::to_string(qh_setsize(qh, facet->vertices)) +
                    " vertices (run with option Qt)";
        break;
      }
      flipflop::Triangle t;
      for (int k = 0; k < 3; ++k) {
        auto* v = static_cast<vertexT*>(facet->vertices->e[k].p);
        t[static_cast<std::size_t>(k)] = static_cast<flipflop::Index>(qh_pointid(qh, v->point));
      }
      if (facet->toporient ^ qh_ORIENTclock) std::swap(t[0], t[1]);  // clockwise → counter-clockwise
      out.triangles.push_back(t);
    }
  }
  int curlong = 0, totlong = 0;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
  std::fclose(err);
  if (exitcode != 0) {
    std::string all(messages ? messages : "", length);
    const std::size_t start = all.find_first_not_of(" \r\n\t");
    const std::size_t end = start == std::string::npos ? start : all.find('\n', start);
    out.error = start == std::string::npos ? "qhull exit code " + std::to_string(exitcode)
                                           : all.substr(start, end == std::string::npos ? end : end - start);
  }
  std::free(messages);
  return out;
}

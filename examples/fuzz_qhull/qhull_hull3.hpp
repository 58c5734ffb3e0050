// qhull_hull3.hpp — the program under test: Qhull's 3D convex hull, called
// the way an application would call it (libqhull_r, the reentrant C API),
// returning triangles of input indices for flipflop's certifier.
#pragma once

#include <string>
#include <vector>

#include "reference/point_set.hpp"

struct QhullHull {
  bool ok = false;
  std::string error;                         // Qhull's first message line when !ok
  std::vector<flipflop::Triangle> triangles;  // counter-clockwise seen from outside
};

// Runs "qhull <options>" (use at least "Qt": triangulated output) on ps (3D).
QhullHull qhull_hull3(const flipflop::PointSet& ps, const std::string& options);

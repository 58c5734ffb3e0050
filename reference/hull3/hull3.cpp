// hull3.cpp — see hull3.hpp.
#include "reference/hull3/hull3.hpp"

#include <stdexcept>

#include "reference/hull3/ffhull.hpp"
#include "reference/hull3/initial_stars.hpp"
#include "reference/hull3/twist_flip.hpp"

namespace flipflop::ref {

std::vector<std::string> hull3_algorithms() { return {"ffhull", "splay", "twist-flip"}; }

std::vector<Triangle> hull3(const PointSet& ps, const std::string& algo, Hull3Stats* stats) {
  if (algo == "ffhull") return hull3_ffhull(ps, stats);
  if (algo == "splay") return hull3_splay(ps, stats);
  if (algo == "twist-flip") return hull3_twist_flip(ps, stats);
  throw std::invalid_argument("unknown 3D hull algorithm '" + algo + "' (ffhull, splay, twist-flip)");
}

}  // namespace flipflop::ref

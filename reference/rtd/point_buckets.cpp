// point_buckets.cpp — redundant points kept in their simplices. See
// point_buckets.hpp.
#include "reference/rtd/point_buckets.hpp"

#include <stdexcept>
#include <string>

namespace flipflop::ref::rtd {

void PointBuckets::points_of(std::int32_t s, std::vector<Index>& out) const {
  if (static_cast<std::size_t>(s) >= first.size()) return;
  for (Index p = first[static_cast<std::size_t>(s)]; p != kNoVertex; p = next[p]) out.push_back(p);
}

void add_point(PointBuckets& B, Index p, std::int32_t s) {
  const auto slot = static_cast<std::size_t>(s);
  if (slot >= B.first.size()) B.first.resize(slot + 1, kNoVertex);
  const Index head = B.first[slot];
  B.next[p] = head;
  B.prev[p] = kNoVertex;
  if (head != kNoVertex) B.prev[head] = p;
  B.first[slot] = p;
  B.where[p] = s;
  ++B.tracked;
}

void remove_point(PointBuckets& B, Index p) {
  const std::int32_t s = B.where[p];
  if (s == kNone) return;
  if (B.prev[p] != kNoVertex)
    B.next[B.prev[p]] = B.next[p];
  else
    B.first[static_cast<std::size_t>(s)] = B.next[p];
  if (B.next[p] != kNoVertex) B.prev[B.next[p]] = B.prev[p];
  B.where[p] = kNone;
  B.next[p] = B.prev[p] = kNoVertex;
  --B.tracked;
}

void take_points(PointBuckets& B, std::int32_t s, std::vector<Index>& out) {
  if (static_cast<std::size_t>(s) >= B.first.size()) return;
  Index p = B.first[static_cast<std::size_t>(s)];
  while (p != kNoVertex) {
    const Index q = B.next[p];
    out.push_back(p);
    B.where[p] = kNone;
    B.next[p] = B.prev[p] = kNoVertex;
    --B.tracked;
    p = q;
  }
  B.first[static_cast<std::size_t>(s)] = kNoVertex;
}

PointBuckets track_all(const TriangulationD& T) {
  PointBuckets B;
  B.first.assign(T.slots(), kNoVertex);
  B.next.assign(T.n, kNoVertex);
  B.prev.assign(T.n, kNoVertex);
  B.where.assign(T.n, kNone);
  std::int32_t hint = kNone;
  for (Index p = 0; p < T.n; ++p) {
    if (T.is_vertex(p)) continue;
    const std::int32_t s = locate(T, p, hint);
    if (is_virtual_simplex(T, s))
      throw std::invalid_argument("point " + std::to_string(p) +
                                  " is not a vertex but lies outside the convex hull of the "
                                  "vertices: not a regular triangulation of all points");
    add_point(B, p, s);
    hint = s;
  }
  return B;
}

void redistribute(const TriangulationD& T, PointBuckets& B, const std::vector<Index>& pts,
                  const std::vector<std::int32_t>& created) {
  for (Index p : pts) {
    std::int32_t home = kNone;
    for (std::int32_t s : created)
      if (!is_virtual_simplex(T, s) && contains(T, s, p)) {
        home = s;
        break;
      }
    if (home == kNone)
      throw std::logic_error("point buckets: point " + std::to_string(p) +
                             " lies in none of the simplices that replaced its own");
    add_point(B, p, home);
  }
}

}  // namespace flipflop::ref::rtd

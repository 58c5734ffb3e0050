// point_buckets.hpp — the redundant points of a d-dimensional regular
// triangulation, each kept in the simplex that contains it (the "conflict
// lists" of incremental constructions, here for the instant flip with
// insertions, instant_flip.hpp).
//
// Every input point that is not a vertex of T lies strictly inside exactly
// one real simplex of T (exact SoS orient_d, rtd::contains): the real part of
// T triangulates conv(vertices) = conv(S), because a point extreme in conv(S)
// (under the perturbation of the coordinates, which the weights do not touch)
// is a vertex of every regular triangulation of S. The buckets are intrusive
// doubly linked lists, one per slot of T: O(1) to add or remove a point, and a
// destroyed simplex hands its points to the simplices that replace it
// (redistribute): a bistellar flip replaces simplices by others covering the
// same region, so each point finds exactly one new simplex.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/rtd/triangulation_d.hpp"

namespace flipflop::ref::rtd {

struct PointBuckets {
  std::vector<Index> first;         // per slot: its first point, kNoVertex when empty
  std::vector<Index> next, prev;    // per point: neighbours in its slot's list
  std::vector<std::int32_t> where;  // per point: the slot containing it, kNone when not tracked
  std::size_t tracked = 0;

  bool is_tracked(Index p) const { return p < where.size() && where[p] != kNone; }
  std::int32_t slot_of(Index p) const { return where[p]; }
  // The points of slot s, appended to out.
  void points_of(std::int32_t s, std::vector<Index>& out) const;
};

// Locates every non-vertex point of T (visibility walks from the previous
// point's simplex) and tracks it. Throws std::invalid_argument when a
// non-vertex lies outside conv(T) (then T is not a regular triangulation of
// all of S).
PointBuckets track_all(const TriangulationD& T);

// Adds point p (not tracked) to slot s / removes p from its slot.
void add_point(PointBuckets& B, Index p, std::int32_t s);
void remove_point(PointBuckets& B, Index p);
// Removes every point of slot s, appending them to out.
void take_points(PointBuckets& B, std::int32_t s, std::vector<Index>& out);
// Tracks each point of pts in the one simplex of `created` that contains it
// (they cover the region of the simplices the points came from). Throws
// std::logic_error when none does.
void redistribute(const TriangulationD& T, PointBuckets& B, const std::vector<Index>& pts,
                  const std::vector<std::int32_t>& created);

}  // namespace flipflop::ref::rtd

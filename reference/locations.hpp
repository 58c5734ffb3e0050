// locations.hpp — the smallest input index at each location (equal
// coordinates; -0.0 and +0.0 are one location), for views and certifiers
// that report one index per location (reference/hull3/strict_hull3.hpp,
// certify::hull3_strict): hashed, O(n) expected.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <vector>

#include "reference/point_set.hpp"

namespace flipflop {

class SmallestAtLocation {
 public:
  explicit SmallestAtLocation(const PointSet& ps) : ps_(ps), first_(ps.size(), Hash{&ps}, Equal{&ps}) {
    for (Index i = 0; i < ps.size(); ++i) first_.emplace(i, i);  // the first (smallest) index stays
  }
  // The smallest index whose coordinates equal point v's.
  Index operator()(Index v) const { return first_.at(v); }

 private:
  struct Hash {
    const PointSet* ps;
    std::size_t operator()(Index i) const {
      std::size_t h = 0;
      for (int c = 0; c < ps->dim; ++c) {
        const double z = ps->point(i)[c] + 0.0;  // -0.0 -> +0.0
        std::uint64_t bits;
        std::memcpy(&bits, &z, sizeof bits);
        h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      }
      return h;
    }
  };
  struct Equal {
    const PointSet* ps;
    bool operator()(Index a, Index b) const {
      for (int c = 0; c < ps->dim; ++c)
        if (ps->point(a)[c] != ps->point(b)[c]) return false;
      return true;
    }
  };
  const PointSet& ps_;
  std::unordered_map<Index, Index, Hash, Equal> first_;
};

}  // namespace flipflop

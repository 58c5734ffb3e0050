// ridge_table.hpp — pairs the halves of ridges created together (the cone of
// an insertion: kernels_cpu/rtd's cavity kernel and hull kernel). Each half is
// a link (an integer naming a slot's side) and the ridge's vertices as a
// sorted key; a ridge is met exactly twice, and its two halves are linked.
// An open-addressing hash table, kept between calls so that its memory is
// reused: begin(), offer() per half, end().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flipflop::cpu {

// Two cells of k corners each (facets of a hull, simplices of a
// triangulation), t and g: when g holds every corner of t but the j-th and
// one more, that one's position in g (the side of g across which it meets t);
// otherwise -1. Corners distinct within each cell. The seeded kernels' check
// that a caller's cells are glued along their faces.
inline int across(const std::uint32_t* t, const std::uint32_t* g, int k, int j) {
  int i = -1, shared = 0;
  for (int c = 0; c < k; ++c) {
    bool in = false;
    for (int q = 0; q < k; ++q) in = in || (q != j && t[q] == g[c]);
    if (in)
      ++shared;
    else
      i = c;
  }
  return shared == k - 1 ? i : -1;
}

template <int K>  // vertices per key
class RidgeTable {
 public:
  using Key = std::array<std::uint32_t, static_cast<std::size_t>(K)>;
  static constexpr std::uint32_t kOpen = 0xffffffffu;

  // a call with at most `halves` halves
  void begin(std::size_t halves) {
    std::size_t cap = 16;
    while (cap < 2 * halves) cap <<= 1;
    if (table_.size() < cap) table_.resize(cap);  // new entries empty; used ones were emptied by end()
    mask_ = cap - 1;
    used_.clear();
    open_ = 0;
  }

  // Sorts a key in place: K rounds of odd-even transposition with branch-free
  // min / max (a sort of K elements; a std::sort of these few entries, with
  // its mispredicted branches, took most of a 5D hull's ridge matching).
  // Unused entries set to kOpen sort last.
  static void sort(Key& k) {
    for (int r = 0; r < K; ++r)
      for (int i = r & 1; i + 1 < K; i += 2) {
        const std::uint32_t a = k[static_cast<std::size_t>(i)], b = k[static_cast<std::size_t>(i + 1)];
        k[static_cast<std::size_t>(i)] = a < b ? a : b;
        k[static_cast<std::size_t>(i + 1)] = a < b ? b : a;
      }
  }

  // The half `link` of the ridge `key` (sorted): the link of the other half
  // when it was offered before in this call (the two are then matched), else
  // kOpen.
  std::uint32_t offer(const Key& key, std::uint32_t link) {
    std::uint64_t hash = 0x9E3779B97F4A7C15ull;
    for (std::uint32_t x : key) hash = (hash ^ x) * 0x100000001B3ull;
    const std::uint32_t tag = static_cast<std::uint32_t>(hash >> 32);
    for (std::size_t slot = (hash >> 20) & mask_;; slot = (slot + 1) & mask_) {
      Half& e = table_[slot];
      if (e.state == 1 && e.tag == tag && same(e.key, key)) {
        e.state = 2;
        --open_;
        return e.link;
      }
      if (e.state == 0) {
        e.key = key;
        e.tag = tag;
        e.link = link;
        e.state = 1;
        used_.push_back(static_cast<std::uint32_t>(slot));
        ++open_;
        return kOpen;
      }
    }
  }

  // Ends the call; true when every half offered was matched.
  bool end() {
    for (std::uint32_t q : used_) table_[q].state = 0;
    return open_ == 0;
  }

 private:
  static bool same(const Key& a, const Key& b) {
    bool eq = true;
    for (std::size_t i = 0; i < static_cast<std::size_t>(K); ++i) eq &= a[i] == b[i];
    return eq;
  }
  struct Half {
    Key key;
    std::uint32_t tag;  // the hash's high half
    std::uint32_t link;
    std::uint8_t state = 0;  // 0 empty, 1 open, 2 matched (a tombstone until end())
  };
  std::vector<Half> table_;
  std::vector<std::uint32_t> used_;  // slots filled by this call
  std::size_t mask_ = 0;
  std::ptrdiff_t open_ = 0;
};

}  // namespace flipflop::cpu

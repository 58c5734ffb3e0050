// cgal_sink.hpp — the output iterator handed to CGAL's point readers
// (internal to io/).
//
// It appends each point CGAL delivers to a PointSet and, once the number of
// vertices declared by the header has arrived, stops CGAL by throwing
// Enough: the faces after the vertices are never read (they are not needed,
// and a list of garbage face sizes must not make CGAL allocate).
#pragma once

#include <cstddef>
#include <iterator>

#include "reference/point_set.hpp"

namespace flipflop::io::detail {

struct Enough {};

template <class Value, class Put>
class CgalSink {
 public:
  using iterator_category = std::output_iterator_tag;
  using value_type = Value;  // read by CGAL::value_type_traits
  using difference_type = std::ptrdiff_t;
  using pointer = void;
  using reference = void;

  CgalSink(std::size_t expected, std::size_t* count, Put put)
      : expected_(expected), count_(count), put_(put) {}
  CgalSink& operator*() { return *this; }
  CgalSink& operator++() { return *this; }
  CgalSink& operator++(int) { return *this; }
  CgalSink& operator=(const Value& v) {
    put_(v);
    if (++*count_ == expected_) throw Enough{};
    return *this;
  }

 private:
  std::size_t expected_;
  std::size_t* count_;
  Put put_;
};

}  // namespace flipflop::io::detail

// values_test.cpp — reference/values.hpp, the owned-or-borrowed doubles of a
// PointSet (the Python package reads numpy arrays in place through it).
//
// Oracles: std::vector<double> (every sequence of operations gives the same
// values on a Values as on a vector, whether it started owned or borrowed) and
// the caller's buffer itself (a borrowed buffer is never written, and reading
// a borrowed Values returns the buffer's own addresses: no copy).
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <vector>

#include "reference/point_set.hpp"
#include "reference/hull2/hull2.hpp"

using namespace flipflop;

namespace {

bool same(const Values& v, const std::vector<double>& want) {
  if (v.size() != want.size()) return false;
  return v.empty() || std::memcmp(v.data(), want.data(), want.size() * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("values: reading a borrowed buffer reads it in place, const PointSet members included", "[values]") {
  const std::vector<double> buf = {0, 0, 1, 0, 0, 1, 0.25, 0.25};
  PointSet ps;
  ps.dim = 2;
  ps.coords = Values::borrow(buf.data(), buf.size());
  const PointSet& c = ps;
  CHECK(c.coords.borrowed());
  CHECK(c.coords.data() == buf.data());
  CHECK(c.size() == 4);
  CHECK(c.point(3) == buf.data() + 6);
  CHECK(&c.coords[5] == buf.data() + 5);
  CHECK(c.coords.end() == buf.data() + buf.size());
  // a copy of a borrowing point set borrows the same buffer
  const PointSet copy = c;
  CHECK(copy.coords.data() == buf.data());
  // an algorithm on the borrowing set gives the owned set's answer and leaves the buffer as it was
  PointSet owned;
  owned.dim = 2;
  owned.coords = buf;
  CHECK(ref::hull2(c, ref::hull2_algorithms().front()) == ref::hull2(owned, ref::hull2_algorithms().front()));
  CHECK(c.coords.data() == buf.data());
}

TEST_CASE("values: writing copies a borrowed buffer first and never writes the buffer", "[values]") {
  const std::vector<double> orig = {1, 2, 3, 4};
  std::vector<double> buf = orig;
  Values v = Values::borrow(buf.data(), buf.size());
  Values other = v;  // borrows too
  v[1] = 20;         // non-const access: copies, then writes the copy
  CHECK(!v.borrowed());
  CHECK(v.data() != buf.data());
  CHECK(buf == orig);
  CHECK(same(v, {1, 20, 3, 4}));
  CHECK(other.borrowed());
  CHECK(same(other, orig));
  other.push_back(5);
  CHECK(buf == orig);
  CHECK(same(other, {1, 2, 3, 4, 5}));
  // assigning from the buffer's own range while borrowing it
  Values w = Values::borrow(buf.data(), buf.size());
  w.assign(w.cbegin() + 1, w.cend());
  CHECK(same(w, {2, 3, 4}));
  CHECK(buf == orig);
}

// Every operation the library uses on coordinates and weights, applied to a
// Values and to a std::vector: the same values after each one, whether the
// Values started owned or borrowing another buffer with the same values.
TEST_CASE("values: behaves as std::vector<double> under random operations, owned or borrowed", "[values]") {
  rc::prop("same values as a std::vector after every operation", [] {
    const auto start = *rc::gen::container<std::vector<double>>(rc::gen::map(rc::gen::inRange(-50, 50), [](int x) {
      return x / 4.0;
    }));
    const bool borrow = *rc::gen::arbitrary<bool>();
    const std::vector<double> buffer = start;
    std::vector<double> model = start;
    Values v = borrow ? Values::borrow(buffer.data(), buffer.size()) : Values(start);
    const int ops = *rc::gen::inRange(1, 30);
    for (int k = 0; k < ops; ++k) {
      const int op = *rc::gen::inRange(0, 10);
      const double x = *rc::gen::inRange(-9, 9);
      const std::size_t n = model.size();
      switch (op) {
        case 0: v.push_back(x); model.push_back(x); break;
        case 1: {
          const std::size_t at = *rc::gen::inRange<std::size_t>(0, n + 1);
          const double ins[3] = {x, x + 1, x + 2};
          v.insert(static_cast<const Values&>(v).begin() + at, ins, ins + 3);
          model.insert(model.begin() + static_cast<std::ptrdiff_t>(at), ins, ins + 3);
          break;
        }
        case 2: {
          const std::size_t m = *rc::gen::inRange<std::size_t>(0, 20);
          v.resize(m);
          model.resize(m);
          break;
        }
        case 3:
          if (n > 0) {
            const std::size_t i = *rc::gen::inRange<std::size_t>(0, n);
            v[i] = x;
            model[i] = x;
          }
          break;
        case 4:
          if (n > 0) {
            const std::size_t a = *rc::gen::inRange<std::size_t>(0, n);
            const std::size_t b = *rc::gen::inRange<std::size_t>(a, n + 1);
            const auto& cv = static_cast<const Values&>(v);
            v.erase(cv.begin() + a, cv.begin() + b);
            model.erase(model.begin() + static_cast<std::ptrdiff_t>(a), model.begin() + static_cast<std::ptrdiff_t>(b));
          }
          break;
        case 5: v.assign(3, x); model.assign(3, x); break;
        case 6: {
          const Values copy = v;
          v = copy;
          break;
        }
        case 7: v.clear(); model.clear(); break;
        case 8:
          for (double& y : v) y += 1;
          for (double& y : model) y += 1;
          break;
        default: v = model; break;
      }
      RC_ASSERT(same(v, model));
      RC_ASSERT(v == Values(model));
    }
    RC_ASSERT(buffer == start);  // the borrowed buffer was never written
  });
}

// Values — the doubles of a PointSet (coordinates, weights): owned, in a
// std::vector, or borrowed, a caller's buffer read in place. The Python
// package borrows a C-contiguous float64 numpy array instead of copying it
// (python/src/module.cpp); everything else owns its values.
//
// A borrowed buffer must outlive every Values that borrows it (copies of a
// borrowing Values borrow the same buffer) and must not change while an
// algorithm reads it. The const members read whichever storage is in use and
// never copy. A borrowed buffer is never written: every member that can
// write — the non-const data(), operator[], begin()/end(), the vector-like
// modifiers and vec() — first copies it into owned storage. That copy is not
// thread-safe, so the algorithms take point sets by const reference (and the
// parallel kernels only read them).
#pragma once

#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <utility>
#include <vector>

namespace flipflop {

class Values {
 public:
  using value_type = double;
  using size_type = std::size_t;
  using iterator = double*;
  using const_iterator = const double*;

  Values() = default;
  Values(std::vector<double> v) : own_(std::move(v)) {}  // NOLINT: implicit, as a vector
  Values(std::initializer_list<double> l) : own_(l) {}
  template <class It, class = decltype(*std::declval<It&>())>
  Values(It first, It last) : own_(first, last) {}
  explicit Values(size_type n, double x = 0.0) : own_(n, x) {}

  // A Values reading p[0..n) in place.
  static Values borrow(const double* p, size_type n) {
    Values v;
    v.ptr_ = p;
    v.n_ = n;
    v.borrowed_ = true;
    return v;
  }
  bool borrowed() const { return borrowed_; }

  // ---- reading: never copies
  const double* data() const { return borrowed_ ? ptr_ : own_.data(); }
  size_type size() const { return borrowed_ ? n_ : own_.size(); }
  bool empty() const { return size() == 0; }
  const double& operator[](size_type i) const { return data()[i]; }
  const double* begin() const { return data(); }
  const double* end() const { return data() + size(); }
  const double* cbegin() const { return begin(); }
  const double* cend() const { return end(); }
  const double& front() const { return data()[0]; }
  const double& back() const { return data()[size() - 1]; }
  std::vector<double> to_vector() const { return std::vector<double>(begin(), end()); }

  // ---- writing: owned storage (a borrowed buffer is copied first)
  double* data() { return vec().data(); }
  double& operator[](size_type i) { return vec()[i]; }
  double* begin() { return vec().data(); }
  double* end() { return vec().data() + own_.size(); }
  double& front() { return vec().front(); }
  double& back() { return vec().back(); }
  std::vector<double>& vec() {
    if (borrowed_) {
      own_.assign(ptr_, ptr_ + n_);
      borrowed_ = false;
      ptr_ = nullptr;
      n_ = 0;
    }
    return own_;
  }

  void push_back(double x) { vec().push_back(x); }
  template <class... A>
  double& emplace_back(A&&... a) {
    return vec().emplace_back(std::forward<A>(a)...);
  }
  template <class It, class = decltype(*std::declval<It&>())>
  double* insert(const double* pos, It first, It last) {
    const std::ptrdiff_t at = pos - static_cast<const Values&>(*this).data();
    auto& v = vec();
    return &*v.insert(v.begin() + at, first, last);
  }
  double* insert(const double* pos, double x) { return insert(pos, &x, &x + 1); }
  double* insert(const double* pos, std::initializer_list<double> l) { return insert(pos, l.begin(), l.end()); }
  double* erase(const double* pos) { return erase(pos, pos + 1); }
  double* erase(const double* first, const double* last) {
    const std::ptrdiff_t a = first - static_cast<const Values&>(*this).data();
    const std::ptrdiff_t b = last - static_cast<const Values&>(*this).data();
    auto& v = vec();
    return v.data() + (v.erase(v.begin() + a, v.begin() + b) - v.begin());
  }
  void resize(size_type n) { vec().resize(n); }
  void resize(size_type n, double x) { vec().resize(n, x); }
  void reserve(size_type n) { vec().reserve(n); }
  void clear() { vec().clear(); }
  void shrink_to_fit() { vec().shrink_to_fit(); }
  template <class It, class = decltype(*std::declval<It&>())>
  void assign(It first, It last) {
    std::vector<double> v(first, last);  // first..last may lie in the buffer itself
    own_ = std::move(v);
    borrowed_ = false;
    ptr_ = nullptr;
    n_ = 0;
  }
  void assign(size_type n, double x) { *this = Values(n, x); }
  void assign(std::initializer_list<double> l) { *this = Values(l); }

  friend bool operator==(const Values& a, const Values& b) {
    if (a.size() != b.size()) return false;
    for (size_type i = 0; i < a.size(); ++i)
      if (!(a[i] == b[i])) return false;
    return true;
  }
  friend bool operator!=(const Values& a, const Values& b) { return !(a == b); }

 private:
  std::vector<double> own_;
  const double* ptr_ = nullptr;
  size_type n_ = 0;
  bool borrowed_ = false;
};

// Bitwise equality: unlike ==, tells -0 from +0 and compares NaNs by their
// bits (the readers and generators are checked to reproduce values exactly).
inline bool same_bits(const Values& a, const Values& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

}  // namespace flipflop

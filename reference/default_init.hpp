// default_init.hpp — DefaultInit<T>: an allocator whose value-initialisation
// is default-initialisation, and UninitVector<T>, a std::vector of it. For
// buffers every step writes before it reads: std::vector<T>(n) or resize(n)
// would first zero them on one thread — a pass over memory that costs as much
// as a parallel step and takes all the fresh pages' faults on that thread.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace flipflop {

template <class T>
struct DefaultInit : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInit<U>;
  };
  DefaultInit() = default;
  template <class U>
  DefaultInit(const DefaultInit<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};

template <class T>
using UninitVector = std::vector<T, DefaultInit<T>>;

}  // namespace flipflop

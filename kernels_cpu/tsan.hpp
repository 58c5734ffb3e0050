// tsan.hpp — ThreadSanitizer annotations for TBB's fork/join.
//
// Debian's libtbb.so is not built with -fsanitize=thread, so ThreadSanitizer
// does not see the synchronisation inside TBB's scheduler: the hand-off of a
// task to a worker thread (everything the caller wrote before parallel_for
// happens-before the task body) and the join (every task body happens-before
// parallel_for's return). Without these edges every read of the caller's data
// in a task is reported as a race. ForkJoin declares exactly these two edges,
// which TBB guarantees; races between tasks running at the same time are
// still reported. Without ThreadSanitizer everything compiles to nothing.
//
//   tsan::ForkJoin fj;                 // before tbb::parallel_for: fork edge
//   tbb::parallel_for(..., [&](...) { fj.task_begin(); ...; fj.task_end(); });
//   fj.joined();                       // after parallel_for: join edge
#pragma once

#if defined(__SANITIZE_THREAD__)
#define FLIPFLOP_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define FLIPFLOP_TSAN 1
#endif
#endif

#if defined(FLIPFLOP_TSAN)
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace flipflop::tsan {
// A lock-like hand-off through an atomic that this folder does not let TSan
// instrument (kernels_cpu/CMakeLists.txt): the thread that takes ownership of
// an object calls acquired(&flag) after its successful compare-exchange, the
// one that gives it up released(&flag) before its releasing store.
#if defined(FLIPFLOP_TSAN)
inline void acquired(void* a) { __tsan_acquire(a); }
inline void released(void* a) { __tsan_release(a); }
#else
inline void acquired(void*) {}
inline void released(void*) {}
#endif


class ForkJoin {
 public:
  ForkJoin() { release(&fork_); }
  void task_begin() { acquire(&fork_); }
  void task_end() { release(&join_); }
  void joined() { acquire(&join_); }

 private:
#if defined(FLIPFLOP_TSAN)
  static void acquire(void* a) { __tsan_acquire(a); }
  static void release(void* a) { __tsan_release(a); }
#else
  static void acquire(void*) {}
  static void release(void*) {}
#endif
  char fork_ = 0, join_ = 0;  // addresses only: the sync objects' identities
};

}  // namespace flipflop::tsan

#pragma once
// A step's OpenMP team (docs/architecture.md, "A step"): the whole step is one parallel region
// whose phases meet at barriers only where data demand them, the serial parts run by the master
// thread between two barriers. The team keeps the time each thread waits at them (the measure
// of imbalance and serial parts) and carries an exception of a serial part out of the region
// (one must not leave a parallel region): the threads skip the remaining phases alike.
//
// Its barrier is its own, a centralised one that spins, then sleeps: libgomp's makes a futex
// system call at every barrier, even in a team of one (measured 1.3-3 us a barrier and 6.7 us a
// two-thread region on this project's machines, docs/performance.md); this one calls the kernel
// only when a thread waited long enough to sleep. One thread runs no region and meets no barrier.

#include <omp.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <vector>

namespace sqdem {

class Team {
 public:
  explicit Team(int threads) : threads_(threads), waits_(static_cast<std::size_t>(threads)) {}

  /// Runs body() on every thread of a new team of `threads` (on this thread alone for one).
  template <typename F>
  void run(F&& body) {
    if (threads_ == 1 && !omp_in_parallel()) {  // (inside another region: a team of its own)
      body();
      return;
    }
#pragma omp parallel num_threads(threads_)
    body();
  }
  /// A barrier of the whole team (with the memory ordering of one); the calling thread's wait
  /// is added to its account.
  void barrier() {
    const int size = omp_get_num_threads();
    if (size == 1) return;
    const auto start = Clock::now();
    const unsigned generation = generation_.value.load(std::memory_order_acquire);
    if (arrived_.value.fetch_add(1, std::memory_order_acq_rel) + 1 == size) {
      arrived_.value.store(0, std::memory_order_relaxed);
      // Sequentially consistent: notify_all's check for sleepers must not pass the store.
      generation_.value.store(generation + 1, std::memory_order_seq_cst);
      generation_.value.notify_all();  // a system call only when some thread sleeps
    } else {
      // Spin a while (a step's waits are mostly shorter), then sleep: with more threads than
      // cores (ranks times threads) a spinning thread would take the core of the one it waits for.
      for (int spins = 0; spins < spinLimit && generation_.value.load(std::memory_order_acquire) == generation; ++spins) relax();
      while (generation_.value.load(std::memory_order_acquire) == generation) {
        generation_.value.wait(generation, std::memory_order_acquire);
      }
    }
    waits_[static_cast<std::size_t>(omp_get_thread_num())].seconds += std::chrono::duration<double>(Clock::now() - start).count();
  }
  /// Runs f on the master thread only (no barrier), unless a serial part failed before; what f
  /// throws is kept for rethrow().
  template <typename F>
  void master(F&& f) {
#pragma omp master
    {
      size_ = omp_get_num_threads();
      if (!failure_) {
        try {
          f();
        } catch (...) {
          failure_ = std::current_exception();
        }
      }
    }
  }
  /// Adds to the calling thread's account of its work in the phase that rebalances the team
  /// (TeamSplit).
  void addWork(double seconds) { waits_[static_cast<std::size_t>(omp_get_thread_num())].work += seconds; }
  /// Each thread's work so far (s), for TeamSplit::rebalance.
  std::vector<double> work() const {
    std::vector<double> w;
    for (int t = 0; t < size_; ++t) w.push_back(waits_[static_cast<std::size_t>(t)].work);
    return w;
  }
  /// Whether a serial part threw: to be read after a barrier, so that every thread sees the same.
  bool failed() const { return failure_ != nullptr; }
  /// After the region: rethrows what a serial part threw.
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }
  /// The threads' mean wait at the barriers (s).
  double meanWait() const {
    double total = 0.0;
    for (const Wait& w : waits_) total += w.seconds;
    return total / size_;
  }

 private:
  using Clock = std::chrono::steady_clock;
  /// A spinning thread's hint to the core (x86's pause; nothing elsewhere).
  static void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  static constexpr int spinLimit = 1 << 8;  ///< pauses before a waiting thread sleeps (~5 us on Zen 5)
  struct alignas(64) Wait {  // a cache line each: the threads write them at every barrier
    double seconds = 0.0;
    double work = 0.0;
  };
  template <typename T>
  struct alignas(64) Line {
    std::atomic<T> value{0};
  };
  int threads_;
  std::vector<Wait> waits_;
  Line<int> arrived_;
  Line<unsigned> generation_;
  std::exception_ptr failure_;
  int size_ = 1;
};

}  // namespace sqdem

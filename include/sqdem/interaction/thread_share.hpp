#pragma once
// How a step's team shares its loops out (docs/architecture.md, "A step"): every thread takes
// one contiguous run of the particles, in thread order, the same run in every pass (drift,
// reduction), and the contacts whose A is one of its particles (Interactions::memberShare): the
// records a thread writes in one pass are those it reads in the next, and stay in its core's
// cache (a core reading lines another one wrote waits for them: measured in
// docs/performance.md). The runs are cut so that the threads' contact work takes equally long,
// as measured over the last steps; the cuts decide who computes what, never the order of a sum,
// so the bits do not depend on them. Outside a parallel region the one thread takes everything.

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace sqdem {

/// Items [begin, end) of a loop.
struct Share {
  std::ptrdiff_t begin = 0, end = 0;
};

/// The calling thread's even share of `count` items.
inline Share threadShare(std::ptrdiff_t count) {
  const std::ptrdiff_t t = omp_get_thread_num(), size = omp_get_num_threads();
  return {count * t / size, count * (t + 1) / size};
}

/// Where a team's runs of particles are cut: run t holds the fraction [cut[t], cut[t + 1]) of
/// them. Even until rebalance() moves the cuts.
class TeamSplit {
 public:
  /// The calling thread's run of `count` particles (of a team of the split's size; an even
  /// share in a team of another size).
  Share share(std::ptrdiff_t count) const {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    if (cut_.size() != static_cast<std::size_t>(omp_get_num_threads()) + 1) return threadShare(count);
    const auto at = [&](std::size_t c) { return static_cast<std::ptrdiff_t>(std::llround(static_cast<double>(count) * cut_[c])); };
    return {at(t), at(t + 1)};
  }
  /// After a step in which thread t took seconds[t] for its run: each run's width scaled by its
  /// thread's speed (width / seconds) so that all would take as long, the cuts moved halfway
  /// there (steps are noisy).
  void rebalance(std::span<const double> seconds) {
    const std::size_t size = seconds.size();
    if (size < 2) return;
    if (cut_.size() != size + 1) {
      cut_.resize(size + 1);
      for (std::size_t t = 0; t <= size; ++t) cut_[t] = static_cast<double>(t) / static_cast<double>(size);
    }
    std::vector<double> speed(size);
    double total = 0.0;
    for (std::size_t t = 0; t < size; ++t) {
      if (!(seconds[t] > 0.0)) return;  // nothing measured
      const double width = std::max(cut_[t + 1] - cut_[t], 0.1 / static_cast<double>(size));  // no run starves
      speed[t] = width / seconds[t];
      total += speed[t];
    }
    double at = 0.0;
    for (std::size_t t = 1; t < size; ++t) {
      at += speed[t - 1] / total;
      cut_[t] = 0.5 * (cut_[t] + at);
    }
  }

 private:
  std::vector<double> cut_;  ///< size + 1 fractions from 0 to 1; empty: even
};

}  // namespace sqdem

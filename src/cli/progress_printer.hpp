#pragma once
// What `sqdem run` prints while it runs: on a terminal a progress line rewritten twice a second;
// otherwise (a batch job's log) the same line as a record every `recordEvery` seconds; and a
// line at each stage's end. A stage that ends at its duration shows its percentage and an ETA;
// a stage with a stop criterion shows the watched quantity against its target instead (its end
// cannot be foreseen). Steps/s are over the last 5 s.

#include <chrono>
#include <deque>
#include <string>
#include <utility>

#include "sqdem/scene/stage_runner.hpp"

namespace sqdem::cli {

class ProgressPrinter : public RunObserver {
 public:
  /// recordEvery: seconds between progress records when stderr is not a terminal (0: none);
  /// speaks: whether this process prints (across ranks rank 0, whose clock paces every rank).
  ProgressPrinter(const Scene& scene, double recordEvery, bool speaks);

  bool wantsUpdate() override;
  void update(const StageSpec& stage, long step, long steps, long stepsThisRun, const World& world) override;
  void stageEnded(const StageSpec& stage, const std::string& reason, const World& world) override;
  /// Clears the terminal's progress line (before other output).
  void clearLine() const;
  /// Wall-clock seconds since the run started.
  double elapsed() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::string line(const StageSpec& stage, long step, long steps, long stepsThisRun, const World& world) const;

  const Scene& scene_;
  bool speaks_, terminal_;
  double recordEvery_;
  Clock::time_point start_ = Clock::now(), lastPrint_ = start_;
  std::deque<std::pair<Clock::time_point, long>> recent_;  ///< (when, steps) samples over the last 5 s
};

}  // namespace sqdem::cli

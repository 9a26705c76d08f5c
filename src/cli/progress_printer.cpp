#include "progress_printer.hpp"

#include <unistd.h>

#include <cstdio>

#include "sqdem/world/packing_measures.hpp"

namespace sqdem::cli {
namespace {

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

ProgressPrinter::ProgressPrinter(const Scene& scene, double recordEvery, bool speaks)
    : scene_(scene), speaks_(speaks), terminal_(speaks && isatty(fileno(stderr))), recordEvery_(recordEvery) {}

bool ProgressPrinter::wantsUpdate() {
  const double since = seconds(Clock::now() - lastPrint_);
  return speaks_ && (terminal_ ? since > 0.5 : recordEvery_ > 0.0 && since >= recordEvery_);
}

void ProgressPrinter::update(const StageSpec& stage, long step, long steps, long stepsThisRun, const World& world) {
  const auto now = Clock::now();
  lastPrint_ = now;
  recent_.emplace_back(now, stepsThisRun);
  while (recent_.size() > 2 && seconds(now - recent_[1].first) >= 5.0) recent_.pop_front();
  const std::string text = line(stage, step, steps, stepsThisRun, world);  // on every rank: its measures are reduced
  if (!speaks_) return;
  if (terminal_) {
    std::fprintf(stderr, "\r%-100s", text.c_str());
  } else {
    std::printf("progress: %s\n", text.c_str());
    std::fflush(stdout);
  }
}

std::string ProgressPrinter::line(const StageSpec& stage, long step, long steps, long stepsThisRun, const World& world) const {
  const auto& [then, stepsThen] = recent_.front();
  const double window = seconds(recent_.back().first - then);
  const double rate = window > 0.0 ? (stepsThisRun - stepsThen) / window
                                   : stepsThisRun / std::max(seconds(Clock::now() - start_), 1e-9);
  char text[256];
  if (stage.kineticEnergyRatio > 0.0 || stage.wallPressure > 0.0 || stage.porosity > 0.0) {
    // The end is where the watched quantity crosses its target: no percentage, no ETA.
    char watched[128];
    if (stage.kineticEnergyRatio > 0.0) {
      std::snprintf(watched, sizeof watched, "E_kin ratio %.3g, stops below %.3g",
                    kineticEnergyRatio(world, scene_.gravity, stage.velocityScale), stage.kineticEnergyRatio);
    } else if (stage.wallPressure > 0.0) {
      std::snprintf(watched, sizeof watched, "wall %zu pressure %.4g Pa, stops at %.4g Pa", stage.pressureWall,
                    world.wallPressure(stage.pressureWall), stage.wallPressure);
    } else {
      std::snprintf(watched, sizeof watched, "porosity %.4f, stops at %.4f", measurePlate(world, stage.pressureWall).porosity,
                    stage.porosity);
    }
    std::snprintf(text, sizeof text, "[%s] t = %.4g s, step %ld of at most %ld; %s; %.0f steps/s", stage.name.c_str(),
                  world.time(), step, steps, watched, rate);
  } else {
    std::snprintf(text, sizeof text, "[%s] %5.1f %%  t = %.4g s  %.0f steps/s  ETA %.0f s", stage.name.c_str(),
                  100.0 * step / steps, world.time(), rate, (steps - step) / rate);
  }
  return text;
}

void ProgressPrinter::stageEnded(const StageSpec& stage, const std::string& reason, const World& world) {
  clearLine();
  const PackingMeasures m = measurePacking(world);  // on every rank: reduced
  std::printf("stage '%s': t = %.4g s, %s; solid fraction %.4f, mean coordination %.3f, E_kin %.3g J", stage.name.c_str(),
              world.time(), reason.c_str(), m.solidFraction, m.meanCoordination, world.kineticEnergy());
  if (stage.kineticEnergyRatio > 0.0) {
    std::printf(" (ratio %.3g)", kineticEnergyRatio(world, scene_.gravity, stage.velocityScale));
  } else if (scene_.gravity.norm() > 0.0) {
    std::printf(" (ratio %.3g)", kineticEnergyRatio(world, scene_.gravity, 0.0));
  }
  std::printf("\n");
  if (m.betweenWallsFraction > 0.0) std::printf("  solid fraction between the walls %.4f\n", m.betweenWallsFraction);
  std::fflush(stdout);
}

void ProgressPrinter::clearLine() const {
  if (terminal_) std::fprintf(stderr, "\r%100s\r", "");
}

double ProgressPrinter::elapsed() const { return seconds(Clock::now() - start_); }

}  // namespace sqdem::cli

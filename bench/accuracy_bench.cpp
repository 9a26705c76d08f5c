// Run time vs error benchmark (issue 12 item 4; printed and written as a table, never asserted).
//
// From a settled bed (the scene's stages, run once with the default settings), every accuracy
// knob of the engine is varied alone: detector tolerance, warm starts, e^2 (exact, tabulated,
// explicit), the curvature cache tolerance, the full elliptic law vs Hertz on volume-equivalent
// spheres, the time step; then the true-gap law (docs/contact_laws.md) at its cache tolerances and
// grids. Each variant runs `steps` steps of the bed (1 thread; the fastest of three identical runs
// is timed; the law's variants after lawWarmUpSteps untimed steps under their own settings) and
// is measured:
//   cost    wall time per particle-step, and per particle and simulated millisecond (the time step
//           changes how many steps a protocol needs);
//   force   contact force error on the same configuration: a copy of the variant's world before
//           its last step takes that step with the reference settings (tightest of every knob),
//           and the two forces of every contact are compared: |F - F_ref| / |F_ref|, median, 99th
//           percentile, max (a contact only one of them has counts 1); the reference keeps the
//           variant's law (true_gap's at its default 16 cells);
//   bulk    drift of solid fraction, mean coordination and mean stress -tr(sigma)/3 after the run
//           against the reference run's: for true_gap the run at curvature tolerance 1e-4, the
//           tightest that runs in minutes (at 0 each contact-step solves two rungs of ~1 ms);
//   rungs   the true-gap rungs solved per 1000 detector calls in the timed run.
// usage: bench_accuracy <bed.yaml> [steps, default 1000] [table.tsv] [settle, s] [only]
//   (bench/scenes/bed_ellipsoid.yaml, bed_sq6.yaml; bench/run_accuracy.sh runs both and plots);
//   settle: how long the bed settles before the variants, instead of the scene's stages (its
//   beds still collapse after their 0.15 s; 0.4 s gives them at rest); only: run just the
//   variants whose name contains this text, and the bulk references their drifts need.

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "sqdem/mechanics/true_gap_law.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/scene_loader.hpp"
#include "sqdem/world/packing_measures.hpp"
#include "sqdem/world/world.hpp"

using namespace sqdem;

namespace {

/// One setting of every knob.
struct Settings {
  double detectorTolerance = DetectorControl{}.tolerance;
  bool warmStart = true;
  EccentricityMethod eccentricity = EccentricityMethod::Tabulated;
  double curvatureTolerance = ContactModel{}.curvatureTolerance;
  bool fullLaw = true;
  double timeStepFactor = 1.0;
  int trueGapCells = 0;  ///< the normal law true_gap on this grid; 0: the scene's law
};

/// Timed runs per variant: this machine's timings scatter by ±30 % from run to run.
constexpr int timingRepeats = 3;
/// Untimed steps of a variant that changes the law before its timed runs. The bed settled under
/// the scene's law: at its first step every contact solves its rungs, and the bed moves until it
/// carries the new law's forces (the true gap raises the n = 6 bed's stress by ~4 %). On that
/// bed at rest (sqdem run, curvature tolerance 1e-2) the first 1,000 steps solve 4,528 rungs,
/// the next 2,000 1,339.
constexpr int lawWarmUpSteps = 2000;

struct Variant {
  std::string name;
  Settings settings;
};

void apply(const Settings& s, World& world, double baseTimeStep) {
  world.setDetectorControl({s.detectorTolerance, s.warmStart});
  const auto n = static_cast<std::uint32_t>(world.materials().size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a; b < n; ++b) {
      ContactModel m = world.contactModel(a, b);
      m.eccentricity = s.eccentricity;
      m.curvatureTolerance = s.curvatureTolerance;
      m.curvatures = s.fullLaw;
      m.tangential.elliptic = s.fullLaw;
      if (s.trueGapCells > 0) m.normal = TrueGapLaw{s.trueGapCells};
      world.setContactModel(a, b, m);
    }
  }
  world.setTimeStep(baseTimeStep * s.timeStepFactor);
}

/// Force on B of every acting contact, by key.
std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> contactForces(const World& world) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> forces;
  for (const ContactView c : world.contacts()) forces[{c.a(), c.b()}] = c.force();
  return forces;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::min(q * static_cast<double>(v.size()), static_cast<double>(v.size() - 1)))];
}

struct Bulk {
  double solidFraction, coordination, pressure;
};

Bulk bulk(const World& world) {
  const PackingMeasures m = measurePacking(world);
  return {m.solidFraction, m.meanCoordination, m.stress.trace() / 3.0};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_accuracy <bed.yaml> [steps, default 1000] [table.tsv] [settle, s: default the scene's stages]"
                         " [only: variants whose name contains this]\n");
    return 2;
  }
  int steps = 1000;
  if (argc > 2) {
    char* end = nullptr;
    const long given = std::strtol(argv[2], &end, 10);
    if (end == argv[2] || *end != '\0' || given < 2 || given > 100000000) {
      std::fprintf(stderr, "bench_accuracy: the steps must be an integer in [2, 1e8], not '%s'\n", argv[2]);
      return 2;
    }
    steps = static_cast<int>(given);
  }
  omp_set_num_threads(1);
  const Scene scene = loadScene(argv[1]);
  World world = buildWorld(scene);
  const double dt = world.timeStep();
  double duration = 0.0;
  for (const StageSpec& stage : scene.stages) duration += stage.duration;
  if (argc > 4) {
    char* end = nullptr;
    duration = std::strtod(argv[4], &end);
    if (end == argv[4] || *end != '\0' || !(duration >= 0.0 && std::isfinite(duration))) {
      std::fprintf(stderr, "bench_accuracy: the settling time must be a number of seconds >= 0, not '%s'\n", argv[4]);
      return 2;
    }
  }
  const auto settleSteps = static_cast<long long>(std::llround(duration / dt));
  std::printf("%s: %zu particles, settling %lld steps ...\n", argv[1], world.particles().size(), settleSteps);
  std::fflush(stdout);
  for (long long s = 0; s < settleSteps; ++s) world.step();
  const World settled = world;

  // The reference of a variant: the tightest of every knob, the variant's law kept.
  const auto referenceOf = [](const Settings& s) {
    Settings reference;
    reference.detectorTolerance = 1e-12;
    reference.eccentricity = EccentricityMethod::Exact;
    reference.curvatureTolerance = 0.0;
    reference.trueGapCells = s.trueGapCells > 0 ? TrueGapLaw{}.cells : 0;
    return reference;
  };
  const Settings defaults;
  std::vector<Variant> variants{{"reference (tightest)", referenceOf(defaults)}, {"default", defaults}};
  const auto vary = [&](const std::string& name, auto change) {
    Settings s = defaults;
    change(s);
    variants.push_back({name, s});
  };
  const auto named = [](const char* what, double value) {
    char name[64];
    std::snprintf(name, sizeof name, "%s%g", what, value);
    return std::string(name);
  };
  for (const double t : {1e-11, 1e-10, 1e-8, 1e-4}) vary(named("detector tolerance ", t), [&](Settings& s) { s.detectorTolerance = t; });
  vary("warm start off", [](Settings& s) { s.warmStart = false; });
  vary("e^2 exact", [](Settings& s) { s.eccentricity = EccentricityMethod::Exact; });
  vary("e^2 explicit", [](Settings& s) { s.eccentricity = EccentricityMethod::Explicit; });
  for (const double t : {0.0, 1e-6, 1e-4, 1e-3, 1e-2}) vary(named("curvature tolerance ", t), [&](Settings& s) { s.curvatureTolerance = t; });
  vary("volume-sphere Hertz", [](Settings& s) { s.fullLaw = false; });
  for (const double f : {0.5, 2.0}) vary(named("time step x", f), [&](Settings& s) { s.timeStepFactor = f; });
  // The true-gap law: its first variant is its bulk reference (above).
  const std::size_t firstTrueGap = variants.size();
  for (const int cells : {16, 8}) {
    for (const double t : {1e-4, 1e-3, 1e-2}) {
      if (cells != TrueGapLaw{}.cells && t == 1e-4) continue;
      char name[64];
      std::snprintf(name, sizeof name, "true_gap %d cells, curv. %g", cells, t);
      vary(name, [&](Settings& s) {
        s.trueGapCells = cells;
        s.curvatureTolerance = t;
      });
    }
  }

  std::FILE* tsv = argc > 3 ? std::fopen(argv[3], "w") : nullptr;
  if (tsv) {
    std::fprintf(tsv, "variant\tus_per_particle_step\tus_per_particle_per_ms\tforce_err_median\tforce_err_p99\tforce_err_max"
                      "\tdrift_solid_fraction\tdrift_coordination\tdrift_pressure_rel\trungs_per_1000_detector_calls\n");
  }
  std::printf("%-32s %12s %12s %10s %10s %10s %12s %12s %12s %10s\n", "variant", "us/p-step", "us/p/ms", "F err med",
              "F err p99", "F err max", "d(phi)", "d(Z)", "d(p)/p", "rungs/kdc");
  const std::string only = argc > 5 ? argv[5] : "";
  Bulk referenceBulk{};
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Variant& v = variants[i];
    const bool bulkReference = i == 0 || i == firstTrueGap;
    if (!bulkReference && v.name.find(only) == std::string::npos) continue;
    // The same (deterministic) run timingRepeats times; its cost is the fastest of them.
    const int n = static_cast<int>(std::lround(steps / v.settings.timeStepFactor));
    World start = settled;
    apply(v.settings, start, dt);
    if (v.settings.trueGapCells > 0) {
      for (int s = 0; s < lawWarmUpSteps; ++s) start.step();
    }
    World w = start;
    double seconds = std::numeric_limits<double>::infinity();
    for (int r = 0; r < timingRepeats; ++r) {
      if (r > 0) w = start;
      const auto t0 = std::chrono::steady_clock::now();
      for (int s = 0; s < n - 1; ++s) w.step();
      seconds = std::min(seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    const ContactStatistics before = start.totalStatistics(), after = w.totalStatistics();
    const double rungRate = 1e3 * static_cast<double>(after.trueGapRungs - before.trueGapRungs) /
                            static_cast<double>(std::max(after.detectorCalls - before.detectorCalls, 1LL));
    World check = w;
    w.step();
    apply(referenceOf(v.settings), check, dt);
    check.setTimeStep(w.timeStep());  // the same step: only the force computation differs
    check.step();
    const auto mine = contactForces(w), exact = contactForces(check);
    std::vector<double> errors;
    for (const auto& [key, f] : exact) {
      const auto it = mine.find(key);
      errors.push_back(it == mine.end() ? 1.0 : (it->second - f).norm() / std::max(f.norm(), 1e-300));
    }
    for (const auto& [key, f] : mine) {
      if (!exact.count(key)) errors.push_back(1.0);
    }
    const Bulk b = bulk(w);
    if (bulkReference) referenceBulk = b;
    const double perStep = 1e6 * seconds / (static_cast<double>(n - 1) * w.particles().size());
    const double perMs = perStep * 1e-3 / w.timeStep();
    const double dPhi = b.solidFraction - referenceBulk.solidFraction, dZ = b.coordination - referenceBulk.coordination;
    const double dP = (b.pressure - referenceBulk.pressure) / referenceBulk.pressure;
    std::printf("%-32s %12.3f %12.3f %10.2e %10.2e %10.2e %12.2e %12.2e %12.2e %10.3f\n", v.name.c_str(), perStep, perMs,
                quantile(errors, 0.5), quantile(errors, 0.99), quantile(errors, 1.0), dPhi, dZ, dP, rungRate);
    std::fflush(stdout);
    if (tsv) {
      std::fprintf(tsv, "%s\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\n", v.name.c_str(), perStep, perMs,
                   quantile(errors, 0.5), quantile(errors, 0.99), quantile(errors, 1.0), dPhi, dZ, dP, rungRate);
    }
  }
  if (tsv) std::fclose(tsv);
  return 0;
}

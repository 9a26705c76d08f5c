#pragma once
// What a plate press (calendering) study reports (scene key output.compression_wall): the plate's
// gap to the floor (the coating thickness while the plate bears on it) and its pressure at every
// CSV row of the run, split into presses (a press ends where the plate lets go: its pressure
// falls below `threshold` x that press's peak; a press whose peak is below `threshold` x the
// run's largest is a touch of the loose top, counted with the press after it), and for each
//   peak pressure            the largest plate pressure (Pa)
//   thickness before         the gap where the pressure first reached `threshold` x the peak
//                            on loading: where the plate takes hold of the bed's top (a single
//                            protruding particle does not count)
//   thickness at the peak    the gap at the peak pressure
//   thickness after          the gap where the pressure last fell below threshold x the peak,
//                            on unloading: the recovered coating the plate lets go of
//   springback               (after - at peak) / at peak, the relative thickness recovery
//   permanent compression    (before - after) / before
//   porosity                 1 - V_solid / (A gap) at each of the three (A the box's cross-section)
// The same numbers come out of the CSV's plate_gap and plate_pressure columns (their resolution
// is the CSV's: output.log_every). Over three or more presses that let go, Meyer et al.'s
// compaction law is fitted to the porosity after each press against its peak pressure, with the
// first press's porosity before at zero pressure (compaction_fit.hpp).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sqdem/scene/compaction_fit.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {

struct CompressionSummary {
  double peakPressure = 0.0;                                        ///< (Pa)
  double thicknessBefore = 0.0, thicknessAtPeak = 0.0, thicknessAfter = 0.0;  ///< (m)
  double porosityBefore = 0.0, porosityAtPeak = 0.0, porosityAfter = 0.0;     ///< (-)
  bool released = false;  ///< the pressure fell below the threshold after the peak (else "after" is the last gap)

  double springback() const { return (thicknessAfter - thicknessAtPeak) / thicknessAtPeak; }
  double permanentCompression() const { return (thicknessBefore - thicknessAfter) / thicknessBefore; }
};

class CompressionRecord {
 public:
  static constexpr double threshold = 0.01;  ///< of the peak pressure: the plate bears on the bed

  void add(double time, const PlateMeasures& plate) { samples_.push_back({time, plate}); }
  /// One summary per press, in order; none before the plate carried any load.
  std::vector<CompressionSummary> presses() const;
  /// Meyer et al.'s law through (0, the first press's porosity before) and each released
  /// press's (peak pressure, porosity after); nothing with fewer than three released presses.
  std::optional<CompactionFit> compaction() const;

  /// Writes <name>_compression.csv (time, gap, pressure, porosity, press: its number from 1,
  /// branch: loading up to the press's peak, then unloading), and, when the plate bore on the bed, its plot
  /// <name>_compression.png (pressure against porosity on both branches, thickness against
  /// time) through gnuplot when it is installed; returns the PNG's path, or nothing.
  std::optional<std::filesystem::path> write(const std::filesystem::path& directory, const std::string& name) const;

 private:
  struct Sample {
    double time;
    PlateMeasures plate;
  };
  /// A press's samples [start, end), its peak and, when the plate let go, the last sample that bore.
  struct Press {
    std::size_t start = 0, end = 0, peak = 0;
    std::optional<std::size_t> letGo;
  };
  std::vector<Press> split() const;
  CompressionSummary summarise(const Press& press) const;
  std::vector<Sample> samples_;
};

}  // namespace sqdem

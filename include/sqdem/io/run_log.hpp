#pragma once
// The CSV log of a run, one row written and flushed at a time (an interrupted run keeps its
// rows). Columns: time (s), step, stage, kinetic_energy (J), contacts, mean_coordination,
// solid_fraction, bed_height (m), detector_failures, stress_xx ... stress_yz (Pa, Love-Weber,
// packing_measures.hpp), and per wall the force the particles exert on it, fx, fy, fz (N),
// after its position: a plane's z (m); a cylinder's axis point x, y, z (m), followed by the
// torque about that point tx, ty, tz (N m); yielded_fraction and largest_overlap_ratio
// (packing_measures.hpp); with a pressing plate (scene/compression_report.hpp) plate_gap (m),
// plate_pressure (Pa) and porosity (-). With an energy ledger (world/energy_ledger.hpp),
// its terms since the start, all in J: work_bodies, work_gravity, elastic_energy (U now),
// plastic_dissipation, damping_dissipation, tangential_dissipation, drag_dissipation and
// energy_residual.

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "sqdem/world/packing_measures.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

class RunLog {
 public:
  /// Creates (truncates) the file and writes the header for the world's walls, the plate (wall
  /// index) and the ledger; throws std::runtime_error if it cannot.
  RunLog(const std::filesystem::path& path, const World& world, std::optional<std::size_t> plate);
  /// Writes a row; returns the plate's measures it logged (with a plate).
  std::optional<PlateMeasures> row(const World& world, long step, const std::string& stage);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::optional<std::size_t> plate_;
};

}  // namespace sqdem

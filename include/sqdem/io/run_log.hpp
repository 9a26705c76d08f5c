#pragma once
// The CSV log of a run, one row written and flushed at a time (an interrupted run keeps its
// rows). Each column's name ends with its unit (_s, _J, _m, _N, _Nm, _Pa; none: a count or a
// ratio): time_s, step, stage, kinetic_energy_J, contacts, mean_coordination, solid_fraction,
// between_walls_solid_fraction (0 without a floor and a lid), bed_height_m,
// detector_failures, stress_xx_Pa ... stress_yz_Pa (Love-Weber, packing_measures.hpp), and per
// wall k the force the particles exert on it, wallk_fx_N, _fy_N, _fz_N, after its position: a
// plane's z (wallk_z_m), and for a plane along a coordinate axis its pressure wallk_p_Pa (the
// normal force over the box's cross-section, > 0 compressive); a cylinder's axis point or a
// mesh's origin x, y, z, followed by the
// torque about that point wallk_tx_Nm, _ty_Nm, _tz_Nm; yielded_fraction and
// largest_overlap_ratio (packing_measures.hpp); with a pressing plate
// (scene/compression_report.hpp) plate_gap_m, plate_pressure_Pa and porosity. With bonds
// (docs/bonds.md), the intact ones (bonds) and those broken since the start (bonds_broken). With
// an interaction that expects deep overlaps (`deep_overlaps: expected`), their contact-steps
// since the start (expected_deep_overlaps). With an energy
// ledger (world/energy_ledger.hpp), its terms since the start: work_bodies_J, work_gravity_J,
// elastic_energy_J (U now), plastic_dissipation_J, damping_dissipation_J,
// tangential_dissipation_J, drag_dissipation_J and energy_residual_J.

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
  /// index) and the ledger; throws std::runtime_error if it cannot. Across ranks rank 0 writes
  /// the file; every rank makes every row (its measures are reduced over the ranks).
  RunLog(const std::filesystem::path& path, const World& world, std::optional<std::size_t> plate);
  /// Writes a row; returns the plate's measures it logged (with a plate).
  std::optional<PlateMeasures> row(const World& world, long step, const std::string& stage);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::optional<std::size_t> plate_;
  bool bonds_ = false;  ///< the world's contacts may carry bonds
  bool expectedDeep_ = false;  ///< a contact model expects deep overlaps (ContactModel::deepOverlapsExpected)
};

}  // namespace sqdem

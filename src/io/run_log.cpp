#include "sqdem/io/run_log.hpp"

#include <stdexcept>

#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

/// A plane wall along a coordinate axis: it has a pressure column (its normal force over the
/// box's cross-section, World::wallArea).
bool alongAnAxis(const Wall& w) {
  return w.is<PlaneWall>() && w.get<PlaneWall>().plane.normal.cwiseAbs().maxCoeff() == 1.0;
}

bool expectsDeepOverlaps(const World& world) {
  const std::uint32_t n = static_cast<std::uint32_t>(world.materials().size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a; b < n; ++b) {
      if (world.contactModel(a, b).deepOverlapsExpected) return true;
    }
  }
  return false;
}

}  // namespace

RunLog::RunLog(const std::filesystem::path& path, const World& world, std::optional<std::size_t> plate)
    : path_(path), plate_(plate), bonds_(world.interactions().store().withBonds),
      expectedDeep_(expectsDeepOverlaps(world)) {
  if (world.communicator().rank() != 0) {
    out_.setstate(std::ios::badbit);  // the other ranks' rows go nowhere
    return;
  }
  out_.open(path, std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write '" + path.string() + "'");
  out_.precision(12);
  out_ << "time_s,step,stage,kinetic_energy_J,contacts,mean_coordination,solid_fraction,between_walls_solid_fraction,"
          "bed_height_m,detector_failures,stress_xx_Pa,stress_yy_Pa,stress_zz_Pa,stress_xy_Pa,stress_xz_Pa,stress_yz_Pa";
  const std::vector<Wall>& walls = world.walls();
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const std::string name = ",wall" + std::to_string(w);
    if (!walls[w].is<PlaneWall>()) out_ << name << "_x_m" << name << "_y_m";
    out_ << name << "_z_m" << name << "_fx_N" << name << "_fy_N" << name << "_fz_N";
    if (alongAnAxis(walls[w])) out_ << name << "_p_Pa";
    if (!walls[w].is<PlaneWall>()) out_ << name << "_tx_Nm" << name << "_ty_Nm" << name << "_tz_Nm";
  }
  out_ << ",yielded_fraction,largest_overlap_ratio";
  if (plate_) out_ << ",plate_gap_m,plate_pressure_Pa,porosity";
  if (bonds_) out_ << ",bonds,bonds_broken";
  if (expectedDeep_) out_ << ",expected_deep_overlaps";
  if (world.energyLedger()) {
    out_ << ",work_bodies_J,work_gravity_J,elastic_energy_J,plastic_dissipation_J,damping_dissipation_J,tangential_dissipation_J"
            ",drag_dissipation_J,energy_residual_J";
    if (bonds_) out_ << ",bond_energy_J,bond_dissipation_J";
  }
  out_ << std::endl;
}

std::optional<PlateMeasures> RunLog::row(const World& world, long step, const std::string& stage) {
  const PackingMeasures m = measurePacking(world);
  out_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ','
       << world.communicator().sum(static_cast<long long>(world.contacts().size()))
       << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.betweenWallsFraction << ',' << m.bedHeight << ','
       << world.totalStatistics().detectorFailures;
  for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) out_ << ',' << m.stress(i, j);
  for (std::size_t k = 0; k < world.walls().size(); ++k) {
    const Wall& w = world.walls()[k];
    const Vec3& x = w.reference();
    if (!w.is<PlaneWall>()) out_ << ',' << x.x() << ',' << x.y();
    out_ << ',' << x.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
    if (alongAnAxis(w)) out_ << ',' << -w.force.dot(w.get<PlaneWall>().plane.normal) / world.wallArea(k);
    if (!w.is<PlaneWall>()) out_ << ',' << w.torque.x() << ',' << w.torque.y() << ',' << w.torque.z();
  }
  out_ << ',' << m.yieldedFraction << ',' << m.largestOverlapRatio;
  std::optional<PlateMeasures> plate;
  if (plate_) {
    plate = measurePlate(world, *plate_);
    out_ << ',' << plate->gap << ',' << plate->pressure << ',' << plate->porosity;
  }
  if (bonds_) out_ << ',' << world.bondCount() << ',' << world.totalStatistics().bondsBroken;
  if (expectedDeep_) out_ << ',' << world.totalStatistics().expectedDeepOverlaps;
  if (const auto& e = world.energyLedger()) {
    out_ << ',' << e->bodies << ',' << e->gravity << ',' << e->stored << ',' << e->plastic() << ',' << e->damping << ','
         << e->tangential << ',' << e->drag << ',' << e->residual(world.kineticEnergy());
    if (bonds_) out_ << ',' << e->bondStored << ',' << e->bondDissipation();
  }
  out_ << std::endl;
  return plate;
}

}  // namespace sqdem

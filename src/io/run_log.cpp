#include "sqdem/io/run_log.hpp"

#include <cmath>
#include <stdexcept>

#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

/// The box's cross-section a plane wall along a coordinate axis presses on (m^2); nothing for
/// other walls.
std::optional<double> planeArea(const Wall& w, const Domain& box) {
  if (w.shape != WallShape::Plane) return std::nullopt;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(w.plane.normal[axis]) == 1.0) {
      const Vec3 extent = box.hi - box.lo;
      return extent[(axis + 1) % 3] * extent[(axis + 2) % 3];
    }
  }
  return std::nullopt;
}

}  // namespace

RunLog::RunLog(const std::filesystem::path& path, const World& world, std::optional<std::size_t> plate)
    : path_(path), out_(path, std::ios::trunc), plate_(plate) {
  if (!out_) throw std::runtime_error("cannot write '" + path.string() + "'");
  out_.precision(12);
  out_ << "time_s,step,stage,kinetic_energy_J,contacts,mean_coordination,solid_fraction,between_walls_solid_fraction,"
          "bed_height_m,detector_failures,stress_xx_Pa,stress_yy_Pa,stress_zz_Pa,stress_xy_Pa,stress_xz_Pa,stress_yz_Pa";
  const std::vector<Wall>& walls = world.walls();
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const std::string name = ",wall" + std::to_string(w);
    if (walls[w].shape != WallShape::Plane) out_ << name << "_x_m" << name << "_y_m";
    out_ << name << "_z_m" << name << "_fx_N" << name << "_fy_N" << name << "_fz_N";
    if (planeArea(walls[w], world.domain())) out_ << name << "_p_Pa";
    if (walls[w].shape != WallShape::Plane) out_ << name << "_tx_Nm" << name << "_ty_Nm" << name << "_tz_Nm";
  }
  out_ << ",yielded_fraction,largest_overlap_ratio";
  if (plate_) out_ << ",plate_gap_m,plate_pressure_Pa,porosity";
  if (world.energyLedger()) {
    out_ << ",work_bodies_J,work_gravity_J,elastic_energy_J,plastic_dissipation_J,damping_dissipation_J,tangential_dissipation_J"
            ",drag_dissipation_J,energy_residual_J";
  }
  out_ << std::endl;
}

std::optional<PlateMeasures> RunLog::row(const World& world, long step, const std::string& stage) {
  const PackingMeasures m = measurePacking(world);
  out_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ',' << world.contacts().size()
       << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.betweenWallsFraction << ',' << m.bedHeight << ','
       << world.statistics().detectorFailures;
  for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) out_ << ',' << m.stress(i, j);
  for (const Wall& w : world.walls()) {
    const Vec3& x = w.reference();
    if (w.shape != WallShape::Plane) out_ << ',' << x.x() << ',' << x.y();
    out_ << ',' << x.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
    if (const std::optional<double> area = planeArea(w, world.domain())) out_ << ',' << -w.force.dot(w.plane.normal) / *area;
    if (w.shape != WallShape::Plane) out_ << ',' << w.torque.x() << ',' << w.torque.y() << ',' << w.torque.z();
  }
  out_ << ',' << m.yieldedFraction << ',' << m.largestOverlapRatio;
  std::optional<PlateMeasures> plate;
  if (plate_) {
    plate = measurePlate(world, *plate_);
    out_ << ',' << plate->gap << ',' << plate->pressure << ',' << plate->porosity;
  }
  if (const auto& e = world.energyLedger()) {
    out_ << ',' << e->bodies << ',' << e->gravity << ',' << e->stored << ',' << e->plastic() << ',' << e->damping << ','
         << e->tangential << ',' << e->drag << ',' << e->residual(world.kineticEnergy());
  }
  out_ << std::endl;
  return plate;
}

}  // namespace sqdem

#include "sqdem/io/run_log.hpp"

#include <stdexcept>

#include "sqdem/world/packing_measures.hpp"

namespace sqdem {

RunLog::RunLog(const std::filesystem::path& path, const World& world, std::optional<std::size_t> plate)
    : path_(path), out_(path, std::ios::trunc), plate_(plate) {
  if (!out_) throw std::runtime_error("cannot write '" + path.string() + "'");
  out_.precision(12);
  out_ << "time,step,stage,kinetic_energy,contacts,mean_coordination,solid_fraction,bed_height,detector_failures"
          ",stress_xx,stress_yy,stress_zz,stress_xy,stress_xz,stress_yz";
  const std::vector<Wall>& walls = world.walls();
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const std::string name = ",wall" + std::to_string(w);
    if (walls[w].shape != WallShape::Plane) out_ << name << "_x" << name << "_y";
    out_ << name << "_z" << name << "_fx" << name << "_fy" << name << "_fz";
    if (walls[w].shape != WallShape::Plane) out_ << name << "_tx" << name << "_ty" << name << "_tz";
  }
  out_ << ",yielded_fraction,largest_overlap_ratio";
  if (plate_) out_ << ",plate_gap,plate_pressure,porosity";
  if (world.energyLedger()) {
    out_ << ",work_bodies,work_gravity,elastic_energy,plastic_dissipation,damping_dissipation,tangential_dissipation"
            ",drag_dissipation,energy_residual";
  }
  out_ << std::endl;
}

std::optional<PlateMeasures> RunLog::row(const World& world, long step, const std::string& stage) {
  const PackingMeasures m = measurePacking(world);
  out_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ',' << world.contacts().size()
       << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.bedHeight << ','
       << world.statistics().detectorFailures;
  for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) out_ << ',' << m.stress(i, j);
  for (const Wall& w : world.walls()) {
    const Vec3& x = w.reference();
    if (w.shape != WallShape::Plane) out_ << ',' << x.x() << ',' << x.y();
    out_ << ',' << x.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
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

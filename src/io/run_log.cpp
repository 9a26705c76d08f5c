#include "sqdem/io/run_log.hpp"

#include <stdexcept>

#include "sqdem/world/packing_measures.hpp"

namespace sqdem {

RunLog::RunLog(const std::filesystem::path& path, std::size_t walls) : path_(path), out_(path, std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot write '" + path.string() + "'");
  out_.precision(12);
  out_ << "time,step,stage,kinetic_energy,contacts,mean_coordination,solid_fraction,bed_height,detector_failures"
          ",stress_xx,stress_yy,stress_zz,stress_xy,stress_xz,stress_yz";
  for (std::size_t w = 0; w < walls; ++w) out_ << ",wall" << w << "_z,wall" << w << "_fx,wall" << w << "_fy,wall" << w << "_fz";
  out_ << std::endl;
}

void RunLog::row(const World& world, long step, const std::string& stage) {
  const PackingMeasures m = measurePacking(world);
  out_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ',' << world.contacts().size()
       << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.bedHeight << ','
       << world.statistics().detectorFailures;
  for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) out_ << ',' << m.stress(i, j);
  for (const Wall& w : world.walls()) {
    out_ << ',' << w.plane.point.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
  }
  out_ << std::endl;
}

}  // namespace sqdem

#include "sqdem/scene/particle_edits.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sqdem {
namespace {

/// Checks rows of k finite values, one per owned particle.
void checkRows(const Simulation& simulation, std::span<const double> rows, std::size_t k, const char* field) {
  const std::size_t n = simulation.world().particles().size();
  if (rows.size() != n * k) {
    throw std::invalid_argument(std::string(field) + ": expected " + std::to_string(n) + " rows of " + std::to_string(k) +
                                " values (this process's particles), got " + std::to_string(rows.size()) + " values");
  }
  for (std::size_t v = 0; v < rows.size(); ++v) {
    if (!std::isfinite(rows[v])) {
      throw std::invalid_argument(std::string(field) + ": row " + std::to_string(v / k) + " is not finite");
    }
  }
}

Vec3 row3(std::span<const double> rows, std::size_t i) { return {rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]}; }

}  // namespace

void setPositions(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 3, "position");
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = row3(rows, i);
  });
}

void setVelocities(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 3, "velocity");
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.velocity[i] = row3(rows, i);
  });
}

void setOrientations(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 4, "orientation");
  const auto norm = [&](std::size_t i) {  // without under- or overflow
    return std::hypot(std::hypot(rows[4 * i], rows[4 * i + 1]), std::hypot(rows[4 * i + 2], rows[4 * i + 3]));
  };
  for (std::size_t i = 0; 4 * i < rows.size(); ++i) {
    if (!(norm(i) > 0.0)) throw std::invalid_argument("orientation: row " + std::to_string(i) + " is the zero quaternion");
  }
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 spin = p.angularVelocity[i];
      const double s = norm(i);
      p.orientation[i] = Quat(rows[4 * i + 3] / s, rows[4 * i] / s, rows[4 * i + 1] / s, rows[4 * i + 2] / s);
      p.setAngularVelocity(i, spin);
    }
  });
}

void setAngularVelocities(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 3, "angular_velocity");
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.setAngularVelocity(i, row3(rows, i));
  });
}

}  // namespace sqdem

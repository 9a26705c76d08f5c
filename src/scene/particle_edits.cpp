#include "sqdem/scene/particle_edits.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "sqdem/distributed/agreed.hpp"

namespace sqdem {
namespace {

/// Checks rows of k finite values, one per owned particle, and then each row by `row(i)`; every
/// rank throws when any rank's rows fail (the lowest failing rank's message).
template <typename RowCheck>
void checkRows(const Simulation& simulation, std::span<const double> rows, std::size_t k, const char* field, RowCheck&& row) {
  agreed<std::invalid_argument>(simulation.world().communicator(), [&] {
    const std::size_t n = simulation.world().particles().size();
    if (rows.size() != n * k) {
      throw std::invalid_argument(std::string(field) + ": expected " + std::to_string(n) + " rows of " + std::to_string(k) +
                                  " values (this process's particles), got " + std::to_string(rows.size()) + " values");
    }
    for (std::size_t v = 0; v < rows.size(); ++v) {
      if (!std::isfinite(rows[v])) throw std::invalid_argument(std::string(field) + ": row " + std::to_string(v / k) + " is not finite");
    }
    for (std::size_t i = 0; i < n; ++i) row(i);
  });
}

Vec3 row3(std::span<const double> rows, std::size_t i) { return {rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]}; }

/// |q| of row i without under- or overflow.
double quaternionNorm(std::span<const double> rows, std::size_t i) {
  return std::hypot(std::hypot(rows[4 * i], rows[4 * i + 1]), std::hypot(rows[4 * i + 2], rows[4 * i + 3]));
}

}  // namespace

void setPositions(Simulation& simulation, std::span<const double> rows) {
  const Domain& domain = simulation.world().domain();
  checkRows(simulation, rows, 3, "position", [&](std::size_t i) {
    if (const int d = domain.outsideAlong(row3(rows, i)); d >= 0) {
      char bounds[96];
      std::snprintf(bounds, sizeof bounds, "[%.6g, %.6g] m", domain.lo(d), domain.hi(d));
      throw std::invalid_argument("position: row " + std::to_string(i) + " lies outside the domain along " + "xyz"[d] +
                                  " (not periodic: " + bounds + ")");
    }
  });
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = row3(rows, i);
  });
}

void setVelocities(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 3, "velocity", [](std::size_t) {});
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.velocity[i] = row3(rows, i);
  });
}

void setOrientations(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 4, "orientation", [&](std::size_t i) {
    if (!(quaternionNorm(rows, i) > 0.0)) throw std::invalid_argument("orientation: row " + std::to_string(i) + " is the zero quaternion");
  });
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 spin = p.angularVelocity[i];
      const double s = quaternionNorm(rows, i);
      p.orientation[i] = Quat(rows[4 * i + 3] / s, rows[4 * i] / s, rows[4 * i + 1] / s, rows[4 * i + 2] / s);
      p.setAngularVelocity(i, spin);
    }
  });
}

void setAngularVelocities(Simulation& simulation, std::span<const double> rows) {
  checkRows(simulation, rows, 3, "angular_velocity", [](std::size_t) {});
  simulation.editParticles([&](ParticleStore& p) {
    for (std::size_t i = 0; i < p.size(); ++i) p.setAngularVelocity(i, row3(rows, i));
  });
}

}  // namespace sqdem

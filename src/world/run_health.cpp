#include "sqdem/world/run_health.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sqdem {
namespace {

bool finiteState(const ParticleStore& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !p.conjugateMomentum[i].allFinite() ||
        !p.force[i].allFinite() || !p.torque[i].allFinite()) {
      return false;
    }
  }
  return true;
}

/// Adds the elastic energy of the contacts, 2/5 F_n delta each (Hertz), to `sum`.
void addElasticEnergy(ExactSum& sum, const World& world) {
  for (const ContactView c : world.contacts()) sum.add(0.4 * std::abs(c.force().dot(c.normal())) * std::max(0.0, c.overlap()));
}

}  // namespace

RunHealth::RunHealth(const World& world) {
  const ParticleStore& p = world.particles();
  const Vec3 g = world.gravity();
  const double fall = g.norm() > 0.0 ? (world.domain().length().cwiseProduct(g.cwiseAbs() / g.norm())).sum() : 0.0;
  ExactSum budget;
  for (std::size_t i = 0; i < p.size(); ++i) budget.add(p.mass[i] * (g.norm() * fall + 0.5));
  addElasticEnergy(budget, world);
  budget_ = world.kineticEnergy() + world.communicator().sum(budget);
}

std::string RunHealth::afterStep(const World& world) {
  if (elasticPending_) {
    ExactSum elastic;
    addElasticEnergy(elastic, world);
    budget_ += world.communicator().sum(elastic);
    elasticPending_ = false;
  }
  for (const Wall& w : world.walls()) {
    wallWork_ += (std::abs(w.force.dot(w.velocity)) + std::abs(w.torque.dot(w.angularVelocity))) * world.timeStep();
  }
  if (++steps_ % checkEvery != 0) return {};
  char text[256];
  const double energy = world.kineticEnergy();
  if (world.communicator().any(!finiteState(world.particles())) || !std::isfinite(energy)) {
    return "non-finite particle state (NaN or inf in positions, velocities or forces)";
  }
  if (energy > 10.0 * budget()) {
    std::snprintf(text, sizeof text, "runaway energy: E_kin = %.3g J exceeds 10 x the %.3g J the initial state, gravity "
                  "and walls can supply", energy, budget());
    return text;
  }
  const long long deep = world.communicator().sum(world.statistics().deepOverlaps);
  deepStreak_ = deep > lastDeepOverlaps_ ? deepStreak_ + 1 : 0;
  lastDeepOverlaps_ = deep;
  if (deepStreak_ >= 10) {
    std::snprintf(text, sizeof text, "deep overlaps (deeper than half the smaller volume radius) keep growing: %lld so far", deep);
    return text;
  }
  return {};
}

}  // namespace sqdem

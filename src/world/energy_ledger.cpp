#include "sqdem/world/energy_ledger.hpp"

#include "sqdem/world/world.hpp"

namespace sqdem {

void EnergyLedger::start(const World& world) {
  *this = {};
  started = true;
  initialKinetic = world.kineticEnergy();
  initialStored = stored = world.interactions().energy().stored;
}

void EnergyLedger::addStep(const World& world, const std::vector<Wall>& before) {
  const double dt = world.timeStep();
  const ParticleStore& p = world.particles();
  Vec3 momentum = Vec3::Zero();
  double twiceKinetic = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    momentum += p.mass[i] * p.velocity[i];
    twiceKinetic += p.mass[i] * p.velocity[i].squaredNorm();
  }
  gravity += dt * world.gravity().dot(momentum);
  drag += dt * world.viscousDamping() * twiceKinetic;
  for (std::size_t w = 0; w < before.size(); ++w) {
    const Wall& now = world.walls()[w];
    bodies -= 0.5 * dt * ((before[w].force + now.force).dot(now.velocity) + (before[w].torque + now.torque).dot(now.angularVelocity));
  }
  const ContactEnergy contacts = world.interactions().energy();
  normal += contacts.normal;
  damping += contacts.damping;
  tangential += contacts.tangential;
  stored = contacts.stored;
}

}  // namespace sqdem

#include "sqdem/world/energy_ledger.hpp"

#include "sqdem/world/world.hpp"

namespace sqdem {

void EnergyLedger::start(const World& world) {
  *this = {};
  started = true;
  initialKinetic = world.kineticEnergy();
  std::array<ExactSum, 6> contacts = world.interactions().energy();
  world.communicator().sum(contacts);
  initialStored = stored = contacts[0].value();
  initialBondStored = bondStored = contacts[4].value();
}

void EnergyLedger::addStep(const World& world, const std::vector<Wall>& before) {
  const double dt = world.timeStep();
  const ParticleStore& p = world.particles();
  std::array<ExactSum, 4> particles;  // the momentum's components, twice the translational energy
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 momentum = p.mass[i] * p.velocity[i];
    for (int d = 0; d < 3; ++d) particles[d].add(momentum(d));
    particles[3].add(p.mass[i] * p.velocity[i].squaredNorm());
  }
  world.communicator().sum(particles);
  const Vec3 momentum(particles[0].value(), particles[1].value(), particles[2].value());
  gravity += dt * world.gravity().dot(momentum);
  drag += dt * world.viscousDamping() * particles[3].value();
  for (std::size_t w = 0; w < before.size(); ++w) {
    const Wall& now = world.walls()[w];
    bodies -= 0.5 * dt * ((before[w].force + now.force).dot(now.velocity) + (before[w].torque + now.torque).dot(now.angularVelocity));
  }
  std::array<ExactSum, 6> contacts = world.interactions().energy();  // stored, normal, damping, tangential, bond's stored, bond's
  world.communicator().sum(contacts);
  stored = contacts[0].value();
  normal += contacts[1].value();
  damping += contacts[2].value();
  tangential += contacts[3].value();
  bondStored = contacts[4].value();
  bonds += contacts[5].value();
}

}  // namespace sqdem

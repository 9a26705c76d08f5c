#include "sqdem/dynamics/particle_store.hpp"

#include <stdexcept>

namespace sqdem {

std::size_t ParticleStore::add(std::uint32_t shapeIndex, std::uint32_t materialIndex, const Vec3& centre,
                               const Quat& q, double particleMass, const Vec3& principalInertia, double bound) {
  if (ghostCount != 0) throw std::logic_error("ParticleStore: particles are added before ghosts are made");
  id.push_back(static_cast<std::uint32_t>(size()));
  shape.push_back(shapeIndex);
  material.push_back(materialIndex);
  position.push_back(centre);
  orientation.push_back(q.normalized());
  velocity.push_back(Vec3::Zero());
  conjugateMomentum.push_back(Vec4::Zero());
  angularVelocity.push_back(Vec3::Zero());
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  mass.push_back(particleMass);
  inertia.push_back(principalInertia);
  boundingRadius.push_back(bound);
  speedBound.push_back(0.0);
  return size() - 1;
}

void ParticleStore::setAngularVelocity(std::size_t i, const Vec3& omegaWorld) {
  const Quat& q = orientation[i];
  const Vec3 L = inertia[i].cwiseProduct(q.conjugate() * omegaWorld);
  conjugateMomentum[i] = 2.0 * asVector(q * Quat(0.0, L.x(), L.y(), L.z()));
  angularVelocity[i] = omegaWorld;
}

Vec3 ParticleStore::bodyAngularMomentum(std::size_t i) const {
  return 0.5 * (orientation[i].conjugate() * asQuat(conjugateMomentum[i])).vec();
}

void ParticleStore::updateAngularVelocity(std::size_t i) {
  angularVelocity[i] = orientation[i] * bodyAngularMomentum(i).cwiseQuotient(inertia[i]);
}

double ParticleStore::rotationalEnergy(std::size_t i) const {
  const Vec3 L = bodyAngularMomentum(i);
  return 0.5 * L.cwiseProduct(L).cwiseQuotient(inertia[i]).sum();
}

}  // namespace sqdem

#include "sqdem/dynamics/integrator.hpp"

#include <cmath>

namespace sqdem {
namespace {

/// P_k v = v ⊗ e_k for v = (w, x, y, z), k = 1, 2, 3 (Miller Eq. 2.7).
Vec4 permute(int k, const Vec4& v) {
  switch (k) {
    case 1: return {-v(1), v(0), v(3), -v(2)};
    case 2: return {-v(2), -v(3), v(0), v(1)};
    default: return {-v(3), v(2), -v(1), v(0)};
  }
}

/// Exact flow R_k(t) of H_k = (p · P_k q)^2 / (8 I_k).
void freeRotation(int k, double t, double inertia, Vec4& q, Vec4& p) {
  const Vec4 Pq = permute(k, q);
  const double zeta = t * p.dot(Pq) / (4.0 * inertia);
  const double c = std::cos(zeta), s = std::sin(zeta);
  const Vec4 Pp = permute(k, p);
  q = c * q + s * Pq;
  p = c * p + s * Pp;
}

}  // namespace

void kick(ParticleStore& particles, std::size_t i, double halfStep) {
  particles.velocity[i] += halfStep / particles.mass[i] * particles.force[i];
  const Quat& q = particles.orientation[i];
  const Vec3 tauBody = q.conjugate() * particles.torque[i];
  const Quat qt = q * Quat(0.0, tauBody.x(), tauBody.y(), tauBody.z());
  particles.conjugateMomentum[i] += 2.0 * halfStep * Vec4(qt.w(), qt.x(), qt.y(), qt.z());
  particles.updateAngularVelocity(i);
}

void drift(ParticleStore& particles, std::size_t i, double step) {
  particles.position[i] += step * particles.velocity[i];
  const Vec3& I = particles.inertia[i];
  if (I.x() == I.y() && I.y() == I.z()) {
    // Isotropic body (a sphere): the free rotor's exact flow is a uniform rotation about the
    // constant world angular velocity; the body angular momentum does not change.
    const Vec3 w = particles.angularVelocity[i];
    const double rate = w.norm();
    if (rate > 0.0) {
      particles.orientation[i] = (Quat(Eigen::AngleAxisd(rate * step, w / rate)) * particles.orientation[i]).normalized();
      particles.setAngularVelocity(i, w);
    }
    return;
  }
  const Quat& orientation = particles.orientation[i];
  Vec4 q(orientation.w(), orientation.x(), orientation.y(), orientation.z());
  Vec4& p = particles.conjugateMomentum[i];
  freeRotation(3, 0.5 * step, I.z(), q, p);
  freeRotation(2, 0.5 * step, I.y(), q, p);
  freeRotation(1, step, I.x(), q, p);
  freeRotation(2, 0.5 * step, I.y(), q, p);
  freeRotation(3, 0.5 * step, I.z(), q, p);
  particles.orientation[i] = Quat(q(0), q(1), q(2), q(3)).normalized();
  particles.updateAngularVelocity(i);
}

}  // namespace sqdem

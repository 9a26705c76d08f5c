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

/// I1 = I2 = I3: the world angular momentum L = vec(p ⊗ q*) / 2 is the body's (p = 2 q ⊗ (0, L_body)
/// = 2 (0, L) ⊗ q), so the kick and the free rotor need no rotation into the body frame.
bool isotropic(const Vec3& I) { return I.x() == I.y() && I.y() == I.z(); }

}  // namespace

void kick(ParticleStore& particles, std::size_t i, double halfStep) {
  particles.velocity[i] += halfStep / particles.mass[i] * particles.force[i];
  const Quat& q = particles.orientation[i];
  const Vec3& tau = particles.torque[i];
  const Vec3& I = particles.inertia[i];
  Vec4& p = particles.conjugateMomentum[i];
  if (isotropic(I)) {  // p += h 2 (0, tau) ⊗ q, w = L / I
    p += 2.0 * halfStep * asVector(Quat(0.0, tau.x(), tau.y(), tau.z()) * q);
    particles.angularVelocity[i] = 0.5 / I.x() * (asQuat(p) * q.conjugate()).vec();
    return;
  }
  const Vec3 tauBody = q.conjugate() * tau;
  p += 2.0 * halfStep * asVector(q * Quat(0.0, tauBody.x(), tauBody.y(), tauBody.z()));
  particles.updateAngularVelocity(i);
}

void drift(ParticleStore& particles, std::size_t i, double step, bool turns) {
  particles.position[i] += step * particles.velocity[i];
  if (!turns) return;
  const Vec3& I = particles.inertia[i];
  Vec4& p = particles.conjugateMomentum[i];
  if (isotropic(I)) {
    // The free rotor's exact flow: a uniform rotation r by |w| h about the constant world angular
    // velocity w; r commutes with (0, L), so p = 2 (0, L) ⊗ q turns into r ⊗ p.
    const Vec3& w = particles.angularVelocity[i];
    const double rate = w.norm();
    if (rate > 0.0) {
      const Quat r(Eigen::AngleAxisd(rate * step, w / rate));
      particles.orientation[i] = (r * particles.orientation[i]).normalized();
      p = asVector(r * asQuat(p));
    }
    return;
  }
  const Quat& orientation = particles.orientation[i];
  Vec4 q = asVector(orientation);
  freeRotation(3, 0.5 * step, I.z(), q, p);
  freeRotation(2, 0.5 * step, I.y(), q, p);
  freeRotation(1, step, I.x(), q, p);
  freeRotation(2, 0.5 * step, I.y(), q, p);
  freeRotation(3, 0.5 * step, I.z(), q, p);
  particles.orientation[i] = asQuat(q).normalized();
  particles.updateAngularVelocity(i);
}

}  // namespace sqdem

// Rigid-body integration (dynamics/integrator.hpp): NO_SQUISH on a free asymmetric top
// (Miller et al. 2002): bounded energy error, conserved world angular momentum, unit
// quaternions, and the intermediate-axis (Dzhanibekov) flip; velocity Verlet on a free fall; a
// sphere that does not turn.

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "sqdem/dynamics/integrator.hpp"

namespace sqdem {
namespace {

double energy(const ParticleStore& p) { return p.translationalEnergy(0) + p.rotationalEnergy(0); }
Vec3 worldAngularMomentum(const ParticleStore& p) { return p.orientation[0] * p.bodyAngularMomentum(0); }

TEST(RigidBody, FreeAsymmetricTopConservesEnergyAndAngularMomentumAndFlips) {
  ParticleStore p;
  p.add(0, 0, Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())), 1.0, Vec3(1.0, 3.0, 5.0), 1.0);
  // Spin about the intermediate axis with a small perturbation: unstable, flips periodically.
  p.setAngularVelocity(0, p.orientation[0] * Vec3(0.1, 2.0, 0.1));
  const double E0 = energy(p);
  const Vec3 L0 = worldAngularMomentum(p);
  const double h = 1e-4;
  int flips = 0;
  double previousSign = p.bodyAngularMomentum(0).y() > 0.0 ? 1.0 : -1.0;
  double maxEnergyError = 0.0, maxMomentumError = 0.0, maxNormError = 0.0;
  for (int step = 0; step < 100000; ++step) {
    kick(p, 0, 0.5 * h);
    drift(p, 0, h);
    kick(p, 0, 0.5 * h);
    maxEnergyError = std::max(maxEnergyError, std::abs(energy(p) - E0) / E0);
    maxMomentumError = std::max(maxMomentumError, (worldAngularMomentum(p) - L0).norm() / L0.norm());
    maxNormError = std::max(maxNormError, std::abs(p.orientation[0].norm() - 1.0));
    const double sign = p.bodyAngularMomentum(0).y() > 0.0 ? 1.0 : -1.0;
    if (sign != previousSign) ++flips;
    previousSign = sign;
  }
  std::printf("relative energy error %.3g, angular momentum error %.3g, flips %d\n", maxEnergyError,
              maxMomentumError, flips);
  EXPECT_LT(maxEnergyError, 1e-8);
  EXPECT_LT(maxMomentumError, 1e-8);
  EXPECT_LT(maxNormError, 1e-14);
  EXPECT_GE(flips, 2);  // the body's intermediate-axis momentum reverses and comes back
}

// Euler's equations I dw/dt = (I w) x w in the body frame, integrated by RK4 with the same step,
// give the same body angular velocity (the scheme rotates about the right axes).
TEST(RigidBody, FreeRotationFollowsEulersEquations) {
  const Vec3 I(1.0, 2.0, 3.0);
  ParticleStore p;
  p.add(0, 0, Vec3::Zero(), Quat::Identity(), 1.0, I, 1.0);
  Vec3 w(0.1, 2.0, 0.1);
  p.setAngularVelocity(0, w);
  const auto rate = [&](const Vec3& v) { return I.cwiseProduct(v).cross(v).cwiseQuotient(I).eval(); };
  const double h = 1e-4;
  for (int step = 0; step < 50000; ++step) {  // through the first flip (t = 5)
    kick(p, 0, 0.5 * h);
    drift(p, 0, h);
    kick(p, 0, 0.5 * h);
    const Vec3 k1 = rate(w), k2 = rate(w + 0.5 * h * k1), k3 = rate(w + 0.5 * h * k2), k4 = rate(w + h * k3);
    w += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  const Vec3 wBody = p.bodyAngularMomentum(0).cwiseQuotient(I);
  EXPECT_LT(w.y(), -1.0);  // flipped
  EXPECT_LT((wBody - w).norm(), 1e-5 * w.norm());
}

// A free spinning sphere (isotropic inertia) turns uniformly about its constant angular
// velocity: after t its orientation is the rotation by |w| t about w (closed form).
TEST(RigidBody, FreeSphereRotatesUniformly) {
  ParticleStore p;
  p.add(0, 0, Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY())), 1.0, Vec3::Constant(0.4), 1.0);
  const Vec3 w(1.0, -2.0, 0.5);
  p.setAngularVelocity(0, w);
  const double h = 1e-3;
  const int steps = 10000;
  for (int step = 0; step < steps; ++step) {
    p.torque[0].setZero();
    kick(p, 0, 0.5 * h);
    drift(p, 0, h);
    kick(p, 0, 0.5 * h);
  }
  const Quat expected = Quat(Eigen::AngleAxisd(w.norm() * h * steps, w.normalized())) * Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  EXPECT_LT(p.orientation[0].angularDistance(expected), 1e-10);
  EXPECT_LT((p.angularVelocity[0] - w).norm(), 1e-12 * w.norm());
}

// A sphere that does not turn (World::setSphereOrientations(false)) keeps its orientation, and
// its angular velocity under a torque that turns in space is the turning sphere's to round-off:
// p = 2 (0, L) ⊗ q holds for any fixed q, so the kicks integrate L exactly either way
// (closed form: L(t) = L0 + integral of the torque).
TEST(RigidBody, SphereThatDoesNotTurnKeepsItsOrientationAndItsSpin) {
  const Quat q0(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  ParticleStore turning, fixed;
  for (ParticleStore* p : {&turning, &fixed}) {
    p->add(0, 0, Vec3::Zero(), q0, 1.0, Vec3::Constant(0.4), 1.0);
    p->setAngularVelocity(0, Vec3(1.0, -2.0, 0.5));
  }
  const Vec4 start = asVector(fixed.orientation[0]);
  const double h = 1e-3;
  const int steps = 10000;
  const auto torque = [](double t) { return Vec3(std::cos(3.0 * t), std::sin(3.0 * t), 0.2); };
  for (int step = 0; step < steps; ++step) {
    for (auto [p, turns] : {std::pair{&turning, true}, std::pair{&fixed, false}}) {
      p->torque[0] = torque(step * h);
      kick(*p, 0, 0.5 * h);
      drift(*p, 0, h, turns);
      p->torque[0] = torque((step + 1) * h);
      kick(*p, 0, 0.5 * h);
    }
  }
  EXPECT_EQ(asVector(fixed.orientation[0]), start);
  EXPECT_GT(turning.orientation[0].angularDistance(q0), 0.1);
  const Vec3 w = fixed.angularVelocity[0];
  EXPECT_LT((w - turning.angularVelocity[0]).norm(), 1e-12 * w.norm());
  // L(t) = L0 + integral_0^t torque, by the trapezoidal kicks to O(h^2) of the closed form.
  const double t = steps * h;
  const Vec3 L = 0.4 * Vec3(1.0, -2.0, 0.5) + Vec3(std::sin(3.0 * t) / 3.0, (1.0 - std::cos(3.0 * t)) / 3.0, 0.2 * t);
  EXPECT_LT((0.4 * w - L).norm(), 1e-6 * L.norm());
}

TEST(RigidBody, VelocityVerletIsExactForConstantForce) {
  ParticleStore p;
  p.add(0, 0, Vec3::Zero(), Quat::Identity(), 2.0, Vec3::Ones(), 1.0);
  p.velocity[0] = Vec3(1.0, 0.0, 3.0);
  const Vec3 g(0.0, 0.0, -9.81);
  const double h = 1e-3;
  for (int step = 0; step < 1000; ++step) {
    p.force[0] = p.mass[0] * g;
    kick(p, 0, 0.5 * h);
    drift(p, 0, h);
    kick(p, 0, 0.5 * h);
  }
  const Vec3 expected = Vec3(1.0, 0.0, 3.0) + 0.5 * g;  // t = 1 s: x = v0 t + g t^2 / 2
  EXPECT_LT((p.position[0] - expected).norm(), 1e-12);
}

}  // namespace
}  // namespace sqdem

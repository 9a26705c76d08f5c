// The World's step loop (world/world.hpp) on collisions with closed-form expectations.

#include <gtest/gtest.h>

#include <cmath>

#include "sqdem/world/packing_measures.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

Domain bigBox() {
  Domain d;
  d.lo = Vec3::Constant(-0.1);
  d.hi = Vec3::Constant(0.1);
  return d;
}

Vec3 linearMomentum(const ParticleStore& p) {
  Vec3 P = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) P += p.mass[i] * p.velocity[i];
  return P;
}

Vec3 angularMomentum(const ParticleStore& p) {
  Vec3 L = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    L += p.mass[i] * p.position[i].cross(p.velocity[i]) + p.orientation[i] * p.bodyAngularMomentum(i);
  }
  return L;
}

struct CollisionErrors {
  double energy, momentum, angularMomentum;  // relative to the initial values / m v / m v L
};

// Two 1.5 x 1 x 0.8 mm ellipsoids collide without damping or friction.
CollisionErrors collide(NormalLaw normal, bool oblique) {
  const Material m{1e7, 0.3, 1000.0, 0.0, 1.0};
  World world({Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3)}, {m}, bigBox(), 2e-4);
  ContactModel law = world.defaultContactModel(0, 0);
  law.eccentricity = EccentricityMethod::Exact;
  law.normal = normal;
  world.setContactModel(0, 0, law);
  if (oblique) {  // off-centre, rotated bodies, one spinning
    world.addParticle(0, 0, Vec3(-2e-3, 0.3e-3, 0.0), Quat(Eigen::AngleAxisd(0.4, Vec3(0, 0, 1))));
    world.addParticle(0, 0, Vec3(2e-3, -0.2e-3, 0.1e-3), Quat(Eigen::AngleAxisd(1.0, Vec3(1, 1, 0).normalized())));
    world.particles().velocity[1] = Vec3(-0.5, 0.05, 0.0);
    world.particles().setAngularVelocity(1, Vec3(0.0, 0.0, 20.0));
  } else {  // head-on at the x tips: the contact curvature stays constant
    world.addParticle(0, 0, Vec3(-2e-3, 0.0, 0.0), Quat::Identity());
    world.addParticle(0, 0, Vec3(2e-3, 0.0, 0.0), Quat::Identity());
    world.particles().velocity[1] = Vec3(-0.5, 0.0, 0.0);
  }
  world.particles().velocity[0] = Vec3(0.5, 0.0, 0.0);
  world.setTimeStep(1e-7);
  const double E0 = world.kineticEnergy();
  const Vec3 P0 = linearMomentum(world.particles()), L0 = angularMomentum(world.particles());
  bool touched = false;
  for (int step = 0; step < 60000 && !(touched && world.contacts().empty()); ++step) {
    world.step();
    touched = touched || !world.contacts().empty();
  }
  EXPECT_TRUE(touched);
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_EQ(world.statistics().detectorFailures, 0);
  const double scaleP = world.particles().mass[0] * 0.5, scaleL = scaleP * 2e-3;
  return {std::abs(world.kineticEnergy() - E0) / E0, (linearMomentum(world.particles()) - P0).norm() / scaleP,
          (angularMomentum(world.particles()) - L0).norm() / scaleL};
}

// Energy and momentum are conserved by a conservative law: elliptic Hertz while the contact
// curvature is constant (head-on at the tips), Hertz on volume-equivalent spheres always.
TEST(World, ElasticEllipsoidCollisionConservesEnergyAndMomentum) {
  for (const auto& [normal, oblique] : {std::pair{NormalLaw::EllipticHertz, false},
                                        std::pair{NormalLaw::VolumeSphereHertz, true}}) {
    const CollisionErrors e = collide(normal, oblique);
    std::printf("energy %.3g, momentum %.3g, angular momentum %.3g\n", e.energy, e.momentum, e.angularMomentum);
    EXPECT_LT(e.energy, 1e-6);
    EXPECT_LT(e.momentum, 1e-9);
    EXPECT_LT(e.angularMomentum, 1e-9);
  }
}

// The elliptic Hertz force uses the curvature at the current contact point, which moves over
// the surfaces in an oblique impact: the force is then not the gradient of a potential and the
// kinetic energy is not restored exactly (measured +0.44 %, independent of the time step).
// Momentum is still conserved: the law acts equally and oppositely at one point.
TEST(World, ObliqueEllipticHertzImpactConservesMomentum) {
  const CollisionErrors e = collide(NormalLaw::EllipticHertz, true);
  std::printf("oblique elliptic Hertz: energy change %.3g (model, not integrator), momentum %.3g, angular %.3g\n",
              e.energy, e.momentum, e.angularMomentum);
  EXPECT_LT(e.momentum, 1e-9);
  EXPECT_LT(e.angularMomentum, 1e-9);
}

// A sphere dropped on a wall with restitution e (001 Eqs. 11-13 damping): the rebound speed is
// e times the impact speed within 1 %.
TEST(World, DampedSphereWallImpactReproducesRestitution) {
  for (const double e : {0.3, 0.6, 0.9}) {
    const Material m{1e8, 0.25, 2500.0, 0.0, e};
    World world({Superquadric::sphere(1e-3)}, {m}, bigBox(), 1e-4);
    world.setContactModel(0, 0, world.defaultContactModel(0, 0));
    world.addWall({Plane{Vec3::Zero(), Vec3::UnitZ()}, Vec3::Zero(), 0});
    world.addParticle(0, 0, Vec3(0.0, 0.0, 1.05e-3), Quat::Identity());
    world.particles().velocity[0] = Vec3(0.0, 0.0, -1.0);
    world.setTimeStep(2e-8);
    bool touched = false;
    for (int step = 0; step < 200000 && !(touched && world.contacts().empty()); ++step) {
      world.step();
      touched = touched || !world.contacts().empty();
    }
    const double rebound = world.particles().velocity[0].z();
    std::printf("e = %.2f: rebound/impact = %.5f\n", e, rebound);
    EXPECT_NEAR(rebound, e, 0.01 * e);
  }
}

// The slab volume of a tilted ellipsoid (packing_measures.hpp) against a grid count of the
// points inside it: whole body V, and a slab through it within the grid's resolution.
TEST(PackingMeasures, EllipsoidVolumeInSlabMatchesPointCount) {
  const Superquadric e = Superquadric::ellipsoid(1.0, 0.6, 0.3);
  const Pose pose{Vec3(0.1, -0.2, 0.05), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 0.5).normalized()))};
  EXPECT_NEAR(volumeInSlab(e, pose, -5.0, 5.0), e.volume(), 1e-12);
  const double lo = -0.1, hi = 0.25, step = 0.01;
  long inside = 0;
  for (double x = -1.2; x < 1.2; x += step) {
    for (double y = -1.2; y < 1.2; y += step) {
      for (double z = lo + 0.5 * step; z < hi; z += step) {
        inside += e.gauge(pose.toBody(Vec3(x, y, z))) <= 1.0;
      }
    }
  }
  const double counted = inside * step * step * step;
  EXPECT_NEAR(volumeInSlab(e, pose, lo, hi), counted, 0.01 * counted);
}

}  // namespace
}  // namespace sqdem

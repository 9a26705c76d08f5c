// Kinematic bodies (wall.hpp): a spinning roller (a cylinder wall) pressing a particle onto a
// frictionless floor. Without friction the spin does nothing (the normal force is radial:
// no drag, no torque about the axis); with friction the surface velocity spin x (x - c) drags the
// particle along the roller's surface motion at the contact, and the torque about the axis is
// the tangential force times the lever arm, opposing the spin.

#include <gtest/gtest.h>

#include <cmath>

#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

constexpr double rollerRadius = 5e-3, particleRadius = 1e-3, squeeze = 2e-6;

Domain bigBox() {
  Domain d;
  d.lo = Vec3::Constant(-0.1);
  d.hi = Vec3::Constant(0.1);
  return d;
}

/// A particle on the floor z = 0 (material 1, frictionless) under a roller of material 2 with
/// its axis along y straight above it, pressing it by `squeeze`; the particle is material 0.
World rollerOverParticle(const Superquadric& shape, double friction, double spin) {
  const Material grain{1e8, 0.3, 2500.0, friction, 0.5}, floor{1e8, 0.3, 2500.0, 0.0, 0.5},
      roller{1e8, 0.3, 2500.0, friction, 0.5};
  World world({shape}, {grain, floor, roller}, bigBox(), 1e-4);
  for (std::uint32_t a = 0; a < 3; ++a) {
    for (std::uint32_t b = a; b < 3; ++b) world.setContactModel(a, b, world.defaultContactModel(a, b));
  }
  const double height = shape.c();
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}, .material = 1});
  Wall top{.material = 2};
  top.surface = CylinderWall{Cylinder{Vec3(0.0, 0.0, 2.0 * height + rollerRadius - squeeze), Vec3::UnitY(), rollerRadius}};
  top.angularVelocity = spin * Vec3::UnitY();
  world.addWall(top);
  world.addParticle(0, 0, Vec3(0.0, 0.0, height), Quat::Identity());
  world.setTimeStep(1e-8);
  return world;
}

/// The roller's contact of the particle (after a force computation).
ContactView rollerContact(const World& world) {
  for (const ContactView c : world.contacts()) {
    if (c.onWall() && c.wall() == 1) return c;
  }
  ADD_FAILURE() << "the roller does not touch the particle";
  return *world.contacts().begin();
}

TEST(KinematicBody, FrictionlessRollerOnlyPushes) {
  for (const Superquadric& shape : {Superquadric::sphere(particleRadius), Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3)}) {
    World still = rollerOverParticle(shape, 0.0, 0.0), spinning = rollerOverParticle(shape, 0.0, 300.0);
    for (int step = 0; step < 200; ++step) {
      still.step();
      spinning.step();
    }
    // (The ellipsoid's normal comes from a search to ~1e-8 rad: equal to round-off there.)
    const ParticleStore &a = still.particles(), &b = spinning.particles();
    const double speed = a.velocity[0].norm();
    EXPECT_LT((a.velocity[0] - b.velocity[0]).norm(), 1e-9 * speed) << "without friction the spin does nothing";
    EXPECT_LT(std::hypot(b.velocity[0].x(), b.velocity[0].y()), 1e-6 * speed) << "no drag";
    EXPECT_LT(b.velocity[0].z(), 0.0) << "pushed down";
    const Wall& roller = spinning.walls()[1];
    EXPECT_GT(roller.force.z(), 0.0) << "the particle pushes the roller up";
    EXPECT_LT(std::abs(roller.torque.dot(roller.get<CylinderWall>().cylinder.axis)), 1e-12 * rollerRadius * roller.force.norm())
        << "a radial normal force has no moment about the axis";
  }
}

TEST(KinematicBody, SpinningRollerDragsAlongItsSurfaceMotion) {
  for (const Superquadric& shape : {Superquadric::sphere(particleRadius), Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3)}) {
    for (const double spin : {300.0, -300.0}) {
      World world = rollerOverParticle(shape, 0.5, spin);
      for (int step = 0; step < 200; ++step) world.step();
      // The roller's surface at its lowest point moves with spin y x (0, 0, -R) = -spin R x.
      const double surfaceMotion = -spin * rollerRadius;
      EXPECT_GT(world.particles().velocity[0].x() * surfaceMotion, 0.0) << "dragged along, spin " << spin;
      const Wall& roller = world.walls()[1];
      const ContactView c = rollerContact(world);
      const Vec3 tangential = c.force() - c.force().dot(c.normal()) * c.normal();
      EXPECT_GT(tangential.norm(), 0.0);
      // One contact: the torque about the axis is the tangential force times the lever arm
      // (the distance from the axis to the contact point), opposing the spin.
      const double lever = roller.get<CylinderWall>().cylinder.fromAxis(c.point()).norm();
      EXPECT_NEAR(std::abs(roller.torque.dot(roller.get<CylinderWall>().cylinder.axis)), lever * tangential.norm(),
                  1e-9 * lever * tangential.norm());
      EXPECT_LT(roller.torque.dot(roller.get<CylinderWall>().cylinder.axis) * spin, 0.0) << "the particle brakes the roller";
      EXPECT_NEAR(lever, rollerRadius - 0.5 * c.overlap(), 1e-6 * rollerRadius) << "the lever is the radius";
    }
  }
}

// In a box periodic along x, a roller standing across the boundary acts through its image: the
// same force and torque as the roller placed at that image in an open box.
// A finite roller (rounded ends, barrel 4 mm long): with the particle under its barrel it acts as
// the infinite one, bit for bit; moved along its axis until the particle lies beyond its end, it
// does not touch it (the infinite one still would).
TEST(KinematicBody, FiniteRollerActsOnlyWhereItIs) {
  const Superquadric shape = Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3);
  World infinite = rollerOverParticle(shape, 0.4, 300.0), under = rollerOverParticle(shape, 0.4, 300.0),
        beyond = rollerOverParticle(shape, 0.4, 300.0);
  under.walls()[1].get<CylinderWall>().cylinder.halfLength = 2e-3;
  beyond.walls()[1].get<CylinderWall>().cylinder.halfLength = 2e-3;
  beyond.walls()[1].get<CylinderWall>().cylinder.point.y() += 2e-3 + rollerRadius + 2e-3;  // the end's hemisphere 2 mm short of the particle's axis station
  for (int step = 0; step < 200; ++step) infinite.step(), under.step(), beyond.step();
  EXPECT_EQ(under.walls()[1].force, infinite.walls()[1].force);
  EXPECT_EQ(under.particles().velocity[0], infinite.particles().velocity[0]);
  EXPECT_GT(infinite.walls()[1].force.norm(), 0.0);
  EXPECT_EQ(beyond.walls()[1].force, Vec3::Zero());
}

TEST(KinematicBody, RollerActsAcrossAPeriodicBoundary) {
  const double length = 20e-3;
  const auto pressed = [&](bool periodic) {
    Domain box;
    box.lo = Vec3(0.0, -0.01, -0.01);
    box.hi = Vec3(length, 0.01, 0.02);
    box.periodic = {periodic, false, false};
    const Material m{1e8, 0.3, 2500.0, 0.5, 0.5};
    World world({Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3)}, {m}, box, 1e-4);
    world.setContactModel(0, 0, world.defaultContactModel(0, 0));
    Wall roller;
    // Periodic: at x = L - 0.7 mm, its image at -0.7 mm; open: at -0.7 mm itself.
    const double x = periodic ? length - 0.7e-3 : -0.7e-3;
    roller.surface = CylinderWall{Cylinder{Vec3(x, 0.0, 0.8e-3 + rollerRadius + 0.6e-3), Vec3::UnitY(), rollerRadius}};
    roller.angularVelocity = 100.0 * Vec3::UnitY();
    world.addWall(roller);
    world.addParticle(0, 0, Vec3(0.5e-3, 0.0, 0.6e-3), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized())));
    world.particles().velocity[0] = Vec3(0.0, 0.0, 0.2);
    world.setTimeStep(1e-8);
    for (int step = 0; step < 20; ++step) world.step();
    return world;
  };
  const World periodic = pressed(true), open = pressed(false);
  ASSERT_EQ(open.contacts().size(), 1u);
  ASSERT_EQ(periodic.contacts().size(), 1u);
  const Wall &a = periodic.walls()[0], &b = open.walls()[0];
  EXPECT_GT(b.force.norm(), 0.0);
  EXPECT_GT((*open.contacts().begin()).overlap(), 0.0);
  EXPECT_LT((*open.contacts().begin()).overlap(), 1e-5) << "a gentle contact";
  EXPECT_LT((a.force - b.force).norm(), 1e-9 * b.force.norm());
  EXPECT_LT((a.torque - b.torque).norm(), 1e-9 * b.torque.norm());
  EXPECT_LT((periodic.particles().velocity[0] - open.particles().velocity[0]).norm(), 1e-9);
}

}  // namespace
}  // namespace sqdem

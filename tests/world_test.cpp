// The World's step loop (world/world.hpp) on collisions with closed-form expectations.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <omp.h>

#include "sqdem/mechanics/collision_time.hpp"
#include "sqdem/mechanics/haervig.hpp"
#include "sqdem/mechanics/roughness_gw.hpp"
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
/// curvatures: elliptic Hertz on the detector's curvatures, else volume-sphere Hertz.
CollisionErrors collide(bool curvatures, bool oblique) {
  const Material m{1e7, 0.3, 1000.0, 0.0, 1.0};
  World world({Superquadric::ellipsoid(1.5e-3, 1e-3, 0.8e-3)}, {m}, bigBox(), 2e-4);
  ContactModel law = world.defaultContactModel(0, 0);
  law.eccentricity = EccentricityMethod::Exact;
  law.curvatures = curvatures;
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
  for (const auto& [curvatures, oblique] : {std::pair{true, false}, std::pair{false, true}}) {
    const CollisionErrors e = collide(curvatures, oblique);
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
  const CollisionErrors e = collide(true, true);
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
    world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
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

// 001 Eq. 24 / Fig. 8 and 13: an adhesive sphere-wall impact (simplified JKR, e = 0.9, chosen so
// that adhesion halves the rebound velocity) keeps its rebound velocity when E is reduced 10x
// and 100x with gamma_mod = gamma (E_mod/E)^2/5, and its collision time scales as
// (E/E_mod)^2/5; without the rule the softer particle sticks.
struct Impact {
  double rebound;        ///< outgoing / incoming speed
  double collisionTime;  ///< (s)
};

Impact adhesiveImpact(double youngs, double surfaceEnergy) {
  const double R = 1e-5, v0 = 0.2;
  World world({Superquadric::sphere(R)}, {Material{youngs, 0.3, 2500.0, 0.0, 0.9}}, bigBox(), 1e-6);
  ContactModel law = world.defaultContactModel(0, 0);
  law.normal = HaervigJkrLaw{surfaceEnergy, surfaceEnergy};
  world.setContactModel(0, 0, law);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  world.addParticle(0, 0, Vec3(0.0, 0.0, 1.0001 * R), Quat::Identity());
  world.particles().velocity[0] = Vec3(0.0, 0.0, -v0);
  const double m = world.particles().mass[0];
  const double hertzTime = 2.87 * std::pow(m * m / (R * youngs * youngs * v0), 0.2);  // order of magnitude
  world.setTimeStep(hertzTime / 4000.0);
  double start = -1.0;
  for (int step = 0; step < 100000; ++step) {
    world.step();
    const bool touching = !world.contacts().empty();
    if (touching && start < 0.0) start = world.time();
    if (!touching && start >= 0.0) return {world.particles().velocity[0].z() / v0, world.time() - start};
  }
  return {0.0, std::numeric_limits<double>::infinity()};  // stuck
}

TEST(World, ReducedStiffnessRuleKeepsAdhesiveReboundVelocity) {
  omp_set_num_threads(1);
  const double E = 1e9, gamma = 0.2;
  const Impact base = adhesiveImpact(E, gamma);
  ASSERT_GT(base.rebound, 0.3);  // adhesion matters: e_eff well below e = 0.9
  ASSERT_LT(base.rebound, 0.7);
  for (const double factor : {0.1, 0.01}) {
    const Impact soft = adhesiveImpact(factor * E, reducedStiffnessSurfaceEnergy(gamma, E, factor * E));
    std::printf("E x %.2f: rebound %.6f vs %.6f, collision time ratio %.5f vs (E/E_mod)^2/5 = %.5f\n", factor,
                soft.rebound, base.rebound, soft.collisionTime / base.collisionTime, std::pow(1.0 / factor, 0.4));
    EXPECT_NEAR(soft.rebound, base.rebound, 1e-3 * base.rebound);
    EXPECT_NEAR(soft.collisionTime / base.collisionTime, std::pow(1.0 / factor, 0.4), 1e-3 * std::pow(1.0 / factor, 0.4));
  }
  EXPECT_EQ(adhesiveImpact(0.1 * E, gamma).rebound, 0.0);  // the unmodified gamma sticks
}

// An elastic sphere-wall impact lasts Johnson's Hertz collision time (collision_time.hpp), and
// World::hertzTimeStep is that time over the steps per collision.
TEST(World, ElasticImpactLastsTheHertzCollisionTime) {
  omp_set_num_threads(1);
  const double R = 1e-3, v0 = 0.5;
  World world({Superquadric::sphere(R)}, {Material{1e8, 0.25, 2500.0, 0.0, 1.0}}, bigBox(), 1e-4);
  const ContactModel law = world.defaultContactModel(0, 0);
  world.setContactModel(0, 0, law);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  world.addParticle(0, 0, Vec3(0.0, 0.0, 1.0001 * R), Quat::Identity());
  world.particles().velocity[0] = Vec3(0.0, 0.0, -v0);
  const double expected = hertzCollisionTime(world.particles().mass[0], R, law.effectiveModulus, v0);
  // hertzTimeStep: the sphere against itself, m* = m/2, R* = R/2.
  EXPECT_NEAR(world.hertzTimeStep(v0, 50.0), hertzCollisionTime(0.5 * world.particles().mass[0], 0.5 * R, law.effectiveModulus, v0) / 50.0,
              1e-15);
  world.setTimeStep(expected / 2000.0);
  double start = -1.0, duration = 0.0;
  for (int step = 0; step < 10000 && duration == 0.0; ++step) {
    world.step();
    const bool touching = !world.contacts().empty();
    if (touching && start < 0.0) start = world.time();
    if (!touching && start >= 0.0) duration = world.time() - start;
  }
  EXPECT_NEAR(duration, expected, 2e-3 * expected);
}

// Becker-Kamlah in the engine: for a sphere the elastic - fully plastic variant (002 Eq. 24,
// unloading Eqs. 32-49 with beta = 1) is Thornton's elastic-perfectly-plastic law (p_Y = 1.6 Y,
// his R_p equals 002 Eq. 44), whose restitution against a rigid flat is (Thornton, J. Appl. Mech.
// 64 (1997) 383, Eq. 42, with v = V_y/V):
//   e = sqrt(6 sqrt3 / 5) sqrt(1 - v^2/6) [v / (v + 2 sqrt(6/5 - v^2/5))]^1/4,
// V_y from the Hertz energy at the yield overlap. No viscous damping (restitution 1): all loss
// is plastic; below V_y the impact stays elastic.
TEST(World, BeckerKamlahSphereImpactFollowsThorntonRestitution) {
  omp_set_num_threads(1);
  const double R = 1e-4, E = 1e9, nu = 0.3, Y = 2e7, rho = 2000.0;
  const auto rebound = [&](double speed) {
    World world({Superquadric::sphere(R)}, {Material{E, nu, rho, 0.0, 1.0, Y}}, bigBox(), 1e-5);
    ContactModel law = world.defaultContactModel(0, 0);
    law.normal = BeckerKamlahLaw{{.yieldStrength = Y, .transition = false}};
    world.setContactModel(0, 0, law);
    world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
    world.addParticle(0, 0, Vec3(0.0, 0.0, 1.00001 * R), Quat::Identity());
    world.particles().velocity[0] = Vec3(0.0, 0.0, -speed);
    world.setTimeStep(hertzCollisionTime(world.particles().mass[0], R, law.effectiveModulus, speed) / 4000.0);
    bool touched = false;
    for (int step = 0; step < 100000 && !(touched && world.contacts().empty()); ++step) {
      world.step();
      touched = touched || !world.contacts().empty();
    }
    EXPECT_TRUE(touched && world.contacts().empty());
    return world.particles().velocity[0].z() / speed;
  };
  // Yield overlap and speed of a sphere on a flat: p0 = p_Y at delta_Y = (pi p_Y / (2 E*))^2 R.
  const double Estar = effectiveModulus(E, nu, E, nu), pY = 1.6 * Y;
  const double deltaY = std::pow(std::numbers::pi * pY / (2.0 * Estar), 2) * R;
  const double mass = rho * 4.0 / 3.0 * std::numbers::pi * R * R * R;
  const double Vy = std::sqrt(2.0 * 8.0 / 15.0 * Estar * std::sqrt(R) * std::pow(deltaY, 2.5) / mass);
  EXPECT_NEAR(rebound(0.5 * Vy), 1.0, 1e-4);
  for (const double ratio : {3.0, 10.0, 30.0}) {
    const double v = 1.0 / ratio;
    const double thornton = std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - v * v / 6.0) *
                            std::pow(v / (v + 2.0 * std::sqrt(6.0 / 5.0 - v * v / 5.0)), 0.25);
    const double e = rebound(ratio * Vy);
    std::printf("V/V_y = %4.0f: rebound %.5f, Thornton %.5f\n", ratio, e, thornton);
    EXPECT_NEAR(e, thornton, 1e-3 * thornton);
  }
}

// Adhesive rolling resistance (001 Eqs. 18-22): a sphere resting on a wall in adhesive
// equilibrium (a = a_0) under an external force F parallel to the wall stays put when
// F < F_yield = 4 F_C xi_crit / R and keeps rolling when F > F_yield (001 Section 4, F^ = F/F_yield).
TEST(World, RollingResistanceHoldsBelowTheYieldForceAndRollsAbove) {
  omp_set_num_threads(1);
  const double R = 5e-6, E = 1e8, nu = 0.3, rho = 2000.0, gamma = 0.05, hysteresis = 0.5;
  const auto travel = [&](double forceRatio) {
    World world({Superquadric::sphere(R)}, {Material{E, nu, rho, 1.0, 0.3}}, bigBox(), 1e-7);
    ContactModel law = world.defaultContactModel(0, 0);
    law.normal = HaervigJkrLaw{gamma, gamma};
    law.rolling = HaervigRollingResistance{hysteresis, law.effectiveModulus};
    world.setContactModel(0, 0, law);
    world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
    world.addParticle(0, 0, Vec3(0.0, 0.0, R - 1e-9), Quat::Identity());
    world.setTimeStep(5e-9);
    for (int step = 0; step < 20000; ++step) world.step();  // adhesive equilibrium
    EXPECT_EQ(world.contacts().size(), 1u);
    const HaervigJkr jkr(law.effectiveModulus, gamma, R);
    const double yieldForce = 4.0 * jkr.criticalForce() * jkr.equilibriumContactRadius() / 12.0 * hysteresis / R;
    world.setGravity(Vec3(forceRatio * yieldForce / world.particles().mass[0], 0.0, 0.0));
    // The suddenly applied force overshoots (no rolling damping in the model), so the sphere
    // may roll a little before it is held; compare the travel over a later, equal interval.
    for (int step = 0; step < 20000; ++step) world.step();
    const double x0 = world.particles().position[0].x();
    for (int step = 0; step < 20000; ++step) world.step();
    EXPECT_EQ(world.contacts().size(), 1u);
    return (world.particles().position[0].x() - x0) / (jkr.equilibriumContactRadius() / 12.0 * hysteresis);
  };
  const double held = travel(0.9), rolling = travel(1.1);
  std::printf("travel over the last 1e-4 s: %.3g xi_crit at F/F_yield = 0.9, %.3g at 1.1\n", held, rolling);
  EXPECT_LT(std::abs(held), 2.0);  // at rest up to the elastic rolling oscillation (amplitude <= 2 xi_crit)
  EXPECT_GT(rolling, 1000.0);      // rolls on
}

// Greenwood-Williamson roughness (004 Eqs. 33, 35): a rough sphere comes to rest on a wall
// at the gap g = sigma h* where the asperity force carries its weight,
// 4/3 N A_n E* Rc^1/2 sigma^3/2 gamma F_3/2(h*) = m g (sphere on a flat: Rc = R/2, gamma = sqrt 2);
// the mean surfaces never touch.
TEST(World, RoughSphereRestsOnItsAsperities) {
  omp_set_num_threads(1);
  const double R = 1e-3, sigma = 1e-6, asperities = 100.0, g = 9.81;
  World world({Superquadric::sphere(R)}, {Material{1e8, 0.3, 2500.0, 0.0, 0.3}}, bigBox(), 1e-4);
  ContactModel law = world.defaultContactModel(0, 0);
  law.normal = GreenwoodWilliamsonLaw{{.asperityCount = asperities, .sigma = sigma}};
  world.setContactModel(0, 0, law);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  world.addParticle(0, 0, Vec3(0.0, 0.0, R + 3.5 * sigma), Quat::Identity());
  world.setGravity(Vec3(0.0, 0.0, -g));
  world.setTimeStep(1e-6);
  for (int step = 0; step < 40000; ++step) world.step();
  ASSERT_EQ(world.contacts().size(), 1u);
  const double weight = world.particles().mass[0] * g;
  const double scale = 4.0 / 3.0 * asperities * law.effectiveModulus * std::sqrt(0.5 * R) * std::pow(sigma, 1.5) * std::sqrt(2.0);
  double lo = 0.0, hi = 4.0;  // F_3/2 decreases with h
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (scale * greenwoodWilliamsonForceIntegral(mid) > weight ? lo : hi) = mid;
  }
  const double gap = world.particles().position[0].z() - R;
  std::printf("resting gap %.6g sigma, equilibrium h* = %.6g\n", gap / sigma, lo);
  EXPECT_NEAR(gap / sigma, lo, 1e-4 * lo);
  EXPECT_NEAR(world.walls()[0].force.z(), -weight, 1e-4 * weight);
}

// A rough contact is found where it starts to act: two rough spheres approaching from far
// apart feel the first asperity force at a gap of 4 sigma (within one step's approach), although
// the neighbour list is rebuilt only every half skin of motion (the candidates' reach includes
// the law's range).
TEST(World, RoughContactStartsAtItsRange) {
  omp_set_num_threads(1);
  const double R = 1e-3, sigma = 1e-6, v = 0.01, dt = 1e-6;
  World world({Superquadric::sphere(R)}, {Material{1e8, 0.3, 2500.0, 0.0, 1.0}}, bigBox(), 10e-6);
  ContactModel law = world.defaultContactModel(0, 0);
  law.normal = GreenwoodWilliamsonLaw{{.asperityCount = 100.0, .sigma = sigma}};
  world.setContactModel(0, 0, law);
  world.addParticle(0, 0, Vec3(-R - 30.3e-6, 0.0, 0.0), Quat::Identity());  // a rebuild falls at a gap just over the skin
  world.addParticle(0, 0, Vec3(R + 30.3e-6, 0.0, 0.0), Quat::Identity());
  world.particles().velocity[0] = Vec3(v, 0.0, 0.0);
  world.particles().velocity[1] = Vec3(-v, 0.0, 0.0);
  world.setTimeStep(dt);
  double firstGap = -1.0;
  for (int step = 0; step < 10000 && firstGap < 0.0; ++step) {
    world.step();
    if (!world.contacts().empty()) firstGap = world.particles().position[1].x() - world.particles().position[0].x() - 2.0 * R;
  }
  EXPECT_GT(world.neighbourList().builds(), 5);  // the list was rebuilt on the way in
  EXPECT_LE(firstGap, 4.0 * sigma);
  EXPECT_GT(firstGap, 4.0 * sigma - 2.0 * v * dt * 1.01);
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

// Love-Weber stress (packing_measures.hpp) of a hand-built contact set, whole tensor. Two
// frictionless spheres pressed along a generic direction n carry sigma = |F| |l| n n^T / V
// (closed form, all six components non-zero); with friction and a sliding sphere the tangential
// force adds shear, checked against sym(l (x) f) / V summed component by component.
TEST(PackingMeasures, StressTensorOfAContactSetEqualsTheLoveWeberSum) {
  for (const double friction : {0.0, 0.5}) {
    const Material m{1e7, 0.3, 1000.0, friction, 1.0};
    World world({Superquadric::ellipsoid(1e-3, 1e-3, 1e-3)}, {m}, bigBox(), 2e-4);
    ContactModel law = world.defaultContactModel(0, 0);
    law.curvatures = false;
    world.setContactModel(0, 0, law);
    const Vec3 n = Vec3(1.0, -2.0, 3.0).normalized(), lever = 1.9e-3 * n;
    world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
    world.addParticle(0, 0, lever, Quat::Identity());
    world.setTimeStep(1e-7);
    if (friction > 0.0) {  // slide B across A: the tangential spring builds up
      world.particles().velocity[1] = 1.0 * n.cross(Vec3::UnitX()).normalized();
      for (int k = 0; k < 200; ++k) world.step();
    } else {
      world.computeForces();
    }
    ASSERT_EQ(world.contacts().size(), 1u);
    const Vec3 l = world.particles().position[1] - world.particles().position[0];
    const Vec3 f = world.contacts().front().force();
    const PackingMeasures measures = measurePacking(world);
    const double V = measures.stressVolume, scale = f.norm() * l.norm() / V;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double expected = friction > 0.0 ? 0.5 * (l[i] * f[j] + l[j] * f[i]) / V : f.norm() * l.norm() * n[i] * n[j] / V;
        EXPECT_NEAR(measures.stress(i, j), expected, 1e-12 * scale) << "component " << i << j << ", friction " << friction;
      }
    }
    if (friction > 0.0) EXPECT_GT((f - f.dot(n) * n).norm(), 0.01 * f.norm());  // the shear is really there
  }
}

}  // namespace
}  // namespace sqdem

// The registered normal laws (law_registry.hpp) in the engine: the World's contact store,
// histories and ranges give the same forces as the single-contact driver (probe/driven_law.hpp)
// on the same overlap history, and the adhesive laws reproduce their closed forms in motion.
// Two bodies are driven quasi-statically (positions prescribed, World::computeForces) or move
// freely (World::step); no damping or friction unless stated.

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "sqdem/probe/driven_law.hpp"
#include "sqdem/mechanics/sticking_velocity.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

using std::numbers::pi;

constexpr double E = 1e9, nu = 0.3, rho = 2000.0, R = 10e-6;

Domain bigBox() {
  Domain d;
  d.lo = Vec3::Constant(-1e-3);
  d.hi = Vec3::Constant(1e-3);
  return d;
}

/// Two bodies of `shape`, B on the +x side of A with its tip facing A's, under `law`.
World pair(const Superquadric& shape, const NormalLaw& law, double restitution = 1.0) {
  World world({shape}, {Material{E, nu, rho, 0.0, restitution}}, bigBox(), 0.1 * R);
  ContactModel model = world.defaultContactModel(0, 0);
  model.normal = law;
  model.eccentricity = EccentricityMethod::Exact;
  world.setContactModel(0, 0, model);
  world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
  world.addParticle(0, 0, Vec3(2.0 * shape.halfExtents().x(), 0.0, 0.0), Quat::Identity());
  world.setTimeStep(1e-6);
  return world;
}

struct Sample {
  double overlap;  ///< the engine's (m), or the prescribed one when there is no contact
  double force;    ///< normal force on B (N), > 0 repulsive; 0 without contact
  bool contact;
};

/// Moves B to overlap `delta` with A (velocity consistent with the move, for the separation
/// bound of the candidate culling) and computes the forces there.
Sample driveTo(World& world, double delta) {
  ParticleStore& p = world.particles();
  const double x = 2.0 * world.shapes()[0].halfExtents().x() - delta;
  p.velocity[1] = Vec3((x - p.position[1].x()) / world.timeStep(), 0.0, 0.0);
  p.position[1] = Vec3(x, 0.0, 0.0);
  world.computeForces();
  for (const ContactView c : world.contacts()) return {c.overlap(), c.normalLoad().force, true};
  return {delta, 0.0, false};
}

/// Overlaps from `from` to `to` in `n` equal steps (without `from`).
std::vector<double> leg(double from, double to, int n) {
  std::vector<double> path;
  for (int k = 1; k <= n; ++k) path.push_back(from + (to - from) * k / n);
  return path;
}

struct LawCase {
  const char* name;
  NormalLaw engine;
  probe::json driver;
};

std::vector<LawCase> laws() {
  const double gamma = 0.05, Y = 1e7, py = 3e7, H = 5e7;
  BeckerKamlahParameters bk{.yieldStrength = Y, .lambdaMax = 3.0, .epsilonMax = 10.0};
  return {
      {"elliptic_hertz", HertzLaw{}, {{"type", "elliptic_hertz"}}},
      {"becker_kamlah", BeckerKamlahLaw{bk},
       {{"type", "becker_kamlah"}, {"yield_strength", Y}, {"lambda_max", 3.0}, {"epsilon_max", 10.0}}},
      {"becker_kamlah+jkr", BeckerKamlahLaw{bk, gamma},
       {{"type", "becker_kamlah"}, {"yield_strength", Y}, {"lambda_max", 3.0}, {"epsilon_max", 10.0}, {"surface_energy", gamma}}},
      {"haervig_jkr", HaervigJkrLaw{gamma, gamma}, {{"type", "haervig_jkr"}, {"surface_energy", gamma}}},
      {"elliptic_jkr", EllipticJkrLaw{gamma}, {{"type", "elliptic_jkr"}, {"surface_energy", gamma}}},
      {"elliptic_jkr+rough", RoughJkrLaw{{.asperityCount = 50.0, .sigma = 2e-8}, gamma},
       {{"type", "elliptic_jkr"}, {"surface_energy", gamma}, {"roughness", {{"sigma", 2e-8}, {"asperity_count", 50.0}}}}},
      {"nan_adhesive", NanAdhesiveLaw{.surfaceEnergy = gamma, .yieldPressure = py},
       {{"type", "nan_adhesive"}, {"surface_energy", gamma}, {"yield_pressure", py}}},
      {"jamari", JamariLaw{{.hardness = H, .maxPressureFactor = 0.454 + 0.41 * nu, .meanPressureFactor = 1.0, .plasticOverlapFactor = 220.0}},
       {{"type", "jamari"}, {"hardness", H}}},
  };
}

struct Body {
  const char* name;
  Superquadric shape;
  RelativeRadii tips;  ///< relative radii of the two facing tips (closed form)
};

std::vector<Body> bodies() {
  const double a = R, b = 0.7 * R, c = 0.5 * R;
  const double Ri = c * c / (2.0 * a), Rj = b * b / (2.0 * a);  // tip radii c^2/a, b^2/a, two bodies
  return {{"spheres", Superquadric::sphere(R), {0.5 * R, 0.5 * R, 1.0, 0.25 * R}},
          {"ellipsoids", Superquadric::ellipsoid(a, b, c), {Ri, Rj, 1.0, Ri * Rj / (Ri + Rj)}}};
}

// 1. Engine = driver, within 1e-9 of the largest force, along approach from a gap, loading to
// 20 x the Becker-Kamlah yield overlap, unloading and retraction to a gap beyond every
// adhesive law's detachment and the rough law's 4 sigma.
TEST(EngineLaws, EachLawEqualsTheDriverOnTheSameHistory) {
  omp_set_num_threads(1);
  const double top = 2e-7;
  std::vector<double> path = leg(-0.05 * top, top, 400);
  for (double d : leg(top, -0.5 * top, 600)) path.push_back(d);
  for (const Body& body : bodies()) {
    for (const LawCase& law : laws()) {
      World world = pair(body.shape, law.engine);
      const double volumeRadius = body.shape.volumeEquivalentRadius();
      probe::DrivenLaw driver(law.driver, law.name, body.tips, {E, nu, E, nu}, 2.0 * volumeRadius);
      double worst = 0.0, largest = 0.0;
      int engineContacts = 0, driverContacts = 0;
      for (const double delta : path) {
        const Sample s = driveTo(world, delta);
        const probe::LawSample d = driver.at(s.overlap);
        engineContacts += s.contact;
        driverContacts += d.contact;
        worst = std::max(worst, std::abs(s.force - d.force));
        largest = std::max(largest, std::abs(d.force));
      }
      std::printf("%-10s %-18s largest force %.4e N, engine - driver %.2e of it, %d / %d samples in contact\n", body.name,
                  law.name, largest, worst / largest, engineContacts, driverContacts);
      EXPECT_LE(worst, 1e-9 * largest) << body.name << " " << law.name;
      EXPECT_EQ(engineContacts, driverContacts) << body.name << " " << law.name;
      EXPECT_FALSE(driveTo(world, path.back()).contact) << "still in contact at the end: " << law.name;
    }
  }
}

/// JKR of a sphere pair (R* = R/2) or a sphere on a wall (R* = R): 004 Eqs. 19-28 at lambda = 1,
/// i.e. the classical JKR: a_0^3 = 9 pi W R*^2 / (2 E*), delta_0 = a_0^2 / (3 R*), pull-off
/// 3/2 pi W R*, detachment under displacement control at -(3/4) (pi^2 W^2 R* / E*^2)^1/3.
struct ClassicalJkr {
  double W, Rstar, Estar;
  double a0() const { return std::cbrt(9.0 * pi * W * Rstar * Rstar / (2.0 * Estar)); }
  double zeroLoadOverlap() const { return a0() * a0() / (3.0 * Rstar); }
  double pullOff() const { return 1.5 * pi * W * Rstar; }
  double detachmentOverlap() const { return -0.75 * std::cbrt(pi * pi * W * W * Rstar / (Estar * Estar)); }
};

// 2. Two touching spheres without gravity settle at the JKR zero-load overlap (within 1 %).
TEST(EngineLaws, EllipticJkrSpheresSettleAtTheZeroLoadOverlap) {
  omp_set_num_threads(1);
  const double gamma = 0.05;
  World world = pair(Superquadric::sphere(R), EllipticJkrLaw{gamma}, 0.3);
  const ClassicalJkr jkr{2.0 * gamma, 0.5 * R, effectiveModulus(E, nu, E, nu)};
  world.particles().position[1].x() = 2.0 * R - 1e-6 * jkr.zeroLoadOverlap();  // just touching: snap-in
  const double m = world.particles().mass[0];
  world.setTimeStep(0.05 * std::sqrt(0.5 * m / (2.0 * jkr.Estar * jkr.a0())));  // contact stiffness 2 E* a_0
  for (int s = 0; s < 40000; ++s) world.step();
  ASSERT_EQ(world.contacts().size(), 1u);
  const double overlap = world.contacts().front().overlap();
  std::printf("settled overlap %.6e m, JKR delta_0 %.6e m (%+.3f %%), E_kin %.2e J\n", overlap, jkr.zeroLoadOverlap(),
              100.0 * (overlap / jkr.zeroLoadOverlap() - 1.0), world.kineticEnergy());
  EXPECT_NEAR(overlap, jkr.zeroLoadOverlap(), 0.01 * jkr.zeroLoadOverlap());
}

// 3. A sphere pulled off a wall: the most tensile force along the retraction is the JKR
// pull-off 3/2 pi W R (within 2 %), and the contact holds across negative overlaps down to the
// detachment overlap, detaches exactly once there, and its history is dropped: approaching
// again, it forms only at overlap 0 (snap-in), not at a gap.
TEST(EngineLaws, EllipticJkrSphereDetachesOnceFromAWallAtThePullOff) {
  omp_set_num_threads(1);
  const double gamma = 0.05;
  World world({Superquadric::sphere(R)}, {Material{E, nu, rho, 0.0, 1.0}}, bigBox(), 0.1 * R);
  ContactModel model = world.defaultContactModel(0, 0);
  model.normal = EllipticJkrLaw{gamma};
  world.setContactModel(0, 0, model);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitX()}}});  // the wall x = 0, B is the sphere
  world.addParticle(0, 0, Vec3(R, 0.0, 0.0), Quat::Identity());
  world.setTimeStep(1e-6);
  const ClassicalJkr jkr{2.0 * gamma, R, effectiveModulus(E, nu, E, nu)};
  const auto at = [&](double delta) {  // the sphere's centre at R - delta from the wall
    ParticleStore& p = world.particles();
    p.velocity[0] = Vec3((R - delta - p.position[0].x()) / world.timeStep(), 0.0, 0.0);
    p.position[0] = Vec3(R - delta, 0.0, 0.0);
    world.computeForces();
    return world.contacts().empty() ? std::optional<double>() : std::optional(world.contacts().front().normalLoad().force);
  };
  const double scale = std::abs(jkr.detachmentOverlap());
  double tensile = 0.0, lastAttached = 0.0, firstDetached = 0.0;
  int detachments = 0;
  bool attached = false;
  for (double d : leg(-scale, scale, 200)) attached = at(d).has_value();
  ASSERT_TRUE(attached);
  for (double d : leg(scale, -2.0 * scale, 30000)) {
    const std::optional<double> f = at(d);
    if (f) {
      tensile = std::min(tensile, *f);
      lastAttached = d;
    } else if (attached) {
      ++detachments;
      firstDetached = d;
    }
    attached = f.has_value();
  }
  std::printf("pull-off %.6e N (JKR 3/2 pi W R %.6e N, %+.3f %%); detached once between overlaps %.5e and %.5e m "
              "(JKR %.5e m)\n", -tensile, jkr.pullOff(), 100.0 * (-tensile / jkr.pullOff() - 1.0), lastAttached,
              firstDetached, jkr.detachmentOverlap());
  EXPECT_NEAR(-tensile, jkr.pullOff(), 0.02 * jkr.pullOff());
  EXPECT_EQ(detachments, 1);
  EXPECT_LT(lastAttached, 0.0);  // it held across negative overlaps
  EXPECT_GE(lastAttached, jkr.detachmentOverlap() - 1e-3 * scale);
  EXPECT_LT(firstDetached, jkr.detachmentOverlap() + 1e-3 * scale);
  EXPECT_FALSE(at(0.5 * jkr.detachmentOverlap()).has_value());  // history gone: no contact at a gap
  EXPECT_TRUE(at(1e-3 * scale).has_value());                    // snap-in at overlap 0 again
}

// 4. An ellipsoid pair's most tensile force along a retraction is the driver's Johnson-Greenwood
// pull-off (004 Eqs. 19-28, lambda = sqrt(Ri/Rj) = 0.71) within 0.1 %.
TEST(EngineLaws, EllipticJkrEllipsoidPullOffEqualsTheDriver) {
  omp_set_num_threads(1);
  const double gamma = 0.05;
  const Body body = bodies()[1];
  World world = pair(body.shape, EllipticJkrLaw{gamma});
  const probe::DrivenLaw driver({{"type", "elliptic_jkr"}, {"surface_energy", gamma}}, "law", body.tips, {E, nu, E, nu}, 0.0);
  const double pullOff = driver.constants()["pull_off_force"].get<double>();
  const double scale = 2e-8;
  for (double d : leg(-scale, scale, 100)) driveTo(world, d);
  double tensile = 0.0;
  for (double d : leg(scale, -3.0 * scale, 20000)) tensile = std::min(tensile, driveTo(world, d).force);
  std::printf("ellipsoid pair pull-off: engine %.6e N, driver %.6e N (%+.4f %%)\n", tensile, pullOff,
              100.0 * (tensile / pullOff - 1.0));
  EXPECT_LT(pullOff, 0.0);
  EXPECT_NEAR(tensile, pullOff, 1e-3 * std::abs(pullOff));
}

// 4b. A carbon-binder bridge (issue 28's electrode: docs/bonds.md, "A coating on its current
// collector", and scene_reference.md, recipes): two NMC spheres (R 5 um, E 200 GPa) held by a
// binder sphere between them (R 0.5 um, E 2 GPa, JKR against the NMC with gamma = 0.1 J/m^2; the
// NMC spheres do not touch). Pulled apart symmetrically (the binder stays in the middle), the
// most tensile force on either NMC sphere is the classical JKR pull-off of one NMC-binder
// contact, 3/2 pi W R* with R* = R_nmc R_cbd / (R_nmc + R_cbd) and the two materials' E*
// (within 2 %, as a sphere on a wall above), and the bridge lets go on both sides at once.
TEST(EngineLaws, CarbonBinderBridgePullsOffAtTheJkrForceOfOneContact) {
  omp_set_num_threads(1);
  const double Rn = 5e-6, Rc = 0.5e-6, gamma = 0.1;
  const Material nmc{200e9, 0.3, 4700.0, 0.0, 1.0}, cbd{2e9, 0.3, 930.0, 0.0, 1.0};
  World world({Superquadric::sphere(Rn), Superquadric::sphere(Rc)}, {nmc, cbd}, bigBox(), 0.1 * Rc);
  world.setContactModel(0, 0, world.defaultContactModel(0, 0));
  world.setContactModel(1, 1, world.defaultContactModel(1, 1));
  ContactModel bridge = world.defaultContactModel(0, 1);
  bridge.normal = EllipticJkrLaw{gamma};
  world.setContactModel(0, 1, bridge);
  world.addParticle(0, 0, Vec3(-(Rn + Rc), 0.0, 0.0), Quat::Identity());
  world.addParticle(1, 1, Vec3::Zero(), Quat::Identity());
  world.addParticle(0, 0, Vec3(Rn + Rc, 0.0, 0.0), Quat::Identity());
  world.setTimeStep(1e-9);
  const ClassicalJkr jkr{2.0 * gamma, Rn * Rc / (Rn + Rc), effectiveModulus(nmc.youngsModulus, nmc.poissonRatio, cbd.youngsModulus, cbd.poissonRatio)};
  // Both NMC spheres at overlap delta with the binder; the force on the right one (> 0 pushing it away).
  const auto at = [&](double delta) {
    ParticleStore& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] == 1) continue;
      const double x = (p.id[i] == 0 ? -1.0 : 1.0) * (Rn + Rc - delta);
      p.velocity[i] = Vec3((x - p.position[i].x()) / world.timeStep(), 0.0, 0.0);
      p.position[i] = Vec3(x, 0.0, 0.0);
    }
    world.computeForces();
    struct Bridge {
      int contacts = 0;
      double right = 0.0;
    } b;
    for (const ContactView c : world.contacts()) {
      ++b.contacts;
      if (p.id[c.b()] == 2 || p.id[c.a()] == 2) b.right = c.normalLoad().force;
    }
    return b;
  };
  const double scale = std::abs(jkr.detachmentOverlap());
  for (double d : leg(-scale, scale, 200)) at(d);
  ASSERT_EQ(at(scale).contacts, 2);
  double tensile = 0.0;
  int oneSided = 0;  // steps at which one side held and the other had let go
  for (const double d : leg(scale, -2.0 * scale, 30000)) {
    const auto b = at(d);
    tensile = std::min(tensile, b.right);
    oneSided += b.contacts == 1;
  }
  std::printf("binder bridge pull-off %.6e N (JKR 3/2 pi W R* %.6e N, %+.3f %%, R* %.4e m, E* %.4e Pa)\n", -tensile, jkr.pullOff(),
              100.0 * (-tensile / jkr.pullOff() - 1.0), jkr.Rstar, jkr.Estar);
  EXPECT_NEAR(-tensile, jkr.pullOff(), 0.02 * jkr.pullOff());
  EXPECT_LE(oneSided, 1) << "the two sides let go at different overlaps";
  EXPECT_EQ(at(-2.0 * scale).contacts, 0);
}

// 5. Nan et al. in the engine: a sphere hitting a wall without viscous damping sticks below the
// critical sticking velocity V_ys of 000 Eqs. 73-79 (sticking_velocity.hpp) and rebounds above
// it; tested at 0.9 and 1.1 V_ys for 000 Table 5's particle (R = 2.45 um) on silicon, with
// p_y = 120 MPa (V_y > V_s: elastic adhesive sticking, V_ys = V_s) and 40 MPa (the contact yields:
// V_ys from the plastic energy balance of Eq. 79).
TEST(EngineLaws, NanSphereSticksBelowAndReboundsAboveTheStickingVelocity) {
  omp_set_num_threads(1);
  const double radius = 2.45e-6, Gamma = 0.24;  // Gamma: 000's work of adhesion W = 2 gamma
  const Material particle{1.2e9, 0.33, 1350.0, 0.0, 1.0}, silicon{166e9, 0.28, 2330.0, 0.0, 1.0};
  for (const double py : {120e6, 40e6}) {
    const StickingVelocities v = stickingVelocities({radius, 1350.0, 1.2e9, 0.33, 166e9, 0.28, Gamma, py});
    ASSERT_GT(v.Vys, 0.0);
    /// Whether the sphere is still attached after 20000 steps, and its final v_z / v_0.
    const auto impact = [&](double speed) {
      World world({Superquadric::sphere(radius)}, {particle, silicon}, bigBox(), 0.1 * radius);
      for (const std::uint32_t m : {0u, 1u}) world.setContactModel(m, m, world.defaultContactModel(m, m));
      ContactModel model = world.defaultContactModel(0, 1);
      model.normal = NanAdhesiveLaw{.surfaceEnergy = 0.5 * Gamma, .yieldPressure = py};
      world.setContactModel(0, 1, model);
      world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}, .material = 1});
      world.addParticle(0, 0, Vec3(0.0, 0.0, radius * (1.0 + 1e-4)), Quat::Identity());
      world.particles().velocity[0] = Vec3(0.0, 0.0, -speed);
      const double m = world.particles().mass[0], kEl = pi * radius * py;  // 000 Eq. 52
      world.setTimeStep(0.01 * nanCriticalTimeStep(m, kEl));
      int contactSteps = 0;
      for (int s = 0; s < 20000; ++s) {
        world.step();
        contactSteps += !world.contacts().empty();
      }
      EXPECT_GT(contactSteps, 0);
      return std::pair{!world.contacts().empty(), world.particles().velocity[0].z() / speed};
    };
    const auto [sticksBelow, velocityBelow] = impact(0.9 * v.Vys);
    const auto [sticksAbove, velocityAbove] = impact(1.1 * v.Vys);
    std::printf("p_y %.0f MPa: V_ys = %.4f m/s (V_s %.4f, V_y %.4f); at 0.9 V_ys %s (v_z/v_0 %+.3f), at 1.1 V_ys %s "
                "(v_z/v_0 %+.3f)\n", py * 1e-6, v.Vys, v.Vs, v.Vy, sticksBelow ? "attached" : "rebounds", velocityBelow,
                sticksAbove ? "attached" : "rebounds", velocityAbove);
    double lo = 0.9 * v.Vys, hi = 1.1 * v.Vys;  // the engine's own threshold, for the record
    for (int k = 0; k < 10; ++k) (impact(0.5 * (lo + hi)).first ? lo : hi) = 0.5 * (lo + hi);
    std::printf("  the engine's sticking threshold: %.4f m/s = %.4f V_ys\n", 0.5 * (lo + hi), 0.5 * (lo + hi) / v.Vys);
    EXPECT_TRUE(sticksBelow) << py;
    EXPECT_FALSE(sticksAbove) << py;
    EXPECT_GT(velocityAbove, 0.0) << py;
  }
}

// Issue 13's plate press on one particle: an NMC sphere (002 Table 1: E 142 GPa, nu 0.25,
// Y 7.9 GPa, the NMC fits of Eq. 54 for l_max and e_max) between a fixed floor and a plate that
// moves down at constant speed to 2.5 x the yield overlap per contact (17 % of the radius) and
// back up until it is free. Slow enough to be quasi-static (a background drag damps the sphere's
// oscillation; its lag behind equilibrium, m c v / k ~ 2e-13 m, is 2e-7 of the overlap), the two
// contacts are in series: the same law and the same force, so each carries half the plate's
// travel, and the plate force against the travel is the single-contact driver's
// sphere-on-a-wall curve at half the travel, loading and unloading.
TEST(EngineLaws, BeckerKamlahPlatePressIsTwoDriverContactsInSeries) {
  omp_set_num_threads(1);
  const double radius = 5e-6, Y = 7.9e9, dt = 1e-9, speed = 2e-3;
  const Material nmc{142e9, 0.25, 4750.0, 0.0, 1.0};
  World world({Superquadric::sphere(radius)}, {nmc}, bigBox(), 0.1 * radius);
  ContactModel model = world.defaultContactModel(0, 0);
  model.normal = BeckerKamlahLaw{{.yieldStrength = Y}};
  world.setContactModel(0, 0, model);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});                     // floor
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3(0.0, 0.0, 2.0 * radius), -Vec3::UnitZ()}}});  // plate
  world.addParticle(0, 0, Vec3(0.0, 0.0, radius), Quat::Identity());
  world.setTimeStep(dt);            // 0.2 x the Rayleigh time
  world.setViscousDamping(2.5e7);   // 1/s
  probe::DrivenLaw driver({{"type", "becker_kamlah"}, {"yield_strength", Y}}, "becker_kamlah",
                        {radius, radius, 1.0, 0.5 * radius},
                        {nmc.youngsModulus, nmc.poissonRatio, nmc.youngsModulus, nmc.poissonRatio}, 2.0 * radius);
  const double yieldOverlap = driver.yield()->overlap, deepest = 5.0 * yieldOverlap;
  const long steps = std::lround(deepest / (speed * dt)), sampleEvery = 1000;
  double worst = 0.0, largest = 0.0, freeTravel = -1.0;
  Wall &floor = world.walls()[0], &plate = world.walls()[1];
  for (long s = 1; s <= 2 * steps; ++s) {
    plate.velocity = Vec3(0.0, 0.0, s <= steps ? -speed : speed);
    world.step();
    if (s % sampleEvery != 0 && s != steps) continue;  // and the turning point: the largest overlap
    const double travel = 2.0 * radius - plate.get<PlaneWall>().plane.point.z();
    const probe::LawSample d = driver.at(0.5 * travel);
    worst = std::max(worst, std::abs(plate.force.z() - d.force));  // the sphere pushes the plate up: > 0
    largest = std::max(largest, d.force);
    if (freeTravel < 0.0 && s > steps && !(d.force > 0.0)) freeTravel = travel;
  }
  std::printf("plate press: delta_Y %.3e m, largest force %.4e N, plate - driver %.2e of it, floor + plate %.1e of it; "
              "the plate is free again at a travel of %.3f delta_Y (two plastic dents)\n",
              yieldOverlap, largest, worst / largest, std::abs(floor.force.z() + plate.force.z()) / largest,
              freeTravel / yieldOverlap);
  EXPECT_LE(worst, 1e-6 * largest);
  EXPECT_GT(freeTravel, 0.0) << "a permanent thickness reduction";
}

}  // namespace
}  // namespace sqdem

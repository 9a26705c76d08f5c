// Bonds in the engine (docs/bonds.md): the loads the World applies against the parallel bond's
// closed forms (Potyondy & Cundall 2004, Eqs. 10-11), its breakage at the strength, the series
// stiffness of a bonded chain of spheres and of ellipsoids, the energy of an undamped bonded
// pair, a particle bonded to a plane under gravity, and the automatic time step's bond limit on a
// bonded block, bonds through a checkpoint, and the energy ledger's bond terms.

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/mechanics/bond_frame.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

constexpr double r = 5e-6;  // sphere radius (m)
constexpr double E = 2e11, nu = 0.3, rho = 4700.0;
const ParallelBond bond{.radiusMultiplier = 0.5, .normalStiffness = 1e17, .shearStiffness = 4e16, .tensileStrength = 50e6,
                        .shearStrength = 80e6};
const BondSection section(bond.radiusMultiplier * r);

Domain bigBox() {
  Domain d;
  d.lo = Vec3::Constant(-1e-3);
  d.hi = Vec3::Constant(1e-3);
  return d;
}

/// A world of `shape`s with bonds `b` between them, frictionless and undamped (restitution 1).
World bondedWorld(const Superquadric& shape, const ParallelBond& b = bond) {
  World world({shape}, {Material{E, nu, rho, 0.0, 1.0}}, bigBox(), 0.2 * r);
  ContactModel model = world.defaultContactModel(0, 0);
  model.bond = b;
  world.setContactModel(0, 0, model);
  world.setTimeStep(1e-10);
  return world;
}

/// Particles along x, `gap` apart surface to surface (long axis along x), bonded.
World bondedChain(const Superquadric& shape, int count, double gap, const ParallelBond& b = bond) {
  World world = bondedWorld(shape, b);
  const double pitch = 2.0 * shape.a() + gap;
  for (int i = 0; i < count; ++i) world.addParticle(0, 0, Vec3(i * pitch, 0.0, 0.0), Quat::Identity());
  world.computeForces();
  EXPECT_EQ(world.formBonds(0.01), static_cast<std::size_t>(count - 1));
  return world;
}

/// Every particle's centre moved along x by stretch per pitch (uniform strain), forces computed.
void stretch(World& world, double perBond) {
  ParticleStore& p = world.particles();
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i].x() += static_cast<double>(p.id[i]) * perBond;
  world.computeForces();
}

// Tension through the engine: B pulled by u from A (both spheres, a gap of 1e-4 r so that no
// contact acts): B feels -k_n A u along x, A the opposite; no torque.
TEST(BondEngine, PairInTensionIsKnAu) {
  omp_set_num_threads(1);
  World world = bondedChain(Superquadric::sphere(r), 2, 1e-4 * r);
  const double u = 2e-10;
  stretch(world, u);
  const ParticleStore& p = world.particles();
  const double F = bond.normalStiffness * section.area * u;
  for (std::size_t i = 0; i < 2; ++i) {
    const double sign = p.id[i] == 1 ? -1.0 : 1.0;
    EXPECT_NEAR((p.force[i] - sign * F * Vec3::UnitX()).norm(), 0.0, 1e-9 * F) << "particle " << p.id[i];
    EXPECT_LT(p.torque[i].norm(), 1e-9 * F * r);
  }
  EXPECT_EQ(world.bondCount(), 1u);
}

// A bond acts beside the pair's contact law (docs/bonds.md): two spheres overlapping by
// delta = 1e-3 R and bonded where they are (the bond's rest state: it carries nothing) push apart
// with Hertz's 4/3 E* sqrt(R*) delta^1.5 (E* = E / (2 (1 - nu^2)), R* = R / 2) as they do unbonded.
TEST(BondEngine, BondedPairInContactKeepsItsHertzForce) {
  omp_set_num_threads(1);
  const double delta = 1e-3 * r, hertz = 4.0 / 3.0 * E / (2.0 * (1.0 - nu * nu)) * std::sqrt(0.5 * r) * std::pow(delta, 1.5);
  for (const bool bonded : {false, true}) {
    World world = bondedWorld(Superquadric::sphere(r));
    world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
    world.addParticle(0, 0, Vec3(2.0 * r - delta, 0.0, 0.0), Quat::Identity());
    world.computeForces();
    if (bonded) {
      ASSERT_EQ(world.formBonds(0.01), 1u);
      world.computeForces();
    }
    const ParticleStore& p = world.particles();
    for (std::size_t i = 0; i < 2; ++i) {
      const double sign = p.id[i] == 0 ? -1.0 : 1.0;
      EXPECT_NEAR((p.force[i] - sign * hertz * Vec3::UnitX()).norm(), 0.0, 1e-9 * hertz) << "bonded " << bonded << ", particle " << p.id[i];
    }
  }
}

// Bonds formed on a World that has not computed its forces yet find their pairs all the same
// (World::formBonds computes the candidates first): a chain of four, three bonds.
TEST(BondEngine, FormsBondsBeforeTheFirstComputation) {
  omp_set_num_threads(1);
  World world = bondedWorld(Superquadric::sphere(r));
  for (int i = 0; i < 4; ++i) world.addParticle(0, 0, Vec3(i * (2.0 + 1e-4) * r, 0.0, 0.0), Quat::Identity());
  EXPECT_EQ(world.formBonds(0.01), 3u);
  EXPECT_EQ(world.bondCount(), 3u);
}

// Breakage at the strength: stretched to u_c (1 -+ 1e-9), u_c = sigma_c / k_n, the bond holds,
// then breaks (counted) and carries nothing.
TEST(BondEngine, BreaksAtTheTensileStrength) {
  omp_set_num_threads(1);
  const double uc = bond.tensileStrength / bond.normalStiffness;
  for (const double f : {1.0 - 1e-9, 1.0 + 1e-9}) {
    World world = bondedChain(Superquadric::sphere(r), 2, 1e-4 * r);
    stretch(world, f * uc);
    EXPECT_EQ(world.bondCount(), f < 1.0 ? 1u : 0u) << f << " u_c";
    EXPECT_EQ(world.totalStatistics().bondsBroken, f < 1.0 ? 0 : 1);
    if (f > 1.0) EXPECT_EQ(world.particles().force[0], Vec3::Zero());
  }
}

// A chain of n bonds stretched uniformly by u each: the interior particles balance, the ends carry
// F = k_n A u, so the chain's stiffness F / (n u) is the series stiffness k_n A / n. Spheres, and
// ellipsoids end to end along their long axis (the bond's radius from the volume radius).
TEST(BondEngine, ChainUnderTensionHasTheSeriesStiffness) {
  omp_set_num_threads(1);
  for (const Superquadric& shape : {Superquadric::sphere(r), Superquadric::ellipsoid(1.6 * r, r, 0.8 * r)}) {
    const int count = 6;
    World world = bondedChain(shape, count, 1e-4 * r);
    const double u = 1e-10;
    stretch(world, u);
    const BondSection s(bond.radiusMultiplier * shape.volumeEquivalentRadius());
    const double F = bond.normalStiffness * s.area * u;
    const ParticleStore& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double expected = p.id[i] == 0 ? F : p.id[i] == count - 1 ? -F : 0.0;
      EXPECT_NEAR(p.force[i].x(), expected, 1e-9 * F) << "particle " << p.id[i];
    }
    const double chainStiffness = F / ((count - 1) * u);
    EXPECT_NEAR(chainStiffness, bond.normalStiffness * s.area / (count - 1), 1e-9 * chainStiffness);
  }
}

// Two bonded spheres released stretched, undamped and without contact: they oscillate, and the
// kinetic plus the bond's energy stays what the stretch stored (velocity Verlet: its error
// O((omega dt)^2), 1e-4 here).
TEST(BondEngine, UndampedBondKeepsItsEnergy) {
  omp_set_num_threads(1);
  World world = bondedChain(Superquadric::sphere(r), 2, 0.005 * r);
  const double u = 2e-10, k = bond.normalStiffness * section.area;  // below u_c = 5e-10 m
  stretch(world, u);
  const double mass = world.particles().mass[0], omega = std::sqrt(2.0 * k / mass);  // reduced mass m/2
  world.setTimeStep(0.02 / omega);
  const BondRecord& record = [&]() -> const BondRecord& {
    const ContactStore& s = world.interactions().store();
    for (std::size_t c = 0; c < s.size(); ++c) {
      if (s.bond[c].intact()) return s.bond[c];
    }
    throw std::runtime_error("no bond");
  }();
  const auto energy = [&] {
    const ParticleStore& p = world.particles();
    const std::size_t a = p.id[0] == 0 ? 0 : 1, b = 1 - a;
    const BondPlace place = bondPlace(record.rest, {p.position[a], p.orientation[a]}, {p.position[b], p.orientation[b]});
    return world.kineticEnergy() + bondLoads(bond, section, place.deformation).energy;
  };
  const double start = energy();
  EXPECT_NEAR(start, 0.5 * k * u * u, 1e-9 * start);
  double worst = 0.0;
  for (int s = 0; s < 2000; ++s) {  // ~6 periods
    world.step();
    worst = std::max(worst, std::abs(energy() / start - 1.0));
  }
  std::printf("undamped bond over 2000 steps of omega dt = 0.02: largest energy error %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
  EXPECT_EQ(world.bondCount(), 1u);
}

// A damped bond (docs/bonds.md, "Damping"): two bonded spheres released stretched oscillate as a
// damped harmonic oscillator of ratio beta (the dashpot 2 beta sqrt(k_n A m*) on their relative
// stretch, m* = m / 2, k = k_n A): successive maxima of the stretch fall by
// exp(-2 pi beta / sqrt(1 - beta^2)) and lie a damped period 2 pi / (omega sqrt(1 - beta^2))
// apart (the damped oscillator's closed form), at beta = 0.05 and 0.3.
TEST(BondEngine, DampedBondDecaysAtItsDampingRatio) {
  omp_set_num_threads(1);
  for (const double beta : {0.05, 0.3}) {
    ParallelBond damped = bond;
    damped.dampingRatio = beta;
    World world = bondedChain(Superquadric::sphere(r), 2, 0.005 * r, damped);
    const double u = 2e-10, k = bond.normalStiffness * section.area;
    stretch(world, u);
    const ParticleStore& p = world.particles();
    const double pitch = std::abs(p.position[1].x() - p.position[0].x()) - u;
    const double omega = std::sqrt(2.0 * k / p.mass[0]), damping = std::sqrt(1.0 - beta * beta);
    world.setTimeStep(0.002 / omega);
    struct Peak {
      double time, stretch;
    };
    std::vector<Peak> peaks;
    double before = u, now = u;
    for (int s = 0; s < 40000 && peaks.size() < 4; ++s) {  // ~13 periods at most
      world.step();
      const double next = std::abs(p.position[1].x() - p.position[0].x()) - pitch;
      if (now > before && now >= next && now > 0.0) peaks.push_back({world.time() - world.timeStep(), now});
      before = now;
      now = next;
    }
    ASSERT_GE(peaks.size(), 2u);
    const double ratio = peaks[1].stretch / peaks[0].stretch, period = peaks[1].time - peaks[0].time;
    const double expectedRatio = std::exp(-2.0 * std::numbers::pi * beta / damping);
    const double expectedPeriod = 2.0 * std::numbers::pi / (omega * damping);
    std::printf("damped bond, beta %.2f: peak ratio %.6f (closed form %.6f), period %.6e s (%.6e s)\n", beta, ratio, expectedRatio,
                period, expectedPeriod);
    EXPECT_NEAR(ratio / expectedRatio, 1.0, 2e-3);
    EXPECT_NEAR(period / expectedPeriod, 1.0, 1e-3);
    EXPECT_EQ(world.bondCount(), 1u);
  }
}

// A sphere hanging from a plane (the current collector) by a bond: under 1e4 g it stays put,
// hanging by the static stretch m g / (k_n A); it holds up to the weight the bond carries,
// m g = sigma_c A (straight under it, no bending), and breaks beyond. Overdamped by a drag of
// 4 omega, so that the load comes on without overshoot.
TEST(BondEngine, ParticleBondedToAPlaneHoldsItsWeightUpToTheStrength) {
  omp_set_num_threads(1);
  const double mass = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r, k = bond.normalStiffness * section.area;
  const double strength = bond.tensileStrength * section.area / mass;  // the gravity the bond holds (m/s^2)
  for (const double g : {1e4 * 9.81, 0.9 * strength, 1.1 * strength}) {
    World world = bondedWorld(Superquadric::sphere(r));
    world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), -Vec3::UnitZ()}}});  // a ceiling at z = 0, the sphere below
    const double z0 = -r - 1e-4 * r;
    world.addParticle(0, 0, Vec3(0.0, 0.0, z0), Quat::Identity());
    world.computeForces();
    ASSERT_EQ(world.formBonds(0.01), 1u);
    world.setGravity(Vec3(0.0, 0.0, -g));
    world.setViscousDamping(4.0 * std::sqrt(k / mass));
    for (int s = 0; s < 5000 && world.bondCount() == 1; ++s) world.step();
    const double sag = z0 - world.particles().position[0].z();
    std::printf("gravity %.4g m/s^2 (%.4g of what the bond holds): bond %s, sag %.4e m (m g / k_n A = %.4e m)\n", g,
                g / strength, world.bondCount() == 1 ? "holds" : "broke", sag, mass * g / k);
    EXPECT_EQ(world.bondCount(), g < strength ? 1u : 0u);
    if (g < strength) EXPECT_NEAR(sag, mass * g / k, 1e-6 * mass * g / k);
  }
}

// The bond limit of the automatic step (docs/bonds.md, "Time step"): a 3 x 3 x 3 block of bonded
// spheres (up to 6 bonds each, 54 in all) with stiff bonds (the bond's 1/omega is 4x shorter than
// the Rayleigh step), given random velocities and spins and stepped undamped, no contact touching.
// At 0.2 / omega its energy (kinetic plus the bonds') stays within velocity Verlet's bound for
// the fastest mode, (omega_max dt)^2 / 4 with omega_max <= sqrt(2 Z) omega (0.12 at Z = 6), and
// does not drift: the mean of the last 2,000 of 20,000 steps is the first 2,000's to 1e-3. At
// 0.2 x the Rayleigh time alone (ignoring the bonds: omega dt = 0.8 per bond, near Verlet's limit
// of 2 for the fastest modes) the energy is wrong by more than itself.
TEST(BondEngine, TheAutomaticStepKeepsABondedBlockStable) {
  omp_set_num_threads(1);
  struct Record {
    double worst = 0.0, drift = 0.0;
  };
  const auto block = [](double dt) {
    World world = bondedWorld(Superquadric::sphere(r));
    const double pitch = 2.0 * r + 1e-3 * r;
    for (int i = 0; i < 27; ++i) world.addParticle(0, 0, pitch * Vec3(i % 3, (i / 3) % 3, i / 9), Quat::Identity());
    world.computeForces();
    EXPECT_EQ(world.formBonds(0.01), 54u);
    std::mt19937_64 random(5);
    std::normal_distribution<double> speed(0.0, 0.01);  // m/s: bonds stretched ~ 1e-11 m, far below u_c
    for (std::size_t i = 0; i < world.particles().size(); ++i) {
      world.particles().velocity[i] = Vec3(speed(random), speed(random), speed(random));
      world.particles().setAngularVelocity(i, Vec3(speed(random), speed(random), speed(random)) / r);
    }
    world.setTimeStep(dt);
    world.computeForces();
    const auto energy = [&world] {
      double bonds = 0.0;
      for (const BondReport& b : world.bonds()) bonds += b.loads.energy;
      return world.kineticEnergy() + bonds;
    };
    const double start = energy();
    const int steps = 20000, window = 2000;
    Record record;
    double first = 0.0, last = 0.0;
    for (int s = 0; s < steps; ++s) {
      world.step();
      const double e = energy();
      record.worst = std::max(record.worst, std::abs(e / start - 1.0));
      if (s < window) first += e;
      if (s >= steps - window) last += e;
    }
    record.drift = std::abs(last / first - 1.0);
    EXPECT_EQ(world.bondCount(), 54u);
    return record;
  };
  World probe = bondedWorld(Superquadric::sphere(r));
  probe.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
  const double bondStep = probe.bondTimeStep(), rayleigh = probe.rayleighTimeStep();
  ASSERT_LT(bondStep, rayleigh);
  const Record automatic = block(0.2 * bondStep), rayleighOnly = block(0.2 * rayleigh);
  std::printf("bonded block, 20,000 undamped steps: at 0.2 / omega_bond = %.3e s energy within %.2e, drift %.1e; "
              "at 0.2 x Rayleigh = %.3e s within %.2e, drift %.1e\n",
              0.2 * bondStep, automatic.worst, automatic.drift, 0.2 * rayleigh, rayleighOnly.worst, rayleighOnly.drift);
  EXPECT_LT(automatic.worst, 0.12);
  EXPECT_LT(automatic.drift, 1e-3);
  EXPECT_GT(rayleighOnly.worst, 1.0);
}

// Bonds through a checkpoint (docs/bonds.md, "Where it lives"): a bonded block shaken hard
// enough that bonds keep breaking, its state written midway and read into a fresh world: both
// continue to the same bits (every particle's state, every bond's place and loads), with the same bonds
// broken before and after the checkpoint. (Compared value by value: a payload's bytes include
// the padding of some records, which two writes of one state need not share.)
TEST(BondEngine, BondsContinueThroughACheckpoint) {
  omp_set_num_threads(1);
  const auto shaken = [] {
    World world = bondedWorld(Superquadric::ellipsoid(1.2 * r, r, 0.8 * r));
    const double pitch = 2.4 * r + 1e-3 * r;
    for (int i = 0; i < 27; ++i) {
      world.addParticle(0, 0, Vec3(pitch * (i % 3), 2.0 * r * ((i / 3) % 3), 1.6 * r * (i / 9)) * (1.0 + 1e-3), Quat::Identity());
    }
    world.computeForces();
    EXPECT_GT(world.formBonds(0.01), 40u);
    std::mt19937_64 random(11);
    std::normal_distribution<double> speed(0.0, 0.3);  // m/s: stretches of order u_c
    for (std::size_t i = 0; i < world.particles().size(); ++i) {
      world.particles().velocity[i] = Vec3(speed(random), speed(random), speed(random));
    }
    world.setTimeStep(0.2 * world.bondTimeStep());
    return world;
  };
  World original = shaken();
  const std::size_t formed = original.bondCount();
  for (int s = 0; s < 10; ++s) original.step();
  CheckpointWriter midway;
  original.writeState(midway);
  const long long brokenMidway = original.totalStatistics().bondsBroken;
  for (int s = 0; s < 2000; ++s) original.step();
  World resumed = shaken();
  CheckpointReader in(midway.bytes());
  resumed.readState(in);
  for (int s = 0; s < 2000; ++s) resumed.step();
  std::printf("shaken block: %zu bonds formed, %lld broke before the checkpoint, %lld after, %zu intact\n", formed, brokenMidway,
              original.totalStatistics().bondsBroken - brokenMidway, original.bondCount());
  EXPECT_GT(brokenMidway, 0);
  EXPECT_GT(original.totalStatistics().bondsBroken, brokenMidway);
  EXPECT_GT(original.bondCount(), 0u);
  EXPECT_EQ(resumed.totalStatistics().bondsBroken, original.totalStatistics().bondsBroken);
  EXPECT_EQ(resumed.bondCount(), original.bondCount());
  const ParticleStore &p = resumed.particles(), &q = original.particles();
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.id[i], q.id[i]);
    EXPECT_EQ(p.position[i], q.position[i]) << "particle " << p.id[i];
    EXPECT_EQ(p.orientation[i].coeffs(), q.orientation[i].coeffs()) << "particle " << p.id[i];
    EXPECT_EQ(p.velocity[i], q.velocity[i]) << "particle " << p.id[i];
    EXPECT_EQ(p.angularVelocity[i], q.angularVelocity[i]) << "particle " << p.id[i];
    EXPECT_EQ(p.force[i], q.force[i]) << "particle " << p.id[i];
    EXPECT_EQ(p.torque[i], q.torque[i]) << "particle " << p.id[i];
  }
  const std::vector<BondReport> a = resumed.bonds(), b = original.bonds();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const ContactStore &s = resumed.interactions().store(), &t = original.interactions().store();
    EXPECT_EQ(s.key(a[k].contact), t.key(b[k].contact));
    EXPECT_EQ(a[k].centre, b[k].centre);
    EXPECT_EQ(a[k].loads.force, b[k].loads.force);
    EXPECT_EQ(a[k].loads.moment, b[k].loads.moment);
  }
}

// The energy ledger with bonds (world/energy_ledger.hpp): a sphere hanging from a plane by a bond,
// released unstretched under a gravity 0.52 of what the bond holds and undamped: it swings down
// to about twice its static sag, past u_c = sigma_c / k_n, and the bond breaks. Before the break
// the bond stores U = k_n A u^2 / 2 and dissipates nothing (D_bonds only the quadrature error);
// as it breaks, what it held is released: D_bonds = k_n A u_c^2 / 2 = sigma_c^2 A / (2 k_n), to
// twice the stretch of the last step. Throughout, the work of gravity is the kinetic energy,
// U_bonds and D_bonds but for velocity Verlet's own term (|F_n|^2 - |F_0|^2) dt^2 / 8m (the
// ledger's residual, contact_work.hpp), to 1e-9 of the work.
TEST(BondEngine, TheLedgerStoresABondsEnergyAndReleasesItAsItBreaks) {
  omp_set_num_threads(1);
  const double mass = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r, k = bond.normalStiffness * section.area;
  const double uc = bond.tensileStrength / bond.normalStiffness, released = 0.5 * k * uc * uc;
  World world = bondedWorld(Superquadric::sphere(r));
  world.enableEnergyLedger();
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), -Vec3::UnitZ()}}});
  world.addParticle(0, 0, Vec3(0.0, 0.0, -r - 1e-4 * r), Quat::Identity());
  world.setGravity(Vec3(0.0, 0.0, -0.52 * bond.tensileStrength * section.area / mass));
  world.setTimeStep(1e-11);  // omega dt = 0.009
  world.computeForces();
  ASSERT_EQ(world.formBonds(0.01), 1u);
  const double F0 = world.particles().force[0].squaredNorm(), dt = world.timeStep();
  double lastStretch = 0.0, stretch = 0.0, worstResidual = 0.0, heldDissipation = 0.0;
  int steps = 0;
  for (; steps < 50000 && world.bondCount() == 1; ++steps) {
    world.step();
    const EnergyLedger& e = *world.energyLedger();
    const double verlet = (world.particles().force[0].squaredNorm() - F0) * dt * dt / (8.0 * mass);
    worstResidual = std::max(worstResidual, std::abs(e.residual(world.kineticEnergy()) + verlet));
    if (world.bondCount() == 1) {
      lastStretch = stretch;
      stretch = world.bonds().at(0).loads.normalForce / k;
      EXPECT_NEAR(e.bondStored, 0.5 * k * stretch * stretch, 1e-12 * released);
      heldDissipation = std::max(heldDissipation, std::abs(e.bondDissipation()));
    }
  }
  ASSERT_EQ(world.bondCount(), 0u) << "the bond held";
  const EnergyLedger& e = *world.energyLedger();
  worstResidual /= e.gravity;
  const double increment = stretch - lastStretch;  // the stretch of the last steps before the break
  std::printf("bond broke after %d steps: D_bonds %.6e J, sigma_c^2 A / 2 k_n %.6e J (%.2e off; the last step stretched "
              "it by %.2e u_c); held: |D_bonds| <= %.2e of it; residual less Verlet's term <= %.2e of the work of gravity\n",
              steps, e.bondDissipation(), released, e.bondDissipation() / released - 1.0, increment / uc,
              heldDissipation / released, worstResidual);
  EXPECT_EQ(e.bondStored, 0.0);
  EXPECT_NEAR(e.bondDissipation(), released, 2.0 * increment / uc * released);
  EXPECT_LT(heldDissipation, 1e-6 * released);
  EXPECT_LT(worstResidual, 1e-9);
}

}  // namespace
}  // namespace sqdem

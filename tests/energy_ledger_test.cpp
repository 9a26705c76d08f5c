// The energy ledger (world/energy_ledger.hpp) of a plate press: a poured bed of 200 ellipsoids
// with friction and damping, pressed by a plate and released, balances the work of the plate and
// of gravity against kinetic, stored and dissipated energy. Closed form checked: the balance
// itself, W_bodies + W_gravity = dE_kin + dU + D_plastic + D_damping + D_tangential + D_drag.

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/scene_loader.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {
namespace {

// Ellipsoids poured into a box periodic in x and y onto a floor; wall 1 is the plate, parked
// above the bed. {law} is filled in per case.
const char* pressScene = R"(seed: 11
domain: {lo: [0, 0, 0], hi: [8.0e-3, 8.0e-3, 14.0e-3], periodic: [x, y]}
gravity: [0, 0, -9.81]
time_step: 2.0e-6
materials:
  glass: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 2500, friction: 0.4, restitution: 0.3, yield_strength: 2.0e4}
shapes:
  grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}
interactions:
  - {materials: [glass, glass], normal: {law}}
walls:
  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}
  - {point: [0, 0, 13.9e-3], normal: [0, 0, -1], material: glass}
insert:
  - {count: 200, shape: grains, material: glass, region: {lo: [0, 0, 0.8e-3], hi: [8.0e-3, 8.0e-3, 8.0e-3]}}
stages:
  - {name: press, duration: 0.1}
output:
  energy: true
)";

Scene sceneWith(const std::string& law) {
  std::string text = pressScene;
  text.replace(text.find("{law}"), 5, law);
  const auto path = std::filesystem::temp_directory_path() / ("sqdem_test_ledger_" + law + ".yaml");
  std::ofstream(path) << text;
  return loadScene(path.string());
}

/// W_bodies + W_gravity: the work done on the particles (J).
double workDone(const EnergyLedger& e) { return e.bodies + e.gravity; }

struct PressResult {
  EnergyLedger atRest, pressed, released;
  double kineticAtRest = 0.0, kineticPressed = 0.0, kineticReleased = 0.0;
  double worstResidual = 0.0;  ///< largest |residual| / work done, sampled every 500 steps
};

/// Pours the bed (drag 50 1/s, terminal speed 0.2 m/s), parks the plate 0.1 mm above it (the
/// plate has not touched it: no work), lowers it at 0.05 m/s until it carries 2 kPa, raises it
/// at the same speed to where it turned plus 1 mm, and lets the bed rest.
PressResult pressCycle(World& world) {
  PressResult r;
  const auto track = [&](long s) {
    if (s % 500 != 0) return;
    const EnergyLedger& e = *world.energyLedger();
    r.worstResidual = std::max(r.worstResidual, std::abs(e.residual(world.kineticEnergy())) / workDone(e));
  };
  world.setViscousDamping(50.0);
  for (long s = 1; s <= 25000; ++s) world.step(), track(s);
  world.setViscousDamping(0.0);
  for (long s = 1; s <= 5000; ++s) world.step(), track(s);
  r.atRest = *world.energyLedger();
  r.kineticAtRest = world.kineticEnergy();
  Wall& plate = world.walls()[1];
  const ParticleStore& p = world.particles();
  double top = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].z() + world.shapes()[p.shape[i]].boundingRadius());
  if (plate.force != Vec3::Zero()) throw std::runtime_error("the bed reached the parked plate");
  plate.get<PlaneWall>().plane.point.z() = top + 0.1e-3;
  plate.velocity = Vec3(0.0, 0.0, -0.05);
  for (long s = 1; world.wallPressure(1) < 2000.0; ++s) {
    world.step(), track(s);
    if (s > 200000) throw std::runtime_error("the plate never reached 2 kPa");
  }
  r.pressed = *world.energyLedger();
  r.kineticPressed = world.kineticEnergy();
  const double lowest = plate.get<PlaneWall>().plane.point.z();
  plate.velocity = Vec3(0.0, 0.0, 0.05);
  for (long s = 1; plate.get<PlaneWall>().plane.point.z() < lowest + 1e-3; ++s) world.step(), track(s);
  plate.velocity.setZero();
  for (long s = 1; s <= 20000; ++s) world.step(), track(s);
  r.released = *world.energyLedger();
  r.kineticReleased = world.kineticEnergy();
  return r;
}

void print(const char* name, const EnergyLedger& e, double kinetic) {
  std::printf("%-8s W_bodies %.4e W_gravity %.4e | E_kin %.3e U %.4e plastic %.4e damping %.4e tangential %.4e drag %.4e | "
              "residual %.3e (%.2e of the work)\n",
              name, e.bodies, e.gravity, kinetic, e.stored, e.plastic(), e.damping, e.tangential, e.drag, e.residual(kinetic),
              e.residual(kinetic) / workDone(e));
}

class EnergyLedgerPress : public ::testing::TestWithParam<const char*> {};

// The balance holds to 1 % of the work done at every sample through the pour, the press and
// the release (issue 13); over the press and release alone its residual stays below 1 % of
// the plate's work. Elastic contacts (Hertz) give back what they stored: the "plastic" column
// is the quadrature error and stays below 1 % of the work too; Becker-Kamlah contacts yield
// (Y = 20 kPa against ~kPa plate pressures on mm grains) and keep a part of the plate's work
// in their dents.
TEST_P(EnergyLedgerPress, BalancesThroughPourPressAndRelease) {
  omp_set_num_threads(2);
  World world = buildWorld(sceneWith(GetParam()));
  const PressResult r = pressCycle(world);
  print("at rest", r.atRest, r.kineticAtRest);
  print("pressed", r.pressed, r.kineticPressed);
  print("released", r.released, r.kineticReleased);
  const double plateWork = r.released.bodies - r.atRest.bodies;
  const double pressResidual = r.released.residual(r.kineticReleased) - r.atRest.residual(r.kineticAtRest);
  const double plastic = r.released.plastic() - r.atRest.plastic();
  std::printf("%s: worst residual %.2e of the work done; press: plate work %.4e J, residual %.2e of it, plastic %.3f of it\n",
              GetParam(), r.worstResidual, plateWork, pressResidual / plateWork, plastic / plateWork);
  ASSERT_GT(plateWork, 0.1 * workDone(r.atRest));  // the press did work comparable to the pour's
  EXPECT_LT(r.worstResidual, 1e-2);
  EXPECT_LT(std::abs(pressResidual), 1e-2 * plateWork);
  EXPECT_EQ(world.statistics().detectorFailures, 0);
  if (std::string(GetParam()) == "elliptic_hertz") {
    EXPECT_LT(std::abs(r.released.plastic()), 1e-2 * workDone(r.released));
  } else {
    EXPECT_GT(plastic, 0.05 * plateWork);
  }
}

INSTANTIATE_TEST_SUITE_P(Laws, EnergyLedgerPress, ::testing::Values("elliptic_hertz", "becker_kamlah"));

// The ledger is part of the world's state: a run resumed from a checkpoint continues it bit for bit.
TEST(EnergyLedger, CheckpointCarriesIt) {
  omp_set_num_threads(1);
  const Scene scene = sceneWith("becker_kamlah");
  World original = buildWorld(scene);
  for (int s = 0; s < 3000; ++s) original.step();
  CheckpointWriter checkpoint;
  original.writeState(checkpoint);
  World resumed = buildWorld(scene);
  CheckpointReader reader(checkpoint.bytes());
  resumed.readState(reader);
  for (int s = 0; s < 1000; ++s) original.step(), resumed.step();
  const EnergyLedger &a = *original.energyLedger(), &b = *resumed.energyLedger();
  ASSERT_GT(a.gravity, 0.0);
  EXPECT_EQ(a.bodies, b.bodies);
  EXPECT_EQ(a.gravity, b.gravity);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.damping, b.damping);
  EXPECT_EQ(a.tangential, b.tangential);
  EXPECT_EQ(a.drag, b.drag);
  EXPECT_EQ(a.stored, b.stored);
  EXPECT_EQ(a.initialKinetic, b.initialKinetic);
  EXPECT_EQ(a.initialStored, b.initialStored);
}

}  // namespace
}  // namespace sqdem

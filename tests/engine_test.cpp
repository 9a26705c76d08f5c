// The engine end to end on small scenes: thread-count independence (bitwise), static
// equilibrium of a resting bed, and the scene loader's error messages.

#include <gtest/gtest.h>
#include <omp.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <fstream>

#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/scene_loader.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/stage_runner.hpp"
#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

std::string writeScene(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("sqdem_test_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

// A small poured bed of ellipsoids in a box periodic in x and y (SI units).
const char* bedScene = R"(seed: 7
domain: {lo: [0, 0, 0], hi: [6.0e-3, 6.0e-3, 12.0e-3], periodic: [x, y]}
gravity: [0, 0, -9.81]
time_step: 2.0e-6
materials:
  glass: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 2500, friction: 0.4, restitution: 0.3}
shapes:
  grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}
interactions:
  - materials: [glass, glass]
walls:
  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}
insert:
  - {count: 60, shape: grains, material: glass, region: {lo: [0, 0, 1.0e-3], hi: [6.0e-3, 6.0e-3, 11.0e-3]}}
stages:
  - {name: settle, duration: 0.2}
)";

/// The scene's world after `steps` steps under gravity and a background drag (1/s) that keeps
/// the pour gentle; the drag stays on.
World pouredBed(const Scene& scene, double drag, int steps) {
  World world = buildWorld(scene);
  world.setViscousDamping(drag);
  for (int s = 0; s < steps; ++s) world.step();
  return world;
}

struct BedState {
  std::vector<Vec3> positions;
  std::size_t contacts;
};

BedState runBed(int threads, int steps) {
  omp_set_num_threads(threads);
  // Terminal velocity 0.2 m/s: the bed forms within the run.
  const World world = pouredBed(loadScene(writeScene("bed", bedScene)), 50.0, steps);
  return {world.particles().position, world.contacts().size()};
}

// docs/architecture.md, "A step": contact-then-reduce in a fixed order, so 1 and 2 threads give identical bits.
TEST(Engine, ResultsDoNotDependOnTheThreadCount) {
  const BedState a = runBed(1, 40000), b = runBed(2, 40000);
  ASSERT_GT(a.contacts, 40u);  // the run exercises many contacts
  const std::vector<Vec3>&one = a.positions, &two = b.positions;
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    for (int d = 0; d < 3; ++d) ASSERT_EQ(one[i](d), two[i](d)) << "particle " << i;
  }
}

// The true-gap law's rungs are solved by the whole team from one queue, after the kernels and
// before the laws that wait for them (docs/architecture.md, "A step"): a bed of blocky grains
// (n = 5, where every contact takes rungs) gives the same bits, the same rungs and no fallback
// on 1 and 2 threads.
TEST(Engine, TrueGapRungsFromTheTeamsQueueDoNotDependOnTheThreadCount) {
  std::string scene = replaced(bedScene, "grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}",
                               "grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2], n1: 5, n2: 5}");
  scene = replaced(scene, "- materials: [glass, glass]", "- {materials: [glass, glass], normal: true_gap, curvature_tolerance: 1.0e-2}");
  scene = replaced(scene, "count: 60", "count: 40");
  scene = replaced(scene, "hi: [6.0e-3, 6.0e-3, 11.0e-3]", "hi: [6.0e-3, 6.0e-3, 4.0e-3]");  // a bed within the run
  const auto run = [&](int threads) {
    omp_set_num_threads(threads);
    return pouredBed(loadScene(writeScene("true_gap_bed", scene)), 50.0, 20000);
  };
  const World one = run(1), two = run(2);
  const ContactStatistics &a = one.totalStatistics(), &b = two.totalStatistics();
  std::printf("%zu contacts, %lld rungs solved, %lld detector calls\n", one.contacts().size(), a.trueGapRungs, a.detectorCalls);
  ASSERT_GT(one.contacts().size(), 15u);
  EXPECT_GT(a.trueGapRungs, 500);
  EXPECT_EQ(a.trueGapRungs, b.trueGapRungs);
  EXPECT_EQ(a.trueGapFallbacks, 0);
  EXPECT_EQ(b.trueGapFallbacks, 0);
  ASSERT_EQ(one.particles().position, two.particles().position);
}

// Newton's third law and equilibrium: once the bed is at rest, the bottom wall carries the
// weight of all particles, sum m g, within 0.1 %.
// Both broad phases return the same sorted candidate list (neighbour_list_test.cpp), so a run
// with FCL's AABB tree is bit for bit the run with the cell list.
TEST(Engine, AabbTreeBroadPhaseGivesTheCellListRun) {
  omp_set_num_threads(2);
  const World cells = pouredBed(loadScene(writeScene("bed", bedScene)), 50.0, 40000);
  const World tree = pouredBed(loadScene(writeScene("tree", replaced(bedScene, "seed: 7", "seed: 7\nbroad_phase: aabb_tree"))),
                               50.0, 40000);
  ASSERT_EQ(tree.neighbourList().search(), BroadPhase::AabbTree);
  ASSERT_GT(cells.contacts().size(), 40u);
  ASSERT_EQ(cells.particles().position, tree.particles().position);
  ASSERT_EQ(cells.neighbourList().builds(), tree.neighbourList().builds());
}

TEST(Engine, RestingBedWallForceEqualsWeight) {
  World world = pouredBed(loadScene(writeScene("bed", bedScene)), 200.0, 40000);  // pour gently,
  world.setViscousDamping(0.0);  // then rest under contact damping alone
  double weight = 0.0;
  for (std::size_t i = 0; i < world.particles().size(); ++i) weight += world.particles().mass[i] * 9.81;
  double error = 1.0;
  for (int s = 0; s < 200000 && error > 1e-4; ++s) {
    world.step();
    if (s % 1000 == 0) error = std::abs(-world.walls()[0].force.z() - weight) / weight;
  }
  std::printf("wall force / weight - 1 = %.3g, kinetic energy %.3g J, %zu contacts\n",
              -world.walls()[0].force.z() / weight - 1.0, world.kineticEnergy(), world.contacts().size());
  EXPECT_LT(error, 1e-3);
  EXPECT_EQ(world.statistics().detectorFailures, 0);
  // Virial identity of a static bed on the wall z = 0: sigma_zz V = sum m g z_i.
  const PackingMeasures m = measurePacking(world);
  double moment = 0.0;
  for (std::size_t i = 0; i < world.particles().size(); ++i) moment += world.particles().mass[i] * 9.81 * world.particles().position[i].z();
  std::printf("sigma_zz V / sum(m g z) - 1 = %.3g\n", m.stress(2, 2) * m.stressVolume / moment - 1.0);
  EXPECT_NEAR(m.stress(2, 2) * m.stressVolume, moment, 2e-3 * moment);
}

// A checkpoint restores the state so that the continuation is bitwise identical.
TEST(Engine, CheckpointRestartContinuesBitwise) {
  const Scene scene = loadScene(writeScene("bed", bedScene));
  World original = pouredBed(scene, 50.0, 30000);
  CheckpointWriter checkpoint;
  original.writeState(checkpoint);
  for (int s = 0; s < 5000; ++s) original.step();

  World resumed = buildWorld(scene);  // same scene: same shapes and laws, fresh state
  const std::string& payload = checkpoint.bytes();
  CheckpointReader reader(payload);
  resumed.readState(reader);
  for (int s = 0; s < 5000; ++s) resumed.step();
  ASSERT_GT(original.contacts().size(), 20u);
  ASSERT_EQ(resumed.time(), original.time());
  for (std::size_t i = 0; i < original.particles().size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(resumed.particles().position[i](d), original.particles().position[i](d)) << "particle " << i;
      ASSERT_EQ(resumed.particles().velocity[i](d), original.particles().velocity[i](d)) << "particle " << i;
    }
  }
  CheckpointReader garbage("not a checkpoint");
  EXPECT_THROW(resumed.readState(garbage), CheckpointError);
}

// Force control: a servo-controlled lid reaches its target pressure on a settled bed and holds
// it within 1 % over the next 20000 steps; the bottom wall then carries the weight plus the
// lid's force (static equilibrium). At max_speed 0.02 m/s and at 1 m/s (50 x; before the servo
// read the elastic load and limited its step by the contact stiffness, the lid chattered in and
// out of the bed at 0.2 m/s and 1 m/s and never held the target: world.hpp, WallServo).
class ServoWall : public testing::TestWithParam<double> {};

TEST_P(ServoWall, ReachesAndHoldsItsPressure) {
  const std::string lidded = replaced(bedScene, "  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}\n",
                                      "  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}\n"
                                      "  - {point: [0, 0, 11.8e-3], normal: [0, 0, -1], material: glass}\n");
  World world = pouredBed(loadScene(writeScene("lid", lidded)), 200.0, 40000);
  world.setViscousDamping(0.0);
  const double target = 50.0;  // Pa, about twice the bed's own weight per area
  world.walls()[1].servo = WallServo{target, GetParam()};
  double weight = 0.0;
  for (std::size_t i = 0; i < world.particles().size(); ++i) weight += world.particles().mass[i] * 9.81;
  double pressureError = 1.0, balance = 1.0;
  int s = 0;
  for (; s < 300000 && (pressureError > 1e-3 || balance > 1e-3); ++s) {
    world.step();
    if (s % 1000 == 0) {
      pressureError = std::abs(world.wallPressure(1) / target - 1.0);
      balance = std::abs((-world.walls()[0].force.z() - world.walls()[1].force.z()) / weight - 1.0);
    }
  }
  double worstHeld = 0.0;
  for (int h = 0; h < 20000; ++h) {
    world.step();
    worstHeld = std::max(worstHeld, std::abs(world.wallPressure(1) / target - 1.0));
  }
  std::printf("max_speed %.2f m/s: target reached after %d steps, lid pressure %.4f Pa (target %.1f), "
              "bottom force / (weight + lid force) - 1 = %.2g, largest deviation over 20000 more steps %.2g\n",
              GetParam(), s, world.wallPressure(1), target, balance, worstHeld);
  EXPECT_LT(pressureError, 1e-3);
  EXPECT_LT(balance, 1e-3);
  EXPECT_LT(worstHeld, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Engine, ServoWall, testing::Values(0.02, 1.0));

// Hilbert re-ordering (spatial_order.hpp) moves particles to new slots. Contacts are keyed and
// oriented by particle ids, each particle sums its contacts in key order and walls sum exactly
// (interactions.hpp), so a bed poured with its slots never re-ordered and one re-ordered at every
// neighbour-list build are the same run: every particle's force, position and velocity, and the
// floor's load, bit for bit.
TEST(Engine, HilbertReorderingChangesNoBit) {
  const auto pour = [](int every) {
    return pouredBed(loadScene(writeScene("bed", replaced(bedScene, "seed: 7", "seed: 7\nreorder_every: " + std::to_string(every)))),
                     50.0, 60000);
  };
  const World inserted = pour(0), reordered = pour(1);
  ASSERT_NE(reordered.particles().id, inserted.particles().id);  // the order did change
  const auto byId = [](const World& w, const std::vector<Vec3>& values) {
    std::vector<Vec3> out(w.particles().size());  // the owned particles (ghosts follow them)
    for (std::size_t i = 0; i < out.size(); ++i) out[w.particles().id[i]] = values[i];
    return out;
  };
  EXPECT_GT(inserted.neighbourList().builds(), 10);
  ASSERT_GT(inserted.contacts().size(), 50u);
  EXPECT_EQ(inserted.contacts().size(), reordered.contacts().size());
  EXPECT_EQ(byId(inserted, inserted.particles().force), byId(reordered, reordered.particles().force));
  EXPECT_EQ(byId(inserted, inserted.particles().position), byId(reordered, reordered.particles().position));
  EXPECT_EQ(byId(inserted, inserted.particles().velocity), byId(reordered, reordered.particles().velocity));
  EXPECT_EQ(inserted.walls()[0].force, reordered.walls()[0].force);
}

/// The message a scene's checks give, from the file or from its text (sceneFromText), or "".
std::string sceneErrorOf(const std::function<Scene()>& load) {
  try {
    buildWorld(load());  // the loader checks the keys, the builder the placement
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

/// The scene fails with `expected` in its message, naming the file, and as a document built in
/// code (its text) with the same message naming the document instead of the file and line.
void expectSceneError(const std::string& text, const std::string& expected) {
  const std::string path = writeScene("bad", text);
  const std::string fromFile = sceneErrorOf([&] { return loadScene(path); });
  const std::string fromText = sceneErrorOf([&] {
    return sceneFromText(text, {"<document>", std::filesystem::temp_directory_path()});
  });
  ASSERT_FALSE(fromFile.empty()) << "no error for: " << expected;
  EXPECT_EQ(fromFile.rfind(path, 0), 0u) << fromFile;
  EXPECT_NE(fromFile.find(expected), std::string::npos) << fromFile;
  std::size_t rest = path.size();
  if (rest < fromFile.size() && fromFile[rest] == ':' && std::isdigit(static_cast<unsigned char>(fromFile[rest + 1]))) {
    rest = fromFile.find(':', rest + 1);
  }
  EXPECT_EQ(fromText, "<document>" + fromFile.substr(rest));
}

// Explicit particles: the `particles:` list places each particle with its pose and velocities,
// and a particle file written from a world (particle_file.hpp) inserts the same particles: shapes,
// materials, centres (wrapped into the periodic box) and velocities bit for bit, orientations
// (normalised again) and angular velocities (kept as the conjugate momentum) to round-off.
TEST(Engine, ExplicitParticlesAndParticleFilesRoundTrip) {
  const std::string listed = replaced(replaced(bedScene, "  grains: {", "  ball: {semi_axes: [0.5e-3, 0.5e-3, 0.4e-3]}\n  grains: {"),
                                      "insert:\n", "particles:\n"
                                      "  - {shape: ball, material: glass, centre: [1.0e-3, 2.0e-3, 3.0e-3], quaternion: [0.8, 0.6, 0, 0],\n"
                                      "     velocity: [0.1, 0, -0.2], angular_velocity: [0, 5, 0]}\n"
                                      "  - {shape: ball, material: glass, centre: [4.0e-3, 2.0e-3, 3.0e-3]}\n"
                                      "insert:\n");
  const World world = buildWorld(loadScene(writeScene("listed", listed)));
  ASSERT_EQ(world.particles().size(), 62u);
  const ParticleStore& p = world.particles();
  EXPECT_EQ(p.position[0], Vec3(1.0e-3, 2.0e-3, 3.0e-3));
  EXPECT_EQ(p.orientation[0].coeffs(), Quat(0.8, 0.6, 0.0, 0.0).coeffs());
  EXPECT_EQ(p.velocity[0], Vec3(0.1, 0.0, -0.2));
  EXPECT_LT((p.angularVelocity[0] - Vec3(0.0, 5.0, 0.0)).norm(), 1e-12);
  // The shape family keeps semi-axes as a volume radius and aspect ratios: equal to round-off.
  EXPECT_LT((world.shapes()[p.shape[1]].halfExtents() - Vec3(0.5e-3, 0.5e-3, 0.4e-3)).norm(), 1e-18);

  World original = pouredBed(loadScene(writeScene("bed", bedScene)), 50.0, 20000);
  const auto file = std::filesystem::temp_directory_path() / "sqdem_test_bed_particles.csv";
  writeParticleFile(file, original, loadScene(writeScene("bed", bedScene)).materials);
  const std::string restart = replaced(bedScene, "  - {count: 60, shape: grains, material: glass, region: {lo: [0, 0, 1.0e-3], hi: [6.0e-3, 6.0e-3, 11.0e-3]}}",
                                       "  - {file: " + file.string() + ", allow_overlap: true}");
  const World copy = buildWorld(loadScene(writeScene("restart", restart)));
  ASSERT_EQ(copy.particles().size(), original.particles().size());
  const ParticleStore &a = original.particles(), &b = copy.particles();
  // The file is in id order and the copy numbers its rows from 0: the same ids.
  std::vector<std::size_t> slotOf(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) slotOf[b.id[j]] = j;
  double spin = 0.0, turn = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = slotOf[a.id[i]];
    EXPECT_EQ(copy.shapes()[b.shape[j]].halfExtents(), original.shapes()[a.shape[i]].halfExtents());
    EXPECT_EQ(b.material[j], a.material[i]);
    // Positions are wrapped into the periodic box at neighbour-list builds; the copy's are
    // wrapped as it is built.
    EXPECT_EQ(b.position[j], copy.domain().wrap(a.position[i]));
    turn = std::max(turn, (b.orientation[j].coeffs() - a.orientation[i].coeffs()).norm());
    EXPECT_EQ(b.velocity[j], a.velocity[i]);
    spin = std::max(spin, (b.angularVelocity[j] - a.angularVelocity[i]).norm() / std::max(a.angularVelocity[i].norm(), 1e-30));
  }
  std::printf("60 particles through a particle file: orientation differs by %.2g, angular velocity by %.2g (relative)\n",
              turn, spin);
  EXPECT_LT(turn, 1e-15);
  EXPECT_LT(spin, 1e-12);

  // Tiling: the bed and its copy offset by the period along x fill a box twice as long; a scene
  // whose particles all come from files needs no shapes.
  const std::string entry = "  - {file: " + file.string() + ", allow_overlap: true}";
  std::string tiled = replaced(replaced(restart, "hi: [6.0e-3, 6.0e-3, 12.0e-3]", "hi: [12.0e-3, 6.0e-3, 12.0e-3]"), entry,
                               entry + "\n" + replaced(entry, "allow_overlap: true}", "allow_overlap: true, offset: [6.0e-3, 0, 0]}"));
  tiled = replaced(tiled, "shapes:\n  grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}\n", "");
  const World twice = buildWorld(loadScene(writeScene("tiled", tiled)));
  ASSERT_EQ(twice.particles().size(), 2 * a.size());
  for (std::size_t j = 0; j < b.size(); ++j) {
    const std::size_t k = j + b.size();  // the copy's rows follow the bed's
    EXPECT_EQ(twice.particles().position[k], twice.particles().position[j] + Vec3(6.0e-3, 0.0, 0.0));
  }
  // A region keeps the file's particles whose bounding spheres lie within it (a strip cut out
  // of the periodic bed): the count of the closed form, the particles in file order.
  const Vec3 lo(1.0e-3, -1.0, -1.0), hi(5.0e-3, 1.0, 1.0);
  std::vector<std::uint32_t> kept;  // ids of the bed's particles inside
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double reach = original.shapes()[a.shape[i]].boundingRadius();
    if (((a.position[i].array() - reach) >= lo.array()).all() && ((a.position[i].array() + reach) <= hi.array()).all()) {
      kept.push_back(a.id[i]);
    }
  }
  std::sort(kept.begin(), kept.end());
  const World strip = buildWorld(
      loadScene(writeScene("strip", replaced(restart, "allow_overlap: true}", "allow_overlap: true, region: {lo: [1.0e-3, -1, -1], hi: [5.0e-3, 1, 1]}}"))));
  ASSERT_GT(kept.size(), 0u);
  ASSERT_LT(kept.size(), a.size());
  ASSERT_EQ(strip.particles().size(), kept.size());
  const auto slotWithId = [](const ParticleStore& s, std::uint32_t id) {
    return static_cast<std::size_t>(std::find(s.id.begin(), s.id.end(), id) - s.id.begin());
  };
  for (std::uint32_t j = 0; j < kept.size(); ++j) {  // the strip's particle j is the file's row kept[j]
    EXPECT_EQ(strip.particles().position[slotWithId(strip.particles(), j)], a.position[slotWithId(a, kept[j])]);
  }

  const std::string strict = replaced(restart, "allow_overlap: true", "allow_overlap: false");
  expectSceneError(strict, "overlaps");
  expectSceneError(replaced(listed, "material: glass, centre: [4.0e-3", "material: glass, centre: [1.5e-3"),
                   ": particles[0] overlaps particles[1] by");
  expectSceneError(replaced(listed, "quaternion: [0.8, 0.6, 0, 0]", "quaternion: [1, 1, 0, 0]"),
                   "'particles[0].quaternion': must be a unit quaternion [w, x, y, z]");
  expectSceneError(replaced(listed, "{shape: ball, material: glass, centre: [4.0e-3", "{shape: grains, material: glass, centre: [4.0e-3"),
                   "'particles[1].shape': shape 'grains' is a distribution");
  expectSceneError(replaced(listed, "centre: [4.0e-3, 2.0e-3, 3.0e-3]", "centre: [4.0e-3, 2.0e-3, 13.0e-3]"),
                   "particles[1]: the centre lies outside the domain along z");
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto corrupt = [&](const std::string& from, const std::string& to, const std::string& expected) {
    std::ofstream(file) << replaced(text, from, to);
    expectSceneError(restart, expected);
  };
  corrupt("material,a,", "material,A,", ":1: the first line must be the header 'material,a,b,c,n1,n2,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz'");
  corrupt("\nglass,", "\nsteel,", ":2: 'material': 'steel' is not a material of the scene");
  corrupt("\nglass,", "\nglass,nan", ":2: 'a': '");
  corrupt("\nglass,", "\nglass,1,", ":2: 20 fields, the header has 19");
}


// insert.solid_fraction: particles are added until their volume reaches the fraction of the
// region (the last one may overshoot by at most its own volume).
TEST(Engine, InsertionByTargetSolidFraction) {
  const Scene scene = loadScene(writeScene("fraction", replaced(bedScene, "count: 60", "solid_fraction: 0.12")));
  const World world = buildWorld(scene);
  const InsertionSpec& in = scene.insertions[0];
  const double region = (in.hi - in.lo).prod();
  double volume = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < world.particles().size(); ++i) {
    const double v = world.shapes()[world.particles().shape[i]].volume();
    volume += v;
    largest = std::max(largest, v);
  }
  EXPECT_GE(volume / region, 0.12);
  EXPECT_LT((volume - largest) / region, 0.12);
  EXPECT_GT(world.particles().size(), 60u);
}

// insert.recipe: two species by mass or by volume fractions (docs/scene_reference.md, insert):
// large grains (2500 kg/m^3) and small binder spheres (930 kg/m^3, 1/8 of their size). With a
// solid_fraction each species' volume reaches its share of it (the last particle of each may
// overshoot by its own volume); with a count, the first species has exactly that many and the
// second its share of the total they imply. The achieved fractions are the recipe's to within one
// particle of each species.
TEST(Engine, InsertionByRecipe) {
  const std::string recipe = replaced(
      replaced(bedScene, "  grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}\n",
               "  grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}\n"
               "  binder: {volume_radius: [0.05e-3, 0.075e-3]}\n"),
      "restitution: 0.3}\n", "restitution: 0.3}\n  cbd: {youngs_modulus: 1.0e6, poisson_ratio: 0.3, density: 930, friction: 0.4, restitution: 0.3}\n");
  const std::string pairs = "interactions:\n  - materials: [glass, glass]\n  - materials: [glass, cbd]\n  - materials: [cbd, cbd]\n";
  const auto withInsert = [&](const std::string& entry) {
    return replaced(replaced(recipe, "interactions:\n  - materials: [glass, glass]\n", pairs),
                    "  - {count: 60, shape: grains, material: glass, region: {lo: [0, 0, 1.0e-3], hi: [6.0e-3, 6.0e-3, 11.0e-3]}}", entry);
  };
  struct Totals {
    double mass[2] = {0.0, 0.0}, volume[2] = {0.0, 0.0}, largestMass[2] = {0.0, 0.0}, largestVolume[2] = {0.0, 0.0};
    std::size_t count[2] = {0, 0};
  };
  const auto totals = [](const World& world) {
    Totals t;
    const ParticleStore& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int s = static_cast<int>(p.material[i]);  // 0 glass grains, 1 cbd binder
      const double v = world.shapes()[p.shape[i]].volume();
      t.mass[s] += p.mass[i];
      t.volume[s] += v;
      t.largestMass[s] = std::max(t.largestMass[s], p.mass[i]);
      t.largestVolume[s] = std::max(t.largestVolume[s], v);
      ++t.count[s];
    }
    return t;
  };
  const std::string region = "region: {lo: [0, 0, 1.0e-3], hi: [6.0e-3, 6.0e-3, 11.0e-3]}";
  const double regionVolume = 6.0e-3 * 6.0e-3 * 10.0e-3;
  // By mass, to a solid fraction of 0.1: 96 % grains, 4 % binder by mass.
  {
    const Totals t = totals(buildWorld(loadScene(writeScene("recipe_mass", withInsert(
        "  - {recipe: [{shape: grains, material: glass, fraction: 0.96}, {shape: binder, material: cbd, fraction: 0.04}], "
        "by: mass, solid_fraction: 0.1, " + region + "}")))));
    const double total = t.mass[0] + t.mass[1];
    ASSERT_GT(t.count[1], 100u);
    EXPECT_NEAR(t.mass[1] / total, 0.04, (t.largestMass[0] + t.largestMass[1]) / total);
    const double volumeShare1 = (0.04 / 930.0) / (0.96 / 2500.0 + 0.04 / 930.0);  // the binder's share of the volume
    EXPECT_GE(t.volume[1], volumeShare1 * 0.1 * regionVolume);
    EXPECT_LT(t.volume[1] - t.largestVolume[1], volumeShare1 * 0.1 * regionVolume);
    EXPECT_GE(t.volume[0], (1.0 - volumeShare1) * 0.1 * regionVolume);
    EXPECT_LT(t.volume[0] - t.largestVolume[0], (1.0 - volumeShare1) * 0.1 * regionVolume);
    std::printf("by mass 0.96 / 0.04 to solid fraction 0.1: %zu grains, %zu binder particles, binder mass fraction %.5f\n", t.count[0],
                t.count[1], t.mass[1] / total);
  }
  // By volume, with a count: 50 grains, and binder to 10 % of the particle volume.
  {
    const Totals t = totals(buildWorld(loadScene(writeScene("recipe_volume", withInsert(
        "  - {recipe: [{shape: grains, material: glass, fraction: 0.9}, {shape: binder, material: cbd, fraction: 0.1}], "
        "by: volume, count: 50, " + region + "}")))));
    EXPECT_EQ(t.count[0], 50u);
    const double target = 0.1 / 0.9 * t.volume[0];
    EXPECT_GE(t.volume[1], target);
    EXPECT_LT(t.volume[1] - t.largestVolume[1], target);
    std::printf("by volume 0.9 / 0.1 with 50 grains: %zu binder particles, binder volume fraction %.5f\n", t.count[1],
                t.volume[1] / (t.volume[0] + t.volume[1]));
  }
  // Its errors.
  const std::string two = "[{shape: grains, material: glass, fraction: 0.9}, {shape: binder, material: cbd, fraction: 0.2}]";
  expectSceneError(withInsert("  - {recipe: " + two + ", count: 5, " + region + "}"),
                   "'insert[0].recipe': the fractions sum to 1.1; they must sum to 1 (of the mass)");
  expectSceneError(withInsert("  - {recipe: [{shape: grains, material: glass, fraction: 1}], count: 5, " + region + "}"),
                   "'insert[0].recipe': must be a list of at least two {shape, material, fraction}");
  expectSceneError(withInsert("  - {recipe: " + two + ", by: weight, count: 5, " + region + "}"), "'insert[0].by': allowed: mass, volume");
  expectSceneError(withInsert("  - {recipe: " + two + ", shape: grains, count: 5, " + region + "}"),
                   "'insert[0].shape': belongs to each entry of the recipe");
  expectSceneError(withInsert("  - {shape: grains, material: glass, by: mass, count: 5, " + region + "}"),
                   "'insert[0].by': belongs to a recipe");
  expectSceneError(withInsert("  - {recipe: [{shape: grains, material: glass, fraction: 0.5}, {shape: binder, material: cbd}], count: 5, " +
                              region + "}"),
                   "'insert[0].recipe[1].fraction': missing");
}

// A bed with Becker-Kamlah contacts (002, NMC fits with the transition, elliptic Mindlin
// tangential) settles like the elastic one; a low yield strength makes contacts plastic, so the
// bed ends with permanent (plastic) overlaps that an elastic bed does not have: after the pour,
// some touching contact carries no force (unloaded below its residual overlap) or is unloading.
TEST(Engine, BeckerKamlahBedSettles) {
  const std::string scene = replaced(replaced(bedScene, "restitution: 0.3}", "restitution: 0.3, yield_strength: 2.0e4}"),
                                     "  - materials: [glass, glass]\n", "  - materials: [glass, glass]\n    normal: becker_kamlah\n");
  omp_set_num_threads(2);
  const World world = pouredBed(loadScene(writeScene("plastic", scene)), 50.0, 40000);
  EXPECT_EQ(world.statistics().detectorFailures, 0);
  ASSERT_GT(world.contacts().size(), 40u);
  std::size_t plastic = 0;
  for (const ContactView c : world.contacts()) plastic += c.normalHistory().load<BeckerKamlahLaw::History>().plastic.maxOverlap > c.overlap();
  EXPECT_GT(plastic, 0u);  // contacts remember a larger overlap than the current one
  for (std::size_t i = 0; i < world.particles().size(); ++i) ASSERT_TRUE(world.particles().position[i].allFinite());
}

// An interaction's own restitution and friction replace the materials' pair values; the
// damping ratio is 001 Eq. 12's zeta(e) = -ln e / sqrt(pi^2 + ln^2 e).
TEST(Engine, InteractionOverridesPairRestitutionAndFriction) {
  const World plain = buildWorld(loadScene(writeScene("plain", bedScene)));
  EXPECT_DOUBLE_EQ(plain.contactModel(0, 0).tangential.friction, 0.4);
  const World pair = buildWorld(loadScene(writeScene(
      "pair", replaced(bedScene, "  - materials: [glass, glass]\n", "  - materials: [glass, glass]\n    restitution: 0.8\n    friction: 0.1\n"))));
  EXPECT_DOUBLE_EQ(pair.contactModel(0, 0).tangential.friction, 0.1);
  const double l = std::log(0.8);
  EXPECT_NEAR(pair.contactModel(0, 0).damping.ratio, -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l), 1e-15);
}

// walls: a cylinder (axis, radius, spin) next to a plane; insertion keeps particles out of it.
TEST(Engine, CylinderWallFromTheScene) {
  const std::string plane = "  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}\n";
  const World world = buildWorld(loadScene(writeScene(
      "roller", replaced(bedScene, plane, plane + "  - {point: [3.0e-3, 0, 6.0e-3], axis: [0, 2, 0], radius: 2.0e-3, spin: -4, "
                                                  "velocity: [0.1, 0, 0], material: glass}\n"))));
  ASSERT_EQ(world.walls().size(), 2u);
  const Wall& w = world.walls()[1];
  ASSERT_TRUE(w.is<CylinderWall>());
  EXPECT_EQ(w.get<CylinderWall>().cylinder.axis, Vec3::UnitY());
  EXPECT_EQ(w.get<CylinderWall>().cylinder.radius, 2.0e-3);
  EXPECT_EQ(w.angularVelocity, Vec3(0.0, -4.0, 0.0));
  EXPECT_EQ(w.velocity, Vec3(0.1, 0.0, 0.0));
  for (std::size_t i = 0; i < world.particles().size(); ++i) {
    EXPECT_GT(w.get<CylinderWall>().distance(world.particles().position[i]), world.shapes()[world.particles().shape[i]].boundingRadius());
  }
}

TEST(Engine, DetectorToleranceKeySetsTheEnginesSolve) {
  EXPECT_EQ(buildWorld(loadScene(writeScene("plain", bedScene))).detectorControl().tolerance, DetectorControl{}.tolerance);
  const World tight = buildWorld(loadScene(writeScene("tight", replaced(bedScene, "seed: 7", "seed: 7\ndetector_tolerance: 1e-10"))));
  EXPECT_EQ(tight.detectorControl().tolerance, 1e-10);
}

// A shape given by its semi-axes has exactly those (not semi-axes rebuilt from a volume radius
// and aspect ratios: 1e-3 came back as 0.9999999999999998e-3), from a file and from a text.
TEST(Engine, SemiAxesAreKeptExactly) {
  const std::string text = replaced(replaced(bedScene, "grains: {volume_radius: [0.4e-3, 0.6e-3], aspect_b: [0.6, 1.2], aspect_c: [0.6, 1.2]}",
                                             "grains: {semi_axes: [1.0e-3, 0.7e-3, 0.3e-3], n1: 3}\n  ball: {semi_axes: [1.0e-3, 1.0e-3, 1.0e-3]}"),
                                    "  - {count: 60, shape: grains",
                                    "  - {count: 5, shape: ball, material: glass, region: {lo: [0, 0, 1.0e-3], hi: [6.0e-3, 6.0e-3, 11.0e-3]}}\n"
                                    "  - {count: 5, shape: grains");
  for (const Scene& scene : {loadScene(writeScene("exact", text)), sceneFromText(text)}) {
    const World world = buildWorld(scene);
    ASSERT_EQ(world.particles().size(), 10u);
    for (std::size_t i = 0; i < world.particles().size(); ++i) {
      const Superquadric& s = world.shapes()[world.particles().shape[i]];
      const bool ball = s.n1() == 2.0;
      EXPECT_EQ(s.a(), 1.0e-3);
      EXPECT_EQ(s.b(), ball ? 1.0e-3 : 0.7e-3);
      EXPECT_EQ(s.c(), ball ? 1.0e-3 : 0.3e-3);
      EXPECT_EQ(s.n1(), ball ? 2.0 : 3.0);
    }
  }
}

TEST(Engine, SceneErrorsNameLineKeyAndWhatIsAllowed) {
  const auto withInteraction = [](const std::string& keys) {
    return replaced(bedScene, "  - materials: [glass, glass]\n", "  - materials: [glass, glass]\n" + keys);
  };
  expectSceneError(replaced(bedScene, "seed: 7", "seed: 7\ncolour: red"), ":2: 'colour': unknown key (allowed: seed,");
  expectSceneError(replaced(bedScene, "restitution: 0.3", "restitution: 1.5"), ":6: 'materials.glass.restitution': must be in (0, 1]");
  expectSceneError(replaced(bedScene, "density: 2500", "density: heavy"), "'materials.glass.density': must be a finite number");
  expectSceneError(replaced(bedScene, "shape: grains", "shape: pebbles"), "unknown shape 'pebbles' (defined: grains)");
  expectSceneError(withInteraction("    normal: dmt\n"),
                   "'interactions[0].normal': unknown law 'dmt' (allowed: elliptic_hertz, volume_sphere_hertz, becker_kamlah, "
                   "haervig_jkr, elliptic_jkr, nan_adhesive, jamari, true_gap)");
  expectSceneError(replaced(bedScene, "periodic: [x, y]", "periodic: [x, w]"), "'domain.periodic': directions are x, y, z");
  expectSceneError(replaced(bedScene, "{name: settle, duration: 0.2}", "{name: settle}"), "'stages[0].duration': missing");
  expectSceneError(withInteraction("    normal: volume_sphere_hertz\n    tangential: elliptic_mindlin\n"),
                   "'interactions[0].tangential': elliptic_mindlin needs a law on the curvatures (allowed here: circular_mindlin)");
  expectSceneError(replaced(bedScene, "seed: 7", "seed: 7\nbroad_phase: octree"), "'broad_phase': allowed: auto, cell_list, aabb_tree");
  expectSceneError(replaced(bedScene, "seed: 7", "seed: 7\ndetector_tolerance: 0.01"),
                   "'detector_tolerance': must be in [1e-14, 1e-3] (relative to sqrt(R_vol,A R_vol,B))");
  expectSceneError(replaced(bedScene, "grains: {volume_radius", "grains: {file: no_such_shape.yaml}\n  unused: {volume_radius"),
                   "'shapes.grains.file': cannot open");
  expectSceneError(replaced(bedScene, "{name: settle, duration: 0.2}", "{name: settle, duration: 0.2, move_wall: {wall: 0, path: [[0.1, 1e-3], [0.05, 0]]}}"),
                   "'stages[0].move_wall.path': times must be > 0 and increasing (s)");
  expectSceneError(replaced(bedScene, "{name: settle, duration: 0.2}", "{name: settle, duration: 0.2, move_wall: {wall: 0}}"),
                   "'stages[0].move_wall': needs exactly one of velocity");
  const std::string roller = "  - {point: [0, 0, 0], normal: [0, 0, 1], material: glass}\n";
  expectSceneError(replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], normal: [0, 0, -1], axis: [0, 1, 0], material: glass}\n"),
                   "'walls[1]': needs exactly one of normal [nx, ny, nz] (a plane), axis [ux, uy, uz] with radius (m) (a cylinder) or mesh: file.stl (a triangle mesh)");
  expectSceneError(replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], axis: [0, 1, 0], material: glass}\n"),
                   "'walls[1].radius': missing");
  expectSceneError(replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], axis: [0, 1, 0], radius: -1, material: glass}\n"),
                   "'walls[1].radius': must be > 0 (m)");
  expectSceneError(replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], normal: [0, 0, -1], spin: 3, material: glass}\n"),
                   "'walls[1].spin': belongs to a cylinder (axis), not a plane (normal)");
  const std::string withRoller =
      replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], axis: [0, 1, 0], radius: 5.0e-3, spin: 3, material: glass}\n");
  expectSceneError(replaced(bedScene, roller, roller + "  - {point: [0, 0, 0.02], axis: [0, 1, 0], radius: 3.0e-3, material: glass}\n"),
                   "walls[1]: a cylinder of radius 0.003 m needs its periodic images along x at least");
  expectSceneError(replaced(withRoller, "{name: settle, duration: 0.2}", "{name: settle, duration: 0.2, servo_wall: {wall: 1, pressure: 10, max_speed: 1}}"),
                   "'stages[0].servo_wall.wall': walls[1] is a cylinder; this needs a plane");
  expectSceneError(replaced(bedScene, "count: 60", "count: 60, solid_fraction: 0.1"), "'insert[0]': needs exactly one of count");
  expectSceneError(replaced(bedScene, "count: 60", "solid_fraction: 0.6"), "'insert[0].solid_fraction': must be in (0, 0.4]");
  expectSceneError(withInteraction("    normal: becker_kamlah\n"),
                   "'interactions[0]': becker_kamlah needs yield_strength (Pa): give it here or in both materials");
  expectSceneError(withInteraction("    lambda_max: 2.5\n"),
                   "'interactions[0].lambda_max': unknown key (allowed: materials, normal, tangential, eccentricity, cap_factor, "
                   "curvature_tolerance, reduced_stiffness, restitution, rolling_hysteresis, friction, bond, deep_overlaps, and for elliptic_hertz: roughness); "
                   "'lambda_max' is a key of normal: becker_kamlah");
  expectSceneError(withInteraction("    roughness: {sigma: 1.0e-6}\n"), "'interactions[0].roughness.asperity_count': missing");
  expectSceneError(withInteraction("    curvature_tolerance: 0.5\n"),
                   "'interactions[0].curvature_tolerance': must be in [0, 0.1] (0: curvatures every step)");
  expectSceneError(withInteraction("    normal: nan_adhesive\n    roughness: {sigma: 1.0e-6, asperity_count: 10}\n"
                                   "    surface_energy: 0.1\n    yield_pressure: 1.0e6\n"),
                   "'interactions[0].roughness': unknown key (allowed: materials, normal, tangential, eccentricity, cap_factor, "
                   "curvature_tolerance, reduced_stiffness, restitution, rolling_hysteresis, friction, bond, deep_overlaps, and for nan_adhesive: surface_energy, "
                   "yield_pressure, elastic_stiffness, plastic_stiffness); 'roughness' is a key of normal: elliptic_hertz, "
                   "volume_sphere_hertz, elliptic_jkr (Greenwood-Williamson roughness is built on elastic asperities");
  expectSceneError(withInteraction("    normal: jamari\n    hardness: 1.0e6\n    surface_energy: 0.1\n"),
                   "'surface_energy' is a key of normal: becker_kamlah, haervig_jkr, elliptic_jkr, nan_adhesive (an adhesive "
                   "form of jamari is not built)");
  expectSceneError(withInteraction("    normal: elliptic_hertz\n    rolling_hysteresis: 0.5\n"),
                   "'interactions[0].rolling_hysteresis': needs normal: haervig_jkr");
  expectSceneError(withInteraction("    normal: elliptic_jkr\n    surface_energy: -0.1\n"),
                   "'interactions[0].surface_energy': must be > 0 (J/m^2, gamma; W = 2 gamma)");
  expectSceneError(withInteraction("    restitution: 0\n"), "'interactions[0].restitution': must be in (0, 1]");
  expectSceneError(withInteraction("    deep_overlaps: sometimes\n"), "'interactions[0].deep_overlaps': allowed: trouble, expected");
  // Bonds (docs/bonds.md): their keys, a stage forming them without any, a gap beyond the skin.
  const std::string bond = "    bond: {normal_stiffness: 1.0e12, shear_stiffness: 4.0e11, tensile_strength: 1.0e6, shear_strength: 2.0e6}\n";
  expectSceneError(withInteraction("    bond: {normal_stiffness: 1.0e12, shear_stiffness: 4.0e11, tensile_strength: 1.0e6}\n"),
                   "'interactions[0].bond.shear_strength': missing");
  expectSceneError(withInteraction("    bond: {normal_stiffness: 1.0e12, shear_stiffness: 4.0e11, tensile_strength: 1.0e6, "
                                   "shear_strength: 2.0e6, radius: 1}\n"),
                   "'interactions[0].bond.radius': unknown key (allowed: radius_multiplier, normal_stiffness, shear_stiffness, "
                   "tensile_strength, shear_strength, damping_ratio)");
  expectSceneError(withInteraction("    bond: {normal_stiffness: 0, shear_stiffness: 4.0e11, tensile_strength: 1.0e6, shear_strength: 2.0e6}\n"),
                   "'interactions[0].bond.normal_stiffness': must be > 0 (Pa/m)");
  expectSceneError(withInteraction("    bond: {normal_stiffness: 1.0e12, shear_stiffness: 4.0e11, tensile_strength: 1.0e6, "
                                   "shear_strength: 2.0e6, damping_ratio: 1.5}\n"),
                   "'interactions[0].bond.damping_ratio': must be in [0, 1] (a fraction of each spring's critical damping)");
  expectSceneError(replaced(bedScene, "{name: settle, duration: 0.2}", "{name: settle, duration: 0.2, form_bonds: {gap: 0.01}}"),
                   "'stages[0].form_bonds': no interaction has a bond");
  expectSceneError(replaced(withInteraction(bond), "{name: settle, duration: 0.2}", "{name: settle, duration: 0.2, form_bonds: {gap: -1}}"),
                   "'stages[0].form_bonds.gap': must be >= 0");
  EXPECT_THROW(buildWorld(loadScene(writeScene("bond_gap", replaced(withInteraction(bond), "{name: settle, duration: 0.2}",
                                                                    "{name: settle, duration: 0.2, form_bonds: {gap: 5}}")))),
               SceneError);
  expectSceneError("seed: [1", "not valid YAML");
  // A roughness range beyond the skin, and a region too small for the particles, are reported
  // before anything runs.
  EXPECT_THROW(buildWorld(loadScene(writeScene("rough", withInteraction("    roughness: {sigma: 1.0e-4, asperity_count: 10}\n")))),
               SceneError);
  const Scene crowded = loadScene(writeScene("crowded", replaced(bedScene, "count: 60", "count: 5000")));
  EXPECT_THROW(buildWorld(crowded), SceneError);
}

// The automatic step's bond limit (docs/bonds.md, "Time step"): with a bond stiffer than the
// particles' Rayleigh time allows for, the scene's step is 0.2 / omega of its stiffest bond; with
// a soft one, the Rayleigh step as without bonds.
TEST(Engine, TheAutomaticStepResolvesTheStiffestBond) {
  const auto withBond = [](const std::string& stiffness) {
    return replaced(replaced(bedScene, "time_step: 2.0e-6\n", ""), "  - materials: [glass, glass]\n",
                    "  - materials: [glass, glass]\n    bond: {normal_stiffness: " + stiffness +
                        ", shear_stiffness: 4.0e11, tensile_strength: 1.0e6, shear_strength: 2.0e6}\n");
  };
  const World stiff = buildWorld(loadScene(writeScene("bond_step", withBond("1.0e12"))));
  EXPECT_LT(stiff.bondTimeStep(), stiff.rayleighTimeStep());
  EXPECT_EQ(stiff.timeStep(), 0.2 * stiff.bondTimeStep());
  const World soft = buildWorld(loadScene(writeScene("bond_step", replaced(withBond("1.0e6"), "shear_stiffness: 4.0e11", "shear_stiffness: 4.0e5"))));
  EXPECT_GT(soft.bondTimeStep(), soft.rayleighTimeStep());
  EXPECT_EQ(soft.timeStep(), 0.2 * soft.rayleighTimeStep());
}

// A bond that breaks in tension only beyond the skin (sigma_c / k_n > skin) would leave the
// neighbour list intact and be lost: the run is told before it starts, naming the interaction
// and the skin it needs; a stiffer bond, which breaks within the skin, is not warned about.
TEST(Engine, WarnsOfABondThatCanOutstretchTheSkin) {
  const auto warnings = [](const std::string& stiffness) {
    const Scene scene = loadScene(writeScene("bond_skin", replaced(replaced(bedScene, "time_step: 2.0e-6\n", ""), "  - materials: [glass, glass]\n",
                                                                    "  - materials: [glass, glass]\n    bond: {normal_stiffness: " + stiffness +
                                                                        ", shear_stiffness: 4.0e8, tensile_strength: 1.0e6, shear_strength: 2.0e6}\n")));
    const World world = buildWorld(scene);
    std::string all;
    for (const std::string& w : planRun(scene, world).warnings) all += w + "\n";
    return all;
  };
  EXPECT_NE(warnings("1.0e9").find("interactions[0].bond breaks in tension at a stretch sigma_c / k_n = 0.001 m, beyond the skin"),
            std::string::npos)
      << warnings("1.0e9");
  EXPECT_EQ(warnings("1.0e12").find("bond breaks"), std::string::npos) << warnings("1.0e12");
}

}  // namespace
}  // namespace sqdem

// The engine decomposed over MPI ranks (docs/architecture.md, "Ghosts"), run under mpirun with
// 1-4 and 8 ranks (and 2 ranks x 2 threads), against one process on one thread running the same
// scene, bit for bit:
//   - a poured bed of mixed shapes on a floor, periodic in x and y (tests/scenes/decomposed_bed.yaml),
//     stepped by every rank on its sub-domain, with migration, ghosts and loads across ranks: its
//     final state (every particle's pose, velocities and force), the wall's load and the kinetic
//     energy, reduced over the ranks. The sub-domains are cut again by cost as the bed settles
//     (the first cut, by counts of the falling particles, is across z), so contacts cross rank
//     faces in the bed. The same bed on a corrugated floor given as a triangle mesh
//     (tests/scenes/decomposed_mesh_bed.yaml): contacts with its faces and edges;
//   - sliding contacts whose particles cross a periodic face and a rank face together
//     (tests/scenes/crossing_slide.yaml): every contact's tangential spring and force at every
//     step, so a history lost or restarted in the migration shows as a jump the one-process run
//     does not have;
//   - an adhesive contact between particles of two ranks (tests/scenes/crossing_adhesion.yaml),
//     which must break on the same step as in one process; at 3, 4 and 8 ranks some ranks own no
//     particle;
//   - a bonded ring travelling across rank faces and the periodic face, shaken until some bonds
//     break (tests/scenes/crossing_bonds.yaml): every contact's force (its bond's loads in it) at
//     every step, and the bonds broken, are one process's.

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdlib>
#include <map>
#include <tuple>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/distributed/mpi_communicator.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem {
namespace {

struct State {
  Vec3 position, velocity, angularVelocity, force, torque;
  Quat orientation;
};

/// Every particle's state by id, gathered on rank 0 (empty on the others).
std::map<std::uint32_t, State> gathered(const World& world) {
  const Communicator& ranks = world.communicator();
  const ParticleStore& p = world.particles();
  CheckpointWriter out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.put(p.id[i]);
    out.put(State{p.position[i], p.velocity[i], p.angularVelocity[i], p.force[i], p.torque[i], p.orientation[i]});
  }
  std::map<std::uint32_t, State> all;
  for (const std::string& m : ranks.gather(out.bytes())) {
    CheckpointReader in(m);
    while (in.left() > 0) {
      std::uint32_t id = 0;
      State s;
      in.get(id);
      in.get(s);
      all[id] = s;
    }
  }
  return all;
}

/// A contact as its A's rank computed it after a step.
struct ContactRecord {
  Vec3 spring, force, point;
  int rank = 0;      ///< the rank that computed it (A's owner)
  bool bLocal = true;  ///< B a particle this rank owns, or a wall (else a ghost)
};
/// Every acting contact after every step, by (step, key); gathered on rank 0 (empty on the others).
using ContactTrace = std::map<std::tuple<int, std::uint64_t, std::uint32_t>, ContactRecord>;

ContactTrace stepAndTrace(World& world, int steps) {
  const Communicator& ranks = world.communicator();
  CheckpointWriter out;
  for (int s = 0; s < steps; ++s) {
    world.step();
    for (const ContactView c : world.contacts()) {
      out.put(s);
      out.put(c.key());
      out.put(ContactRecord{c.spring(), c.force(), c.point(), ranks.rank(), c.onWall() || c.b() < world.particles().size()});
    }
  }
  ContactTrace all;
  for (const std::string& m : ranks.gather(out.bytes())) {
    CheckpointReader in(m);
    while (in.left() > 0) {
      int s = 0;
      ContactKey key;
      ContactRecord r;
      in.get(s);
      in.get(key);
      in.get(r);
      EXPECT_TRUE(all.emplace(std::tuple{s, key.pair, key.feature}, r).second) << "a contact computed twice at step " << s;
    }
  }
  return all;
}

struct Traces {
  ContactTrace decomposed, one;  ///< empty on ranks other than 0
  int steps = 0;
};

/// The scene's world, on `ranks` (one process without), with the bonds its first stage forms (as
/// StageRunner forms them).
World startedWorld(const Scene& scene, std::shared_ptr<Communicator> ranks = nullptr) {
  World world = buildWorld(scene);
  if (ranks) world.setCommunicator(std::move(ranks));
  if (const std::optional<double> gap = scene.stages.at(0).bondGap) {
    world.computeForces();
    world.formBonds(*gap);
  }
  return world;
}

/// The scene run for its first stage's duration at this process's rank count, and on rank 0
/// again in one process on one thread.
Traces decomposedAndOne(const char* file) {
  const Scene scene = loadScene(std::string(SQDEM_TEST_SCENES "/") + file);
  World world = startedWorld(scene, worldCommunicator());
  const int steps = static_cast<int>(scene.stages.at(0).duration / world.timeStep());
  ContactTrace decomposed = stepAndTrace(world, steps);
  if (world.communicator().rank() != 0) return {};
  omp_set_num_threads(1);
  World one = startedWorld(scene);
  return {std::move(decomposed), stepAndTrace(one, steps), steps};
}

/// Both traces hold the same contacts at every step with the same springs and forces.
void expectSameTrace(const ContactTrace& decomposed, const ContactTrace& one) {
  ASSERT_EQ(decomposed.size(), one.size());
  for (const auto& [key, r] : one) {
    const auto it = decomposed.find(key);
    ASSERT_NE(it, decomposed.end()) << "step " << std::get<0>(key) << ": contact " << std::get<1>(key) << " missing";
    ASSERT_EQ(it->second.spring, r.spring) << "step " << std::get<0>(key) << ", contact " << std::get<1>(key);
    ASSERT_EQ(it->second.force, r.force) << "step " << std::get<0>(key) << ", contact " << std::get<1>(key);
  }
}

/// The scene's final state after SQDEM_STEPS steps (default 30,000) is one process's.
void expectSameBed(const char* file) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const Scene scene = loadScene(std::string(SQDEM_TEST_SCENES "/") + file);
  const int steps = std::getenv("SQDEM_STEPS") ? std::atoi(std::getenv("SQDEM_STEPS")) : 30000;
  World world = buildWorld(scene);
  world.setCommunicator(ranks);
  for (int s = 0; s < steps; ++s) world.step();
  const std::map<std::uint32_t, State> decomposed = gathered(world);
  const double kinetic = world.kineticEnergy();
  const Vec3 floorForce = world.walls()[0].force;
  long long owned = world.particles().size(), contacts = world.contacts().size();
  owned = ranks->sum(owned);
  contacts = ranks->sum(contacts);
  std::printf("rank %d of %d, %d thread(s): %zu particles, %zu ghosts, %zu contacts; imbalance %.3f after %d re-balances; "
              "sent %.1f messages and %.0f bytes per step\n",
              ranks->rank(), ranks->size(), omp_get_max_threads(), world.particles().size(), world.particles().ghostCount,
              world.contacts().size(), world.imbalance(), world.rebalances(),
              static_cast<double>(ranks->traffic().messages) / steps, static_cast<double>(ranks->traffic().bytes) / steps);
  if (ranks->rank() != 0) return;

  omp_set_num_threads(1);
  World one = buildWorld(scene);
  for (int s = 0; s < steps; ++s) one.step();
  ASSERT_EQ(owned, static_cast<long long>(one.particles().size()));
  EXPECT_EQ(contacts, static_cast<long long>(one.contacts().size()));
  EXPECT_GT(contacts, 100);  // a bed, not a gas
  EXPECT_EQ(kinetic, one.kineticEnergy());
  EXPECT_EQ(floorForce, one.walls()[0].force);
  if (one.walls()[0].is<MeshWall>()) {  // particles rest on the ridges' edges too
    long long edges = 0;
    for (const ContactView c : one.contacts()) {
      edges += c.onWall() && one.meshes()[one.walls()[c.wall()].get<MeshWall>().mesh].kind(c.feature()) == FeatureKind::Edge;
    }
    EXPECT_GT(edges, 0);
  }
  const ParticleStore& p = one.particles();
  ASSERT_EQ(decomposed.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const State& s = decomposed.at(p.id[i]);
    ASSERT_EQ(s.position, p.position[i]) << "particle " << p.id[i];
    ASSERT_EQ(s.orientation.coeffs(), p.orientation[i].coeffs()) << "particle " << p.id[i];
    ASSERT_EQ(s.velocity, p.velocity[i]) << "particle " << p.id[i];
    ASSERT_EQ(s.angularVelocity, p.angularVelocity[i]) << "particle " << p.id[i];
    ASSERT_EQ(s.force, p.force[i]) << "particle " << p.id[i];
    ASSERT_EQ(s.torque, p.torque[i]) << "particle " << p.id[i];
  }
}

TEST(MpiEngine, APouredBedIsTheSameAtAnyRankCount) { expectSameBed("decomposed_bed.yaml"); }

TEST(MpiEngine, ABedOnAMeshFloorIsTheSameAtAnyRankCount) { expectSameBed("decomposed_mesh_bed.yaml"); }

TEST(MpiEngine, SlidingContactsKeepTheirSpringsAcrossAPeriodicAndARankFace) {
  const auto [decomposed, one, total] = decomposedAndOne("crossing_slide.yaml");
  if (worldCommunicator()->rank() != 0) return;
  expectSameTrace(decomposed, one);
  // The three contacts (A with B, each with its wall) changed hands at more than one rank with
  // their springs loaded: the histories travelled. A and B are still touching at the end.
  std::map<std::uint64_t, int> steps, handovers;
  std::map<std::uint64_t, ContactRecord> last;
  for (const auto& [key, r] : decomposed) {
    const std::uint64_t pair = std::get<1>(key);
    ++steps[pair];
    if (last.contains(pair) && last[pair].rank != r.rank && r.spring.norm() > 0.0) ++handovers[pair];
    last[pair] = r;
  }
  ASSERT_EQ(steps.size(), 3u);
  // A and B still touch at the end, on the far side of the periodic face x = 0 (box 8 mm long).
  ASSERT_TRUE(one.contains({total - 1, std::uint64_t{1}, 0u})) << "A and B came apart";
  EXPECT_LT(one.at({0, std::uint64_t{1}, 0u}).point.x(), 1e-3);
  EXPECT_GT(one.at({total - 1, std::uint64_t{1}, 0u}).point.x(), 4e-3);
  for (const auto& [pair, n] : steps) {
    if (worldCommunicator()->size() > 1) EXPECT_GE(handovers[pair], 1) << "contact " << pair << " never changed rank";
    std::printf("contact %016llx: %d steps, changed rank %d times, spring at the end %.3e m\n",
                static_cast<unsigned long long>(pair), n, handovers[pair], last[pair].spring.norm());
  }
}

TEST(MpiEngine, AnAdhesiveContactAcrossARankFaceBreaksOnTheSameStep) {
  const auto [decomposed, one, total] = decomposedAndOne("crossing_adhesion.yaml");
  if (worldCommunicator()->rank() != 0) return;
  expectSameTrace(decomposed, one);
  ASSERT_FALSE(one.empty());
  const int lastActing = std::get<0>(one.rbegin()->first);
  EXPECT_EQ(static_cast<int>(one.size()), lastActing + 1) << "the neck acts from the first step until it breaks";
  EXPECT_LT(lastActing, total - 1) << "the neck did not break";
  bool pulled = false, acrossRanks = true;
  for (const auto& [key, r] : decomposed) {
    pulled = pulled || r.force.x() < 0.0;  // on B, towards A: the neck held B back
    acrossRanks = acrossRanks && !r.bLocal;
  }
  EXPECT_TRUE(pulled);
  if (worldCommunicator()->size() > 1) EXPECT_TRUE(acrossRanks) << "B was owned by A's rank at some step";
  std::printf("the neck broke after step %d of %d\n", lastActing, total);
}

TEST(MpiEngine, BondsTravelWithTheirParticlesAndBreakOnTheSameStep) {
  const Scene scene = loadScene(SQDEM_TEST_SCENES "/crossing_bonds.yaml");
  World world = startedWorld(scene, worldCommunicator());
  const std::size_t formed = world.bondCount();
  const int steps = static_cast<int>(scene.stages.at(0).duration / world.timeStep());
  const ContactTrace decomposed = stepAndTrace(world, steps);
  const std::size_t intact = world.bondCount();
  const long long broken = world.totalStatistics().bondsBroken;
  if (world.communicator().rank() != 0) return;
  omp_set_num_threads(1);
  World one = startedWorld(scene);
  const ContactTrace alone = stepAndTrace(one, steps);
  expectSameTrace(decomposed, alone);
  EXPECT_EQ(formed, 16u);  // eight around the ring, eight on the floor
  EXPECT_EQ(intact, one.bondCount());
  EXPECT_EQ(broken, one.totalStatistics().bondsBroken);
  EXPECT_GT(broken, 0) << "no bond broke";
  EXPECT_GT(intact, 0u) << "every bond broke";
  // Some bonded pair was computed across a rank face (B a ghost) at some step.
  bool acrossRanks = false;
  for (const auto& [key, r] : decomposed) acrossRanks = acrossRanks || !r.bLocal;
  if (worldCommunicator()->size() > 1) EXPECT_TRUE(acrossRanks);
  std::printf("bonded ring, %d steps: %zu bonds formed, %lld broke, %zu intact\n", steps, formed, broken, intact);
}

}  // namespace
}  // namespace sqdem

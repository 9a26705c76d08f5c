// The engine decomposed over MPI ranks (docs/architecture.md, "Ghosts"), run under mpirun with
// 1-4 ranks (and 2 ranks x 2 threads): a poured bed of mixed shapes on a floor, periodic in x and y
// (tests/scenes/decomposed_bed.yaml), is stepped by every rank on its sub-domain, with
// migration, ghosts and loads across ranks, and its final state (every particle's pose,
// velocities and force) is, bit for bit, that of one process on one thread running the same
// scene. Also the wall's load and the kinetic energy, reduced over the ranks. The sub-domains are
// cut again by cost as the bed settles (the first cut, by counts of the falling particles, is
// across z), so contacts cross rank faces in the bed.

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdlib>
#include <map>

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
  std::vector<std::string> outbox(ranks.size());
  outbox[0] = out.bytes();
  std::map<std::uint32_t, State> all;
  for (const std::string& m : ranks.exchangeAll(std::move(outbox))) {
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

TEST(MpiEngine, APouredBedIsTheSameAtAnyRankCount) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const Scene scene = loadScene(SQDEM_TEST_SCENES "/decomposed_bed.yaml");
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

}  // namespace
}  // namespace sqdem

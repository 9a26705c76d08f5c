// Checkpoint files (world/checkpoint_file.hpp, world_state.cpp) under random corruption: every
// changed byte is refused with a CheckpointError (never a crash, never a silent accept), and a
// payload corrupted behind a recomputed checksum is still bounds-checked (no crash, no other
// exception).

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <random>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

namespace fs = std::filesystem;
constexpr std::uint64_t sceneHash = 0x5eed5eed5eed5eedull;

/// 27 ellipsoids in a periodic-x box on a floor, pressed together: contacts with history,
/// candidates and a wall to index.
World makeWorld() {
  Domain d;
  d.lo = Vec3(0, 0, 0);
  d.hi = Vec3(6e-3, 6e-3, 6e-3);
  d.periodic = {true, false, false};
  const Material m{1e7, 0.3, 2500.0, 0.3, 0.5};
  World world({Superquadric::ellipsoid(1.1e-3, 0.9e-3, 0.8e-3)}, {m}, d, 2e-4);
  world.setContactModel(0, 0, world.defaultContactModel(0, 0));
  Wall floor;
  floor.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}};
  world.addWall(floor);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        world.addParticle(0, 0, Vec3(1e-3 + 1.9e-3 * i, 1e-3 + 1.9e-3 * j, 0.85e-3 + 1.65e-3 * k), Quat::Identity());
  world.setGravity(Vec3(0, 0, -9.81));
  world.setTimeStep(1e-6);
  for (int s = 0; s < 50; ++s) world.step();
  return world;
}

std::string payloadOf(const World& world) {
  CheckpointWriter out;
  world.writeState(out);
  return out.bytes();
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeFile(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// Reads the file into a fresh world: true when accepted.
bool accepted(const fs::path& p) {
  World world = makeWorld();
  const CheckpointContents file = readCheckpointFile(p, World::stateFingerprint());
  if (file.scene != sceneHash) throw CheckpointError("another scene");  // the run checkpoint's check
  const std::string& payload = file.payload;
  CheckpointReader reader(payload);
  world.readState(reader);
  return true;
}

TEST(Checkpoint, RoundTripRestoresTheState) {
  const World original = makeWorld();
  ASSERT_GT(original.contacts().size(), 10u);
  const fs::path file = fs::temp_directory_path() / "sqdem_checkpoint_roundtrip.checkpoint";
  writeCheckpointFile(file, {World::stateFingerprint(), sceneHash}, payloadOf(original));
  World restored = makeWorld();
  for (int s = 0; s < 5; ++s) restored.step();  // a different state, overwritten by the read
  const CheckpointContents contents = readCheckpointFile(file, World::stateFingerprint());
  EXPECT_EQ(contents.scene, sceneHash);  // the scene it was written for, for its reader to compare
  const std::string& payload = contents.payload;
  CheckpointReader reader(payload);
  restored.readState(reader);
  EXPECT_EQ(payloadOf(restored), payloadOf(original));
  EXPECT_THROW(readCheckpointFile(file, World::stateFingerprint() + 1), CheckpointError);  // another build
  fs::remove(file);
}

TEST(Checkpoint, EveryRandomCorruptionIsRefused) {
  const fs::path good = fs::temp_directory_path() / "sqdem_checkpoint_good.checkpoint";
  const fs::path bad = fs::temp_directory_path() / "sqdem_checkpoint_bad.checkpoint";
  writeCheckpointFile(good, {World::stateFingerprint(), sceneHash}, payloadOf(makeWorld()));
  const std::string original = readFile(good);
  std::mt19937_64 rng(2026);
  const auto below = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  int refused = 0, silentAccepts = 0;
  const int trials = 600;
  for (int t = 0; t < trials; ++t) {
    std::string bytes = original;
    switch (t % 4) {
      case 0: bytes[below(bytes.size())] ^= static_cast<char>(1u << below(8)); break;  // one bit
      case 1: {                                                                          // a run of bytes
        const std::size_t at = below(bytes.size()), length = 1 + below(16);
        for (std::size_t k = at; k < std::min(bytes.size(), at + length); ++k) bytes[k] = static_cast<char>(below(256));
        break;
      }
      case 2: bytes.resize(below(bytes.size())); break;                                   // truncated
      case 3: bytes += std::string(1 + below(64), static_cast<char>(below(256))); break;  // padded
    }
    if (bytes == original) continue;  // a random run can repeat the bytes it replaces
    writeFile(bad, bytes);
    try {
      silentAccepts += accepted(bad);
    } catch (const CheckpointError&) {
      ++refused;
    }
  }
  std::printf("%d corrupted checkpoints: %d refused, %d accepted\n", trials, refused, silentAccepts);
  EXPECT_EQ(silentAccepts, 0);
  EXPECT_GE(refused, trials * 9 / 10);
  fs::remove(good);
  fs::remove(bad);
}

// Behind a valid checksum (a deliberately forged file), the reader still checks every count and
// index: corrupted payloads are refused or read, never a crash or an out-of-range access.
TEST(Checkpoint, ForgedPayloadsAreBoundsChecked) {
  const std::string payload = payloadOf(makeWorld());
  const fs::path forged = fs::temp_directory_path() / "sqdem_checkpoint_forged.checkpoint";
  std::mt19937_64 rng(7);
  int refused = 0, read = 0;
  for (int t = 0; t < 400; ++t) {
    std::string bytes = payload;
    // Counts and indices sit in the first words of each array: corrupt anywhere, but favour
    // whole 32-bit words set to large values.
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 4)(rng);
    const std::uint32_t word = t % 2 ? static_cast<std::uint32_t>(rng()) : 0xffffffffu - static_cast<std::uint32_t>(rng() % 4);
    std::memcpy(bytes.data() + at, &word, sizeof word);
    writeCheckpointFile(forged, {World::stateFingerprint(), sceneHash}, bytes);
    try {
      read += accepted(forged);
    } catch (const CheckpointError&) {
      ++refused;
    }
  }
  std::printf("400 forged payloads: %d refused by the bounds checks, %d read\n", refused, read);
  EXPECT_GT(refused, 0);
  fs::remove(forged);
}

}  // namespace
}  // namespace sqdem

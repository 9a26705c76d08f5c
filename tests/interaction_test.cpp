// The interaction layer (interaction/): the contact store's bookkeeping, the curvature cache's
// error bound, the round (sphere) kernels against the volume-sphere law, and the ellipsoid
// detector path against the general gauge derivatives.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <cmath>
#include <random>
#include <string>
#include <tuple>

#include "sqdem/contact/detector.hpp"
#include "sqdem/interaction/contact_store.hpp"
#include "sqdem/world/world.hpp"

using namespace sqdem;

namespace {

/// An open box far larger than the pairs below.
const Domain openSpace{.lo = Vec3::Constant(-1.0), .hi = Vec3::Constant(1.0)};

ContactStore twoContacts() {
  ContactStore s;
  s.withRolling = true;
  s.add({(std::uint64_t{4} << 32) | 9, 0}, 0, 3, Vec3(0.1, 0.0, 0.0));
  s.add({(std::uint64_t{1} << 32) | 2, 0}, 1, 2, Vec3::Zero());
  s.localA[0] = Vec3(1, 2, 3);
  s.localB[0] = Vec3(4, 5, 6);
  s.normal[0] = Vec3(0, 0, 1);
  s.point[0] = Vec3(0.5, 0.5, 0.5);
  s.spring[0] = Vec3(1e-6, 0, 0);
  s.force[0] = Vec3(0, 0, 2);
  s.moment[0] = Vec3(0, 1, 0);
  s.rolling[0] = Vec3(0, 0, 3e-6);
  return s;
}

}  // namespace

// A contact's key is its bodies' ids (and feature), not its slots; carryOver copies the state,
// not the identity; a store without rolling keeps neither the rolling displacement nor the moment.
TEST(ContactStore, KeysCarryOverAndOptionalArrays) {
  const ContactStore s = twoContacts();
  EXPECT_EQ(s.idA[0], 4u);
  EXPECT_EQ(s.idB[0], 9u);
  EXPECT_EQ(s.a[0], 0u);
  EXPECT_EQ(s.b[0], 3u);
  EXPECT_LT(s.key(1), s.key(0));  // ids 1-2 before 4-9, whatever the slots
  ContactStore next;
  next.add({(std::uint64_t{7} << 32) | 8, 0}, 5, 6, Vec3::Zero());
  next.carryOver(0, s, 0);
  EXPECT_EQ(next.a[0], 5u);
  EXPECT_EQ(next.idA[0], 7u);
  EXPECT_EQ(next.localA[0], Vec3(1, 2, 3));
  EXPECT_EQ(next.spring[0], Vec3(1e-6, 0, 0));
  EXPECT_TRUE(next.rolling.empty());
  EXPECT_TRUE(next.moment.empty());
  EXPECT_TRUE(next.curvatureCache.empty());
  next.reset(0);
  EXPECT_EQ(next.status[0], ContactStatus::Separated);
  EXPECT_EQ(next.spring[0], Vec3::Zero());
}

namespace {

/// Two ellipsoids colliding while one spins (its contact point moves on both bodies and the
/// pair twists). At every step of the run with curvature tolerance eps, a copy of the world
/// takes the same step with eps = 0: the largest relative difference of the elastic normal
/// force on the same configuration (the damped total crosses zero before the bodies part), and
/// the number of steps in contact.
std::pair<double, int> cacheError(double eps) {
  const Material m{1e7, 0.3, 2500.0, 0.3, 0.8};
  World world({Superquadric::ellipsoid(1.3e-3, 0.9e-3, 0.8e-3)}, {m}, openSpace, 2e-4);
  ContactModel law = world.defaultContactModel(0, 0);
  law.curvatureTolerance = eps;
  world.setContactModel(0, 0, law);
  world.addParticle(0, 0, Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())));
  world.addParticle(0, 0, Vec3(2.05e-3, 0.3e-3, 0.2e-3), Quat(Eigen::AngleAxisd(1.1, Vec3(-1, 0.5, 2).normalized())));
  world.particles().velocity[1] = Vec3(-0.02, 0.01, 0.005);
  world.particles().setAngularVelocity(1, Vec3(0.0, 50.0, 200.0));
  world.setTimeStep(1e-7);
  double worst = 0.0;
  int touching = 0;
  for (int k = 0; k < 4000; ++k) {
    World exact = world;
    law.curvatureTolerance = 0.0;
    exact.setContactModel(0, 0, law);
    exact.step();
    world.step();
    if (world.contacts().empty() || exact.contacts().empty()) continue;
    ++touching;
    const NormalLoad& f = world.contacts().front().normalLoad();
    const NormalLoad& g = exact.contacts().front().normalLoad();
    worst = std::max(worst, std::abs((f.force - f.damping) - (g.force - g.damping)) / (g.force - g.damping));
  }
  return {worst, touching};
}

}  // namespace

// curvature_cache.hpp: holding the curvature constants while the contact moves by at most
// eps R_ref (or turns by eps) changes the Hertz force by O(eps/2) relative, so not more than eps;
// with eps = 1e-2 the cache is really used (the forces differ from the exact ones).
TEST(CurvatureCache, ForceErrorStaysWithinTheTolerance) {
  for (const double eps : {1e-4, 1e-2}) {
    const auto [worst, touching] = cacheError(eps);
    std::printf("eps %g: %d steps in contact, largest relative force error %.3g\n", eps, touching, worst);
    ASSERT_GT(touching, 500);  // an impact of ~700 steps
    EXPECT_LE(worst, eps) << "eps " << eps;
    if (eps == 1e-2) EXPECT_GT(worst, 1e-5);  // the cache was used
  }
}

// pair_kind.hpp: two spheres (radii 1 and 0.6 mm) under the curvature-exact law are the law on
// the volume-equivalent spheres, R* = rA rB / (rA + rB), circle: the same force to round-off.
TEST(RoundContacts, SpherePairUnderTheEllipticLawIsTheVolumeSphereLaw) {
  const Material m{1e7, 0.3, 2500.0, 0.3, 0.5};
  Vec3 force[2];
  for (const bool curvatures : {true, false}) {
    World world({Superquadric::sphere(1e-3), Superquadric::sphere(0.6e-3)}, {m}, openSpace, 2e-4);
    ContactModel law = world.defaultContactModel(0, 0);
    law.curvatures = curvatures;
    law.tangential.elliptic = curvatures;
    world.setContactModel(0, 0, law);
    world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
    world.addParticle(1, 0, Vec3(1.0, -0.5, 0.3).normalized() * 1.59e-3, Quat::Identity());
    world.particles().velocity[1] = Vec3(0.01, 0.02, -0.03);
    world.setTimeStep(1e-7);
    for (int k = 0; k < 50; ++k) world.step();
    ASSERT_EQ(world.contacts().size(), 1u);
    force[curvatures] = world.contacts().front().force();
  }
  ASSERT_GT(force[1].norm(), 0.0);
  EXPECT_LT((force[0] - force[1]).norm(), 1e-12 * force[1].norm());
}

// pair_surfaces.hpp: the ellipsoid path's curvatures at its solution equal those of the
// general gauge derivatives (Superquadric::derivatives, curvature.hpp) at the same points, and
// the solution is a common-normal pair (004 §2.1): nA = -nB along pB - pA.
TEST(EllipsoidDetector, CurvaturesAndCommonNormalAgreeWithTheGeneralGauge) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> axis(0.4, 1.2), angle(-3.0, 3.0), unit(-1.0, 1.0);
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Superquadric A = Superquadric::ellipsoid(axis(rng), axis(rng), axis(rng));
    const Superquadric B = Superquadric::ellipsoid(axis(rng), axis(rng), axis(rng));
    const auto rotation = [&] { return Quat(Eigen::AngleAxisd(angle(rng), Vec3(unit(rng), unit(rng), unit(rng)).normalized())); };
    const Pose poseA{Vec3::Zero(), rotation()};
    const Vec3 direction = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const Pose poseB{direction * 0.9 * (A.boundingRadius() + B.boundingRadius()), rotation()};
    const ContactGeometry g = detectContact(A, poseA, B, poseB, {.cutoff = 10.0});
    if (!g.converged()) continue;
    ++solved;
    for (const auto& [shape, pose, local, curvature, sign] :
         {std::tuple{&A, &poseA, g.localPointA, g.curvatureA, 1.0}, std::tuple{&B, &poseB, g.localPointB, g.curvatureB, -1.0}}) {
      const GaugeDerivatives d = shape->derivatives(local);
      const PrincipalCurvatures expected = principalCurvatures(d.gradient, d.hessian).rotated(pose->rotation());
      EXPECT_NEAR(curvature.k1, expected.k1, 1e-9 * expected.k1) << "trial " << trial;
      EXPECT_NEAR(curvature.k2, expected.k2, 1e-9 * expected.k1) << "trial " << trial;
      EXPECT_NEAR(std::abs(curvature.d1.dot(expected.d1)), 1.0, 1e-6) << "trial " << trial;
      const Vec3 normal = (pose->rotation() * d.gradient).normalized();
      EXPECT_NEAR((sign * normal - g.normal).norm(), 0.0, 1e-9) << "trial " << trial;
    }
    EXPECT_NEAR((g.pointB - g.pointA).cross(g.normal).norm(), 0.0, 1e-9) << "trial " << trial;
  }
  EXPECT_GT(solved, 150);
}

namespace {

/// A periodic 4 x 4 x 4 lattice of `shape` (touching its six neighbours before the tilts, small random
/// tilts and velocities): persistent contacts that move a little every step, as in a settled bed.
World jigglingLattice(const Superquadric& shape, bool confirmWarm) {
  const Vec3 spacing = 2.0 * shape.halfExtents();
  const Domain box{.lo = Vec3::Zero(), .hi = 4.0 * spacing, .periodic = {true, true, true}};
  World world({shape}, {Material{1e7, 0.3, 1000.0, 0.3, 0.5}}, box, 0.1 * shape.halfExtents().minCoeff());
  world.setContactModel(0, 0, world.defaultContactModel(0, 0));
  DetectorControl control;
  control.confirmWarm = confirmWarm;
  world.setDetectorControl(control);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> tilt(0.0, 1e-4), speed(0.0, 1e-5);
  for (int i = 0; i < 64; ++i) {
    const Vec3 axis(tilt(rng), tilt(rng), tilt(rng));
    const std::size_t n = world.addParticle(0, 0, (Vec3(i % 4, i / 4 % 4, i / 16) + Vec3::Constant(0.5)).cwiseProduct(spacing),
                                            Quat(Eigen::AngleAxisd(axis.norm(), axis.normalized())));
    world.particles().velocity[n] = Vec3(speed(rng), speed(rng), speed(rng));
    world.particles().setAngularVelocity(n, Vec3(speed(rng), speed(rng), speed(rng)) / shape.halfExtents().minCoeff());
  }
  world.setTimeStep(0.2 * world.rayleighTimeStep());
  return world;
}

}  // namespace

// warm_skip.hpp, detector.hpp (confirmContact): a warm answer confirmed from the kept normals is
// the warm solve's answer to the bit, so a run that confirms and one that evaluates every surface
// stay identical at every step (positions, orientations, velocities, every contact's force), with
// the same detector calls and iterations, while the first confirms a share of its warm answers.
TEST(ConfirmedWarmAnswers, SameBitsAsEvaluatingEverySurface) {
  for (const Superquadric& shape : {Superquadric::ellipsoid(1.3e-3, 0.9e-3, 0.8e-3), Superquadric(1.1e-3, 0.75e-3, 0.7e-3, 6.0, 6.0)}) {
    World confirming = jigglingLattice(shape, true), evaluating = jigglingLattice(shape, false);
    for (int step = 0; step < 1500; ++step) {
      confirming.step();
      evaluating.step();
      const ParticleStore &p = confirming.particles(), &q = evaluating.particles();
      for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_EQ(p.position[i], q.position[i]) << "step " << step << ", particle " << i;
        ASSERT_EQ(p.orientation[i].coeffs(), q.orientation[i].coeffs()) << "step " << step << ", particle " << i;
        ASSERT_EQ(p.velocity[i], q.velocity[i]) << "step " << step << ", particle " << i;
        ASSERT_EQ(p.angularVelocity[i], q.angularVelocity[i]) << "step " << step << ", particle " << i;
      }
      ASSERT_EQ(confirming.interactions().actingCount(), evaluating.interactions().actingCount()) << "step " << step;
      const auto mine = confirming.contacts(), theirs = evaluating.contacts();
      for (auto c = mine.begin(), e = theirs.begin(); c != mine.end(); ++c, ++e) {
        ASSERT_EQ((*c).key(), (*e).key());
        ASSERT_EQ((*c).force(), (*e).force()) << "step " << step;
      }
    }
    const ContactStatistics &sc = confirming.statistics(), &se = evaluating.statistics();
    std::printf("n1 = %g: %lld detector calls, %.2f iterations per call, %lld confirmed (%.1f %%)\n", shape.n1(),
                sc.detectorCalls, static_cast<double>(sc.detectorIterations) / sc.detectorCalls, sc.detectorConfirmations,
                100.0 * sc.detectorConfirmations / sc.detectorCalls);
    EXPECT_EQ(sc.detectorCalls, se.detectorCalls);
    EXPECT_EQ(sc.detectorIterations, se.detectorIterations);
    EXPECT_EQ(se.detectorConfirmations, 0);
    EXPECT_GT(sc.detectorConfirmations, sc.detectorCalls / 10);  // the path this test is about was taken
  }
}

namespace {

/// A 5 x 5 x 4 lattice of spheres, periodic in x and y, on a floor and under a tilted lid that
/// moves (down and sideways): radii 1 and 0.8 mm and densities 2500 and 4000 kg/m^3 in turn (A
/// and B differ in every input), sites 2 mm apart +- 5 um, with random velocities and spins large
/// enough that contacts open, close and slide, on the given path.
World shakenSpheres(SimdPath path) {
  const double r = 1e-3, pitch = 2e-3;
  const Domain box{.lo = Vec3::Zero(), .hi = Vec3(5 * pitch, 5 * pitch, 4 * pitch), .periodic = {true, true, false}};
  World world({Superquadric::sphere(r), Superquadric::sphere(0.8 * r)},
              {Material{1e7, 0.3, 2500.0, 0.3, 0.5}, Material{2e7, 0.25, 4000.0, 0.4, 0.6}}, box, 0.1 * r);
  for (std::uint32_t m : {0u, 1u}) {
    for (std::uint32_t n : {0u, 1u}) world.setContactModel(m, n, world.defaultContactModel(m, n));
  }
  world.setSimdPath(path);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3(0.0, 0.0, 4 * pitch), Vec3(0.05, 0.0, -1.0).normalized()}},
                     .velocity = Vec3(1e-3, 0.0, -1e-3), .material = 1});
  std::mt19937_64 rng(3);
  std::normal_distribution<double> speed(0.0, 2e-3), jitter(0.0, 5e-6);
  for (int i = 0; i < 100; ++i) {
    const Vec3 site = (Vec3(i % 5, i / 5 % 5, i / 25) + Vec3::Constant(0.5)) * pitch + Vec3(jitter(rng), jitter(rng), jitter(rng));
    const std::size_t n = world.addParticle(i % 3 == 0, i % 2, site, Quat::Identity());
    world.particles().velocity[n] = Vec3(speed(rng), speed(rng), speed(rng));
    world.particles().setAngularVelocity(n, Vec3(speed(rng), speed(rng), speed(rng)) / r);
  }
  world.setTimeStep(0.2 * world.rayleighTimeStep());
  return world;
}

/// Bit for bit, -0 and +0 told apart (Eigen's == is not).
template <typename T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace

// simd_path.hpp, round_hertz_lanes.hpp: every path of the round Hertz kernels across contacts
// (sphere pairs, spheres on plane walls) gives the contact-by-contact kernel's bits: the state of
// every particle, every wall's load and every record of every candidate contact (status, normal,
// overlap, point, spring, the normal law's record, force, load) and every statistic, at every
// step of a run in which contacts form, open and slide (Coulomb's cap, mindlin_spring.hpp).
TEST(RoundHertzLanes, EveryPathGivesTheContactByContactBits) {
  for (const SimdPath path : availableSimdPaths()) {
    if (path == SimdPath::Scalar) continue;
    World lanes = shakenSpheres(path), reference = shakenSpheres(SimdPath::Scalar);
    const auto mu = [&](std::uint32_t a, std::uint32_t b) {
      const ParticleStore& p = lanes.particles();
      const std::uint32_t mb = b & wallFlag ? lanes.walls()[b & ~wallFlag].material : p.material[b];
      return lanes.defaultContactModel(p.material[a], mb).tangential.friction;
    };
    long long sliding = 0, acting = 0, opened = 0, onWalls = 0;
    for (int step = 0; step < 600; ++step) {
      lanes.step();
      reference.step();
      const ParticleStore &p = lanes.particles(), &q = reference.particles();
      for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_EQ(p.position[i], q.position[i]) << simdPathName(path) << ", step " << step << ", particle " << i;
        ASSERT_EQ(p.velocity[i], q.velocity[i]) << simdPathName(path) << ", step " << step << ", particle " << i;
        ASSERT_EQ(p.angularVelocity[i], q.angularVelocity[i]) << simdPathName(path) << ", step " << step << ", particle " << i;
      }
      for (std::size_t w = 0; w < lanes.walls().size(); ++w) {
        ASSERT_TRUE(sameBits(lanes.walls()[w].force, reference.walls()[w].force)) << simdPathName(path) << ", step " << step;
        ASSERT_TRUE(sameBits(lanes.walls()[w].torque, reference.walls()[w].torque)) << simdPathName(path) << ", step " << step;
      }
      const ContactStore &s = lanes.interactions().store(), &t = reference.interactions().store();
      ASSERT_EQ(s.size(), t.size());
      for (std::size_t k = 0; k < s.size(); ++k) {
        const auto where = [&] { return std::string(simdPathName(path)) + ", step " + std::to_string(step) + ", contact " + std::to_string(k); };
        ASSERT_EQ(s.key(k), t.key(k)) << where();
        ASSERT_EQ(s.status[k], t.status[k]) << where();
        ASSERT_TRUE(sameBits(s.normal[k], t.normal[k])) << where();
        ASSERT_TRUE(sameBits(s.overlap[k], t.overlap[k])) << where();
        ASSERT_TRUE(sameBits(s.point[k], t.point[k])) << where();
        ASSERT_TRUE(sameBits(s.spring[k], t.spring[k])) << where();
        ASSERT_TRUE(sameBits(s.normalHistory[k], t.normalHistory[k])) << where();
        ASSERT_EQ(s.acting[k], t.acting[k]) << where();
        ASSERT_TRUE(sameBits(s.force[k], t.force[k])) << where();
        const NormalLoad &a = s.load[k], &b = t.load[k];
        ASSERT_TRUE(sameBits(std::array{a.force, a.damping, a.stiffness, a.area}, std::array{b.force, b.damping, b.stiffness, b.area})) << where();
        ASSERT_EQ(a.yielded, b.yielded) << where();
        if (!s.acting[k]) continue;
        ++acting;
        onWalls += s.onWall(k);
        const Vec3 tangential = s.force[k] - s.force[k].dot(s.normal[k]) * s.normal[k];
        sliding += std::abs(tangential.norm() - mu(s.a[k], s.b[k]) * a.force) < 1e-9 * a.force;
      }
      opened += s.size() - std::count(s.acting.begin(), s.acting.end(), std::uint8_t{1});
    }
    std::printf("%s: %lld contact-steps acting (%lld on walls), %lld sliding, %lld candidate-steps not acting\n",
                std::string(simdPathName(path)).c_str(), acting, onWalls, sliding, opened);
    EXPECT_GT(onWalls, acting / 20);
    EXPECT_GT(sliding, acting / 100);  // the cap's branch was taken
    EXPECT_GT(opened, acting / 10);    // and the separated lanes'
    std::vector<long long> mine, theirs;
    ContactStatistics::forEachCount(lanes.statistics(), [&](long long n) { mine.push_back(n); });
    ContactStatistics::forEachCount(reference.statistics(), [&](long long n) { theirs.push_back(n); });
    EXPECT_EQ(mine, theirs);
  }
}

// Coincident centres are Degenerate on every path (round_contact.hpp: normal +z, overlap rA + rB,
// no force), counted once per force computation (the first step computes two).
TEST(RoundHertzLanes, CoincidentCentresAreDegenerateOnEveryPath) {
  for (const SimdPath path : availableSimdPaths()) {
    World world({Superquadric::sphere(1e-3)}, {Material{1e7, 0.3, 2500.0, 0.3, 0.5}}, openSpace, 1e-4);
    world.setContactModel(0, 0, world.defaultContactModel(0, 0));
    world.setSimdPath(path);
    world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
    world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
    world.setTimeStep(1e-6);
    world.step();
    const ContactStore& s = world.interactions().store();
    ASSERT_EQ(s.size(), 1u) << simdPathName(path);
    EXPECT_EQ(s.status[0], ContactStatus::Degenerate) << simdPathName(path);
    EXPECT_EQ(s.overlap[0], 2e-3) << simdPathName(path);
    EXPECT_EQ(s.force[0], Vec3::Zero()) << simdPathName(path);
    EXPECT_EQ(s.normal[0], Vec3::UnitZ()) << simdPathName(path);
    EXPECT_EQ(world.statistics().failuresByStatus[static_cast<int>(ContactStatus::Degenerate)], 2) << simdPathName(path);
    EXPECT_EQ(world.statistics().detectorFailures, 2) << simdPathName(path);
  }
}

// A deep overlap is one deeper than half the smaller volume radius of the pair, whichever body
// is A (the count once took A's radius, so a small particle deep in a large one counted or not by
// the pair's order): a small and a large body, on the round path (spheres) and the general one
// (ellipsoids along x), overlapping by 0.6 and by 0.4 of the small one's R_vol, in both orders.
// A model that expects deep overlaps (`deep_overlaps: expected`) counts them apart.
TEST(DeepOverlaps, CountAgainstTheSmallerVolumeRadiusInEitherOrder) {
  const Material m{1e7, 0.3, 2500.0, 0.3, 0.5};
  const std::array<std::array<Superquadric, 2>, 2> pairs{{{Superquadric::sphere(1e-3), Superquadric::sphere(0.2e-3)},
                                                           {Superquadric::ellipsoid(1.2e-3, 1e-3, 1e-3),
                                                            Superquadric::ellipsoid(0.24e-3, 0.2e-3, 0.2e-3)}}};
  for (const auto& shapes : pairs) {
    const double small = shapes[1].volumeEquivalentRadius();
    for (const double depth : {0.6, 0.4}) {
      for (const auto& [smallFirst, expected] : {std::pair{false, false}, {true, false}, {false, true}, {true, true}}) {
        World world({shapes[0], shapes[1]}, {m}, openSpace, 1e-4);
        ContactModel model = world.defaultContactModel(0, 0);
        model.deepOverlapsExpected = expected;
        world.setContactModel(0, 0, model);
        const double distance = shapes[0].a() + shapes[1].a() - depth * small;  // along x: a is the x semi-axis
        const std::array<Vec3, 2> at{Vec3::Zero(), Vec3(distance, 0.0, 0.0)};
        for (const int k : smallFirst ? std::array<int, 2>{1, 0} : std::array<int, 2>{0, 1}) {
          world.addParticle(k, 0, at[k], Quat::Identity());
        }
        world.computeForces();
        ASSERT_EQ(world.contacts().size(), 1u);
        EXPECT_NEAR(world.contacts().front().overlap(), depth * small, 1e-9 * small);
        const int deep = depth > 0.5 ? 1 : 0;
        EXPECT_EQ(world.statistics().deepOverlaps, expected ? 0 : deep)
            << "a/c " << shapes[0].a() / shapes[0].c() << ", overlap " << depth << " R_vol, small body first " << smallFirst;
        EXPECT_EQ(world.statistics().expectedDeepOverlaps, expected ? deep : 0)
            << "a/c " << shapes[0].a() / shapes[0].c() << ", overlap " << depth << " R_vol, small body first " << smallFirst;
      }
    }
  }
}

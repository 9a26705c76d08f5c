// The bond component of the contacts (docs/bonds.md): bonds formed between the pairs whose model
// has one, and each step their loads added to their contacts' (after the contact law, by the
// thread that computed the contact), or the bond broken.

#include <algorithm>

#include "sqdem/contact/detector.hpp"
#include "sqdem/interaction/interactions.hpp"

#include "contact_force.hpp"

namespace sqdem {
namespace {

/// Body A of contact k.
Pose bondPoseA(const InteractionScene& scene, const ContactStore& s, std::uint32_t k) {
  return {scene.particles.position[s.a[k]], scene.particles.orientation[s.a[k]]};
}

/// Body B of contact k as a bond sees it: a particle's pose, or a plane's point unturned (planes
/// translate only).
Pose bondPoseB(const InteractionScene& scene, const ContactStore& s, std::uint32_t k) {
  if (s.onWall(k)) return {scene.walls[s.b[k] & ~wallFlag].reference(), Quat::Identity()};
  return {scene.particles.position[s.b[k]], scene.particles.orientation[s.b[k]]};
}

/// Velocity of B's material point at x minus A's (m/s): a plane wall's surface velocity for B.
Vec3 relativeVelocity(const InteractionScene& scene, const ContactStore& s, std::uint32_t k, const Vec3& x) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const Vec3 velocityA = p.velocity[a] + p.angularVelocity[a].cross(x - p.position[a]);
  if (s.onWall(k)) return scene.walls[b & ~wallFlag].surfaceVelocity(x) - velocityA;
  return p.velocity[b] + p.angularVelocity[b].cross(x - p.position[b]) - velocityA;
}

/// Angular velocity of B minus A's (rad/s): a plane wall does not turn.
Vec3 relativeSpin(const InteractionScene& scene, const ContactStore& s, std::uint32_t k) {
  const ParticleStore& p = scene.particles;
  return (s.onWall(k) ? Vec3::Zero() : p.angularVelocity[s.b[k]]) - p.angularVelocity[s.a[k]];
}

/// The dashpots of a damped bond (parallel_bond.hpp) of contact k, deformed along `axis`, at `centre`.
BondDashpots dashpots(const InteractionScene& scene, const ContactStore& s, std::uint32_t k, const ParallelBond& bond,
                      const BondSection& section, const Vec3& axis, const Vec3& centre) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const double mass = s.onWall(k) ? p.mass[a] : detail::reduced(p.mass[a], p.mass[b]);
  const double moment = s.onWall(k) ? p.inertia[a].minCoeff() : detail::reduced(p.inertia[a].minCoeff(), p.inertia[b].minCoeff());
  return bondDashpots(bond, section, axis, relativeVelocity(scene, s, k, centre), relativeSpin(scene, s, k), mass, moment);
}

}  // namespace

std::size_t Interactions::formBonds(const InteractionScene& scene, double gapRatio) {
  const ParticleStore& p = scene.particles;
  ContactStore& s = store_;
  std::size_t formed = 0;
  for (const Group& group : groups_) {
    const ContactModel& model = scene.models[group.model];
    // Bonds to a plane, not to a cylinder or a mesh (they turn: docs/bonds.md).
    if (!model.bond || group.kind == PairKind::ParticleCylinder || group.kind == PairKind::ParticleMesh) continue;
    for (const std::uint32_t k : group.members) {
      if (s.bond[k].state != BondRecord::State::None) continue;
      const Superquadric& A = scene.shapes[p.shape[s.a[k]]];
      const Pose poseA{p.position[s.a[k]], p.orientation[s.a[k]]}, poseB = bondPoseB(scene, s, k);
      const DetectorSettings settings{.cutoff = scene.skin, .tolerance = scene.detector.tolerance, .curvatures = false};
      ContactGeometry g;
      double r = A.volumeEquivalentRadius();
      if (s.onWall(k)) {
        g = detectContact(A, poseA, scene.walls[s.b[k] & ~wallFlag].get<PlaneWall>().plane, settings);
      } else {
        const Superquadric& B = scene.shapes[p.shape[s.b[k]]];
        g = detectContact(A, poseA, B, poseB, settings);
        r = std::min(r, B.volumeEquivalentRadius());
      }
      if (!g.converged() || -g.overlap > gapRatio * r) continue;
      s.bond[k] = {.rest = BondRest::formed(poseA, poseB, 0.5 * (g.pointA + g.pointB), g.normal),
                   .radius = model.bond->radiusMultiplier * r,
                   .state = BondRecord::State::Intact};
      ++formed;
    }
  }
  return formed;
}

void Interactions::addBondLoads(const InteractionScene& scene, std::span<const std::uint32_t> members, const ParallelBond& bond,
                                ContactStatistics& statistics) {
  ContactStore& s = store_;
  long long broken = 0;
  for (const std::uint32_t k : members) {
    BondRecord& record = s.bond[k];
    if (!record.intact()) continue;
    const BondPlace place = bondPlace(record.rest, bondPoseA(scene, s, k), bondPoseB(scene, s, k));
    const BondSection section(record.radius);
    BondLoads loads = bondLoads(bond, section, place.deformation);
    if (loads.breaks(bond)) {
      record.state = BondRecord::State::Broken;
      loads = {};
      ++broken;
    } else {
      if (bond.dampingRatio > 0.0) {  // the cement's stresses are the springs'; the dashpots add their loads
        const BondDashpots d = dashpots(scene, s, k, bond, section, place.deformation.axis, place.centre);
        loads.force += d.force;
        loads.moment += d.moment;
      }
      // The bond's force acts at its centre: about the contact point, its moment joins the pure
      // moment (reduction.cpp sums (point - x) x force + moment).
      if (!s.acting[k]) s.point[k] = place.centre;
      s.moment[k] += (place.centre - s.point[k]).cross(loads.force) + loads.moment;
      s.force[k] += loads.force;
      s.acting[k] = 1;
    }
    if (s.withEnergy) {
      // Trapezoidal in the loads with the drift's velocities, as the contacts' work
      // (contact_work.hpp), at the bond's centre: what the bodies lost to the bond.
      const Vec3 velocity = relativeVelocity(scene, s, k, place.centre), spin = relativeSpin(scene, s, k);
      s.energy[k].bond = -0.5 * scene.dt * ((record.force + loads.force).dot(velocity) + (record.moment + loads.moment).dot(spin));
      s.energy[k].bondStored = loads.energy;
    }
    record.force = loads.force;
    record.moment = loads.moment;
  }
#pragma omp critical(sqdem_contact_statistics)
  statistics.bondsBroken += broken;
}

std::size_t Interactions::bondCount() const { return store_.intactBonds(); }

std::vector<BondReport> Interactions::bonds(const InteractionScene& scene) const {
  const ContactStore& s = store_;
  std::vector<BondReport> reports;
  for (const Group& group : groups_) {
    const std::optional<ParallelBond>& bond = scene.models[group.model].bond;
    if (!bond) continue;
    for (const std::uint32_t k : group.members) {
      if (!s.bond[k].intact()) continue;
      const BondPlace place = bondPlace(s.bond[k].rest, bondPoseA(scene, s, k), bondPoseB(scene, s, k));
      const BondLoads loads = bondLoads(*bond, BondSection(s.bond[k].radius), place.deformation);
      reports.push_back({k, place.centre, loads,
                         std::max(loads.tensileStress / bond->tensileStrength, loads.shearStress / bond->shearStrength)});
    }
  }
  std::ranges::sort(reports, {}, [&s](const BondReport& r) { return s.key(r.contact); });
  return reports;
}

}  // namespace sqdem

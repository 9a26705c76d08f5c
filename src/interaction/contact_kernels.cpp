// The fused detect-then-law kernels: one instantiation per pair kind and normal law type, run
// over a group's contacts with the law fixed for the whole loop.

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <span>
#include <variant>

#include "contact_force.hpp"
#include "contact_work.hpp"
#include "round_hertz_lanes.hpp"
#include "sqdem/contact/detector.hpp"
#include "sqdem/interaction/interactions.hpp"
#include "sqdem/truegap/true_gap_rungs.hpp"

namespace sqdem {
namespace {

Pose poseOf(const ParticleStore& p, std::uint32_t i) { return {p.position[i], p.orientation[i]}; }

/// Whether a group computes curvatures from a cache (curvature_cache.hpp) rather than every step.
bool cachesCurvatures(const ContactModel& model, PairKind kind) {
  return !round(kind) && model.usesCurvatures() && model.curvatureTolerance > 0.0;
}

/// A round kind's closed form for contact k (round_contact.hpp), solved only within the cut-off:
/// the skin, or the law's range where that is shorter (a gap the law does not act across is
/// Separated, as nothing is warm-started from a round contact). Two spheres beyond it are
/// told apart by their squared distance (no square root). A sphere's radius is its bounding
/// radius (ParticleStore::boundingRadius: one load, where its shape's is three in a chain).
template <PairKind Kind>
[[gnu::always_inline]] inline RoundContact detectRound(const InteractionScene& scene, const ContactStore& s, std::uint32_t k, double range) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const double rA = p.boundingRadius[a], cutoff = std::min(scene.skin, range);
  if constexpr (withWall(Kind)) {
    return detectSphereWall(p.position[a], rA, scene.walls[b & ~wallFlag].get<PlaneWall>().plane, cutoff);
  } else {
    const double rB = p.boundingRadius[b], reach = rA + rB + cutoff;
    if ((p.position[b] - p.position[a]).squaredNorm() > reach * reach) return RoundContact{};
    return detectSpheres(p.position[a], rA, p.position[b], rB, cutoff);
  }
}

/// The pair kind's detector for contact k, warm-started from the store; the curvatures only
/// when asked for (a law that does not use them, or takes them from its cache, does not pay).
/// A quiet pair's warm answer (WarmSkip::quiet) is confirmed from its kept
/// normals where it still holds (skip: the contact's record, null when not kept;
/// warm_skip.hpp), counted in confirmations.
template <PairKind Kind>
ContactGeometry detect(const InteractionScene& scene, const std::vector<double>& speedBound, const ContactModel& model,
                       ContactStore& s, std::uint32_t k, bool curvatures, detail::WarmSkip* skip, long long& confirmations) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const Superquadric& A = scene.shapes[p.shape[a]];
  // Gaps within the skin are solved too (rough and adhesive contacts act across them, and every
  // candidate is warm-started next step).
  const DetectorSettings settings{.cutoff = scene.skin, .tolerance = scene.detector.tolerance, .curvatures = curvatures};
  if constexpr (Kind == PairKind::ParticleCylinder || Kind == PairKind::ParticleMesh) {
    const WarmStart warm{s.localA[k], s.localB[k], s.overlap[k]};
    const WarmStart* touched = s.status[k] == ContactStatus::Converged && scene.detector.warmStart ? &warm : nullptr;
    const Wall& wall = scene.walls[b & ~wallFlag];
    if constexpr (Kind == PairKind::ParticleCylinder) {
      Cylinder image = wall.get<CylinderWall>().cylinder;  // the image nearest A (a periodic box)
      image.point += s.wallImage[k];
      return detectContact(A, poseOf(p, a), image, settings, touched);
    } else {
      const MeshWall& mesh = wall.get<MeshWall>();
      return detectContact(A, poseOf(p, a), scene.meshes[mesh.mesh], mesh.pose(), s.feature[k], settings, touched);
    }
  } else if constexpr (withWall(Kind)) {
    return detectContact(A, poseOf(p, a), scene.walls[b & ~wallFlag].get<PlaneWall>().plane, settings);
  } else {
    // A pair found separated stays so until the particles could have moved by its gap.
    if (s.separation[k] > 0.0) {
      s.separation[k] -= scene.dt * (speedBound[a] + speedBound[b]);
      if (s.separation[k] > model.reach) return ContactGeometry{};  // Separated, no iterations
    }
    const Superquadric& B = scene.shapes[p.shape[b]];
    const Pose poseA = poseOf(p, a), poseB = poseOf(p, b);
    const bool warm = s.status[k] == ContactStatus::Converged && scene.detector.warmStart;
    const WarmStart previous{s.localA[k], s.localB[k], s.overlap[k]};
    ContactGeometry g;
    bool confirmed = false;
    if (warm && skip != nullptr && skip->left > 0 && !curvatures) {
      if (const std::optional<ContactGeometry> c = confirmContact(A, poseA, B, poseB, settings, previous, skip->normalA, skip->normalB)) {
        g = *c;
        confirmed = true;
      }
    }
    if (!confirmed) g = warm ? detectContact(A, poseA, B, poseB, settings, previous) : detectContact(A, poseA, B, poseB, settings);
    if (skip != nullptr) {
      if (confirmed) {
        --skip->left;
        ++confirmations;
      } else if (detail::WarmSkip::quiet(g, settings.tolerance * referenceVolumeRadius(A, B))) {
        skip->restart(g.localNormalA, g.localNormalB);
      } else {
        skip->unset();
      }
    }
    s.separation[k] = g.status == ContactStatus::Separated ? -g.overlap : 0.0;
    return g;
  }
}

/// Relative motion at the contact point; the volume radii (a sphere's own: detectRound).
template <PairKind Kind>
[[gnu::always_inline]] inline ContactKinematics kinematics(const InteractionScene& scene, const ContactStore& s, std::uint32_t k, const Vec3& point) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const auto volumeRadius = [&](std::uint32_t i) {
    if constexpr (round(Kind)) {
      return p.boundingRadius[i];
    } else {
      return scene.shapes[p.shape[i]].volumeEquivalentRadius();
    }
  };
  ContactKinematics motion;
  motion.volumeRadiusA = volumeRadius(a);
  motion.angularVelocityA = p.angularVelocity[a];
  const Vec3 velocityA = p.velocity[a] + p.angularVelocity[a].cross(point - p.position[a]);
  if constexpr (withWall(Kind)) {
    motion.relativeVelocity = scene.walls[b & ~wallFlag].surfaceVelocity(point - s.wallImage[k]) - velocityA;
    motion.effectiveMass = p.mass[a];
  } else {
    motion.relativeVelocity = p.velocity[b] + p.angularVelocity[b].cross(point - p.position[b]) - velocityA;
    motion.volumeRadiusB = volumeRadius(b);
    motion.angularVelocityB = p.angularVelocity[b];
    motion.effectiveMass = detail::reduced(p.mass[a], p.mass[b]);
  }
  return motion;
}

/// B's tilt against A since a curvature cache was kept, for the true-gap rungs' bound
/// (TrueGapRungs::holdAfterTurning): its turn from the kept relative orientation to `relative`
/// (q_A* q_B) as a rotation vector in A's frame, along the rungs' plane axes t1 (the kept major
/// axis laid on the plane as the rungs' gap lays it, truegap/pair_gap.hpp) and t2 = n x t1, n
/// the contact normal now (A's frame); its twist about n left out.
Vec2 tiltSince(const CurvatureCache& cache, const Quat& relative, const Vec3& n) {
  Quat turn = relative * Quat(cache.relative).conjugate();  // applied on the left: in A's frame
  if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();
  const double half = turn.vec().norm();  // sin(angle / 2)
  if (!(half > 0.0)) return Vec2::Zero();
  const Vec3 rotation = 2.0 * std::atan2(half, turn.w()) / half * turn.vec(), t1 = planeAxis(cache.majorAxisA, n);
  return {rotation.dot(t1), rotation.dot(n.cross(t1))};
}

/// The law's view of contact k from its curvature cache while that holds, and under the true-gap
/// law while the bodies' tilt since keeps the gap across the contact within the law's
/// gap_tolerance of the overlap; otherwise the curvatures at the new contact points are computed
/// and the cache refreshed.
template <PairKind Kind>
LawGeometry cachedLawGeometry(const InteractionScene& scene, const ContactModel& model, ContactStore& s,
                              std::uint32_t k, ContactGeometry& g, const ContactKinematics& motion, double cosHalfAngle) {
  constexpr bool wall = withWall(Kind);
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const Quat relative = wall ? p.orientation[a].conjugate() : Quat(p.orientation[a].conjugate() * p.orientation[b]);
  const double reference = wall ? motion.volumeRadiusA : std::sqrt(motion.volumeRadiusA * motion.volumeRadiusB);
  CurvatureCache& cache = s.curvatureCache[k];
  const Mat3 RA = p.orientation[a].toRotationMatrix();
  const TrueGapLaw* trueGap = s.withTrueGap ? std::get_if<TrueGapLaw>(&model.normal) : nullptr;
  const auto tiltedTooFar = [&] {  // the true-gap law's rungs: the gap across the contact changed too much
    if (trueGap == nullptr || s.trueGap[k].weight == 0.0) return false;
    const Vec2 tilt = tiltSince(cache, relative, RA.transpose() * g.normal);
    return !s.trueGap[k].holdAfterTurning(g.overlap, tilt.x(), tilt.y(), trueGap->gapTolerance);
  };
  if (!cache.holds(g.localPointA, g.localPointB, relative, model.curvatureTolerance * reference, cosHalfAngle) || tiltedTooFar()) {
    const Superquadric& A = scene.shapes[p.shape[a]];
    if constexpr (wall) {
      addCurvatures(g, A, poseOf(p, a));
    } else {
      addCurvatures(g, A, poseOf(p, a), scene.shapes[p.shape[b]], poseOf(p, b));
    }
    const LawGeometry fresh = detail::lawGeometry(model, g, motion);
    cache = {g.localPointA, g.localPointB, relative.coeffs(), fresh.contact.radii, fresh.contact.factors,
             RA.transpose() * fresh.majorAxis};
    if (s.withTrueGap) s.trueGap[k].forget();  // solved on the pose the cache kept
    return fresh;
  }
  LawGeometry held{g.overlap, g.normal, detail::sizedContact(model, motion), Vec3::Zero()};
  held.contact.radii = cache.radii;
  held.contact.factors = cache.factors;
  if (model.tangential.elliptic && model.tangential.friction > 0.0) {  // the held axis, in today's tangent plane
    const Vec3 u = RA * cache.majorAxisA;
    held.majorAxis = (u - u.dot(g.normal) * g.normal).normalized();
  }
  return held;
}

/// Whether contact k's true-gap rungs around `overlap` (mechanics/true_gap_law.hpp) wait to be
/// solved (Interactions::solveDeferredRungs): not where one of them failed on this pose. Solved
/// on the pose the curvature cache keeps, or without a cache on the step's own (rungPose), whose
/// rungs are dropped after it.
bool rungsWait(TrueGapRungs& rungs, const Superquadric& A, const Superquadric& B, bool cached, double overlap) {
  if (rungs.length == 0.0) rungs = trueGapLadder(A, B);
  if (!cached) rungs.forget();
  if (rungs.holds(overlap)) return false;
  const int segment = rungs.segment(overlap);
  return !rungs.failed(segment) && !rungs.failed(segment + 1);
}

/// The pose contact k's rungs are solved on: the one its curvature cache keeps (its points and
/// the bodies' relative orientation: the same rungs from the same cache on any thread or rank,
/// and after a restart), or without a cache the step's own.
PairGap rungPose(const InteractionScene& scene, const ContactStore& s, std::uint32_t k, bool cached, const ContactGeometry& g) {
  const ParticleStore& p = scene.particles;
  const std::uint32_t a = s.a[k], b = s.b[k];
  const Superquadric &A = scene.shapes[p.shape[a]], &B = scene.shapes[p.shape[b]];
  if (!cached) return PairGap({A, poseOf(p, a)}, {B, poseOf(p, b)}, g);
  const CurvatureCache& c = s.curvatureCache[k];
  return PairGap::touchingAt(A, B, c.localA, c.localB, Quat(c.relative), c.majorAxisA, c.radii);
}

/// The rungs handed on to the law in `view`; where one around its overlap is missing (its
/// half-space contact failed on this pose) none: elliptic Hertz, counted, until the pose is
/// refreshed.
void handOnRungs(const TrueGapRungs& rungs, LawGeometry& view, long long& fallbacks) {
  view.contact.trueGap = &rungs;
  if (rungs.holds(view.overlap)) return;
  view.contact.trueGap = nullptr;
  ++fallbacks;
}

/// The model as a kind runs it: a round contact (pair_kind.hpp) on the circle, without curvatures.
ContactModel asRun(ContactModel model, PairKind kind) {
  if (round(kind)) {
    model.curvatures = false;
    model.tangential.elliptic = false;
  }
  return model;
}

/// A kernel's counts, added to the step's statistics once per thread and group.
struct KernelCounts {
  long long calls = 0, iterations = 0, confirmations = 0, failures = 0, deep = 0, lost = 0, invalid = 0, rungSolves = 0, rungFallbacks = 0;
  long long byStatus[contactStatusCount] = {};

  /// A law's answer on a contact: an invalid form, a deep overlap.
  void tally(const ContactForce& force, double overlap, const ContactKinematics& motion) {
    invalid += !force.valid;
    deep += force.acting && detail::deepOverlap(overlap, motion.volumeRadiusA, motion.volumeRadiusB);
  }
  void addTo(ContactStatistics& statistics, bool deepOverlapsExpected) const {
#pragma omp critical(sqdem_contact_statistics)
    {
      statistics.detectorCalls += calls;
      statistics.detectorIterations += iterations;
      statistics.detectorConfirmations += confirmations;
      statistics.detectorFailures += failures;
      for (int k = 0; k < contactStatusCount; ++k) statistics.failuresByStatus[k] += byStatus[k];
      (deepOverlapsExpected ? statistics.expectedDeepOverlaps : statistics.deepOverlaps) += deep;
      statistics.lostAdhesions += lost;
      statistics.lawFailures += invalid;
      statistics.trueGapRungs += rungSolves;
      statistics.trueGapFallbacks += rungFallbacks;
    }
  }
};

ContactHistory storedHistory(const ContactStore& s, std::uint32_t k) {
  ContactHistory history{.spring = s.spring[k], .normal = s.normalHistory[k]};
  if (s.withRolling) history.rolling = s.rolling[k];
  return history;
}

/// The law on a contact's view (a round contact under Hertz takes roundHertzForce); with the
/// ledger, its stored energy.
template <NormalLawComponent Law, bool Ledger>
ContactForce lawForce(const ContactModel& model, const Law& law, const LawGeometry& view, const ContactKinematics& motion,
                      ContactHistory& history, double dt, double& stored) {
  const ContactForce force = detail::contactForce(model, law, view, motion, history, dt);
  if constexpr (Ledger) {
    if (force.acting) stored = storedEnergy(law, view.contact, view.overlap, history.normal, force.normal - force.normalDamping);
  }
  return force;
}

/// Contact k's record of the step: the detector's normal, overlap and point, the law's loads and
/// history; with the ledger, its work over the step (contact_work.hpp) and stored energy.
template <PairKind Kind, bool Ledger>
void record(const InteractionScene& scene, ContactStore& s, std::uint32_t k, const Vec3& normal, double overlap, const Vec3& point,
            bool converged, const ContactHistory& history, const ContactForce& force, double stored) {
  // The ledger's load before the step: the law's (the bond's part is the bond's work, bonds.cpp).
  [[maybe_unused]] const detail::ContactLoad before =
      Ledger ? detail::ContactLoad{s.normal[k], s.withBonds ? Vec3(s.force[k] - s.bond[k].force) : s.force[k], s.load[k]}
             : detail::ContactLoad{};
  [[maybe_unused]] const Vec3 pointBefore = Ledger ? s.point[k] : Vec3::Zero();
  s.normal[k] = normal;
  s.overlap[k] = overlap;
  s.point[k] = point;
  s.spring[k] = history.spring;
  s.normalHistory[k] = history.normal;
  if (s.withRolling) s.rolling[k] = history.rolling;
  if (s.withMoment()) s.moment[k] = force.momentOnB;
  s.acting[k] = force.acting;
  s.force[k] = force.onB;
  s.load[k] = {force.normal, force.normalDamping, force.normalStiffness, force.area, force.yielded};
  if constexpr (Ledger) {
    ContactEnergy& e = s.energy[k];
    e = {};
    if (before.force != Vec3::Zero() || force.acting) {  // a load before or after the step did work
      const Vec3 at = converged ? point : pointBefore;
      e = detail::contactWork(before, {normal, s.force[k], s.load[k]}, kinematics<Kind>(scene, s, k, at).relativeVelocity, scene.dt);
    }
    e.stored = stored;
  }
}

/// Whether a group's laws may wait for true-gap rungs (DeferredLaw): the law's on superquadric
/// pairs (walls keep elliptic Hertz; two ellipsoids take it too, the blend's weight 0).
template <PairKind Kind, typename Law>
constexpr bool waitsForRungs = std::is_same_v<Law, TrueGapLaw> && Kind == PairKind::SuperquadricPair;

/// One group: detect, then (within the law's range) the law; the step's statistics; with the
/// Ledger, each contact's energy (ContactEnergy). Every thread of the team runs it on its own
/// members (Interactions::memberShare); a law waiting for its true-gap rungs is handed over to
/// `deferred` (finishDeferred completes it).
template <PairKind Kind, NormalLawComponent Law, bool Ledger>
void groupKernel(std::span<const std::uint32_t> members, std::uint32_t group, const ContactModel& pairModel, const Law& law,
                 const InteractionScene& scene, const std::vector<double>& speedBound, std::vector<detail::WarmSkip>* skips,
                 ContactStore& s, std::vector<DeferredLaw>& deferred, ContactStatistics& statistics) {
  const ContactModel model = asRun(pairModel, Kind);
  [[maybe_unused]] const detail::RoundHertz roundHertz(model);
  const bool cached = cachesCurvatures(model, Kind);
  const double cosHalfAngle = std::cos(0.5 * model.curvatureTolerance);
  KernelCounts counts;
  const auto count = static_cast<std::ptrdiff_t>(members.size());
  for (std::ptrdiff_t m = 0; m < count; ++m) {
    const std::uint32_t k = members[m];
    if (m + ContactStore::prefetchAhead < count) s.prefetch(members[m + ContactStore::prefetchAhead]);
    ContactHistory history = storedHistory(s, k);
    const double range = normalRange(law, history.normal);
    // Round kinds solve a RoundContact (no body-frame points, no curvatures), the others a
    // ContactGeometry: both carry what the store keeps of the geometry.
    auto g = [&] {
      if constexpr (round(Kind)) {
        return detectRound<Kind>(scene, s, k, range);
      } else {
        const bool curvatures = model.usesCurvatures() && !cached;
        return detect<Kind>(scene, speedBound, model, s, k, curvatures, skips != nullptr ? &(*skips)[k] : nullptr,
                            counts.confirmations);
      }
    }();
    s.status[k] = g.status;
    if constexpr (!round(Kind)) {
      s.localA[k] = g.localPointA;
      s.localB[k] = g.localPointB;
    }
    if constexpr (!withWall(Kind)) {
      ++counts.calls;
      if constexpr (!round(Kind)) counts.iterations += g.iterations;
    }
    if (g.status != ContactStatus::Converged && g.status != ContactStatus::Separated) {
      ++counts.failures;
      ++counts.byStatus[static_cast<int>(g.status)];
    }
    const Vec3 point = 0.5 * (g.pointA + g.pointB);
    // Out of its law's range a pair is a gap, kept as the next step's warm start or cull, and
    // its history ends; within range the law acts, or keeps its history without acting (a
    // detached contact inside a plastic dent).
    ContactForce force{.acting = false};
    [[maybe_unused]] double stored = 0.0;
    if (g.converged() && g.overlap > -range) {
      const ContactKinematics motion = kinematics<Kind>(scene, s, k, point);
      if constexpr (round(Kind) && std::is_same_v<Law, HertzLaw>) {
        force = detail::roundHertzForce(model, roundHertz, motion, g.overlap, g.normal, history, scene.dt);
        if constexpr (Ledger) {  // (HertzLaw's lean round form needs no contact, nor does its energy)
          if (force.acting) stored = storedEnergy(law, NormalContact{}, g.overlap, history.normal, force.normal - force.normalDamping);
        }
      } else {
        LawGeometry view = [&] {
          if constexpr (round(Kind)) {
            return LawGeometry{g.overlap, g.normal, detail::circularContact(model, motion), Vec3::Zero()};
          } else {
            return cached ? cachedLawGeometry<Kind>(scene, model, s, k, g, motion, cosHalfAngle)
                          : detail::lawGeometry(model, g, motion);
          }
        }();
        if constexpr (waitsForRungs<Kind, Law>) {
          const ParticleStore& p = scene.particles;
          if (rungsWait(s.trueGap[k], scene.shapes[p.shape[s.a[k]]], scene.shapes[p.shape[s.b[k]]], cached, view.overlap)) {
            deferred.push_back({k, group, view, motion, point, rungPose(scene, s, k, cached, g), {}});
            continue;  // its law and record: finishDeferred's
          }
          handOnRungs(s.trueGap[k], view, counts.rungFallbacks);
        }
        force = lawForce<Law, Ledger>(model, law, view, motion, history, scene.dt, stored);
      }
      counts.tally(force, g.overlap, motion);
    } else {
      counts.lost += std::isinf(range);  // an adhesive contact its law still held
      history = {};
    }
    record<Kind, Ledger>(scene, s, k, g.normal, g.overlap, point, g.converged(), history, force, stored);
    if constexpr (!round(Kind)) {  // (a round contact's record is all written above)
      if (!g.converged() && s.separation[k] <= 0.0) s.reset(k);  // nothing to warm-start or cull
    }
  }
  counts.addTo(statistics, model.deepOverlapsExpected);
}

/// The laws a thread's kernel of one group handed over, their rungs now solved: the rest of the
/// kernel's work on them, as it would have done it (the law states no stored energy: no ledger).
template <PairKind Kind>
void finishDeferred(std::span<const DeferredLaw> laws, const ContactModel& pairModel, const TrueGapLaw& law,
                    const InteractionScene& scene, ContactStore& s, ContactStatistics& statistics) {
  static_assert(!StoredEnergyLaw<TrueGapLaw>);
  const ContactModel model = asRun(pairModel, Kind);
  KernelCounts counts;
  for (const DeferredLaw& d : laws) {
    TrueGapRungs& rungs = s.trueGap[d.contact];
    const int segment = rungs.segment(d.view.overlap);
    for (int r = 0; r < 2 && !rungs.failed(segment); ++r) {  // (past a failed rung none taken, as solveRungs)
      if (rungs.has(segment + r)) continue;
      take(rungs, segment + r, d.solutions[r]);
      counts.rungSolves += rungs.has(segment + r);
    }
    ContactHistory history = storedHistory(s, d.contact);
    LawGeometry view = d.view;
    handOnRungs(rungs, view, counts.rungFallbacks);
    double stored = 0.0;
    const ContactForce force = lawForce<TrueGapLaw, false>(model, law, view, d.motion, history, scene.dt, stored);
    counts.tally(force, view.overlap, d.motion);
    record<Kind, false>(scene, s, d.contact, view.normal, view.overlap, d.point, true, history, force, stored);
  }
  counts.addTo(statistics, model.deepOverlapsExpected);
}

/// The group's kernel, with the ledger when the store keeps one (only laws that state their
/// stored energy can: the scene loader refuses the others); round Hertz contacts without it on
/// the scene's path across contacts (round_hertz_lanes.hpp).
template <PairKind Kind, NormalLawComponent Law>
void runGroup(std::span<const std::uint32_t> members, std::uint32_t group, const ContactModel& model, const Law& law,
              const InteractionScene& scene, const std::vector<double>& speedBound, std::vector<detail::WarmSkip>* skips,
              ContactStore& s, std::vector<DeferredLaw>& deferred, ContactStatistics& statistics) {
  if constexpr (StoredEnergyLaw<Law>) {
    if (s.withEnergy) return groupKernel<Kind, Law, true>(members, group, model, law, scene, speedBound, skips, s, deferred, statistics);
  }
  if constexpr (round(Kind) && std::is_same_v<Law, HertzLaw>) {  // several per instruction
    if (scene.simd != SimdPath::Scalar) return detail::roundHertzContacts(scene.simd, Kind, members, asRun(model, Kind), scene, s, statistics);
  }
  groupKernel<Kind, Law, false>(members, group, model, law, scene, speedBound, skips, s, deferred, statistics);
}

/// f.template operator()<Kind>() for the pair kind.
template <typename F>
void visitKind(PairKind kind, F&& f) {
  switch (kind) {
    case PairKind::SphereSphere: return f.template operator()<PairKind::SphereSphere>();
    case PairKind::EllipsoidPair: return f.template operator()<PairKind::EllipsoidPair>();
    case PairKind::SuperquadricPair: return f.template operator()<PairKind::SuperquadricPair>();
    case PairKind::SphereWall: return f.template operator()<PairKind::SphereWall>();
    case PairKind::ParticleWall: return f.template operator()<PairKind::ParticleWall>();
    case PairKind::ParticleCylinder: return f.template operator()<PairKind::ParticleCylinder>();
    case PairKind::ParticleMesh: return f.template operator()<PairKind::ParticleMesh>();
  }
}

}  // namespace

void Interactions::beginCompute(const InteractionScene& scene) {
  // Records only where pairs are solved (round kinds and walls keep none): made after every
  // change of the store (storeChanged empties them), so a record is always its slot's.
  if (!recording(scene)) warmSkips_.clear();  // none kept while not recording, so none goes stale
  if (recording(scene) && warmSkips_.size() != store_.size()) warmSkips_.assign(store_.size(), {});
  interactingListed_ = false;  // the acting flags are written now
  // Each thread's sums of the loads of the wall contacts it computes (reduce).
  threadWallLoads_.resize(static_cast<std::size_t>(omp_get_num_threads()));  // the calling team's (1 outside one)
  for (std::vector<WallLoadSum>& loads : threadWallLoads_) loads.resize(scene.walls.size());
  deferred_.resize(threadWallLoads_.size());
  for (std::vector<DeferredLaw>& laws : deferred_) laws.clear();
  rungClaims_ = 0;
}

bool Interactions::cullsBySpeed() const {
  return std::ranges::any_of(groups_, [](const Group& g) { return !round(g.kind) && !withWall(g.kind); });
}

bool Interactions::defersLaws(const InteractionScene& scene) const {
  return std::ranges::any_of(groups_, [&](const Group& g) {
    bool waits = false;
    std::visit([&]<typename Law>(const Law&) { visitKind(g.kind, [&]<PairKind Kind>() { waits = waitsForRungs<Kind, Law>; }); },
               scene.models[g.model].normal);
    return waits;
  });
}

void Interactions::compute(const InteractionScene& scene, ContactStatistics& statistics) {
  std::vector<detail::WarmSkip>* skips = recording(scene) ? &warmSkips_ : nullptr;
  const std::vector<double>& speedBound = scene.particles.speedBound;
  std::vector<DeferredLaw>& deferred = deferred_[static_cast<std::size_t>(omp_get_thread_num())];
  // The groups' loops do not wait for each other: each writes only its own contacts.
  const auto owned = static_cast<std::ptrdiff_t>(scene.particles.size());
  for (std::uint32_t g = 0; g < groups_.size(); ++g) {
    const Group& group = groups_[g];
    const ContactModel& model = scene.models[group.model];
    const std::span<const std::uint32_t> members = memberShare(group, owned, scene.split);
    std::visit(
        [&](const auto& law) {
          visitKind(group.kind, [&]<PairKind Kind>() {
            runGroup<Kind>(members, g, model, law, scene, speedBound, skips, store_, deferred, statistics);
          });
        },
        model.normal);
  }
}

void Interactions::solveDeferredRungs(const InteractionScene& scene) {
  std::size_t total = 0;  // entries: rung k and k + 1 of each waiting law
  for (const std::vector<DeferredLaw>& laws : deferred_) total += 2 * laws.size();
  std::atomic_ref<std::size_t> next(rungClaims_);
  for (std::size_t i = next.fetch_add(1, std::memory_order_relaxed); i < total; i = next.fetch_add(1, std::memory_order_relaxed)) {
    std::size_t t = 0, j = i / 2;
    for (; j >= deferred_[t].size(); ++t) j -= deferred_[t].size();
    DeferredLaw& d = deferred_[t][j];
    const TrueGapRungs& rungs = store_.trueGap[d.contact];  // (read only: the ladder takes the solutions in finishCompute)
    const int k = rungs.segment(d.view.overlap) + static_cast<int>(i % 2);
    if (rungs.has(k)) continue;
    const ContactModel& model = scene.models[groups_[d.group].model];
    d.solutions[i % 2] = solveRung(rungs, k, d.gap, model.effectiveModulus, std::get<TrueGapLaw>(model.normal).cells);
  }
}

void Interactions::finishCompute(const InteractionScene& scene, ContactStatistics& statistics) {
  std::vector<DeferredLaw>& deferred = deferred_[static_cast<std::size_t>(omp_get_thread_num())];
  auto next = deferred.begin();  // (handed over group by group)
  const auto owned = static_cast<std::ptrdiff_t>(scene.particles.size());
  for (std::uint32_t g = 0; g < groups_.size(); ++g) {
    const Group& group = groups_[g];
    const ContactModel& model = scene.models[group.model];
    const auto end = std::find_if(next, deferred.end(), [&](const DeferredLaw& d) { return d.group != g; });
    if (next != end) {
      visitKind(group.kind, [&]<PairKind Kind>() {
        if constexpr (waitsForRungs<Kind, TrueGapLaw>) {
          finishDeferred<Kind>({next, end}, model, std::get<TrueGapLaw>(model.normal), scene, store_, statistics);
        }
      });
    }
    next = end;
    if (model.bond) addBondLoads(scene, memberShare(group, owned, scene.split), *model.bond, statistics);
  }
  deferred.clear();  // (its gaps point at the scene's shapes: none kept past the computation)
}

}  // namespace sqdem

#pragma once
// The interaction layer (docs/architecture.md, "Layers", "Identity"): the contact store, the contacts
// grouped by pair type (shape-class pair x the material pair's contact model), one fused
// detect-then-law kernel per group with the law chosen once per group (no per-contact
// dispatch), and the reduction of the contacts' loads to particles and walls.
//
// Determinism: every contact is computed into its own slot of the store from its bodies, A the
// lower id; each particle then sums its contacts in key order (ids, not slots), and walls sum
// theirs exactly (ExactSum), so results depend neither on the thread count, nor on the slots
// (re-ordering), nor, across ranks, on the decomposition.

#include <algorithm>
#include <array>
#include <cstdint>
#include <ranges>
#include <span>
#include <vector>

#include "sqdem/contact/detector.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/dynamics/wall.hpp"
#include "sqdem/geometry/mesh_features.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/interaction/contact_model.hpp"
#include "sqdem/interaction/contact_store.hpp"
#include "sqdem/interaction/deferred_law.hpp"
#include "sqdem/interaction/pair_kind.hpp"
#include "sqdem/interaction/simd_path.hpp"
#include "sqdem/interaction/thread_share.hpp"
#include "sqdem/interaction/warm_skip.hpp"
#include "sqdem/math/exact_sum.hpp"

namespace sqdem {

class CheckpointReader;
class CheckpointWriter;

/// Counters of the contact computations, accumulated over a run.
struct ContactStatistics {
  long long detectorCalls = 0;
  long long detectorIterations = 0;
  long long detectorConfirmations = 0;  ///< warm answers confirmed without evaluating a surface (warm_skip.hpp)
  long long detectorFailures = 0;  ///< statuses other than Converged/Separated (contact skipped)
  /// detectorFailures by ContactStatus (index = the status's value).
  std::array<long long, contactStatusCount> failuresByStatus{};
  long long deepOverlaps = 0;      ///< contacts with overlap > 0.5 x the smaller R_vol (time step too large?)
  long long expectedDeepOverlaps = 0;  ///< the same, of models that expect them (ContactModel::deepOverlapsExpected)
  /// Adhesive contacts lost while their law still held them (the detector gave no geometry
  /// within its cut-off): should stay 0, the cut-off covers ContactModel::reach.
  long long lostAdhesions = 0;
  long long lawFailures = 0;       ///< contacts whose law had no valid form (NormalResponse::valid)
  long long trueGapRungs = 0;      ///< rungs of the true-gap law solved (mechanics/true_gap_law.hpp)
  long long trueGapFallbacks = 0;  ///< its contact-steps on elliptic Hertz: a rung's half-space contact failed
  long long bondsBroken = 0;       ///< bonds whose stresses reached a strength (parallel_bond.hpp)
  /// Intact bonds dropped because their pair left the candidate list (stretched beyond the
  /// skin): should stay 0.
  long long lostBonds = 0;

  /// Calls f(counter) for every counter, in a fixed order (sums, reductions over ranks).
  template <typename Statistics, typename F>
  static void forEachCount(Statistics& s, F&& f) {
    for (auto* count : {&s.detectorCalls, &s.detectorIterations, &s.detectorConfirmations, &s.detectorFailures, &s.deepOverlaps, &s.expectedDeepOverlaps,
                        &s.lostAdhesions,
                        &s.lawFailures, &s.trueGapRungs, &s.trueGapFallbacks, &s.bondsBroken, &s.lostBonds}) {
      f(*count);
    }
    for (auto& count : s.failuresByStatus) f(count);
  }
};

/// The accuracy knobs of the common-normal detector (an engine-wide choice).
struct DetectorControl {
  /// DetectorSettings::tolerance (-), scene key `detector_tolerance`. The engine's default is
  /// looser than a single query's: a residual below tol L leaves the normal within ~tol rad and
  /// the two points within ~tol L of the exact pair, and the overlap (measured along the normal)
  /// within ~tol^2 L, so forces are off by ~tol in direction and far less in magnitude; a
  /// warm-started contact that moved less than that in a step needs no Newton iteration (settled
  /// beds: 0.19 instead of 0.70 iterations per call). Measured in bench/accuracy_bench.cpp.
  double tolerance = 1e-6;
  bool warmStart = true;  ///< start from the last solution; false: every solve is cold
  /// Confirm a pair's warm answer from its kept normals where its residual at the new
  /// poses is within the tolerance (warm_skip.hpp): the same results to the bit; false
  /// evaluates every surface.
  bool confirmWarm = true;
};

/// What the kernels read of the world (all unchanged during a force computation).
struct InteractionScene {
  const ParticleStore& particles;
  const std::vector<Superquadric>& shapes;
  const std::vector<Wall>& walls;
  const std::vector<MeshFeatures>& meshes;  ///< of the mesh walls (Wall::mesh)
  /// Contact model of material pair (i, j) at models[i * materialCount + j] (symmetric).
  const std::vector<ContactModel>& models;
  std::size_t materialCount = 0;
  double skin = 0.0;  ///< detector cut-off (m): gaps within it are solved, for warm starts
  double dt = 0.0;    ///< time step (s)
  DetectorControl detector;
  bool energy = false;  ///< the contacts account their energy (ContactEnergy)
  const TeamSplit* split = nullptr;  ///< how a team shares the particles out (null: evenly)
  SimdPath simd = SimdPath::Scalar;  ///< the kernels across contacts' code path (one this CPU runs)
};

/// A candidate pair for Interactions::setCandidates: slots a and b (a particle slot, owned or a
/// ghost, or wallFlag | wall), oriented by id (for two particles, id[a] < id[b]), a cylinder
/// wall's image offset (ContactStore::wallImage) and a mesh wall's feature.
struct CandidateKey {
  std::uint32_t a = 0, b = 0;
  Vec3 wallImage = Vec3::Zero();
  std::uint32_t feature = 0;
};

/// A wall's load from this process's contacts, every part an exact sum: the shares of all
/// processes add up to the same bits in any decomposition (the World reduces them).
struct WallLoadSum {
  static constexpr int force = 0, torque = 3, elasticForce = 6, stiffness = 9;  ///< offsets in part
  std::array<ExactSum, 10> part;  ///< force (N), torque about the reference (N m), elastic force (N), stiffness (N/m)
  void clear() {
    for (ExactSum& p : part) p.clear();
  }
};

/// A contact computed on another rank (where its A is owned) whose B this process owns: B's slot
/// here and the contact's key, so that B sums it in key order with its own.
struct RemoteContact {
  std::uint32_t slot;
  ContactKey key;
};

/// A contact's load on its B (Interactions::loadOnB), sent to B's owner: the same terms, in the
/// same order, as B's sum would add for a contact of its own process.
struct LoadOnB {
  Vec3 force = Vec3::Zero();   ///< (N)
  Vec3 torque = Vec3::Zero();  ///< about B's centre, the pure moment included (N m)
  std::uint8_t acting = 0;     ///< whether it carried force (else it is not added)
};

/// The contact ellipse of a contact (Interactions::ellipses).
struct ContactEllipse {
  double major = 0.0;             ///< semi-axis (m); 0 for a pair not in contact
  double minor = 0.0;             ///< semi-axis (m), <= major
  Vec3 majorAxis = Vec3::Zero();  ///< unit, in the tangent plane (world frame); zero for a circle
};

/// An intact bond as the bodies' current poses deform it (Interactions::bonds).
struct BondReport {
  std::uint32_t contact = 0;   ///< its contact's store slot
  Vec3 centre = Vec3::Zero();  ///< where its force acts (m)
  BondLoads loads;             ///< on B (parallel_bond.hpp)
  /// max(sigma / sigma_c, tau / tau_c): how near it is to breaking (< 1 while intact).
  double utilisation = 0.0;
};

/// An empty store with the optional arrays the scene's contact models need.
ContactStore emptyStore(const InteractionScene& scene);

class Interactions {
 public:
  /// ghostOwner's entry for a ghost whose particle another rank owns (that rank sums its loads).
  static constexpr std::uint32_t remoteGhost = 0xFFFFFFFFu;
  /// Replaces the candidates (unique keys, in any order: the store keeps theirs), carrying over
  /// the geometry and histories of pairs that persist (matched by key), and regroups them. A is
  /// an owned slot; ghostOwner[g] is the owned slot that ghost slot particles.size() + g stands
  /// for (its loads go there), or remoteGhost. Returns how many intact bonds were dropped with
  /// their pairs (they left the candidates: ContactStatistics::lostBonds).
  std::size_t setCandidates(const std::vector<CandidateKey>& candidates, const InteractionScene& scene,
                     const std::vector<std::uint32_t>& ghostOwner);
  /// Keeps the store's optional arrays (rolling, curvature cache) to what the scene's contact
  /// models need, after a model changed: arrays added fresh, arrays no longer needed dropped;
  /// the true-gap law's rungs forgotten (solved for the former models' E* and cells).
  void fitStore(const InteractionScene& scene);
  /// Drops every pair's separation bound (ContactStore::separation): after the particles were
  /// moved other than by a step, the next computation solves each pair again.
  void forgetSeparations() { std::fill(store_.separation.begin(), store_.separation.end(), 0.0); }
  // compute and reduce are a step's team work (docs/architecture.md, "A step"): called by every
  // thread of an OpenMP team, each takes its share of the particles (thread_share.hpp) and of the
  // contacts, those whose A is one of them; they end without a barrier: the caller's ends them.
  // Outside a parallel region one thread does all.

  /// Serial: the computation's records fitted to the store and the threads' wall sums to the
  /// walls (before compute and reduce, by one thread).
  void beginCompute(const InteractionScene& scene);
  /// Team work: detection and laws of every candidate; adds to the statistics. The particles'
  /// speed bounds (ParticleStore::speedBound, ghosts too) must be current when cullsBySpeed().
  /// A law waiting for its true-gap rungs is handed over (deferred_law.hpp): the computation
  /// ends with finishCompute, after solveDeferredRungs between two barriers when defersLaws().
  void compute(const InteractionScene& scene, ContactStatistics& statistics);
  /// Whether some group's law may wait for rungs (the true-gap law on superquadric pairs).
  bool defersLaws(const InteractionScene& scene) const;
  /// Team work, after compute and a barrier: the rungs every thread's kernels wait for, each
  /// taken from one queue by whichever thread is free (into the waiting law's record).
  void solveDeferredRungs(const InteractionScene& scene);
  /// Team work, after compute (and the rungs' barrier): the laws this thread handed over, their
  /// rungs entered into the ladders, then its share's bond loads.
  void finishCompute(const InteractionScene& scene, ContactStatistics& statistics);
  /// Bonds formed (docs/bonds.md) between the stored pairs whose model has one, where a pair's
  /// gap is at most gapRatio times the smaller volume radius (a particle's own on a plane; not
  /// on a cylinder or a mesh), at the middle of the common-normal points; returns how many.
  /// Serial, between computations, the store's candidates current.
  std::size_t formBonds(const InteractionScene& scene, double gapRatio);
  /// This process's intact bonds.
  std::size_t bondCount() const;
  /// This process's intact bonds with their loads at the current poses, in key order (computed
  /// when asked, as the next computation would find them).
  std::vector<BondReport> bonds(const InteractionScene& scene) const;
  /// Whether some group culls separated pairs by the particles' speed bounds (the iterative kinds).
  bool cullsBySpeed() const;
  /// Team work: per particle, F = m (g - c v) plus its contacts' loads, and the torques; per
  /// wall this process's share of its load added to wallLoads (one per wall, zero before). remote[m]: the load of the m-th contact of setRemoteContacts.
  /// halfStep > 0: each particle then takes a kick of that half step (integrator.hpp) in the
  /// same pass, the step's closing kick without a pass of its own.
  void reduce(ParticleStore& particles, const Vec3& gravity, double drag, const std::vector<Wall>& walls,
              std::vector<WallLoadSum>& wallLoads, std::span<const LoadOnB> remote, double halfStep, const TeamSplit& split);

  /// Migration (docs/architecture.md, "Ghosts"): the contacts whose A leaves this process
  /// (leaving[slot of A], written out by the caller) removed; `count` contacts that arrived with
  /// their A read from a record (ContactStore::write). The next setCandidates carries all of them
  /// over by key (until then no other use of the store).
  void removeLeaving(const std::vector<std::uint8_t>& leaving);
  void readArrived(CheckpointReader& in, std::uint64_t count);
  /// The contacts other ranks compute whose B is owned here (after setCandidates, which drops
  /// the last ones): each owned B sums them in key order with its own.
  void setRemoteContacts(const std::vector<RemoteContact>& contacts, std::size_t owned,
                         const std::vector<std::uint32_t>& ghostOwner);
  /// setRemoteContacts' list, in its order.
  const std::vector<RemoteContact>& remoteContacts() const { return remote_; }
  /// Contact k's load on its B (a particle), as B's sum adds it.
  LoadOnB loadOnB(std::uint32_t k, const ParticleStore& particles) const;

  /// The contacts that carried force in the last computation, in key order (listed when first
  /// asked for after a computation: the steps need no list; not to be called from two threads).
  auto acting() const {
    return listActing() | std::views::transform([this](std::uint32_t k) { return ContactView(store_, k); });
  }
  const ContactStore& store() const { return store_; }
  /// Every stored contact's ellipse, by store slot (contact_ellipse.cpp): its area is its law's
  /// (NormalLoad::area), its aspect b/a = sqrt(1 - e^2) the Hertz ellipse's of the pair's
  /// relative radii at the current poses (004 Eq. 13, as the law's model computes them; exact for
  /// elliptic Hertz, Hertz's shape of the spot for the laws whose area differs: JKR, rough,
  /// plastic), its major axis that of the smaller relative curvature; a circle for the laws on
  /// volume-equivalent spheres and for round pairs. Computed when asked, not kept by the steps.
  std::vector<ContactEllipse> ellipses(const InteractionScene& scene) const;
  std::size_t actingCount() const { return listActing().size(); }
  /// This process's share of the contacts' ContactEnergy of the last computation, exact sums
  /// of its fields in their order (stored, normal, damping, tangential, bondStored, bond); zero
  /// without a store made withEnergy.
  std::array<ExactSum, 6> energy() const;
  /// Bytes held (store, groups, key order, particle index).
  std::size_t bytes() const;

  /// A store from a checkpoint, its slots those of this process (A owned, B owned or a ghost)
  /// and its contacts' states as they were: the acting list (its acting flags in key order),
  /// the groups and the particles' involvement made again. Throws CheckpointError
  /// (checkpoint_file.hpp) when a slot does not fit the scene's particles and walls.
  static Interactions restore(ContactStore store, const InteractionScene& scene,
                              const std::vector<std::uint32_t>& ghostOwner);

 private:
  /// Contacts of one pair kind and one contact model.
  struct Group {
    PairKind kind;
    std::uint32_t model;  ///< index into InteractionScene::models
    std::vector<std::uint32_t> members;  ///< contact indices, ascending
  };
  void regroup(const InteractionScene& scene);
  /// The bonds of a group's members (by the thread that computed them): their loads added to the
  /// contacts', or broken (counted).
  void addBondLoads(const InteractionScene& scene, std::span<const std::uint32_t> members, const ParallelBond& bond,
                    ContactStatistics& statistics);
  /// The calling thread's run of a group's members: those whose A is one of its particles
  /// (its share of the `owned` ones by `split`, evenly without) while the store holds its
  /// contacts by A's slot, as setCandidates makes it; else an even share.
  std::span<const std::uint32_t> memberShare(const Group& group, std::ptrdiff_t owned, const TeamSplit* split) const;
  /// Whether the computation keeps warm-skip records (iterative kinds, confirmWarm).
  bool recording(const InteractionScene& scene) const { return cullsBySpeed() && scene.detector.confirmWarm; }
  /// After the store's slots changed: keyOrder_ and the wall contacts from its keys, the skip
  /// records dropped.
  void storeChanged();
  void indexInvolvement(std::size_t owned, const std::vector<std::uint32_t>& ghostOwner);
  /// interacting_, made from the acting flags in key order if the store changed since.
  const std::vector<std::uint32_t>& listActing() const;

  ContactStore store_;
  std::vector<Group> groups_;
  bool bySlot_ = true;  ///< the store's contacts ascend by A's slot (regroup)
  std::vector<std::uint32_t> keyOrder_;  ///< the contacts in key order
  static constexpr std::uint32_t bodyBFlag = 0x80000000u;  ///< in involvement_: the particle is body B
  static constexpr std::uint32_t remoteFlag = 0x40000000u;  ///< in involvement_: an index into remote_
  static constexpr std::uint32_t imageFlag = 0x20000000u;   ///< in involvement_: B is the particle's image (a ghost slot)
  static constexpr std::uint32_t contactMask = imageFlag - 1;  ///< the contact index in an involvement entry
  /// Owned particle i's contacts (also those of its ghosts), in key order:
  /// involvement_[start[i], start[i+1]).
  std::vector<std::uint32_t> involvementStart_;
  /// contact index, | bodyBFlag where i is body B (| imageFlag through its image), or remoteFlag | m
  std::vector<std::uint32_t> involvement_;
  std::vector<RemoteContact> remote_;            ///< setRemoteContacts' list, in its order
  mutable std::vector<std::uint32_t> interacting_;  ///< the force-carrying contacts, in key order (listActing)
  mutable bool interactingListed_ = false;
  std::vector<std::vector<WallLoadSum>> threadWallLoads_;  ///< per thread, per wall (reduce)
  std::vector<detail::WarmSkip> warmSkips_;      ///< by store slot (warm_skip.hpp); empty without particle pairs to solve
  std::vector<std::vector<DeferredLaw>> deferred_;  ///< per thread: the laws its kernels handed over (compute)
  std::size_t rungClaims_ = 0;                   ///< solveDeferredRungs' next entry, taken atomically
};

}  // namespace sqdem

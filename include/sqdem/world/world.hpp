#pragma once
// The World: particles, shapes, materials, the interaction table, walls, the persistent contact
// list and the time step loop (docs/architecture.md, "A step"):
//   half kick, drift (and walls move) -> broad phase (neighbour list and candidate contacts,
//   rebuilt when particles or walls moved half the skin) -> narrow phase (detector, warm-started
//   from the contact's history) -> contact law -> forces reduced per particle -> half kick.
// Contacts live in the interaction layer (interactions.hpp): computed in parallel (OpenMP) into
// their own slots, summed per particle in key order, so results do not depend on the number of
// threads. Every global quantity (wall loads, kinetic energy, the rebuild decision, time steps)
// goes through the world's Communicator (communicator.hpp), a no-op in one process.

#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <ranges>
#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/distributed/decomposition.hpp"
#include "sqdem/distributed/ghosts.hpp"
#include "sqdem/distributed/remote_loads.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/dynamics/wall.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/interaction/interactions.hpp"
#include "sqdem/world/energy_ledger.hpp"
#include "sqdem/world/mesh_tree.hpp"
#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {

class CheckpointReader;
class CheckpointWriter;
class Team;

struct Material {
  double youngsModulus = 0.0;  ///< E (Pa)
  double poissonRatio = 0.0;   ///< nu (-)
  double density = 0.0;        ///< rho (kg/m^3)
  double friction = 0.0;       ///< mu (-), pair value = min of the two
  double restitution = 1.0;    ///< e (-), pair value = min of the two
  double yieldStrength = 0.0;  ///< Y (Pa) in simple tension, for plastic laws; pair value = min of the two
};

/// Wall-clock seconds spent in each part of the step (accumulated).
struct StepTiming {
  double integration = 0.0;  ///< kicks and drifts
  double broadPhase = 0.0;   ///< neighbour list, candidate list, history carry-over
  double contacts = 0.0;     ///< detectors and contact laws (the fused kernels)
  double reduction = 0.0;    ///< forces and torques per particle and wall
  /// ghosts made and refreshed, particles migrated, loads sent across ranks: across ranks the
  /// communication (not counted in the others)
  double ghosts = 0.0;
  /// The threads' mean wait at the step's barriers (imbalance and serial parts; counted in the
  /// phases above as well)
  double barrierWait = 0.0;
};

/// The most threads a World's team is given.
inline constexpr int mostThreads = 1024;

class World {
 public:
  /// skin (m): Verlet skin of the neighbour list; search: how candidate pairs are found.
  World(std::vector<Superquadric> shapes, std::vector<Material> materials, const Domain& domain, double skin,
        BroadPhase search = BroadPhase::CellList);

  /// Sets the law of a material pair (symmetric); every pair must be set before the first step.
  /// Set during a run, it acts from the next force computation (the contacts keep their
  /// histories; the list of acting contacts is empty until then).
  /// Sets the model's reach from the shapes (the normal law's reach at relative radius
  /// capFactor x the largest volume radius); throws std::invalid_argument when the law admits
  /// no contact of that size.
  void setContactModel(std::uint32_t materialA, std::uint32_t materialB, const ContactModel& model);
  const ContactModel& contactModel(std::uint32_t materialA, std::uint32_t materialB) const { return model(materialA, materialB); }
  /// The default law from two materials: elliptic Hertz, pair friction/restitution.
  ContactModel defaultContactModel(std::uint32_t materialA, std::uint32_t materialB) const;

  std::size_t addParticle(std::uint32_t shape, std::uint32_t material, const Vec3& centre, const Quat& q);
  void addWall(const Wall& wall) { walls_.push_back(wall); }
  /// Adds a triangle mesh with its contact features for mesh walls (Wall::mesh is the index
  /// returned); its candidate tree is built here.
  std::uint32_t addMesh(MeshFeatures mesh);
  const std::vector<MeshFeatures>& meshes() const { return meshes_; }

  /// The ranks this world's particles are divided between (default: one process). Set before
  /// the first step, with every rank holding every particle (built from the same scene): each
  /// keeps those of its sub-domain (recursive coordinate bisection, decomposition.hpp).
  void setCommunicator(std::shared_ptr<const Communicator> communicator);
  /// Every rank's sub-domain of the last neighbour-list build (one process: the whole box).
  const std::vector<SubDomain>& subDomains() const { return parts_; }
  /// At a neighbour-list build, the sub-domains are cut again by cost (recursive coordinate
  /// bisection, a particle's cost 1 + its candidate contacts) when the ranks' largest cost
  /// exceeds their mean by this factor (default 1.2; results do not depend on it).
  void setRebalanceThreshold(double imbalance) { rebalanceThreshold_ = imbalance; }
  /// The ranks' largest cost over their mean at the last build (1: balanced), and how many
  /// times the sub-domains were cut again.
  double imbalance() const { return imbalance_; }
  int rebalances() const { return rebalances_; }
  const Communicator& communicator() const { return *communicator_; }

  void setGravity(const Vec3& g) { gravity_ = g; }
  /// Whether a step advances spheres' orientations (default: no). Nothing a sphere does depends
  /// on its orientation (its contacts are round, its inertia isotropic) unless a contact model
  /// has a bond (then they always turn: bond_frame.hpp); otherwise only the output's quaternions
  /// show it, and turning it costs most of a sphere's integration.
  void setSphereOrientations(bool advanced);
  const Vec3& gravity() const { return gravity_; }
  /// Re-order the particle slots along a Hilbert curve every `rebuilds` neighbour-list builds
  /// (0: never). Results do not change: contacts and sums follow ids, not slots.
  void setReorderInterval(int rebuilds) { reorderInterval_ = rebuilds; }
  /// Background drag F = -c m v (c in 1/s, translation only; 0 = off): settling in a viscous
  /// medium with terminal velocity |g|/c, a declared packing aid.
  void setViscousDamping(double c) { viscousDamping_ = c; }
  double viscousDamping() const { return viscousDamping_; }
  /// Keeps an energy ledger (energy_ledger.hpp) from the first force computation on; the
  /// contacts then account their work (a cost per contact and step). Call before it; every
  /// contact model's law must state its stored energy (std::invalid_argument otherwise, here or
  /// in setContactModel).
  void enableEnergyLedger();
  /// The ledger, when enabled.
  const std::optional<EnergyLedger>& energyLedger() const { return ledger_; }
  /// The detector's tolerance and warm starts (interactions.hpp; defaults: 1e-10, on).
  void setDetectorControl(const DetectorControl& control) { detector_ = control; }
  const DetectorControl& detectorControl() const { return detector_; }
  /// The threads of a step's team (0, the default: OpenMP's, omp_get_max_threads(); at most
  /// mostThreads, std::invalid_argument otherwise); results are the same bits at any count.
  void setThreads(int threads);
  int threads() const;
  /// The code path of the kernels across contacts (simd_path.hpp; default: the widest this CPU
  /// runs). Every path gives the same bits; std::invalid_argument for one this CPU cannot run.
  void setSimdPath(SimdPath path);
  SimdPath simdPath() const { return simd_; }
  void setTimeStep(double dt) { dt_ = dt; }
  double timeStep() const { return dt_; }
  double time() const { return time_; }

  /// Advances one step (computes the initial forces first if needed).
  void step();
  /// Call after setting particle state between steps (positions, velocities, rotations), with
  /// the kinetic energy before (J); returns the kinetic energy the edit gave (J, < 0: took). The
  /// pairs' separation bounds, which assume the particles moved by their velocities alone, are
  /// dropped, so every pair is solved again at the next step; the energy ledger books the
  /// energy given as work done from outside (EnergyLedger::edits). The neighbour list needs
  /// nothing: its rebuild test measures every displacement since its build, an edit's too.
  /// Collective.
  double particlesEdited(double kineticBefore);
  /// Computes contacts and forces at the current state (no integration).
  void computeForces();
  /// Forms bonds (docs/bonds.md) between the pairs whose contact model has one and whose gap is
  /// at most gapRatio times the smaller volume radius, among the last computation's candidates
  /// (computed first if there was none yet); returns how many formed, over every rank. Their
  /// loads act from the next computation. Collective.
  std::size_t formBonds(double gapRatio);
  /// Intact bonds, over every rank.
  std::size_t bondCount() const;

  /// The owned particles, slots [0, size()), and their ghosts after them (ghosts()).
  ParticleStore& particles() { return particles_; }
  const ParticleStore& particles() const { return particles_; }
  const Ghosts& ghosts() const { return ghosts_; }
  /// The owned slot that `slot` stands for: itself, or a ghost's owner in this process
  /// (Ghosts::remote when another rank owns it).
  std::uint32_t ownedSlot(std::uint32_t slot) const {
    return slot < particles_.size() ? slot : ghosts_.localOwners()[slot - particles_.size()];
  }
  const std::vector<Superquadric>& shapes() const { return shapes_; }
  const std::vector<Material>& materials() const { return materials_; }
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }
  /// The contacts that carried force in the last computation (touching, or rough within
  /// range), in key order.
  auto contacts() const { return interactions_.acting(); }
  const Interactions& interactions() const { return interactions_; }
  /// Every stored contact's ellipse at the current state, by store slot (Interactions::ellipses).
  std::vector<ContactEllipse> contactEllipses() const { return interactions_.ellipses(interactionScene()); }
  /// This process's intact bonds and their loads at the current state (Interactions::bonds).
  std::vector<BondReport> bonds() const { return interactions_.bonds(interactionScene()); }
  /// The loads of the last force computation that other ranks' contacts put on this rank's
  /// particles, one per Interactions::remoteContacts() entry (empty in one process).
  const std::vector<LoadOnB>& remoteLoads() const { return remoteLoadsNow_; }
  const Domain& domain() const { return domain_; }
  /// This process's counters of its contacts' computations (after a restore, rank 0 holds the
  /// run's totals until then).
  const ContactStatistics& statistics() const { return statistics_; }
  /// The run's: every rank's counters summed. Collective.
  ContactStatistics totalStatistics() const;
  const StepTiming& timing() const { return timing_; }
  const NeighbourList& neighbourList() const { return neighbours_; }

  /// Checkpoint of the dynamic state (particles, walls, contact history, the positions of the
  /// last neighbour-list build, time, statistics) in a binary form for the same build, as one
  /// process holding every particle would keep it (distributed/whole_state.hpp): gathered from
  /// the ranks, written into rank 0's `out` (the others' stay empty). The static parts (shapes,
  /// materials, laws) come from the scene. Collective.
  void writeState(CheckpointWriter& out) const;
  /// The fingerprint of writeState's payload (its version and the byte layout of its raw
  /// records): a checkpoint's build stamp (checkpoint_file.hpp).
  static std::uint64_t stateFingerprint();
  /// Restores a state written by writeState at any rank count into a world built from the same
  /// scene, on every rank (each keeps its share) and continues bit for bit; throws
  /// CheckpointError (checkpoint_file.hpp), on every rank alike, if it does not match this world
  /// or any count or index is out of range. The world is unchanged when it throws. Collective.
  void readState(CheckpointReader& in);

  /// Normal pressure on wall w: |F . n| over the box cross-section normal to the wall's
  /// dominant axis (Pa).
  double wallPressure(std::size_t w) const;
  /// Its cross-section there (m^2).
  double wallArea(std::size_t w) const;

  double kineticEnergy() const;
  /// Rayleigh time (000 Eq. 71) of the particle with the smallest semi-axis (s); scenes use a
  /// fraction of it.
  double rayleighTimeStep() const;
  /// Hertz collision time (collision_time.hpp) of the smallest particle against itself at
  /// impact speed v (m/s), on volume-equivalent spheres with the pair's (possibly reduced) E*,
  /// divided by stepsPerCollision (s).
  double hertzTimeStep(double speed, double stepsPerCollision) const;
  /// 1 / omega of the fastest bond a particle could hold (bondAngularFrequency, with the bond's
  /// radius from the particle's own volume radius) over every particle and every material its
  /// material's model bonds to (s); infinite without bonds. Scenes use a fraction of it.
  double bondTimeStep() const;

 private:
  /// Runs body(team) on every thread of a new Team (team.hpp), rethrows what its serial parts
  /// threw, and books the threads' waits and work (timing_, split_).
  template <typename Body>
  void inTeam(Body&& body);
  /// Throws std::logic_error when a material pair has no contact model.
  void requireModels() const;
  /// turns_ from the shapes, setSphereOrientations and the models' bonds.
  void fitTurns();
  /// Serial part of a force computation (the master's, team.hpp): the broad phase when some
  /// particle `moved` more than half the skin (a decision reduced over ranks) or a wall did,
  /// else the ghosts refreshed; the interactions' records fitted.
  void prepareForces(bool moved);
  /// A team's force computation after prepareForces (every thread calls it): contacts, the
  /// other ranks' loads, the reduction and the walls' loads; halfStep > 0: every owned particle
  /// then takes a kick of that half step in the reduction's pass (Interactions::reduce).
  void forcePhases(Team& team, double halfStep);
  const ContactModel& model(std::uint32_t ma, std::uint32_t mb) const { return models_[ma * materials_.size() + mb]; }
  /// What the interaction layer reads of this world.
  InteractionScene interactionScene() const {
    return {particles_, shapes_, walls_, meshes_, models_, materials_.size(), neighbours_.skin(), dt_, detector_,
            ledger_.has_value(), &split_, simd_};
  }
  /// The candidate list from the neighbour list and the walls within reach, carrying the
  /// histories of persisting pairs; kept until the next rebuild (particles or walls moved more
  /// than half the skin), so steps in between copy no contact records.
  void buildCandidates();
  /// Re-orders the owned slots (no ghosts then), world_reorder.cpp.
  void reorderAlongHilbertCurve();
  /// The cut-off the ghosts of particles p cover (m): the largest pair reach, r_a + r_b + range + skin.
  double ghostCutoff(const ParticleStore& p) const;
  /// Wraps the owned particles into the box, migrates (and re-balances) them across the ranks,
  /// makes their ghosts and rebuilds the neighbour list.
  void rebuildNeighbours();
  /// The cost of each owned particle (1 + the candidate contacts it is A of); measures the
  /// imbalance and cuts the sub-domains again past the threshold.
  void rebalance();
  /// Wall w's load from its exact sums (wallLoads_, summed over the ranks).
  void setWallLoad(std::size_t w);
  /// Mesh wall w's features within `reach` (m) of particle i, ascending.
  void addMeshCandidates(std::uint32_t i, std::uint32_t w, const MeshWall& wall, double reach, std::vector<CandidateKey>& next) const;
  bool wallsMovedHalfSkin() const;
  const Vec3& planeNormal(std::size_t w) const;  ///< of wall w, a plane (else std::invalid_argument)
  double servoVelocity(std::size_t w) const;  ///< along wall w's normal (m/s), WallServo
  double largestRange() const;  ///< the largest gap any law acts across (m)
  std::vector<Superquadric> shapes_;
  std::vector<Material> materials_;
  std::vector<ContactModel> models_;
  std::vector<bool> modelSet_;
  Domain domain_;
  NeighbourList neighbours_;
  ParticleStore particles_;
  Ghosts ghosts_;
  std::vector<SubDomain> parts_;  ///< every rank's sub-domain
  RemoteLoads remoteLoads_;
  std::vector<LoadOnB> remoteLoadsNow_;  ///< this step's loads on this rank's particles from the others
  double rebalanceThreshold_ = 1.2, imbalance_ = 1.0;
  int rebalances_ = 0;
  std::vector<Wall> walls_;
  std::vector<WallLoadSum> wallLoads_;
  std::vector<MeshFeatures> meshes_;
  std::vector<MeshTree> meshTrees_;       ///< meshes_[i]'s candidate search
  std::vector<Vec3> wallReference_;       ///< wall points at the last candidate build
  std::vector<std::uint8_t> turns_;       ///< per shape: whether a drift advances the orientation (fitTurns)
  bool sphereOrientations_ = false;       ///< setSphereOrientations
  Interactions interactions_;
  ContactStatistics statistics_;
  StepTiming timing_;
  TeamSplit split_;  ///< the threads' runs of particles, balanced by their measured contact work
  Vec3 gravity_ = Vec3::Zero();
  double viscousDamping_ = 0.0;
  DetectorControl detector_;
  SimdPath simd_ = widestSimdPath();
  int threads_ = 0;  ///< setThreads
  std::optional<EnergyLedger> ledger_;
  std::shared_ptr<const Communicator> communicator_ = std::make_shared<SerialCommunicator>();
  int reorderInterval_ = 0;
  double dt_ = 0.0, time_ = 0.0;
  bool forcesCurrent_ = false;
};

}  // namespace sqdem

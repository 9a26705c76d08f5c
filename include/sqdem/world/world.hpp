#pragma once
// The World: particles, shapes, materials, the interaction table, walls, the persistent contact
// list and the time step loop (DESIGN.md §2):
//   half kick, drift (and walls move) -> broad phase (neighbour list and candidate contacts,
//   rebuilt when particles or walls moved half the skin) -> narrow phase (detector, warm-started
//   from the contact's history) -> contact law -> forces reduced per particle -> half kick.
// Contacts are computed in parallel (OpenMP) into their own records; each particle then sums
// its contacts in their key order (also in parallel), so results do not depend on the number
// of threads.

#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <ranges>
#include <vector>

#include "sqdem/contact/detector.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/geometry/plane.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/world/neighbour_list.hpp"
#include "sqdem/world/contact_model.hpp"

namespace sqdem {

class CheckpointReader;
class CheckpointWriter;

struct Material {
  double youngsModulus = 0.0;  ///< E (Pa)
  double poissonRatio = 0.0;   ///< nu (-)
  double density = 0.0;        ///< rho (kg/m^3)
  double friction = 0.0;       ///< mu (-), pair value = min of the two
  double restitution = 1.0;    ///< e (-), pair value = min of the two
  double yieldStrength = 0.0;  ///< Y (Pa) in simple tension, for plastic laws; pair value = min of the two
};

/// Force control of a wall: before each step the wall moves along its normal with
///   v = max_speed clamp((p_target - p) / p_target, -1, 1),
/// limited to |v| <= |F_target - F| / (2 k dt) while it touches particles (proportional
/// control; the wall advances into the particles while p < p_target). p and F are the elastic
/// part of the wall's normal load: the contacts' damping depends on the wall's own velocity and
/// would feed the command back into the reading. k is the sum of the wall contacts' normal
/// stiffnesses, so one step closes at most half the force error the contacts see at once; this
/// keeps the loop stable however large max_speed is (without it, max_speed dt k / F_target > 2
/// made the wall chatter in and out of the bed).
struct WallServo {
  double pressure = 0.0;  ///< target normal pressure (Pa), > 0
  double maxSpeed = 0.0;  ///< (m/s), > 0
};

/// An infinite plane moving with a prescribed velocity or under servo control; `force` is what
/// the particles exert on it.
struct Wall {
  Plane plane;
  Vec3 velocity = Vec3::Zero();  ///< (m/s)
  std::uint32_t material = 0;
  Vec3 force = Vec3::Zero();     ///< (N), from the last force computation
  Vec3 elasticForce = Vec3::Zero();  ///< the same without the contacts' normal damping (N)
  double stiffness = 0.0;        ///< sum of its contacts' normal stiffnesses S_n (N/m)
  std::optional<WallServo> servo;
};

inline constexpr std::uint32_t wallFlag = 0x80000000u;

/// A candidate pair and its history. b is a particle slot, or wallFlag | wall index.
struct Contact {
  std::uint32_t a = 0, b = 0;
  Vec3 shift = Vec3::Zero();    ///< periodic image offset of b (m)
  ContactGeometry geometry;     ///< last solution: warm start for the next step
  ContactHistory history;       ///< tangential spring, rolling displacement, the normal law's record
  ContactForce force;           ///< force on b from the last step
  /// When the last solve found the pair Separated: a lower bound of its gap (m), reduced every
  /// step by a bound of the motion since; the pair is not solved again while it stays > 0.
  double separation = 0.0;

  bool onWall() const { return (b & wallFlag) != 0; }
  std::uint64_t key() const { return (std::uint64_t{a} << 32) | b; }
};

struct WorldStatistics {
  long long detectorCalls = 0;
  long long detectorIterations = 0;
  long long detectorFailures = 0;  ///< statuses other than Converged/Separated (contact skipped)
  /// detectorFailures by ContactStatus (index = the status's value).
  std::array<long long, contactStatusCount> failuresByStatus{};
  long long deepOverlaps = 0;      ///< contacts with overlap > 0.5 R_vol (time step too large?)
  /// Adhesive contacts lost while their law still held them (the detector gave no geometry
  /// within its cut-off): should stay 0, the cut-off covers ContactModel::reach.
  long long lostAdhesions = 0;
  long long lawFailures = 0;       ///< contacts whose law had no valid form (NormalResponse::valid)
};

/// Wall-clock seconds spent in each part of the step (accumulated).
struct StepTiming {
  double integration = 0.0;  ///< kicks and drifts
  double broadPhase = 0.0;   ///< neighbour list, candidate list, history carry-over
  double detection = 0.0;    ///< common-normal detector
  double law = 0.0;          ///< contact laws
  double reduction = 0.0;    ///< forces and torques per particle, statistics
};

class World {
 public:
  /// skin (m): Verlet skin of the neighbour list; search: how candidate pairs are found.
  World(std::vector<Superquadric> shapes, std::vector<Material> materials, const Domain& domain, double skin,
        BroadPhase search = BroadPhase::CellList);

  /// Sets the law of a material pair (symmetric); every pair must be set before the first step.
  /// Sets the model's reach from the shapes (the normal law's reach at relative radius
  /// capFactor x the largest volume radius); throws std::invalid_argument when the law admits
  /// no contact of that size.
  void setContactModel(std::uint32_t materialA, std::uint32_t materialB, const ContactModel& model);
  const ContactModel& contactModel(std::uint32_t materialA, std::uint32_t materialB) const { return model(materialA, materialB); }
  /// The default law from two materials: elliptic Hertz, pair friction/restitution.
  ContactModel defaultContactModel(std::uint32_t materialA, std::uint32_t materialB) const;

  std::size_t addParticle(std::uint32_t shape, std::uint32_t material, const Vec3& centre, const Quat& q);
  void addWall(const Wall& wall) { walls_.push_back(wall); }

  void setGravity(const Vec3& g) { gravity_ = g; }
  const Vec3& gravity() const { return gravity_; }
  /// Re-order the particle slots along a Hilbert curve every `rebuilds` neighbour-list builds
  /// (0: never). Results then differ from an unordered run by round-off only (summation order).
  void setReorderInterval(int rebuilds) { reorderInterval_ = rebuilds; }
  /// Re-orders now (world_reorder.cpp); ids, contacts and their histories follow the particles.
  void reorderAlongHilbertCurve();
  /// Background drag F = -c m v (c in 1/s, translation only; 0 = off): settling in a viscous
  /// medium with terminal velocity |g|/c, a declared packing aid.
  void setViscousDamping(double c) { viscousDamping_ = c; }
  void setTimeStep(double dt) { dt_ = dt; }
  double timeStep() const { return dt_; }
  double time() const { return time_; }

  /// Advances one step (computes the initial forces first if needed).
  void step();
  /// Computes contacts and forces at the current state (no integration).
  void computeForces();

  ParticleStore& particles() { return particles_; }
  const ParticleStore& particles() const { return particles_; }
  const std::vector<Superquadric>& shapes() const { return shapes_; }
  const std::vector<Material>& materials() const { return materials_; }
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }
  /// The contacts that carried force in the last computation (touching, or rough within
  /// range), in key order.
  auto contacts() const {
    return interacting_ | std::views::transform([this](std::uint32_t k) -> const Contact& { return pairs_[k]; });
  }
  const Domain& domain() const { return domain_; }
  const WorldStatistics& statistics() const { return statistics_; }
  const StepTiming& timing() const { return timing_; }
  const NeighbourList& neighbourList() const { return neighbours_; }

  /// Checkpoint of the dynamic state (particles, walls, contact history, neighbour list,
  /// time, statistics) in a binary form for the same build; the static parts (shapes,
  /// materials, laws) come from the scene. Restoring into a world built from the same scene
  /// continues bit for bit (world_state.cpp).
  void writeState(CheckpointWriter& out) const;
  /// Restores a state written by writeState; throws CheckpointError (checkpoint_file.hpp) if it
  /// does not match this world or any count or index is out of range. The world is unchanged
  /// when it throws.
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

 private:
  const ContactModel& model(std::uint32_t ma, std::uint32_t mb) const { return models_[ma * materials_.size() + mb]; }
  const ContactModel& lawOf(const Contact& c) const {
    return model(particles_.material[c.a], c.onWall() ? walls_[c.b & ~wallFlag].material : particles_.material[c.b]);
  }
  /// Within its law's range (touching, a rough contact's gap below 4 sigma, an adhesive contact
  /// until it detaches).
  bool interacting(const Contact& c) const {
    return c.geometry.converged() && c.geometry.overlap > -c.history.range(lawOf(c));
  }
  /// The candidate list from the neighbour list and the walls within reach, carrying the
  /// histories of persisting pairs; kept until the next rebuild (particles or walls moved more
  /// than half the skin), so steps in between copy no contact records.
  void buildCandidates();
  bool wallsMovedHalfSkin() const;
  double servoVelocity(std::size_t w) const;  ///< along wall w's normal (m/s), WallServo
  double largestRange() const;  ///< the largest gap any law acts across (m)
  /// Per particle, the indices of its contacts in key order (for the parallel reduction).
  void indexInvolvement();
  void detect(Contact& c) const;    ///< narrow phase, warm-started from c.geometry
  void applyLaw(Contact& c) const;  ///< force of a contact within its law's range, updates its history

  std::vector<Superquadric> shapes_;
  std::vector<Material> materials_;
  std::vector<ContactModel> models_;
  std::vector<bool> modelSet_;
  Domain domain_;
  NeighbourList neighbours_;
  ParticleStore particles_;
  std::vector<double> boundingRadius_;
  std::vector<Wall> walls_;
  std::vector<Vec3> wallReference_;       ///< wall points at the last candidate build
  std::vector<Contact> pairs_;            ///< every candidate of the current neighbour list, key order
  /// What the reduction needs of a force-carrying contact, packed densely (the full records
  /// are ~440 bytes): force on B, contact point, moment on B, B's periodic shift.
  struct ContactLoad {
    Vec3 force, point, moment, shift;
  };
  static constexpr std::uint32_t bodyBFlag = 0x80000000u;  ///< in involvement_: the particle is body B
  std::vector<std::uint8_t> acting_;               ///< per contact of pairs_: carries force this step
  std::vector<ContactLoad> loads_;                 ///< per contact of pairs_, valid where acting_
  std::vector<std::uint32_t> involvementStart_;    ///< particle i's contacts: involvement_[start[i], start[i+1])
  std::vector<std::uint32_t> involvement_;         ///< contact index, | bodyBFlag where i is body B
  std::vector<std::uint32_t> interacting_;  ///< indices of the force-carrying ones in pairs_
  WorldStatistics statistics_;
  StepTiming timing_;
  Vec3 gravity_ = Vec3::Zero();
  double viscousDamping_ = 0.0;
  int reorderInterval_ = 0;
  double dt_ = 0.0, time_ = 0.0;
  bool forcesCurrent_ = false;
};

}  // namespace sqdem

#pragma once
// The contact store (docs/architecture.md, "Stores"): every candidate pair of the current
// neighbour list, as a structure of arrays so that a kernel touches only the fields it reads and
// writes:
//   identity     idA, idB: the bodies' global ids (A the lower; B a particle id, or
//                wallFlag | wall index), the feature of a mesh wall B touches (mesh_features.hpp;
//                0 for other bodies): the contact's key, the same in every process and however
//                the particles are stored
//   where        a, b: the bodies' slots in this process's particle store (b = wallFlag | wall
//                for a wall; a particle B may be a ghost, its periodic image), a cylinder
//                wall's image: found again at every candidate build
//   warm start   status, both surface points in their body frames, the separation bound
//   geometry     normal, overlap, contact point (the reduction's lever arm)
//   histories    tangential spring, the normal law's record, the rolling displacement
//   law cache    the curvature-derived law constants (curvature_cache.hpp) and the true-gap
//                law's rungs solved on the pose the cache keeps (mechanics/true_gap_law.hpp)
//   load         acting, force and moment on B, the normal force's parts and the area (carried
//                with the state: the energy ledger integrates from the last step's load)
//   energy       the contact's stored energy and the work it absorbed in the last step
//   bond         a parallel bond between the two bodies, where one formed (bond_frame.hpp)
// The rolling displacement exists only in a store made withRolling, the moment withRolling or
// withBonds, the law cache only withCurvatureCache, the rungs only withTrueGap, the energy only
// withEnergy, the bond only withBonds (a scene without rolling resistance, caching, the true-gap
// law, an energy ledger or bonds stores none of them). A bond outlives a failed solve of its pair (reset keeps it).
// Curvatures themselves are not stored: the fused kernels hand them from the detector to the
// law within one contact. The store is kept in the order the candidates were found (near
// slots together, for the kernels' memory traffic); key order is Interactions' index of it.

#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/dynamics/wall.hpp"
#include "sqdem/interaction/curvature_cache.hpp"
#include "sqdem/mechanics/bond_frame.hpp"
#include "sqdem/mechanics/normal_law.hpp"
#include "sqdem/mechanics/true_gap_law.hpp"

namespace sqdem {

class CheckpointReader;
class CheckpointWriter;

/// The parts of a contact's normal force that outputs and wall servos read.
struct NormalLoad {
  double force = 0.0;      ///< normal force magnitude (N), damping included
  double damping = 0.0;    ///< its viscous part (N)
  double stiffness = 0.0;  ///< S_n of the elastic part (N/m)
  double area = 0.0;       ///< contact area (m^2)
  bool yielded = false;    ///< NormalResponse::yielded: the contact carries a plastic dent
};

/// A contact's share of the energy ledger (world/energy_ledger.hpp), all in J: the elastic energy
/// its normal law stores now, and the work the contact absorbed from the bodies over the last
/// step (trapezoidal in its forces, with the relative velocity of the step's drift), split by
/// the force that did it.
struct ContactEnergy {
  double stored = 0.0;      ///< StoredEnergyLaw::storedEnergy
  double normal = 0.0;      ///< by the rate-independent normal force: stored or plastically dissipated
  double damping = 0.0;     ///< by the normal viscous force
  double tangential = 0.0;  ///< by the tangential force and the rolling moment: springs and sliding
  double bondStored = 0.0;  ///< the bond's elastic energy (parallel_bond.hpp), 0 when none holds
  double bond = 0.0;        ///< by the bond's force and moment: stored, or released as it broke
};

/// A contact's bond (docs/bonds.md): where it sits on both bodies and its section's radius. A
/// broken one stays broken (it does not form again while the pair is a candidate).
struct BondRecord {
  enum class State : std::uint8_t { None, Intact, Broken };
  BondRest rest;
  double radius = 0.0;            ///< R = lambda min(R_vol A, R_vol B) (m)
  Vec3 force = Vec3::Zero();      ///< its load on B at the last computation (N; zero once broken): the
  Vec3 moment = Vec3::Zero();     ///< energy ledger's work, and what the contact's force holds besides the law's
  State state = State::None;

  bool intact() const { return state == State::Intact; }
};

/// A contact's place in key order: the pair of ids (A, then B: walls after particles), then the
/// mesh feature.
struct ContactKey {
  std::uint64_t pair = 0;
  std::uint32_t feature = 0;
  auto operator<=>(const ContactKey&) const = default;
};

struct ContactStore {
  std::vector<std::uint32_t> idA, idB;  ///< global ids (idB: wallFlag | wall for a wall)
  std::vector<std::uint32_t> feature;   ///< of a mesh wall (0 otherwise)
  std::vector<std::uint32_t> a, b;      ///< slots in this process (b: wallFlag | wall for a wall)
  /// A cylinder wall's image nearest A in a periodic box, as an offset (m); zero otherwise (a
  /// particle's periodic image is a ghost slot, distributed/ghosts.hpp).
  std::vector<Vec3> wallImage;

  std::vector<ContactStatus> status;  ///< of the last solve
  std::vector<Vec3> localA, localB;   ///< surface points in A's and B's body frames (m)
  /// When the last solve found the pair Separated: a lower bound of its gap (m), reduced every
  /// step by a bound of the motion since; the pair is not solved again while it stays > reach.
  std::vector<double> separation;
  std::vector<Vec3> normal;      ///< unit, from A towards B
  std::vector<double> overlap;   ///< (m), < 0: a gap
  std::vector<Vec3> point;       ///< midpoint of the two surface points (m)

  std::vector<Vec3> spring;                ///< tangential spring (m)
  std::vector<NormalHistory> normalHistory;  ///< the normal law's record
  std::vector<Vec3> rolling;               ///< rolling displacement (m), withRolling only
  std::vector<CurvatureCache> curvatureCache;  ///< withCurvatureCache only
  std::vector<TrueGapRungs> trueGap;           ///< withTrueGap only

  std::vector<std::uint8_t> acting;  ///< carried force in the last computation
  std::vector<Vec3> force;           ///< on B (N); A receives -force
  std::vector<Vec3> moment;          ///< pure moment on B (N m), withMoment() only
  std::vector<NormalLoad> load;
  std::vector<ContactEnergy> energy;  ///< withEnergy only
  std::vector<BondRecord> bond;       ///< withBonds only

  bool withRolling = false;
  bool withCurvatureCache = false;
  bool withTrueGap = false;
  bool withEnergy = false;
  bool withBonds = false;

  /// Whether `other` keeps the same optional arrays.
  bool sameOptionalArrays(const ContactStore& other) const {
    return withRolling == other.withRolling && withCurvatureCache == other.withCurvatureCache && withTrueGap == other.withTrueGap &&
           withEnergy == other.withEnergy && withBonds == other.withBonds;
  }

  /// The moment array is kept: rolling resistance or bonds.
  bool withMoment() const { return withRolling || withBonds; }

  std::size_t size() const { return a.size(); }
  /// The bonds that hold (none without withBonds).
  std::size_t intactBonds() const;
  bool onWall(std::size_t k) const { return (b[k] & wallFlag) != 0; }
  ContactKey key(std::size_t k) const { return {(std::uint64_t{idA[k]} << 32) | idB[k], feature[k]}; }

  /// The arrays a contact carries from one step to the next (warm start, geometry, histories):
  /// what candidate rebuilds carry over.
  static constexpr auto stateArrays =
      std::tuple{&ContactStore::status, &ContactStore::localA, &ContactStore::localB, &ContactStore::separation,
                 &ContactStore::normal, &ContactStore::overlap, &ContactStore::point, &ContactStore::spring,
                 &ContactStore::normalHistory, &ContactStore::rolling, &ContactStore::curvatureCache,
                 &ContactStore::trueGap, &ContactStore::force, &ContactStore::moment, &ContactStore::load};
  /// Calls f(array) for every array, in a fixed order: the one list that checkpoints,
  /// re-ordering and resizing use, so a new field cannot be forgotten there.
  template <typename Store, typename F>
  static void forEachArray(Store& s, F&& f) {
    f(s.idA);
    f(s.idB);
    f(s.feature);
    f(s.a);
    f(s.b);
    f(s.wallImage);
    std::apply([&](auto... member) { (f(s.*member), ...); }, stateArrays);
    f(s.acting);
    f(s.energy);
    f(s.bond);
  }
  /// Whether an array (one of this store's) is kept: all but the optional ones (above).
  bool keeps(const void* array) const {
    if (array == &rolling) return withRolling;
    if (array == &moment) return withMoment();
    if (array == &energy) return withEnergy;
    if (array == &bond) return withBonds;
    if (array == &trueGap) return withTrueGap;
    return array != &curvatureCache || withCurvatureCache;
  }

  /// How many contacts ahead the kernels prefetch: a few us ahead for spheres, tens of us for
  /// ellipsoids; 24 contacts' records (~6-11 kB) stay well inside L1.
  static constexpr std::ptrdiff_t prefetchAhead = 24;
  /// Asks the memory system for every cache line of contact k in every kept array but the mesh
  /// feature (only mesh contacts read it; its prefetch cost the sphere kernel 0.9 %), ahead of a
  /// kernel's use: a group visits its contacts in ascending order, but the store's ~16 arrays
  /// are more streams than the hardware prefetcher follows (measured: the loads of a record
  /// missed the cache in the ellipsoid kernel). Always inlined, and the arrays named one by
  /// one: GCC 12 takes a function that does nothing but prefetch for one without effects and
  /// drops the call (measured: a binary without a single prefetch instruction).
  [[gnu::always_inline]] void prefetch(std::size_t k) const {
    const auto ahead = [k](const auto& array) {
      const char* first = reinterpret_cast<const char*>(array.data() + k);
      const char* last = first + sizeof(array[k]) - 1;
      for (const char* line = first; line < last; line += 64) __builtin_prefetch(line);
      __builtin_prefetch(last);
    };
    ahead(a), ahead(b), ahead(wallImage), ahead(status), ahead(localA), ahead(localB), ahead(separation);
    ahead(normal), ahead(overlap), ahead(point), ahead(spring), ahead(normalHistory);
    ahead(acting), ahead(force), ahead(load);
    if (withRolling) ahead(rolling);
    if (withMoment()) ahead(moment);
    if (withCurvatureCache) ahead(curvatureCache);
    if (withEnergy) ahead(energy);
  }
  /// Room for n contacts in every kept array.
  void reserve(std::size_t n);
  /// Appends a fresh candidate (no geometry, no history): its key, its bodies' slots and a
  /// cylinder wall's image offset.
  void add(const ContactKey& key, std::uint32_t slotA, std::uint32_t slotB, const Vec3& wallImageOffset);
  /// Forgets contact k's geometry and history (it is solved cold next time).
  void reset(std::size_t k);
  /// Copies contact `from` of `other` into contact k: every state array and the bond (those both
  /// stores keep).
  void carryOver(std::size_t k, const ContactStore& other, std::size_t from);
  /// Contact k's record, every kept array, for another process (its A migrates there).
  void write(std::size_t k, CheckpointWriter& out) const;
  /// Appends a record written by write() of a store with the same optional arrays.
  void read(CheckpointReader& in);
  /// Every kept array whole, after the optional arrays' flags (checkpoints).
  void writeArrays(CheckpointWriter& out) const;
  /// A store written by writeArrays, whose optional arrays must be `layout`'s; every array of
  /// the same length (CheckpointError otherwise). Indices are the caller's to check.
  static ContactStore readArrays(CheckpointReader& in, const ContactStore& layout);
  /// The store re-ordered: contact k of the result is contact order[k] of this one (order may
  /// name a subset: the others are dropped).
  void permute(const std::vector<std::uint32_t>& order);
};

/// Read access to one contact of a store (outputs, tests).
class ContactView {
 public:
  ContactView(const ContactStore& store, std::uint32_t k) : s_(&store), k_(k) {}

  std::uint32_t a() const { return s_->a[k_]; }  ///< slot of A
  /// Particle slot of B (only for a particle pair).
  std::uint32_t b() const { return s_->b[k_]; }
  ContactKey key() const { return s_->key(k_); }
  std::uint32_t slot() const { return k_; }  ///< in the store (Interactions::ellipses' index)
  bool onWall() const { return s_->onWall(k_); }
  std::uint32_t wall() const { return s_->b[k_] & ~wallFlag; }
  std::uint32_t feature() const { return s_->feature[k_]; }  ///< of a mesh wall
  const Vec3& normal() const { return s_->normal[k_]; }
  double overlap() const { return s_->overlap[k_]; }
  const Vec3& point() const { return s_->point[k_]; }
  const Vec3& force() const { return s_->force[k_]; }  ///< on B (N)
  Vec3 moment() const { return s_->withMoment() ? s_->moment[k_] : Vec3::Zero(); }
  const NormalLoad& normalLoad() const { return s_->load[k_]; }
  const NormalHistory& normalHistory() const { return s_->normalHistory[k_]; }
  const Vec3& spring() const { return s_->spring[k_]; }

 private:
  const ContactStore* s_;
  std::uint32_t k_;
};

}  // namespace sqdem

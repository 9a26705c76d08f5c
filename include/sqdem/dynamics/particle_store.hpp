#pragma once
// Structure-of-arrays particle state (docs/architecture.md, "Stores"). Index i is a particle's
// slot in this process; `id` is its global number, the same in every process and for the whole
// run (slots are re-ordered and, across ranks, particles migrate; ids never change). Everything
// kept of a particle lives here, shape and material as indices into the scene's tables.
//
// Rotation uses the NO_SQUISH variables of Miller et al. (J. Chem. Phys. 116, 8649, 2002): the
// unit quaternion q (body -> world) and its conjugate momentum p = 2 q ⊗ (0, L_body), a
// 4-vector; the body angular momentum is L_body = vec(q* ⊗ p) / 2. `angularVelocity` (world) is
// derived from (q, p) after every integration stage.

#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem {


struct ParticleStore {
  std::vector<std::uint32_t> id;
  std::vector<std::uint32_t> shape;     ///< index into the scene's shape table
  std::vector<std::uint32_t> material;  ///< index into the scene's material table
  std::vector<Vec3> position;           ///< centre (m)
  std::vector<Quat> orientation;        ///< body -> world
  std::vector<Vec3> velocity;           ///< (m/s)
  std::vector<Vec4> conjugateMomentum;  ///< NO_SQUISH p (kg m^2/s)
  std::vector<Vec3> angularVelocity;    ///< world frame (rad/s), derived
  std::vector<Vec3> force;              ///< (N), reset every step
  std::vector<Vec3> torque;             ///< world frame (N m), reset every step
  std::vector<double> mass;             ///< (kg)
  std::vector<Vec3> inertia;            ///< principal moments in the body frame (kg m^2)
  std::vector<double> boundingRadius;   ///< of its shape (m)
  /// |v| + |w| R_bound (m/s), how fast any point of it moves, this step; kept only when a scene's
  /// detectors cull separated pairs by it (Interactions::cullsBySpeed), 0 otherwise.
  std::vector<double> speedBound;

  /// Slots [0, size()) hold the particles this process owns, slots [size(), slots()) their
  /// ghosts (distributed/ghosts.hpp): copies of particles seen from elsewhere in the domain (a
  /// periodic image), made again at every neighbour-list build. Every array has slots() entries.
  std::size_t ghostCount = 0;
  std::size_t size() const { return position.size() - ghostCount; }
  std::size_t slots() const { return position.size(); }

  /// Calls f(array) for every per-particle array, in a fixed order: the one list of them that
  /// checkpoints, re-ordering and ghosts use, so a new field cannot be forgotten there.
  template <typename Store, typename F>
  static void forEachArray(Store& store, F&& f) {
    f(store.id);
    f(store.shape);
    f(store.material);
    f(store.position);
    f(store.orientation);
    f(store.velocity);
    f(store.conjugateMomentum);
    f(store.angularVelocity);
    f(store.force);
    f(store.torque);
    f(store.mass);
    f(store.inertia);
    f(store.boundingRadius);
    f(store.speedBound);
  }

  /// Appends a particle at rest, its id the next one; returns its slot. The store holds no
  /// ghosts then (std::logic_error otherwise).
  std::size_t add(std::uint32_t shapeIndex, std::uint32_t materialIndex, const Vec3& centre, const Quat& q,
                  double particleMass, const Vec3& principalInertia, double bound);

  /// Sets the angular velocity (world frame) of particle i, i.e. its conjugate momentum.
  void setAngularVelocity(std::size_t i, const Vec3& omegaWorld);
  /// Body-frame angular momentum L_body = vec(q* ⊗ p) / 2.
  Vec3 bodyAngularMomentum(std::size_t i) const;
  /// Recomputes angularVelocity[i] from (q, p).
  void updateAngularVelocity(std::size_t i);

  double translationalEnergy(std::size_t i) const { return 0.5 * mass[i] * velocity[i].squaredNorm(); }
  double rotationalEnergy(std::size_t i) const;
};

}  // namespace sqdem

#pragma once
// The work a contact absorbs over one step, for the energy ledger (world/energy_ledger.hpp).
//
// Velocity Verlet drifts every body with its half-step velocity v_{n+1/2} between the forces F_n
// and F_{n+1}; the kinetic energy it gains over the step is (F_n + F_{n+1}) / 2 . v_{n+1/2} dt
// plus (F_{n+1}^2 - F_n^2) dt^2 / 8m, a term that telescopes over a run. The kernels see
// v_{n+1/2} (the force computation comes between drift and second kick), so a contact whose
// force on B was f_n before the step and is f_{n+1} now absorbs
//   W = -(f_n + f_{n+1}) / 2 . v_rel dt,   v_rel = velocity of B minus A at the contact point,
// the energy the bodies lost to it. Each force is split along its own normal into the
// rate-independent part F_e n, the viscous part F_d n and the tangential rest, and W with it.
// Rolling moments are not counted: they come only with haervig_jkr, which states no stored
// energy (the ledger refuses it).

#include "sqdem/interaction/contact_model.hpp"
#include "sqdem/interaction/contact_store.hpp"

namespace sqdem::detail {

/// A contact's load as the store kept it.
struct ContactLoad {
  Vec3 normal = Vec3::UnitZ();
  Vec3 force = Vec3::Zero();  ///< on B (N)
  NormalLoad load;            ///< zero when it did not act
};

/// W of the step, split into ContactEnergy's normal, damping and tangential parts (J); `stored`
/// is left to the caller.
inline ContactEnergy contactWork(const ContactLoad& before, const ContactLoad& after, const Vec3& relativeVelocity,
                                 double dt) {
  const auto absorbed = [&](const Vec3& f0, const Vec3& f1) { return -0.5 * dt * (f0 + f1).dot(relativeVelocity); };
  const auto elastic = [](const ContactLoad& c) { return Vec3((c.load.force - c.load.damping) * c.normal); };
  const auto viscous = [](const ContactLoad& c) { return Vec3(c.load.damping * c.normal); };
  ContactEnergy w;
  w.normal = absorbed(elastic(before), elastic(after));
  w.damping = absorbed(viscous(before), viscous(after));
  w.tangential = absorbed(before.force, after.force) - w.normal - w.damping;
  return w;
}

}  // namespace sqdem::detail

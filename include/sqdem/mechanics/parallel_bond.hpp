#pragma once
// bond: the parallel bond of Potyondy & Cundall (2004; docs/references.md, docs/bonds.md): a
// cylinder of cement of radius R = lambda r between two bodies, a beam of elastic stiffnesses per
// area k_n, k_s (Pa/m) that carries a normal force, a shear force, a twisting and a bending moment
// (their Eq. 10 with the increments summed):
//   F_n = k_n A u_n (> 0 in tension)   F_s = -k_s A u_s   M_t = -k_s J theta_t   M_b = -k_n I theta_b
//   A = pi R^2, I = pi R^4 / 4, J = pi R^4 / 2,
// u_n the extension along the bond's axis, u_s the shear displacement, theta_t the twist about the
// axis and theta_b the bending rotation (bond_frame.hpp). It breaks when the largest tensile or
// shear stress on its cross-section reaches the strength (their Eq. 11):
//   sigma = F_n / A + |M_b| R / I >= sigma_c   or   tau = |F_s| / A + |M_t| R / J >= tau_c.
// Its stored energy is (1/2)(k_n A u_n^2 + k_s A |u_s|^2 + k_s J theta_t^2 + k_n I |theta_b|^2).
// Beside each spring, optionally, a dashpot at beta times its critical coefficient (a viscous
// binder; docs/bonds.md, "Damping"): against B's velocity relative to A at the bond's centre,
// split along and across the axis, and against B's spin relative to A's,
//   F = -2 beta (sqrt(k_n A m*) v_n + sqrt(k_s A m*) v_s)
//   M = -2 beta (sqrt(k_s J j*) w_t + sqrt(k_n I j*) w_b),
// m* the pair's reduced mass and j* its reduced smallest principal moment of inertia (a plane's
// are infinite: the particle's own): a bonded pair's relative stretch is then a damped oscillator
// of damping ratio beta exactly, and its other modes at most beta.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/math/types.hpp"

namespace sqdem {

/// A bond's material (per material pair, `interactions[].bond`).
struct ParallelBond {
  double radiusMultiplier = 1.0;  ///< lambda: the bond's radius over the smaller body's radius (-), > 0
  double normalStiffness = 0.0;   ///< k_n per area (Pa/m), > 0
  double shearStiffness = 0.0;    ///< k_s per area (Pa/m), > 0
  double tensileStrength = 0.0;   ///< sigma_c (Pa), > 0
  double shearStrength = 0.0;     ///< tau_c (Pa), > 0
  double dampingRatio = 0.0;      ///< beta (-), in [0, 1]: 0 is Potyondy & Cundall's undamped bond

  /// std::invalid_argument naming the first value out of range.
  void check() const {
    const auto positive = [](double x, const char* what) {
      if (!(x > 0.0 && std::isfinite(x))) throw std::invalid_argument(std::string(what) + " must be positive and finite");
    };
    positive(radiusMultiplier, "radius_multiplier");
    positive(normalStiffness, "normal_stiffness");
    positive(shearStiffness, "shear_stiffness");
    positive(tensileStrength, "tensile_strength");
    positive(shearStrength, "shear_strength");
    if (!(dampingRatio >= 0.0 && dampingRatio <= 1.0)) throw std::invalid_argument("damping_ratio must be in [0, 1]");
  }
};

/// The bond's cross-section: radius R (m), area A, second moment I and polar moment J.
struct BondSection {
  double radius = 0.0, area = 0.0, inertia = 0.0, polar = 0.0;

  explicit BondSection(double R = 0.0)
      : radius(R), area(std::numbers::pi * R * R), inertia(0.25 * std::numbers::pi * R * R * R * R),
        polar(0.5 * std::numbers::pi * R * R * R * R) {}
};

/// How a bond is deformed, in its frame (bond_frame.hpp): n its unit axis from A to B.
struct BondDeformation {
  Vec3 axis = Vec3::UnitZ();        ///< n
  double extension = 0.0;           ///< u_n (m), > 0 stretched
  Vec3 shear = Vec3::Zero();        ///< u_s of B relative to A, normal to n (m)
  double twist = 0.0;               ///< theta_t of B relative to A about n (rad)
  Vec3 bending = Vec3::Zero();      ///< theta_b of B relative to A, normal to n (rad)
};

/// What a bond carries (on B; A carries the opposite) and its largest stresses.
struct BondLoads {
  Vec3 force = Vec3::Zero();         ///< F_n n + F_s (N)
  Vec3 moment = Vec3::Zero();        ///< M_t n + M_b (N m), besides the force's moment
  double normalForce = 0.0;          ///< F_n (N), > 0 in tension
  Vec3 shearForce = Vec3::Zero();    ///< F_s (N)
  double tensileStress = 0.0;        ///< sigma (Pa)
  double shearStress = 0.0;          ///< tau (Pa)
  double energy = 0.0;               ///< stored elastic energy (J)

  /// The stresses reach a strength: the bond breaks.
  bool breaks(const ParallelBond& bond) const { return tensileStress >= bond.tensileStrength || shearStress >= bond.shearStrength; }
};

/// Potyondy & Cundall's Eqs. 10-11 for a bond of section s deformed by d.
inline BondLoads bondLoads(const ParallelBond& bond, const BondSection& s, const BondDeformation& d) {
  const double kn = bond.normalStiffness, ks = bond.shearStiffness;
  const double Fn = kn * s.area * d.extension, Mt = -ks * s.polar * d.twist;
  const Vec3 Fs = -ks * s.area * d.shear, Mb = -kn * s.inertia * d.bending;
  BondLoads l;
  l.normalForce = Fn;
  l.shearForce = Fs;
  l.force = -Fn * d.axis + Fs;  // a stretched bond pulls B back towards A
  l.moment = Mt * d.axis + Mb;
  l.tensileStress = Fn / s.area + Mb.norm() * s.radius / s.inertia;
  l.shearStress = Fs.norm() / s.area + std::abs(Mt) * s.radius / s.polar;
  l.energy = 0.5 * (kn * s.area * d.extension * d.extension + ks * s.area * d.shear.squaredNorm() +
                    ks * s.polar * d.twist * d.twist + kn * s.inertia * d.bending.squaredNorm());
  return l;
}

/// The bond's dashpots on B (A carries the opposite), for B's velocity `velocity` and spin `spin`
/// relative to A's at the bond's centre, the pair's reduced mass and reduced smallest principal
/// moment of inertia.
struct BondDashpots {
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
};
inline BondDashpots bondDashpots(const ParallelBond& bond, const BondSection& s, const Vec3& axis, const Vec3& velocity,
                                 const Vec3& spin, double reducedMass, double reducedMoment) {
  const double b = 2.0 * bond.dampingRatio, kn = bond.normalStiffness, ks = bond.shearStiffness;
  const Vec3 vn = velocity.dot(axis) * axis, wt = spin.dot(axis) * axis;
  return {-b * (std::sqrt(kn * s.area * reducedMass) * vn + std::sqrt(ks * s.area * reducedMass) * (velocity - vn)),
          -b * (std::sqrt(ks * s.polar * reducedMoment) * wt + std::sqrt(kn * s.inertia * reducedMoment) * (spin - wt))};
}

/// The fastest angular frequency (rad/s) of a body of mass m, smallest principal moment of inertia
/// J_min and largest half-extent l held by one bond of section s (docs/bonds.md, "Time step"):
/// its translation against k A (the stiffer of k_n and k_s), its turn against the shear spring at
/// lever l plus the stiffer of bending (k_n I) and twisting (k_s J).
inline double bondAngularFrequency(const ParallelBond& bond, const BondSection& s, double mass, double smallestInertia, double lever) {
  const double kn = bond.normalStiffness, ks = bond.shearStiffness;
  const double translation = std::max(kn, ks) * s.area / mass;
  const double rotation = (ks * s.area * lever * lever + std::max(kn * s.inertia, ks * s.polar)) / smallestInertia;
  return std::sqrt(std::max(translation, rotation));
}

}  // namespace sqdem

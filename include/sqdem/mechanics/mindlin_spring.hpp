#pragma once
// tangential: elliptic_mindlin / circular_mindlin, the engine's tangential component: an
// incremental spring xi kept in the tangent plane (tangent_plane.hpp), F_t = -K_t xi - damping,
// Coulomb cap |F_t| <= limit (mu F_n, or mu |F_n + 2 F_C| with adhesion: the caller's).
//   elliptic   K_t = 8 G* a_c (u u^T / Phi(0) + v v^T / Phi(pi/2)): Mindlin's no-slip stiffness
//              of the contact ellipse (004 Eqs. 56-57, a_c its semi-major axis from the area and
//              e^2, u its direction from both surfaces' curvatures, v the minor one); a force
//              along theta from u meets the stiffness 8 G* a_c / Phi(theta) of Eq. 56 exactly
//   circular   K_t = 8 G* a I, a = sqrt(A/pi) (the area-equivalent circle, Phi = 1)
// Damping per axis: ViscousDamping with k_u, k_v. The partial-slip softening of 004 Eqs. 59-67
// is not applied: the spring is linear up to the Coulomb limit. History: the spring (m).

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/damping.hpp"
#include "sqdem/mechanics/normal_law.hpp"
#include "sqdem/mechanics/tangent_plane.hpp"

namespace sqdem {

struct MindlinSpring {
  bool elliptic = true;         ///< on the contact ellipse (needs curvatures), else the circle
  double effectiveShear = 0.0;  ///< G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 (Pa)
  double poissonRatio = 0.0;    ///< nu of Eq. 57, the mean of the two materials' (-)
  double friction = 0.0;        ///< mu (-); 0: no tangential force

  /// Force on B at a contact of area A (m^2) with the normal n (A to B) and, if elliptic, the
  /// contact ellipse's major axis u (unit, normal to n: contactMajorAxis of elliptic.hpp); vt the
  /// tangential velocity of B relative to A (m/s), mass m* (kg), step dt (s). Updates the spring.
  /// Inline: the circle is the whole of every round (sphere) contact's tangential work.
  Vec3 force(const NormalContact& c, const Vec3& majorAxis, const Vec3& n, double area, const Vec3& vt, double limit,
             const ViscousDamping& damping, double mass, Vec3& spring, double dt) const {
    if (elliptic) {
      advance(spring, n, vt, dt);
      return ellipticForce(c, majorAxis, n, area, vt, limit, damping, mass, spring);
    }
    // The circle: one stiffness in every tangential direction, K_t = 8 G* a I.
    const double k = 8.0 * effectiveShear * std::sqrt(area / std::numbers::pi);
    return circleForce(k, damping.coefficient(mass, k), n, vt, limit, spring, dt);
  }

  /// The circle's force with its stiffness k = 8 G* a (N/m) and damping coefficient eta (N s/m)
  /// given (the round Hertz contact has both from its own square roots, contact_force.hpp).
  Vec3 circleForce(double k, double eta, const Vec3& n, const Vec3& vt, double limit, Vec3& spring, double dt) const {
    advance(spring, n, vt, dt);
    Vec3 Ft = -(k * spring + eta * vt);
    if (Ft.squaredNorm() > limit * limit) {
      // Slip: the spring shrinks to what carries the Coulomb force.
      Ft *= limit / Ft.norm();
      spring = k > 0.0 ? Vec3(-(Ft + eta * vt) / k) : Vec3::Zero();
    }
    return Ft;
  }

 private:
  /// The spring turned into today's tangent plane and advanced by the step's slip.
  static void advance(Vec3& spring, const Vec3& n, const Vec3& vt, double dt) {
    keepInTangentPlane(spring, n);
    spring += vt * dt;
  }
  /// The ellipse, with the spring already turned and advanced.
  Vec3 ellipticForce(const NormalContact& c, const Vec3& u, const Vec3& n, double area, const Vec3& vt, double limit,
                     const ViscousDamping& damping, double mass, Vec3& spring) const;
};

}  // namespace sqdem

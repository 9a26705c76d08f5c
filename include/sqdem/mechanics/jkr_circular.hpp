#pragma once
// Classical JKR contact of two spheres (Johnson, Kendall & Roberts 1971), the circular limit of
// the elliptic Johnson-Greenwood law and the force of Haervig et al.'s simplified JKR model
// (001 Eqs. 7-10, where the surface energy density gamma enters as W = 2 gamma):
//
//   overlap  delta(a) = a^2/R - sqrt(2 pi W a / E*)          (001 Eq. A.9 with W = 2 gamma)
//   force    F(a)     = 4 E* a^3 / (3 R) - sqrt(8 pi W E* a^3)    (001 Eqs. 8-9, > 0 repulsive)
//   pull-off (load control)  F_C = 3/2 pi W R, at a = (9 pi W R^2 / (8 E*))^(1/3)
//   equilibrium (F = 0)      a_0 = (9 pi W R^2 / (2 E*))^(1/3)  (001 Eq. 7)
//   zero overlap             a(0) = (2 pi W R^2 / E*)^(1/3)     (001 Eq. A.5)
//
// E* effective modulus (Pa), W work of adhesion (J/m^2), R effective radius (m), a contact
// radius (m). The stable branch under displacement control is a >= a_min, the radius at which
// d delta / da = 0, a_min = (pi W R^2 / (8 E*))^(1/3); delta(a_min) is the overlap at which a
// displacement-controlled contact detaches (negative).

namespace sqdem {

struct CircularJkr {
  double effectiveModulus;  ///< E* (Pa)
  double workOfAdhesion;    ///< W (J/m^2)
  double radius;            ///< R (m)

  double overlapAt(double contactRadius) const;
  double forceAt(double contactRadius) const;
  /// Smallest contact radius of the stable branch, where d delta/da = 0 (m).
  double minimumContactRadius() const;
  /// Contact radius on the stable branch for overlap >= overlapAt(minimumContactRadius()).
  double contactRadius(double overlap) const;
  double pullOffForce() const;  ///< 3/2 pi W R (N), magnitude of the most tensile force
};

}  // namespace sqdem

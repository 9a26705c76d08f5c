#pragma once
// Superquadric particle shape (004 Eq. 15, written with blockiness exponents n = 2/eta):
//
//     (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 = 1,     n1, n2 >= 2,
//
// a, b, c are the semi-axes along the body x, y, z axes (m); n1 shapes the y-z and x-z sections,
// n2 the x-y section. n1 = n2 = 2 is an ellipsoid, and a sphere when a = b = c.
//
// The surface is represented by its gauge (Minkowski functional)
//
//     g(x) = ((|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1)^(1/n1),
//
// whose level set g = 1 is Eq. 15. g is convex and homogeneous of degree one: g(t x) = t g(x),
// so x / g(x) is the radial projection of x onto the surface, g - 1 is a well-scaled implicit
// function for any n (no |x|^20 under- or overflow), and its gradient and Hessian stay finite
// on and near the coordinate planes. All functions take body-frame coordinates.
//
// Smoothness: the surface is C2 everywhere except at the poles (0, 0, +-c) when n1 = 2 < n2,
// where the second derivatives are bounded but depend on the direction of approach (the
// x-y section is not round); curvatures there are those of the limit along the x or y axis.

#include <cmath>

#include "sqdem/math/types.hpp"

namespace sqdem {

/// Value, gradient and Hessian of the gauge g (or of F = g^n1, insideOutside) at one body-frame point.
struct GaugeDerivatives {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
};

class Superquadric {
 public:
  /// Semi-axes a, b, c > 0 (m), exponents n1, n2 in [2, maxExponent]. Throws
  /// std::invalid_argument naming the offending parameter.
  Superquadric(double a, double b, double c, double n1, double n2);

  static Superquadric sphere(double radius) { return {radius, radius, radius, 2.0, 2.0}; }
  static Superquadric ellipsoid(double a, double b, double c) { return {a, b, c, 2.0, 2.0}; }
  /// The papers' squareness convention eta = 2/n (004 Eq. 15: eta1, eta2 in (0, 1]).
  static Superquadric fromEta(double a, double b, double c, double eta1, double eta2) {
    return {a, b, c, 2.0 / eta1, 2.0 / eta2};
  }

  /// Largest exponent accepted; beyond it the shape is numerically a box.
  static constexpr double maxExponent = 50.0;

  double a() const { return halfExtents_.x(); }
  double b() const { return halfExtents_.y(); }
  double c() const { return halfExtents_.z(); }
  double n1() const { return n1_; }
  double n2() const { return n2_; }
  const Vec3& halfExtents() const { return halfExtents_; }
  bool isEllipsoid() const { return n1_ == 2.0 && n2_ == 2.0; }
  bool isSphere() const { return isEllipsoid() && a() == b() && b() == c(); }

  /// Gauge g(x); the surface is g = 1, the inside g < 1.
  double gauge(const Vec3& x) const;
  /// Implicit function g(x) - 1 (negative inside).
  double implicitFunction(const Vec3& x) const { return gauge(x) - 1.0; }
  /// g, grad g and Hessian of g at x (x != 0).
  GaugeDerivatives derivatives(const Vec3& x) const;
  /// g and grad g at x (x != 0), the Hessian left 0: the same bits as derivatives'.
  GaugeDerivatives firstDerivatives(const Vec3& x) const;
  /// F = g^n1, the left side of Eq. 15 (the inside-outside function: F - 1 has the sign of
  /// g - 1), and grad F at x, the Hessian left 0: no root taken. Convex as g is.
  GaugeDerivatives insideOutside(const Vec3& x) const;
  /// Outward unit normal at (or radially through) x.
  Vec3 outwardNormal(const Vec3& x) const;
  /// Radial projection x / g(x) of x != 0 onto the surface.
  Vec3 projectRadially(const Vec3& x) const { return x / gauge(x); }
  /// Surface point furthest along `direction` (need not be unit): the support map, in closed
  /// form through the dual (Hoelder-conjugate) nested norm.
  Vec3 supportPoint(const Vec3& direction) const;
  /// Surface parametrisation, eta in [-pi/2, pi/2] (latitude), omega in [-pi, pi] (longitude).
  Vec3 surfacePoint(double eta, double omega) const;

  /// Volume (m^3): 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2), e = 2/n (Jaklic et al. 2000),
  /// computed once (the packing measures ask for it every log row).
  double volume() const { return volume_; }
  /// Radius of the sphere of equal volume (m).
  double volumeEquivalentRadius() const { return volumeEquivalentRadius_; }
  double mass(double density) const { return density * volume(); }
  /// Principal moments of inertia about the body axes (kg m^2) for a uniform density (kg/m^3).
  Vec3 principalMomentsOfInertia(double density) const;
  /// Second moments of volume (integral of x^2, y^2, z^2 over the body, m^5).
  Vec3 secondMomentsOfVolume() const;
  /// Radius of a sphere about the centre that contains the whole body (m).
  double boundingRadius() const { return boundingRadius_; }

 private:
  Vec3 halfExtents_;
  double n1_, n2_;
  double boundingRadius_ = 0.0;
  double volume_ = 0.0;
  double volumeEquivalentRadius_ = 0.0;
};

/// R_vol_ref = sqrt(R_vol,A R_vol,B) (m): the pair's length scale, used for the detector's
/// tolerance and for the radius cap (docs/contact_laws.md, "Conventions").
inline double referenceVolumeRadius(const Superquadric& A, const Superquadric& B) {
  return std::sqrt(A.volumeEquivalentRadius() * B.volumeEquivalentRadius());
}

}  // namespace sqdem

#pragma once
// The curvature-derived constants of a contact's law (relative radii, e^2, gamma, beta, K, D and
// the contact ellipse's major axis), kept while the contact stays where they were evaluated:
// both contact points within eps R_ref of their positions then (on their own bodies; R_ref =
// sqrt(R_vol,A R_vol,B)) and the bodies' relative orientation within eps rad (a twist about the
// normal turns the principal directions against each other without moving either point).
// eps = the contact model's curvature_tolerance; 0 evaluates them every step.
//
// Error: an ellipsoid's curvatures vary over lengths of order R_ref, so a point moved by
// eps R_ref (or a turn by eps) changes the relative radii by O(eps) relative and the Hertz force
// F ~ E* sqrt(Rc) delta^3/2 gamma by O(eps/2); a blocky superquadric's vary faster where its
// faces round into edges (n = 6: up to ~5 eps measured). Measured in the run time vs error
// benchmark (bench/accuracy_bench.cpp).

#include <cmath>

#include "sqdem/math/types.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

struct CurvatureCache {
  Vec3 localA = Vec3::Zero();      ///< contact point on A when evaluated (A's body frame, m)
  Vec3 localB = Vec3::Zero();      ///< on B (B's body frame; a wall's: the world, m)
  Vec4 relative = Vec4::Zero();    ///< coefficients of q_A* q_B then (q_A* for a wall)
  RelativeRadii radii;             ///< Rc = 0: empty
  HertzFactors factors;
  Vec3 majorAxisA = Vec3::Zero();  ///< the ellipse's major axis (A's body frame)

  /// Whether the cache holds for a contact now at a, b (body frames) with relative orientation
  /// q: tolerance (m) for the points, cosHalfAngle = cos(eps / 2) for the orientation
  /// (|q1 . q2| = cos(theta / 2) for the angle theta between two rotations).
  bool holds(const Vec3& a, const Vec3& b, const Quat& q, double tolerance, double cosHalfAngle) const {
    return radii.Rc > 0.0 && (a - localA).squaredNorm() <= tolerance * tolerance &&
           (b - localB).squaredNorm() <= tolerance * tolerance && std::abs(q.coeffs().dot(relative)) >= cosHalfAngle;
  }
  /// The turn from the relative orientation kept to q as a rotation vector in A's frame, on the
  /// axes of the true-gap rungs' plane (truegap/pair_gap.hpp) for the contact normal n now (A's
  /// frame): t1 the major axis kept laid on the plane (any tangent where it has no part there),
  /// t2 = n x t1. Returns its components (tilt1, tilt2) (rad); the twist about n is left out.
  Vec2 tiltTo(const Quat& q, const Vec3& n) const {
    Quat d = q * Quat(relative).conjugate();  // B's turn as A sees it
    if (d.w() < 0.0) d.coeffs() = -d.coeffs();
    const double half = d.vec().norm();
    if (!(half > 0.0)) return Vec2::Zero();
    const Vec3 turn = 2.0 * std::atan2(half, d.w()) / half * d.vec();
    const Vec3 laid = majorAxisA - majorAxisA.dot(n) * n;
    const Vec3 t1 = laid.norm() > 1e-6 * majorAxisA.norm() && laid.norm() > 0.0 ? Vec3(laid.normalized()) : Vec3(n.unitOrthogonal());
    return {turn.dot(t1), turn.dot(n.cross(t1))};
  }
};

}  // namespace sqdem

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
};

}  // namespace sqdem

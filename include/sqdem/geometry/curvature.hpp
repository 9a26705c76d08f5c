#pragma once
// Principal curvatures and directions of an implicit surface f = const at a point
// (004 Eqs. 6-10; 002 Appendix A, Eqs. 55-70, for the ellipsoid special case).
//
// With n = grad f / |grad f| the outward normal and P = I - n n^T, the shape operator on the
// tangent plane is S = P H P / |grad f|; its eigenpairs are the principal curvatures k1 >= k2
// (positive on a convex surface) and principal directions d1, d2 (unit, orthogonal, tangent).
// This is 004 Eq. 7 (k = K_M +- sqrt(K_M^2 - K_G), mean and Gaussian curvature) with the
// directions of Eqs. 9-10, evaluated without the arbitrary (u, v) parametrisation.

#include "sqdem/math/types.hpp"

namespace sqdem {

struct PrincipalCurvatures {
  double k1 = 0.0;            ///< larger principal curvature (1/m)
  double k2 = 0.0;            ///< smaller principal curvature (1/m)
  Vec3 d1 = Vec3::UnitX();    ///< unit direction of k1 (tangent)
  Vec3 d2 = Vec3::UnitY();    ///< unit direction of k2, d1 x d2 = outward normal

  double mean() const { return 0.5 * (k1 + k2); }
  double gaussian() const { return k1 * k2; }
  /// The same curvatures with directions rotated by R (body -> world).
  PrincipalCurvatures rotated(const Mat3& R) const { return {k1, k2, R * d1, R * d2}; }
  /// The curvatures of a flat surface (a wall) with normal n.
  static PrincipalCurvatures flat(const Vec3& normal);
};

/// Principal curvatures of the level set through a point with the given gradient (non-zero)
/// and Hessian of the implicit function. Umbilics (k1 = k2) get an arbitrary tangent frame.
PrincipalCurvatures principalCurvatures(const Vec3& gradient, const Mat3& hessian);

/// Symmetric 2x2 eigen-decomposition: eigenvalues l1 >= l2, unit eigenvector of l1.
struct SymmetricEigen2 {
  double l1, l2;
  Vec2 v1;
};
SymmetricEigen2 symmetricEigen2(double s11, double s12, double s22);

}  // namespace sqdem

#include "sqdem/geometry/curvature.hpp"

#include <cmath>

namespace sqdem {

SymmetricEigen2 symmetricEigen2(double s11, double s12, double s22) {
  const double mean = 0.5 * (s11 + s22);
  const double half = 0.5 * (s11 - s22);
  const double radius = std::sqrt(half * half + s12 * s12);  // curvatures: no overflow risk, cheaper than hypot
  SymmetricEigen2 e{mean + radius, mean - radius, Vec2::UnitX()};
  if (radius == 0.0) return e;  // umbilic: every direction is principal
  // Eigenvector of l1 from the better-conditioned of the two rows of (S - l1 I).
  const Vec2 fromRow1(s12, e.l1 - s11), fromRow2(e.l1 - s22, s12);
  e.v1 = (fromRow1.squaredNorm() > fromRow2.squaredNorm() ? fromRow1 : fromRow2).normalized();
  return e;
}

PrincipalCurvatures principalCurvatures(const Vec3& gradient, const Mat3& hessian) {
  const double gradNorm = gradient.norm();
  const Vec3 n = gradient / gradNorm;
  Vec3 t1, t2;
  tangentBasis(n, t1, t2);
  const Vec3 Ht1 = hessian * t1, Ht2 = hessian * t2;
  const SymmetricEigen2 e = symmetricEigen2(t1.dot(Ht1) / gradNorm, t1.dot(Ht2) / gradNorm,
                                            t2.dot(Ht2) / gradNorm);
  PrincipalCurvatures pc;
  pc.k1 = e.l1;
  pc.k2 = e.l2;
  pc.d1 = (e.v1.x() * t1 + e.v1.y() * t2).normalized();
  pc.d2 = n.cross(pc.d1);
  return pc;
}

PrincipalCurvatures PrincipalCurvatures::flat(const Vec3& normal) {
  PrincipalCurvatures pc;
  tangentBasis(normal, pc.d1, pc.d2);
  return pc;
}

}  // namespace sqdem

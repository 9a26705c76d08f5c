// Particle against a point (detector.hpp): a mesh vertex.
//
// The common normal of a convex body A and a point P passes through P: A's surface point x with
// P - x parallel to A's outward normal n(x), overlap = -n . (P - x) (P inside A: the distance
// to the nearest boundary point). x is found by Newton's method on A's surface, in A's body
// frame: the residual is the tangential part tau = (I - n n^T)(P - x); moving x by dx along the
// tangent plane changes it by -(I + rho S) dx, rho = n . (P - x), S the shape operator
// (curvature.hpp), so each step solves (I + rho S) dx = tau in the principal frame and projects
// x + dx radially back onto the surface. Flat faces (S = 0) are solved in one step. A step is
// capped at a quarter of A's volume radius; the start is the radial projection of P, or the last
// solution. A sphere is solved in closed form.

#include <algorithm>
#include <cmath>

#include "sqdem/contact/detector.hpp"

namespace sqdem {
namespace {

ContactGeometry separatedBy(double gap) {
  ContactGeometry g;
  g.overlap = -std::max(gap, 0.0);
  return g;
}

}  // namespace

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Vec3& point,
                              const DetectorSettings& settings, const WarmStart* previous) {
  const Vec3 P = poseA.toBody(point);
  const double centreDistance = P.norm();
  ContactGeometry g;
  if (centreDistance - A.boundingRadius() > settings.cutoff) return separatedBy(centreDistance - A.boundingRadius());
  if (centreDistance == 0.0) {
    g.status = ContactStatus::Degenerate;
    return g;
  }
  const double length = A.volumeEquivalentRadius();
  Vec3 x = A.isSphere() ? Vec3(A.a() / centreDistance * P)
                        : (previous != nullptr ? previous->localPointA : A.projectRadially(P));
  Vec3 n = A.isSphere() ? Vec3(P / centreDistance) : A.outwardNormal(x);
  int iterations = 0;
  bool converged = A.isSphere();
  while (!converged && iterations < settings.maxIterations) {
    const GaugeDerivatives d = A.derivatives(x);
    n = d.gradient.normalized();
    const Vec3 r = P - x;
    const double rho = n.dot(r);
    const Vec3 tau = r - rho * n;
    if (!tau.allFinite()) break;
    if (tau.norm() <= settings.tolerance * length) {
      converged = true;
      break;
    }
    const PrincipalCurvatures c = principalCurvatures(d.gradient, d.hessian);
    // (I + rho S) dx = tau; beyond a centre of curvature (1 + rho k <= 0) a plain gradient step.
    const auto along = [&](const Vec3& dir, double k) {
      const double stiffness = 1.0 + rho * k;
      return tau.dot(dir) / (stiffness > 0.1 ? stiffness : 1.0) * dir;
    };
    Vec3 dx = along(c.d1, c.k1) + along(c.d2, c.k2);
    if (dx.norm() > 0.25 * length) dx *= 0.25 * length / dx.norm();
    x = A.projectRadially(x + dx);
    ++iterations;
  }
  g.iterations = iterations;
  if (!converged) {
    g.status = x.allFinite() ? ContactStatus::MaxIterations : ContactStatus::NonFinite;
    return g;
  }
  const double gap = n.dot(P - x);
  if (gap > settings.cutoff) return separatedBy(gap);
  const bool inside = A.gauge(P) < 1.0;
  if (inside != (gap < 0.0)) {
    g.status = ContactStatus::WrongBranch;  // the far side's normal through P
    return g;
  }
  g.status = -gap >= A.halfExtents().minCoeff() ? ContactStatus::Degenerate : ContactStatus::Converged;
  const Mat3 R = poseA.rotation();
  g.normal = R * n;
  g.overlap = -gap;
  g.localPointA = x;
  g.pointA = poseA.toWorld(x);
  g.pointB = point;
  g.localPointB = point;  // kinematic bodies keep world-frame points
  g.curvatureB = PrincipalCurvatures::flat(-g.normal);
  if (settings.curvatures && g.converged()) addCurvatures(g, A, poseA);
  return g;
}

}  // namespace sqdem

#include "sqdem/truegap/pair_gap.hpp"

#include <cmath>
#include <stdexcept>

#include "sqdem/contact/surface_along_line.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

namespace {

const ContactGeometry& converged(const ContactGeometry& contact) {
  if (!contact.converged()) throw std::invalid_argument("the true gap: the detector's contact did not converge");
  return contact;
}

}  // namespace

// (Where t1 has no part on the plane, the region's search finds its own axes.)
Vec3 planeAxis(const Vec3& t1, const Vec3& n) {
  const Vec3 t = t1 - t1.dot(n) * n;
  return t.norm() > 1e-6 * t1.norm() && t.norm() > 0.0 ? Vec3(t.normalized()) : Vec3(n.unitOrthogonal());
}

PairGap::PairGap(const PairBody& A, const PairBody& B, const ContactGeometry& contact)
    : PairGap(A, B, 0.5 * (converged(contact).pointA + contact.pointB), contact.normal,
              contactMajorAxis(contact.curvatureA, contact.curvatureB, contact.normal), contact.overlap,
              relativeRadii(contact.curvatureA, contact.curvatureB, 10.0 * referenceVolumeRadius(A.shape, B.shape))) {}

PairGap PairGap::touchingAt(const Superquadric& A, const Superquadric& B, const Vec3& localA, const Vec3& localB, const Quat& relative,
                            const Vec3& majorAxisA, const RelativeRadii& radii) {
  const Pose poseA, poseB{localA - relative * localB, relative};
  return PairGap({A, poseA}, {B, poseB}, localA, A.outwardNormal(localA).normalized(), majorAxisA, 0.0, radii);
}

PairGap::PairGap(const PairBody& A, const PairBody& B, const Vec3& origin, const Vec3& normal, const Vec3& t1, double overlap,
                 const RelativeRadii& radii)
    : shapeA_(&A.shape), shapeB_(&B.shape), poseA_(A.pose), poseB_(B.pose), origin_(origin), normal_(normal),
      t1_(planeAxis(t1, normal)), t2_(normal.cross(t1_)),
      overlap_(overlap), referenceLength_(referenceVolumeRadius(A.shape, B.shape)), quadraticAspect_(std::sqrt(radii.ratio())),
      majorRadius_(radii.Rj) {}

double PairGap::operator()(double x, double y) const {
  Heights none;
  return (*this)(x, y, none, 0.0);
}

double PairGap::operator()(double x, double y, Heights& near, double distance) const {
  const Vec3 q = origin_ + x * t1_ + y * t2_;
  near.top = surfaceFarthestAlong(*shapeA_, poseA_, q, normal_, near.top + distance);
  near.bottom = -surfaceFarthestAlong(*shapeB_, poseB_, q, -normal_, distance - near.bottom);
  return near.bottom - near.top + overlap_;  // +infinity where a line misses a body
}

}  // namespace sqdem

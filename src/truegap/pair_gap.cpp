#include "sqdem/truegap/pair_gap.hpp"

#include <cmath>
#include <stdexcept>

#include "sqdem/contact/surface_along_line.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

PairGap::PairGap(const PairBody& A, const PairBody& B, const ContactGeometry& contact)
    : A_(A), B_(B), origin_(0.5 * (contact.pointA + contact.pointB)), normal_(contact.normal), overlap_(contact.overlap),
      referenceLength_(referenceVolumeRadius(A.shape, B.shape)) {
  if (!contact.converged()) throw std::invalid_argument("the true gap: the detector's contact did not converge");
  t1_ = contactMajorAxis(contact.curvatureA, contact.curvatureB, normal_);
  t2_ = normal_.cross(t1_);
  const RelativeRadii radii = relativeRadii(contact.curvatureA, contact.curvatureB, 10.0 * referenceLength_);
  quadraticAspect_ = std::sqrt(radii.ratio());
  majorRadius_ = radii.Rj;
}

double PairGap::operator()(double x, double y) const {
  const Vec3 q = origin_ + x * t1_ + y * t2_;
  const double top = surfaceFarthestAlong(A_.shape, A_.pose, q, normal_), bottom = -surfaceFarthestAlong(B_.shape, B_.pose, q, -normal_);
  return bottom - top + overlap_;  // +infinity where a line misses a body
}

}  // namespace sqdem

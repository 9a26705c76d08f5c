#pragma once
// Independent checks of a detector answer from the shapes themselves, for the detector sweeps.

#include <algorithm>
#include <cmath>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::testing {

/// Every number of the answer is finite (points, normal, overlap, residual, curvatures).
inline bool allFinite(const ContactGeometry& g) {
  return g.pointA.allFinite() && g.pointB.allFinite() && g.normal.allFinite() && std::isfinite(g.overlap) &&
         std::isfinite(g.residual) && std::isfinite(g.curvatureA.k1) && std::isfinite(g.curvatureA.k2) &&
         std::isfinite(g.curvatureB.k1) && std::isfinite(g.curvatureB.k2) && g.curvatureA.d1.allFinite() &&
         g.curvatureB.d1.allFinite() && g.curvatureA.d2.allFinite() && g.curvatureB.d2.allFinite();
}

/// The largest violation of the common-normal conditions (detector.hpp) in world frame (m):
/// antiparallel normals (times L), connecting vector along the normal, points on the surfaces
/// (implicit function times L).
inline double commonNormalError(const Superquadric& A, const Pose& pa, const Superquadric& B, const Pose& pb,
                                const ContactGeometry& g, double L) {
  const Vec3 nA = pa.orientation * A.outwardNormal(pa.toBody(g.pointA));
  const Vec3 nB = pb.orientation * B.outwardNormal(pb.toBody(g.pointB));
  const Vec3 d = g.pointB - g.pointA;
  const double onA = std::abs(A.implicitFunction(pa.toBody(g.pointA))) * L;
  const double onB = std::abs(B.implicitFunction(pb.toBody(g.pointB))) * L;
  return std::max({(nA + nB).norm() * L, (d - d.dot(nA) * nA).norm(), onA, onB});
}

}  // namespace sqdem::testing

// Independent check of separated pairs (issue 2, item 7): the detector's gap (-overlap) for
// separated ellipsoids equals FCL's GJK distance (libccd) within 1e-6 relative.

#include <gtest/gtest.h>

#include <fcl/narrowphase/distance.h>
#include <fcl/geometry/shape/ellipsoid.h>

#include "sqdem/contact/detector.hpp"
#include "support/random_pairs.hpp"

namespace sqdem {
namespace {

double fclDistance(const Superquadric& A, const Pose& pa, const Superquadric& B, const Pose& pb) {
  const auto object = [](const Superquadric& s, const Pose& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = p.position;
    tf.linear() = p.rotation();
    return fcl::CollisionObjectd(std::make_shared<fcl::Ellipsoidd>(s.a(), s.b(), s.c()), tf);
  };
  fcl::CollisionObjectd oa = object(A, pa), ob = object(B, pb);
  fcl::DistanceRequestd request(true, false, 0.0, 0.0, 1e-12, fcl::GST_LIBCCD);
  fcl::DistanceResultd result;
  fcl::distance(&oa, &ob, request, result);
  return result.min_distance;
}

TEST(FclCrossCheck, SeparatedEllipsoidGapEqualsGjkDistance) {
  testing::PairGenerator gen(2024);
  gen.minExponent = gen.maxExponent = 2.0;
  DetectorSettings settings;
  settings.cutoff = 10.0;
  double worst = 0.0;
  int checked = 0;
  for (int k = 0; k < 200; ++k) {
    testing::PlantedPair p = gen.next();
    const Superquadric A = Superquadric::ellipsoid(p.A.a(), p.A.b(), p.A.c());
    const Superquadric B = Superquadric::ellipsoid(p.B.a(), p.B.b(), p.B.c());
    p.poseB.position += (p.overlap + 0.01 + 0.5 * gen.uniform(0, 1)) * p.normal;  // open a gap
    const ContactGeometry g = detectContact(A, p.poseA, B, p.poseB, settings);
    ASSERT_TRUE(g.converged()) << describe(g.status);
    ASSERT_LT(g.overlap, 0.0);
    const double reference = fclDistance(A, p.poseA, B, p.poseB);
    worst = std::max(worst, std::abs(-g.overlap - reference) / reference);
    ++checked;
  }
  std::printf("%d separated ellipsoid pairs: max relative |gap - FCL distance| = %.2e\n", checked, worst);
  EXPECT_LT(worst, 1e-6);
}

}  // namespace
}  // namespace sqdem

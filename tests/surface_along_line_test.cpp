// Where a line meets a superquadric (contact/surface_along_line.hpp): the far crossing lies on the
// surface (gauge g = 1, the surface's definition, 004 Eq. 15) with the body behind it along the
// line (g < 1 just before it); every start gives the same crossing: beyond it near and far, inside
// the body, before the body (Newton on the convex F = g^n1 is monotone only from beyond the far
// side, and the search starts afresh from the sphere around the body's box otherwise); a line that
// misses the body, beside it or through the box's corner outside it, is -infinity from any start;
// a thin plate of n = 50 seen edge-on and face-on.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sqdem/contact/surface_along_line.hpp"

namespace sqdem {
namespace {

TEST(SurfaceAlongLine, EveryStartFindsTheFarCrossing) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Superquadric& s : {Superquadric::ellipsoid(1.0, 0.6, 0.4), Superquadric(1.0, 0.7, 0.5, 6.0, 6.0),
                                Superquadric(0.8, 0.5, 1.2, 10.0, 4.0), Superquadric(1.0, 0.6, 0.9, 2.7, 7.3)}) {
    const double R = s.boundingRadius();
    for (int k = 0; k < 50; ++k) {
      const Pose pose{Vec3(normal(rng), normal(rng), normal(rng)),
                      Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized()};
      const Vec3 d = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
      // A line through a point inside the body: it crosses the surface twice.
      const Vec3 inside = pose.toWorld(0.5 * unit(rng) * s.projectRadially(Vec3(normal(rng), normal(rng), normal(rng))));
      const Vec3 q = inside - 0.3 * R * d;
      const double t = surfaceFarthestAlong(s, pose, q, d);
      ASSERT_TRUE(std::isfinite(t));
      EXPECT_NEAR(s.gauge(pose.toBody(q + t * d)), 1.0, 1e-12);
      EXPECT_LT(s.gauge(pose.toBody(q + (t - 1e-6 * R) * d)), 1.0);  // the body behind it
      EXPECT_GT(s.gauge(pose.toBody(q + (t + 1e-6 * R) * d)), 1.0);
      const double before = (inside - q).dot(d) - 3.0 * R;  // a point before the body along the line
      for (const double start : {t + 1e-9 * R, t + 1e-3 * R, t + 0.5 * R, t + R, t, t - 1e-3 * R, 0.3 * R, before}) {
        EXPECT_NEAR(surfaceFarthestAlong(s, pose, q, d, start), t, 1e-12 * R) << "start " << start << " crossing " << t;
      }
      // A line beside the body, parallel to d at twice its bounding radius: no crossing.
      const Vec3 beside = pose.position + 2.0 * R * d.unitOrthogonal();
      for (const double start : {std::numeric_limits<double>::infinity(), 0.0, R, -R}) {
        EXPECT_EQ(surfaceFarthestAlong(s, pose, beside, d, start), -std::numeric_limits<double>::infinity());
      }
    }
  }
}

TEST(SurfaceAlongLine, MissesPastTheCornerAndThinPlates) {
  // n = 10 cube of half-edge 1: along (1, 1, 1) its surface is at 3^(1/2 - 1/10) = 1.552 from the
  // centre, its box's corner at 3^(1/2) = 1.732; a line across (1, 1, 1) at 1.65 misses the body
  // inside the box's sphere.
  const Superquadric cube(1.0, 1.0, 1.0, 10.0, 10.0);
  const Vec3 diagonal = Vec3(1, 1, 1).normalized(), across = Vec3(1, -1, 0).normalized();
  for (const double start : {std::numeric_limits<double>::infinity(), 0.0, 0.5}) {
    EXPECT_EQ(surfaceFarthestAlong(cube, Pose{}, 1.65 * diagonal, across, start), -std::numeric_limits<double>::infinity());
  }
  const double t = surfaceFarthestAlong(cube, Pose{}, 1.5 * diagonal, across);  // through the body's diagonal section
  EXPECT_GT(t, 0.0);
  EXPECT_NEAR(cube.gauge(1.5 * diagonal + t * across), 1.0, 1e-12);
  // A plate 100 x 100 x 2 (half-extents 1, 1, 0.02), n = 50: its top above the centre is at 0.02,
  // its far edge along x at 1.
  const Superquadric plate(1.0, 1.0, 0.02, 50.0, 50.0);
  EXPECT_NEAR(surfaceFarthestAlong(plate, Pose{}, Vec3::Zero(), Vec3::UnitZ()), 0.02, 1e-14);
  EXPECT_NEAR(surfaceFarthestAlong(plate, Pose{}, Vec3::Zero(), Vec3::UnitX()), 1.0, 1e-14);
  EXPECT_NEAR(surfaceFarthestAlong(plate, Pose{}, Vec3(0.3, 0.2, -0.5), Vec3::UnitZ()), 0.52, 1e-14);
}

}  // namespace
}  // namespace sqdem

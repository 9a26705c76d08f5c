// Principal curvatures from the implicit surface (curvature.hpp; 004 Eqs. 6-10): ellipsoid axis
// tips (closed form a/b^2, a/c^2), umbilics, flat-face centres, and general ellipsoid points
// against the independent parametric formulas of 002 Appendix A (Eqs. 57-63).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sqdem/geometry/curvature.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {
namespace {

PrincipalCurvatures curvatureAt(const Superquadric& s, const Vec3& p) {
  const GaugeDerivatives d = s.derivatives(p);
  return principalCurvatures(d.gradient, d.hessian);
}

TEST(Curvature, EllipsoidAxisTips) {
  const double a = 1.0, b = 0.6, c = 0.3;
  const Superquadric e = Superquadric::ellipsoid(a, b, c);
  // Tip of the a axis: curvatures a/b^2 (direction y) and a/c^2 (direction z).
  const PrincipalCurvatures x = curvatureAt(e, Vec3(a, 0, 0));
  EXPECT_NEAR(x.k1, a / (c * c), 1e-12);
  EXPECT_NEAR(x.k2, a / (b * b), 1e-12);
  EXPECT_NEAR(std::abs(x.d1.z()), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(x.d2.y()), 1.0, 1e-12);
  const PrincipalCurvatures z = curvatureAt(e, Vec3(0, 0, -c));
  EXPECT_NEAR(z.k1, c / (b * b), 1e-12);
  EXPECT_NEAR(z.k2, c / (a * a), 1e-12);
  EXPECT_NEAR(z.d1.cross(z.d2).dot(Vec3(0, 0, -1)), 1.0, 1e-12);  // d1 x d2 = outward normal
}

TEST(Curvature, SphereIsUmbilicEverywhere) {
  const Superquadric s = Superquadric::sphere(2.0);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  for (int k = 0; k < 50; ++k) {
    const PrincipalCurvatures pc = curvatureAt(s, s.projectRadially(Vec3(g(rng), g(rng), g(rng))));
    EXPECT_NEAR(pc.k1, 0.5, 1e-12);
    EXPECT_NEAR(pc.k2, 0.5, 1e-12);
    EXPECT_NEAR(pc.d1.dot(pc.d2), 0.0, 1e-12);
  }
  // The umbilics of a triaxial ellipsoid (x^2/a^2 + z^2/c^2 = 1 plane, y = 0): k1 = k2.
  const double a = 1.0, b = 0.7, c = 0.4;
  const double x = a * std::sqrt((a * a - b * b) / (a * a - c * c));
  const double z = c * std::sqrt((b * b - c * c) / (a * a - c * c));
  const PrincipalCurvatures u = curvatureAt(Superquadric::ellipsoid(a, b, c), Vec3(x, 0, z));
  EXPECT_NEAR(u.k1, u.k2, 1e-7 * u.k1);
}

TEST(Curvature, FlatFaceCentresOfBlockySuperquadrics) {
  for (const double n : {4.0, 6.0, 10.0}) {
    const Superquadric s(1.0, 0.8, 2.0, n, n);
    for (const Vec3& p : {Vec3(0, 0, 2), Vec3(1, 0, 0), Vec3(0, -0.8, 0)}) {
      const PrincipalCurvatures pc = curvatureAt(s, p);
      EXPECT_NEAR(pc.k1, 0.0, 1e-14) << "n=" << n;
      EXPECT_NEAR(pc.k2, 0.0, 1e-14);
    }
  }
}

TEST(Curvature, EllipsoidMatchesBeckerAppendixA) {
  // 002 App. A: x = a sqrt(1 - y^2/b^2 - z^2/c^2) (Eq. 56), fundamental forms (Eqs. 61-62);
  // the principal curvatures solve (EG - F^2) k^2 - (EN + GL - 2FM) k + (LN - M^2) = 0.
  const double a = 1.0, b = 0.55, c = 0.35;
  const Superquadric e = Superquadric::ellipsoid(a, b, c);
  for (const auto& [y, z] : {std::pair{0.2, 0.1}, {-0.3, 0.2}, {0.05, -0.3}, {0.4, 0.1}}) {
    const double x = a * std::sqrt(1 - y * y / (b * b) - z * z / (c * c));
    const double E = std::pow(a, 4) * y * y / (std::pow(b, 4) * x * x) + 1;
    const double F = std::pow(a, 4) * y * z / (b * b * c * c * x * x);
    const double G = std::pow(a, 4) * z * z / (std::pow(c, 4) * x * x) + 1;
    const double n = std::sqrt(E + G - 1);  // Eq. 60
    const double L = std::pow(a, 4) * (c * c - z * z) / (b * b * c * c * n * x * x * x);
    const double M = std::pow(a, 4) * y * z / (b * b * c * c * n * x * x * x);
    const double N = std::pow(a, 4) * (b * b - y * y) / (b * b * c * c * n * x * x * x);
    const double qa = E * G - F * F, qb = E * N + G * L - 2 * F * M, qc = L * N - M * M;
    const double disc = std::sqrt(qb * qb - 4 * qa * qc);
    const PrincipalCurvatures pc = curvatureAt(e, Vec3(x, y, z));
    EXPECT_NEAR(pc.k1, (qb + disc) / (2 * qa), 1e-10);
    EXPECT_NEAR(pc.k2, (qb - disc) / (2 * qa), 1e-10);
  }
}

TEST(Curvature, SymmetricEigen2) {
  const SymmetricEigen2 e = symmetricEigen2(2.0, 1.0, 2.0);
  EXPECT_NEAR(e.l1, 3.0, 1e-15);
  EXPECT_NEAR(e.l2, 1.0, 1e-15);
  EXPECT_NEAR(std::abs(e.v1.x()), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(std::abs(e.v1.y()), std::sqrt(0.5), 1e-15);
}

}  // namespace
}  // namespace sqdem

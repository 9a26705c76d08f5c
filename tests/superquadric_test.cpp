// Superquadric shape (superquadric.hpp; 004 Eq. 15): gauge derivatives against finite
// differences for n up to 20 and near the coordinate planes (n1 = n2 takes the single 3-D norm,
// checked against 004 Eq. 15 like the nested one), the inside-outside function F = g^n1 and its
// gradient by the chain rule, support map, parametrisation,
// bounding radius, and the closed-form volume and inertia (Jaklic et al. 2000) against an
// independent numerical quadrature of the solid.

#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {
namespace {

std::vector<Superquadric> shapes() {
  return {Superquadric::sphere(1.3),           Superquadric::ellipsoid(1.0, 0.5, 0.3),
          Superquadric(1.0, 0.7, 0.4, 3.5, 2.0), Superquadric(1.0, 1.0, 2.0, 6.0, 6.0),
          Superquadric(0.8, 0.5, 1.2, 10.0, 4.0), Superquadric(1.0, 0.6, 0.9, 20.0, 20.0),
          Superquadric(1.0, 0.6, 0.9, 2.0, 20.0),  Superquadric(0.9, 0.7, 1.1, 3.5, 3.5)};
}

/// Surface points including some within 1e-9 of the coordinate planes.
std::vector<Vec3> probePoints(const Superquadric& s) {
  std::vector<Vec3> points;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 40; ++k) points.push_back(s.projectRadially(Vec3(g(rng), g(rng), g(rng))));
  for (const Vec3& d : {Vec3(1e-9, 0.6, 0.3), Vec3(0.5, -1e-10, 0.7), Vec3(0.4, 0.3, 1e-9),
                        Vec3(0.0, 0.6, 0.3), Vec3(0.8, 0.0, -0.2)}) {
    points.push_back(s.projectRadially(d));
  }
  return points;
}

TEST(Superquadric, DerivativesMatchFiniteDifferences) {
  for (const Superquadric& s : shapes()) {
    for (const Vec3& p : probePoints(s)) {
      for (const double scale : {1.0, 0.9, 1.2}) {  // on, inside and outside the surface
        const Vec3 x = scale * p;
        const GaugeDerivatives d = s.derivatives(x);
        ASSERT_TRUE(d.gradient.allFinite() && d.hessian.allFinite());
        EXPECT_NEAR(d.value, s.gauge(x), 1e-14);
        const double h = 1e-6;
        for (int i = 0; i < 3; ++i) {
          const Vec3 e = h * Vec3::Unit(i);
          const double fd = (s.gauge(x + e) - s.gauge(x - e)) / (2 * h);
          EXPECT_NEAR(d.gradient(i), fd, 1e-7 * (1.0 + std::abs(fd))) << "n1=" << s.n1() << " x=" << x.transpose();
          const Vec3 fdCol = (s.derivatives(x + e).gradient - s.derivatives(x - e).gradient) / (2 * h);
          for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(d.hessian(j, i), fdCol(j), 2e-5 * (1.0 + d.hessian.cwiseAbs().maxCoeff()))
                << "n1=" << s.n1() << " n2=" << s.n2() << " x=" << x.transpose();
          }
        }
      }
    }
  }
}

TEST(Superquadric, FirstDerivativesAndInsideOutside) {
  for (const Superquadric& s : shapes()) {
    for (const Vec3& p : probePoints(s)) {
      for (const double scale : {1.0, 0.9, 1.2}) {
        const Vec3 x = scale * p;
        const GaugeDerivatives d = s.derivatives(x), first = s.firstDerivatives(x);
        EXPECT_EQ(first.value, d.value);  // the same operations: the same bits
        EXPECT_EQ(first.gradient, d.gradient);
        // F = g^n1 (the left side of 004 Eq. 15), grad F = n1 g^(n1 - 1) grad g.
        const GaugeDerivatives f = s.insideOutside(x);
        const double g = d.value;
        EXPECT_NEAR(f.value, std::pow(g, s.n1()), 1e-13 * std::pow(g, s.n1())) << "n1=" << s.n1() << " n2=" << s.n2();
        const Vec3 chain = s.n1() * std::pow(g, s.n1() - 1.0) * d.gradient;
        EXPECT_LT((f.gradient - chain).norm(), 1e-12 * chain.norm()) << "n1=" << s.n1() << " n2=" << s.n2() << " x=" << x.transpose();
      }
    }
  }
}

TEST(Superquadric, GaugeIsHomogeneousAndEquivalentToEq15) {
  for (const Superquadric& s : shapes()) {
    for (const Vec3& p : probePoints(s)) {
      EXPECT_NEAR(s.gauge(p), 1.0, 1e-14);
      EXPECT_NEAR(s.gauge(2.5 * p), 2.5, 1e-13);
      // 004 Eq. 15 on the surface: (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 = 1.
      const double eq15 = std::pow(std::pow(std::abs(p.x() / s.a()), s.n2()) +
                                       std::pow(std::abs(p.y() / s.b()), s.n2()),
                                   s.n1() / s.n2()) +
                          std::pow(std::abs(p.z() / s.c()), s.n1());
      EXPECT_NEAR(eq15, 1.0, 1e-12);
    }
  }
}

TEST(Superquadric, DerivativesFiniteOnAxesAndForLargeExponents) {
  const Superquadric s(1.0, 0.5, 2.0, 20.0, 20.0);
  for (const Vec3& x : {Vec3(1, 0, 0), Vec3(0, 0.5, 0), Vec3(0, 0, 2), Vec3(0, 0, -2), Vec3(1e-300, 0, 2),
                        Vec3(50, 50, 50)}) {
    const GaugeDerivatives d = s.derivatives(x);
    EXPECT_TRUE(d.gradient.allFinite() && d.hessian.allFinite()) << x.transpose();
    EXPECT_GT(d.gradient.norm(), 0.0);
  }
}

TEST(Superquadric, SupportPointIsTheFurthestSurfacePoint) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  for (const Superquadric& s : shapes()) {
    for (int k = 0; k < 30; ++k) {
      const Vec3 d = Vec3(g(rng), g(rng), g(rng)).normalized();
      const Vec3 p = s.supportPoint(d);
      EXPECT_NEAR(s.gauge(p), 1.0, 1e-12);
      EXPECT_NEAR(s.outwardNormal(p).dot(d), 1.0, 1e-9) << "n1=" << s.n1() << " d=" << d.transpose();
      for (int j = 0; j < 200; ++j) {  // no sampled surface point lies further along d
        const Vec3 q = s.projectRadially(Vec3(g(rng), g(rng), g(rng)));
        EXPECT_LE(q.dot(d), p.dot(d) + 1e-12);
      }
    }
  }
}

TEST(Superquadric, ParametrisationLiesOnSurfaceInsideBoundingSphere) {
  for (const Superquadric& s : shapes()) {
    double furthest = 0.0;
    for (int i = 0; i <= 200; ++i) {
      for (int j = 0; j <= 200; ++j) {
        const Vec3 p = s.surfacePoint(-std::numbers::pi / 2 + std::numbers::pi * i / 200,
                                      -std::numbers::pi + 2 * std::numbers::pi * j / 200);
        EXPECT_NEAR(s.gauge(p), 1.0, 1e-12);
        furthest = std::max(furthest, p.norm());
      }
    }
    EXPECT_LE(furthest, s.boundingRadius() * (1.0 + 1e-12));
    EXPECT_GE(furthest, s.boundingRadius() * (1.0 - 1e-3));  // a 200 x 200 grid under-samples the maximum
  }
}

TEST(Superquadric, ClosedFormsForSpheresAndEllipsoids) {
  const Superquadric e = Superquadric::ellipsoid(1.0, 0.5, 0.3);
  EXPECT_NEAR(e.volume(), 4.0 / 3.0 * std::numbers::pi * 0.15, 1e-14);
  const Vec3 I = e.principalMomentsOfInertia(2.0);
  const double m = e.mass(2.0);  // I_x = m (b^2 + c^2) / 5
  EXPECT_NEAR(I.x(), m * (0.25 + 0.09) / 5, 1e-14);
  EXPECT_NEAR(I.y(), m * (1.0 + 0.09) / 5, 1e-14);
  EXPECT_NEAR(I.z(), m * (1.0 + 0.25) / 5, 1e-14);
  EXPECT_NEAR(Superquadric::sphere(2.0).volumeEquivalentRadius(), 2.0, 1e-14);
  const Superquadric byEta = Superquadric::fromEta(1, 1, 2, 1.0 / 3.0, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(byEta.n1(), 6.0);
}

/// Independent quadrature: the solid is |z| <= c (1 - (|x/a|^n2 + |y/b|^n2)^(n1/n2))^(1/n1) over
/// the planform |y| <= b (1 - |x/a|^n2)^(1/n2); integrate moments of x^2, y^2, z^2 (tanh-sinh).
Vec3 quadratureMoments(const Superquadric& s, double& volume) {
  boost::math::quadrature::tanh_sinh<double> integrator;
  const auto halfHeight = [&](double x, double y) {
    const double inner = std::pow(std::abs(x / s.a()), s.n2()) + std::pow(std::abs(y / s.b()), s.n2());
    return s.c() * std::pow(std::max(0.0, 1.0 - std::pow(inner, s.n1() / s.n2())), 1.0 / s.n1());
  };
  const auto yMax = [&](double x) {
    return s.b() * std::pow(std::max(0.0, 1.0 - std::pow(std::abs(x / s.a()), s.n2())), 1.0 / s.n2());
  };
  const auto integrate = [&](auto weight) {  // 8 x integral over the positive octant
    return 8.0 * integrator.integrate([&](double x) {
      const double ym = yMax(x);
      if (ym <= 0.0) return 0.0;
      return integrator.integrate([&](double y) { return weight(x, y, halfHeight(x, y)); }, 0.0, ym, 1e-10);
    }, 0.0, s.a(), 1e-10);
  };
  volume = integrate([](double, double, double z) { return z; });
  return {integrate([](double x, double, double z) { return x * x * z; }),
          integrate([](double, double y, double z) { return y * y * z; }),
          integrate([](double, double, double z) { return z * z * z / 3.0; })};
}

TEST(Superquadric, VolumeAndInertiaMatchQuadrature) {
  for (const Superquadric& s : shapes()) {
    double volume = 0.0;
    const Vec3 moments = quadratureMoments(s, volume);
    EXPECT_NEAR(s.volume(), volume, 1e-7 * volume) << "n1=" << s.n1() << " n2=" << s.n2();
    const Vec3 closed = s.secondMomentsOfVolume();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(closed(i), moments(i), 1e-7 * moments(i)) << i;
  }
}

TEST(Superquadric, RejectsImpossibleParameters) {
  EXPECT_THROW(Superquadric(0.0, 1, 1, 2, 2), std::invalid_argument);
  EXPECT_THROW(Superquadric(1, -1, 1, 2, 2), std::invalid_argument);
  EXPECT_THROW(Superquadric(1, 1, 1, 1.5, 2), std::invalid_argument);
  EXPECT_THROW(Superquadric(1, 1, 1, 2, NAN), std::invalid_argument);
  EXPECT_THROW(Superquadric(1, 1, 1, 2, 80), std::invalid_argument);
}

}  // namespace
}  // namespace sqdem

// A superquadric's surface area (analysis/surface_area.hpp) against closed forms: a sphere's
// 4 pi R^2; a prolate spheroid's 2 pi b^2 (1 + a / (b e) asin(e)), e^2 = 1 - b^2 / a^2; a triaxial
// ellipsoid's by Legendre's formula computed here by numerical quadrature of the surface element
// instead; the extrapolated tessellation of a shape next to an ellipsoid (n = 2 + 1e-7) against
// the ellipsoid's closed form; superballs |x|^n + |y|^n + |z|^n = a^n (n1 = n2 = n) against
// quadrature of the graph z(x, y) over the sixth of the surface where z is the largest coordinate
// (smooth there: |grad z| <= 2^(1/2)), A = 48 a^2 int_0^x1 int_0^y1(x) (1 + z_x^2 + z_y^2)^(1/2) dy dx
// with y1 = min(x, (1 - 2 x^n)^(1/n)), x1 = 2^(-1/n), a = 1.

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sqdem/analysis/surface_area.hpp"

namespace sqdem {
namespace {

constexpr double pi = std::numbers::pi;

/// An ellipsoid's area by quadrature of |r_theta x r_phi| over theta in [0, pi], phi in [0, 2 pi].
double quadratureArea(double a, double b, double c) {
  using boost::math::quadrature::gauss_kronrod;
  return gauss_kronrod<double, 61>::integrate([&](double theta) {
    return gauss_kronrod<double, 61>::integrate([&](double phi) {
      const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
      const Vec3 rt(a * ct * cp, b * ct * sp, -c * st), rp(-a * st * sp, b * st * cp, 0.0);
      return rt.cross(rp).norm();
    }, 0.0, 2.0 * pi, 10, 1e-13);
  }, 0.0, pi, 10, 1e-13);
}

TEST(SurfaceArea, EllipsoidsInClosedForm) {
  EXPECT_NEAR(surfaceArea(Superquadric::sphere(3e-6)) / (4.0 * pi * 9e-12), 1.0, 1e-14);
  const double a = 5e-6, b = 2e-6, e = std::sqrt(1.0 - b * b / (a * a));
  EXPECT_NEAR(surfaceArea(Superquadric::ellipsoid(a, b, b)) / (2.0 * pi * b * b * (1.0 + a / (b * e) * std::asin(e))), 1.0, 1e-12);
  for (const Vec3 axes : {Vec3(5e-6, 3e-6, 2e-6), Vec3(1e-6, 4e-6, 2.5e-6), Vec3(2e-6, 2e-6, 7e-6)}) {
    const double expected = quadratureArea(axes.x(), axes.y(), axes.z());
    EXPECT_NEAR(surfaceArea(Superquadric::ellipsoid(axes.x(), axes.y(), axes.z())) / expected, 1.0, 1e-10) << axes.transpose();
  }
}

/// The unit superball's area by quadrature (above).
double superballArea(double n) {
  using boost::math::quadrature::gauss_kronrod;
  const double x1 = std::pow(2.0, -1.0 / n);
  return 48.0 * gauss_kronrod<double, 61>::integrate([&](double x) {
    const double y1 = std::min(x, std::pow(std::max(0.0, 1.0 - 2.0 * std::pow(x, n)), 1.0 / n));
    return gauss_kronrod<double, 61>::integrate([&](double y) {
      const double z = std::pow(1.0 - std::pow(x, n) - std::pow(y, n), 1.0 / n);
      const double zx = std::pow(x / z, n - 1.0), zy = std::pow(y / z, n - 1.0);
      return std::sqrt(1.0 + zx * zx + zy * zy);
    }, 0.0, y1, 8, 1e-12);
  }, 0.0, x1, 8, 1e-12);
}

TEST(SurfaceArea, TessellatedShapesConvergeToTheClosedForms) {
  const Superquadric near(5e-6, 3e-6, 2e-6, 2.0 + 1e-7, 2.0 + 1e-7);
  EXPECT_NEAR(surfaceArea(near) / surfaceArea(Superquadric::ellipsoid(5e-6, 3e-6, 2e-6)), 1.0, 2e-4);
  EXPECT_NEAR(superballArea(2.0) / (4.0 * pi), 1.0, 1e-9);  // the quadrature itself
  for (const double n : {3.0, 6.0, 10.0, 50.0}) {
    const double expected = superballArea(n), area = surfaceArea(Superquadric(1.0, 1.0, 1.0, n, n));
    std::printf("superball n = %g: area %.8f, quadrature %.8f, error %.2e\n", n, area, expected, area / expected - 1.0);
    EXPECT_NEAR(area / expected, 1.0, 1e-5) << "n = " << n;
  }
}

}  // namespace
}  // namespace sqdem

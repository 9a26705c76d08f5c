// The engine's contact law (world/contact_model.hpp) on single detected contacts: the tangential
// spring's stiffness along the contact ellipse's axes is Mindlin's 8 G* a_c / Phi(theta)
// (004 Eqs. 56-57), the circle gives 8 G* a, and the Coulomb limit caps the force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/contact/detector.hpp"
#include "sqdem/mechanics/mindlin_deresiewicz.hpp"
#include "sqdem/interaction/contact_model.hpp"

namespace sqdem {
namespace {

constexpr double E = 1e8, nu = 0.3, G = E / (2.0 * (1.0 + nu));

/// elliptic: tangential stiffness on the contact ellipse (else the area-equivalent circle).
ContactModel model(bool elliptic, double friction) {
  ContactModel m;
  m.eccentricity = EccentricityMethod::Exact;
  m.effectiveModulus = effectiveModulus(E, nu, E, nu);
  m.tangential = {.elliptic = elliptic, .effectiveShear = effectiveShearModulus(E, nu, E, nu), .poissonRatio = nu,
                  .friction = friction};
  return m;
}

/// The tip z = -c of a 3 x 1.5 x 1 mm ellipsoid turned by psi about z, pressed 2 um into the
/// wall z = 0: the relative curvatures are c/a^2 along the turned x axis and c/b^2 along y.
ContactGeometry ellipsoidTipOnWall(double psi) {
  const Superquadric s = Superquadric::ellipsoid(3e-3, 1.5e-3, 1e-3);
  const Pose pose{Vec3(0.0, 0.0, 1e-3 - 2e-6), Quat(Eigen::AngleAxisd(psi, Vec3::UnitZ()))};
  const ContactGeometry g = detectContact(s, pose, Plane{Vec3::Zero(), Vec3::UnitZ()});
  EXPECT_TRUE(g.touching());
  return g;
}

/// Force on B for a spring xi (m) at rest.
Vec3 tangentialForce(const ContactModel& m, const ContactGeometry& g, const Vec3& xi) {
  ContactHistory history{.spring = xi};
  const ContactForce f = contactForce(m, g, {.effectiveMass = 1e-6, .volumeRadiusA = 1.44e-3}, history, 1e-7);
  return f.onB - f.normal * g.normal;
}

TEST(ContactModel, EllipticSpringStiffnessIsMindlinAlongBothAxes) {
  const double psi = 0.7;
  const ContactGeometry g = ellipsoidTipOnWall(psi);
  const Vec3 major(std::cos(psi), std::sin(psi), 0.0), minor(-std::sin(psi), std::cos(psi), 0.0);
  EXPECT_NEAR(std::abs(contactMajorAxis(g.curvatureA, g.curvatureB, g.normal).dot(major)), 1.0, 1e-9);

  const ContactModel m = model(true, 1e3);
  const double Ri = 1.5e-3 * 1.5e-3 / 1e-3, Rj = 3e-3 * 3e-3 / 1e-3;  // b^2/c, a^2/c
  const HertzFactors h = hertzFactors(Ri / Rj, EccentricityMethod::Exact);
  const double Rc = Ri * Rj / (Ri + Rj);
  const double Fn = 4.0 / 3.0 * m.effectiveModulus * std::sqrt(Rc) * h.gamma * std::pow(2e-6, 1.5);  // 004 Eq. 1
  const double ac = contactSemiMajorAxis(std::numbers::pi * Rc * h.beta * 2e-6, h.e2);
  const double xi = 1e-8;
  for (const auto& [direction, theta] : {std::pair{major, 0.0}, std::pair{minor, std::numbers::pi / 2}}) {
    const MindlinDeresiewicz md(m.tangential.effectiveShear, ac, h.e2, nu, theta, m.tangential.friction, Fn);
    const Vec3 F = tangentialForce(m, g, xi * direction);
    EXPECT_NEAR(F.dot(direction) / (-xi), md.noSlipStiffness(), 1e-6 * md.noSlipStiffness()) << "theta " << theta;
    EXPECT_LT((F - F.dot(direction) * direction).norm(), 1e-9 * F.norm());  // the axes are principal
  }
  // Stiffer along the minor axis: Phi(0) / Phi(pi/2) = [(1 - nu) K + nu D] / [K - nu D] > 1 for
  // nu > 0, since 2 D(e) > K(e) for e > 0 (series: 2D = pi/2 (1 + 3e^2/8), K = pi/2 (1 + e^2/4)).
  EXPECT_LT(-tangentialForce(m, g, xi * major).dot(major), -tangentialForce(m, g, xi * minor).dot(minor));
}

TEST(ContactModel, CircularSpringIsEightGStarA) {
  const Superquadric s = Superquadric::sphere(1e-3);
  const ContactGeometry g = detectContact(s, Pose{Vec3(0.0, 0.0, 1e-3 - 2e-6), Quat::Identity()},
                                          Plane{Vec3::Zero(), Vec3::UnitZ()});
  const double a = std::sqrt(1e-3 * 2e-6);  // Hertz sphere on a flat: a^2 = R delta
  for (const bool elliptic : {true, false}) {
    const ContactModel m = model(elliptic, 1e3);
    const Vec3 F = tangentialForce(m, g, Vec3(1e-8, 0.0, 0.0));
    EXPECT_NEAR(-F.x() / 1e-8, 8.0 * m.tangential.effectiveShear * a, 1e-6 * 8.0 * m.tangential.effectiveShear * a);
  }
}

TEST(ContactModel, CoulombLimitCapsTheSpring) {
  const ContactGeometry g = ellipsoidTipOnWall(0.3);
  const ContactModel m = model(true, 0.4);
  ContactHistory history{.spring = Vec3(1e-5, 2e-5, 0.0)};  // far beyond sliding
  const ContactForce f = contactForce(m, g, {.effectiveMass = 1e-6, .volumeRadiusA = 1.44e-3}, history, 1e-7);
  const Vec3 Ft = f.onB - f.normal * g.normal;
  EXPECT_NEAR(Ft.norm(), 0.4 * f.normal, 1e-12 * f.normal);
  // The spring was shrunk to what carries the limit force: re-applying it gives the same force.
  EXPECT_LT((tangentialForce(m, g, history.spring) - Ft).norm(), 1e-9 * Ft.norm());
}

}  // namespace
}  // namespace sqdem

#include "sqdem/validation/becker_cases.hpp"

#include <cmath>
#include <stdexcept>

#include "sqdem/contact/detector.hpp"

namespace sqdem {

Superquadric ellipsoidWithMeanRadius(const std::array<double, 3>& ratios, double meanRadius) {
  const double scale = meanRadius / std::cbrt(ratios[0] * ratios[1] * ratios[2]);
  return Superquadric::ellipsoid(scale * ratios[0], scale * ratios[1], scale * ratios[2]);
}

BeckerCaseGeometry beckerCaseGeometry(const BeckerValidationCase& c) {
  const Superquadric I = ellipsoidWithMeanRadius(c.ratiosI, c.meanRadius);
  const Superquadric J = ellipsoidWithMeanRadius(c.ratiosJ, c.meanRadius);
  Pose poseJ;
  poseJ.position = Vec3(I.a() + J.a() - 1e-9 * c.meanRadius, 0.0, 0.0);
  const ContactGeometry contact = detectContact(I, Pose{}, J, poseJ);
  if (!contact.converged()) throw std::runtime_error("Becker case: detector did not converge");
  BeckerCaseGeometry g;
  g.radii = relativeRadii(contact.curvatureA, contact.curvatureB, 1e6 * c.meanRadius);
  g.factors = beckerFactors(g.radii);
  g.meanRadiusSum = 2.0 * c.meanRadius;
  return g;
}

BeckerKamlahParameters nmcBeckerKamlahParameters(const BeckerCaseGeometry& g, bool transition) {
  BeckerKamlahParameters p;
  p.effectiveModulus = effectiveModulus(nmcYoungsModulus, nmcPoissonRatio, nmcYoungsModulus, nmcPoissonRatio);
  p.yieldStrength = nmcYieldStrength;
  const BeckerKamlahFits fits = nmcBeckerKamlahFits(g.factors.Re, g.meanRadiusSum);
  p.lambdaMax = fits.lambdaMax;
  p.epsilonMax = fits.epsilonMax;
  p.transition = transition;
  return p;
}

}  // namespace sqdem

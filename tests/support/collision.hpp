#pragma once
// A one-dimensional head-on collision driven by a normal force law F(overlap, rate), integrated
// with classical RK4: returns the coefficient of restitution |v_out| / v_in, measured when the
// overlap returns to zero (the usual definition for spring-dashpot laws).
#include <cmath>
#include <functional>

namespace sqdem::testing {

inline double restitutionOf(const std::function<double(double, double)>& force, double mass,
                            double impactVelocity, double timeStep) {
  double x = 0.0, v = impactVelocity;  // overlap and its rate
  const auto acc = [&](double xx, double vv) { return -force(xx, vv) / mass; };
  for (long step = 0; step < 100000000; ++step) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * timeStep * k1v, k2v = acc(x + 0.5 * timeStep * k1x, k2x);
    const double k3x = v + 0.5 * timeStep * k2v, k3v = acc(x + 0.5 * timeStep * k2x, k3x);
    const double k4x = v + timeStep * k3v, k4v = acc(x + timeStep * k3x, k4x);
    const double xNext = x + timeStep / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vNext = v + timeStep / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xNext <= 0.0 && step > 0) {  // linear interpolation of v at the crossing
      const double s = x / (x - xNext);
      return -(v + s * (vNext - v)) / impactVelocity;
    }
    x = xNext;
    v = vNext;
  }
  return NAN;
}

}  // namespace sqdem::testing

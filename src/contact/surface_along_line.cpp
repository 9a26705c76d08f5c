#include "sqdem/contact/surface_along_line.hpp"

#include <cmath>
#include <limits>

namespace sqdem {

double surfaceFarthestAlong(const Superquadric& shape, const Pose& pose, const Vec3& q, const Vec3& d) {
  // In the body's frame the line is x(t) = local + t direction; at t = t0 it is beyond the
  // bounding sphere, and Newton walks t down from there.
  const Vec3 local = pose.toBody(q), direction = pose.orientation.conjugate() * d;
  const double t0 = 2.0 * shape.boundingRadius() - local.dot(direction);
  double t = t0;
  for (int k = 0; k < 200; ++k) {
    const GaugeDerivatives g = shape.derivatives(local + t * direction);
    if (g.value <= 1.0) break;
    const double slope = g.gradient.dot(direction);  // dg/dt > 0 on the way in from beyond
    if (slope <= 0.0) return -std::numeric_limits<double>::infinity();
    const double step = (g.value - 1.0) / slope;
    t -= step;
    // Quadratic convergence: the next step would be below ~1e-16 R^2 / (the line's curvature radius).
    if (step <= 1e-8 * shape.boundingRadius()) break;
  }
  return t;
}

}  // namespace sqdem

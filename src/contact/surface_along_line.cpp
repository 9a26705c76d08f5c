#include "sqdem/contact/surface_along_line.hpp"

#include <cmath>
#include <limits>

namespace sqdem {

double surfaceFarthestAlong(const Superquadric& shape, const Pose& pose, const Vec3& q, const Vec3& d, double start) {
  // In the body's frame the line is x(t) = local + t direction; at t = t0 it leaves the bounding
  // sphere, and Newton walks t down from there or from the given start.
  const Vec3 local = pose.toBody(q), direction = pose.orientation.conjugate() * d;
  const double along = local.dot(direction), radius = shape.boundingRadius();
  const double chord = along * along - (local.squaredNorm() - radius * radius);  // (half the chord)^2
  if (!(chord > 0.0)) return -std::numeric_limits<double>::infinity();          // the line misses the sphere
  const double t0 = std::sqrt(chord) - along;
  bool started = std::isfinite(start) && start < t0;  // from the given start, while its first point is checked
  double t = started ? start : t0;
  for (int k = 0; k < 200; ++k) {
    const GaugeDerivatives g = shape.insideOutside(local + t * direction);
    const double slope = g.gradient.dot(direction);  // dg/dt > 0 on the way in from beyond
    if (started && !(g.value > 1.0 && slope > 0.0)) {  // the start is not beyond the far side
      started = false, t = t0;
      continue;
    }
    started = false;
    if (g.value <= 1.0) break;
    if (slope <= 0.0) return -std::numeric_limits<double>::infinity();
    const double step = (g.value - 1.0) / slope;
    t -= step;
    // Quadratic convergence: the next step would be below ~1e-16 R^2 / (the line's curvature radius).
    if (step <= 1e-8 * radius) break;
  }
  return t;
}

}  // namespace sqdem

#include "sqdem/contact/surface_along_line.hpp"

#include <cmath>
#include <limits>

namespace sqdem {

double surfaceFarthestAlong(const Superquadric& shape, const Pose& pose, const Vec3& q, const Vec3& d, double start) {
  constexpr double miss = -std::numeric_limits<double>::infinity();
  // In the body's frame the line is x(t) = local + t direction; it crosses the sphere around the
  // body's box (a bound for every n) between t = -chord - along and t0 = chord - along, and
  // Newton walks t down from t0 or from the given start.
  const Vec3 local = pose.toBody(q), direction = pose.orientation.conjugate() * d;
  const double along = local.dot(direction), radius = shape.halfExtents().norm();
  const double squaredChord = along * along - (local.squaredNorm() - radius * radius);
  if (!(squaredChord > 0.0)) return miss;  // the line misses the sphere
  const double chord = std::sqrt(squaredChord), t0 = chord - along, nearSide = -chord - along;
  const double n1 = shape.n1();
  bool started = std::isfinite(start) && start < t0;  // from the given start, while its first point is checked
  double t = started ? start : t0;
  for (int k = 0; k < 200; ++k) {
    const GaugeDerivatives F = shape.insideOutside(local + t * direction);
    const double slope = F.gradient.dot(direction);  // dF/dt > 0 on the way in from beyond
    if (started && !(F.value > 1.0 && slope > 0.0)) {  // the start is not beyond the far side
      started = false, t = t0;
      continue;
    }
    started = false;
    if (F.value <= 1.0) break;
    if (!(slope > 0.0)) return miss;
    // Newton on F near the surface; far from it (F > 2) Newton on g = F^(1/n1), whose step
    // (g - 1) / g' = n1 F (g - 1) / (g F') takes a few steps where F's would take ~n1 ln g.
    const double g = F.value > 2.0 ? std::pow(F.value, 1.0 / n1) : 0.0;
    const double step = F.value > 2.0 ? n1 * F.value * (g - 1.0) / (g * slope) : (F.value - 1.0) / slope;
    t -= step;
    if (t < nearSide) return miss;  // past the sphere's near side: the line misses the body
    // Quadratic convergence: the next step would be below ~n1 1e-16 R^2 / (the line's curvature radius).
    if (step <= 1e-8 * radius) break;
  }
  return t;
}

}  // namespace sqdem

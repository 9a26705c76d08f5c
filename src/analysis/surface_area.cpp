#include "sqdem/analysis/surface_area.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "sqdem/geometry/superquadric_tessellation.hpp"

namespace sqdem {
namespace {

double ellipsoidArea(Vec3 axes) {
  std::sort(axes.data(), axes.data() + 3, std::greater<>());
  const double a = axes[0], b = axes[1], c = axes[2];
  if (a - c <= 1e-12 * a) return 4.0 * std::numbers::pi * a * a;
  const double phi = std::acos(c / a), s = std::sin(phi), cosine = c / a;
  const double k = std::min(1.0, std::sqrt(a * a * (b * b - c * c) / (b * b * (a * a - c * c))));  // 1 at a = b, by round-off above
  return 2.0 * std::numbers::pi * c * c +
         2.0 * std::numbers::pi * a * b / s * (boost::math::ellint_2(k, phi) * s * s + boost::math::ellint_1(k, phi) * cosine * cosine);
}

/// The tessellation's area at `resolution` (each quad's vector area, half its diagonals' cross product).
double tessellatedArea(const Superquadric& shape, int resolution) {
  const Tessellation t = tessellate(shape, resolution);
  double area = 0.0;
  for (const auto& q : t.quads) area += 0.5 * (t.points[q[2]] - t.points[q[0]]).cross(t.points[q[3]] - t.points[q[1]]).norm();
  return area;
}

}  // namespace

double surfaceArea(const Superquadric& shape) {
  if (shape.n1() == 2.0 && shape.n2() == 2.0) return ellipsoidArea(shape.halfExtents());
  constexpr int resolution = 24;
  return (4.0 * tessellatedArea(shape, 2 * resolution) - tessellatedArea(shape, resolution)) / 3.0;
}

}  // namespace sqdem

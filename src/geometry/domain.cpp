#include "sqdem/geometry/domain.hpp"

#include <cmath>

namespace sqdem {

Vec3 Domain::wrap(Vec3 x) const {
  for (int d = 0; d < 3; ++d) {
    if (!periodic[d]) continue;
    const double L = hi(d) - lo(d);
    x(d) -= L * std::floor((x(d) - lo(d)) / L);
    if (x(d) >= hi(d)) x(d) -= L;  // round-off at the upper bound
  }
  return x;
}

Vec3 Domain::minimumImage(Vec3 d) const {
  for (int k = 0; k < 3; ++k) {
    if (periodic[k]) d(k) -= length()(k) * std::round(d(k) / length()(k));
  }
  return d;
}

int Domain::outsideAlong(const Vec3& x) const {
  for (int d = 0; d < 3; ++d) {
    if (!periodic[d] && (x(d) < lo(d) || x(d) > hi(d))) return d;
  }
  return -1;
}

}  // namespace sqdem

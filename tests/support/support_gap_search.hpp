#pragma once
// A brute-force upper bound of two bodies' least penetration, for the detector sweeps: the
// support gap s(n) = h_A(n) + h_B(-n) (detector.hpp) at the directions of a Fibonacci sphere,
// the best few refined by a shrinking pattern search on the sphere. Every s(n) is an overlap the
// pair has along n, so the minimum found bounds the least penetration from above; it shares no
// code with the detector's solve but the bodies' support maps.

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::testing {

/// h_A(n) + h_B(-n) for a unit world direction n: the overlap the pair has along n (m).
inline double supportGap(const Superquadric& A, const Pose& pa, const Superquadric& B, const Pose& pb, const Vec3& n) {
  const Vec3 pA = pa.toWorld(A.supportPoint(pa.orientation.conjugate() * n));
  const Vec3 pB = pb.toWorld(B.supportPoint(pb.orientation.conjugate() * -n));
  return n.dot(pA - pB);
}

inline double searchedLeastOverlap(const Superquadric& A, const Pose& pa, const Superquadric& B, const Pose& pb,
                                   int directions = 2000, int refined = 8) {
  const auto s = [&](const Vec3& n) { return supportGap(A, pa, B, pb, n); };
  std::vector<std::pair<double, Vec3>> samples;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < directions; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / directions, r = std::sqrt(1.0 - z * z);
    const Vec3 n(r * std::cos(golden * k), r * std::sin(golden * k), z);
    samples.emplace_back(s(n), n);
  }
  std::partial_sort(samples.begin(), samples.begin() + refined, samples.end(),
                    [](const auto& x, const auto& y) { return x.first < y.first; });
  double best = samples.front().first;
  for (int k = 0; k < refined; ++k) {
    auto [value, n] = samples[k];
    // Compass search: a step is taken only for a gain above round-off (on a flat face s barely
    // changes), and at most 4000 evaluations.
    int evaluations = 0;
    for (double step = 0.05; step > 1e-10 && evaluations < 4000;) {
      const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
      bool moved = false;
      for (const Vec3& t : {t1, Vec3(-t1), t2, Vec3(-t2)}) {
        const Vec3 m = (n + step * t).normalized();
        const double v = s(m);
        ++evaluations;
        if (v < value - 1e-14 * std::abs(value)) {
          value = v;
          n = m;
          moved = true;
        }
      }
      if (!moved) step *= 0.5;
    }
    best = std::min(best, value);
  }
  return best;
}

}  // namespace sqdem::testing

#pragma once
// A wall's prescribed position as a function of time: its offset along its own normal (m) from
// where it stood at the start of the stage, piecewise linear through (time, offset) points with
// times from the stage start (s). The path starts at (0, 0) and holds its last offset.

#include <algorithm>
#include <array>
#include <vector>

namespace sqdem {

struct WallPath {
  std::vector<std::array<double, 2>> points;  ///< (t (s), offset (m)), t increasing, t > 0

  double offset(double t) const {
    double t0 = 0.0, x0 = 0.0;
    for (const auto& [t1, x1] : points) {
      if (t <= t1) return x0 + (x1 - x0) * (std::max(t, t0) - t0) / (t1 - t0);
      t0 = t1;
      x0 = x1;
    }
    return x0;
  }
};

}  // namespace sqdem

#pragma once
// Oriented bounding box and the separating-axis overlap test (Gottschalk et al. 1996, 15 axes).

#include "sqdem/math/types.hpp"

namespace sqdem {

struct OrientedBox {
  Vec3 centre;       ///< world position (m)
  Mat3 axes;         ///< columns: the box axes (body -> world rotation)
  Vec3 halfExtents;  ///< half lengths along the axes (m)
};

/// True when the boxes, each grown by `margin` (m) on every side, overlap or touch.
bool boxesOverlap(const OrientedBox& A, const OrientedBox& B, double margin = 0.0);

}  // namespace sqdem

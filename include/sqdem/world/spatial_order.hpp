#pragma once
// Spatial re-ordering for memory locality (docs/architecture.md, "Identity"): the order of points along a Hilbert
// curve (CGAL's hilbert_sort with the deterministic median policy). CGAL stays in its own CMake
// target (spatial_order.cpp): its -frounding-math must not reach the physics code.

#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem {

/// Permutation p such that points[p[0]], points[p[1]], ... follow a Hilbert curve.
std::vector<std::uint32_t> hilbertOrder(const std::vector<Vec3>& points);

}  // namespace sqdem

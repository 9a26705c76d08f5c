#pragma once
// The walls as surfaces for the ParaView output (vtk_writer.hpp): each plane clipped to the
// domain box (a convex polygon, the plane's cross-section of the box), each cylinder a tube of
// `segments` quads spanning the box's extent along its axis (a finite one's barrel within it;
// its rounded ends are not drawn), each mesh its triangles. The engine's planes and cylinders are
// infinite; these are what of them lies in the box.

#include <cstdint>
#include <vector>

#include "sqdem/dynamics/wall.hpp"
#include "sqdem/geometry/mesh_features.hpp"
#include "sqdem/geometry/domain.hpp"

namespace sqdem {

struct WallSurfaces {
  std::vector<Vec3> points;                            ///< (m)
  std::vector<std::vector<std::uint32_t>> polygons;    ///< point indices, counter-clockwise seen from the particles' side
  std::vector<std::uint32_t> wall;                     ///< the wall of each polygon
};

/// meshes: the World's, for mesh walls (drawn whole, where the wall has moved them).
WallSurfaces wallSurfaces(const std::vector<Wall>& walls, const std::vector<MeshFeatures>& meshes, const Domain& box,
                          int segments = 48);

}  // namespace sqdem

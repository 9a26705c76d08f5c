#pragma once
// STL files (ASCII or binary) as triangle meshes, read and repaired with CGAL (its own library
// target: CGAL's headers and its -frounding-math stay out of the engine, docs/architecture.md, "Layers"):
//   read        CGAL::IO::read_STL (ASCII or binary, told apart by the content)
//   repair      zero-area triangles dropped (collinear corners, an exact predicate), then
//               Polygon_mesh_processing::repair_polygon_soup: duplicate vertices merged (STL
//               repeats every vertex per triangle), duplicate triangles and unused vertices removed
//   orient      orient_polygon_soup: one orientation across each connected sheet (an STL
//               exporter's flipped triangles); a closed mesh is then turned to face outwards
//               (orient_to_bound_a_volume), its normals pointing away from the body
// Units: as in the file, times `scale` (STL has none; a scene states it).

#include <cstddef>
#include <filesystem>
#include <stdexcept>

#include "sqdem/geometry/triangle_mesh.hpp"

namespace sqdem {

struct MeshRepairs {
  std::size_t verticesRead = 0, trianglesRead = 0;  ///< as the file lists them (3 per triangle)
  std::size_t verticesMerged = 0;     ///< duplicates and unused vertices removed
  std::size_t trianglesRemoved = 0;   ///< degenerate or duplicate
  bool reoriented = false;            ///< some triangles were flipped to agree with their neighbours
  bool closed = false;                ///< the mesh bounds a volume (then its normals point outwards)
};

struct StlMesh {
  TriangleMesh mesh;
  MeshRepairs repairs;
};

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads and repairs the STL file at `path`, coordinates times `scale`; throws MeshError naming
/// the file when it cannot be read or holds no triangle.
StlMesh readStlMesh(const std::filesystem::path& path, double scale = 1.0);

}  // namespace sqdem

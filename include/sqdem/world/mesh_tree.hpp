#pragma once
// Candidate triangles of a mesh wall: CGAL's AABB tree of the mesh's triangles in its body frame
// (own CMake target, mesh_tree.cpp: CGAL's headers stay out of the engine). A mesh wall is not
// in the particle cell list (its extent would collapse the cells); each particle asks the tree
// for the triangles within its reach at every candidate rebuild.

#include <cstdint>
#include <memory>
#include <vector>

#include "sqdem/geometry/triangle_mesh.hpp"

namespace sqdem {

class MeshTree {
 public:
  explicit MeshTree(const TriangleMesh& mesh);

  /// The triangles closer than `radius` to `centre` (body frame, m), ascending.
  std::vector<std::uint32_t> trianglesNear(const Vec3& centre, double radius) const;

 private:
  struct Tree;
  std::shared_ptr<const Tree> tree_;  ///< built once, never changed: copies share it
};

}  // namespace sqdem

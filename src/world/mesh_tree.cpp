#include "sqdem/world/mesh_tree.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <iterator>

namespace sqdem {
namespace {

// Inexact double arithmetic: the tree only preselects; the contact detector decides.
using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

struct MeshTree::Tree {
  Triangles triangles;
  sqdem::Tree tree;
};

MeshTree::MeshTree(const TriangleMesh& mesh) {
  auto built = std::make_shared<Tree>();  // the tree refers into its triangles: never moved
  for (const auto& [i, j, k] : mesh.triangles) {
    built->triangles.emplace_back(point(mesh.vertices[i]), point(mesh.vertices[j]), point(mesh.vertices[k]));
  }
  built->tree.insert(built->triangles.cbegin(), built->triangles.cend());
  built->tree.build();
  tree_ = std::move(built);
}

std::vector<std::uint32_t> MeshTree::trianglesNear(const Vec3& centre, double radius) const {
  const CGAL::Bbox_3 box(centre.x() - radius, centre.y() - radius, centre.z() - radius, centre.x() + radius,
                         centre.y() + radius, centre.z() + radius);
  std::vector<Primitive::Id> hits;
  tree_->tree.all_intersected_primitives(box, std::back_inserter(hits));
  std::vector<std::uint32_t> near;
  const Kernel::Point_3 c = point(centre);
  for (const Primitive::Id& t : hits) {
    if (CGAL::squared_distance(c, *t) < radius * radius) near.push_back(static_cast<std::uint32_t>(t - tree_->triangles.cbegin()));
  }
  std::sort(near.begin(), near.end());
  return near;
}

}  // namespace sqdem

#include "sqdem/geometry/triangle_mesh.hpp"

#include <map>
#include <utility>

namespace sqdem {

Vec3 TriangleMesh::normal(std::size_t t) const {
  const auto& [i, j, k] = triangles[t];
  return (vertices[j] - vertices[i]).cross(vertices[k] - vertices[i]).normalized();
}

double TriangleMesh::area() const {
  double a = 0.0;
  for (const auto& [i, j, k] : triangles) a += 0.5 * (vertices[j] - vertices[i]).cross(vertices[k] - vertices[i]).norm();
  return a;
}

double TriangleMesh::volume() const {
  double v = 0.0;
  for (const auto& [i, j, k] : triangles) v += vertices[i].dot(vertices[j].cross(vertices[k])) / 6.0;
  return v;
}

bool TriangleMesh::closed() const {
  // Each directed edge once, and its reverse once: a consistently oriented two-manifold.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles) {
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

}  // namespace sqdem

#include "sqdem/io/wall_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sqdem {
namespace {

/// A unit vector normal to n.
Vec3 normalTo(const Vec3& n) {
  const Vec3 other = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(other).normalized();
}

/// The box's corner k (bits: x, y, z high).
Vec3 corner(const Domain& box, int k) {
  return Vec3(k & 1 ? box.hi.x() : box.lo.x(), k & 2 ? box.hi.y() : box.lo.y(), k & 4 ? box.hi.z() : box.lo.z());
}

/// The plane's cross-section of the box: where it crosses the box's 12 edges, ordered around
/// their centroid counter-clockwise about the normal (nothing when it misses the box).
void addPlane(WallSurfaces& s, const Plane& plane, std::uint32_t w, const Domain& box) {
  const double tolerance = 1e-12 * box.length().norm();
  std::vector<Vec3> crossings;
  for (int k = 0; k < 8; ++k) {
    for (int d = 0; d < 3; ++d) {
      if (k & (1 << d)) continue;  // each edge once, from its low end
      const Vec3 a = corner(box, k), b = corner(box, k | (1 << d));
      const double da = plane.normal.dot(a - plane.point), db = plane.normal.dot(b - plane.point);
      if ((da > 0.0) == (db > 0.0) && std::abs(da) > tolerance && std::abs(db) > tolerance) continue;
      if (std::abs(da - db) <= tolerance) continue;  // the edge lies in the plane: its ends come from other edges
      const Vec3 x = a + (b - a) * (da / (da - db));
      if (std::ranges::none_of(crossings, [&](const Vec3& c) { return (c - x).norm() <= tolerance; })) crossings.push_back(x);
    }
  }
  if (crossings.size() < 3) return;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : crossings) centre += x / static_cast<double>(crossings.size());
  const Vec3 u = normalTo(plane.normal), v = plane.normal.cross(u);
  std::ranges::sort(crossings, {}, [&](const Vec3& x) { return std::atan2((x - centre).dot(v), (x - centre).dot(u)); });
  std::vector<std::uint32_t> polygon;
  for (const Vec3& x : crossings) {
    polygon.push_back(static_cast<std::uint32_t>(s.points.size()));
    s.points.push_back(x);
  }
  s.polygons.push_back(std::move(polygon));
  s.wall.push_back(w);
}

/// A tube of `segments` quads over the box's extent along the axis; a flat end within it, a disc.
void addCylinder(WallSurfaces& s, const Cylinder& c, std::uint32_t w, const Domain& box, int segments) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const double t = c.axis.dot(corner(box, k) - c.point);
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  lo = std::max(lo, -c.halfLength), hi = std::min(hi, c.halfLength);  // a finite barrel (rounded ends are not drawn)
  const Vec3 u = normalTo(c.axis), v = c.axis.cross(u);
  const auto first = static_cast<std::uint32_t>(s.points.size());
  for (int k = 0; k < segments; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / segments;
    const Vec3 radial = c.radius * (std::cos(angle) * u + std::sin(angle) * v);
    s.points.push_back(c.point + lo * c.axis + radial);
    s.points.push_back(c.point + hi * c.axis + radial);
  }
  for (int k = 0; k < segments; ++k) {  // outward normals: counter-clockwise seen from outside
    const std::uint32_t a = first + 2 * k, b = first + 2 * ((k + 1) % segments);
    s.polygons.push_back({a, b, b + 1, a + 1});
    s.wall.push_back(w);
  }
  if (!c.flatEnds) return;
  std::vector<std::uint32_t> low, high;  // counter-clockwise seen from outside: against the axis at lo
  for (int k = 0; k < segments; ++k) {
    low.push_back(first + 2 * (segments - 1 - k));
    high.push_back(first + 2 * k + 1);
  }
  for (auto [end, disc] : {std::pair{lo, std::move(low)}, std::pair{hi, std::move(high)}}) {
    if (std::abs(end) != c.halfLength) continue;  // the box cuts the barrel before its end
    s.polygons.push_back(std::move(disc));
    s.wall.push_back(w);
  }
}


/// The mesh's triangles where the wall has moved it.
void addMesh(WallSurfaces& s, const TriangleMesh& mesh, const Pose& pose, std::uint32_t w) {
  const auto first = static_cast<std::uint32_t>(s.points.size());
  for (const Vec3& v : mesh.vertices) s.points.push_back(pose.toWorld(v));
  for (const auto& [i, j, k] : mesh.triangles) {
    s.polygons.push_back({first + i, first + j, first + k});
    s.wall.push_back(w);
  }
}

}  // namespace

WallSurfaces wallSurfaces(const std::vector<Wall>& walls, const std::vector<MeshFeatures>& meshes, const Domain& box,
                          int segments) {
  WallSurfaces s;
  for (std::uint32_t w = 0; w < walls.size(); ++w) {
    std::visit(PerShape{[&](const PlaneWall& p) { addPlane(s, p.plane, w, box); },
                        [&](const CylinderWall& c) { addCylinder(s, c.cylinder, w, box, segments); },
                        [&](const MeshWall& m) { addMesh(s, meshes[m.mesh].mesh(), m.pose(), w); }},
               walls[w].surface);
  }
  return s;
}

}  // namespace sqdem

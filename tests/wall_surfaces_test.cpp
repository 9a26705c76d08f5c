// Walls as output surfaces (io/wall_surfaces.hpp) against closed forms: a plane's cross-section
// of the box (area and orientation), a cylinder's tube (radius, length along the axis, outward
// quads).

#include <gtest/gtest.h>

#include <cmath>

#include "sqdem/io/wall_surfaces.hpp"

namespace sqdem {
namespace {

Domain unitBox() {
  Domain d;
  d.lo = Vec3::Zero();
  d.hi = Vec3(1.0, 2.0, 3.0);
  return d;
}

/// The polygon's area vector, 1/2 sum x_k x x_{k+1}: its length the area, its direction the
/// normal of a counter-clockwise traversal.
Vec3 areaVector(const WallSurfaces& s, std::size_t k) {
  const auto& polygon = s.polygons[k];
  Vec3 a = Vec3::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) a += 0.5 * s.points[polygon[i]].cross(s.points[polygon[(i + 1) % polygon.size()]]);
  return a;
}

// In the box [0, 1] x [0, 2] x [0, 3]: a floor (z = 0, on the box's face) and a plate (z = 1.5)
// are its 1 x 2 cross-section, facing their normals; the inclined plane x + z = 2 crosses the
// x-z side in the segment from (0, 2) to (1, 1), of length sqrt 2: a sqrt 2 x 2 rectangle.
TEST(WallSurfaces, PlanesAreTheirCrossSectionsOfTheBox) {
  std::vector<Wall> walls(3);
  walls[0].surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}};
  walls[1].surface = PlaneWall{Plane{Vec3(0.0, 0.0, 1.5), -Vec3::UnitZ()}};
  walls[2].surface = PlaneWall{Plane{Vec3(0.5, 1.0, 1.5), Vec3(1.0, 0.0, 1.0).normalized()}};
  const WallSurfaces s = wallSurfaces(walls, {}, unitBox());
  ASSERT_EQ(s.polygons.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(s.wall[k], k);
    const Vec3 a = areaVector(s, k);
    EXPECT_NEAR(a.norm(), k < 2 ? 2.0 : 2.0 * std::sqrt(2.0), 1e-12) << "wall " << k;
    EXPECT_NEAR(a.normalized().dot(walls[k].get<PlaneWall>().plane.normal), 1.0, 1e-12) << "wall " << k;
    for (const std::uint32_t i : s.polygons[k]) EXPECT_NEAR(walls[k].get<PlaneWall>().plane.normal.dot(s.points[i] - walls[k].get<PlaneWall>().plane.point), 0.0, 1e-12);
  }
  EXPECT_EQ(s.polygons[0].size(), 4u);
  EXPECT_EQ(s.polygons[2].size(), 4u);
}

// A roller along y through (0.5, *, 2) of radius 0.25: 48 quads at that radius spanning y in
// [0, 2], each facing away from the axis; the tube's lateral area approaches 2 pi R L.
TEST(WallSurfaces, CylinderIsATubeAcrossTheBox) {
  std::vector<Wall> walls(1);
  walls[0].surface = CylinderWall{Cylinder{Vec3(0.5, 0.7, 2.0), Vec3::UnitY(), 0.25}};
  const WallSurfaces s = wallSurfaces(walls, {}, unitBox(), 48);
  ASSERT_EQ(s.polygons.size(), 48u);
  double area = 0.0, lo = 1e9, hi = -1e9;
  for (const Vec3& x : s.points) {
    EXPECT_NEAR(walls[0].get<CylinderWall>().cylinder.distance(x), 0.0, 1e-12);
    lo = std::min(lo, x.y()), hi = std::max(hi, x.y());
  }
  for (std::size_t k = 0; k < s.polygons.size(); ++k) {
    const Vec3 a = areaVector(s, k);
    area += a.norm();
    Vec3 centre = Vec3::Zero();
    for (const std::uint32_t i : s.polygons[k]) centre += s.points[i] / 4.0;
    EXPECT_GT(a.dot(walls[0].get<CylinderWall>().cylinder.outwardNormal(centre)), 0.0) << "quad " << k;
  }
  EXPECT_NEAR(lo, 0.0, 1e-12);
  EXPECT_NEAR(hi, 2.0, 1e-12);
  const double exact = 2.0 * std::numbers::pi * 0.25 * 2.0, chords = exact * std::sin(std::numbers::pi / 48) / (std::numbers::pi / 48);
  EXPECT_NEAR(area, chords, 1e-12);
}

// A finite flat-ended roller inside the box (y in [0.5, 1.5]): the tube over its barrel and
// its two end discs, each a 48-gon facing out along the axis with the polygon's area.
TEST(WallSurfaces, FlatEndsAreDiscs) {
  std::vector<Wall> walls(1);
  Cylinder roller{Vec3(0.5, 1.0, 2.0), Vec3::UnitY(), 0.25};
  roller.halfLength = 0.5;
  roller.flatEnds = true;
  walls[0].surface = CylinderWall{roller};
  const WallSurfaces s = wallSurfaces(walls, {}, unitBox(), 48);
  ASSERT_EQ(s.polygons.size(), 50u);
  const double polygon = 0.5 * 48 * 0.25 * 0.25 * std::sin(2.0 * std::numbers::pi / 48);
  const Vec3 low = areaVector(s, 48), high = areaVector(s, 49);
  EXPECT_NEAR((low + polygon * Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((high - polygon * Vec3::UnitY()).norm(), 0.0, 1e-12);
  for (std::uint32_t i : s.polygons[48]) EXPECT_NEAR(s.points[i].y(), 0.5, 1e-15);
  for (std::uint32_t i : s.polygons[49]) EXPECT_NEAR(s.points[i].y(), 1.5, 1e-15);
}

}  // namespace
}  // namespace sqdem

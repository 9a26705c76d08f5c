// Contacts with triangle meshes (geometry/mesh_features.hpp, contact/mesh_detector.cpp,
// contact/point_detector.cpp). Closed forms: a sphere's overlap with a convex polyhedron is its
// radius minus the distance from its centre to the polyhedron (the common normal runs from the
// centre to the nearest point); the face, edge and vertex regions share that touch out so that
// exactly one feature reports it. A flat mesh is its plane (the analytic plane's answer, bit for
// bit). The point contact of an ellipsoid satisfies the common-normal conditions and is the
// nearest point found by sampling its surface.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sqdem/contact/detector.hpp"
#include "sqdem/geometry/mesh_features.hpp"

namespace sqdem {
namespace {

/// The unit cube [0, 1]^3, 8 vertices and 12 outward triangles.
TriangleMesh cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

/// A flat hexagon in z = 0 as a fan of six triangles about its centre (vertex 0), facing +z.
TriangleMesh hexagonFan() {
  TriangleMesh m;
  m.vertices.emplace_back(0.0, 0.0, 0.0);
  for (int k = 0; k < 6; ++k) m.vertices.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.0);
  for (std::uint32_t k = 0; k < 6; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  return m;
}

/// Distance from x to the unit cube (0 inside).
double distanceToCube(const Vec3& x) { return (x - x.cwiseMax(0.0).cwiseMin(1.0)).norm(); }

TEST(MeshFeatures, CubeHasTwelveSharpEdgesSixFlatDiagonalsAndEightCorners) {
  const MeshFeatures f(cube());
  ASSERT_EQ(f.edgeCount(), 18u);
  int sharp = 0, flat = 0;
  for (std::uint32_t e = 0; e < f.edgeCount(); ++e) {
    sharp += f.edge(e).feature;
    flat += f.edge(e).flat;
    EXPECT_NE(f.edge(e).face[1], MeshFeatures::noFace);
  }
  EXPECT_EQ(sharp, 12);
  EXPECT_EQ(flat, 6);
  for (std::uint32_t v = 0; v < 8; ++v) EXPECT_TRUE(f.vertexIsFeature(v));
  EXPECT_EQ(f.featureCount(), 12u + 18u + 8u);
  EXPECT_EQ(f.kind(11), FeatureKind::Face);
  EXPECT_EQ(f.kind(12), FeatureKind::Edge);
  EXPECT_EQ(f.kind(30), FeatureKind::Vertex);
  EXPECT_EQ(f.index(30), 0u);
}

TEST(MeshFeatures, ConcaveEdgesAreNoFeatures) {
  // Two squares folded into a valley (a V open upwards): the fold is concave.
  TriangleMesh m;
  m.vertices = {{-1, 0, 1}, {-1, 1, 1}, {0, 0, 0}, {0, 1, 0}, {1, 0, 1}, {1, 1, 1}};
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {2, 4, 5}, {2, 5, 3}};
  const MeshFeatures f(m);
  for (std::uint32_t e = 0; e < f.edgeCount(); ++e) {
    const auto& edge = f.edge(e);
    if (edge.vertex[0] == 2 && edge.vertex[1] == 3) EXPECT_FALSE(edge.feature);
  }
}

TEST(MeshFeatures, CoplanarFacesShareTheirEdgesAndVerticesWithoutOverlap) {
  const MeshFeatures f(hexagonFan());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> radius(0.0, 0.85), angle(-M_PI, M_PI);  // inside the hexagon
  std::vector<Vec3> points{Vec3::Zero()};  // the fan's centre
  for (int k = 0; k < 6; ++k) points.push_back(0.5 * f.mesh().vertices[1 + k]);  // on the spokes
  for (int k = 0; k < 200; ++k) {
    const double r = radius(random), phi = angle(random);
    points.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.0);
  }
  for (const Vec3& x : points) {
    int owners = 0;
    for (std::uint32_t t = 0; t < 6; ++t) owners += f.faceContains(t, x);
    EXPECT_EQ(owners, 1) << x.transpose();
  }
}

TEST(MeshDetector, FlatMeshGivesThePlanesContactBitForBit) {
  TriangleMesh square;
  square.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const MeshFeatures f(square);
  const Vec3 origin(0.25, -0.5, 2.0);
  const Plane plane{origin, Vec3::UnitZ()};
  const Superquadric shapes[] = {Superquadric::sphere(0.1), Superquadric::ellipsoid(0.2, 0.1, 0.05), Superquadric(0.1, 0.15, 0.1, 6, 4)};
  const Pose poses[] = {{origin + Vec3(0.3, 0.2, 0.09), Quat::Identity()},
                        {origin + Vec3(-0.4, 0.1, 0.07), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))},
                        {origin + Vec3(0.2, 0.2, 0.08), Quat(Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized()))}};  // on the diagonal
  for (int s = 0; s < 3; ++s) {
    const ContactGeometry expected = detectContact(shapes[s], poses[s], plane);
    ASSERT_TRUE(expected.touching());
    int touching = 0;
    for (std::uint32_t feature = 0; feature < f.featureCount(); ++feature) {
      const ContactGeometry g = detectContact(shapes[s], poses[s], f, Pose{origin, Quat::Identity()}, feature);
      if (!g.converged()) continue;
      ++touching;
      EXPECT_EQ(f.kind(feature), FeatureKind::Face);
      EXPECT_EQ(g.overlap, expected.overlap);
      EXPECT_EQ(g.normal, expected.normal);
      EXPECT_EQ(g.pointA, expected.pointA);
      EXPECT_EQ(g.pointB, expected.pointB);
      EXPECT_EQ(g.localPointB, expected.pointB - origin);
      EXPECT_EQ(g.curvatureA.k1, expected.curvatureA.k1);
      EXPECT_EQ(g.curvatureA.k2, expected.curvatureA.k2);
      EXPECT_EQ(g.curvatureB.k1, 0.0);
      EXPECT_EQ(g.curvatureB.k2, 0.0);
    }
    EXPECT_EQ(touching, 1) << "shape " << s;
  }
}

TEST(MeshDetector, SphereAroundACubeTouchesExactlyOneFeatureWithTheClosedFormOverlap) {
  const MeshFeatures f(cube());
  const double r = 0.3;
  const Superquadric ball = Superquadric::sphere(r);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-0.25, 1.25);
  int faces = 0, edges = 0, vertices = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 c(u(random), u(random), u(random));
    const double distance = distanceToCube(c);
    if (distance == 0.0 || distance > 0.95 * r) continue;  // inside, or too far to touch
    int touching = 0;
    for (std::uint32_t feature = 0; feature < f.featureCount(); ++feature) {
      const ContactGeometry g = detectContact(ball, Pose{c, Quat::Identity()}, f, Pose{}, feature);
      if (!g.touching()) continue;
      ++touching;
      EXPECT_NEAR(g.overlap, r - distance, 1e-14) << c.transpose();
      EXPECT_NEAR((g.pointB - g.pointA).dot(g.normal), -g.overlap, 1e-14);
      EXPECT_NEAR(distanceToCube(g.pointB), 0.0, 1e-14);
      faces += f.kind(feature) == FeatureKind::Face;
      edges += f.kind(feature) == FeatureKind::Edge;
      vertices += f.kind(feature) == FeatureKind::Vertex;
    }
    EXPECT_EQ(touching, 1) << c.transpose();
  }
  EXPECT_GT(faces, 50);
  EXPECT_GT(edges, 50);
  EXPECT_GT(vertices, 20);
}

TEST(MeshDetector, ATurnedMeshGivesItsOwnFramesContactTurned) {
  // The same touch seen from the mesh's frame and from the world with the mesh at a turned,
  // moved pose: the detector places each feature by the pose, so the results are one rigid
  // motion apart (round-off only), for faces, edges and corners alike.
  const MeshFeatures f(cube());
  const Pose cubePose{Vec3(0.3, -1.2, 2.0), Quat(Eigen::AngleAxisd(2.1, Vec3(1, -2, 0.5).normalized()))};
  const Superquadric shapes[] = {Superquadric::sphere(0.3), Superquadric::ellipsoid(0.3, 0.15, 0.1)};
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.25, 1.25);
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 1500; ++trial) {
    const Superquadric& A = shapes[trial % 2];
    const Pose inCube{Vec3(u(random), u(random), u(random)), Quat(Eigen::AngleAxisd(u(random) * 3, Vec3(1, 1, 0).normalized()))};
    if (distanceToCube(inCube.position) == 0.0) continue;
    const Pose inWorld{cubePose.toWorld(inCube.position), cubePose.orientation * inCube.orientation};
    for (std::uint32_t feature = 0; feature < f.featureCount(); ++feature) {
      const ContactGeometry own = detectContact(A, inCube, f, Pose{}, feature);
      const ContactGeometry turned = detectContact(A, inWorld, f, cubePose, feature);
      ASSERT_EQ(own.touching(), turned.touching()) << trial << " feature " << feature;
      if (!own.touching()) continue;
      ++counts[static_cast<int>(f.kind(feature))];
      EXPECT_NEAR(turned.overlap, own.overlap, 1e-12);
      EXPECT_LT((turned.pointB - cubePose.toWorld(own.pointB)).norm(), 1e-12);
      EXPECT_LT((turned.pointA - cubePose.toWorld(own.pointA)).norm(), 1e-12);
      EXPECT_LT((turned.normal - cubePose.orientation * own.normal).norm(), 1e-9);
      EXPECT_LT((turned.localPointB - own.localPointB).norm(), 1e-12);
      EXPECT_LT((turned.localPointA - own.localPointA).norm(), 1e-9);
    }
  }
  EXPECT_GT(counts[static_cast<int>(FeatureKind::Face)], 50);
  EXPECT_GT(counts[static_cast<int>(FeatureKind::Edge)], 50);
  EXPECT_GT(counts[static_cast<int>(FeatureKind::Vertex)], 20);
}

TEST(MeshDetector, EllipsoidOnACubeEdgeSatisfiesTheCommonNormalConditions) {
  const MeshFeatures f(cube());
  const Superquadric e = Superquadric::ellipsoid(0.3, 0.15, 0.1);
  const Pose pose{Vec3(1.06, 0.5, 1.05), Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()))};
  int touching = 0;
  for (std::uint32_t feature = 0; feature < f.featureCount(); ++feature) {
    const ContactGeometry g = detectContact(e, pose, f, Pose{}, feature);
    if (!g.touching()) continue;
    ++touching;
    ASSERT_EQ(f.kind(feature), FeatureKind::Edge);
    EXPECT_NEAR(g.pointB.x(), 1.0, 1e-12);  // on the edge x = z = 1
    EXPECT_NEAR(g.pointB.z(), 1.0, 1e-12);
    EXPECT_NEAR(g.normal.y(), 0.0, 1e-8);   // normal to the edge
    EXPECT_NEAR(e.gauge(pose.toBody(g.pointA)), 1.0, 1e-12);
    EXPECT_NEAR((pose.rotation() * e.outwardNormal(g.localPointA)).dot(g.normal), 1.0, 1e-12);
    EXPECT_NEAR(((g.pointA - g.pointB) - (g.pointA - g.pointB).dot(g.normal) * g.normal).norm(), 0.0, 1e-8);
  }
  EXPECT_EQ(touching, 1);
}

TEST(PointDetector, EllipsoidAgainstAPointIsTheNearestSurfacePoint) {
  const Superquadric e = Superquadric::ellipsoid(0.3, 0.2, 0.1);
  const Pose pose{Vec3(0.1, -0.2, 0.3), Quat(Eigen::AngleAxisd(0.9, Vec3(1, -1, 2).normalized()))};
  // Points outside (gaps within the cut-off) and inside (overlaps), off the principal planes.
  const Vec3 bodyPoints[] = {{0.25, 0.12, 0.06}, {0.05, 0.05, 0.12}, {0.28, 0.02, 0.01}, {0.1, 0.15, 0.02}, {-0.2, 0.05, -0.05}};
  DetectorSettings settings;
  settings.cutoff = 0.1;
  for (const Vec3& local : bodyPoints) {
    const Vec3 P = pose.toWorld(local);
    const ContactGeometry g = detectContact(e, pose, P, settings);
    ASSERT_TRUE(g.converged()) << local.transpose();
    EXPECT_NEAR(e.gauge(g.localPointA), 1.0, 1e-13);
    EXPECT_NEAR((P - g.pointA).dot(g.normal), -g.overlap, 1e-15);
    EXPECT_LT(((P - g.pointA) + g.overlap * g.normal).norm(), 1e-10 * e.volumeEquivalentRadius());
    EXPECT_EQ(g.overlap > 0.0, e.gauge(local) < 1.0);
    // Nearest sampled surface point: no closer than |overlap| (to the sampling's resolution).
    double nearest = 1e9;
    for (int i = 0; i <= 400; ++i) {
      for (int j = 0; j < 800; ++j) {
        const Vec3 y = e.surfacePoint(-M_PI / 2 + M_PI * i / 400, -M_PI + 2 * M_PI * j / 800);
        nearest = std::min(nearest, (y - local).norm());
      }
    }
    EXPECT_GE(nearest, std::abs(g.overlap) - 1e-12);
    EXPECT_NEAR(nearest, std::abs(g.overlap), 2e-5);
  }
}

TEST(PointDetector, SphereIsTheClosedForm) {
  const Pose pose{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))};
  const ContactGeometry g = detectContact(Superquadric::sphere(0.5), pose, Vec3(1.3, 2.4, 3.0));
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, 0.0, 1e-15);
  EXPECT_NEAR((g.normal - Vec3(0.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace sqdem

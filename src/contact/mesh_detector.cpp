// Particle against one feature of a triangle mesh (detector.hpp, mesh_features.hpp) whose body
// frame is at poseB: the feature is placed in the world, its region tested in the body frame.
//   face    the face's plane (closed form through the support map), kept when the touching
//           point lies in the triangle and A's centre in front of the face;
//   edge    the line through the edge (line_contact.hpp, radius 0), kept when the touching point
//           lies strictly inside the edge and the direction in the edge's region;
//   vertex  the point contact, kept when the direction lies in the vertex's region.
// An edge or a vertex is a kink of the surface: its true curvature is infinite, which no
// continuum contact law takes. The laws see it as flat (the counter-surface a plane normal to
// the contact normal), as the particle on a face would; the contact area is then set by the
// particle's curvatures alone.

#include <cmath>

#include "line_contact.hpp"
#include "sqdem/contact/detector.hpp"

namespace sqdem {
namespace {

/// Not a contact of this feature: another feature (or none) answers for this touch.
ContactGeometry elsewhere(int iterations) {
  ContactGeometry g;
  g.iterations = iterations;
  return g;
}

}  // namespace

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const MeshFeatures& mesh, const Pose& poseB,
                              std::uint32_t feature, const DetectorSettings& settings, const WarmStart* previous) {
  const TriangleMesh& m = mesh.mesh();
  const std::uint32_t i = mesh.index(feature);
  const Mat3 R = poseB.rotation();
  const auto world = [&](std::uint32_t vertex) { return Vec3(poseB.position + R * m.vertices[vertex]); };
  const auto body = [&](const Vec3& direction) { return Vec3(R.transpose() * direction); };
  ContactGeometry g;
  switch (mesh.kind(feature)) {
    case FeatureKind::Face: {
      const Plane plane{world(m.triangles[i][0]), R * mesh.faceNormal(i)};
      if ((poseA.position - plane.point).dot(plane.normal) <= 0.0) return elsewhere(0);  // behind the face
      g = detectContact(A, poseA, plane, settings);
      if (g.converged() && !mesh.faceContains(i, poseB.toBody(g.pointB))) return elsewhere(0);
      break;
    }
    case FeatureKind::Edge: {
      const MeshFeatures::Edge& e = mesh.edge(i);
      const Vec3 p = world(e.vertex[0]), q = world(e.vertex[1]);
      const Vec3 along = (q - p).normalized();
      g = lineContact(A, poseA, Cylinder{p, along, 0.0}, settings, previous);
      if (!g.converged()) return g;
      const double station = (g.pointB - p).dot(along);
      if (!(station > 0.0 && station < (q - p).norm()) || !mesh.edgeRegionContains(i, body(-g.normal))) {
        return elsewhere(g.iterations);
      }
      g.curvatureB = PrincipalCurvatures::flat(-g.normal);
      break;
    }
    case FeatureKind::Vertex: {
      g = detectContact(A, poseA, world(i), settings, previous);
      if (g.converged() && !mesh.vertexRegionContains(i, body(-g.normal))) return elsewhere(g.iterations);
      break;
    }
  }
  g.localPointB = poseB.toBody(g.pointB);  // on the mesh, in its body frame
  return g;
}

}  // namespace sqdem

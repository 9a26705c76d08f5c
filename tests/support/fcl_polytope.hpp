#pragma once
// An independent lower bound for the detector sweeps: the distance of two superquadrics'
// tessellations (superquadric_tessellation.hpp, every vertex on the surface) by FCL's GJK. The
// tessellations are inscribed, so polytopes that overlap prove the bodies overlap, and the
// bodies are no further apart than their polytopes.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/distance.h>

#include <optional>

#include <memory>
#include <vector>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric_tessellation.hpp"

namespace sqdem::testing {

/// A superquadric's tessellation as FCL's convex polytope: the convex hull of its vertices (CGAL),
/// triangulated. FCL finds a polytope's support point by walking its edges, which is exact only
/// on the hull's own edges: on the tessellation's quads split into triangles (not all of them
/// hull edges where a blocky body's vertices crowd) the walk stops early, and FCL's EPA then
/// reported overlaps deeper than the bodies' own.
inline std::shared_ptr<fcl::Convexd> fclPolytope(const Superquadric& shape, int resolution) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  std::vector<Kernel::Point_3> points;
  for (const Vec3& p : tessellate(shape, resolution).points) points.emplace_back(p.x(), p.y(), p.z());
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (const auto v : hull.vertices()) {
    const Kernel::Point_3& p = hull.point(v);
    vertices->emplace_back(p.x(), p.y(), p.z());
  }
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto face : hull.faces()) {
    faces->push_back(3);
    for (const auto v : CGAL::vertices_around_face(hull.halfedge(face), hull)) faces->push_back(static_cast<int>(v.idx()));
  }
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.number_of_faces()), faces);
}

/// The polytopes' distance in their poses by FCL's GJK (libccd), or nothing when they overlap.
/// (Their penetration by FCL's EPA is not used: on these polytopes libccd's EPA aborts on an
/// assertion and FCL's own, GST_INDEP, ends InvalidHull or deeper than the bodies overlap.)
inline std::optional<double> fclDistance(const std::shared_ptr<fcl::Convexd>& A, const Pose& poseA,
                                         const std::shared_ptr<fcl::Convexd>& B, const Pose& poseB) {
  const auto object = [](const std::shared_ptr<fcl::Convexd>& shape, const Pose& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = p.position;
    tf.linear() = p.rotation();
    return fcl::CollisionObjectd(shape, tf);
  };
  fcl::CollisionObjectd oa = object(A, poseA), ob = object(B, poseB);
  const fcl::DistanceRequestd request(false, false, 0.0, 0.0, 1e-12, fcl::GST_LIBCCD);
  fcl::DistanceResultd result;
  fcl::distance(&oa, &ob, request, result);
  if (!(result.min_distance > 0.0)) return std::nullopt;
  return result.min_distance;
}

}  // namespace sqdem::testing

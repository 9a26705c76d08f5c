#pragma once
// The contact features of a triangle mesh (a kinematic body's surface, in its body frame): its
// faces, the edges and vertices a particle can touch, and the regions of directions each one
// answers for. A particle touches a mesh through one contact per feature, each with its own
// history (issue 13); the regions make the features of a surface share the directions around
// it without overlap, so that no touch is counted twice:
//   face    the particle's point nearest the face's plane projects into the triangle;
//   edge    a boundary edge or a convex (sharp) one: the outward direction m from the edge to
//           the particle points away from both faces' interiors (m . t > 0 for each face's
//           in-plane direction t normal to the edge, pointing out of that face);
//   vertex  one with a feature edge: m points away from every edge leaving it (m . u < 0).
// Flat edges (the faces coplanar to within flatTolerance) and concave ones are no features:
// the faces on either side cover them. Where coplanar faces meet, a point exactly on their
// shared edge or vertex belongs to one face only: the edge's side function is evaluated with
// the same numbers by both faces, and a flat fan's vertex belongs to its lowest-numbered face.
//
// Feature numbers: faces 0 .. T-1, then edges T .. T+E-1, then vertices T+E .. T+E+V-1.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sqdem/geometry/triangle_mesh.hpp"

namespace sqdem {

enum class FeatureKind : std::uint8_t { Face, Edge, Vertex };

class MeshFeatures {
 public:
  /// 1 - cos of the largest angle between two faces' normals whose shared edge counts as flat.
  static constexpr double flatTolerance = 1e-10;

  struct Edge {
    std::array<std::uint32_t, 2> vertex;  ///< ascending vertex indices
    std::array<std::uint32_t, 2> face;    ///< adjacent faces; face[1] == noFace on a boundary
    /// Unit in-plane directions normal to the edge pointing out of face[0], face[1].
    std::array<Vec3, 2> outward{Vec3::Zero(), Vec3::Zero()};
    bool feature = false;  ///< boundary or convex: a contact feature
    bool flat = false;     ///< two coplanar faces: the side test is shared (above)
  };
  static constexpr std::uint32_t noFace = 0xffffffffu;

  explicit MeshFeatures(TriangleMesh mesh);

  const TriangleMesh& mesh() const { return mesh_; }
  std::size_t faceCount() const { return mesh_.triangles.size(); }
  std::size_t featureCount() const { return faceCount() + edges_.size() + mesh_.vertices.size(); }
  FeatureKind kind(std::uint32_t feature) const;
  /// The index of a feature among those of its kind.
  std::uint32_t index(std::uint32_t feature) const;
  std::uint32_t edgeFeature(std::uint32_t edge) const { return static_cast<std::uint32_t>(faceCount() + edge); }
  std::uint32_t vertexFeature(std::uint32_t vertex) const {
    return static_cast<std::uint32_t>(faceCount() + edges_.size() + vertex);
  }

  const Vec3& faceNormal(std::uint32_t face) const { return normals_[face]; }
  const Edge& edge(std::uint32_t e) const { return edges_[e]; }
  std::size_t edgeCount() const { return edges_.size(); }
  /// The edges of face t: edge i joins its corners i and i + 1.
  const std::array<std::uint32_t, 3>& faceEdges(std::uint32_t face) const { return faceEdges_[face]; }
  bool vertexIsFeature(std::uint32_t v) const { return vertexFeature_[v] != 0; }
  /// The unit directions of the edges leaving vertex v.
  std::span<const Vec3> edgeDirections(std::uint32_t v) const {
    return {leaving_.data() + vertexEdgeStart_[v], leaving_.data() + vertexEdgeStart_[v + 1]};
  }

  /// Whether x (in the face's plane, body frame) lies in face t: the face region's test.
  bool faceContains(std::uint32_t face, const Vec3& x) const;
  /// Whether a contact on edge e with outward direction m (unit, normal to the edge) lies in
  /// the edge's region: m . outward > 0 for each adjacent face.
  bool edgeRegionContains(std::uint32_t e, const Vec3& m) const;
  /// Whether direction m lies in vertex v's region: m . u < 0 for every edge leaving v.
  bool vertexRegionContains(std::uint32_t v, const Vec3& m) const;

 private:
  /// The side function of face t's edge i at x: > 0 inside the face; for a flat edge the same
  /// numbers for both of its faces (the sign flipped for face[1]).
  double side(std::uint32_t face, int i, const Vec3& x) const;

  TriangleMesh mesh_;
  std::vector<Vec3> normals_;
  std::vector<Edge> edges_;
  std::vector<std::array<std::uint32_t, 3>> faceEdges_;
  std::vector<std::uint32_t> vertexEdgeStart_, vertexEdges_;  ///< edges at each vertex (CSR)
  std::vector<Vec3> leaving_;  ///< per entry of vertexEdges_: the unit direction away from the vertex
  std::vector<std::uint8_t> vertexFeature_;
  /// Per face and corner: the face owns that corner of a flat fan (the fan's lowest face).
  std::vector<std::array<bool, 3>> ownsCorner_;
};

}  // namespace sqdem

#include "sqdem/geometry/mesh_features.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace sqdem {

MeshFeatures::MeshFeatures(TriangleMesh mesh) : mesh_(std::move(mesh)) {
  const auto faces = static_cast<std::uint32_t>(mesh_.triangles.size());
  const std::size_t vertexCount = mesh_.vertices.size();
  normals_.reserve(faces);
  for (std::uint32_t t = 0; t < faces; ++t) normals_.push_back(mesh_.normal(t));

  // Edges by their ascending vertex pair, faces in ascending order.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> byVertices;
  faceEdges_.resize(faces);
  for (std::uint32_t t = 0; t < faces; ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t p = mesh_.triangles[t][i], q = mesh_.triangles[t][(i + 1) % 3];
      const auto [it, added] = byVertices.try_emplace({std::min(p, q), std::max(p, q)}, static_cast<std::uint32_t>(edges_.size()));
      if (added) edges_.push_back({{std::min(p, q), std::max(p, q)}, {t, noFace}, {Vec3::Zero(), Vec3::Zero()}, false, false});
      Edge& e = edges_[it->second];
      if (!added) {
        if (e.face[1] != noFace) {
          throw std::invalid_argument("mesh: the edge between vertices " + std::to_string(e.vertex[0]) + " and " +
                                      std::to_string(e.vertex[1]) + " has more than two faces (not a manifold surface)");
        }
        e.face[1] = t;
      }
      faceEdges_[t][i] = it->second;
      e.outward[added ? 0 : 1] = (mesh_.vertices[q] - mesh_.vertices[p]).cross(normals_[t]).normalized();
    }
  }
  for (Edge& e : edges_) {
    if (e.face[1] == noFace) {
      e.feature = true;
      continue;
    }
    const Vec3& n0 = normals_[e.face[0]];
    e.flat = n0.dot(normals_[e.face[1]]) >= 1.0 - flatTolerance;
    // Convex: face[1] falls away below face[0]'s plane beyond the edge.
    const Vec3& p = mesh_.vertices[e.vertex[0]];
    double beyond = 0.0;
    for (std::uint32_t v : mesh_.triangles[e.face[1]]) beyond = std::min(beyond, (mesh_.vertices[v] - p).dot(n0));
    e.feature = !e.flat && beyond < 0.0;
  }

  // Edges at each vertex (CSR), vertex features.
  vertexEdgeStart_.assign(vertexCount + 1, 0);
  for (const Edge& e : edges_) ++vertexEdgeStart_[e.vertex[0] + 1], ++vertexEdgeStart_[e.vertex[1] + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) vertexEdgeStart_[v + 1] += vertexEdgeStart_[v];
  vertexEdges_.resize(vertexEdgeStart_.back());
  leaving_.resize(vertexEdgeStart_.back());
  std::vector<std::uint32_t> fill(vertexEdgeStart_.begin(), vertexEdgeStart_.end() - 1);
  vertexFeature_.assign(vertexCount, 0);
  for (std::uint32_t k = 0; k < edges_.size(); ++k) {
    for (int end = 0; end < 2; ++end) {
      const std::uint32_t v = edges_[k].vertex[end], other = edges_[k].vertex[1 - end];
      leaving_[fill[v]] = (mesh_.vertices[other] - mesh_.vertices[v]).normalized();
      vertexEdges_[fill[v]++] = k;
      vertexFeature_[v] |= edges_[k].feature;
    }
  }

  // Corner ownership: the faces at a vertex joined through flat edges at it share the plane
  // there; the lowest-numbered of each such group owns the vertex.
  ownsCorner_.assign(faces, {true, true, true});
  for (std::uint32_t t = 0; t < faces; ++t) {
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh_.triangles[t][c];
      std::vector<std::uint32_t> group{t}, frontier{t};
      while (!frontier.empty()) {
        const std::uint32_t f = frontier.back();
        frontier.pop_back();
        for (std::uint32_t k = vertexEdgeStart_[v]; k < vertexEdgeStart_[v + 1]; ++k) {
          const Edge& e = edges_[vertexEdges_[k]];
          if (!e.flat || (e.face[0] != f && e.face[1] != f)) continue;
          const std::uint32_t other = e.face[0] == f ? e.face[1] : e.face[0];
          if (std::find(group.begin(), group.end(), other) == group.end()) group.push_back(other), frontier.push_back(other);
        }
      }
      ownsCorner_[t][c] = *std::min_element(group.begin(), group.end()) == t;
    }
  }
}

FeatureKind MeshFeatures::kind(std::uint32_t feature) const {
  if (feature < faceCount()) return FeatureKind::Face;
  return feature < faceCount() + edges_.size() ? FeatureKind::Edge : FeatureKind::Vertex;
}

std::uint32_t MeshFeatures::index(std::uint32_t feature) const {
  switch (kind(feature)) {
    case FeatureKind::Face: return feature;
    case FeatureKind::Edge: return static_cast<std::uint32_t>(feature - faceCount());
    case FeatureKind::Vertex: break;
  }
  return static_cast<std::uint32_t>(feature - faceCount() - edges_.size());
}

double MeshFeatures::side(std::uint32_t face, int i, const Vec3& x) const {
  const Edge& e = edges_[faceEdges_[face][i]];
  if (e.flat) {  // the edge's own numbers, shared by its two faces
    const Vec3& p = mesh_.vertices[e.vertex[0]];
    const double s = (mesh_.vertices[e.vertex[1]] - p).cross(x - p).dot(normals_[e.face[0]]);
    return mesh_.triangles[face][i] == e.vertex[0] ? s : -s;  // this face runs along p -> q, or back
  }
  const Vec3& p = mesh_.vertices[mesh_.triangles[face][i]];
  return (mesh_.vertices[mesh_.triangles[face][(i + 1) % 3]] - p).cross(x - p).dot(normals_[face]);
}

bool MeshFeatures::faceContains(std::uint32_t face, const Vec3& x) const {
  std::array<double, 3> s;
  for (int i = 0; i < 3; ++i) s[i] = side(face, i, x);
  for (int c = 0; c < 3; ++c) {  // exactly at corner c: edges c - 1 and c meet there
    if (s[c] == 0.0 && s[(c + 2) % 3] == 0.0) return ownsCorner_[face][c];
  }
  for (int i = 0; i < 3; ++i) {
    const Edge& e = edges_[faceEdges_[face][i]];
    const bool shared = e.flat && e.face[1] == face;  // the edge's first face owns its points
    if (s[i] < 0.0 || (shared && s[i] == 0.0)) return false;
  }
  return true;
}

bool MeshFeatures::edgeRegionContains(std::uint32_t e, const Vec3& m) const {
  const Edge& edge = edges_[e];
  if (!(m.dot(edge.outward[0]) > 0.0)) return false;
  return edge.face[1] == noFace || m.dot(edge.outward[1]) > 0.0;
}

bool MeshFeatures::vertexRegionContains(std::uint32_t v, const Vec3& m) const {
  for (const Vec3& u : edgeDirections(v)) {
    if (!(m.dot(u) < 0.0)) return false;
  }
  return true;
}

}  // namespace sqdem

#include "penetration_depth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace sqdem::detail {
namespace {

/// A triangle of the polytope, counter-clockwise seen from outside: its outward unit normal and
/// the signed distance of its plane from the origin.
struct Face {
  std::array<int, 3> v;
  Vec3 normal;
  double distance;
};

/// The support points of K taken so far and their convex hull, kept by adding one point at a
/// time: the faces the point sees are removed and the horizon joined to it.
class Polytope {
 public:
  /// A tetrahedron of four points; false when they are (nearly) coplanar.
  bool start(const std::array<Vec3, 4>& corners) {
    points_.assign(corners.begin(), corners.end());
    const double volume = (points_[1] - points_[0]).cross(points_[2] - points_[0]).dot(points_[3] - points_[0]);
    if (!(std::abs(volume) > 1e-12)) return false;
    // Each face with the corner opposite it, turned to face away from that corner.
    for (auto [a, b, c, opposite] : {std::array<int, 4>{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}}) {
      if ((points_[b] - points_[a]).cross(points_[c] - points_[a]).dot(points_[opposite] - points_[a]) > 0.0) std::swap(b, c);
      if (!addFace(a, b, c)) return false;
    }
    return true;
  }

  /// Adds point w: the faces it sees are replaced by the horizon joined to it. False, with the
  /// polytope unchanged, when no face sees it (it is inside, to round-off) or a new face would
  /// degenerate.
  bool add(const Vec3& w) {
    edges_.clear();
    for (const Face& face : faces_) {
      if (seenFrom(face, w)) {
        for (int k = 0; k < 3; ++k) edges_.emplace_back(face.v[k], face.v[(k + 1) % 3]);
      }
    }
    if (edges_.empty()) return false;
    points_.push_back(w);
    const int apex = static_cast<int>(points_.size()) - 1;
    fresh_.clear();
    for (const auto& [a, b] : edges_) {  // the horizon: edges whose reverse no seen face has
      if (std::find(edges_.begin(), edges_.end(), std::make_pair(b, a)) != edges_.end()) continue;
      const std::optional<Face> face = makeFace(a, b, apex);
      if (!face) {
        points_.pop_back();
        return false;
      }
      fresh_.push_back(*face);
    }
    std::erase_if(faces_, [&](const Face& face) { return seenFrom(face, w); });
    faces_.insert(faces_.end(), fresh_.begin(), fresh_.end());
    return true;
  }

  const std::vector<Face>& faces() const { return faces_; }

 private:
  /// w lies beyond the face's plane by more than round-off (scaled coordinates).
  static bool seenFrom(const Face& face, const Vec3& w) { return face.normal.dot(w) - face.distance > 1e-13; }

  std::optional<Face> makeFace(int a, int b, int c) const {
    const Vec3 n = (points_[b] - points_[a]).cross(points_[c] - points_[a]);
    const double length = n.norm();
    if (!(length > 0.0)) return std::nullopt;
    return Face{{a, b, c}, n / length, n.dot(points_[a]) / length};
  }

  bool addFace(int a, int b, int c) {
    const std::optional<Face> face = makeFace(a, b, c);
    if (face) faces_.push_back(*face);
    return face.has_value();
  }

  std::vector<Vec3> points_;
  std::vector<Face> faces_;
  std::vector<std::pair<int, int>> edges_;  // scratch of add(): the seen faces' edges
  std::vector<Face> fresh_;                  // scratch of add(): the faces on the horizon
};

}  // namespace

std::optional<Penetration> penetrationDepth(const PairFrame& f, double relativeTolerance) {
  constexpr int maxIterations = 600;
  const double L = f.lengthScale;
  Penetration best;
  best.lowerBound = -std::numeric_limits<double>::infinity();
  best.upperBound = std::numeric_limits<double>::infinity();
  // K's support point along unit n (scaled); every one bounds the least penetration from above.
  const auto support = [&](const Vec3& n) {
    const Vec3 w = (f.supportOfA(n) - f.supportOfB(n)) / L;
    ++best.iterations;
    const double gap = n.dot(w) * L;
    if (gap < best.upperBound) {
      best.upperBound = gap;
      best.normal = n;
    }
    return w;
  };
  // Start: the support points along A's axes, both ways; a tetrahedron of the four most spread.
  std::array<Vec3, 6> axes;
  for (int k = 0; k < 6; ++k) axes[k] = support(Vec3::Unit(k / 2) * (k % 2 ? -1.0 : 1.0));
  const auto furthest = [&](const auto& distance) {
    return *std::max_element(axes.begin(), axes.end(), [&](const Vec3& x, const Vec3& y) { return distance(x) < distance(y); });
  };
  const Vec3 p0 = axes[0];
  const Vec3 p1 = furthest([&](const Vec3& x) { return (x - p0).squaredNorm(); });
  const Vec3 p2 = furthest([&](const Vec3& x) { return (x - p0).cross(p1 - p0).squaredNorm(); });
  const Vec3 n012 = (p1 - p0).cross(p2 - p0);
  const Vec3 p3 = furthest([&](const Vec3& x) { return std::abs((x - p0).dot(n012)); });
  Polytope polytope;
  if (!polytope.start({p0, p1, p2, p3})) return std::nullopt;
  for (const Vec3& x : axes) polytope.add(x);  // unchanged for the corners and points inside

  // A face with the origin on or beyond its plane first (the polytope must enclose the origin
  // before its nearest face bounds anything), else the nearest face.
  while (best.iterations < maxIterations) {
    const auto& faces = polytope.faces();
    const Face& face = *std::min_element(faces.begin(), faces.end(),
                                         [](const Face& x, const Face& y) { return x.distance < y.distance; });
    const bool enclosed = face.distance > 0.0;
    const Vec3 n = face.normal;
    const double distance = face.distance;
    const Vec3 w = support(n);
    const double reach = n.dot(w);       // h_K along the face's normal (scaled)
    if (reach <= 0.0) return std::nullopt;  // a separating plane: the bodies do not overlap
    if (enclosed) best.lowerBound = distance * L;
    if (enclosed && reach - distance <= relativeTolerance) {
      best.converged = true;
      break;
    }
    if (!polytope.add(w)) break;  // w is the face's own point to round-off, or a face degenerates
  }
  return best;
}

}  // namespace sqdem::detail

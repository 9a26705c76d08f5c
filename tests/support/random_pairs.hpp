#pragma once
// Random superquadric pairs with a planted common-normal contact, for the robustness sweep and
// the detector benchmarks. The planted pair is exact by construction: pA = support_A(n),
// pB = support_B(-n) and B is placed so that pB = pA - overlap * n, which satisfies the
// common-normal conditions (detector.hpp) with the given overlap and normal n.

#include <cmath>
#include <random>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::testing {

enum class PairKind { Generic, FaceOnFace, NearEdge };

struct PlantedPair {
  Superquadric A, B;
  Pose poseA, poseB;
  Vec3 normal;     ///< planted common normal (world, from A towards B)
  double overlap;  ///< planted overlap (m)
  PairKind kind;
};

struct PairGenerator {
  std::mt19937_64 rng;
  double minExponent = 2.0, maxExponent = 10.0;
  double minAxisRatio = 0.2;
  double minOverlap = 1e-6, maxOverlap = 1e-1;  ///< in units of sqrt(R_vol,A R_vol,B)

  explicit PairGenerator(std::uint64_t seed) : rng(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

  Quat randomRotation() {
    std::normal_distribution<double> g;
    return Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
  }

  Vec3 randomUnit() {
    std::normal_distribution<double> g;
    return Vec3(g(rng), g(rng), g(rng)).normalized();
  }

  Superquadric randomShape() {
    const double scale = uniform(0.5, 2.0);
    const bool ellipsoid = uniform(0.0, 1.0) < 0.2;
    const double n1 = ellipsoid ? 2.0 : uniform(minExponent, maxExponent);
    const double n2 = ellipsoid ? 2.0 : uniform(minExponent, maxExponent);
    return Superquadric(scale, scale * uniform(minAxisRatio, 1.0), scale * uniform(minAxisRatio, 1.0), n1, n2);
  }

  /// A body axis direction (+-x, +-y or +-z) in world coordinates.
  Vec3 randomFaceNormal(const Quat& q) {
    const int axis = static_cast<int>(uniform(0.0, 3.0));
    return q * (Vec3::Unit(axis) * (uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0));
  }

  /// A body direction that picks an edge or corner of a blocky body, slightly perturbed.
  Vec3 randomEdgeNormal(const Quat& q) {
    Vec3 d(uniform(0.0, 1.0) < 0.5 ? -1 : 1, uniform(0.0, 1.0) < 0.5 ? -1 : 1,
           uniform(0.0, 1.0) < 0.5 ? 0.0 : (uniform(0.0, 1.0) < 0.5 ? -1 : 1));
    const int roll = static_cast<int>(uniform(0.0, 3.0));
    d = Vec3(d((roll) % 3), d((roll + 1) % 3), d((roll + 2) % 3));
    return q * (d.normalized() + 0.05 * randomUnit()).normalized();
  }

  PairKind randomKind() {
    const double kindDraw = uniform(0.0, 1.0);
    return kindDraw < 0.1 ? PairKind::FaceOnFace : kindDraw < 0.2 ? PairKind::NearEdge : PairKind::Generic;
  }

  PlantedPair next() {
    const PairKind kind = randomKind();
    Superquadric A = randomShape();
    return next(A, randomShape(), kind);
  }

  /// A planted pair of the given shapes.
  PlantedPair next(const Superquadric& A, const Superquadric& B) { return next(A, B, randomKind()); }

  PlantedPair next(const Superquadric& A, const Superquadric& B, PairKind kind) {
    PlantedPair p{A, B, {}, {}, Vec3::UnitZ(), 0.0, kind};
    p.poseA.orientation = randomRotation();
    p.poseB.orientation = randomRotation();
    p.poseA.position = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    switch (kind) {
      case PairKind::Generic: p.normal = randomUnit(); break;
      case PairKind::NearEdge: p.normal = randomEdgeNormal(p.poseA.orientation); break;
      case PairKind::FaceOnFace: {
        p.normal = randomFaceNormal(p.poseA.orientation);
        // Turn B so that one of its faces looks back along -normal.
        const Vec3 faceB = randomFaceNormal(p.poseB.orientation);
        p.poseB.orientation = Quat::FromTwoVectors(faceB, -p.normal) * p.poseB.orientation;
        break;
      }
    }
    const double L = referenceVolumeRadius(p.A, p.B);
    p.overlap = L * std::pow(10.0, uniform(std::log10(minOverlap), std::log10(maxOverlap)));
    const Vec3 pA = p.poseA.toWorld(p.A.supportPoint(p.poseA.orientation.conjugate() * p.normal));
    const Vec3 pBLocal = p.B.supportPoint(p.poseB.orientation.conjugate() * -p.normal);
    p.poseB.position = pA - p.overlap * p.normal - p.poseB.orientation * pBLocal;
    return p;
  }
};

}  // namespace sqdem::testing

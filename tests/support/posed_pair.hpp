#pragma once
// Two superquadrics posed to touch: B slid along a direction until the detector's overlap is the
// one asked for, and the blocky poses of the true-gap tests (a face, an edge or a corner of each
// body turned towards the other).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "sqdem/contact/detector.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::testing {

struct PosedPair {
  std::string kind;
  Superquadric A = Superquadric::ellipsoid(1.0, 1.0, 1.0), B = A;
  Pose poseA, poseB;
  ContactGeometry contact;
};

/// Slides B (poseB.position = distance u from A's centre) until the overlap is `overlap` (m);
/// false when the detector fails or the overlap is not met to 1e-12 of the pair's length.
inline bool slideToOverlap(PosedPair& p, const Vec3& u, double overlap) {
  DetectorSettings settings;
  settings.cutoff = 4.0 * (p.A.boundingRadius() + p.B.boundingRadius());
  double distance = 1.2 * (p.A.boundingRadius() + p.B.boundingRadius());
  p.poseB.position = p.poseA.position + distance * u;
  ContactGeometry c = detectContact(p.A, p.poseA, p.B, p.poseB, settings);
  const double length = referenceVolumeRadius(p.A, p.B);
  for (int k = 0; k < 100 && c.converged() && std::abs(c.overlap - overlap) > 1e-13 * length; ++k) {
    distance += (c.overlap - overlap) / c.normal.dot(u);
    p.poseB.position = p.poseA.position + distance * u;
    c = detectContact(p.A, p.poseA, p.B, p.poseB, settings, c);
  }
  p.contact = c;
  return c.converged() && std::abs(c.overlap - overlap) < 1e-12 * length;
}

/// The four classes of blocky poses, B above A along z.
inline constexpr const char* blockyPoseKinds[] = {"face-face", "face-edge", "edge-edge", "corner-face"};

/// A random pair of class `kind` (0-3): semi-axes in [1, 3] with aspect up to 1:3, exponents in
/// [2, 10], each body tilted by up to 3 degrees and B twisted about z; touching at an overlap of
/// 1e-9 R_ref. False when the detector fails.
inline bool randomBlockyPair(int kind, std::mt19937& rng, PosedPair& p) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const auto shape = [&] {
    const double a = 1.0 + 2.0 * U(rng), b = 1.0 + 2.0 * U(rng);
    const double c = std::clamp(1.0 + 2.0 * U(rng), std::max(a, b) / 3.0, std::min(a, b) * 3.0);
    return Superquadric(a, b, c, 2.0 + 8.0 * U(rng), 2.0 + 8.0 * U(rng));
  };
  const auto tilt = [&] {
    const Vec3 axis(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    return Quat(Eigen::AngleAxisd(3.0 * std::numbers::pi / 180.0 * U(rng), axis.normalized()));
  };
  p.kind = blockyPoseKinds[kind];
  p.A = shape();
  p.B = shape();
  const Quat twist(Eigen::AngleAxisd(2.0 * std::numbers::pi * U(rng), Vec3::UnitZ()));
  const Quat edgeDown(Eigen::AngleAxisd(std::numbers::pi / 4.0, Vec3::UnitX()));
  const Quat cornerDown = Quat::FromTwoVectors(Vec3(1.0, 1.0, 1.0).normalized(), -Vec3::UnitZ());
  p.poseA = Pose{};
  p.poseA.orientation = tilt() * (kind == 2 ? edgeDown : Quat::Identity());
  p.poseB = Pose{};
  p.poseB.orientation = tilt() * twist * (kind == 0 ? Quat::Identity() : kind == 3 ? cornerDown : edgeDown);
  return slideToOverlap(p, Vec3::UnitZ(), 1e-9 * referenceVolumeRadius(p.A, p.B));
}

}  // namespace sqdem::testing

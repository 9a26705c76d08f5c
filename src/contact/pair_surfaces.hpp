#pragma once
// The two surfaces of a pair as the common-normal Newton solve sees them, in A's body frame
// (detector.cpp): a point's gradient and unit normal, the shape operator S u = H u / |grad g| of a
// tangent vector u (H the gauge's Hessian; dotted with tangents, the Jacobian's curvature terms),
// the radial projection onto each surface, and the principal curvatures of a solution. One
// policy per shape-pair kind:
//   SuperquadricSurfaces  general exponents: Superquadric::derivatives (Hessians formed), B's
//                         rotated into A's frame
//   EllipsoidSurfaces     n1 = n2 = 2: g(x) = sqrt((x - c)' Q (x - c)) with Q = R diag(1/a^2) R',
//                         so grad g = Q (x - c) / g, H = (Q - grad grad') / g and on tangent
//                         vectors (orthogonal to grad) t.S.u = t.Q.u / (g |grad g|): no power, no
//                         Hessian, no rotation of B's derivatives per evaluation.

#include "sqdem/geometry/curvature.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::detail {

/// The pair seen from A's body frame: B's rotation R (B body -> A body) and centre c.
struct PairFrame {
  const Superquadric& A;
  const Superquadric& B;
  Mat3 R;
  Vec3 c;
  double lengthScale;

  Vec3 toB(const Vec3& p) const { return R.transpose() * (p - c); }
  Vec3 fromB(const Vec3& x) const { return c + R * x; }
  /// Support points (A's frame) of A along n and of B along -n: their difference is the support
  /// point of the Minkowski difference A - B along n.
  Vec3 supportOfA(const Vec3& n) const { return A.supportPoint(n); }
  Vec3 supportOfB(const Vec3& n) const { return fromB(B.supportPoint(R.transpose() * -n)); }
};

class SuperquadricSurfaces {
 public:
  struct Point {
    Vec3 point, gradient, normal;
    double gradientNorm = 0.0;
    Mat3 hessian;
  };
  explicit SuperquadricSurfaces(const PairFrame& f) : f_(f) {}

  Point onA(const Vec3& p) const { return at(p, f_.A.derivatives(p), Mat3::Identity(), false); }
  Point onB(const Vec3& p) const { return at(p, f_.B.derivatives(f_.toB(p)), f_.R, true); }
  Vec3 shapeOperator(const Point& s, const Vec3& u) const { return s.hessian * u / s.gradientNorm; }
  bool finite(const Point& s) const { return s.hessian.allFinite(); }
  Vec3 projectOnA(const Vec3& y) const { return f_.A.projectRadially(y); }
  Vec3 projectOnB(const Vec3& y) const { return f_.fromB(f_.B.projectRadially(f_.toB(y))); }
  PrincipalCurvatures curvatures(const Point& s) const { return principalCurvatures(s.gradient, s.hessian); }

 private:
  static Point at(const Vec3& p, const GaugeDerivatives& d, const Mat3& R, bool rotate) {
    const Vec3 g = rotate ? Vec3(R * d.gradient) : d.gradient;
    const double gn = g.norm();
    return {p, g, g / gn, gn, rotate ? Mat3(R * d.hessian * R.transpose()) : d.hessian};
  }
  const PairFrame& f_;
};

class EllipsoidSurfaces {
 public:
  struct Point {
    Vec3 point, gradient, normal;
    double gradientNorm = 0.0;
    double gauge = 0.0;
    const Mat3* Q = nullptr;
  };
  explicit EllipsoidSurfaces(const PairFrame& f)
      : c_(f.c),
        QA_(f.A.halfExtents().cwiseInverse().cwiseAbs2().asDiagonal()),
        QB_(f.R * f.B.halfExtents().cwiseInverse().cwiseAbs2().asDiagonal() * f.R.transpose()) {}

  Point onA(const Vec3& p) const { return at(p, p, QA_); }
  Point onB(const Vec3& p) const { return at(p, p - c_, QB_); }
  Vec3 shapeOperator(const Point& s, const Vec3& u) const { return *s.Q * u / (s.gauge * s.gradientNorm); }
  bool finite(const Point& s) const { return std::isfinite(s.gauge) && s.gauge > 0.0; }
  Vec3 projectOnA(const Vec3& y) const { return y / std::sqrt(y.dot(QA_ * y)); }
  Vec3 projectOnB(const Vec3& y) const {
    const Vec3 x = y - c_;
    return c_ + x / std::sqrt(x.dot(QB_ * x));
  }
  PrincipalCurvatures curvatures(const Point& s) const {
    return principalCurvatures(s.gradient, (*s.Q - s.gradient * s.gradient.transpose()) / s.gauge);
  }

 private:
  static Point at(const Vec3& p, const Vec3& x, const Mat3& Q) {
    const Vec3 Qx = Q * x;
    const double g = std::sqrt(x.dot(Qx));
    const Vec3 gradient = Qx / g;
    const double gn = gradient.norm();
    return {p, gradient, gradient / gn, gn, g, &Q};
  }
  Vec3 c_;
  Mat3 QA_, QB_;
};

}  // namespace sqdem::detail

#include "sqdem/geometry/superquadric.hpp"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sqdem {
namespace {

/// The 2-D p-norm h(u, v) = (|u|^p + |v|^p)^(1/p) and its derivatives. With t = |.|/h:
///   dh/du = sgn(u) t_u^(p-1),
///   h d2h/du2 = (p-1) t_u^(p-2) t_v^p,   h d2h/dudv = -(p-1) sgn(u)sgn(v) t_u^(p-1) t_v^(p-1),
/// i.e. second derivatives are returned multiplied by h, which keeps them bounded for p >= 2.
/// powU = t_u^(p-2), powV = t_v^(p-2) are returned for the chain rule of the nested norm.
struct NormDerivatives {
  double h = 0.0, du = 0.0, dv = 0.0;
  double hUU = 0.0, hUV = 0.0, hVV = 0.0;
  double powU = 0.0, powV = 0.0;
};

/// x^p, x >= 0: by repeated squaring for the integer exponents of common shapes (n = 4, 6, 8, 10
/// and their p - 2), which need no pow (it was 46 % of an n = 6 bed's run time).
double power(double x, double p) {
  if (p == std::floor(p) && p <= 64.0) {
    double result = 1.0;
    for (auto e = static_cast<unsigned>(p); e != 0; e >>= 1, x *= x) {
      if (e & 1u) result *= x;
    }
    return result;
  }
  return std::pow(x, p);
}

/// x^(1/p), x >= 0: square and cube roots for p = 2, 3, 4, 6, 8.
double root(double x, double p) {
  if (p == 2.0) return std::sqrt(x);
  if (p == 3.0) return std::cbrt(x);
  if (p == 4.0) return std::sqrt(std::sqrt(x));
  if (p == 6.0) return std::cbrt(std::sqrt(x));
  if (p == 8.0) return std::sqrt(std::sqrt(std::sqrt(x)));
  return std::pow(x, 1.0 / p);
}

double pNorm(double u, double v, double p) {
  const double au = std::abs(u), av = std::abs(v);
  const double m = std::max(au, av);
  if (m == 0.0) return 0.0;
  return m * root(1.0 + power(std::min(au, av) / m, p), p);
}

NormDerivatives pNormDerivatives(double u, double v, double p) {
  NormDerivatives d;
  d.h = pNorm(u, v, p);
  if (d.h == 0.0) {
    // Direction undefined at the origin; the p = 2 limit h*H = I - t t^T averages to the
    // identity, for p > 2 the curvature term vanishes.
    d.powU = d.powV = (p == 2.0) ? 1.0 : 0.0;
    d.hUU = d.hVV = d.powU;
    return d;
  }
  const double tu = std::abs(u) / d.h, tv = std::abs(v) / d.h;
  d.powU = power(tu, p - 2.0);  // 0^0 = 1 for p = 2
  d.powV = power(tv, p - 2.0);
  const double tu1 = d.powU * tu, tv1 = d.powV * tv;
  d.du = std::copysign(tu1, u);
  d.dv = std::copysign(tv1, v);
  d.hUU = (p - 1.0) * d.powU * tv1 * tv;
  d.hVV = (p - 1.0) * d.powV * tu1 * tu;
  d.hUV = -(p - 1.0) * d.du * d.dv;
  return d;
}

/// The 3-D p-norm g(u) = (|u1|^p + |u2|^p + |u3|^p)^(1/p): the nested gauge when n1 = n2 = p (one
/// root instead of two), scaled by the largest |u_i| against overflow.
double pNorm3(const Vec3& u, double p) {
  const Vec3 au = u.cwiseAbs();
  const double m = au.maxCoeff();
  if (m == 0.0) return 0.0;
  return m * root(power(au.x() / m, p) + power(au.y() / m, p) + power(au.z() / m, p), p);
}

/// sgn(x) |x|^e
double signedPow(double x, double e) { return std::copysign(std::pow(std::abs(x), e), x); }

void requireInRange(const char* name, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    throw std::invalid_argument("superquadric parameter '" + std::string(name) + "' = " +
                                std::to_string(value) + " is outside the allowed range [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

/// 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2), e = 2/n (Jaklic et al. 2000).
double computeVolume(const Superquadric& s) {
  using boost::math::beta;
  const double e1 = 2.0 / s.n1(), e2 = 2.0 / s.n2();
  return 2.0 * s.a() * s.b() * s.c() * e1 * e2 * beta(e1 / 2.0 + 1.0, e1) * beta(e2 / 2.0, e2 / 2.0);
}

/// Largest |x| over the surface: dense sampling of one octant of the parametrisation, refined
/// by a shrinking pattern search, with a small safety margin; never above the box corner.
double computeBoundingRadius(const Superquadric& s) {
  if (s.isEllipsoid()) return s.halfExtents().maxCoeff();
  constexpr double halfPi = std::numbers::pi / 2.0;
  constexpr int samples = 16;
  double bestEta = 0.0, bestOmega = 0.0, best = 0.0;
  for (int i = 0; i <= samples; ++i) {
    for (int j = 0; j <= samples; ++j) {
      const double eta = halfPi * i / samples, omega = halfPi * j / samples;
      const double r2 = s.surfacePoint(eta, omega).squaredNorm();
      if (r2 > best) best = r2, bestEta = eta, bestOmega = omega;
    }
  }
  for (double step = halfPi / samples; step > 1e-12; step *= 0.5) {
    for (bool improved = true; improved;) {
      improved = false;
      for (const auto& [de, dw] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
        const double eta = std::clamp(bestEta + de, 0.0, halfPi);
        const double omega = std::clamp(bestOmega + dw, 0.0, halfPi);
        const double r2 = s.surfacePoint(eta, omega).squaredNorm();
        if (r2 > best) best = r2, bestEta = eta, bestOmega = omega, improved = true;
      }
    }
  }
  return std::min(std::sqrt(best) * (1.0 + 1e-9), s.halfExtents().norm());
}

}  // namespace

Superquadric::Superquadric(double a, double b, double c, double n1, double n2)
    : halfExtents_(a, b, c), n1_(n1), n2_(n2) {
  constexpr double huge = 1e300;
  requireInRange("a", a, 0.0, huge);
  requireInRange("b", b, 0.0, huge);
  requireInRange("c", c, 0.0, huge);
  if (a == 0.0 || b == 0.0 || c == 0.0) {
    throw std::invalid_argument("superquadric semi-axes a, b, c must be > 0");
  }
  requireInRange("n1", n1, 2.0, maxExponent);
  requireInRange("n2", n2, 2.0, maxExponent);
  boundingRadius_ = computeBoundingRadius(*this);
  volume_ = computeVolume(*this);
  volumeEquivalentRadius_ = std::cbrt(3.0 * volume_ / (4.0 * std::numbers::pi));
}

double Superquadric::gauge(const Vec3& x) const {
  const Vec3 u = x.cwiseQuotient(halfExtents_);
  if (isEllipsoid()) return u.norm();
  if (n1_ == n2_) return pNorm3(u, n1_);
  return pNorm(pNorm(u.x(), u.y(), n2_), u.z(), n1_);
}

namespace {

/// g, grad g and, withHessian, the Hessian of g at x.
template <bool withHessian>
GaugeDerivatives gaugeDerivatives(const Superquadric& s, const Vec3& x) {
  const Vec3 u = x.cwiseQuotient(s.halfExtents());
  GaugeDerivatives out;
  Vec3 gradU;
  [[maybe_unused]] Mat3 hessU;
  if (s.isEllipsoid()) {
    const double g = u.norm();
    if (g == 0.0) return out;
    out.value = g;
    gradU = u / g;
    if constexpr (withHessian) hessU = (Mat3::Identity() - gradU * gradU.transpose()) / g;
  } else if (s.n1() == s.n2()) {
    // g = ||u||_p: with t_i = |u_i| / g, dg/du_i = sgn(u_i) t_i^(p-1) and
    // g d2g/du_i du_j = (p - 1) (delta_ij t_i^(p-2) - dg/du_i dg/du_j).
    const double p = s.n1(), g = pNorm3(u, p);
    if (g == 0.0) return out;
    out.value = g;
    Vec3 curvature;  // t_i^(p-2)
    for (int i = 0; i < 3; ++i) {
      const double t = std::abs(u(i)) / g;
      curvature(i) = power(t, p - 2.0);
      gradU(i) = std::copysign(curvature(i) * t, u(i));
    }
    if constexpr (withHessian) hessU = (p - 1.0) / g * (Mat3(curvature.asDiagonal()) - gradU * gradU.transpose());
  } else {
    const NormDerivatives in = pNormDerivatives(u.x(), u.y(), s.n2());     // s(u, v)
    const NormDerivatives outer = pNormDerivatives(in.h, u.z(), s.n1());  // g(s, w)
    const double g = outer.h;
    if (g == 0.0) return out;
    out.value = g;
    gradU = Vec3(outer.du * in.du, outer.du * in.dv, outer.dv);
    if constexpr (withHessian) {
      // Chain rule g(s(u, v), w); every term carries 1/g, and g_s * s_ab = t_s^(n1-2) (s s_ab) / g.
      const double sUU = outer.hUU * in.du * in.du + outer.powU * in.hUU;
      const double sUV = outer.hUU * in.du * in.dv + outer.powU * in.hUV;
      const double sVV = outer.hUU * in.dv * in.dv + outer.powU * in.hVV;
      hessU << sUU, sUV, outer.hUV * in.du,  //
          sUV, sVV, outer.hUV * in.dv,       //
          outer.hUV * in.du, outer.hUV * in.dv, outer.hVV;
      hessU /= g;
    }
  }
  const Vec3 inv = s.halfExtents().cwiseInverse();
  out.gradient = gradU.cwiseProduct(inv);
  if constexpr (withHessian) out.hessian = inv.asDiagonal() * hessU * inv.asDiagonal();
  return out;
}

}  // namespace

GaugeDerivatives Superquadric::derivatives(const Vec3& x) const { return gaugeDerivatives<true>(*this, x); }

GaugeDerivatives Superquadric::firstDerivatives(const Vec3& x) const { return gaugeDerivatives<false>(*this, x); }

GaugeDerivatives Superquadric::insideOutside(const Vec3& x) const {
  // With P_i = |u_i|^n and dP_i/du_i = n sgn(u_i) |u_i|^(n-1): F = (P_x + P_y)^(n1/n2) + P_z
  // (n2 inside n1), F = P_x + P_y + P_z when n1 = n2.
  const Vec3 u = x.cwiseQuotient(halfExtents_), inv = halfExtents_.cwiseInverse();
  const auto part = [](double v, double n, double& slope) {  // |v|^n, and n sgn(v) |v|^(n-1) in slope
    const double below = power(std::abs(v), n - 1.0);
    slope = std::copysign(n * below, v);
    return below * std::abs(v);
  };
  GaugeDerivatives out;
  Vec3 slope;
  const double px = part(u.x(), n2_, slope.x()), py = part(u.y(), n2_, slope.y()), pz = part(u.z(), n1_, slope.z());
  if (n1_ == n2_) {
    out.value = px + py + pz;
  } else {
    const double inner = px + py, outer = inner > 0.0 ? std::pow(inner, n1_ / n2_) : 0.0;
    out.value = outer + pz;
    const double chain = inner > 0.0 ? n1_ / n2_ * outer / inner : 0.0;  // d(inner^(n1/n2)) / d(inner)
    slope.x() *= chain, slope.y() *= chain;
  }
  out.gradient = slope.cwiseProduct(inv);
  return out;
}

Vec3 Superquadric::outwardNormal(const Vec3& x) const {
  return firstDerivatives(x).gradient.normalized();
}

Vec3 Superquadric::supportPoint(const Vec3& direction) const {
  // Maximise d.x over g(x) <= 1: with u = x/a and d~ = a d, the dual of the nested
  // (n2 inside n1) norm is the nested (q2 inside q1) norm, 1/q + 1/n = 1, and the maximiser
  // component is sgn(d~_i) (|d~_i| / ||d~||_q)^(q-1).
  const Vec3 d = direction.cwiseProduct(halfExtents_);
  if (isEllipsoid()) return (d / d.norm()).cwiseProduct(halfExtents_);
  const double e1 = 1.0 / (n1_ - 1.0), e2 = 1.0 / (n2_ - 1.0);  // q - 1
  const double q1 = n1_ * e1, q2 = n2_ * e2;
  const double dXY = pNorm(d.x(), d.y(), q2);
  const double dAll = pNorm(dXY, d.z(), q1);
  const double s = std::pow(dXY / dAll, e1);
  const double w = signedPow(d.z() / dAll, e1);
  const double ux = dXY > 0.0 ? signedPow(d.x() / dXY, e2) : 0.0;
  const double uy = dXY > 0.0 ? signedPow(d.y() / dXY, e2) : 0.0;
  return Vec3(a() * s * ux, b() * s * uy, c() * w);
}

Vec3 Superquadric::surfacePoint(double eta, double omega) const {
  const double e1 = 2.0 / n1_, e2 = 2.0 / n2_;
  const double ring = std::pow(std::abs(std::cos(eta)), e1);
  return Vec3(a() * ring * signedPow(std::cos(omega), e2),
              b() * ring * signedPow(std::sin(omega), e2), c() * signedPow(std::sin(eta), e1));
}

Vec3 Superquadric::secondMomentsOfVolume() const {
  // Jaklic, Leonardis & Solina (2000), Appendix: moments of a superquadric in Beta functions.
  using boost::math::beta;
  const double e1 = 2.0 / n1_, e2 = 2.0 / n2_;
  const double abc = a() * b() * c();
  const double planar = 0.5 * abc * e1 * e2 * beta(1.5 * e2, 0.5 * e2) * beta(0.5 * e1, 2.0 * e1 + 1.0);
  const double axial = 2.0 * abc * e1 * e2 * beta(0.5 * e2, 0.5 * e2 + 1.0) * beta(1.5 * e1, e1 + 1.0);
  return Vec3(planar * a() * a(), planar * b() * b(), axial * c() * c());
}

Vec3 Superquadric::principalMomentsOfInertia(double density) const {
  const Vec3 m = density * secondMomentsOfVolume();
  return Vec3(m.y() + m.z(), m.x() + m.z(), m.x() + m.y());
}

}  // namespace sqdem

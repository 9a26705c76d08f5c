#include "sqdem/mechanics/elliptic.hpp"

#include "sqdem/math/cubic_stencil.hpp"
#include "sqdem/mechanics/elliptic_integrals.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <utility>
#include <stdexcept>
#include <vector>

namespace sqdem {
namespace {

double capRadius(double inverseRadius, double cap) {
  return inverseRadius > 1.0 / cap ? 1.0 / inverseRadius : cap;
}

/// Eq. 13 and the factors of Eqs. 11-12 tabulated on a uniform grid in u = ln(Ri/Rj), cubic
/// (4-point Lagrange) interpolation of e^2, gamma, beta, K and D with the same weights.
class EccentricityTable {
 public:
  static constexpr double minRatio = 1e-8;
  static constexpr int intervals = 1024;

  EccentricityTable() : uMin_(std::log(minRatio)), step_(-uMin_ / intervals) {
    nodes_.resize(intervals + 1);
    for (int k = 0; k <= intervals; ++k) {
      nodes_[k] = hertzFactorsFromEccentricity(eccentricitySquaredExact(std::exp(uMin_ + k * step_)));
    }
  }

  HertzFactors operator()(double ratio) const {
    const CubicStencil c = cubicStencil((std::log(ratio) - uMin_) / step_, intervals);
    const HertzFactors* y = &nodes_[c.first];
    const std::array<double, 4>& l = c.weight;
    HertzFactors h{0.0, 0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 4; ++i) {
      h.e2 += l[i] * y[i].e2;
      h.gamma += l[i] * y[i].gamma;
      h.beta += l[i] * y[i].beta;
      h.K += l[i] * y[i].K;
      h.D += l[i] * y[i].D;
    }
    h.e2 = std::max(0.0, h.e2);
    return h;
  }

 private:
  double uMin_, step_;
  std::vector<HertzFactors> nodes_;
};

const EccentricityTable& eccentricityTable() {
  static const EccentricityTable table;
  return table;
}

void requireRatio(double ratio) {
  if (!(ratio > 0.0 && ratio <= 1.0)) {
    throw std::invalid_argument("elliptic contact: Ri/Rj must be in (0, 1], got " +
                                std::to_string(ratio));
  }
}

}  // namespace

RelativeRadii relativeRadii(const PrincipalCurvatures& A, const PrincipalCurvatures& B,
                            double radiusCap) {
  const double cosOmega = std::min(1.0, std::abs(A.d1.dot(B.d1)));
  const double cos2Omega = 2.0 * cosOmega * cosOmega - 1.0;
  const double sum = A.k1 + A.k2 + B.k1 + B.k2;
  const double dA = A.k1 - A.k2, dB = B.k1 - B.k2;
  const double root = std::sqrt(std::max(0.0, dA * dA + dB * dB + 2.0 * dA * dB * cos2Omega));
  RelativeRadii r;
  r.cosOmega = cosOmega;
  r.Ri = capRadius(0.5 * (sum + root), radiusCap);
  r.Rj = capRadius(0.5 * (sum - root), radiusCap);
  r.Rc = r.Ri * r.Rj / (r.Ri + r.Rj);
  return r;
}

Vec3 contactMajorAxis(const PrincipalCurvatures& A, const PrincipalCurvatures& B, const Vec3& normal) {
  // Relative curvature tensor sum k_i d_i d_i^T of both surfaces in a tangent basis (t1, t2);
  // the major axis is its eigenvector of the smaller eigenvalue.
  const Vec3 t1 = (A.d1 - A.d1.dot(normal) * normal).normalized(), t2 = normal.cross(t1);
  double m11 = 0.0, m12 = 0.0, m22 = 0.0;
  for (const PrincipalCurvatures* s : {&A, &B}) {
    for (const auto& [k, d] : {std::pair{s->k1, s->d1}, std::pair{s->k2, s->d2}}) {
      const double x = d.dot(t1), y = d.dot(t2);
      m11 += k * x * x;
      m12 += k * x * y;
      m22 += k * y * y;
    }
  }
  // Eigenvector of the smaller eigenvalue s of [[m11, m12], [m12, m22]]: (m12, s - m11) or
  // (s - m22, m12), whichever is longer (a circle: any direction).
  const double half = 0.5 * (m11 - m22);
  const double s = 0.5 * (m11 + m22) - std::sqrt(half * half + m12 * m12);
  const double x1 = m12, y1 = s - m11, x2 = s - m22, y2 = m12;
  const bool first = x1 * x1 + y1 * y1 >= x2 * x2 + y2 * y2;
  const Vec3 u = first ? Vec3(x1 * t1 + y1 * t2) : Vec3(x2 * t1 + y2 * t2);
  const double length = u.norm();
  return length > 0.0 ? Vec3(u / length) : t1;
}

double eccentricitySquaredExact(double ratio) {
  requireRatio(ratio);
  if (ratio == 1.0) return 0.0;
  // psi(x) = ratio E / ((ratio + 1) K - E) - (1 - x), x = e^2 (Eq. 13 rearranged). x = 0 and
  // x = 1 are spurious roots; psi < 0 just above 0 and psi > 0 just below 1.
  const auto psi = [ratio](double x) {
    const double t = 1.0 - x;
    const EllipticIntegrals I = ellipticIntegrals(x, t);
    return ratio * I.E / ((ratio + 1.0) * I.K - I.E) - t;
  };
  double lo = 1e-3 * (1.0 - ratio);
  double hi = 1.0 - std::pow(ratio, 4.0 / 3.0) / 16.0;
  while (psi(lo) >= 0.0 && lo > 1e-300) lo *= 1e-3;
  if (psi(lo) >= 0.0) return 0.0;  // the ratio 1 to psi's rounding (1 - ratio ~ 1e-15): a circle
  while (psi(hi) <= 0.0 && hi < 1.0) hi = 1.0 - (1.0 - hi) * 1e-2;
  std::uintmax_t maxIterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      psi, lo, hi, boost::math::tools::eps_tolerance<double>(52), maxIterations);
  return 0.5 * (a + b);
}

double eccentricitySquaredExplicit(double ratio) {
  requireRatio(ratio);
  const double braces = -0.177 + std::sqrt(0.5 / ratio * std::log(16.0 / ratio)) + 0.16 * std::log(ratio);
  return std::clamp(1.0 - 1.0 / (braces * braces), 0.0, 1.0);
}

double eccentricitySquaredTabulated(double ratio) {
  requireRatio(ratio);
  if (ratio < EccentricityTable::minRatio) return eccentricitySquaredExact(ratio);
  return eccentricityTable()(ratio).e2;
}

double eccentricitySquared(double ratio, EccentricityMethod method) {
  switch (method) {
    case EccentricityMethod::Exact: return eccentricitySquaredExact(ratio);
    case EccentricityMethod::Explicit: return eccentricitySquaredExplicit(ratio);
    case EccentricityMethod::Tabulated: return eccentricitySquaredTabulated(ratio);
  }
  return eccentricitySquaredExact(ratio);
}

HertzFactors hertzFactorsFromEccentricity(double e2) {
  const double t = 1.0 - e2;
  const EllipticIntegrals I = ellipticIntegrals(e2, t);
  const double K = I.K, E = I.E;
  HertzFactors h;
  h.e2 = e2;
  h.gamma = std::numbers::pi * std::numbers::sqrt2 * std::sqrt(E) / (2.0 * K * std::sqrt(K * t));
  h.beta = 2.0 * E / (K * std::sqrt(t));
  h.K = K;
  h.D = I.D;
  return h;
}

HertzFactors hertzFactors(double ratio, EccentricityMethod method) {
  if (method == EccentricityMethod::Tabulated) {
    requireRatio(ratio);
    if (ratio >= EccentricityTable::minRatio) return eccentricityTable()(ratio);
  }
  return hertzFactorsFromEccentricity(eccentricitySquared(ratio, method));
}

double ellipticHertzForce(double effectiveModulus, double Rc, double overlap, double gamma) {
  return overlap > 0.0 ? 4.0 / 3.0 * effectiveModulus * std::sqrt(Rc) * overlap * std::sqrt(overlap) * gamma
                       : 0.0;
}

double ellipticHertzArea(double Rc, double overlap, double beta) {
  return overlap > 0.0 ? std::numbers::pi * Rc * overlap * beta : 0.0;
}

BeckerFactors beckerFactors(const RelativeRadii& radii) {
  BeckerFactors f;
  f.A = 0.5 / radii.Rj;
  f.B = 0.5 / radii.Ri;
  f.Re = 0.5 / std::sqrt(f.A * f.B);
  const double ratio = f.B / f.A;
  f.f1 = 1.0 - std::pow(std::pow(ratio, 0.0602) - 1.0, 1.456);
  f.f2 = 1.0 - std::pow(std::pow(ratio, 0.0684) - 1.0, 1.531);
  return f;
}

double beckerHertzForce(double effectiveModulus, const BeckerFactors& f, double overlap) {
  return overlap > 0.0 ? 4.0 / 3.0 * effectiveModulus * std::sqrt(f.Re) * std::pow(overlap / f.f2, 1.5)
                       : 0.0;
}

double effectiveModulus(double youngsA, double poissonA, double youngsB, double poissonB) {
  return 1.0 / ((1.0 - poissonA * poissonA) / youngsA + (1.0 - poissonB * poissonB) / youngsB);
}

double effectiveShearModulus(double youngsA, double poissonA, double youngsB, double poissonB) {
  const double GA = youngsA / (2.0 * (1.0 + poissonA)), GB = youngsB / (2.0 * (1.0 + poissonB));
  return 1.0 / ((2.0 - poissonA) / GA + (2.0 - poissonB) / GB);
}

}  // namespace sqdem

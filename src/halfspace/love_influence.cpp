#include "sqdem/halfspace/love_influence.hpp"

#include <cmath>

namespace sqdem {
namespace {

/// s + (s^2 + t^2)^(1/2) without the cancellation of s < 0: t^2 / ((s^2 + t^2)^(1/2) - s).
double plusHypot(double s, double t) {
  const double r = std::hypot(s, t);
  return s >= 0.0 ? s + r : t * t / (r - s);
}

/// m ln(n / d), 0 for m = 0 (on the rectangle's edge lines, where n or d vanishes: the limit).
double term(double m, double n, double d) { return m == 0.0 ? 0.0 : m * std::log(n / d); }

}  // namespace

double loveRectangleDisplacement(double x, double y, double a, double b) {
  const double xp = x + a, xm = x - a, yp = y + b, ym = y - b;
  return term(xp, plusHypot(yp, xp), plusHypot(ym, xp)) + term(yp, plusHypot(xp, yp), plusHypot(xm, yp)) +
         term(xm, plusHypot(ym, xm), plusHypot(yp, xm)) + term(ym, plusHypot(xm, ym), plusHypot(xp, ym));
}

}  // namespace sqdem

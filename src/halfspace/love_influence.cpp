#include "sqdem/halfspace/love_influence.hpp"

#include <cmath>
#include <cstddef>

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

std::vector<double> loveGridDisplacements(int nx, int ny, double hx, double hy) {
  // In units of hx, corner (m, l) at X_m = m - 1/2, Y_l = (l - 1/2) hy / hx. Each logarithm of
  // the bracket is of the ratio of one corner's sum to its neighbour's along an edge: acrossY(m, l)
  // = ln((Y_l+1 + r) / (Y_l + r)) on X_m, acrossX(m, l) = ln((X_m+1 + r) / (X_m + r)) on Y_l, each
  // shared by the two cells on either side of that edge.
  const double aspect = hy / hx;
  const auto X = [](int m) { return m - 0.5; };
  const auto Y = [&](int l) { return (l - 0.5) * aspect; };
  const auto index = [&](int m, int l) { return m + static_cast<std::size_t>(nx + 1) * l; };
  std::vector<double> sumY((nx + 1) * static_cast<std::size_t>(ny + 1)), sumX(sumY.size());  // Y + r, X + r at the corners
  for (int l = 0; l <= ny; ++l) {
    for (int m = 0; m <= nx; ++m) sumY[index(m, l)] = plusHypot(Y(l), X(m)), sumX[index(m, l)] = plusHypot(X(m), Y(l));
  }
  std::vector<double> acrossY(sumY.size()), acrossX(sumY.size());
  for (int l = 0; l <= ny; ++l) {
    for (int m = 0; m <= nx; ++m) {
      if (l < ny) acrossY[index(m, l)] = std::log(sumY[index(m, l + 1)] / sumY[index(m, l)]);
      if (m < nx) acrossX[index(m, l)] = std::log(sumX[index(m + 1, l)] / sumX[index(m, l)]);
    }
  }
  std::vector<double> bracket(static_cast<std::size_t>(nx) * ny);
  for (int dj = 0; dj < ny; ++dj) {
    for (int di = 0; di < nx; ++di) {  // the four terms above, the cell's corners X_di, X_di+1 and Y_dj, Y_dj+1
      bracket[di + static_cast<std::size_t>(nx) * dj] =
          hx * (X(di + 1) * acrossY[index(di + 1, dj)] + Y(dj + 1) * acrossX[index(di, dj + 1)] -
                X(di) * acrossY[index(di, dj)] - Y(dj) * acrossX[index(di, dj)]);
    }
  }
  return bracket;
}

}  // namespace sqdem

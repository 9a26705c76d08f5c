#include "sqdem/truegap/gap_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

namespace sqdem {
namespace {

constexpr int rays = 16;

/// An ellipse's frame on the plane: its major axis at `angle` from t1, minor over major `aspect`.
struct RayFrame {
  double angle = 0.0, aspect = 1.0;

  Vec2 direction(int k) const {  // the k-th ray, evenly spread over the ellipse
    const double t = 2.0 * std::numbers::pi * k / rays;
    const Vec2 e1(std::cos(angle), std::sin(angle)), e2(-e1.y(), e1.x());
    return std::cos(t) * e1 + aspect * std::sin(t) * e2;
  }
};

/// Evenly spaced points of the plane, one after another along a line, each point's surface lines
/// started beyond both surfaces: from the last two points' heights extended along the line (A's
/// top is concave over the plane and B's bottom convex, pair_gap.hpp, so the extension lies
/// beyond them, by their second difference, ~spacing^2 / R: 2.7 Newton steps per line of a rung,
/// its rays' included, instead of 4.0 in the peer n = 6 bed), or one spacing beyond the last
/// point's while there is only that one or the one before missed a body.
class LineWalk {
 public:
  explicit LineWalk(double spacing) : spacing_(spacing) {}

  /// The gap at the next point (x, y).
  double next(const PairGap& gap, double x, double y) {
    PairGap::Heights near = last_;
    double distance = spacing_;
    const PairGap::Heights extended{2.0 * last_.top - before_.top, 2.0 * last_.bottom - before_.bottom};
    if (count_ >= 2 && std::isfinite(extended.top) && std::isfinite(extended.bottom)) {
      near = extended, distance = 1e-6 * spacing_;  // (a slack far above the heights' rounding)
    }
    const double g = gap(x, y, near, distance);
    before_ = last_, last_ = near, ++count_;
    return g;
  }
  /// A walk along another line through the last point, `spacing` apart.
  LineWalk turned(double spacing) const {
    LineWalk walk(spacing);
    walk.last_ = last_, walk.count_ = std::min(count_, 1);
    return walk;
  }
  /// The walk back along the line from its last point, through the one before.
  LineWalk reversed() const {
    LineWalk walk = *this;
    if (count_ >= 2) std::swap(walk.before_, walk.last_);
    return walk;
  }

 private:
  double spacing_;
  PairGap::Heights before_, last_;
  int count_ = 0;
};

/// rho where the gap along rho d first reaches the level (the gap convex and below it at 0), the
/// point returned at or beyond it, its gap within 2 % of it (rho within 1 % for m >= 2).
double crossing(const PairGap& gap, double level, const Vec2& d, double guess, double limit) {
  // A bracket [inside, outside] kept about the crossing; each step takes the crossing of the
  // power law through the last two points (log g linear in log rho: one step for a gap c rho^m),
  // or the bracket's geometric middle where that leaves it or where two steps did not halve it.
  // Each point's lines start from the last point's heights.
  PairGap::Heights near;
  double rho = guess, lastRho = rho;
  const auto at = [&](double r) { return gap(r * d.x(), r * d.y(), near, std::abs(r - lastRho) * d.norm()); };
  double inside = 0.0, outside = std::numeric_limits<double>::infinity(), gOutside = 0.0;
  double g = at(rho), lastG = 0.0, widthBefore = 0.0, width = 0.0;
  for (int step = 0; step < 100; ++step) {
    if (g < level) inside = rho;
    else outside = rho, gOutside = g;
    if (inside >= limit) throw std::runtime_error("the true gap: the region where it is below the approach is not bounded");
    if (std::isfinite(outside) && (gOutside <= 1.02 * level || outside <= 1.001 * inside)) return outside;
    double m = 2.0, next = 0.0;  // Hertz's exponent until two points give one
    if (lastG > 0.0 && std::isfinite(lastG) && std::isfinite(g) && g != lastG) m = std::log(g / lastG) / std::log(rho / lastRho);
    if (std::isfinite(g) && g > 0.0 && m > 0.0) next = rho * std::pow(1.01 * level / g, 1.0 / m);
    const double bracket = inside > 0.0 && std::isfinite(outside) ? std::log(outside / inside) : 0.0;
    const bool slow = bracket > 0.0 && widthBefore > 0.0 && bracket > 0.5 * widthBefore;
    widthBefore = width, width = bracket;
    if (slow || !(next > inside && next < outside)) {  // the power law's step is slow, or left the bracket
      next = inside == 0.0 ? 0.5 * outside : std::isinf(outside) ? 2.0 * inside : std::sqrt(inside * outside);
    }
    if (std::isinf(outside)) next = std::min({next, 4.0 * inside, limit});  // no bracket yet: at most 4x out
    if (next < 1e-15 * limit) throw std::runtime_error("the true gap: no crossing of the approach found along a ray");
    lastRho = rho, lastG = g;
    rho = next, g = at(rho);
  }
  return outside;  // not reached: the bracket halves at least every other step
}

}  // namespace

GapRegion gapRegion(const PairGap& gap, double level) {
  if (!(level > 0.0)) throw std::invalid_argument("gapRegion: level > 0");
  if (!(gap(0.0, 0.0) < level)) {
    throw std::runtime_error("the true gap: no point of the tangent plane where it is below the approach " + std::to_string(level) + " m");
  }
  const double limit = 1e3 * gap.referenceLength();
  RayFrame frame{0.0, gap.quadraticAspect()};
  double guess = std::max(std::sqrt(2.0 * gap.majorRadius() * level), 1e-9 * gap.referenceLength());
  std::array<Vec2, rays> crossings;
  for (int pass = 0; pass < 8; ++pass) {
    Vec2 mean = Vec2::Zero();
    for (int k = 0; k < rays; ++k) {
      const Vec2 d = frame.direction(k);
      guess = crossing(gap, level, d, guess, limit);
      crossings[k] = guess * d;
      mean += crossings[k] / rays;
    }
    Mat2 spread = Mat2::Zero();
    for (const Vec2& p : crossings) spread += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat2> axes(spread);  // eigenvalues ascending
    const Vec2 major = axes.eigenvectors().col(1);
    // Rays spread with aspect a over an elliptic region of aspect alpha, centred on the contact
    // and aligned with them, cross it at points whose spread has the aspect sqrt(a alpha) (the
    // rays' parameter is uneven along the ellipse; with 16 rays to ~((a - alpha) / (a +
    // alpha))^8): the region's is the spread's squared over the rays'. Taking the spread's own,
    // half-way, took up to four passes (docs/performance.md, "Cheaper rungs, second round").
    // Capped at 1, where the spread's major axis lies across the rays' (the estimate does not hold).
    const double spreadAspect = std::sqrt(std::max(axes.eigenvalues()(0), 0.0) / axes.eigenvalues()(1));
    const RayFrame next{std::atan2(major.y(), major.x()), std::min(1.0, spreadAspect * spreadAspect / frame.aspect)};
    const double turn = std::abs(std::remainder(next.angle - frame.angle, std::numbers::pi));
    const bool settled = std::abs(std::log(spreadAspect / frame.aspect)) < 0.1 && turn < 0.1 * spreadAspect;  // (the region's within 0.2)
    frame = next;
    if (settled) break;
  }
  // The extent of the crossings along their principal axes.
  GapRegion region;
  region.level = level;
  region.major = Vec2(std::cos(frame.angle), std::sin(frame.angle));
  for (const Vec2& p : crossings) {
    region.low1 = std::min(region.low1, p.dot(region.major)), region.high1 = std::max(region.high1, p.dot(region.major));
    region.low2 = std::min(region.low2, p.dot(region.minor())), region.high2 = std::max(region.high2, p.dot(region.minor()));
  }
  return region;
}

GapGrid gapGrid(const PairGap& gap, const GapRegion& region, int cells, double margin) {
  if (cells < 2 || !(margin >= 0.0)) throw std::invalid_argument("gapGrid: cells >= 2, margin >= 0");
  // The margin also covers the region's bulge past the polygon of its crossings (~2 % between rays).
  const Vec2 e1 = region.major, e2 = region.minor();
  const double pad1 = margin * (region.high1 - region.low1), pad2 = margin * (region.high2 - region.low2);
  GapGrid grid;
  grid.nx = grid.ny = cells;
  grid.x0 = region.low1 - pad1;
  grid.y0 = region.low2 - pad2;
  grid.hx = (region.high1 - region.low1 + 2.0 * pad1) / cells;
  grid.hy = (region.high2 - region.low2 + 2.0 * pad2) / cells;
  grid.gap.assign(static_cast<std::size_t>(cells) * cells, std::numeric_limits<double>::infinity());
  // Each row is walked from the contact's column outwards, each way until the gap is at or above
  // the level and rising: the gap is convex along the row (pair_gap.hpp), so it stays above the
  // level beyond, and those cells are left +infinity (a rung of the peer n = 6 bed evaluates 210
  // of its 256 cells: docs/performance.md, "Cheaper rungs"). The contact's column is walked up
  // the rows, each row's walks start from it.
  const auto at = [&](int i, int j, LineWalk& walk) {
    const Vec2 p = grid.x(i) * e1 + grid.y(j) * e2;
    return grid.gap[i + static_cast<std::size_t>(cells) * j] = walk.next(gap, p.x(), p.y());
  };
  const int contactColumn = std::clamp(static_cast<int>(std::floor(-grid.x0 / grid.hx)), 0, cells - 1);
  LineWalk column(grid.hy);
  for (int j = 0; j < cells; ++j) {
    at(contactColumn, j, column);
    LineWalk right = column.turned(grid.hx);  // the walk to the right, kept at its first cell: the left one's start
    for (const int step : {1, -1}) {
      LineWalk walk = step == 1 ? right : right.reversed();
      for (int i = contactColumn + step, before = contactColumn; i >= 0 && i < cells; before = i, i += step) {
        const double g = at(i, j, walk);
        if (step == 1 && i == contactColumn + 1) right = walk;
        if (g >= region.level && g > grid.gap[before + static_cast<std::size_t>(cells) * j]) break;  // (+infinity after a finite gap: the line left a body)
      }
    }
  }
  return grid;
}

}  // namespace sqdem
